//! Quadrature: fixed Gauss–Legendre rules, and adaptive Gauss–Kronrod (7–15 points) with an
//! error estimate for integrands that cost a solve each.

use std::f64::consts::PI;

use super::driver::{Budget, Counter, Driver, Stopped, Verdict};
use crate::fidelity::{IterationUnit, SolverReport};

/// Gauss–Legendre nodes and weights on [−1, 1] (Newton on P_n from Tricomi's guesses).
pub fn gauss_legendre(n: usize) -> Vec<(f64, f64)> {
    (0..n)
        .map(|i| {
            let mut x = (PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            let mut derivative = 1.0;
            for _ in 0..100 {
                let (mut p0, mut p1) = (1.0, x);
                for k in 2..=n {
                    let p2 = ((2 * k - 1) as f64 * x * p1 - (k - 1) as f64 * p0) / k as f64;
                    p0 = p1;
                    p1 = p2;
                }
                derivative = n as f64 * (x * p1 - p0) / (x * x - 1.0);
                let step = p1 / derivative;
                x -= step;
                if step.abs() < 1e-15 {
                    break;
                }
            }
            (x, 2.0 / ((1.0 - x * x) * derivative * derivative))
        })
        .collect()
}

/// Kronrod nodes on [0, 1] of the 15-point rule (the odd ones, 1, 3, …, 13, are the 7-point
/// Gauss nodes), with the Kronrod weights and, for the Gauss nodes, the Gauss weights
/// (Piessens et al., *QUADPACK*, 1983, `qk15`). The rule is symmetric about 0.
const KRONROD_NODES: [f64; 8] = [
    0.991_455_371_120_812_6,
    0.949_107_912_342_758_5,
    0.864_864_423_359_769_1,
    0.741_531_185_599_394_4,
    0.586_087_235_467_691_1,
    0.405_845_151_377_397_2,
    0.207_784_955_007_898_5,
    0.0,
];
const KRONROD_WEIGHTS: [f64; 8] = [
    0.022_935_322_010_529_22,
    0.063_092_092_629_978_55,
    0.104_790_010_322_250_2,
    0.140_653_259_715_525_9,
    0.169_004_726_639_267_9,
    0.190_350_578_064_785_4,
    0.204_432_940_075_298_9,
    0.209_482_141_084_727_8,
];
/// Gauss weights of the 7-point rule at Kronrod nodes 1, 3, 5 and 7 (the centre).
const GAUSS_WEIGHTS: [f64; 4] = [
    0.129_484_966_168_869_7,
    0.279_705_391_489_276_7,
    0.381_830_050_505_118_9,
    0.417_959_183_673_469_4,
];

/// When an adaptive integral is good enough: its estimated error at most
/// max(`relative` |I|, `absolute`), within at most `max_bisections` bisections after the
/// `initial_panels` equal panels it starts from (at least 1; more where the caller wants the
/// running integral at their ends).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tolerance {
    pub relative: f64,
    pub absolute: f64,
    pub max_bisections: u32,
    pub initial_panels: u32,
}

/// An adaptive integral: its value, the estimated absolute error, the panels it was summed
/// over (a, b, ∫ₐᵇ f) in order of a, and the driver's report (iterations: panels built;
/// evaluations: integrand calls; residual: the estimated error relative to the value).
#[derive(Debug, Clone, PartialEq)]
#[must_use]
pub struct Integral {
    pub value: f64,
    pub error: f64,
    pub panels: Vec<(f64, f64, f64)>,
    pub report: SolverReport,
}

/// Why an adaptive integral has no value: the integrand failed (its error), or the driver
/// stopped (panel cap without meeting the tolerance, deadline, a non-finite integrand).
#[derive(Debug, Clone, PartialEq)]
pub enum IntegralError<E> {
    Integrand(E),
    Stopped(Stopped),
}

/// One panel [a, b]: its Kronrod value and |Kronrod − Gauss| as its error.
#[derive(Debug, Clone, Copy)]
struct Panel {
    a: f64,
    b: f64,
    value: f64,
    error: f64,
}

/// The 15-point Kronrod and 7-point Gauss sums on [a, b] (15 evaluations).
fn panel<E>(
    f: &mut impl FnMut(f64) -> Result<f64, E>,
    a: f64,
    b: f64,
    counter: &mut Counter,
) -> Result<Panel, E> {
    let (centre, half) = (0.5 * (a + b), 0.5 * (b - a));
    let (mut kronrod, mut gauss) = (0.0, 0.0);
    for (k, (&x, &w)) in KRONROD_NODES.iter().zip(&KRONROD_WEIGHTS).enumerate() {
        let values = if x == 0.0 {
            let v = f(centre)?;
            counter.evaluated(1);
            v
        } else {
            let v = f(centre - half * x)? + f(centre + half * x)?;
            counter.evaluated(2);
            v
        };
        kronrod += w * values;
        if k % 2 == 1 {
            gauss += GAUSS_WEIGHTS[k / 2] * values;
        }
    }
    Ok(Panel {
        a,
        b,
        value: kronrod * half,
        error: ((kronrod - gauss) * half).abs(),
    })
}

/// ∫ₐᵇ f by adaptive Gauss–Kronrod 7–15: start with `initial_panels` equal panels, then bisect
/// the panel with the largest error estimate |K15 − G7| until the sum of the estimates meets
/// `tolerance` (the estimate is conservative: K15 is far more accurate than G7 on a smooth
/// panel). The first iteration builds the initial panels (15 evaluations each), each later one
/// is one bisection (30 evaluations), under the solver driver: the bisection cap,
/// the deadline and a non-finite integrand stop it. Meant for integrands that cost a solve
/// each (a film's load at one eccentricity): the error estimate says what the evaluations bought.
pub fn adaptive_gauss_kronrod<E>(
    mut f: impl FnMut(f64) -> Result<f64, E>,
    a: f64,
    b: f64,
    tolerance: Tolerance,
    budget: &Budget,
) -> Result<Integral, IntegralError<E>> {
    let mut failure = None;
    let mut panels: Vec<Panel> = Vec::new();
    let driver = Driver::new(
        "adaptive_gauss_kronrod_7_15",
        IterationUnit::Evaluations,
        tolerance.max_bisections.saturating_add(1),
        budget,
    );
    let initial = tolerance.initial_panels.max(1);
    let run = driver.run(|counter| {
        let step = if panels.is_empty() {
            (0..initial).try_for_each(|k| {
                let at = |k: u32| a + (b - a) * f64::from(k) / f64::from(initial);
                let end = if k + 1 == initial { b } else { at(k + 1) };
                panel(&mut f, at(k), end, counter).map(|p| panels.push(p))
            })
        } else {
            // Bisect the worst panel.
            let worst = panels
                .iter()
                .enumerate()
                .max_by(|x, y| x.1.error.total_cmp(&y.1.error))
                .map_or(0, |w| w.0);
            let p = panels.swap_remove(worst);
            let mid = 0.5 * (p.a + p.b);
            panel(&mut f, p.a, mid, counter)
                .and_then(|left| Ok((left, panel(&mut f, mid, p.b, counter)?)))
                .map(|(left, right)| panels.extend([left, right]))
        };
        if let Err(e) = step {
            failure = Some(e);
            return Verdict::Stalled(f64::NAN);
        }
        let value: f64 = panels.iter().map(|p| p.value).sum();
        let error: f64 = panels.iter().map(|p| p.error).sum();
        if !(value.is_finite() && error.is_finite()) {
            return Verdict::Diverged(f64::NAN);
        }
        // The report's residual is the error relative to the integral (the absolute one has
        // the integrand's units times the variable's).
        let residual = relative_error(error, value);
        if error <= (tolerance.relative * value.abs()).max(tolerance.absolute) {
            Verdict::Converged((value, error), residual)
        } else {
            Verdict::Continue(residual)
        }
    });
    match (run, failure) {
        (_, Some(e)) => Err(IntegralError::Integrand(e)),
        (Ok(done), None) => {
            let mut pieces: Vec<(f64, f64, f64)> =
                panels.iter().map(|p| (p.a, p.b, p.value)).collect();
            pieces.sort_by(|x, y| x.0.total_cmp(&y.0));
            Ok(Integral {
                value: done.value.0,
                error: done.value.1,
                panels: pieces,
                report: done.report,
            })
        }
        (Err(stopped), None) => Err(IntegralError::Stopped(stopped)),
    }
}

/// |error/value|, or the absolute error where the integral is 0 or so small that the ratio
/// would not be finite.
fn relative_error(error: f64, value: f64) -> f64 {
    let relative = error / value.abs();
    if relative.is_finite() {
        relative
    } else {
        error
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const TIGHT: Tolerance = Tolerance {
        relative: 1e-12,
        absolute: 0.0,
        max_bisections: 200,
        initial_panels: 1,
    };

    fn integrate(f: impl Fn(f64) -> f64, a: f64, b: f64, tol: Tolerance) -> Integral {
        adaptive_gauss_kronrod(|x| Ok::<_, ()>(f(x)), a, b, tol, &Budget::unlimited()).unwrap()
    }

    #[test]
    fn kronrod_integrates_smooth_functions_in_one_panel() {
        // G7 is exact to degree 13 (and K15 to 22): x^12 on [0, 1] in one panel, K − G ≈ 0.
        let i = integrate(|x| x.powi(12), 0.0, 1.0, TIGHT);
        assert!((i.value - 1.0 / 13.0).abs() < 1e-15, "{}", i.value);
        assert_eq!(i.report.evaluations, Some(15));
    }

    #[test]
    fn adaptive_panels_resolve_a_steep_integrand_and_bound_the_error() {
        // ∫₀^0.999 dx/(1 − x)^{3/2} = 2((0.001)^{-1/2} − 1).
        let exact = 2.0 * (0.001f64.powf(-0.5) - 1.0);
        let i = integrate(|x| (1.0 - x).powf(-1.5), 0.0, 0.999, TIGHT);
        assert!(((i.value - exact) / exact).abs() < 1e-11, "{}", i.value);
        assert!(i.error <= 1e-12 * exact);
        assert!(i.report.iterations > 1);
        // The report's residual is the relative error estimate.
        assert_eq!(i.report.residual, Some(i.error / i.value));
        assert_eq!(
            (relative_error(1e-3, 0.0), relative_error(0.0, 0.0)),
            (1e-3, 0.0)
        );
        // The panels tile [0, 0.999] in order and sum to the value.
        assert_eq!(
            (i.panels[0].0, i.panels[i.panels.len() - 1].1),
            (0.0, 0.999)
        );
        assert!(i.panels.windows(2).all(|w| w[0].1 == w[1].0));
        let sum: f64 = i.panels.iter().map(|p| p.2).sum();
        assert!(((sum - i.value) / i.value).abs() < 1e-14);
    }

    #[test]
    fn a_capped_run_and_a_failing_integrand_are_errors() {
        let tol = Tolerance {
            max_bisections: 2,
            ..TIGHT
        };
        let started = Tolerance {
            initial_panels: 7,
            ..TIGHT
        };
        let i = integrate(|x| x.exp(), 0.0, 1.0, started);
        assert_eq!(i.panels.len(), 7);
        assert!((i.panels[3].0 - 3.0 / 7.0).abs() < 1e-16 && i.panels[6].1 == 1.0);
        assert!((i.value - (1f64.exp() - 1.0)).abs() < 1e-14);
        let r = adaptive_gauss_kronrod(
            |x| Ok::<_, ()>((1.0 - x).powf(-1.5)),
            0.0,
            0.999,
            tol,
            &Budget::unlimited(),
        );
        assert!(matches!(r, Err(IntegralError::Stopped(_))));
        let r = adaptive_gauss_kronrod(
            |x| if x > 0.5 { Err("no film") } else { Ok(x) },
            0.0,
            1.0,
            TIGHT,
            &Budget::unlimited(),
        );
        assert_eq!(r, Err(IntegralError::Integrand("no film")));
    }

    #[test]
    fn gauss_legendre_integrates_polynomials_exactly() {
        // n points are exact to degree 2n − 1: ∫₋₁¹ x^k dx = 2/(k + 1) for even k.
        let rule = gauss_legendre(6);
        for k in 0..=11 {
            let sum: f64 = rule.iter().map(|&(x, w)| w * x.powi(k)).sum();
            let exact = if k % 2 == 0 {
                2.0 / (k + 1) as f64
            } else {
                0.0
            };
            assert!((sum - exact).abs() < 1e-14, "x^{k}: {sum} vs {exact}");
        }
    }
}
