//! Bracketed one-dimensional minimisation: Brent's method (golden-section steps with parabolic
//! interpolation where it is safe), which converges superlinearly on smooth functions and never
//! leaves the bracket (Brent 1973, *Algorithms for Minimization without Derivatives*, ch. 5).

use super::driver::{Budget, Driver, Verdict};
use crate::fidelity::IterationUnit;

/// Iterations of [`brent_minimise`]: each shrinks the bracket, at worst every other one by the
/// golden ratio, so 100 take any bracket far below a double's resolution of its ends.
const MAX_ITERATIONS: u32 = 100;

/// The minimum of f on [a, b] to an absolute tolerance `x_tolerance` in x: (x, f(x)). Runs
/// under the solver driver with a cap of 100 iterations; a capped run (a tolerance below the
/// bracket's round-off) still returns the best point found, which is then as good as the
/// doubles allow.
pub fn brent_minimise(
    mut f: impl FnMut(f64) -> f64,
    a: f64,
    b: f64,
    x_tolerance: f64,
) -> (f64, f64) {
    // (3 − √5)/2, the golden-section fraction.
    const GOLDEN: f64 = 0.381_966_011_250_105_1;
    let (mut a, mut b) = (a.min(b), a.max(b));
    let mut x = a + GOLDEN * (b - a);
    let (mut w, mut v) = (x, x);
    let mut fx = f(x);
    let (mut fw, mut fv) = (fx, fx);
    let (mut d, mut e) = (0.0f64, 0.0f64);
    let driver = Driver::new(
        "brent_minimise",
        IterationUnit::RootSearchSteps,
        MAX_ITERATIONS,
        &Budget::unlimited(),
    );
    // The verdict carries no value: the minimum is the state (x, fx) the loop leaves.
    let _capped_or_converged = driver.run(|_| {
        let middle = 0.5 * (a + b);
        let tol1 = x_tolerance;
        let tol2 = 2.0 * tol1;
        if (x - middle).abs() <= tol2 - 0.5 * (b - a) {
            return Verdict::Converged((), b - a);
        }
        let mut golden = true;
        if e.abs() > tol1 {
            // The parabola through (x, fx), (w, fw), (v, fv).
            let r = (x - w) * (fx - fv);
            let mut q = (x - v) * (fx - fw);
            let mut p = (x - v) * q - (x - w) * r;
            q = 2.0 * (q - r);
            if q > 0.0 {
                p = -p;
            } else {
                q = -q;
            }
            let previous = e;
            e = d;
            if p.abs() < (0.5 * q * previous).abs() && p > q * (a - x) && p < q * (b - x) {
                d = p / q;
                let u = x + d;
                if u - a < tol2 || b - u < tol2 {
                    d = tol1.copysign(middle - x);
                }
                golden = false;
            }
        }
        if golden {
            e = if x >= middle { a - x } else { b - x };
            d = GOLDEN * e;
        }
        let u = if d.abs() >= tol1 {
            x + d
        } else {
            x + tol1.copysign(d)
        };
        let fu = f(u);
        if fu <= fx {
            if u >= x {
                a = x;
            } else {
                b = x;
            }
            (v, fv, w, fw, x, fx) = (w, fw, x, fx, u, fu);
        } else {
            if u < x {
                a = u;
            } else {
                b = u;
            }
            if fu <= fw || w == x {
                (v, fv, w, fw) = (w, fw, u, fu);
            } else if fu <= fv || v == x || v == w {
                (v, fv) = (u, fu);
            }
        }
        // The bracket's width is the residual; a NaN from f leaves the bracket unchanged.
        Verdict::Continue((b - a).abs().min(f64::MAX))
    });
    (x, fx)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_smooth_and_edge_minima_in_few_evaluations() {
        let mut calls = 0;
        let (x, fx) = brent_minimise(
            |x| {
                calls += 1;
                (x - 0.3).powi(2) * (1.0 + x) - 2.0
            },
            0.0,
            1.0,
            1e-9,
        );
        assert!((x - 0.3).abs() < 1e-8 && (fx + 2.0).abs() < 1e-15);
        assert!(calls < 20, "{calls} evaluations");
        // A minimum at the bracket's end is approached to within the tolerance.
        let (x, _) = brent_minimise(|x| x, 0.0, 2.0, 1e-7);
        assert!(x < 1e-6);
    }
}
