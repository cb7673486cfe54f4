//! Roughness against the film: the composite roughness of two surfaces and the film parameter
//! Λ = h_min/√(σ₁² + σ₂²) that sorts a lubricated contact into full-film, mixed or boundary
//! lubrication (Hamrock §21.3.6, Khonsari §15.6, Stachowiak §7.5).

use serde::Serialize;
use utoipa::ToSchema;

/// Film parameter above which the surfaces are fully separated (Hamrock §21.3.6; Khonsari
/// FE-7; Stachowiak §7.5: Λ ≥ 3 minimal wear).
pub const FULL_FILM_LAMBDA: f64 = 3.0;
/// Below this Λ the asperities carry most of the load (boundary lubrication; Khonsari FE-7).
pub const BOUNDARY_LAMBDA: f64 = 1.0;

/// Composite RMS roughness √(σ₁² + σ₂²) of two surfaces, m.
pub fn composite_rms(sigma1_m: f64, sigma2_m: f64) -> f64 {
    sigma1_m.hypot(sigma2_m)
}

/// Film parameter Λ = h_min/σ with σ the composite RMS roughness, dimensionless.
pub fn film_parameter(min_film_m: f64, composite_rms_m: f64) -> f64 {
    min_film_m / composite_rms_m
}

// `LubricationRegime` is a value the responses carry by name; it derives its wire form here
// rather than through a mirror enum of the same three variants.
/// Whether the asperities touch, from Λ.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, ToSchema)]
#[serde(rename_all = "kebab-case")]
pub enum LubricationRegime {
    /// Λ > 3: full separation, no life reduction (Hamrock §21.3.6; Khonsari FE-7).
    FullFilm,
    /// 1 ≤ Λ ≤ 3: mixed, asperities share the load (surface distress, glazing: Stachowiak §7.5).
    Mixed,
    /// Λ < 1: boundary lubrication, smearing and wear (Stachowiak §7.5; Khonsari FE-7).
    Boundary,
}

impl LubricationRegime {
    /// The regime of a film parameter Λ.
    pub fn of(lambda: f64) -> Self {
        if lambda > FULL_FILM_LAMBDA {
            LubricationRegime::FullFilm
        } else if lambda >= BOUNDARY_LAMBDA {
            LubricationRegime::Mixed
        } else {
            LubricationRegime::Boundary
        }
    }
}
