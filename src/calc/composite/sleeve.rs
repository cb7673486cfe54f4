//! The sleeve unit's restraint and its steady speed (Harnoy ch. 18, Eqs. 18-4 to 18-11;
//! spec PART B.1.4).
//!
//! - **Pin friction** (Eqs. 18-4 to 18-6): centrifugal pins of total mass m_c, their centres at
//!   R_m when thrown against the housing at R_h, rubbing with a boundary friction coefficient
//!   f_c: M_f = f_c m_c R_m R_h ω_b|ω_b| = k ω_b|ω_b|, k = f_c m_c R_m R_h (kg·m²; the text's
//!   m of Eq. 18-9). The text writes ω_b²; the signed form opposes the rotation in either sense
//!   (spec B.3 item 4).
//! - **Rolling-bearing friction** M_r: a constant (Coulomb) torque opposing the sleeve's
//!   rotation; at rest it holds the sleeve while the film's torque is below it.
//! - **Steady balance** (Eq. 18-7): M_h = M_f + M_r with M_h = 2n(ω_j − ω_b). In ξ = ω_b/ω_j
//!   it is the quadratic κ ξ² + ξ − r = 0 with κ = k ω_j/(2n) and r = 1 − M_r/(2n ω_j), whose
//!   root in [0, 1] is
//!   ξ = 2r/(1 + √(1 + 4κr))   (r > 0; the sleeve stands, ξ = 0, when r ≤ 0).
//!   With M_r = 0 it is the text's ω_b = [(n² + k q)^½ − n]/k, q = 2n ω_j (Eq. 18-8), written
//!   without its cancellation at small k. A constant M_r keeps the balance quadratic, so no
//!   iteration is needed for it.

/// The restraint on the sleeve unit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Restraint {
    /// k = f_c m_c R_m R_h, kg·m².
    pub coefficient: f64,
    /// M_r ≥ 0, N·m.
    pub rolling_torque: f64,
}

impl Restraint {
    /// M_f = k ω_b|ω_b|, N·m: the pins' friction torque, opposing ω_b.
    pub fn pin_torque(&self, sleeve_speed: f64) -> f64 {
        self.coefficient * sleeve_speed * sleeve_speed.abs()
    }

    /// The steady sleeve speed ratio ξ = ω_b/ω_j ∈ [0, 1) of a film whose torque is
    /// 2n(ω_j − ω_b) (`petroff` = n, N·m·s) at journal speed ω_j > 0, rad/s.
    pub fn steady_speed_ratio(&self, petroff: f64, journal_speed: f64) -> f64 {
        let drag = 2.0 * petroff * journal_speed;
        let r = 1.0 - self.rolling_torque / drag;
        if r <= 0.0 || r.is_nan() {
            return 0.0;
        }
        let kappa = self.coefficient * journal_speed / (2.0 * petroff);
        2.0 * r / (1.0 + (1.0 + 4.0 * kappa * r).sqrt())
    }
}

#[cfg(test)]
mod tests {
    use std::f64::consts::PI;

    use super::*;
    use crate::calc::composite::film::SleeveFilm;

    const FILM: SleeveFilm = SleeveFilm {
        radius: 0.05,
        length: 0.1,
        clearance: 6e-5,
        viscosity: 0.03,
    };

    fn rad_s(rpm: f64) -> f64 {
        rpm * PI / 30.0
    }

    /// Spec B-R1, derived: holding 200 rpm at 3500 rpm and ε = 0.5 takes
    /// f_c m_c R_m R_h = M_h/ω_b² = 0.0357 kg·m².
    #[test]
    fn table_18_1_restraint_holds_200_rpm() {
        let (wj, wb) = (rad_s(3500.0), rad_s(200.0));
        let k = FILM.torque(0.5, wj, wb) / (wb * wb);
        assert!((k / 0.0357 - 1.0).abs() < 1e-3, "{k}");
        let r = Restraint {
            coefficient: 0.0357,
            rolling_torque: 0.0,
        };
        let xi = r.steady_speed_ratio(FILM.petroff_coefficient(0.5), wj);
        assert!((xi * 3500.0 / 200.0 - 1.0).abs() < 2e-3, "{}", xi * 3500.0);
    }

    /// The closed form round trip (spec B.1.4, [verified]): k derived from a chosen ω_b returns
    /// that ω_b to round-off, over speeds, eccentricities and split ratios; and the text's
    /// Eq. 18-8 as printed-with-its-fraction-bar agrees where it does not cancel.
    #[test]
    fn the_closed_form_round_trips() {
        for eps in [0.0, 0.3, 0.5, 0.9, 0.999] {
            for wj in [1.0, rad_s(3500.0), 1e4] {
                for xi in [1e-4, 0.05, 0.5, 0.9, 0.9999] {
                    let wb = xi * wj;
                    let n = FILM.petroff_coefficient(eps);
                    let k = FILM.torque(eps, wj, wb) / (wb * wb);
                    let r = Restraint {
                        coefficient: k,
                        rolling_torque: 0.0,
                    };
                    let got = r.steady_speed_ratio(n, wj);
                    assert!(
                        (got / xi - 1.0).abs() < 1e-12,
                        "ε {eps} ω_j {wj} ξ {xi}: {got}"
                    );
                    if xi < 0.99 {
                        let q = 2.0 * n * wj;
                        let text = ((n * n + k * q).sqrt() - n) / k;
                        assert!((text / wb - 1.0).abs() < 1e-8, "{text} vs {wb}");
                    }
                }
            }
        }
    }

    /// With M_r > 0 the balance M_h = M_f + M_r holds at the returned ξ, and ξ falls as M_r
    /// grows, to a standing sleeve once M_r reaches the held sleeve's torque 2n ω_j.
    #[test]
    fn rolling_friction_balances_and_can_hold_the_sleeve() {
        let (eps, wj) = (0.5, rad_s(3500.0));
        let n = FILM.petroff_coefficient(eps);
        let held = 2.0 * n * wj;
        let mut last = 1.0;
        for share in [0.0, 0.1, 0.5, 0.9, 0.999] {
            let r = Restraint {
                coefficient: 0.0357,
                rolling_torque: share * held,
            };
            let xi = r.steady_speed_ratio(n, wj);
            let wb = xi * wj;
            let residual = FILM.torque(eps, wj, wb) - r.pin_torque(wb) - r.rolling_torque;
            assert!(residual.abs() < 1e-12 * held, "{share}: {residual}");
            assert!(xi < last && xi > 0.0, "{share}: {xi}");
            last = xi;
        }
        for share in [1.0, 2.0] {
            let r = Restraint {
                coefficient: 0.0357,
                rolling_torque: share * held,
            };
            assert_eq!(r.steady_speed_ratio(n, wj), 0.0);
        }
    }

    /// The pins' torque opposes the rotation in either sense (−ξ|ξ|H₂, spec B.3 item 4).
    #[test]
    fn pin_torque_is_odd() {
        let r = Restraint {
            coefficient: 0.02,
            rolling_torque: 0.0,
        };
        assert_eq!(r.pin_torque(-3.0), -r.pin_torque(3.0));
        assert_eq!(r.pin_torque(3.0), 0.18);
    }
}
