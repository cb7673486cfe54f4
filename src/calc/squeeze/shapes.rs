//! Squeeze films between rigid surfaces approaching each other without sliding: the load a
//! film carries at an approach speed, its peak pressure, and the time to squeeze it from one
//! film thickness to another under a constant load (Khonsari & Booser §9.3–9.5; spec
//! khonsari-booser-ch9-17 SQ-1 to SQ-5). Isoviscous, Newtonian, laminar, no inertia, gauge
//! pressure zero at the edges.
//!
//! Every law here is linear in μV: W = μ V g(h), p_max = μ V q(h), with g the
//! [`Shape::load_coefficient`] and q the [`Shape::max_pressure_coefficient`]. Under a constant
//! load the film thins at V = W/(μ g(h)), so the squeeze time from h₁ to h₂ is
//! Δt = (μ/W) ∫_{h₂}^{h₁} g(h) dh ([`Shape::time_integral`]).

use std::f64::consts::{PI, SQRT_2};

use crate::numerics::driver::Budget;
use crate::numerics::quadrature::{self, Integral, IntegralError, Tolerance};

/// A squeezed pair of surfaces and its dimensions, m. Plates are parallel; the curved bodies
/// approach a flat plane, their film h being the smallest gap.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shape {
    /// Parallel circular disks of radius R (SQ-1).
    CircularDisk { radius: f64 },
    /// A concentric annulus R_i < r < R_o (SQ-3).
    Annulus {
        inner_radius: f64,
        outer_radius: f64,
    },
    /// A rectangular plate L × B (SQ-4).
    Rectangle { length: f64, width: f64 },
    /// Elliptical plates with semi-axes a ≥ b (SQ-2).
    Ellipse { semi_major: f64, semi_minor: f64 },
    /// A sphere of radius R approaching a flat (SQ-5, Eq. 9.17).
    SphereOnFlat { radius: f64 },
    /// A cylinder of radius R and length L approaching a flat, axis parallel to it (SQ-5).
    CylinderOnFlat { radius: f64, length: f64 },
}

/// Odd terms of the rectangle's series: the remainders fall as e^{−nπ B/(2L)} with B ≥ L, so 40
/// odd terms leave less than e^{−60} of the first.
const RECTANGLE_TERMS: usize = 40;

/// ζ(5), for Σ_{n odd} 1/n⁵ = (31/32) ζ(5).
const ZETA_5: f64 = 1.036_927_755_143_37;

impl Shape {
    /// The name on the wire.
    pub fn name(&self) -> &'static str {
        match self {
            Shape::CircularDisk { .. } => "circular_disk",
            Shape::Annulus { .. } => "annulus",
            Shape::Rectangle { .. } => "rectangle",
            Shape::Ellipse { .. } => "ellipse",
            Shape::SphereOnFlat { .. } => "sphere_on_flat",
            Shape::CylinderOnFlat { .. } => "cylinder_on_flat",
        }
    }

    /// The squeezed area A of a plate, m² (None for the curved bodies).
    pub fn area(&self) -> Option<f64> {
        match *self {
            Shape::CircularDisk { radius } => Some(PI * radius * radius),
            Shape::Annulus {
                inner_radius,
                outer_radius,
            } => Some(PI * (outer_radius.powi(2) - inner_radius.powi(2))),
            Shape::Rectangle { length, width } => Some(length * width),
            Shape::Ellipse {
                semi_major,
                semi_minor,
            } => Some(PI * semi_major * semi_minor),
            Shape::SphereOnFlat { .. } | Shape::CylinderOnFlat { .. } => None,
        }
    }

    /// The shape factor K of Khonsari & Booser Eq. 9.13/9.14 (Table 9.1), dimensionless:
    /// Δt = K μ A²/W (1/h₂² − 1/h₁²), V = h³ W/(2 K μ A²). None for the curved bodies, whose
    /// film is not uniform.
    /// - circle K = 3/(4π); ellipse, ℜ = b/a: K = 3ℜ/(2π(1 + ℜ²));
    /// - annulus, ℜ = R_i/R_o: K = (3/(4π)) [(1 + ℜ²)/(1 − ℜ²) + 1/ln ℜ];
    /// - rectangle: K = 96 S L/(π⁴ B) from the exact series S of SQ-4 (L the shorter side),
    ///   the same as Table 9.1's (1/(2ℜ))[1 − (192/(π⁵ℜ)) Σ tanh(nπℜ/2)/n⁵], ℜ = B/L.
    pub fn shape_factor(&self) -> Option<f64> {
        let k = match *self {
            Shape::CircularDisk { .. } => 3.0 / (4.0 * PI),
            Shape::Annulus {
                inner_radius,
                outer_radius,
            } => annulus_shape_factor(inner_radius / outer_radius),
            Shape::Rectangle { length, width } => {
                let (short, long) = (length.min(width), length.max(width));
                96.0 * rectangle_series(short / long) * short / (PI.powi(4) * long)
            }
            Shape::Ellipse {
                semi_major,
                semi_minor,
            } => {
                let r = semi_minor / semi_major;
                3.0 * r / (2.0 * PI * (1.0 + r * r))
            }
            Shape::SphereOnFlat { .. } | Shape::CylinderOnFlat { .. } => return None,
        };
        Some(k)
    }

    /// g(h) = W/(μV) at film h, m: the load per unit viscosity and approach speed.
    /// - plates: g = 2 K A²/h³ (Eq. 9.13; the disk's 3πR⁴/(2h³), Eq. 9.6);
    /// - sphere on a flat, x = R/h (Table 9.2 with the log coefficient corrected from 1 to 3,
    ///   spec E-4: the printed −(1 + x) ln(1 + x) does not integrate Eq. 9.17; the corrected
    ///   bracket is 55.415 at x = 10, as the integral of 9.17 gives):
    ///   g = 6π h [(3/2)(x − 1) − 3(1 + x) ln(1 + x) + (1 + x)² + 1/(2(1 + x))], → 6πR²/h for
    ///   x ≫ 1;
    /// - cylinder on a flat: g = 3√2 π L (R/h)^{3/2} (Table 9.2 prints 3πR/h·√(R/h), missing
    ///   √2·L, spec E-3; the corrected form is the integral of the printed pressure
    ///   6μVR/h₀² [1 + x²/(2Rh₀)]⁻², and agrees with the printed squeeze time).
    pub fn load_coefficient(&self, h: f64) -> f64 {
        match *self {
            Shape::SphereOnFlat { radius } => {
                let x = radius / h;
                let xp = 1.0 + x;
                6.0 * PI * h * (1.5 * (x - 1.0) - 3.0 * xp * xp.ln() + xp * xp + 0.5 / xp)
            }
            Shape::CylinderOnFlat { radius, length } => {
                3.0 * SQRT_2 * PI * length * (radius / h).powf(1.5)
            }
            plate => {
                let (k, a) = (
                    plate.shape_factor().unwrap_or(0.0),
                    plate.area().unwrap_or(0.0),
                );
                2.0 * k * a * a / h.powi(3)
            }
        }
    }

    /// q(h) = p_max/(μV), 1/m: the peak pressure per unit viscosity and approach speed.
    /// - disk 3R²/h³ (Eq. 9.4); ellipse 6a²b²/((a² + b²)h³) (Eq. 9.9, at the centre);
    /// - annulus: p = (3μV/h³)[R_o² − r² − (R_o² − R_i²) ln(R_o/r)/ln(R_o/R_i)] (polar
    ///   Reynolds, SQ-0, p = 0 on both rims), largest at r*² = (R_o² − R_i²)/(2 ln(R_o/R_i));
    /// - rectangle: the centre of the SQ-4 series (corrected form, spec E-1), L the shorter side:
    ///   p = (48μL²V/(π³h³)) Σ_{n odd} (−1)^{(n−1)/2} n⁻³ [1 − 1/cosh(nπB/(2L))]
    ///   = (3/2)μL²V/h³ − (48μL²V/(π³h³)) Σ (−1)^{(n−1)/2}/(n³ cosh(nπB/(2L)));
    /// - sphere: Eq. 9.17 at r = 0, 3R²/(h²(h + R));
    /// - cylinder: 6R/h² (Table 9.2's pressure at x = 0).
    pub fn max_pressure_coefficient(&self, h: f64) -> f64 {
        let h3 = h.powi(3);
        match *self {
            Shape::CircularDisk { radius } => 3.0 * radius * radius / h3,
            Shape::Annulus {
                inner_radius: ri,
                outer_radius: ro,
            } => 3.0 * ro * ro / h3 * annulus_peak_shape(ri, ro),
            Shape::Rectangle { length, width } => {
                let (short, long) = (length.min(width), length.max(width));
                let aspect = long / short;
                let edge: f64 = (0..RECTANGLE_TERMS)
                    .map(|k| {
                        let n = (2 * k + 1) as f64;
                        let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
                        sign / (n.powi(3) * (0.5 * n * PI * aspect).cosh())
                    })
                    .sum();
                short * short / h3 * (1.5 - 48.0 / PI.powi(3) * edge)
            }
            Shape::Ellipse {
                semi_major: a,
                semi_minor: b,
            } => 6.0 * a * a * b * b / ((a * a + b * b) * h3),
            Shape::SphereOnFlat { radius } => 3.0 * radius * radius / (h * h * (h + radius)),
            Shape::CylinderOnFlat { radius, .. } => 6.0 * radius / (h * h),
        }
    }

    /// ∫_{h₂}^{h₁} g(h) dh, m²: the squeeze time under load W is μ/W times it.
    /// - plates: K A² (1/h₂² − 1/h₁²) (Eq. 9.14);
    /// - cylinder: 6√2 π R L (√(R/h₂) − √(R/h₁)) (Table 9.2, correct as printed);
    /// - sphere: by adaptive Gauss–Kronrod quadrature of the exact g in ln h (the integrand
    ///   h g(h) is smooth there; for R ≫ h it tends to 6πR², whose integral is Table 9.2's
    ///   asymptotic 6πR² ln(h₁/h₂)); the integral's report comes with it.
    pub fn time_integral(
        &self,
        initial_film: f64,
        final_film: f64,
        budget: &Budget,
    ) -> Result<(f64, Option<Integral>), IntegralError<()>> {
        let (h1, h2) = (initial_film, final_film);
        match *self {
            Shape::SphereOnFlat { .. } => {
                let tolerance = Tolerance {
                    relative: 1e-10,
                    absolute: 0.0,
                    max_bisections: 64,
                    initial_panels: 1,
                };
                let integral = quadrature::adaptive_gauss_kronrod(
                    |u: f64| {
                        let h = u.exp();
                        Ok(h * self.load_coefficient(h))
                    },
                    h2.ln(),
                    h1.ln(),
                    tolerance,
                    budget,
                )?;
                Ok((integral.value, Some(integral)))
            }
            Shape::CylinderOnFlat { radius, length } => Ok((
                6.0 * SQRT_2 * PI * radius * length * ((radius / h2).sqrt() - (radius / h1).sqrt()),
                None,
            )),
            plate => {
                let (k, a) = (
                    plate.shape_factor().unwrap_or(0.0),
                    plate.area().unwrap_or(0.0),
                );
                Ok((k * a * a * (1.0 / (h2 * h2) - 1.0 / (h1 * h1)), None))
            }
        }
    }
}

/// K of the concentric annulus, ℜ = R_i/R_o (Table 9.1, in the form
/// (3/(4π))[(1 + ℜ²)/(1 − ℜ²) + 1/ln ℜ], equal to the printed
/// [ln ℜ − ℜ⁴ ln ℜ + (1 − ℜ²)²]/[(1 − ℜ²)² ln ℜ]). The bracket cancels as ℜ → 1 (a narrow
/// ring, K → 0): there its series in δ = 1 − ℜ is used.
fn annulus_shape_factor(ratio: f64) -> f64 {
    let d = 1.0 - ratio;
    if d < 1e-4 {
        // (1 + ℜ²)/(1 − ℜ²) + 1/ln ℜ = δ/3 + δ²/6 + 4δ³/45 + O(δ⁴) for ℜ = 1 − δ.
        3.0 / (4.0 * PI) * d * (1.0 / 3.0 + d / 6.0 + 4.0 * d * d / 45.0)
    } else {
        let r2 = ratio * ratio;
        3.0 / (4.0 * PI) * ((1.0 + r2) / (1.0 - r2) + 1.0 / ratio.ln())
    }
}

/// S(L/B) of SQ-4 (Khonsari & Booser Eq. 9.41), `ratio` = L/B ≤ 1 (L the shorter side):
/// S = Σ_{n odd} [1/(2n⁴) − (L/(n⁵πB)) tanh(nπB/(2L))]
///   = π⁴/192 − (L/(πB)) [(31/32) ζ(5) − Σ_{n odd} (1 − tanh(nπB/(2L)))/n⁵],
/// the slowly converging parts summed exactly (Σ_{n odd} n⁻⁴ = π⁴/96); → π⁴/192 as L/B → 0.
pub fn rectangle_series(ratio: f64) -> f64 {
    let tail: f64 = (0..RECTANGLE_TERMS)
        .map(|k| {
            let n = (2 * k + 1) as f64;
            // 1 − tanh z = 2/(e^{2z} + 1), without cancellation.
            let z = 0.5 * n * PI / ratio;
            2.0 / ((2.0 * z).exp() + 1.0) / n.powi(5)
        })
        .sum();
    PI.powi(4) / 192.0 - ratio / PI * (31.0 / 32.0 * ZETA_5 - tail)
}

/// The annulus's peak pressure over 3μV R_o²/h³, in δ = (R_o − R_i)/R_o: with
/// u = r*²/R_o² = s/(2Λ), s = 1 − (R_i/R_o)² = δ(2 − δ), Λ = ln(R_o/R_i) = −ln(1 − δ), it is
/// 1 − u + u ln u = f(e), e = 1 − u. For a narrow ring both e and f cancel away their leading
/// terms, so they are summed from their series there: 2Λ − s = 2δ² + Σ_{k≥3} 2δᵏ/k and
/// f(e) = Σ_{k≥2} eᵏ/(k(k − 1)) (the strip's limit, f → δ²/2: p_max = (3/2) μ V w²/h³).
fn annulus_peak_shape(inner: f64, outer: f64) -> f64 {
    const SERIES_BELOW: f64 = 1e-3;
    let delta = (outer - inner) / outer;
    let s = delta * (2.0 - delta);
    let two_span = if delta < 0.5 {
        -2.0 * (-delta).ln_1p()
    } else {
        2.0 * (outer / inner).ln()
    };
    let u = s / two_span;
    if u < 0.5 {
        // A wide ring (u → 0 as the hole closes: the disk's 1).
        return 1.0 - u + if u > 0.0 { u * u.ln() } else { 0.0 };
    }
    let excess = if delta < SERIES_BELOW {
        2.0 * delta * delta + (3..12).map(|k| 2.0 * delta.powi(k) / k as f64).sum::<f64>()
    } else {
        two_span - s
    };
    let e = excess / two_span;
    if e < SERIES_BELOW {
        (2..12).map(|k| e.powi(k) / (k * (k - 1)) as f64).sum()
    } else {
        e + (1.0 - e) * (-e).ln_1p()
    }
}

#[cfg(test)]
mod annulus_peak_tests {
    use super::*;

    #[test]
    fn the_annulus_peak_is_smooth_from_a_wide_ring_to_a_thin_strip() {
        // The closed form evaluated directly where it is well conditioned.
        let direct = |delta: f64| {
            let (ro, ri) = (1.0, 1.0 - delta);
            let span = (ro / ri).ln();
            let r2 = (ro * ro - ri * ri) / (2.0 * span);
            1.0 - r2 - (ro * ro - ri * ri) * (ro * ro / r2).ln() / (2.0 * span)
        };
        for delta in [0.9, 0.5, 0.1, 0.01, 2e-3] {
            let got = annulus_peak_shape(1.0 - delta, 1.0);
            assert!((got / direct(delta) - 1.0).abs() < 1e-9, "δ = {delta}");
        }
        // A narrow ring is a strip of width w = δ R_o: f → δ²/2 (p_max = 1.5 μ V w²/h³).
        for delta in [1e-4, 1e-7, 1e-10] {
            // The δ the doubles hold (1 − δ rounds).
            let delta = 1.0 - (1.0 - delta);
            let got = annulus_peak_shape(1.0 - delta, 1.0);
            assert!(
                (got / (0.5 * delta * delta) - 1.0).abs() < 2.0 * delta,
                "δ = {delta}: {got}"
            );
        }
        // Continuous across the switch to the series.
        let (below, above) = (
            annulus_peak_shape(1.0 - 0.999e-3, 1.0),
            annulus_peak_shape(1.0 - 1.001e-3, 1.0),
        );
        // A vanishing hole tends to the disk's 1, logarithmically: u = 1/(2 ln(R_o/R_i)).
        let u = 1.0 / (2.0 * 1e300f64.ln());
        let want = 1.0 - u + u * u.ln();
        assert!((annulus_peak_shape(1e-300, 1.0) / want - 1.0).abs() < 1e-12);
        assert!((above / below - (1.001f64 / 0.999).powi(2)).abs() < 1e-4);
    }
}
