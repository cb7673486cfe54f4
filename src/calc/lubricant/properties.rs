//! `POST /v1/lubricants/properties`: density, thermal properties and pressure–viscosity
//! estimates of a lubricant at a set of temperatures.

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::model::{roelands_z_fein, wooster_alpha_1_pa, PressureLaw, Thermal};
use super::spec::LubricantSpec;
use super::validity;
use crate::calc::quantity::Celsius;
use crate::calc::range_schemas;
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::fidelity::Level;

/// Most temperatures one request may ask for.
pub const MAX_TEMPERATURES: usize = 10_000;

pub struct Properties;

/// Request.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct PropertiesInput {
    pub lubricant: LubricantSpec,
    /// Temperatures, °C: see [`range_schemas::property_temperatures`].
    #[schema(schema_with = range_schemas::property_temperatures)]
    pub temperatures_c: Vec<Celsius>,
}

/// The validated case.
#[derive(Debug, Clone)]
pub struct PropertiesCase {
    pub lubricant: super::model::Lubricant,
    pub temperatures_c: Vec<f64>,
}

impl Validate for PropertiesInput {
    type Valid = PropertiesCase;
    fn validate(self) -> Result<PropertiesCase, Vec<FieldError>> {
        let n = self.temperatures_c.len();
        if n == 0 || n > MAX_TEMPERATURES {
            return Err(vec![FieldError::new(
                "/temperatures_c",
                format!("must hold 1 … {MAX_TEMPERATURES} temperatures, got {n}"),
            )]);
        }
        let lubricant = self.lubricant.parse("/lubricant")?;
        Ok(PropertiesCase {
            lubricant,
            temperatures_c: self.temperatures_c.iter().map(|t| t.get()).collect(),
        })
    }
}

/// Properties at one temperature (atmospheric pressure).
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct PropertyPoint {
    /// °C.
    pub temperature_c: f64,
    /// Dynamic viscosity, Pa·s.
    pub dynamic_viscosity_pa_s: f64,
    /// Kinematic viscosity, mm²/s.
    pub kinematic_viscosity_mm2_s: f64,
    /// Density, kg/m³ (Khonsari & Booser Eq. 2.19 unless the law is a constant density).
    pub density_kg_m3: f64,
    /// Specific heat c_p, J/(kg·K).
    pub specific_heat_j_kg_k: f64,
    /// Thermal conductivity k, W/(m·K).
    pub thermal_conductivity_w_m_k: f64,
    /// Thermal diffusivity k/(ρ c_p), m²/s.
    pub thermal_diffusivity_m2_s: f64,
    /// Volumetric heat capacity ρ c_p, J/(m³·K).
    pub volumetric_heat_capacity_j_m3_k: f64,
    /// α of the lubricant's own pressure law, 1/Pa: Barus' α, or for Roelands the EHL
    /// coefficient Z·5.1e-9·(ln μ0 + 9.67) (Khonsari & Booser Eq. 2.13). Absent without a law.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pressure_viscosity_coefficient_1_pa: Option<f64>,
    /// Estimate of α_EHL from Fein's Z (Eq. 2.11) and Eq. 2.13, 1/Pa: mineral oils, PAOs, esters.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pressure_viscosity_coefficient_fein_1_pa: Option<f64>,
    /// Wooster's estimate α = (0.6 + 0.965 log10 μ0[mPa·s])·1e-8, 1/Pa (Stachowiak & Batchelor §2.5).
    pub pressure_viscosity_coefficient_wooster_1_pa: f64,
}

/// Result.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct PropertiesOutput {
    /// Where c_p and k come from: `petroleum_correlation` (Khonsari & Booser Eq. 2.24, 2.25) or `given`.
    #[schema(example = "petroleum_correlation")]
    pub thermal_model: String,
    /// ν40, mm²/s, from the lubricant's law.
    pub kinematic_viscosity_40c_mm2_s: f64,
    /// ν100, mm²/s, from the lubricant's law.
    pub kinematic_viscosity_100c_mm2_s: f64,
    /// VTC = 1 − ν100/ν40 (Khonsari & Booser Eq. 2.8), dimensionless.
    pub viscosity_temperature_coefficient: f64,
    /// Roelands Z estimated from μ40 and μ100 (Fein; Khonsari & Booser Eq. 2.11), dimensionless.
    /// Absent where the formula leaves its domain (a constant-viscosity oil, for one).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub roelands_pressure_viscosity_index_fein: Option<f64>,
    /// One entry per requested temperature, in order.
    pub points: Vec<PropertyPoint>,
}

impl Calculation for Properties {
    const PATH: &'static str = "/v1/lubricants/properties";
    const SUMMARY: &'static str =
        "Density, thermal properties and pressure–viscosity estimates of a lubricant";
    const DESCRIPTION: &'static str = include_str!("properties.md");
    const FIDELITY: &'static [Level] = &[Level::ClosedForm];
    const EFFECTS: &'static [&'static str] = &[];
    const EXAMPLE: &'static str = r#"{"lubricant": {"kinematic_viscosity_40c_mm2_s": 31.0, "kinematic_viscosity_100c_mm2_s": 5.4, "density_15c_kg_m3": 863.0}, "temperatures_c": [40.0, 65.0, 100.0]}"#;

    type Input = PropertiesInput;
    type Output = PropertiesOutput;

    fn run(case: PropertiesCase, ctx: &mut Context) -> Result<PropertiesOutput, CalcError> {
        let lub = &case.lubricant;
        validity::check_temperatures(ctx, lub, &case.temperatures_c)?;
        let (mu40, mu100) = (lub.viscosity_pa_s(40.0), lub.viscosity_pa_s(100.0));
        let z_fein = roelands_z_fein(mu40, mu100);
        let mut points = Vec::with_capacity(case.temperatures_c.len());
        for (i, &t) in case.temperatures_c.iter().enumerate() {
            if i % 1024 == 0 {
                ctx.check_deadline()?;
            }
            let mu = lub.viscosity_pa_s(t);
            let rho = lub.density_kg_m3(t);
            let cp = lub.specific_heat_j_kg_k(t);
            let k = lub.thermal_conductivity_w_m_k(t);
            if !(rho > 0.0 && cp > 0.0 && k > 0.0) {
                return Err(CalcError::impossible(
                    &format!("/temperatures_c/{i}"),
                    format!("at {t} °C the property correlations give a non-positive density, specific heat or conductivity: outside their range"),
                ));
            }
            points.push(PropertyPoint {
                temperature_c: t,
                dynamic_viscosity_pa_s: mu,
                kinematic_viscosity_mm2_s: mu / rho * 1e6,
                density_kg_m3: rho,
                specific_heat_j_kg_k: cp,
                thermal_conductivity_w_m_k: k,
                thermal_diffusivity_m2_s: k / (rho * cp),
                volumetric_heat_capacity_j_m3_k: rho * cp,
                pressure_viscosity_coefficient_1_pa: lub.pressure_law.map(|law| law.alpha_1_pa(mu)),
                pressure_viscosity_coefficient_fein_1_pa: z_fein
                    .map(|z| PressureLaw::Roelands { z }.alpha_1_pa(mu))
                    .filter(|a| *a > 0.0),
                pressure_viscosity_coefficient_wooster_1_pa: wooster_alpha_1_pa(mu),
            });
        }
        if matches!(lub.thermal, Thermal::PetroleumCorrelation) {
            if let Some(&t) = case
                .temperatures_c
                .iter()
                .find(|&&t| !(0.0..=200.0).contains(&t))
            {
                ctx.warn(
                    "thermal_correlation_range",
                    format!("the petroleum-oil c_p and k correlations are for oils in service, about 0 … 200 °C; {t} °C is outside"),
                );
            }
        }
        for (code, message) in &lub.assumptions {
            ctx.warn(code, message.clone());
        }
        let (nu40, nu100) = (lub.kinematic_mm2_s(40.0), lub.kinematic_mm2_s(100.0));
        Ok(PropertiesOutput {
            thermal_model: match lub.thermal {
                Thermal::PetroleumCorrelation => "petroleum_correlation",
                Thermal::Given { .. } => "given",
            }
            .to_owned(),
            kinematic_viscosity_40c_mm2_s: nu40,
            kinematic_viscosity_100c_mm2_s: nu100,
            viscosity_temperature_coefficient: 1.0 - nu100 / nu40,
            roelands_pressure_viscosity_index_fein: z_fein,
            points,
        })
    }
}
