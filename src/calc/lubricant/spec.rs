//! The `lubricant` object of every request, as it arrives, and its parser into [`Lubricant`].

use serde::Deserialize;
use utoipa::ToSchema;

use super::astm_d2270;
use super::model::{Lubricant, PressureLaw, TemperatureLaw, Thermal};
use crate::calc::quantity::{Celsius, Positive};
use crate::calc::FieldError;

/// A lubricant. Give exactly one viscosity–temperature description: `viscosity_pa_s` (constant),
/// `iso_vg` (preset), `kinematic_viscosity_40c_mm2_s` with `kinematic_viscosity_100c_mm2_s`
/// (Walther / ASTM D341), `vogel` (three points) or `exponential`. Optionally one
/// pressure–viscosity law (`pressure_viscosity_coefficient_1_pa` for Barus, or
/// `roelands_pressure_viscosity_index`), a density and thermal properties.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
#[schema(example = json!({"kinematic_viscosity_40c_mm2_s": 32.0, "kinematic_viscosity_100c_mm2_s": 5.4, "density_15c_kg_m3": 870.0}))]
pub struct LubricantSpec {
    /// Constant dynamic viscosity, Pa·s (1e-6 … 1e4).
    #[schema(value_type = Option<f64>, minimum = 1e-6, maximum = 1e4, example = 0.03)]
    pub viscosity_pa_s: Option<Positive>,
    /// ISO 3448 viscosity grade (2 … 3200): ν40 at the grade's mid-point, mm²/s; ν100 from
    /// `viscosity_index` (default 100) through ASTM D2270; density 870 kg/m³ at 15 °C unless given.
    #[schema(minimum = 2, maximum = 3200, example = 32)]
    pub iso_vg: Option<u32>,
    /// With `iso_vg` only: the oil's viscosity index (dimensionless, 0 … 400; default 100).
    #[schema(minimum = 0.0, maximum = 400.0, example = 100.0)]
    pub viscosity_index: Option<f64>,
    /// Kinematic viscosity at 40 °C, mm²/s (cSt), > 0; with the 100 °C value it fixes the
    /// Walther (ASTM D341) line.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e6, example = 32.0)]
    pub kinematic_viscosity_40c_mm2_s: Option<Positive>,
    /// Kinematic viscosity at 100 °C, mm²/s (cSt), > 0 and below the 40 °C value.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e5, example = 5.4)]
    pub kinematic_viscosity_100c_mm2_s: Option<Positive>,
    /// Vogel law μ = a·exp(b/(T − c)) fitted through three points.
    pub vogel: Option<VogelSpec>,
    /// Exponential law μ = μ_ref·exp(−β (T − T_ref)).
    pub exponential: Option<ExponentialSpec>,
    /// Density at 15 °C, kg/m³ (500 … 2500); default 870 (a mineral oil). Varies with temperature
    /// as ρ = ρ15 [1 − 0.00063 (T − 15)] (Khonsari & Booser Eq. 2.19).
    #[schema(value_type = Option<f64>, minimum = 500.0, maximum = 2500.0, example = 870.0)]
    pub density_15c_kg_m3: Option<Positive>,
    /// Barus pressure–viscosity coefficient α, 1/Pa (0 … 1e-7; mineral oils 1.5e-8 … 3.5e-8).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e-7, example = 2.0e-8)]
    pub pressure_viscosity_coefficient_1_pa: Option<Positive>,
    /// Roelands pressure–viscosity index Z, dimensionless (0 … 1.5; mineral oil 0.6, PAO 0.45).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1.5, example = 0.6)]
    pub roelands_pressure_viscosity_index: Option<Positive>,
    /// Specific heat, J/(kg·K) (500 … 10000); default the petroleum-oil correlation.
    #[schema(value_type = Option<f64>, minimum = 500.0, maximum = 10000.0, example = 1900.0)]
    pub specific_heat_j_kg_k: Option<Positive>,
    /// Thermal conductivity, W/(m·K) (0.01 … 1); default the petroleum-oil correlation.
    #[schema(value_type = Option<f64>, minimum = 0.01, maximum = 1.0, example = 0.13)]
    pub thermal_conductivity_w_m_k: Option<Positive>,
    /// Pour point, °C: below it viscosity laws do not hold and a warning is given.
    #[schema(value_type = Option<f64>, minimum = -273.0, maximum = 1000.0, example = -9.0)]
    pub pour_point_c: Option<Celsius>,
}

/// Three (temperature, viscosity) points for the Vogel law.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct VogelSpec {
    /// Exactly three points at distinct temperatures, viscosity falling as temperature rises.
    #[schema(min_items = 3, max_items = 3, example = json!([{"temperature_c": 20.0, "viscosity_pa_s": 0.387}, {"temperature_c": 60.0, "viscosity_pa_s": 0.0351}, {"temperature_c": 100.0, "viscosity_pa_s": 0.0099}]))]
    pub points: Vec<VogelPoint>,
}

/// A measured viscosity.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct VogelPoint {
    /// °C (−273 … 1000).
    #[schema(value_type = f64, minimum = -273.0, maximum = 1000.0, example = 40.0)]
    pub temperature_c: Celsius,
    /// Dynamic viscosity, Pa·s (1e-6 … 1e4).
    #[schema(value_type = f64, minimum = 1e-6, maximum = 1e4, example = 0.03)]
    pub viscosity_pa_s: Positive,
}

/// The exponential viscosity–temperature law.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct ExponentialSpec {
    /// μ_ref, Pa·s, > 0.
    #[schema(value_type = f64, minimum = 1e-6, maximum = 1e4, example = 0.03)]
    pub reference_viscosity_pa_s: Positive,
    /// T_ref, °C.
    #[schema(value_type = f64, minimum = -273.0, maximum = 1000.0, example = 40.0)]
    pub reference_temperature_c: Celsius,
    /// β, 1/K (0 … 1; mineral oils about 0.02 … 0.05).
    #[schema(minimum = 0.0, maximum = 1.0, example = 0.03)]
    pub temperature_coefficient_1_k: f64,
}

/// ISO 3448 grades (mid-point ν40 in mm²/s).
pub const ISO_VG_GRADES: [u32; 20] = [
    2, 3, 5, 7, 10, 15, 22, 32, 46, 68, 100, 150, 220, 320, 460, 680, 1000, 1500, 2200, 3200,
];

/// Lowest viscosity accepted, Pa·s: below any liquid or gas (air is 1.8e-5), and far above
/// where μ/ρ underflows.
pub const MIN_VISCOSITY_PA_S: f64 = 1e-6;

/// Default density of a mineral oil at 15 °C, kg/m³.
pub const DEFAULT_DENSITY_KG_M3: f64 = 870.0;

fn range_check(
    errors: &mut Vec<FieldError>,
    pointer: String,
    value: Option<f64>,
    lo: f64,
    hi: f64,
) {
    if let Some(v) = value {
        if !(lo..=hi).contains(&v) {
            errors.push(FieldError::new(
                pointer,
                format!("must be within [{lo}, {hi}], got {v}"),
            ));
        }
    }
}

impl LubricantSpec {
    /// Parse into a [`Lubricant`]; `at` is the JSON pointer of this object in the request.
    pub fn parse(self, at: &str) -> Result<Lubricant, Vec<FieldError>> {
        let mut errors = Vec::new();
        let p = |field: &str| format!("{at}/{field}");
        let get = |v: Option<Positive>| v.map(Positive::get);

        range_check(
            &mut errors,
            p("viscosity_pa_s"),
            get(self.viscosity_pa_s),
            MIN_VISCOSITY_PA_S,
            1e4,
        );
        if let Some(e) = self.exponential {
            range_check(
                &mut errors,
                p("exponential/reference_viscosity_pa_s"),
                Some(e.reference_viscosity_pa_s.get()),
                MIN_VISCOSITY_PA_S,
                1e4,
            );
        }
        if let Some(v) = &self.vogel {
            for (i, q) in v.points.iter().enumerate() {
                range_check(
                    &mut errors,
                    p(&format!("vogel/points/{i}/viscosity_pa_s")),
                    Some(q.viscosity_pa_s.get()),
                    MIN_VISCOSITY_PA_S,
                    1e4,
                );
            }
        }
        range_check(
            &mut errors,
            p("density_15c_kg_m3"),
            get(self.density_15c_kg_m3),
            500.0,
            2500.0,
        );
        if let Some(alpha) = get(self.pressure_viscosity_coefficient_1_pa) {
            FieldError::check_at_most(
                &mut errors,
                p("pressure_viscosity_coefficient_1_pa"),
                alpha,
                1e-7,
            );
        }
        if let Some(z) = get(self.roelands_pressure_viscosity_index) {
            FieldError::check_at_most(&mut errors, p("roelands_pressure_viscosity_index"), z, 1.5);
        }
        range_check(
            &mut errors,
            p("specific_heat_j_kg_k"),
            get(self.specific_heat_j_kg_k),
            500.0,
            1e4,
        );
        range_check(
            &mut errors,
            p("thermal_conductivity_w_m_k"),
            get(self.thermal_conductivity_w_m_k),
            0.01,
            1.0,
        );
        range_check(
            &mut errors,
            p("viscosity_index"),
            self.viscosity_index,
            0.0,
            400.0,
        );
        if self.viscosity_index.is_some() && self.iso_vg.is_none() {
            errors.push(FieldError::new(
                p("viscosity_index"),
                "is only used with iso_vg",
            ));
        }

        let given: Vec<&str> = [
            ("viscosity_pa_s", self.viscosity_pa_s.is_some()),
            ("iso_vg", self.iso_vg.is_some()),
            (
                "kinematic_viscosity_40c_mm2_s",
                self.kinematic_viscosity_40c_mm2_s.is_some()
                    || self.kinematic_viscosity_100c_mm2_s.is_some(),
            ),
            ("vogel", self.vogel.is_some()),
            ("exponential", self.exponential.is_some()),
        ]
        .into_iter()
        .filter_map(|(name, present)| present.then_some(name))
        .collect();
        if given.len() != 1 {
            let message = if given.is_empty() {
                "give one viscosity description: viscosity_pa_s, iso_vg, kinematic_viscosity_40c_mm2_s with kinematic_viscosity_100c_mm2_s, vogel or exponential".to_owned()
            } else {
                format!(
                    "give exactly one viscosity description, got {}",
                    given.join(", ")
                )
            };
            errors.push(FieldError::new(at.to_owned(), message));
            return Err(errors);
        }

        let mut assumptions = Vec::new();
        let density = match self.density_15c_kg_m3 {
            Some(d) => d.get(),
            None => {
                assumptions.push((
                    "density_assumed",
                    format!("density_15c_kg_m3 not given: {DEFAULT_DENSITY_KG_M3} kg/m³ assumed (a mineral oil)"),
                ));
                DEFAULT_DENSITY_KG_M3
            }
        };

        let temperature_law = if let Some(mu) = self.viscosity_pa_s {
            Some(TemperatureLaw::Constant {
                viscosity_pa_s: mu.get(),
            })
        } else if let Some(vg) = self.iso_vg {
            let vi = self.viscosity_index.unwrap_or(100.0);
            if !ISO_VG_GRADES.contains(&vg) {
                errors.push(FieldError::new(
                    p("iso_vg"),
                    format!("must be an ISO 3448 grade, one of {ISO_VG_GRADES:?}"),
                ));
                None
            } else {
                let nu40 = f64::from(vg);
                match astm_d2270::kinematic_100c_for(nu40, vi) {
                    Some(nu100) => {
                        assumptions.push((
                            "iso_vg_preset",
                            format!("ISO VG {vg}: ν40 = {nu40} mm²/s (grade mid-point), viscosity index {vi} gives ν100 = {nu100:.3} mm²/s (ASTM D2270); Walther line through both"),
                        ));
                        Some(TemperatureLaw::walther_through(40.0, nu40, 100.0, nu100))
                    }
                    None => {
                        errors.push(FieldError::new(
                            p("viscosity_index"),
                            format!("no oil of ν40 = {nu40} mm²/s with ν100 ≥ 2 mm²/s has viscosity index {vi}"),
                        ));
                        None
                    }
                }
            }
        } else if self.kinematic_viscosity_40c_mm2_s.is_some()
            || self.kinematic_viscosity_100c_mm2_s.is_some()
        {
            match (
                self.kinematic_viscosity_40c_mm2_s,
                self.kinematic_viscosity_100c_mm2_s,
            ) {
                (Some(n40), _) if n40.get() > 1e6 => {
                    errors.push(FieldError::new(
                        p("kinematic_viscosity_40c_mm2_s"),
                        "must be at most 1e6 mm²/s",
                    ));
                    None
                }
                (Some(n40), Some(n100)) if n100.get() < n40.get() => Some(
                    TemperatureLaw::walther_through(40.0, n40.get(), 100.0, n100.get()),
                ),
                (Some(_), Some(_)) => {
                    errors.push(FieldError::new(
                        p("kinematic_viscosity_100c_mm2_s"),
                        "must be below kinematic_viscosity_40c_mm2_s",
                    ));
                    None
                }
                (None, _) => {
                    errors.push(FieldError::new(
                        p("kinematic_viscosity_40c_mm2_s"),
                        "is required with kinematic_viscosity_100c_mm2_s",
                    ));
                    None
                }
                (_, None) => {
                    errors.push(FieldError::new(
                        p("kinematic_viscosity_100c_mm2_s"),
                        "is required with kinematic_viscosity_40c_mm2_s",
                    ));
                    None
                }
            }
        } else if let Some(vogel) = &self.vogel {
            if vogel.points.len() != 3 {
                errors.push(FieldError::new(
                    p("vogel/points"),
                    format!("must hold exactly 3 points, got {}", vogel.points.len()),
                ));
                None
            } else {
                let pts: Vec<(f64, f64)> = vogel
                    .points
                    .iter()
                    .map(|q| (q.temperature_c.get(), q.viscosity_pa_s.get()))
                    .collect();
                let fit = TemperatureLaw::vogel_through([pts[0], pts[1], pts[2]]);
                if fit.is_none() {
                    errors.push(FieldError::new(
                        p("vogel/points"),
                        "no Vogel law fits these points: temperatures must differ and viscosity must fall with temperature, more steeply than an exponential at the cold end",
                    ));
                }
                fit
            }
        } else if let Some(e) = self.exponential {
            if !(0.0..=1.0).contains(&e.temperature_coefficient_1_k) {
                errors.push(FieldError::new(
                    p("exponential/temperature_coefficient_1_k"),
                    "must be within [0, 1]",
                ));
            }
            Some(TemperatureLaw::Exponential {
                reference_viscosity_pa_s: e.reference_viscosity_pa_s.get(),
                reference_temperature_c: e.reference_temperature_c.get(),
                beta_1_k: e.temperature_coefficient_1_k,
            })
        } else {
            None
        };

        let pressure_law = match (
            self.pressure_viscosity_coefficient_1_pa,
            self.roelands_pressure_viscosity_index,
        ) {
            (Some(_), Some(_)) => {
                errors.push(FieldError::new(
                    p("roelands_pressure_viscosity_index"),
                    "give one pressure–viscosity law: pressure_viscosity_coefficient_1_pa (Barus) or roelands_pressure_viscosity_index",
                ));
                None
            }
            (Some(alpha), None) => Some(PressureLaw::Barus {
                alpha_1_pa: alpha.get(),
            }),
            (None, Some(z)) => Some(PressureLaw::Roelands { z: z.get() }),
            (None, None) => None,
        };

        let thermal = match (self.specific_heat_j_kg_k, self.thermal_conductivity_w_m_k) {
            (None, None) => Thermal::PetroleumCorrelation,
            (Some(c), Some(k)) => Thermal::Given {
                specific_heat_j_kg_k: c.get(),
                thermal_conductivity_w_m_k: k.get(),
            },
            (Some(_), None) => {
                errors.push(FieldError::new(
                    p("thermal_conductivity_w_m_k"),
                    "is required with specific_heat_j_kg_k",
                ));
                Thermal::PetroleumCorrelation
            }
            (None, Some(_)) => {
                errors.push(FieldError::new(
                    p("specific_heat_j_kg_k"),
                    "is required with thermal_conductivity_w_m_k",
                ));
                Thermal::PetroleumCorrelation
            }
        };

        match temperature_law {
            Some(temperature_law) if errors.is_empty() => Ok(Lubricant {
                temperature_law,
                pressure_law,
                density_15c_kg_m3: density,
                thermal,
                pour_point_c: self.pour_point_c.map(Celsius::get),
                assumptions,
            }),
            _ => Err(errors),
        }
    }
}
