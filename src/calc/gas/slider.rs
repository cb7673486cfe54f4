//! `POST /v1/gas-bearings/slider`: a plane gas slider (finite, or infinitely wide) on the
//! compressible Reynolds equation (Khonsari & Booser §11.2–11.3; Stachowiak & Batchelor §4.8).

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::cost::{self, Least};
use super::gas_spec::{GasSpec, FIRST_ORDER_SLIP_LIMIT};
use super::method::{self, Method};
use super::slider_film::{self, SliderFilm};
use crate::calc::quantity::{ratio_within, Positive};
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::effects::Mode;
use crate::fidelity::{FidelityRequest, Level};
use crate::numerics::reynolds_gas::FarEdge;

/// The h1/h2 accepted, as the thrust pads' (1.01 … 10): a parallel film carries no load, and a
/// nearly parallel one next to nothing.
const FILM_RATIOS: (f64, f64) = (1.01, 10.0);

pub struct GasSlider;

/// The pad: B along the sliding direction, L across it.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct GasSliderPad {
    /// Breadth B along the sliding direction, m (> 0, at most 1).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 1.0, example = 0.02)]
    pub breadth_m: Positive,
    /// Length L across the sliding direction, m (> 0, at most 1; L/B from 0.05 to 50). Omit it
    /// for an infinitely wide slider: loads, forces and power are then per metre of width
    /// (the `_per_m` fields).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1.0, example = 0.02)]
    pub length_m: Option<Positive>,
}

/// Effects a gas film understands.
#[derive(Debug, Clone, Copy, Default, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct GasEffects {
    /// Rarefaction: first-order slip (Burgdorfer; Khonsari & Booser Eq. 11.10), the Poiseuille
    /// term's H³P becoming H³P(1 + 6Kn/(PH)) with Kn = λ_a/h_ref. `auto` applies it when the
    /// Knudsen number at the thinnest film, λ_a/h_min, exceeds 0.01 (§11.2: continuum flow
    /// below); a warning follows above 1, where the first-order form no longer holds.
    #[serde(default)]
    pub slip_flow: Mode,
}

/// Request.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct GasSliderInput {
    pub pad: GasSliderPad,
    /// Leading-edge film h1, m (1e-8 … 1e-3), 1.01 to 10 times `outlet_film_m` (a converging
    /// slider).
    #[schema(value_type = f64, minimum = 1e-8, maximum = 1e-3, example = 1e-5)]
    pub inlet_film_m: Positive,
    /// Trailing-edge film h2, m (1e-8 … 1e-3): the minimum film and the scale of Λ.
    #[schema(value_type = f64, minimum = 1e-8, maximum = 1e-3, example = 5e-6)]
    pub outlet_film_m: Positive,
    /// Runner speed U, m/s (> 0, at most 1000).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 1000.0, example = 10.0)]
    pub sliding_speed_m_s: Positive,
    pub gas: GasSpec,
    /// `fast`, `standard` (default), `high`, or `{"grid": [cells along B 8…1024, cells across
    /// half of L 2…256]}`; each is also solved on its half mesh and Richardson-extrapolated; a
    /// grid whose Newton solves would outlast the request's deadline is refused at once (422 at
    /// `/fidelity/grid`, with the estimate).
    #[serde(default)]
    pub fidelity: FidelityRequest,
    #[serde(default)]
    pub effects: GasEffects,
    /// Include the mid-plane pressure profile (default false).
    #[serde(default)]
    #[schema(example = false)]
    pub include_field: bool,
}

/// The parsed request.
#[derive(Debug, Clone)]
pub struct Case {
    pub breadth_m: f64,
    pub length_m: Option<f64>,
    pub inlet_film_m: f64,
    pub outlet_film_m: f64,
    pub speed_m_s: f64,
    pub gas: super::Gas,
    pub slip_flow: Mode,
    pub method: Method,
    pub include_field: bool,
}

impl Case {
    /// Λ = 6μUB/(p_a h2²).
    pub fn bearing_number(&self) -> f64 {
        6.0 * self.gas.viscosity_pa_s * self.speed_m_s * self.breadth_m
            / (self.gas.ambient_pressure_pa * self.outlet_film_m.powi(2))
    }
}

fn film_range(errors: &mut Vec<FieldError>, field: &str, v: f64) {
    if !(1e-8..=1e-3).contains(&v) {
        errors.push(FieldError::new(
            format!("/{field}"),
            format!("must be within [1e-8, 1e-3] m, got {v}"),
        ));
    }
}

impl Validate for GasSliderInput {
    type Valid = Case;
    fn validate(self) -> Result<Case, Vec<FieldError>> {
        let mut errors = Vec::new();
        let (b, l) = (
            self.pad.breadth_m.get(),
            self.pad.length_m.map(Positive::get),
        );
        if b > 1.0 {
            errors.push(FieldError::new(
                "/pad/breadth_m",
                format!("must be at most 1 m, got {b}"),
            ));
        }
        if let Some(l) = l {
            if l > 1.0 {
                errors.push(FieldError::new(
                    "/pad/length_m",
                    format!("must be at most 1 m, got {l}"),
                ));
            } else if !ratio_within(l / b, 0.05, 50.0) {
                errors.push(FieldError::new(
                    "/pad/length_m",
                    format!("L/B must be within [0.05, 50], got {:.4}", l / b),
                ));
            }
        }
        let (h1, h2) = (self.inlet_film_m.get(), self.outlet_film_m.get());
        film_range(&mut errors, "inlet_film_m", h1);
        film_range(&mut errors, "outlet_film_m", h2);
        if h1 < h2 {
            errors.push(FieldError::new(
                "/inlet_film_m",
                format!("a converging slider needs inlet_film_m ≥ outlet_film_m (h1 = {h1} m < h2 = {h2} m): a diverging film carries no load"),
            ));
        } else if h1 / h2 < FILM_RATIOS.0 {
            errors.push(FieldError::new(
                "/inlet_film_m",
                format!("h1/h2 must be at least {}, got {:.6}: a parallel film carries no load, and a nearly parallel one next to nothing", FILM_RATIOS.0, h1 / h2),
            ));
        } else if h1 / h2 > FILM_RATIOS.1 {
            errors.push(FieldError::new(
                "/inlet_film_m",
                format!(
                    "h1/h2 must be at most {}, got {:.4}",
                    FILM_RATIOS.1,
                    h1 / h2
                ),
            ));
        }
        let speed = self.sliding_speed_m_s.get();
        if speed > 1000.0 {
            errors.push(FieldError::new(
                "/sliding_speed_m_s",
                format!("must be at most 1000 m/s, got {speed}"),
            ));
        }
        let method = method::parse(
            self.fidelity,
            slider_film::level_mesh,
            (8, 1024),
            (2, 256),
            &mut errors,
        );
        let gas = self.gas.parse_into("/gas", &mut errors);
        let Some(gas) = gas.filter(|_| errors.is_empty()) else {
            return Err(errors);
        };
        let case = Case {
            breadth_m: b,
            length_m: l,
            inlet_film_m: h1,
            outlet_film_m: h2,
            speed_m_s: speed,
            gas,
            slip_flow: self.effects.slip_flow,
            method,
            include_field: self.include_field,
        };
        method::check_bearing_number(
            case.bearing_number(),
            "/sliding_speed_m_s",
            "6μUB/(p_a h2²)",
            "the film is P H = const (Table 11.3's Λ → ∞ limit) to better than 0.1 %",
        )
        .map_err(|e| vec![e])?;
        Ok(case)
    }
}

/// A point of the mid-plane pressure profile.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct GasPressurePoint {
    /// x/B from the leading edge.
    pub position_fraction: f64,
    /// Absolute pressure, Pa.
    pub pressure_pa: f64,
}

/// Response. A finite pad gives `load_n`, `friction_force_runner_n`, `friction_force_pad_n`
/// and `power_loss_w`; an infinitely wide one the same per metre of width (`_per_m`).
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct GasSliderOutput {
    /// Λ = 6μUB/(p_a h2²), dimensionless.
    pub bearing_number: f64,
    /// Load carried W (∫(p − p_a) dA), N; finite pads.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub load_n: Option<f64>,
    /// Load per metre of width W/L, N/m; infinitely wide pads.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub load_n_per_m: Option<f64>,
    /// W/(p_a B L), dimensionless.
    pub load_dimensionless: f64,
    /// Centre of pressure, x/B from the leading edge.
    pub center_of_pressure_fraction: f64,
    /// Friction on the runner (moving surface), N; finite pads.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub friction_force_runner_n: Option<f64>,
    /// Friction on the pad (stationary surface), N; finite pads.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub friction_force_pad_n: Option<f64>,
    /// Friction on the runner per metre of width, N/m; infinitely wide pads.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub friction_force_runner_n_per_m: Option<f64>,
    /// Friction on the pad per metre of width, N/m; infinitely wide pads.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub friction_force_pad_n_per_m: Option<f64>,
    /// F h2/(μ U B L) on the runner, dimensionless.
    pub friction_dimensionless_runner: f64,
    /// F h2/(μ U B L) on the pad, dimensionless.
    pub friction_dimensionless_pad: f64,
    /// Peak film pressure, Pa, **absolute**.
    pub max_pressure_pa: f64,
    /// Where the peak is, x/B from the leading edge.
    pub max_pressure_position_fraction: f64,
    /// Power loss F_runner U, W; finite pads.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub power_loss_w: Option<f64>,
    /// Power loss per metre of width, W/m; infinitely wide pads.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub power_loss_w_per_m: Option<f64>,
    /// h1/h2.
    pub film_ratio: f64,
    /// Kn = λ_a/h2 at the outlet film, dimensionless.
    pub knudsen_number: f64,
    /// The mid-plane pressure profile (with `include_field`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pressure_profile: Option<Vec<GasPressurePoint>>,
}

impl Calculation for GasSlider {
    const PATH: &'static str = "/v1/gas-bearings/slider";
    const SUMMARY: &'static str =
        "Plane gas slider (finite or infinitely wide): compressible Reynolds by Newton, load, friction, centre of pressure";
    const DESCRIPTION: &'static str = include_str!("slider.md");
    const FIDELITY: &'static [Level] = &[Level::Fast, Level::Standard, Level::High];
    const EFFECTS: &'static [&'static str] = &["slip_flow"];
    const EXAMPLE: &'static str = r#"{"pad": {"breadth_m": 0.02, "length_m": 0.02}, "inlet_film_m": 1e-5, "outlet_film_m": 5e-6, "sliding_speed_m_s": 10, "gas": {"name": "air"}}"#;

    type Input = GasSliderInput;
    type Output = GasSliderOutput;

    fn run(case: Case, ctx: &mut Context) -> Result<GasSliderOutput, CalcError> {
        for (code, message) in &case.gas.assumptions {
            ctx.warn(code, message.clone());
        }
        let slip = case.gas.slip_flow(case.slip_flow, case.outlet_film_m);
        let knudsen_number = case.gas.knudsen_number(case.outlet_film_m);
        if slip.applied && knudsen_number > FIRST_ORDER_SLIP_LIMIT {
            ctx.warn(
                "slip_beyond_first_order",
                format!("Kn = {knudsen_number:.3} exceeds {FIRST_ORDER_SLIP_LIMIT}: the first-order slip form is valid for Kn ≪ 1 only (molecular flow needs the Boltzmann equation)"),
            );
        }
        let film = SliderFilm {
            film_ratio: case.inlet_film_m / case.outlet_film_m,
            bearing_number: case.bearing_number(),
            knudsen_number: if slip.applied { knudsen_number } else { 0.0 },
            width_ratio: case.length_m.map(|l| l / case.breadth_m),
        };
        ctx.decide("slip_flow", slip);
        let budget = ctx.budget();
        cost::check(
            case.method,
            slider_film::level_mesh,
            (
                &slider_film::grid(&film, case.method.mesh),
                FarEdge::Symmetry,
            ),
            Least::one_film(film.bearing_number),
            &budget,
        )?;
        let evaluated = slider_film::evaluate(&film, case.method, &budget)?;
        ctx.report(
            evaluated
                .fine
                .report
                .clone()
                .named("finite_volume_newton_fitted_flux")
                .counting(evaluated.iterations, evaluated.evaluations)
                .at(case.method.level)
                .on_grid(if case.length_m.is_some() {
                    case.method.grid()
                } else {
                    // An infinitely wide film has cells along B only.
                    vec![case.method.mesh.along as u32]
                })
                .with_error_estimate(evaluated.error_estimate)
                .with_film_solves(budget.field_solves()),
        );
        let p = evaluated.performance;
        let pa = case.gas.ambient_pressure_pa;
        let (b, u, mu, h2) = (
            case.breadth_m,
            case.speed_m_s,
            case.gas.viscosity_pa_s,
            case.outlet_film_m,
        );
        let width = case.length_m.unwrap_or(1.0);
        let load = p.load * pa * b * width;
        let friction = |f: f64| f * mu * u * b * width / h2;
        let (finite, wide) = (case.length_m.is_some(), case.length_m.is_none());
        let pick = |v: f64, on: bool| on.then_some(v);
        let profile = case.include_field.then(|| {
            let grid = &evaluated.fine.grid;
            let j = grid.y.len() - 1;
            (0..=grid.nx())
                .map(|i| GasPressurePoint {
                    position_fraction: grid.x[i],
                    pressure_pa: evaluated.fine.p[grid.at(i, j)] * pa,
                })
                .collect()
        });
        let out = GasSliderOutput {
            bearing_number: film.bearing_number,
            load_n: pick(load, finite),
            load_n_per_m: pick(load, wide),
            load_dimensionless: p.load,
            center_of_pressure_fraction: p.center_of_pressure,
            friction_force_runner_n: pick(friction(p.friction_runner), finite),
            friction_force_pad_n: pick(friction(p.friction_pad), finite),
            friction_force_runner_n_per_m: pick(friction(p.friction_runner), wide),
            friction_force_pad_n_per_m: pick(friction(p.friction_pad), wide),
            friction_dimensionless_runner: p.friction_runner,
            friction_dimensionless_pad: p.friction_pad,
            max_pressure_pa: p.max_pressure * pa,
            max_pressure_position_fraction: p.max_pressure_position,
            power_loss_w: pick(friction(p.friction_runner) * u, finite),
            power_loss_w_per_m: pick(friction(p.friction_runner) * u, wide),
            film_ratio: film.film_ratio,
            knudsen_number,
            pressure_profile: profile,
        };
        let numbers = [
            out.bearing_number,
            load,
            out.load_dimensionless,
            out.center_of_pressure_fraction,
            friction(p.friction_runner),
            friction(p.friction_pad),
            out.max_pressure_pa,
        ];
        CalcError::unless_finite(&numbers)?;
        Ok(out)
    }
}
