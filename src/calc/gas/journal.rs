//! `POST /v1/gas-bearings/journal`: a plain 360° gas journal bearing on the compressible
//! Reynolds equation, at a given eccentricity or load (Khonsari & Booser §11.2–11.5).

use std::cell::RefCell;

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::gas_spec::{GasSpec, FIRST_ORDER_SLIP_LIMIT};
use super::journal_film::{self, JournalEvaluated, JournalFilm};
use super::method::{self, Method};
use super::slider::GasEffects;
use crate::calc::journal::plain::GeometrySpec;
use crate::calc::quantity::Positive;
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::effects::Mode;
use crate::fidelity::{FidelityRequest, Level, SolverReport};
use crate::numerics::driver::Stopped;
use crate::numerics::roots::{secant_bracketed, RootError, Stopping};

pub struct GasJournal;

/// Largest eccentricity ratio solved: beyond it the minimum film, C(1 − ε), needs grids finer
/// than the levels offer (ε ≥ 1 is contact).
pub const MAX_ECCENTRICITY: f64 = 0.95;

/// Smallest eccentricity ratio: the attitude angle is the direction of a vanishing load below.
pub const MIN_ECCENTRICITY: f64 = 1e-4;

/// Request. Give exactly one of `eccentricity_ratio` and `load_n`.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct GasJournalInput {
    pub geometry: GeometrySpec,
    /// Journal speed N, rev/min (> 0, at most 1e6); the bearing is stationary.
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 1e6, example = 30000.0)]
    pub speed_rpm: Positive,
    pub gas: GasSpec,
    /// ε = e/C, dimensionless, in [1e-4, 0.95] (ε ≥ 1 is contact); instead of `load_n`.
    #[schema(minimum = 1e-4, maximum = 0.95, example = 0.5)]
    pub eccentricity_ratio: Option<f64>,
    /// Load W, N (> 0); instead of `eccentricity_ratio`: ε and the attitude angle are found by
    /// a root search on the film's load.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e9, example = 20.0)]
    pub load_n: Option<Positive>,
    /// `fast`, `standard` (default), `high`, or `{"grid": [circumferential cells 16…512 (even),
    /// half-length axial cells 2…128]}`; each is also solved on its half mesh and
    /// Richardson-extrapolated.
    #[serde(default)]
    pub fidelity: FidelityRequest,
    #[serde(default)]
    pub effects: GasEffects,
    /// Include the pressure field over the half bearing (default false).
    #[serde(default)]
    #[schema(example = false)]
    pub include_field: bool,
}

/// What the request fixes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Given {
    Eccentricity(f64),
    Load(f64),
}

/// The parsed request.
#[derive(Debug, Clone)]
pub struct Case {
    pub diameter_m: f64,
    pub length_m: f64,
    pub clearance_m: f64,
    pub speed_rpm: f64,
    pub gas: super::Gas,
    pub given: Given,
    pub slip_flow: Mode,
    pub method: Method,
    pub include_field: bool,
}

impl Case {
    pub fn radius_m(&self) -> f64 {
        0.5 * self.diameter_m
    }
    /// ω, rad/s.
    pub fn angular_speed(&self) -> f64 {
        self.speed_rpm * std::f64::consts::PI / 30.0
    }
    /// Λ = 6μω(R/C)²/p_a.
    pub fn bearing_number(&self) -> f64 {
        6.0 * self.gas.viscosity_pa_s
            * self.angular_speed()
            * (self.radius_m() / self.clearance_m).powi(2)
            / self.gas.ambient_pressure_pa
    }
}

impl Validate for GasJournalInput {
    type Valid = Case;
    fn validate(self) -> Result<Case, Vec<FieldError>> {
        let mut errors = Vec::new();
        let (d, l, c) = self.geometry.check(&mut errors);
        let speed = self.speed_rpm.get();
        if speed > 1e6 {
            errors.push(FieldError::new(
                "/speed_rpm",
                format!("must be at most 1e6 rpm, got {speed}"),
            ));
        }
        let given = match (self.eccentricity_ratio, self.load_n) {
            (Some(e), None) if !e.is_finite() || !(0.0..1.0).contains(&e) => {
                errors.push(FieldError::new(
                    "/eccentricity_ratio",
                    format!(
                        "must be within [0, 1): ε ≥ 1 puts the journal on the bearing, got {e}"
                    ),
                ));
                Given::Eccentricity(0.5)
            }
            (Some(e), None) if !(MIN_ECCENTRICITY..=MAX_ECCENTRICITY).contains(&e) => {
                errors.push(FieldError::new(
                    "/eccentricity_ratio",
                    format!("must be within [{MIN_ECCENTRICITY}, {MAX_ECCENTRICITY}] (the minimum film resolved by the grids; the attitude of a vanishing load below), got {e}"),
                ));
                Given::Eccentricity(0.5)
            }
            (Some(e), None) => Given::Eccentricity(e),
            (None, Some(w)) => Given::Load(w.get()),
            _ => {
                errors.push(FieldError::new(
                    "/load_n",
                    "give exactly one of eccentricity_ratio and load_n",
                ));
                Given::Eccentricity(0.5)
            }
        };
        let method = method::parse(
            self.fidelity,
            journal_film::level_mesh,
            (16, 512),
            (2, 128),
            &mut errors,
        );
        if let FidelityRequest::Custom(f) = self.fidelity {
            if f.grid.is_some_and(|[n, _]| n % 2 != 0) {
                errors.push(FieldError::new(
                    "/fidelity/grid",
                    "the circumferential cell count must be even",
                ));
            }
        }
        let gas = match self.gas.parse("/gas") {
            Ok(gas) => Some(gas),
            Err(mut e) => {
                errors.append(&mut e);
                None
            }
        };
        let Some(gas) = gas.filter(|_| errors.is_empty()) else {
            return Err(errors);
        };
        let case = Case {
            diameter_m: d,
            length_m: l,
            clearance_m: c,
            speed_rpm: speed,
            gas,
            given,
            slip_flow: self.effects.slip_flow,
            method,
            include_field: self.include_field,
        };
        method::check_bearing_number(
            case.bearing_number(),
            "/speed_rpm",
            "6μω(R/C)²/p_a",
            "the film is at Table 11.4's Λ → ∞ limit",
        )
        .map_err(|e| vec![e])?;
        Ok(case)
    }
}

/// A node of the pressure field.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct GasJournalFieldPoint {
    /// θ from the maximum film in the direction of rotation, degrees.
    pub angle_deg: f64,
    /// z/L from a bearing end (0) to the mid-plane (0.5).
    pub axial_fraction: f64,
    /// Absolute pressure, Pa.
    pub pressure_pa: f64,
}

/// Response.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct GasJournalOutput {
    /// Λ = 6μω(R/C)²/p_a, dimensionless.
    pub bearing_number: f64,
    /// Load W (∫(p − p_a) dA, resultant), N.
    pub load_n: f64,
    /// W/(p_a L D), dimensionless.
    pub load_dimensionless: f64,
    /// ε = e/C (given, or found for the load).
    pub eccentricity_ratio: f64,
    /// From the load line to the line of centres, degrees (90 as Λ → 0, 0 as Λ → ∞).
    pub attitude_angle_deg: f64,
    /// Friction on the journal (moving surface), N.
    pub friction_force_journal_n: f64,
    /// Friction on the bearing (stationary surface), N.
    pub friction_force_bearing_n: f64,
    /// F C/(2π μ U R L) on the journal, dimensionless (1 at ε = 0: Petroff).
    pub friction_dimensionless_journal: f64,
    /// F C/(2π μ U R L) on the bearing, dimensionless.
    pub friction_dimensionless_bearing: f64,
    /// Friction torque on the journal F R, N·m.
    pub friction_torque_n_m: f64,
    /// Power loss F U, W.
    pub power_loss_w: f64,
    /// Peak film pressure, Pa, **absolute**.
    pub max_pressure_pa: f64,
    /// Where the peak is, θ from the maximum film in the direction of rotation, degrees.
    pub max_pressure_angle_deg: f64,
    /// h_min = C(1 − ε), m.
    pub min_film_m: f64,
    /// Kn = λ_a/h_min, dimensionless.
    pub knudsen_number: f64,
    /// The pressure field over the half bearing (with `include_field`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pressure_field: Option<Vec<GasJournalFieldPoint>>,
}

/// The stretched eccentricity s = ln(ε/(1 − ε)) in which the load search runs: W̄ ∝ ε at small ε
/// (linear theory), so ln W̄ is nearly linear in s there and bends only gently toward ε → 1.
fn stretch(e: f64) -> f64 {
    (e / (1.0 - e)).ln()
}

/// ε from the stretched s of [`stretch`].
fn unstretch(s: f64) -> f64 {
    1.0 / (1.0 + (-s).exp())
}

/// The film at the given load: a bracketed secant on ln(W̄/W̄_target) in the stretched s of
/// [`stretch`] over ε in [1e-4, 0.95]. The residual is nearly linear in s, so the secant lands in
/// a few film solves where Brent on W̄(ε) − W̄ took 10–12 (each solve is the film and its
/// Richardson half mesh); each film is solved by Newton from the last one's field (continuation in
/// Λ where that fails).
fn at_load(
    film: JournalFilm,
    target: f64,
    method: Method,
    budget: &crate::calc::Budget,
) -> Result<(JournalEvaluated, SolverReport), CalcError> {
    let last: RefCell<Option<JournalEvaluated>> = RefCell::new(None);
    let failed: RefCell<Option<Stopped>> = RefCell::new(None);
    let residual_at = |s: f64| -> f64 {
        let f = JournalFilm {
            eccentricity: unstretch(s),
            ..film
        };
        let warm = last.borrow().clone();
        match journal_film::evaluate(&f, method, warm.as_ref(), budget) {
            Ok(done) => {
                let w = done.performance.load();
                *last.borrow_mut() = Some(done);
                (w / target).ln()
            }
            Err(stop) => {
                *failed.borrow_mut() = Some(stop);
                f64::NAN
            }
        }
    };
    let (s_lo, s_hi) = (stretch(MIN_ECCENTRICITY), stretch(MAX_ECCENTRICITY));
    let hi = residual_at(s_hi);
    if let Some(stop) = failed.borrow_mut().take() {
        return Err(stop.into());
    }
    if hi < 0.0 {
        return Err(CalcError::impossible(
            "/load_n",
            format!(
                "the film carries at most W/(p_a L D) = {:.4} at ε = {MAX_ECCENTRICITY}; the load asks {target:.4}",
                target * hi.exp()
            ),
        ));
    }
    let lo = residual_at(s_lo);
    let root = secant_bracketed(
        residual_at,
        (s_lo, lo),
        (s_hi, hi),
        Stopping {
            // Δε = ε(1 − ε)Δs ≤ Δs/4: the old 1e-9 on ε or finer.
            x_tolerance: 4e-9,
            max_iterations: 60,
        },
    );
    if let Some(stop) = failed.borrow_mut().take() {
        return Err(stop.into());
    }
    let root = match root {
        Ok(r) => r,
        Err(RootError::NoSignChange { .. }) => {
            return Err(CalcError::impossible(
                "/load_n",
                format!(
                "the load W/(p_a L D) = {target:.4e} is below what ε = {MIN_ECCENTRICITY} carries"
            ),
            ))
        }
        Err(e) => return Err(CalcError::from_root("gas_journal_load", e)),
    };
    // The secant returns its last evaluated point: the film solved there is the answer.
    let done = last
        .into_inner()
        .expect("the search evaluated at least the bracket's ends");
    debug_assert_eq!(done.eccentricity, unstretch(root.x));
    Ok((done, root.report))
}

impl Calculation for GasJournal {
    const PATH: &'static str = "/v1/gas-bearings/journal";
    const SUMMARY: &'static str =
        "Plain 360° gas journal bearing: compressible Reynolds by Newton, load or eccentricity, attitude, friction, peak pressure";
    const DESCRIPTION: &'static str = include_str!("journal.md");
    const FIDELITY: &'static [Level] = &[Level::Fast, Level::Standard, Level::High];
    const EFFECTS: &'static [&'static str] = &["slip_flow"];
    const EXAMPLE: &'static str = r#"{"geometry": {"diameter_m": 0.025, "length_m": 0.025, "radial_clearance_m": 1e-5}, "speed_rpm": 30000, "gas": {"name": "air"}, "eccentricity_ratio": 0.5}"#;

    type Input = GasJournalInput;
    type Output = GasJournalOutput;

    fn run(case: Case, ctx: &mut Context) -> Result<GasJournalOutput, CalcError> {
        for (code, message) in &case.gas.assumptions {
            ctx.warn(code, message.clone());
        }
        let pa = case.gas.ambient_pressure_pa;
        let (r, l, c) = (case.radius_m(), case.length_m, case.clearance_m);
        let mut film = JournalFilm {
            eccentricity: 0.5,
            bearing_number: case.bearing_number(),
            knudsen_number: 0.0,
            l_over_d: l / case.diameter_m,
        };
        // Slip is decided on the thinnest film, C(1 − ε). For a load, ε is not known before the
        // film is solved: `auto` solves the continuum film first, decides on its h_min, and
        // solves again with slip if that decides so.
        let budget = ctx.budget();
        let solve =
            |film: JournalFilm| -> Result<(JournalEvaluated, Option<SolverReport>), CalcError> {
                match case.given {
                    Given::Eccentricity(e) => Ok((
                        journal_film::evaluate(
                            &JournalFilm {
                                eccentricity: e,
                                ..film
                            },
                            case.method,
                            None,
                            &budget,
                        )?,
                        None,
                    )),
                    Given::Load(w) => {
                        let (done, report) =
                            at_load(film, w / (pa * l * case.diameter_m), case.method, &budget)?;
                        Ok((done, Some(report)))
                    }
                }
            };
        let slip_film = JournalFilm {
            knudsen_number: case.gas.knudsen_number(c),
            ..film
        };
        let (evaluated, search, slip) = match (case.given, case.slip_flow) {
            (Given::Eccentricity(e), mode) => {
                let slip = case.gas.slip_flow(mode, c * (1.0 - e));
                let (done, search) = solve(if slip.applied { slip_film } else { film })?;
                (done, search, slip)
            }
            (Given::Load(_), Mode::On) => {
                let (done, search) = solve(slip_film)?;
                let slip = case.gas.slip_flow(Mode::On, c * (1.0 - done.eccentricity));
                (done, search, slip)
            }
            (Given::Load(_), mode) => {
                let (done, search) = solve(film)?;
                let slip = case.gas.slip_flow(mode, c * (1.0 - done.eccentricity));
                if slip.applied {
                    let (done, search) = solve(slip_film)?;
                    (done, search, slip)
                } else {
                    (done, search, slip)
                }
            }
        };
        film.eccentricity = evaluated.eccentricity;
        ctx.decide("slip_flow", slip.clone());
        let e = film.eccentricity;
        let knudsen_number = case.gas.knudsen_number(c * (1.0 - e));
        if slip.applied && knudsen_number > FIRST_ORDER_SLIP_LIMIT {
            ctx.warn(
                "slip_beyond_first_order",
                format!("Kn = {knudsen_number:.3} at the minimum film exceeds {FIRST_ORDER_SLIP_LIMIT}: the first-order slip form holds for Kn ≪ 1 only"),
            );
        }
        let mut report = evaluated
            .fine
            .report
            .clone()
            .named(if search.is_some() {
                "finite_volume_newton_fitted_flux_secant_load"
            } else {
                "finite_volume_newton_fitted_flux"
            })
            .counting(evaluated.iterations, evaluated.evaluations)
            .at(case.method.level)
            .on_grid(case.method.grid())
            .with_error_estimate(evaluated.error_estimate)
            .with_film_solves(budget.field_solves());
        if let Some(s) = search {
            report.iterations = s.iterations;
            report.iterations_unit = s.iterations_unit;
        }
        ctx.report(report);
        let p = evaluated.performance;
        let (mu, omega) = (case.gas.viscosity_pa_s, case.angular_speed());
        let u = r * omega;
        let petroff = 2.0 * std::f64::consts::PI * mu * u * r * l / c;
        let friction_journal = p.friction_journal * petroff;
        let pressure_field = case.include_field.then(|| {
            let g = &evaluated.fine.grid;
            let w = film.l_over_d;
            let mut points = Vec::with_capacity(g.x.len() * g.y.len());
            for i in 0..g.x.len() {
                for j in 0..g.y.len() {
                    points.push(GasJournalFieldPoint {
                        angle_deg: g.x[i].to_degrees(),
                        axial_fraction: 0.5 * g.y[j] / w,
                        pressure_pa: evaluated.fine.p[g.at(i, j)] * pa,
                    });
                }
            }
            points
        });
        let out = GasJournalOutput {
            bearing_number: film.bearing_number,
            load_n: p.load() * pa * l * case.diameter_m,
            load_dimensionless: p.load(),
            eccentricity_ratio: e,
            attitude_angle_deg: p.attitude().to_degrees(),
            friction_force_journal_n: friction_journal,
            friction_force_bearing_n: p.friction_bearing * petroff,
            friction_dimensionless_journal: p.friction_journal,
            friction_dimensionless_bearing: p.friction_bearing,
            friction_torque_n_m: friction_journal * r,
            power_loss_w: friction_journal * u,
            max_pressure_pa: p.max_pressure * pa,
            max_pressure_angle_deg: p.max_pressure_angle.to_degrees(),
            min_film_m: c * (1.0 - e),
            knudsen_number,
            pressure_field,
        };
        let numbers = [
            out.bearing_number,
            out.load_n,
            out.attitude_angle_deg,
            out.friction_force_journal_n,
            out.friction_force_bearing_n,
            out.power_loss_w,
            out.max_pressure_pa,
        ];
        if numbers.iter().all(|v| v.is_finite()) {
            Ok(out)
        } else {
            Err(CalcError::impossible(
                "",
                "this combination of inputs takes the result outside the floating-point range",
            ))
        }
    }
}
