//! `POST /v1/composite-bearings/orbit`: the journal locus of Harnoy's composite bearing under a
//! dynamic load beside the same bearing with its sleeve held (Harnoy ch. 18 §18.5, Figs 18-9
//! to 18-11; spec PART B.1.3–B.1.6).
//!
//! This file is the wire (request, validation, response); the physics is [`super::locus`] (the
//! composite) and `journal::orbit` (the regular bearing), the bearing's parsing the speed
//! split's and the load's the dynamic journal room's.

use std::f64::consts::PI;

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::film::{LoadError, SleeveFilm};
use super::locus::{self, Equilibrium, Locus, Problem, Settling, SleeveGroups};
use super::speed_split::{
    parse_bearing, parse_thermal, peclet_number, rpm, Bearing, BearingFields, LOW_SLEEVE_RPM,
    SHORT_L_OVER_D,
};
use crate::calc::journal::dynamic::{load_law, DynamicLoadSpec};
use crate::calc::journal::load_law::LoadLaw;
use crate::calc::journal::moving_film::{ShortArc, ShortFilm};
use crate::calc::journal::orbit::{self, Orbit, OrbitError, OrbitFilm, Scales, Start, Until};
use crate::calc::lubricant::LubricantSpec;
use crate::calc::quantity::{Celsius, NonNegative, Positive};
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::fidelity::{FidelityRequest, Level, SolverReport};
use crate::numerics::driver::{Budget, Stopped};

pub struct CompositeOrbit;

/// Journal speed range, rev/min.
const MIN_SPEED_RPM: f64 = 1e-6;
/// Largest journal mass, kg, and the smallest nonzero one.
const MAX_MASS_KG: f64 = 1e6;
const MIN_MASS_KG: f64 = 1e-6;
/// Sleeve unit's inertia range, kg·m².
const MIN_INERTIA_KG_M2: f64 = 1e-9;
const MAX_INERTIA_KG_M2: f64 = 1e6;
/// The longest run, in journal revolutions, and so the longest load period, and the most load
/// periods to settle: the sleeve takes hundreds of time steps a revolution (about 5 ms a
/// revolution at `high`), so a hundred revolutions keep a run within seconds.
const MAX_REVOLUTIONS: f64 = 100.0;
const MAX_PERIODS: u32 = 400;
/// Points of each sampled locus.
const ORBIT_POINTS: usize = 181;

/// The composite orbit's film model.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum CompositeOrbitFilmModel {
    /// The fixed arc [0, π] from the maximum film: Harnoy's book mode.
    #[default]
    ShortFixedArc,
    /// Dynamic half-Sommerfeld short bearing: the π-wide arc centred on the squeeze vector.
    ShortPiFilm,
}

/// Request.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct CompositeOrbitInput {
    /// Journal radius R, m (0 … 10).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 10.0, example = 0.05)]
    pub journal_radius_m: Positive,
    /// Length L of the sleeve's bore (the film), m (0 … 10; L/D at most 2, the short-bearing
    /// film is meant for L/D ≤ 1/2).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 10.0, example = 0.02)]
    pub sleeve_length_m: Positive,
    /// Radial clearance C between journal and sleeve, m (1e-7 … a tenth of the radius).
    #[schema(value_type = f64, minimum = 1e-7, maximum = 0.1, example = 5e-5)]
    pub radial_clearance_m: Positive,
    pub lubricant: LubricantSpec,
    /// Film temperature, °C (−273 … 1000): where the viscosity is taken; required unless the
    /// lubricant has a constant `viscosity_pa_s`.
    #[schema(value_type = Option<f64>, minimum = -273.0, maximum = 1000.0, example = 40.0)]
    pub temperature_c: Option<Celsius>,
    /// Journal speed ω_j, rpm (1e-6 … 1e6).
    #[schema(value_type = f64, minimum = 1e-6, maximum = 1e6, example = 3000.0)]
    pub journal_speed_rpm: Positive,
    /// The mass the bearing carries, kg (0, or 1e-6 … 1e6; default 0: the massless mobility
    /// solution).
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 1e6, example = 50.0)]
    pub journal_mass_kg: Option<NonNegative>,
    /// Equivalent moment of inertia I_eq of the sleeve unit (sleeve, disc, pins, the rolling
    /// bearing's inner ring and elements), kg·m² (1e-9 … 1e6).
    #[schema(value_type = f64, minimum = 1e-9, maximum = 1e6, example = 1e-4)]
    pub sleeve_inertia_kg_m2: Positive,
    /// Boundary friction coefficient f_c between the centrifugal pins and the housing,
    /// dimensionless (0 … 2); with `pin_mass_kg`, `pin_radius_m` and `housing_radius_m`, or
    /// give their product `restraint_coefficient_kg_m2`.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 2.0, example = 0.3)]
    pub pin_friction_coefficient: Option<Positive>,
    /// Total mass of the centrifugal pins m_c, kg (0 … 1e4).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e4, example = 0.05)]
    pub pin_mass_kg: Option<Positive>,
    /// Radius R_m of the circle of the pins' centres when they touch the housing, m (0 … 10,
    /// at most `housing_radius_m`).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 0.08)]
    pub pin_radius_m: Option<Positive>,
    /// Radius R_h of the housing bore the pins rub on, m (0 … 10).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 0.09)]
    pub housing_radius_m: Option<Positive>,
    /// The restraint's coefficient k = f_c m_c R_m R_h, kg·m² (0 … 1e6): M_f = k ω_b|ω_b|;
    /// instead of its four factors.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e6, example = 1e-4)]
    pub restraint_coefficient_kg_m2: Option<Positive>,
    /// Friction torque M_r of the rolling bearing, N·m (0 … 1e6; default 0), constant,
    /// opposing the sleeve's rotation (regularised over |ξ| < 1e-6, so a held sleeve stands).
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 1e6, example = 0.0)]
    pub rolling_friction_torque_n_m: Option<NonNegative>,
    /// The load, as `/v1/journal-bearings/dynamic`'s, but a rotating or sinusoidal load's ratio
    /// at least 0.01 in magnitude (one load period within 100 revolutions).
    pub load: DynamicLoadSpec,
    /// `short_fixed_arc` (default: Harnoy's book mode) or `short_pi_film`.
    #[serde(default)]
    pub film_model: CompositeOrbitFilmModel,
    /// `fast`, `standard` (default), `high` (step tolerance 1e-6, 1e-7, 1e-9) or
    /// `{"tolerance": 1e-12…1e-4}`.
    #[serde(default)]
    pub fidelity: FidelityRequest,
    /// Include 181 samples of each locus over its last load period.
    #[serde(default)]
    #[schema(example = false)]
    pub include_orbit: bool,
    /// Sleeve wall thickness b = R_o − R_i, m (0 … 1): with `sleeve_thermal_diffusivity_m2_s`,
    /// the sleeve's Péclet number at its slowest over the cycle.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1.0, example = 0.01)]
    pub sleeve_wall_thickness_m: Option<Positive>,
    /// Thermal diffusivity α_b = k/(ρ c_p) of the sleeve, m²/s (0 … 1e-2; steel about 1.5e-5).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e-2, example = 1.5e-5)]
    pub sleeve_thermal_diffusivity_m2_s: Option<Positive>,
}

/// The parsed request.
#[derive(Debug, Clone, PartialEq)]
pub struct CompositeOrbitCase {
    bearing: Bearing,
    /// kg.
    mass: f64,
    /// I_eq, kg·m².
    inertia: f64,
    load: LoadLaw,
    arc: ShortArc,
    tolerance: f64,
    level: Level,
    include_orbit: bool,
    thermal: Option<(f64, f64)>,
}

/// The step tolerance and level of a fidelity: the dynamic journal's levels (docs/accuracy.md's
/// orbit table: against a 1e-12 run, 1e-6 holds ε_max to 3e-6 at ε_max = 0.996, 1e-7 to 2e-7).
fn tolerance(fidelity: FidelityRequest, errors: &mut Vec<FieldError>) -> (f64, Level) {
    match fidelity {
        FidelityRequest::Level(Level::Fast) => (1e-6, Level::Fast),
        FidelityRequest::Level(Level::Standard) => (1e-7, Level::Standard),
        FidelityRequest::Level(Level::High) => (1e-9, Level::High),
        FidelityRequest::Level(Level::ClosedForm) => {
            errors.push(FieldError::new(
                "/fidelity",
                "a locus is integrated in time: use fast, standard, high or {\"tolerance\": …}",
            ));
            (1e-7, Level::Standard)
        }
        FidelityRequest::Custom(custom) => {
            if custom.grid.is_some() {
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
    }
}

impl Validate for CompositeOrbitInput {
    type Valid = CompositeOrbitCase;
    fn validate(self) -> Result<CompositeOrbitCase, Vec<FieldError>> {
        let mut errors = Vec::new();
        let n = self.journal_speed_rpm.get();
        if n < MIN_SPEED_RPM {
            errors.push(FieldError::new(
                "/journal_speed_rpm",
                format!("must be within [{MIN_SPEED_RPM:e}, 1e6] rpm, got {n}"),
            ));
        }
        let mass = self.journal_mass_kg.map_or(0.0, NonNegative::get);
        if mass != 0.0 && !(MIN_MASS_KG..=MAX_MASS_KG).contains(&mass) {
            errors.push(FieldError::new(
                "/journal_mass_kg",
                format!("must be 0 (massless) or within [{MIN_MASS_KG:e}, {MAX_MASS_KG:e}] kg, got {mass}"),
            ));
        }
        let inertia = self.sleeve_inertia_kg_m2.get();
        if !(MIN_INERTIA_KG_M2..=MAX_INERTIA_KG_M2).contains(&inertia) {
            errors.push(FieldError::new(
                "/sleeve_inertia_kg_m2",
                format!("must be within [{MIN_INERTIA_KG_M2:e}, {MAX_INERTIA_KG_M2:e}] kg·m², got {inertia}"),
            ));
        }
        let load = load_law(self.load, n * PI / 30.0, MAX_REVOLUTIONS, &mut errors);
        let (tolerance, level) = tolerance(self.fidelity, &mut errors);
        let thermal = parse_thermal(
            self.sleeve_wall_thickness_m,
            self.sleeve_thermal_diffusivity_m2_s,
            &mut errors,
        );
        let bearing = parse_bearing(
            BearingFields {
                journal_radius_m: self.journal_radius_m,
                sleeve_length_m: self.sleeve_length_m,
                radial_clearance_m: self.radial_clearance_m,
                lubricant: self.lubricant,
                temperature_c: self.temperature_c,
                journal_speed_rpm: self.journal_speed_rpm,
                pin_friction_coefficient: self.pin_friction_coefficient,
                pin_mass_kg: self.pin_mass_kg,
                pin_radius_m: self.pin_radius_m,
                housing_radius_m: self.housing_radius_m,
                restraint_coefficient_kg_m2: self.restraint_coefficient_kg_m2,
                rolling_friction_torque_n_m: self.rolling_friction_torque_n_m,
            },
            &mut errors,
        );
        match (errors.is_empty(), bearing) {
            (true, Some(bearing)) => Ok(CompositeOrbitCase {
                bearing,
                mass,
                inertia,
                load,
                arc: match self.film_model {
                    CompositeOrbitFilmModel::ShortFixedArc => ShortArc::FixedArc,
                    CompositeOrbitFilmModel::ShortPiFilm => ShortArc::PiFilm,
                },
                tolerance,
                level,
                include_orbit: self.include_orbit,
                thermal,
            }),
            _ => Err(errors),
        }
    }
}

/// One sample of a locus.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct CompositeOrbitPoint {
    /// s.
    pub time_s: f64,
    /// Journal rotation since the start of the load period, degrees.
    pub load_cycle_angle_deg: f64,
    /// Journal centre along x, m.
    pub x_m: f64,
    /// Journal centre along y (up), m.
    pub y_m: f64,
    /// ε, dimensionless.
    pub eccentricity_ratio: f64,
    /// ξ = ω_b/ω_j, dimensionless (0 for the held sleeve).
    pub speed_ratio: f64,
}

/// The same bearing with its sleeve held (ξ = 0): a plain short journal bearing.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct CompositeOrbitRegular {
    /// Largest ε over the last load period (with `contact_time_s`: where the journal reached
    /// the wall), dimensionless.
    pub max_eccentricity_ratio: f64,
    /// Smallest ε over the last load period, dimensionless; absent when the journal reaches
    /// the wall (no orbit).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub min_eccentricity_ratio: Option<f64>,
    /// h_min = C(1 − ε_max), m.
    pub min_film_m: f64,
    /// Journal rotation since the start of the load period (the crank angle for engine loads)
    /// where the film is thinnest, degrees.
    pub load_cycle_angle_at_min_film_deg: f64,
    /// ε of the static equilibrium under the load at time 0 (the start), dimensionless; absent
    /// where the film cannot carry that load (the run then starts at the centre).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub static_eccentricity_ratio: Option<f64>,
    /// True when one load period mapped onto itself within the tolerance.
    pub steady_orbit: bool,
    /// Load periods integrated.
    pub periods_to_settle: u32,
    /// When the held-sleeve journal reached the wall, s; absent when it carries the load
    /// cycle.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub contact_time_s: Option<f64>,
    /// What happened, in words.
    pub verdict: String,
    /// The locus's samples, with `include_orbit` (none when the journal reaches the wall).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub orbit: Option<Vec<CompositeOrbitPoint>>,
}

/// The composite bearing: journal and sleeve together.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct CompositeOrbitSleeve {
    /// Largest ε over the last load period, dimensionless.
    pub max_eccentricity_ratio: f64,
    /// Smallest ε over the last load period, dimensionless.
    pub min_eccentricity_ratio: f64,
    /// h_min = C(1 − ε_max), m.
    pub min_film_m: f64,
    /// Journal rotation since the start of the load period (the crank angle for engine loads)
    /// where the film is thinnest, degrees.
    pub load_cycle_angle_at_min_film_deg: f64,
    /// Smallest sleeve speed ratio ξ = ω_b/ω_j over the last period, dimensionless (negative:
    /// the sleeve turned backwards).
    pub min_speed_ratio: f64,
    /// Largest ξ over the last period, dimensionless.
    pub max_speed_ratio: f64,
    /// Mean ξ over the last period, dimensionless.
    pub mean_speed_ratio: f64,
    /// Mean sleeve speed ω_b, rpm.
    pub mean_sleeve_speed_rpm: f64,
    /// The film's heat flux over a held sleeve's at the same film, (ω_j − ω_b)/ω_j = 1 − ξ
    /// (Eq. 18-42), averaged over the last period, dimensionless.
    pub mean_heat_flux_ratio: f64,
    /// ε of the joint static equilibrium under the load at time 0 (the start), dimensionless.
    pub static_eccentricity_ratio: f64,
    /// ξ of the joint static equilibrium (the speed split's), dimensionless.
    pub static_speed_ratio: f64,
    /// True when one load period mapped onto itself (position and ξ) within the tolerance.
    pub steady_orbit: bool,
    /// Load periods integrated.
    pub periods_to_settle: u32,
    /// What happened, in words.
    pub verdict: String,
    /// The locus's samples, with `include_orbit`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub orbit: Option<Vec<CompositeOrbitPoint>>,
}

/// Result.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct CompositeOrbitOutput {
    /// The same bearing with its sleeve held.
    pub regular: CompositeOrbitRegular,
    /// The composite bearing.
    pub composite: CompositeOrbitSleeve,
    /// The composite's h_min over the regular's, dimensionless (> 1: the composite's film is
    /// thicker); absent when the regular bearing's journal reaches the wall.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub min_film_ratio: Option<f64>,
    /// Modified Péclet number ω_b R_b b/α_b of the sleeve at its slowest over the cycle
    /// (Eq. 18-40; R_b = R + C + b/2), dimensionless, with `sleeve_wall_thickness_m` and
    /// `sleeve_thermal_diffusivity_m2_s`: ≫ 1 means an axisymmetric sleeve temperature.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sleeve_peclet_number: Option<f64>,
    /// m̄ = m C³ ω_j/(μ R L³), the dimensionless mass (Harnoy Eq. 18-30 with μ restored).
    pub mass_parameter: f64,
    /// F_s = μ R ω_j L³/C², N: the force scale (F̄ = F/F_s).
    pub force_scale_n: f64,
    /// H₁ = L μ R³/(C I_eq ω_j), the sleeve's drive parameter (Eq. 18-16), dimensionless.
    pub sleeve_drive_parameter: f64,
    /// H₂ = k/I_eq, the pins' restraint parameter (Eq. 18-16 with I_eq restored),
    /// dimensionless.
    pub sleeve_restraint_parameter: f64,
    /// M_r/(I_eq ω_j²), the rolling bearing's friction parameter, dimensionless.
    pub rolling_friction_parameter: f64,
    /// The restraint's coefficient k = f_c m_c R_m R_h used, kg·m².
    pub restraint_coefficient_kg_m2: f64,
    /// Largest load over one period, N.
    pub peak_load_n: f64,
    /// Viscosity used, Pa·s.
    pub viscosity_pa_s: f64,
}

/// The regular bearing's run: from its static equilibrium (`None`: it has none; from the
/// centre) to a steady or capped orbit, or to the wall at (τ, ε).
struct Regular {
    start: Option<[f64; 2]>,
    outcome: Result<Orbit, (f64, f64)>,
}

fn degrees_within(a: f64, period: f64) -> f64 {
    a.rem_euclid(period).to_degrees()
}

/// Everything a run needs beyond the problem.
struct Run<'a> {
    settling: Settling,
    tolerance: f64,
    /// The fidelity the tolerance stands for (the report of a run that stopped short names it).
    level: Level,
    samples: usize,
    budget: &'a Budget,
    /// ω_j, rad/s.
    omega: f64,
}

impl Run<'_> {
    /// An integration that stopped short: the one mapping of a driver stop (past the deadline
    /// a 504, otherwise a 422 with its report at the request's fidelity).
    fn stopped(&self, report: SolverReport) -> CalcError {
        Stopped {
            report: report.at(self.level),
        }
        .into()
    }

    /// The held sleeve's orbit by the journal room's code, from its static equilibrium (or the
    /// centre, where it has none).
    fn regular(&self, problem: &Problem) -> Result<Regular, CalcError> {
        let held = orbit::Problem {
            film: OrbitFilm::Short(ShortFilm {
                arc: problem.arc,
                speed_sum: 1.0,
            }),
            mass: problem.mass,
            load: problem.load.clone(),
            force_scale: problem.force_scale,
        };
        let start = problem.equilibrium(true).ok().map(|e| e.position);
        let until = Until::SteadyOrbit {
            tolerance: self.settling.tolerance,
            max_periods: self.settling.max_periods,
        };
        let from = Start {
            position: start.unwrap_or([0.0, 0.0]),
            velocity: [0.0, 0.0],
        };
        let outcome = match orbit::run(
            &held,
            from,
            until,
            self.tolerance,
            self.samples,
            self.budget,
        ) {
            Ok(orbit) => Ok(orbit),
            Err(OrbitError::Contact { time, eccentricity }) => Err((time, eccentricity)),
            Err(OrbitError::Stopped(report)) => return Err(self.stopped(report)),
        };
        Ok(Regular { start, outcome })
    }

    /// The regular block: its steady (or capped) orbit, or its run to the wall.
    fn regular_block(
        &self,
        regular: &Regular,
        c: f64,
        period: f64,
        include_orbit: bool,
    ) -> CompositeOrbitRegular {
        let static_eccentricity_ratio = regular.start.map(|p| p[0].hypot(p[1]));
        match &regular.outcome {
            Ok(orbit) => {
                let w = &orbit.window;
                CompositeOrbitRegular {
                    max_eccentricity_ratio: w.max_eccentricity,
                    min_eccentricity_ratio: Some(w.min_eccentricity),
                    min_film_m: c * (1.0 - w.max_eccentricity),
                    load_cycle_angle_at_min_film_deg: degrees_within(w.time_of_max, period),
                    static_eccentricity_ratio,
                    steady_orbit: orbit.steady,
                    periods_to_settle: orbit.periods,
                    contact_time_s: None,
                    verdict: steady_verdict(
                        orbit.steady,
                        orbit.periods,
                        orbit.period_residual.unwrap_or(0.0),
                    ),
                    orbit: include_orbit.then(|| {
                        self.points(
                            w.samples.iter().map(|&(t, x, y)| (t, [x, y], 0.0)),
                            period,
                            c,
                        )
                    }),
                }
            }
            Err((time, eccentricity)) => CompositeOrbitRegular {
                max_eccentricity_ratio: *eccentricity,
                min_eccentricity_ratio: None,
                min_film_m: c * (1.0 - eccentricity),
                load_cycle_angle_at_min_film_deg: degrees_within(*time, period),
                static_eccentricity_ratio,
                steady_orbit: false,
                periods_to_settle: (time / period).ceil().max(1.0) as u32,
                contact_time_s: Some(time / self.omega),
                verdict: format!(
                    "with the sleeve held the journal cannot carry this load cycle: it reaches the wall at t = {:.6e} s (ε = {eccentricity:.6}){}",
                    time / self.omega,
                    if regular.start.is_none() { ", from the centre: the held film has no static equilibrium under the load at time 0" } else { "" }
                ),
                orbit: None,
            },
        }
    }

    fn points(
        &self,
        samples: impl Iterator<Item = (f64, [f64; 2], f64)>,
        period: f64,
        c: f64,
    ) -> Vec<CompositeOrbitPoint> {
        samples
            .map(|(t, [x, y], xi)| CompositeOrbitPoint {
                time_s: t / self.omega,
                load_cycle_angle_deg: degrees_within(t, period),
                x_m: x * c,
                y_m: y * c,
                eccentricity_ratio: x.hypot(y),
                speed_ratio: xi,
            })
            .collect()
    }
}

/// Add the regular run's work to the composite's report.
fn combined(mut composite: SolverReport, regular: &SolverReport) -> SolverReport {
    composite.iterations += regular.iterations;
    composite.evaluations =
        Some(composite.evaluations.unwrap_or(0) + regular.evaluations.unwrap_or(0));
    if let (Some(c), Some(r)) = (
        composite.time_integration.as_mut(),
        regular.time_integration.as_ref(),
    ) {
        c.rejected_steps += r.rejected_steps;
    }
    composite
}

fn steady_verdict(steady: bool, periods: u32, residual: f64) -> String {
    if steady {
        format!("steady orbit after {periods} load periods (the last period's end repeats within {residual:.1e})")
    } else {
        format!("no steady orbit within {periods} load periods: the state still changes by {residual:.3e} per period (a whirl, a subharmonic or a slow transient); the results describe the last period")
    }
}

impl Calculation for CompositeOrbit {
    const PATH: &'static str = "/v1/composite-bearings/orbit";
    const SUMMARY: &'static str = "Composite bearing (Harnoy) under a dynamic load: the journal locus with the sleeve's speed as a state, beside the same bearing with the sleeve held; ε max/min, minimum films and their ratio, the sleeve speed ratio's range, heat-flux ratio";
    const DESCRIPTION: &'static str = include_str!("orbit.md");
    const FIDELITY: &'static [Level] = &[Level::Fast, Level::Standard, Level::High];
    const EFFECTS: &'static [&'static str] = &[];
    const EXAMPLE: &'static str = r#"{"journal_radius_m": 0.05, "sleeve_length_m": 0.02, "radial_clearance_m": 5e-5, "lubricant": {"viscosity_pa_s": 0.01}, "journal_speed_rpm": 3000, "journal_mass_kg": 500, "sleeve_inertia_kg_m2": 1.6e-5, "restraint_coefficient_kg_m2": 1.6e-5, "load": {"kind": "sinusoidal", "static_n": 10000, "amplitude_n": 10000, "frequency_ratio": 2, "direction_deg": -90}, "film_model": "short_fixed_arc", "fidelity": "standard"}"#;

    type Input = CompositeOrbitInput;
    type Output = CompositeOrbitOutput;

    fn run(case: CompositeOrbitCase, ctx: &mut Context) -> Result<CompositeOrbitOutput, CalcError> {
        let Bearing {
            film,
            restraint,
            journal_speed: w,
            viscosity,
        } = case.bearing;
        for (code, message) in &viscosity.assumptions {
            ctx.warn(code, message.clone());
        }
        let SleeveFilm {
            radius: r,
            length: l,
            clearance: c,
            viscosity: mu,
        } = film;
        let l_over_d = l / (2.0 * r);
        if l_over_d > SHORT_L_OVER_D {
            ctx.warn(
                "short_bearing_beyond_validity",
                format!("L/D = {l_over_d:.3}: the short-bearing film overestimates the load capacity above L/D ≈ 0.5 (Ocvirk); both loci's ε are then too small"),
            );
        }
        let scales = Scales::of(mu, r, l, c, w);
        let force_scale = scales.force;
        let sleeve = SleeveGroups::of(&film, &restraint, case.inertia, w);
        let problem = Problem {
            arc: case.arc,
            mass: scales.mass(case.mass),
            load: case.load.clone(),
            force_scale,
            sleeve,
        };
        let period = case.load.period();
        let horizon = MAX_REVOLUTIONS * 2.0 * PI;
        let run = Run {
            settling: Settling {
                tolerance: 100.0 * case.tolerance,
                max_periods: MAX_PERIODS.min((horizon / period).floor().max(1.0) as u32),
            },
            tolerance: case.tolerance,
            level: case.level,
            samples: if case.include_orbit { ORBIT_POINTS } else { 0 },
            budget: &ctx.budget(),
            omega: w,
        };
        let started = std::time::Instant::now();
        let start: Equilibrium = problem.equilibrium(false).map_err(|e| match e {
            LoadError::TooHeavy { max_load } => {
                let load = case.load.force(0.0);
                CalcError::impossible(
                    "/load",
                    format!(
                        "no static equilibrium to start from: the load at time 0, {:.6e} N, exceeds the most the composite film carries short of contact ({:.6e} N) — lower the load, raise the speed, the viscosity or the sleeve length",
                        load[0].hypot(load[1]),
                        max_load * force_scale
                    ),
                )
            }
            LoadError::Search(e) => CalcError::from_root("composite_equilibrium_search", e),
        })?;
        let composite: Locus = locus::run(&problem, start, run.settling, run.tolerance, run.samples, run.budget)
            .map_err(|e| match e {
                OrbitError::Contact { time, eccentricity } => CalcError::impossible(
                    "/load",
                    format!(
                        "the composite bearing's journal reaches the wall at t = {:.6e} s (ε = {eccentricity:.6}): its film cannot carry this load cycle — lower the load, raise the speed, viscosity or length",
                        time / w
                    ),
                ),
                OrbitError::Stopped(report) => run.stopped(report),
            })?;
        let regular = run.regular(&problem)?;
        let mut report = composite.report.clone();
        if let Ok(orbit) = &regular.outcome {
            report = combined(report, &orbit.report);
        }
        let mut report = report.at(case.level);
        report.elapsed_ms = started.elapsed().as_secs_f64() * 1e3;
        ctx.report(report);
        let regular = run.regular_block(&regular, c, period, case.include_orbit);

        let cw = &composite.window;
        let composite_film = c * (1.0 - cw.max_eccentricity);
        let composite_verdict = steady_verdict(
            composite.steady,
            composite.periods,
            composite.period_residual,
        );
        if cw.max_eccentricity > 0.99 {
            ctx.warn(
                "film_thinner_than_1_percent_of_clearance",
                format!(
                    "the composite bearing's ε_max = {:.5}: h_min = {composite_film:.3e} m, likely below the surfaces' roughness (mixed lubrication, not modelled)",
                    cw.max_eccentricity
                ),
            );
        }
        if !composite.steady {
            ctx.warn("no_steady_orbit", composite_verdict.clone());
        }
        if regular.contact_time_s.is_some() {
            ctx.warn("regular_bearing_touches", regular.verdict.clone());
        }
        if cw.min_speed_ratio < 0.0 {
            ctx.warn(
                "sleeve_reverses",
                format!("the sleeve turns backwards over part of the cycle (ξ_min = {:.4}): its rotation lags the load (Harnoy §18.5, spec B.3 item 4)", cw.min_speed_ratio),
            );
        } else if cw.min_speed_ratio > 0.0 && rpm(cw.min_speed_ratio * w) < LOW_SLEEVE_RPM {
            ctx.warn(
                "low_sleeve_speed",
                format!("the sleeve slows to {:.1} rpm over the cycle: below about {LOW_SLEEVE_RPM} rpm the rolling bearing's EHL film is poor and its friction higher (Harnoy §18.6, Fig 18-4)", rpm(cw.min_speed_ratio * w)),
            );
        }
        let slowest = if cw.min_speed_ratio <= 0.0 && cw.max_speed_ratio >= 0.0 {
            0.0
        } else {
            cw.min_speed_ratio.abs().min(cw.max_speed_ratio.abs())
        };
        let composite_points = case.include_orbit.then(|| {
            run.points(
                cw.samples
                    .iter()
                    .map(|s| (s.time, s.position, s.speed_ratio)),
                period,
                c,
            )
        });
        let output = CompositeOrbitOutput {
            min_film_ratio: regular
                .contact_time_s
                .is_none()
                .then(|| composite_film / regular.min_film_m),
            regular,
            composite: CompositeOrbitSleeve {
                max_eccentricity_ratio: cw.max_eccentricity,
                min_eccentricity_ratio: cw.min_eccentricity,
                min_film_m: composite_film,
                load_cycle_angle_at_min_film_deg: degrees_within(cw.time_of_max, period),
                min_speed_ratio: cw.min_speed_ratio,
                max_speed_ratio: cw.max_speed_ratio,
                mean_speed_ratio: cw.mean_speed_ratio,
                mean_sleeve_speed_rpm: rpm(cw.mean_speed_ratio * w),
                mean_heat_flux_ratio: 1.0 - cw.mean_speed_ratio,
                static_eccentricity_ratio: start.position[0].hypot(start.position[1]),
                static_speed_ratio: start.speed_ratio,
                steady_orbit: composite.steady,
                periods_to_settle: composite.periods,
                verdict: composite_verdict,
                orbit: composite_points,
            },
            sleeve_peclet_number: case
                .thermal
                .map(|thermal| peclet_number(&film, thermal, slowest * w)),
            mass_parameter: problem.mass,
            force_scale_n: force_scale,
            sleeve_drive_parameter: sleeve.drive,
            sleeve_restraint_parameter: sleeve.restraint,
            rolling_friction_parameter: sleeve.rolling,
            restraint_coefficient_kg_m2: restraint.coefficient,
            peak_load_n: case.load.peak(),
            viscosity_pa_s: mu,
        };
        CalcError::finite_or_out_of_range(output, "the load, speed, inertia and geometry")
    }
}

#[cfg(test)]
#[path = "orbit_tests.rs"]
mod tests;
