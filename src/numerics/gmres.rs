//! Restarted GMRES with right preconditioning (Saad & Schultz 1986; Saad, *Iterative Methods
//! for Sparse Linear Systems*, 2nd ed., 2003, Alg. 6.9 and §9.3.2): the operator and the
//! preconditioner are closures, so a matrix that is never assembled (a Newton Jacobian applied
//! matrix-free) can be solved. Right preconditioning, A M⁻¹ u = b with x = M⁻¹u, keeps the
//! residual GMRES minimises the true residual b − A x, so the stopping test is on the system
//! itself. The Arnoldi basis is orthogonalised by modified Gram–Schmidt and the small least
//! squares problem reduced by Givens rotations as it grows. Work per iteration: one operator
//! product, one preconditioner solve and k + 1 vector operations of length n at the k-th
//! iteration of a cycle; storage (restart + 1) vectors.

use super::dense::dot;

/// How a [`solve`] ended.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Outcome {
    /// Arnoldi iterations taken (one operator product and one preconditioner solve each; a
    /// cycle's end adds one product for the true residual).
    pub iterations: usize,
    /// ‖b − A x‖₂ / ‖b‖₂ at the end (0 for b = 0).
    pub relative_residual: f64,
    /// Whether that reached the tolerance.
    pub converged: bool,
}

/// The iteration's knobs.
#[derive(Debug, Clone, Copy)]
pub struct Settings {
    /// Stop when ‖b − A x‖₂ ≤ `tolerance` · ‖b‖₂.
    pub tolerance: f64,
    /// Krylov vectors per cycle before a restart.
    pub restart: usize,
    /// Arnoldi iterations in all.
    pub max_iterations: usize,
}

/// Solves A x = b from x = 0: `apply(v, out)` sets out = A v, `precondition(v)` replaces v by
/// M⁻¹v. Returns x and how the iteration ended (x is the last iterate either way, which may
/// not be finite when the iteration broke down; the caller judges a non-converged one).
pub fn solve(
    b: &[f64],
    mut apply: impl FnMut(&[f64], &mut [f64]),
    mut precondition: impl FnMut(&mut [f64]),
    settings: Settings,
) -> (Vec<f64>, Outcome) {
    let n = b.len();
    let m = settings.restart.max(1);
    let norm = |v: &[f64]| dot(v, v).sqrt();
    let b_norm = norm(b);
    let mut x = vec![0.0; n];
    let mut outcome = Outcome {
        iterations: 0,
        relative_residual: 0.0,
        converged: true,
    };
    if b_norm == 0.0 {
        return (x, outcome);
    }
    let target = settings.tolerance * b_norm;
    let mut residual = b.to_vec();
    let mut product = vec![0.0; n];
    loop {
        let beta = norm(&residual);
        outcome.relative_residual = beta / b_norm;
        outcome.converged = beta <= target;
        if outcome.converged || outcome.iterations >= settings.max_iterations {
            return (x, outcome);
        }
        // Arnoldi on A M⁻¹ from r/‖r‖, the Hessenberg columns rotated as they come.
        let mut basis: Vec<Vec<f64>> = vec![residual.iter().map(|r| r / beta).collect()];
        let mut hessenberg: Vec<Vec<f64>> = Vec::with_capacity(m);
        let mut rotations: Vec<(f64, f64)> = Vec::with_capacity(m);
        let mut g = vec![beta];
        let mut preconditioned = vec![0.0; n];
        while hessenberg.len() < m && outcome.iterations < settings.max_iterations {
            let k = hessenberg.len();
            preconditioned.copy_from_slice(&basis[k]);
            precondition(&mut preconditioned);
            apply(&preconditioned, &mut product);
            outcome.iterations += 1;
            let mut h = vec![0.0; k + 2];
            for (j, v) in basis.iter().enumerate() {
                h[j] = dot(&product, v);
                product.iter_mut().zip(v).for_each(|(w, v)| *w -= h[j] * v);
            }
            let next = norm(&product);
            h[k + 1] = next;
            for (j, &(c, s)) in rotations.iter().enumerate() {
                let (a, b) = (h[j], h[j + 1]);
                h[j] = c * a + s * b;
                h[j + 1] = -s * a + c * b;
            }
            let r = h[k].hypot(h[k + 1]);
            let (c, s) = if r == 0.0 {
                (1.0, 0.0)
            } else {
                (h[k] / r, h[k + 1] / r)
            };
            h[k] = r;
            h[k + 1] = 0.0;
            rotations.push((c, s));
            g.push(-s * g[k]);
            g[k] *= c;
            hessenberg.push(h);
            // |g[k + 1]| is the cycle's residual norm; a zero `next` is a lucky breakdown.
            if g[k + 1].abs() <= target || next == 0.0 {
                break;
            }
            basis.push(product.iter().map(|w| w / next).collect());
        }
        // y from the triangle R y = g, then x += M⁻¹ V y; the residual afresh (not |g|, which
        // drifts from the true residual in floating point).
        let k = hessenberg.len();
        let mut y = vec![0.0; k];
        for i in (0..k).rev() {
            let s: f64 = (i + 1..k).map(|j| hessenberg[j][i] * y[j]).sum();
            y[i] = (g[i] - s) / hessenberg[i][i];
        }
        let mut update = vec![0.0; n];
        for (v, yj) in basis.iter().zip(&y) {
            update.iter_mut().zip(v).for_each(|(u, v)| *u += yj * v);
        }
        precondition(&mut update);
        x.iter_mut().zip(&update).for_each(|(x, u)| *x += u);
        apply(&x, &mut product);
        residual
            .iter_mut()
            .zip(b.iter().zip(&product))
            .for_each(|(r, (b, ax))| *r = b - ax);
        if y.iter().any(|v| !v.is_finite()) {
            outcome.relative_residual = f64::NAN;
            outcome.converged = false;
            return (x, outcome);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A nonsymmetric, non-normal matrix: a convection–diffusion stencil plus a dense smooth
    /// coupling 0.3·exp(−|i − j|/8)/n (as a deformation integral couples a film equation).
    fn matrix(n: usize) -> Vec<Vec<f64>> {
        (0..n)
            .map(|i| {
                (0..n)
                    .map(|j| {
                        let d = i as f64 - j as f64;
                        let stencil = match i as i64 - j as i64 {
                            0 => 2.5,
                            1 => -1.6,
                            -1 => -0.4,
                            _ => 0.0,
                        };
                        stencil + 0.3 * (-d.abs() / 8.0).exp() / n as f64
                    })
                    .collect()
            })
            .collect()
    }

    fn product(a: &[Vec<f64>], v: &[f64], out: &mut [f64]) {
        for (o, row) in out.iter_mut().zip(a) {
            *o = row.iter().zip(v).map(|(a, v)| a * v).sum();
        }
    }

    #[test]
    fn matches_the_direct_solution_with_and_without_restarts() {
        let n = 120;
        let a = matrix(n);
        let x_true: Vec<f64> = (0..n).map(|i| (0.13 * i as f64).sin() + 0.5).collect();
        let mut b = vec![0.0; n];
        product(&a, &x_true, &mut b);
        for restart in [n, 30] {
            let settings = Settings {
                tolerance: 1e-12,
                restart,
                max_iterations: 2000,
            };
            let (x, outcome) = solve(&b, |v, out| product(&a, v, out), |_| {}, settings);
            assert!(outcome.converged, "restart {restart}: {outcome:?}");
            assert!(outcome.relative_residual <= 1e-12);
            for (got, want) in x.iter().zip(&x_true) {
                assert!(
                    (got - want).abs() < 1e-9,
                    "restart {restart}: {got} vs {want}"
                );
            }
        }
    }

    #[test]
    fn a_good_preconditioner_cuts_the_iterations() {
        let n = 200;
        let a = matrix(n);
        let b: Vec<f64> = (0..n).map(|i| 1.0 + (i % 7) as f64).collect();
        let settings = Settings {
            tolerance: 1e-10,
            restart: 50,
            max_iterations: 5000,
        };
        let (_, plain) = solve(&b, |v, out| product(&a, v, out), |_| {}, settings);
        // M = the stencil's tridiagonal part (plus the coupling's diagonal), by the Thomas
        // algorithm.
        let diagonal = 2.5 + 0.3 / n as f64;
        let thomas = |v: &mut [f64]| {
            let (lower, upper) = (-1.6, -0.4);
            let mut c = vec![0.0; n];
            c[0] = upper / diagonal;
            v[0] /= diagonal;
            for i in 1..n {
                let d = diagonal - lower * c[i - 1];
                c[i] = upper / d;
                v[i] = (v[i] - lower * v[i - 1]) / d;
            }
            for i in (0..n - 1).rev() {
                v[i] -= c[i] * v[i + 1];
            }
        };
        let (x, good) = solve(&b, |v, out| product(&a, v, out), thomas, settings);
        assert!(plain.converged && good.converged);
        assert!(
            good.iterations * 3 < plain.iterations,
            "{good:?} against {plain:?}"
        );
        let mut r = vec![0.0; n];
        product(&a, &x, &mut r);
        let worst = r
            .iter()
            .zip(&b)
            .map(|(r, b)| (r - b).abs())
            .fold(0.0, f64::max);
        assert!(worst < 1e-8, "{worst}");
    }

    #[test]
    fn a_zero_right_hand_side_takes_no_iteration_and_a_cap_is_reported() {
        let a = matrix(10);
        let settings = Settings {
            tolerance: 1e-12,
            restart: 3,
            max_iterations: 2,
        };
        let (x, outcome) = solve(&[0.0; 10], |v, out| product(&a, v, out), |_| {}, settings);
        assert_eq!(x, vec![0.0; 10]);
        assert_eq!(outcome.iterations, 0);
        let (_, capped) = solve(&[1.0; 10], |v, out| product(&a, v, out), |_| {}, settings);
        assert_eq!(capped.iterations, 2);
        assert!(!capped.converged && capped.relative_residual > 1e-12);
    }
}
