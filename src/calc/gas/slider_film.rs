//! A plane gas slider's film, dimensionless: the compressible Reynolds equation on the pad
//! (finite, or infinitely wide) and its performance, in Khonsari & Booser §11.3's scaling
//! (Table 11.3): X = x/B from the leading edge, H = h/h2, P = p/p_a, Λ = 6μUB/(p_a h2²),
//! W̄ = W/(p_a B L), F̄ = F h2/(μ U B L).

use super::method::{Mesh, Method};
use crate::calc::Budget;
use crate::fidelity::{Level, SolverReport};
use crate::numerics::driver::Stopped;
use crate::numerics::reynolds_gas::{self, graded, GasGrid, GasProblem, GasStopping};
use crate::numerics::richardson::{extrapolate, fine_error};

/// The film, dimensionless.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SliderFilm {
    /// H1 = h1/h2 ≥ 1.
    pub film_ratio: f64,
    /// Λ = 6μUB/(p_a h2²).
    pub bearing_number: f64,
    /// Kn = λ_a/h2 of the slip factor (0: continuum).
    pub knudsen_number: f64,
    /// L/B; `None` for an infinitely wide pad.
    pub width_ratio: Option<f64>,
}

/// The dimensionless performance.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SliderPerformance {
    /// W̄ = W/(p_a B L) = mean of P − 1 over the pad.
    pub load: f64,
    /// Centre of pressure, X from the leading edge.
    pub center_of_pressure: f64,
    /// F̄ on the runner (the moving surface), F h2/(μ U B L).
    pub friction_runner: f64,
    /// F̄ on the pad (stationary).
    pub friction_pad: f64,
    /// Peak P (absolute, over ambient).
    pub max_pressure: f64,
    /// Where the peak is, X from the leading edge.
    pub max_pressure_position: f64,
}

/// The cells of a level: along B, across the half of L (the infinitely wide pad: along only).
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

/// The grid: X graded toward the trailing edge so that its last cell is about 1/(2Λ) (the
/// boundary layer where P falls from about H1 to 1 is ~1/Λ thick); Y graded toward the side
/// edge, its first cell about 1/(3√Λ) (the side layer's thickness scales as Λ^−½).
pub fn grid(film: &SliderFilm, mesh: Mesh) -> GasGrid {
    let lambda = film.bearing_number.max(1.0);
    let x = graded(mesh.along, 0.5 / lambda, false);
    let y = match film.width_ratio {
        None => vec![0.0],
        Some(l_over_b) => {
            let half = 0.5 * l_over_b;
            let finest = (0.33 / lambda.sqrt()) / half;
            graded(mesh.across.max(2), finest, true)
                .into_iter()
                .map(|v| v * half)
                .collect()
        }
    };
    GasGrid {
        x,
        y,
        periodic: false,
    }
}

/// The half mesh of `fine`: every other node.
pub fn coarsen(fine: &GasGrid) -> GasGrid {
    let every_other = |v: &[f64]| -> Vec<f64> { v.iter().step_by(2).copied().collect() };
    GasGrid {
        x: every_other(&fine.x),
        y: if fine.y.len() == 1 {
            fine.y.clone()
        } else {
            every_other(&fine.y)
        },
        periodic: false,
    }
}

/// The film on one grid: the field and the performance.
#[derive(Debug, Clone)]
pub struct SliderSolve {
    pub grid: GasGrid,
    pub p: Vec<f64>,
    pub performance: SliderPerformance,
    pub report: SolverReport,
}

/// Solve the film on `grid`, by Newton from `start` when given.
pub fn solve_on(
    film: &SliderFilm,
    grid: GasGrid,
    start: Option<&[f64]>,
    budget: &Budget,
) -> Result<SliderSolve, Stopped> {
    let h1 = film.film_ratio;
    let problem = GasProblem::new(&grid, film.bearing_number, film.knudsen_number, |x, _| {
        h1 - (h1 - 1.0) * x
    });
    let solved = reynolds_gas::solve(&grid, &problem, start, GasStopping::default(), budget)?;
    let performance = performance(film, &grid, &solved.p);
    Ok(SliderSolve {
        grid,
        p: solved.p,
        performance,
        report: solved.report,
    })
}

/// W̄, X_cp, F̄ and the peak from a solved field. The friction uses the plane pad's identity
/// ∫H ∂P/∂X dX = (H1 − 1)∫(P − 1) dX (by parts, P = 1 at both edges), exact row by row, so
/// F̄ = ∫1/H dX ± 3(H1 − 1)W̄/Λ (+ runner, − pad; Table 11.3's correction terms for every Λ).
pub fn performance(film: &SliderFilm, grid: &GasGrid, p: &[f64]) -> SliderPerformance {
    let h1 = film.film_ratio;
    let (mut area, mut load, mut moment) = (0.0, 0.0, 0.0);
    let (mut max_p, mut max_x) = (f64::MIN, 0.0);
    for i in 0..=grid.nx() {
        for j in 0..grid.y.len() {
            let w = grid.weight(i, j);
            let gauge = p[grid.at(i, j)] - 1.0;
            area += w;
            load += w * gauge;
            moment += w * gauge * grid.x[i];
            if p[grid.at(i, j)] > max_p {
                max_p = p[grid.at(i, j)];
                max_x = grid.x[i];
            }
        }
    }
    let load = load / area;
    // ∫₀¹ dX/H = ln H1/(H1 − 1) (1 for a parallel film).
    let couette = if (h1 - 1.0).abs() < 1e-12 {
        1.0
    } else {
        h1.ln() / (h1 - 1.0)
    };
    let poiseuille = 3.0 * (h1 - 1.0) * load / film.bearing_number;
    SliderPerformance {
        load,
        center_of_pressure: if load.abs() > 0.0 {
            moment / (load * area)
        } else {
            0.5
        },
        friction_runner: couette + poiseuille,
        friction_pad: couette - poiseuille,
        max_pressure: max_p,
        max_pressure_position: max_x,
    }
}

/// The performance by `method`: on its mesh, and with Richardson also on the half mesh,
/// extrapolated.
#[derive(Debug, Clone)]
pub struct SliderEvaluated {
    pub performance: SliderPerformance,
    /// Relative error estimate of W̄ (a third of the two meshes' difference over W̄).
    pub error_estimate: Option<f64>,
    /// The fine solve (its field and report).
    pub fine: SliderSolve,
    /// Newton steps and line-search trials over both meshes.
    pub iterations: u32,
    pub evaluations: u32,
}

pub fn evaluate(
    film: &SliderFilm,
    method: Method,
    budget: &Budget,
) -> Result<SliderEvaluated, Stopped> {
    let fine_grid = grid(film, method.mesh);
    let Some(coarse_grid) = method.richardson.then(|| coarsen(&fine_grid)) else {
        let fine = solve_on(film, fine_grid, None, budget)?;
        let (iterations, evaluations) =
            (fine.report.iterations, fine.report.evaluations.unwrap_or(0));
        return Ok(SliderEvaluated {
            performance: fine.performance,
            error_estimate: None,
            fine,
            iterations,
            evaluations,
        });
    };
    // The half mesh first: its field, interpolated, starts the fine Newton.
    let coarse = solve_on(film, coarse_grid, None, budget)?;
    let start = reynolds_gas::prolong(&coarse.grid, &coarse.p, &fine_grid);
    let fine = solve_on(film, fine_grid, Some(&start), budget)?;
    let iterations = fine.report.iterations + coarse.report.iterations;
    let evaluations = fine.report.evaluations.unwrap_or(0) + coarse.report.evaluations.unwrap_or(0);
    let (c, f) = (coarse.performance, fine.performance);
    let x = |a: f64, b: f64| extrapolate(a, b);
    let performance = SliderPerformance {
        load: x(c.load, f.load),
        center_of_pressure: x(c.center_of_pressure, f.center_of_pressure),
        friction_runner: x(c.friction_runner, f.friction_runner),
        friction_pad: x(c.friction_pad, f.friction_pad),
        max_pressure: f.max_pressure,
        max_pressure_position: f.max_pressure_position,
    };
    let error_estimate =
        Some((fine_error(c.load, f.load) / performance.load).abs()).filter(|e| e.is_finite());
    Ok(SliderEvaluated {
        performance,
        error_estimate,
        fine,
        iterations,
        evaluations,
    })
}

#[cfg(test)]
#[path = "slider_film_tests.rs"]
mod tests;
