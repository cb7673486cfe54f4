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
}
