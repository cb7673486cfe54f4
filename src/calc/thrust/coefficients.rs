//! A pad's dimensionless performance in Khonsari & Booser Table 7.2's scaling (every number
//! per unit h2, the trailing-edge film): what the long pad's closed form and the numerical film
//! both produce.

use crate::numerics::richardson::extrapolate;

/// A pad's performance, dimensionless (B along the sliding direction, L across it).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Performance {
    /// W̄ = W h2²/(μ U B² L) (= K_h², Table 7.2).
    pub load: f64,
    /// F̄ = F h2/(μ U B L), the force on the runner (= K_f: E_p = K_f μ U² B L/h2).
    pub friction: f64,
    /// x̄_cp: the centre of pressure, a fraction of B from the leading edge.
    pub center_of_pressure: f64,
    /// P̄_max = p_max h2²/(μ U B).
    pub max_pressure: f64,
    /// Where the peak is, a fraction of B from the leading edge.
    pub max_pressure_position: f64,
    /// Q̄₁ = Q₁/(U L h2) through the leading edge (= K_q).
    pub inlet_flow: f64,
    /// Q̄_s through both side edges (= K_s).
    pub side_flow: f64,
    /// Q̄₂ through the trailing edge.
    pub outlet_flow: f64,
}

impl Performance {
    /// K_h = √W̄ (Eq. 7.5: h2 = K_h (μ U B/P_avg)^½).
    pub fn k_h(&self) -> f64 {
        self.load.sqrt()
    }

    /// Richardson's extrapolation of every number from `coarse` and this (fine) one; the
    /// peak's position stays the fine grid's.
    pub fn extrapolated(&self, coarse: &Performance) -> Performance {
        let e = |f: fn(&Performance) -> f64| extrapolate(f(coarse), f(self));
        Performance {
            load: e(|p| p.load),
            friction: e(|p| p.friction),
            center_of_pressure: e(|p| p.center_of_pressure),
            max_pressure: e(|p| p.max_pressure),
            max_pressure_position: self.max_pressure_position,
            inlet_flow: e(|p| p.inlet_flow),
            side_flow: e(|p| p.side_flow).max(0.0),
            outlet_flow: e(|p| p.outlet_flow),
        }
    }
}
