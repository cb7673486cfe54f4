//! Elastic deformation of a half-space under piecewise-constant surface pressure: the
//! influence coefficients of the discretised deformation integrals (Venner & Lubrecht 2000,
//! ch. 3 and 8; Johnson 1985, §2.8 and §3.9).

/// Line contact (plane strain). For pressure constant over the cells [faces[j], faces[j+1]],
/// the deformation integral ∫ ln|X − X′| P(X′) dX′ at `points[i]` is Σⱼ K_{ij} Pⱼ with
/// K_{ij} = F(Xᵢ − aⱼ) − F(Xᵢ − bⱼ), F(t) = t ln|t| − t, the exact integral of ln|t| over the
/// cell [aⱼ, bⱼ]. Returns K row-major, `points.len()` × (`faces.len()` − 1).
#[must_use]
pub fn line_log_influence(points: &[f64], faces: &[f64]) -> Vec<f64> {
    let antiderivative = |t: f64| {
        if t == 0.0 {
            0.0
        } else {
            t * t.abs().ln() - t
        }
    };
    let mut k = Vec::with_capacity(points.len() * (faces.len() - 1));
    for &x in points {
        let mut upper = antiderivative(x - faces[0]);
        for &face in &faces[1..] {
            let lower = antiderivative(x - face);
            k.push(upper - lower);
            upper = lower;
        }
    }
    k
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_influence_integrates_the_logarithm_over_each_cell() {
        let faces = [-1.0, -0.3, -0.25, 0.1, 0.6, 2.0];
        let points = [-0.7, -0.27, 0.0, 0.35, 1.9];
        let k = line_log_influence(&points, &faces);
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
                let got = k[i * (faces.len() - 1) + j];
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
}
