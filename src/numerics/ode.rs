//! Stiff initial-value problems y′ = f(t, y) under the solver driver, by one of two implicit
//! Runge–Kutta methods with embedded error estimates ([`Method`]):
//!
//! - **Radau IIA**, three stages, order 5, stage order 3 (Hairer & Wanner, *Solving ODEs II*,
//!   2nd ed., §IV.5, Table 5.6; the estimate and its filter as their `radau5`, §IV.8). The
//!   stages Zᵢ = Yᵢ − y solve Z = h(A ⊗ I)F(y + Z) together, by simplified Newton with the
//!   3N × 3N matrix I − h(A ⊗ J), started from the last step's collocation polynomial. Its
//!   stage order spares it the order reduction a stiff squeeze film inflicts on SDIRK: near
//!   contact it takes several times fewer steps. Where its coupled Newton stalls on a fresh
//!   Jacobian (the film force's round-off within 10⁻⁸ of the wall), the step is SDIRK's.
//! - **SDIRK**, L-stable and stiffly accurate, order 4 with an embedded order-3 estimate (§IV.6,
//!   Table 6.5, γ = 1/4): five stages Yᵢ = y + h Σⱼ₍ⱼ₍ᵢ₎ aᵢⱼ kⱼ + hγ f(t + cᵢh, Yᵢ), each an
//!   N × N simplified Newton solve with I − hγJ. The local error h Σ (bᵢ − b̂ᵢ) kᵢ is filtered
//!   by (I − hγJ)⁻¹ (§IV.8: without it the estimate is far too large on stiff components).
//!
//! Why implicit: a journal's squeeze damping grows as (1 − ε²)^(−5/2), so orbits near contact
//! are stiff; an explicit method would need steps of the film's damping time. Both methods
//! are stiffly accurate (the last stage is the new state), so the rate at the step's end
//! comes free for dense output. J is a forward-difference Jacobian, kept across steps until a
//! Newton solve converges slowly or fails. Errors are measured in the weighted RMS norm with
//! weights `absolute + relative·|y|`; the step size follows h ← h·0.9·err^(−1/4), within
//! [0.2, 5] times the last.
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

/// The implicit Runge–Kutta method of a run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    /// SDIRK of order 4: five stages solved one after another, each an N × N Newton solve
    /// from the stages before it.
    Sdirk4,
    /// Radau IIA of order 5: three stages solved together (a 3N × 3N Newton solve), stage
    /// order 3, so no order reduction on stiff components (Hairer & Wanner §IV.15); several
    /// times fewer steps near contact. Its coupled Newton starts from the last step's
    /// collocation polynomial.
    RadauIia5,
}

/// The method names the solver report carries.
const SDIRK4: &str = "sdirk4_l_stable";
const RADAU_IIA5: &str = "radau_iia5";

impl Method {
    /// The name the solver report carries.
    pub fn name(self) -> &'static str {
        match self {
            Method::Sdirk4 => SDIRK4,
            Method::RadauIia5 => RADAU_IIA5,
        }
    }

    /// The run's driver under this method's name.
    fn driver(self, settings: &Settings, budget: &Budget) -> Driver {
        let (unit, cap) = (IterationUnit::TimeSteps, settings.max_steps);
        match self {
            Method::Sdirk4 => Driver::new(SDIRK4, unit, cap, budget),
            Method::RadauIia5 => Driver::new(RADAU_IIA5, unit, cap, budget),
        }
    }
}

/// The integrator's knobs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    pub method: Method,
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

    /// The largest and smallest value of a scalar g(y) over the step, on the dense output: g at
    /// nine equally spaced times, and where the largest (smallest) of them is inside the step,
    /// Brent's minimisation between its neighbours (a step spans a fraction of the motion: one
    /// extremum of each kind between probes at most).
    pub fn extremes(&self, g: impl Fn(&SVector<f64, N>) -> f64) -> Extremes {
        const PROBES: usize = 8;
        let at = |t: f64| g(&self.at(t));
        let (t0, t1) = (self.t0, self.t1);
        let times: [f64; PROBES + 1] = std::array::from_fn(|k| {
            if k == PROBES {
                t1
            } else {
                t0 + (t1 - t0) * k as f64 / PROBES as f64
            }
        });
        let values = times.map(at);
        let tolerance = 1e-10 * (t1 - t0).max(1e-300);
        // The probe of the largest value of `sign`·g, refined when inside the step.
        let extreme = |sign: f64| {
            let k = (0..=PROBES)
                .max_by(|&a, &b| (sign * values[a]).total_cmp(&(sign * values[b])))
                .unwrap_or(0);
            if k == 0 || k == PROBES {
                (times[k], values[k])
            } else {
                let (t, m) =
                    brent_minimise(|t| -sign * at(t), times[k - 1], times[k + 1], tolerance);
                if -m >= sign * values[k] {
                    (t, -m * sign)
                } else {
                    (times[k], values[k])
                }
            }
        };
        let (time_of_max, max) = extreme(1.0);
        let (time_of_min, min) = extreme(-1.0);
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
    /// Radau steps taken by SDIRK instead (Radau's Newton stalled on a fresh Jacobian).
    pub fallback_steps: u32,
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
        /// Radau's stages Zᵢ = Yᵢ − y (the collocation polynomial's values); None for SDIRK.
        stages: Option<[SVector<f64, N>; 3]>,
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
    let mut h = first_step(&y, &f, settings).min(span);
    // The smallest step: a 10⁻¹² part of the span, or less where the first step already is.
    let h_min = (1e-12 * span.abs().max(1.0)).min(1e-6 * h);
    let mut jacobian: Option<SMatrix<f64, N, N>> = None;
    let mut fresh = false;
    let mut stopped_by_observer = false;
    let mut last_error = 0.0;
    let mut careful = true;
    let mut last_stages: Option<(f64, [SVector<f64, N>; 3])> = None;
    let driver = settings.method.driver(settings, budget).check_every(4);
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
        let attempt = match settings.method {
            Method::Sdirk4 => sdirk_step(rate, t, &y, &f, h, &j, settings, &mut work),
            Method::RadauIia5 => radau_step(
                rate,
                t,
                &y,
                &f,
                h,
                &j,
                careful,
                last_stages.as_ref(),
                settings,
                &mut work,
            )
            .and_then(|attempt| match attempt {
                // Radau's coupled Newton failed on a fresh Jacobian: at the wall the film
                // force's round-off can stall it where SDIRK's stage-by-stage Newton converges.
                // This step is SDIRK's, at the same size and tolerance.
                Attempt::NewtonFailed if fresh => {
                    work.fallback_steps += 1;
                    last_stages = None;
                    sdirk_step(rate, t, &y, &f, h, &j, settings, &mut work)
                }
                other => Ok(other),
            }),
        };
        let attempt = match attempt {
            Ok(a) => a,
            Err(e) => {
                failed = Some(e);
                return Verdict::Stalled(f64::NAN);
            }
        };
        counter.evaluated(work.rate_evaluations - before);
        match attempt {
            Attempt::Done {
                y1,
                f1,
                error,
                stages,
            } if error <= 1.0 => {
                last_stages = stages.map(|z| (h, z));
                let step = Step {
                    t0: t,
                    t1: t + h,
                    y0: y,
                    y1,
                    f0: f,
                    f1,
                };
                work.accepted += 1;
                careful = false;
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
                careful = true;
                h *= (0.9 * error.powf(-0.25)).clamp(0.1, 0.9);
                if h < h_min {
                    return Verdict::Stalled(error);
                }
                Verdict::Continue(error)
            }
            Attempt::NewtonFailed | Attempt::Outside => {
                work.rejected += 1;
                careful = true;
                if !fresh && matches!(attempt, Attempt::NewtonFailed) {
                    // A fresh Jacobian first; the step is not smaller, so not a stall.
                    jacobian = None;
                } else {
                    h *= 0.25;
                    // No error estimate: the residual stays the last accepted step's.
                    if h < h_min {
                        return Verdict::Stalled(last_error);
                    }
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
    let stopped = settings
        .method
        .driver(settings, budget)
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

/// Where a simplified Newton solve stands after an iterate.
enum Newton {
    /// Diverging or too slow (contraction ≥ 0.9), or not finite: retry the step.
    Failed,
    /// The remaining error, estimated from the contraction, is below 3 % of the tolerance.
    Settled,
    Going,
}

/// The verdict on an iterate whose correction had weighted size `size`, `previous` the last
/// one's (Hairer & Wanner §IV.8's stopping rule: η = θ/(1 − θ), η·size < κ = 0.03; the first
/// iterate settles below 10⁻³).
fn newton_progress(previous: &mut Option<f64>, size: f64) -> Newton {
    if !size.is_finite() {
        return Newton::Failed;
    }
    let contraction = previous.replace(size).map(|p| size / p);
    match contraction {
        Some(r) if r >= 0.9 => Newton::Failed,
        Some(r) if r / (1.0 - r) * size < 0.03 => Newton::Settled,
        None if size < 1e-3 => Newton::Settled,
        _ => Newton::Going,
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
            stage += delta;
            match newton_progress(&mut previous, size) {
                Newton::Failed => return Ok(Attempt::NewtonFailed),
                Newton::Settled => {
                    converged = true;
                    break;
                }
                Newton::Going => {}
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
        stages: None,
        error: if error.is_finite() {
            error
        } else {
            f64::INFINITY
        },
    })
}

/// Radau IIA, three stages (order 5, stage order 3; Hairer & Wanner §IV.5, Table 5.6).
const SQRT_6: f64 = 2.449_489_742_783_178;
const RADAU_C: [f64; 3] = [(4.0 - SQRT_6) / 10.0, (4.0 + SQRT_6) / 10.0, 1.0];
const RADAU_A: [[f64; 3]; 3] = [
    [
        (88.0 - 7.0 * SQRT_6) / 360.0,
        (296.0 - 169.0 * SQRT_6) / 1800.0,
        (-2.0 + 3.0 * SQRT_6) / 225.0,
    ],
    [
        (296.0 + 169.0 * SQRT_6) / 1800.0,
        (88.0 + 7.0 * SQRT_6) / 360.0,
        (-2.0 - 3.0 * SQRT_6) / 225.0,
    ],
    [(16.0 - SQRT_6) / 36.0, (16.0 + SQRT_6) / 36.0, 1.0 / 9.0],
];
/// The last row of A⁻¹: the end slope from the stages.
const A_INVERSE_LAST_ROW: [f64; 3] = [5.531_972_647_421_811, -7.531_972_647_421_811, 5.0];
/// γ₀, A's real eigenvalue.
const GAMMA_0: f64 = 0.274_888_829_595_677_3;
/// The embedded estimate's weights on the stages (Hairer's radau5: dd₁, dd₂, dd₃).
const RADAU_ERROR_WEIGHTS: [f64; 3] = [
    -(13.0 + 7.0 * SQRT_6) / 3.0,
    (-13.0 + 7.0 * SQRT_6) / 3.0,
    -1.0 / 3.0,
];

/// The collocation polynomial of a Radau step at s = (t − t₀)/h: the cubic through 0 at s = 0
/// and the stages Zᵢ at s = cᵢ.
fn collocation<const N: usize>(z: &[SVector<f64, N>; 3], s: f64) -> SVector<f64, N> {
    let nodes = [0.0, RADAU_C[0], RADAU_C[1], RADAU_C[2]];
    let mut u = SVector::<f64, N>::zeros();
    for (k, zk) in z.iter().enumerate() {
        let node = nodes[k + 1];
        let weight: f64 = nodes
            .iter()
            .filter(|&&m| m != node)
            .map(|m| (s - m) / (node - m))
            .product();
        u += zk * weight;
    }
    u
}

/// The 3N × 3N iteration matrix I − h(A ⊗ J) of the coupled stages, factorised.
struct StageMatrix {
    lu: LU<f64, Dyn, Dyn>,
}

impl StageMatrix {
    fn factor<const N: usize>(jacobian: &SMatrix<f64, N, N>, h: f64) -> Option<Self> {
        let m = DMatrix::from_fn(3 * N, 3 * N, |r, c| {
            let (i, p, j, q) = (r / N, r % N, c / N, c % N);
            f64::from(u8::from(r == c)) - h * RADAU_A[i][j] * jacobian[(p, q)]
        });
        let lu = m.lu();
        lu.is_invertible().then_some(StageMatrix { lu })
    }

    fn solve<const N: usize>(&self, b: &[SVector<f64, N>; 3]) -> Option<[SVector<f64, N>; 3]> {
        let stacked = DVector::from_iterator(3 * N, b.iter().flat_map(|v| v.iter().copied()));
        let x = self.lu.solve(&stacked)?;
        x.iter().all(|v| v.is_finite()).then(|| {
            std::array::from_fn(|i| {
                SVector::<f64, N>::from_column_slice(&x.as_slice()[i * N..(i + 1) * N])
            })
        })
    }
}

/// One attempted step of size h from (t, y) with rate f there. `careful` (the first step, or
/// one after a rejection): an error estimate above 1 is recomputed with the rate at the
/// estimate's state, which tames it on stiff components (Hairer & Wanner §IV.8, Eq. 8.20).
#[allow(clippy::too_many_arguments)]
fn radau_step<const N: usize, R: Rate<N>>(
    rate: &mut R,
    t: f64,
    y: &SVector<f64, N>,
    f: &SVector<f64, N>,
    h: f64,
    jacobian: &SMatrix<f64, N, N>,
    careful: bool,
    last: Option<&(f64, [SVector<f64, N>; 3])>,
    settings: &Settings,
    work: &mut Work,
) -> Result<Attempt<N>, R::Error> {
    let Some(stages) = StageMatrix::factor(jacobian, h) else {
        return Ok(Attempt::NewtonFailed);
    };
    // Zᵢ = Yᵢ − y: the last step's collocation polynomial extrapolated (Hairer & Wanner
    // §IV.8), or zero on the first step.
    let mut z = match last {
        Some((h_last, previous)) => {
            let end = collocation(previous, 1.0);
            std::array::from_fn(|i| collocation(previous, 1.0 + RADAU_C[i] * h / h_last) - end)
        }
        None => [SVector::<f64, N>::zeros(); 3],
    };
    let mut previous: Option<f64> = None;
    let mut converged = false;
    for _ in 0..MAX_NEWTON {
        let mut rates = [SVector::<f64, N>::zeros(); 3];
        for (i, r) in rates.iter_mut().enumerate() {
            work.rate_evaluations += 1;
            *r = match rate.rate(t + RADAU_C[i] * h, &(y + z[i])) {
                Ok(v) => v,
                Err(RateError::Outside) => return Ok(Attempt::Outside),
                Err(RateError::Failed(e)) => return Err(e),
            };
        }
        let residual: [SVector<f64, N>; 3] = std::array::from_fn(|i| {
            z[i] - (rates[0] * RADAU_A[i][0] + rates[1] * RADAU_A[i][1] + rates[2] * RADAU_A[i][2])
                * h
        });
        let Some(delta) = stages.solve(&residual) else {
            return Ok(Attempt::NewtonFailed);
        };
        let size = (delta
            .iter()
            .zip(&z)
            .map(|(d, zi)| norm(d, &(y + zi), settings).powi(2))
            .sum::<f64>()
            / 3.0)
            .sqrt();
        for (zi, d) in z.iter_mut().zip(&delta) {
            *zi -= d;
        }
        match newton_progress(&mut previous, size) {
            Newton::Failed => return Ok(Attempt::NewtonFailed),
            Newton::Settled => {
                converged = true;
                break;
            }
            Newton::Going => {}
        }
    }
    if !converged {
        return Ok(Attempt::NewtonFailed);
    }
    let y1 = y + z[2];
    // Stiffly accurate: f at the step's end is the last stage's slope, (A⁻¹Z)₃/h.
    let f1 = (z[0] * A_INVERSE_LAST_ROW[0]
        + z[1] * A_INVERSE_LAST_ROW[1]
        + z[2] * A_INVERSE_LAST_ROW[2])
        / h;
    // The embedded estimate: γ₀(I − hγ₀J)⁻¹(h f₀ + Σ eᵢZᵢ), γ₀ A's real eigenvalue.
    let Some(filter) = IterationMatrix::factor(jacobian, h * GAMMA_0) else {
        return Ok(Attempt::NewtonFailed);
    };
    let combination = z[0] * RADAU_ERROR_WEIGHTS[0]
        + z[1] * RADAU_ERROR_WEIGHTS[1]
        + z[2] * RADAU_ERROR_WEIGHTS[2];
    let scale = y.zip_map(&y1, |a, b| a.abs().max(b.abs()));
    let estimate = |slope: &SVector<f64, N>| {
        let local = (slope * h + combination) * GAMMA_0;
        norm(&filter.solve(&local).unwrap_or(local), &scale, settings)
    };
    let mut error = estimate(f);
    if careful && error >= 1.0 {
        let local = (f * h + combination) * GAMMA_0;
        let probe = y + filter.solve(&local).unwrap_or(local);
        work.rate_evaluations += 1;
        match rate.rate(t, &probe) {
            Ok(slope) => error = estimate(&slope),
            Err(RateError::Outside) => {}
            Err(RateError::Failed(e)) => return Err(e),
        }
    }
    Ok(Attempt::Done {
        y1,
        f1,
        stages: Some(z),
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

    const METHODS: [Method; 2] = [Method::Sdirk4, Method::RadauIia5];

    fn settings(relative: f64) -> Settings {
        Settings {
            method: Method::Sdirk4,
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

    #[test]
    fn radau_iia_is_the_order_5_collocation_method_with_its_constants() {
        // B(5): Σbᵢcᵢ^(k−1) = 1/k, k ≤ 5 (b = A's last row: stiffly accurate); C(3): Σⱼaᵢⱼcⱼ^(k−1)
        // = cᵢ^k/k, k ≤ 3 (stage order 3).
        let (a, c) = (RADAU_A, RADAU_C);
        for k in 1..=5 {
            let got: f64 = (0..3).map(|i| a[2][i] * c[i].powi(k - 1)).sum();
            assert!((got - 1.0 / k as f64).abs() < 1e-14, "B({k})");
        }
        for i in 0..3 {
            for k in 1..=3 {
                let got: f64 = (0..3).map(|j| a[i][j] * c[j].powi(k - 1)).sum();
                assert!(
                    (got - c[i].powi(k) / k as f64).abs() < 1e-14,
                    "C({k}) row {i}"
                );
            }
            // The last row of A⁻¹ times A is the last unit row.
            let e: f64 = (0..3).map(|j| A_INVERSE_LAST_ROW[j] * a[j][i]).sum();
            assert!(
                (e - f64::from(u8::from(i == 2))).abs() < 1e-13,
                "A⁻¹ row {i}"
            );
        }
        // γ₀ is an eigenvalue of A: det(A − γ₀I) = 0.
        let m = |i: usize, j: usize| a[i][j] - if i == j { GAMMA_0 } else { 0.0 };
        let det = m(0, 0) * (m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1))
            - m(0, 1) * (m(1, 0) * m(2, 2) - m(1, 2) * m(2, 0))
            + m(0, 2) * (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0));
        assert!(det.abs() < 1e-15, "{det}");
    }

    fn harmonic(method: Method, t_end: f64, tol: f64) -> (Integrated<2>, f64) {
        let mut rate = |_t: f64, y: &Vector2<f64>| -> Result<Vector2<f64>, RateError<()>> {
            Ok(Vector2::new(y[1], -y[0]))
        };
        let run = integrate(
            &mut rate,
            0.0,
            Vector2::new(1.0, 0.0),
            t_end,
            &Settings {
                method,
                ..settings(tol)
            },
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
        for method in METHODS {
            let (loose, e_loose) = harmonic(method, t_end, 1e-5);
            let (tight, e_tight) = harmonic(method, t_end, 1e-9);
            assert!(e_loose < 1e-2, "{method:?} {e_loose}");
            assert!(e_tight < 1e-6, "{method:?} {e_tight}");
            assert!(e_tight < e_loose / 100.0, "{method:?}");
            assert!(tight.work.accepted > 2 * loose.work.accepted, "{method:?}");
            assert_eq!(loose.report.stop_reason, StopReason::Converged);
            assert_eq!(loose.report.method, method.name());
            assert_eq!(
                loose
                    .report
                    .time_integration
                    .as_ref()
                    .map(|t| t.relative_tolerance),
                Some(1e-5)
            );
        }
    }

    #[test]
    fn a_stiff_decay_is_crossed_in_few_steps() {
        // y' = −10⁶(y − cos t): explicit methods need h < 2·10⁻⁶; an L-stable one follows
        // the slow solution y ≈ cos t + 10⁻⁶ sin t in tens of steps.
        let mut rate = |t: f64, y: &Vector1<f64>| -> Result<Vector1<f64>, RateError<()>> {
            Ok(Vector1::new(-1e6 * (y[0] - t.cos())))
        };
        for method in METHODS {
            let run = integrate(
                &mut rate,
                0.0,
                Vector1::new(0.0),
                2.0,
                &Settings {
                    method,
                    ..settings(1e-6)
                },
                |_| Flow::Continue,
                &Budget::unlimited(),
            )
            .unwrap();
            assert!((run.y[0] - (2f64.cos() + 1e-6 * 2f64.sin())).abs() < 1e-6);
            assert!(run.work.accepted < 200, "{method:?} {:?}", run.work);
        }
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
        for method in METHODS {
            let failure = integrate(
                &mut rate,
                0.0,
                Vector1::new(0.0),
                5.0,
                &Settings {
                    method,
                    ..settings(1e-6)
                },
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
                "{method:?}: {t} {y}"
            );
        }
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
