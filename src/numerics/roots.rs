//! Bracketed root finding. Brent's method (inverse quadratic interpolation with bisection as a
//! safeguard): it never leaves the bracket, so it converges whenever f changes sign on [a, b].
//! Where only one end of the bracket is known, [`grow_bracket`] finds the other by doubling.

use super::driver::{Budget, Converged, Driver, Stopped, Verdict};
use crate::fidelity::{IterationUnit, SolverReport};

/// When to stop: `x_tolerance` on the root (absolute), with an iteration cap that is never
/// unbounded.
#[derive(Debug, Clone, Copy)]
pub struct Stopping {
    pub x_tolerance: f64,
    pub max_iterations: u32,
}

/// How a root search ended without a root.
#[derive(Debug, Clone, PartialEq)]
pub enum RootError {
    /// f(a) and f(b) have the same sign: there is no root in the bracket to find.
    NoSignChange { a: f64, fa: f64, b: f64, fb: f64 },
    /// f returned NaN or ±∞ at x.
    NonFinite { x: f64 },
    /// The cap was reached; the last bracket width is the residual.
    NotConverged { iterations: u32, width: f64 },
}

/// [`grow_bracket`] found no end: f stayed ≤ 0 while the upper end was doubled
/// [`MAX_DOUBLINGS`] times (or until it overflowed).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NoBracket {
    pub hi: f64,
    pub doublings: u32,
}

/// Doublings [`grow_bracket`] allows: 2²⁰⁰ times the first guess spans any scale a problem in
/// f64 has, so a function still ≤ 0 there has no root to find.
pub const MAX_DOUBLINGS: u32 = 200;

/// A root and the work it took: the driver's report (method `brent`; rename it with
/// [`SolverReport::named`] where the search is the room's headline solve).
#[derive(Debug, Clone, PartialEq)]
#[must_use]
pub struct Root {
    pub x: f64,
    pub iterations: u32,
    pub report: SolverReport,
}

/// Find x in [a, b] with f(x) = 0, given f(a)·f(b) ≤ 0 (Brent 1973, *Algorithms for
/// Minimization without Derivatives*, ch. 4).
pub fn brent(
    mut f: impl FnMut(f64) -> f64,
    a: f64,
    b: f64,
    stop: Stopping,
) -> Result<Root, RootError> {
    let (fa, fb) = (f(a), f(b));
    brent_bracketed(f, (a, fa), (b, fb), stop)
}

/// Runs `search` over f's values, the first failed evaluation of f (a nested solve) standing
/// for the search's outcome: `Err` with it, else `Ok` with what the search found.
fn with_failures<E>(
    mut f: impl FnMut(f64) -> Result<f64, E>,
    search: impl FnOnce(&mut dyn FnMut(f64) -> f64) -> Result<Root, RootError>,
) -> Result<Result<Root, RootError>, E> {
    let mut failure = None;
    let root = search(&mut |x| match f(x) {
        Ok(v) => v,
        Err(e) => {
            failure.get_or_insert(e);
            f64::NAN
        }
    });
    failure.map_or(Ok(root), Err)
}

/// [`brent`] over an f whose evaluations can fail: the first failure ends the search and is
/// returned as it was, else the search's own outcome (as `E`).
pub fn brent_fallible<E: From<RootError>>(
    f: impl FnMut(f64) -> Result<f64, E>,
    a: f64,
    b: f64,
    stop: Stopping,
) -> Result<Root, E> {
    brent_outcome(f, a, b, stop)?.map_err(E::from)
}

/// [`brent`] over an f whose evaluations can fail: `Err` with the first failure, else `Ok`
/// with the search's outcome, for the caller to read (as [`secant_fallible`]'s).
pub fn brent_outcome<E>(
    f: impl FnMut(f64) -> Result<f64, E>,
    a: f64,
    b: f64,
    stop: Stopping,
) -> Result<Result<Root, RootError>, E> {
    with_failures(f, |g| brent(g, a, b, stop))
}

/// [`secant_bracketed`] over an f whose evaluations can fail: `Err` with the first failure,
/// else `Ok` with the search's outcome, for the caller to read (a bracket without a sign change
/// is often a refusal of its own).
pub fn secant_fallible<E>(
    f: impl FnMut(f64) -> Result<f64, E>,
    lo: (f64, f64),
    hi: (f64, f64),
    stop: Stopping,
) -> Result<Result<Root, RootError>, E> {
    with_failures(f, |g| secant_bracketed(g, lo, hi, stop))
}

/// [`brent`] from a bracket whose ends the caller has already evaluated (f(a), f(b)), for a
/// function that costs a solve: the ends are not evaluated again.
pub fn brent_bracketed(
    mut f: impl FnMut(f64) -> f64,
    (a, fa): (f64, f64),
    (b, fb): (f64, f64),
    stop: Stopping,
) -> Result<Root, RootError> {
    let (mut a, mut b) = (a, b);
    let (mut fa, mut fb) = (fa, fb);
    finite_ends((a, fa), (b, fb))?;
    let driver = Driver::new(
        "brent",
        IterationUnit::RootSearchSteps,
        stop.max_iterations,
        &Budget::unlimited(),
    );
    for (x, fx) in [(a, fa), (b, fb)] {
        if fx == 0.0 {
            let done = driver.converged_at_start(x, 0.0);
            return Ok(Root {
                x,
                iterations: 0,
                report: done.report,
            });
        }
    }
    if fa.signum() == fb.signum() {
        return Err(RootError::NoSignChange { a, fa, b, fb });
    }
    let (mut c, mut fc) = (a, fa);
    let mut d = b - a;
    let mut e = d;
    let mut failure = None;
    // One driver iteration: test the bracket, then (if open) one interpolation or bisection
    // step with its evaluation. The driver's cap is the search's; there is no deadline here
    // (each step is one evaluation of f, which polls its own).
    let run = driver.run(|_| {
        if fb.signum() == fc.signum() {
            c = a;
            fc = fa;
            d = b - a;
            e = d;
        }
        if fc.abs() < fb.abs() {
            (a, b, c) = (b, c, b);
            (fa, fb, fc) = (fb, fc, fb);
        }
        let tol = 2.0 * f64::EPSILON * b.abs() + 0.5 * stop.x_tolerance;
        let m = 0.5 * (c - b);
        if m.abs() <= tol || fb == 0.0 {
            return Verdict::Converged(b, (c - b).abs());
        }
        if e.abs() >= tol && fa.abs() > fb.abs() {
            let s = fb / fa;
            let (mut p, mut q) = if a == c {
                (2.0 * m * s, 1.0 - s)
            } else {
                let q = fa / fc;
                let r = fb / fc;
                (
                    s * (2.0 * m * q * (q - r) - (b - a) * (r - 1.0)),
                    (q - 1.0) * (r - 1.0) * (s - 1.0),
                )
            };
            if p > 0.0 {
                q = -q;
            } else {
                p = -p;
            }
            if 2.0 * p < (3.0 * m * q - (tol * q).abs()).min((e * q).abs()) {
                e = d;
                d = p / q;
            } else {
                d = m;
                e = m;
            }
        } else {
            d = m;
            e = m;
        }
        a = b;
        fa = fb;
        b += if d.abs() > tol { d } else { tol.copysign(m) };
        fb = f(b);
        if !fb.is_finite() {
            failure = Some(RootError::NonFinite { x: b });
            return Verdict::Diverged(f64::NAN);
        }
        Verdict::Continue((c - b).abs())
    });
    finished(run, failure)
}

/// [`brent_bracketed`]'s contract for a nearly linear f that costs a solve: secant steps from
/// the two latest points, a bisection wherever the secant leaves the bracket (which is kept, so
/// the search cannot leave it). It stops when the next step would be below `x_tolerance` and
/// returns the **last evaluated** x, so the caller's last solve is the answer's (Brent's last
/// point need not be, and its bracket closing costs one or two evaluations more).
pub fn secant_bracketed(
    mut f: impl FnMut(f64) -> f64,
    (a, fa): (f64, f64),
    (b, fb): (f64, f64),
    stop: Stopping,
) -> Result<Root, RootError> {
    finite_ends((a, fa), (b, fb))?;
    let driver = Driver::new(
        "secant",
        IterationUnit::RootSearchSteps,
        stop.max_iterations,
        &Budget::unlimited(),
    );
    if fa.signum() == fb.signum() && fa != 0.0 && fb != 0.0 {
        return Err(RootError::NoSignChange { a, fa, b, fb });
    }
    let (mut lo, mut flo) = (a, fa);
    let (mut hi, mut fhi) = (b, fb);
    // The latest point is the end nearer the root in f.
    let ((mut x0, mut f0), (mut x1, mut f1)) = if fa.abs() < fb.abs() {
        ((b, fb), (a, fa))
    } else {
        ((a, fa), (b, fb))
    };
    let mut failure = None;
    let run = driver.run(|_| {
        if f1 == 0.0 {
            return Verdict::Converged(x1, 0.0);
        }
        let mut x = x1 - f1 * (x1 - x0) / (f1 - f0);
        let (left, right) = (lo.min(hi), lo.max(hi));
        if !(x > left && x < right) {
            x = 0.5 * (lo + hi);
        }
        if (x - x1).abs() <= stop.x_tolerance {
            return Verdict::Converged(x1, (x - x1).abs());
        }
        let fx = f(x);
        if !fx.is_finite() {
            failure = Some(RootError::NonFinite { x });
            return Verdict::Diverged(f64::NAN);
        }
        if fx.signum() == flo.signum() {
            (lo, flo) = (x, fx);
        } else {
            (hi, fhi) = (x, fx);
        }
        ((x0, f0), (x1, f1)) = ((x1, f1), (x, fx));
        Verdict::Continue((hi - lo).abs().min((fhi - flo).abs()))
    });
    finished(run, failure)
}

/// Both ends of a bracket must be finite before a search starts.
fn finite_ends((a, fa): (f64, f64), (b, fb): (f64, f64)) -> Result<(), RootError> {
    for (x, fx) in [(a, fa), (b, fb)] {
        if !fx.is_finite() {
            return Err(RootError::NonFinite { x });
        }
    }
    Ok(())
}

/// A bracketed search's outcome: the root, or why not (the evaluation that failed, else the cap).
fn finished(
    run: Result<Converged<f64>, Stopped>,
    failure: Option<RootError>,
) -> Result<Root, RootError> {
    match run {
        Ok(done) => Ok(Root {
            x: done.value,
            iterations: done.report.iterations,
            report: done.report,
        }),
        Err(stopped) => Err(failure.unwrap_or(RootError::NotConverged {
            iterations: stopped.report.iterations,
            width: stopped.report.residual.unwrap_or(f64::NAN),
        })),
    }
}

/// The upper end of a bracket [0, hi] of an f that is ≤ 0 at 0 and turns positive somewhere
/// beyond: `hi` is doubled (at most [`MAX_DOUBLINGS`] times) until f(hi) > 0. Used before
/// [`brent`] on monotone balances whose scale is known only roughly (a load balance against a
/// displacement: a first guess from the characteristic deflection, then doubled).
pub fn grow_bracket(mut f: impl FnMut(f64) -> f64, mut hi: f64) -> Result<f64, NoBracket> {
    let mut doublings = 0;
    while f(hi) <= 0.0 {
        hi *= 2.0;
        doublings += 1;
        if doublings > MAX_DOUBLINGS || !hi.is_finite() {
            return Err(NoBracket { hi, doublings });
        }
    }
    Ok(hi)
}

/// Where [`broyden2`] ended: the root (the last point it evaluated and accepted), the Jacobian
/// estimate there, and the evaluations it made.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Broyden2 {
    pub x: [f64; 2],
    pub jacobian: [[f64; 2]; 2],
    pub evaluations: u32,
}

/// How far [`broyden2`] may go.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Steps {
    /// The longest step per component.
    pub max_step: [f64; 2],
    /// The box each component stays in.
    pub bounds: [(f64, f64); 2],
    /// Converged when the next quasi-Newton step is shorter than this in every component.
    pub tolerance: [f64; 2],
    pub max_evaluations: u32,
}

/// A root of two equations f(x) = 0 by Broyden's method (Broyden 1965, the rank-one update
/// J ← J + (Δf − J Δx) Δxᵀ/|Δx|²), from x0 where f = f0 and a Jacobian estimate j0: each step is
/// the quasi-Newton step −J⁻¹f, limited per component, kept in the bounds and halved (at most
/// four times) while the trial point is infeasible (`f` gives None) or does not lower the
/// residual scaled by j0's diagonal (|f₁/j0₁₁| + |f₂/j0₂₂|: each equation in its own variable's
/// units). The root is the last accepted point once the next step is below the tolerance.
/// `Ok(None)` when it does not settle (capped, a singular estimate, or halving fails): the
/// caller's safer search takes over; an error of `f` ends it.
pub fn broyden2<E>(
    mut f: impl FnMut([f64; 2]) -> Result<Option<[f64; 2]>, E>,
    x0: [f64; 2],
    f0: [f64; 2],
    j0: [[f64; 2]; 2],
    steps: Steps,
) -> Result<Option<Broyden2>, E> {
    let scale = [j0[0][0].abs(), j0[1][1].abs()];
    if !(scale[0] > 0.0 && scale[1] > 0.0) {
        return Ok(None);
    }
    let merit = |v: [f64; 2]| (v[0] / scale[0]).abs() + (v[1] / scale[1]).abs();
    let (mut x, mut fx, mut j) = (x0, f0, j0);
    let mut evaluations = 0;
    while evaluations < steps.max_evaluations {
        let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
        if !(det.is_finite() && det != 0.0) {
            return Ok(None);
        }
        let newton = [
            -(j[1][1] * fx[0] - j[0][1] * fx[1]) / det,
            -(j[0][0] * fx[1] - j[1][0] * fx[0]) / det,
        ];
        if newton[0].abs() < steps.tolerance[0] && newton[1].abs() < steps.tolerance[1] {
            return Ok(Some(Broyden2 {
                x,
                jacobian: j,
                evaluations,
            }));
        }
        let step: [f64; 2] =
            std::array::from_fn(|k| newton[k].clamp(-steps.max_step[k], steps.max_step[k]));
        let mut accepted = None;
        let mut lambda = 1.0;
        for _ in 0..5 {
            let trial: [f64; 2] = std::array::from_fn(|k| {
                (x[k] + lambda * step[k]).clamp(steps.bounds[k].0, steps.bounds[k].1)
            });
            evaluations += 1;
            match f(trial)? {
                Some(ft) if ft.iter().all(|v| v.is_finite()) && merit(ft) < merit(fx) => {
                    accepted = Some((trial, ft));
                    break;
                }
                _ if evaluations >= steps.max_evaluations => break,
                _ => lambda *= 0.5,
            }
        }
        let Some((xn, fn_)) = accepted else {
            return Ok(None);
        };
        let dx = [xn[0] - x[0], xn[1] - x[1]];
        let norm = dx[0] * dx[0] + dx[1] * dx[1];
        if norm == 0.0 {
            return Ok(None);
        }
        for r in 0..2 {
            let predicted = j[r][0] * dx[0] + j[r][1] * dx[1];
            let miss = fn_[r] - fx[r] - predicted;
            for c in 0..2 {
                j[r][c] += miss * dx[c] / norm;
            }
        }
        (x, fx) = (xn, fn_);
    }
    Ok(None)
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    const STOP: Stopping = Stopping {
        x_tolerance: 1e-12,
        max_iterations: 100,
    };

    #[test]
    fn the_secant_finds_the_cube_root_of_two_in_few_steps_and_stays_in_its_bracket() {
        let mut evaluations = 0;
        let r = secant_bracketed(
            |x| {
                evaluations += 1;
                assert!((0.0..=2.0).contains(&x), "{x}");
                x * x * x - 2.0
            },
            (0.0, -2.0),
            (2.0, 6.0),
            STOP,
        )
        .unwrap();
        assert!((r.x - 2f64.cbrt()).abs() < 1e-11, "{}", r.x);
        assert!(evaluations <= 12, "{evaluations}");
        assert_eq!(
            secant_bracketed(|x| x, (1.0, 1.0), (2.0, 2.0), STOP),
            Err(RootError::NoSignChange {
                a: 1.0,
                fa: 1.0,
                b: 2.0,
                fb: 2.0
            })
        );
    }

    #[test]
    fn finds_the_cube_root_of_two() {
        let r = brent(|x| x * x * x - 2.0, 0.0, 2.0, STOP).unwrap();
        assert!((r.x - 2f64.cbrt()).abs() < 1e-11);
    }

    #[test]
    fn refuses_a_bracket_without_sign_change() {
        let r = brent(|x| x * x + 1.0, -1.0, 1.0, STOP);
        assert!(matches!(r, Err(RootError::NoSignChange { .. })));
    }

    #[test]
    fn reports_a_capped_run_as_not_converged() {
        let stop = Stopping {
            x_tolerance: 0.0,
            max_iterations: 3,
        };
        let r = brent(|x| x.exp() - 5.0, -10.0, 10.0, stop);
        assert!(matches!(
            r,
            Err(RootError::NotConverged { iterations: 3, .. })
        ));
    }

    #[test]
    fn grows_a_bracket_then_brent_finds_the_root() {
        let f = |x: f64| x - 1e6;
        let hi = grow_bracket(f, 1e-3).unwrap();
        assert!(hi > 1e6 && hi <= 2e6 + 1.0, "{hi}");
        let r = brent(f, 0.0, hi, STOP).unwrap();
        assert!((r.x - 1e6).abs() < 1e-6);
        // Already positive at the first guess: the guess is the bracket.
        assert_eq!(grow_bracket(f, 4e6).unwrap(), 4e6);
    }

    #[test]
    fn refuses_to_grow_without_end() {
        let r = grow_bracket(|_| -1.0, 1.0);
        assert!(matches!(r, Err(NoBracket { doublings: 201, .. })));
        assert!(grow_bracket(|_| 0.0, 1e300).is_err());
    }

    proptest! {
        #[test]
        fn root_stays_in_bracket_and_solves(k in -50.0f64..50.0, a in -100.0f64..-60.0, b in 60.0f64..100.0) {
            let r = brent(|x| (x - k).tanh(), a, b, STOP).unwrap();
            prop_assert!(r.x >= a && r.x <= b);
            prop_assert!((r.x - k).abs() < 1e-9);
        }
    }

    /// `brent_fallible` returns a root where every evaluation succeeds, and the first failure
    /// as it was where one does not (at a bracket's end, or in the middle of the search).
    #[test]
    fn fallible_brent_returns_the_first_failure() {
        let stop = Stopping {
            x_tolerance: 1e-14,
            max_iterations: 100,
        };
        let root = brent_fallible(|x: f64| Ok::<f64, RootError>(x * x - 2.0), 0.0, 2.0, stop);
        assert!((root.unwrap().x - 2f64.sqrt()).abs() < 1e-13);
        let fail = |at: f64| RootError::NonFinite { x: at };
        let end = brent_fallible(
            |x: f64| if x > 1.5 { Err(fail(x)) } else { Ok(x - 1.0) },
            0.0,
            2.0,
            stop,
        );
        assert_eq!(end.unwrap_err(), fail(2.0));
        let mut calls = 0;
        let middle = brent_fallible(
            |x: f64| {
                calls += 1;
                if calls == 3 {
                    Err(fail(x))
                } else {
                    Ok(x - 0.3)
                }
            },
            0.0,
            2.0,
            stop,
        );
        assert!(matches!(middle, Err(RootError::NonFinite { .. })));
        let none = brent_fallible(|x: f64| Ok::<f64, RootError>(x + 1.0), 0.0, 2.0, stop);
        assert!(matches!(none, Err(RootError::NoSignChange { .. })));
        // The secant's form keeps the search's own outcome apart from the failure.
        let f = |x: f64| if x > 1.5 { Err("failed") } else { Ok(x - 1.0) };
        let inner = secant_fallible(f, (0.0, -1.0), (1.2, 0.2), stop).unwrap();
        assert!((inner.unwrap().x - 1.0).abs() < 1e-12);
        // Its first step from (0, −1) and (2, 1) lands on 1, where this f fails.
        let near_one = |x: f64| {
            if (x - 1.0).abs() < 0.1 {
                Err("failed")
            } else {
                Ok(x - 1.0)
            }
        };
        let outer = secant_fallible(near_one, (0.0, -1.0), (2.0, 1.0), stop);
        assert_eq!(outer.unwrap_err(), "failed");
        let apart = secant_fallible(f, (0.0, -1.0), (0.5, -0.5), stop).unwrap();
        assert!(matches!(apart, Err(RootError::NoSignChange { .. })));
    }

    #[test]
    fn broyden2_finds_a_coupled_root_and_hands_over_where_it_cannot() {
        // x² + y − 3 = 0, x − y³ + 7 = 0: the root (1, 2), from a diagonal estimate.
        let f = |[x, y]: [f64; 2]| -> Result<Option<[f64; 2]>, ()> {
            Ok(Some([x * x + y - 3.0, x - y * y * y + 7.0]))
        };
        let steps = Steps {
            max_step: [1.0, 1.0],
            bounds: [(-10.0, 10.0), (-10.0, 10.0)],
            tolerance: [1e-12, 1e-12],
            max_evaluations: 40,
        };
        let x0 = [1.3, 1.8];
        let j0 = [[2.6, 0.0], [0.0, -9.7]];
        let found = broyden2(f, x0, f(x0).unwrap().unwrap(), j0, steps)
            .unwrap()
            .expect("a root");
        assert!(
            (found.x[0] - 1.0).abs() < 1e-10 && (found.x[1] - 2.0).abs() < 1e-10,
            "{found:?}"
        );
        assert!(found.evaluations < 15, "{found:?}");
        // Infeasible everywhere but the start: it hands over (None), it does not fail.
        let walled = |_: [f64; 2]| -> Result<Option<[f64; 2]>, ()> { Ok(None) };
        assert_eq!(broyden2(walled, x0, [1.0, 1.0], j0, steps), Ok(None));
        // An error of the function ends the search with it.
        let failing = |_: [f64; 2]| -> Result<Option<[f64; 2]>, &str> { Err("deadline") };
        assert_eq!(
            broyden2(failing, x0, [1.0, 1.0], j0, steps),
            Err("deadline")
        );
    }
}
