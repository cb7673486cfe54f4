//! The composite bearing's fluid film: a short (Ocvirk) journal bearing whose sleeve turns
//! (Harnoy, *Bearing Design in Machinery*, ch. 18, Eqs. 18-1, 18-3, 18-24 to 18-28; spec PART B).
//!
//! Symbols: journal radius R, sleeve (bore) length L, radial clearance C, viscosity μ, journal
//! speed ω_j, sleeve speed ω_b, eccentricity ratio ε = e/C, h_min = C(1 − ε).
//!
//! - **Load** (Eq. 18-1, the short-bearing half-Sommerfeld film of Eqs. 18-24 to 18-28 at rest):
//!   the pressure is driven by the speed *sum* ω_j + ω_b, so
//!   W = μ R (ω_j + ω_b) L³/C² · w̄(ε), w̄(ε) = ε [16ε² + π²(1 − ε²)]^½ / [4(1 − ε²)²],
//!   the classic Ocvirk load with ω_j replaced by the sum. With the sleeve held (ω_b = 0) it is
//!   the journal room's short bearing; rolling (ω_b = ω_j) doubles it (the text's start-up claim).
//! - **Torque** (Eq. 18-3, Petroff-type, full film): the shear is driven by the *difference*,
//!   M_h = (L μ R³/C)(ω_j − ω_b) 2π/√(1 − ε²) = 2 n (ω_j − ω_b), with the text's
//!   n = π L μ R³/[C √(1 − ε²)] (Eq. 18-10 with its fraction bar restored).
//! - **Attitude** (the short bearing's, unchanged by ξ): tan ψ = π √(1 − ε²)/(4ε).
//!
//! The torque is quasi-steady: the same formula holds while the sleeve accelerates.

use std::f64::consts::PI;

use crate::calc::journal::orbit::Scales;
use crate::numerics::roots::{brent_bracketed, RootError, Stopping};

/// Where an eccentricity search stops: ε of a film that cannot carry more has
/// h_min = C(1 − ε) below a thousandth of the clearance, far below any surface finish.
pub const MAX_ECCENTRICITY: f64 = 0.999;

/// The bound of the held-sleeve comparison: it carries the composite's load with at most twice
/// the composite's load coefficient, so it may run a little beyond [`MAX_ECCENTRICITY`].
pub const COMPARISON_MAX_ECCENTRICITY: f64 = 1.0 - 1e-9;

/// The film's geometry and viscosity, SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SleeveFilm {
    /// Journal radius R, m.
    pub radius: f64,
    /// Sleeve bore length L, m.
    pub length: f64,
    /// Radial clearance C, m.
    pub clearance: f64,
    /// Dynamic viscosity μ, Pa·s.
    pub viscosity: f64,
}

/// An eccentricity ratio found for a load, with the search's work.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Found {
    pub eccentricity: f64,
    /// Evaluations of the closed-form load.
    pub evaluations: u32,
}

/// Why no ε up to the search's bound carries a load.
#[derive(Debug, Clone, PartialEq)]
pub enum LoadError {
    /// Even at the bound the film carries only `max_load` N.
    TooHeavy { max_load: f64 },
    /// The search failed (a bug: the function is monotone and bracketed by construction).
    Search(RootError),
}

/// ε from the logit v = ln(ε/(1 − ε)): well scaled at both ends (ε → 0 and 1 − ε → 0).
fn eccentricity_of(v: f64) -> f64 {
    1.0 / (1.0 + (-v).exp())
}

/// The logit of ε.
fn logit(eps: f64) -> f64 {
    (eps / (1.0 - eps)).ln()
}

/// The smallest ε a load search returns (a practically concentric journal).
const MIN_ECCENTRICITY: f64 = 1e-12;

impl SleeveFilm {
    /// n = π L μ R³/[C √(1 − ε²)], N·m·s: half the torque per unit relative speed (Eq. 18-10).
    pub fn petroff_coefficient(&self, eps: f64) -> f64 {
        PI * self.length * self.viscosity * self.radius.powi(3)
            / (self.clearance * (1.0 - eps * eps).sqrt())
    }

    /// M_h = 2 n (ω_j − ω_b), N·m: the viscous torque the film exerts on the sleeve (in the
    /// journal's sense) and, equal and opposite, on the journal (Eq. 18-3).
    pub fn torque(&self, eps: f64, journal_speed: f64, sleeve_speed: f64) -> f64 {
        2.0 * self.petroff_coefficient(eps) * (journal_speed - sleeve_speed)
    }

    /// w̄(ε) = ε [16ε² + π²(1 − ε²)]^½ / [4(1 − ε²)²]: the short bearing's load over
    /// μ R (ω_j + ω_b) L³/C².
    pub fn load_coefficient(eps: f64) -> f64 {
        let e2 = eps * eps;
        eps * (16.0 * e2 + PI * PI * (1.0 - e2)).sqrt() / (4.0 * (1.0 - e2).powi(2))
    }

    /// W, N, at ε with the surfaces turning at ω_j + ω_b = `speed_sum`, rad/s.
    pub fn load(&self, eps: f64, speed_sum: f64) -> f64 {
        self.force_scale(speed_sum) * Self::load_coefficient(eps)
    }

    /// μ R (ω_j + ω_b) L³/C², N: the load's scale at the speed sum `speed_sum`, rad/s.
    fn force_scale(&self, speed_sum: f64) -> f64 {
        Scales::of(
            self.viscosity,
            self.radius,
            self.length,
            self.clearance,
            speed_sum,
        )
        .force
    }

    /// The attitude angle ψ between the load line and the line of centres, rad.
    pub fn attitude_angle(eps: f64) -> f64 {
        (PI * (1.0 - eps * eps).sqrt()).atan2(4.0 * eps)
    }

    /// The ε ≤ `max_eccentricity` at which the film carries `load` N when the speed sum follows ε as
    /// `speed_sum(ε)` (constant for a held or rolling sleeve; rising with ε where the sleeve
    /// speed follows the torque balance). W(ε) must rise with ε — it does whenever `speed_sum`
    /// does not fall — so one bracketed root (Brent, in the logit of ε) finds it.
    pub fn eccentricity_for(
        &self,
        load: f64,
        max_eccentricity: f64,
        mut speed_sum: impl FnMut(f64) -> f64,
    ) -> Result<Found, LoadError> {
        let mut evaluations = 0;
        let mut mismatch = |v: f64| {
            evaluations += 1;
            let eps = eccentricity_of(v);
            // A sum of logs: at the smallest loads and speeds the film's load at ε = 1e-12
            // underflows to 0 though the root lies well inside (ln 0 was a 500 in the search).
            self.force_scale(speed_sum(eps)).ln() - load.ln() + Self::load_coefficient(eps).ln()
        };
        let (lo, hi) = (logit(MIN_ECCENTRICITY), logit(max_eccentricity));
        let f_hi = mismatch(hi);
        if f_hi.is_nan() || f_hi < 0.0 {
            let eps = max_eccentricity;
            return Err(LoadError::TooHeavy {
                max_load: self.load(eps, speed_sum(eps)),
            });
        }
        let f_lo = mismatch(lo);
        if f_lo >= 0.0 {
            return Ok(Found {
                eccentricity: MIN_ECCENTRICITY,
                evaluations,
            });
        }
        let stop = Stopping {
            x_tolerance: 1e-13,
            max_iterations: 200,
        };
        let root =
            brent_bracketed(mismatch, (lo, f_lo), (hi, f_hi), stop).map_err(LoadError::Search)?;
        Ok(Found {
            eccentricity: eccentricity_of(root.x),
            evaluations: evaluations + root.iterations,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::calc::journal::closed_form::{short_bearing, Boundary};
    use crate::numerics::roots::brent;

    fn brent_root(f: impl FnMut(f64) -> f64, a: f64, b: f64) -> f64 {
        let stop = Stopping {
            x_tolerance: 1e-14,
            max_iterations: 200,
        };
        brent(f, a, b, stop).unwrap().x
    }

    /// Table 18-1's bearing (spec B-R1): R = 0.05 m, L = 0.1 m, C = 60 µm, μ = 0.03 Pa·s.
    pub(crate) const TABLE_18_1: SleeveFilm = SleeveFilm {
        radius: 0.05,
        length: 0.1,
        clearance: 6e-5,
        viscosity: 0.03,
    };

    fn rad_s(rpm: f64) -> f64 {
        rpm * PI / 30.0
    }

    /// Spec B-R1, derived illustration: M_h = 15.67 N·m at ε = 0.5, 3500 rpm, sleeve 200 rpm.
    #[test]
    fn table_18_1_torque() {
        let m = TABLE_18_1.torque(0.5, rad_s(3500.0), rad_s(200.0));
        assert!((m / 15.67 - 1.0).abs() < 5e-4, "{m}");
        // Exactly (LμR³/C)(ω_j − ω_b) 2π/√(1 − ε²) (Eq. 18-3).
        let direct =
            0.1 * 0.03 * 0.05f64.powi(3) / 6e-5 * rad_s(3300.0) * 2.0 * PI / (1.0 - 0.25f64).sqrt();
        assert!((m / direct - 1.0).abs() < 1e-14);
    }

    /// With the sleeve held the load is the journal room's short bearing (half Sommerfeld):
    /// S = μ N_s L D (R/C)²/W with N_s = ω/2π.
    #[test]
    fn a_held_sleeve_is_the_journal_rooms_short_bearing() {
        let f = TABLE_18_1;
        let omega = rad_s(3500.0);
        for eps in [0.05, 0.3, 0.5, 0.8, 0.95, 0.999] {
            let w = f.load(eps, omega);
            let s =
                short_bearing(eps, f.length / (2.0 * f.radius), Boundary::HalfSommerfeld).unwrap();
            let w_journal = f.viscosity * omega / (2.0 * PI)
                * f.length
                * 2.0
                * f.radius
                * (f.radius / f.clearance).powi(2)
                / s.sommerfeld_number;
            assert!((w / w_journal - 1.0).abs() < 1e-12, "ε {eps}");
            assert!(
                (SleeveFilm::attitude_angle(eps) - s.attitude_angle_rad).abs() < 1e-12,
                "ε {eps}"
            );
        }
    }

    /// Spec B-R2: rolling (ω_b = ω_j) carries at half the journal speed the load a held sleeve
    /// carries at the full speed, at the same ε — an exact ratio 2, searched both ways.
    #[test]
    fn rolling_gives_the_same_film_at_half_the_journal_speed() {
        let f = TABLE_18_1;
        let omega = rad_s(3500.0);
        for eps in [0.1, 0.5, 0.9] {
            let held = f.load(eps, omega);
            let rolling = f.load(eps, 0.5 * omega + 0.5 * omega);
            assert_eq!(held, rolling);
        }
        let load = 20_000.0;
        let held = f
            .eccentricity_for(load, MAX_ECCENTRICITY, |_| omega)
            .unwrap()
            .eccentricity;
        let rolling = f
            .eccentricity_for(load, MAX_ECCENTRICITY, |_| 2.0 * (0.5 * omega))
            .unwrap();
        assert!((rolling.eccentricity - held).abs() < 1e-13);
    }

    /// The search returns the ε whose load is the request's, to round-off in ε and in 1 − ε,
    /// from nearly concentric to nearly touching; the plain Brent on ε agrees.
    #[test]
    fn the_load_search_inverts_the_load() {
        let f = TABLE_18_1;
        let omega = rad_s(3500.0);
        for eps in [1e-6, 0.01, 0.5, 0.9, 0.99, 0.998] {
            let load = f.load(eps, omega);
            let found = f
                .eccentricity_for(load, MAX_ECCENTRICITY, |_| omega)
                .unwrap();
            assert!(
                ((1.0 - found.eccentricity) / (1.0 - eps) - 1.0).abs() < 1e-9
                    && (found.eccentricity / eps - 1.0).abs() < 1e-9,
                "ε {eps}: {found:?}"
            );
            let plain = brent_root(|e| f.load(e, omega) - load, 0.0, MAX_ECCENTRICITY);
            assert!(
                (plain - eps).abs() < 1e-9 * eps.max(1e-3),
                "ε {eps}: {plain}"
            );
        }
        let max = f.load(MAX_ECCENTRICITY, omega);
        assert_eq!(
            f.eccentricity_for(2.0 * max, MAX_ECCENTRICITY, |_| omega),
            Err(LoadError::TooHeavy { max_load: max })
        );
    }
}
