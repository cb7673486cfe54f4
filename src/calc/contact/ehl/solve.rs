//! The numerical EHL room's solves (model): the line contact's Newton solves on nested grids,
//! refined with Richardson's estimate under [`refine`], and the point contact's multigrid with
//! its fall-back to coarser grids under the solver driver and its step-up to finer ones while
//! the films' estimated errors exceed the level's tolerances. Warnings are returned as data; the
//! reports are the drivers'.

use super::corrections::fully_flooded_meniscus;
use super::line::{LineProblem, LineSolution};
use super::point::{self, Accuracy, PointFailure, PointProblem, PointSolution};
use crate::calc::{Budget, CalcError, Warning};
use crate::fidelity::{IterationUnit, Level, SolverReport, StopReason};
use crate::numerics::driver::{Driver, Stopped, Verdict};
use crate::numerics::interpolate::linear;
use crate::numerics::refine::{refine, Judgement, RefineError, Refined};
use crate::numerics::richardson;
use std::time::Instant;

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

/// The point solver's grids: the first, the finest a step-up may reach, and the relative errors
/// of the central and the minimum film above which the solve steps up to a grid twice as fine.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointGrids {
    pub level: Level,
    pub cells: usize,
    pub finest: usize,
    pub central_tolerance: f64,
    pub min_tolerance: f64,
    /// The domain's inlet and sides as a multiple of [`point::domain`]'s: 1 on the wire; the
    /// accuracy bench's independent reference widens it (see `numerical::point_reference`).
    pub domain_scale: f64,
}

impl PointGrids {
    /// The tolerances as the accuracy the levels' cycles are asked for.
    fn accuracy(&self) -> Accuracy {
        Accuracy {
            central: self.central_tolerance,
            min: self.min_tolerance,
        }
    }
}

/// The point contact's result: the finest level's field, the Richardson-extrapolated central
/// and minimum films (H = hR_x/a²) with the minimum's Y and their estimated relative errors, the
/// report (the finest level's cycles, with the larger estimate) and the warnings.
pub struct PointRun {
    pub fine: PointSolution,
    pub central: f64,
    pub min: f64,
    pub min_y: f64,
    pub central_error: f64,
    pub min_error: f64,
    pub report: SolverReport,
    pub warnings: Vec<Warning>,
}

/// The films' relative change when the domain is doubled away from the outlet
/// ([`PointProblem::doubled_domain`]): the boundary's P = 0 truncates the inlet's and the
/// sides' slowly decaying pressure. Measured at M = 20 and L = 10 (512² cells, inlet and sides
/// scaled together) the films are 0.7 % (central) and 1.2 % (minimum) thin on the problem's
/// domain, 0.1 % and 0.2 % on the doubled one, and within 0.02 % of converged on the tripled
/// one; at M = 100, 0.5 % and 0.8 %; at M = 1000 within the grid's error ([`HEAVY_MENISCUS`]).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
struct Truncation {
    central: f64,
    min: f64,
}

/// The truncation falls about as the domain's size to the power q = 2–3 (the measurements
/// above), so the doubling's change is 1 − 2^−q ≈ 0.82 of the whole: the films are corrected by
/// this multiple of it, and [`TRUNCATION_UNCERTAINTY`] of it joins their error estimates (the
/// spread of q, and the coarse grid the change is measured on).
const TRUNCATION_GAIN: f64 = 1.2;
const TRUNCATION_UNCERTAINTY: f64 = 0.35;
/// A level's film further than this from the finest level's is not resolved enough for its
/// truncation to be the finest's: it is not corrected (the minimum film in the side lobes of a
/// heavy load, 26 % off on 128² cells against 256² at M = 1000, gave a spurious +0.34 %).
/// Central films 5–14 % off on the level measured still give their truncation within about a
/// third (M = 100 and the ellipse at M = 200 on 64² cells, M = 1000 on 128²).
const UNRESOLVED: f64 = 0.15;
/// A contact whose fully flooded meniscus m* (from the first film guess) is this close to it
/// does not measure its truncation: a heavy load's pressure is confined near the Hertz zone.
/// At M = 1000, L = 10 (m* = 1.375) the truncation is within the grid's error: 2048² against
/// its doubled domain gives 0.16 % (h_c) and 0.00 % (h_min); a domain 1.5 times as wide on
/// 2048² cells 0.06 % and 0.23 %, against that solve's estimates of 0.13 % and 0.44 %.
const HEAVY_MENISCUS: f64 = 1.5;
/// A level asking 5 % or more of its films (fast's 10 %) does not measure the truncation, at
/// most about 1 % (see [`Truncation`]).
const TRUNCATION_NEGLIGIBLE: f64 = 0.05;

impl Truncation {
    /// The truncation of the solve whose levels are `solved` (coarsest first): the doubled
    /// domain solved on twice the cells of a level below the finest, whose nodes and spacing it
    /// shares, against that level's films. The second-finest level is tried first (the
    /// doubled domain then costs about what the finest level did), the next coarser, down to
    /// [`point::MIN_CELLS`], when the doubled domain's cycles stall; the reason when every one
    /// stalls. Not measured (zero) for a level whose tolerances are [`TRUNCATION_NEGLIGIBLE`]
    /// or more.
    fn measure(
        problem: &PointProblem,
        solved: &[PointSolution],
        accuracy: Accuracy,
        budget: &Budget,
    ) -> Result<Result<Truncation, String>, CalcError> {
        if accuracy.central.min(accuracy.min) >= TRUNCATION_NEGLIGIBLE {
            return Ok(Ok(Truncation::default()));
        }
        let cells_of = |level: &PointSolution| level.x.len() - 1;
        let mut stalled = Vec::new();
        let below_finest = &solved[..solved.len() - 1];
        for level in below_finest
            .iter()
            .rev()
            .filter(|l| cells_of(l) >= point::MIN_CELLS)
        {
            let cells = 2 * cells_of(level);
            let doubled = match problem.doubled_domain().solve(cells, accuracy, budget) {
                Ok(levels) => levels.into_iter().next_back().expect("a solve's levels"),
                Err(PointFailure::DeadlineExceeded) => return Err(CalcError::DeadlineExceeded),
                Err(PointFailure::NotConverged { cells, cycles, .. }) => {
                    stalled.push(format!("{cells}² cells after {cycles} cycles"));
                    continue;
                }
            };
            // A film the level does not resolve (off the finest level's by more than
            // UNRESOLVED) changes with the domain in ways the finest does not share.
            let change = |wide: f64, near: f64, finest: f64| {
                if wide > 0.0 && near > 0.0 && (near / finest - 1.0).abs() <= UNRESOLVED {
                    wide / near - 1.0
                } else {
                    0.0
                }
            };
            let finest = solved.last().expect("a solve's levels");
            return Ok(Ok(Truncation {
                central: change(
                    doubled.central_film(),
                    level.central_film(),
                    finest.central_film(),
                ),
                min: change(
                    doubled.min_film().0,
                    level.min_film().0,
                    finest.min_film().0,
                ),
            }));
        }
        Ok(Err(if stalled.is_empty() {
            format!(
                "no level below the finest has {} cells or more",
                point::MIN_CELLS
            )
        } else {
            format!(
                "the doubled domain's cycles stalled on {}",
                stalled.join(", ")
            )
        }))
    }
}

/// The films of one solve on `cells`² cells: extrapolated, with their estimated errors.
struct Films {
    cells: usize,
    central: f64,
    min: f64,
    min_y: f64,
    /// Relative errors of the films: the grid's (see [`film_error`]) plus what the cycles left.
    central_error: f64,
    min_error: f64,
    /// The central film's share of the grid, of the cycles and of the domain's truncation, for
    /// the warning.
    discretisation: f64,
    cycles_left: f64,
    truncation: f64,
    /// The minimum film's share of the domain's truncation.
    min_truncation: f64,
    /// The second-finest level closed the minimum film: it is the finest level's, not extrapolated.
    min_extrapolated: bool,
}

/// A film's estimated relative error on the finest level (of `films`, coarsest first), which
/// bounds that of the extrapolated `value`: with three levels the observed order's
/// ([`richardson::observed_order_error`]), with two Richardson's third of the difference; a
/// coarser film that closes (≤ 0) is not in the asymptotic range, so then first order (the
/// finest pair's whole difference). On a heavily loaded contact the minimum (in the outlet's
/// side lobes) converges at first order on coarse grids where the central film is already
/// second-order.
fn film_error(films: &[f64], value: f64) -> f64 {
    let n = films.len();
    let (middle, fine) = (films[n - 2], films[n - 1]);
    let error = match films.get(n.wrapping_sub(3)) {
        _ if middle <= 0.0 => (fine - middle).abs(),
        Some(&coarse) if coarse > 0.0 => {
            richardson::observed_order_error(coarse, middle, fine, 2.0).0
        }
        Some(_) => (fine - middle).abs(),
        None => richardson::fine_error(middle, fine).abs(),
    };
    error / value.abs()
}

impl Films {
    /// The films of the converged levels `solved` (coarsest first) on `cells`² cells, corrected
    /// for the domain's `truncation`, or the refusal when the finest level does not resolve
    /// them (a film closes).
    fn of(
        solved: &[PointSolution],
        cells: usize,
        truncation: Truncation,
    ) -> Result<Films, CalcError> {
        let central_films: Vec<f64> = solved.iter().map(PointSolution::central_film).collect();
        let mins: Vec<(f64, f64, f64)> = solved.iter().map(PointSolution::min_film).collect();
        let min_films: Vec<f64> = mins.iter().map(|m| m.0).collect();
        let n = solved.len();
        let (c0, c1) = (central_films[n - 2], central_films[n - 1]);
        let (m0, (m1, _, min_y)) = (min_films[n - 2], mins[n - 1]);
        let central = richardson::extrapolate(c0, c1);
        if !(c0 > 0.0 && c1 > 0.0 && m1 > 0.0 && central > 0.0) {
            return Err(CalcError::impossible(
                "/load_n",
                format!("the film is not resolved on {cells}² cells (central {c1:.3e}, minimum {m1:.3e} in units of a²/R_x): the load is too heavy for this grid; give a finer fidelity"),
            ));
        }
        // The minimum (a parabola's vertex between nodes) converges like the film, so it is
        // extrapolated too — unless the coarser level closes it.
        let extrapolated = richardson::extrapolate(m0, m1);
        let min_extrapolated = m0 > 0.0 && extrapolated > 0.0;
        let min = if min_extrapolated { extrapolated } else { m1 };
        let (coarse, fine) = (&solved[n - 2], &solved[n - 1]);
        // The extrapolated value (4f₁ − f₀)/3 carries the levels' iteration errors so weighted.
        let cycles_left = (4.0 * fine.iteration_error + coarse.iteration_error) / 3.0;
        let min_cycles_left = (4.0 * fine.min_iteration_error + coarse.min_iteration_error) / 3.0;
        let discretisation = film_error(&central_films, central);
        let domain = |change: f64| TRUNCATION_UNCERTAINTY * change.abs();
        Ok(Films {
            cells,
            central_error: discretisation + cycles_left + domain(truncation.central),
            min_error: film_error(&min_films, min) + min_cycles_left + domain(truncation.min),
            discretisation,
            cycles_left,
            truncation: domain(truncation.central),
            min_truncation: domain(truncation.min),
            central: central * (1.0 + TRUNCATION_GAIN * truncation.central),
            min: min * (1.0 + TRUNCATION_GAIN * truncation.min),
            min_y,
            min_extrapolated,
        })
    }

    fn within(&self, grids: &PointGrids) -> bool {
        self.central_error <= grids.central_tolerance && self.min_error <= grids.min_tolerance
    }
}

/// The point problem solved on `grids.cells` per direction with the coarser levels
/// ([`solve_levels`]), the films extrapolated and their errors estimated ([`Films`]); while an
/// estimate exceeds its tolerance (or a film closes) the solve steps up to a grid twice as
/// fine ([`PointProblem::step_up`]: only the new level is cycled), up to `grids.finest`, if the
/// budget allows the step (about four times the last solve's time): the warnings
/// `grid_stepped_up`, and `grid_limited` when the finest grid tried, or the deadline, leaves an
/// estimate above its tolerance.
pub fn solve_point(
    problem: &PointProblem,
    grids: PointGrids,
    budget: &Budget,
) -> Result<PointRun, CalcError> {
    let started = Instant::now();
    let (solved, cells, mut warnings) =
        solve_levels(problem, grids.cells, grids.accuracy(), budget)?;
    // The first solve's time, which a step-up's cost is judged by.
    let first_time = started.elapsed();
    // A widened domain (the accuracy bench's reference) is not corrected: its truncation is
    // below 0.02 %, and a doubled domain's coarse pair would only add its own error. Nor is a
    // heavily loaded contact's (see HEAVY_MENISCUS). The doubled domain costs about what the
    // first solve did: when the deadline does not leave that, the films go uncorrected.
    let measured = if grids.domain_scale != 1.0
        || fully_flooded_meniscus(problem.film_guess) <= HEAVY_MENISCUS
    {
        Ok(Truncation::default())
    } else if !budget.allows(first_time) {
        Err("the deadline leaves too little time for the doubled domain".to_owned())
    } else {
        Truncation::measure(problem, &solved, grids.accuracy(), budget)?
    };
    let truncation = measured.unwrap_or_else(|why| {
        warnings.push(Warning {
            code: "domain_truncation_unmeasured",
            message: format!("the domain's truncation could not be measured ({why}): the films are not corrected for it and may be up to 1 % thin"),
        });
        Truncation::default()
    });
    let first = cells;
    // A grid the first solve fell back from is not tried again.
    let finest = if cells < grids.cells {
        cells
    } else {
        grids.finest
    };
    let mut films = Films::of(&solved, cells, truncation);
    let mut levels = solved;
    let mut last_time = first_time;
    let first_errors = films.as_ref().ok().map(|f| (f.central_error, f.min_error));
    let mut cells = cells;
    // Why the step-up ended short of the tolerances, when it did.
    let mut limited_by = None;
    while !films.as_ref().is_ok_and(|f| f.within(&grids)) && 2 * cells <= finest {
        let next = 2 * cells;
        if !budget.allows(last_time.mul_f64(STEP_UP_COST)) {
            limited_by = Some(format!(
                "the deadline leaves too little time for {next}² cells"
            ));
            break;
        }
        let step = Instant::now();
        match problem.step_up(&levels, grids.accuracy(), budget) {
            Ok(level) => {
                // The last solve's two finest levels are the new one's coarser pair.
                levels.drain(..levels.len().saturating_sub(2));
                levels.push(level);
                films = Films::of(&levels, next, truncation);
                cells = next;
                last_time = step.elapsed();
            }
            Err(PointFailure::DeadlineExceeded) => return Err(CalcError::DeadlineExceeded),
            Err(PointFailure::NotConverged {
                residual, cycles, ..
            }) => {
                limited_by = Some(format!("the multigrid cycles on {next}² cells stalled or diverged after {cycles} cycles with scaled residual {residual:.3e}"));
                break;
            }
        }
    }
    let films = films?;
    if films.cells != first {
        let before = first_errors.map_or_else(
            || "a film closed".to_owned(),
            |(c, m)| {
                format!(
                    "the estimated errors were {:.2} % (central) and {:.2} % (minimum)",
                    c * 100.0,
                    m * 100.0
                )
            },
        );
        warnings.push(Warning {
            code: "grid_stepped_up",
            message: format!("on {first}² cells {before}, above the level's {:.1} % and {:.1} %: the solve stepped up to {}² cells", grids.central_tolerance * 100.0, grids.min_tolerance * 100.0, films.cells),
        });
    }
    if !films.min_extrapolated {
        warnings.push(Warning {
            code: "min_film_not_extrapolated",
            message: format!("the minimum film closes on {}² cells, so the {}² cells' minimum is reported without Richardson's extrapolation: it may be off by tens of per cent; a higher fidelity resolves it", films.cells / 2, films.cells),
        });
    }
    if !films.within(&grids) {
        // A finer grid does not reduce the domain's share.
        let remedy = if films.truncation >= 0.5 * grids.central_tolerance
            || films.min_truncation >= 0.5 * grids.min_tolerance
        {
            format!("the domain's truncation, which a finer grid does not reduce, takes {:.2} % (central) and {:.2} % (minimum) of them", films.truncation * 100.0, films.min_truncation * 100.0)
        } else {
            "the Hertz zone is thin for this grid; a higher fidelity resolves it".to_owned()
        };
        let why = limited_by.map_or_else(
            || format!("on {}² cells, the finest this level tries", films.cells),
            |why| format!("on {}² cells ({why})", films.cells),
        );
        warnings.push(Warning {
            code: "grid_limited",
            message: format!("the films' estimated errors, central {:.2} % ({:.2} % the grid's, {:.2} % the cycles', {:.2} % the domain's) and minimum {:.2} %, exceed the level's {:.1} % and {:.1} % {why}: {remedy}", films.central_error * 100.0, films.discretisation * 100.0, films.cycles_left * 100.0, films.truncation * 100.0, films.min_error * 100.0, grids.central_tolerance * 100.0, grids.min_tolerance * 100.0),
        });
    }
    let fine = levels.pop().expect("the two finest levels");
    let report = fine
        .report
        .clone()
        .named("fas_multigrid_finite_difference_richardson")
        .at(grids.level)
        .on_grid(vec![films.cells as u32, films.cells as u32])
        .with_error_estimate(Some(films.central_error.max(films.min_error)));
    Ok(PointRun {
        fine,
        central: films.central,
        min: films.min,
        min_y: films.min_y,
        central_error: films.central_error,
        min_error: films.min_error,
        report,
        warnings,
    })
}

/// A step up to a grid twice as fine costs about four times the last solve's finest level
/// (four times the nodes, about the same cycles), less than four times the whole last solve:
/// the step is taken only when the budget allows this multiple of the last solve.
const STEP_UP_COST: f64 = 4.5;

/// The point problem's two finest levels on `cells` per direction, or, when a level's cycles
/// stall or diverge (strongly piezoviscous contacts, or light loads, on fine grids), on the grid
/// half as fine as that level (and so on, down to [`point::MIN_CELLS`]). The attempts run
/// under the solver driver (one iteration: one whole multigrid solve; the deadline polled
/// before each); the driver's report is not the room's, which is the finest level's own. Returns the levels, the cells they
/// reached and the `grid_fallback` warning when they are not the requested ones.
fn solve_levels(
    problem: &PointProblem,
    cells: usize,
    accuracy: Accuracy,
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
    .run(|_| match problem.solve(cells, accuracy, budget) {
        Ok(solved) => Verdict::Converged(solved, 0.0),
        // A level that stalls stalls the same way as the finest of a coarser solve: the next
        // attempt's finest is the grid below it.
        Err(PointFailure::NotConverged {
            residual,
            cycles,
            cells: stalled,
        }) if stalled <= cells && stalled / 2 >= point::MIN_CELLS => {
            failed.push(format!(
                "{stalled}² cells (after {cycles} cycles, scaled residual {residual:.3e})"
            ));
            cells = stalled / 2;
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
