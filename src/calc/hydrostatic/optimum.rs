//! The texts' optimisation of a circular step pad: for a load W and an outer radius R2, the
//! recess ratio x = R1/R2 and the film h that minimise the total power E_p + E_f
//! (Khonsari & Booser §10.3, Eq. 10.17–10.20; Stachowiak & Batchelor §6.4, Eq. 6.20–6.22).
//!
//! At a fixed load E_p = W² h³ B̄/(μ η A_eff²) rises as h³ and E_f = π μ ω² R2⁴(1 − x⁴)/(2h)
//! falls as 1/h, so for each x the best film is where E_f = 3 E_p (ζ = 3, Stachowiak &
//! Batchelor's optimum clearance), h* = (E_f h/(3 E_p/h³))^¼, or the floor the user sets.
//!
//! - Film held: the total over x is minimised — at rest Eq. 10.19's 0.53354 whatever the film;
//!   at speed the friction moves it to a larger recess. The search: a scan of [0.05, 0.95]
//!   (spec H-7: away from the trivial root x = 1), then Brent's minimiser between the best
//!   scan point's neighbours.
//! - Film free: the texts' two steps. The joint minimum over x and h does not exist inside the
//!   model: with h = h*(x) the total is (4/3)E_f(h*) ∝ [(1 − x⁴)³ ln(1/x)/(1 − x²)²]^¼, which
//!   falls to 0 as x → 1 while h*/(R2 − R1) grows without bound — the land vanishes under a
//!   film that is no longer thin (the tests show it). So, as Stachowiak & Batchelor §6.4 do
//!   (Eq. 6.22: minimise H̄ for the geometry, then set the clearance), the recess ratio is the
//!   one that needs the least pumping power for the load and film, Eq. 10.19's 0.53354
//!   (independent of h), and the film is h* at that ratio.

use std::f64::consts::PI;

use crate::numerics::optimise::brent_minimise;

/// The recess ratios searched.
pub const RATIOS: (f64, f64) = (0.05, 0.95);

/// How the film is chosen.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FilmChoice {
    /// The film is given, m.
    Fixed(f64),
    /// The power-minimising film (needs speed), at least `min`, m.
    Free { min: Option<f64> },
}

/// A minimum-power design problem, SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Problem {
    pub outer_radius: f64,
    pub load: f64,
    /// μ, Pa·s.
    pub viscosity: f64,
    /// ω, rad/s (0 at rest).
    pub omega: f64,
    pub pump_efficiency: f64,
    pub film: FilmChoice,
}

/// One design point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DesignPoint {
    pub ratio: f64,
    pub film: f64,
    /// p_s = p_r = W/A_eff, Pa (constant flow).
    pub supply: f64,
    pub flow: f64,
    pub pumping: f64,
    pub friction: f64,
    pub friction_torque: f64,
}

impl DesignPoint {
    pub fn total(&self) -> f64 {
        self.pumping + self.friction
    }
}

impl Problem {
    /// (E_p/h³, E_f·h) at ratio x: the film's two power coefficients.
    fn coefficients(&self, x: f64) -> (f64, f64, f64, f64) {
        let r2 = self.outer_radius;
        let ln = (1.0 / x).ln();
        let area = PI * r2 * r2 * (1.0 - x * x) / (2.0 * ln);
        let supply = self.load / area;
        let c2 = PI / (6.0 * self.viscosity * ln);
        let pumping = supply * c2 * supply / self.pump_efficiency;
        let torque = PI * self.viscosity * self.omega * r2.powi(4) * (1.0 - x.powi(4)) / 2.0;
        (pumping, torque * self.omega, supply, c2)
    }

    /// The best film at ratio x (or the given one).
    pub fn film_at(&self, x: f64) -> f64 {
        match self.film {
            FilmChoice::Fixed(h) => h,
            FilmChoice::Free { min } => {
                let (a, b, _, _) = self.coefficients(x);
                let h = (b / (3.0 * a)).powf(0.25);
                min.map_or(h, |m| h.max(m))
            }
        }
    }

    /// The design at ratio x and film h.
    pub fn point(&self, x: f64, h: f64) -> DesignPoint {
        let (a, b, supply, c2) = self.coefficients(x);
        DesignPoint {
            ratio: x,
            film: h,
            supply,
            flow: c2 * h.powi(3) * supply,
            pumping: a * h.powi(3),
            friction: b / h,
            friction_torque: if self.omega > 0.0 {
                b / h / self.omega
            } else {
                0.0
            },
        }
    }

    /// The design at ratio x with its best film.
    pub fn at_ratio(&self, x: f64) -> DesignPoint {
        self.point(x, self.film_at(x))
    }

    /// The minimum-power design and the number of power evaluations it took.
    pub fn optimum(&self) -> (DesignPoint, u32) {
        if let FilmChoice::Free { .. } = self.film {
            let x = super::geometry::minimum_pumping_ratio();
            return (self.at_ratio(x), 1);
        }
        const SCAN: usize = 36;
        let (lo, hi) = RATIOS;
        let step = (hi - lo) / SCAN as f64;
        let total = |x: f64| self.at_ratio(x).total();
        let best = (0..=SCAN)
            .map(|i| lo + step * i as f64)
            .min_by(|a, b| total(*a).total_cmp(&total(*b)))
            .unwrap_or(0.5);
        let mut evaluations = SCAN as u32 + 1;
        let (a, b) = ((best - step).max(lo), (best + step).min(hi));
        let (x, _) = brent_minimise(
            |x| {
                evaluations += 1;
                total(x)
            },
            a,
            b,
            1e-10,
        );
        (self.at_ratio(x), evaluations)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn problem(omega: f64, film: FilmChoice) -> Problem {
        Problem {
            outer_radius: 0.2032,
            load: 479_073.0,
            viscosity: 0.054_124,
            omega,
            pump_efficiency: 0.8,
            film,
        }
    }

    /// At rest the optimum is Eq. 10.19's root whatever the film.
    #[test]
    fn at_rest_the_optimum_is_eq_10_19() {
        let want = super::super::geometry::minimum_pumping_ratio();
        for h in [1e-5, 7.62e-5, 3e-4] {
            let (d, _) = problem(0.0, FilmChoice::Fixed(h)).optimum();
            assert!((d.ratio - want).abs() < 1e-7, "{h}: {}", d.ratio);
            assert_eq!(d.friction, 0.0);
        }
    }

    /// With speed and a free film, the optimum film makes friction three times the pumping
    /// power (Stachowiak & Batchelor's ζ = 3), and it is a minimum in h: a golden-section
    /// search on the total power at the optimum ratio finds the same film.
    #[test]
    fn at_speed_the_optimum_film_has_zeta_3() {
        let p = problem(100.0, FilmChoice::Free { min: None });
        let (d, _) = p.optimum();
        assert!((d.friction / d.pumping - 3.0).abs() < 1e-9);
        let (h, _) = brent_minimise(|h| p.point(d.ratio, h).total(), 1e-6, 1e-3, 1e-13);
        assert!((h / d.film - 1.0).abs() < 1e-5, "{h} vs {}", d.film);
        assert!((d.ratio - 0.533_543).abs() < 1e-6);
    }

    /// Why the free-film design does not minimise over x as well: at each ratio's best film the
    /// total power keeps falling towards x = 1 while the film outgrows the land.
    #[test]
    fn the_joint_minimum_runs_off_the_thin_film_model() {
        let p = problem(100.0, FilmChoice::Free { min: None });
        let mut last = (f64::INFINITY, 0.0);
        for i in 1..=19 {
            let x = 0.05 * i as f64;
            let d = p.at_ratio(x);
            let thickness = d.film / (p.outer_radius * (1.0 - x));
            assert!(d.total() < last.0 && thickness > last.1, "{x}");
            last = (d.total(), thickness);
        }
        let x = 1.0 - 1e-6;
        assert!(p.at_ratio(x).film > p.outer_radius * (1.0 - x));
    }

    /// With the film held at speed, the optimum ratio is a minimum of the total over x, above
    /// the at-rest 0.5335 (friction favours a smaller land).
    #[test]
    fn a_held_film_at_speed_moves_the_ratio_up() {
        let p = problem(20.0, FilmChoice::Fixed(7.62e-5));
        let (d, _) = p.optimum();
        assert!(d.ratio > 0.54 && d.ratio < 0.95, "{}", d.ratio);
        for dx in [-1e-3, 1e-3] {
            assert!(p.at_ratio(d.ratio + dx).total() > d.total());
        }
    }

    /// A film floor above the free optimum binds.
    #[test]
    fn a_film_floor_binds() {
        let p = problem(10.0, FilmChoice::Free { min: Some(5e-4) });
        let (d, _) = p.optimum();
        assert_eq!(d.film, 5e-4);
    }
}
