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

/// [`brent`] over an f whose evaluations can fail (a nested solve): the first failure ends the
/// search and is returned as it was, else the search's own outcome (as `E`).
pub fn brent_fallible<E: From<RootError>>(
    mut f: impl FnMut(f64) -> Result<f64, E>,
    a: f64,
    b: f64,
    stop: Stopping,
) -> Result<Root, E> {
    let mut failure = None;
    let root = brent(
        |x| match f(x) {
            Ok(v) => v,
            Err(e) => {
                failure.get_or_insert(e);
                f64::NAN
            }
        },
        a,
        b,
        stop,
    );
    match failure {
        Some(e) => Err(e),
        None => root.map_err(E::from),
    }
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
    }
}
