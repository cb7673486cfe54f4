//! The one solver driver: every iterative loop of the service runs under it.
//!
//! A room supplies only its physics — one iteration and its convergence criterion — as a
//! closure that returns a [`Verdict`]; the [`Driver`] owns everything else, so that every loop
//! has the same guarantees (DESIGN.md §5):
//! - an iteration cap that is never unbounded (a cap of 0 means "do not iterate", never "forever");
//! - the deadline: one carrier, [`Budget`], polled every `check_every` iterations, so a late or
//!   cancelled request stops computing;
//! - a typed [`StopReason`]: only [`StopReason::Converged`] yields a value;
//! - counted iterations (in a stated [`IterationUnit`]) and evaluations, the final residual and
//!   the elapsed time, written into the [`SolverReport`] the response carries.
//!
//! The pattern is argmin's executor (the solver gives `next_iter`, the executor owns the loop),
//! with three defaults inverted: the cap is finite, the deadline is checked inside long runs, and
//! a capped run is an error, not a result.

use std::sync::atomic::{AtomicBool, AtomicU32, Ordering};
use std::sync::Arc;
use std::time::Instant;

use crate::fidelity::{IterationUnit, Level, SolverReport, StopReason};

/// The deadline carrier numerics poll: the request's deadline and its cancel flag, and the tally
/// of the field solves it paid for. Cheap to clone (clones share the tally); `Context::budget`
/// hands one out.
#[derive(Debug, Clone)]
pub struct Budget {
    deadline: Option<Instant>,
    cancelled: Option<Arc<AtomicBool>>,
    field_solves: Arc<AtomicU32>,
}

impl Budget {
    /// Stop at `deadline` or when `cancelled` is set.
    pub fn new(deadline: Instant, cancelled: Arc<AtomicBool>) -> Self {
        Budget {
            deadline: Some(deadline),
            cancelled: Some(cancelled),
            field_solves: Arc::default(),
        }
    }

    /// No deadline (unit tests and benches of a kernel).
    pub fn unlimited() -> Self {
        Budget {
            deadline: None,
            cancelled: None,
            field_solves: Arc::default(),
        }
    }

    /// Counts one solve of a discretised field (a film's Reynolds equation on its grid).
    pub fn count_field_solve(&self) {
        self.field_solves.fetch_add(1, Ordering::Relaxed);
    }

    /// The field solves counted so far under this budget and its clones.
    pub fn field_solves(&self) -> u32 {
        self.field_solves.load(Ordering::Relaxed)
    }

    /// True when work expected to take `duration` would end before the deadline (always
    /// without one): a solver that may go on to a costlier step asks first.
    pub fn allows(&self, duration: std::time::Duration) -> bool {
        self.deadline.is_none_or(|d| Instant::now() + duration < d)
    }

    /// The time left before the deadline (None without one).
    pub fn remaining(&self) -> Option<std::time::Duration> {
        self.deadline
            .map(|d| d.saturating_duration_since(Instant::now()))
    }

    /// True while the request is neither late nor cancelled.
    pub fn alive(&self) -> bool {
        let cancelled = self
            .cancelled
            .as_ref()
            .is_some_and(|c| c.load(Ordering::Relaxed));
        let late = self.deadline.is_some_and(|d| Instant::now() >= d);
        !cancelled && !late
    }
}

/// What one iteration found.
#[derive(Debug, Clone, PartialEq)]
pub enum Verdict<T> {
    /// Not there yet; the residual after this iteration.
    Continue(f64),
    /// The room's criterion is met: the value and the residual it was met with.
    Converged(T, f64),
    /// The iteration cannot make progress (a line search that finds no descent, a step that
    /// leaves the physical domain); the residual where it stuck.
    Stalled(f64),
    /// The iterate blew up (the residual may be non-finite).
    Diverged(f64),
}

/// A run that ended without a value: why, and what it did (the report's `stop_reason` says
/// which of cap, deadline, stall or divergence).
#[derive(Debug, Clone, PartialEq)]
pub struct Stopped {
    pub report: SolverReport,
}

impl Stopped {
    /// A search that converged by its own criterion but left the caller's unmet (a root found
    /// to the bracket's tolerance where the balance it stands for is not): stalled.
    pub fn stalled(report: SolverReport) -> Self {
        Stopped {
            report: SolverReport {
                stop_reason: StopReason::Stalled,
                ..report
            },
        }
    }

    pub fn reason(&self) -> StopReason {
        self.report.stop_reason
    }
}

/// A converged run: the value and the report.
#[derive(Debug, Clone, PartialEq)]
#[must_use]
pub struct Converged<T> {
    pub value: T,
    pub report: SolverReport,
}

/// Owns one iterative loop. Build it with the method's name, what one of its iterations is,
/// the cap and the budget; then [`Driver::run`] the iteration.
#[derive(Debug, Clone)]
pub struct Driver {
    method: String,
    unit: IterationUnit,
    max_iterations: u32,
    check_every: u32,
    budget: Budget,
}

/// The counts a running iteration may add to (evaluations of the physics beyond one per
/// iteration: trial points of a line search, film solves of an outer search).
#[derive(Debug, Default, Clone, Copy, PartialEq)]
pub struct Counter {
    /// Iterations completed before the current one.
    pub iterations: u32,
    pub evaluations: u32,
}

impl Counter {
    /// Count `n` evaluations of the physics.
    pub fn evaluated(&mut self, n: u32) {
        self.evaluations += n;
    }
}

impl Driver {
    /// A loop of at most `max_iterations` iterations of `unit`, stopped early when `budget`
    /// runs out (polled before every iteration; see [`Driver::check_every`]).
    pub fn new(
        method: impl Into<String>,
        unit: IterationUnit,
        max_iterations: u32,
        budget: &Budget,
    ) -> Self {
        Driver {
            method: method.into(),
            unit,
            max_iterations,
            check_every: 1,
            budget: budget.clone(),
        }
    }

    /// Poll the budget only before iterations whose 1-based number is a multiple of `n` (for
    /// loops whose iteration is cheaper than reading the clock).
    pub fn check_every(mut self, n: u32) -> Self {
        self.check_every = n.max(1);
        self
    }

    /// True while the budget is neither spent nor cancelled: an iteration made of several
    /// costly parts (a Newton step's line-search trials) asks between them, and stalls when it
    /// is not ([`Driver::run`] then reports the deadline).
    pub fn alive(&self) -> bool {
        self.budget.alive()
    }

    /// Run `iterate` until it converges, stalls or diverges, the cap is reached or the budget
    /// runs out. `iterate` receives the counter (iterations done so far, evaluations) and does
    /// one iteration. A non-finite residual is a divergence whatever the verdict says.
    pub fn run<T>(
        &self,
        mut iterate: impl FnMut(&mut Counter) -> Verdict<T>,
    ) -> Result<Converged<T>, Stopped> {
        let started = Instant::now();
        let mut counter = Counter::default();
        let mut residual = f64::NAN;
        let reason = loop {
            if counter.iterations >= self.max_iterations {
                break StopReason::IterationCap;
            }
            if (counter.iterations + 1).is_multiple_of(self.check_every) && !self.budget.alive() {
                break StopReason::Deadline;
            }
            let verdict = iterate(&mut counter);
            counter.iterations += 1;
            match verdict {
                Verdict::Continue(r) => {
                    residual = r;
                    if !r.is_finite() {
                        break StopReason::Diverged;
                    }
                }
                Verdict::Converged(value, r) => {
                    if !r.is_finite() {
                        residual = r;
                        break StopReason::Diverged;
                    }
                    let report = self.report(StopReason::Converged, counter, r, started);
                    return Ok(Converged { value, report });
                }
                Verdict::Stalled(r) => {
                    residual = r;
                    // An iteration that stalled on a spent budget was cut short by it (a
                    // factorisation that polls the budget gives up part-way): the deadline's.
                    break if self.budget.alive() {
                        StopReason::Stalled
                    } else {
                        StopReason::Deadline
                    };
                }
                Verdict::Diverged(r) => {
                    residual = r;
                    break StopReason::Diverged;
                }
            }
        };
        Err(Stopped {
            report: self.report(reason, counter, residual, started),
        })
    }

    /// The report of a start that already meets the criterion: converged in 0 iterations.
    pub fn converged_at_start<T>(&self, value: T, residual: f64) -> Converged<T> {
        Converged {
            value,
            report: self.report(
                StopReason::Converged,
                Counter::default(),
                residual,
                Instant::now(),
            ),
        }
    }

    fn report(
        &self,
        stop_reason: StopReason,
        counter: Counter,
        residual: f64,
        started: Instant,
    ) -> SolverReport {
        SolverReport {
            method: self.method.clone(),
            fidelity: Level::Standard,
            grid: None,
            iterations: counter.iterations,
            iterations_unit: self.unit,
            evaluations: (counter.evaluations > 0).then_some(counter.evaluations),
            stop_reason,
            residual: residual.is_finite().then_some(residual),
            error_estimate: None,
            film_solves: None,
            time_integration: None,
            elapsed_ms: started.elapsed().as_secs_f64() * 1e3,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn driver(cap: u32) -> Driver {
        Driver::new("halving", IterationUnit::Sweeps, cap, &Budget::unlimited())
    }

    #[test]
    fn a_budget_allows_work_that_ends_before_its_deadline() {
        use std::time::Duration;
        assert!(Budget::unlimited().allows(Duration::from_secs(1_000_000)));
        let budget = Budget::new(
            Instant::now() + Duration::from_secs(60),
            Arc::new(AtomicBool::new(false)),
        );
        assert!(budget.allows(Duration::from_secs(1)));
        assert!(!budget.allows(Duration::from_secs(120)));
        let left = budget.remaining().unwrap();
        assert!(left <= Duration::from_secs(60) && left > Duration::from_secs(59));
        assert_eq!(Budget::unlimited().remaining(), None);
    }

    #[test]
    fn counts_iterations_and_reports_convergence() {
        let mut x = 1.0f64;
        let run = driver(100)
            .run(|c| {
                c.evaluated(2);
                x *= 0.5;
                if x < 1e-3 {
                    Verdict::Converged(x, x)
                } else {
                    Verdict::Continue(x)
                }
            })
            .unwrap();
        // 2^-10 < 1e-3 ≤ 2^-9: ten halvings.
        assert_eq!(run.report.iterations, 10);
        assert_eq!(run.report.evaluations, Some(20));
        assert_eq!(run.report.stop_reason, StopReason::Converged);
        assert_eq!(run.report.residual, Some(2f64.powi(-10)));
        assert_eq!(run.report.iterations_unit, IterationUnit::Sweeps);
    }

    #[test]
    fn the_cap_is_an_error_with_the_last_residual() {
        let stopped = driver(3).run(|_| Verdict::<()>::Continue(0.5)).unwrap_err();
        assert_eq!(stopped.reason(), StopReason::IterationCap);
        assert_eq!(stopped.report.iterations, 3);
        assert_eq!(stopped.report.residual, Some(0.5));
    }

    #[test]
    fn a_cap_of_zero_does_not_iterate() {
        let mut calls = 0;
        let stopped = driver(0)
            .run(|_| {
                calls += 1;
                Verdict::<()>::Continue(1.0)
            })
            .unwrap_err();
        assert_eq!((calls, stopped.reason()), (0, StopReason::IterationCap));
    }

    #[test]
    fn non_finite_residuals_diverge_and_stalls_say_so() {
        let d = driver(10).run(|_| Verdict::<()>::Continue(f64::NAN));
        assert_eq!(d.unwrap_err().reason(), StopReason::Diverged);
        let d = driver(10).run(|_| Verdict::Converged((), f64::INFINITY));
        assert_eq!(d.unwrap_err().reason(), StopReason::Diverged);
        let s = driver(10).run(|_| Verdict::<()>::Stalled(0.1)).unwrap_err();
        assert_eq!((s.reason(), s.report.iterations), (StopReason::Stalled, 1));
    }

    #[test]
    fn a_passed_deadline_stops_before_the_next_check() {
        let budget = Budget::new(Instant::now(), Arc::new(AtomicBool::new(false)));
        let mut calls = 0;
        let stopped = Driver::new("late", IterationUnit::NewtonSteps, 100, &budget)
            .check_every(4)
            .run(|_| {
                calls += 1;
                Verdict::<()>::Continue(1.0)
            })
            .unwrap_err();
        assert_eq!(stopped.reason(), StopReason::Deadline);
        assert_eq!(calls, 3, "polled before the 4th iteration");
        let cancelled = Budget::new(
            Instant::now() + std::time::Duration::from_secs(60),
            Arc::new(AtomicBool::new(true)),
        );
        assert!(!cancelled.alive() && Budget::unlimited().alive());
    }

    /// An iteration that stalls once the budget is spent (a factorisation that gave up on it)
    /// stops for the deadline; with budget left a stall is a stall.
    #[test]
    fn a_stall_on_a_spent_budget_is_the_deadline() {
        let cancel = Arc::new(AtomicBool::new(false));
        let budget = Budget::new(
            Instant::now() + std::time::Duration::from_secs(60),
            cancel.clone(),
        );
        let d = Driver::new("cut", IterationUnit::NewtonSteps, 100, &budget);
        let stalled = d.run(|_| Verdict::<()>::Stalled(0.1)).unwrap_err();
        assert_eq!(stalled.reason(), StopReason::Stalled);
        let cut = d
            .run(|_| {
                cancel.store(true, std::sync::atomic::Ordering::Relaxed);
                Verdict::<()>::Stalled(0.1)
            })
            .unwrap_err();
        assert_eq!(
            (cut.reason(), cut.report.iterations),
            (StopReason::Deadline, 1)
        );
    }
}
