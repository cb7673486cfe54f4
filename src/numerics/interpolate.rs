//! Interpolation on sampled curves: linear between samples, and the parabola through three
//! samples that refines an extremum found at a node (its vertex converges with the grid like
//! the curve itself, instead of jumping with where the nodes fall).

/// Linear interpolation of the samples (xs ascending, ys) at x; constant beyond the ends.
#[must_use]
pub fn linear(xs: &[f64], ys: &[f64], x: f64) -> f64 {
    let n = xs.len();
    if x <= xs[0] {
        return ys[0];
    }
    if x >= xs[n - 1] {
        return ys[n - 1];
    }
    let j = xs.partition_point(|&v| v <= x).clamp(1, n - 1);
    let t = (x - xs[j - 1]) / (xs[j] - xs[j - 1]);
    ys[j - 1] + t * (ys[j] - ys[j - 1])
}

/// The parabola y = a x² + b x + c through three samples with distinct x.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Parabola {
    pub a: f64,
    pub b: f64,
    pub c: f64,
}

impl Parabola {
    /// Lagrange's form, expanded (any spacing).
    #[must_use]
    pub fn through(x: [f64; 3], y: [f64; 3]) -> Parabola {
        let ([x0, x1, x2], [y0, y1, y2]) = (x, y);
        let denom = (x0 - x1) * (x0 - x2) * (x1 - x2);
        let a = (x2 * (y1 - y0) + x1 * (y0 - y2) + x0 * (y2 - y1)) / denom;
        let b = (x2 * x2 * (y0 - y1) + x1 * x1 * (y2 - y0) + x0 * x0 * (y1 - y2)) / denom;
        let c = y1 - a * x1 * x1 - b * x1;
        Parabola { a, b, c }
    }

    /// The x of the vertex, −b/2a (not finite for a straight line).
    #[must_use]
    pub fn vertex(&self) -> f64 {
        -self.b / (2.0 * self.a)
    }

    #[must_use]
    pub fn at(&self, x: f64) -> f64 {
        self.a * x * x + self.b * x + self.c
    }
}

/// The minimum of the parabola through three equally spaced samples (before, at, after), as
/// (how far it lies below `at`, its offset from `at` in units of the spacing); `None` when the
/// samples are not convex (no minimum between them to refine).
#[must_use]
pub fn uniform_minimum(before: f64, at: f64, after: f64) -> Option<(f64, f64)> {
    let slope = 0.5 * (after - before);
    let curvature = after - 2.0 * at + before;
    (curvature > 0.0).then(|| (0.5 * slope * slope / curvature, -slope / curvature))
}

/// The periodic cubic Hermite interpolant (Catmull–Rom: slopes by central differences of the
/// neighbours, wrapping round the period) of samples at ascending `xs` within one `period`, at
/// any x. Smooth (C¹) and exact on the samples; a table of one load cycle becomes a force that a
/// time integrator can follow without kinks.
#[must_use]
pub fn periodic_cubic(xs: &[f64], ys: &[f64], period: f64, x: f64) -> f64 {
    let n = xs.len();
    if n == 1 {
        return ys[0];
    }
    let x = xs[0] + (x - xs[0]).rem_euclid(period);
    // Sample k (any integer) and its abscissa, unwrapped.
    let node = |k: isize| {
        let wraps = k.div_euclid(n as isize);
        let i = k.rem_euclid(n as isize) as usize;
        (xs[i] + wraps as f64 * period, ys[i])
    };
    let j = xs.partition_point(|&v| v <= x) as isize - 1;
    let ((x0, y0), (x1, y1)) = (node(j), node(j + 1));
    let slope = |k: isize| {
        let ((xa, ya), (xb, yb)) = (node(k - 1), node(k + 1));
        (yb - ya) / (xb - xa)
    };
    let h = x1 - x0;
    let t = (x - x0) / h;
    let (t2, t3) = (t * t, t * t * t);
    (2.0 * t3 - 3.0 * t2 + 1.0) * y0
        + (t3 - 2.0 * t2 + t) * h * slope(j)
        + (-2.0 * t3 + 3.0 * t2) * y1
        + (t3 - t2) * h * slope(j + 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_periodic_cubic_hits_its_samples_wraps_and_follows_a_smooth_curve() {
        let period = 2.0 * std::f64::consts::PI;
        let xs: Vec<f64> = (0..24).map(|i| f64::from(i) * period / 24.0).collect();
        let ys: Vec<f64> = xs.iter().map(|x| x.sin()).collect();
        for (x, y) in xs.iter().zip(&ys) {
            assert!((periodic_cubic(&xs, &ys, period, *x) - y).abs() < 1e-15);
            assert!((periodic_cubic(&xs, &ys, period, *x + 3.0 * period) - y).abs() < 1e-12);
        }
        for i in 0..100 {
            let x = -1.0 + 0.09 * f64::from(i);
            assert!(
                (periodic_cubic(&xs, &ys, period, x) - x.sin()).abs() < 2e-3,
                "{x}"
            );
        }
    }

    #[test]
    fn linear_is_exact_on_lines_and_clamps() {
        let xs = [0.0, 1.0, 3.0];
        let ys = [1.0, 3.0, 7.0];
        assert_eq!(linear(&xs, &ys, 2.0), 5.0);
        assert_eq!(linear(&xs, &ys, -1.0), 1.0);
        assert_eq!(linear(&xs, &ys, 9.0), 7.0);
    }

    #[test]
    fn parabolas_recover_their_vertex() {
        // y = 2 − 3(x − 0.4)² sampled unevenly.
        let f = |x: f64| 2.0 - 3.0 * (x - 0.4) * (x - 0.4);
        let p = Parabola::through([0.0, 0.3, 1.0], [f(0.0), f(0.3), f(1.0)]);
        assert!((p.vertex() - 0.4).abs() < 1e-14 && (p.at(p.vertex()) - 2.0).abs() < 1e-14);
        // y = (x − 0.25)² + 1 on x = −1, 0, 1: the minimum 1 at 0.25 cells.
        let (drop, offset) = uniform_minimum(2.5625, 1.0625, 1.5625).unwrap();
        assert!((1.0625 - drop - 1.0).abs() < 1e-15 && (offset - 0.25).abs() < 1e-15);
        assert_eq!(uniform_minimum(0.0, 1.0, 0.0), None);
    }
}
