//! Stiff initial-value problems y′ = f(t, y): the L-stable, stiffly accurate SDIRK method of
//! order 4 with an embedded order-3 estimate (Hairer & Wanner, *Solving ODEs II*, 2nd ed.,
//! §IV.6, Table 6.5, γ = 1/4), under the solver driver.
//!
//! Why this method: a journal's squeeze damping grows as (1 − ε²)^(−5/2), so orbits near
//! contact are stiff; an explicit method would need steps of the film's damping time. Diagonally
//! implicit stages keep each Newton solve N × N (N ≤ 5 here), and stiff accuracy makes the
//! last stage the new state, so the rate at the step's end comes free for dense output.
//!
//! Each stage Yᵢ = y + h Σⱼ₍ⱼ₍ᵢ₎ aᵢⱼ kⱼ + hγ f(t + cᵢh, Yᵢ) is solved by simplified Newton with
//! the iteration matrix I − hγJ; J is a forward-difference Jacobian, kept across steps until a
//! Newton solve converges slowly or fails. The local error h Σ (bᵢ − b̂ᵢ) kᵢ is filtered by
//! (I − hγJ)⁻¹ (Hairer & Wanner §IV.8: without it the estimate is far too large on stiff
//! components) and measured in the weighted RMS norm with weights `absolute + relative·|y|`.
//! The step size follows h ← h·0.9·err^(−1/4), within [0.2, 5] times the last.
//!
//! A rate may refuse a state outside its model's domain (a journal through its clearance): the
//! step is retried at a quarter of the size. Between accepted steps the solution is the cubic
//! Hermite interpolant of y and f at both ends ([`Step::at`]), which the observer uses to find
//! extrema and events; it may end the integration at any time within the step.

use nalgebra::{DMatrix, DVector, Dyn, SMatrix, SVector, LU};

use super::driver::{Budget, Driver, Stopped, Verdict};
use super::optimise::brent_minimise;
use crate::fidelity::{IterationUnit, SolverReport, TimeIntegration};

/// γ, the stages' common diagonal.
const GAMMA: f64 = 0.25;
/// The stages' abscissae cᵢ.
const C: [f64; 5] = [0.25, 0.75, 11.0 / 20.0, 0.5, 1.0];
/// The strictly lower part of the Butcher matrix, row by row (row 5 is b: stiffly accurate).
const A: [[f64; 4]; 5] = [
    [0.0, 0.0, 0.0, 0.0],
    [0.5, 0.0, 0.0, 0.0],
    [17.0 / 50.0, -1.0 / 25.0, 0.0, 0.0],
    [371.0 / 1360.0, -137.0 / 2720.0, 15.0 / 544.0, 0.0],
    [25.0 / 24.0, -49.0 / 48.0, 125.0 / 16.0, -85.0 / 12.0],
];
/// b − b̂: the order-4 weights (A's last row with γ) minus the embedded order-3 ones.
const ERROR_WEIGHTS: [f64; 5] = [
    25.0 / 24.0 - 59.0 / 48.0,
    -49.0 / 48.0 + 17.0 / 96.0,
    125.0 / 16.0 - 225.0 / 32.0,
    0.0,
    GAMMA,
];
/// Newton iterations per stage before the step is retried.
const MAX_NEWTON: usize = 8;

/// Why a rate gave no value at a state.
#[derive(Debug, Clone, PartialEq)]
pub enum RateError<E> {
    /// The state is outside the model's domain: the integrator retries with a smaller step.
    Outside,
    /// The model failed (a film solve out of time): the integration stops with this error.
    Failed(E),
}

/// The right-hand side f(t, y).
pub trait Rate<const N: usize> {
    type Error;
    fn rate(
        &mut self,
        t: f64,
        y: &SVector<f64, N>,
    ) -> Result<SVector<f64, N>, RateError<Self::Error>>;
}

impl<const N: usize, E, F> Rate<N> for F
where
    F: FnMut(f64, &SVector<f64, N>) -> Result<SVector<f64, N>, RateError<E>>,
{
    type Error = E;
    fn rate(&mut self, t: f64, y: &SVector<f64, N>) -> Result<SVector<f64, N>, RateError<E>> {
        self(t, y)
    }
}

/// The integrator's knobs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    /// Relative tolerance on each accepted step's local error.
    pub relative: f64,
    /// Absolute tolerance (the state's components should be scaled to order one).
    pub absolute: f64,
    /// The largest step (also the first step's bound).
    pub max_step: f64,
    /// Attempted steps before the run is capped.
    pub max_steps: u32,
}

/// One accepted step, with its dense output.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Step<const N: usize> {
    pub t0: f64,
    pub t1: f64,
    pub y0: SVector<f64, N>,
    pub y1: SVector<f64, N>,
    /// f at both ends.
    pub f0: SVector<f64, N>,
    pub f1: SVector<f64, N>,
}

impl<const N: usize> Step<N> {
    /// The cubic Hermite interpolant of (y, f) at both ends, at t in [t0, t1] (third order).
    pub fn at(&self, t: f64) -> SVector<f64, N> {
        let h = self.t1 - self.t0;
        let s = ((t - self.t0) / h).clamp(0.0, 1.0);
        let (s2, s3) = (s * s, s * s * s);
        let h00 = 2.0 * s3 - 3.0 * s2 + 1.0;
        let h10 = s3 - 2.0 * s2 + s;
        let h01 = -2.0 * s3 + 3.0 * s2;
        let h11 = s3 - s2;
        self.y0 * h00 + self.f0 * (h * h10) + self.y1 * h01 + self.f1 * (h * h11)
    }

    /// The largest and smallest value of a scalar g(y) over the step, on the dense output: the
    /// ends, or an interior extremum found by Brent's minimisation where the midpoint lies
    /// beyond both ends (steps are short against the motion, so one of each kind at most).
    pub fn extremes(&self, g: impl Fn(&SVector<f64, N>) -> f64) -> Extremes {
        let at = |t: f64| g(&self.at(t));
        let (t0, t1) = (self.t0, self.t1);
        let mid = 0.5 * (t0 + t1);
        let (g0, gm, g1) = (at(t0), at(mid), at(t1));
        let tolerance = 1e-10 * (t1 - t0).max(1e-300);
        let (time_of_max, max) = if gm > g0.max(g1) {
            let (t, m) = brent_minimise(|t| -at(t), t0, t1, tolerance);
            (t, -m)
        } else if g1 >= g0 {
            (t1, g1)
        } else {
            (t0, g0)
        };
        let (time_of_min, min) = if gm < g0.min(g1) {
            brent_minimise(at, t0, t1, tolerance)
        } else if g1 <= g0 {
            (t1, g1)
        } else {
            (t0, g0)
        };
        Extremes {
            max,
            time_of_max,
            min,
            time_of_min,
        }
    }
}

/// A scalar's extremes over one step, with their times.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Extremes {
    pub max: f64,
    pub time_of_max: f64,
    pub min: f64,
    pub time_of_min: f64,
}

/// What the observer wants after a step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Flow {
    Continue,
    /// End the integration at this time within the step just taken (an event).
    StopAt(f64),
}

/// Counts of the work done.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Work {
    pub accepted: u32,
    pub rejected: u32,
    pub rate_evaluations: u32,
    pub jacobians: u32,
}

/// A finished integration: where it ended and what it cost.
#[derive(Debug, Clone, PartialEq)]
pub struct Integrated<const N: usize> {
    pub t: f64,
    pub y: SVector<f64, N>,
    /// True when the observer ended it before `t_end`.
    pub stopped_by_observer: bool,
    pub work: Work,
    pub report: SolverReport,
}

/// An integration that did not reach its end.
#[derive(Debug, Clone, PartialEq)]
pub enum Failure<E, const N: usize> {
    /// Capped, out of time, or the step size underflowed (the rate refused every step, or
    /// Newton failed at the smallest step).
    Halted(Box<Halted<N>>),
    /// The rate failed.
    Rate(E),
}

/// Where a halted integration stopped: the last accepted state and the driver's report.
#[derive(Debug, Clone, PartialEq)]
pub struct Halted<const N: usize> {
    pub t: f64,
    pub y: SVector<f64, N>,
    pub stopped: Stopped,
}

/// The stage solver's verdict on one attempted step.
enum Attempt<const N: usize> {
    Done {
        y1: SVector<f64, N>,
        f1: SVector<f64, N>,
        error: f64,
    },
    /// Newton did not converge: retry smaller (with a fresh Jacobian if this one was old).
    NewtonFailed,
    /// A stage left the model's domain.
    Outside,
}

/// Integrate from (t0, y0) to `t_end`, calling `observe` after every accepted step.
pub fn integrate<const N: usize, R: Rate<N>>(
    rate: &mut R,
    t0: f64,
    y0: SVector<f64, N>,
    t_end: f64,
    settings: &Settings,
    mut observe: impl FnMut(&Step<N>) -> Flow,
    budget: &Budget,
) -> Result<Integrated<N>, Failure<R::Error, N>> {
    let mut work = Work::default();
    let mut failed: Option<R::Error> = None;
    let mut t = t0;
    let mut y = y0;
    let mut f = match rate.rate(t, &y) {
        Ok(f) => f,
        Err(RateError::Failed(e)) => return Err(Failure::Rate(e)),
        Err(RateError::Outside) => {
            return Err(halted_at_start(t, y, settings, budget));
        }
    };
    work.rate_evaluations += 1;
    let span = t_end - t0;
    let h_min = 1e-12 * span.abs().max(1.0);
    let mut h = first_step(&y, &f, settings).min(span);
    let mut jacobian: Option<SMatrix<f64, N, N>> = None;
    let mut fresh = false;
    let mut stopped_by_observer = false;
    let mut last_error = 0.0;
    let driver = Driver::new(
        "sdirk4_l_stable",
        IterationUnit::TimeSteps,
        settings.max_steps,
        budget,
    )
    .check_every(4);
    let run = driver.run(|counter| {
        if jacobian.is_none() {
            match finite_difference_jacobian(rate, t, &y, &f, settings, &mut work) {
                Ok(j) => jacobian = Some(j),
                Err(e) => {
                    failed = Some(e);
                    return Verdict::Stalled(f64::NAN);
                }
            }
            fresh = true;
        }
        let j = jacobian.expect("set above");
        let before = work.rate_evaluations;
        let attempt = match sdirk_step(rate, t, &y, &f, h, &j, settings, &mut work) {
            Ok(a) => a,
            Err(e) => {
                failed = Some(e);
                return Verdict::Stalled(f64::NAN);
            }
        };
        counter.evaluated(work.rate_evaluations - before);
        match attempt {
            Attempt::Done { y1, f1, error } if error <= 1.0 => {
                let step = Step {
                    t0: t,
                    t1: t + h,
                    y0: y,
                    y1,
                    f0: f,
                    f1,
                };
                work.accepted += 1;
                last_error = error;
                fresh = false;
                let flow = observe(&step);
                if let Flow::StopAt(at) = flow {
                    t = at.clamp(step.t0, step.t1);
                    y = step.at(t);
                    stopped_by_observer = true;
                    return Verdict::Converged((), error);
                }
                (t, y, f) = (step.t1, y1, f1);
                if (t_end - t) <= 1e-12 * span.abs().max(1.0) {
                    return Verdict::Converged((), error);
                }
                let grow = (0.9 * error.max(1e-10).powf(-0.25)).clamp(0.2, 5.0);
                h = (h * grow).min(settings.max_step).min(t_end - t);
                Verdict::Continue(error)
            }
            Attempt::Done { error, .. } => {
                work.rejected += 1;
                h *= (0.9 * error.powf(-0.25)).clamp(0.1, 0.9);
                if h < h_min {
                    return Verdict::Stalled(error);
                }
                Verdict::Continue(error)
            }
            Attempt::NewtonFailed | Attempt::Outside => {
                work.rejected += 1;
                if !fresh && matches!(attempt, Attempt::NewtonFailed) {
                    jacobian = None;
                } else {
                    h *= 0.25;
                }
                // No error estimate: the residual stays the last accepted step's.
                if h < h_min {
                    return Verdict::Stalled(last_error);
                }
                Verdict::Continue(last_error)
            }
        }
    });
    if let Some(e) = failed {
        return Err(Failure::Rate(e));
    }
    let with_work = |mut report: SolverReport| {
        report.time_integration = Some(Box::new(TimeIntegration {
            rejected_steps: work.rejected,
            relative_tolerance: settings.relative,
        }));
        report
    };
    match run {
        Ok(done) => Ok(Integrated {
            t,
            y,
            stopped_by_observer,
            work,
            report: with_work(done.report),
        }),
        Err(stopped) => Err(Failure::Halted(Box::new(Halted {
            t,
            y,
            stopped: Stopped {
                report: with_work(stopped.report),
            },
        }))),
    }
}

/// The run that cannot start: the initial state is outside the rate's domain.
fn halted_at_start<E, const N: usize>(
    t: f64,
    y: SVector<f64, N>,
    settings: &Settings,
    budget: &Budget,
) -> Failure<E, N> {
    let stopped = Driver::new(
        "sdirk4_l_stable",
        IterationUnit::TimeSteps,
        settings.max_steps,
        budget,
    )
    .run(|_| Verdict::<()>::Stalled(f64::INFINITY))
    .expect_err("a stalled verdict stops the run");
    Failure::Halted(Box::new(Halted { t, y, stopped }))
}

/// The weighted RMS norm of `v` against the state `y`.
fn norm<const N: usize>(v: &SVector<f64, N>, y: &SVector<f64, N>, settings: &Settings) -> f64 {
    let sum: f64 = v
        .iter()
        .zip(y.iter())
        .map(|(v, y)| (v / (settings.absolute + settings.relative * y.abs())).powi(2))
        .sum();
    (sum / N as f64).sqrt()
}

/// The first step: a hundredth of the time the state takes to change by its own size (Hairer,
/// Nørsett & Wanner, *Solving ODEs I*, §II.4's first guess), within `max_step`.
fn first_step<const N: usize>(
    y: &SVector<f64, N>,
    f: &SVector<f64, N>,
    settings: &Settings,
) -> f64 {
    let d0 = norm(y, y, settings);
    let d1 = norm(f, y, settings);
    let h = if d0 < 1e-5 || d1 < 1e-5 {
        1e-6
    } else {
        0.01 * d0 / d1
    };
    h.min(settings.max_step)
}

/// ∂f/∂y by forward differences (backward where the forward point is outside the domain).
fn finite_difference_jacobian<const N: usize, R: Rate<N>>(
    rate: &mut R,
    t: f64,
    y: &SVector<f64, N>,
    f: &SVector<f64, N>,
    settings: &Settings,
    work: &mut Work,
) -> Result<SMatrix<f64, N, N>, R::Error> {
    work.jacobians += 1;
    // The base rate afresh: the f carried from the last step is its last stage's slope, off by
    // the Newton residual over hγ, which a difference over √ε would magnify past use.
    work.rate_evaluations += 1;
    let f = match rate.rate(t, y) {
        Ok(v) => v,
        Err(RateError::Failed(e)) => return Err(e),
        Err(RateError::Outside) => *f,
    };
    let mut j = SMatrix::<f64, N, N>::zeros();
    for col in 0..N {
        let delta = f64::EPSILON.sqrt()
            * y[col]
                .abs()
                .max(settings.absolute / settings.relative)
                .max(1e-5);
        let mut column = None;
        for sign in [1.0, -1.0] {
            let mut yp = *y;
            yp[col] += sign * delta;
            work.rate_evaluations += 1;
            match rate.rate(t, &yp) {
                Ok(fp) => {
                    column = Some((fp - f) / (sign * delta));
                    break;
                }
                Err(RateError::Failed(e)) => return Err(e),
                Err(RateError::Outside) => continue,
            }
        }
        if let Some(c) = column {
            j.set_column(col, &c);
        }
    }
    Ok(j)
}

/// I − hγJ, factorised (nalgebra's LU on a dynamic matrix: its static form needs type-level
/// dimension bounds that a const-generic N cannot name).
struct IterationMatrix {
    lu: LU<f64, Dyn, Dyn>,
}

impl IterationMatrix {
    fn factor<const N: usize>(jacobian: &SMatrix<f64, N, N>, hg: f64) -> Option<Self> {
        let m = DMatrix::from_fn(N, N, |i, j| {
            f64::from(u8::from(i == j)) - hg * jacobian[(i, j)]
        });
        let lu = m.lu();
        lu.is_invertible().then_some(IterationMatrix { lu })
    }

    fn solve<const N: usize>(&self, b: &SVector<f64, N>) -> Option<SVector<f64, N>> {
        let x = self.lu.solve(&DVector::from_column_slice(b.as_slice()))?;
        let x = SVector::<f64, N>::from_column_slice(x.as_slice());
        x.iter().all(|v| v.is_finite()).then_some(x)
    }
}

/// One attempted step of size h from (t, y) with rate f there.
#[allow(clippy::too_many_arguments)]
fn sdirk_step<const N: usize, R: Rate<N>>(
    rate: &mut R,
    t: f64,
    y: &SVector<f64, N>,
    f: &SVector<f64, N>,
    h: f64,
    jacobian: &SMatrix<f64, N, N>,
    settings: &Settings,
    work: &mut Work,
) -> Result<Attempt<N>, R::Error> {
    let hg = h * GAMMA;
    let Some(lu) = IterationMatrix::factor(jacobian, hg) else {
        return Ok(Attempt::NewtonFailed);
    };
    let mut k = [SVector::<f64, N>::zeros(); 5];
    let mut stage = *y;
    for i in 0..5 {
        let mut base = *y;
        for (jdx, a) in A[i].iter().enumerate().take(i) {
            base += k[jdx] * (h * a);
        }
        // Start from the previous stage's slope (the initial rate for the first).
        let guess_slope = if i == 0 { *f } else { k[i - 1] };
        stage = base + guess_slope * hg;
        let mut previous: Option<f64> = None;
        let mut converged = false;
        for _ in 0..MAX_NEWTON {
            work.rate_evaluations += 1;
            let fy = match rate.rate(t + C[i] * h, &stage) {
                Ok(v) => v,
                Err(RateError::Outside) => return Ok(Attempt::Outside),
                Err(RateError::Failed(e)) => return Err(e),
            };
            let residual = stage - base - fy * hg;
            let delta = -lu.solve(&residual).unwrap_or(residual * f64::NAN);
            let size = norm(&delta, &stage, settings);
            if !size.is_finite() {
                return Ok(Attempt::NewtonFailed);
            }
            stage += delta;
            let rate_of_convergence = previous.map(|p| size / p);
            if rate_of_convergence.is_some_and(|r| r >= 0.9) {
                return Ok(Attempt::NewtonFailed);
            }
            let settled = match rate_of_convergence {
                Some(r) => r / (1.0 - r) * size < 0.03,
                None => size < 1e-3,
            };
            previous = Some(size);
            if settled {
                converged = true;
                break;
            }
        }
        if !converged {
            return Ok(Attempt::NewtonFailed);
        }
        k[i] = (stage - base) / hg;
    }
    let mut local = SVector::<f64, N>::zeros();
    for (ki, w) in k.iter().zip(ERROR_WEIGHTS) {
        local += ki * (h * w);
    }
    let filtered = lu.solve(&local).unwrap_or(local);
    let scale = y.zip_map(&stage, |a, b| a.abs().max(b.abs()));
    let error = norm(&filtered, &scale, settings);
    Ok(Attempt::Done {
        y1: stage,
        f1: k[4],
        error: if error.is_finite() {
            error
        } else {
            f64::INFINITY
        },
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fidelity::StopReason;
    use nalgebra::{Vector1, Vector2};

    fn settings(relative: f64) -> Settings {
        Settings {
            relative,
            absolute: relative,
            max_step: 1.0,
            max_steps: 100_000,
        }
    }

    #[test]
    fn the_order_conditions_hold_to_fourth_order() {
        // Σb = 1, Σbc = 1/2, Σbc² = 1/3, ΣbAc = 1/6, and the four fourth-order conditions.
        let mut a = [[0.0; 5]; 5];
        for i in 0..5 {
            a[i][..4].copy_from_slice(&A[i]);
            a[i][i] = GAMMA;
        }
        let b = a[4];
        let ac: Vec<f64> = (0..5)
            .map(|i| (0..5).map(|j| a[i][j] * C[j]).sum())
            .collect();
        let ac2: Vec<f64> = (0..5)
            .map(|i| (0..5).map(|j| a[i][j] * C[j] * C[j]).sum())
            .collect();
        let aac: Vec<f64> = (0..5)
            .map(|i| (0..5).map(|j| a[i][j] * ac[j]).sum())
            .collect();
        let sum = |g: &dyn Fn(usize) -> f64| (0..5).map(g).sum::<f64>();
        let conditions = [
            (sum(&|i| b[i]), 1.0),
            (sum(&|i| b[i] * C[i]), 0.5),
            (sum(&|i| b[i] * C[i] * C[i]), 1.0 / 3.0),
            (sum(&|i| b[i] * ac[i]), 1.0 / 6.0),
            (sum(&|i| b[i] * C[i].powi(3)), 0.25),
            (sum(&|i| b[i] * C[i] * ac[i]), 0.125),
            (sum(&|i| b[i] * ac2[i]), 1.0 / 12.0),
            (sum(&|i| b[i] * aac[i]), 1.0 / 24.0),
        ];
        for (got, want) in conditions {
            assert!((got - want).abs() < 1e-14, "{got} vs {want}");
        }
        for (i, row) in a.iter().enumerate() {
            assert!(
                (row.iter().sum::<f64>() - C[i]).abs() < 1e-14,
                "row sum = c"
            );
        }
    }

    fn harmonic(t_end: f64, tol: f64) -> (Integrated<2>, f64) {
        let mut rate = |_t: f64, y: &Vector2<f64>| -> Result<Vector2<f64>, RateError<()>> {
            Ok(Vector2::new(y[1], -y[0]))
        };
        let run = integrate(
            &mut rate,
            0.0,
            Vector2::new(1.0, 0.0),
            t_end,
            &settings(tol),
            |_| Flow::Continue,
            &Budget::unlimited(),
        )
        .unwrap();
        let error = (run.y - Vector2::new(t_end.cos(), -t_end.sin())).norm();
        (run, error)
    }

    #[test]
    fn the_oscillator_is_followed_within_the_tolerance_and_tighter_costs_more() {
        // y'' = −y over ten periods: the global error follows the tolerance down.
        let t_end = 20.0 * std::f64::consts::PI;
        let (loose, e_loose) = harmonic(t_end, 1e-5);
        let (tight, e_tight) = harmonic(t_end, 1e-9);
        assert!(e_loose < 1e-2, "{e_loose}");
        assert!(e_tight < 1e-6, "{e_tight}");
        assert!(e_tight < e_loose / 100.0);
        assert!(tight.work.accepted > 3 * loose.work.accepted);
        assert_eq!(loose.report.stop_reason, StopReason::Converged);
        assert_eq!(
            loose
                .report
                .time_integration
                .as_ref()
                .map(|t| t.relative_tolerance),
            Some(1e-5)
        );
    }

    #[test]
    fn a_stiff_decay_is_crossed_in_few_steps() {
        // y' = −10⁶(y − cos t): explicit methods need h < 2·10⁻⁶; an L-stable one follows
        // the slow solution y ≈ cos t + 10⁻⁶ sin t in tens of steps.
        let mut rate = |t: f64, y: &Vector1<f64>| -> Result<Vector1<f64>, RateError<()>> {
            Ok(Vector1::new(-1e6 * (y[0] - t.cos())))
        };
        let run = integrate(
            &mut rate,
            0.0,
            Vector1::new(0.0),
            2.0,
            &settings(1e-6),
            |_| Flow::Continue,
            &Budget::unlimited(),
        )
        .unwrap();
        assert!((run.y[0] - (2f64.cos() + 1e-6 * 2f64.sin())).abs() < 1e-6);
        assert!(run.work.accepted < 200, "{:?}", run.work);
    }

    #[test]
    fn the_observer_ends_the_run_at_an_event_found_in_the_dense_output() {
        // y' = 1 from 0: the event y = 0.7303 lies inside a step; the dense output finds it.
        let mut rate = |_t: f64, _y: &Vector1<f64>| -> Result<Vector1<f64>, RateError<()>> {
            Ok(Vector1::new(1.0))
        };
        let target = 0.7303;
        let run = integrate(
            &mut rate,
            0.0,
            Vector1::new(0.0),
            5.0,
            &settings(1e-6),
            |s| {
                if s.y1[0] >= target {
                    Flow::StopAt(s.t0 + (target - s.y0[0]))
                } else {
                    Flow::Continue
                }
            },
            &Budget::unlimited(),
        )
        .unwrap();
        assert!(run.stopped_by_observer);
        assert!((run.t - target).abs() < 1e-12 && (run.y[0] - target).abs() < 1e-12);
    }

    #[test]
    fn a_rate_that_refuses_states_shrinks_the_step_and_a_wall_halts_with_the_last_state() {
        // y' = 1 with y ≥ 1 outside: the run halts just below the wall, never past it.
        let mut rate = |_t: f64, y: &Vector1<f64>| -> Result<Vector1<f64>, RateError<()>> {
            if y[0] >= 1.0 {
                Err(RateError::Outside)
            } else {
                Ok(Vector1::new(1.0))
            }
        };
        let failure = integrate(
            &mut rate,
            0.0,
            Vector1::new(0.0),
            5.0,
            &settings(1e-6),
            |_| Flow::Continue,
            &Budget::unlimited(),
        )
        .unwrap_err();
        let Failure::Halted(halted) = failure else {
            panic!("halted expected");
        };
        let Halted { t, y, stopped } = *halted;
        assert_eq!(stopped.reason(), StopReason::Stalled);
        assert!(
            y[0] < 1.0 && y[0] > 0.999 && (t - y[0]).abs() < 1e-9,
            "{t} {y}"
        );
    }

    #[test]
    fn a_late_budget_and_a_failing_rate_stop_the_run() {
        let late = Budget::new(
            std::time::Instant::now(),
            std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false)),
        );
        let mut rate =
            |_t: f64, y: &Vector1<f64>| -> Result<Vector1<f64>, RateError<()>> { Ok(-y) };
        let s = Settings {
            max_step: 1e-3,
            ..settings(1e-8)
        };
        let failure = integrate(
            &mut rate,
            0.0,
            Vector1::new(1.0),
            10.0,
            &s,
            |_| Flow::Continue,
            &late,
        )
        .unwrap_err();
        assert!(
            matches!(failure, Failure::Halted(ref h) if h.stopped.reason() == StopReason::Deadline)
        );
        let mut failing = |_t: f64, _y: &Vector1<f64>| -> Result<Vector1<f64>, RateError<&str>> {
            Err(RateError::Failed("film"))
        };
        let failure = integrate(
            &mut failing,
            0.0,
            Vector1::new(1.0),
            1.0,
            &s,
            |_| Flow::Continue,
            &Budget::unlimited(),
        )
        .unwrap_err();
        assert_eq!(failure, Failure::Rate("film"));
    }

    #[test]
    fn a_steps_extremes_are_found_inside_it_on_the_dense_output() {
        // y = (sin t, cos t) over [1.4, 1.8]: sin peaks at π/2 inside the step, cos falls
        // throughout (its extremes at the ends); the Hermite cubic is O(h⁴) accurate.
        let (t0, t1) = (1.4f64, 1.8f64);
        let step = Step {
            t0,
            t1,
            y0: Vector2::new(t0.sin(), t0.cos()),
            y1: Vector2::new(t1.sin(), t1.cos()),
            f0: Vector2::new(t0.cos(), -t0.sin()),
            f1: Vector2::new(t1.cos(), -t1.sin()),
        };
        let sine = step.extremes(|y| y[0]);
        assert!(
            (sine.max - 1.0).abs() < 1e-3
                && (sine.time_of_max - std::f64::consts::FRAC_PI_2).abs() < 1e-2
        );
        assert_eq!((sine.min, sine.time_of_min), (t1.sin(), t1));
        let cosine = step.extremes(|y| y[1]);
        assert_eq!((cosine.max, cosine.time_of_max), (t0.cos(), t0));
        assert_eq!((cosine.min, cosine.time_of_min), (t1.cos(), t1));
        // A trough inside the step: −sin.
        let trough = step.extremes(|y| -y[0]);
        assert!(
            (trough.min + 1.0).abs() < 1e-3
                && (trough.time_of_min - std::f64::consts::FRAC_PI_2).abs() < 1e-2
        );
    }
}
