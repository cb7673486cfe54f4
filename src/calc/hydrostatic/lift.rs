//! Hydrostatic oil lift of a large journal bearing at start-up (Khonsari & Booser §10.8):
//! the breakaway pocket pressure (Elwell, Eq. 10.46), the lift flow that holds the journal at
//! a lift h (Fuller, Eq. 10.44) and the equilibrium feed pressure after lift (Eq. 10.45).
//! The texts print these in lbf, in and reyn; each is dimensionally consistent, so SI in gives
//! SI out (spec H-22 checked: Ex 10.4 reproduced in SI).

/// An oil-lift arrangement, SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lift {
    /// Bearing load W, N.
    pub load: f64,
    /// Bore D, m.
    pub diameter: f64,
    /// Bearing length L, m.
    pub length: f64,
    /// Radial clearance C, m.
    pub clearance: f64,
    /// Lift of the journal off the bottom h, m (< C).
    pub lift: f64,
    /// Pockets along the bottom line n.
    pub pockets: u32,
    /// Area of one pocket A, m².
    pub pocket_area: f64,
    /// Elwell's breakaway coefficient k_BA (experimental, typically 3).
    pub breakaway_coefficient: f64,
    /// B: the lift zone's axial length (pocket pattern + half the rest of the bearing), m.
    pub lift_zone_length: Option<f64>,
    /// μ, Pa·s.
    pub viscosity: f64,
}

/// What the lift needs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LiftResult {
    /// P_BA = k_BA W/(D n √A), Pa.
    pub breakaway_pressure: f64,
    /// ε = 1 − h/C.
    pub eccentricity_ratio: f64,
    /// Q = (W C/(6μ)) (C/R)² (1 − ε)²/(2 − ε), m³/s.
    pub flow: f64,
    /// Eq. 10.45, Pa (with B).
    pub equilibrium_pressure: Option<f64>,
    /// n A/(L D).
    pub pocket_area_fraction: f64,
}

pub fn lift(l: &Lift) -> LiftResult {
    let eps = 1.0 - l.lift / l.clearance;
    let r = 0.5 * l.diameter;
    let breakaway_pressure =
        l.breakaway_coefficient * l.load / (l.diameter * l.pockets as f64 * l.pocket_area.sqrt());
    let flow = l.load * l.clearance / (6.0 * l.viscosity)
        * (l.clearance / r).powi(2)
        * (1.0 - eps).powi(2)
        / (2.0 - eps);
    let equilibrium_pressure = l.lift_zone_length.map(|b| {
        let e2 = eps * eps;
        let s = (1.0 - e2).sqrt();
        let bracket = 0.5 * eps * (4.0 - e2) + (2.0 + e2) / (1.0 - e2) * ((1.0 + eps) / s).atan();
        2.0 * l.load / (b * l.diameter) * bracket / ((1.0 - e2) * (2.0 - eps))
    });
    LiftResult {
        breakaway_pressure,
        eccentricity_ratio: eps,
        flow,
        equilibrium_pressure,
        pocket_area_fraction: l.pockets as f64 * l.pocket_area / (l.length * l.diameter),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const IN: f64 = 0.0254;
    const LBF: f64 = 4.448_221_615_260_5;
    const PSI: f64 = 6_894.757_293_168_361;

    /// Ex 10.4 in SI (spec: P_BA = 2041.2 psi, ε = 0.6875, Q = 7.256 in³/s).
    #[test]
    fn example_10_4_in_si() {
        let l = Lift {
            load: 100_000.0 * LBF,
            diameter: 20.0 * IN,
            length: 18.0 * IN,
            clearance: 0.016 * IN,
            lift: 0.005 * IN,
            pockets: 3,
            pocket_area: 6.0 * IN * IN,
            breakaway_coefficient: 3.0,
            lift_zone_length: None,
            viscosity: 7e-6 * PSI,
        };
        let r = lift(&l);
        assert!((r.breakaway_pressure / PSI / 2041.2 - 1.0).abs() < 1e-4);
        assert!((r.eccentricity_ratio - 0.6875).abs() < 1e-12);
        assert!((r.flow / IN.powi(3) / 7.256 - 1.0).abs() < 1e-3);
        assert!(r.equilibrium_pressure.is_none());
    }

    /// Eq. 10.45 at ε → 0 is (2W/(BD))·(π/2)/2 = πW/(2BD); it rises with ε (less lift needs
    /// more pressure to hold the journal).
    #[test]
    fn equilibrium_pressure_limits() {
        let mut l = Lift {
            load: 1e5,
            diameter: 0.5,
            length: 0.45,
            clearance: 4e-4,
            lift: 4e-4 * (1.0 - 1e-9),
            pockets: 2,
            pocket_area: 4e-3,
            breakaway_coefficient: 3.0,
            lift_zone_length: Some(0.3),
            viscosity: 0.05,
        };
        let p0 = lift(&l).equilibrium_pressure.unwrap();
        let want = std::f64::consts::PI * l.load / (2.0 * 0.3 * l.diameter);
        assert!((p0 / want - 1.0).abs() < 1e-6, "{p0} vs {want}");
        let mut last = p0;
        for i in 1..10 {
            l.lift = 4e-4 * (1.0 - i as f64 / 10.0);
            let p = lift(&l).equilibrium_pressure.unwrap();
            assert!(p > last);
            last = p;
        }
    }
}
