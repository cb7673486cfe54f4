//! The lubricant inside an EHL conjunction, in the solver's dimensionless pressure P = p/p_h:
//! viscosity η̄ = η/η₀ (Barus or Roelands) and density ρ̄ = ρ/ρ₀ (Dowson–Higginson), each
//! with its slope in P for the Newton Jacobian.

use crate::calc::lubricant::model::{PressureLaw, ROELANDS_C_PA};

/// ln η̄ is capped here (η̄ ≈ 10⁸⁶): beyond it the film carries no Poiseuille flow at any grid
/// a solver can afford, and the cap keeps a Newton overshoot from overflowing.
const MAX_LN_VISCOSITY: f64 = 200.0;

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fluid {
    pub law: PressureLaw,
    /// η₀, the viscosity at the inlet temperature and ambient pressure, Pa·s.
    pub eta0_pa_s: f64,
    /// The Hertz pressure p_h that scales P, Pa.
    pub hertz_pressure_pa: f64,
    /// Whether the Dowson–Higginson density rise is applied (else ρ̄ = 1).
    pub compressible: bool,
}

impl Fluid {
    /// (ln η̄, d ln η̄/dP) at P ≥ 0. Barus: ln η̄ = αp (Khonsari eq. 2.9). Roelands (Khonsari
    /// eq. 2.10): log₁₀η + 1.2 = (log₁₀η₀ + 1.2)(1 + p/C)^Z, η in mPa·s, C = 196.1 MPa, so
    /// ln η̄ = ln 10 · (log₁₀η₀ + 1.2)[(1 + p/C)^Z − 1].
    pub fn ln_viscosity(&self, pressure: f64) -> (f64, f64) {
        let ph = self.hertz_pressure_pa;
        let p = pressure.max(0.0) * ph;
        let (value, slope) = match self.law {
            PressureLaw::Barus { alpha_1_pa } => (alpha_1_pa * p, alpha_1_pa * ph),
            PressureLaw::Roelands { z } => {
                let g0 = std::f64::consts::LN_10 * ((self.eta0_pa_s * 1e3).log10() + 1.2);
                let base = 1.0 + p / ROELANDS_C_PA;
                let power = base.powf(z);
                (
                    g0 * (power - 1.0),
                    g0 * z * power / base * ph / ROELANDS_C_PA,
                )
            }
        };
        if value > MAX_LN_VISCOSITY {
            (MAX_LN_VISCOSITY, 0.0)
        } else {
            (value, slope)
        }
    }

    /// (ρ̄, dρ̄/dP): Dowson–Higginson ρ̄ = 1 + 0.6p/(1 + 1.7p), p in GPa (Khonsari eq. 2.20), when
    /// compressible; else (1, 0).
    pub fn density(&self, pressure: f64) -> (f64, f64) {
        if !self.compressible {
            return (1.0, 0.0);
        }
        let scale = self.hertz_pressure_pa * 1e-9;
        let p = pressure.max(0.0) * scale;
        let denominator = 1.0 + 1.7 * p;
        (
            1.0 + 0.6 * p / denominator,
            0.6 / (denominator * denominator) * scale,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::calc::lubricant::model::dowson_higginson_density_ratio;

    fn fluid(law: PressureLaw) -> Fluid {
        Fluid {
            law,
            eta0_pa_s: 0.04,
            hertz_pressure_pa: 1.5e9,
            compressible: true,
        }
    }

    #[test]
    fn laws_agree_with_the_lubricant_model_and_their_slopes_with_differences() {
        for law in [
            PressureLaw::Barus { alpha_1_pa: 2e-8 },
            PressureLaw::Roelands { z: 0.6 },
        ] {
            let f = fluid(law);
            for &p in &[0.0, 0.1, 0.5, 1.0, 1.3] {
                let (ln_eta, slope) = f.ln_viscosity(p);
                let direct = law.viscosity_ratio(0.04, p * 1.5e9).ln();
                assert!(
                    (ln_eta - direct).abs() < 1e-9 * direct.abs().max(1.0),
                    "{law:?} {p}"
                );
                let h = 1e-6;
                let numeric = (f.ln_viscosity(p + h).0 - f.ln_viscosity(p).0) / h;
                assert!(
                    (slope - numeric).abs() < 1e-4 * slope.abs().max(1.0),
                    "{law:?} {p}"
                );
                let (rho, rho_slope) = f.density(p);
                assert!((rho - dowson_higginson_density_ratio(p * 1.5e9)).abs() < 1e-14);
                let numeric = (f.density(p + h).0 - rho) / h;
                assert!((rho_slope - numeric).abs() < 1e-5);
            }
        }
    }
}
