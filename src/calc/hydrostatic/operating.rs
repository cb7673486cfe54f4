//! A pad at its operating point: the determinate set the request gives (two of film, load,
//! supply pressure and flow) solved with the restrictor's law — in closed form when the flow is
//! laminar, by bracketed roots of the turbulent laws' closed forms when the turbulence effect
//! applies ([`solve_lands`]) — the stiffness, the powers and the temperature rise, the effects
//! decided (Khonsari & Booser §10.3–10.6; Stachowiak & Batchelor §6.2–6.4).
//!
//! The film carries W = A_eff p_r and passes Q = c₂ h³ p_r (c₂ = B̄/μ); the restrictor
//! passes the same Q at p_s − p_r. Two of (h, W, p_s, Q) fix the rest, except W with p_s
//! when nothing ties p_r to the film (constant flow, or a restrictor still to be sized).

use super::geometry::{Drag, Geometry};
use super::lands::{Film, Lands, Slit};
use super::point::Point;
use super::power::{self, Motion, Power, Shear};
use super::restrictor::{self, Kind, Law, Pipe};
use crate::calc::lubricant::model::{Lubricant, TemperatureLaw};
use crate::calc::lubricant::validity;
use crate::calc::{CalcError, Notes};
use crate::effects::{Criterion, Decision, Mode};
use crate::numerics::roots::{brent_fallible, brent_outcome, RootError, Stopping, MAX_DOUBLINGS};

/// The two quantities the request fixes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Known {
    FilmLoad(f64, f64),
    FilmSupply(f64, f64),
    FilmFlow(f64, f64),
    LoadSupply(f64, f64),
    LoadFlow(f64, f64),
    SupplyFlow(f64, f64),
}

/// A restrictor given by its size, or to be sized for a pressure ratio m = p_r/p_s.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Sizing {
    /// Capillary length, or orifice radius, m.
    Given(f64),
    /// m, within (0, 1).
    Ratio(f64),
}

/// What feeds the recess.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Compensation {
    ConstantFlow,
    Capillary {
        radius: f64,
        sizing: Sizing,
    },
    Orifice {
        discharge_coefficient: f64,
        sizing: Sizing,
    },
}

impl Compensation {
    pub fn kind(self) -> Kind {
        match self {
            Compensation::ConstantFlow => Kind::ConstantFlow,
            Compensation::Capillary { .. } => Kind::Capillary,
            Compensation::Orifice { .. } => Kind::Orifice,
        }
    }

    /// The law at the restrictor's viscosity μ and density ρ; a capillary with `turbulent` is a
    /// [`Pipe`] (the larger of the laminar and turbulent drops).
    pub fn law(self, mu: f64, rho: f64, turbulent: bool) -> Law {
        match self {
            Compensation::ConstantFlow => Law::Direct,
            Compensation::Capillary {
                radius,
                sizing: Sizing::Given(length),
            } if turbulent => Law::Pipe(Pipe {
                radius,
                length,
                mu,
                rho,
            }),
            Compensation::Capillary {
                radius,
                sizing: Sizing::Given(length),
            } => Law::Linear(restrictor::capillary_conductance(radius, length, mu)),
            Compensation::Orifice {
                discharge_coefficient,
                sizing: Sizing::Given(radius),
            } => Law::Root(restrictor::orifice_coefficient(
                radius,
                discharge_coefficient,
                rho,
            )),
            Compensation::Capillary {
                sizing: Sizing::Ratio(m),
                ..
            }
            | Compensation::Orifice {
                sizing: Sizing::Ratio(m),
                ..
            } => Law::Ratio(m),
        }
    }
}

/// The point where `known` holds on laminar lands, in closed form (a turbulent capillary at a
/// given film and supply pressure by [`solve_lands`]). Refusals name the request field at fault.
pub fn solve(film: Film, law: Law, known: Known) -> Result<Point, CalcError> {
    let Film { area, c2 } = film;
    let film_for = |q: f64, pr: f64| (q / (c2 * pr)).cbrt();
    let (h, pr, q, ps) = match known {
        Known::FilmLoad(h, w) => {
            let pr = w / area;
            (h, pr, c2 * h.powi(3) * pr, None)
        }
        Known::FilmFlow(h, q) => (h, q / (c2 * h.powi(3)), q, None),
        Known::LoadFlow(w, q) => {
            let pr = w / area;
            (film_for(q, pr), pr, q, None)
        }
        Known::FilmSupply(h, ps) => {
            let a = c2 * h.powi(3);
            let pr = match law {
                Law::Direct => ps,
                Law::Ratio(m) => m * ps,
                Law::Linear(k) => k * ps / (a + k),
                // The positive root of c₂²h⁶p_r² + k²p_r − k²p_s = 0 (Eq. 10.32–10.33), in the
                // form without cancellation when the orifice is large.
                Law::Root(k) => 2.0 * k * k * ps / (k * k + k * (k * k + 4.0 * a * a * ps).sqrt()),
                Law::Pipe(_) => return solve_lands(&Lands::Laminar(film), law, known, &mut 0),
            };
            (h, pr, a * pr, Some(ps))
        }
        Known::LoadSupply(w, ps) => {
            let pr = w / area;
            tied_by_supply(law)?;
            if pr >= ps {
                return Err(beyond_supply(pr, ps));
            }
            let q = law.flow(ps - pr).unwrap_or(0.0);
            (film_for(q, pr), pr, q, Some(ps))
        }
        Known::SupplyFlow(ps, q) => {
            let pr = recess_at_flow(law, ps, q)?;
            (film_for(q, pr), pr, q, Some(ps))
        }
    };
    Ok(point(law, h, pr, q, ps, area))
}

/// The point of film h, recess pressure p_r and flow Q on area A_eff, its supply pressure given
/// or found behind the restrictor.
fn point(law: Law, h: f64, pr: f64, q: f64, ps: Option<f64>, area: f64) -> Point {
    let supply = ps.unwrap_or_else(|| match law {
        Law::Ratio(m) => pr / m,
        other => pr + other.drop(q).unwrap_or(0.0),
    });
    Point {
        film: h,
        load: area * pr,
        supply,
        recess: pr,
        flow: q,
    }
}

/// Load with supply pressure fixes nothing when p_r is tied to p_s (constant flow, or a
/// restrictor still to be sized).
fn tied_by_supply(law: Law) -> Result<(), CalcError> {
    match law {
        Law::Direct | Law::Ratio(_) => Err(CalcError::impossible(
            "/supply_pressure_pa",
            "load and supply pressure are tied by W = A_eff·m·p_s whatever the film: give film_m or flow_m3_s instead of one of them",
        )),
        _ => Ok(()),
    }
}

/// A load whose recess pressure W/A_eff is not below the supply pressure.
fn beyond_supply(pr: f64, ps: f64) -> CalcError {
    CalcError::impossible(
        "/load_n",
        format!(
            "the load needs a recess pressure W/A_eff = {pr:.6e} Pa, not below the supply pressure {ps:.6e} Pa: no film carries it"
        ),
    )
}

/// p_r behind the restrictor at supply pressure p_s and flow Q.
fn recess_at_flow(law: Law, ps: f64, q: f64) -> Result<f64, CalcError> {
    match law {
        Law::Direct => Ok(ps),
        Law::Ratio(m) => Ok(m * ps),
        _ => {
            let drop = law.drop(q).unwrap_or(0.0);
            if drop >= ps {
                return Err(CalcError::impossible(
                    "/flow_m3_s",
                    format!(
                        "the restrictor alone drops {drop:.6e} Pa at this flow, not less than the supply pressure {ps:.6e} Pa"
                    ),
                ));
            }
            Ok(ps - drop)
        }
    }
}

/// The method name of the roots on turbulent lands.
const TURBULENT_ROOTS: &str = "hydrostatic_turbulent_film";

/// A turbulent root that failed: the cap as not converged; a bracket or an evaluation lost to
/// the floating-point range (a bore of 1e-100 m) as a 422.
fn root_failure(e: RootError) -> CalcError {
    match e {
        RootError::NotConverged { .. } => CalcError::from_root(TURBULENT_ROOTS, e),
        RootError::NoSignChange { .. } | RootError::NonFinite { .. } => CalcError::impossible(
            "",
            "this combination of inputs takes the turbulent flow balance outside the floating-point range",
        ),
    }
}

/// Brent to round-off relative to the root (a recess pressure of a thousandth of the supply's
/// still gets all its digits), a root error named for this room; each evaluation of the balance
/// `f` is counted in `evaluations`.
fn root_of(
    mut f: impl FnMut(f64) -> Result<f64, RootError>,
    a: f64,
    b: f64,
    evaluations: &mut u32,
) -> Result<f64, CalcError> {
    let stop = Stopping {
        x_tolerance: f64::MIN_POSITIVE,
        max_iterations: 200,
    };
    let counted = |x: f64| {
        *evaluations += 1;
        f(x)
    };
    brent_fallible(counted, a, b, stop)
        .map(|root| root.x)
        .map_err(root_failure)
}

/// The point where `known` holds on any lands: [`solve`]'s closed forms on laminar lands with a
/// laminar restrictor, else bracketed Brent roots of monotone balances (W rises with p_r at a
/// film; the lands' flow rises and the restrictor's falls with p_r at a supply pressure), their
/// balances' evaluations added to `evaluations`.
pub fn solve_lands(
    lands: &Lands,
    law: Law,
    known: Known,
    evaluations: &mut u32,
) -> Result<Point, CalcError> {
    if let (Lands::Laminar(film), false) = (lands, matches!(law, Law::Pipe(_))) {
        return solve(*film, law, known);
    }
    // (h, p_r, Q, given p_s, A_eff)
    let (h, pr, q, ps, area) = match known {
        Known::FilmFlow(h, q) => {
            let (s, area) = lands.at_flow(q).map_err(root_failure)?;
            (h, s / h.powi(3), q, None, area)
        }
        Known::LoadFlow(w, q) => {
            let (s, area) = lands.at_flow(q).map_err(root_failure)?;
            let pr = w / area;
            ((s / pr).cbrt(), pr, q, None, area)
        }
        Known::FilmLoad(h, w) => {
            let h3 = h.powi(3);
            let excess = |pr: f64| lands.at(pr * h3).map(|(_, area)| area * pr - w);
            // W/A_eff at no flow, doubled until the load is passed (A_eff moves by far less).
            let mut hi = w / lands.at(0.0).map_err(root_failure)?.1;
            for _ in 0..MAX_DOUBLINGS {
                if excess(hi).map_err(root_failure)? > 0.0 {
                    break;
                }
                hi *= 2.0;
            }
            let pr = root_of(excess, 0.0, hi, evaluations)?;
            let (q, area) = lands.at(pr * h3).map_err(root_failure)?;
            (h, pr, q, None, area)
        }
        Known::FilmSupply(h, ps) => {
            let s_at = |t: f64| t * ps * h.powi(3);
            let t = match law {
                Law::Direct => 1.0,
                Law::Ratio(m) => m,
                _ => root_of(
                    |t| {
                        let restrictor = law.flow((1.0 - t) * ps).unwrap_or(0.0);
                        lands.at(s_at(t)).map(|(q, _)| q - restrictor)
                    },
                    0.0,
                    1.0,
                    evaluations,
                )?,
            };
            let (q, area) = lands.at(s_at(t)).map_err(root_failure)?;
            (h, t * ps, q, Some(ps), area)
        }
        Known::LoadSupply(w, ps) => {
            tied_by_supply(law)?;
            let still = lands.at(0.0).map_err(root_failure)?.1;
            if w / still >= ps {
                return Err(beyond_supply(w / still, ps));
            }
            let at_recess = |pr: f64| {
                let q = law.flow(ps - pr).unwrap_or(0.0);
                lands.at_flow(q).map(|(s, area)| (q, s, area))
            };
            let pr = root_of(
                |pr| at_recess(pr).map(|(_, _, area)| area * pr - w),
                0.0,
                ps,
                evaluations,
            )?;
            let (q, s, area) = at_recess(pr).map_err(root_failure)?;
            ((s / pr).cbrt(), pr, q, Some(ps), area)
        }
        Known::SupplyFlow(ps, q) => {
            let pr = recess_at_flow(law, ps, q)?;
            let (s, area) = lands.at_flow(q).map_err(root_failure)?;
            ((s / pr).cbrt(), pr, q, Some(ps), area)
        }
    };
    Ok(point(law, h, pr, q, ps, area))
}

/// −dW/dh at fixed supply pressure through the restrictor as built, on any lands: the closed
/// form on laminar lands with a laminar restrictor; at constant flow 3W/h (Q fixes s = h³p_r and
/// so A_eff); else central differences of the film-and-supply solve (step 1e-4 h: truncation
/// ~1e-8, the roots' round-off ~1e-10), the roots' evaluations added to `evaluations`.
fn stiffness_on(
    lands: &Lands,
    law: Law,
    kind: Kind,
    point: &Point,
    evaluations: &mut u32,
) -> Result<f64, CalcError> {
    match (lands, law) {
        (_, Law::Direct) | (Lands::Laminar(_), Law::Linear(_) | Law::Root(_)) => {
            Ok(stiffness(kind, point))
        }
        _ => {
            let dh = 1e-4 * point.film;
            let mut load = |h: f64| {
                solve_lands(lands, law, Known::FilmSupply(h, point.supply), evaluations)
                    .map(|p| p.load)
            };
            Ok((load(point.film - dh)? - load(point.film + dh)?) / (2.0 * dh))
        }
    }
}

/// −dW/dh at fixed supply pressure (fixed flow for constant flow): (3W/h) × the restrictor's
/// factor at the point's m (Eq. 10.12, 10.27, 10.34).
pub fn stiffness(kind: Kind, point: &Point) -> f64 {
    3.0 * point.load / point.film * kind.stiffness_factor(point.ratio())
}

/// Effects the pad understands.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Effects {
    pub thermal: Mode,
    pub turbulence: Mode,
}

/// One pad request, parsed.
#[derive(Debug, Clone, PartialEq)]
pub struct Case {
    pub geometry: Geometry,
    pub compensation: Compensation,
    pub known: Known,
    pub motion: Motion,
    pub pump_efficiency: f64,
    pub lubricant: Lubricant,
    pub inlet_temperature_c: f64,
    pub effects: Effects,
}

/// The restrictor as built: its size (given or designed) and the flow through it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Restrictor {
    pub kind: Kind,
    /// Capillary or orifice radius, m.
    pub radius: Option<f64>,
    /// Capillary length, m.
    pub length: Option<f64>,
    pub discharge_coefficient: Option<f64>,
    /// K_c, m³/(s·Pa) (capillary) or k_o, m³/(s·Pa^½) (orifice).
    pub conductance: Option<f64>,
    pub pressure_drop: f64,
    pub mean_velocity: Option<f64>,
    pub reynolds_number: Option<f64>,
}

/// A pad at its operating point.
#[derive(Debug, Clone, PartialEq)]
pub struct Operating {
    pub point: Point,
    pub effective_area: f64,
    pub flow_coefficient: f64,
    pub stiffness: f64,
    pub power: Power,
    pub restrictor: Restrictor,
    /// The lands' pressure flow's Reynolds number 2ρQ′/μ where the flow per unit width Q′ peaks
    /// (hydraulic diameter 2h; None for chart factors).
    pub land_pressure_flow_reynolds_number: Option<f64>,
    /// The lands' shear flow's film Reynolds number ρUh/μ at the fastest edge.
    pub land_shear_reynolds_number: Option<f64>,
    /// Where the film's viscosity is taken, °C, and that viscosity, Pa·s.
    pub film_temperature_c: f64,
    pub film_viscosity_pa_s: f64,
    /// The restrictor's (inlet) viscosity and density.
    pub inlet_viscosity_pa_s: f64,
    pub inlet_density_kg_m3: f64,
    /// Evaluations of the pad in the thermal root (0: closed form, no search).
    pub thermal_evaluations: u32,
    /// Evaluations of the flow balance in the Brent roots of the point and its stiffness (0: in
    /// closed form).
    pub balance_evaluations: u32,
    /// Whether the turbulent laws were applied (the point then comes from Brent roots).
    pub turbulent: bool,
    pub notes: Notes,
}

/// Capillary laminar limit, where the turbulent law takes over ([`restrictor::Pipe`]).
pub const CAPILLARY_REYNOLDS_LIMIT: f64 = restrictor::PIPE_TRANSITION_REYNOLDS;
/// Capillary length-to-bore for Hagen–Poiseuille to hold (entry losses; S&B §6.4: l/d > 100).
pub const CAPILLARY_MIN_L_OVER_D: f64 = 100.0;
/// Below this orifice Reynolds number C_D falls from about 0.6–0.7 towards 0.3 (Khonsari &
/// Booser §10.5).
pub const ORIFICE_LOW_REYNOLDS: f64 = 100.0;
/// Above this recess-to-supply ratio a restrictor drops almost nothing: a capillary's or an
/// orifice's pad keeps less than a tenth of the stiffness it has at the optimum ratio.
pub const INEFFECTIVE_RESTRICTOR_RATIO: f64 = 0.95;
/// Laminar limit of a slit's pressure flow, Reynolds number on the hydraulic diameter 2h
/// (Khonsari & Booser §16.1).
pub const LAND_PRESSURE_FLOW_REYNOLDS_LIMIT: f64 = 2000.0;
/// Thin-film transition to turbulence under a moving surface, film Reynolds number ρUh/μ
/// (Khonsari & Booser §7.11's lower bound, 580–800).
pub const LAND_SHEAR_REYNOLDS_LIMIT: f64 = 580.0;
/// The thermal effect applies (auto) when the isothermal rise lowers μ by more than this.
pub const THERMAL_VISCOSITY_DROP: f64 = 0.05;

/// How the flow is modelled: laminar everywhere, or the turbulent effect applied (the
/// capillary a [`Pipe`], the lands' pressure flow by the slit law, their shear by the surface
/// drag of Eq. 7.17–7.18).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Regime {
    Laminar,
    Turbulent,
}

/// The pad at temperature `t_film` (the film's viscosity and density) with the restrictor at the
/// inlet.
fn at(case: &Case, t_film: f64, regime: Regime) -> Result<Operating, CalcError> {
    let t_in = case.inlet_temperature_c;
    let lub = &case.lubricant;
    let (mu_in, rho) = (lub.viscosity_pa_s(t_in), lub.density_kg_m3(t_in));
    let (mu, rho_film) = (lub.viscosity_pa_s(t_film), lub.density_kg_m3(t_film));
    let cp = lub.specific_heat_j_kg_k(t_in);
    let turbulent = regime == Regime::Turbulent;
    let lands = if turbulent {
        case.geometry.turbulent_lands(Slit { mu, rho: rho_film })
    } else {
        case.geometry.laminar_lands(mu)
    };
    let law = case.compensation.law(mu_in, rho, turbulent);
    let mut balance_evaluations = 0;
    let point = solve_lands(&lands, law, case.known, &mut balance_evaluations)?;
    let kind = case.compensation.kind();
    // The restrictor's own law gives its drop without the cancellation of p_s − p_r near m = 1;
    // a pipe in transition holds its flow while its drop varies, so its drop is p_s − p_r.
    let drop = match law {
        Law::Pipe(_) => point.supply - point.recess,
        _ => law.drop(point.flow).unwrap_or(point.supply - point.recess),
    };
    let (restrictor, built) = match case.compensation {
        Compensation::ConstantFlow => (
            Restrictor {
                kind,
                radius: None,
                length: None,
                discharge_coefficient: None,
                conductance: None,
                pressure_drop: 0.0,
                mean_velocity: None,
                reynolds_number: None,
            },
            Law::Direct,
        ),
        Compensation::Capillary { radius, sizing } => {
            let conductance = point.flow / drop;
            let length = match sizing {
                Sizing::Given(l) => l,
                Sizing::Ratio(_) if turbulent => {
                    restrictor::pipe_length(point.flow, drop, radius, rho, mu_in)
                }
                Sizing::Ratio(_) => restrictor::capillary_length(radius, conductance, mu_in),
            };
            let (u, re) = restrictor::bore_flow(point.flow, radius, rho, mu_in);
            let built = match sizing {
                Sizing::Given(_) => law,
                Sizing::Ratio(_) => Compensation::Capillary {
                    radius,
                    sizing: Sizing::Given(length),
                }
                .law(mu_in, rho, turbulent),
            };
            (
                Restrictor {
                    kind,
                    radius: Some(radius),
                    length: Some(length),
                    discharge_coefficient: None,
                    conductance: Some(conductance),
                    pressure_drop: drop,
                    mean_velocity: Some(u),
                    reynolds_number: Some(re),
                },
                built,
            )
        }
        Compensation::Orifice {
            discharge_coefficient,
            sizing,
        } => {
            let radius = match sizing {
                Sizing::Given(r) => r,
                Sizing::Ratio(_) => {
                    restrictor::orifice_radius(point.flow, drop, discharge_coefficient, rho)
                }
            };
            let (u, re) = restrictor::bore_flow(point.flow, radius, rho, mu_in);
            let coefficient = restrictor::orifice_coefficient(radius, discharge_coefficient, rho);
            (
                Restrictor {
                    kind,
                    radius: Some(radius),
                    length: None,
                    discharge_coefficient: Some(discharge_coefficient),
                    conductance: Some(coefficient),
                    pressure_drop: drop,
                    mean_velocity: Some(u),
                    reynolds_number: Some(re),
                },
                Law::Root(coefficient),
            )
        }
    };
    let shear = if turbulent {
        Shear::Turbulent { rho: rho_film }
    } else {
        Shear::Laminar
    };
    let friction = power::friction(case.geometry.drag(), case.motion, point.film, mu, shear);
    let power = power::of(
        friction,
        &point,
        case.motion,
        case.pump_efficiency,
        rho * cp,
    );
    let shear_speed = match (case.motion, case.geometry.outer_radius()) {
        (Motion::Rotating { omega }, Some(r)) => omega * r,
        (Motion::Sliding { speed }, _) => speed,
        _ => 0.0,
    };
    let peak = case.geometry.peak_flow_per_width(point.flow);
    Ok(Operating {
        stiffness: stiffness_on(&lands, built, kind, &point, &mut balance_evaluations)?,
        effective_area: point.load / point.recess,
        flow_coefficient: point.flow * mu / (point.film.powi(3) * point.recess),
        point,
        power,
        restrictor,
        land_pressure_flow_reynolds_number: peak.map(|q| 2.0 * rho_film * q / mu),
        land_shear_reynolds_number: peak.map(|_| rho_film * shear_speed * point.film / mu),
        film_temperature_c: t_film,
        film_viscosity_pa_s: mu,
        inlet_viscosity_pa_s: mu_in,
        inlet_density_kg_m3: rho,
        thermal_evaluations: 0,
        balance_evaluations,
        turbulent,
        notes: Notes::default(),
    })
}

/// The pad at its operating point: turbulence decided on the laminar isothermal point (and the
/// turbulent laws applied where it holds), then the thermal effect decided (and solved as a root
/// in the film temperature where it applies; a laminar film is then decided again at its film
/// temperature, where the thinner oil runs at a higher Reynolds number), warnings noted.
pub fn operate(case: &Case) -> Result<Operating, CalcError> {
    let t_in = case.inlet_temperature_c;
    let laminar = at(case, t_in, Regime::Laminar)?;
    let mut turbulence = decide_turbulence(case, &laminar, "at the inlet temperature");
    let mut regime = if turbulence.applied {
        Regime::Turbulent
    } else {
        Regime::Laminar
    };
    let isothermal = match regime {
        Regime::Laminar => laminar,
        Regime::Turbulent => at(case, t_in, regime)?,
    };
    let constant = matches!(
        case.lubricant.temperature_law,
        TemperatureLaw::Constant { .. }
    );
    let rise = isothermal.power.temperature_rise;
    let mut op = if constant {
        let mut op = isothermal;
        op.notes.decide(
            "thermal",
            Decision::not_applicable(
                case.effects.thermal,
                "thermal: the lubricant's viscosity is constant; the temperature rise is reported, the viscosity does not follow it",
            ),
        );
        op
    } else {
        let decision = decide_thermal(case, rise);
        if decision.applied {
            let mut op = thermal_root(case, rise, regime)?;
            if regime == Regime::Laminar {
                turbulence = decide_turbulence(case, &op, "at the film temperature");
                if turbulence.applied {
                    // At the inlet the film was laminar, where the turbulent laws (the larger
                    // loss of the two) are the laminar ones: the isothermal rise, the root's
                    // bracket and the thermal decision stand. The laminar root's evaluations
                    // count.
                    regime = Regime::Turbulent;
                    let spent = op.thermal_evaluations;
                    op = thermal_root(case, rise, regime)?;
                    op.thermal_evaluations += spent;
                }
            }
            op.notes.decide("thermal", decision);
            op
        } else {
            let mut op = isothermal;
            op.notes.decide("thermal", decision);
            op
        }
    };
    op.notes.decide("turbulence", turbulence);
    warn(case, &mut op, regime);
    Ok(op)
}

/// Thermal: the viscosity's fall from the inlet to the mean film temperature T_in + ΔT/2 of the
/// isothermal point's rise ΔT, against [`THERMAL_VISCOSITY_DROP`].
fn decide_thermal(case: &Case, rise: f64) -> Decision {
    let t_in = case.inlet_temperature_c;
    let mean = t_in + 0.5 * rise;
    let mu_in = case.lubricant.viscosity_pa_s(t_in);
    let drop = if mean <= crate::calc::quantity::Celsius::MAX {
        1.0 - case.lubricant.viscosity_pa_s(mean) / mu_in
    } else {
        1.0
    };
    let mut decision = Decision::decide(
        case.effects.thermal,
        Criterion {
            name: "viscosity_drop_fraction",
            value: drop,
            threshold: THERMAL_VISCOSITY_DROP,
        },
        "thermal (film viscosity at the mean film temperature T_in + ΔT/2)",
    );
    decision.model = Some("mean_film_temperature");
    decision
}

/// T such that T = T_in + ΔT(μ(T))/2. ΔT falls as the film warms (the flow rises and the
/// shear falls with μ), so the root lies in [T_in, T_in + ΔT_iso/2].
fn thermal_root(case: &Case, rise: f64, regime: Regime) -> Result<Operating, CalcError> {
    // A restrictor too small to pass a representable flow (a 1e-300 m bore) heats the film by
    // ∞ or 0/0: refused as the room refuses any result outside the range (a 500 in the root).
    if !rise.is_finite() {
        return Err(CalcError::impossible(
            "",
            format!("this combination of inputs takes the result outside the floating-point range (the isothermal temperature rise is {rise})"),
        ));
    }
    let t_in = case.inlet_temperature_c;
    let hi = (t_in + 0.5 * rise).min(crate::calc::quantity::Celsius::MAX);
    let mut evaluations = 0;
    let residual = |t: f64| {
        evaluations += 1;
        at(case, t, regime).map(|op| t - t_in - 0.5 * op.power.temperature_rise)
    };
    let stop = Stopping {
        x_tolerance: 1e-9,
        max_iterations: 100,
    };
    match brent_outcome(residual, t_in, hi, stop)? {
        Ok(root) => at(case, root.x, regime).map(|op| Operating {
            thermal_evaluations: evaluations + 1,
            ..op
        }),
        Err(RootError::NoSignChange { .. }) => Err(CalcError::impossible(
            "/temperature_c",
            format!(
                "thermal runaway: the film heats by {rise:.4e} K, beyond what the oil's viscosity law covers"
            ),
        )),
        // The film at a T above the inlet's is not finite where the law's viscosity has fallen
        // to nothing (an exponential law with β = 1/K at 1000 °C, a pad heated by 1e300 K).
        Err(RootError::NonFinite { x }) => Err(CalcError::impossible(
            "/temperature_c",
            format!(
                "thermal runaway: the film heats by {rise:.4e} K, beyond what the oil's viscosity law covers (at {x} °C the film has no finite answer)"
            ),
        )),
        Err(e) => Err(CalcError::from_root("hydrostatic_film_temperature", e)),
    }
}

/// Turbulence: the largest of the capillary's Reynolds number over 2000, the lands' pressure
/// flow's (hydraulic diameter 2h, where the flow per unit width peaks) over 2000 and their
/// shear's (ρUh/μ at the fastest edge) over 580, on the laminar point (`at` says at which
/// temperature), against 1.
fn decide_turbulence(case: &Case, laminar: &Operating, at: &str) -> Decision {
    let capillary = match (laminar.restrictor.kind, laminar.restrictor.reynolds_number) {
        (Kind::Capillary, Some(re)) => re / CAPILLARY_REYNOLDS_LIMIT,
        _ => 0.0,
    };
    let pressure = laminar.land_pressure_flow_reynolds_number.unwrap_or(0.0)
        / LAND_PRESSURE_FLOW_REYNOLDS_LIMIT;
    let shear = laminar.land_shear_reynolds_number.unwrap_or(0.0) / LAND_SHEAR_REYNOLDS_LIMIT;
    let mut decision = Decision::decide(
        case.effects.turbulence,
        Criterion {
            name: "reynolds_number_over_transition",
            value: capillary.max(pressure).max(shear),
            threshold: 1.0,
        },
        &format!("turbulence (capillary Re against 2000, land pressure flow Re_2h against 2000, land shear Re_h against 580, on the laminar point {at})"),
    );
    decision.model = Some("larger_loss_of_laminar_and_turbulent");
    decision
}

fn warn(case: &Case, op: &mut Operating, regime: Regime) {
    let laminar = regime == Regime::Laminar;
    let notes = &mut op.notes;
    // Density enters the temperature rise and the restrictor's Reynolds number: every
    // assumption is the pad's.
    for (code, message) in &case.lubricant.assumptions {
        notes.warn(code, message.clone());
    }
    if let Some((code, message)) = validity::hot_oil("the film's oil", op.film_temperature_c) {
        notes.warn(code, message);
    }
    let r = &op.restrictor;
    match (r.kind, r.reynolds_number) {
        (Kind::Capillary, Some(re)) => {
            if re > CAPILLARY_REYNOLDS_LIMIT {
                let consequence = if laminar {
                    "Hagen–Poiseuille overstates its flow (the turbulence effect applies the turbulent line loss)"
                } else {
                    "the turbulent line loss (Khonsari & Booser Eq. 2.36) was applied; a restrictor is usually kept laminar so that its drop follows the viscosity as the film's does"
                };
                notes.warn(
                    "restrictor_not_laminar",
                    format!("capillary Reynolds number {re:.4e} exceeds {CAPILLARY_REYNOLDS_LIMIT} (Stachowiak & Batchelor; Khonsari & Booser allow 2500): {consequence}"),
                );
            }
            if let (Some(l), Some(radius)) = (r.length, r.radius) {
                let ld = l / (2.0 * radius);
                if ld < CAPILLARY_MIN_L_OVER_D {
                    notes.warn(
                        "capillary_short",
                        format!("capillary l/d = {ld:.4e} is below {CAPILLARY_MIN_L_OVER_D}: entry losses, which the pipe laws leave out, make its drop inexact"),
                    );
                }
            }
        }
        (Kind::Orifice, Some(re)) if re < ORIFICE_LOW_REYNOLDS => notes.warn(
            "orifice_low_reynolds",
            format!("orifice Reynolds number {re:.4e} is below {ORIFICE_LOW_REYNOLDS}: the discharge coefficient falls towards 0.3 there (Khonsari & Booser §10.5); check the one given"),
        ),
        _ => {}
    }
    let m = op.point.ratio();
    if r.kind != Kind::ConstantFlow && m > INEFFECTIVE_RESTRICTOR_RATIO {
        notes.warn(
            "restrictor_ineffective",
            format!("the restrictor drops only {:.4e} of the supply pressure (recess over supply {m:.6}): the pad's stiffness, {:.4e} of 3W/h, vanishes as the ratio reaches 1; a narrower restrictor (or `pressure_ratio` to design one) restores it", 1.0 - m, op.stiffness * op.point.film / (3.0 * op.point.load)),
        );
    }
    let pressure_re = op.land_pressure_flow_reynolds_number.unwrap_or(0.0);
    let shear_re = op.land_shear_reynolds_number.unwrap_or(0.0);
    if pressure_re > LAND_PRESSURE_FLOW_REYNOLDS_LIMIT {
        let consequence = if laminar {
            "the laminar film law overstates the flow"
        } else {
            "the slit law (Khonsari & Booser Eq. 16.2) was applied where it loses more than the laminar law"
        };
        notes.warn(
            "land_flow_not_laminar",
            format!("the lands' pressure flow has Reynolds number {pressure_re:.4e} (hydraulic diameter 2h) where its flow per unit width peaks, above {LAND_PRESSURE_FLOW_REYNOLDS_LIMIT}: {consequence}"),
        );
    }
    if laminar && shear_re > LAND_SHEAR_REYNOLDS_LIMIT {
        notes.warn(
            "land_shear_not_laminar",
            format!("the lands' shear flow has film Reynolds number {shear_re:.4e}, above {LAND_SHEAR_REYNOLDS_LIMIT}: the laminar friction is understated"),
        );
    }
    if !laminar && shear_re > LAND_SHEAR_REYNOLDS_LIMIT {
        notes.warn(
            "shear_turbulence_on_flow_not_modelled",
            format!("the lands' shear flow is turbulent (film Reynolds number {shear_re:.4e}): its friction is the surface drag's (Khonsari & Booser Eq. 7.17–7.18), but the resistance it adds to the pressure flow (Ng–Pan's G_x, G_y, Eq. 6.27) is not modelled, so the flow is overstated"),
        );
    }
    if !laminar && matches!(case.geometry, Geometry::PerformanceFactors { .. }) {
        notes.warn(
            "turbulent_lands_not_modelled",
            "performance factors are laminar charts: turbulence is applied to the capillary only",
        );
    }
    if let Some(land) = case.geometry.narrowest_land() {
        let ratio = op.point.film / land;
        if ratio > 0.01 {
            notes.warn(
                "film_thick_against_land",
                format!("the film is {ratio:.4e} of the narrowest land (above 0.01): the thin-film (Reynolds) model loses accuracy"),
            );
        }
    }
    if op.power.power_ratio >= 1.0 {
        notes.warn(
            "hydrodynamic_effects",
            format!(
                "friction power is {:.4e} times the pumping power (ζ ≥ 1: a high-speed bearing, Stachowiak & Batchelor §6.4): hydrodynamic pressures, not modelled here, become significant",
                op.power.power_ratio
            ),
        );
    }
    if matches!(case.geometry.drag(), Drag::None) && !matches!(case.motion, Motion::Still) {
        notes.warn(
            "friction_not_modelled",
            "performance factors carry no land friction: friction is reported as zero",
        );
    }
    if case
        .lubricant
        .pour_point_c
        .is_some_and(|p| case.inlet_temperature_c < p)
    {
        notes.warn(
            "below_pour_point",
            "the inlet temperature is below the pour point: the oil does not flow and viscosity laws do not hold",
        );
    }
}
