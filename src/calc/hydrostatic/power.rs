//! Where a hydrostatic pad's power goes: the pump (p_s Q/η_p, Khonsari & Booser Eq. 10.16), the
//! lands' shear (Couette, recess neglected: Eq. 10.14–10.15) and the oil's temperature rise
//! ΔT = E_total/(ρ c_p Q) (§10.3; Stachowiak & Batchelor §6.4 with ζ = H_f/H_p). With
//! turbulence applied the shear stress is the larger of Couette's μU/h and the surface drag
//! f ρU²/2 with f = 0.016/Re^¼, Re = ρUh/μ (Eq. 7.17–7.18, as §7.11 recommends for a turbulent
//! film's power loss): they cross at Re = 625, within §7.11's transition of 580–800.

use std::f64::consts::PI;

use super::geometry::Drag;
use super::point::Point;
use crate::calc::turbulence::surface_drag_friction_factor;

/// How the runner moves over the lands.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Motion {
    Still,
    /// ω, rad/s (circular and annular pads).
    Rotating {
        omega: f64,
    },
    /// U, m/s (rectangular pads).
    Sliding {
        speed: f64,
    },
}

/// How the lands shear the oil.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shear {
    /// Couette, τ = μU/h.
    Laminar,
    /// The larger of Couette's stress and the surface drag's, ρ the film's mass density, kg/m³.
    Turbulent { rho: f64 },
}

/// The surface drag's stress f ρU²/2 (Eq. 7.17–7.18) at speed U over film h.
fn drag_stress(speed: f64, h: f64, mu: f64, rho: f64) -> f64 {
    surface_drag_friction_factor(rho * speed * h / mu) * 0.5 * rho * speed * speed
}

/// The lands' friction (torque, force) at film h and viscosity μ.
pub fn friction(drag: Drag, motion: Motion, h: f64, mu: f64, shear: Shear) -> (f64, f64) {
    match (drag, motion) {
        (Drag::Torque(rings), Motion::Rotating { omega }) => {
            let laminar =
                |ri: f64, ro: f64| PI * mu * omega * (ro.powi(4) - ri.powi(4)) / (2.0 * h);
            let torque = rings
                .iter()
                .map(|&(ri, ro)| match shear {
                    Shear::Laminar => laminar(ri, ro),
                    Shear::Turbulent { rho } => {
                        // Turbulent beyond r_s, where ρωrh/μ = 625 (0.016 Re^−¼ = 2/Re); there
                        // τ ∝ r^{7/4}, so ∫2πr²τ dr = 2π τ(ω r_o) r_o^{−7/4} (r_o^{19/4} − r^{19/4})·4/19.
                        let re_crossing = (2.0 / surface_drag_friction_factor(1.0)).powf(4.0 / 3.0);
                        let rs = (re_crossing * mu / (rho * omega * h)).clamp(ri, ro);
                        let tau = drag_stress(omega * ro, h, mu, rho);
                        laminar(ri, rs)
                            + 2.0 * PI * tau * ro.powf(-1.75) * (ro.powf(4.75) - rs.powf(4.75))
                                / 4.75
                    }
                })
                .sum();
            (torque, 0.0)
        }
        (Drag::Force(area), Motion::Sliding { speed }) => {
            let couette = mu * speed / h;
            let stress = match shear {
                Shear::Laminar => couette,
                Shear::Turbulent { rho } => couette.max(drag_stress(speed, h, mu, rho)),
            };
            (0.0, stress * area)
        }
        _ => (0.0, 0.0),
    }
}

/// The powers of one pad, SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Power {
    pub pumping: f64,
    pub friction_torque: f64,
    pub friction_force: f64,
    pub friction: f64,
    pub total: f64,
    pub temperature_rise: f64,
    /// ζ = friction power over pumping power.
    pub power_ratio: f64,
}

/// The powers at `point` with the lands' friction (torque, force), pump efficiency η_p and
/// volumetric heat capacity ρ c_p (J/(m³·K)).
pub fn of(
    (torque, force): (f64, f64),
    point: &Point,
    motion: Motion,
    eta: f64,
    rho_cp: f64,
) -> Power {
    let pumping = point.supply * point.flow / eta;
    let friction = match motion {
        Motion::Rotating { omega } => torque * omega,
        Motion::Sliding { speed } => force * speed,
        Motion::Still => 0.0,
    };
    let total = pumping + friction;
    Power {
        pumping,
        friction_torque: torque,
        friction_force: force,
        friction,
        total,
        temperature_rise: total / (rho_cp * point.flow),
        power_ratio: friction / pumping,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The turbulent torque against a fine midpoint rule of 2πr² max(μωr/h, f ρ(ωr)²/2) over
    /// lands that are laminar, mixed and turbulent; and the laminar law where Re < 625 throughout.
    #[test]
    fn turbulent_torque_integrates_the_larger_stress() {
        let (mu, rho, h) = (0.005, 850.0, 1e-4);
        let rings = [(0.02, 0.03), (0.05, 0.09)];
        for omega in [100.0, 600.0, 5000.0] {
            let motion = Motion::Rotating { omega };
            let (got, _) = friction(Drag::Torque(rings), motion, h, mu, Shear::Turbulent { rho });
            let n = 100_000;
            let want: f64 = rings
                .iter()
                .map(|&(ri, ro): &(f64, f64)| {
                    let dr = (ro - ri) / n as f64;
                    (0..n)
                        .map(|i| {
                            let r = ri + (i as f64 + 0.5) * dr;
                            let tau = (mu * omega * r / h).max(drag_stress(omega * r, h, mu, rho));
                            2.0 * PI * r * r * tau * dr
                        })
                        .sum::<f64>()
                })
                .sum();
            assert!((got / want - 1.0).abs() < 1e-8, "{omega}: {got} vs {want}");
            let (laminar, _) = friction(Drag::Torque(rings), motion, h, mu, Shear::Laminar);
            assert!(got >= laminar);
            if rho * omega * 0.09 * h / mu < 625.0 {
                assert!((got / laminar - 1.0).abs() < 1e-14, "{omega}");
            }
        }
    }

    /// Eq. 7.18 meets Couette's stress at Re = 625.
    #[test]
    fn surface_drag_meets_couette_at_625() {
        let (mu, rho, h) = (0.005, 850.0, 1e-4);
        let speed = 625.0 * mu / (rho * h);
        assert!((drag_stress(speed, h, mu, rho) / (mu * speed / h) - 1.0).abs() < 1e-14);
    }
}
