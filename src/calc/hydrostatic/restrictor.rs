//! Compensation: what feeds the recess. Constant flow (a pump per pad), a capillary
//! (Hagen–Poiseuille, Q = K_c Δp) or an orifice (Q = k_o √Δp), each given by its size or
//! designed from the recess-to-supply pressure ratio m = p_r/p_s (Khonsari & Booser §10.4–10.6;
//! Stachowiak & Batchelor §6.4).

use std::f64::consts::PI;

/// Which restrictor.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    ConstantFlow,
    Capillary,
    Orifice,
}

impl Kind {
    pub fn name(self) -> &'static str {
        match self {
            Kind::ConstantFlow => "constant_flow",
            Kind::Capillary => "capillary",
            Kind::Orifice => "orifice",
        }
    }

    /// The pressure ratio m = p_r/p_s that maximises the stiffness at a given supply pressure
    /// and film: ½ for a capillary (Eq. 10.27–10.28), 2 − √2 for an orifice (Eq. 10.34–10.35).
    /// The tests find both by maximising a numerical −dW/dh over the restrictor's size.
    pub fn optimum_ratio(self) -> Option<f64> {
        match self {
            Kind::ConstantFlow => None,
            Kind::Capillary => Some(0.5),
            Kind::Orifice => Some(2.0 - std::f64::consts::SQRT_2),
        }
    }

    /// K h/(3W): the stiffness at fixed supply pressure (fixed flow for constant flow) over the
    /// constant-flow stiffness 3W/h, at pressure ratio m: 1; 1 − m (Eq. 10.27); 2(1 − m)/(2 − m)
    /// (Eq. 10.34).
    pub fn stiffness_factor(self, m: f64) -> f64 {
        match self {
            Kind::ConstantFlow => 1.0,
            Kind::Capillary => 1.0 - m,
            Kind::Orifice => 2.0 * (1.0 - m) / (2.0 - m),
        }
    }
}

/// The restrictor's law at the oil's state in it: Q = g(Δp).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Law {
    /// No restrictor: p_s = p_r.
    Direct,
    /// Q = k Δp, k = π R_c⁴/(8 μ l_c) (Eq. 10.21–10.22), m³/(s·Pa).
    Linear(f64),
    /// Q = k √Δp, k = π R_o² C_D √(2/ρ) (Eq. 10.30, 10.32), m³/(s·Pa^½).
    Root(f64),
    /// A restrictor to be sized so that p_r = m p_s.
    Ratio(f64),
}

impl Law {
    /// Δp across the restrictor at flow Q (None for a ratio law, which needs p_r).
    pub fn drop(self, q: f64) -> Option<f64> {
        match self {
            Law::Direct => Some(0.0),
            Law::Linear(k) => Some(q / k),
            Law::Root(k) => Some((q / k).powi(2)),
            Law::Ratio(_) => None,
        }
    }
}

/// A capillary's conductance K_c = π R_c⁴/(8 μ l_c), m³/(s·Pa).
pub fn capillary_conductance(radius: f64, length: f64, mu: f64) -> f64 {
    PI * radius.powi(4) / (8.0 * mu * length)
}

/// The capillary length that gives conductance k: l_c = π R_c⁴/(8 μ K_c).
pub fn capillary_length(radius: f64, conductance: f64, mu: f64) -> f64 {
    PI * radius.powi(4) / (8.0 * mu * conductance)
}

/// An orifice's coefficient k_o = π R_o² C_D √(2/ρ), m³/(s·Pa^½).
pub fn orifice_coefficient(radius: f64, discharge_coefficient: f64, rho: f64) -> f64 {
    PI * radius * radius * discharge_coefficient * (2.0 / rho).sqrt()
}

/// The orifice radius passing Q at Δp: R_o = [Q/(π C_D √(2Δp/ρ))]^½.
pub fn orifice_radius(q: f64, drop: f64, discharge_coefficient: f64, rho: f64) -> f64 {
    (q / (PI * discharge_coefficient * (2.0 * drop / rho).sqrt())).sqrt()
}

/// Flow through a tube or hole of radius R: mean velocity Q/(πR²) and the Reynolds number
/// ρ U 2R/μ (with the mass density: spec H-8's unit trap).
pub fn bore_flow(q: f64, radius: f64, rho: f64, mu: f64) -> (f64, f64) {
    let u = q / (PI * radius * radius);
    (u, rho * u * 2.0 * radius / mu)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_invert() {
        let (mu, rho) = (0.05, 850.0);
        let k = capillary_conductance(7.62e-4, 0.4, mu);
        assert!((capillary_length(7.62e-4, k, mu) / 0.4 - 1.0).abs() < 1e-14);
        let ko = orifice_coefficient(3e-4, 0.6, rho);
        let q = ko * 2e6f64.sqrt();
        assert!((orifice_radius(q, 2e6, 0.6, rho) / 3e-4 - 1.0).abs() < 1e-14);
        assert!((Law::Root(ko).drop(q).unwrap() / 2e6 - 1.0).abs() < 1e-14);
    }

    #[test]
    fn stiffness_factors_at_the_optimum() {
        // Spec T3, T4: ½ and 2m(1 − m)/(2 − m) = 0.34315 of 3 p_s A_eff/h, i.e. 0.5 and 0.586 of 3W/h.
        let m = Kind::Orifice.optimum_ratio().unwrap();
        assert!((m * Kind::Orifice.stiffness_factor(m) - 0.343_146).abs() < 1e-6);
        assert!((Kind::Orifice.stiffness_factor(m) - 0.585_786).abs() < 1e-6);
        assert_eq!(Kind::Capillary.stiffness_factor(0.5), 0.5);
    }
}
