//! The film force on a moving journal of finite length: the journal room's finite-volume
//! Reynolds film ([`super::film`]) with cavitation, driven by Booker's squeeze vector, for
//! orbits (Hamrock, Harnoy & Stachowiak, spec PART B.1.5, force model 3: an impedance table
//! from the full Reynolds solution; Childs, Moes & van Leeuwen's impedance method).
//!
//! Frame, signs and units as [`super::moving_film`]: bearing-fixed, x horizontal, y up, the
//! journal turning counter-clockwise; r̄ = r/C, w̄ = w/(C ω_j), F̄ = F C²/(μ R ω_j L³), p̄ =
//! p/(μ ω_j (L/C)²). In the frame turning at the mean surface speed the film is a pure squeeze
//! film driven by w = v − ½(ω_j + ω_b) k × r: the Reynolds equation
//!
//! ```text
//! ∂θ(h̄³ ∂θ P̄) + (1/(4λ²)) ∂ȳ(h̄³ ∂ȳ P̄) = 12 (w̄_a cos θ + w̄_b sin θ),   P̄ ≥ 0
//! ```
//!
//! with θ from the maximum film in the direction of rotation, h̄ = 1 + ε cos θ, (w̄_a, w̄_b) the
//! squeeze vector along the line of centres a = r̂ (towards the minimum film) and b = k × a,
//! P̄ = p (C/R)²/(μ ω_j), λ = L/D, P̄ = 0 at both ends and the Reynolds (Swift–Stieber)
//! condition where the film opens (Khonsari & Booser Eq. 8.36 with the wedge replaced by its
//! squeeze equivalent: at w̄ = −½ k × r̄ the source is 12π ∂θh̄ in rev/s units, the steady
//! bearing exactly). The film has no feed line: it is cut where the film opens fastest (θ = α,
//! the direction of w̄ from a), where the pressure is zero up to L/D ≈ 2 (checked in the
//! tests); in longer bearings near the centre the film may carry pressure round the whole
//! circle and the cut then holds it at zero: every solve reports the pressure next to the cut. The force on the journal is F̄ = (R/L)² ∫∫ P̄ (cos θ, sin θ) dθ dȳ in (a, b).
//!
//! The equation is linear in w̄ and its cavitated region does not change when w̄ is scaled, so
//! F̄(r̄, w̄) = |w̄| G(ε, α), with G the force of a unit squeeze at angle α from the line of
//! centres. [`ImpedanceTable`] holds G (and the peak pressure, homogeneous the same way) on a
//! grid in (s, α), ε = tanh s, from film solves on the request's mesh, and interpolates it by
//! bicubic Catmull–Rom (C¹): the orbit's integrator then sees a smooth force at the cost of a
//! table look-up, where a film solve per stage would cost milliseconds and follow the active
//! set's kinks. The values are stored times (1 − ε²)² (times (1 − ε²)³ for the pressure),
//! which takes out most of their growth towards contact.

use std::f64::consts::PI;

use super::film::{self, Film, FilmModel, Mesh};
use super::moving_film::{line_of_centres, mobility_squeeze};
use crate::calc::{Budget, CalcError};
use crate::fidelity::Level;
use crate::numerics::reynolds::Stopping;

/// A film solve's stopping (the cavitated film is solved directly by its active set; the
/// sweep tolerance is not used).
const FILM_STOP: Stopping = Stopping {
    tolerance: 1e-11,
    max_sweeps: 200_000,
};

/// The finite pure squeeze film of one bearing on one mesh.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FiniteSqueezeFilm {
    pub l_over_d: f64,
    pub mesh: Mesh,
}

/// The film's response to a unit squeeze: G = F̄/|w̄| in (a, b) and p̄_max/|w̄|, and the
/// mid-plane pressure at the nodes next to the cut over the peak (0 when the cut lies in the
/// cavitated film, as it should).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct UnitResponse {
    pub force: [f64; 2],
    pub peak_pressure: f64,
    pub cut_pressure: f64,
}

impl FiniteSqueezeFilm {
    /// The journal room's film at ε, squeezed at unit rate along α, cut at θ = α.
    fn squeezed(&self, eccentricity_ratio: f64, alpha: f64) -> Film {
        let (sin, cos) = alpha.sin_cos();
        Film {
            cos_rate: cos,
            sin_rate: sin,
            rotating: false,
            physics: FilmModel::REYNOLDS,
            span: Some((alpha, alpha + 2.0 * PI)),
            ..Film::steady(eccentricity_ratio, self.l_over_d)
        }
    }

    /// The film at ε squeezed at unit rate along α (from the line of centres, positive with
    /// rotation), solved on the mesh: one film solve (and its half mesh's, to start from).
    pub fn unit_response(
        &self,
        eccentricity_ratio: f64,
        alpha: f64,
        budget: &Budget,
    ) -> Result<UnitResponse, CalcError> {
        // From rest the solve starts from its half mesh's field (a start from the neighbouring
        // ε's field was tried: it took more active-set steps, not fewer).
        let squeezed = self.squeezed(eccentricity_ratio, alpha);
        let (solution, _) = film::solve(squeezed, self.mesh, FILM_STOP, None, budget)?;
        // (R/L)² = 1/(4λ²); the load is along −a (towards h_max) and +b.
        let scale = 1.0 / (4.0 * self.l_over_d * self.l_over_d);
        let mid = &solution.midplane;
        let at_cut = mid[1].1.max(mid[mid.len() - 2].1);
        Ok(UnitResponse {
            force: [
                -scale * solution.load_radial,
                scale * solution.load_tangential,
            ],
            peak_pressure: scale * solution.max_pressure_nd,
            cut_pressure: at_cut / solution.max_pressure_nd.max(f64::MIN_POSITIVE),
        })
    }
}

/// How densely the impedance table samples (s, α), and how far towards contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TableDensity {
    /// Spacing in s = atanh ε.
    pub step: f64,
    /// Columns round the circle in α (even: α + π is a column).
    pub columns: usize,
    /// The largest ε the table answers for; beyond it the film model refuses the state.
    pub top: f64,
}

/// The largest ε the rooms' tables reach (h_min = 0.005 C).
pub const TOP: f64 = 0.995;

impl TableDensity {
    /// The table's density at a fidelity level, up to [`TOP`] (see the `/dynamic` room's
    /// `dynamic.md`: the interpolation error measured against direct film solves stays below the
    /// grid's discretisation error).
    pub fn at(level: Level) -> TableDensity {
        let (step, columns) = match level {
            Level::Fast => (0.12, 36),
            // A denser table on the finest grid would take longer than the deadline allows.
            Level::High => (0.1, 40),
            _ => (0.08, 48),
        };
        TableDensity {
            step,
            columns,
            top: TOP,
        }
    }
}

impl TableDensity {
    /// The film solves a table of this density takes ([`ImpedanceTable::build`]): the centred
    /// journal once, then half the columns and one on each row up to the top.
    pub fn solves(&self) -> usize {
        let rows = (self.top.atanh() / self.step).ceil() as usize + 2;
        1 + (rows - 1) * (self.columns / 2 + 1)
    }
}

/// G(ε, α) and the peak pressure on a grid in (s = atanh ε, α), interpolated bicubically (see
/// the module doc). Rows i = 0, 1, …, n + 1 at s = i·step (row n + 1 only feeds the last
/// cell's stencil); columns j at α = 2πj/M, the lower half mirrored from the upper
/// (G(ε, −α) = (G_a, −G_b)(ε, α): the film mirrored about the line of centres). Below s = 0
/// the row is G(−ε, α) = −G(ε, α + π) (the same position seen from the opposite side).
#[derive(Debug, Clone, PartialEq)]
pub struct ImpedanceTable {
    film: FiniteSqueezeFilm,
    density: TableDensity,
    /// Rows stored (n + 2).
    rows: usize,
    /// [(1 − ε²)² G_a, (1 − ε²)² G_b, (1 − ε²)³ p̄_max] per node, row-major.
    values: Vec<[f64; 3]>,
    /// Film solves the table took.
    pub solves: u32,
    /// The largest [`UnitResponse::cut_pressure`] over the table's solves: above zero the cut
    /// held pressure the film would have had (long bearings, L/D ≳ 3, near the centre).
    pub cut_pressure: f64,
}

/// Catmull–Rom weights of the samples at −1, 0, 1, 2 for a point at t ∈ [0, 1] between 0 and 1.
fn catmull_rom(t: f64) -> [f64; 4] {
    let (t2, t3) = (t * t, t * t * t);
    [
        0.5 * (-t3 + 2.0 * t2 - t),
        0.5 * (3.0 * t3 - 5.0 * t2 + 2.0),
        0.5 * (-3.0 * t3 + 4.0 * t2 + t),
        0.5 * (t3 - t2),
    ]
}

impl ImpedanceTable {
    /// The table of `film` at `density`: (n + 1)·(M/2 + 1) film solves (row 0, the centred
    /// journal, is one solve turned round the circle), under `budget`.
    pub fn build(
        film: FiniteSqueezeFilm,
        density: TableDensity,
        budget: &Budget,
    ) -> Result<ImpedanceTable, CalcError> {
        let m = density.columns;
        let n = (density.top.atanh() / density.step).ceil() as usize;
        let rows = n + 2;
        let mut values = vec![[0.0; 3]; rows * m];
        let mut solves = 0;
        let mut cut_pressure = 0.0f64;
        let centred = film.unit_response(0.0, 0.0, budget)?;
        solves += 1;
        for (j, value) in values.iter_mut().take(m).enumerate() {
            let (sin, cos) = (2.0 * PI * j as f64 / m as f64).sin_cos();
            let [ga, gb] = centred.force;
            *value = [
                cos * ga - sin * gb,
                sin * ga + cos * gb,
                centred.peak_pressure,
            ];
        }
        for i in 1..rows {
            let eps = (i as f64 * density.step).tanh();
            let q = 1.0 - eps * eps;
            for j in 0..=m / 2 {
                let alpha = 2.0 * PI * j as f64 / m as f64;
                let unit = film.unit_response(eps, alpha, budget)?;
                solves += 1;
                cut_pressure = cut_pressure.max(unit.cut_pressure);
                let v = [
                    q * q * unit.force[0],
                    q * q * unit.force[1],
                    q * q * q * unit.peak_pressure,
                ];
                values[i * m + j] = v;
                values[i * m + (m - j) % m] = [v[0], -v[1], v[2]];
            }
        }
        Ok(ImpedanceTable {
            film,
            density,
            rows,
            values,
            solves,
            cut_pressure,
        })
    }

    /// The film this table samples.
    pub fn film(&self) -> FiniteSqueezeFilm {
        self.film
    }

    /// The largest ε the table answers for.
    pub fn top(&self) -> f64 {
        self.density.top
    }

    /// The stored node (i, j), i ≥ −1 (row −1 by the opposite-side symmetry), j any integer.
    fn node(&self, i: isize, j: isize) -> [f64; 3] {
        let m = self.density.columns as isize;
        if i < 0 {
            let [a, b, p] = self.node(-i, j + m / 2);
            return [-a, -b, p];
        }
        self.values[i as usize * self.density.columns + j.rem_euclid(m) as usize]
    }

    /// (G_a, G_b, p̄_max) for a unit squeeze at α from the line of centres at ε; None beyond the
    /// table's top (or for a non-finite state).
    pub fn unit(&self, eccentricity_ratio: f64, alpha: f64) -> Option<[f64; 3]> {
        if !(eccentricity_ratio.is_finite() && alpha.is_finite())
            || eccentricity_ratio > self.density.top
        {
            return None;
        }
        let u = eccentricity_ratio.atanh() / self.density.step;
        let i = (u.floor() as isize).min(self.rows as isize - 3);
        let wu = catmull_rom(u - i as f64);
        let v = alpha.rem_euclid(2.0 * PI) / (2.0 * PI) * self.density.columns as f64;
        let j = v.floor() as isize;
        let wv = catmull_rom(v - j as f64);
        let mut out = [0.0; 3];
        for (di, a) in wu.iter().enumerate() {
            for (dj, b) in wv.iter().enumerate() {
                let node = self.node(i - 1 + di as isize, j - 1 + dj as isize);
                for k in 0..3 {
                    out[k] += a * b * node[k];
                }
            }
        }
        let q = 1.0 - eccentricity_ratio * eccentricity_ratio;
        Some([
            out[0] / (q * q),
            out[1] / (q * q),
            (out[2] / (q * q * q)).max(0.0),
        ])
    }

    /// F̄ on the journal at r̄ with squeeze vector w̄; None beyond the table.
    #[must_use]
    pub fn force(&self, position: [f64; 2], squeeze: [f64; 2]) -> Option<[f64; 2]> {
        let (eps, size, c, s, alpha) = Self::frame(position, squeeze)?;
        let [ga, gb, _] = self.unit(eps, alpha)?;
        let (fa, fb) = (size * ga, size * gb);
        let force = [fa * c - fb * s, fa * s + fb * c];
        force.iter().all(|f| f.is_finite()).then_some(force)
    }

    /// Booker's mobility on the table: the squeeze that carries `load` (F̄_film = −F̄_load).
    #[must_use]
    pub fn squeeze_for(&self, position: [f64; 2], load: [f64; 2]) -> Option<[f64; 2]> {
        if load[0] == 0.0 && load[1] == 0.0 {
            return self.force(position, [0.0, 0.0]).map(|_| [0.0, 0.0]);
        }
        let response = |psi: f64| {
            let f = self.force(position, [psi.cos(), psi.sin()])?;
            Some([-f[0], -f[1]])
        };
        mobility_squeeze(response, load)
    }

    /// The peak film pressure p̄ at r̄ with squeeze vector w̄ (∞ beyond the table).
    #[must_use]
    pub fn peak_pressure(&self, position: [f64; 2], squeeze: [f64; 2]) -> f64 {
        Self::frame(position, squeeze)
            .and_then(|(eps, size, _, _, alpha)| Some(size * self.unit(eps, alpha)?[2]))
            .unwrap_or(f64::INFINITY)
    }

    /// ε, |w̄|, cos φ and sin φ of the line of centres, and α (w̄'s angle from it).
    fn frame(position: [f64; 2], squeeze: [f64; 2]) -> Option<(f64, f64, f64, f64, f64)> {
        let eps = position[0].hypot(position[1]);
        let (c, s, [wa, wb]) = line_of_centres(position, squeeze);
        let size = wa.hypot(wb);
        (eps.is_finite() && size.is_finite()).then(|| (eps, size, c, s, wb.atan2(wa)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::calc::journal::moving_film::{squeeze_vector, ShortArc, ShortFilm};

    fn film(l_over_d: f64, cells: usize, axial: usize) -> FiniteSqueezeFilm {
        FiniteSqueezeFilm {
            l_over_d,
            mesh: Mesh {
                circumferential: cells,
                axial_half: axial,
            },
        }
    }

    fn unit(f: FiniteSqueezeFilm, eps: f64, alpha: f64) -> UnitResponse {
        f.unit_response(eps, alpha, &Budget::unlimited()).unwrap()
    }

    #[test]
    fn the_finite_film_tends_to_the_short_pi_film_as_the_bearing_shortens() {
        // Issue 15's check: as L/D → 0 the finite film's axial flow dominates and its force
        // tends to the short bearing's (Ocvirk; spec B.1.1–B.1.2), here the dynamic π-film with
        // the journal along +x, so that (a, b) = (x, y). The gap shrinks with L/D (like (L/D)²
        // at first): within 4 % at L/D = 0.1, 1.5 % at 0.05.
        let short = ShortFilm {
            arc: ShortArc::PiFilm,
            speed_sum: 0.0,
        };
        for eps in [0.3, 0.8] {
            for alpha in [0.0f64, 1.0, 2.0, 3.0] {
                let want = short.force([eps, 0.0], [alpha.cos(), alpha.sin()]).unwrap();
                let gap = |l_over_d: f64| {
                    let got = unit(film(l_over_d, 96, 12), eps, alpha).force;
                    (got[0] - want[0]).hypot(got[1] - want[1]) / want[0].hypot(want[1])
                };
                let (g2, g1, g05) = (gap(0.2), gap(0.1), gap(0.05));
                assert!(g05 < g1 && g1 < g2, "{eps} {alpha}: {g2} {g1} {g05}");
                assert!(g1 < 0.04 && g05 < 0.015, "{eps} {alpha}: {g1} {g05}");
            }
        }
    }

    #[test]
    fn the_squeeze_at_the_turning_journals_vector_is_the_journal_rooms_steady_film() {
        // At rest and turning, w̄ = −½ k × r̄: the squeeze film must carry what the journal room's
        // steady film (Khonsari & Booser Eq. 8.36, fed at h_max) carries, on the same mesh —
        // the wedge's exact cell integral and the source's midpoint rule differ by the
        // discretisation error only. Steady P̄_s is in rev/s: P̄ = P̄_s/(2π).
        for (l_over_d, eps) in [(0.5, 0.6), (1.0, 0.9), (0.25, 0.3)] {
            let f = film(l_over_d, 96, 12);
            let r = [eps, 0.0];
            let w = squeeze_vector(r, [0.0, 0.0], 1.0);
            let alpha = w[1].atan2(w[0]);
            let g = unit(f, eps, alpha).force;
            let size = w[0].hypot(w[1]);
            let (steady, _) = film::solve(
                Film::steady(eps, l_over_d),
                f.mesh,
                FILM_STOP,
                None,
                &Budget::unlimited(),
            )
            .unwrap();
            let scale = 1.0 / (4.0 * l_over_d * l_over_d * 2.0 * PI);
            let want = [-scale * steady.load_radial, scale * steady.load_tangential];
            let gap = (size * g[0] - want[0]).hypot(size * g[1] - want[1]) / want[0].hypot(want[1]);
            // 0.55 % at L/D = 1, ε = 0.9 on 96 × 12.
            assert!(gap < 1e-2, "L/D {l_over_d} ε {eps}: {gap}");
        }
    }

    #[test]
    fn the_cut_lies_where_the_film_has_cavitated_up_to_twice_the_diameter() {
        // The film is cut where it opens fastest (θ = α); the cut is harmless only if the
        // pressure there is zero anyway: the nodes next to it carry none (below 10⁻⁵ of the
        // peak) for bearings up to L/D = 2, near and far from the wall, whatever the squeeze's
        // direction. A long bearing near the centre (L/D = 5, ε = 0.3) carries pressure round
        // the circle, and the report says so (a few per cent of the peak).
        let cut = |l_over_d: f64, eps: f64| {
            let f = film(l_over_d, 48, 6);
            (0..8)
                .map(|k| unit(f, eps, f64::from(k) * PI / 4.0).cut_pressure)
                .fold(0.0, f64::max)
        };
        for (l_over_d, eps) in [(0.1, 0.5), (1.0, 0.9), (2.0, 0.98), (2.0, 0.3)] {
            let worst = cut(l_over_d, eps);
            assert!(worst < 1e-5, "L/D {l_over_d} ε {eps}: {worst}");
        }
        assert!(cut(5.0, 0.3) > 1e-3);
    }

    #[test]
    fn the_table_reproduces_the_film_between_its_nodes_and_keeps_its_symmetries() {
        // Off-node points against direct solves on the same (fast) mesh: within 1 % in force
        // and 2 % in peak pressure (below the 48 × 6 mesh's own error, about 1 % near ε = 0.99
        // against 384 × 48).
        let f = film(0.5, 48, 6);
        let density = TableDensity {
            step: 0.12,
            columns: 36,
            top: 0.995,
        };
        let table = ImpedanceTable::build(f, density, &Budget::unlimited()).unwrap();
        assert_eq!(table.solves, 1 + 26 * 19);
        for k in 0..30 {
            let eps = 0.995 * ((f64::from(k) * 0.618_034) % 1.0).sqrt();
            let alpha = f64::from(k) * 2.399_96;
            let want = unit(f, eps, alpha);
            let got = table.unit(eps, alpha).unwrap();
            let size = want.force[0].hypot(want.force[1]);
            let gap = (got[0] - want.force[0]).hypot(got[1] - want.force[1]) / size;
            assert!(gap < 0.01, "ε {eps} α {alpha}: {gap}");
            assert!(
                (got[2] / want.peak_pressure - 1.0).abs() < 0.02,
                "ε {eps} α {alpha}: {} {}",
                got[2],
                want.peak_pressure
            );
        }
        // Homogeneous of degree 1 in w̄, turning with the journal, refusing beyond its top.
        let (r, w) = ([0.3, -0.5], [0.2, 0.7]);
        let f1 = table.force(r, w).unwrap();
        let f3 = table.force(r, [3.0 * w[0], 3.0 * w[1]]).unwrap();
        assert!((f3[0] - 3.0 * f1[0]).abs() < 1e-12 && (f3[1] - 3.0 * f1[1]).abs() < 1e-12);
        let turn = |v: [f64; 2]| [-v[1], v[0]];
        let ft = table.force(turn(r), turn(w)).unwrap();
        assert!((ft[0] - turn(f1)[0]).abs() < 1e-9 && (ft[1] - turn(f1)[1]).abs() < 1e-9);
        assert_eq!(table.force([0.996, 0.0], w), None);
        assert_eq!(table.force([0.0, 0.0], [0.0, 0.0]), Some([0.0, 0.0]));
        // The mobility's squeeze carries the load.
        let load = [1.0, -7.0];
        let ws = table.squeeze_for(r, load).unwrap();
        let carried = table.force(r, ws).unwrap();
        assert!((carried[0] + load[0]).abs() < 1e-9 && (carried[1] + load[1]).abs() < 1e-9);
    }
}
