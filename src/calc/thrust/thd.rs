//! Jang & Khonsari's thermohydrodynamic temperatures of a plane fixed pad (Khonsari & Booser
//! §7.9, Eq. 7.15, Table 7.5): fits of full THD solutions for a pad of B/L = 1 with film
//! ratios a_s = h1/h2 from 1.25 to 3.25, in the temperature-rise parameters
//!
//! ```text
//! κ₁ = (α μ_i β U/(k B)) (B/s_h)²,   κ₂ = U (μ_i β/k)^½,   s_h = h1 − h2,
//! T̄_max = [a + b/κ₁ + c/κ₂^1.5]⁻¹,   T̄_mean = [a + b/κ₁ + c/κ₂²]⁻¹,   T̄ = β (T − T_i)
//! ```
//!
//! with α = k/(ρ c_p) the oil's thermal diffusivity, β its temperature–viscosity coefficient
//! (μ = μ_i e^{−β (T − T_i)}) and the constants a, b, c of the film ratio's region.

/// The film ratios the fits cover.
pub const RATIOS: (f64, f64) = (1.25, 3.25);
/// B/L the fits were made for, and how far from it they are still used (with a warning).
pub const ASPECT_SPREAD: (f64, f64) = (0.8, 1.25);

/// Table 7.5: (a, b, c) for T̄_max and for T̄_mean, by region of a_s (lower bounds 1.25, 1.75,
/// 2.25, 2.75).
const REGIONS: [(f64, [f64; 3], [f64; 3]); 4] = [
    (
        1.25,
        [0.24314, 0.69569, 1.94883],
        [1.03892, 4.63987, 3.03201],
    ),
    (
        1.75,
        [0.22144, 0.25883, 1.44159],
        [0.84089, 1.90308, 2.95531],
    ),
    (
        2.25,
        [0.21092, 0.15082, 1.26859],
        [0.76222, 1.21812, 3.07632],
    ),
    (
        2.75,
        [0.20586, 0.10500, 1.16447],
        [0.71834, 0.91341, 3.20380],
    ),
];

/// The dimensionless maximum and mean temperature rises (T̄_max, T̄_mean) at film ratio
/// `ratio` (inside [`RATIOS`]).
pub fn rises(ratio: f64, kappa_1: f64, kappa_2: f64) -> (f64, f64) {
    let (_, max, mean) = REGIONS
        .iter()
        .rev()
        .find(|(lower, _, _)| ratio >= *lower)
        .copied()
        .unwrap_or(REGIONS[0]);
    let t_max = 1.0 / (max[0] + max[1] / kappa_1 + max[2] / kappa_2.powf(1.5));
    let t_mean = 1.0 / (mean[0] + mean[1] / kappa_1 + mean[2] / (kappa_2 * kappa_2));
    (t_max, t_mean)
}

/// The oil and the pad the parameters need (SI units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Parameters {
    /// Thermal diffusivity α = k/(ρ c_p), m²/s.
    pub diffusivity_m2_s: f64,
    /// Thermal conductivity k, W/(m·K).
    pub conductivity_w_m_k: f64,
    /// Inlet viscosity μ_i, Pa·s.
    pub inlet_viscosity_pa_s: f64,
    /// β = −d ln μ/dT at the inlet, 1/K.
    pub beta_1_k: f64,
    pub speed_m_s: f64,
    pub breadth_m: f64,
}

impl Parameters {
    /// (κ₁, κ₂) for a pad of taper s_h = h1 − h2 (Eq. 7.15).
    pub fn kappas(&self, taper_m: f64) -> (f64, f64) {
        let p = self;
        let kappa_1 = p.diffusivity_m2_s * p.inlet_viscosity_pa_s * p.beta_1_k * p.speed_m_s
            / (p.conductivity_w_m_k * p.breadth_m)
            * (p.breadth_m / taper_m).powi(2);
        let kappa_2 =
            p.speed_m_s * (p.inlet_viscosity_pa_s * p.beta_1_k / p.conductivity_w_m_k).sqrt();
        (kappa_1, kappa_2)
    }

    /// The maximum and mean temperatures above the inlet, K, for taper s_h and film ratio a.
    pub fn temperature_rises(&self, taper_m: f64, ratio: f64) -> (f64, f64) {
        let (k1, k2) = self.kappas(taper_m);
        let (t_max, t_mean) = rises(ratio, k1, k2);
        (t_max / self.beta_1_k, t_mean / self.beta_1_k)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Khonsari & Booser Ex 7.5 (spec: recomputed κ₁ = 0.3395, κ₂ = 2.9033).
    fn example_7_5() -> Parameters {
        Parameters {
            diffusivity_m2_s: 0.9355e-7,
            conductivity_w_m_k: 0.13,
            inlet_viscosity_pa_s: 0.035,
            beta_1_k: 0.0337,
            speed_m_s: 30.48,
            breadth_m: 0.0762,
        }
    }

    #[test]
    fn example_7_5_parameters_and_temperatures() {
        let p = example_7_5();
        // m = s_h/B = 0.001.
        let taper = 0.001 * 0.0762;
        let (k1, k2) = p.kappas(taper);
        assert!((k1 / 0.3395 - 1.0).abs() < 1e-3, "κ₁ {k1}");
        assert!((k2 / 2.9033 - 1.0).abs() < 1e-4, "κ₂ {k2}");
        // Pass 1, region III (a_s = 2.685): T̄_max = 1.0970 (the book's 1.0977, spec).
        let (t_max, _) = rises(2.685, k1, k2);
        assert!((t_max - 1.0970).abs() < 5e-4, "{t_max}");
        // Pass 2, region IV (a = 2.872): T̄_max = 1.3324, T̄_mean = 0.2639; T_max = 82.8 °C,
        // T_mean = 51 °C from T_i = 43.3 °C.
        let (t_max, t_mean) = rises(2.872, k1, k2);
        assert!((t_max - 1.3324).abs() < 5e-4, "{t_max}");
        assert!((t_mean - 0.2639).abs() < 5e-4, "{t_mean}");
        let (rise_max, rise_mean) = p.temperature_rises(taper, 2.872);
        assert!((43.3 + rise_max - 82.8).abs() < 0.1);
        assert!((43.3 + rise_mean - 51.1).abs() < 0.1);
    }
}
