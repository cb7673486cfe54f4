//! Elastic deformation of a half-space under piecewise-constant surface pressure: the
//! influence coefficients of the discretised deformation integrals (Venner & Lubrecht 2000,
//! ch. 3 and 8; Johnson 1985, §2.8 and §3.9).

/// Line contact (plane strain). For pressure constant over the cell [a, b], the deformation
/// integral ∫ ln|X − X′| P(X′) dX′ at X takes P times F(X − a) − F(X − b), F(t) = t ln|t| − t,
/// the exact integral of ln|t| over the cell: the influence coefficient K_{ij} of point i and
/// cell j ([`super::log_fmm`] applies the whole matrix).
#[must_use]
pub fn line_log_cell(x: f64, a: f64, b: f64) -> f64 {
    log_antiderivative(x - a) - log_antiderivative(x - b)
}

/// [`line_log_cell`] at `x` for each cell between consecutive `faces`: one logarithm per face.
pub fn line_log_cells(x: f64, faces: &[f64]) -> impl Iterator<Item = f64> + '_ {
    let mut upper = log_antiderivative(x - faces[0]);
    faces[1..].iter().map(move |&face| {
        let lower = log_antiderivative(x - face);
        let k = upper - lower;
        upper = lower;
        k
    })
}

/// F(t) = t ln|t| − t, F(0) = 0.
fn log_antiderivative(t: f64) -> f64 {
    if t == 0.0 {
        0.0
    } else {
        t * t.abs().ln() - t
    }
}

/// Point contact. The integral of 1/r over the rectangle [x − hx/2, x + hx/2] × [y − hy/2,
/// y + hy/2] seen from the origin (Love 1929; Venner & Lubrecht 2000 eq. 8.8): with
/// G(s, t) = |s| asinh(t/s) + |t| asinh(s/t) (G = 0 on the axes), the integral is
/// G(x₊, y₊) − G(x₋, y₊) − G(x₊, y₋) + G(x₋, y₋), x± = x ± hx/2, y± = y ± hy/2. Times
/// 2/(πE′) it is the normal surface displacement under unit pressure on that cell.
#[must_use]
pub fn rectangle_inverse_distance(x: f64, y: f64, hx: f64, hy: f64) -> f64 {
    let g = |s: f64, t: f64| {
        let a = if s == 0.0 {
            0.0
        } else {
            s.abs() * (t / s).asinh()
        };
        let b = if t == 0.0 {
            0.0
        } else {
            t.abs() * (s / t).asinh()
        };
        a + b
    };
    let (xp, xm, yp, ym) = (x + 0.5 * hx, x - 0.5 * hx, y + 0.5 * hy, y - 0.5 * hy);
    g(xp, yp) - g(xm, yp) - g(xp, ym) + g(xm, ym)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_influence_integrates_the_logarithm_over_each_cell() {
        let faces = [-1.0, -0.3, -0.25, 0.1, 0.6, 2.0];
        let points = [-0.7, -0.27, 0.0, 0.35, 1.9];
        for (i, &x) in points.iter().enumerate() {
            for j in 0..faces.len() - 1 {
                // Midpoint rule on 200 000 sub-cells (the log singularity is integrable).
                let n = 200_000;
                let width = faces[j + 1] - faces[j];
                let sum: f64 = (0..n)
                    .map(|s| {
                        let t = faces[j] + (s as f64 + 0.5) * width / n as f64;
                        (x - t).abs().ln() * width / n as f64
                    })
                    .sum();
                let got = line_log_cell(x, faces[j], faces[j + 1]);
                let row: Vec<f64> = line_log_cells(x, &faces).collect();
                assert!(
                    (row[j] - got).abs() < 1e-15,
                    "row {i}: {} against {got}",
                    row[j]
                );
                // The midpoint rule converges slowly across the logarithm's singularity.
                let inside = faces[j] < x && x < faces[j + 1];
                let tol = if inside { 1e-5 } else { 1e-8 };
                assert!(
                    (got - sum).abs() < tol,
                    "K[{i}][{j}] = {got}, quadrature {sum}"
                );
            }
        }
    }

    #[test]
    fn rectangle_influence_integrates_the_inverse_distance() {
        // Midpoint rule on 800 × 800 sub-cells away from the singularity; at the cell's own
        // centre the closed form 4·(h/2)·2·asinh(1) for a square.
        for &(x, y, hx, hy) in &[
            (1.3, -0.4, 0.5, 0.25),
            (-2.0, 3.0, 0.1, 0.3),
            (0.6, 0.0, 0.2, 0.2),
        ] {
            let n = 800;
            let mut sum = 0.0;
            for a in 0..n {
                for b in 0..n {
                    let s = x - 0.5 * hx + (a as f64 + 0.5) * hx / n as f64;
                    let t = y - 0.5 * hy + (b as f64 + 0.5) * hy / n as f64;
                    sum += hx * hy / (n * n) as f64 / (s * s + t * t).sqrt();
                }
            }
            let got = rectangle_inverse_distance(x, y, hx, hy);
            assert!((got - sum).abs() < 1e-6 * sum, "({x}, {y}): {got} vs {sum}");
        }
        let h = 0.3;
        let own = rectangle_inverse_distance(0.0, 0.0, h, h);
        assert!((own - 4.0 * h * 1f64.asinh()).abs() < 1e-14, "{own}");
    }
}
