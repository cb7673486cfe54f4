//! Complete elliptic integrals of the first and second kind by the arithmetic–geometric mean,
//! and Carlson's symmetric integral R_D by duplication.
//!
//! **Parameter convention: m = k²** (k the modulus, m the parameter, m₁ = 1 − m the
//! complementary parameter), as in Abramowitz & Stegun ch. 17 and scipy's `ellipk(m)`:
//!
//! ```text
//! K(m) = ∫₀^{π/2} dθ / √(1 − m sin²θ),     E(m) = ∫₀^{π/2} √(1 − m sin²θ) dθ,     0 ≤ m < 1.
//! ```
//!
//! Near m → 1 the parameter itself carries no information (1 − 10⁻¹⁷ rounds to 1), so the
//! kernel takes the complementary parameter m₁: [`complete_from_complement`] stays accurate down
//! to m₁ = 10⁻³⁰⁰, where K ≈ ln(4/√m₁) grows only logarithmically. Callers who know m₁ exactly
//! (a Hertz contact knows m₁ = 1/κ² from its ellipticity κ) should use it.

use std::f64::consts::FRAC_PI_2;

/// K(m) and E(m), or NaN for m outside [0, 1). See the module doc for the convention.
#[must_use]
pub fn complete(m: f64) -> (f64, f64) {
    complete_from_complement(1.0 - m)
}

/// K and E as functions of the complementary parameter m₁ = 1 − m, for 0 < m₁ ≤ 1 (NaN outside).
///
/// Gauss's AGM: a₀ = 1, g₀ = √m₁, c₀ = √m; aₙ₊₁ = (aₙ + gₙ)/2, gₙ₊₁ = √(aₙ gₙ),
/// cₙ₊₁ = (aₙ − gₙ)/2. Then K = π/(2 a_∞) and E = K (1 − Σₙ 2ⁿ⁻¹ cₙ²) (A&S 17.6.1–17.6.4).
/// Convergence is quadratic: about a dozen steps even for m₁ = 10⁻³⁰⁰. K is accurate to a few
/// ulps everywhere; E loses about K·ε to the cancellation in 1 − Σ ≈ 1/K as m₁ → 0
/// (7 × 10⁻¹⁵ relative at m₁ = 10⁻¹⁰⁰, where K = 116).
#[must_use]
pub fn complete_from_complement(m1: f64) -> (f64, f64) {
    if !(m1 > 0.0 && m1 <= 1.0) {
        return (f64::NAN, f64::NAN);
    }
    let (mut a, mut g) = (1.0_f64, m1.sqrt());
    // c₀² = m = 1 − m₁ is computed from m₁ without cancellation trouble: it only matters
    // when it is not small.
    let mut sum = 0.5 * (1.0 - m1);
    let mut weight = 0.5;
    // 64 steps is far beyond what quadratic convergence needs from any m₁ in (0, 1].
    for _ in 0..64 {
        let c = 0.5 * (a - g);
        if c.abs() <= f64::EPSILON * a {
            break;
        }
        weight *= 2.0;
        sum += weight * c * c;
        (a, g) = (0.5 * (a + g), (a * g).sqrt());
    }
    let k = FRAC_PI_2 / a;
    (k, k * (1.0 - sum))
}

/// Carlson's symmetric elliptic integral of the second kind,
///
/// ```text
/// R_D(x, y, z) = (3/2) ∫₀^∞ dt / [(t + x)^{1/2} (t + y)^{1/2} (t + z)^{3/2}],
/// ```
///
/// for x, y ≥ 0 with at most one of them zero and z > 0 (NaN outside). Duplication
/// (Carlson 1995, *Numer. Algorithms* 10, 13–26) until the arguments agree to 1.5 × 10⁻³, then
/// the fifth-order Taylor series: relative error below 10⁻¹⁵. Each duplication shrinks the
/// arguments' spread fourfold, so even a spread of 10³⁰⁰ needs only about 500 steps.
///
/// In this convention (K − E)/m = R_D(0, 1 − m, 1)/3, which stays well-conditioned as m → 0,
/// where K and E both tend to π/2.
#[must_use]
pub fn carlson_rd(x: f64, y: f64, z: f64) -> f64 {
    const TOLERANCE: f64 = 1.5e-3;
    let valid = x >= 0.0 && y >= 0.0 && z > 0.0 && x + y > 0.0 && (x + y + z).is_finite();
    if !valid {
        return f64::NAN;
    }
    let (mut x, mut y, mut z) = (x, y, z);
    let (mut sum, mut factor) = (0.0, 1.0);
    let (mut mean, mut dx, mut dy, mut dz);
    let mut steps = 0;
    loop {
        mean = 0.2 * (x + y + 3.0 * z);
        dx = (mean - x) / mean;
        dy = (mean - y) / mean;
        dz = (mean - z) / mean;
        if dx.abs().max(dy.abs()).max(dz.abs()) < TOLERANCE || steps >= 2000 {
            break;
        }
        let (sx, sy, sz) = (x.sqrt(), y.sqrt(), z.sqrt());
        let lambda = sx * (sy + sz) + sy * sz;
        sum += factor / (sz * (z + lambda));
        factor *= 0.25;
        x = 0.25 * (x + lambda);
        y = 0.25 * (y + lambda);
        z = 0.25 * (z + lambda);
        steps += 1;
    }
    const C1: f64 = 3.0 / 14.0;
    const C2: f64 = 1.0 / 6.0;
    const C3: f64 = 9.0 / 22.0;
    const C4: f64 = 3.0 / 26.0;
    const C5: f64 = 0.25 * C3;
    const C6: f64 = 1.5 * C4;
    let ea = dx * dy;
    let eb = dz * dz;
    let ec = ea - eb;
    let ed = ea - 6.0 * eb;
    let ee = ed + ec + ec;
    let series =
        1.0 + ed * (-C1 + C5 * ed - C6 * dz * ee) + dz * (C2 * ee + dz * (-C3 * ec + dz * C4 * ea));
    3.0 * sum + factor * series / (mean * mean.sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;
    use std::f64::consts::PI;

    fn close(got: f64, want: f64, rel: f64) -> bool {
        ((got - want) / want).abs() <= rel
    }

    #[test]
    fn both_integrals_are_half_pi_at_zero() {
        let (k, e) = complete(0.0);
        assert_eq!(k, FRAC_PI_2);
        assert_eq!(e, FRAC_PI_2);
    }

    #[test]
    fn matches_tabulated_values() {
        // A&S Table 17.1 / scipy.special.ellipk, ellipe (parameter m).
        for (m, k_want, e_want) in [
            (0.1, 1.612_441_348_720_219, 1.530_757_636_897_763),
            (0.5, 1.854_074_677_301_372, 1.350_643_881_047_675_5),
            (0.9, 2.578_092_113_348_173, 1.104_774_732_704_073),
            (0.99, 3.695_637_362_989_875, 1.015_993_545_025_224),
        ] {
            let (k, e) = complete(m);
            assert!(close(k, k_want, 1e-14), "K({m}) = {k}");
            assert!(close(e, e_want, 1e-14), "E({m}) = {e}");
        }
    }

    #[test]
    fn stays_accurate_as_m_tends_to_one() {
        // K = L + (m₁/4)(L − 1) + O(m₁² L), E = 1 + (m₁/2)(L − ½) + O(m₁² L), L = ln(4/√m₁)
        // (A&S 17.3.26, 17.3.36).
        for m1 in [1e-8, 1e-12, 1e-20, 1e-100, 1e-300] {
            let l = (4.0 / f64::sqrt(m1)).ln();
            let (k, e) = complete_from_complement(m1);
            assert!(
                close(k, l + 0.25 * m1 * (l - 1.0), 1e-14),
                "K at m1 = {m1}: {k}"
            );
            // E = K(1 − Σ) loses about K·ε to the cancellation in 1 − Σ ≈ 1/K.
            let e_tol = 20.0 * k * f64::EPSILON;
            assert!(
                close(e, 1.0 + 0.5 * m1 * (l - 0.5), e_tol),
                "E at m1 = {m1}: {e}"
            );
        }
    }

    #[test]
    fn refuses_parameters_outside_the_domain() {
        for m in [1.0, 1.5, -0.1, f64::NAN] {
            let (k, e) = complete(m);
            assert!(k.is_nan() && e.is_nan(), "m = {m}");
        }
    }

    #[test]
    fn carlson_rd_matches_carlsons_test_values() {
        // Carlson (1995) §3 test values, and R_D(x, x, x) = x^(−3/2).
        assert!(close(
            carlson_rd(0.0, 2.0, 1.0),
            1.797_210_352_103_388_3,
            1e-14
        ));
        assert!(close(
            carlson_rd(2.0, 3.0, 4.0),
            0.165_105_272_942_610_53,
            1e-14
        ));
        assert!(close(carlson_rd(4.0, 4.0, 4.0), 0.125, 1e-15));
        assert!(carlson_rd(0.0, 0.0, 1.0).is_nan());
        assert!(carlson_rd(1.0, 1.0, 0.0).is_nan());
    }

    #[test]
    fn carlson_rd_gives_k_minus_e_without_cancellation() {
        // (K − E)/m = R_D(0, 1 − m, 1)/3 → π/4 as m → 0, where K − E itself loses all digits.
        assert!(close(carlson_rd(0.0, 1.0, 1.0) / 3.0, PI / 4.0, 1e-15));
        let m = 1e-9;
        let d = carlson_rd(0.0, 1.0 - m, 1.0) / 3.0;
        assert!(close(d, PI / 4.0 * (1.0 + 0.375 * m), 1e-14));
    }

    proptest! {
        #[test]
        fn carlson_rd_agrees_with_the_agm(m in 0.01f64..0.999_999) {
            let (k, e) = complete(m);
            let d = carlson_rd(0.0, 1.0 - m, 1.0) / 3.0;
            prop_assert!(close(d, (k - e) / m, 1e-12), "m = {}: {} vs {}", m, d, (k - e) / m);
        }

        #[test]
        fn legendre_relation_holds(m in 0.0001f64..0.9999) {
            // E K' + E' K − K K' = π/2 (A&S 17.3.13), K' = K(1 − m).
            let (k, e) = complete(m);
            let (kp, ep) = complete(1.0 - m);
            prop_assert!((e * kp + ep * k - k * kp - FRAC_PI_2).abs() < 1e-13);
        }

        #[test]
        fn k_grows_and_e_falls_with_m(m in 0.0f64..0.99, dm in 1e-6f64..0.009) {
            let (k0, e0) = complete(m);
            let (k1, e1) = complete(m + dm);
            prop_assert!(k1 > k0 && e1 < e0 && e1 >= 1.0 && k0 >= FRAC_PI_2);
        }
    }
}
