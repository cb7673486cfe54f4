//! `POST /v1/squeeze-films/piston-ring`: a compression ring's film over an engine cycle — the
//! reciprocating crowned slider that squeezes at the dead centres (Khonsari & Booser §9.7,
//! Eqs. 9.44–9.59, Table 9.5; spec SQ-8).
//!
//! This file is the wire (request, validation, response); the physics is
//! [`super::piston_film`].

use std::f64::consts::PI;

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::piston_film::{Boundary, CycleError, Engine, Numerics, PistonRing, Ring, Sample};
use crate::calc::journal::dynamic::{ascending_angles, PressurePoint};
use crate::calc::lubricant::isoviscous::{self, Viscosity};
use crate::calc::lubricant::LubricantSpec;
use crate::calc::quantity::{Celsius, Positive};
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::fidelity::{FidelityRequest, Level};

pub struct PistonRingSqueeze;

/// Table 9.5's boundary friction coefficient f (Jeng 1992).
const DEFAULT_FRICTION_COEFFICIENT: f64 = 0.08;
/// P_bot / P_top: "half of that pressure" (Jeng 1992, as the text takes it).
const DEFAULT_BOTTOM_FRACTION: f64 = 0.5;
/// The shooting's first guess of h_m(0), as a share of the crown height.
const DEFAULT_GUESS_OVER_CROWN: f64 = 0.1;

/// The ring.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct PistonRingSpec {
    /// Axial width b of the ring face, m (0 … 0.05; Table 9.5: 1.475 mm).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 0.05, example = 1.475e-3)]
    pub width_m: Positive,
    /// Crown height δ₀ of the parabolic face, m (0 … 1e-3, below the width; Table 9.5:
    /// 14.9 μm). A flat face (δ₀ = 0) has no wedge and is refused.
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 1e-3, example = 14.9e-6)]
    pub crown_height_m: Positive,
    /// Radial thickness t_r of the ring, m (0 … 0.05, below the bore radius; Table 9.5:
    /// 3.8 mm).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 0.05, example = 3.8e-3)]
    pub thickness_m: Positive,
    /// Young's modulus E of the ring, Pa (1e8 … 1e12; Table 9.5: 70 GPa).
    #[schema(value_type = f64, minimum = 1e8, maximum = 1e12, example = 70e9)]
    pub modulus_pa: Positive,
    /// The ring's own tension pressure on the liner at zero deflection, Pa (0 … 1e8; default
    /// 0, the text's Eq. 9.50).
    #[serde(default)]
    #[schema(minimum = 0.0, maximum = 1e8, example = 0.0)]
    pub tension_pressure_pa: f64,
}

/// The engine.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct PistonEngineSpec {
    /// Cylinder bore B, m (0.005 … 2; Table 9.5: 88.9 mm).
    #[schema(value_type = f64, minimum = 0.005, maximum = 2.0, example = 0.0889)]
    pub bore_m: Positive,
    /// Crank radius R, m (0 … 1; Table 9.5: 40 mm).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 1.0, example = 0.040)]
    pub crank_radius_m: Positive,
    /// Connecting-rod length L, m (above 1.2 R, at most 5; Table 9.5: 141.9 mm).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 5.0, example = 0.1419)]
    pub rod_length_m: Positive,
    /// Crank speed, rev/min (1 … 20 000; Table 9.5: 2000).
    #[schema(value_type = f64, minimum = 1.0, maximum = 20000.0, example = 2000.0)]
    pub speed_rpm: Positive,
    /// The cycle in crank angle, degrees: 720 (four-stroke, default) or 360 (two-stroke).
    #[serde(default = "four_stroke")]
    #[schema(minimum = 360.0, maximum = 720.0, example = 720.0)]
    pub cycle_deg: f64,
}

fn four_stroke() -> f64 {
    720.0
}

/// Request.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct PistonRingInput {
    pub ring: PistonRingSpec,
    pub engine: PistonEngineSpec,
    /// Gas pressure above the ring over one cycle (above the crankcase's, Pa; crank angle from
    /// top dead centre of the power stroke), at least 3 points ascending within the cycle,
    /// joined by the periodic cubic. Default: none — both sides at the crankcase pressure (a
    /// ring loaded by its own tension and stiffness only). The text's Fig. 9.25 is not
    /// digitised: give the engine's own.
    #[serde(default)]
    #[schema(example = json!([{"crank_angle_deg": 0.0, "pressure_pa": 4e6}, {"crank_angle_deg": 20.0, "pressure_pa": 6e6}, {"crank_angle_deg": 180.0, "pressure_pa": 2e5}, {"crank_angle_deg": 360.0, "pressure_pa": 0.0}, {"crank_angle_deg": 680.0, "pressure_pa": 1e6}]))]
    pub gas_pressure: Vec<PressurePoint>,
    /// P_bot / P_top, the pressure below the ring as a share of the one above (0 … 1; default
    /// 0.5, Jeng's "half" that the text takes).
    #[serde(default)]
    #[schema(minimum = 0.0, maximum = 1.0, example = 0.5)]
    pub bottom_pressure_fraction: Option<f64>,
    pub lubricant: LubricantSpec,
    /// Film temperature, °C (−273 … 1000): where the viscosity is taken; required unless the
    /// lubricant has a constant `viscosity_pa_s`.
    #[schema(value_type = Option<f64>, minimum = -273.0, maximum = 1000.0, example = 100.0)]
    pub temperature_c: Option<Celsius>,
    /// Composite roughness σ of ring and liner, m (0 … 1e-4; Table 9.5: 0.5 μm): where the
    /// film is thinner the friction is the boundary one (Eq. 9.56) and a warning says so.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e-4, example = 0.5e-6)]
    pub composite_roughness_m: Option<Positive>,
    /// Boundary friction coefficient μ_c (0 … 1; default 0.08, Table 9.5), with
    /// `composite_roughness_m`.
    #[schema(minimum = 0.0, maximum = 1.0, example = 0.08)]
    pub boundary_friction_coefficient: Option<f64>,
    /// The shooting's first guess of the film at 0°, m (1e-10 … 1e-3; default a tenth of the
    /// crown). The converged cycle does not depend on it.
    #[schema(value_type = Option<f64>, minimum = 1e-10, maximum = 1e-3, example = 1e-6)]
    pub initial_film_m: Option<Positive>,
    /// `fast`, `standard` (default), `high`, or `{"grid": [cells across the face 20…2000, 1],
    /// "tolerance": 1e-10…1e-4}` (the integrator's relative tolerance; the cycle repeats to 10
    /// times it).
    #[serde(default)]
    pub fidelity: FidelityRequest,
    /// Include the path: the film, speeds, pressures, friction and power at every crank-angle
    /// degree of the cycle.
    #[serde(default)]
    #[schema(example = false)]
    pub include_field: bool,
}

/// The parsed request.
#[derive(Debug, Clone, PartialEq)]
pub struct PistonRingCase {
    pub model: PistonRing,
    pub viscosity: Viscosity,
    pub numerics: Numerics,
    pub level: Level,
    pub guess: f64,
    pub include_field: bool,
}

/// The numerical settings of a level: cells across the face and the integrator's tolerance.
fn level_numerics(level: Level) -> (usize, f64) {
    match level {
        Level::Fast => (60, 1e-5),
        Level::High => (400, 1e-8),
        _ => (160, 1e-6),
    }
}

impl Validate for PistonRingInput {
    type Valid = PistonRingCase;
    fn validate(self) -> Result<PistonRingCase, Vec<FieldError>> {
        let mut errors = Vec::new();
        let viscosity = isoviscous::viscosity(self.lubricant, self.temperature_c, &mut errors);
        let (ring, engine) = (self.ring, self.engine);
        let (b, crown, t_r, modulus) = (
            ring.width_m.get(),
            ring.crown_height_m.get(),
            ring.thickness_m.get(),
            ring.modulus_pa.get(),
        );
        let (bore, crank, rod, rpm) = (
            engine.bore_m.get(),
            engine.crank_radius_m.get(),
            engine.rod_length_m.get(),
            engine.speed_rpm.get(),
        );
        FieldError::check_at_most(&mut errors, "/ring/width_m", b, 0.05);
        FieldError::check_at_most(&mut errors, "/ring/crown_height_m", crown, 1e-3);
        if crown >= b {
            errors.push(FieldError::new(
                "/ring/crown_height_m",
                "must be below the ring's width (a thin film on a gently crowned face)",
            ));
        }
        FieldError::check_within(&mut errors, "/ring/modulus_pa", modulus, (1e8, 1e12));
        FieldError::check_within(
            &mut errors,
            "/ring/tension_pressure_pa",
            ring.tension_pressure_pa,
            (0.0, 1e8),
        );
        FieldError::check_within(&mut errors, "/engine/bore_m", bore, (0.005, 2.0));
        if t_r >= 0.5 * bore || t_r > 0.05 {
            errors.push(FieldError::new(
                "/ring/thickness_m",
                "must be at most 0.05 m and below the bore radius",
            ));
        }
        if b >= bore {
            errors.push(FieldError::new("/ring/width_m", "must be below the bore"));
        }
        FieldError::check_at_most(&mut errors, "/engine/crank_radius_m", crank, 1.0);
        if !(rod > 1.2 * crank && rod <= 5.0) {
            errors.push(FieldError::new(
                "/engine/rod_length_m",
                format!("must exceed 1.2 times the crank radius ({crank} m) and be at most 5 m: a rod no longer than the crank cannot drive the piston through the cycle"),
            ));
        }
        FieldError::check_within(&mut errors, "/engine/speed_rpm", rpm, (1.0, 20000.0));
        let cycle = engine.cycle_deg;
        if cycle != 720.0 && cycle != 360.0 {
            errors.push(FieldError::new(
                "/engine/cycle_deg",
                format!("must be 720 (four-stroke) or 360 (two-stroke), got {cycle}"),
            ));
        }
        let (angles, pressures) = if self.gas_pressure.is_empty() {
            (vec![0.0], vec![0.0])
        } else {
            let degrees: Vec<f64> = self
                .gas_pressure
                .iter()
                .map(|p| p.crank_angle_deg)
                .collect();
            let angles = ascending_angles(&mut errors, "/gas_pressure", &degrees, cycle);
            for (i, p) in self.gas_pressure.iter().enumerate() {
                FieldError::check_within(
                    &mut errors,
                    format!("/gas_pressure/{i}/pressure_pa"),
                    p.pressure_pa,
                    (-1e5, 1e9),
                );
            }
            (
                angles,
                self.gas_pressure.iter().map(|p| p.pressure_pa).collect(),
            )
        };
        let bottom_fraction = self
            .bottom_pressure_fraction
            .unwrap_or(DEFAULT_BOTTOM_FRACTION);
        FieldError::check_within(
            &mut errors,
            "/bottom_pressure_fraction",
            bottom_fraction,
            (0.0, 1.0),
        );
        let friction = self
            .boundary_friction_coefficient
            .unwrap_or(DEFAULT_FRICTION_COEFFICIENT);
        FieldError::check_within(
            &mut errors,
            "/boundary_friction_coefficient",
            friction,
            (0.0, 1.0),
        );
        if self.boundary_friction_coefficient.is_some() && self.composite_roughness_m.is_none() {
            errors.push(FieldError::new(
                "/boundary_friction_coefficient",
                "applies below the composite roughness: give composite_roughness_m with it",
            ));
        }
        if let Some(sigma) = self.composite_roughness_m {
            FieldError::check_at_most(&mut errors, "/composite_roughness_m", sigma.get(), 1e-4);
        }
        let guess = self
            .initial_film_m
            .map_or(DEFAULT_GUESS_OVER_CROWN * crown, Positive::get);
        FieldError::check_within(&mut errors, "/initial_film_m", guess, (1e-10, 1e-3));
        let (level, (cells, tolerance)) = match self.fidelity {
            FidelityRequest::Level(Level::ClosedForm) => {
                errors.push(FieldError::new(
                    "/fidelity",
                    "the piston ring has no closed form over a cycle: give fast, standard or high",
                ));
                (Level::ClosedForm, (2, 1e-6))
            }
            FidelityRequest::Level(level) => (level, level_numerics(level)),
            FidelityRequest::Custom(custom) => {
                let (mut cells, mut tolerance) = level_numerics(Level::Standard);
                if let Some([nx, ny]) = custom.grid {
                    if !(20..=2000).contains(&nx) || ny != 1 {
                        errors.push(FieldError::new(
                            "/fidelity/grid",
                            "must be [cells across the face 20…2000, 1] (the film is 1-D)",
                        ));
                    }
                    cells = 2 * (nx as usize).div_ceil(2);
                }
                if let Some(t) = custom.tolerance {
                    FieldError::check_within(&mut errors, "/fidelity/tolerance", t, (1e-10, 1e-4));
                    tolerance = t;
                }
                (Level::Standard, (cells, tolerance))
            }
        };
        let Some(viscosity) = viscosity.filter(|_| errors.is_empty()) else {
            return Err(errors);
        };
        let boundary = self.composite_roughness_m.map(|sigma| Boundary {
            roughness: sigma.get(),
            friction_coefficient: friction,
        });
        let bore_radius = 0.5 * bore;
        Ok(PistonRingCase {
            model: PistonRing {
                ring: Ring {
                    half_width: 0.5 * b,
                    crown_height: crown,
                    stiffness: modulus * t_r / (bore_radius * bore_radius),
                    tension_pressure: ring.tension_pressure_pa,
                },
                engine: Engine {
                    bore,
                    crank_radius: crank,
                    rod_length: rod,
                    omega: rpm * PI / 30.0,
                    cycle: cycle.to_radians(),
                    angles,
                    pressures,
                    bottom_fraction,
                },
                viscosity: viscosity.pa_s,
                boundary,
            },
            viscosity,
            numerics: Numerics {
                cells,
                tolerance,
                periodicity: 10.0 * tolerance,
            },
            level,
            guess,
            include_field: self.include_field,
        })
    }
}

/// One crank angle of the converged cycle.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct CyclePoint {
    /// Crank angle from top dead centre of the power stroke, degrees.
    pub crank_angle_deg: f64,
    /// Minimum film h_m, m.
    pub min_film_m: f64,
    /// Piston speed towards the crankcase, m/s.
    pub piston_speed_m_s: f64,
    /// Gas pressure above the ring, Pa (gauge).
    pub top_pressure_pa: f64,
    /// Gas pressure below the ring, Pa (gauge).
    pub bottom_pressure_pa: f64,
    /// dh_m/dt, m/s (positive while the film opens).
    pub squeeze_velocity_m_s: f64,
    /// The film's radial force on the whole ring, π B ∫P dx, N.
    pub film_load_n: f64,
    /// Peak film pressure, Pa.
    pub max_pressure_pa: f64,
    /// Friction on the ring along the bore axis, N (positive towards the crankcase).
    pub friction_force_n: f64,
    /// Power loss, W.
    pub power_loss_w: f64,
    /// `hydrodynamic`, or `boundary` where h_m is below the composite roughness.
    pub regime: &'static str,
}

impl CyclePoint {
    fn of(s: &Sample) -> Self {
        CyclePoint {
            crank_angle_deg: s.theta.to_degrees(),
            min_film_m: s.min_film,
            piston_speed_m_s: s.piston_speed,
            top_pressure_pa: s.top_pressure,
            bottom_pressure_pa: s.bottom_pressure,
            squeeze_velocity_m_s: s.squeeze_velocity,
            film_load_n: s.load,
            max_pressure_pa: s.max_pressure,
            friction_force_n: s.friction,
            power_loss_w: s.power,
            regime: if s.boundary {
                "boundary"
            } else {
                "hydrodynamic"
            },
        }
    }
}

/// Result: the converged cycle.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct PistonRingOutput {
    /// Viscosity used, Pa·s.
    pub viscosity_pa_s: f64,
    /// The ring's radial stiffness as a thin-walled ring, K = E t_r / r² (r the bore radius),
    /// Pa per m of deflection: the film carries 2a (P_top + p_e + K h_m) per unit
    /// circumference (Eq. 9.50).
    pub ring_stiffness_pa_per_m: f64,
    /// The smallest film over the cycle, m.
    pub min_film_m: f64,
    /// Where the film is smallest, crank-angle degrees from top dead centre of the power
    /// stroke.
    pub min_film_crank_angle_deg: f64,
    /// The largest film over the cycle, m.
    pub max_film_m: f64,
    /// Where the film is largest, crank-angle degrees.
    pub max_film_crank_angle_deg: f64,
    /// The largest friction force on the ring (magnitude) over the degree samples, N.
    pub max_friction_force_n: f64,
    /// Where the friction is largest, crank-angle degrees.
    pub max_friction_crank_angle_deg: f64,
    /// The largest power loss over the degree samples, W.
    pub max_power_loss_w: f64,
    /// Where the power loss is largest, crank-angle degrees.
    pub max_power_crank_angle_deg: f64,
    /// Cycle-mean power loss of the ring, W.
    pub mean_power_loss_w: f64,
    /// Crank-angle degrees of the cycle with h_m below the composite roughness (boundary
    /// friction); 0 without a roughness.
    pub boundary_lubrication_deg: f64,
    /// Cycles integrated until the cycle repeated.
    pub cycles: u32,
    /// The path, with `include_field`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub path: Option<Vec<CyclePoint>>,
}

impl Calculation for PistonRingSqueeze {
    const PATH: &'static str = "/v1/squeeze-films/piston-ring";
    const SUMMARY: &'static str = "Piston-ring film over an engine cycle: minimum film, friction and power loss of a crowned compression ring (squeeze and sliding, cavitating)";
    const DESCRIPTION: &'static str = include_str!("piston_ring.md");
    const FIDELITY: &'static [Level] = &[Level::Fast, Level::Standard, Level::High];
    const EFFECTS: &'static [&'static str] = &[];
    const EXAMPLE: &'static str = r#"{"ring": {"width_m": 1.475e-3, "crown_height_m": 14.9e-6, "thickness_m": 3.8e-3, "modulus_pa": 70e9}, "engine": {"bore_m": 0.0889, "crank_radius_m": 0.040, "rod_length_m": 0.1419, "speed_rpm": 2000}, "gas_pressure": [{"crank_angle_deg": 0, "pressure_pa": 4e6}, {"crank_angle_deg": 20, "pressure_pa": 6e6}, {"crank_angle_deg": 60, "pressure_pa": 1.5e6}, {"crank_angle_deg": 180, "pressure_pa": 2e5}, {"crank_angle_deg": 360, "pressure_pa": 0}, {"crank_angle_deg": 540, "pressure_pa": 1e5}, {"crank_angle_deg": 680, "pressure_pa": 1e6}], "lubricant": {"viscosity_pa_s": 0.00689}, "composite_roughness_m": 0.5e-6, "fidelity": "fast"}"#;

    type Input = PistonRingInput;
    type Output = PistonRingOutput;

    fn run(case: PistonRingCase, ctx: &mut Context) -> Result<PistonRingOutput, CalcError> {
        for (code, message) in &case.viscosity.assumptions {
            ctx.warn(code, message.clone());
        }
        let model = &case.model;
        let cycle = model
            .cycle(case.guess, &case.numerics, &ctx.budget())
            .map_err(|e| match e {
                CycleError::Stopped(stopped) => CalcError::from(*stopped),
                CycleError::Halted {
                    theta,
                    min_film,
                    stopped,
                } => CalcError::impossible(
                    "",
                    format!(
                        "the film could not be followed past crank angle {:.2}° (h_m = {min_film:.4e} m; {:?} after {} steps): check the loads against the ring's size",
                        theta.to_degrees(),
                        stopped.reason(),
                        stopped.report.iterations
                    ),
                ),
            })?;
        let samples = &cycle.samples;
        let largest = |f: fn(&Sample) -> f64| {
            samples
                .iter()
                .map(|s| (f(s), s.theta))
                .fold((f64::MIN, 0.0), |a, b| if b.0 > a.0 { b } else { a })
        };
        let (friction, friction_at) = largest(|s| s.friction.abs());
        let (power, power_at) = largest(|s| s.power);
        let step = model.engine.cycle.to_degrees() / (samples.len() - 1) as f64;
        let boundary_deg = samples[..samples.len() - 1]
            .iter()
            .filter(|s| s.boundary)
            .count() as f64
            * step;
        if let Some(b) = model.boundary {
            if cycle.min_film.0 < b.roughness {
                ctx.warn(
                    "film_below_roughness",
                    format!(
                        "the film falls to {:.3e} m at {:.1}°, below the composite roughness {:.3e} m: boundary friction (μ_c = {}) over {boundary_deg:.0}° of the cycle",
                        cycle.min_film.0,
                        cycle.min_film.1.to_degrees(),
                        b.roughness,
                        b.friction_coefficient
                    ),
                );
            }
        }
        ctx.report(cycle.report.clone().at(case.level));
        let out = PistonRingOutput {
            viscosity_pa_s: model.viscosity,
            ring_stiffness_pa_per_m: model.ring.stiffness,
            min_film_m: cycle.min_film.0,
            min_film_crank_angle_deg: cycle.min_film.1.to_degrees(),
            max_film_m: cycle.max_film.0,
            max_film_crank_angle_deg: cycle.max_film.1.to_degrees(),
            max_friction_force_n: friction,
            max_friction_crank_angle_deg: friction_at.to_degrees(),
            max_power_loss_w: power,
            max_power_crank_angle_deg: power_at.to_degrees(),
            mean_power_loss_w: cycle.mean_power,
            boundary_lubrication_deg: boundary_deg,
            cycles: cycle.cycles,
            path: case
                .include_field
                .then(|| samples.iter().map(CyclePoint::of).collect()),
        };
        CalcError::finite_or_out_of_range(out, "the ring, engine and lubricant")
    }
}

#[cfg(test)]
#[path = "piston_ring_tests.rs"]
mod tests;
