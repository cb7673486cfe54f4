//! `POST /v1/journal-bearings/whirl`: the oil-whirl threshold of a rigid rotor on a plain 360°
//! journal bearing — the threshold mass at a given speed, or the threshold speed of a given
//! mass — with the linearised stiffness and damping (model: `journal::threshold`).

use std::sync::Arc;

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::cost;
use super::dynamics::Coefficients;
use super::film::Mesh;
use super::finite_moving_film::{FiniteSqueezeFilm, ImpedanceTable, TableDensity};
use super::moving_film::{ShortArc, ShortFilm};
use super::orbit::OrbitFilm;
use super::performance::Method;
use super::plain::{grid_mesh, DynamicCoefficients, GeometrySpec};
use super::threshold::{Rotor, SpeedThreshold, WhirlFilm};
use super::whirl_confirm;
use crate::calc::lubricant::model::TemperatureLaw;
use crate::calc::lubricant::{validity, LubricantSpec};
use crate::calc::quantity::{Celsius, Positive};
use crate::calc::{Budget, CalcError, Calculation, Context, FieldError, Validate};
use crate::fidelity::{FidelityRequest, Level};

pub struct Whirl;

/// Temperature at which the viscosity is taken when none is given, °C (as `/plain`'s inlet).
const DEFAULT_TEMPERATURE_C: f64 = 40.0;
/// Load range, N (as `/plain`).
const LOAD_RANGE_N: (f64, f64) = (1e-6, 1e12);
/// Largest speed, rev/min (as `/plain`).
const MAX_SPEED_RPM: f64 = 1e6;
/// Largest rotor mass, kg.
const MAX_MASS_KG: f64 = 1e9;
/// The frame every coefficient is given in.
const FRAME: &str =
    "x along the static load, y perpendicular to it, 90° ahead in the direction of rotation";

/// The film whose linearised forces set the threshold.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum FilmModelChoice {
    /// Short (Ocvirk) bearing, half-Sommerfeld film whose ends move with the squeeze velocity
    /// (valid for L/D ≤ 1/2; closed form).
    ShortPiFilm,
    /// Short bearing, half-Sommerfeld film on the fixed arc [0, π] from h_max: the same
    /// linearised coefficients as `short_pi_film` (the film's drive vanishes at both ends of
    /// the arc at equilibrium, so their motion is second order).
    ShortFixedArc,
    /// Short bearing, full Sommerfeld film (no cavitation): its direct stiffnesses vanish and
    /// the rotor whirls at half speed for every mass — the answer is a threshold of 0.
    ShortFull,
    /// The finite bearing's Reynolds film with cavitation (the Reynolds condition), solved at
    /// `fidelity`; coefficients by perturbation of the converged film (default).
    #[default]
    Finite,
}

/// Request. Give `speed_rpm`, `journal_mass_kg`, or both.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct WhirlInput {
    pub geometry: GeometrySpec,
    pub lubricant: LubricantSpec,
    /// Oil film temperature, °C (−273 … 1000; default 40): the viscosity is taken here
    /// (isoviscous; a constant viscosity ignores it).
    #[schema(value_type = Option<f64>, minimum = -273.0, maximum = 1000.0, example = 40.0)]
    pub temperature_c: Option<Celsius>,
    /// Static load on this bearing W, N (1e-6 … 1e12).
    #[schema(value_type = f64, minimum = 1e-6, maximum = 1e12, example = 10000.0)]
    pub load_n: Positive,
    /// Journal speed, rev/min (> 0, at most 1e6): the threshold mass is found at it. With
    /// `journal_mass_kg` as well, the verdict and the margins.
    #[schema(value_type = Option<f64>, minimum = 1e-6, maximum = 1e6, example = 3000.0)]
    pub speed_rpm: Option<Positive>,
    /// Mass of the rigid rotor carried by this bearing, kg (1e-6 … 1e9): the threshold speed
    /// is found for it.
    #[schema(value_type = Option<f64>, minimum = 1e-6, maximum = 1e9, example = 1000.0)]
    pub journal_mass_kg: Option<Positive>,
    /// `short_pi_film`, `short_fixed_arc`, `short_full` or `finite` (default).
    #[serde(default)]
    pub film_model: FilmModelChoice,
    /// For `finite`: `fast`, `standard` (default), `high`, or `{"grid": [circumferential
    /// 16…1024 (even), half-length axial 2…256]}`; the short film models are closed forms and
    /// ignore it.
    #[serde(default)]
    pub fidelity: FidelityRequest,
    /// Confirm the threshold by simulation: the nonlinear orbit of rotors 0.8 and 1.25 times
    /// the threshold mass, disturbed from equilibrium, with their measured growth rates beside
    /// the eigenvalues' (short π film, fixed arc, or the finite film through its impedance
    /// table at the request's fidelity; the full film has no threshold; default false).
    #[serde(default)]
    #[schema(example = false)]
    pub confirm: bool,
}

/// The film a confirmation's orbits run on.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ConfirmFilm {
    /// The short film's closed forms on this arc.
    Short(ShortArc),
    /// The finite film's impedance table on the rotor's mesh.
    Finite { mesh: Mesh, density: TableDensity },
}

impl ConfirmFilm {
    /// The orbit's film for a bearing of `l_over_d` (the finite film's table is built here).
    fn orbit_film(self, l_over_d: f64, budget: &Budget) -> Result<OrbitFilm, CalcError> {
        Ok(match self {
            ConfirmFilm::Short(arc) => OrbitFilm::Short(ShortFilm {
                arc,
                speed_sum: 1.0,
            }),
            ConfirmFilm::Finite { mesh, density } => OrbitFilm::Finite {
                table: Arc::new(ImpedanceTable::build(
                    FiniteSqueezeFilm { l_over_d, mesh },
                    density,
                    budget,
                )?),
                speed_sum: 1.0,
            },
        })
    }
}

/// The validated request.
#[derive(Debug, Clone)]
pub struct WhirlCase {
    pub rotor: Rotor,
    pub speed_rpm: Option<f64>,
    pub mass_kg: Option<f64>,
    /// Simulate the orbit on this film below and above the threshold.
    pub confirm: Option<ConfirmFilm>,
    /// The lubricant's parsing assumptions and validity warnings.
    pub assumptions: Vec<(&'static str, String)>,
}

impl Validate for WhirlInput {
    type Valid = WhirlCase;
    fn validate(self) -> Result<WhirlCase, Vec<FieldError>> {
        let mut errors = Vec::new();
        let (d, l, c) = self.geometry.check(&mut errors);
        let w = self.load_n.get();
        if !(LOAD_RANGE_N.0..=LOAD_RANGE_N.1).contains(&w) {
            errors.push(FieldError::new(
                "/load_n",
                format!("must be within [1e-6, 1e12] N, got {w}"),
            ));
        }
        let speed = self.speed_rpm.map(Positive::get);
        // As /plain: below 1e-6 rev/min S underflows (schemathesis's 5e-324 rev/min was a 500).
        if speed.is_some_and(|n| !(1e-6..=MAX_SPEED_RPM).contains(&n)) {
            errors.push(FieldError::new(
                "/speed_rpm",
                "must be within [1e-6, 1e6] rev/min",
            ));
        }
        let mass = self.journal_mass_kg.map(Positive::get);
        // A subnormal mass sent the threshold-speed search past the deadline (schemathesis's
        // 5e-324 kg): masses below 1e-6 kg are no rotor.
        if mass.is_some_and(|m| !(1e-6..=MAX_MASS_KG).contains(&m)) {
            errors.push(FieldError::new(
                "/journal_mass_kg",
                format!("must be within [1e-6, {MAX_MASS_KG:e}] kg"),
            ));
        }
        if speed.is_none() && mass.is_none() {
            errors.push(FieldError::new(
                "/speed_rpm",
                "give speed_rpm (for the threshold mass), journal_mass_kg (for the threshold speed), or both (for the verdict)",
            ));
        }
        let mut assumptions = Vec::new();
        let viscosity = match self.lubricant.parse("/lubricant") {
            Ok(lubricant) => {
                let t = self
                    .temperature_c
                    .map_or(DEFAULT_TEMPERATURE_C, Celsius::get);
                let vogel_pole = match lubricant.temperature_law {
                    TemperatureLaw::Vogel { c, .. } => Some(c - 273.15),
                    _ => None,
                };
                let mu = lubricant.viscosity_pa_s(t);
                if vogel_pole.is_some_and(|pole| t <= pole + 1.0) || !(mu.is_finite() && mu > 0.0) {
                    errors.push(FieldError::new(
                        "/temperature_c",
                        format!("the lubricant's viscosity law has no value at {t} °C"),
                    ));
                    None
                } else {
                    assumptions.extend(lubricant.assumptions);
                    assumptions.extend(validity::hot_oil("the oil", t));
                    Some(mu)
                }
            }
            Err(mut e) => {
                errors.append(&mut e);
                None
            }
        };
        let film = match self.film_model {
            FilmModelChoice::ShortPiFilm => Some(WhirlFilm::ShortPiFilm),
            FilmModelChoice::ShortFixedArc => Some(WhirlFilm::ShortFixedArc),
            FilmModelChoice::ShortFull => Some(WhirlFilm::ShortFull),
            FilmModelChoice::Finite => match self.fidelity {
                FidelityRequest::Level(Level::ClosedForm) => {
                    errors.push(FieldError::new(
                        "/fidelity",
                        "the finite film is numerical: use fast, standard, high or a grid; for a closed form choose film_model short_pi_film, short_fixed_arc or short_full",
                    ));
                    None
                }
                FidelityRequest::Level(level) => {
                    Some(WhirlFilm::Finite(Method::numerical(level, None, None)))
                }
                FidelityRequest::Custom(custom) => {
                    let mesh = grid_mesh(custom.grid, &mut errors);
                    if let Some(t) = custom.tolerance {
                        if !(1e-14..=1e-3).contains(&t) {
                            errors.push(FieldError::new(
                                "/fidelity/tolerance",
                                "must be within [1e-14, 1e-3]",
                            ));
                        }
                    }
                    Some(WhirlFilm::Finite(Method::numerical(
                        Level::Standard,
                        mesh,
                        custom.tolerance,
                    )))
                }
            },
        };
        let confirm = match (self.confirm, film) {
            (false, _) | (true, None) => None,
            (true, Some(WhirlFilm::ShortPiFilm)) => Some(ConfirmFilm::Short(ShortArc::PiFilm)),
            (true, Some(WhirlFilm::ShortFixedArc)) => Some(ConfirmFilm::Short(ShortArc::FixedArc)),
            (true, Some(WhirlFilm::Finite(Method::Numerical { level, mesh, .. }))) => {
                Some(ConfirmFilm::Finite {
                    mesh,
                    density: TableDensity::at(level),
                })
            }
            (true, Some(WhirlFilm::Finite(Method::ClosedForm(_)))) => None,
            (true, Some(WhirlFilm::ShortFull)) => {
                errors.push(FieldError::new(
                    "/confirm",
                    "the full film has no threshold to confirm (a rotor of any mass whirls on it): choose film_model finite, short_pi_film or short_fixed_arc",
                ));
                None
            }
        };
        match (errors.is_empty(), viscosity, film) {
            (true, Some(viscosity_pa_s), Some(film)) => Ok(WhirlCase {
                rotor: Rotor {
                    diameter_m: d,
                    length_m: l,
                    radial_clearance_m: c,
                    viscosity_pa_s,
                    load_n: w,
                    film,
                },
                speed_rpm: speed,
                mass_kg: mass,
                confirm,
                assumptions,
            }),
            _ => Err(errors),
        }
    }
}

/// Result. The threshold is Lund's rigid-rotor one (Routh–Hurwitz of m ẍ + C ẋ + K x = 0).
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct WhirlOutput {
    /// The film model used.
    #[schema(example = "finite")]
    pub film_model: String,
    /// Static load on this bearing, N.
    pub load_n: f64,
    /// Given a speed: the rotor mass on this bearing at which it starts to whirl at that
    /// speed, kg (lighter is stable); 0 for `short_full` (no mass is stable); absent when no
    /// mass whirls at this speed (the film is stable for any mass: see `statement`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub threshold_mass_kg: Option<f64>,
    /// Given a mass: the speed above which it whirls, rev/min, holding load and viscosity;
    /// 0 for `short_full` (it whirls at every speed); absent when the locus holds no threshold
    /// (see `statement`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub threshold_speed_rpm: Option<f64>,
    /// ε = e/C at the threshold, dimensionless: the operating point's when a speed is given
    /// (the threshold mass is at that speed), else the threshold speed's.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub eccentricity_ratio_at_threshold: Option<f64>,
    /// Whirl frequency over running speed at the threshold, dimensionless (→ 0.5 for a lightly
    /// loaded bearing; exactly 0.5 for `short_full`); absent when the film cannot whirl.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub whirl_frequency_ratio: Option<f64>,
    /// Lund's critical mass parameter M̄_c = m C ω²/W at the threshold, dimensionless; absent
    /// when the film is stable for any mass.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub critical_mass_parameter: Option<f64>,
    /// Given a speed: the equilibrium eccentricity ratio there, dimensionless.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub eccentricity_ratio: Option<f64>,
    /// Given a speed: the attitude angle there, from the load line to the line of centres in
    /// the direction of rotation, degrees.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub attitude_angle_deg: Option<f64>,
    /// Given a speed: S = μ N_s L D (R/C)²/W, dimensionless (N_s in rev/s).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sommerfeld_number: Option<f64>,
    /// Given a speed: h_min = C (1 − ε), m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub min_film_thickness_m: Option<f64>,
    /// Given both: whether the rotor runs stably (every eigenvalue of its 4×4 linearised
    /// system decays).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stable: Option<bool>,
    /// Given both: the rotor's mass parameter M̄ = m C ω²/W at the speed, dimensionless (Khonsari
    /// & Booser's (C/W) M ω²; it whirls when M̄ exceeds `critical_mass_parameter`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mass_parameter: Option<f64>,
    /// Given both: threshold mass over the rotor's mass, dimensionless (> 1: stable); absent
    /// when no mass whirls at this speed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mass_margin: Option<f64>,
    /// Given both: threshold speed over the speed, dimensionless (> 1: stable); absent without
    /// a threshold speed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub speed_margin: Option<f64>,
    /// Given both: the growth rate of the least damped mode of the linearised system, 1/s
    /// (negative: a disturbance decays as e^(rate·t)).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub growth_rate_per_s: Option<f64>,
    /// Given both: that mode's frequency over the running speed, dimensionless.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mode_frequency_ratio: Option<f64>,
    /// With `confirm`: the simulated rotors just below and just above the threshold mass (at
    /// the operating speed, or at the threshold speed when only a mass is given).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub confirmation: Option<WhirlConfirmation>,
    /// Stiffness and damping: at the operating point when a speed is given, else at the
    /// threshold speed (absent when there is none).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub coefficients: Option<DynamicCoefficients>,
    /// The verdict in words.
    pub statement: String,
}

impl Calculation for Whirl {
    const PATH: &'static str = "/v1/journal-bearings/whirl";
    const SUMMARY: &'static str =
        "Oil whirl of a rigid rotor on a plain journal bearing: threshold mass or speed, K and C";
    const DESCRIPTION: &'static str = include_str!("whirl.md");
    const FIDELITY: &'static [Level] = &[Level::Fast, Level::Standard, Level::High];
    const EFFECTS: &'static [&'static str] = &[];
    const EXAMPLE: &'static str = r#"{"geometry": {"diameter_m": 0.1, "length_m": 0.05, "radial_clearance_m": 0.0001}, "lubricant": {"iso_vg": 32}, "temperature_c": 50, "load_n": 2000, "speed_rpm": 6000, "journal_mass_kg": 150, "film_model": "finite", "fidelity": "fast"}"#;

    type Input = WhirlInput;
    type Output = WhirlOutput;

    fn run(case: WhirlCase, ctx: &mut Context) -> Result<WhirlOutput, CalcError> {
        for (code, message) in &case.assumptions {
            ctx.warn(code, message.clone());
        }
        let budget = ctx.budget();
        let solves_before = budget.field_solves();
        let rotor = case.rotor;
        // A finite film's grid the deadline cannot pay for is refused before any solve (every
        // question here starts with an equilibrium search).
        cost::check_affordable(rotor.film.method(), &rotor.film.physics(), true, &budget)?;
        let mut evaluations = 0;
        let at_speed = match case.speed_rpm {
            Some(n) => {
                let (at, k) = rotor.at_speed(n, &budget)?;
                evaluations += k + 1;
                Some(at)
            }
            None => None,
        };
        let by_mass = match case.mass_kg {
            Some(m) => {
                let (t, k) = rotor.threshold_speed(m, &budget)?;
                evaluations += k;
                Some(t)
            }
            None => None,
        };
        ctx.report(rotor.report(evaluations, budget.field_solves() - solves_before));
        let film_model = match rotor.film {
            WhirlFilm::ShortPiFilm => "short_pi_film",
            WhirlFilm::ShortFixedArc => "short_fixed_arc",
            WhirlFilm::ShortFull => "short_full",
            WhirlFilm::Finite(_) => "finite",
        };
        let method = match rotor.film {
            WhirlFilm::Finite(_) => "perturbation of the converged Reynolds film: ±δ displacement and ±δ̇ velocity along each axis, the linear response of the cavitating film",
            WhirlFilm::ShortFull => "closed form of the short (Ocvirk) bearing with the full Sommerfeld film",
            _ => "closed form of the short (Ocvirk) bearing with the half-Sommerfeld film (the π film and the fixed arc share it)",
        };
        let block = |c: &Coefficients, speed_rpm: f64| {
            let (k, d) = rotor.dimensional(c, speed_rpm);
            DynamicCoefficients {
                frame: FRAME.into(),
                kxx: k[0],
                kxy: k[1],
                kyx: k[2],
                kyy: k[3],
                cxx: d[0],
                cxy: d[1],
                cyx: d[2],
                cyy: d[3],
                stiffness_dimensionless: c.stiffness,
                damping_dimensionless: c.damping,
                method: method.into(),
            }
        };
        let mut out = WhirlOutput {
            film_model: film_model.into(),
            load_n: rotor.load_n,
            threshold_mass_kg: None,
            threshold_speed_rpm: None,
            eccentricity_ratio_at_threshold: None,
            whirl_frequency_ratio: None,
            critical_mass_parameter: None,
            eccentricity_ratio: None,
            attitude_angle_deg: None,
            sommerfeld_number: None,
            min_film_thickness_m: None,
            stable: None,
            mass_parameter: None,
            mass_margin: None,
            speed_margin: None,
            growth_rate_per_s: None,
            mode_frequency_ratio: None,
            coefficients: None,
            confirmation: None,
            statement: String::new(),
        };
        let mut statements = Vec::new();
        if let Some(at) = &at_speed {
            let s = &at.state;
            out.threshold_mass_kg = at.threshold_mass_kg;
            out.eccentricity_ratio_at_threshold = Some(s.eccentricity_ratio);
            out.whirl_frequency_ratio = s.whirl.whirl_frequency_ratio;
            out.critical_mass_parameter = s.whirl.critical_mass_parameter;
            out.eccentricity_ratio = Some(s.eccentricity_ratio);
            out.attitude_angle_deg = s.attitude_angle_rad.map(f64::to_degrees);
            out.sommerfeld_number = Some(s.coefficients.sommerfeld_number);
            out.min_film_thickness_m =
                Some(rotor.radial_clearance_m * (1.0 - s.eccentricity_ratio));
            out.coefficients = Some(block(&s.coefficients, s.speed_rpm));
            statements.push(match at.threshold_mass_kg {
                Some(m) if m > 0.0 => format!(
                    "at {:.0} rev/min (ε = {:.4}) a rigid rotor heavier than {} kg on this bearing whirls at {:.3} × running speed",
                    s.speed_rpm,
                    s.eccentricity_ratio,
                    readable(m),
                    s.whirl.whirl_frequency_ratio.unwrap_or(f64::NAN)
                ),
                Some(_) => format!(
                    "at {:.0} rev/min every rotor mass whirls: the full film has no direct stiffness",
                    s.speed_rpm
                ),
                None => format!(
                    "at {:.0} rev/min (ε = {:.4}) the film is stable for any rotor mass",
                    s.speed_rpm, s.eccentricity_ratio
                ),
            });
        }
        if let Some(t) = by_mass {
            let mass = case.mass_kg.unwrap_or(f64::NAN);
            match t {
                SpeedThreshold::Found(s) => {
                    out.threshold_speed_rpm = Some(s.speed_rpm);
                    if at_speed.is_none() {
                        out.eccentricity_ratio_at_threshold = Some(s.eccentricity_ratio);
                        out.whirl_frequency_ratio = s.whirl.whirl_frequency_ratio;
                        out.critical_mass_parameter = s.whirl.critical_mass_parameter;
                        out.coefficients = Some(block(&s.coefficients, s.speed_rpm));
                    }
                    statements.push(format!(
                        "a rigid rotor of {} kg on this bearing runs stably below {:.0} rev/min and whirls above it (ε = {:.4} there)",
                        readable(mass),
                        s.speed_rpm,
                        s.eccentricity_ratio
                    ));
                }
                SpeedThreshold::EverySpeed => {
                    out.threshold_speed_rpm = Some(0.0);
                    if at_speed.is_none() {
                        out.whirl_frequency_ratio = Some(0.5);
                    }
                    statements.push(format!(
                        "a rigid rotor of {mass} kg whirls at every speed on the full film"
                    ));
                }
                SpeedThreshold::StableUpTo(n) => {
                    ctx.warn(
                        "no_threshold_in_range",
                        format!("no whirl threshold up to {n:.4e} rev/min, the speed of the lightest eccentricity the model follows (ε = {:.0e})", if matches!(rotor.film, WhirlFilm::Finite(_)) { 1e-3 } else { 1e-4 }),
                    );
                    statements.push(format!(
                        "a rigid rotor of {mass} kg is stable at every speed up to at least {n:.4e} rev/min"
                    ));
                }
                SpeedThreshold::UnstableDownTo(n) => {
                    ctx.warn(
                        "no_stable_speed_in_range",
                        format!(
                            "the rotor whirls at every speed down to {n:.4e} rev/min (ε = 0.999)"
                        ),
                    );
                    statements.push(format!(
                        "a rigid rotor of {mass} kg whirls at every speed down to {n:.4e} rev/min"
                    ));
                }
            }
        }
        if let (Some(at), Some(mass)) = (&at_speed, case.mass_kg) {
            let v = rotor.verdict(&at.state, mass);
            // At k_eq = 0 (the full film) the eigenvalue of a light rotor is within rounding of
            // the axis: the threshold of 0 decides.
            let stable = match at.threshold_mass_kg {
                Some(0.0) => false,
                _ => v.stable,
            };
            out.stable = Some(stable);
            out.mass_parameter = Some(rotor.mass_parameter(mass, at.state.speed_rpm));
            out.mass_margin = at.threshold_mass_kg.map(|m| m / mass);
            out.speed_margin = out
                .threshold_speed_rpm
                .map(|n| n / at.state.speed_rpm)
                .filter(|r| r.is_finite());
            out.growth_rate_per_s = Some(v.growth_rate_per_s);
            out.mode_frequency_ratio = Some(v.frequency_ratio);
            statements.insert(
                0,
                format!(
                    "{} at {:.0} rev/min",
                    if stable {
                        "STABLE"
                    } else {
                        "UNSTABLE (oil whirl)"
                    },
                    at.state.speed_rpm
                ),
            );
            if !stable {
                ctx.warn(
                    "oil_whirl",
                    format!(
                        "the rotor of {mass} kg whirls at {:.0} rev/min",
                        at.state.speed_rpm
                    ),
                );
            }
        }
        if rotor.film == WhirlFilm::ShortFull {
            ctx.warn(
                "whirls_at_every_speed",
                "the full (Sommerfeld) film has no direct stiffness: Lund's equivalent stiffness is 0 and a rotor of any mass whirls at half speed at every speed; the threshold is 0",
            );
        }
        if let Some(confirm) = case.confirm {
            // The threshold to confirm: the mass at the speed, or the speed of the mass.
            let around = match (&at_speed, &by_mass) {
                (Some(at), _) => at.threshold_mass_kg.map(|m| (at.state, m)),
                (None, Some(SpeedThreshold::Found(s))) => case.mass_kg.map(|m| (*s, m)),
                _ => None,
            };
            match around {
                Some((state, threshold)) if threshold > 0.0 => {
                    let film = confirm.orbit_film(rotor.l_over_d(), &budget)?;
                    let [below, above] =
                        whirl_confirm::confirm(&rotor, &film, &state, threshold, &budget)?;
                    let agrees = below.simulated_growth_rate_per_s < 0.0
                        && above.simulated_growth_rate_per_s > 0.0;
                    statements.push(format!(
                        "simulated at {:.0} rev/min: a rotor of {} kg settles (growth {:.4} 1/s, eigenvalue {:.4}) and one of {} kg whirls (growth {:.4} 1/s, eigenvalue {:.4}){}",
                        state.speed_rpm,
                        readable(below.mass_kg),
                        below.simulated_growth_rate_per_s,
                        below.linear_growth_rate_per_s,
                        readable(above.mass_kg),
                        above.simulated_growth_rate_per_s,
                        above.linear_growth_rate_per_s,
                        if agrees { "" } else { " — NOT as the linearised threshold says" },
                    ));
                    out.confirmation = Some(WhirlConfirmation {
                        speed_rpm: state.speed_rpm,
                        threshold_mass_kg: threshold,
                        below: below.into(),
                        above: above.into(),
                        agrees,
                    });
                }
                _ => ctx.warn(
                    "nothing_to_confirm",
                    "confirm: there is no threshold mass here to simulate around (the film is stable for any mass, or no threshold speed was found)",
                ),
            }
        }
        out.statement = statements.join("; ");
        CalcError::finite_or_out_of_range(out, "load_n, speed_rpm and journal_mass_kg")
    }
}

/// The threshold confirmed by simulation.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct WhirlConfirmation {
    /// The speed simulated at, rev/min.
    pub speed_rpm: f64,
    /// The linearised threshold mass there, kg.
    pub threshold_mass_kg: f64,
    /// The rotor 0.8 times the threshold mass.
    pub below: SimulatedRotor,
    /// The rotor 1.25 times the threshold mass.
    pub above: SimulatedRotor,
    /// Whether the lighter rotor's disturbance decays and the heavier one's grows.
    pub agrees: bool,
}

/// One simulated rotor: the orbit from its equilibrium displaced by 10⁻³(1 − ε)C.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct SimulatedRotor {
    /// Rotor mass on this bearing, kg.
    pub mass_kg: f64,
    /// The growth rate of the least damped mode of the linearised system, 1/s.
    pub linear_growth_rate_per_s: f64,
    /// The growth rate measured on the simulated orbit (peaks of the distance from
    /// equilibrium, fitted), 1/s.
    pub simulated_growth_rate_per_s: f64,
    /// The time simulated, s.
    pub simulated_time_s: f64,
}

impl From<whirl_confirm::Simulated> for SimulatedRotor {
    fn from(s: whirl_confirm::Simulated) -> Self {
        SimulatedRotor {
            mass_kg: s.mass_kg,
            linear_growth_rate_per_s: s.linear_growth_rate_per_s,
            simulated_growth_rate_per_s: s.simulated_growth_rate_per_s,
            simulated_time_s: s.simulated_time_s,
        }
    }
}

/// A number for a sentence: four decimals from 1 up, four significant digits below.
fn readable(x: f64) -> String {
    if x.abs() >= 1.0 {
        format!("{x:.4}")
    } else {
        format!("{x:.4e}")
    }
}

#[cfg(test)]
mod tests;
