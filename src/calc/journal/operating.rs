//! From a parsed request to the plain bearing's dimensional result: viscosity at the effective
//! temperature, equilibrium, outputs, dynamic coefficients and the stability threshold, with
//! every effect decided and reported.

use std::f64::consts::PI;

mod decisions;
mod solution;
mod stability;
mod thermal;

pub use solution::{
    BushTemperatures, CoefficientsMethod, Dynamics, Moment, ProfileNode, RotorStability, Solution,
};

use super::cost;
use super::dynamics::Coefficients;
use super::eccentricity::EccentricityRatio;
use super::feed::{self, Feed, Flows};
use super::film::{FeedLine, FilmModel, Misalignment, Port, Supply};
use super::performance::{self, Method, Point};
use crate::calc::lubricant::model::TemperatureLaw;
use crate::calc::lubricant::validity;
use crate::calc::lubricant::Lubricant;
use crate::calc::{Budget, CalcError, Notes};
use crate::effects::{Criterion, Decision, Mode};
use crate::fidelity::SolverReport;

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
    Eccentricity(EccentricityRatio),
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
    /// The journal's tilt the request gives; None when aligned. Whether it applies is the
    /// misalignment effect's mode ([`Case::tilt`]).
    pub misalignment: Option<Misalignment>,
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
    /// Gümbel's half-Sommerfeld film: the full film with its negative pressures set to zero.
    HalfSommerfeld,
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

/// The effect modes the plain bearing understands.
#[derive(Debug, Clone, Copy, Default)]
pub struct Effects {
    pub thermal: Mode,
    pub cavitation: Cavitation,
    pub turbulence: Mode,
    pub inertia: Mode,
    /// Applies the request's misalignment (auto, on) or not (off).
    pub misalignment: Mode,
}

/// A solved operating point at one viscosity.
#[derive(Debug, Clone)]
struct Operating {
    point: Point,
    load_n: f64,
    viscosity_pa_s: f64,
    temperature_c: f64,
    /// S(ε) evaluations of the equilibrium search (0 when ε was given).
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
    /// Whether the film ruptures (any model but the full film).
    fn cavitation(&self) -> bool {
        self.effects.cavitation != Cavitation::Off
    }
    fn half_sommerfeld(&self) -> bool {
        self.effects.cavitation == Cavitation::HalfSommerfeld
    }

    /// The misalignment the film is solved with: the request's, unless the effect is off.
    fn tilt(&self) -> Option<Misalignment> {
        self.misalignment
            .filter(|_| self.effects.misalignment != Mode::Off)
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
        let at = |position: feed::Position| match position {
            feed::Position::OppositeLoad => FeedLine::OppositeLoad,
            feed::Position::AtMaxFilm => FeedLine::MaxFilm,
        };
        let port = |length_ratio: f64, width_m: f64, p_s: f64| Port {
            length_ratio,
            width: 2.0 * width_m / g.diameter_m,
            pressure_nd: p_s / pressure_scale,
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

    /// Whether the film model is the same at every oil temperature: laminar, and no ported
    /// supply (whose dimensionless pressure follows the viscosity).
    fn film_independent_of_temperature(&self) -> bool {
        !self.turbulent && !self.ported()
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
            cavitation: self.cavitation() && !self.half_sommerfeld(),
            half_sommerfeld: self.half_sommerfeld(),
            turbulence_reynolds: self.turbulent.then(|| self.film_reynolds(t)),
            arc: self.arc,
            misalignment: self.tilt(),
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
        let (point, load_n, evaluations) = match self.given {
            Given::Load(w) => {
                let (p, n) = performance::equilibrium(
                    scale / w,
                    l_over_d,
                    self.method,
                    self.physics(temperature_c),
                    budget,
                )?;
                (p, w, n)
            }
            Given::Eccentricity(eps) => {
                let p = performance::at_eccentricity(
                    eps,
                    l_over_d,
                    self.method,
                    self.physics(temperature_c),
                    budget,
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
        op.point.side_leakage_nd
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
    let solves_before = budget.field_solves();
    let mut notes = Notes::default();
    let notes = &mut notes;
    let inlet = inlet_conditions(case, notes)?;
    let mut case = case.clone();
    case.turbulent = decisions::decide_turbulence(notes, &case, case.film_reynolds(inlet.t_in));
    let case = &case;
    // A grid the deadline cannot pay for is refused before any solve.
    let load_given = matches!(case.given, Given::Load(_));
    cost::check_affordable(case.method, &case.physics(inlet.t_in), load_given, budget)?;
    let (isothermal, op) = equilibrium_at_effective_temperature(case, &inlet, budget, notes)?;
    let thd = if inlet.temperature_dependent {
        thermal::thd_temperatures(notes, case, inlet.t_in, isothermal.point.eccentricity_ratio)
    } else {
        None
    };
    let reynolds = film_reynolds_at(case, &op);
    decisions::decide_inertia(notes, case.effects, reynolds, case.geometry);
    decisions::decide_cavitation(notes, case, op.temperature_c);
    decisions::decide_misalignment(notes, case);
    decisions::validity_warnings(notes, case, &op.point);
    let rise = case.temperature_rise(&op);
    if rise.is_none() {
        notes.warn("no_temperature_rise", "the long-bearing closed form has no side leakage, so no adiabatic temperature rise; use a numerical fidelity");
    }
    let dynamics = if case.dynamics {
        stability::dynamic_coefficients(case, &op, budget, notes)?
    } else {
        None
    };
    let mut solution = outputs(case, &op, rise, thd, reynolds);
    if let Some(t) = solution
        .bush_temperatures
        .filter(|t| t.max_c < solution.effective_temperature_c)
    {
        // Outside its range the fit can put the hottest oil below the mean: no answer at all.
        notes.warn(
            "thd_temperatures_withheld",
            format!("Jang–Khonsari's fit, outside its range here, puts the maximum bush temperature at {:.1} °C, below the effective {:.1} °C of the heat balance: the THD maximum and shaft temperatures are not reported", t.max_c, solution.effective_temperature_c),
        );
        solution.bush_temperatures = None;
    }
    let hottest = solution
        .bush_temperatures
        .map_or(solution.effective_temperature_c, |t| {
            t.max_c.max(solution.effective_temperature_c)
        });
    if let Some((code, message)) = validity::hot_oil("the film's hottest oil", hottest) {
        notes.warn(code, message);
    }
    solution.dynamics = dynamics
        .map(|(coefficients, stability)| dimensional_dynamics(case, &op, coefficients, stability));
    solution.notes = std::mem::take(notes);
    if matches!(case.method, Method::Numerical { .. }) {
        solution.report = solution
            .report
            .with_film_solves(budget.field_solves() - solves_before);
    }
    Ok(solution)
}

/// The inlet: its temperature (assumed when not given), whether the viscosity depends on it,
/// and the viscosity there.
struct Inlet {
    t_in: f64,
    mu_in: f64,
    temperature_dependent: bool,
}

/// The inlet temperature and viscosity, with the lubricant's assumptions as warnings.
fn inlet_conditions(case: &Case, notes: &mut Notes) -> Result<Inlet, CalcError> {
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
    Ok(Inlet {
        t_in,
        mu_in,
        temperature_dependent,
    })
}

/// The equilibrium at the inlet temperature (isothermal) and, when the thermal effect applies,
/// at the effective temperature: (isothermal, operating).
fn equilibrium_at_effective_temperature(
    case: &Case,
    inlet: &Inlet,
    budget: &Budget,
    notes: &mut Notes,
) -> Result<(Operating, Operating), CalcError> {
    let lub = &case.lubricant;
    let Inlet {
        t_in,
        mu_in,
        temperature_dependent,
    } = *inlet;
    // The isothermal equilibrium screens the thermal effect. Where the effect may apply and
    // the method is numerical it is taken on the coarse mesh: it then only decides and starts
    // the thermal search (and picks the THD fits' region); if the effect does not apply after
    // all, the equilibrium is solved on the method's own mesh.
    let screened = temperature_dependent && case.effects.thermal != Mode::Off;
    let isothermal = match case.method {
        Method::Numerical { .. } if screened => Case {
            method: case.method.coarser(),
            ..case.clone()
        }
        .operate(t_in, budget)?,
        _ => case.operate(t_in, budget)?,
    };
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
                op = match case.given {
                    Given::Load(w) if case.film_independent_of_temperature() => {
                        thermal::thermal_equilibrium(case, t_in, w, &isothermal, budget)?
                    }
                    _ => thermal::effective_temperature(case, t_in, k * rise, budget)?,
                };
            } else if screened {
                op = case.operate(t_in, budget)?;
            }
            notes.decide("thermal", decision);
        }
    }

    Ok((isothermal, op))
}

/// Film Reynolds number ρ U C/μ at the operating point's temperature and viscosity.
fn film_reynolds_at(case: &Case, op: &Operating) -> f64 {
    let g = case.geometry;
    let n_s = case.speed_rps();
    let mu = op.viscosity_pa_s;
    let rho = case.lubricant.density_kg_m3(op.temperature_c);
    let u = PI * g.diameter_m * n_s;
    rho * u * g.radial_clearance_m / mu
}

/// The dimensional outputs at the operating point (dynamics aside).
fn outputs(
    case: &Case,
    op: &Operating,
    rise: Option<f64>,
    thd: Option<BushTemperatures>,
    reynolds: f64,
) -> Solution {
    let g = case.geometry;
    let point = &op.point;
    let n_s = case.speed_rps();
    let mu = op.viscosity_pa_s;
    let power = case.power_loss(op);
    let flows = case.flows(op);
    // The Reynolds film's pressures are relative to the supply's; a ported JFO film holds it.
    let supply_pressure = if case.ported() {
        0.0
    } else {
        case.feed.map_or(0.0, |f| f.supply_pressure_pa())
    };
    // A circumferential groove makes two half-bearings: the solve is of one half.
    let halves = case.halves();
    let friction = point.friction_parameter / g.r_over_c();
    let pressure_scale = mu * n_s * g.r_over_c().powi(2);
    let flow_scale = 0.5 * PI * n_s * g.diameter_m * g.length_m * g.radial_clearance_m;
    Solution {
        load_n: halves * op.load_n,
        sommerfeld_number: point.sommerfeld_number,
        eccentricity_ratio: point.eccentricity_ratio,
        attitude_angle: point.attitude_angle,
        min_film_thickness_m: g.radial_clearance_m * point.min_film_nd,
        max_pressure_pa: point.max_pressure_nd * pressure_scale + supply_pressure,
        max_pressure_nd: point.max_pressure_nd,
        max_pressure_angle: point.max_pressure_angle,
        cavitation_start_angle: point.cavitation_angle,
        cavitated_area_fraction: point.cavitated_fraction,
        friction_coefficient: friction,
        friction_parameter: point.friction_parameter,
        friction_torque_n_m: halves * friction * op.load_n * 0.5 * g.diameter_m,
        power_loss_w: halves * power,
        side_leakage_m3_s: point.side_leakage_nd * flow_scale,
        side_leakage_nd: point.side_leakage_nd,
        inlet_flow_m3_s: point
            .inlet_flow_nd
            .filter(|_| halves == 1.0)
            .map(|q| q * flow_scale),
        temperature_rise_k: rise,
        bush_temperatures: thd,
        flows,
        effective_temperature_c: op.temperature_c,
        effective_viscosity_pa_s: mu,
        reynolds_number: reynolds,
        approximation: decisions::approximation_name(case),
        approximation_note: decisions::approximation_note(case),
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
        moment: point.moment_nd.map(|m| {
            let scale = pressure_scale * 0.5 * g.diameter_m * g.length_m * g.length_m;
            let (mx, my) = (m[0] * scale, m[1] * scale);
            Moment {
                mx_n_m: mx,
                my_n_m: my,
                magnitude_n_m: mx.hypot(my),
                nd: m,
                restoring_n_m: case
                    .tilt()
                    .unwrap_or_default()
                    .restoring(point.attitude_angle, [mx, my]),
            }
        }),
        dynamics: None,
        report: report(case, point, op.evaluations),
        notes: Notes::default(),
    }
}

/// Stiffness and damping in N/m and N·s/m (whole bearing), with the rotor's stability.
fn dimensional_dynamics(
    case: &Case,
    op: &Operating,
    coefficients: Coefficients,
    stability: RotorStability,
) -> Dynamics {
    let (w, c, omega) = (
        case.halves() * op.load_n,
        case.geometry.radial_clearance_m,
        2.0 * PI * case.speed_rps(),
    );
    Dynamics {
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
    }
}

/// The response's solver block. Numerical: the film solves' driver report (the active-set steps
/// or sweeps of the fine and the coarse mesh, the fine field's equation residual), at the level
/// and on the mesh asked, with the error estimate; the equilibrium search's evaluations (each a
/// film solve, or an attitude search of them) as its evaluations; the request's film solves.
/// Closed form: a direct evaluation, counting the evaluations of the equilibrium search (the
/// count the block has always carried).
fn report(case: &Case, point: &Point, evaluations: u32) -> SolverReport {
    match case.method {
        Method::ClosedForm(_) => {
            let name = decisions::approximation_name(case).unwrap_or_default();
            let method = format!("closed_form_{name}");
            match evaluations {
                0 => SolverReport::closed_form(&method),
                n => SolverReport::closed_form_search(&method, n),
            }
        }
        Method::Numerical { level, mesh, .. } => {
            let report = point
                .solve
                .clone()
                .expect("a numerical point carries its film solves' report");
            let sweeps = report.iterations;
            report
                .at(level)
                .on_grid(vec![mesh.circumferential as u32, mesh.axial_half as u32])
                .with_error_estimate(point.error_estimate)
                .counting(sweeps, evaluations)
        }
    }
}
