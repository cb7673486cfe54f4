//! The eccentricity ratio ε = e/C as a type: where an ε crosses a module boundary it has been
//! checked once (0 ≤ ε < 1: at 1 the journal touches the bearing).

/// ε = e/C, the journal centre's displacement over the radial clearance, dimensionless;
/// 0 ≤ ε < 1.
#[derive(Debug, Clone, Copy, PartialEq, PartialOrd)]
pub struct EccentricityRatio(f64);

impl EccentricityRatio {
    /// ε when 0 ≤ ε < 1 (None for NaN, a negative ε, or a journal that touches: ε ≥ 1).
    #[must_use]
    pub fn new(eps: f64) -> Option<EccentricityRatio> {
        (0.0..1.0).contains(&eps).then_some(EccentricityRatio(eps))
    }

    #[must_use]
    pub fn get(self) -> f64 {
        self.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_a_journal_inside_its_clearance_has_a_ratio() {
        assert_eq!(
            EccentricityRatio::new(0.6).map(EccentricityRatio::get),
            Some(0.6)
        );
        assert!(EccentricityRatio::new(0.0).is_some());
        for bad in [1.0, 1.5, -1e-9, f64::NAN, f64::INFINITY] {
            assert_eq!(EccentricityRatio::new(bad), None, "{bad}");
        }
    }
}
