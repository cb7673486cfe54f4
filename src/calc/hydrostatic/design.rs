//! `POST /v1/hydrostatic-bearings/design`: the texts' design questions. For a load and a
//! circular step pad's outer radius, the recess ratio and film that minimise the total power
//! (pumping + land friction; Khonsari & Booser Eq. 10.17–10.20, Stachowiak & Batchelor §6.4),
//! with the power curves on request; or the hydraulic oil lift of a large journal bearing at
//! start-up (Khonsari & Booser §10.8, Ex 10.4).
//!
//! This file is the wire; the physics is [`super::optimum`] and [`super::lift`].

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::lift::{self, Lift};
use super::optimum::{DesignPoint, FilmChoice, Problem, RATIOS};
use crate::calc::lubricant::{validity, Lubricant, LubricantSpec};
use crate::calc::quantity::{ratio_within, Celsius, NonNegative, Positive};
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::fidelity::{Level, SolverReport};

pub struct HydrostaticDesign;

const MAX_SIZE_M: f64 = 10.0;
const FILM_M: (f64, f64) = (1e-8, 1e-2);
const LOAD_N: (f64, f64) = (1e-6, 1e10);
const MAX_SPEED_RPM: f64 = 1e5;
/// Points of each power curve.
const CURVE_POINTS: usize = 37;

/// The pad whose recess and film are designed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum HydrostaticDesignPadKind {
    /// Circular pad with a central circular recess.
    CircularStep,
}

/// The pad to design: its kind and outer radius (the recess radius is designed).
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct HydrostaticDesignPad {
    pub kind: HydrostaticDesignPadKind,
    /// Outer radius R2, m (> 0, at most 10).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 10.0, example = 0.2032)]
    pub outer_radius_m: Positive,
}

/// A journal bearing's oil lift (Khonsari & Booser §10.8).
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct HydrostaticOilLiftSpec {
    /// Bore D, m (> 0, at most 10).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 10.0, example = 0.508)]
    pub diameter_m: Positive,
    /// Bearing length L, m (> 0, at most 10).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 10.0, example = 0.4572)]
    pub length_m: Positive,
    /// Radial clearance C, m (> 0, below the radius).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 0.1, example = 4.064e-4)]
    pub radial_clearance_m: Positive,
    /// Lift of the journal off the bottom h, m (> 0, below C): ε = 1 − h/C.
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 0.1, example = 1.27e-4)]
    pub lift_m: Positive,
    /// Lift pockets along the bottom line n (1 … 100).
    #[schema(minimum = 1, maximum = 100, example = 3)]
    pub pocket_count: u32,
    /// Area of one pocket A, m² (> 0; all pockets together below the projected area L D).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 10.0, example = 0.003871)]
    pub pocket_area_m2: Positive,
    /// Elwell's breakaway coefficient k_BA, dimensionless (0 … 100; default 3, "typically 3",
    /// found by experiment).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 100.0, example = 3.0)]
    pub breakaway_coefficient: Option<Positive>,
    /// B, the lift zone's effective axial length: the pocket pattern's axial extent plus half
    /// the remaining bearing length, m (> 0, at most L). With it the equilibrium feed pressure
    /// after lift (Eq. 10.45, as printed and unverified: see the warning) and the lift pump's
    /// power follow.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 0.3)]
    pub lift_zone_length_m: Option<Positive>,
}

/// Request: the load, the lubricant, and exactly one of `pad` (minimum-power design) and
/// `oil_lift`.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct HydrostaticDesignInput {
    /// Load W, N (1e-6 … 1e10).
    #[schema(value_type = f64, minimum = 1e-6, maximum = 1e10, example = 479083.0)]
    pub load_n: Positive,
    pub lubricant: LubricantSpec,
    /// Oil temperature, °C (−273 … 1000; default 40): where viscosity and density are taken.
    #[schema(value_type = Option<f64>, minimum = -273.0, maximum = 1000.0, example = 40.0)]
    pub temperature_c: Option<Celsius>,
    /// Pump efficiency η_p, dimensionless (0 … 1; default 1).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1.0, example = 0.8)]
    pub pump_efficiency: Option<Positive>,
    /// The pad to design for minimum power (give this or `oil_lift`).
    pub pad: Option<HydrostaticDesignPad>,
    /// `pad`: runner speed, rpm (0 … 1e5; default 0). At rest only the pumping power counts.
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 1e5, example = 0.0)]
    pub speed_rpm: Option<NonNegative>,
    /// `pad`: hold the film at this value, m (1e-8 … 1e-2, below a tenth of the land at the
    /// optimum); only the recess ratio is then optimised. Required at rest (the pumping power
    /// falls without bound as the film thins) unless `min_film_m` is given.
    #[schema(value_type = Option<f64>, minimum = 1e-8, maximum = 1e-2, example = 7.62e-5)]
    pub film_m: Option<Positive>,
    /// `pad`: the thinnest film allowed, m (1e-8 … 1e-2): the optimum film is raised to it
    /// (dirt, flatness, thermal distortion set it in practice).
    #[schema(value_type = Option<f64>, minimum = 1e-8, maximum = 1e-2, example = 2.5e-5)]
    pub min_film_m: Option<Positive>,
    /// `pad`: include the power curves (over the film at the optimum ratio, and over the recess
    /// ratio at each ratio's film); default false.
    #[serde(default)]
    #[schema(example = false)]
    pub include_power_curve: bool,
    /// The oil lift to size (give this or `pad`).
    pub oil_lift: Option<HydrostaticOilLiftSpec>,
}

/// The parsed request.
#[derive(Debug, Clone, PartialEq)]
pub enum DesignCase {
    MinimumPower {
        problem: Problem,
        density: f64,
        specific_heat: f64,
        include_curve: bool,
        assumptions: Vec<(&'static str, String)>,
    },
    OilLift {
        lift: Lift,
        pump_efficiency: f64,
        assumptions: Vec<(&'static str, String)>,
    },
}

fn lubricant_at(
    spec: LubricantSpec,
    t: f64,
    errors: &mut Vec<FieldError>,
) -> Option<(Lubricant, f64)> {
    match spec.parse("/lubricant") {
        Ok(mut l) => {
            let mu = l.viscosity_pa_s(t);
            if mu.is_finite() && mu > 0.0 {
                l.assumptions.extend(validity::hot_oil("the oil", t));
                Some((l, mu))
            } else {
                errors.push(FieldError::new(
                    "/temperature_c",
                    format!("the lubricant's viscosity law has no value at {t} °C"),
                ));
                None
            }
        }
        Err(mut e) => {
            errors.append(&mut e);
            None
        }
    }
}

impl Validate for HydrostaticDesignInput {
    type Valid = DesignCase;
    fn validate(self) -> Result<DesignCase, Vec<FieldError>> {
        let mut errors = Vec::new();
        let load = self.load_n.get();
        if !(LOAD_N.0..=LOAD_N.1).contains(&load) {
            errors.push(FieldError::new(
                "/load_n",
                format!(
                    "must be within [{:e}, {:e}] N, got {load}",
                    LOAD_N.0, LOAD_N.1
                ),
            ));
        }
        if let Some(eta) = self.pump_efficiency.map(Positive::get).filter(|&e| e > 1.0) {
            errors.push(FieldError::new(
                "/pump_efficiency",
                format!("must be within (0, 1], got {eta}"),
            ));
        }
        let t = self.temperature_c.map_or(40.0, Celsius::get);
        let lubricant = lubricant_at(self.lubricant, t, &mut errors);
        let eta = self.pump_efficiency.map_or(1.0, Positive::get).min(1.0);
        for (name, film) in [("film_m", self.film_m), ("min_film_m", self.min_film_m)] {
            if let Some(h) = film.map(Positive::get) {
                if !(FILM_M.0..=FILM_M.1).contains(&h) {
                    errors.push(FieldError::new(
                        format!("/{name}"),
                        format!("must be within [{:e}, {:e}] m, got {h}", FILM_M.0, FILM_M.1),
                    ));
                }
            }
        }
        let case = match (self.pad, self.oil_lift) {
            (Some(_), Some(_)) | (None, None) => {
                for pointer in ["/pad", "/oil_lift"] {
                    errors.push(FieldError::new(
                        pointer,
                        "give exactly one of pad (minimum-power design) and oil_lift",
                    ));
                }
                None
            }
            (Some(pad), None) => {
                let r2 = pad.outer_radius_m.get();
                if r2 > MAX_SIZE_M {
                    errors.push(FieldError::new(
                        "/pad/outer_radius_m",
                        format!("must be at most {MAX_SIZE_M} m"),
                    ));
                }
                let n = self.speed_rpm.map_or(0.0, NonNegative::get);
                if n > MAX_SPEED_RPM {
                    errors.push(FieldError::new(
                        "/speed_rpm",
                        format!("must be at most {MAX_SPEED_RPM} rpm, got {n}"),
                    ));
                }
                let film = match (self.film_m, self.min_film_m) {
                    (Some(_), Some(_)) => {
                        errors.push(FieldError::new(
                            "/min_film_m",
                            "give film_m (held) or min_film_m (a floor for the optimum film), not both",
                        ));
                        FilmChoice::Fixed(1e-5)
                    }
                    (Some(h), None) => FilmChoice::Fixed(h.get()),
                    (None, min) if n > 0.0 => FilmChoice::Free {
                        min: min.map(Positive::get),
                    },
                    (None, Some(min)) => FilmChoice::Fixed(min.get()),
                    (None, None) => {
                        errors.push(FieldError::new(
                            "/film_m",
                            "at rest the pumping power falls without bound as the film thins: give film_m, min_film_m or a speed_rpm",
                        ));
                        FilmChoice::Fixed(1e-5)
                    }
                };
                lubricant.map(|(l, mu)| DesignCase::MinimumPower {
                    problem: Problem {
                        outer_radius: r2,
                        load,
                        viscosity: mu,
                        omega: n * std::f64::consts::PI / 30.0,
                        pump_efficiency: eta,
                        film,
                    },
                    density: l.density_kg_m3(t),
                    specific_heat: l.specific_heat_j_kg_k(t),
                    include_curve: self.include_power_curve,
                    assumptions: l.assumptions,
                })
            }
            (None, Some(spec)) => {
                for (name, present) in [
                    ("speed_rpm", self.speed_rpm.is_some()),
                    ("film_m", self.film_m.is_some()),
                    ("min_film_m", self.min_film_m.is_some()),
                    ("include_power_curve", self.include_power_curve),
                ] {
                    if present {
                        errors.push(FieldError::new(
                            format!("/{name}"),
                            "belongs to a pad design, not to an oil lift",
                        ));
                    }
                }
                let (d, l, c, h) = (
                    spec.diameter_m.get(),
                    spec.length_m.get(),
                    spec.radial_clearance_m.get(),
                    spec.lift_m.get(),
                );
                for (name, v) in [("diameter_m", d), ("length_m", l)] {
                    if v > MAX_SIZE_M {
                        errors.push(FieldError::new(
                            format!("/oil_lift/{name}"),
                            format!("must be at most {MAX_SIZE_M} m"),
                        ));
                    }
                }
                if c >= 0.05 * d {
                    errors.push(FieldError::new(
                        "/oil_lift/radial_clearance_m",
                        format!("must be below a tenth of the radius ({:.6e} m)", 0.05 * d),
                    ));
                }
                if h >= c {
                    errors.push(FieldError::new(
                        "/oil_lift/lift_m",
                        format!("must be below the radial clearance ({c} m): a lift of C or more leaves the journal nothing to hold it"),
                    ));
                }
                if !(1..=100).contains(&spec.pocket_count) {
                    errors.push(FieldError::new(
                        "/oil_lift/pocket_count",
                        "must be within [1, 100]",
                    ));
                }
                let pockets = spec.pocket_count as f64 * spec.pocket_area_m2.get();
                if pockets >= l * d {
                    errors.push(FieldError::new(
                        "/oil_lift/pocket_area_m2",
                        format!("the pockets ({pockets:.6e} m²) must cover less than the projected area L·D ({:.6e} m²)", l * d),
                    ));
                }
                if let Some(b) = spec.lift_zone_length_m.map(Positive::get) {
                    if !ratio_within(b / l, 0.0, 1.0) {
                        errors.push(FieldError::new(
                            "/oil_lift/lift_zone_length_m",
                            format!("must be at most the bearing length ({l} m)"),
                        ));
                    }
                }
                let k = spec.breakaway_coefficient.map_or(3.0, Positive::get);
                if k > 100.0 {
                    errors.push(FieldError::new(
                        "/oil_lift/breakaway_coefficient",
                        "must be at most 100",
                    ));
                }
                lubricant.map(|(lub, mu)| DesignCase::OilLift {
                    lift: Lift {
                        load,
                        diameter: d,
                        length: l,
                        clearance: c,
                        lift: h,
                        pockets: spec.pocket_count,
                        pocket_area: spec.pocket_area_m2.get(),
                        breakaway_coefficient: k,
                        lift_zone_length: spec.lift_zone_length_m.map(Positive::get),
                        viscosity: mu,
                    },
                    pump_efficiency: eta,
                    // The lift needs only the viscosity: an assumed density is no assumption.
                    assumptions: lub
                        .assumptions
                        .into_iter()
                        .filter(|(code, _)| *code != "density_assumed")
                        .collect(),
                })
            }
        };
        match case {
            Some(case) if errors.is_empty() => Ok(case),
            _ => Err(errors),
        }
    }
}

/// A point of a power curve.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct HydrostaticPowerPoint {
    /// R1/R2, dimensionless.
    pub recess_ratio: f64,
    /// h, m.
    pub film_thickness_m: f64,
    /// p_s, Pa.
    pub supply_pressure_pa: f64,
    /// Q, m³/s.
    pub flow_m3_s: f64,
    /// p_s Q/η_p, W.
    pub pumping_power_w: f64,
    /// Land friction power, W.
    pub friction_power_w: f64,
    /// Pumping + friction power, W.
    pub total_power_w: f64,
}

impl From<&DesignPoint> for HydrostaticPowerPoint {
    fn from(d: &DesignPoint) -> Self {
        HydrostaticPowerPoint {
            recess_ratio: d.ratio,
            film_thickness_m: d.film,
            supply_pressure_pa: d.supply,
            flow_m3_s: d.flow,
            pumping_power_w: d.pumping,
            friction_power_w: d.friction,
            total_power_w: d.total(),
        }
    }
}

/// The power curves.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct HydrostaticPowerCurves {
    /// Over the film, ¼ to 4 times the optimum's, at the optimum recess ratio.
    pub over_film: Vec<HydrostaticPowerPoint>,
    /// Over the recess ratio, 0.05 to 0.95, each at its own best (or the held) film.
    pub over_recess_ratio: Vec<HydrostaticPowerPoint>,
}

/// The minimum-power circular step pad (constant flow: p_s = p_r).
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct HydrostaticMinimumPower {
    /// R1/R2, dimensionless (0.53354 at rest: Eq. 10.19).
    pub recess_ratio: f64,
    /// R1, m.
    pub recess_radius_m: f64,
    /// R2, m.
    pub outer_radius_m: f64,
    /// `held` (film_m), `optimum` (E_f = 3 E_p) or `minimum` (raised to min_film_m).
    #[schema(example = "optimum")]
    pub film_choice: &'static str,
    /// h, m.
    pub film_thickness_m: f64,
    /// A_eff, m².
    pub effective_area_m2: f64,
    /// p_s = p_r = W/A_eff, Pa.
    pub supply_pressure_pa: f64,
    /// Q, m³/s.
    pub flow_m3_s: f64,
    /// 3W/h (constant flow), N/m.
    pub stiffness_n_m: f64,
    /// p_s Q/η_p, W.
    pub pumping_power_w: f64,
    /// Land friction torque, N·m.
    pub friction_torque_n_m: f64,
    /// Land friction power ω T, W.
    pub friction_power_w: f64,
    /// Pumping + friction power, W.
    pub total_power_w: f64,
    /// ζ = friction/pumping power (3 at a free optimum film).
    pub power_ratio: f64,
    /// ΔT = total power/(ρ c_p Q), K.
    pub temperature_rise_k: f64,
    /// μ, Pa·s.
    pub viscosity_pa_s: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub power_curve: Option<HydrostaticPowerCurves>,
}

/// The oil lift.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct HydrostaticOilLiftResult {
    /// Elwell's breakaway pocket pressure P_BA = k_BA W/(D n √A), Pa (Eq. 10.46).
    pub breakaway_pressure_pa: f64,
    /// ε = 1 − h/C at the lift, dimensionless.
    pub eccentricity_ratio: f64,
    /// Fuller's flow holding the lift, m³/s (Eq. 10.44).
    pub lift_flow_m3_s: f64,
    /// Equilibrium feed pressure after lift, Pa (Eq. 10.45; with `lift_zone_length_m`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub equilibrium_pressure_pa: Option<f64>,
    /// P_BA over the equilibrium pressure (1.2 … 4 in practice, Khonsari & Booser §10.8).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub breakaway_to_equilibrium_ratio: Option<f64>,
    /// Lift pump power at the equilibrium pressure P Q/η_p, W.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pumping_power_w: Option<f64>,
    /// n A/(L D), dimensionless.
    pub pocket_area_fraction: f64,
    /// μ, Pa·s.
    pub viscosity_pa_s: f64,
}

/// Result: one of the two blocks, as asked.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct HydrostaticDesignOutput {
    #[serde(skip_serializing_if = "Option::is_none")]
    pub minimum_power: Option<HydrostaticMinimumPower>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub oil_lift: Option<HydrostaticOilLiftResult>,
}

impl Calculation for HydrostaticDesign {
    const PATH: &'static str = "/v1/hydrostatic-bearings/design";
    const SUMMARY: &'static str = "Hydrostatic design: the circular step's minimum-power recess ratio and film (with power curves), or a journal bearing's oil lift at start-up";
    const DESCRIPTION: &'static str = include_str!("design.md");
    const FIDELITY: &'static [Level] = &[Level::ClosedForm];
    const EFFECTS: &'static [&'static str] = &[];
    const EXAMPLE: &'static str = r#"{"load_n": 479083, "lubricant": {"viscosity_pa_s": 0.054124, "density_15c_kg_m3": 850}, "pump_efficiency": 0.8, "pad": {"kind": "circular_step", "outer_radius_m": 0.2032}, "film_m": 7.62e-5}"#;

    type Input = HydrostaticDesignInput;
    type Output = HydrostaticDesignOutput;

    fn run(case: DesignCase, ctx: &mut Context) -> Result<HydrostaticDesignOutput, CalcError> {
        match case {
            DesignCase::MinimumPower {
                problem,
                density,
                specific_heat,
                include_curve,
                assumptions,
            } => {
                for (code, message) in &assumptions {
                    ctx.warn(code, message.clone());
                }
                let (d, evaluations) = problem.optimum();
                let film_choice = match problem.film {
                    FilmChoice::Fixed(_) => "held",
                    FilmChoice::Free { min: Some(m) } if d.film == m => "minimum",
                    FilmChoice::Free { .. } => "optimum",
                };
                let r2 = problem.outer_radius;
                let land = r2 * (1.0 - d.ratio);
                if d.film > 0.1 * land {
                    return Err(CalcError::impossible(
                        "/film_m",
                        format!("the film {:.6e} m is above a tenth of the optimum pad's land ({land:.6e} m): not a thin film", d.film),
                    ));
                }
                if d.film > 0.01 * land {
                    ctx.warn("film_thick_against_land", format!("the film is {:.4e} of the land (above 0.01): the thin-film model loses accuracy", d.film / land));
                }
                let (lo, hi) = RATIOS;
                if d.ratio < lo + 1e-6 || d.ratio > hi - 1e-6 {
                    ctx.warn("optimum_at_search_bound", format!("the minimum lies at the searched bound R1/R2 = {:.4}: the power still falls beyond it (friction dominates: consider a thicker film)", d.ratio));
                }
                if d.friction >= d.pumping && matches!(problem.film, FilmChoice::Free { .. }) {
                    ctx.warn("hydrodynamic_effects", format!("friction power is {:.4e} times the pumping power (ζ ≥ 1, Stachowiak & Batchelor §6.4): hydrodynamic pressures, not modelled, become significant", d.friction / d.pumping));
                }
                let area = problem.load / d.supply;
                let curve = include_curve.then(|| {
                    let over_film = (0..CURVE_POINTS)
                        .map(|i| {
                            let s = 4f64.powf(2.0 * i as f64 / (CURVE_POINTS - 1) as f64 - 1.0);
                            HydrostaticPowerPoint::from(&problem.point(d.ratio, d.film * s))
                        })
                        .collect();
                    let over_recess_ratio = (0..CURVE_POINTS)
                        .map(|i| {
                            let x = lo + (hi - lo) * i as f64 / (CURVE_POINTS - 1) as f64;
                            HydrostaticPowerPoint::from(&problem.at_ratio(x))
                        })
                        .collect();
                    HydrostaticPowerCurves {
                        over_film,
                        over_recess_ratio,
                    }
                });
                let out = HydrostaticMinimumPower {
                    recess_ratio: d.ratio,
                    recess_radius_m: d.ratio * r2,
                    outer_radius_m: r2,
                    film_choice,
                    film_thickness_m: d.film,
                    effective_area_m2: area,
                    supply_pressure_pa: d.supply,
                    flow_m3_s: d.flow,
                    stiffness_n_m: 3.0 * problem.load / d.film,
                    pumping_power_w: d.pumping,
                    friction_torque_n_m: d.friction_torque,
                    friction_power_w: d.friction,
                    total_power_w: d.total(),
                    power_ratio: d.friction / d.pumping,
                    temperature_rise_k: d.total() / (density * specific_heat * d.flow),
                    viscosity_pa_s: problem.viscosity,
                    power_curve: curve,
                };
                let mut numbers = vec![
                    out.recess_ratio,
                    out.film_thickness_m,
                    out.effective_area_m2,
                    out.supply_pressure_pa,
                    out.flow_m3_s,
                    out.stiffness_n_m,
                    out.total_power_w,
                    out.power_ratio,
                    out.temperature_rise_k,
                    out.friction_torque_n_m,
                ];
                if let Some(c) = &out.power_curve {
                    for p in c.over_film.iter().chain(&c.over_recess_ratio) {
                        numbers.extend([
                            p.film_thickness_m,
                            p.supply_pressure_pa,
                            p.flow_m3_s,
                            p.total_power_w,
                        ]);
                    }
                }
                CalcError::unless_finite(&numbers)?;
                ctx.report(SolverReport::closed_form_search(
                    "minimum_power_scan_brent",
                    evaluations,
                ));
                Ok(HydrostaticDesignOutput {
                    minimum_power: Some(out),
                    oil_lift: None,
                })
            }
            DesignCase::OilLift {
                lift: l,
                pump_efficiency,
                assumptions,
            } => {
                for (code, message) in &assumptions {
                    ctx.warn(code, message.clone());
                }
                let r = lift::lift(&l);
                let ratio = r.equilibrium_pressure.map(|p| r.breakaway_pressure / p);
                if r.equilibrium_pressure.is_some() {
                    ctx.warn("equilibrium_pressure_unverified", "Eq. 10.45 is evaluated as printed; the book evaluates it in no example and it could not be checked (with Ex 10.4's bearing and a lift zone of 0.3 m it exceeds the breakaway pressure, against the text's rule that breakaway is 1.2 to 4 times it): treat it as an estimate");
                }
                if let Some(k) = ratio.filter(|k| !(1.2..=4.0).contains(k)) {
                    ctx.warn("breakaway_ratio_unusual", format!("breakaway pressure is {k:.4} times the equilibrium pressure; practice gives 1.2 to 4 (Khonsari & Booser §10.8): check k_BA and the lift zone length"));
                }
                if !(0.01..=0.1).contains(&r.pocket_area_fraction) {
                    ctx.warn("pocket_area_unusual", format!("the pockets cover {:.4e} of the projected area; the texts' experience spans 1 % to 10 %", r.pocket_area_fraction));
                }
                let out = HydrostaticOilLiftResult {
                    breakaway_pressure_pa: r.breakaway_pressure,
                    eccentricity_ratio: r.eccentricity_ratio,
                    lift_flow_m3_s: r.flow,
                    equilibrium_pressure_pa: r.equilibrium_pressure,
                    breakaway_to_equilibrium_ratio: ratio,
                    pumping_power_w: r.equilibrium_pressure.map(|p| p * r.flow / pump_efficiency),
                    pocket_area_fraction: r.pocket_area_fraction,
                    viscosity_pa_s: l.viscosity,
                };
                let mut numbers = vec![
                    out.breakaway_pressure_pa,
                    out.eccentricity_ratio,
                    out.lift_flow_m3_s,
                    out.pocket_area_fraction,
                ];
                numbers.extend(
                    [out.equilibrium_pressure_pa, ratio, out.pumping_power_w]
                        .into_iter()
                        .flatten(),
                );
                CalcError::unless_finite(&numbers)?;
                ctx.report(SolverReport::closed_form("oil_lift_closed_form"));
                Ok(HydrostaticDesignOutput {
                    minimum_power: None,
                    oil_lift: Some(out),
                })
            }
        }
    }
}
