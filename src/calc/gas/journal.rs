//! `POST /v1/gas-bearings/journal`: a plain 360° gas journal bearing on the compressible
//! Reynolds equation, at a given eccentricity or load (Khonsari & Booser §11.2–11.5).

use std::cell::RefCell;
use std::f64::consts::PI;

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::cost::{self, Least};
use super::gas_spec::{GasSpec, FIRST_ORDER_SLIP_LIMIT};
use super::journal_dynamics::{self, STANDARD_GRAVITY};
use super::journal_film::{self, stretch, unstretch, JournalEvaluated, JournalFilm, MIN_FILM};
use super::method::{self, Given, Method};
use crate::calc::journal::dynamics::Coefficients;
use crate::calc::journal::film::Misalignment;
use crate::calc::journal::plain::{DynamicCoefficients, GeometrySpec, MisalignmentSpec};
use crate::calc::quantity::Positive;
use crate::calc::range_schemas;
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::effects::Mode;
use crate::fidelity::{FidelityRequest, Level, SolverReport};
use crate::numerics::roots::{secant_fallible, RootError, Stopping};

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
    /// Richardson-extrapolated; a grid whose Newton solves would outlast the request's deadline
    /// is refused at once (422 at `/fidelity/grid`, with the estimate).
    #[serde(default)]
    pub fidelity: FidelityRequest,
    /// Journal misalignment: the shaft's slope in the bearing and the plane it tilts in (the
    /// liquid journal room's object and conventions). The film is then solved over the whole
    /// length and the response gives its moment on the journal (`misalignment_moment`).
    pub misalignment: Option<MisalignmentSpec>,
    #[serde(default)]
    pub effects: GasJournalEffects,
    /// Include the pressure field over the half bearing (the whole length when misaligned;
    /// default false).
    #[serde(default)]
    #[schema(example = false)]
    pub include_field: bool,
    /// Ask for the film's frequency-dependent stiffness and damping and the rigid rotor's whirl
    /// threshold (`{}` for the defaults); absent: none computed.
    #[serde(default)]
    pub dynamics: Option<GasDynamicsRequest>,
}

/// Effects the gas journal understands.
#[derive(Debug, Clone, Copy, Default, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct GasJournalEffects {
    /// Rarefaction: first-order slip (Burgdorfer; Khonsari & Booser Eq. 11.10), the Poiseuille
    /// term's H³P becoming H³P(1 + 6Kn/(PH)) with Kn = λ_a/h_ref. `auto` applies it when the
    /// Knudsen number at the thinnest film, λ_a/h_min, exceeds 0.01 (§11.2: continuum flow
    /// below); a warning follows above 1, where the first-order form no longer holds.
    #[serde(default)]
    pub slip_flow: Mode,
    /// Journal misalignment (the whole-length film of a tilted journal, the liquid room's
    /// Khonsari & Booser Eq. 8.70 film; Ausman's moment, §11.5). `auto` and `on` apply the
    /// request's `misalignment` when it gives one (the journal is aligned otherwise, on the
    /// half length); `off` solves the aligned journal whatever `misalignment` gives.
    #[serde(default)]
    pub misalignment: Mode,
}

/// Most whirl frequency ratios a request may list.
pub const MAX_WHIRL_RATIOS: usize = 16;

/// Largest whirl frequency ratio ν/ω a request may list.
pub const MAX_WHIRL_RATIO: f64 = 100.0;

/// What the dynamics block should hold.
#[derive(Debug, Clone, Default, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct GasDynamicsRequest {
    /// Whirl frequency ratios: see [`range_schemas::whirl_frequency_ratios`].
    #[serde(default)]
    #[schema(schema_with = range_schemas::whirl_frequency_ratios)]
    pub whirl_frequency_ratios: Vec<f64>,
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
    /// The request's misalignment (ε′ = slope L/C and its direction), whatever the
    /// misalignment effect's mode ([`Case::tilt`]).
    pub misalignment: Option<Misalignment>,
    pub misalignment_mode: Mode,
    pub method: Method,
    pub include_field: bool,
    /// Whirl ratios besides the synchronous one, when dynamics are asked for.
    pub dynamics: Option<Vec<f64>>,
}

impl Case {
    pub fn radius_m(&self) -> f64 {
        0.5 * self.diameter_m
    }
    /// ω, rad/s.
    pub fn angular_speed(&self) -> f64 {
        self.speed_rpm * std::f64::consts::PI / 30.0
    }
    /// The misalignment the film is solved with: the request's, unless the effect is off.
    pub fn tilt(&self) -> Option<Misalignment> {
        self.misalignment
            .filter(|_| self.misalignment_mode != Mode::Off)
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
        let given = method::given(
            self.eccentricity_ratio,
            self.load_n,
            (MIN_ECCENTRICITY, MAX_ECCENTRICITY),
            "ε ≥ 1 puts the journal on the bearing",
            "the minimum film resolved by the grids; the attitude of a vanishing load below",
            &mut errors,
        );
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
        if let Some(d) = &self.dynamics {
            if d.whirl_frequency_ratios.len() > MAX_WHIRL_RATIOS {
                errors.push(FieldError::new(
                    "/dynamics/whirl_frequency_ratios",
                    format!(
                        "at most {MAX_WHIRL_RATIOS} ratios, got {}",
                        d.whirl_frequency_ratios.len()
                    ),
                ));
            }
            for (n, &r) in d.whirl_frequency_ratios.iter().enumerate() {
                if !(0.0..=MAX_WHIRL_RATIO).contains(&r) {
                    errors.push(FieldError::new(
                        format!("/dynamics/whirl_frequency_ratios/{n}"),
                        format!("a whirl frequency ratio ν/ω must be within [0, {MAX_WHIRL_RATIO}], got {r}"),
                    ));
                }
            }
        }
        let misalignment = self.misalignment.and_then(|m| m.parse(l, c, &mut errors));
        let gas = self.gas.parse_into("/gas", &mut errors);
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
            misalignment,
            misalignment_mode: self.effects.misalignment,
            method,
            include_field: self.include_field,
            dynamics: self.dynamics.map(|d| d.whirl_frequency_ratios),
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
    /// z/L from a bearing end (0) to the mid-plane (0.5), or on to the other end (1) when
    /// misaligned.
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
    /// h_min, m: C(1 − ε) when aligned; a misaligned journal's at its worse end.
    pub min_film_m: f64,
    /// Kn = λ_a/h_min, dimensionless.
    pub knudsen_number: f64,
    /// The film's moment on the journal when `misalignment` is given and applied (absent when
    /// aligned: it is then zero by symmetry).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub misalignment_moment: Option<GasFilmMoment>,
    /// The pressure field over the half bearing, or the whole length when misaligned (with
    /// `include_field`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pressure_field: Option<Vec<GasJournalFieldPoint>>,
    /// Stiffness, damping and the whirl threshold (with `dynamics`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dynamics: Option<GasJournalDynamics>,
}

/// The film's moment on a misaligned gas journal: Ausman's misalignment moment (Khonsari &
/// Booser §11.5, Fig. 11.15), from the whole-length film.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct GasFilmMoment {
    /// The frame: x along the static load, y 90° ahead of it in the direction of rotation, z
    /// along the journal's spin vector (x, y, z right-handed); the tilted journal's end at +z is
    /// the one displaced towards `misalignment.direction_deg`. The moment is the gauge
    /// pressure's (p − p_a), taken about the bearing centre (on the axis at mid-length).
    pub frame: String,
    /// Moment about x, N·m.
    pub mx_n_m: f64,
    /// Moment about y, N·m.
    pub my_n_m: f64,
    /// |M|, N·m.
    pub magnitude_n_m: f64,
    /// (M_x, M_y)/(p_a R L²), dimensionless.
    pub dimensionless: [f64; 2],
    /// M̄ = 12 C |M|/(π p_a R L³ β), β the slope (Khonsari & Booser's normalisation of
    /// Ausman's chart, Fig. 11.15: M = M̄ π p_a R L³ β/(12C)), dimensionless; it rises with Λ
    /// and tends to 1 as Λ → ∞ (small-ε linear theory). The chart is a small-ε perturbation
    /// result (ε ≤ 0.5); this is the full film's at the solved ε.
    pub moment_coefficient: f64,
    /// The moment's component against the tilt, N·m: −M·(z × u) for the tilt direction u (a
    /// tilt by the slope about z × u); positive when the film resists the misalignment.
    pub restoring_n_m: f64,
    /// Relative error estimate of |M| (the Richardson pair's difference over 3), dimensionless.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error_estimate: Option<f64>,
}

/// The film's dynamics about the solved equilibrium.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct GasJournalDynamics {
    /// At synchronous whirl, ν = ω (unbalance response).
    pub synchronous: GasFilmCoefficients,
    /// At the requested `whirl_frequency_ratios`, in their order.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub at_whirl_frequency_ratios: Vec<GasFilmCoefficients>,
    pub whirl_threshold: GasWhirlThreshold,
}

/// Stiffness and damping of the gas film at one whirl frequency ν. A gas film's coefficients
/// depend on ν: its squeeze number σ = 2Λ ν/ω grows with ν, and as σ → ∞ the gas cannot leak
/// in a cycle, so the film stiffens toward a trapped gas spring and its damping falls to 0.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct GasFilmCoefficients {
    /// ν/ω, dimensionless.
    pub whirl_frequency_ratio: f64,
    /// σ = 2Λ ν/ω (Khonsari & Booser Eq. 11.3's squeeze number in the journal's scaling),
    /// dimensionless.
    pub squeeze_number: f64,
    /// The frame, x along the static load and y 90° ahead in the direction of rotation; the
    /// film force on the journal for a displacement δ e^{iνt} is −(K + iνC)δ, K_ij and C_ij the
    /// real part and the imaginary part over ν of the film's impedance at ν. Dimensionless
    /// k = K C/W, c = C C ω/W (ω the journal speed), [xx, xy, yx, yy].
    pub coefficients: DynamicCoefficients,
    /// Relative error estimate (the Richardson pair's difference over 3, against the largest
    /// coefficient of each kind), dimensionless.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error_estimate: Option<f64>,
}

/// The rigid rotor's half-frequency whirl threshold on the film (Khonsari & Booser Fig. 11.16),
/// at this film's Λ and ε, with the coefficients taken at the whirl frequency itself.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct GasWhirlThreshold {
    /// M̄_c = m C ω²/W at the threshold: a rigid rotor of larger M̄ (per bearing) whirls;
    /// dimensionless; the smallest where the film's frequency-dependent coefficients give more
    /// than one crossing; absent when no whirl frequency in (0.01, 2)·ω exists (stable for any
    /// mass); 0 when no mass is stable.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub critical_mass_parameter: Option<f64>,
    /// ν/ω at the threshold (about ½: half-frequency whirl), dimensionless.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub whirl_frequency_ratio: Option<f64>,
    /// ω_T (C/g)^½ = M̄_c^½, dimensionless: Fig. 11.16's ordinate (a gravity-loaded rotor,
    /// m = W/g).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub threshold_speed_dimensionless: Option<f64>,
    /// ω_T = (M̄_c g/C)^½ for a gravity-loaded rotor (m = W/g), rad/s, with the film's Λ and ε
    /// held (as the chart is read).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub threshold_speed_rad_s: Option<f64>,
    /// ω_T in rev/min.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub threshold_speed_rpm: Option<f64>,
    /// The coefficients at the threshold's whirl frequency.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub coefficients: Option<GasFilmCoefficients>,
    /// M̄ = C ω²/g of a gravity-loaded rotor (m = W/g) at the request's speed, dimensionless.
    pub mass_parameter_at_speed: f64,
    /// Whether that rotor runs stably at the request's speed (M̄ < M̄_c).
    pub stable_at_speed: bool,
}

/// The film at the given load: a bracketed secant on ln(W̄/W̄_target) in the stretched s of
/// [`stretch`] over ε in [1e-4, 0.95]. The residual is nearly linear in s, so the secant lands in
/// a few film solves where Brent on W̄(ε) − W̄ took 10–12 (each solve is the film and its
/// Richardson half mesh); each film is solved by Newton from the last one's field (continuation in
/// Λ where that fails). A misaligned journal's search ends at ε = 0.95 − ε′/2, where its film
/// may reach [`MIN_FILM`] at an end whatever the attitude.
fn at_load(
    film: JournalFilm,
    tilt: Option<Misalignment>,
    target: f64,
    method: Method,
    budget: &crate::calc::Budget,
) -> Result<(JournalEvaluated, SolverReport), CalcError> {
    let last: RefCell<Option<JournalEvaluated>> = RefCell::new(None);
    let residual_at = |s: f64| -> Result<f64, CalcError> {
        let f = JournalFilm {
            eccentricity: unstretch(s),
            ..film
        };
        let warm = last.borrow().clone();
        let done = evaluate(&f, tilt, method, warm.as_ref(), budget)?;
        let w = done.performance.load();
        *last.borrow_mut() = Some(done);
        // A difference of logs: the smallest loads make W̄_target subnormal, and W̄/W̄_target
        // overflowed to an infinite residual (a 500; the edge fuzzer's find).
        Ok(w.ln() - target.ln())
    };
    let largest = match tilt {
        None => MAX_ECCENTRICITY,
        // The worst end's centre is ε + ε′/2 off (both at once when the tilt lies along the
        // line of centres); a hair inside, so that rounding does not refuse the bracket's end.
        Some(m) => (1.0 - MIN_FILM - 0.5 * m.tilt) * (1.0 - 1e-12),
    };
    if largest <= MIN_ECCENTRICITY {
        return Err(CalcError::impossible(
            "/misalignment",
            format!("the misaligned journal's film would fall below {MIN_FILM} C at an end even when centred: reduce the misalignment"),
        ));
    }
    let (s_lo, s_hi) = (stretch(MIN_ECCENTRICITY), stretch(largest));
    let hi = residual_at(s_hi)?;
    if hi < 0.0 {
        return Err(CalcError::impossible(
            "/load_n",
            format!(
                "the film carries at most W/(p_a L D) = {:.4} at ε = {largest:.4}{}; the load asks {target:.4}",
                target * hi.exp(),
                if tilt.is_some() { " (the misaligned journal's largest, its film at an end reaching the grids' smallest)" } else { "" }
            ),
        ));
    }
    let lo = residual_at(s_lo)?;
    let root = secant_fallible(
        residual_at,
        (s_lo, lo),
        (s_hi, hi),
        Stopping {
            // Δε = ε(1 − ε)Δs ≤ Δs/4: the old 1e-9 on ε or finer.
            x_tolerance: 4e-9,
            max_iterations: 60,
        },
    )?;
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

/// The film at `film`'s ε by `method`: aligned, or tilted by `tilt`
/// ([`journal_film::evaluate_tilted`]), from `warm` when given.
fn evaluate(
    film: &JournalFilm,
    tilt: Option<Misalignment>,
    method: Method,
    warm: Option<&JournalEvaluated>,
    budget: &crate::calc::Budget,
) -> Result<JournalEvaluated, CalcError> {
    match tilt {
        None => Ok(journal_film::evaluate(film, method, warm, budget)?),
        Some(m) => journal_film::evaluate_tilted(film, m, method, warm, budget),
    }
}

/// A film's coefficients on the wire: dimensionless as computed, in SI by W/C and W/(C ω).
fn wire_coefficients(
    e: &journal_dynamics::Evaluated,
    load_n: f64,
    clearance_m: f64,
    omega: f64,
) -> GasFilmCoefficients {
    let Coefficients {
        stiffness, damping, ..
    } = e.coefficients;
    let k = stiffness.map(|v| v * load_n / clearance_m);
    let c = damping.map(|v| v * load_n / (clearance_m * omega));
    GasFilmCoefficients {
        whirl_frequency_ratio: e.whirl_ratio,
        squeeze_number: e.squeeze_number,
        coefficients: DynamicCoefficients {
            frame: "x along the static load, y perpendicular, 90° ahead in the direction of rotation; a film force f_i = −K_ij δ_j − C_ij δ̇_j on the journal for harmonic motion at this frequency".into(),
            kxx: k[0],
            kxy: k[1],
            kyx: k[2],
            kyy: k[3],
            cxx: c[0],
            cxy: c[1],
            cyx: c[2],
            cyy: c[3],
            stiffness_dimensionless: stiffness,
            damping_dimensionless: damping,
            method: format!(
                "linearised compressible Reynolds about the converged film (harmonic perturbation, squeeze number 2Λν/ω; one complex solve with the steady Newton Jacobian per direction){}",
                if e.error_estimate.is_some() {
                    ", Richardson-extrapolated from the half mesh"
                } else {
                    ""
                }
            ),
        },
        error_estimate: e.error_estimate,
    }
}

/// The dynamics block: the coefficients at ν = ω and at the asked ratios, and the threshold.
fn dynamics(
    case: &Case,
    film: &JournalFilm,
    evaluated: &JournalEvaluated,
    ratios: &[f64],
    budget: &crate::calc::Budget,
) -> Result<GasJournalDynamics, CalcError> {
    let pa = case.gas.ambient_pressure_pa;
    let load_n = evaluated.performance.load() * pa * case.length_m * case.diameter_m;
    let (c, omega) = (case.clearance_m, case.angular_speed());
    let at = |ratio: f64| -> Result<GasFilmCoefficients, CalcError> {
        let e = journal_dynamics::evaluated(film, evaluated, ratio, budget)?;
        Ok(wire_coefficients(&e, load_n, c, omega))
    };
    let synchronous = at(1.0)?;
    let at_whirl_frequency_ratios = ratios.iter().map(|&r| at(r)).collect::<Result<_, _>>()?;
    let threshold = journal_dynamics::threshold(film, evaluated, budget)?;
    let mass_parameter_at_speed = c * omega * omega / STANDARD_GRAVITY;
    let critical = threshold.map(|t| t.critical_mass_parameter);
    let speed = critical.map(|m| (m * STANDARD_GRAVITY / c).sqrt());
    Ok(GasJournalDynamics {
        synchronous,
        at_whirl_frequency_ratios,
        whirl_threshold: GasWhirlThreshold {
            critical_mass_parameter: critical,
            whirl_frequency_ratio: threshold.map(|t| t.whirl_ratio),
            threshold_speed_dimensionless: critical.map(f64::sqrt),
            threshold_speed_rad_s: speed,
            threshold_speed_rpm: speed.map(|w| w * 30.0 / std::f64::consts::PI),
            coefficients: threshold.map(|t| wire_coefficients(&t.at, load_n, c, omega)),
            mass_parameter_at_speed,
            stable_at_speed: critical.is_none_or(|m| mass_parameter_at_speed < m),
        },
    })
}

impl Calculation for GasJournal {
    const PATH: &'static str = "/v1/gas-bearings/journal";
    const SUMMARY: &'static str =
        "Plain 360° gas journal bearing: compressible Reynolds by Newton, load or eccentricity, attitude, friction, peak pressure";
    const DESCRIPTION: &'static str = include_str!("journal.md");
    const FIDELITY: &'static [Level] = &[Level::Fast, Level::Standard, Level::High];
    const EFFECTS: &'static [&'static str] = &["slip_flow", "misalignment"];
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
            tilt: None,
        };
        let tilt = case.tilt();
        ctx.decide(
            "misalignment",
            Misalignment::decision(case.misalignment, case.misalignment_mode),
        );
        // Slip is decided on the thinnest film, C(1 − ε) when aligned. For a load, ε is not
        // known before the film is solved, nor a misaligned film's thinnest end before its
        // attitude is: `auto` solves the continuum film first, decides on its h_min, and solves
        // again with slip if that decides so.
        let budget = ctx.budget();
        let least = match case.given {
            Given::Eccentricity(_) => Least::one_film(film.bearing_number),
            Given::Load(_) => Least::JOURNAL_BY_LOAD,
        };
        // The whirl threshold's scan, the synchronous ratio and the asked ones, at least.
        let least = match &case.dynamics {
            Some(ratios) => {
                least.with_whirl_ratios(journal_dynamics::WHIRL_RATIO_SCAN.len() + 1 + ratios.len())
            }
            None => least,
        };
        let sized = JournalFilm {
            tilt: tilt.map(|_| (0.0, 0.0)),
            ..film
        };
        let grid = journal_film::grid(&sized, case.method.mesh);
        let far_edge = journal_film::problem(&sized, &grid).far_edge;
        cost::check(
            case.method,
            journal_film::level_mesh,
            (&grid, far_edge),
            least,
            &budget,
        )?;
        // `warm`: an earlier film at this ε (the continuum one, before slip is applied) to start
        // from; a load search starts afresh.
        let solve = |film: JournalFilm,
                     warm: Option<&JournalEvaluated>|
         -> Result<(JournalEvaluated, Option<SolverReport>), CalcError> {
            match case.given {
                Given::Eccentricity(e) => Ok((
                    evaluate(
                        &JournalFilm {
                            eccentricity: e,
                            ..film
                        },
                        tilt,
                        case.method,
                        warm,
                        &budget,
                    )?,
                    None,
                )),
                Given::Load(w) => {
                    let (done, report) = at_load(
                        film,
                        tilt,
                        w / (pa * l * case.diameter_m),
                        case.method,
                        &budget,
                    )?;
                    Ok((done, Some(report)))
                }
            }
        };
        // h_min of a solved film, m.
        let min_film = |done: &JournalEvaluated| {
            let solved = JournalFilm {
                eccentricity: done.eccentricity,
                tilt: done.tilt,
                ..film
            };
            c * solved.min_thickness()
        };
        let slip_film = JournalFilm {
            knudsen_number: case.gas.knudsen_number(c),
            ..film
        };
        let (evaluated, search, slip) = match (case.given, case.slip_flow) {
            (Given::Eccentricity(e), mode) if tilt.is_none() => {
                let slip = case.gas.slip_flow(mode, c * (1.0 - e));
                let (done, search) = solve(if slip.applied { slip_film } else { film }, None)?;
                (done, search, slip)
            }
            (_, Mode::On) => {
                let (done, search) = solve(slip_film, None)?;
                let slip = case.gas.slip_flow(Mode::On, min_film(&done));
                (done, search, slip)
            }
            (_, mode) => {
                let (done, search) = solve(film, None)?;
                let slip = case.gas.slip_flow(mode, min_film(&done));
                if slip.applied {
                    let (done, search) = solve(slip_film, Some(&done))?;
                    (done, search, slip)
                } else {
                    (done, search, slip)
                }
            }
        };
        film.eccentricity = evaluated.eccentricity;
        film.tilt = evaluated.tilt;
        ctx.decide("slip_flow", slip.clone());
        let e = film.eccentricity;
        let min_film_m = min_film(&evaluated);
        let knudsen_number = case.gas.knudsen_number(min_film_m);
        if slip.applied && knudsen_number > FIRST_ORDER_SLIP_LIMIT {
            ctx.warn(
                "slip_beyond_first_order",
                format!("Kn = {knudsen_number:.3} at the minimum film exceeds {FIRST_ORDER_SLIP_LIMIT}: the first-order slip form holds for Kn ≪ 1 only"),
            );
        }
        // The film as solved (with slip when applied), for its dynamics.
        let solved_film = JournalFilm {
            knudsen_number: if slip.applied {
                slip_film.knudsen_number
            } else {
                0.0
            },
            ..film
        };
        let dynamics = match &case.dynamics {
            Some(ratios) => Some(dynamics(&case, &solved_film, &evaluated, ratios, &budget)?),
            None => None,
        };
        let mut report = evaluated
            .fine
            .report
            .clone()
            .named(match (search.is_some(), tilt.is_some()) {
                (true, false) => "finite_volume_newton_fitted_flux_secant_load",
                (false, false) => "finite_volume_newton_fitted_flux",
                (true, true) => "finite_volume_newton_fitted_flux_whole_length_secant_load",
                (false, true) => "finite_volume_newton_fitted_flux_whole_length",
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
            min_film_m,
            knudsen_number,
            misalignment_moment: tilt.map(|m| {
                let scale = pa * r * l * l;
                let nd = p.moment_in_load_frame();
                let (mx, my) = (nd[0] * scale, nd[1] * scale);
                let magnitude = mx.hypot(my);
                GasFilmMoment {
                    frame: "x along the static load, y 90° ahead in the direction of rotation, z along the spin; the +z end of the journal is displaced towards the tilt direction; about the bearing centre".into(),
                    mx_n_m: mx,
                    my_n_m: my,
                    magnitude_n_m: magnitude,
                    dimensionless: nd,
                    // β = ε′ C/L: 12 C M/(π p_a R L³ β) = 12 M/(π p_a R L² ε′).
                    moment_coefficient: 12.0 * nd[0].hypot(nd[1]) / (PI * m.tilt),
                    restoring_n_m: m.restoring(p.attitude(), [mx, my]),
                    error_estimate: evaluated.moment_error_estimate,
                }
            }),
            pressure_field,
            dynamics,
        };
        let numbers = [
            out.bearing_number,
            out.load_n,
            out.attitude_angle_deg,
            out.friction_force_journal_n,
            out.friction_force_bearing_n,
            out.power_loss_w,
            out.max_pressure_pa,
            out.misalignment_moment.as_ref().map_or(0.0, |m| {
                m.magnitude_n_m + m.moment_coefficient + m.error_estimate.unwrap_or(0.0)
            }),
        ];
        CalcError::unless_finite(&numbers)?;
        Ok(out)
    }
}
