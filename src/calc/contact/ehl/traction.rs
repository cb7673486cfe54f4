//! Sliding traction of a converged EHL film: the shear stress τ(γ̇ = sū/h, η(p)) of a
//! Newtonian or Eyring fluid, optionally capped by a limiting shear stress γp (Stachowiak
//! §7.7, eq. 7.52), integrated over the pressurised film.

use super::fluid::Fluid;

/// The fluid's shear law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ShearLaw {
    /// τ = ηγ̇.
    Newtonian,
    /// τ = τ₀ asinh(ηγ̇/τ₀), with the Eyring stress τ₀ in Pa.
    Eyring { stress_pa: f64 },
}

/// A traction law: the shear law and an optional limiting shear coefficient γ (τ ≤ γp).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TractionLaw {
    pub shear: ShearLaw,
    pub limiting_shear_coefficient: Option<f64>,
}

/// The traction of a film.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Traction {
    /// ∫τ dA, N.
    pub force_n: f64,
    /// F_t/F.
    pub coefficient: f64,
    /// Share of the load carried where the limiting shear stress caps τ (0 without it).
    pub limited_load_fraction: f64,
}

/// Sliding traction ∫τ dA over the pressurised film, with the shear rate γ̇ = u_s/h (u_s the
/// sliding speed, m/s) and the local viscosity η(p); `load_n` the normal load. `cells` yields
/// (P, film in m, area in m²) per node.
pub fn traction(
    law: &TractionLaw,
    fluid: &Fluid,
    sliding_m_s: f64,
    load_n: f64,
    cells: impl Iterator<Item = (f64, f64, f64)>,
) -> Traction {
    let ph = fluid.hertz_pressure_pa;
    let mut force = 0.0;
    let (mut limited, mut pressurised) = (0.0, 0.0);
    for (p, h, area) in cells {
        if p <= 0.0 {
            continue;
        }
        let eta = fluid.eta0_pa_s * fluid.ln_viscosity(p).0.exp();
        let newtonian = eta * sliding_m_s / h.max(1e-12);
        let mut tau = match law.shear {
            ShearLaw::Eyring { stress_pa: t0 } => t0 * (newtonian / t0).asinh(),
            ShearLaw::Newtonian => newtonian,
        };
        pressurised += p * area;
        if let Some(gamma) = law.limiting_shear_coefficient {
            let cap = gamma * p * ph;
            if tau > cap {
                tau = cap;
                limited += p * area;
            }
        }
        force += tau * area;
    }
    Traction {
        force_n: force,
        coefficient: force / load_n,
        limited_load_fraction: if pressurised > 0.0 {
            limited / pressurised
        } else {
            0.0
        },
    }
}
