//! A plain (360°, full-film) gas journal bearing's film, dimensionless, in Khonsari & Booser
//! §11.3's scaling (Table 11.4): θ from the line of centres at the maximum film, positive with
//! rotation; y = z/R from a bearing end (ambient pressure) to the mid-plane (symmetry) at
//! y = L/D; H = h/C = 1 + ε cos θ; P = p/p_a absolute; Λ = 6μω(R/C)²/p_a.
//!
//! The film is periodic in θ and has no cavitation (a gas film keeps its sub-ambient pressures).
//! Its pressure level is fixed by the ambient ends: the infinitely long journal, periodic with no
//! ends, is singular (every P H = const is a Λ → ∞ solution), which is why the texts print two
//! different Λ → ∞ forms. The finite film fixes it: integrating the equation over θ and then y
//! from the mid-plane shows ∫ H³P² dθ = ∫ H³ dθ at every y, so the interior's P H = c has
//! c = √(1 + 1.5ε²) (Table 11.4), not the foil section's (1 + ε) (§11.7, P = 1 at the widest gap).

use super::method::{Mesh, Method};
use crate::calc::Budget;
use crate::fidelity::{Level, SolverReport};
use crate::numerics::driver::Stopped;
use crate::numerics::reynolds_gas::{self, graded, GasGrid, GasProblem, GasStopping};
use crate::numerics::richardson::{extrapolate, fine_error};
use std::f64::consts::{PI, TAU};

/// The film, dimensionless.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JournalFilm {
    /// ε = e/C, in [0, 1).
    pub eccentricity: f64,
    /// Λ = 6μω(R/C)²/p_a.
    pub bearing_number: f64,
    /// Kn = λ_a/C of the slip factor (0: continuum).
    pub knudsen_number: f64,
    /// L/D (the half-length in y = z/R).
    pub l_over_d: f64,
}

/// The dimensionless performance.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JournalPerformance {
    /// W̄1 = W₁/(p_a L D), along the line of centres (toward the maximum film).
    pub load_along: f64,
    /// W̄2, perpendicular to it, ahead in the direction of rotation.
    pub load_across: f64,
    /// F C/(2π μ U R L) on the journal (moving; 1 at ε = 0).
    pub friction_journal: f64,
    /// The same on the bearing (stationary).
    pub friction_bearing: f64,
    /// Peak P (absolute over ambient).
    pub max_pressure: f64,
    /// Where the peak is, θ in radians.
    pub max_pressure_angle: f64,
}

impl JournalPerformance {
    /// W̄ = W/(p_a L D).
    pub fn load(&self) -> f64 {
        self.load_along.hypot(self.load_across)
    }
    /// Attitude angle φ (load line to line of centres), radians.
    pub fn attitude(&self) -> f64 {
        self.load_across.atan2(self.load_along)
    }
}

/// The cells of a level: around the circumference, across the half-length.
pub fn level_mesh(level: Level) -> Mesh {
    match level {
        Level::Fast => Mesh {
            along: 32,
            across: 8,
        },
        Level::ClosedForm | Level::Standard => Mesh {
            along: 64,
            across: 12,
        },
        Level::High => Mesh {
            along: 128,
            across: 24,
        },
    }
}

/// The grid: θ uniform; y graded toward the bearing end so that its first cell is about
/// 1/(3√Λ) (the end layer's thickness scales as Λ^−½).
pub fn grid(film: &JournalFilm, mesh: Mesh) -> GasGrid {
    let w = film.l_over_d;
    let finest = 0.33 / film.bearing_number.max(1.0).sqrt();
    GasGrid {
        x: (0..=mesh.along)
            .map(|k| k as f64 * TAU / mesh.along as f64)
            .collect(),
        y: graded(mesh.across.max(2), finest / w, true)
            .into_iter()
            .map(|v| v * w)
            .collect(),
        periodic: true,
    }
}

/// The half mesh of `fine`: every other node.
pub fn coarsen(fine: &GasGrid) -> GasGrid {
    let every_other = |v: &[f64]| -> Vec<f64> { v.iter().step_by(2).copied().collect() };
    GasGrid {
        x: every_other(&fine.x),
        y: every_other(&fine.y),
        periodic: true,
    }
}

/// A film solved on one grid.
#[derive(Debug, Clone)]
pub struct JournalSolve {
    pub grid: GasGrid,
    pub p: Vec<f64>,
    pub performance: JournalPerformance,
    pub report: SolverReport,
}

/// The problem of `film` on `grid`.
pub fn problem(film: &JournalFilm, grid: &GasGrid) -> GasProblem {
    let e = film.eccentricity;
    GasProblem::new(grid, film.bearing_number, film.knudsen_number, |t, _| {
        1.0 + e * t.cos()
    })
}

/// Solve on `grid`, by Newton from `start` when given (a field on this grid near this film).
pub fn solve_on(
    film: &JournalFilm,
    grid: GasGrid,
    start: Option<&[f64]>,
    budget: &Budget,
) -> Result<JournalSolve, Stopped> {
    let problem = problem(film, &grid);
    let solved = reynolds_gas::solve(&grid, &problem, start, GasStopping::default(), budget)?;
    let performance = performance(film, &grid, &solved.p);
    Ok(JournalSolve {
        grid,
        p: solved.p,
        performance,
        report: solved.report,
    })
}

/// Loads, friction and the peak of a solved field. Over the half bearing modelled,
/// S_c = ∫∫(P − 1) cos θ dθ dy and S_s likewise with sin θ; W̄1 = −S_c/(2 L/D),
/// W̄2 = S_s/(2 L/D). The journal's friction F̄ = ⟨1/H⟩ + (3ε/Λ) W̄2/π, ⟨1/H⟩ = 1/√(1 − ε²) (by
/// parts: ∫H ∂θP dθ = ε∫(P − 1) sin θ dθ); the bearing's has the pressure term's other sign.
pub fn performance(film: &JournalFilm, grid: &GasGrid, p: &[f64]) -> JournalPerformance {
    let (mut sc, mut ss) = (0.0, 0.0);
    let (mut max_p, mut max_t) = (f64::MIN, 0.0);
    for i in 0..grid.nx() {
        let (s, c) = grid.x[i].sin_cos();
        for j in 0..grid.y.len() {
            let w = grid.weight(i, j);
            let g = p[grid.at(i, j)] - 1.0;
            sc += w * g * c;
            ss += w * g * s;
            if p[grid.at(i, j)] > max_p {
                max_p = p[grid.at(i, j)];
                max_t = grid.x[i];
            }
        }
    }
    let w = film.l_over_d;
    let (along, across) = (-sc / (2.0 * w), ss / (2.0 * w));
    let e = film.eccentricity;
    let couette = 1.0 / (1.0 - e * e).sqrt();
    let poiseuille = 3.0 * e / film.bearing_number * across / PI;
    JournalPerformance {
        load_along: along,
        load_across: across,
        friction_journal: couette + poiseuille,
        friction_bearing: couette - poiseuille,
        max_pressure: max_p,
        max_pressure_angle: max_t,
    }
}

/// The performance by a method: the mesh, and with Richardson the half mesh, extrapolated.
#[derive(Debug, Clone)]
pub struct JournalEvaluated {
    /// ε of the film solved.
    pub eccentricity: f64,
    pub performance: JournalPerformance,
    /// Relative error estimate of W̄.
    pub error_estimate: Option<f64>,
    pub fine: JournalSolve,
    pub coarse: Option<JournalSolve>,
    /// Newton steps and line-search trials over both meshes.
    pub iterations: u32,
    pub evaluations: u32,
}

/// Solve `film` by `method`, starting Newton from `warm` (an earlier evaluation at a nearby
/// eccentricity and the same Λ and grid) when given.
pub fn evaluate(
    film: &JournalFilm,
    method: Method,
    warm: Option<&JournalEvaluated>,
    budget: &Budget,
) -> Result<JournalEvaluated, Stopped> {
    let fine_grid = grid(film, method.mesh);
    let Some(coarse_grid) = method.richardson.then(|| coarsen(&fine_grid)) else {
        let fine = solve_on(film, fine_grid, warm.map(|w| w.fine.p.as_slice()), budget)?;
        let (iterations, evaluations) =
            (fine.report.iterations, fine.report.evaluations.unwrap_or(0));
        return Ok(JournalEvaluated {
            eccentricity: film.eccentricity,
            performance: fine.performance,
            error_estimate: None,
            fine,
            coarse: None,
            iterations,
            evaluations,
        });
    };
    // The half mesh first (from the warm start's, if any); its field, interpolated, starts the
    // fine Newton unless a warm fine field is at hand.
    let coarse = solve_on(
        film,
        coarse_grid,
        warm.and_then(|w| w.coarse.as_ref()).map(|c| c.p.as_slice()),
        budget,
    )?;
    let start = match warm {
        Some(w) => w.fine.p.clone(),
        None => reynolds_gas::prolong(&coarse.grid, &coarse.p, &fine_grid),
    };
    let fine = solve_on(film, fine_grid, Some(&start), budget)?;
    let iterations = fine.report.iterations + coarse.report.iterations;
    let evaluations = fine.report.evaluations.unwrap_or(0) + coarse.report.evaluations.unwrap_or(0);
    let (c, f) = (coarse.performance, fine.performance);
    let performance = JournalPerformance {
        load_along: extrapolate(c.load_along, f.load_along),
        load_across: extrapolate(c.load_across, f.load_across),
        friction_journal: extrapolate(c.friction_journal, f.friction_journal),
        friction_bearing: extrapolate(c.friction_bearing, f.friction_bearing),
        max_pressure: f.max_pressure,
        max_pressure_angle: f.max_pressure_angle,
    };
    let error_estimate = Some((fine_error(c.load(), f.load()) / performance.load()).abs());
    Ok(JournalEvaluated {
        eccentricity: film.eccentricity,
        performance,
        error_estimate,
        fine,
        coarse: Some(coarse),
        iterations,
        evaluations,
    })
}

#[cfg(test)]
#[path = "journal_film_tests.rs"]
pub(crate) mod tests;
