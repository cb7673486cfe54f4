//! The numerical EHL room's solves (model): the line contact's Newton solves on nested grids,
//! refined with Richardson's estimate under [`refine`], and the point contact's multigrid with
//! its fall-back to coarser grids under the solver driver. Warnings are returned as data; the
//! reports are the drivers'.

use super::line::{LineProblem, LineSolution};
use super::point::{self, PointFailure, PointProblem, PointSolution};
use crate::calc::{Budget, CalcError, Warning};
use crate::fidelity::{IterationUnit, Level, SolverReport, StopReason};
use crate::numerics::driver::{Driver, Stopped, Verdict};
use crate::numerics::interpolate::linear;
use crate::numerics::refine::{refine, Judgement, RefineError, Refined};
use crate::numerics::richardson;

/// The grid every line solve starts on (from the Hertz pressure).
pub const FIRST_CELLS: usize = 32;

/// The line solver's grids.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cells {
    pub level: Level,
    /// The fine grid of the first pair.
    pub fine: usize,
    /// Refinement stops after this fine grid.
    pub finest: usize,
    /// Refine while the estimated relative error of the central film exceeds this.
    pub tolerance: f64,
}

/// The line contact's result: the fine grid's field, the Richardson-extrapolated films, the
/// report (Newton steps over every grid solved up to the fine one) and the warnings.
pub struct Nested {
    pub fine: LineSolution,
    pub central: f64,
    pub min: f64,
    pub report: SolverReport,
    pub warnings: Vec<Warning>,
}

/// A solve on one grid with the Newton steps and trial evaluations of every solve before it
/// in the chain of starts (cumulative).
#[derive(Clone)]
struct Solved {
    solution: LineSolution,
    steps: u32,
    evaluations: u32,
}

impl Solved {
    /// The fine solve's report, counting the Newton steps and evaluations of every grid.
    fn report(&self) -> SolverReport {
        self.solution
            .report
            .clone()
            .counting(self.steps, self.evaluations)
    }
}

/// The central (at X = 0) and the smallest film of a line solution.
fn films(s: &LineSolution) -> (f64, f64) {
    let central = linear(&s.x, &s.film, 0.0);
    let min = s.film.iter().copied().fold(f64::INFINITY, f64::min);
    (central, min)
}

/// The Richardson-extrapolated central and minimum films of a pair, whether the pair resolves
/// the film, and the fine grid's estimated relative error of the central film.
fn extrapolate(coarse: &LineSolution, fine: &LineSolution) -> (f64, f64, bool, f64) {
    let (c0, m0) = films(coarse);
    let (c1, m1) = films(fine);
    let central = richardson::extrapolate(c0, c1);
    let min = richardson::extrapolate(m0, m1);
    let error = (richardson::fine_error(c0, c1) / central).abs();
    let resolved = central > 0.0 && min > 0.0 && m1 > 0.0;
    (central, min, resolved, error)
}

/// A line solve that stopped: the deadline, or a Newton solve that stalled (the 422 says so,
/// pointing at the load).
fn line_failure(stopped: &Stopped, cells: usize) -> CalcError {
    match stopped.reason() {
        StopReason::Deadline => CalcError::DeadlineExceeded,
        _ => {
            let iterations = stopped.report.iterations;
            let residual = stopped.report.residual.unwrap_or(f64::NAN);
            CalcError::impossible(
                "/load_n",
                format!("the Newton solve on {cells} cells stalled after {iterations} iterations with scaled residual {residual:.3e}: this load and speed are beyond the solver (try another fidelity)"),
            )
        }
    }
}

/// Solve on a coarse and a fine grid (the coarse solution starts the fine one), extrapolate the
/// films (second order: the observed ratio of successive differences is about 4), and refine
/// while the estimated error exceeds the level's tolerance, up to `cells.finest`.
///
/// Nested iteration leads up to the first pair's coarse grid: Newton started from the Hertz
/// pressure on a fine grid can stall where the same start converges on [`FIRST_CELLS`] cells and
/// each finer grid then starts within its basin.
pub fn solve_line(
    problem: &LineProblem,
    cells: Cells,
    budget: &Budget,
) -> Result<Nested, CalcError> {
    let solve = |n: usize, start: Option<&Solved>| -> Result<Solved, Stopped> {
        let solution = problem.solve(n, start.map(|s| &s.solution), budget)?;
        let (steps, evaluations) = start.map_or((0, 0), |s| (s.steps, s.evaluations));
        Ok(Solved {
            steps: steps + solution.report.iterations,
            evaluations: evaluations + solution.report.evaluations.unwrap_or(0),
            solution,
        })
    };
    let first = (cells.fine / 2).min(FIRST_CELLS);
    let mut coarse = solve(first, None).map_err(|s| line_failure(&s, first))?;
    // Doubling while the grid is below half the first fine grid (so an explicit fine grid that
    // is not a power-of-two multiple of the first starts from the next doubling above its half).
    let ladder = std::iter::successors(Some(first), |n| Some(2 * n))
        .take_while(|&n| n < cells.fine / 2)
        .map(|n| 2 * n);
    for n in ladder {
        coarse = solve(n, Some(&coarse)).map_err(|s| line_failure(&s, n))?;
    }
    // The ladder's grids are the fine cell counts; the start is labelled by half the first.
    let refined = refine(
        cells.fine / 2,
        coarse,
        cells.tolerance,
        |n| (2 * n <= cells.finest).then_some(2 * n),
        |n, start| solve(n, Some(start)),
        |coarse, fine| match extrapolate(&coarse.solution, &fine.solution) {
            (_, _, true, error) => Judgement::Resolved(error),
            _ => Judgement::Unresolved,
        },
    );
    let mut warnings = Vec::new();
    let (pair, error) = match refined {
        Ok(Refined::Converged { pair, error }) => (pair, error),
        Ok(Refined::GridLimited { pair, error }) => {
            if error > cells.tolerance {
                warnings.push(Warning {
                    code: "grid_limited",
                    message: format!("the central film's estimated error {:.2} % exceeds the level's {:.1} % on the finest grid tried ({} cells)", error * 100.0, cells.tolerance * 100.0, pair.grid),
                });
            }
            (pair, error)
        }
        Ok(Refined::FellBack {
            pair,
            error,
            failed_grid,
            failure,
        }) => {
            warnings.push(Warning {
                code: "grid_limited",
                message: format!("refining to {failed_grid} cells failed ({}); the result is the {}-cell solution, whose estimated error is {:.2} %", line_failure(&failure, failed_grid), pair.grid, error * 100.0),
            });
            (pair, error)
        }
        Err(RefineError::Failed { grid, failure }) => return Err(line_failure(&failure, grid)),
        Err(RefineError::Unresolved(pair)) => {
            let (c1, m1) = films(&pair.fine.solution);
            return Err(CalcError::impossible(
                "/load_n",
                format!("the film is not resolved on {} cells (central {c1:.3e}, minimum {m1:.3e} in units of b²/R_x): the load is too heavy for this grid; give a finer fidelity", pair.grid),
            ));
        }
        Err(RefineError::NoFinerGrid) => {
            return Err(CalcError::Internal(
                "the line solver's first fine grid exceeds its finest".to_owned(),
            ))
        }
    };
    let (central, min, ..) = extrapolate(&pair.coarse.solution, &pair.fine.solution);
    let report = pair
        .fine
        .report()
        .named("newton_finite_volume_richardson")
        .at(cells.level)
        .on_grid(vec![pair.grid as u32, 1])
        .with_error_estimate(Some(error));
    Ok(Nested {
        fine: pair.fine.solution,
        central,
        min,
        report,
        warnings,
    })
}

/// The point contact's result: the finest level's field, the Richardson-extrapolated central
/// and minimum films (H = hR_x/a²) with the minimum's Y, the report (the finest level's cycles,
/// with the estimated error) and the warnings.
pub struct PointRun {
    pub fine: PointSolution,
    pub central: f64,
    pub min: f64,
    pub min_y: f64,
    pub report: SolverReport,
    pub warnings: Vec<Warning>,
}

/// The point problem solved on `cells` per direction and the grid of half as many
/// ([`solve_levels`]), the films extrapolated, and the central film's error estimated:
/// Richardson's plus what the cycles left (a limit cycle's spread, or the last cycle's change),
/// weighted as in (4c₁ − c₀)/3; a warning when it exceeds `tolerance`.
pub fn solve_point(
    problem: &PointProblem,
    (level, cells, tolerance): (Level, usize, f64),
    budget: &Budget,
) -> Result<PointRun, CalcError> {
    let (mut solved, cells, mut warnings) = solve_levels(problem, cells, tolerance, budget)?;
    let fine = solved.pop().expect("the two finest levels");
    let coarse = solved.pop().expect("the two finest levels");
    let (c0, c1) = (coarse.central_film(), fine.central_film());
    let ((m0, ..), (m1, _, min_y)) = (coarse.min_film(), fine.min_film());
    let central = richardson::extrapolate(c0, c1);
    if !(c0 > 0.0 && c1 > 0.0 && m1 > 0.0 && central > 0.0) {
        return Err(CalcError::impossible(
            "/load_n",
            format!("the film is not resolved on {cells}² cells (central {c1:.3e}, minimum {m1:.3e} in units of a²/R_x): the load is too heavy for this grid; give a finer fidelity"),
        ));
    }
    // The minimum (a parabola's vertex between nodes) converges like the film, so it is
    // extrapolated too — unless the coarser grid closes it.
    let extrapolated = richardson::extrapolate(m0, m1);
    let min = if m0 > 0.0 && extrapolated > 0.0 {
        extrapolated
    } else {
        warnings.push(Warning {
            code: "min_film_not_extrapolated",
            message: format!("the minimum film closes on {}² cells, so the {cells}² cells' minimum is reported without Richardson's extrapolation: it may be off by tens of per cent; a higher fidelity resolves it", cells / 2),
        });
        m1
    };
    let discretisation = (richardson::fine_error(c0, c1) / central).abs();
    let cycles_left = (4.0 * fine.iteration_error + coarse.iteration_error) / 3.0;
    let error = discretisation + cycles_left;
    let report = fine
        .report
        .clone()
        .named("fas_multigrid_finite_difference_richardson")
        .at(level)
        .on_grid(vec![cells as u32, cells as u32])
        .with_error_estimate(Some(error));
    if error > tolerance {
        warnings.push(Warning {
            code: "grid_limited",
            message: format!("the central film's estimated error {:.2} % ({:.2} % the grid's, {:.2} % the cycles') exceeds the level's {:.1} % on {cells}² cells: the Hertz zone is thin for this grid; a higher fidelity resolves it", error * 100.0, discretisation * 100.0, cycles_left * 100.0, tolerance * 100.0),
        });
    }
    Ok(PointRun {
        fine,
        central,
        min,
        min_y,
        report,
        warnings,
    })
}

/// The point problem's two finest levels on `cells` per direction, or on half as many (and so
/// on, down to [`point::MIN_CELLS`]) when the finest level's cycles stall or diverge (strongly
/// piezoviscous contacts on fine grids). The attempts run under the solver driver (one
/// iteration: one whole multigrid solve; the deadline polled before each); the driver's report
/// is not the room's, which is the finest level's own. Returns the levels, the cells they
/// reached and the `grid_fallback` warning when they are not the requested ones.
fn solve_levels(
    problem: &PointProblem,
    cells: usize,
    tolerance: f64,
    budget: &Budget,
) -> Result<(Vec<PointSolution>, usize, Vec<Warning>), CalcError> {
    let mut cells = cells;
    let mut failed = Vec::new();
    let mut refusal = None;
    // cells, cells/2, …, MIN_CELLS: the last attempt refuses rather than falls back, so the cap
    // is never what stops the ladder.
    let attempts = (cells / point::MIN_CELLS).max(1).ilog2() + 1;
    let run = Driver::new(
        "multigrid_grid_fallback",
        IterationUnit::Evaluations,
        attempts,
        budget,
    )
    .run(|_| match problem.solve(cells, tolerance, budget) {
        Ok(solved) => Verdict::Converged(solved, 0.0),
        Err(PointFailure::NotConverged {
            residual,
            cycles,
            cells: stalled,
        }) if stalled == cells && cells / 2 >= point::MIN_CELLS => {
            failed.push(format!(
                "{cells}² cells (after {cycles} cycles, scaled residual {residual:.3e})"
            ));
            cells /= 2;
            Verdict::Continue(residual)
        }
        Err(failure) => {
            refusal = Some(failure);
            Verdict::Stalled(0.0)
        }
    });
    let solved = match (run, refusal) {
        (Ok(done), _) => done.value,
        (Err(_), Some(PointFailure::DeadlineExceeded)) => return Err(CalcError::DeadlineExceeded),
        (
            Err(_),
            Some(PointFailure::NotConverged {
                residual,
                cycles,
                cells,
            }),
        ) => {
            return Err(CalcError::impossible(
                "/load_n",
                format!("the multigrid cycles on {cells}² cells stalled or diverged after {cycles} cycles with scaled residual {residual:.3e}: this load and speed are beyond the point solver (try another fidelity)"),
            ))
        }
        (Err(stopped), None) => return Err(stopped.into()),
    };
    let mut warnings = Vec::new();
    if !failed.is_empty() {
        warnings.push(Warning {
            code: "grid_fallback",
            message: format!("the multigrid cycles stalled or diverged on {}; the result is the {cells}² cells' solution", failed.join(", ")),
        });
    }
    Ok((solved, cells, warnings))
}
