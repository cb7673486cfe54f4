//! The lands' film law: the flow Q and the effective area A_eff (W = A_eff p_r) as functions of
//! s = h³ p_r, laminar or with the texts' turbulent slit law.
//!
//! - Laminar (Khonsari & Booser §10.3): Q = B̄ s/μ and A_eff is fixed by the geometry.
//! - Turbulent pressure flow: the slit law (Khonsari & Booser Eq. 16.2),
//!   ṁ = 4.71 w (ρh³Δp/(μ^¼ L))^{4/7}, is h³|dp/dx| = K q′^{7/4} with q′ = Q/w the flow per unit
//!   width and K = 4.71^{−7/4} ρ^¾ μ^¼ (Blasius for a hydraulic diameter 2h). Laminar it is
//!   12 μ q′. Each point of a land takes the larger (§7.11: where in doubt, the regime with the
//!   higher loss is the one to expect); they cross at ρq′/μ = (12 · 4.71^{7/4})^{4/3} = 1021, a
//!   Reynolds number ρU·2h/μ of 2043 (§16.1's laminar limit is 2000).
//! - A radial land a … b (the circular step's, both of the annulus) carries q′ = Q/(2πr): it is
//!   turbulent inside r_t = Q/(2π q′_c) and laminar outside, and both parts integrate in closed
//!   form: s = ∫ g dr, and by parts A_eff = ∫ πr² g dr / ∫ g dr (Eq. 10.5 when g ∝ 1/r). The
//!   inner land of an annulus enters with the opposite sign (its pressure rises outward).
//! - The rectangular pad's strips carry a uniform q′: their profile stays linear in either
//!   regime, and A_eff does not move.
//!
//! h enters only through s: the flow's regime depends on Q alone.

use std::f64::consts::PI;

use crate::numerics::roots::{brent, brent_fallible, RootError, Stopping};

/// Eq. 16.2's constant: ṁ = 4.71 w (ρh³Δp/(μ^¼ L))^{4/7}.
pub const SLIT_CONSTANT: f64 = 4.71;

/// The slit law at one oil state: viscosity μ (Pa·s) and mass density ρ (kg/m³).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Slit {
    pub mu: f64,
    pub rho: f64,
}

impl Slit {
    /// K in h³|dp/dx| = K q′^{7/4}: 4.71^{−7/4} ρ^¾ μ^¼.
    fn turbulent_coefficient(self) -> f64 {
        SLIT_CONSTANT.powf(-1.75) * self.rho.powf(0.75) * self.mu.powf(0.25)
    }

    /// q′_c, m²/s: where 12 μ q′ = K q′^{7/4}.
    pub fn crossing(self) -> f64 {
        (12.0 * self.mu / self.turbulent_coefficient()).powf(4.0 / 3.0)
    }

    /// h³|dp/dx| at flow per unit width q′: the larger of the laminar and turbulent laws.
    pub fn gradient(self, q: f64) -> f64 {
        (12.0 * self.mu * q).max(self.turbulent_coefficient() * q.powf(1.75))
    }

    /// q′ at h³|dp/dx| = g: the smaller of the two laws' flows (the inverse of `gradient`).
    pub fn flow(self, g: f64) -> f64 {
        (g / (12.0 * self.mu)).min((g / self.turbulent_coefficient()).powf(4.0 / 7.0))
    }
}

/// A radial land between radii `inner` and `outer`, m.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RadialLand {
    pub inner: f64,
    pub outer: f64,
}

impl RadialLand {
    /// (s/Q, ∫πr²g dr/Q) at flow Q: the drop times h³ and the load moment, per unit flow
    /// (finite as Q → 0, where the land is laminar).
    fn per_flow(self, slit: Slit, q: f64) -> (f64, f64) {
        let (a, b) = (self.inner, self.outer);
        let rt = (q / (2.0 * PI * slit.crossing())).clamp(a, b);
        // Laminar on [r_t, b]: g = 12 μ Q/(2πr); turbulent on [a, r_t]: g = K (Q/2πr)^{7/4}.
        let laminar = 6.0 * slit.mu / PI;
        let turbulent = slit.turbulent_coefficient() * q.powf(0.75) / (2.0 * PI).powf(1.75);
        let drop =
            laminar * (b / rt).ln() + turbulent * 4.0 / 3.0 * (a.powf(-0.75) - rt.powf(-0.75));
        let moment = laminar * PI * (b * b - rt * rt) / 2.0
            + turbulent * PI * 0.8 * (rt.powf(1.25) - a.powf(1.25));
        (drop, moment)
    }

    /// s = h³Δp across the land at flow Q, and the land's share of A_eff as ∫πr²g/∫g, m².
    fn at_flow(self, slit: Slit, q: f64) -> (f64, f64) {
        let (drop, moment) = self.per_flow(slit, q);
        (q * drop, moment / drop)
    }

    /// Q at s, by Brent between the flows of the two pure laws (the composite's drop is at
    /// least either's and at most their sum).
    fn flow(self, slit: Slit, s: f64) -> Result<f64, RootError> {
        if s <= 0.0 {
            return Ok(0.0);
        }
        let (a, b) = (self.inner, self.outer);
        let laminar = |s: f64| PI * s / (6.0 * slit.mu * (b / a).ln());
        let turbulent = |s: f64| {
            let k = slit.turbulent_coefficient() / (2.0 * PI).powf(1.75);
            (s / (k * 4.0 / 3.0 * (a.powf(-0.75) - b.powf(-0.75)))).powf(4.0 / 7.0)
        };
        // The bound is exact where the land is all one regime: widened past round-off.
        let hi = laminar(s).min(turbulent(s)) * (1.0 + 1e-9);
        let lo = laminar(0.5 * s).min(turbulent(0.5 * s));
        let root = brent(|q| self.at_flow(slit, q).0 / s - 1.0, lo, hi, stop(hi))?;
        Ok(root.x)
    }
}

/// Brent's stopping rule here: 1e-14 of the bracket's scale.
fn stop(scale: f64) -> Stopping {
    Stopping {
        x_tolerance: 1e-14 * scale,
        max_iterations: 200,
    }
}

/// The laminar film's two constants at one viscosity.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Film {
    /// A_eff, m².
    pub area: f64,
    /// c₂ = B̄/μ, m/(Pa·s): Q = c₂ h³ p_r.
    pub c2: f64,
}

/// How the lands pass flow and carry load.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Lands {
    /// Q = c₂ s, A_eff fixed: every pad laminar, and the chart-factor pads always.
    Laminar(Film),
    /// A central recess's outward land, and an annulus's inward land where there is one.
    Radial {
        slit: Slit,
        outward: RadialLand,
        inward: Option<RadialLand>,
    },
    /// Strips of total width `width` (at their mean lengths) and length `length` across the
    /// flow, carrying the fixed `area`.
    Strips {
        slit: Slit,
        width: f64,
        length: f64,
        area: f64,
    },
}

impl Lands {
    /// (Q, A_eff) at s = h³ p_r.
    pub fn at(&self, s: f64) -> Result<(f64, f64), RootError> {
        match *self {
            Lands::Laminar(Film { area, c2 }) => Ok((c2 * s, area)),
            Lands::Radial {
                slit,
                outward,
                inward,
            } => {
                let q = outward.flow(slit, s)?;
                let (_, area) = outward.at_flow(slit, q);
                match inward {
                    None => Ok((q, area)),
                    Some(land) => {
                        let q_in = land.flow(slit, s)?;
                        Ok((q + q_in, area - land.at_flow(slit, q_in).1))
                    }
                }
            }
            Lands::Strips {
                slit,
                width,
                length,
                area,
            } => Ok((width * slit.flow(s / length), area)),
        }
    }

    /// (s, A_eff) at flow Q. Two radial lands share Q at one s: found by Brent between the
    /// drops of either land carrying all of Q and the smaller of theirs carrying half.
    pub fn at_flow(&self, q: f64) -> Result<(f64, f64), RootError> {
        match *self {
            Lands::Laminar(Film { area, c2 }) => Ok((q / c2, area)),
            Lands::Radial {
                slit,
                outward,
                inward: None,
            } => Ok(outward.at_flow(slit, q)),
            Lands::Radial {
                slit,
                outward,
                inward: Some(land),
            } => {
                if q <= 0.0 {
                    return self.at(0.0).map(|(_, area)| (0.0, area));
                }
                let drop = |q: f64| (outward.at_flow(slit, q).0, land.at_flow(slit, q).0);
                let (whole_out, whole_in) = drop(q);
                let (half_out, half_in) = drop(0.5 * q);
                let (lo, hi) = (half_out.min(half_in), whole_out.max(whole_in));
                let s = brent_fallible(
                    |s| self.at(s).map(|(flow, _)| flow / q - 1.0),
                    lo,
                    hi,
                    stop(hi),
                )?
                .x;
                self.at(s).map(|(_, area)| (s, area))
            }
            Lands::Strips {
                slit,
                width,
                length,
                area,
            } => Ok((length * slit.gradient(q / width), area)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn oil() -> Slit {
        Slit {
            mu: 0.01,
            rho: 850.0,
        }
    }

    /// Eq. 16.2 is the turbulent law: a slit of width w and length L at Δp passes
    /// ṁ = 4.71 w (ρh³Δp/(μ^¼L))^{4/7} where that is below the laminar ρh³wΔp/(12μL) (Eq. 16.1),
    /// and the two cross at a Reynolds number ρU·2h/μ of 2043.
    #[test]
    fn slit_is_eq_16_2_beyond_the_crossing() {
        let slit = oil();
        let (w, l, h): (f64, f64, f64) = (0.1, 0.02, 2e-4);
        let re_crossing = 2.0 * slit.rho * slit.crossing() / slit.mu;
        assert!((re_crossing - 2043.0).abs() < 1.0, "{re_crossing}");
        for dp in [1e3, 1e5, 1e7] {
            let m_dot = slit.rho * w * slit.flow(h.powi(3) * dp / l);
            let laminar = slit.rho * h.powi(3) * w * dp / (12.0 * slit.mu * l);
            let turbulent = SLIT_CONSTANT
                * w
                * (slit.rho * h.powi(3) * dp / (slit.mu.powf(0.25) * l)).powf(4.0 / 7.0);
            assert!((m_dot / laminar.min(turbulent) - 1.0).abs() < 1e-13, "{dp}");
            let q = m_dot / (slit.rho * w);
            assert!((slit.gradient(q) * l / (h.powi(3) * dp) - 1.0).abs() < 1e-13);
        }
    }

    /// The radial land's closed forms against a fine midpoint rule of g(Q/2πr), in the laminar,
    /// mixed and turbulent regimes; laminar they are Eq. 10.5–10.6.
    #[test]
    fn radial_land_integrates_its_gradient() {
        let slit = oil();
        let land = RadialLand {
            inner: 0.03,
            outer: 0.07,
        };
        let qc = slit.crossing();
        for q in [1e-3 * qc, 2.0 * PI * 0.05 * qc, 10.0 * qc] {
            let n = 200_000;
            let dr = (land.outer - land.inner) / n as f64;
            let (mut s, mut m) = (0.0, 0.0);
            for i in 0..n {
                let r = land.inner + (i as f64 + 0.5) * dr;
                let g = slit.gradient(q / (2.0 * PI * r));
                s += g * dr;
                m += PI * r * r * g * dr;
            }
            let (got_s, got_a) = land.at_flow(slit, q);
            assert!((got_s / s - 1.0).abs() < 1e-8, "{q}: {got_s} vs {s}");
            assert!((got_a / (m / s) - 1.0).abs() < 1e-8, "{q}");
            assert!((land.flow(slit, got_s).unwrap() / q - 1.0).abs() < 1e-12);
        }
        let q = 1e-3 * qc;
        let ln = (land.outer / land.inner).ln();
        let (s, area) = land.at_flow(slit, q);
        assert!((s / (6.0 * slit.mu * q * ln / PI) - 1.0).abs() < 1e-14);
        let eq_10_5 = PI * (land.outer.powi(2) - land.inner.powi(2)) / (2.0 * ln);
        assert!((area / eq_10_5 - 1.0).abs() < 1e-14);
    }

    /// The annulus in the mixed regime against its pressure field integrated independently:
    /// each land's p(r) by a midpoint rule of g(Q_land/2πr) from its exit, the recess at p_r,
    /// W/p_r = ∫p dA/p_r.
    #[test]
    fn annulus_area_integrates_its_pressure_field() {
        let slit = oil();
        let (a, b, c, d) = (0.03, 0.05, 0.06, 0.09);
        let lands = Lands::Radial {
            slit,
            outward: RadialLand { inner: c, outer: d },
            inward: Some(RadialLand { inner: a, outer: b }),
        };
        // Each land turbulent where its flow per unit width peaks (c, a) and laminar at its
        // other edge (d, b): the first such s on a fine scan.
        let mixed = |s: f64| {
            let q_out = lands_flow(&RadialLand { inner: c, outer: d }, slit, s);
            let q_in = lands_flow(&RadialLand { inner: a, outer: b }, slit, s);
            let between = |q: f64, near: f64, far: f64| {
                q / (2.0 * PI * near) > slit.crossing() && q / (2.0 * PI * far) < slit.crossing()
            };
            between(q_out, c, d) && between(q_in, a, b)
        };
        let s = (0..400)
            .map(|i| 1e-6 * 1.02f64.powi(i))
            .find(|&s| mixed(s))
            .expect("a mixed annulus");
        let (q, area) = lands.at(s).unwrap();
        let n = 100_000;
        // One land's load ∫p 2πr dr, p rising from 0 at `exit` towards the recess.
        let land = |q_land: f64, from: f64, to: f64| {
            let (mut p, mut load) = (0.0, 0.0);
            let dr = (to - from) / n as f64;
            for i in 0..n {
                let r = from + (i as f64 + 0.5) * dr;
                let step = slit.gradient(q_land / (2.0 * PI * r)) * dr.abs();
                p += 0.5 * step;
                load += p * 2.0 * PI * r * dr.abs();
                p += 0.5 * step;
            }
            (p, load)
        };
        let q_out = lands_flow(&RadialLand { inner: c, outer: d }, slit, s);
        let q_in = q - q_out;
        let (p_out, w_out) = land(q_out, d, c);
        let (p_in, w_in) = land(q_in, a, b);
        assert!((p_out / s - 1.0).abs() < 1e-8 && (p_in / s - 1.0).abs() < 1e-8);
        let want = (w_out + w_in) / s + PI * (c * c - b * b);
        assert!((area / want - 1.0).abs() < 1e-8, "{area} vs {want}");
    }

    fn lands_flow(land: &RadialLand, slit: Slit, s: f64) -> f64 {
        land.flow(slit, s).unwrap()
    }

    /// Two lands share one s: the annulus's flow splits so that both drop the same pressure, and
    /// `at_flow` inverts `at`.
    #[test]
    fn annulus_lands_share_the_drop() {
        let slit = oil();
        let lands = Lands::Radial {
            slit,
            outward: RadialLand {
                inner: 0.05,
                outer: 0.07,
            },
            inward: Some(RadialLand {
                inner: 0.02,
                outer: 0.03,
            }),
        };
        for s in [1e-9, 1e-6, 1e-4] {
            let (q, area) = lands.at(s).unwrap();
            let (back, area_back) = lands.at_flow(q).unwrap();
            assert!((back / s - 1.0).abs() < 1e-10, "{s}: {back}");
            assert!((area_back / area - 1.0).abs() < 1e-10);
        }
    }
}
