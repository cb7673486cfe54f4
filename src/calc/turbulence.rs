//! The turbulent film of the linearised (Ng–Pan, Constantinescu) theory, shared by every film
//! room: the pressure-flow factors that scale the Poiseuille conductances of the Reynolds
//! equation and the Couette shear factor, at the local film Reynolds number Re = ρ U h/μ
//! (Khonsari & Booser Eq. 6.26–6.31; Stachowiak & Batchelor §4.8):
//!
//! ```text
//! ∂x(G_x h³/μ ∂x p) + ∂y(G_y h³/μ ∂y p) = ½ U ∂x h,   τ = (h/2) ∂x p + G_f μ U/h,
//! 1/G_x = 12 + 0.0136 Re^0.90,   1/G_y = 12 + 0.0043 Re^0.96,   G_f = 1 + 0.0012 Re^0.94.
//! ```
//!
//! Laminar flow is G_x = G_y = 1/12, G_f = 1: every factor here is relative to it, so each is
//! exactly 1 at Re = 0.

/// Ng–Pan pressure-flow coefficients relative to laminar, 12 G_x and 12 G_y, at local Re
/// (1/G_x = 12 + 0.0136 Re^0.90, 1/G_y = 12 + 0.0043 Re^0.96; Khonsari & Booser Eq. 6.27).
pub fn turbulent_flow_factors(re: f64) -> (f64, f64) {
    (
        12.0 / (12.0 + 0.0136 * re.powf(0.90)),
        12.0 / (12.0 + 0.0043 * re.powf(0.96)),
    )
}

/// Ng–Pan Couette shear factor G_f = 1 + 0.0012 Re^0.94 (Khonsari & Booser Eq. 6.30).
pub fn turbulent_shear_factor(re: f64) -> f64 {
    1.0 + 0.0012 * re.powf(0.94)
}

/// Hydraulic drag on a surface moving past a wall at a gap, f = 0.016/Re^0.25 with Re = ρUh/μ
/// (Khonsari & Booser Eq. 7.18): the power loss per area is f (ρ U²/2) U (Eq. 7.17).
pub fn surface_drag_friction_factor(re: f64) -> f64 {
    0.016 / re.powf(0.25)
}

/// The turbulent friction factor of a thrust film, f = 0.026/Re^0.25 (Khonsari & Booser
/// Eq. 7.20, from Missana et al.'s tests; parasitic losses included, so above the 0.016 of
/// plain hydraulic drag, Eq. 7.18): the power loss per area is f (ρ U²/2) U (Eq. 7.17).
pub fn missana_friction_factor(re: f64) -> f64 {
    0.026 / re.powf(0.25)
}

/// A film's flow regime, for films scaled by a reference thickness h_ref (h̄ = h/h_ref).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum Flow {
    /// Laminar: every factor 1.
    #[default]
    Laminar,
    /// Turbulent (Ng–Pan), the local Re = Re_ref h̄ with Re_ref = ρ U h_ref/μ.
    Turbulent { reference_reynolds: f64 },
}

impl Flow {
    /// (12 G_x, 12 G_y) where the film is h̄ thick.
    pub fn pressure_factors(self, h: f64) -> (f64, f64) {
        match self {
            Flow::Laminar => (1.0, 1.0),
            Flow::Turbulent { reference_reynolds } => {
                turbulent_flow_factors(reference_reynolds * h)
            }
        }
    }

    /// G_f where the film is h̄ thick.
    pub fn shear_factor(self, h: f64) -> f64 {
        match self {
            Flow::Laminar => 1.0,
            Flow::Turbulent { reference_reynolds } => {
                turbulent_shear_factor(reference_reynolds * h)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn missanas_friction_factor_is_eq_7_20() {
        // 0.026/Re^0.25: at Re = 10⁴ the fourth root is 10; it falls by √2 per fourfold Re.
        assert!((missana_friction_factor(1e4) - 0.0026).abs() < 1e-18);
        let ratio = missana_friction_factor(800.0) / missana_friction_factor(3200.0);
        assert!((ratio - 2f64.sqrt()).abs() < 1e-14);
    }

    #[test]
    fn every_factor_is_laminar_at_zero_reynolds_number() {
        assert_eq!(turbulent_flow_factors(0.0), (1.0, 1.0));
        assert_eq!(turbulent_shear_factor(0.0), 1.0);
        let zero = Flow::Turbulent {
            reference_reynolds: 0.0,
        };
        assert_eq!(
            zero.pressure_factors(2.0),
            Flow::Laminar.pressure_factors(2.0)
        );
        assert_eq!(zero.shear_factor(2.0), 1.0);
    }

    #[test]
    fn ng_pan_factors_at_a_thousand() {
        // Eq. 6.27 and 6.30 at Re = 1000: 12 G_x = 12/(12 + 0.0136·1000^0.9) = 0.63775,
        // 12 G_y = 12/(12 + 0.0043·1000^0.96) = 0.78627, G_f = 1 + 0.0012·1000^0.94 = 1.79283.
        let (gx, gy) = turbulent_flow_factors(1000.0);
        assert!((gx - 12.0 / (12.0 + 0.0136 * 1000f64.powf(0.9))).abs() < 1e-15);
        assert!((gx - 0.63775).abs() < 1e-5, "{gx}");
        assert!((gy - 0.78627).abs() < 1e-5, "{gy}");
        assert!((turbulent_shear_factor(1000.0) - 1.79283).abs() < 1e-5);
        let flow = Flow::Turbulent {
            reference_reynolds: 500.0,
        };
        assert_eq!(flow.pressure_factors(2.0), (gx, gy));
    }
}
