//! Damped Newton with a backtracking line search, under the solver driver.
//!
//! Each iteration asks the system for its Newton direction at the current point, then halves
//! the step `t = 1, ½, ¼, …` (at most `max_halvings` times) until the system accepts the trial
//! point. What counts as acceptance is the system's: Armijo's sufficient decrease of an energy
//! (Nocedal & Wright, *Numerical Optimization*, 2nd ed., §3.1, with c₁ = 10⁻⁴), a fall of the
//! residual norm, or both. A direction that does not descend, a singular system or a line
//! search that finds no acceptable point stalls the iteration; the driver then answers with the
//! report. Convergence is the residual at or below `tolerance` (tested on the start point too:
//! a start that already balances takes no step).

use super::driver::{Converged, Driver, Stopped, Verdict};

/// A nonlinear system for [`solve`]: the rooms supply the physics, this module the iteration.
pub trait NewtonSystem {
    /// The unknowns.
    type Point: Clone;
    /// What one evaluation at a point gives (residual vector, energy, Jacobian blocks…).
    type Eval;
    /// A Newton direction.
    type Step;

    fn evaluate(&self, x: &Self::Point) -> Self::Eval;
    /// The scalar convergence measure of an evaluation (a scaled norm of the residual).
    fn residual(&self, at: &Self::Eval) -> f64;
    /// The Newton direction at `x`; `None` when the linear system is singular or its solution
    /// not finite.
    fn direction(&self, x: &Self::Point, at: &Self::Eval) -> Option<Self::Step>;
    /// The directional derivative of the energy along `step`, where the system has an energy
    /// (it must be negative: a descent direction); `None` when steps are judged otherwise.
    fn slope(&self, _at: &Self::Eval, _step: &Self::Step) -> Option<f64> {
        None
    }
    /// The trial point x + t·step (projected onto the system's domain where it has one).
    fn advance(&self, x: &Self::Point, step: &Self::Step, t: f64) -> Self::Point;
    /// Whether the line search takes the trial point at step length `t`.
    fn accepts(&self, here: &Self::Eval, trial: &Self::Eval, t: f64, slope: Option<f64>) -> bool;
}

/// The line search's knobs.
#[derive(Debug, Clone, Copy)]
pub struct LineSearch {
    /// Halvings of the step before the search gives up (the shortest step is 2^−max_halvings).
    pub max_halvings: u32,
    /// Take the shortest step even when the system does not accept it (a damped step that keeps
    /// going, as Venner's EHL Newton does), instead of stalling.
    pub take_shortest: bool,
}

/// Armijo's sufficient-decrease test on an energy, E(x + t·d) ≤ E(x) + c₁·t·∇E·d, c₁ = 10⁻⁴.
#[must_use]
pub fn armijo(energy_here: f64, energy_trial: f64, t: f64, slope: f64) -> bool {
    energy_trial <= energy_here + 1e-4 * t * slope
}

/// The residual-norm test, ‖r(x + t·d)‖ ≤ (1 − 10⁻⁴·t)‖r(x)‖.
#[must_use]
pub fn residual_falls(residual_here: f64, residual_trial: f64, t: f64) -> bool {
    residual_trial <= (1.0 - 1e-4 * t) * residual_here
}

/// A converged Newton run: the point, its evaluation and the report.
pub type Solved<S> = Converged<(<S as NewtonSystem>::Point, <S as NewtonSystem>::Eval)>;

/// Newton from `start` until `system.residual` ≤ `tolerance`, under `driver` (one iteration =
/// one Newton step with its line search; the trial points are counted as evaluations). The
/// converged value is the point and its evaluation.
pub fn solve<S: NewtonSystem>(
    system: &S,
    start: S::Point,
    tolerance: f64,
    line: LineSearch,
    driver: &Driver,
) -> Result<Solved<S>, Stopped> {
    let here = system.evaluate(&start);
    let mut residual = system.residual(&here);
    if residual <= tolerance {
        return Ok(driver.converged_at_start((start, here), residual));
    }
    let mut current = Some((start, here));
    driver.run(|counter| {
        let (x, here) = current.take().expect("the iterate is put back every step");
        let Some(step) = system.direction(&x, &here) else {
            return Verdict::Stalled(residual);
        };
        let slope = system.slope(&here, &step);
        if slope.is_some_and(|s| s.is_nan() || s >= 0.0) {
            return Verdict::Stalled(residual);
        }
        let mut t = 1.0;
        let mut accepted = None;
        for halving in 0..=line.max_halvings {
            // A trial of a fine film's step takes a good part of a second: one more past the
            // deadline is the deadline's.
            if !driver.alive() {
                return Verdict::Stalled(residual);
            }
            let trial = system.advance(&x, &step, t);
            let at = system.evaluate(&trial);
            counter.evaluated(1);
            let last = halving == line.max_halvings;
            if system.accepts(&here, &at, t, slope) || (last && line.take_shortest) {
                accepted = Some((trial, at));
                break;
            }
            t *= 0.5;
        }
        let Some((trial, at)) = accepted else {
            return Verdict::Stalled(residual);
        };
        residual = system.residual(&at);
        if residual <= tolerance {
            return Verdict::Converged((trial, at), residual);
        }
        current = Some((trial, at));
        Verdict::Continue(residual)
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fidelity::{IterationUnit, StopReason};
    use crate::numerics::driver::Budget;

    /// The energy E = ¼(x⁴ + y⁴) − x − y (minimum at (1, 1)); residual |∇E|∞.
    struct Quartic;

    impl NewtonSystem for Quartic {
        type Point = [f64; 2];
        type Eval = ([f64; 2], f64);
        type Step = [f64; 2];
        fn evaluate(&self, x: &[f64; 2]) -> ([f64; 2], f64) {
            let g = [x[0].powi(3) - 1.0, x[1].powi(3) - 1.0];
            (g, 0.25 * (x[0].powi(4) + x[1].powi(4)) - x[0] - x[1])
        }
        fn residual(&self, at: &([f64; 2], f64)) -> f64 {
            at.0[0].abs().max(at.0[1].abs())
        }
        fn direction(&self, x: &[f64; 2], at: &([f64; 2], f64)) -> Option<[f64; 2]> {
            let h = [3.0 * x[0] * x[0], 3.0 * x[1] * x[1]];
            (h[0] > 0.0 && h[1] > 0.0).then(|| [-at.0[0] / h[0], -at.0[1] / h[1]])
        }
        fn slope(&self, at: &([f64; 2], f64), d: &[f64; 2]) -> Option<f64> {
            Some(at.0[0] * d[0] + at.0[1] * d[1])
        }
        fn advance(&self, x: &[f64; 2], d: &[f64; 2], t: f64) -> [f64; 2] {
            [x[0] + t * d[0], x[1] + t * d[1]]
        }
        fn accepts(&self, here: &Self::Eval, trial: &Self::Eval, t: f64, s: Option<f64>) -> bool {
            armijo(here.1, trial.1, t, s.unwrap_or(0.0))
        }
    }

    fn driver(cap: u32) -> Driver {
        Driver::new(
            "newton_test",
            IterationUnit::NewtonSteps,
            cap,
            &Budget::unlimited(),
        )
    }

    const LINE: LineSearch = LineSearch {
        max_halvings: 30,
        take_shortest: false,
    };

    #[test]
    fn converges_quadratically_to_the_minimum() {
        let run = solve(&Quartic, [3.0, 0.5], 1e-12, LINE, &driver(50)).unwrap();
        let (x, _) = run.value;
        assert!((x[0] - 1.0).abs() < 1e-12 && (x[1] - 1.0).abs() < 1e-12);
        assert!(run.report.iterations <= 10, "{:?}", run.report);
        assert!(run.report.evaluations.unwrap() >= run.report.iterations);
        assert_eq!(run.report.stop_reason, StopReason::Converged);
    }

    #[test]
    fn a_balanced_start_takes_no_step_and_a_singular_one_stalls() {
        let run = solve(&Quartic, [1.0, 1.0], 1e-12, LINE, &driver(50)).unwrap();
        assert_eq!(run.report.iterations, 0);
        // At x = 0 the Hessian is singular: no direction.
        let stalled = solve(&Quartic, [0.0, 2.0], 1e-12, LINE, &driver(50)).unwrap_err();
        assert_eq!(stalled.reason(), StopReason::Stalled);
        let capped = solve(&Quartic, [3.0, 0.5], 1e-12, LINE, &driver(2)).unwrap_err();
        assert_eq!(capped.reason(), StopReason::IterationCap);
    }

    /// A budget spent while a step is being found (its factorisation, here the direction)
    /// stops the step before any line-search trial: the deadline, after one iteration and no
    /// evaluation.
    #[test]
    fn a_budget_spent_within_a_step_stops_before_its_trials() {
        use std::sync::atomic::{AtomicBool, Ordering};
        use std::sync::Arc;
        struct Cancelling(Arc<AtomicBool>);
        impl NewtonSystem for Cancelling {
            type Point = [f64; 2];
            type Eval = ([f64; 2], f64);
            type Step = [f64; 2];
            fn evaluate(&self, x: &[f64; 2]) -> ([f64; 2], f64) {
                Quartic.evaluate(x)
            }
            fn residual(&self, at: &([f64; 2], f64)) -> f64 {
                Quartic.residual(at)
            }
            fn direction(&self, x: &[f64; 2], at: &([f64; 2], f64)) -> Option<[f64; 2]> {
                self.0.store(true, Ordering::Relaxed);
                Quartic.direction(x, at)
            }
            fn advance(&self, x: &[f64; 2], d: &[f64; 2], t: f64) -> [f64; 2] {
                Quartic.advance(x, d, t)
            }
            fn accepts(&self, h: &Self::Eval, t: &Self::Eval, s: f64, d: Option<f64>) -> bool {
                Quartic.accepts(h, t, s, d)
            }
        }
        let cancel = Arc::new(AtomicBool::new(false));
        let budget = Budget::new(
            std::time::Instant::now() + std::time::Duration::from_secs(60),
            cancel.clone(),
        );
        let d = Driver::new("newton_test", IterationUnit::NewtonSteps, 50, &budget);
        let stopped = solve(&Cancelling(cancel), [3.0, 0.5], 1e-12, LINE, &d).unwrap_err();
        assert_eq!(stopped.reason(), StopReason::Deadline);
        assert_eq!(stopped.report.iterations, 1);
        assert_eq!(stopped.report.evaluations, None, "no trial evaluated");
    }
}
