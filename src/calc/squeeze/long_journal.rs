//! The infinitely long journal squeezed without rotation (Khonsari & Booser §9.5, Table 9.2;
//! spec SQ-5): no side leakage, valid for L/D > 2 or end-sealed bearings. With the load
//! coefficient W̄ = W C³/(μ L R³ V) (the form of Table 9.3; V = C dε/dt the approach speed), the
//! squeeze time under a constant load W is Δt = (μ L R³/(W C²)) ∫_{ε₁}^{ε₂} W̄ dε.

/// The film of a squeezed journal.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FilmExtent {
    /// The full 360° film: the negative pressures on the opening side are kept.
    Full,
    /// A cavitated film: only the closing side carries pressure (the 180° film of Table 9.2 in
    /// the closed form; the Reynolds condition p ≥ 0 in the numerical film).
    Cavitated,
}

/// W̄(ε) of the infinitely long journal:
/// - 360°: W̄ = 12π/(1 − ε²)^{3/2};
/// - 180°: W̄ = 12 [ε/(1 − ε²) + 2 tan⁻¹√((1 + ε)/(1 − ε))/(1 − ε²)^{3/2}].
pub fn load_coefficient(eps: f64, film: FilmExtent) -> f64 {
    let s = 1.0 - eps * eps;
    match film {
        FilmExtent::Full => 12.0 * std::f64::consts::PI / s.powf(1.5),
        FilmExtent::Cavitated => {
            12.0 * (eps / s + 2.0 * ((1.0 + eps) / (1.0 - eps)).sqrt().atan() / s.powf(1.5))
        }
    }
}

/// ∫₀^ε W̄ dε′ (Table 9.2's squeeze times; the 180° form verified against the derivative of W̄):
/// - 360°: 12π ε/√(1 − ε²);
/// - 180°: 24 [ε tan⁻¹√((1 + ε)/(1 − ε))/√(1 − ε²)] measured from ε = 0 (where it is 0).
pub fn load_integral(eps: f64, film: FilmExtent) -> f64 {
    let root = (1.0 - eps * eps).sqrt();
    match film {
        FilmExtent::Full => 12.0 * std::f64::consts::PI * eps / root,
        FilmExtent::Cavitated => 24.0 * eps * ((1.0 + eps) / (1.0 - eps)).sqrt().atan() / root,
    }
}
