//! `POST /v1/contacts/flash-temperature`: the flash temperature of a sliding contact — the rise
//! of the contact's surface temperature above the bulk temperature of the solids entering it —
//! for circular, square and line (band) heat sources, with the frictional heat shared between
//! the two bodies.
//!
//! Symbols (Stachowiak & Batchelor §7.6; Khonsari & Booser §3.8):
//! - Q = μW|U_A − U_B|, the frictional heat, W (Khonsari: Q = fWV), generated uniformly over the
//!   contact and all conducted into the solids, steady state.
//! - Each body i moves past the heat source at its own surface speed U_i; its Peclet number is
//!   L_i = |U_i| a/(2χ_i) (Khonsari's Pe = Va/2κ), with a the contact radius (circular), the
//!   half-side b (square) or the half-width b across the band (line); χ = K/(ρσ) the thermal
//!   diffusivity, K the conductivity.
//! - Each body alone, taking all of Q, would reach the flash temperature T_fi = Q/C_i; C_i (W/K)
//!   is its thermal conductance, which depends on the shape and on L_i. The true flash
//!   temperature is the one common to both surfaces: 1/T_f = 1/T_fA + 1/T_fB (Stachowiak
//!   eq. 7.37; Khonsari eq. 3.49 with the conductances added), so T_f = Q/(C_A + C_B) and body i
//!   takes the fraction C_i/(C_A + C_B) of the heat.
//!
//! Models (`model`):
//! - `tian_kennedy` (circular only; Khonsari & Booser eqs 3.49–3.51): a moving body has
//!   C = 4.56 a K (0.66 + Pe)^½ over the whole speed range; a stationary body (U = 0) has the
//!   steady-conduction C = 4aK of eq. 3.49, as Example 3.2 uses it. The fit at Pe → 0 gives
//!   3.705 aK, 7 % below 4aK (the uniform-flux disc against the isothermal one).
//! - `jaeger` (Blok–Jaeger–Archard; Stachowiak & Batchelor Tables 7.5–7.7): the slow form for
//!   L ≤ 0.1 and the fast form for L ≥ 5, per body. In the intermediate range 0.1 < L < 5 the
//!   texts give only charts (α for circles, C₁–C₄ of Fig. 7.30, which the text lacks); there the
//!   service integrates Jaeger's moving-source solution itself for a uniform flux
//!   ([`crate::calc::surface::moving_heat_source`]: the circle and the square as 3D sources,
//!   the line as the infinitely long band the table's forms describe), which reproduces the
//!   square's and the
//!   band's slow and fast forms at the range ends. For a circle the slow form is the isothermal
//!   disc's 0.25 Q/(Ka) while the uniform flux gives 8/(3π²)·Q/(Ka) = 0.27 Q/(Ka): the mean
//!   steps up 8 % as L crosses 0.1.
//!   - Circular: slow T̄ = 0.25 Q/(Ka); fast T̄ = 0.308 (Q/(Ka))(χ/(Ua))^½, T_max = 1.64 T̄.
//!     (The slow T_max of Table 7.5 is written for a plastic junction through the flow pressure
//!     p_y, not for a given radius, so no slow maximum is reported.)
//!   - Square, q = Q/(4b²): slow T̄ = 0.946 qb/K, T_max = 1.122 qb/K; fast
//!     T̄ = 1.064 (q/K)(χb/U)^½, T_max = (2q/K)(2χb/(πU))^½.
//!   - Line, half-length l, q = Q/(4bl): slow T̄ = (2qb/(πK))(1.616 − ln 2L),
//!     T_max = (2qb/(πK))(1.116 − ln L) (the table's 4χq/(πKU)·L(−2.303 log₁₀ 2L + 1.616));
//!     fast as the square with this q. A stationary body under a line source has no steady
//!     state (C → 0 as L → 0): it takes none of the heat.
//!
//! This file is the wire (request, validation, response); the physics is the surface model
//! [`crate::calc::surface::flash`] (`flash::solve(&FlashTemperatureCase) -> FlashSolution`).
//!
//! Two fast bodies in a line contact reproduce Blok's eq. 7.39 with 2√2 × 0.399 = 1.128 in place
//! of the text's rounded 1.11: the service follows Table 7.7, 1.6 % above eq. 7.39–7.40.

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use crate::calc::quantity::{Celsius, NonNegative, Positive};
pub use crate::calc::surface::flash::FlashModel;
use crate::calc::surface::flash::{
    self, Body, BodyShare, FlashTemperatureCase, PecletRegime, Source,
};
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::fidelity::Level;

pub struct FlashTemperature;

/// Largest accepted magnitudes: beyond them no tribological contact is meant.
const MAX_LENGTH_M: f64 = 10.0;
/// Smallest accepted contact dimension, m: a nanometre asperity junction.
const MIN_LENGTH_M: f64 = 1e-9;
const MAX_LOAD_N: f64 = 1e9;
const MAX_SPEED_M_S: f64 = 1e4;
const MAX_FRICTION: f64 = 10.0;

/// The shape of the heat source.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum FlashShape {
    /// A circle of radius `radius_m` (Archard; Khonsari's junction of radius a).
    Circular,
    /// A square of half-side `half_width_m` (Jaeger).
    Square,
    /// A band of half-width `half_width_m` across the sliding direction and full length
    /// `length_m` along it (Jaeger; gears, rollers).
    Line,
}

/// The contact: its shape and size.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct FlashGeometry {
    pub shape: FlashShape,
    /// Contact radius a, m, 1e-9 ≤ a ≤ 10; `circular` only.
    #[schema(value_type = Option<f64>, minimum = 1e-9, maximum = 10.0, example = 0.01)]
    pub radius_m: Option<Positive>,
    /// Half-width b in the sliding direction, m, 1e-9 ≤ b ≤ 10; `square` (half-side) and
    /// `line` (half the band's width, e.g. the Hertz half-width).
    #[schema(value_type = Option<f64>, minimum = 1e-9, maximum = 10.0, example = 1.82e-4)]
    pub half_width_m: Option<Positive>,
    /// Full length 2l of the band across the sliding direction, m, 1e-9 ≤ 2l ≤ 10; `line`
    /// only.
    #[schema(value_type = Option<f64>, minimum = 1e-9, maximum = 10.0, example = 0.01)]
    pub length_m: Option<Positive>,
}

/// One body: its surface speed past the contact and its thermal properties. Give
/// `thermal_diffusivity_m2_s`, or `density_kg_m3` with `specific_heat_j_kg_k`.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct FlashBody {
    /// Surface speed U of this body relative to the contact, m/s, |U| ≤ 1e4; 0 for a
    /// stationary body (a pin), the sign giving the direction (the sliding speed is
    /// |U_A − U_B|).
    #[schema(minimum = -1e4, maximum = 1e4, example = 0.5)]
    pub speed_m_s: f64,
    /// Thermal conductivity K, W/(m·K), 1e-3 … 1e4 (carbon steel 54, bearing steel 46.7;
    /// still air 0.026).
    #[schema(value_type = f64, minimum = 1e-3, maximum = 1e4, example = 54.0)]
    pub thermal_conductivity_w_m_k: Positive,
    /// Thermal diffusivity χ = K/(ρσ), m²/s, > 0 (carbon steel 1.474e-5).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1.0, example = 1.474e-5)]
    pub thermal_diffusivity_m2_s: Option<Positive>,
    /// Density ρ, kg/m³, > 0 (steel 7800); with `specific_heat_j_kg_k`, instead of the
    /// diffusivity.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e5, example = 7800.0)]
    pub density_kg_m3: Option<Positive>,
    /// Specific heat σ, J/(kg·K), > 0 (steel 460); with `density_kg_m3`.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e5, example = 460.0)]
    pub specific_heat_j_kg_k: Option<Positive>,
}

/// Request: a sliding contact, its load, friction and the two bodies.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct FlashTemperatureInput {
    pub geometry: FlashGeometry,
    /// Normal load W, N, 0 < W ≤ 1e9.
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 1e9, example = 3000.0)]
    pub load_n: Positive,
    /// Coefficient of friction μ, dimensionless, 0 ≤ μ ≤ 10.
    #[schema(value_type = f64, minimum = 0.0, maximum = 10.0, example = 0.1)]
    pub friction_coefficient: NonNegative,
    pub body_a: FlashBody,
    pub body_b: FlashBody,
    /// `tian_kennedy` or `jaeger`; default `tian_kennedy` for a circular contact (it covers all
    /// Peclet numbers), `jaeger` for square and line contacts (the only one they have).
    pub model: Option<FlashModel>,
    /// Bulk temperature T_b of both solids entering the contact, °C, −273 … 1000; gives the
    /// surface temperatures T_b + T_f.
    #[schema(value_type = Option<f64>, minimum = -273.0, maximum = 1000.0, example = 80.0)]
    pub bulk_temperature_c: Option<Celsius>,
}

fn body_error(name: &str, field: &str, message: impl Into<String>) -> FieldError {
    FieldError::new(format!("/{name}/{field}"), message)
}

fn parse_body(spec: &FlashBody, name: &str, errors: &mut Vec<FieldError>) -> Option<Body> {
    let mut ok = true;
    if !spec.speed_m_s.is_finite() || spec.speed_m_s.abs() > MAX_SPEED_M_S {
        errors.push(body_error(
            name,
            "speed_m_s",
            format!(
                "must be finite with |U| ≤ {MAX_SPEED_M_S:e} m/s, got {}",
                spec.speed_m_s
            ),
        ));
        ok = false;
    }
    let k = spec.thermal_conductivity_w_m_k.get();
    if !(1e-3..=1e4).contains(&k) {
        errors.push(body_error(
            name,
            "thermal_conductivity_w_m_k",
            format!("must be within 1e-3 … 1e4 W/(m·K) (an insulating foam to diamond), got {k}"),
        ));
        ok = false;
    }
    let diffusivity = match (
        spec.thermal_diffusivity_m2_s,
        spec.density_kg_m3,
        spec.specific_heat_j_kg_k,
    ) {
        (Some(chi), None, None) if chi.get() <= 1.0 => Some(chi.get()),
        (Some(chi), None, None) => {
            errors.push(body_error(
                name,
                "thermal_diffusivity_m2_s",
                format!("must be at most 1 m²/s, got {}", chi.get()),
            ));
            None
        }
        (None, Some(rho), Some(c)) if rho.get() <= 1e5 && c.get() <= 1e5 => {
            Some(k / (rho.get() * c.get()))
        }
        (None, Some(_), Some(_)) => {
            errors.push(body_error(
                name,
                "density_kg_m3",
                "density and specific heat must each be at most 1e5",
            ));
            None
        }
        (Some(_), _, _) => {
            errors.push(body_error(
                name,
                "thermal_diffusivity_m2_s",
                "give the diffusivity or density with specific heat, not both",
            ));
            None
        }
        (None, None, _) => {
            errors.push(body_error(
                name,
                "thermal_diffusivity_m2_s",
                "give thermal_diffusivity_m2_s, or density_kg_m3 with specific_heat_j_kg_k",
            ));
            None
        }
        (None, Some(_), None) => {
            errors.push(body_error(
                name,
                "specific_heat_j_kg_k",
                "needed with density_kg_m3",
            ));
            None
        }
    };
    match (ok, diffusivity) {
        (true, Some(diffusivity)) => Some(Body {
            speed: spec.speed_m_s,
            conductivity: k,
            diffusivity,
        }),
        _ => None,
    }
}

fn parse_source(g: &FlashGeometry, errors: &mut Vec<FieldError>) -> Option<Source> {
    let n = errors.len();
    let mut need = |value: Option<Positive>, field: &str, wanted: bool| -> f64 {
        match (value, wanted) {
            (Some(v), true) if (MIN_LENGTH_M..=MAX_LENGTH_M).contains(&v.get()) => v.get(),
            (Some(v), true) => {
                errors.push(FieldError::new(
                    format!("/geometry/{field}"),
                    format!(
                        "must be within {MIN_LENGTH_M:e} … {MAX_LENGTH_M} m (a nanometre asperity to a machine), got {}",
                        v.get()
                    ),
                ));
                f64::NAN
            }
            (None, true) => {
                errors.push(FieldError::new(
                    format!("/geometry/{field}"),
                    "is required for this shape",
                ));
                f64::NAN
            }
            (Some(_), false) => {
                errors.push(FieldError::new(
                    format!("/geometry/{field}"),
                    "does not belong to this shape",
                ));
                f64::NAN
            }
            (None, false) => f64::NAN,
        }
    };
    let (circular, line) = (g.shape == FlashShape::Circular, g.shape == FlashShape::Line);
    let radius = need(g.radius_m, "radius_m", circular);
    let half_width = need(g.half_width_m, "half_width_m", !circular);
    let length = need(g.length_m, "length_m", line);
    if errors.len() > n {
        return None;
    }
    Some(match g.shape {
        FlashShape::Circular => Source::Circular { radius },
        FlashShape::Square => Source::Square { half_width },
        FlashShape::Line => Source::Line {
            half_width,
            half_length: length / 2.0,
        },
    })
}

impl Validate for FlashTemperatureInput {
    type Valid = FlashTemperatureCase;
    fn validate(self) -> Result<FlashTemperatureCase, Vec<FieldError>> {
        let mut errors = Vec::new();
        let source = parse_source(&self.geometry, &mut errors);
        let a = parse_body(&self.body_a, "body_a", &mut errors);
        let b = parse_body(&self.body_b, "body_b", &mut errors);
        let load = self.load_n.get();
        if load > MAX_LOAD_N {
            errors.push(FieldError::new(
                "/load_n",
                format!("must be at most {MAX_LOAD_N:e} N"),
            ));
        }
        let friction = self.friction_coefficient.get();
        if friction > MAX_FRICTION {
            errors.push(FieldError::new(
                "/friction_coefficient",
                format!("must be at most {MAX_FRICTION}"),
            ));
        }
        let (Some(source), Some(a), Some(b)) = (source, a, b) else {
            return Err(errors);
        };
        let model = self.model.unwrap_or(match source {
            Source::Circular { .. } => FlashModel::TianKennedy,
            _ => FlashModel::Jaeger,
        });
        if model == FlashModel::TianKennedy && !matches!(source, Source::Circular { .. }) {
            errors.push(FieldError::new(
                "/model",
                "tian_kennedy is for circular contacts; use jaeger for square and line contacts",
            ));
        }
        if a.speed == 0.0 && b.speed == 0.0 {
            errors.push(FieldError::new(
                "/body_a/speed_m_s",
                "both bodies are stationary: nothing slides, no heat source moves",
            ));
        }
        if !errors.is_empty() {
            return Err(errors);
        }
        Ok(FlashTemperatureCase {
            source,
            load,
            friction,
            bodies: [a, b],
            model,
            bulk_c: self.bulk_temperature_c.map(Celsius::get),
        })
    }
}

/// One body's share.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct BodyResult {
    /// Peclet number L = |U| a/(2χ), dimensionless.
    #[schema(example = 169.6)]
    pub peclet_number: f64,
    pub regime: PecletRegime,
    /// Thermal diffusivity χ used, m²/s.
    pub thermal_diffusivity_m2_s: f64,
    /// Thermal conductance C = Q/T for the mean flash temperature, W/K (Khonsari's "Q
    /// coefficient": 32.2 W/°C for the moving body of Ex. 3.2).
    #[schema(example = 32.13)]
    pub thermal_conductance_w_k: f64,
    /// Fraction of the frictional heat this body takes, C_i/(C_A + C_B), dimensionless.
    pub heat_fraction: f64,
    /// Heat conducted into this body, W.
    pub heat_w: f64,
    /// Mean flash temperature rise if this body took all the heat, Q/C_i, K (Stachowiak's
    /// T_fA, T_fB); absent where C_i = 0 (a stationary body under a line source).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub flash_temperature_rise_alone_k: Option<f64>,
    /// Maximum flash temperature rise if this body took all the heat, K; where the model gives
    /// a maximum.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_flash_temperature_rise_alone_k: Option<f64>,
}

/// Result.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct FlashTemperatureOutput {
    /// The model used.
    pub model: FlashModel,
    /// `circular`, `square` or `line`.
    #[schema(example = "circular")]
    pub shape: String,
    /// Sliding speed |U_A − U_B|, m/s.
    pub sliding_speed_m_s: f64,
    /// Frictional heat Q = μW|U_A − U_B|, W.
    #[schema(example = 150.0)]
    pub heat_flux_w: f64,
    /// Heat supply per unit area q = Q/A, W/m² (A = πa², 4b², 4bl).
    pub heat_flux_density_w_m2: f64,
    /// Contact area A, m².
    pub contact_area_m2: f64,
    pub body_a: BodyResult,
    pub body_b: BodyResult,
    /// Mean (average over the contact) flash temperature rise T_f = Q/(C_A + C_B), K.
    #[schema(example = 4.37)]
    pub flash_temperature_rise_k: f64,
    /// Maximum flash temperature rise, 1/T_fmax = 1/T_fmaxA + 1/T_fmaxB (Stachowiak eq. 7.38), K;
    /// model `jaeger` where both bodies' forms give a maximum (square and line; circular when
    /// both are fast, T_max = 1.64 T̄).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_flash_temperature_rise_k: Option<f64>,
    /// T_b + T_f (mean), °C, when `bulk_temperature_c` is given.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mean_surface_temperature_c: Option<f64>,
    /// Contact temperature T_c = T_b + T_fmax (Stachowiak eq. 7.36), °C, when
    /// `bulk_temperature_c` is given and a maximum is available.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_surface_temperature_c: Option<f64>,
}

impl Calculation for FlashTemperature {
    const PATH: &'static str = "/v1/contacts/flash-temperature";
    const SUMMARY: &'static str =
        "Flash temperature of a sliding contact (circular, square, line), heat shared by two bodies";
    const DESCRIPTION: &'static str = include_str!("flash_temperature.md");
    const FIDELITY: &'static [Level] = &[Level::ClosedForm];
    const EFFECTS: &'static [&'static str] = &[];
    const EXAMPLE: &'static str = r#"{"geometry": {"shape": "circular", "radius_m": 0.01}, "load_n": 3000, "friction_coefficient": 0.1, "body_a": {"speed_m_s": 0.5, "thermal_conductivity_w_m_k": 54, "thermal_diffusivity_m2_s": 1.474e-5}, "body_b": {"speed_m_s": 0, "thermal_conductivity_w_m_k": 54, "thermal_diffusivity_m2_s": 1.474e-5}, "bulk_temperature_c": 40}"#;

    type Input = FlashTemperatureInput;
    type Output = FlashTemperatureOutput;

    fn run(
        case: FlashTemperatureCase,
        ctx: &mut Context,
    ) -> Result<FlashTemperatureOutput, CalcError> {
        let s = flash::solve(&case)?;
        for warning in &s.warnings {
            ctx.warn(warning.code, warning.message.clone());
        }
        ctx.report(s.report.clone());
        let body = |b: &BodyShare| BodyResult {
            peclet_number: b.peclet_number,
            regime: b.regime,
            thermal_diffusivity_m2_s: b.thermal_diffusivity_m2_s,
            thermal_conductance_w_k: b.thermal_conductance_w_k,
            heat_fraction: b.heat_fraction,
            heat_w: b.heat_w,
            flash_temperature_rise_alone_k: b.flash_temperature_rise_alone_k,
            max_flash_temperature_rise_alone_k: b.max_flash_temperature_rise_alone_k,
        };
        let (q, flash, max) = (
            s.heat_w,
            s.flash_temperature_rise_k,
            s.max_flash_temperature_rise_k,
        );
        Ok(FlashTemperatureOutput {
            model: case.model,
            shape: case.source.name().to_owned(),
            sliding_speed_m_s: s.sliding_speed_m_s,
            heat_flux_w: q,
            heat_flux_density_w_m2: q / s.contact_area_m2,
            contact_area_m2: s.contact_area_m2,
            body_a: body(&s.bodies[0]),
            body_b: body(&s.bodies[1]),
            flash_temperature_rise_k: flash,
            max_flash_temperature_rise_k: max,
            mean_surface_temperature_c: case.bulk_c.map(|t| t + flash),
            max_surface_temperature_c: case.bulk_c.zip(max).map(|(t, m)| t + m),
        })
    }
}

#[cfg(test)]
#[path = "flash_temperature_tests.rs"]
mod tests;
