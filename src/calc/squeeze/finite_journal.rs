//! The finite journal squeezed without rotation, numerically (Khonsari & Booser §9.6, Figs
//! 9.13–9.16, Table 9.3; spec SQ-6): the film is the journal room's finite-volume Reynolds film
//! ([`crate::calc::journal::film`]) with the wedge off and the squeeze source on.
//!
//! With the journal still, the film equation is linear in the approach rate, and the Reynolds
//! condition's cavitated zone does not change when the rate is scaled: at fixed ε the load is
//! W = μ V L R³/C³ · W̄(ε), V = C dε/dt, with W̄ from one film solve at the rate Ȧ = dε/dτ = 1
//! (the film's pressure scale N_s is then the squeeze rate). Under a constant load the journal
//! closes at V(ε) = W C³/(μ L R³ W̄(ε)), so the squeeze time is the quadrature
//!
//! ```text
//! Δt = ∫ C dε / V(ε) = (μ L R³/(W C²)) ∫_{ε₁}^{ε₂} W̄(ε) dε
//! ```
//!
//! taken by adaptive Gauss–Kronrod (7–15) in s = −ln(1 − ε) (W̄ grows like (1 − ε)^{-3/2}
//! towards contact; in s the integrand W̄ (1 − ε) is smooth), one film solve per node: the
//! book's trapezoid march over a chart (Ex 9.4) with the chart replaced by the film and the
//! march by a quadrature whose error is estimated.

use std::cell::Cell;

use super::long_journal::FilmExtent;
use crate::calc::journal::cost;
use crate::calc::journal::film::{self, Film, FilmModel, Mesh};
use crate::calc::{Budget, CalcError};
use crate::fidelity::{Level, SolverReport};
use crate::numerics::quadrature::{self, IntegralError, Tolerance};
use crate::numerics::reynolds::Stopping;

/// The numerical settings of one request.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Numerical {
    pub level: Level,
    pub mesh: Mesh,
    /// Relative tolerance of the time quadrature.
    pub tolerance: f64,
}

impl Numerical {
    /// The mesh and quadrature tolerance of a fidelity level (or explicit ones): `fast` 48 × 6
    /// cells (circumferential × half-length) and 1e-3, `standard` 96 × 12 and 1e-4, `high`
    /// 192 × 24 and 1e-6, the axial cells multiplied by ⌈√(L/D)⌉ for a bearing longer than
    /// its diameter (a half-length of 2.5 D on 6 cells converged at a ratio of 2.8, not 4, and
    /// its three-mesh estimate fell short of its error).
    pub fn at(
        level: Level,
        mesh: Option<Mesh>,
        tolerance: Option<f64>,
        l_over_d: f64,
    ) -> Numerical {
        let (cells, axial, tol) = match level {
            Level::Fast => (48, 6, 1e-3),
            Level::High => (192, 24, 1e-6),
            _ => (96, 12, 1e-4),
        };
        // L/D is validated to at most 5; an invalid one (the request is refused anyway) must
        // not overflow the count.
        let l_over_d = if l_over_d.is_finite() {
            l_over_d.clamp(1.0, 5.0)
        } else {
            1.0
        };
        let longer = l_over_d.sqrt().ceil() as usize;
        Numerical {
            level,
            mesh: mesh.unwrap_or(Mesh {
                circumferential: cells,
                axial_half: axial * longer,
            }),
            tolerance: tolerance.unwrap_or(tol),
        }
    }
}

/// Film solves a squeeze takes at least: one Gauss–Kronrod panel's 15 nodes and the two ends.
const LEAST_SOLVES: usize = 17;

/// Sweep stopping the film solve takes; both squeeze films are direct solves that do not use it.
const FILM_STOP: Stopping = Stopping {
    tolerance: 1e-11,
    max_sweeps: 200_000,
};

/// Bisections the time quadrature may make (each 30 film solves).
const MAX_BISECTIONS: u32 = 40;
/// Panels the quadrature starts from when the path is asked for: the path has a point at
/// each panel end, at least every tenth of the way in s = −ln(1 − ε).
const PATH_PANELS: u32 = 10;

/// A squeeze from ε₁ to ε₂: ∫ W̄ dε, W̄ at both ends, and the path when asked for.
#[derive(Debug, Clone, PartialEq)]
pub struct FiniteSqueeze {
    /// ∫_{ε₁}^{ε₂} W̄ dε, dimensionless.
    pub load_integral: f64,
    pub load_initial: f64,
    pub load_final: f64,
    /// (ε, ∫_{ε₁}^{ε} W̄, W̄(ε)) at the quadrature's panel ends.
    pub path: Option<Vec<(f64, f64, f64)>>,
    /// The report: grid, panels, film solves, residual (the largest film residual), error
    /// estimate (quadrature + discretisation at ε₂, from three meshes).
    pub report: SolverReport,
}

/// W̄(ε) = W C³/(μ L R³ V) of the still, finite journal at L/D `l_over_d` on `mesh`, and the
/// film solve's residual.
pub fn load_coefficient(
    eps: f64,
    l_over_d: f64,
    extent: FilmExtent,
    mesh: Mesh,
    budget: &Budget,
) -> Result<(f64, f64), CalcError> {
    let squeezed = Film {
        cos_rate: 1.0,
        rotating: false,
        physics: FilmModel {
            cavitation: extent == FilmExtent::Cavitated,
            ..FilmModel::REYNOLDS
        },
        ..Film::steady(eps, l_over_d)
    };
    let (solution, _) = film::solve(squeezed, mesh, FILM_STOP, None, budget)?;
    Ok((
        solution.load_radial,
        solution.solved.report.residual.unwrap_or(0.0),
    ))
}

/// The squeeze from `eps1` to `eps2` (0 ≤ ε₁ < ε₂ < 1) by the quadrature of the module doc.
pub fn squeeze(
    eps1: f64,
    eps2: f64,
    l_over_d: f64,
    extent: FilmExtent,
    numerical: Numerical,
    with_path: bool,
    budget: &Budget,
) -> Result<FiniteSqueeze, CalcError> {
    let mesh = numerical.mesh;
    // A grid the deadline cannot pay for is refused before any solve: the quadrature's first
    // Gauss–Kronrod panel and the two ends take 17 solves on the mesh at least.
    let explicit = Numerical::at(numerical.level, None, None, l_over_d).mesh != mesh;
    let periodic = extent != FilmExtent::Cavitated;
    cost::check_solves(mesh, periodic, explicit, LEAST_SOLVES, budget)?;
    let worst_residual = Cell::new(0.0f64);
    let load = |eps: f64, m: Mesh| {
        load_coefficient(eps, l_over_d, extent, m, budget).map(|(w, r)| {
            worst_residual.set(worst_residual.get().max(r));
            w
        })
    };
    let to_eps = |s: f64| -(-s).exp_m1();
    let integral = quadrature::adaptive_gauss_kronrod(
        |s: f64| load(to_eps(s), mesh).map(|w| w * (-s).exp()),
        -(-eps1).ln_1p(),
        -(-eps2).ln_1p(),
        Tolerance {
            relative: numerical.tolerance,
            absolute: 0.0,
            max_bisections: MAX_BISECTIONS,
            initial_panels: if with_path { PATH_PANELS } else { 1 },
        },
        budget,
    )
    .map_err(|e| match e {
        IntegralError::Integrand(e) => e,
        IntegralError::Stopped(stopped) => CalcError::from(stopped),
    })?;
    let load_initial = load(eps1, mesh)?;
    let load_final = load(eps2, mesh)?;
    // Discretisation, at ε₂ (where the integrand is largest), second order: the half mesh's
    // difference |W̄_h − W̄_2h|/(r² − 1), guarded against an accidental agreement of the pair by
    // the quarter mesh's difference scaled to this mesh, |W̄_2h − W̄_4h|/((r² − 1) r²). A mesh
    // too coarse to halve twice (or to halve across the length) is compared with the next
    // finer one instead, (4/3)|W̄_h/2 − W̄_h|: its pair would miss the error it has.
    let mesh_error = if mesh.coarse().coarse().circumferential >= 12 && mesh.halves_exactly() {
        let (coarse, quarter) = (mesh.coarse(), mesh.coarse().coarse());
        let w2 = load(eps2, coarse)?;
        let w4 = load(eps2, quarter)?;
        let r2 = mesh.refinement_ratio().powi(2);
        ((load_final - w2) / (r2 - 1.0))
            .abs()
            .max(((w2 - w4) / ((r2 - 1.0) * r2)).abs())
            / load_final
    } else {
        let finer = Mesh {
            circumferential: 2 * mesh.circumferential,
            axial_half: 2 * mesh.axial_half,
        };
        4.0 / 3.0 * ((load(eps2, finer)? - load_final) / load_final).abs()
    };
    let path = if with_path {
        let mut points = vec![(eps1, 0.0, load_initial)];
        let mut sum = 0.0;
        let last = integral.panels.len().saturating_sub(1);
        for (k, &(_, b, value)) in integral.panels.iter().enumerate() {
            sum += value;
            let eps = if k == last { eps2 } else { to_eps(b) };
            let w = if k == last {
                load_final
            } else {
                load(eps, mesh)?
            };
            points.push((eps, sum, w));
        }
        Some(points)
    } else {
        None
    };
    let quadrature_error = integral.error / integral.value.abs();
    let report = SolverReport {
        method: "finite_volume_active_set_gauss_kronrod_time".to_owned(),
        ..integral.report
    }
    .at(numerical.level)
    .on_grid(vec![mesh.circumferential as u32, mesh.axial_half as u32])
    .with_residual(worst_residual.get())
    .with_error_estimate(Some(quadrature_error + mesh_error))
    .with_film_solves(budget.field_solves());
    Ok(FiniteSqueeze {
        load_integral: integral.value,
        load_initial,
        load_final,
        path,
        report,
    })
}
