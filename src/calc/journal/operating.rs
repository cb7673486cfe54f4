//! From a parsed request to the plain bearing's dimensional result: viscosity at the effective
//! temperature, equilibrium, outputs, dynamic coefficients and the stability threshold, with
//! every effect decided and reported.

use std::f64::consts::PI;

use super::closed_form;
use super::dynamics::{self, Coefficients};
use super::feed::{self, Feed, Flows};
use super::film::{FeedLine, FilmModel, Port, Supply};
use super::performance::{self, Approximation, Method, Point, MAX_ECCENTRICITY};
use crate::calc::lubricant::model::TemperatureLaw;
use crate::calc::lubricant::Lubricant;
use crate::calc::{Budget, CalcError, Warning};
use crate::effects::{Criterion, Decision, Mode};
use crate::fidelity::SolverReport;
use crate::numerics::roots::{brent, RootError, Stopping};

/// Standard gravity, m/s² (the default rotor mass is W/g).
const GRAVITY: f64 = 9.80665;
/// Film Reynolds number above which the film turns turbulent (Khonsari & Booser §6, 1000–2000).
const TURBULENT_REYNOLDS: f64 = 1000.0;
/// Largest oil temperature rise the effective-temperature search considers, K (far beyond
/// where any oil or bearing metal survives).
const MAX_TEMPERATURE_RISE_K: f64 = 400.0;
/// Inlet temperature when none is given, °C.
const DEFAULT_INLET_C: f64 = 40.0;

#[derive(Debug, Clone, Copy)]
pub struct Geometry {
    pub diameter_m: f64,
    pub length_m: f64,
    pub radial_clearance_m: f64,
}

impl Geometry {
    fn l_over_d(&self) -> f64 {
        self.length_m / self.diameter_m
    }
    fn r_over_c(&self) -> f64 {
        0.5 * self.diameter_m / self.radial_clearance_m
    }
}

#[derive(Debug, Clone, Copy)]
pub enum Given {
    Load(f64),
    Eccentricity(f64),
}

/// The validated plain-bearing case.
#[derive(Debug, Clone)]
pub struct Case {
    pub geometry: Geometry,
    pub speed_rpm: f64,
    pub lubricant: Lubricant,
    pub given: Given,
    pub inlet_temperature_c: Option<f64>,
    pub feed: Option<Feed>,
    /// Bearing arc, rad, centred on the load line; None for 360°.
    pub arc: Option<f64>,
    /// (ε′, direction of the tilt from the load line, rad); None when aligned.
    pub misalignment: Option<(f64, f64, bool)>,
    pub rotor_mass_kg: Option<f64>,
    /// Shaft stiffness in series with the film, N/m (None: rigid).
    pub shaft_stiffness_n_m: Option<f64>,
    pub method: Method,
    pub effects: Effects,
    pub dynamics: bool,
    pub include_field: bool,
    /// Decided in [`solve`] from the film Reynolds number: the Ng–Pan turbulent film applies.
    pub turbulent: bool,
}

/// How the film cavitates: the model's reading of the request's cavitation mode.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Cavitation {
    /// The Reynolds condition.
    #[default]
    Auto,
    /// The Reynolds condition.
    On,
    /// No cavitation: the full Sommerfeld film.
    Off,
    /// The Reynolds (Swift–Stieber) condition, p ≥ 0.
    Reynolds,
    /// Mass-conserving Jakobsson–Floberg–Olsson cavitation.
    Jfo,
}

impl Cavitation {
    /// The auto/on/off mode an effect report carries.
    pub fn mode(self) -> Mode {
        match self {
            Cavitation::Auto => Mode::Auto,
            Cavitation::Off => Mode::Off,
            _ => Mode::On,
        }
    }
}

/// The effect modes the plain bearing understands (misalignment is decided from the geometry).
#[derive(Debug, Clone, Copy, Default)]
pub struct Effects {
    pub thermal: Mode,
    pub cavitation: Cavitation,
    pub turbulence: Mode,
    pub inertia: Mode,
}

/// What the model says beside its numbers, in the order it said it: the decision on each effect
/// and the warnings (the caller records them).
#[derive(Debug, Clone, Default)]
pub struct Notes {
    pub decisions: Vec<(&'static str, Decision)>,
    pub warnings: Vec<Warning>,
}

impl Notes {
    fn decide(&mut self, effect: &'static str, decision: Decision) {
        self.decisions.push((effect, decision));
    }
    fn warn(&mut self, code: &'static str, message: impl Into<String>) {
        self.warnings.push(Warning {
            code,
            message: message.into(),
        });
    }
}

/// The plain bearing solved: dimensional results in SI units, angles in radians from h_max in
/// the direction of rotation (Table 8.6 conventions; S and P̄ with N_s in rev/s).
#[derive(Debug, Clone)]
pub struct Solution {
    /// Steady load W, N (the whole bearing's).
    pub load_n: f64,
    pub sommerfeld_number: f64,
    pub eccentricity_ratio: f64,
    /// φ, between the load line and the line of centres, rad.
    pub attitude_angle: f64,
    pub min_film_thickness_m: f64,
    /// Peak film pressure, Pa gauge (with the supply pressure unless the film holds it).
    pub max_pressure_pa: f64,
    /// P̄_max = p_max (C/R)²/(μ N_s).
    pub max_pressure_nd: f64,
    /// Angle of the peak, rad.
    pub max_pressure_angle: f64,
    /// Film rupture angle, rad; None for a full film.
    pub cavitation_start_angle: Option<f64>,
    pub cavitated_area_fraction: Option<f64>,
    pub petroff_friction_coefficient: f64,
    pub friction_coefficient: f64,
    /// (R/C) f.
    pub friction_parameter: f64,
    pub friction_torque_n_m: f64,
    pub power_loss_w: f64,
    pub side_leakage_m3_s: f64,
    /// Q_L/((π/2) N_s D L C).
    pub side_leakage_nd: f64,
    pub inlet_flow_m3_s: Option<f64>,
    pub temperature_rise_k: Option<f64>,
    /// Jang & Khonsari's THD temperatures, for temperature-dependent lubricants.
    pub bush_temperatures: Option<BushTemperatures>,
    /// Martin's flows, with a feed (not for a JFO film fed through ports).
    pub flows: Option<Flows>,
    pub effective_temperature_c: f64,
    pub effective_viscosity_pa_s: f64,
    /// Film Reynolds number ρ U C/μ.
    pub reynolds_number: f64,
    /// The closed form used, by name; None for the numerical solution.
    pub approximation: Option<&'static str>,
    pub approximation_note: Option<String>,
    /// Mid-plane pressure profile, when asked and numerical.
    pub pressure_profile: Option<Vec<ProfileNode>>,
    /// The film's moment on a misaligned journal.
    pub moment: Option<Moment>,
    /// Stiffness, damping and stability, when asked and available.
    pub dynamics: Option<Dynamics>,
    pub report: SolverReport,
    pub notes: Notes,
}

/// Jang & Khonsari's maximum bush and shaft temperatures, °C.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BushTemperatures {
    pub max_c: f64,
    pub shaft_c: f64,
}

/// One node of the mid-plane pressure profile.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ProfileNode {
    /// θ from h_max, rad.
    pub angle: f64,
    /// Film pressure, Pa.
    pub pressure_pa: f64,
    /// Film content θ_f (mass-conserving films).
    pub film_content: Option<f64>,
}

/// The film's moment on a misaligned journal, about the bearing centre, in the load frame (x
/// along the static load, y 90° ahead in the rotation, z along the spin).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Moment {
    pub mx_n_m: f64,
    pub my_n_m: f64,
    pub magnitude_n_m: f64,
    /// (M_x, M_y)/(μ N_s (R/C)² R L²).
    pub nd: [f64; 2],
    /// The component against the tilt, N·m (positive: the film resists the misalignment).
    pub restoring_n_m: f64,
}

/// Stiffness and damping in the load frame, [xx, xy, yx, yy], and the rotor's stability.
#[derive(Debug, Clone)]
pub struct Dynamics {
    pub stiffness_n_m: [f64; 4],
    pub damping_n_s_m: [f64; 4],
    /// K_ij C/W.
    pub stiffness_nd: [f64; 4],
    /// C_ij C ω/W.
    pub damping_nd: [f64; 4],
    pub method: CoefficientsMethod,
    pub stability: RotorStability,
}

/// How the dynamic coefficients were obtained.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CoefficientsMethod {
    /// The short (Ocvirk) bearing's closed form with the half-Sommerfeld film.
    ShortBearing,
    /// Perturbation of the converged Reynolds film.
    Perturbation,
    /// Perturbation of the converged mass-conserving (JFO) film.
    PerturbationMassConserving,
}

/// Rigid-rotor stability (Lund's linearised threshold).
#[derive(Debug, Clone)]
pub struct RotorStability {
    pub stable_at_operating_speed: bool,
    pub threshold_speed_rpm: Option<f64>,
    pub whirl_frequency_ratio: Option<f64>,
    /// m C ω²/W at the threshold.
    pub critical_mass_parameter: Option<f64>,
    pub critical_speed_rad_s: Option<f64>,
    /// ω_c (C/g)^½.
    pub critical_speed_nd: Option<f64>,
    /// The rotor's m C ω²/W at the operating speed.
    pub mass_parameter: f64,
    pub rotor_mass_kg: f64,
    /// The verdict in words.
    pub statement: String,
}

/// A solved operating point at one viscosity.
#[derive(Debug, Clone)]
struct Operating {
    point: Point,
    load_n: f64,
    viscosity_pa_s: f64,
    temperature_c: f64,
    /// Equilibrium iterations (0 when ε was given).
    evaluations: u32,
}

impl Case {
    fn speed_rps(&self) -> f64 {
        self.speed_rpm / 60.0
    }
    /// μ N_s L D (R/C)²: S·W.
    fn load_scale(&self, mu: f64) -> f64 {
        let g = self.geometry;
        mu * self.speed_rps() * g.length_m * g.diameter_m * g.r_over_c().powi(2)
    }
    fn cavitation(&self) -> bool {
        self.effects.cavitation != Cavitation::Off
    }

    /// Mass-conserving cavitation, and its supply at oil temperature t: without a feed (or with a
    /// circumferential groove, or on a partial arc) a flooded line at h_max at the edges'
    /// pressure; a hole or axial groove(s) as ports at supply pressure in a periodic film,
    /// where the feed sits (opposite the load, at h_max, or two grooves at ±90°).
    fn supply(&self, t: f64) -> Option<Supply> {
        if self.effects.cavitation != Cavitation::Jfo {
            return None;
        }
        let g = self.geometry;
        let pressure_scale =
            self.lubricant.viscosity_pa_s(t) * self.speed_rps() * g.r_over_c().powi(2);
        let at = |position: feed::FeedPosition| match position {
            feed::FeedPosition::OppositeLoad => FeedLine::OppositeLoad,
            feed::FeedPosition::AtMaxFilm => FeedLine::MaxFilm,
        };
        let port = |length_ratio: f64, width_m: f64, p_s: f64| Port {
            length_ratio,
            width: 2.0 * width_m / g.diameter_m,
            pressure_bar: p_s / pressure_scale,
        };
        Some(match self.feed {
            _ if self.arc.is_some() => Supply::line(FeedLine::MaxFilm),
            Some(Feed::Hole {
                position,
                supply_pressure_pa,
                hole_over_length,
            }) => Supply {
                position: at(position),
                port: Some(port(
                    hole_over_length,
                    hole_over_length * g.length_m,
                    supply_pressure_pa,
                )),
            },
            Some(Feed::AxialGroove {
                position,
                supply_pressure_pa,
                length_ratio,
                width_over_diameter,
            }) => Supply {
                position: at(position),
                port: Some(port(
                    length_ratio,
                    width_over_diameter * g.diameter_m,
                    supply_pressure_pa,
                )),
            },
            Some(Feed::TwoAxialGrooves {
                supply_pressure_pa,
                length_ratio,
                width_over_diameter,
            }) => Supply {
                position: FeedLine::TwoGrooves,
                port: Some(port(
                    length_ratio,
                    width_over_diameter * g.diameter_m,
                    supply_pressure_pa,
                )),
            },
            Some(Feed::CircumferentialGroove { .. }) | None => Supply::line(FeedLine::MaxFilm),
        })
    }

    fn mass_conserving(&self) -> bool {
        self.cavitation() && self.effects.cavitation == Cavitation::Jfo
    }

    /// Whether the film's pressures are above ambient with the supply in them (JFO ports)
    /// rather than relative to the supply pressure.
    fn ported(&self) -> bool {
        self.supply(DEFAULT_INLET_C)
            .is_some_and(|s| s.port.is_some())
    }

    /// Film Reynolds number ρ U C/μ at temperature t.
    fn film_reynolds(&self, t: f64) -> f64 {
        let g = self.geometry;
        self.lubricant.density_kg_m3(t)
            * PI
            * g.diameter_m
            * self.speed_rps()
            * g.radial_clearance_m
            / self.lubricant.viscosity_pa_s(t)
    }

    /// The film model at oil temperature t.
    fn physics(&self, t: f64) -> FilmModel {
        FilmModel {
            cavitation: self.cavitation(),
            turbulence_reynolds: self.turbulent.then(|| self.film_reynolds(t)),
            arc: self.arc,
            misalignment: self.misalignment,
            mass_conserving: self.supply(t),
        }
    }

    fn operate(&self, temperature_c: f64, budget: &Budget) -> Result<Operating, CalcError> {
        let mu = self.lubricant.viscosity_pa_s(temperature_c);
        if !(mu.is_finite() && mu > 0.0 && self.lubricant.density_kg_m3(temperature_c) > 0.0) {
            return Err(CalcError::impossible(
                "/inlet_temperature_c",
                format!("the lubricant's laws have no value at {temperature_c:.1} °C"),
            ));
        }
        let scale = self.load_scale(mu);
        let l_over_d = self.geometry.l_over_d();
        let mut alive = || budget.alive();
        let (point, load_n, evaluations) = match self.given {
            Given::Load(w) => {
                let (p, n) = performance::equilibrium(
                    scale / w,
                    l_over_d,
                    self.method,
                    self.physics(temperature_c),
                    &mut alive,
                )?;
                (p, w, n)
            }
            Given::Eccentricity(eps) => {
                let p = performance::at_eccentricity(
                    eps,
                    l_over_d,
                    self.method,
                    self.physics(temperature_c),
                    &mut alive,
                )?;
                let w = scale / p.sommerfeld_number;
                (p, w, 0)
            }
        };
        Ok(Operating {
            point,
            load_n,
            viscosity_pa_s: mu,
            temperature_c,
            evaluations,
        })
    }

    /// Friction power E_p = F U, W.
    fn power_loss(&self, op: &Operating) -> f64 {
        let g = self.geometry;
        let friction = op.point.friction_parameter / g.r_over_c() * op.load_n;
        friction * PI * g.diameter_m * self.speed_rps()
    }

    fn side_leakage(&self, op: &Operating) -> f64 {
        let g = self.geometry;
        op.point.side_leakage_bar
            * 0.5
            * PI
            * self.speed_rps()
            * g.diameter_m
            * g.length_m
            * g.radial_clearance_m
    }

    /// Martin's flows when the request gives a feed (the supply at the inlet temperature). None
    /// for a JFO film fed through ports: its ports already hold the supply pressure, so its side
    /// leakage is the whole supply (reported as `inlet_flow_m3_s`), and adding Martin's
    /// pressure-fed flow to it would count that flow twice.
    fn flows(&self, op: &Operating) -> Option<Flows> {
        if self.ported() {
            return None;
        }
        let t_in = self.inlet_temperature_c.unwrap_or(DEFAULT_INLET_C);
        self.feed.map(|feed| {
            let g = self.geometry;
            let p = &op.point;
            feed::flows(
                feed,
                feed::FlowPoint {
                    leakage: self.side_leakage(op),
                    diameter_m: g.diameter_m,
                    l_over_d: g.l_over_d(),
                    clearance_m: g.radial_clearance_m,
                    mu_inlet: self.lubricant.viscosity_pa_s(t_in),
                    eps: p.eccentricity_ratio,
                    attitude: p.attitude_angle,
                },
            )
        })
    }

    /// ΔT = E_p/(ρ c_p Q) (Eq. 8.44), Q the total flow with a feed (Martin, as in Ex 8.4), else
    /// the side leakage (Table 8.6; with JFO ports the leakage is the whole supply); None
    /// without flow (the long-bearing closed form).
    fn temperature_rise(&self, op: &Operating) -> Option<f64> {
        let q = self
            .flows(op)
            .map_or_else(|| self.side_leakage(op), |f| f.total);
        let t = op.temperature_c;
        let heat = self.lubricant.density_kg_m3(t) * self.lubricant.specific_heat_j_kg_k(t) * q;
        (q > 0.0 && heat > 0.0).then(|| self.halves() * self.power_loss(op) / heat)
    }

    /// 2 when a circumferential groove splits the bearing into halves (each solved as a bearing
    /// of the land length carrying half the load), else 1.
    fn halves(&self) -> f64 {
        if self.feed.is_some_and(|f| f.halves()) {
            2.0
        } else {
            1.0
        }
    }

    /// k in T_e = T_in + k ΔT: 1 (Eq. 8.63, heat to the housing neglected for D > 2 in), ½ for
    /// smaller bearings (Eq. 8.64).
    fn effective_fraction(&self) -> f64 {
        if self.geometry.diameter_m >= 0.0508 {
            1.0
        } else {
            0.5
        }
    }
}

/// The plain bearing at its operating point: every effect decided, the equilibrium, the
/// dimensional outputs and (when asked) the dynamics; `budget` stops a late request.
pub fn solve(case: &Case, budget: &Budget) -> Result<Solution, CalcError> {
    let mut notes = Notes::default();
    let notes = &mut notes;
    let lub = &case.lubricant;
    let t_in = case.inlet_temperature_c.unwrap_or(DEFAULT_INLET_C);
    let temperature_dependent = !matches!(lub.temperature_law, TemperatureLaw::Constant { .. });
    if case.inlet_temperature_c.is_none() && temperature_dependent {
        notes.warn(
            "inlet_temperature_assumed",
            format!("inlet_temperature_c not given: {DEFAULT_INLET_C} °C assumed"),
        );
    }
    for (code, message) in &lub.assumptions {
        notes.warn(code, message.clone());
    }
    let mu_in = lub.viscosity_pa_s(t_in);
    if !(mu_in.is_finite() && mu_in > 0.0) {
        return Err(CalcError::impossible(
            "/inlet_temperature_c",
            "the lubricant's viscosity law has no value at this temperature",
        ));
    }

    let mut case = case.clone();
    case.turbulent = decide_turbulence(notes, &case, case.film_reynolds(t_in));
    let case = &case;
    let isothermal = case.operate(t_in, budget)?;
    let mut op = isothermal.clone();
    let k = case.effective_fraction();
    match (temperature_dependent, case.temperature_rise(&isothermal)) {
        (false, _) => notes.decide(
            "thermal",
            Decision::not_applicable(
                case.effects.thermal,
                "the lubricant's viscosity does not depend on temperature",
            ),
        ),
        (true, None) => notes.decide(
            "thermal",
            Decision::not_applicable(
                case.effects.thermal,
                "no side leakage in the long-bearing closed form: the heat balance has no flow",
            ),
        ),
        (true, Some(rise)) => {
            let drop = 1.0 - lub.viscosity_pa_s(t_in + k * rise) / mu_in;
            let criterion = Criterion {
                name: "viscosity_drop_over_temperature_rise",
                value: drop,
                threshold: 0.05,
            };
            let decision = Decision::decide(case.effects.thermal, criterion, "thermal");
            if decision.applied {
                op = effective_temperature(case, t_in, k * rise, budget)?;
            }
            notes.decide("thermal", decision);
        }
    }

    let thd = if temperature_dependent {
        thd_temperatures(notes, case, t_in, isothermal.point.eccentricity_ratio)
    } else {
        None
    };
    let g = case.geometry;
    let point = &op.point;
    let n_s = case.speed_rps();
    let mu = op.viscosity_pa_s;
    let rho = lub.density_kg_m3(op.temperature_c);
    let u = PI * g.diameter_m * n_s;
    let reynolds = rho * u * g.radial_clearance_m / mu;
    decide_inertia(notes, case.effects, reynolds, g);
    let cavitation = Decision {
        applied: case.cavitation(),
        mode: case.effects.cavitation.mode(),
        reason: match (case.cavitation(), case.supply(op.temperature_c)) {
            (false, _) => "requested off: full Sommerfeld film, negative pressures kept".into(),
            (true, None) => "Reynolds (Swift–Stieber) condition: p ≥ 0, the film ruptures where the pressure and its gradient vanish (auto keeps it; `jfo` conserves mass through rupture and reformation)".into(),
            (true, Some(supply)) => format!(
                "mass-conserving JFO cavitation (Elrod–Adams film content, finite volumes): rupture and reformation conserve mass; fed {}",
                match (supply.position, supply.port) {
                    (FeedLine::MaxFilm, None) => "flooded along a line at h_max".to_string(),
                    (FeedLine::OppositeLoad, None) => "flooded along a line opposite the load".to_string(),
                    (position, Some(port)) => format!(
                        "through the feed at {} at P̄_s = {:.4} (supply pressure), a periodic 360° film elsewhere",
                        match position {
                            FeedLine::MaxFilm => "h_max",
                            FeedLine::OppositeLoad => "the top, opposite the load",
                            FeedLine::TwoGrooves => "±90° to the load line",
                        },
                        port.pressure_bar
                    ),
                    (FeedLine::TwoGrooves, None) => "through two grooves".to_string(),
                }
            ),
        },
        criterion: None,
        model: case
            .cavitation()
            .then_some(if case.mass_conserving() { "jfo" } else { "reynolds" }),
    };
    if case.mass_conserving() && matches!(case.feed, Some(Feed::CircumferentialGroove { .. })) {
        notes.warn("jfo_circumferential_groove", "circumferential groove: each land's mass-conserving film is fed along a line at h_max at the edges' pressure, as the Reynolds model is; the groove's supply pressure is not applied at the land's edge");
    }
    notes.decide("cavitation", cavitation);
    notes.decide(
        "misalignment",
        match case.misalignment {
            None => Decision::not_applicable(Mode::Auto, "the request gives no misalignment: journal aligned"),
            Some((e, dir, from_centres)) => Decision {
                applied: true,
                mode: Mode::On,
                reason: format!(
                    "journal tilted {:.1}° from the {}: the ends' centres differ by ε′ = {e:.4} of the clearance (Khonsari & Booser Eq. 8.70); whole-length film, h_min at an end",
                    dir.to_degrees(),
                    if from_centres { "line of centres" } else { "load line" }
                ),
                criterion: None,
                model: None,
            },
        },
    );

    validity_warnings(notes, case, point);

    let power = case.power_loss(&op);
    let flows = case.flows(&op);
    // The Reynolds film's pressures are relative to the supply's; a ported JFO film holds it.
    let supply_pressure = if case.ported() {
        0.0
    } else {
        case.feed.map_or(0.0, |f| f.supply_pressure_pa())
    };
    // A circumferential groove makes two half-bearings: the solve is of one half.
    let halves = case.halves();
    let friction = point.friction_parameter / g.r_over_c();
    let rise = case.temperature_rise(&op);
    if rise.is_none() {
        notes.warn("no_temperature_rise", "the long-bearing closed form has no side leakage, so no adiabatic temperature rise; use a numerical fidelity");
    }
    let pressure_scale = mu * n_s * g.r_over_c().powi(2);
    let flow_scale = 0.5 * PI * n_s * g.diameter_m * g.length_m * g.radial_clearance_m;

    let dynamics = if case.dynamics {
        dynamic_coefficients(case, &op, budget, notes)?
    } else {
        None
    };
    let mut solution = Solution {
        load_n: halves * op.load_n,
        sommerfeld_number: point.sommerfeld_number,
        eccentricity_ratio: point.eccentricity_ratio,
        attitude_angle: point.attitude_angle,
        min_film_thickness_m: g.radial_clearance_m * point.min_film_bar,
        max_pressure_pa: point.max_pressure_bar * pressure_scale + supply_pressure,
        max_pressure_nd: point.max_pressure_bar,
        max_pressure_angle: point.max_pressure_angle,
        cavitation_start_angle: point.cavitation_angle,
        cavitated_area_fraction: point.cavitated_fraction,
        friction_coefficient: friction,
        friction_parameter: point.friction_parameter,
        friction_torque_n_m: halves * friction * op.load_n * 0.5 * g.diameter_m,
        power_loss_w: halves * power,
        side_leakage_m3_s: point.side_leakage_bar * flow_scale,
        side_leakage_nd: point.side_leakage_bar,
        inlet_flow_m3_s: point
            .inlet_flow_bar
            .filter(|_| halves == 1.0)
            .map(|q| q * flow_scale),
        temperature_rise_k: rise,
        bush_temperatures: thd,
        flows,
        effective_temperature_c: op.temperature_c,
        effective_viscosity_pa_s: mu,
        reynolds_number: reynolds,
        approximation: approximation_name(case),
        approximation_note: approximation_note(case),
        petroff_friction_coefficient: 2.0 * PI * PI * point.sommerfeld_number / g.r_over_c(),
        pressure_profile: if case.include_field {
            point.midplane.as_ref().map(|m| {
                m.iter()
                    .enumerate()
                    .map(|(i, &(theta, p))| ProfileNode {
                        angle: theta,
                        pressure_pa: p * pressure_scale,
                        film_content: point
                            .midplane_content
                            .as_ref()
                            .and_then(|c| c.get(i).copied()),
                    })
                    .collect()
            })
        } else {
            None
        },
        moment: point.moment_bar.map(|m| {
            let scale = pressure_scale * 0.5 * g.diameter_m * g.length_m * g.length_m;
            let (mx, my) = (m[0] * scale, m[1] * scale);
            // The tilt direction u in the load frame; the tilt is a rotation about z × u.
            let (_, dir, from_centres) = case.misalignment.unwrap_or_default();
            let towards = if from_centres {
                // From the line of centres (h_min lies φ ahead of the load line).
                dir + point.attitude_angle
            } else {
                dir
            };
            let axis = [-towards.sin(), towards.cos()];
            Moment {
                mx_n_m: mx,
                my_n_m: my,
                magnitude_n_m: mx.hypot(my),
                nd: m,
                restoring_n_m: -(mx * axis[0] + my * axis[1]),
            }
        }),
        dynamics: None,
        report: report(case, point, op.evaluations),
        notes: Notes::default(),
    };
    if let Some((coefficients, stability)) = dynamics {
        let (w, c, omega) = (halves * op.load_n, g.radial_clearance_m, 2.0 * PI * n_s);
        solution.dynamics = Some(Dynamics {
            stiffness_n_m: coefficients.stiffness.map(|v| v * w / c),
            damping_n_s_m: coefficients.damping.map(|v| v * w / (c * omega)),
            stiffness_nd: coefficients.stiffness,
            damping_nd: coefficients.damping,
            method: match case.method {
                Method::ClosedForm(_) => CoefficientsMethod::ShortBearing,
                Method::Numerical { .. } if case.mass_conserving() => {
                    CoefficientsMethod::PerturbationMassConserving
                }
                Method::Numerical { .. } => CoefficientsMethod::Perturbation,
            },
            stability,
        });
    }
    solution.notes = std::mem::take(notes);
    Ok(solution)
}

/// Jang & Khonsari's THD fits for the maximum bush and the shaft temperature (Khonsari & Booser
/// Eq. 8.65, Table 8.11): T̄ = β (T − T_in), κ1 = (α_t μ_i β U/(k R))(R/C)², κ2 = U (μ_i β/k)^½,
/// T̄_max = exp[a + b/√κ1 + c/√κ2], T̄_shaft = 1/[a + b/√κ1 + c/κ2²], the region by the isothermal ε.
/// β is −d ln μ/dT at the inlet (exact for the exponential law).
fn thd_temperatures(
    notes: &mut Notes,
    case: &Case,
    t_in: f64,
    eps: f64,
) -> Option<BushTemperatures> {
    let lub = &case.lubricant;
    let g = case.geometry;
    let mu = lub.viscosity_pa_s(t_in);
    let beta = (lub.viscosity_pa_s(t_in - 0.5) / lub.viscosity_pa_s(t_in + 0.5)).ln();
    let k = lub.thermal_conductivity_w_m_k(t_in);
    let diffusivity = k / (lub.density_kg_m3(t_in) * lub.specific_heat_j_kg_k(t_in));
    let u = PI * g.diameter_m * case.speed_rps();
    let r = 0.5 * g.diameter_m;
    let kappa1 = diffusivity * mu * beta * u / (k * r) * g.r_over_c().powi(2);
    let kappa2 = u * (mu * beta / k).sqrt();
    if !(beta > 0.0 && kappa1.is_finite() && kappa2.is_finite()) {
        return None;
    }
    let (max, shaft) = match eps {
        e if e < 0.3 => ((1.63105, -0.20250, -0.84050), (0.14092, 0.24303, 0.10054)),
        e if e <= 0.7 => ((1.68517, -0.19962, -1.04999), (0.04734, 0.39751, 0.11007)),
        _ => ((1.79973, -0.13627, -1.25216), (0.06200, 0.38264, 0.10102)),
    };
    let t_max = (max.0 + max.1 / kappa1.sqrt() + max.2 / kappa2.sqrt()).exp();
    let t_shaft = 1.0 / (shaft.0 + shaft.1 / kappa1.sqrt() + shaft.2 / (kappa2 * kappa2));
    let in_range = (0.001..=0.5).contains(&kappa1)
        && (0.01..=5.0).contains(&kappa2)
        && (0.1..=0.9).contains(&eps);
    if !in_range || (g.l_over_d() - 1.0).abs() > 0.5 {
        notes.warn(
            "thd_fit_outside_range",
            format!("Jang–Khonsari's THD fits hold for L/D ≈ 1, 0.001 ≤ κ1 ≤ 0.5, 0.01 ≤ κ2 ≤ 5, 0.1 ≤ ε ≤ 0.9; here L/D = {:.2}, κ1 = {kappa1:.3e}, κ2 = {kappa2:.3e}, ε = {eps:.3}", g.l_over_d()),
        );
    }
    (t_max.is_finite() && t_shaft.is_finite() && t_shaft > 0.0).then(|| BushTemperatures {
        max_c: t_in + t_max / beta,
        shaft_c: t_in + t_shaft / beta,
    })
}

/// Effective temperature: T solves T = T_in + k ΔT(μ(T)) — a bracketed root on [T_in, T_in + k ΔT_iso]
/// (the rise falls as the oil thins, so the bracket holds).
fn effective_temperature(
    case: &Case,
    t_in: f64,
    rise_iso: f64,
    budget: &Budget,
) -> Result<Operating, CalcError> {
    let k = case.effective_fraction();
    let mut failure = None;
    let mut last: Option<Operating> = None;
    let f = |t: f64| -> f64 {
        match case.operate(t, budget) {
            Ok(op) => {
                let rise = case.temperature_rise(&op).unwrap_or(0.0);
                let g = t - t_in - k * rise;
                last = Some(op);
                g
            }
            // Too hot for the model (the thinned oil cannot carry the load, or the viscosity law
            // has no value there): the effective temperature lies below.
            Err(CalcError::Impossible { .. }) if t > t_in => 1e3,
            Err(e) => {
                failure.get_or_insert(e);
                f64::NAN
            }
        }
    };
    let root = brent(
        f,
        t_in,
        t_in + rise_iso.min(MAX_TEMPERATURE_RISE_K),
        Stopping {
            x_tolerance: 1e-3,
            max_iterations: 60,
        },
    );
    if let Some(e) = failure {
        return Err(e);
    }
    match root {
        Ok(r) => case
            .operate(r.x, budget)
            .or_else(|_| last.ok_or(CalcError::Internal("thermal".into()))),
        Err(RootError::NotConverged { iterations, width }) => Err(CalcError::NotConverged {
            method: "brent_effective_temperature",
            iterations,
            residual: width,
        }),
        Err(e) => Err(CalcError::impossible(
            "/inlet_temperature_c",
            format!(
                "no effective temperature in [{t_in:.2}, {:.2}] °C: {e:?}",
                t_in + rise_iso
            ),
        )),
    }
}

/// Turbulence: `auto` applies the Ng–Pan film above a film Reynolds number of 1000 (at the
/// inlet temperature); the closed forms are laminar only.
fn decide_turbulence(notes: &mut Notes, case: &Case, reynolds: f64) -> bool {
    let criterion = Criterion {
        name: "film_reynolds_number",
        value: reynolds,
        threshold: TURBULENT_REYNOLDS,
    };
    let decision = Decision::decide(case.effects.turbulence, criterion, "turbulence");
    if decision.applied && matches!(case.method, Method::ClosedForm(_)) {
        notes.warn(
            "turbulent_film",
            format!("film Reynolds number {reynolds:.0}: the film is turbulent, but the closed forms are laminar and underestimate friction and load capacity; use a numerical fidelity"),
        );
        notes.decide(
            "turbulence",
            Decision {
                applied: false,
                reason: format!("{}; closed forms are laminar", decision.reason),
                ..decision
            },
        );
        return false;
    }
    let applied = decision.applied;
    let reason = if applied {
        format!(
            "{}: linearised turbulent film (Ng–Pan coefficients, Khonsari & Booser Eq. 6.26–6.31)",
            decision.reason
        )
    } else {
        decision.reason.clone()
    };
    notes.decide("turbulence", Decision { reason, ..decision });
    applied
}

fn decide_inertia(notes: &mut Notes, effects: Effects, reynolds: f64, g: Geometry) {
    let reduced = reynolds * g.radial_clearance_m / (0.5 * g.diameter_m);
    let inertia = Decision::decide(
        effects.inertia,
        Criterion {
            name: "reduced_reynolds_number",
            value: reduced,
            threshold: 1.0,
        },
        "inertia",
    );
    if inertia.applied {
        notes.warn("fluid_inertia", format!("reduced Reynolds number {reduced:.2} exceeds 1: fluid inertia matters and is not modelled"));
    }
    notes.decide(
        "inertia",
        Decision {
            applied: false,
            ..inertia
        },
    );
}

fn approximation_name(case: &Case) -> Option<&'static str> {
    let cav = case.cavitation();
    match case.method {
        Method::ClosedForm(Approximation::Short) => Some(if cav {
            "short_half_sommerfeld"
        } else {
            "short_full_sommerfeld"
        }),
        Method::ClosedForm(Approximation::Long) => Some(if cav {
            "long_reynolds"
        } else {
            "long_full_sommerfeld"
        }),
        Method::Numerical { .. } => None,
    }
}

fn approximation_note(case: &Case) -> Option<String> {
    let ld = case.geometry.l_over_d();
    match case.method {
        Method::ClosedForm(Approximation::Short) => Some(if ld <= 0.5 {
            format!("infinitely short bearing (Ocvirk): axial pressure flow dominates; valid for L/D ≤ 0.5, and L/D = {ld:.3} fits")
        } else {
            format!("infinitely short bearing (Ocvirk): chosen for L/D ≤ 1 but valid only to L/D = 0.5; at L/D = {ld:.3} it gives trends, not numbers")
        }),
        Method::ClosedForm(Approximation::Long) => Some(if ld >= 2.0 {
            format!("infinitely long bearing: circumferential flow dominates; it suits L/D ≥ 2 or end-sealed bearings, and L/D = {ld:.3} fits")
        } else {
            format!("infinitely long bearing: it suits L/D ≥ 2; at L/D = {ld:.3} it overestimates the load capacity")
        }),
        Method::Numerical { .. } => None,
    }
}

fn validity_warnings(notes: &mut Notes, case: &Case, point: &Point) {
    let ld = case.geometry.l_over_d();
    match case.method {
        Method::ClosedForm(Approximation::Short) if ld > 0.5 => notes.warn(
            "short_bearing_outside_validity",
            format!("the short-bearing approximation holds for L/D ≤ 0.5 (trends to 1); L/D = {ld:.3}: use a numerical fidelity"),
        ),
        Method::ClosedForm(Approximation::Long) if ld < 2.0 => notes.warn(
            "long_bearing_outside_validity",
            format!("the long-bearing approximation overestimates load capacity below L/D ≈ 2; L/D = {ld:.3}: use a numerical fidelity"),
        ),
        _ => {}
    }
    if point.eccentricity_ratio > 0.95 {
        notes.warn(
            "very_high_eccentricity",
            format!("ε = {:.4}: the minimum film is {:.1} % of the clearance; surface roughness, elastic and thermal distortion matter here", point.eccentricity_ratio, 100.0 * (1.0 - point.eccentricity_ratio)),
        );
    }
}

fn report(case: &Case, point: &Point, evaluations: u32) -> SolverReport {
    match case.method {
        Method::ClosedForm(_) => SolverReport {
            method: format!(
                "closed_form_{}",
                approximation_name(case).unwrap_or_default()
            ),
            iterations: evaluations,
            ..SolverReport::closed_form("closed_form")
        },
        Method::Numerical { level, mesh, .. } => SolverReport {
            method: if case.mass_conserving() {
                "finite_volume_jfo_gauss_seidel"
            } else {
                "finite_volume_psor"
            }
            .into(),
            fidelity: level,
            grid: Some(vec![mesh.circumferential as u32, mesh.axial_half as u32]),
            iterations: point.sweeps,
            residual: point.residual,
            error_estimate: point.error_estimate,
            elapsed_ms: 0.0,
        },
    }
}

/// Coefficients at ε for the case's method (None for the long closed form), and S there.
fn coefficients_at(
    case: &Case,
    method: Method,
    eps: f64,
    physics: FilmModel,
    budget: &Budget,
) -> Result<Option<Coefficients>, CalcError> {
    let ld = case.geometry.l_over_d();
    match method {
        Method::ClosedForm(Approximation::Short) => {
            let (stiffness, damping) = closed_form::short_bearing_dynamic_coefficients(eps);
            let s = closed_form::short_bearing(eps, ld, closed_form::Boundary::HalfSommerfeld)
                .map_or(f64::NAN, |p| p.sommerfeld_number);
            Ok(Some(Coefficients {
                stiffness,
                damping,
                sommerfeld_number: s,
            }))
        }
        Method::ClosedForm(Approximation::Long) => Ok(None),
        Method::Numerical { mesh, stop, .. } => {
            let mut alive = || budget.alive();
            dynamics::perturbation(eps, ld, physics, mesh, stop, &mut alive).map(Some)
        }
    }
}

fn dynamic_coefficients(
    case: &Case,
    op: &Operating,
    budget: &Budget,
    notes: &mut Notes,
) -> Result<Option<(Coefficients, RotorStability)>, CalcError> {
    if !case.cavitation() {
        notes.warn(
            "no_dynamics_full_film",
            "stiffness and damping are given for the cavitating film only",
        );
        return Ok(None);
    }
    let eps = op.point.eccentricity_ratio;
    let physics = case.physics(op.temperature_c);
    let Some(coefficients) = coefficients_at(case, case.method, eps, physics, budget)? else {
        notes.warn("no_dynamics_long_bearing", "the long-bearing closed form has no dynamic coefficients here; use the short form or a numerical fidelity");
        return Ok(None);
    };
    let g = case.geometry;
    let w = op.load_n;
    // Per half-bearing with a circumferential groove: half the rotor on half the load.
    let mass = case
        .rotor_mass_kg
        .map_or(w / GRAVITY, |m| m / case.halves());
    let omega = 2.0 * PI * case.speed_rps();
    let s_op = coefficients.sommerfeld_number;
    let mass_parameter = |omega: f64| mass * g.radial_clearance_m * omega * omega / w;
    // γ = W/(k_s C) with the whole bearing's load and shaft (per half-bearing with a
    // circumferential groove both halve: the same γ).
    let flexibility = case
        .shaft_stiffness_n_m
        .map_or(0.0, |k| case.halves() * w / (k * g.radial_clearance_m));
    let whirl = dynamics::whirl_on_shaft(&coefficients, flexibility);
    let stable_now = whirl
        .critical_mass_parameter
        .is_none_or(|mc| mass_parameter(omega) < mc);

    // Threshold: along the equilibrium locus at fixed load and viscosity, speed is ω(ε) =
    // ω_op S(ε)/S_op; stability margin ln(m̄_c/m̄) changes sign at the threshold.
    // The threshold search walks the locus on the `fast` mesh (a few per cent on the
    // threshold speed, a fraction of the cost); S_op is taken on the same mesh.
    let search = match case.method {
        Method::Numerical { level, stop, .. } => {
            Method::numerical(crate::fidelity::Level::Fast, None, None).with_stop(stop, level)
        }
        m => m,
    };
    // S_op on the search mesh: one film solve, not a set of perturbations.
    let s_op = match search {
        Method::Numerical { mesh, stop, .. } => {
            let mut alive = || budget.alive();
            let ld = case.geometry.l_over_d();
            let (_, film, _) =
                performance::positioned_film(eps, ld, physics, mesh, stop, None, &mut alive)?;
            film.sommerfeld_number()
        }
        _ => s_op,
    };
    // Along the locus the speed changes, and with it a turbulent film's Reynolds number
    // (Re ∝ speed at fixed viscosity): the film at ε has Re = Re_op S(ε; Re)/S_op, a fixed point
    // found from single film solves (S changes little with Re, so it settles in a few steps)
    // before the coefficients are taken there. The turbulence decision itself stays the
    // operating point's (the Ng–Pan factors tend to laminar as Re falls).
    let locus_physics = |e: f64| -> Result<FilmModel, CalcError> {
        let (Some(re_op), Method::Numerical { mesh, stop, .. }) =
            (physics.turbulence_reynolds, search)
        else {
            return Ok(physics);
        };
        let ld = case.geometry.l_over_d();
        let mut re = re_op;
        // 10⁻⁴ in Re moves the Ng–Pan factors by far less than the mesh error; a contraction
        // this mild settles in three or four solves, and twelve bound the cost.
        for _ in 0..12 {
            let mut alive = || budget.alive();
            let with = FilmModel {
                turbulence_reynolds: Some(re),
                ..physics
            };
            let (_, film, _) =
                performance::positioned_film(e, ld, with, mesh, stop, None, &mut alive)?;
            let next = re_op * film.sommerfeld_number() / s_op;
            let settled = (next / re - 1.0).abs() < 1e-4;
            re = next;
            if settled {
                break;
            }
        }
        Ok(FilmModel {
            turbulence_reynolds: Some(re),
            ..physics
        })
    };
    let failure = std::cell::RefCell::new(None);
    let mut margin = |e: f64| -> f64 {
        match locus_physics(e).and_then(|ph| coefficients_at(case, search, e, ph, budget)) {
            Ok(Some(c)) => {
                let speed = omega * c.sommerfeld_number / s_op;
                match dynamics::whirl_on_shaft(&c, flexibility).critical_mass_parameter {
                    Some(mc) => (mc / mass_parameter(speed)).ln(),
                    None => 50.0,
                }
            }
            Ok(None) => 50.0,
            // Lighter than this a ported supply outweighs the film: the locus ends here.
            Err(CalcError::Impossible { pointer, .. })
                if pointer == performance::SUPPLY_DOMINATES =>
            {
                f64::NAN
            }
            Err(err) => {
                failure.borrow_mut().get_or_insert(err);
                f64::NAN
            }
        }
    };
    let m0 = if stable_now { 1.0 } else { -1.0 };
    let mut bracket = None;
    let mut previous = eps;
    let mut lightest = eps;
    for k in 1..=10 {
        let next = if stable_now {
            (eps * 0.6f64.powi(k)).max(1e-3)
        } else {
            (1.0 - (1.0 - eps) * 0.6f64.powi(k)).min(MAX_ECCENTRICITY)
        };
        let m = margin(next);
        if m.is_nan() {
            break;
        }
        lightest = lightest.min(next);
        if m.signum() != m0 {
            bracket = Some((previous, next));
            break;
        }
        previous = next;
        if next <= 1e-3 || next >= MAX_ECCENTRICITY {
            break;
        }
    }
    if let Some(e) = failure.borrow_mut().take() {
        return Err(e);
    }
    let threshold_eps = match bracket {
        Some((a, b)) => brent(
            &mut margin,
            a.min(b),
            a.max(b),
            Stopping {
                x_tolerance: 1e-5,
                max_iterations: 40,
            },
        )
        .ok()
        .map(|r| r.x),
        None => None,
    };
    if let Some(e) = failure.into_inner() {
        return Err(e);
    }
    let threshold_rpm = match threshold_eps {
        Some(e) => Some(
            coefficients_at(case, search, e, locus_physics(e)?, budget)?
                .map_or(f64::NAN, |c| case.speed_rpm * c.sommerfeld_number / s_op),
        )
        .filter(|v| v.is_finite()),
        None => None,
    };
    let statement = match (stable_now, threshold_rpm) {
        (true, Some(t)) => format!("stable at {:.0} rev/min; oil whirl sets in at about {t:.0} rev/min (rigid rotor of {mass:.3} kg, load and viscosity held)", case.speed_rpm),
        (true, None) if whirl.critical_mass_parameter.is_none() => format!("stable at every speed: at ε = {eps:.3} the film cannot sustain whirl for any rotor mass"),
        (true, None) => format!("stable at {:.0} rev/min and at every speed up to the lightest load solved (ε = {lightest:.4})", case.speed_rpm),
        (false, Some(t)) => format!("UNSTABLE: oil whirl above about {t:.0} rev/min, below the operating speed {:.0} rev/min", case.speed_rpm),
        (false, None) => format!("UNSTABLE at {:.0} rev/min, and no stable speed was found down to ε = {MAX_ECCENTRICITY}", case.speed_rpm),
    };
    if !stable_now {
        notes.warn("oil_whirl", statement.clone());
    }
    let stability = RotorStability {
        stable_at_operating_speed: stable_now,
        threshold_speed_rpm: threshold_rpm,
        whirl_frequency_ratio: whirl.whirl_frequency_ratio,
        critical_mass_parameter: whirl.critical_mass_parameter,
        critical_speed_rad_s: whirl
            .critical_mass_parameter
            .map(|mc| (mc * w / (mass * g.radial_clearance_m)).sqrt()),
        critical_speed_nd: whirl
            .critical_mass_parameter
            .map(|mc| (mc * w / (mass * GRAVITY)).sqrt()),
        mass_parameter: mass_parameter(omega),
        rotor_mass_kg: mass * case.halves(),
        statement,
    };
    Ok(Some((coefficients, stability)))
}
