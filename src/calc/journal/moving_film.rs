//! The film force on a journal that moves: the infinitely short bearing (Ocvirk) with the
//! squeeze term, for orbits (Harnoy ch. 18, Eqs 18-22 to 18-28 as corrected in the spec, B.1.1–
//! B.1.2; Booker's squeeze-vector form).
//!
//! Frame and signs: bearing-fixed, x horizontal, y up, θ counter-clockwise from +x; the journal
//! turns counter-clockwise at ω_j and the bearing (a composite bearing's sleeve) at ω_b. The
//! journal centre sits at r = (x, y) and moves at v; the film is h = C − r·n, n = (cos θ, sin θ).
//!
//! Model: the short-bearing Reynolds equation ∂z(h³ ∂z p) = 6μ(ω_j + ω_b) ∂θh + 12μ ∂t h, with
//! p = 0 at z = ±L/2. Its right side is exactly −12μ w·n, with the squeeze vector
//! w = v − ½(ω_j + ω_b) k × r: a turning journal is a journal squeezing at w (Booker). So
//! p = (6μ/h³)(w·n)(L²/4 − z²), and the force on the journal is
//!
//! F = −μ R L³ ∫ (w·n) n / h³ dθ over the film's active arc:
//! - `PiFilm`: where p > 0, the π-wide arc centred on w (the dynamic half-Sommerfeld film: the
//!   arc moves with the squeeze velocity);
//! - `FixedArc`: the arc [0, π] from the maximum film in the direction of rotation (Harnoy's
//!   "book mode", the Gümbel condition of the steady film);
//! - `Full`: the whole circle, negative pressures kept (the Sommerfeld film).
//!
//! The arc integrals are exact: Sommerfeld's substitution turns ∫ sinᵃβ cosᵇβ/(1 + ε cos β)³ dβ
//! (β from the maximum film) with a + b = 2 into trigonometric polynomials.
//!
//! Dimensionless: r̄ = r/C, w̄ = w/(C ω_j), F̄ = F C²/(μ R ω_j L³) (Harnoy's scaling), and the
//! peak pressure p̄ = p/(μ ω_j (L/C)²).

use std::f64::consts::PI;

use crate::numerics::optimise::brent_minimise;
use crate::numerics::roots::{brent, Stopping};

/// Which part of the short film carries pressure.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ShortArc {
    PiFilm,
    FixedArc,
    Full,
}

/// The largest eccentricity ratio a film force is evaluated at; beyond it the journal touches
/// (h_min = 10⁻⁹ C).
pub const CONTACT: f64 = 1.0 - 1e-9;

/// w̄ = v̄ − ½Ω̄ k × r̄, with Ω̄ = (ω_j + ω_b)/ω_j.
#[must_use]
pub fn squeeze_vector(position: [f64; 2], velocity: [f64; 2], speed_sum: f64) -> [f64; 2] {
    [
        velocity[0] + 0.5 * speed_sum * position[1],
        velocity[1] - 0.5 * speed_sum * position[0],
    ]
}

/// The film's integrals over an arc of β (from the maximum film): [[∫cos², ∫sin cos],
/// [∫sin cos, ∫sin²]] of 1/(1 + ε cos β)³.
struct ArcIntegrals {
    eps: f64,
}

impl ArcIntegrals {
    /// Sommerfeld's angle γ(β), continuous in β (|γ − β| < π).
    fn gamma(&self, beta: f64) -> f64 {
        let s = (1.0 - self.eps * self.eps).sqrt();
        let g = (s * beta.sin()).atan2(self.eps + beta.cos());
        g + 2.0 * PI * ((beta - g) / (2.0 * PI)).round()
    }

    /// The antiderivatives [cc, sc, ss] at β.
    fn primitive(&self, beta: f64) -> [f64; 3] {
        let e = self.eps;
        let q = 1.0 - e * e;
        let g = self.gamma(beta);
        let (sg, cg) = g.sin_cos();
        let s2g = 2.0 * sg * cg;
        let cc = (g / 2.0 + s2g / 4.0 - 2.0 * e * sg + e * e * g) / q.powf(2.5);
        let sc = (sg * sg / 2.0 + e * cg) / (q * q);
        let ss = (g / 2.0 - s2g / 4.0) / q.powf(1.5);
        [cc, sc, ss]
    }

    fn over(&self, from: f64, to: f64) -> [f64; 3] {
        let (a, b) = (self.primitive(from), self.primitive(to));
        [b[0] - a[0], b[1] - a[1], b[2] - a[2]]
    }
}

/// The state of the film for one position and squeeze vector.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShortFilm {
    pub arc: ShortArc,
    /// Ω̄ = (ω_j + ω_b)/ω_j: the fixed arc's direction follows the rotation's sign.
    pub speed_sum: f64,
}

impl ShortFilm {
    /// F̄ on the journal at r̄ with squeeze vector w̄; None at or beyond contact.
    #[must_use]
    pub fn force(&self, position: [f64; 2], squeeze: [f64; 2]) -> Option<[f64; 2]> {
        let eps = position[0].hypot(position[1]);
        if eps.is_nan() || eps >= CONTACT || !squeeze.iter().all(|w| w.is_finite()) {
            return None;
        }
        let (c, s, [wa, wb]) = line_of_centres(position, squeeze);
        if wa == 0.0 && wb == 0.0 && self.arc != ShortArc::Full {
            return Some([0.0, 0.0]);
        }
        // β from the maximum film (θ = φ + π + β); n = −(cos β, sin β) in (a, b), so
        // w̄·n = −(w_a cos β + w_b sin β).
        let (from, to) = match self.arc {
            ShortArc::Full => (0.0, 2.0 * PI),
            ShortArc::FixedArc if self.speed_sum >= 0.0 => (0.0, PI),
            ShortArc::FixedArc => (PI, 2.0 * PI),
            // p > 0 where w̄·n > 0: β within ±π/2 of the direction opposite w̄.
            ShortArc::PiFilm => {
                let centre = (-wb).atan2(-wa);
                (centre - 0.5 * PI, centre + 0.5 * PI)
            }
        };
        let [cc, sc, ss] = ArcIntegrals { eps }.over(from, to);
        // F̄ = −∫ (w̄·n) n/h̄³ = −M w̄ with M = ∫ n nᵀ/h̄³ (n's sign cancels in n nᵀ).
        let fa = -(cc * wa + sc * wb);
        let fb = -(sc * wa + ss * wb);
        let force = [fa * c - fb * s, fa * s + fb * c];
        force.iter().all(|f| f.is_finite()).then_some(force)
    }

    /// Booker's mobility: the squeeze vector w̄ at which the film carries `load` (F̄_film =
    /// −F̄_load), for a massless journal. The half films and the full film are linear in w̄ at a
    /// fixed arc (a 2 × 2 solve); the π-film's arc turns with w̄, so its direction ψ is the root
    /// of the angle between M(ψ)ŵ(ψ) and the load, bracketed within ±π/2 of the load because
    /// M is positive definite (M ŵ stays within 90° of ŵ). None at contact.
    #[must_use]
    pub fn squeeze_for(&self, position: [f64; 2], load: [f64; 2]) -> Option<[f64; 2]> {
        let magnitude = load[0].hypot(load[1]);
        if magnitude == 0.0 {
            return self.force(position, [0.0, 0.0]).map(|_| [0.0, 0.0]);
        }
        // −F̄_film(ŵ) for a unit squeeze along ψ.
        let response = |psi: f64| -> Option<[f64; 2]> {
            let f = self.force(position, [psi.cos(), psi.sin()])?;
            Some([-f[0], -f[1]])
        };
        if self.arc == ShortArc::PiFilm {
            return mobility_squeeze(response, load);
        }
        // Linear: solve M w̄ = F̄ from the responses to the two unit squeezes.
        let (rx, ry) = (response(0.0)?, response(0.5 * PI)?);
        let det = rx[0] * ry[1] - ry[0] * rx[1];
        let w = [
            (load[0] * ry[1] - ry[0] * load[1]) / det,
            (rx[0] * load[1] - load[0] * rx[1]) / det,
        ];
        w.iter().all(|v| v.is_finite()).then_some(w)
    }

    /// The peak film pressure p̄ = max 1.5 (w̄·n)/h̄³ over the active arc (mid-plane): the best
    /// of 96 points, refined by Brent's minimisation between its neighbours.
    #[must_use]
    pub fn peak_pressure(&self, position: [f64; 2], squeeze: [f64; 2]) -> f64 {
        const POINTS: usize = 96;
        let eps = position[0].hypot(position[1]);
        if eps.is_nan() || eps >= CONTACT {
            return f64::INFINITY;
        }
        let fixed_from = if eps > 0.0 {
            position[1].atan2(position[0]) + PI
        } else {
            PI
        };
        let pressure = |theta: f64| {
            let n = [theta.cos(), theta.sin()];
            let h = 1.0 - position[0] * n[0] - position[1] * n[1];
            let wn = squeeze[0] * n[0] + squeeze[1] * n[1];
            let on_arc = match self.arc {
                ShortArc::PiFilm | ShortArc::Full => true,
                ShortArc::FixedArc => {
                    let beta = (theta - fixed_from).rem_euclid(2.0 * PI);
                    (beta <= PI) == (self.speed_sum >= 0.0)
                }
            };
            if on_arc {
                1.5 * wn / (h * h * h)
            } else {
                0.0
            }
        };
        let step = 2.0 * PI / POINTS as f64;
        let (best, value) = (0..POINTS)
            .map(|i| (i, pressure(i as f64 * step)))
            .fold((0, f64::NEG_INFINITY), |a, b| if b.1 > a.1 { b } else { a });
        let t = best as f64 * step;
        let (_, minus_peak) = brent_minimise(|theta| -pressure(theta), t - step, t + step, 1e-10);
        let peak = (-minus_peak).max(value);
        peak.max(0.0)
    }
}

/// The line-of-centres frame of r̄: a along r̄ (towards the minimum film; +x at the centre),
/// b = k × a. Returns cos φ, sin φ of a's direction and w̄'s components (w_a, w_b).
#[must_use]
pub fn line_of_centres(position: [f64; 2], squeeze: [f64; 2]) -> (f64, f64, [f64; 2]) {
    let phi = if position[0] != 0.0 || position[1] != 0.0 {
        position[1].atan2(position[0])
    } else {
        0.0
    };
    let (s, c) = phi.sin_cos();
    (
        c,
        s,
        [
            squeeze[0] * c + squeeze[1] * s,
            -squeeze[0] * s + squeeze[1] * c,
        ],
    )
}

/// Booker's mobility for a film whose force is positively homogeneous of degree 1 in the
/// squeeze vector and dissipative (−F̄·w̄ > 0, so the response to a unit squeeze stays within
/// 90° of it): `response(ψ)` is −F̄_film for the unit squeeze along ψ, and the squeeze that
/// carries `load` (non-zero) points along the root ψ of the angle between the response and the
/// load, bracketed within ±π/2 of the load, scaled by |load|/|response(ψ)|. None when the
/// response is refused (contact) or the root is not found.
#[must_use]
pub fn mobility_squeeze(
    response: impl Fn(f64) -> Option<[f64; 2]>,
    load: [f64; 2],
) -> Option<[f64; 2]> {
    let target = load[1].atan2(load[0]);
    // Continuous angle of the response, unwrapped about ψ (it lies within ±π/2).
    let miss = |psi: f64| match response(psi) {
        Some(r) => {
            let turn = (r[1].atan2(r[0]) - psi + PI).rem_euclid(2.0 * PI) - PI;
            psi + turn - target
        }
        None => f64::NAN,
    };
    let stop = Stopping {
        x_tolerance: 1e-13,
        max_iterations: 100,
    };
    let direction = brent(miss, target - 0.5 * PI, target + 0.5 * PI, stop)
        .ok()?
        .x;
    let unit = response(direction)?;
    let scale = load[0].hypot(load[1]) / unit[0].hypot(unit[1]);
    let w = [scale * direction.cos(), scale * direction.sin()];
    w.iter().all(|v| v.is_finite()).then_some(w)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::quadrature;

    fn film(arc: ShortArc) -> ShortFilm {
        ShortFilm {
            arc,
            speed_sum: 1.0,
        }
    }

    /// The journal at rest at ε along angle φ: w̄ = −½ k × r̄.
    fn steady(arc: ShortArc, eps: f64, phi: f64) -> [f64; 2] {
        let r = [eps * phi.cos(), eps * phi.sin()];
        film(arc)
            .force(r, squeeze_vector(r, [0.0, 0.0], 1.0))
            .unwrap()
    }

    #[test]
    fn the_arc_integrals_are_the_texts_closed_forms_and_agree_with_quadrature() {
        // J₁₁, J₁₂, J₂₂ over [0, π] (spec B.1.2) and an arbitrary arc by adaptive quadrature.
        for eps in [0.0, 0.3, 0.7, 0.95, 0.995] {
            let q: f64 = 1.0 - eps * eps;
            let [cc, sc, ss] = ArcIntegrals { eps }.over(0.0, PI);
            assert!((ss / (PI / (2.0 * q.powf(1.5))) - 1.0).abs() < 1e-12);
            assert!((sc - (-2.0 * eps / (q * q))).abs() < 1e-12 * (1.0 + sc.abs()));
            assert!(
                (cc / (PI * (1.0 + 2.0 * eps * eps) / (2.0 * q.powf(2.5))) - 1.0).abs() < 1e-12
            );
            let (a, b) = (-2.1, 1.9);
            let got = ArcIntegrals { eps }.over(a, b);
            let integrands: [fn(f64) -> f64; 3] = [
                |b| b.cos().powi(2),
                |b| b.sin() * b.cos(),
                |b| b.sin().powi(2),
            ];
            for (k, g) in integrands.iter().enumerate() {
                let want = quadrature::adaptive_gauss_kronrod(
                    |beta| Ok::<f64, ()>(g(beta) / (1.0 + eps * beta.cos()).powi(3)),
                    a,
                    b,
                    quadrature::Tolerance {
                        relative: 1e-10,
                        absolute: 1e-12,
                        max_bisections: 2000,
                        initial_panels: 8,
                    },
                    &crate::numerics::driver::Budget::unlimited(),
                )
                .unwrap()
                .value;
                assert!(
                    (got[k] - want).abs() < 1e-7 * want.abs().max(1.0),
                    "{eps} {k}"
                );
            }
        }
    }

    #[test]
    fn the_steady_half_films_are_ocvirks_bearing_and_the_full_film_stands_at_90_degrees() {
        // Ocvirk: radial ε²/(1−ε²)², tangential πε/(4(1−ε²)^1.5) (spec B.1.2, ξ = 0, at rest).
        for eps in [0.1, 0.5, 0.8, 0.99] {
            let q: f64 = 1.0 - eps * eps;
            for arc in [ShortArc::PiFilm, ShortArc::FixedArc] {
                // Journal displaced downward (φ = −90°): a = −y, b = +x.
                let f = steady(arc, eps, -0.5 * PI);
                let radial = -f[1]; // along a = (0, −1)
                let tangential = f[0];
                assert!(
                    (-radial / (eps * eps / (q * q)) - 1.0).abs() < 1e-12,
                    "{arc:?}"
                );
                assert!((tangential / (PI * eps / (4.0 * q.powf(1.5))) - 1.0).abs() < 1e-12);
            }
            let f = steady(ShortArc::Full, eps, 0.3);
            let along = f[0] * 0.3f64.cos() + f[1] * 0.3f64.sin();
            assert!(
                along.abs() < 1e-10 * f[0].hypot(f[1]),
                "full film: no radial force"
            );
            // The tangential force doubles the half film's.
            let across = -f[0] * 0.3f64.sin() + f[1] * 0.3f64.cos();
            assert!((across / (PI * eps / (2.0 * q.powf(1.5))) - 1.0).abs() < 1e-12);
        }
    }

    #[test]
    fn a_pure_squeeze_resists_the_motion_and_the_pi_film_turns_with_it() {
        // Journal at the centre moving at v̄ along any direction, no rotation: the π-film force
        // is −(π/2) v̄ (∫ cos² over a half circle), opposite the motion whatever its direction.
        let f = ShortFilm {
            arc: ShortArc::PiFilm,
            speed_sum: 0.0,
        };
        for angle in [0.0f64, 1.0, 2.5, -2.0] {
            let v = [angle.cos(), angle.sin()];
            let got = f.force([0.0, 0.0], v).unwrap();
            assert!(
                (got[0] + 0.5 * PI * v[0]).abs() < 1e-12
                    && (got[1] + 0.5 * PI * v[1]).abs() < 1e-12
            );
        }
        // Off-centre, the force is degree-1 homogeneous in w̄ and continuous across directions.
        let r = [0.4, -0.3];
        let a = f.force(r, [0.2, 0.1]).unwrap();
        let b = f.force(r, [0.6, 0.3]).unwrap();
        assert!((b[0] - 3.0 * a[0]).abs() < 1e-12 && (b[1] - 3.0 * a[1]).abs() < 1e-12);
        let near = f.force(r, [0.2, 0.1 + 1e-9]).unwrap();
        assert!((near[0] - a[0]).abs() < 1e-7 && (near[1] - a[1]).abs() < 1e-7);
    }

    #[test]
    fn the_mobility_squeeze_carries_the_load_for_every_film() {
        // F̄_film(r̄, w̄) = −F̄ at the w̄ found, over positions and load directions.
        for arc in [ShortArc::PiFilm, ShortArc::FixedArc, ShortArc::Full] {
            for (r, load) in [
                ([0.0, 0.0], [0.0, -3.0]),
                ([0.3, -0.5], [1.0, -7.0]),
                ([-0.9, 0.2], [4.0, 0.5]),
                ([0.1, 0.97], [-2.0, -20.0]),
            ] {
                let w = film(arc).squeeze_for(r, load).unwrap();
                let f = film(arc).force(r, w).unwrap();
                let scale = load[0].hypot(load[1]);
                assert!(
                    (f[0] + load[0]).abs() < 1e-9 * scale && (f[1] + load[1]).abs() < 1e-9 * scale,
                    "{arc:?} {r:?}: {f:?}"
                );
            }
        }
    }

    #[test]
    fn the_peak_pressure_is_the_short_bearings_and_contact_has_no_force() {
        // Steady short bearing: p̄_max = 1.5·max(½ε sin β/(1+ε cos β)³) over the arc.
        let eps: f64 = 0.8;
        let r = [0.0, -eps];
        let w = squeeze_vector(r, [0.0, 0.0], 1.0);
        let got = film(ShortArc::PiFilm).peak_pressure(r, w);
        let want = (0..200_000)
            .map(|i| {
                let b = PI * f64::from(i) / 200_000.0;
                0.75 * eps * b.sin() / (1.0 + eps * b.cos()).powi(3)
            })
            .fold(0.0, f64::max);
        assert!((got / want - 1.0).abs() < 1e-6, "{got} {want}");
        assert_eq!(film(ShortArc::PiFilm).force([0.0, -1.0], w), None);
        assert_eq!(film(ShortArc::Full).force([f64::NAN, 0.0], w), None);
    }
}
