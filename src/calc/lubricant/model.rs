//! The parsed lubricant: a viscosity–temperature law, an optional pressure–viscosity law, and
//! density and thermal properties. Every family that needs an oil takes this.

/// Viscosity against temperature at atmospheric pressure.
#[derive(Debug, Clone, PartialEq)]
pub enum TemperatureLaw {
    /// μ independent of temperature, Pa·s.
    Constant { viscosity_pa_s: f64 },
    /// Walther / ASTM D341 (Khonsari & Booser Eq. 2.3): log10 log10(ν + 0.7) = A − B·log10 T,
    /// ν in mm²/s (cSt), T in K. Fitted through two points.
    Walther { a: f64, b: f64 },
    /// Vogel (Stachowiak & Batchelor Table 2.1): μ = a·exp(b / (T − c)), T in K, μ in Pa·s.
    Vogel { a: f64, b: f64, c: f64 },
    /// Exponential (Reynolds) law (Khonsari & Booser Eq. 2.5): μ = μ_ref·exp(−β (T − T_ref)).
    Exponential {
        reference_viscosity_pa_s: f64,
        reference_temperature_c: f64,
        beta_1_k: f64,
    },
}

/// Viscosity against pressure at a fixed temperature.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PressureLaw {
    /// Barus (Khonsari & Booser Eq. 2.9): μ = μ0·exp(α p). α in 1/Pa.
    Barus { alpha_1_pa: f64 },
    /// Roelands (Khonsari & Booser Eq. 2.10): log10 μ + 1.2 = (log10 μ0 + 1.2)(1 + p/C)^Z,
    /// μ in mPa·s, C = 196.1 MPa.
    Roelands { z: f64 },
}

/// Where the thermal properties come from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Thermal {
    /// Petroleum-oil correlations (Khonsari & Booser Eq. 2.24, 2.25).
    PetroleumCorrelation,
    /// Constants given by the user.
    Given {
        specific_heat_j_kg_k: f64,
        thermal_conductivity_w_m_k: f64,
    },
}

/// A lubricant ready for physics.
#[derive(Debug, Clone, PartialEq)]
pub struct Lubricant {
    pub temperature_law: TemperatureLaw,
    pub pressure_law: Option<PressureLaw>,
    /// Density at 15 °C, kg/m³.
    pub density_15c_kg_m3: f64,
    pub thermal: Thermal,
    pub pour_point_c: Option<f64>,
    /// Assumptions made while parsing (defaults filled in), reported as warnings.
    pub assumptions: Vec<(&'static str, String)>,
}

/// Roelands' pressure constant C = 196.1 MPa (the 5.1e-9 1/Pa of the Houpert form is 1/C).
pub const ROELANDS_C_PA: f64 = 196.1e6;
/// Walther's additive constant in ASTM D341 for ν ≥ 2 mm²/s.
pub const WALTHER_OFFSET: f64 = 0.7;
/// Thermal expansion coefficient of the density law (Khonsari & Booser Eq. 2.19), 1/K.
pub const DENSITY_EXPANSION_1_K: f64 = 0.00063;

const KELVIN: f64 = 273.15;

impl TemperatureLaw {
    /// Walther constants through (T1, ν1) and (T2, ν2), T in °C, ν in mm²/s.
    pub fn walther_through(t1_c: f64, nu1: f64, t2_c: f64, nu2: f64) -> Self {
        let y = |nu: f64| (nu + WALTHER_OFFSET).log10().log10();
        let (x1, x2) = ((t1_c + KELVIN).log10(), (t2_c + KELVIN).log10());
        let b = (y(nu1) - y(nu2)) / (x2 - x1);
        let a = y(nu1) + b * x1;
        TemperatureLaw::Walther { a, b }
    }

    /// Vogel constants through three (T °C, μ Pa·s) points (Stachowiak & Batchelor App. A.2):
    /// c solves k2·c² + k1·c + k0 = 0; of the two roots the one with c below every Tᵢ and b > 0.
    /// None when the points admit no such fit (viscosity not falling with temperature, or
    /// points on an exponential, where Vogel degenerates).
    pub fn vogel_through(points: [(f64, f64); 3]) -> Option<Self> {
        let t: Vec<f64> = points.iter().map(|p| p.0 + KELVIN).collect();
        let y: Vec<f64> = points.iter().map(|p| p.1.ln()).collect();
        let (y12, y13) = (y[0] - y[1], y[0] - y[2]);
        let k2 = y12 * (t[2] - t[0]) - y13 * (t[1] - t[0]);
        let k1 = y12 * (t[0] - t[2]) * (t[1] + t[0]) + y13 * (t[1] - t[0]) * (t[0] + t[2]);
        let k0 = y12 * (t[2] - t[0]) * t[0] * t[1] - y13 * (t[1] - t[0]) * t[0] * t[2];
        let disc = k1 * k1 - 4.0 * k2 * k0;
        if k2 == 0.0 || disc.is_nan() || disc < 0.0 {
            return None;
        }
        let t_min = t.iter().cloned().fold(f64::INFINITY, f64::min);
        let roots = [
            (-k1 + disc.sqrt()) / (2.0 * k2),
            (-k1 - disc.sqrt()) / (2.0 * k2),
        ];
        roots.into_iter().find_map(|c| {
            let b = y12 * (t[0] * t[1] - c * (t[0] + t[1]) + c * c) / (t[1] - t[0]);
            let a = points[0].1 * (-b / (t[0] - c)).exp();
            let ok = c.is_finite() && c < t_min - 1e-9 && b > 0.0 && a > 0.0 && a.is_finite();
            ok.then_some(TemperatureLaw::Vogel { a, b, c })
        })
    }

    pub fn name(&self) -> &'static str {
        match self {
            TemperatureLaw::Constant { .. } => "constant",
            TemperatureLaw::Walther { .. } => "walther_astm_d341",
            TemperatureLaw::Vogel { .. } => "vogel",
            TemperatureLaw::Exponential { .. } => "exponential",
        }
    }
}

impl PressureLaw {
    /// μ(p)/μ0 at gauge pressure p (Pa), with μ0 in Pa·s the viscosity at p = 0.
    pub fn viscosity_ratio(self, mu0_pa_s: f64, p_pa: f64) -> f64 {
        match self {
            PressureLaw::Barus { alpha_1_pa } => (alpha_1_pa * p_pa).exp(),
            PressureLaw::Roelands { z } => {
                let g0 = (mu0_pa_s * 1e3).log10() + 1.2;
                let log_mu = g0 * (1.0 + p_pa / ROELANDS_C_PA).powf(z) - 1.2;
                10f64.powf(log_mu) / (mu0_pa_s * 1e3)
            }
        }
    }

    /// The pressure–viscosity coefficient α (1/Pa) the law implies at viscosity μ0: Barus' α;
    /// for Roelands the EHL coefficient of Khonsari & Booser Eq. 2.13,
    /// α = Z·5.1e-9·(ln μ0 + 9.67).
    pub fn alpha_1_pa(self, mu0_pa_s: f64) -> f64 {
        match self {
            PressureLaw::Barus { alpha_1_pa } => alpha_1_pa,
            PressureLaw::Roelands { z } => z / ROELANDS_C_PA * (mu0_pa_s.ln() + 9.67),
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            PressureLaw::Barus { .. } => "barus",
            PressureLaw::Roelands { .. } => "roelands",
        }
    }
}

impl Lubricant {
    /// Density at temperature t (°C) and atmospheric pressure, kg/m³ (Khonsari & Booser Eq. 2.19).
    pub fn density_kg_m3(&self, t_c: f64) -> f64 {
        self.density_15c_kg_m3 * (1.0 - DENSITY_EXPANSION_1_K * (t_c - 15.0))
    }

    /// Dynamic viscosity at temperature t (°C) and atmospheric pressure, Pa·s.
    pub fn viscosity_pa_s(&self, t_c: f64) -> f64 {
        let t_k = t_c + KELVIN;
        match self.temperature_law {
            TemperatureLaw::Constant { viscosity_pa_s } => viscosity_pa_s,
            TemperatureLaw::Walther { a, b } => {
                let nu = 10f64.powf(10f64.powf(a - b * t_k.log10())) - WALTHER_OFFSET;
                nu * 1e-6 * self.density_kg_m3(t_c)
            }
            TemperatureLaw::Vogel { a, b, c } => a * (b / (t_k - c)).exp(),
            TemperatureLaw::Exponential {
                reference_viscosity_pa_s,
                reference_temperature_c,
                beta_1_k,
            } => reference_viscosity_pa_s * (-beta_1_k * (t_c - reference_temperature_c)).exp(),
        }
    }

    /// Kinematic viscosity at temperature t (°C), mm²/s.
    pub fn kinematic_mm2_s(&self, t_c: f64) -> f64 {
        self.viscosity_pa_s(t_c) / self.density_kg_m3(t_c) * 1e6
    }

    /// Specific heat, J/(kg·K) (Khonsari & Booser Eq. 2.24: c_p = 1800 (1 + 0.002 T), T in °C).
    pub fn specific_heat_j_kg_k(&self, t_c: f64) -> f64 {
        match self.thermal {
            Thermal::PetroleumCorrelation => 1800.0 * (1.0 + 0.002 * t_c),
            Thermal::Given {
                specific_heat_j_kg_k,
                ..
            } => specific_heat_j_kg_k,
        }
    }

    /// Thermal conductivity, W/(m·K) (Khonsari & Booser Eq. 2.25: k = 0.1312 (1 − 6.3e-4 T)).
    pub fn thermal_conductivity_w_m_k(&self, t_c: f64) -> f64 {
        match self.thermal {
            Thermal::PetroleumCorrelation => 0.1312 * (1.0 - 6.3e-4 * t_c),
            Thermal::Given {
                thermal_conductivity_w_m_k,
                ..
            } => thermal_conductivity_w_m_k,
        }
    }
}

/// Density rise with pressure, ρ(p)/ρ0 (Dowson–Higginson; Khonsari & Booser Eq. 2.20):
/// 1 + 0.6 p / (1 + 1.7 p), p in GPa (gauge).
pub fn dowson_higginson_density_ratio(p_pa: f64) -> f64 {
    let p = p_pa * 1e-9;
    1.0 + 0.6 * p / (1.0 + 1.7 * p)
}

/// Roelands pressure–viscosity index from the 40 and 100 °C viscosities (Fein; Khonsari &
/// Booser Eq. 2.11): H = log10(log10 μ + 1.2), μ in mPa·s; Z = [7.81 (H40 − H100)]^1.5·(0.885 − 0.864 H40).
/// None where the formula leaves its domain (μ ≤ about 0.06 mPa·s or a viscosity rising with T).
pub fn roelands_z_fein(mu40_pa_s: f64, mu100_pa_s: f64) -> Option<f64> {
    let h = |mu: f64| ((mu * 1e3).log10() + 1.2).log10();
    let (h40, h100) = (h(mu40_pa_s), h(mu100_pa_s));
    let z = (7.81 * (h40 - h100)).powf(1.5) * (0.885 - 0.864 * h40);
    (z.is_finite() && z > 0.0).then_some(z)
}

/// Wooster's estimate of the Barus coefficient (Stachowiak & Batchelor §2.5):
/// α = (0.6 + 0.965 log10 μ0) × 1e-8 m²/N, μ0 in mPa·s.
pub fn wooster_alpha_1_pa(mu0_pa_s: f64) -> f64 {
    (0.6 + 0.965 * (mu0_pa_s * 1e3).log10()) * 1e-8
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ex_2_1_oil() -> Lubricant {
        Lubricant {
            temperature_law: TemperatureLaw::walther_through(40.0, 31.0, 100.0, 5.4),
            pressure_law: None,
            density_15c_kg_m3: 863.0,
            thermal: Thermal::PetroleumCorrelation,
            pour_point_c: None,
            assumptions: vec![],
        }
    }

    /// Khonsari & Booser Ex 2.1 (spec: A = 9.39796, B = 3.69501 with T = t + 273.1; ν65 = 12.793).
    #[test]
    fn walther_fit_reproduces_example_2_1() {
        let oil = ex_2_1_oil();
        let nu65 = oil.kinematic_mm2_s(65.0);
        assert!((nu65 / 12.793 - 1.0).abs() < 1e-3, "ν65 = {nu65}");
        assert!((oil.kinematic_mm2_s(40.0) - 31.0).abs() < 1e-9);
        assert!((oil.kinematic_mm2_s(100.0) - 5.4).abs() < 1e-9);
        // Densities (printed to 3 digits in g/cc).
        assert!((oil.density_kg_m3(65.0) - 836.0).abs() < 0.6);
        assert!((oil.density_kg_m3(40.0) - 850.0).abs() < 0.6);
        assert!((oil.density_kg_m3(100.0) - 817.0).abs() < 0.6);
        // μ65 = 10.697 cP.
        assert!((oil.viscosity_pa_s(65.0) / 10.697e-3 - 1.0).abs() < 2e-3);
    }

    /// Ex 2.1: Z = 0.680 from unrounded μ40, μ100; α_EHL at 65 °C = 1.781e-8 1/Pa.
    #[test]
    fn fein_z_and_ehl_alpha_reproduce_example_2_1() {
        let oil = ex_2_1_oil();
        let z = roelands_z_fein(oil.viscosity_pa_s(40.0), oil.viscosity_pa_s(100.0)).unwrap();
        assert!((z / 0.680 - 1.0).abs() < 0.01, "Z = {z}");
        let alpha = PressureLaw::Roelands { z }.alpha_1_pa(oil.viscosity_pa_s(65.0));
        assert!((alpha / 1.781e-8 - 1.0).abs() < 0.01, "α = {alpha}");
    }

    /// Stachowiak & Batchelor App. A.2 VISCOSITY example (spec R2.3):
    /// a = 1.658e-4 Pa·s, b = 692.13 K, c = 203.91 K.
    #[test]
    fn vogel_fit_reproduces_the_viscosity_program_example() {
        let law = TemperatureLaw::vogel_through([(100.0, 0.0099), (60.0, 0.0351), (20.0, 0.387)]);
        let Some(TemperatureLaw::Vogel { a, b, c }) = law else {
            panic!("no fit: {law:?}")
        };
        assert!((a / 1.658e-4 - 1.0).abs() < 2e-3, "a = {a}");
        assert!((b / 692.13 - 1.0).abs() < 1e-3, "b = {b}");
        assert!((c / 203.91 - 1.0).abs() < 1e-3, "c = {c}");
    }

    #[test]
    fn vogel_refuses_viscosity_rising_with_temperature() {
        assert!(
            TemperatureLaw::vogel_through([(20.0, 0.01), (60.0, 0.02), (100.0, 0.05)]).is_none()
        );
    }

    /// Roelands at p = 0 is the identity; both laws rise monotonically with pressure.
    #[test]
    fn pressure_laws_start_at_one_and_rise() {
        for law in [
            PressureLaw::Barus { alpha_1_pa: 2e-8 },
            PressureLaw::Roelands { z: 0.6 },
        ] {
            assert!((law.viscosity_ratio(0.03, 0.0) - 1.0).abs() < 1e-12);
            let mut last = 1.0;
            for i in 1..50 {
                let r = law.viscosity_ratio(0.03, i as f64 * 2e7);
                assert!(r > last);
                last = r;
            }
        }
    }

    /// Ex 2.1 remark (spec): Roelands at 1.4 GPa gives about 1.2e8 cP from μ65 = 10.7 cP, Z = 0.68.
    #[test]
    fn roelands_at_1_4_gpa_matches_the_spec_remark() {
        let ratio = PressureLaw::Roelands { z: 0.680 }.viscosity_ratio(10.697e-3, 1.4e9);
        let mu_cp = 10.697 * ratio;
        assert!((mu_cp / 1.2e8 - 1.0).abs() < 0.1, "μ = {mu_cp:e} cP");
    }

    #[test]
    fn dowson_higginson_limits() {
        assert_eq!(dowson_higginson_density_ratio(0.0), 1.0);
        // Asymptote 1 + 0.6/1.7 as p → ∞.
        assert!((dowson_higginson_density_ratio(1e15) - (1.0 + 0.6 / 1.7)).abs() < 1e-6);
    }
}
