//! The flash temperature of a sliding contact: the rise of the contact's surface temperature
//! above the bulk temperature of the solids entering it, for circular, square and line (band)
//! heat sources, with the frictional heat shared between the two bodies so both surfaces reach
//! the same temperature (1/T_f = 1/T_fA + 1/T_fB). The symbols, the models and their sources
//! are in the room's module doc (`crate::calc::contact::flash_temperature`); the intermediate
//! Peclet range integrates [`super::moving_heat_source`].

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::moving_heat_source::{self, Shape};
use crate::calc::quantity::Celsius;
use crate::calc::{CalcError, Warning};
use crate::fidelity::SolverReport;

/// Upper end of the slow (stationary-source) range of the Jaeger/Archard forms.
const SLOW_PECLET: f64 = 0.1;
/// Lower end of the fast-source range of the Jaeger/Archard forms.
const FAST_PECLET: f64 = 5.0;
/// Circular fast source: T_max ≈ 1.64 T̄ (Stachowiak Fig. 7.32).
const CIRCULAR_MAX_OVER_MEAN: f64 = 1.64;
// `FlashModel` and `PecletRegime` are values the requests and responses carry by name; they
// derive their wire form here rather than through mirror enums.
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
    pub fn peclet_length(self) -> f64 {
        match self {
            Source::Circular { radius } => radius,
            Source::Square { half_width } | Source::Line { half_width, .. } => half_width,
        }
    }

    pub fn area(self) -> f64 {
        match self {
            Source::Circular { radius } => std::f64::consts::PI * radius * radius,
            Source::Square { half_width } => 4.0 * half_width * half_width,
            Source::Line {
                half_width,
                half_length,
            } => 4.0 * half_width * half_length,
        }
    }

    /// `circular`, `square` or `line`.
    pub fn name(self) -> &'static str {
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

/// A checked flash-temperature case.
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
    /// The range of a Peclet number.
    pub fn of(peclet: f64) -> Self {
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

/// 1/T = Σ 1/T_i for conductances C_i: T = Q/ΣC_i.
fn shared(q: f64, c: [f64; 2]) -> f64 {
    q / (c[0] + c[1])
}

/// One body's share of the heat.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyShare {
    /// L = |U| a/(2χ).
    pub peclet_number: f64,
    pub regime: PecletRegime,
    /// χ, m²/s.
    pub thermal_diffusivity_m2_s: f64,
    /// C = Q/T for the mean flash temperature, W/K.
    pub thermal_conductance_w_k: f64,
    /// C_i/(C_A + C_B).
    pub heat_fraction: f64,
    /// Heat conducted into this body, W.
    pub heat_w: f64,
    /// Q/C_i, K; None where C_i = 0.
    pub flash_temperature_rise_alone_k: Option<f64>,
    /// The maximum if this body took all the heat, K, where the model gives one.
    pub max_flash_temperature_rise_alone_k: Option<f64>,
}

/// A solved flash-temperature case.
#[derive(Debug, Clone, PartialEq)]
pub struct FlashSolution {
    /// |U_A − U_B|, m/s.
    pub sliding_speed_m_s: f64,
    /// Q = μW|U_A − U_B|, W.
    pub heat_w: f64,
    /// The contact area A, m².
    pub contact_area_m2: f64,
    pub bodies: [BodyShare; 2],
    /// Mean flash temperature rise T_f = Q/(C_A + C_B), K.
    pub flash_temperature_rise_k: f64,
    /// Maximum flash temperature rise, K, where both bodies' forms give one.
    pub max_flash_temperature_rise_k: Option<f64>,
    /// Which forms were used (closed forms, or with the moving-source quadrature).
    pub report: SolverReport,
    pub warnings: Vec<Warning>,
}

/// The flash temperatures of a checked case, with the heat shared between the two bodies.
/// Refusals (neither body conducts the heat away; a temperature that is not finite) carry the
/// room's pointers.
pub fn solve(case: &FlashTemperatureCase) -> Result<FlashSolution, CalcError> {
    let mut warnings = Vec::new();
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
    if matches!(case.source, Source::Line { .. }) && [a, b].iter().any(|body| body.speed == 0.0) {
        warnings.push(Warning {
            code: "stationary_band_source",
            message: "a band source has no steady state in a stationary body (Jaeger's line forms diverge as L → 0): the moving body takes all the heat".to_owned(),
        });
    }
    if let Some(bulk) = case.bulk_c {
        if bulk + max.unwrap_or(flash) > Celsius::MAX {
            warnings.push(Warning {
                code: "surface_above_1000_c",
                message: "the surface temperature exceeds 1000 °C: the contact would melt, oxidise or change its friction long before".to_owned(),
            });
        }
    }
    let body = |body: &Body, c: &Conductance| BodyShare {
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
        && [a, b]
            .iter()
            .any(|body| PecletRegime::of(body.peclet(case.source)) == PecletRegime::Intermediate);
    let report = match case.model {
        FlashModel::TianKennedy => SolverReport::closed_form("tian_kennedy"),
        // The request has no fidelity to choose: the quadrature is fixed (720 directions,
        // 24² Gauss points; 0.3 % against the exact slow limits).
        FlashModel::Jaeger if integrated => {
            SolverReport::closed_form("jaeger_archard_with_moving_source_quadrature")
        }
        FlashModel::Jaeger => SolverReport::closed_form("jaeger_archard"),
    };

    Ok(FlashSolution {
        sliding_speed_m_s: sliding,
        heat_w: q,
        contact_area_m2: case.source.area(),
        bodies: [body(&a, &ca), body(&b, &cb)],
        flash_temperature_rise_k: flash,
        max_flash_temperature_rise_k: max,
        report,
        warnings,
    })
}
