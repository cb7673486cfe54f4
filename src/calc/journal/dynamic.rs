//! `POST /v1/journal-bearings/dynamic`: the orbit of a dynamically loaded journal (Harnoy
//! §18.5; Booker's short-bearing squeeze vector). This file is the wire (request, validation,
//! response); the physics is [`super::moving_film`], [`super::load_law`] and [`super::orbit`].

use std::f64::consts::PI;

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use std::sync::Arc;

use super::cost;
use super::film::Mesh;
use super::finite_moving_film::{
    FiniteSqueezeFilm, ImpedanceTable, TableDensity, TOP as FINITE_TOP,
};
use super::load_law::{Engine, LoadLaw};
use super::moving_film::{squeeze_vector, ShortArc, ShortFilm};
use super::orbit::{self, OrbitError, OrbitFilm, Problem, Scales, Start, Until};
use super::performance::Method;
use super::plain::{grid_mesh, GeometrySpec};
use crate::calc::lubricant::isoviscous::{self, Viscosity};
use crate::calc::lubricant::LubricantSpec;
use crate::calc::quantity::{Celsius, NonNegative, Positive};
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::fidelity::{FidelityRequest, Level};
use crate::numerics::driver::Stopped;
use crate::numerics::roots::{brent, Stopping};

pub struct DynamicJournal;

/// Largest load magnitude, N.
const MAX_LOAD_N: f64 = 1e9;
/// Largest speed and frequency ratios of a load.
const MAX_RATIO: f64 = 100.0;
/// Largest journal mass, kg.
const MAX_MASS_KG: f64 = 1e6;
/// The longest run, in journal revolutions, and so the longest load period (a steady orbit
/// integrates whole periods; a slower load is quasi-static): at least 50 time steps a
/// revolution, up to 200 on a whirling film at `high`, keep it within a few seconds.
const MAX_REVOLUTIONS: f64 = 2_000.0;
/// Load periods a steady orbit may take to settle.
const MAX_PERIODS: u32 = 400;
/// The largest target eccentricity ratio.
const MAX_TARGET: f64 = 0.999;
/// Points of the sampled orbit.
const ORBIT_POINTS: usize = 181;

/// The film model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum DynamicFilmModel {
    /// Dynamic half-Sommerfeld short bearing: the π-wide arc centred on the squeeze vector.
    #[default]
    ShortPiFilm,
    /// The fixed arc [0, π] from the maximum film (Harnoy's book mode).
    ShortFixedArc,
    /// The full 360° short film, negative pressures kept.
    ShortFull,
    /// The finite bearing: the journal room's Reynolds solver with cavitation (p ≥ 0) on its
    /// grid at the request's fidelity, tabulated once per request as the squeeze film's
    /// impedance and interpolated at every step.
    Finite,
}

/// One point of a tabulated load period.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct LoadPoint {
    /// Journal rotation angle within the period, degrees (ascending, from 0 to below the period).
    #[schema(minimum = 0.0, exclusive_maximum = 36000.0)]
    pub angle_deg: f64,
    /// Force on the journal along x, N (|F| ≤ 1e9).
    #[schema(minimum = -1e9, maximum = 1e9)]
    pub force_x_n: f64,
    /// Force on the journal along y (up), N (|F| ≤ 1e9).
    #[schema(minimum = -1e9, maximum = 1e9)]
    pub force_y_n: f64,
}

/// One point of an engine's cylinder pressure.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct PressurePoint {
    /// Crank angle from top dead centre, degrees (ascending within the cycle).
    #[schema(minimum = 0.0, exclusive_maximum = 720.0)]
    pub crank_angle_deg: f64,
    /// Cylinder pressure above the crankcase's, Pa (−1e5 … 1e9: no lower than a vacuum).
    #[schema(minimum = -1e5, maximum = 1e9)]
    pub pressure_pa: f64,
}

/// The load on the journal.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum DynamicLoadSpec {
    /// A fixed force.
    Constant {
        /// N (0 … 1e9).
        #[schema(minimum = 0.0, maximum = 1e9)]
        magnitude_n: f64,
        /// Where the force on the journal points, degrees from +x (−90 = down).
        #[schema(minimum = -3600.0, maximum = 3600.0)]
        direction_deg: f64,
    },
    /// A force of fixed magnitude turning at `speed_ratio` times the journal speed (1:
    /// unbalance; 0.5: the half-speed load no film can carry).
    Rotating {
        /// N (0 … 1e9).
        #[schema(minimum = 0.0, maximum = 1e9)]
        magnitude_n: f64,
        /// Load speed over journal speed (−100 … 100; negative turns against the journal): 0 (a
        /// fixed direction) or at least 5e-4 in magnitude (one turn of the load within 2 000
        /// revolutions; the composite orbit's at least 0.01).
        #[schema(minimum = -100.0, maximum = 100.0)]
        speed_ratio: f64,
        /// Direction at time 0, degrees from +x.
        #[schema(minimum = -3600.0, maximum = 3600.0)]
        direction_at_start_deg: f64,
    },
    /// F = F_s + F_o sin(α ω t) along a fixed direction (Harnoy Eq. 18-35).
    Sinusoidal {
        /// F_s, N.
        #[schema(minimum = -1e9, maximum = 1e9)]
        static_n: f64,
        /// F_o, N.
        #[schema(minimum = -1e9, maximum = 1e9)]
        amplitude_n: f64,
        /// α, the load frequency over the journal's (5e-4 … 100: one load period within 2 000
        /// revolutions, a slower load being quasi-static; the composite orbit's at least 0.01).
        #[schema(minimum = 5e-4, maximum = 100.0)]
        frequency_ratio: f64,
        /// Degrees from +x (−90 = down).
        #[schema(minimum = -3600.0, maximum = 3600.0)]
        direction_deg: f64,
    },
    /// One period of tabulated force, interpolated by a periodic cubic (C¹).
    Table {
        /// At least 3 points, angles ascending within [0, period_deg).
        points: Vec<LoadPoint>,
        /// The period in journal rotation, degrees (default 360; 720 for a four-stroke cycle).
        #[schema(minimum = 1.0, maximum = 36000.0)]
        period_deg: Option<f64>,
    },
    /// A single-cylinder slider-crank on its main bearing.
    Engine {
        /// Cylinder bore, m.
        #[schema(minimum = 1e-3, maximum = 5.0)]
        bore_m: f64,
        /// Crank radius (half the stroke), m.
        #[schema(minimum = 1e-3, maximum = 5.0)]
        crank_radius_m: f64,
        /// Connecting-rod length (centre to centre), m; longer than the crank radius.
        #[schema(exclusive_minimum = 1.2e-3, maximum = 20.0)]
        rod_length_m: f64,
        /// Reciprocating mass (piston, pin, rings, the rod's small-end share), kg.
        #[schema(minimum = 0.0, maximum = 1e5)]
        reciprocating_mass_kg: f64,
        /// Cylinder pressure over the cycle (at least 3 points, crank angles ascending within
        /// [0, cycle_deg)), periodic cubic between them.
        cylinder_pressure: Vec<PressurePoint>,
        /// Degrees of crank angle per cycle: 720 (four-stroke, default) or 360 (two-stroke).
        #[schema(minimum = 360.0, maximum = 720.0)]
        cycle_deg: Option<f64>,
    },
}

/// A named initial state.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum InitialStateName {
    /// At the bearing centre, at rest.
    Centre,
    /// At the static equilibrium under the load at time 0, at rest.
    Equilibrium,
}

/// A given initial position and velocity of the journal centre.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct GivenState {
    /// Journal centre from the bearing centre along x, m (inside 0.999 C).
    #[schema(minimum = -1.0, maximum = 1.0, example = 0.0)]
    pub x_m: f64,
    /// Along y (up), m.
    #[schema(minimum = -1.0, maximum = 1.0, example = -5e-5)]
    pub y_m: f64,
    /// Velocity of the centre along x, m/s (at most 1000 C ω in size).
    #[schema(minimum = -1e4, maximum = 1e4, example = 0.0)]
    pub velocity_x_m_s: f64,
    /// Along y, m/s.
    #[schema(minimum = -1e4, maximum = 1e4, example = 0.0)]
    pub velocity_y_m_s: f64,
}

/// `"centre"`, `"equilibrium"` (default) or a given state.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(untagged)]
pub enum InitialState {
    Named(InitialStateName),
    Given(GivenState),
}

/// The named end of a run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum UntilName {
    /// Until one load period maps onto itself (at most 400 periods).
    SteadyOrbit,
}

/// A run for a set time.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct UntilTime {
    /// s (> 0, at most 2 000 journal revolutions).
    #[schema(exclusive_minimum = 0.0, maximum = 1e13)]
    pub time_s: f64,
}

/// A run until an eccentricity ratio is reached.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct UntilEccentricity {
    /// (0, 0.999]; the run also stops when the orbit settles below it (it never will).
    #[schema(exclusive_minimum = 0.0, maximum = 0.999)]
    pub eccentricity_ratio: f64,
}

/// `"steady_orbit"` (default), `{"time_s": t}` or `{"eccentricity_ratio": e}`.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(untagged)]
pub enum UntilSpec {
    Named(UntilName),
    Time(UntilTime),
    Eccentricity(UntilEccentricity),
}

/// Request.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct DynamicJournalInput {
    pub geometry: GeometrySpec,
    pub lubricant: LubricantSpec,
    /// Film temperature, °C: where the viscosity is taken; required unless the lubricant has a
    /// constant `viscosity_pa_s`.
    #[schema(value_type = Option<f64>, minimum = -273.0, maximum = 1000.0, example = 60.0)]
    pub temperature_c: Option<Celsius>,
    /// Journal speed, rev/min (> 0, at most 1e6).
    #[schema(value_type = f64, minimum = 1e-6, maximum = 1e6, example = 3000.0)]
    pub speed_rpm: Positive,
    /// The mass the bearing carries, kg (0 … 1e6; default 0: the massless mobility solution).
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 1e6, example = 10.0)]
    pub journal_mass_kg: Option<NonNegative>,
    pub load: DynamicLoadSpec,
    /// `short_pi_film` (default), `short_fixed_arc`, `short_full` or `finite`.
    #[serde(default)]
    pub film_model: DynamicFilmModel,
    /// `"centre"`, `"equilibrium"` (default) or `{"x_m", "y_m", "velocity_x_m_s",
    /// "velocity_y_m_s"}` (inside the clearance).
    pub initial_state: Option<InitialState>,
    /// `"steady_orbit"` (default), `{"time_s": t}` or `{"eccentricity_ratio": e}`.
    pub until: Option<UntilSpec>,
    /// `fast`, `standard` (default), `high` (step tolerance 1e-6, 1e-7, 1e-9; for `finite`
    /// also the film's grid 48 × 6, 96 × 12, 192 × 24 and its table's density) or
    /// `{"tolerance": 1e-12…1e-4}` (with `finite` also `"grid": [circumferential 16…1024 (even),
    /// half-length axial 2…256]`).
    #[serde(default)]
    pub fidelity: FidelityRequest,
    /// Include 181 samples of the orbit over the result's window.
    #[serde(default)]
    #[schema(example = false)]
    pub include_orbit: bool,
}

/// The parsed request.
#[derive(Debug, Clone, PartialEq)]
pub struct DynamicJournalCase {
    radius: f64,
    length: f64,
    clearance: f64,
    viscosity: Viscosity,
    omega: f64,
    mass: f64,
    load: LoadLaw,
    engine: bool,
    film: FilmChoice,
    initial: InitialStart,
    until: UntilRun,
    tolerance: f64,
    level: Level,
    include_orbit: bool,
}

/// The film model and, for the finite film, its grid and table.
#[derive(Debug, Clone, Copy, PartialEq)]
enum FilmChoice {
    Short(ShortArc),
    Finite { mesh: Mesh, density: TableDensity },
}

#[derive(Debug, Clone, Copy, PartialEq)]
enum InitialStart {
    Centre,
    Equilibrium,
    /// r̄ and dr̄/dτ.
    Given([f64; 2], [f64; 2]),
}

/// The run's end in τ.
#[derive(Debug, Clone, Copy, PartialEq)]
enum UntilRun {
    Steady,
    Time(f64),
    Eccentricity(f64),
}

fn finite_within(errors: &mut Vec<FieldError>, pointer: &str, v: f64, lo: f64, hi: f64) {
    if !(v.is_finite() && (lo..=hi).contains(&v)) {
        errors.push(FieldError::new(
            pointer,
            format!("must be within [{lo}, {hi}], got {v}"),
        ));
    }
}

/// Angles (degrees) ascending within [0, period): radians.
pub(crate) fn ascending_angles(
    errors: &mut Vec<FieldError>,
    pointer: &str,
    angles: &[f64],
    period: f64,
) -> Vec<f64> {
    let ok = angles.len() >= 3
        && angles
            .iter()
            .all(|a| a.is_finite() && (0.0..period).contains(a))
        && angles.windows(2).all(|w| w[1] > w[0]);
    if !ok {
        errors.push(FieldError::new(
            pointer,
            format!("needs at least 3 points with angles ascending within [0, {period}) degrees"),
        ));
    }
    angles.iter().map(|a| a.to_radians()).collect()
}

/// The load law of a request's `load`, its invalid fields pushed onto `errors` (also the
/// composite orbit's). One load period, 1/ratio revolutions for a rotating or sinusoidal load,
/// may last at most `longest_period` revolutions (a steady orbit integrates whole periods; a
/// slower load is quasi-static).
pub(crate) fn load_law(
    spec: DynamicLoadSpec,
    omega: f64,
    longest_period: f64,
    errors: &mut Vec<FieldError>,
) -> LoadLaw {
    let min_ratio = 1.0 / longest_period;
    let force = |errors: &mut Vec<FieldError>, field: &str, v: f64| {
        finite_within(
            errors,
            &format!("/load/{field}"),
            v,
            -MAX_LOAD_N,
            MAX_LOAD_N,
        );
    };
    let angle = |errors: &mut Vec<FieldError>, field: &str, v: f64| {
        finite_within(errors, &format!("/load/{field}"), v, -3600.0, 3600.0);
        v.to_radians()
    };
    match spec {
        DynamicLoadSpec::Constant {
            magnitude_n,
            direction_deg,
        } => {
            finite_within(errors, "/load/magnitude_n", magnitude_n, 0.0, MAX_LOAD_N);
            let a = angle(errors, "direction_deg", direction_deg);
            LoadLaw::Constant {
                force: [magnitude_n * a.cos(), magnitude_n * a.sin()],
            }
        }
        DynamicLoadSpec::Rotating {
            magnitude_n,
            speed_ratio,
            direction_at_start_deg,
        } => {
            finite_within(errors, "/load/magnitude_n", magnitude_n, 0.0, MAX_LOAD_N);
            finite_within(
                errors,
                "/load/speed_ratio",
                speed_ratio,
                -MAX_RATIO,
                MAX_RATIO,
            );
            if speed_ratio != 0.0 && speed_ratio.abs() < min_ratio {
                errors.push(FieldError::new(
                    "/load/speed_ratio",
                    format!("must be 0 or at least {min_ratio:e} in magnitude (one turn of the load within {longest_period} revolutions, the longest load period this room integrates), got {speed_ratio:e}"),
                ));
            }
            LoadLaw::Rotating {
                magnitude: magnitude_n,
                speed_ratio,
                start: angle(errors, "direction_at_start_deg", direction_at_start_deg),
            }
        }
        DynamicLoadSpec::Sinusoidal {
            static_n,
            amplitude_n,
            frequency_ratio,
            direction_deg,
        } => {
            force(errors, "static_n", static_n);
            force(errors, "amplitude_n", amplitude_n);
            if !(frequency_ratio.is_finite() && (min_ratio..=MAX_RATIO).contains(&frequency_ratio))
            {
                errors.push(FieldError::new(
                    "/load/frequency_ratio",
                    format!("must be within [{min_ratio:e}, {MAX_RATIO}] (one load period within {longest_period} revolutions, the longest this room integrates; a slower load is quasi-static), got {frequency_ratio}"),
                ));
            }
            LoadLaw::Sinusoidal {
                steady: static_n,
                amplitude: amplitude_n,
                frequency_ratio,
                direction: angle(errors, "direction_deg", direction_deg),
            }
        }
        DynamicLoadSpec::Table { points, period_deg } => {
            let period = period_deg.unwrap_or(360.0);
            finite_within(errors, "/load/period_deg", period, 1.0, 36_000.0);
            let degrees: Vec<f64> = points.iter().map(|p| p.angle_deg).collect();
            let angles = ascending_angles(errors, "/load/points", &degrees, period);
            for (i, p) in points.iter().enumerate() {
                force(errors, &format!("points/{i}/force_x_n"), p.force_x_n);
                force(errors, &format!("points/{i}/force_y_n"), p.force_y_n);
            }
            LoadLaw::Table {
                angles,
                fx: points.iter().map(|p| p.force_x_n).collect(),
                fy: points.iter().map(|p| p.force_y_n).collect(),
                period: period.to_radians(),
            }
        }
        DynamicLoadSpec::Engine {
            bore_m,
            crank_radius_m,
            rod_length_m,
            reciprocating_mass_kg,
            cylinder_pressure,
            cycle_deg,
        } => {
            let cycle = cycle_deg.unwrap_or(720.0);
            if cycle != 720.0 && cycle != 360.0 {
                errors.push(FieldError::new(
                    "/load/cycle_deg",
                    format!("must be 720 (four-stroke) or 360 (two-stroke), got {cycle}"),
                ));
            }
            finite_within(errors, "/load/bore_m", bore_m, 1e-3, 5.0);
            finite_within(errors, "/load/crank_radius_m", crank_radius_m, 1e-3, 5.0);
            if !(rod_length_m.is_finite()
                && rod_length_m > 1.2 * crank_radius_m
                && rod_length_m <= 20.0)
            {
                errors.push(FieldError::new(
                    "/load/rod_length_m",
                    "must exceed 1.2 times the crank radius (and be at most 20 m)",
                ));
            }
            finite_within(
                errors,
                "/load/reciprocating_mass_kg",
                reciprocating_mass_kg,
                0.0,
                1e5,
            );
            let degrees: Vec<f64> = cylinder_pressure
                .iter()
                .map(|p| p.crank_angle_deg)
                .collect();
            let crank_angles = ascending_angles(errors, "/load/cylinder_pressure", &degrees, cycle);
            for (i, p) in cylinder_pressure.iter().enumerate() {
                finite_within(
                    errors,
                    &format!("/load/cylinder_pressure/{i}/pressure_pa"),
                    p.pressure_pa,
                    -1e5,
                    1e9,
                );
            }
            LoadLaw::Engine(Engine {
                bore: bore_m,
                crank_radius: crank_radius_m,
                rod_length: rod_length_m,
                reciprocating_mass: reciprocating_mass_kg,
                angular_speed: omega,
                crank_angles,
                pressures: cylinder_pressure.iter().map(|p| p.pressure_pa).collect(),
                cycle: cycle.to_radians(),
            })
        }
    }
}

impl Validate for DynamicJournalInput {
    type Valid = DynamicJournalCase;
    fn validate(self) -> Result<DynamicJournalCase, Vec<FieldError>> {
        let mut errors = Vec::new();
        let (d, l, c) = self.geometry.check(&mut errors);
        let viscosity = isoviscous::viscosity(self.lubricant, self.temperature_c, &mut errors);
        let rpm = self.speed_rpm.get();
        if !(1e-6..=1e6).contains(&rpm) {
            errors.push(FieldError::new(
                "/speed_rpm",
                format!("must be within [1e-6, 1e6] rev/min, got {rpm}"),
            ));
        }
        let omega = rpm * PI / 30.0;
        let mass = self.journal_mass_kg.map_or(0.0, NonNegative::get);
        if mass > MAX_MASS_KG {
            errors.push(FieldError::new(
                "/journal_mass_kg",
                format!("must be at most {MAX_MASS_KG} kg, got {mass}"),
            ));
        }
        let engine = matches!(self.load, DynamicLoadSpec::Engine { .. });
        let load = load_law(self.load, omega, MAX_REVOLUTIONS, &mut errors);
        let initial = match self.initial_state {
            None | Some(InitialState::Named(InitialStateName::Equilibrium)) => {
                InitialStart::Equilibrium
            }
            Some(InitialState::Named(InitialStateName::Centre)) => InitialStart::Centre,
            Some(InitialState::Given(g)) => {
                let r = [g.x_m / c, g.y_m / c];
                let v = [
                    g.velocity_x_m_s / (c * omega),
                    g.velocity_y_m_s / (c * omega),
                ];
                let e = r[0].hypot(r[1]);
                if !(e.is_finite() && e <= MAX_TARGET) {
                    errors.push(FieldError::new(
                        "/initial_state",
                        format!("the position must lie within 0.999 of the clearance (ε = {e:.4})"),
                    ));
                }
                if !v.iter().all(|x| x.is_finite() && x.abs() <= 1e3) {
                    errors.push(FieldError::new(
                        "/initial_state",
                        "the velocity must be finite and at most 1000 C ω in size",
                    ));
                }
                InitialStart::Given(r, v)
            }
        };
        let horizon = MAX_REVOLUTIONS * 2.0 * PI;
        let until = match self.until {
            None | Some(UntilSpec::Named(UntilName::SteadyOrbit)) => UntilRun::Steady,
            Some(UntilSpec::Time(UntilTime { time_s })) => {
                let tau = time_s * omega;
                // The bound itself is allowed: 40 s at 3000 rpm is 2000 revolutions, though
                // 40 × 100π rounds above 2000 × 2π.
                if !(time_s.is_finite() && time_s > 0.0 && tau <= horizon * (1.0 + 1e-12)) {
                    errors.push(FieldError::new(
                        "/until/time_s",
                        format!(
                            "must be positive and at most {MAX_REVOLUTIONS} journal revolutions ({:.4e} s at this speed)",
                            horizon / omega
                        ),
                    ));
                }
                UntilRun::Time(tau)
            }
            Some(UntilSpec::Eccentricity(UntilEccentricity { eccentricity_ratio })) => {
                if !(eccentricity_ratio.is_finite()
                    && eccentricity_ratio > 0.0
                    && eccentricity_ratio <= MAX_TARGET)
                {
                    errors.push(FieldError::new(
                        "/until/eccentricity_ratio",
                        format!("must be within (0, {MAX_TARGET}], got {eccentricity_ratio}"),
                    ));
                }
                UntilRun::Eccentricity(eccentricity_ratio)
            }
        };
        let (tolerance, level) = match self.fidelity {
            FidelityRequest::Level(Level::ClosedForm) => {
                errors.push(FieldError::new(
                    "/fidelity",
                    "an orbit is integrated in time: use fast, standard, high or {\"tolerance\": …}",
                ));
                (1e-7, Level::Standard)
            }
            // docs/accuracy.md's orbit table: against a 1e-12 run, 1e-6 holds ε_max to 3e-6 and
            // h_min to 0.07 % at ε_max = 0.996, 1e-7 to 2e-7 and 0.005 %.
            FidelityRequest::Level(Level::Fast) => (1e-6, Level::Fast),
            FidelityRequest::Level(Level::Standard) => (1e-7, Level::Standard),
            FidelityRequest::Level(Level::High) => (1e-9, Level::High),
            FidelityRequest::Custom(custom) => {
                if custom.grid.is_some() && self.film_model != DynamicFilmModel::Finite {
                    errors.push(FieldError::new(
                        "/fidelity/grid",
                        "the short film models have no grid; give a tolerance only",
                    ));
                }
                let t = custom.tolerance.unwrap_or(1e-7);
                if !(1e-12..=1e-4).contains(&t) {
                    errors.push(FieldError::new(
                        "/fidelity/tolerance",
                        "must be within [1e-12, 1e-4]",
                    ));
                }
                (t, Level::Standard)
            }
        };
        if let (DynamicFilmModel::Finite, UntilRun::Eccentricity(e)) = (self.film_model, until) {
            if e > FINITE_TOP {
                errors.push(FieldError::new(
                    "/until/eccentricity_ratio",
                    format!("the finite film is tabulated to ε = {FINITE_TOP}: must be within (0, {FINITE_TOP}], got {e}"),
                ));
            }
        }
        if let (DynamicFilmModel::Finite, InitialStart::Given(r, _)) = (self.film_model, initial) {
            let e = r[0].hypot(r[1]);
            if e > FINITE_TOP {
                errors.push(FieldError::new(
                    "/initial_state",
                    format!("the finite film is tabulated to ε = {FINITE_TOP}: the position must lie within {FINITE_TOP} of the clearance (ε = {e:.4})"),
                ));
            }
        }
        let film = match self.film_model {
            DynamicFilmModel::ShortPiFilm => FilmChoice::Short(ShortArc::PiFilm),
            DynamicFilmModel::ShortFixedArc => FilmChoice::Short(ShortArc::FixedArc),
            DynamicFilmModel::ShortFull => FilmChoice::Short(ShortArc::Full),
            DynamicFilmModel::Finite => {
                let given = match self.fidelity {
                    FidelityRequest::Custom(custom) => grid_mesh(custom.grid, &mut errors),
                    FidelityRequest::Level(_) => None,
                };
                let mesh = Method::numerical(level, given, None)
                    .mesh()
                    .unwrap_or(Mesh {
                        circumferential: 96,
                        axial_half: 12,
                    });
                FilmChoice::Finite {
                    mesh,
                    density: TableDensity::at(level),
                }
            }
        };
        match (errors.is_empty(), viscosity) {
            (true, Some(viscosity)) => Ok(DynamicJournalCase {
                radius: 0.5 * d,
                length: l,
                clearance: c,
                viscosity,
                omega,
                mass,
                load,
                engine,
                film,
                initial,
                until,
                tolerance,
                level,
                include_orbit: self.include_orbit,
            }),
            _ => Err(errors),
        }
    }
}

/// One sample of the orbit.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct DynamicOrbitPoint {
    /// s.
    pub time_s: f64,
    /// Journal rotation since the start of the load period, degrees.
    pub load_cycle_angle_deg: f64,
    /// Journal centre along x, m.
    pub x_m: f64,
    /// Journal centre along y (up), m.
    pub y_m: f64,
    /// ε.
    pub eccentricity_ratio: f64,
}

/// Result.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct DynamicJournalOutput {
    /// Largest ε over the window (the last load period of a steady orbit, the whole run
    /// otherwise).
    pub max_eccentricity_ratio: f64,
    /// Smallest ε over the window.
    pub min_eccentricity_ratio: f64,
    /// h_min = C(1 − ε_max), m.
    pub min_film_m: f64,
    /// Journal rotation since the start of the load period where the film is thinnest,
    /// degrees (non-engine loads).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub load_cycle_angle_at_min_film_deg: Option<f64>,
    /// Crank angle from top dead centre where the film is thinnest, degrees (engine loads).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub crank_angle_at_min_film_deg: Option<f64>,
    /// Direction of the eccentricity vector at the thinnest film (where the minimum film lies
    /// on the bearing), degrees from +x.
    pub direction_of_min_film_deg: f64,
    /// ε at the end of the run.
    pub final_eccentricity_ratio: f64,
    /// Angle from the load vector to the eccentricity vector at the end, degrees, positive
    /// with rotation.
    pub final_attitude_angle_deg: f64,
    /// Largest ε over the whole run (the transient included).
    pub peak_eccentricity_ratio: f64,
    /// When it occurred, s.
    pub time_of_peak_s: f64,
    /// True when one load period mapped onto itself within the tolerance.
    pub steady_orbit: bool,
    /// Load periods integrated (for a steady orbit: until it repeated).
    pub periods_to_settle: u32,
    /// With `until: {"eccentricity_ratio": e}`: when ε reached e, s (absent if it did not).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub time_to_target_s: Option<f64>,
    /// Largest load over one period, N.
    pub peak_load_n: f64,
    /// Largest film pressure over the window (at the integrator's steps), Pa.
    pub peak_film_pressure_pa: f64,
    /// Mean Couette power loss over the window, W.
    pub mean_power_loss_w: f64,
    /// What happened, in words.
    pub verdict: String,
    /// m̄ = m C³ ω/(μ R L³), the dimensionless mass (Harnoy Eq. 18-30).
    pub mass_parameter: f64,
    /// F_s = μ R ω L³/C², N: the force scale (F̄ = F/F_s).
    pub force_scale_n: f64,
    /// Viscosity used, Pa·s.
    pub viscosity_pa_s: f64,
    /// The orbit's samples, with `include_orbit`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub orbit: Option<Vec<DynamicOrbitPoint>>,
}

/// Static equilibrium of the film under F̄: the journal at rest at the ε where the steady
/// film's force |F̄_film(ε)| (the journal turning, w̄ = −½Ω̄ k × r̄) equals |F̄| (Brent), turned
/// so that the film's force opposes the load (the film is axisymmetric: its force turns with
/// the line of centres). None when the film cannot carry it within its reach.
fn equilibrium(film: &OrbitFilm, load: [f64; 2]) -> Option<[f64; 2]> {
    let magnitude = load[0].hypot(load[1]);
    if magnitude == 0.0 {
        return Some([0.0, 0.0]);
    }
    // The steady force with the line of centres along +x.
    let steady = |e: f64| {
        let r = [e, 0.0];
        film.force(r, squeeze_vector(r, [0.0, 0.0], film.speed_sum()))
    };
    let carried = |e: f64| steady(e).map_or(f64::INFINITY, |f| f[0].hypot(f[1])) - magnitude;
    let stop = Stopping {
        x_tolerance: 1e-14,
        max_iterations: 200,
    };
    let reach = film.reach().min(1.0 - 1e-8);
    let e = brent(carried, 1e-12, reach, stop).ok()?.x;
    let f = steady(e)?;
    // The line of centres lies the load's direction less the angle of −F̄_film from it.
    let a = load[1].atan2(load[0]) - (-f[1]).atan2(-f[0]);
    Some([e * a.cos(), e * a.sin()])
}

fn degrees_within(a: f64, period: f64) -> f64 {
    a.rem_euclid(period).to_degrees()
}

impl Calculation for DynamicJournal {
    const PATH: &'static str = "/v1/journal-bearings/dynamic";
    const SUMMARY: &'static str = "Dynamically loaded journal bearing: the journal's orbit under a constant, rotating, sinusoidal, tabulated or engine load (short π-film, fixed-arc or full film, or the finite Reynolds film with cavitation; with mass or by mobility), ε_max, h_min and where, peak pressure, power";
    const DESCRIPTION: &'static str = include_str!("dynamic.md");
    const FIDELITY: &'static [Level] = &[Level::Fast, Level::Standard, Level::High];
    const EFFECTS: &'static [&'static str] = &[];
    const EXAMPLE: &'static str = r#"{"geometry": {"diameter_m": 0.1, "length_m": 0.04, "radial_clearance_m": 0.0001}, "lubricant": {"viscosity_pa_s": 0.02}, "speed_rpm": 3000, "journal_mass_kg": 20, "load": {"kind": "sinusoidal", "static_n": 10000, "amplitude_n": 5000, "frequency_ratio": 1, "direction_deg": -90}, "film_model": "short_pi_film", "fidelity": "standard"}"#;

    type Input = DynamicJournalInput;
    type Output = DynamicJournalOutput;

    fn run(case: DynamicJournalCase, ctx: &mut Context) -> Result<DynamicJournalOutput, CalcError> {
        for (code, message) in &case.viscosity.assumptions {
            ctx.warn(code, message.clone());
        }
        let (r, l, c, w) = (case.radius, case.length, case.clearance, case.omega);
        let mu = case.viscosity.pa_s;
        let l_over_d = l / (2.0 * r);
        if l_over_d > 0.5 && matches!(case.film, FilmChoice::Short(_)) {
            ctx.warn(
                "short_bearing_beyond_validity",
                format!("L/D = {l_over_d:.3}: the short-bearing film overestimates the load capacity above L/D ≈ 0.5 (Ocvirk); the orbit's ε is then too small"),
            );
        }
        let scales = Scales::of(mu, r, l, c, w);
        let (force_scale, mass) = (scales.force, scales.mass(case.mass));
        let started = std::time::Instant::now();
        let budget = ctx.budget();
        let film = match case.film {
            FilmChoice::Short(arc) => OrbitFilm::Short(ShortFilm {
                arc,
                speed_sum: 1.0,
            }),
            FilmChoice::Finite { mesh, density } => {
                // A grid whose table the deadline cannot pay for is refused before any solve.
                let explicit = Method::numerical(case.level, None, None).mesh() != Some(mesh);
                cost::check_solves(mesh, false, explicit, density.solves(), &budget)?;
                let film = FiniteSqueezeFilm { l_over_d, mesh };
                let table = ImpedanceTable::build(film, density, &budget)?;
                if table.cut_pressure > 1e-3 {
                    ctx.warn(
                        "finite_film_cut_holds_pressure",
                        format!("L/D = {l_over_d:.3}: the squeeze film is cut where it opens fastest, and there it still carried {:.2} % of its peak pressure in some states (a long bearing near the centre keeps pressure round the circle); the force is then somewhat low", 100.0 * table.cut_pressure),
                    );
                }
                OrbitFilm::Finite {
                    table: Arc::new(table),
                    speed_sum: 1.0,
                }
            }
        };
        let reach = match case.film {
            FilmChoice::Short(_) => "short of contact".to_owned(),
            FilmChoice::Finite { .. } => format!(
                "within the finite film's table (ε ≤ {FINITE_TOP}, h_min ≥ {:.3e} m)",
                c * (1.0 - FINITE_TOP)
            ),
        };
        let problem = Problem {
            film: film.clone(),
            mass,
            load: case.load.clone(),
            force_scale,
        };
        let start = match case.initial {
            InitialStart::Centre => [0.0, 0.0],
            InitialStart::Equilibrium => {
                let f = case.load.force(0.0);
                equilibrium(&film, [f[0] / force_scale, f[1] / force_scale]).ok_or_else(|| {
                    CalcError::impossible(
                        "/load",
                        format!("the film cannot carry the load at time 0 {reach} (no static equilibrium to start from): lower the load, raise the speed or viscosity, or start from \"centre\""),
                    )
                })?
            }
            InitialStart::Given(p, _) => p,
        };
        let velocity = match case.initial {
            InitialStart::Given(_, v) => v,
            _ => [0.0, 0.0],
        };
        let period = case.load.period();
        let horizon = MAX_REVOLUTIONS * 2.0 * PI;
        let until = match case.until {
            UntilRun::Steady => Until::SteadyOrbit {
                tolerance: 100.0 * case.tolerance,
                max_periods: MAX_PERIODS.min((horizon / period).floor().max(1.0) as u32),
            },
            UntilRun::Time(t) => Until::Time(t),
            UntilRun::Eccentricity(e) => Until::Eccentricity {
                target: e,
                horizon,
                settled_within: 100.0 * case.tolerance,
            },
        };
        let samples = if case.include_orbit { ORBIT_POINTS } else { 0 };
        let orbit = orbit::run(
            &problem,
            Start {
                position: start,
                velocity,
            },
            until,
            case.tolerance,
            samples,
            &budget,
        )
        .map_err(|e| match e {
            OrbitError::Contact { time, eccentricity } => CalcError::impossible(
                "/load",
                match case.film {
                    FilmChoice::Short(_) => format!(
                        "the journal reaches the bearing wall at t = {:.6e} s (ε = {eccentricity:.6}): the film cannot carry this load cycle — lower the load, raise the speed, viscosity or length",
                        time / w
                    ),
                    FilmChoice::Finite { .. } => format!(
                        "the journal leaves the finite film's table at t = {:.6e} s (ε = {eccentricity:.6}; the table reaches ε = {FINITE_TOP}): the film cannot carry this load cycle with h_min above {:.3e} m — lower the load, raise the speed, viscosity or length",
                        time / w,
                        c * (1.0 - FINITE_TOP)
                    ),
                },
            ),
            OrbitError::Stopped(report) => Stopped {
                report: report.at(case.level),
            }
            .into(),
        })?;
        let mut report = orbit.report.clone().at(case.level);
        if let FilmChoice::Finite { mesh, density } = case.film {
            // The grid's error: the same run on the table of the half mesh, the minimum films'
            // difference over 3 (Richardson, second order) when the mesh halves exactly, else
            // the whole difference, times the journal room's safety factor 1.25; relative to
            // the minimum film. None when the coarse film cannot carry the cycle.
            let coarse = FiniteSqueezeFilm {
                l_over_d,
                mesh: mesh.coarse(),
            };
            let coarse_film = OrbitFilm::Finite {
                table: Arc::new(ImpedanceTable::build(coarse, density, &budget)?),
                speed_sum: 1.0,
            };
            let coarse_orbit = orbit::run(
                &Problem {
                    film: coarse_film,
                    ..problem.clone()
                },
                Start {
                    position: start,
                    velocity,
                },
                until,
                case.tolerance,
                0,
                &budget,
            );
            let estimate = coarse_orbit.ok().map(|coarse| {
                let (fine_film, coarse_film) = (
                    1.0 - orbit.window.max_eccentricity,
                    1.0 - coarse.window.max_eccentricity,
                );
                let share = if mesh.halves_exactly() {
                    1.25 / 3.0
                } else {
                    1.25
                };
                share * (fine_film - coarse_film).abs() / fine_film
            });
            report = report
                .named("radau_iia5_on_finite_volume_active_set_impedance_table")
                .on_grid(vec![mesh.circumferential as u32, mesh.axial_half as u32])
                .with_film_solves(budget.field_solves())
                .with_error_estimate(estimate);
        }
        report.elapsed_ms = started.elapsed().as_secs_f64() * 1e3;
        ctx.report(report);
        let window = &orbit.window;
        let angle_at_min = degrees_within(window.time_of_max, period);
        let final_load = case.load.force(orbit.end);
        let attitude = if final_load[0].hypot(final_load[1]) > 0.0 && orbit.position != [0.0, 0.0] {
            let a = orbit.position[1].atan2(orbit.position[0]) - final_load[1].atan2(final_load[0]);
            (a + PI).rem_euclid(2.0 * PI) - PI
        } else {
            0.0
        };
        let verdict = match case.until {
            UntilRun::Steady if orbit.steady => format!(
                "steady orbit after {} load periods (the last period's end repeats within {:.1e} of the clearance)",
                orbit.periods,
                orbit.period_residual.unwrap_or(0.0)
            ),
            UntilRun::Steady => format!(
                "no steady orbit within {} load periods: the orbit still changes by {:.3e} of the clearance per period (a whirl, a subharmonic or a slow transient); the results describe the last period",
                orbit.periods,
                orbit.period_residual.unwrap_or(f64::NAN)
            ),
            UntilRun::Time(_) => format!("integrated to t = {:.6e} s", orbit.end / w),
            UntilRun::Eccentricity(e) => match orbit.time_to_target {
                Some(t) => format!("ε reached {e} at t = {:.6e} s", t / w),
                None if orbit.steady => format!(
                    "ε never reaches {e}: the orbit settled after {} load periods with ε at most {:.4}",
                    orbit.periods, orbit.peak_eccentricity
                ),
                None => format!(
                    "ε did not reach {e} within {MAX_REVOLUTIONS} revolutions (largest {:.4})",
                    orbit.peak_eccentricity
                ),
            },
        };
        if window.max_eccentricity > 0.99 {
            ctx.warn(
                "film_thinner_than_1_percent_of_clearance",
                format!(
                    "ε_max = {:.5}: h_min = {:.3e} m, likely below the surfaces' roughness (mixed lubrication, not modelled)",
                    window.max_eccentricity,
                    c * (1.0 - window.max_eccentricity)
                ),
            );
        }
        if !orbit.steady && case.until == UntilRun::Steady {
            ctx.warn("no_steady_orbit", verdict.clone());
        }
        let orbit_points = case.include_orbit.then(|| {
            window
                .samples
                .iter()
                .map(|&(t, x, y)| DynamicOrbitPoint {
                    time_s: t / w,
                    load_cycle_angle_deg: degrees_within(t, period),
                    x_m: x * c,
                    y_m: y * c,
                    eccentricity_ratio: x.hypot(y),
                })
                .collect()
        });
        let output = DynamicJournalOutput {
            max_eccentricity_ratio: window.max_eccentricity,
            min_eccentricity_ratio: window.min_eccentricity,
            min_film_m: c * (1.0 - window.max_eccentricity),
            load_cycle_angle_at_min_film_deg: (!case.engine).then_some(angle_at_min),
            crank_angle_at_min_film_deg: case.engine.then_some(angle_at_min),
            direction_of_min_film_deg: window.direction_of_max.to_degrees(),
            final_eccentricity_ratio: orbit.position[0].hypot(orbit.position[1]),
            final_attitude_angle_deg: attitude.to_degrees(),
            peak_eccentricity_ratio: orbit.peak_eccentricity,
            time_of_peak_s: orbit.time_of_peak / w,
            steady_orbit: orbit.steady,
            periods_to_settle: orbit.periods,
            time_to_target_s: orbit.time_to_target.map(|t| t / w),
            peak_load_n: case.load.peak(),
            peak_film_pressure_pa: window.peak_pressure * mu * w * (l / c).powi(2),
            mean_power_loss_w: mu * r.powi(3) * l * w * w * 2.0 * PI / c
                * window.mean_couette_factor,
            verdict,
            mass_parameter: mass,
            force_scale_n: force_scale,
            viscosity_pa_s: mu,
            orbit: orbit_points,
        };
        CalcError::finite_or_out_of_range(output, "the load, speed and geometry")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::calc::testing::{invalid_pointers, ok, post, result_field, warning_codes};
    use crate::calc::Failure;
    use proptest::prelude::*;
    use serde_json::{json, Value};

    fn example() -> Value {
        serde_json::from_str(DynamicJournal::EXAMPLE).unwrap()
    }

    /// An orbit past its deadline is a 504 (the driver's one mapping), not a 422 with a report.
    #[test]
    fn a_run_past_its_deadline_is_a_504() {
        let body = serde_json::to_vec(&example()).unwrap();
        let deadline = std::time::Instant::now() + std::time::Duration::from_micros(200);
        match crate::calc::execute::<DynamicJournal>(&body, deadline, Default::default()) {
            Err(Failure::Calc(CalcError::DeadlineExceeded)) => {}
            other => panic!("expected the deadline, got {:?}", other.map(|_| ())),
        }
    }

    #[test]
    fn the_example_settles_on_a_finite_orbit_inside_the_clearance() {
        let mut body = example();
        body["include_orbit"] = json!(true);
        let v = ok::<DynamicJournal>(&body);
        assert_eq!(v["result"]["steady_orbit"], json!(true));
        let (max, min) = (
            result_field(&v, "max_eccentricity_ratio"),
            result_field(&v, "min_eccentricity_ratio"),
        );
        assert!(0.0 < min && min < max && max < 1.0);
        let orbit = v["result"]["orbit"].as_array().unwrap();
        assert_eq!(orbit.len(), ORBIT_POINTS);
        let largest = orbit
            .iter()
            .map(|p| p["eccentricity_ratio"].as_f64().unwrap())
            .fold(0.0, f64::max);
        // The samples lie on the orbit the extrema were taken from.
        assert!(
            largest <= max + 1e-9 && largest > max - 1e-3,
            "{largest} {max}"
        );
        assert_eq!(v["solver"]["iterations_unit"], json!("time_steps"));
        assert!(v["solver"]["time_integration"]["rejected_steps"].is_u64());
        // L/D = 0.4: inside the short bearing's range, no warning.
        assert!(warning_codes(&v).is_empty(), "{v}");
    }

    #[test]
    fn tighter_tolerances_agree_and_the_orbit_converges() {
        // The accuracy ladder: fast and standard within their tolerances of high.
        let at = |level: &str| {
            let mut body = example();
            body["fidelity"] = json!(level);
            result_field(&ok::<DynamicJournal>(&body), "max_eccentricity_ratio")
        };
        let high = at("high");
        assert!((at("standard") - high).abs() < 1e-7);
        assert!((at("fast") - high).abs() < 1e-6);
    }

    #[test]
    fn an_engine_load_reports_the_crank_angle_of_the_thinnest_film() {
        // Firing near TDC: the thinnest film follows the gas load, shortly after TDC.
        let mut body = example();
        body["load"] = json!({"kind": "engine", "bore_m": 0.1, "crank_radius_m": 0.045,
            "rod_length_m": 0.15, "reciprocating_mass_kg": 0.8, "cycle_deg": 720,
            "cylinder_pressure": [
                {"crank_angle_deg": 0, "pressure_pa": 4e6}, {"crank_angle_deg": 20, "pressure_pa": 6e6},
                {"crank_angle_deg": 60, "pressure_pa": 1.5e6}, {"crank_angle_deg": 180, "pressure_pa": 2e5},
                {"crank_angle_deg": 360, "pressure_pa": 0}, {"crank_angle_deg": 540, "pressure_pa": 1e5},
                {"crank_angle_deg": 680, "pressure_pa": 1e6}]});
        body["fidelity"] = json!("fast");
        let v = ok::<DynamicJournal>(&body);
        let crank = result_field(&v, "crank_angle_at_min_film_deg");
        assert!(v["result"]
            .get("load_cycle_angle_at_min_film_deg")
            .is_none());
        assert!((0.0..90.0).contains(&crank), "{crank}");
        assert!(result_field(&v, "peak_load_n") > 4e4);
    }

    #[test]
    fn a_half_speed_load_is_answered_with_the_time_to_reach_the_target() {
        let mut body = example();
        body["load"] = json!({"kind": "rotating", "magnitude_n": 2000, "speed_ratio": 0.5,
            "direction_at_start_deg": -90});
        body["journal_mass_kg"] = json!(0);
        body["until"] = json!({"eccentricity_ratio": 0.9});
        body["initial_state"] = json!("centre");
        let v = ok::<DynamicJournal>(&body);
        assert!(result_field(&v, "time_to_target_s") > 0.0);
        assert_eq!(v["result"]["steady_orbit"], json!(false));
    }

    #[test]
    fn the_finite_films_error_estimate_bounds_the_error_of_its_minimum_film() {
        // The grid's error from the half mesh's table (Richardson): against `high` (192 × 24,
        // four times finer than `fast`), `fast`'s and `standard`'s estimates bound their
        // minimum films' errors, and `high`'s is the smallest.
        let mut body = example();
        body["film_model"] = json!("finite");
        let run = |fidelity: &str| {
            let mut b = body.clone();
            b["fidelity"] = json!(fidelity);
            let v = ok::<DynamicJournal>(&b);
            (
                result_field(&v, "min_film_m"),
                v["solver"]["error_estimate"].as_f64().unwrap(),
            )
        };
        let (reference, high) = run("high");
        let mut last = f64::INFINITY;
        for fidelity in ["fast", "standard"] {
            let (film, estimate) = run(fidelity);
            let error = (film / reference - 1.0).abs();
            assert!(error <= estimate, "{fidelity}: {error} > {estimate}");
            assert!(estimate < last);
            last = estimate;
        }
        assert!(high < last, "{high} {last}");
    }

    #[test]
    fn a_run_to_a_target_the_orbit_settles_short_of_stops_when_it_settles() {
        // The example's orbit settles well inside ε = 0.999 (schemathesis's boundary case): the
        // run stops at the first period that maps onto itself, not after 2 000 revolutions.
        let mut body = example();
        body["until"] = json!({"eccentricity_ratio": 0.999});
        let v = ok::<DynamicJournal>(&body);
        assert!(v["result"].get("time_to_target_s").is_none());
        assert_eq!(v["result"]["steady_orbit"], json!(true));
        let periods = result_field(&v, "periods_to_settle");
        assert!((1.0..400.0).contains(&periods), "{periods}");
        let verdict = v["result"]["verdict"].as_str().unwrap();
        assert!(verdict.starts_with("ε never reaches 0.999"), "{verdict}");
        // The same orbit as the steady run's, to the settling tolerance.
        let steady = ok::<DynamicJournal>(&example());
        let (a, b) = (
            result_field(&v, "max_eccentricity_ratio"),
            result_field(&steady, "max_eccentricity_ratio"),
        );
        assert!(a >= b - 1e-4, "{a} {b}");
    }

    #[test]
    fn the_finite_films_constant_load_orbit_ends_at_the_journal_rooms_equilibrium() {
        // A constant load from the centre: the orbit's end is the steady film's equilibrium,
        // which the journal room's `/plain` model finds at the same Sommerfeld number
        // S = μ N_s L D (R/C)²/W on the same (standard, 96 × 12) mesh (Khonsari & Booser
        // §8.12): the same ε and attitude to the two discretisations' difference.
        use crate::calc::journal::film::FilmModel;
        use crate::calc::journal::performance::{equilibrium, Method};
        for mass in [0.0, 20.0] {
            let mut body = example();
            body["film_model"] = json!("finite");
            body["journal_mass_kg"] = json!(mass);
            body["initial_state"] = json!("centre");
            body["load"] = json!({"kind": "constant", "magnitude_n": 10000, "direction_deg": -90});
            let v = ok::<DynamicJournal>(&body);
            assert_eq!(v["result"]["steady_orbit"], json!(true));
            let (mu, n_s, l, d, r_over_c) = (0.02, 50.0, 0.04, 0.1, 500.0);
            let s = mu * n_s * l * d * r_over_c * r_over_c / 10000.0;
            let (point, _) = equilibrium(
                s,
                l / d,
                Method::numerical(Level::Standard, None, None),
                FilmModel::REYNOLDS,
                &crate::calc::Budget::unlimited(),
            )
            .unwrap();
            let eps = result_field(&v, "final_eccentricity_ratio");
            let want = point.eccentricity_ratio.get();
            assert!((eps - want).abs() < 2e-3, "m = {mass}: {eps} vs {want}");
            let attitude = result_field(&v, "final_attitude_angle_deg");
            assert!(
                (attitude - point.attitude_angle.to_degrees()).abs() < 0.5,
                "{attitude} vs {}",
                point.attitude_angle.to_degrees()
            );
            assert_eq!(v["solver"]["grid"], json!([96, 12]));
            assert!(v["solver"]["film_solves"].as_u64().unwrap() > 900);
        }
    }

    #[test]
    fn the_finite_orbit_converges_with_the_grid_and_carries_less_than_the_short_film() {
        // The fidelity ladder of the finite film (grid, table and step tolerance together):
        // ε_max of the example at fast and standard against high (release runs: 0.85694,
        // 0.85636, 0.85624). L/D = 0.4: the short π-film overestimates the capacity, so its
        // ε_max (0.8195) lies below the finite film's.
        let at = |level: &str, model: &str| {
            let mut body = example();
            body["fidelity"] = json!(level);
            body["film_model"] = json!(model);
            let v = ok::<DynamicJournal>(&body);
            assert!(result_field(&v, "peak_film_pressure_pa") > 0.0);
            assert!(result_field(&v, "mean_power_loss_w") > 0.0);
            result_field(&v, "max_eccentricity_ratio")
        };
        let high = at("high", "finite");
        let (fast, standard) = (at("fast", "finite"), at("standard", "finite"));
        assert!((fast - high).abs() < 2e-3, "{fast} {high}");
        assert!((standard - high).abs() < 5e-4, "{standard} {high}");
        assert!((standard - high).abs() < (fast - high).abs());
        assert!(at("standard", "short_pi_film") < high - 0.02);
    }

    #[test]
    fn invalid_requests_name_their_fields() {
        let rows: [(Value, Value, &str); 12] = [
            (json!("speed_rpm"), json!(5e-324), "/speed_rpm"),
            (
                json!("load"),
                json!({"kind": "constant", "magnitude_n": -1, "direction_deg": 0}),
                "/load/magnitude_n",
            ),
            (
                json!("load"),
                json!({"kind": "sinusoidal", "static_n": 1, "amplitude_n": 1, "frequency_ratio": 0, "direction_deg": 0}),
                "/load/frequency_ratio",
            ),
            // A load period of 1e300 revolutions ran on to the deadline (a bound scan's 504).
            (
                json!("load"),
                json!({"kind": "sinusoidal", "static_n": 1, "amplitude_n": 1, "frequency_ratio": 1e-300, "direction_deg": 0}),
                "/load/frequency_ratio",
            ),
            (
                json!("load"),
                json!({"kind": "rotating", "magnitude_n": 1, "speed_ratio": -1e-300, "direction_at_start_deg": 0}),
                "/load/speed_ratio",
            ),
            (
                json!("load"),
                json!({"kind": "table", "points": [{"angle_deg": 0, "force_x_n": 0, "force_y_n": -1}, {"angle_deg": 0, "force_x_n": 0, "force_y_n": -2}]}),
                "/load/points",
            ),
            (
                json!("load"),
                json!({"kind": "engine", "bore_m": 0.1, "crank_radius_m": 0.05, "rod_length_m": 0.05, "reciprocating_mass_kg": 1, "cylinder_pressure": [{"crank_angle_deg": 0, "pressure_pa": 1}, {"crank_angle_deg": 10, "pressure_pa": 1}, {"crank_angle_deg": 20, "pressure_pa": 1}]}),
                "/load/rod_length_m",
            ),
            (
                json!("until"),
                json!({"eccentricity_ratio": 1.0}),
                "/until/eccentricity_ratio",
            ),
            (json!("until"), json!({"time_s": 1e9}), "/until/time_s"),
            (
                json!("initial_state"),
                json!({"x_m": 1e-4, "y_m": 0, "velocity_x_m_s": 0, "velocity_y_m_s": 0}),
                "/initial_state",
            ),
            (json!("fidelity"), json!("closed_form"), "/fidelity"),
            (
                json!("fidelity"),
                json!({"grid": [96, 12]}),
                "/fidelity/grid",
            ),
        ];
        for (field, value, pointer) in rows {
            let mut body = example();
            body[field.as_str().unwrap()] = value;
            assert_eq!(
                invalid_pointers::<DynamicJournal>(&body),
                vec![pointer.to_owned()]
            );
        }
    }

    #[test]
    fn a_run_of_exactly_the_longest_time_is_accepted_and_a_little_longer_is_not() {
        // 2000 revolutions at 3000 rpm are 40 s; 40 × 100π rounds above 2000 × 2π, and the
        // message quoted 40 s as the limit while refusing 40 s.
        let accepts = |time_s: f64| {
            let mut body = example();
            body["until"] = json!({"time_s": time_s});
            serde_json::from_value::<DynamicJournalInput>(body)
                .unwrap()
                .validate()
                .is_ok()
        };
        assert!(accepts(40.0));
        assert!(!accepts(40.0 * (1.0 + 1e-9)));
    }

    #[test]
    fn a_crushing_load_is_carried_on_a_film_thinner_than_any_surface_and_says_so() {
        // The short film's force grows without bound as ε → 1: 1 GN rides on 71 nm.
        let mut body = example();
        body["load"] = json!({"kind": "constant", "magnitude_n": 1e9, "direction_deg": -90});
        let v = ok::<DynamicJournal>(&body);
        assert!(result_field(&v, "min_film_m") < 1e-7);
        assert!(warning_codes(&v).contains(&"film_thinner_than_1_percent_of_clearance".to_owned()));
    }

    /// A finite film's grid whose impedance table the deadline cannot pay for is refused before
    /// any solve, naming the grid with the estimate ([1024, 256] ran into a 504); the table's
    /// count is the one `ImpedanceTable::build` solves.
    #[test]
    fn a_grid_whose_table_outlasts_the_deadline_is_refused() {
        let density = TableDensity::at(Level::Standard);
        let film = FiniteSqueezeFilm {
            l_over_d: 0.4,
            mesh: Mesh {
                circumferential: 16,
                axial_half: 2,
            },
        };
        let budget = crate::calc::Budget::unlimited();
        let table = ImpedanceTable::build(film, density, &budget).unwrap();
        assert_eq!(table.solves as usize, density.solves());
        let mut body = example();
        body["film_model"] = json!("finite");
        body["fidelity"] = json!({"grid": [1024, 256]});
        match post::<DynamicJournal>(&body) {
            Err(Failure::Calc(CalcError::Impossible { pointer, message })) => {
                assert_eq!(pointer, "/fidelity/grid");
                assert!(message.contains("s at least"), "{message}");
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn finite_requests_name_their_fields() {
        let rows: [(Value, Value, &str); 3] = [
            (
                json!("until"),
                json!({"eccentricity_ratio": 0.998}),
                "/until/eccentricity_ratio",
            ),
            (
                json!("initial_state"),
                json!({"x_m": 0, "y_m": -9.97e-5, "velocity_x_m_s": 0, "velocity_y_m_s": 0}),
                "/initial_state",
            ),
            (
                json!("fidelity"),
                json!({"grid": [97, 12]}),
                "/fidelity/grid",
            ),
        ];
        for (field, value, pointer) in rows {
            let mut body = example();
            body["film_model"] = json!("finite");
            body[field.as_str().unwrap()] = value;
            assert_eq!(
                invalid_pointers::<DynamicJournal>(&body),
                vec![pointer.to_owned()]
            );
        }
        // A load the finite film cannot carry within its table: a 422 that says so.
        let mut body = example();
        body["film_model"] = json!("finite");
        body["fidelity"] = json!("fast");
        body["load"] = json!({"kind": "constant", "magnitude_n": 1e9, "direction_deg": -90});
        match post::<DynamicJournal>(&body) {
            Err(Failure::Calc(CalcError::Impossible { message, .. })) => {
                assert!(message.contains("table"), "{message}");
            }
            other => panic!("{other:?}"),
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(8))]
        #[test]
        fn every_finite_orbit_is_finite_and_inside_the_clearance_or_a_422(
            load_exp in 1.0f64..5.5,
            mass_exp in -2.0f64..3.0,
            massless in any::<bool>(),
            kind in 0usize..3,
            ratio in 0.1f64..3.0,
            l_over_d in 0.1f64..2.0,
        ) {
            let magnitude = 10f64.powf(load_exp);
            let mut body = example();
            body["film_model"] = json!("finite");
            body["fidelity"] = json!("fast");
            body["geometry"]["length_m"] = json!(0.1 * l_over_d);
            body["journal_mass_kg"] = json!(if massless { 0.0 } else { 10f64.powf(mass_exp) });
            body["until"] = json!({"time_s": 0.1});
            body["load"] = load_of_kind(kind, magnitude, ratio);
            within_the_clearance_or_a_422(&body, FINITE_TOP)?;
        }
    }

    /// A downward constant (0), rotating (1) or sinusoidal (2) load of `magnitude` N.
    fn load_of_kind(kind: usize, magnitude: f64, ratio: f64) -> Value {
        match kind {
            0 => json!({"kind": "constant", "magnitude_n": magnitude, "direction_deg": -90}),
            1 => {
                json!({"kind": "rotating", "magnitude_n": magnitude, "speed_ratio": ratio, "direction_at_start_deg": 0})
            }
            _ => {
                json!({"kind": "sinusoidal", "static_n": magnitude, "amplitude_n": magnitude, "frequency_ratio": ratio, "direction_deg": -90})
            }
        }
    }

    /// The orbit of `body` is finite, within ε ≤ `reach`, with a positive power loss and a
    /// finite peak pressure — or the request is refused as impossible (422).
    fn within_the_clearance_or_a_422(body: &Value, reach: f64) -> Result<(), TestCaseError> {
        match post::<DynamicJournal>(body) {
            Ok(v) => {
                let max = result_field(&v, "max_eccentricity_ratio");
                let min = result_field(&v, "min_eccentricity_ratio");
                prop_assert!(0.0 <= min && min <= max && max <= reach, "{v}");
                prop_assert!(result_field(&v, "mean_power_loss_w") > 0.0);
                prop_assert!(result_field(&v, "peak_film_pressure_pa").is_finite());
            }
            Err(Failure::Calc(CalcError::Impossible { .. })) => {}
            Err(other) => prop_assert!(false, "{body}: {other:?}"),
        }
        Ok(())
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(24))]
        #[test]
        fn every_orbit_is_finite_and_inside_the_clearance_or_a_422(
            load_exp in -2.0f64..7.0,
            mass_exp in -3.0f64..4.0,
            massless in any::<bool>(),
            model in 0usize..3,
            kind in 0usize..3,
            ratio in 0.1f64..4.0,
        ) {
            let magnitude = 10f64.powf(load_exp);
            let mut body = example();
            body["fidelity"] = json!("fast");
            body["journal_mass_kg"] = json!(if massless { 0.0 } else { 10f64.powf(mass_exp) });
            body["film_model"] = json!(["short_pi_film", "short_fixed_arc", "short_full"][model]);
            body["until"] = json!({"time_s": 0.2});
            body["load"] = load_of_kind(kind, magnitude, ratio);
            within_the_clearance_or_a_422(&body, crate::calc::journal::moving_film::CONTACT)?;
        }
    }
}
