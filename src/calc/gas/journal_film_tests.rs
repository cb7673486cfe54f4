//! The gas journal's film against the incompressible basement, Table 11.4's limits, small-ε
//! linear theory and its own Richardson estimate.

use super::*;
use crate::numerics::reynolds::{self as incompressible, Grid, Problem, Stencil};

pub(crate) fn film(e: f64, lambda: f64, l_over_d: f64) -> JournalFilm {
    JournalFilm {
        eccentricity: e,
        bearing_number: lambda,
        knudsen_number: 0.0,
        l_over_d,
        tilt: None,
    }
}

pub(crate) fn method(level: Level) -> Method {
    Method {
        level,
        mesh: level_mesh(level),
        richardson: true,
    }
}

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

/// The incompressible full film (no cavitation) ∂θ(H³∂θp) + ∂y(H³∂yp) = ∂θH on the
/// incompressible basement (`numerics::reynolds`, one banded solve of the periodic film): (W̄1/Λ, W̄2/Λ).
fn incompressible_load(e: f64, l_over_d: f64, n: usize, m: usize) -> (f64, f64) {
    let h = move |t: f64, _: f64| 1.0 + e * t.cos();
    let [a, b] = incompressible_force(&h, 1.0, None, l_over_d, (n, m));
    (a, -b)
}

/// The incompressible full film's force on the journal (a toward h_max, b 90° ahead) per
/// p_a L D per Λ, of ∂θ(H³∂θp) + ∂y(H³∂yp) = `wedge` ∂θH + s on the incompressible basement
/// (one banded solve of the periodic film), on `n` × `m` cells of the half bearing.
pub(crate) fn incompressible_force(
    h: &dyn Fn(f64, f64) -> f64,
    wedge: f64,
    source: Option<&dyn Fn(f64, f64) -> f64>,
    l_over_d: f64,
    (n, m): (usize, usize),
) -> [f64; 2] {
    let (grid, p) = incompressible_film(h, wedge, source, l_over_d, (n, m), false);
    let (mut sc, mut ss) = (0.0, 0.0);
    for i in 0..n {
        let (s, c) = grid.x[i].sin_cos();
        for j in 0..=m {
            let w = grid.cv_x(i) * grid.cv_y(j);
            let v = p[incompressible::at(&grid, i, j)];
            sc += w * v * c;
            ss += w * v * s;
        }
    }
    [-sc / (2.0 * l_over_d), -ss / (2.0 * l_over_d)]
}

/// The incompressible full film of ∂θ(H³∂θp) + ∂y(H³∂yp) = `wedge` ∂θH + s, periodic in θ, on
/// the incompressible basement (one banded solve): on `n` × `m` cells of the half bearing (y
/// from an end to the mid-plane, L/D) or, `whole`, of the whole length (y to 2 L/D, both ends
/// at p = 0).
pub(crate) fn incompressible_film(
    h: &dyn Fn(f64, f64) -> f64,
    wedge: f64,
    source: Option<&dyn Fn(f64, f64) -> f64>,
    l_over_d: f64,
    (n, m): (usize, usize),
    whole: bool,
) -> (Grid, Vec<f64>) {
    let grid = Grid {
        x: (0..=n).map(|k| k as f64 * TAU / n as f64).collect(),
        ny: m,
        width: if whole { 2.0 * l_over_d } else { l_over_d },
        symmetric: !whole,
        periodic: true,
    };
    let problem = Problem {
        film: h,
        conductance: None,
        anisotropy: 1.0,
        wedge,
        source,
        held: None,
    };
    let stencil = Stencil::assemble(&grid, &problem);
    let mut p = vec![0.0; (n + 1) * (m + 1)];
    incompressible::solve(&stencil, &mut p, false, &Budget::unlimited()).unwrap();
    (grid, p)
}

#[test]
fn small_bearing_numbers_tend_to_the_incompressible_film() {
    let budget = Budget::unlimited();
    for (e, l_over_d) in [(0.5, 1.0), (0.8, 0.5)] {
        let lambda = 1e-3;
        let gas = evaluate(
            &film(e, lambda, l_over_d),
            method(Level::High),
            None,
            &budget,
        )
        .unwrap();
        let (w1, w2) = incompressible_load(e, l_over_d, 256, 48);
        let liquid = w1.hypot(w2);
        assert!(
            rel(gas.performance.load() / lambda, liquid) < 5e-3,
            "ε {e}: W̄/Λ {} vs incompressible {liquid}",
            gas.performance.load() / lambda
        );
        // Full film: the load is perpendicular to the line of centres.
        assert!((gas.performance.attitude() - PI / 2.0).abs() < 0.01);
    }
}

#[test]
fn a_long_bearing_at_small_bearing_number_approaches_table_11_4() {
    // Table 11.4, Λ → 0: W̄2 = πεΛ/((2 + ε²)√(1 − ε²)), W̄1 = 0, friction
    // M̄_j/(2π) = 2(1 + 2ε²)/((2 + ε²)√(1 − ε²)). L/D = 8 leaves a few % to the ends.
    let budget = Budget::unlimited();
    let (e, lambda) = (0.5, 1e-3);
    let gas = evaluate(
        &film(e, lambda, 8.0),
        method(Level::Standard),
        None,
        &budget,
    )
    .unwrap();
    let s = (1.0 - e * e).sqrt();
    let w2 = PI * e * lambda / ((2.0 + e * e) * s);
    let ratio = gas.performance.load_across / w2;
    assert!(ratio < 1.0 && ratio > 0.85, "{ratio}");
    let friction = 2.0 * (1.0 + 2.0 * e * e) / ((2.0 + e * e) * s);
    assert!(rel(gas.performance.friction_journal, friction) < 0.03);
}

#[test]
fn large_bearing_numbers_tend_to_the_mass_conserving_limit_not_the_foil_section_one() {
    // The interior P H tends to √(1 + 1.5ε²) (Table 11.4: the constant the ambient ends fix
    // through ∫H³P² dθ = ∫H³ dθ), not 1 + ε (§11.7's P = 1 at the widest gap).
    let budget = Budget::unlimited();
    let e = 0.5;
    let f = film(e, 1000.0, 3.0);
    let solved = solve_on(
        &f,
        grid(
            &f,
            Mesh {
                along: 96,
                across: 24,
            },
        ),
        None,
        &budget,
    )
    .unwrap();
    let g = &solved.grid;
    let mid = g.y.len() - 1;
    let c = (1.0 + 1.5 * e * e).sqrt();
    for i in 0..g.nx() {
        let ph = solved.p[g.at(i, mid)] * (1.0 + e * g.x[i].cos());
        assert!(
            (ph - c).abs() < 0.01 * c,
            "θ {}: P H = {ph}, want {c}",
            g.x[i]
        );
    }
    // The invariant, row by row (to the grid's accuracy).
    let want: f64 = (0..g.nx()).map(|i| (1.0 + e * g.x[i].cos()).powi(3)).sum();
    for j in 0..g.y.len() {
        let got: f64 = (0..g.nx())
            .map(|i| (1.0 + e * g.x[i].cos()).powi(3) * solved.p[g.at(i, j)].powi(2))
            .sum();
        assert!(rel(got, want) < 2e-3, "row {j}: {got} vs {want}");
    }
    // The load tends to Table 11.4's W̄1 = (π/ε)√(1 + 1.5ε²)(1 − √(1 − ε²))/√(1 − ε²), the
    // ends taking a layer of width ~Λ^−½.
    let s = (1.0 - e * e).sqrt();
    let w1 = PI / e * c * (1.0 - s) / s;
    let w_foil = PI / e * (1.0 + e) * (1.0 - s) / s;
    let load = solved.performance.load();
    assert!(load < w1 && rel(load, w1) < 0.03, "{load} vs {w1}");
    assert!(rel(load, w_foil) > 0.2);
    assert!(solved.performance.attitude().abs() < 0.05);
}

/// `f` on a mesh finer than `high` (192 × 36), Richardson-extrapolated: the reference the
/// levels' error estimates are held to.
pub(crate) fn reference(f: &JournalFilm, budget: &Budget) -> JournalEvaluated {
    let mesh = Mesh {
        along: 192,
        across: 36,
    };
    let method = Method {
        level: Level::High,
        mesh,
        richardson: true,
    };
    evaluate(f, method, None, budget).unwrap()
}

/// A complex number, for the linear theory.
#[derive(Clone, Copy, Debug)]
pub(crate) struct C(pub(crate) f64, pub(crate) f64);

impl C {
    pub(crate) fn mul(self, o: C) -> C {
        C(self.0 * o.0 - self.1 * o.1, self.0 * o.1 + self.1 * o.0)
    }
    pub(crate) fn add(self, o: C) -> C {
        C(self.0 + o.0, self.1 + o.1)
    }
    pub(crate) fn abs(self) -> f64 {
        self.0.hypot(self.1)
    }
    pub(crate) fn div(self, o: C) -> C {
        let d = o.0 * o.0 + o.1 * o.1;
        C(
            (self.0 * o.0 + self.1 * o.1) / d,
            (self.1 * o.0 - self.0 * o.1) / d,
        )
    }
    pub(crate) fn sqrt(self) -> C {
        let r = self.0.hypot(self.1).sqrt();
        let t = self.1.atan2(self.0) / 2.0;
        C(r * t.cos(), r * t.sin())
    }
    pub(crate) fn exp(self) -> C {
        let m = self.0.exp();
        C(m * self.1.cos(), m * self.1.sin())
    }
    pub(crate) fn tanh(self) -> C {
        // Re z > 0 here: (1 − e^−2z)/(1 + e^−2z).
        let q = C(-2.0 * self.0, -2.0 * self.1).exp();
        C(1.0 - q.0, -q.1).div(C(1.0 + q.0, q.1))
    }
}

#[test]
fn small_eccentricity_follows_linear_theory() {
    // P = 1 + ε Re(g(y) e^{iθ}) with g″ − (1 + iΛ) g = iΛ, g(0) = 0, g′(w) = 0:
    // ∫₀^w g dy = −iΛ/(1 + iΛ) (w − tanh(κw)/κ), κ = √(1 + iΛ); W̄1 = −επ Re G/(4w),
    // W̄2 = −επ Im G/(4w) with G the integral over the whole length.
    let budget = Budget::unlimited();
    let (e, w) = (1e-3, 1.0);
    for lambda in [1.0, 10.0, 100.0] {
        let k = C(1.0, lambda).sqrt();
        let kw = k.mul(C(w, 0.0));
        let bracket = C(w, 0.0);
        let t = kw.tanh().div(k);
        let inner = C(bracket.0 - t.0, bracket.1 - t.1);
        let half = C(0.0, -lambda).div(C(1.0, lambda)).mul(inner);
        let g = C(2.0 * half.0, 2.0 * half.1);
        let (w1, w2) = (-e * PI * g.0 / (4.0 * w), -e * PI * g.1 / (4.0 * w));
        let gas = evaluate(&film(e, lambda, w), method(Level::High), None, &budget).unwrap();
        let p = gas.performance;
        assert!(
            rel(p.load(), w1.hypot(w2)) < 5e-3,
            "Λ {lambda}: W̄ {} vs {}",
            p.load(),
            w1.hypot(w2)
        );
        assert!(
            (p.attitude() - w2.atan2(w1)).abs() < 5e-3,
            "Λ {lambda}: φ {} vs {}",
            p.attitude(),
            w2.atan2(w1)
        );
    }
}

#[test]
fn the_richardson_estimate_brackets_the_error_from_lambda_1_to_1000() {
    let budget = Budget::unlimited();
    for lambda in [1.0, 10.0, 100.0, 1000.0] {
        let f = film(0.6, lambda, 1.0);
        let reference = reference(&f, &budget).performance.load();
        for level in [Level::Fast, Level::Standard, Level::High] {
            let got = evaluate(&f, method(level), None, &budget).unwrap();
            let err = rel(got.performance.load(), reference);
            let estimate = got.error_estimate.unwrap();
            println!("Λ {lambda} {level:?}: error {err:.2e}, estimate {estimate:.2e}");
            assert!(
                err <= estimate.max(2e-4),
                "Λ {lambda} {level:?}: error {err:e} above the estimate {estimate:e}"
            );
        }
    }
}

#[test]
fn eccentricity_0_9_at_lambda_1000_converges_and_stays_positive() {
    let budget = Budget::unlimited();
    let got = evaluate(
        &film(0.9, 1000.0, 1.0),
        method(Level::Standard),
        None,
        &budget,
    )
    .unwrap();
    assert!(got.fine.p.iter().all(|p| *p > 0.0 && p.is_finite()));
    assert!(got.performance.load() > 1.0);
    assert!(got.error_estimate.unwrap() < 0.05);
}
