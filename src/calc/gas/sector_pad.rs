//! A crowned sector pad of a tilting-pad gas thrust bearing (Khonsari & Booser §11.4 after
//! Shapiro & Colsher 1968): its film at a tilt, and the load, moments and friction of a solved
//! field. [`super::pivoted_pad`] balances it on its pivot.
//!
//! **Frame.** Polar coordinates on the runner, scaled by the outer radius: R = r/r_o from
//! R_i = r_i/r_o to 1, θ from the pad's leading edge (0) to its trailing edge θ_p, the runner
//! turning toward +θ. The pivot is at (R_p, θ_v), θ_v = γ. P = p/p_a (absolute), H = h/C.
//!
//! **Film.** C is Shapiro & Colsher's clearance: the film at the crown's peak before the pad
//! tilts. The crown is cylindrical, its axis the pad's radial centre line θ_c = θ_p/2, so it
//! grows with the square of the distance from that line, R sin(θ − θ_c); δ is its height at
//! the leading and trailing edges on the mean radius R_m (as the texts size a sector by its
//! mean-radius rectangle). The pad tilts about the pivot, where
//! the film does not move: pitch a = α r_o/C about the pivot's radial line (positive closing
//! the trailing part), roll b = β r_o/C about the line across it (positive closing the outer
//! part):
//!
//! ```text
//! H = 1 + κ [R sin(θ − θ_c) / (R_m sin(θ_p/2))]² + a R sin(θ_v − θ) + b (R_p − R cos(θ − θ_v))
//! ```
//!
//! with κ = δ/C. Every term is a polynomial of degree ≤ 2 in the pad's Cartesian coordinates:
//! H is a convex quadratic over the pad.
//!
//! **Film equation.** The isothermal compressible Reynolds equation in polar coordinates
//! ([`Metric::Polar`]), ∂θ(k/R ∂θP) + ∂R(R k ∂R P) = Λ R ∂θ(P H), k = H³P (+ slip), with
//! Shapiro & Colsher's bearing number Λ = 6μω r_o²/(p_a C²) (derived from the mass balance of
//! a ring element: the flow along θ carries ρ ω r h/2), P = 1 on all four edges.
//!
//! **Results.** Load C_L = W/(p_a r_o²) = ∫∫(P − 1) R dR dθ; moments over p_a r_o³ about the
//! pivot's radial line, ∫∫(P − 1) R sin(θ − θ_v) R dR dθ, and across it,
//! ∫∫(P − 1)(R cos(θ − θ_v) − R_p) R dR dθ; friction moment on the runner about the axis,
//! F = M_f/(p_a r_o² C) = (Λ/6)∫∫R³/H dR dθ + ½∫∫R H ∂θP dR dθ, the second term taken by parts
//! (P = 1 at both θ edges) as −½∫∫R ∂θH (P − 1) dR dθ, exact row by row (+ on the pad).

use super::method::Mesh;
use super::slider_film::coarsen;
use crate::numerics::optimise::brent_minimise;
use crate::numerics::quadrature::gauss_legendre;
use crate::numerics::reynolds_gas::{graded, graded_both_ends, GasGrid};
use crate::numerics::roots::MAX_DOUBLINGS;

/// The pad's shape and pivot, dimensionless.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sector {
    /// R_i = r_i/r_o.
    pub inner_radius: f64,
    /// θ_p, rad.
    pub angle: f64,
    /// R_p = r_pv/r_o.
    pub pivot_radius: f64,
    /// θ_v = γ, rad from the leading edge.
    pub pivot_angle: f64,
}

impl Sector {
    /// R_m.
    pub fn mean_radius(&self) -> f64 {
        0.5 * (1.0 + self.inner_radius)
    }
}

/// The pad's tilt: pitch a = α r_o/C and roll b = β r_o/C.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Tilt {
    pub pitch: f64,
    pub roll: f64,
}

/// The film and its physics, dimensionless.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PadFilm {
    pub sector: Sector,
    /// Λ = 6μω r_o²/(p_a C²).
    pub bearing_number: f64,
    /// κ = δ/C.
    pub crown: f64,
    /// Kn = λ_a/C of the slip factor (0: continuum).
    pub knudsen_number: f64,
}

impl PadFilm {
    /// The crown's term's scale, (R_m sin(θ_p/2))².
    fn crown_scale(&self) -> f64 {
        (self.sector.mean_radius() * (0.5 * self.sector.angle).sin()).powi(2)
    }

    /// H(θ, R).
    pub fn height(&self, t: Tilt, theta: f64, r: f64) -> f64 {
        let s = &self.sector;
        let across = r * (theta - 0.5 * s.angle).sin();
        1.0 + self.crown * across * across / self.crown_scale()
            + t.pitch * r * (s.pivot_angle - theta).sin()
            + t.roll * (s.pivot_radius - r * (theta - s.pivot_angle).cos())
    }

    /// ∂H/∂θ.
    pub fn height_slope(&self, t: Tilt, theta: f64, r: f64) -> f64 {
        let s = &self.sector;
        let c = theta - 0.5 * s.angle;
        self.crown * r * r * (2.0 * c).sin() / self.crown_scale()
            - t.pitch * r * (s.pivot_angle - theta).cos()
            + t.roll * r * (theta - s.pivot_angle).sin()
    }

    /// The thinnest film and where: (H_min, θ, R). In Cartesian coordinates along the pad's
    /// centre line (ξ) and across it (η), H is quadratic in η (the crown) and linear in ξ, so
    /// its minimum over the pad lies on the pad's boundary: each of the four edges is searched
    /// from the best of 65 samples by Brent's method. NaN when H is not a number somewhere.
    pub fn thinnest(&self, t: Tilt) -> (f64, f64, f64) {
        let s = &self.sector;
        let (ri, tp) = (s.inner_radius, s.angle);
        let mut best = (f64::INFINITY, 0.0, 0.0);
        // A film that is not a number anywhere is no film: NaN, which no test of H > 0 passes.
        let mut consider = |h: f64, theta: f64, r: f64| {
            if h < best.0 || h.is_nan() && !best.0.is_nan() {
                best = (h, theta, r);
            }
        };
        // Edges as a parameter u ∈ [0, 1].
        let edges: [&dyn Fn(f64) -> (f64, f64); 4] = [
            &|u| (0.0, ri + u * (1.0 - ri)),
            &|u| (tp, ri + u * (1.0 - ri)),
            &|u| (u * tp, ri),
            &|u| (u * tp, 1.0),
        ];
        const SAMPLES: usize = 64;
        for edge in edges {
            let h_at = |u: f64| {
                let (theta, r) = edge(u);
                self.height(t, theta, r)
            };
            let k = (0..=SAMPLES)
                .min_by(|&a, &b| {
                    h_at(a as f64 / SAMPLES as f64).total_cmp(&h_at(b as f64 / SAMPLES as f64))
                })
                .unwrap_or(0);
            let (lo, hi) = (
                k.saturating_sub(1) as f64 / SAMPLES as f64,
                (k + 1).min(SAMPLES) as f64 / SAMPLES as f64,
            );
            let (u, h) = brent_minimise(h_at, lo, hi, 1e-12);
            let (theta, r) = edge(u);
            consider(h, theta, r);
            let (theta, r) = edge(k as f64 / SAMPLES as f64);
            consider(self.height(t, theta, r), theta, r);
        }
        best
    }

    /// The pitches (roll 0) at which the film's minimum falls to `floor` (below 1): (closing the
    /// leading part, closing the trailing part). Min H is concave in the pitch and 1 at 0, so
    /// each is a bisection on the sign of min H − floor, from a bracket found by doubling.
    pub fn pitches_to_film(&self, floor: f64) -> (f64, f64) {
        let above = |m: f64| {
            self.thinnest(Tilt {
                pitch: m,
                roll: 0.0,
            })
            .0 > floor
        };
        let reach = |dir: f64| {
            let (mut lo, mut hi) = (0.0, dir);
            for _ in 0..MAX_DOUBLINGS {
                if !above(hi) {
                    break;
                }
                lo = hi;
                hi *= 2.0;
            }
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if above(mid) {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            lo
        };
        (reach(-1.0), reach(1.0))
    }
}

/// The dimensionless performance of a solved pad.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PadPerformance {
    /// C_L = W/(p_a r_o²).
    pub load: f64,
    /// The pressure's moment about the pivot's radial line over p_a r_o³ (positive: the
    /// pressure's centre behind the pivot).
    pub pitch_moment: f64,
    /// Its moment about the line across the pivot over p_a r_o³ (positive: the centre outside
    /// the pivot's radius).
    pub roll_moment: f64,
    /// F = M_f/(p_a r_o² C) on the runner (the moving surface).
    pub friction_runner: f64,
    /// The same on the pad.
    pub friction_pad: f64,
    /// Peak P (absolute, over ambient).
    pub max_pressure: f64,
}

impl PadPerformance {
    /// The larger moment over the load: how far the pressure's centre is from the pivot, in
    /// units of r_o.
    pub fn imbalance(&self) -> f64 {
        self.pitch_moment.abs().max(self.roll_moment.abs()) / self.load.abs()
    }
}

/// (Λ/6)∫∫R³/H dR dθ, the Couette part of F: 16 × 8 panels of 8 × 8 Gauss–Legendre points.
fn couette_moment(film: &PadFilm, t: Tilt) -> f64 {
    const PANELS: (usize, usize) = (16, 8);
    let rule = gauss_legendre(8);
    let s = &film.sector;
    let (wt, wr) = (
        s.angle / PANELS.0 as f64,
        (1.0 - s.inner_radius) / PANELS.1 as f64,
    );
    let mut sum = 0.0;
    for pt in 0..PANELS.0 {
        for pr in 0..PANELS.1 {
            let (t0, r0) = (
                (pt as f64 + 0.5) * wt,
                s.inner_radius + (pr as f64 + 0.5) * wr,
            );
            for &(u, wu) in &rule {
                for &(v, wv) in &rule {
                    let (theta, r) = (t0 + 0.5 * wt * u, r0 + 0.5 * wr * v);
                    sum += 0.25 * wt * wr * wu * wv * r * r * r / film.height(t, theta, r);
                }
            }
        }
    }
    film.bearing_number / 6.0 * sum
}

/// Load, moments, friction and the peak of a field solved at tilt `t`.
pub fn performance(film: &PadFilm, t: Tilt, grid: &GasGrid, p: &[f64]) -> PadPerformance {
    let s = &film.sector;
    let (mut load, mut pitch, mut roll, mut shear) = (0.0, 0.0, 0.0, 0.0);
    let mut max_pressure = f64::MIN;
    for i in 0..=grid.nx() {
        let theta = grid.x[i];
        for j in 0..grid.y.len() {
            let r = grid.y[j];
            let w = grid.weight(i, j) * r;
            let gauge = p[grid.at(i, j)] - 1.0;
            load += w * gauge;
            pitch += w * gauge * r * (theta - s.pivot_angle).sin();
            roll += w * gauge * (r * (theta - s.pivot_angle).cos() - s.pivot_radius);
            shear += w * film.height_slope(t, theta, r) * gauge;
            max_pressure = max_pressure.max(p[grid.at(i, j)]);
        }
    }
    let couette = couette_moment(film, t);
    PadPerformance {
        load,
        pitch_moment: pitch,
        roll_moment: roll,
        friction_runner: couette - 0.5 * shear,
        friction_pad: couette + 0.5 * shear,
        max_pressure,
    }
}

/// The pad's grid: θ graded toward the trailing edge so that its last cell is about 1/(4Λ_B) of
/// the pad (the boundary layer where P falls to ambient is ~1/Λ_B thick, with Λ_B = Λ R_m² θ_p
/// the equivalent rectangle's bearing number), R graded toward both edges with the first cell
/// about a third of the side layer (~ R_m θ_p/√Λ_B); `mesh.across` cells on each half of the
/// radial width. With `half`, every other node of it (the Richardson pair's half mesh).
pub fn grid(film: &PadFilm, mesh: Mesh, half: bool) -> GasGrid {
    let s = &film.sector;
    let rm = s.mean_radius();
    let lambda = (film.bearing_number * rm * rm * s.angle).max(1.0);
    let x = graded(mesh.along, 0.25 / lambda, false)
        .into_iter()
        .map(|v| v * s.angle)
        .collect();
    let width = 1.0 - s.inner_radius;
    let finest = 0.33 * rm * s.angle / lambda.sqrt() / width;
    let y = graded_both_ends(mesh.across.max(2), finest)
        .into_iter()
        .map(|v| s.inner_radius + v * width)
        .collect();
    let fine = GasGrid {
        x,
        y,
        periodic: false,
    };
    if half {
        coarsen(&fine)
    } else {
        fine
    }
}
