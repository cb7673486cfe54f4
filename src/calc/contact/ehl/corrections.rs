//! Corrections to the isothermal, fully flooded EHL films: inlet shear heating (the Gupta et
//! al. thermal reduction factor) and inlet starvation (Hamrock & Dowson's meniscus factors).
//! Mixed lubrication is judged from the film parameter Λ ([`crate::calc::surface::roughness`]).
//! Plain formulas: the rooms decide when each applies.

/// `auto` applies the inlet-heating reduction when it thins the film by more than this fraction.
pub const THERMAL_THRESHOLD: f64 = 0.05;

/// Gupta et al.'s (1992) thermal loading parameter L = (−∂η/∂T) ū²/k_f, dimensionless, from the
/// viscosity's slope |∂η/∂T| (Pa·s/K), the mean speed ū (m/s) and the oil's conductivity k_f
/// (W/(m·K)).
pub fn thermal_loading(viscosity_slope: f64, speed_m_s: f64, conductivity_w_m_k: f64) -> f64 {
    viscosity_slope * speed_m_s.powi(2) / conductivity_w_m_k
}

/// Gupta et al. (1992) thermal reduction factor φ_T = [1 − 13.2 (p_h/E′) L^0.42] /
/// [1 + 0.213 (1 + 2.23 s^0.83) L^0.64], with `pressure_ratio` p_h/E′, `loading` L and the
/// slide-to-roll ratio s (Tribol. Trans. 35:269; the texts name inlet heating without a
/// formula: verify). Not positive where the correlation has no footing.
pub fn gupta_thermal_factor(pressure_ratio: f64, loading: f64, slide_roll_ratio: f64) -> f64 {
    let numerator = 1.0 - 13.2 * pressure_ratio * loading.powf(0.42);
    numerator / (1.0 + 0.213 * (1.0 + 2.23 * slide_roll_ratio.powf(0.83)) * loading.powf(0.64))
}

/// Hamrock & Dowson's (1977) fully-flooded inlet distance m̄*_c = 1 + 3.06 H^0.58 over the
/// semi-axis along the rolling direction, for the central film in the units H = h R_x/b²
/// (see [`starvation_factor`]).
pub fn fully_flooded_meniscus(film: f64) -> f64 {
    1.0 + 3.06 * film.powf(0.58)
}

/// Hamrock & Dowson's (1977) fully-flooded inlet distance for the minimum film,
/// m̄*_min = 1 + 3.34 H_min^0.56 (H_min in the units of [`fully_flooded_meniscus`]).
pub fn fully_flooded_meniscus_min(film: f64) -> f64 {
    1.0 + 3.34 * film.powf(0.56)
}

/// Hamrock & Dowson (1977, J. Lubr. Technol. 99:15, point contacts; not in the texts: verify):
/// with m̄ = m/b the meniscus distance over the Hertz semi-axis along the rolling direction,
/// a film is starved below its fully-flooded distance m̄* to [(m̄ − 1)/(m̄* − 1)]^exponent of
/// its flooded value (exponent 0.29 for the central film, 0.25 for the minimum); 1 at or
/// beyond m̄*.
pub fn starvation_factor(meniscus_ratio: f64, critical: f64, exponent: f64) -> f64 {
    if meniscus_ratio < critical {
        ((meniscus_ratio - 1.0) / (critical - 1.0)).powf(exponent)
    } else {
        1.0
    }
}
