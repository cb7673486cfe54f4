//! Richardson's extrapolation of a second-order quantity computed on a grid and on the grid of
//! half its spacing (the error ∝ h², so the fine value is off by a third of the difference).

/// The fine grid's error estimate, (fine − coarse)/3 (to be added to it).
#[must_use]
pub fn fine_error(coarse: f64, fine: f64) -> f64 {
    (fine - coarse) / 3.0
}

/// The extrapolated value, fine + (fine − coarse)/3.
#[must_use]
pub fn extrapolate(coarse: f64, fine: f64) -> f64 {
    fine + fine_error(coarse, fine)
}

/// The error of the finest of three values on grids refined by `r` each time, from the observed
/// order p = ln(d₂/d₁)/ln r of the successive differences (d₁ the finer pair's) held to [1, 2]:
/// the scheme's order is 2, and a smaller ratio means the grids are not yet in the asymptotic
/// range, where the estimate must not trust second order. Each difference gives the fine value's
/// error (the finer pair's d₁/(r^p − 1), the coarser's d₂/(r^p − 1) scaled down by r^p); the
/// larger counts (absolute; Roache's grid convergence index without its safety factor).
/// Returns it with r^p, the factor from the fine value's error to the middle one's.
#[must_use]
pub fn observed_order_error(coarse: f64, middle: f64, fine: f64, r: f64) -> (f64, f64) {
    let (d1, d2) = ((fine - middle).abs(), (middle - coarse).abs());
    let p = if d1 > 0.0 && d2 > 0.0 {
        ((d2 / d1).ln() / r.ln()).clamp(1.0, 2.0)
    } else {
        2.0
    };
    let rp = r.powf(p);
    ((d1 / (rp - 1.0)).max(d2 / (rp * (rp - 1.0))), rp)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_quadratic_error_is_removed() {
        // f(h) = 2 + 5h²: on h = 0.2 and 0.1 the extrapolation recovers f(0) exactly.
        let (coarse, fine) = (2.0 + 5.0 * 0.04, 2.0 + 5.0 * 0.01);
        assert!((extrapolate(coarse, fine) - 2.0).abs() < 1e-14);
        assert!((fine_error(coarse, fine) + 0.05).abs() < 1e-14);
    }

    #[test]
    fn the_observed_order_sets_the_three_grid_error() {
        // Second order (differences 0.12, 0.03): the fine value 2.01 is off by 0.01.
        let (e, rp) = observed_order_error(2.16, 2.04, 2.01, 2.0);
        assert!(
            (e - 0.01).abs() < 1e-12 && (rp - 4.0).abs() < 1e-12,
            "{e} {rp}"
        );
        // First order (0.4, 0.2): off by the last difference, 0.2.
        let (e, _) = observed_order_error(2.8, 2.4, 2.2, 2.0);
        assert!((e - 0.2).abs() < 1e-12, "{e}");
        // A ratio below 2 is held to first order; an exact fine pair leans on the coarse one.
        let (e, _) = observed_order_error(2.3, 2.2, 2.1, 2.0);
        assert!((e - 0.1).abs() < 1e-12, "{e}");
        let (e, _) = observed_order_error(2.4, 2.0, 2.0, 2.0);
        assert!((e - 0.4 / 12.0).abs() < 1e-12, "{e}");
    }
}
