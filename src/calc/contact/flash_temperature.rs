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
//!   ([`super::moving_heat_source`]: the circle and the square as 3D sources, the line as the
//!   infinitely long band the table's forms describe), which reproduces the square's and the
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
//! Two fast bodies in a line contact reproduce Blok's eq. 7.39 with 2√2 × 0.399 = 1.128 in place
//! of the text's rounded 1.11: the service follows Table 7.7, 1.6 % above eq. 7.39–7.40.

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use crate::calc::quantity::{Celsius, NonNegative, Positive};
use crate::calc::surface::moving_heat_source::{self, Shape};
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::fidelity::{Level, SolverReport};

pub struct FlashTemperature;

/// Upper end of the slow (stationary-source) range of the Jaeger/Archard forms.
const SLOW_PECLET: f64 = 0.1;
/// Lower end of the fast-source range of the Jaeger/Archard forms.
const FAST_PECLET: f64 = 5.0;
/// Circular fast source: T_max ≈ 1.64 T̄ (Stachowiak Fig. 7.32).
const CIRCULAR_MAX_OVER_MEAN: f64 = 1.64;
/// Largest accepted magnitudes: beyond them no tribological contact is meant.
const MAX_LENGTH_M: f64 = 10.0;
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
    /// Contact radius a, m, 0 < a ≤ 10; `circular` only.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 0.01)]
    pub radius_m: Option<Positive>,
    /// Half-width b in the sliding direction, m, 0 < b ≤ 10; `square` (half-side) and `line`
    /// (half the band's width, e.g. the Hertz half-width).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 1.82e-4)]
    pub half_width_m: Option<Positive>,
    /// Full length 2l of the band across the sliding direction, m, 0 < 2l ≤ 10; `line` only.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 0.01)]
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
    /// Thermal conductivity K, W/(m·K), > 0 (carbon steel 54, bearing steel 46.7).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 1e4, example = 54.0)]
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

/// Which conductances are used.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum FlashModel {
    /// Tian & Kennedy (1994) as Khonsari & Booser eq. 3.51 give it: circular contacts, every
    /// Peclet number; 4aK for a stationary body (eq. 3.49).
    TianKennedy,
    /// Blok–Jaeger–Archard slow (L ≤ 0.1) and fast (L ≥ 5) forms, Stachowiak & Batchelor
    /// Tables 7.5–7.7; mean and maximum flash temperatures.
    Jaeger,
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

/// The source as the physics takes it (lengths in m).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Source {
    Circular {
        radius: f64,
    },
    Square {
        half_width: f64,
    },
    /// `half_length` is l, half the band's length.
    Line {
        half_width: f64,
        half_length: f64,
    },
}

impl Source {
    /// The length in the Peclet number: a or b.
    fn peclet_length(self) -> f64 {
        match self {
            Source::Circular { radius } => radius,
            Source::Square { half_width } | Source::Line { half_width, .. } => half_width,
        }
    }

    fn area(self) -> f64 {
        match self {
            Source::Circular { radius } => std::f64::consts::PI * radius * radius,
            Source::Square { half_width } => 4.0 * half_width * half_width,
            Source::Line {
                half_width,
                half_length,
            } => 4.0 * half_width * half_length,
        }
    }

    fn name(self) -> &'static str {
        match self {
            Source::Circular { .. } => "circular",
            Source::Square { .. } => "square",
            Source::Line { .. } => "line",
        }
    }
}

/// One body as the physics takes it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Body {
    /// Surface speed U, m/s (signed).
    pub speed: f64,
    /// Conductivity K, W/(m·K).
    pub conductivity: f64,
    /// Diffusivity χ, m²/s.
    pub diffusivity: f64,
}

/// The validated case.
#[derive(Debug, Clone, Copy)]
pub struct FlashTemperatureCase {
    pub source: Source,
    pub load: f64,
    pub friction: f64,
    pub bodies: [Body; 2],
    pub model: FlashModel,
    pub bulk_c: Option<f64>,
}

/// The Peclet range a body's Peclet number falls in (Stachowiak's three ranges).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum PecletRegime {
    /// L ≤ 0.1: the source is (nearly) stationary over this body; steady conduction.
    Slow,
    /// 0.1 < L < 5.
    Intermediate,
    /// L ≥ 5: fast source; heat diffuses normal to the surface only.
    Fast,
}

impl PecletRegime {
    fn of(peclet: f64) -> Self {
        if peclet <= SLOW_PECLET {
            PecletRegime::Slow
        } else if peclet < FAST_PECLET {
            PecletRegime::Intermediate
        } else {
            PecletRegime::Fast
        }
    }
}

impl Body {
    /// L = |U| a/(2χ).
    pub fn peclet(&self, source: Source) -> f64 {
        self.speed.abs() * source.peclet_length() / (2.0 * self.diffusivity)
    }
}

/// Thermal conductances C = Q/T of one body taking all the heat, W/K: for the mean flash
/// temperature, and for the maximum where the model gives one.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Conductance {
    pub mean: f64,
    pub max: Option<f64>,
}

/// The conductances of `body` under `source` by `model` (see the module doc for the forms).
/// `None` where the model has no formula (Tian–Kennedy for a non-circular source).
pub fn conductance(model: FlashModel, source: Source, body: &Body) -> Option<Conductance> {
    let k = body.conductivity;
    let l = body.peclet(source);
    match (model, source) {
        (FlashModel::TianKennedy, Source::Circular { radius: a }) => {
            let mean = if body.speed == 0.0 {
                4.0 * a * k
            } else {
                4.56 * a * k * (0.66 + l).sqrt()
            };
            Some(Conductance { mean, max: None })
        }
        (FlashModel::TianKennedy, _) => None,
        (FlashModel::Jaeger, _) => match PecletRegime::of(l) {
            PecletRegime::Intermediate => Some(moving_source(source, k, l)),
            regime => Some(jaeger(source, k, l, regime == PecletRegime::Fast)),
        },
    }
}

/// Conductances from the integrated moving-source solution (T in units of qℓ/K, so
/// C = Q/T = A K/(ℓ T)).
fn moving_source(source: Source, k: f64, l: f64) -> Conductance {
    let shape = match source {
        Source::Circular { .. } => Shape::Circle,
        Source::Square { .. } => Shape::Rectangle { half_length: 1.0 },
        Source::Line { .. } => Shape::Band,
    };
    let t = moving_heat_source::temperatures(shape, l);
    let per_coefficient = source.area() * k / source.peclet_length();
    Conductance {
        mean: per_coefficient / t.mean,
        max: Some(per_coefficient / t.max),
    }
}

/// Jaeger/Archard conductances, written through q = Q/A so that C = Q/T = A·(q/T).
fn jaeger(source: Source, k: f64, l: f64, fast: bool) -> Conductance {
    let area = source.area();
    let pi = std::f64::consts::PI;
    match source {
        Source::Circular { radius: a } => {
            if fast {
                // T̄ = 0.308 (Q/(Ka)) (χ/(Ua))^½ and χ/(Ua) = 1/(2L).
                let mean = k * a * (2.0 * l).sqrt() / 0.308;
                Conductance {
                    mean,
                    max: Some(mean / CIRCULAR_MAX_OVER_MEAN),
                }
            } else {
                Conductance {
                    mean: 4.0 * k * a,
                    max: None,
                }
            }
        }
        Source::Square { half_width: b } | Source::Line { half_width: b, .. } => {
            // T = coefficient × q b/K, so C = A K/(b × coefficient).
            let per_coefficient = area * k / b;
            let (mean, max) = if fast {
                // (χb/U)^½ = b/(2L)^½; (2χb/(πU))^½ = b/(πL)^½.
                (1.064 / (2.0 * l).sqrt(), 2.0 / (pi * l).sqrt())
            } else if let Source::Line { .. } = source {
                // (2/π)(1.616 − ln 2L) and (2/π)(1.116 − ln L): infinite at L = 0.
                (
                    2.0 / pi * (1.616 - (2.0 * l).ln()),
                    2.0 / pi * (1.116 - l.ln()),
                )
            } else {
                (0.946, 1.122)
            };
            Conductance {
                mean: per_coefficient / mean,
                max: Some(per_coefficient / max),
            }
        }
    }
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
    if k > 1e4 {
        errors.push(body_error(
            name,
            "thermal_conductivity_w_m_k",
            format!("must be at most 1e4 W/(m·K), got {k}"),
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
            (Some(v), true) if v.get() <= MAX_LENGTH_M => v.get(),
            (Some(v), true) => {
                errors.push(FieldError::new(
                    format!("/geometry/{field}"),
                    format!("must be at most {MAX_LENGTH_M} m, got {}", v.get()),
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

/// 1/T = Σ 1/T_i for conductances C_i: T = Q/ΣC_i.
fn shared(q: f64, c: [f64; 2]) -> f64 {
    q / (c[0] + c[1])
}

impl Calculation for FlashTemperature {
    const PATH: &'static str = "/v1/contacts/flash-temperature";
    const SUMMARY: &'static str =
        "Flash temperature of a sliding contact (circular, square, line), heat shared by two bodies";
    const DESCRIPTION: &'static str = "Mean and maximum flash temperature rise of a uniform frictional heat source Q = μW|U_A − U_B| \
on a circular, square or band contact, each body with its own Peclet number L = Ua/(2χ), the heat shared so both surfaces reach \
the same temperature (1/T_f = 1/T_fA + 1/T_fB). Models: Tian–Kennedy for circular contacts over all Peclet numbers \
(Khonsari & Booser eq. 3.49–3.51, 4aK for a stationary body) and the Blok–Jaeger–Archard slow (L ≤ 0.1) and fast (L ≥ 5) forms \
(Stachowiak & Batchelor Tables 7.5–7.7); in between (0.1 < L < 5), where the texts have only charts, Jaeger's moving-source \
solution for a uniform flux integrated numerically (3D for circles and squares, the 2D band for lines).";
    const FIDELITY: &'static [Level] = &[Level::ClosedForm];
    const EFFECTS: &'static [&'static str] = &[];
    const EXAMPLE: &'static str = r#"{"geometry": {"shape": "circular", "radius_m": 0.01}, "load_n": 3000, "friction_coefficient": 0.1, "body_a": {"speed_m_s": 0.5, "thermal_conductivity_w_m_k": 54, "thermal_diffusivity_m2_s": 1.474e-5}, "body_b": {"speed_m_s": 0, "thermal_conductivity_w_m_k": 54, "thermal_diffusivity_m2_s": 1.474e-5}, "bulk_temperature_c": 40}"#;

    type Input = FlashTemperatureInput;
    type Output = FlashTemperatureOutput;

    fn run(
        case: FlashTemperatureCase,
        ctx: &mut Context,
    ) -> Result<FlashTemperatureOutput, CalcError> {
        let [a, b] = case.bodies;
        let sliding = (a.speed - b.speed).abs();
        let q = case.friction * case.load * sliding;
        let [ca, cb] = [a, b].map(|body| conductance(case.model, case.source, &body));
        let (Some(ca), Some(cb)) = (ca, cb) else {
            return Err(CalcError::Internal(
                "validation let through a body without a formula".to_owned(),
            ));
        };
        let mean = [ca.mean, cb.mean];
        let total = mean[0] + mean[1];
        if !(total > 0.0 && total.is_finite()) {
            return Err(CalcError::impossible(
                "/body_a/speed_m_s",
                "neither body conducts the heat away in steady state (a band source over two stationary bodies)",
            ));
        }
        let flash = shared(q, mean);
        let max = match (ca.max, cb.max) {
            (Some(x), Some(y)) => Some(shared(q, [x, y])),
            _ => None,
        };
        if !flash.is_finite() || max.is_some_and(|m| !m.is_finite()) {
            return Err(CalcError::impossible(
                "",
                "the flash temperature is not finite for these inputs",
            ));
        }
        if matches!(case.source, Source::Line { .. }) && [a, b].iter().any(|body| body.speed == 0.0)
        {
            ctx.warn(
                "stationary_band_source",
                "a band source has no steady state in a stationary body (Jaeger's line forms diverge as L → 0): the moving body takes all the heat",
            );
        }
        if let Some(bulk) = case.bulk_c {
            if bulk + max.unwrap_or(flash) > Celsius::MAX {
                ctx.warn(
                    "surface_above_1000_c",
                    "the surface temperature exceeds 1000 °C: the contact would melt, oxidise or change its friction long before",
                );
            }
        }
        let body = |body: &Body, c: &Conductance| BodyResult {
            peclet_number: body.peclet(case.source),
            regime: PecletRegime::of(body.peclet(case.source)),
            thermal_diffusivity_m2_s: body.diffusivity,
            thermal_conductance_w_k: c.mean,
            heat_fraction: c.mean / total,
            heat_w: q * c.mean / total,
            flash_temperature_rise_alone_k: (c.mean > 0.0).then(|| q / c.mean),
            max_flash_temperature_rise_alone_k: c.max.filter(|m| *m > 0.0).map(|m| q / m),
        };
        let integrated = case.model == FlashModel::Jaeger
            && [a, b].iter().any(|body| {
                PecletRegime::of(body.peclet(case.source)) == PecletRegime::Intermediate
            });
        ctx.report(match case.model {
            FlashModel::TianKennedy => SolverReport::closed_form("tian_kennedy"),
            // The request has no fidelity to choose: the quadrature is fixed (720 directions,
            // 24² Gauss points; 0.3 % against the exact slow limits).
            FlashModel::Jaeger if integrated => {
                SolverReport::closed_form("jaeger_archard_with_moving_source_quadrature")
            }
            FlashModel::Jaeger => SolverReport::closed_form("jaeger_archard"),
        });
        Ok(FlashTemperatureOutput {
            model: case.model,
            shape: case.source.name().to_owned(),
            sliding_speed_m_s: sliding,
            heat_flux_w: q,
            heat_flux_density_w_m2: q / case.source.area(),
            contact_area_m2: case.source.area(),
            body_a: body(&a, &ca),
            body_b: body(&b, &cb),
            flash_temperature_rise_k: flash,
            max_flash_temperature_rise_k: max,
            mean_surface_temperature_c: case.bulk_c.map(|t| t + flash),
            max_surface_temperature_c: case.bulk_c.zip(max).map(|(t, m)| t + m),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::calc::testing::{assert_rel, invalid_pointers, ok, result_field};
    use proptest::prelude::*;
    use serde_json::{json, Value};

    fn steel(speed: f64) -> Value {
        json!({"speed_m_s": speed, "thermal_conductivity_w_m_k": 54.0, "thermal_diffusivity_m2_s": 1.474e-5})
    }

    /// Khonsari & Booser Ex. 3.2.
    fn example_3_2() -> Value {
        json!({
            "geometry": {"shape": "circular", "radius_m": 0.01},
            "load_n": 3000.0, "friction_coefficient": 0.1,
            "body_a": steel(0.5), "body_b": steel(0.0)
        })
    }

    /// Stachowiak & Batchelor §7.6 example: two steel rollers, b from Hertz.
    fn two_rollers() -> Value {
        let roller = |u: f64| json!({"speed_m_s": u, "thermal_conductivity_w_m_k": 46.7, "density_kg_m3": 7800.0, "specific_heat_j_kg_k": 460.0});
        json!({
            "geometry": {"shape": "line", "half_width_m": 1.819456736586892e-4, "length_m": 0.01},
            "load_n": 5000.0, "friction_coefficient": 0.2,
            "body_a": roller(2.0), "body_b": roller(1.0), "bulk_temperature_c": 80.0
        })
    }

    fn body(v: &Value, name: &str, field: &str) -> f64 {
        v["result"][name][field]
            .as_f64()
            .unwrap_or_else(|| panic!("{name}.{field} missing in {v}"))
    }

    #[test]
    fn khonsari_example_3_2_moving_steel_on_a_stationary_pin() {
        let v = ok::<FlashTemperature>(&example_3_2());
        // Spec recomputation: Pe = 169.6, 32.13 and 2.16 W/°C, ΔT = 4.37 °C, 69.4 °C.
        assert_rel(body(&v, "body_a", "peclet_number"), 169.6, 1e-3, "Pe");
        assert_rel(
            body(&v, "body_a", "thermal_conductance_w_k"),
            32.13,
            1e-3,
            "C1",
        );
        assert_rel(
            body(&v, "body_b", "thermal_conductance_w_k"),
            2.16,
            1e-9,
            "C2",
        );
        assert_rel(
            result_field(&v, "flash_temperature_rise_k"),
            4.37,
            2e-3,
            "ΔT",
        );
        assert_rel(
            body(&v, "body_b", "flash_temperature_rise_alone_k"),
            69.4,
            1e-3,
            "all heat in body 2",
        );
        assert_rel(result_field(&v, "heat_flux_w"), 150.0, 1e-12, "Q");
        assert_eq!(v["result"]["model"], "tian_kennedy");
        assert_eq!(v["result"]["body_a"]["regime"], "fast");
        assert_eq!(v["result"]["body_b"]["regime"], "slow");
        assert!(v["result"]["max_flash_temperature_rise_k"].is_null());
    }

    #[test]
    fn stachowiak_two_rollers_follow_table_7_7_and_blok_eq_7_40() {
        let v = ok::<FlashTemperature>(&two_rollers());
        assert_rel(body(&v, "body_a", "peclet_number"), 13.98, 1e-3, "L_A");
        assert_rel(body(&v, "body_b", "peclet_number"), 6.99, 1e-3, "L_B");
        assert_rel(
            body(&v, "body_a", "thermal_diffusivity_m2_s"),
            13.02e-6,
            1e-3,
            "χ",
        );
        // Table 7.7 summed over two fast bodies is eq. 7.40 with 2/√π = 1.128 for 1.11.
        let (mu, w, two_l, b): (f64, f64, f64, f64) = (0.2, 5000.0, 0.01, 1.819456736586892e-4);
        let krs: f64 = 46.7 * 7800.0 * 460.0;
        let eq_7_40 =
            |c: f64| c * mu * w * (2f64.sqrt() - 1.0) / (two_l * (2.0 * b).sqrt() * krs.sqrt());
        let t_max = result_field(&v, "max_flash_temperature_rise_k");
        assert_rel(
            t_max,
            eq_7_40(2.0 / std::f64::consts::PI.sqrt()),
            1e-3,
            "Table 7.7 = eq 7.40 with 1.128",
        );
        assert_rel(eq_7_40(1.11), 186.2, 1e-3, "the book's eq 7.40");
        assert_rel(
            t_max,
            186.2,
            0.017,
            "within the 1.11/1.128 difference of the book",
        );
        assert_rel(
            result_field(&v, "max_surface_temperature_c"),
            80.0 + t_max,
            1e-12,
            "T_c",
        );
        assert!(result_field(&v, "flash_temperature_rise_k") < t_max);
    }

    #[test]
    fn tian_kennedy_meets_archard_fast_at_high_peclet_and_4ak_near_zero() {
        let source = Source::Circular { radius: 0.01 };
        let at = |speed: f64| Body {
            speed,
            conductivity: 54.0,
            diffusivity: 1.474e-5,
        };
        let c = |m, b: &Body| conductance(m, source, b).expect("a formula").mean;
        // L = 1e4: 4.56 against 1/0.308 × √2 = 4.592, their constants 0.7 % apart.
        let fast = at(1e4 * 2.0 * 1.474e-5 / 0.01);
        assert_rel(
            c(FlashModel::TianKennedy, &fast),
            c(FlashModel::Jaeger, &fast),
            0.01,
            "high Pe",
        );
        // Pe → 0: 4.56 √0.66 aK = 3.705 aK against 4aK (eq 3.50), the disc's flux vs isothermal.
        let creep = at(1e-9);
        let ratio = c(FlashModel::TianKennedy, &creep) / c(FlashModel::Jaeger, &creep);
        assert_rel(ratio, 4.56 * 0.66f64.sqrt() / 4.0, 1e-6, "low Pe");
        assert_eq!(
            c(FlashModel::TianKennedy, &at(0.0)),
            c(FlashModel::Jaeger, &at(0.0))
        );
    }

    #[test]
    fn a_stationary_body_under_a_band_takes_no_heat() {
        let mut req = two_rollers();
        req["body_b"]["speed_m_s"] = json!(0.0);
        let v = ok::<FlashTemperature>(&req);
        assert_eq!(body(&v, "body_b", "heat_w"), 0.0);
        assert_rel(body(&v, "body_a", "heat_fraction"), 1.0, 1e-12, "all to A");
        assert!(v["result"]["body_b"]["flash_temperature_rise_alone_k"].is_null());
        assert_eq!(v["warnings"][0]["code"], "stationary_band_source");
    }

    #[test]
    fn square_slow_and_fast_forms_match_table_7_6() {
        // A slow square (L = 0.01) on a fast one (L = 50): both forms by hand.
        let (b, k, chi, mu, w) = (1e-3, 50.0, 1e-5, 0.3, 100.0);
        let (ua, ub) = (1.0, 2e-4);
        let req = json!({
            "geometry": {"shape": "square", "half_width_m": b},
            "load_n": w, "friction_coefficient": mu,
            "body_a": {"speed_m_s": ua, "thermal_conductivity_w_m_k": k, "thermal_diffusivity_m2_s": chi},
            "body_b": {"speed_m_s": ub, "thermal_conductivity_w_m_k": k, "thermal_diffusivity_m2_s": chi}
        });
        let v = ok::<FlashTemperature>(&req);
        let q: f64 = mu * w * (ua - ub) / (4.0 * b * b);
        let ta = 1.064 * q / k * (chi * b / ua).sqrt();
        let tb = 0.946 * q * b / k;
        let tmax_a = 2.0 * q / k * (2.0 * chi * b / (std::f64::consts::PI * ua)).sqrt();
        let tmax_b = 1.122 * q * b / k;
        assert_rel(
            body(&v, "body_a", "flash_temperature_rise_alone_k"),
            ta,
            1e-12,
            "T_fA",
        );
        assert_rel(
            body(&v, "body_b", "flash_temperature_rise_alone_k"),
            tb,
            1e-12,
            "T_fB",
        );
        assert_rel(
            result_field(&v, "flash_temperature_rise_k"),
            1.0 / (1.0 / ta + 1.0 / tb),
            1e-12,
            "eq 7.37",
        );
        assert_rel(
            result_field(&v, "max_flash_temperature_rise_k"),
            1.0 / (1.0 / tmax_a + 1.0 / tmax_b),
            1e-12,
            "eq 7.38",
        );
    }

    #[test]
    fn the_intermediate_peclet_range_is_integrated_between_the_slow_and_fast_forms() {
        // A square on a moving body through L = 0.1 … 5: the integrated mean lies below the slow
        // form and above the fast one, and falls with speed (Stachowiak Table 7.6, Fig. 7.30).
        let mut last = f64::INFINITY;
        for speed in [0.004, 0.01, 0.03, 0.1] {
            let mut r = two_rollers();
            r["geometry"] = json!({"shape": "square", "half_width_m": 1e-3});
            r["body_b"]["speed_m_s"] = json!(0.0);
            r["body_a"]["speed_m_s"] = json!(speed);
            let v = ok::<FlashTemperature>(&r);
            let l = body(&v, "body_a", "peclet_number");
            assert!(0.1 < l && l < 5.0, "L = {l}");
            assert_eq!(
                v["solver"]["method"],
                "jaeger_archard_with_moving_source_quadrature"
            );
            let alone = body(&v, "body_a", "flash_temperature_rise_alone_k");
            let q = v["result"]["heat_flux_w"].as_f64().unwrap();
            let qb_k = q / 4e-6 * 1e-3 / 46.7;
            // Each limiting form overestimates outside its own range: the exact lies below both.
            let (slow, fast) = (0.946 * qb_k, 1.064 / (2.0 * l).sqrt() * qb_k);
            assert!(alone < slow.min(fast), "L = {l}");
            // … and approaches each near its range: within 15 % at L = 0.15 and L = 3.8.
            assert!(l > 0.2 || alone > 0.85 * slow, "L = {l}");
            assert!(l < 3.0 || alone > 0.85 * fast, "L = {l}");
            let per_heat = alone / q;
            assert!(per_heat < last);
            last = per_heat;
        }
    }

    #[test]
    fn refusals_name_the_field() {
        let mut tk_square = two_rollers();
        tk_square["model"] = json!("tian_kennedy");
        let mut missing = example_3_2();
        missing["geometry"] = json!({"shape": "line", "half_width_m": 1e-4});
        let mut both_thermal = example_3_2();
        both_thermal["body_b"]["density_kg_m3"] = json!(7800.0);
        let mut still = example_3_2();
        still["body_a"]["speed_m_s"] = json!(0.0);
        let mut typo = example_3_2();
        typo["lod_n"] = json!(1.0);
        let mut stray = example_3_2();
        stray["geometry"]["length_m"] = json!(0.01);
        let rows: [(&Value, &str, &str); 5] = [
            (&tk_square, "/model", "Tian–Kennedy is circular"),
            (&missing, "/geometry/length_m", "a band needs its length"),
            (
                &both_thermal,
                "/body_b/thermal_diffusivity_m2_s",
                "χ and ρ, σ both",
            ),
            (&still, "/body_a/speed_m_s", "nothing moves"),
            (&stray, "/geometry/length_m", "a circle has no length"),
        ];
        for (req, pointer, why) in rows {
            assert_eq!(
                invalid_pointers::<FlashTemperature>(req),
                vec![pointer.to_owned()],
                "{why}"
            );
        }
        assert!(crate::calc::testing::post::<FlashTemperature>(&typo).is_err());
    }

    #[test]
    fn example_runs() {
        let req: Value = serde_json::from_str(FlashTemperature::EXAMPLE).expect("example is JSON");
        let v = ok::<FlashTemperature>(&req);
        assert_rel(
            result_field(&v, "mean_surface_temperature_c"),
            40.0 + 4.374,
            1e-3,
            "T_b + ΔT",
        );
    }

    #[test]
    fn reference_cases_pass() {
        for case in [
            include_str!("../../../tests/data/contact/kb_ex3_2_flash_temperature_pin.json"),
            include_str!(
                "../../../tests/data/contact/stachowiak_r7_6_flash_temperature_two_rollers.json"
            ),
        ] {
            let case: Value = serde_json::from_str(case).expect("case is JSON");
            assert_eq!(case["path"], FlashTemperature::PATH);
            let v = ok::<FlashTemperature>(&case["request"]);
            for want in case["expected"].as_array().expect("expected list") {
                let pointer = want["pointer"].as_str().expect("pointer");
                let got = v
                    .pointer(pointer)
                    .and_then(Value::as_f64)
                    .unwrap_or(f64::NAN);
                let (value, tol) = (want["value"].as_f64(), want["rel_tol"].as_f64());
                assert_rel(got, value.expect("value"), tol.expect("rel_tol"), pointer);
            }
        }
    }

    /// A request over the valid ranges: a circular Tian–Kennedy case, or a Jaeger square or
    /// band with body A fast (L ≥ 5) and body B fast or stationary.
    fn request(shape: u8, load: f64, mu: f64, speed: f64, b_moves: bool) -> Value {
        let geometry = match shape {
            0 => json!({"shape": "circular", "radius_m": 1e-3}),
            1 => json!({"shape": "square", "half_width_m": 1e-3}),
            _ => json!({"shape": "line", "half_width_m": 1e-3, "length_m": 0.02}),
        };
        let b_speed = if b_moves { speed / 3.0 } else { 0.0 };
        json!({
            "geometry": geometry, "load_n": load, "friction_coefficient": mu,
            "body_a": steel(speed), "body_b": steel(b_speed)
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(64))]
        #[test]
        fn finite_shared_and_monotone(
            shape in 0u8..3, load in 1.0f64..1e5, mu in 0.01f64..1.0,
            // L_A = U·1e-3/(2·1.474e-5) ≥ 5 (and L_B ≥ 5 when B moves at U/3).
            speed in 0.45f64..100.0, b_moves: bool, grow in 1.01f64..3.0,
        ) {
            let run = |l: f64, m: f64, u: f64| ok::<FlashTemperature>(&request(shape, l, m, u, b_moves));
            let v = run(load, mu, speed);
            let t = result_field(&v, "flash_temperature_rise_k");
            prop_assert!(t.is_finite() && t > 0.0);
            let q = result_field(&v, "heat_flux_w");
            let shares = body(&v, "body_a", "heat_w") + body(&v, "body_b", "heat_w");
            prop_assert!((shares / q - 1.0).abs() < 1e-12);
            let fractions = body(&v, "body_a", "heat_fraction") + body(&v, "body_b", "heat_fraction");
            prop_assert!((fractions - 1.0).abs() < 1e-12);
            for bigger in [run(load * grow, mu, speed), run(load, mu * grow, speed), run(load, mu, speed * grow)] {
                prop_assert!(result_field(&bigger, "flash_temperature_rise_k") > t);
            }
        }
    }
}
