//! `POST /v1/gas-bearings/tilting-pad-thrust`: a thrust bearing of crowned, point-pivoted gas
//! sector pads (Khonsari & Booser §11.4 after Shapiro & Colsher 1968), each pad balanced on its
//! pivot in pitch and roll, at a clearance or under the bearing's load.
//!
//! This file is the wire; the physics is [`super::pivoted_pad`].

use std::f64::consts::PI;

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::cost::{self, Least};
use super::gas_spec::{GasSpec, FIRST_ORDER_SLIP_LIMIT};
use super::method::{self, Method};
use super::pivoted_pad::{self, PadEvaluated, PadGiven, PadScales, CLEARANCE_RANGE_M};
use super::sector_pad::{self, Sector};
use super::slider::GasEffects;
use super::slider_film;
use crate::calc::quantity::{ratio_within, NonNegative, Positive};
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::effects::Mode;
use crate::fidelity::{FidelityRequest, Level};
use crate::numerics::reynolds_gas::FarEdge;

pub struct GasTiltingPadThrust;

/// Shapiro & Colsher's pad angle θ_p, degrees (their charts' pads).
const DEFAULT_PAD_ANGLE_DEG: f64 = 45.0;
/// γ/θ_p, Ex 11.2's pivot read from Fig. 11.9 for δ/C = 1.
const DEFAULT_PIVOT_ANGLE_FRACTION: f64 = 0.6;
/// r_pv over the mean radius: "about 1–2 % beyond the mean radius" (§11.4), where the pad
/// hardly rolls.
const DEFAULT_PIVOT_RADIUS_OVER_MEAN: f64 = 1.015;

/// Request.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct GasTiltingPadThrustInput {
    /// Inner radius of the pads r_i, m (> 0; r_i/r_o from 0.1 to 0.95).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 10.0, example = 0.0508)]
    pub inner_radius_m: Positive,
    /// Outer radius r_o, m (> 0, at most 10): the scale of Λ and of the load coefficient.
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 10.0, example = 0.1016)]
    pub outer_radius_m: Positive,
    /// Number of pads (1 … 64), sharing the load equally.
    #[schema(minimum = 1, maximum = 64, example = 6)]
    pub pad_count: u32,
    /// Each pad's angle θ_p, degrees (5 … 180; default 45, Shapiro & Colsher's; all pads
    /// together at most 360°).
    #[schema(value_type = Option<f64>, minimum = 5.0, maximum = 180.0, example = 45.0)]
    pub pad_angle_deg: Option<f64>,
    /// The pivot's angle from the pad's leading edge as a fraction of the pad angle, γ/θ_p
    /// (0.05 … 0.95; default 0.6, Ex 11.2's).
    #[schema(value_type = Option<f64>, minimum = 0.05, maximum = 0.95, example = 0.6)]
    pub pivot_angle_fraction: Option<f64>,
    /// The pivot's radius r_pv, m (between the pads' radii; default 1.5 % beyond the mean
    /// radius, where the texts find the pad hardly rolls).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 0.07747)]
    pub pivot_radius_m: Option<Positive>,
    /// Crown height δ, m (0 … 1e-3; default 0, a flat pad): a cylindrical crown whose axis is
    /// the pad's radial centre line, δ at the leading and trailing edges on the mean radius
    /// (Shapiro & Colsher find δ/C = 1 best for load).
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 1e-3, example = 1.0505e-5)]
    pub crown_m: Option<NonNegative>,
    /// Runner speed, rpm (> 0, at most 1e6).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 1e6, example = 20000.0)]
    pub speed_rpm: Positive,
    pub gas: GasSpec,
    /// The bearing's whole load W, N, shared by the pads; give it or `clearance_m`.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e9, example = 2001.7)]
    pub load_n: Option<Positive>,
    /// Clearance C, m (1e-8 … 1e-3): the film at the crown's peak before the pad tilts; give it
    /// or `load_n`.
    #[schema(value_type = Option<f64>, minimum = 1e-8, maximum = 1e-3, example = 1.0505e-5)]
    pub clearance_m: Option<Positive>,
    /// `fast`, `standard` (default), `high`, or `{"grid": [cells along the pad's angle 8…512,
    /// cells across each half of its radial width 2…128]}`; a level, or a grid of even counts,
    /// is also solved on its half mesh and Richardson-extrapolated; a grid whose Newton solves
    /// would outlast the request's deadline is refused at once (422 at `/fidelity/grid`, with
    /// the estimate).
    #[serde(default)]
    pub fidelity: FidelityRequest,
    #[serde(default)]
    pub effects: GasEffects,
}

/// What the request gives, dimensional: the bearing's load (N) or the clearance (m).
#[derive(Debug, Clone, Copy)]
enum Given {
    Load(f64),
    Clearance(f64),
}

/// The parsed request.
#[derive(Debug, Clone)]
pub struct Case {
    pub outer_radius_m: f64,
    pub pad_count: u32,
    pub scales: PadScales,
    pub given: PadGiven,
    pub speed_rad_s: f64,
    pub gas: super::Gas,
    pub slip_flow: Mode,
    pub method: Method,
}

impl Validate for GasTiltingPadThrustInput {
    type Valid = Case;
    fn validate(self) -> Result<Case, Vec<FieldError>> {
        let mut errors = Vec::new();
        let (ri, ro) = (self.inner_radius_m.get(), self.outer_radius_m.get());
        FieldError::check_at_most(&mut errors, "/outer_radius_m", ro, 10.0);
        if !ratio_within(ri / ro, 0.1, 0.95) {
            errors.push(FieldError::new(
                "/inner_radius_m",
                format!(
                    "r_i/r_o must be within [0.1, 0.95] (pads from near the axis to thin rings), got {:.4}",
                    ri / ro
                ),
            ));
        }
        let count = self.pad_count;
        if !(1..=64).contains(&count) {
            errors.push(FieldError::new(
                "/pad_count",
                format!("must be within [1, 64], got {count}"),
            ));
        }
        let angle_deg = self.pad_angle_deg.unwrap_or(DEFAULT_PAD_ANGLE_DEG);
        if !(5.0..=180.0).contains(&angle_deg) {
            errors.push(FieldError::new(
                "/pad_angle_deg",
                format!("must be within [5, 180] degrees, got {angle_deg}"),
            ));
        } else if f64::from(count) * angle_deg > 360.0 * (1.0 + 1e-12) {
            errors.push(FieldError::new(
                "/pad_angle_deg",
                format!("{count} pads of {angle_deg}° take more than the 360° of the runner"),
            ));
        }
        let fraction = self
            .pivot_angle_fraction
            .unwrap_or(DEFAULT_PIVOT_ANGLE_FRACTION);
        FieldError::check_within(&mut errors, "/pivot_angle_fraction", fraction, (0.05, 0.95));
        let pivot_radius = self.pivot_radius_m.map_or(
            DEFAULT_PIVOT_RADIUS_OVER_MEAN * 0.5 * (ri + ro),
            Positive::get,
        );
        if !(pivot_radius > ri && pivot_radius < ro) {
            errors.push(FieldError::new(
                "/pivot_radius_m",
                format!("must lie between the pads' radii ({ri} m, {ro} m), got {pivot_radius}"),
            ));
        }
        let crown = self.crown_m.map_or(0.0, NonNegative::get);
        FieldError::check_within(&mut errors, "/crown_m", crown, (0.0, 1e-3));
        let speed = self.speed_rpm.get();
        FieldError::check_at_most(&mut errors, "/speed_rpm", speed, 1e6);
        let given = match (self.load_n, self.clearance_m) {
            (Some(w), None) => {
                FieldError::check_at_most(&mut errors, "/load_n", w.get(), 1e9);
                Some(Given::Load(w.get()))
            }
            (None, Some(c)) => {
                FieldError::check_within(&mut errors, "/clearance_m", c.get(), CLEARANCE_RANGE_M);
                Some(Given::Clearance(c.get()))
            }
            (Some(_), Some(_)) => {
                for p in ["/load_n", "/clearance_m"] {
                    errors.push(FieldError::new(
                        p,
                        "give `load_n` or `clearance_m`, not both: each fixes the other",
                    ));
                }
                None
            }
            (None, None) => {
                errors.push(FieldError::new(
                    "/load_n",
                    "give `load_n` (the clearance follows) or `clearance_m` (the load follows)",
                ));
                None
            }
        };
        let method = method::parse(
            self.fidelity,
            slider_film::level_mesh,
            (8, 512),
            (2, 128),
            &mut errors,
        );
        let gas = self.gas.parse_into("/gas", &mut errors);
        let (Some(gas), Some(given), true) = (gas, given, errors.is_empty()) else {
            return Err(errors);
        };
        let angle = angle_deg.to_radians();
        let omega = speed * PI / 30.0;
        let scales = PadScales {
            sector: Sector {
                inner_radius: ri / ro,
                angle,
                pivot_radius: pivot_radius / ro,
                pivot_angle: fraction * angle,
            },
            bearing_number_m2: 6.0 * gas.viscosity_pa_s * omega * ro * ro / gas.ambient_pressure_pa,
            crown_m: crown,
            mean_free_path_m: None,
        };
        let given = match given {
            Given::Load(w) => {
                if scales.load_search_range().is_none() {
                    return Err(vec![no_clearance_for_the_load(&scales)]);
                }
                PadGiven::Load(w / f64::from(count) / (gas.ambient_pressure_pa * ro * ro))
            }
            Given::Clearance(c) => {
                method::check_bearing_number(
                    scales.bearing_number_m2 / (c * c),
                    "/clearance_m",
                    "6μω r_o²/(p_a C²)",
                    "the film is P H = const (the Λ → ∞ limit) to better than 0.1 %",
                )
                .map_err(|e| vec![e])?;
                PadGiven::Clearance(c)
            }
        };
        Ok(Case {
            outer_radius_m: ro,
            pad_count: count,
            scales,
            given,
            speed_rad_s: omega,
            gas,
            slip_flow: self.effects.slip_flow,
            method,
        })
    }
}

/// The 422 of a load for which no clearance in the model's range has a bearing number the film
/// can be solved at.
fn no_clearance_for_the_load(scales: &PadScales) -> FieldError {
    FieldError::new(
        "/speed_rpm",
        format!(
            "the speed, viscosity and ambient pressure give Λ C² = 6μω r_o²/p_a = {:.3e} m²: no clearance in [{:e}, {:e}] m has a bearing number Λ in [{:e}, {:e}]",
            scales.bearing_number_m2,
            CLEARANCE_RANGE_M.0,
            CLEARANCE_RANGE_M.1,
            pivoted_pad::LOAD_SEARCH_BEARING_NUMBERS.1,
            pivoted_pad::LOAD_SEARCH_BEARING_NUMBERS.0
        ),
    )
}

/// Where on the pad a film is.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct PadPoint {
    /// Angle from the leading edge over the pad angle.
    pub angle_fraction: f64,
    /// Radius, m.
    pub radius_m: f64,
}

/// Response: per pad where it says so, the whole bearing otherwise.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct GasTiltingPadThrustOutput {
    /// Λ = 6μω r_o²/(p_a C²), dimensionless (Shapiro & Colsher's).
    pub bearing_number: f64,
    /// Clearance C, m: the film at the crown's peak before the pad tilts.
    pub clearance_m: f64,
    /// The bearing's load W (all pads), N.
    pub load_n: f64,
    /// One pad's load, N.
    pub load_per_pad_n: f64,
    /// C_L = W_pad/(p_a r_o²), dimensionless.
    pub load_coefficient: f64,
    /// δ/C.
    pub crown_ratio: f64,
    /// The thinnest film h_min, m.
    pub min_film_m: f64,
    /// H_min = h_min/C.
    pub min_film_ratio: f64,
    /// Where the film is thinnest.
    pub min_film_position: PadPoint,
    /// The film at the pivot, m.
    pub pivot_film_m: f64,
    /// Pitch α about the pivot's radial line, rad (positive closing the trailing part).
    pub pitch_rad: f64,
    /// Roll β about the line across the pivot, rad (positive closing the outer part).
    pub roll_rad: f64,
    /// F = M_f/(p_a r_o² C) on the runner (one pad's friction moment), dimensionless.
    pub friction_moment_factor: f64,
    /// The friction moment on the runner, all pads, N·m.
    pub friction_torque_runner_n_m: f64,
    /// The friction moment on the pads (stationary), all pads together, N·m.
    pub friction_torque_pads_n_m: f64,
    /// Power loss M_f ω, all pads, W.
    pub power_loss_w: f64,
    /// Peak film pressure, Pa, **absolute**.
    pub max_pressure_pa: f64,
    /// Kn = λ_a/h_min at the thinnest film, dimensionless.
    pub knudsen_number: f64,
}

impl GasTiltingPadThrust {
    /// The pads with or without slip flow, from a nearby evaluation's pads when given.
    fn evaluate(
        case: &Case,
        slip: bool,
        warm: Option<&PadEvaluated>,
        ctx: &Context,
    ) -> Result<PadEvaluated, CalcError> {
        let scales = PadScales {
            mean_free_path_m: slip.then_some(case.gas.mean_free_path_m),
            ..case.scales
        };
        pivoted_pad::evaluate(&scales, case.given, case.method, warm, &ctx.budget())
    }
}

impl Calculation for GasTiltingPadThrust {
    const PATH: &'static str = "/v1/gas-bearings/tilting-pad-thrust";
    const SUMMARY: &'static str =
        "Tilting-pad gas thrust bearing: crowned sector pads balanced in pitch and roll on point pivots, compressible Reynolds in polar coordinates";
    const DESCRIPTION: &'static str = include_str!("tilting_pad_thrust.md");
    const FIDELITY: &'static [Level] = &[Level::Fast, Level::Standard, Level::High];
    const EFFECTS: &'static [&'static str] = &["slip_flow"];
    const EXAMPLE: &'static str = r#"{"inner_radius_m": 0.0508, "outer_radius_m": 0.1016, "pad_count": 6, "pad_angle_deg": 45, "pivot_angle_fraction": 0.6, "pivot_radius_m": 0.07747, "crown_m": 1.0505e-5, "speed_rpm": 20000, "gas": {"viscosity_pa_s": 2.2e-5, "ambient_pressure_pa": 103421}, "load_n": 2001.7}"#;

    type Input = GasTiltingPadThrustInput;
    type Output = GasTiltingPadThrustOutput;

    fn run(case: Case, ctx: &mut Context) -> Result<GasTiltingPadThrustOutput, CalcError> {
        for (code, message) in &case.gas.assumptions {
            ctx.warn(code, message.clone());
        }
        // Slip is decided on the thinnest film, known once the film is solved: `auto` solves the
        // continuum film first and again with slip, from the continuum pads, if its h_min asks
        // for it.
        // The grid's shape, all that is costed, is any clearance's; both radial edges held.
        let (clearance, least) = match case.given {
            PadGiven::Clearance(c) => (c, Least::THRUST_PAD_AT_CLEARANCE),
            PadGiven::Load(_) => (case.scales.clearance_at(1.0), Least::THRUST_PAD_BY_LOAD),
        };
        let grid = sector_pad::grid(&case.scales.film(clearance), case.method.mesh, false);
        cost::check(
            case.method,
            slider_film::level_mesh,
            (&grid, FarEdge::Held),
            least,
            &ctx.budget(),
        )?;
        let first = Self::evaluate(&case, case.slip_flow == Mode::On, None, ctx)?;
        let slip = case.gas.slip_flow(case.slip_flow, first.thinnest_m().0);
        let done = if slip.applied && case.slip_flow != Mode::On {
            Self::evaluate(&case, true, Some(&first), ctx)?
        } else {
            first
        };
        let (h_min, theta, r) = done.thinnest_m();
        let knudsen_number = case.gas.knudsen_number(h_min);
        if slip.applied && knudsen_number > FIRST_ORDER_SLIP_LIMIT {
            ctx.warn(
                "slip_beyond_first_order",
                format!("Kn = {knudsen_number:.3} at the thinnest film exceeds {FIRST_ORDER_SLIP_LIMIT}: the first-order slip form holds for Kn ≪ 1 only"),
            );
        }
        ctx.decide("slip_flow", slip);
        let budget = ctx.budget();
        let fine = &done.fine.solve;
        ctx.report(
            fine.report
                .clone()
                .named("finite_volume_newton_fitted_flux_polar_pivot_balance")
                .counting(done.newton_steps, budget.field_solves())
                .with_residual(fine.performance.imbalance())
                .at(case.method.level)
                .on_grid(case.method.grid())
                .with_error_estimate(done.error_estimate)
                .with_film_solves(budget.field_solves()),
        );
        let (ro, pa, c) = (
            case.outer_radius_m,
            case.gas.ambient_pressure_pa,
            done.clearance_m,
        );
        let pads = f64::from(case.pad_count);
        let p = done.performance;
        let load_per_pad = p.load * pa * ro * ro;
        let torque = |f: f64| f * pa * ro * ro * c * pads;
        let s = &case.scales.sector;
        let pivot = done.film.height(done.tilt, s.pivot_angle, s.pivot_radius);
        let out = GasTiltingPadThrustOutput {
            bearing_number: done.film.bearing_number,
            clearance_m: c,
            load_n: load_per_pad * pads,
            load_per_pad_n: load_per_pad,
            load_coefficient: p.load,
            crown_ratio: done.film.crown,
            min_film_m: h_min,
            min_film_ratio: h_min / c,
            min_film_position: PadPoint {
                angle_fraction: theta / s.angle,
                radius_m: r * ro,
            },
            pivot_film_m: pivot * c,
            pitch_rad: done.tilt.pitch * c / ro,
            roll_rad: done.tilt.roll * c / ro,
            friction_moment_factor: p.friction_runner,
            friction_torque_runner_n_m: torque(p.friction_runner),
            friction_torque_pads_n_m: torque(p.friction_pad),
            power_loss_w: torque(p.friction_runner) * case.speed_rad_s,
            max_pressure_pa: p.max_pressure * pa,
            knudsen_number,
        };
        CalcError::finite_or_out_of_range(out, "the pad's size, speed and load")
    }
}
