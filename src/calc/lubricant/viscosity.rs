//! `POST /v1/lubricants/viscosity`: dynamic and kinematic viscosity and density of a lubricant at
//! a grid of temperatures and pressures.

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::model::{dowson_higginson_density_ratio, Lubricant, PressureLaw};
use super::spec::LubricantSpec;
use super::validity;
use crate::calc::quantity::{Celsius, NonNegative};
use crate::calc::range_schemas;
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::effects::{Criterion, Decision, Mode};
use crate::fidelity::Level;

/// Most state points one request may ask for (temperatures × pressures).
pub const MAX_POINTS: usize = 100_000;
/// Highest gauge pressure accepted, Pa.
pub const MAX_PRESSURE_PA: f64 = 5e9;

pub struct Viscosity;

/// Effects this calculation understands.
#[derive(Debug, Clone, Copy, Default, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct ViscosityEffects {
    /// Viscosity rise with pressure (the lubricant's Barus or Roelands law). `auto` applies it
    /// when it raises viscosity by more than 1 % at the highest pressure asked for.
    #[serde(default)]
    pub piezoviscosity: Mode,
    /// Density rise with pressure (Dowson–Higginson). `auto` applies it when it raises density
    /// by more than 1 % at the highest pressure asked for (about 17 MPa).
    #[serde(default)]
    pub compressibility: Mode,
}

/// Request: a lubricant and the temperatures and pressures to evaluate it at.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct ViscosityInput {
    pub lubricant: LubricantSpec,
    /// Temperatures, °C: see [`range_schemas::viscosity_temperatures`].
    #[schema(schema_with = range_schemas::viscosity_temperatures)]
    pub temperatures_c: Vec<Celsius>,
    /// Gauge pressures, Pa: see [`range_schemas::pressures`].
    #[serde(default)]
    #[schema(schema_with = range_schemas::pressures)]
    pub pressures_pa: Vec<NonNegative>,
    #[serde(default)]
    pub effects: ViscosityEffects,
}

/// The validated case.
#[derive(Debug, Clone)]
pub struct ViscosityCase {
    pub lubricant: Lubricant,
    pub temperatures_c: Vec<f64>,
    pub pressures_pa: Vec<f64>,
    pub effects: ViscosityEffects,
}

impl Validate for ViscosityInput {
    type Valid = ViscosityCase;
    fn validate(self) -> Result<ViscosityCase, Vec<FieldError>> {
        let mut errors = Vec::new();
        let temperatures_c: Vec<f64> = self.temperatures_c.iter().map(|t| t.get()).collect();
        let mut pressures_pa: Vec<f64> = self.pressures_pa.iter().map(|p| p.get()).collect();
        if pressures_pa.is_empty() {
            pressures_pa.push(0.0);
        }
        if temperatures_c.is_empty() {
            errors.push(FieldError::new(
                "/temperatures_c",
                "must hold at least one temperature",
            ));
        }
        if let Some(i) = pressures_pa.iter().position(|&p| p > MAX_PRESSURE_PA) {
            errors.push(FieldError::new(
                format!("/pressures_pa/{i}"),
                format!("must be within [0, {MAX_PRESSURE_PA:e}] Pa"),
            ));
        }
        if temperatures_c.len().saturating_mul(pressures_pa.len()) > MAX_POINTS {
            errors.push(FieldError::new(
                "/pressures_pa",
                format!("temperatures × pressures must be at most {MAX_POINTS} points"),
            ));
        }
        let lubricant = self.lubricant.parse("/lubricant");
        let lubricant = match lubricant {
            Ok(l) if errors.is_empty() => l,
            Ok(_) => return Err(errors),
            Err(mut e) => {
                errors.append(&mut e);
                return Err(errors);
            }
        };
        let effects = self.effects;
        if effects.piezoviscosity == Mode::On && lubricant.pressure_law.is_none() {
            return Err(vec![FieldError::new(
                "/effects/piezoviscosity",
                "is on, but the lubricant has no pressure–viscosity law: give pressure_viscosity_coefficient_1_pa or roelands_pressure_viscosity_index",
            )]);
        }
        Ok(ViscosityCase {
            lubricant,
            temperatures_c,
            pressures_pa,
            effects,
        })
    }
}

/// One evaluated state.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct StatePoint {
    /// °C.
    pub temperature_c: f64,
    /// Gauge pressure, Pa.
    pub pressure_pa: f64,
    /// Dynamic viscosity μ, Pa·s.
    pub dynamic_viscosity_pa_s: f64,
    /// Kinematic viscosity ν = μ/ρ, mm²/s (cSt).
    pub kinematic_viscosity_mm2_s: f64,
    /// Density ρ, kg/m³.
    pub density_kg_m3: f64,
}

/// Result.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct ViscosityOutput {
    /// The viscosity–temperature law: `constant`, `walther_astm_d341`, `vogel` or `exponential`.
    #[schema(example = "walther_astm_d341")]
    pub temperature_model: String,
    /// The pressure–viscosity law applied: `barus`, `roelands` or `none`.
    #[schema(example = "none")]
    pub pressure_model: String,
    /// The density law applied with pressure: `dowson_higginson` or `none`.
    #[schema(example = "none")]
    pub density_pressure_model: String,
    /// One point per temperature and pressure, temperatures varying slowest.
    pub points: Vec<StatePoint>,
}

impl Calculation for Viscosity {
    const PATH: &'static str = "/v1/lubricants/viscosity";
    const SUMMARY: &'static str =
        "Viscosity and density of a lubricant against temperature and pressure";
    const DESCRIPTION: &'static str = include_str!("viscosity.md");
    const FIDELITY: &'static [Level] = &[Level::ClosedForm];
    const EFFECTS: &'static [&'static str] = &["piezoviscosity", "compressibility"];
    const EXAMPLE: &'static str = r#"{"lubricant": {"kinematic_viscosity_40c_mm2_s": 31.0, "kinematic_viscosity_100c_mm2_s": 5.4, "density_15c_kg_m3": 863.0, "roelands_pressure_viscosity_index": 0.68}, "temperatures_c": [40.0, 65.0, 100.0], "pressures_pa": [0.0, 1.0e8]}"#;

    type Input = ViscosityInput;
    type Output = ViscosityOutput;

    fn run(case: ViscosityCase, ctx: &mut Context) -> Result<ViscosityOutput, CalcError> {
        let lub = &case.lubricant;
        let p_max = case.pressures_pa.iter().cloned().fold(0.0, f64::max);
        validity::check_temperatures(ctx, lub, &case.temperatures_c)?;
        if lub.pressure_law.is_some() && p_max > 0.0 && case.effects.piezoviscosity != Mode::Off {
            validity::check_pressure_law(lub, &case.temperatures_c)?;
        }
        let pressure_law = decide_piezoviscosity(
            ctx,
            lub,
            &case.temperatures_c,
            p_max,
            case.effects.piezoviscosity,
        );
        let compressible = decide_compressibility(ctx, p_max, case.effects.compressibility);
        if let (Some(PressureLaw::Barus { .. }), true) =
            (pressure_law, p_max > validity::BARUS_LIMIT_PA)
        {
            ctx.warn(
                "barus_above_70_mpa",
                format!("Barus' law overestimates viscosity above about 70 MPa (Khonsari & Booser §2.5); the highest pressure asked is {p_max:.3e} Pa: prefer roelands_pressure_viscosity_index"),
            );
        }

        if pressure_law.is_some() && p_max > validity::PIEZOVISCOUS_LIMIT_PA {
            ctx.warn(
                "pressure_beyond_piezoviscous_range",
                format!("{p_max:.3e} Pa is beyond the 3 GPa to which the pressure–viscosity laws were fitted (EHL contacts run at 0.5–3 GPa; Khonsari & Booser §2.5): there the oil is a glassy solid, its shear strength rather than its viscosity carries the load, and the viscosity given is an extrapolation"),
            );
        }
        let mut points = Vec::with_capacity(case.temperatures_c.len() * case.pressures_pa.len());
        for &t in &case.temperatures_c {
            let mu0 = lub.viscosity_pa_s(t);
            let rho0 = lub.density_kg_m3(t);
            for &p in &case.pressures_pa {
                if points.len() % 1024 == 0 {
                    ctx.check_deadline()?;
                }
                let mu = pressure_law.map_or(mu0, |law| mu0 * law.viscosity_ratio(mu0, p));
                let rho = if compressible {
                    rho0 * dowson_higginson_density_ratio(p)
                } else {
                    rho0
                };
                if !(mu.is_finite() && mu > 0.0) {
                    return Err(CalcError::impossible(
                        "/pressures_pa",
                        format!("viscosity leaves the floating-point range at {t} °C and {p:e} Pa: the pressure law is outside its range"),
                    ));
                }
                points.push(StatePoint {
                    temperature_c: t,
                    pressure_pa: p,
                    dynamic_viscosity_pa_s: mu,
                    kinematic_viscosity_mm2_s: mu / rho * 1e6,
                    density_kg_m3: rho,
                });
            }
        }
        for (code, message) in &lub.assumptions {
            ctx.warn(code, message.clone());
        }
        Ok(ViscosityOutput {
            temperature_model: lub.temperature_law.name().to_owned(),
            pressure_model: pressure_law.map_or("none", PressureLaw::name).to_owned(),
            density_pressure_model: if compressible {
                "dowson_higginson"
            } else {
                "none"
            }
            .to_owned(),
            points,
        })
    }
}

/// Piezoviscosity: applies where the lubricant has a law and it matters at the pressures asked.
fn decide_piezoviscosity(
    ctx: &mut Context,
    lub: &Lubricant,
    temperatures_c: &[f64],
    p_max: f64,
    mode: Mode,
) -> Option<PressureLaw> {
    let Some(law) = lub.pressure_law else {
        ctx.decide(
            "piezoviscosity",
            Decision::not_applicable(mode, "the lubricant has no pressure–viscosity law"),
        );
        return None;
    };
    let rise = temperatures_c
        .iter()
        .map(|&t| law.viscosity_ratio(lub.viscosity_pa_s(t), p_max) - 1.0)
        .fold(0.0, f64::max);
    let criterion = Criterion {
        name: "viscosity_rise_at_max_pressure",
        value: finite_or_max(rise),
        threshold: 0.01,
    };
    let decision = Decision::decide(mode, criterion, "piezoviscosity");
    let applied = decision.applied;
    ctx.decide("piezoviscosity", decision);
    applied.then_some(law)
}

/// Compressibility: the Dowson–Higginson density rise at the highest pressure against 1 %.
fn decide_compressibility(ctx: &mut Context, p_max: f64, mode: Mode) -> bool {
    let rise = dowson_higginson_density_ratio(p_max) - 1.0;
    let criterion = Criterion {
        name: "density_rise_at_max_pressure",
        value: rise,
        threshold: 0.01,
    };
    let decision = Decision::decide(mode, criterion, "compressibility");
    let applied = decision.applied;
    ctx.decide("compressibility", decision);
    applied
}

fn finite_or_max(x: f64) -> f64 {
    if x.is_finite() {
        x
    } else {
        f64::MAX
    }
}
