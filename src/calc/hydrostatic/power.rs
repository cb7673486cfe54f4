//! Where a hydrostatic pad's power goes: the pump (p_s Q/η_p, Khonsari & Booser Eq. 10.16), the
//! lands' shear (Couette, recess neglected: Eq. 10.14–10.15) and the oil's temperature rise
//! ΔT = E_total/(ρ c_p Q) (§10.3; Stachowiak & Batchelor §6.4 with ζ = H_f/H_p).

use super::geometry::Drag;
use super::point::Point;

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

/// The powers at `point` with film viscosity μ, pump efficiency η_p and volumetric heat
/// capacity ρ c_p (J/(m³·K)).
pub fn of(drag: Drag, point: &Point, mu: f64, motion: Motion, eta: f64, rho_cp: f64) -> Power {
    let pumping = point.supply * point.flow / eta;
    let (torque, force, friction) = match (drag, motion) {
        (Drag::Torque(c), Motion::Rotating { omega }) => {
            let t = mu * omega * c / point.film;
            (t, 0.0, t * omega)
        }
        (Drag::Force(c), Motion::Sliding { speed }) => {
            let f = mu * speed * c / point.film;
            (0.0, f, f * speed)
        }
        _ => (0.0, 0.0, 0.0),
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
