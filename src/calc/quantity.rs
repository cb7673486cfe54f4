//! Numbers with an invariant, parsed once at the door. Code holding one never re-checks it:
//! NaN, ±∞ and out-of-range values become a 422 naming the field before any physics runs.
//! In the OpenAPI each field using them says `value_type = f64` with its own range and example.

use serde::Deserialize;

/// Whether a ratio computed from two inputs lies in [lo, hi], allowing its last bits of
/// rounding: L/D made from L = 5 × 0.0381 and D = 0.0381 is 5.000000000000001, and a request
/// that sends exactly the limit must not be refused for it.
pub fn ratio_within(value: f64, lo: f64, hi: f64) -> bool {
    const SLACK: f64 = 1e-12;
    value >= lo * (1.0 - SLACK) && value <= hi * (1.0 + SLACK)
}

/// A finite number > 0, and a normal one (≥ 2.2e-308): a subnormal x such as 5e-324 makes 1/x
/// infinite, so any room dividing by it would answer a 500 (the edge fuzzer's finds in the
/// life, gas-journal and hydrostatic rooms).
#[derive(Debug, Clone, Copy, PartialEq, PartialOrd, Deserialize)]
#[serde(try_from = "f64")]
pub struct Positive(f64);

impl Positive {
    pub fn get(self) -> f64 {
        self.0
    }
}

impl TryFrom<f64> for Positive {
    type Error = String;
    fn try_from(v: f64) -> Result<Self, String> {
        if v.is_normal() && v > 0.0 {
            Ok(Positive(v))
        } else if v > 0.0 && v < f64::MIN_POSITIVE {
            Err(format!(
                "must be a finite number > 0 and at least {:e} (not subnormal), got {v:e}",
                f64::MIN_POSITIVE
            ))
        } else {
            Err(format!("must be a finite number > 0, got {v}"))
        }
    }
}

/// A finite number ≥ 0.
#[derive(Debug, Clone, Copy, PartialEq, PartialOrd, Deserialize)]
#[serde(try_from = "f64")]
pub struct NonNegative(f64);

impl NonNegative {
    pub const ZERO: NonNegative = NonNegative(0.0);

    pub fn get(self) -> f64 {
        self.0
    }
}

impl TryFrom<f64> for NonNegative {
    type Error = String;
    fn try_from(v: f64) -> Result<Self, String> {
        if v.is_finite() && v >= 0.0 {
            Ok(NonNegative(v))
        } else {
            Err(format!("must be a finite number >= 0, got {v}"))
        }
    }
}

/// A temperature in °C, finite and above absolute zero; at most 1000 °C (no lubricant model here
/// means anything beyond).
#[derive(Debug, Clone, Copy, PartialEq, PartialOrd, Deserialize)]
#[serde(try_from = "f64")]
pub struct Celsius(f64);

impl Celsius {
    pub const MIN: f64 = -273.0;
    pub const MAX: f64 = 1000.0;

    pub fn get(self) -> f64 {
        self.0
    }
    /// Absolute temperature in K.
    pub fn kelvin(self) -> f64 {
        self.0 + 273.15
    }
}

impl TryFrom<f64> for Celsius {
    type Error = String;
    fn try_from(v: f64) -> Result<Self, String> {
        if v.is_finite() && (Self::MIN..=Self::MAX).contains(&v) {
            Ok(Celsius(v))
        } else {
            Err(format!(
                "must be a temperature in °C within [{}, {}], got {v}",
                Self::MIN,
                Self::MAX
            ))
        }
    }
}

/// The speeds of a rolling bearing's two rings, rev/min, signed in one sense (rings turning
/// opposite ways have opposite signs). The rooms that take them check their own ranges.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RingSpeed {
    /// Inner-ring speed n_i, rpm.
    pub inner_rpm: f64,
    /// Outer-ring speed n_o, rpm.
    pub outer_rpm: f64,
}

impl RingSpeed {
    pub fn new(inner_rpm: f64, outer_rpm: f64) -> Self {
        RingSpeed {
            inner_rpm,
            outer_rpm,
        }
    }

    /// n_i − n_o, rpm: the speed of the inner ring relative to the outer.
    pub fn relative_rpm(self) -> f64 {
        self.inner_rpm - self.outer_rpm
    }

    /// Both rings at rest.
    pub fn at_rest(self) -> bool {
        self.inner_rpm == 0.0 && self.outer_rpm == 0.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn positive_refuses_zero_negative_and_non_finite() {
        for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert!(Positive::try_from(bad).is_err(), "{bad}");
        }
        assert_eq!(Positive::try_from(2.5).unwrap().get(), 2.5);
    }

    #[test]
    fn celsius_is_bounded() {
        assert!(Celsius::try_from(-300.0).is_err());
        assert!(Celsius::try_from(1e6).is_err());
        assert!((Celsius::try_from(40.0).unwrap().kelvin() - 313.15).abs() < 1e-12);
    }
}

/// Smallest magnitude of a principal radius of curvature, m (a flat is an absent radius).
pub const MIN_RADIUS_M: f64 = 1e-9;
/// Largest magnitude of a principal radius of curvature, m: a million kilometres is a flat for
/// any contact (give no radius for one).
pub const MAX_RADIUS_M: f64 = 1e9;

/// A signed principal radius of curvature, m: 1 nm ≤ |r| ≤ 1e9 m; convex > 0, concave < 0.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(try_from = "f64")]
pub struct Radius(f64);

impl Radius {
    pub fn get(self) -> f64 {
        self.0
    }
}

impl TryFrom<f64> for Radius {
    type Error = String;
    fn try_from(v: f64) -> Result<Self, String> {
        if (MIN_RADIUS_M..=MAX_RADIUS_M).contains(&v.abs()) {
            Ok(Radius(v))
        } else {
            Err(format!(
                "must be a radius with {MIN_RADIUS_M:e} m ≤ |r| ≤ {MAX_RADIUS_M:e} m (negative for concave; omit it for a flat), got {v:e}"
            ))
        }
    }
}

/// Poisson's ratio ν, dimensionless, within (−1, 0.5] (the range where the elastic energy is
/// positive definite for an isotropic solid).
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(try_from = "f64")]
pub struct PoissonRatio(f64);

impl PoissonRatio {
    pub fn get(self) -> f64 {
        self.0
    }
}

impl TryFrom<f64> for PoissonRatio {
    type Error = String;
    fn try_from(v: f64) -> Result<Self, String> {
        if v.is_finite() && v > -1.0 && v <= 0.5 {
            Ok(PoissonRatio(v))
        } else {
            Err(format!(
                "must be within (−1, 0.5] (isotropic elastic solid), got {v}"
            ))
        }
    }
}

#[cfg(test)]
mod positive_tests {
    use super::Positive;

    #[test]
    fn a_subnormal_is_refused_and_the_smallest_normal_accepted() {
        for v in [5e-324, 1e-310, f64::MIN_POSITIVE * (1.0 - f64::EPSILON)] {
            let e = Positive::try_from(v).unwrap_err();
            assert!(e.contains("not subnormal"), "{v:e}: {e}");
        }
        for v in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert!(Positive::try_from(v).is_err(), "{v}");
        }
        assert_eq!(
            Positive::try_from(f64::MIN_POSITIVE).unwrap().get(),
            f64::MIN_POSITIVE
        );
        assert_eq!(Positive::try_from(f64::MAX).unwrap().get(), f64::MAX);
    }
}

#[cfg(test)]
mod ratio_tests {
    use super::ratio_within;

    #[test]
    fn a_ratio_at_its_limit_passes_despite_rounding() {
        assert!(ratio_within(5.0 * 0.0381 / 0.0381, 0.05, 5.0));
        assert!(ratio_within(0.005 / 0.1, 0.05, 5.0));
        assert!(!ratio_within(5.001, 0.05, 5.0));
        assert!(!ratio_within(0.0499, 0.05, 5.0));
        assert!(!ratio_within(f64::NAN, 0.05, 5.0));
    }
}
