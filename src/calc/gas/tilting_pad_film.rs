//! The three-pad tilting-pad gas journal bearing's films and equilibria, dimensionless, in the
//! plain gas journal's scaling (Khonsari & Booser §11.6, after Shapiro & Colsher 1970): θ and
//! ψ in radians, positive with rotation; y = z/R from a bearing end (ambient) to the mid-plane
//! (symmetry) at y = L/D; H = h/C with C the **machined** clearance; P = p/p_a absolute;
//! Λ = 6μΩ(R/C)²/p_a.
//!
//! **Geometry** (the frame of `calc::journal::dynamics`: the journal turns toward +θ, θ from the
//! load line). Each pad is an arc of radius R + C about its own centre; the pivot lies on the
//! pad's back at the **pivot clearance** C′ from the bearing centre's circle R, so the pad's
//! centre of curvature sits C − C′ from the bearing centre, away from the pivot (the preload
//! factor C′/C < 1). Pad i's pivot is at θ_pi; pad 3 takes the load (θ_p3 = 0, on the load
//! line), pads 1 and 2 sit at ±120°. The journal's centre is displaced e′ along the load line,
//! ε′ = e′/C′. A pad tilts about its pivot by a small rigid rotation δ. To first order in C/R
//! (the thin-film geometry of the plain journal's H = 1 + ε cos θ), with ψ = θ − θ_pi:
//!
//! ```text
//! h(ψ) = C − (C − C′) cos ψ − e′ cos(ψ + θ_pi) − R δ sin ψ
//! ```
//!
//! (the pad's offset centre, the journal's displacement, the tilt's radial motion of the pad
//! surface). The journal's term splits into cos ψ and sin ψ parts, and the sin ψ part is a tilt:
//! with the pivot film H_p = h(0)/C = (C′/C)(1 − ε′ cos θ_pi) and the pad's **free** tilt
//! τ = R δ/C − (C′/C) ε′ sin θ_pi,
//!
//! ```text
//! H(ψ) = 1 − (1 − H_p) cos ψ − τ sin ψ
//! ```
//!
//! so a pad in equilibrium depends on its pivot film alone (Shapiro & Colsher's Figs. 11.20–11.22
//! read the pad's minimum film, load and friction against H_p). The pivot film is geometry:
//! H_p3 = (C′/C)(1 − ε′), H_p1 = H_p2 = (C′/C)(1 + ε′/2).
//!
//! **Equilibrium.** A pivoted pad carries no moment about its pivot: the pressure, normal to the
//! surfaces (radial to first order), gives M̄ = ∫∫(P − 1) sin ψ dψ dy = 0 — a 1-D root in τ per
//! pad, found by a bracketed secant ([`crate::numerics::roots::secant_bracketed`]) after a walk
//! that brackets it between the tilts at which the leading or the trailing edge would touch.
//! Its resultant then passes through the pivot and the journal's centre: the pad pushes the
//! journal away from it along the pivot line with F̄ = F/(p_a R L) = (D/L)∫∫(P − 1) cos ψ dψ dy
//! (over the half length modelled). Pads 1 and 2 mirror each other about the load line (equal
//! pivot films, equal forces, the sideways parts cancel), so the load is
//! C_LT = W/(p_a R L) = F̄3 − 2 F̄1 cos 60° = F̄3 − F̄1 — one pad-1 and one pad-3 equilibrium per
//! ε′. The shear's O(C/R) share of the forces is neglected, as in the texts.
//!
//! **Friction** on the journal (moving surface) per pad, F_i = F_fi/(p_a C L) =
//! (D/L)[(Λ/6)∫∫dψ dy/H + ½∫∫H ∂ψP dψ dy] from τ = μU/h + (h/2)∂p/∂x, with
//! ∫H ∂ψP dψ = −∫(P − 1) H′ dψ (by parts, P = 1 at both pad edges); the pad's has the pressure
//! term's other sign.

use std::cell::RefCell;
use std::f64::consts::FRAC_PI_3;

use super::journal_film::{stretch, unstretch};
use super::method::{Mesh, Method};
use super::slider_film::coarsen;
use crate::calc::{Budget, CalcError};
use crate::fidelity::{Level, SolverReport};
use crate::numerics::driver::Stopped;
use crate::numerics::reynolds_gas::{self, graded, GasGrid, GasProblem, GasStopping};
use crate::numerics::richardson::{extrapolate, fine_error};
use crate::numerics::roots::{secant_bracketed, secant_fallible, RootError, Stopping};

/// The largest bearing eccentricity ratio ε′ = e′/C′ solved: pad 3's pivot film is
/// (C′/C)(1 − ε′), which a grid resolves down to about a twentieth of C′ (ε′ ≥ 1: contact).
pub const MAX_ECCENTRICITY: f64 = 0.95;

/// The pivot angles θ_pi from the load line, in the direction of rotation: pads 1, 2, 3.
pub const PIVOT_ANGLES: [f64; 3] = [2.0 * FRAC_PI_3, 4.0 * FRAC_PI_3, 0.0];

/// The smallest film a bracket's tilts leave, as a fraction of the pivot film: the tilt walk
/// stops short of a touching edge.
const EDGE_FLOOR: f64 = 0.02;

/// A pad's shape.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PadGeometry {
    /// α, the pad's arc, radians.
    pub arc: f64,
    /// The pivot's position from the leading edge, a fraction of the arc (0.5: central).
    pub pivot_offset: f64,
}

impl PadGeometry {
    /// ψ of the leading edge (negative: ahead of the pivot).
    pub fn leading(&self) -> f64 {
        -self.pivot_offset * self.arc
    }
    /// ψ of the trailing edge.
    pub fn trailing(&self) -> f64 {
        (1.0 - self.pivot_offset) * self.arc
    }
}

/// One pad's film, dimensionless.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PadFilm {
    pub geometry: PadGeometry,
    /// H_p = h_p/C at the pivot (> 0).
    pub pivot_film: f64,
    /// τ, the free tilt (R δ/C less the journal's sideways share, (C′/C) ε′ sin θ_p).
    pub tilt: f64,
    /// Λ = 6μΩ(R/C)²/p_a.
    pub bearing_number: f64,
    /// L/D; `None`: an infinitely long pad (no side leakage; loads per unit length).
    pub l_over_d: Option<f64>,
}

impl PadFilm {
    /// H(ψ) = 1 − (1 − H_p) cos ψ − τ sin ψ.
    pub fn film(&self, psi: f64) -> f64 {
        let (s, c) = psi.sin_cos();
        1.0 - (1.0 - self.pivot_film) * c - self.tilt * s
    }
    /// H′(ψ).
    pub fn film_slope(&self, psi: f64) -> f64 {
        let (s, c) = psi.sin_cos();
        (1.0 - self.pivot_film) * s - self.tilt * c
    }
    /// The pad's thinnest film H_M and where it is (ψ): H = 1 − A cos(ψ − φ) with
    /// A cos φ = 1 − H_p, A sin φ = τ, least at φ when the pad spans it, else at an edge.
    pub fn min_film(&self) -> (f64, f64) {
        let g = self.geometry;
        let phi = self.tilt.atan2(1.0 - self.pivot_film);
        let mut best = (self.film(g.leading()), g.leading());
        for psi in [g.trailing(), phi] {
            if (g.leading()..=g.trailing()).contains(&psi) && self.film(psi) < best.0 {
                best = (self.film(psi), psi);
            }
        }
        best
    }
}

/// The tilts (τ_lo, τ_hi) between which the pad's film stays above `floor` everywhere: H is
/// linear in τ at each ψ, so each sampled ψ bounds τ from one side.
pub fn tilt_limits(geometry: PadGeometry, pivot_film: f64, floor: f64) -> (f64, f64) {
    let a = 1.0 - pivot_film;
    let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
    let n = 400;
    for k in 0..=n {
        let psi = geometry.leading() + geometry.arc * k as f64 / n as f64;
        let (s, c) = psi.sin_cos();
        let room = 1.0 - a * c - floor;
        if s > 1e-12 {
            hi = hi.min(room / s);
        } else if s < -1e-12 {
            lo = lo.max(room / s);
        }
    }
    (lo, hi)
}

/// The dimensionless performance of one pad.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PadPerformance {
    /// F̄ = F/(p_a R L) along the pivot line, pushing the journal away from the pad (per unit
    /// length over p_a R for an infinitely long pad).
    pub load: f64,
    /// M̄ = (D/L)∫∫(P − 1) sin ψ: the moment about the pivot over p_a R² L (positive: the centre
    /// of pressure behind the pivot).
    pub moment: f64,
    /// F_f/(p_a C L) on the journal (the moving surface).
    pub friction_journal: f64,
    /// The same on the pad.
    pub friction_pad: f64,
    /// Peak P.
    pub max_pressure: f64,
}

/// The cells of a level: along the pad's arc, across the half length.
pub fn level_mesh(level: Level) -> Mesh {
    match level {
        Level::Fast => Mesh {
            along: 24,
            across: 6,
        },
        Level::ClosedForm | Level::Standard => Mesh {
            along: 48,
            across: 12,
        },
        Level::High => Mesh {
            along: 96,
            across: 24,
        },
    }
}

/// The grid: ψ over the pad, graded toward the trailing edge so that its last cell is about
/// half the edge layer (1/Λ_s of the arc, Λ_s = Λ α/H_p² the pad's slider bearing number, at
/// least a thousandth of the arc); y graded toward the bearing end, its first cell about
/// 1/(3√Λ) as the plain journal's.
pub fn grid(film: &PadFilm, mesh: Mesh) -> GasGrid {
    let g = film.geometry;
    let slider_number = film.bearing_number * g.arc / film.pivot_film.powi(2);
    let finest = (0.5 / slider_number.max(1.0)).max(1e-3);
    let x = graded(mesh.along, finest, false)
        .into_iter()
        .map(|s| g.leading() + g.arc * s)
        .collect();
    let y = match film.l_over_d {
        None => vec![0.0],
        Some(w) => {
            let finest = 0.33 / film.bearing_number.max(1.0).sqrt();
            graded(mesh.across.max(2), finest / w, true)
                .into_iter()
                .map(|v| v * w)
                .collect()
        }
    };
    GasGrid {
        x,
        y,
        periodic: false,
    }
}

/// The problem of `film` on `grid`.
pub fn problem(film: &PadFilm, grid: &GasGrid) -> GasProblem {
    GasProblem::new(grid, film.bearing_number, 0.0, |psi, _| film.film(psi))
}

/// A pad's film solved on one grid.
#[derive(Debug, Clone)]
pub struct PadSolve {
    pub grid: GasGrid,
    pub p: Vec<f64>,
    pub performance: PadPerformance,
    pub report: SolverReport,
}

/// Loads, moment, friction and the peak of a solved field (trapezoid weights of the grid).
pub fn performance(film: &PadFilm, grid: &GasGrid, p: &[f64]) -> PadPerformance {
    let (mut load, mut moment, mut couette, mut pressure) = (0.0, 0.0, 0.0, 0.0);
    let mut max_pressure = f64::MIN;
    for i in 0..=grid.nx() {
        let psi = grid.x[i];
        let (s, c) = psi.sin_cos();
        let (h, slope) = (film.film(psi), film.film_slope(psi));
        for j in 0..grid.y.len() {
            let w = grid.weight(i, j);
            let g = p[grid.at(i, j)] - 1.0;
            load += w * g * c;
            moment += w * g * s;
            couette += w / h;
            pressure -= w * g * slope;
            max_pressure = max_pressure.max(p[grid.at(i, j)]);
        }
    }
    let scale = 1.0 / film.l_over_d.unwrap_or(1.0);
    let couette = film.bearing_number / 6.0 * couette * scale;
    let pressure = 0.5 * pressure * scale;
    PadPerformance {
        load: load * scale,
        moment: moment * scale,
        friction_journal: couette + pressure,
        friction_pad: couette - pressure,
        max_pressure,
    }
}

/// Solve on `grid`, by Newton from `start` when given (a field on this grid).
pub fn solve_on(
    film: &PadFilm,
    grid: GasGrid,
    start: Option<&[f64]>,
    budget: &Budget,
) -> Result<PadSolve, Stopped> {
    let problem = problem(film, &grid);
    let solved = reynolds_gas::solve(&grid, &problem, start, GasStopping::default(), budget)?;
    let performance = performance(film, &grid, &solved.p);
    Ok(PadSolve {
        grid,
        p: solved.p,
        performance,
        report: solved.report,
    })
}

/// A pad's performance by a method: the mesh, and with Richardson its half mesh, extrapolated.
#[derive(Debug, Clone)]
pub struct PadEvaluated {
    pub film: PadFilm,
    pub performance: PadPerformance,
    /// Relative error estimate of F̄.
    pub error_estimate: Option<f64>,
    pub fine: PadSolve,
    pub coarse: Option<PadSolve>,
    /// Newton steps and line-search trials over both meshes.
    pub iterations: u32,
    pub evaluations: u32,
}

/// A warm field for `grid`: `from`'s, interpolated when its grid differs.
fn warm_field(from: &PadSolve, grid: &GasGrid) -> Vec<f64> {
    if from.grid == *grid {
        from.p.clone()
    } else {
        reynolds_gas::prolong(&from.grid, &from.p, grid)
    }
}

/// Solve `film` by `method`, Newton starting from `warm` (a nearby pad's solution) when given.
pub fn evaluate(
    film: &PadFilm,
    method: Method,
    warm: Option<&PadEvaluated>,
    budget: &Budget,
) -> Result<PadEvaluated, Stopped> {
    let fine_grid = grid(film, method.mesh);
    let mut iterations = 0;
    let mut evaluations = 0;
    let mut tally = |s: &PadSolve| {
        iterations += s.report.iterations;
        evaluations += s.report.evaluations.unwrap_or(0);
    };
    let coarse = match method.richardson.then(|| coarsen(&fine_grid)) {
        Some(coarse_grid) => {
            let start = warm
                .and_then(|w| w.coarse.as_ref())
                .map(|c| warm_field(c, &coarse_grid));
            let solved = solve_on(film, coarse_grid, start.as_deref(), budget)?;
            tally(&solved);
            Some(solved)
        }
        None => None,
    };
    let start = match (warm, &coarse) {
        (Some(w), _) => Some(warm_field(&w.fine, &fine_grid)),
        (None, Some(c)) => Some(reynolds_gas::prolong(&c.grid, &c.p, &fine_grid)),
        (None, None) => None,
    };
    let fine = solve_on(film, fine_grid, start.as_deref(), budget)?;
    tally(&fine);
    let f = fine.performance;
    let (performance, error_estimate) = match &coarse {
        Some(c) => {
            let c = c.performance;
            let load = extrapolate(c.load, f.load);
            let estimate = (fine_error(c.load, f.load) / load).abs();
            (
                PadPerformance {
                    load,
                    moment: extrapolate(c.moment, f.moment),
                    friction_journal: extrapolate(c.friction_journal, f.friction_journal),
                    friction_pad: extrapolate(c.friction_pad, f.friction_pad),
                    max_pressure: f.max_pressure,
                },
                Some(estimate).filter(|e| e.is_finite()),
            )
        }
        None => (f, None),
    };
    Ok(PadEvaluated {
        film: *film,
        performance,
        error_estimate,
        fine,
        coarse,
        iterations,
        evaluations,
    })
}

/// A pad at its moment-free tilt.
#[derive(Debug, Clone)]
pub struct PadEquilibrium {
    pub evaluated: PadEvaluated,
    /// Film evaluations of the tilt search (each the mesh and its half mesh).
    pub searches: u32,
    /// dM̄/dτ near the root (the search's last two tilts): a nearby pad's first step.
    pub moment_slope: f64,
}

/// Steps the walk may take toward a touching edge before the pad is declared without an
/// equilibrium.
const MAX_WALK: u32 = 40;

/// The pad with pivot film `pivot_film` at its moment-free tilt: M̄(τ) = 0 by a walk from the
/// warm tilt (or 0) until M̄ changes sign — downhill, since M̄ rises with τ (tilting the trailing
/// edge closed moves the pressure aft) — each step at most half the way to the tilt at which
/// an edge's film falls to [`EDGE_FLOOR`] H_p, then a bracketed secant. A warm pad's slope
/// dM̄/dτ makes the walk's first step a Newton step, a tenth longer, so that it brackets the root
/// at once. `pointer` names the field a missing equilibrium is blamed on.
#[allow(clippy::too_many_arguments)]
pub fn equilibrium(
    geometry: PadGeometry,
    pivot_film: f64,
    bearing_number: f64,
    l_over_d: Option<f64>,
    method: Method,
    warm: Option<&PadEquilibrium>,
    budget: &Budget,
    pointer: &str,
) -> Result<PadEquilibrium, CalcError> {
    let (lo, hi) = tilt_limits(geometry, pivot_film, EDGE_FLOOR * pivot_film);
    if !(lo.is_finite() && hi.is_finite() && lo < hi) {
        return Err(CalcError::impossible(
            pointer,
            format!("a pad of pivot film H_p = {pivot_film:.4} touches the journal at every tilt"),
        ));
    }
    let last: RefCell<Option<PadEvaluated>> = RefCell::new(warm.map(|w| w.evaluated.clone()));
    let failed: RefCell<Option<Stopped>> = RefCell::new(None);
    let searches = RefCell::new(0u32);
    let tried: RefCell<[(f64, f64); 2]> = RefCell::new([(f64::NAN, f64::NAN); 2]);
    let moment_at = |tilt: f64| -> f64 {
        let film = PadFilm {
            geometry,
            pivot_film,
            tilt,
            bearing_number,
            l_over_d,
        };
        let start = last.borrow().clone();
        *searches.borrow_mut() += 1;
        match evaluate(&film, method, start.as_ref(), budget) {
            Ok(done) => {
                let m = done.performance.moment;
                *last.borrow_mut() = Some(done);
                let mut t = tried.borrow_mut();
                *t = [t[1], (tilt, m)];
                m
            }
            Err(stop) => {
                *failed.borrow_mut() = Some(stop);
                f64::NAN
            }
        }
    };
    let slope = |tried: &RefCell<[(f64, f64); 2]>| {
        let [(ta, ma), (tb, mb)] = *tried.borrow();
        (mb - ma) / (tb - ta)
    };
    let stopped = |failed: &RefCell<Option<Stopped>>| failed.borrow_mut().take();
    let inside = |t: f64| t.clamp(lo + 1e-6 * (hi - lo), hi - 1e-6 * (hi - lo));
    let mut t0 = inside(warm.map_or(0.0, |w| w.evaluated.film.tilt));
    let mut m0 = moment_at(t0);
    if let Some(stop) = stopped(&failed) {
        return Err(stop.into());
    }
    if m0 == 0.0 {
        // Already moment-free (a uniform film).
        let evaluated = last.borrow_mut().take().expect("evaluated once");
        return Ok(PadEquilibrium {
            evaluated,
            searches: *searches.borrow(),
            moment_slope: f64::NAN,
        });
    }
    let no_equilibrium = || {
        CalcError::impossible(
            pointer,
            format!("a pad of pivot film H_p = {pivot_film:.4} has no moment-free tilt before an edge touches: move the pivot toward the pad's middle or trailing part"),
        )
    };
    // Downhill: M̄ > 0 lowers τ.
    let (dir, limit) = if m0 > 0.0 { (-1.0, lo) } else { (1.0, hi) };
    let mut step = match warm.map(|w| w.moment_slope) {
        Some(s) if s.is_finite() && s > 0.0 => 1.1 * (m0 / s).abs(),
        _ => 0.05 * (hi - lo),
    };
    let mut t1 = inside(t0 + dir * step.min(0.5 * (limit - t0).abs()));
    let mut m1 = moment_at(t1);
    let mut walked = 1;
    while m1.signum() == m0.signum() && m1 != 0.0 {
        if let Some(stop) = stopped(&failed) {
            return Err(stop.into());
        }
        if walked >= MAX_WALK || !m1.is_finite() {
            return Err(no_equilibrium());
        }
        // The secant's guess if it points on, at least twice the last step; never more than
        // half the way to the limit.
        let slope = (m1 - m0) / (t1 - t0);
        let guess = if slope * dir < 0.0 {
            -m1 / slope
        } else {
            f64::INFINITY
        };
        step = (1.5 * guess.abs())
            .max(2.0 * step)
            .min(0.5 * (limit - t1).abs());
        (t0, m0) = (t1, m1);
        t1 = inside(t1 + dir * step);
        m1 = moment_at(t1);
        walked += 1;
    }
    if let Some(stop) = stopped(&failed) {
        return Err(stop.into());
    }
    let root = secant_bracketed(
        moment_at,
        (t0, m0),
        (t1, m1),
        Stopping {
            x_tolerance: 1e-10,
            max_iterations: 60,
        },
    );
    if let Some(stop) = stopped(&failed) {
        return Err(stop.into());
    }
    let root = match root {
        Ok(r) => r,
        Err(RootError::NoSignChange { .. }) => return Err(no_equilibrium()),
        Err(e) => return Err(CalcError::from_root("tilting_pad_tilt", e)),
    };
    // The secant returns its last evaluated point, the film solved there, unless it stopped
    // at once on the bracket's other end: solve that one again.
    if last.borrow().as_ref().map(|l| l.film.tilt) != Some(root.x) {
        moment_at(root.x);
        if let Some(stop) = stopped(&failed) {
            return Err(stop.into());
        }
    }
    let evaluated = last
        .into_inner()
        .expect("the walk evaluated at least two tilts");
    let moment_slope = slope(&tried);
    Ok(PadEquilibrium {
        evaluated,
        searches: searches.into_inner(),
        moment_slope,
    })
}

/// The bearing, dimensionless.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BearingFilm {
    pub geometry: PadGeometry,
    /// C′/C, the preload factor, in (0, 1).
    pub preload_factor: f64,
    /// Λ = 6μΩ(R/C)²/p_a.
    pub bearing_number: f64,
    pub l_over_d: f64,
}

impl BearingFilm {
    /// H_pi = (C′/C)(1 − ε′ cos θ_pi) for pads 1, 2, 3.
    pub fn pivot_films(&self, eccentricity: f64) -> [f64; 3] {
        PIVOT_ANGLES.map(|t| self.preload_factor * (1.0 - eccentricity * t.cos()))
    }
}

/// The bearing at one ε′: pad 3 (loaded) and pad 1 (pad 2 its mirror image).
#[derive(Debug, Clone)]
pub struct BearingEquilibrium {
    pub eccentricity: f64,
    pub upper: PadEquilibrium,
    pub loaded: PadEquilibrium,
}

impl BearingEquilibrium {
    /// C_LT = W/(p_a R L) = F̄3 − F̄1 (pads 1 and 2 at ±120°, each pushing with the load by
    /// F̄1 cos 60°).
    pub fn load(&self) -> f64 {
        self.loaded.evaluated.performance.load - self.upper.evaluated.performance.load
    }
    /// Pads 1, 2, 3.
    pub fn pads(&self) -> [&PadEquilibrium; 3] {
        [&self.upper, &self.upper, &self.loaded]
    }
    /// Relative error estimate of C_LT: Richardson's on the difference F̄3 − F̄1 itself (the
    /// pads' errors are alike and largely cancel in it), from the two meshes at the found tilts.
    pub fn error_estimate(&self) -> Option<f64> {
        let (l, u) = (&self.loaded.evaluated, &self.upper.evaluated);
        let (lc, uc) = (l.coarse.as_ref()?, u.coarse.as_ref()?);
        let coarse = lc.performance.load - uc.performance.load;
        let fine = l.fine.performance.load - u.fine.performance.load;
        Some((fine_error(coarse, fine) / self.load()).abs()).filter(|e| e.is_finite())
    }
}

/// Both pads' equilibria at ε′, each tilt search started from `warm`'s when given.
pub fn at_eccentricity(
    bearing: &BearingFilm,
    eccentricity: f64,
    method: Method,
    warm: Option<&BearingEquilibrium>,
    budget: &Budget,
    pointer: &str,
) -> Result<BearingEquilibrium, CalcError> {
    let [upper, _, loaded] = bearing.pivot_films(eccentricity);
    let pad = |h: f64, warm: Option<&PadEquilibrium>| {
        equilibrium(
            bearing.geometry,
            h,
            bearing.bearing_number,
            Some(bearing.l_over_d),
            method,
            warm,
            budget,
            pointer,
        )
    };
    Ok(BearingEquilibrium {
        eccentricity,
        upper: pad(upper, warm.map(|w| &w.upper))?,
        loaded: pad(loaded, warm.map(|w| &w.loaded))?,
    })
}

/// The smallest ε′ the load search tries: the lower end of its bracket.
pub const MIN_ECCENTRICITY: f64 = 1e-4;

/// The bearing at the load C_LT = `target`: a bracketed secant on ln(C_LT/target) in the
/// stretched s = ln(ε′/(1 − ε′)) over ε′ in [[`MIN_ECCENTRICITY`], [`MAX_ECCENTRICITY`]] (as the
/// plain gas journal's load search: C_LT ∝ ε′ at small ε′, so the residual is nearly linear in
/// s); each equilibrium starts from the last one's tilts, slopes and fields.
pub fn at_load(
    bearing: &BearingFilm,
    target: f64,
    method: Method,
    budget: &Budget,
) -> Result<(BearingEquilibrium, SolverReport), CalcError> {
    let last: RefCell<Option<BearingEquilibrium>> = RefCell::new(None);
    let residual_at = |s: f64| -> Result<f64, CalcError> {
        let warm = last.borrow().clone();
        let done = at_eccentricity(
            bearing,
            unstretch(s),
            method,
            warm.as_ref(),
            budget,
            "/pads/pivot_offset",
        )?;
        let w = done.load();
        *last.borrow_mut() = Some(done);
        // Apart: a target near the smallest double overflows w/target.
        Ok(w.ln() - target.ln())
    };
    // The light end first: a load near it need not wait on the heavy end's thin pad-3 film.
    let s_lo = stretch(MIN_ECCENTRICITY);
    let lo = residual_at(s_lo)?;
    let below = || {
        CalcError::impossible(
            "/load_n",
            format!("the load C_LT = W/(p_a R L) = {target:.4e} is below what ε′ = {MIN_ECCENTRICITY} carries"),
        )
    };
    if lo.is_nan() || lo > 0.0 {
        return Err(below());
    }
    // The heavy end: ε′ = 0.95, or, where pad 3's film is too thin there for its film solve to
    // converge, the largest of 0.9 and 0.8 that solves.
    let mut upper = None;
    for e in [MAX_ECCENTRICITY, 0.9, 0.8] {
        match residual_at(stretch(e)) {
            Ok(hi) => {
                upper = Some((e, hi));
                break;
            }
            Err(CalcError::DeadlineExceeded) => return Err(CalcError::DeadlineExceeded),
            Err(err) if e == 0.8 => return Err(err),
            Err(_) => {}
        }
    }
    let (e_hi, hi) = upper.expect("the loop returns unless an end solved");
    let s_hi = stretch(e_hi);
    if hi < 0.0 {
        return Err(CalcError::impossible(
            "/load_n",
            format!(
                "the bearing carries at most C_LT = W/(p_a R L) = {:.4} at ε′ = {e_hi}; the load asks {target:.4}",
                (target.ln() + hi).exp()
            ),
        ));
    }
    let root = secant_fallible(
        residual_at,
        (s_lo, lo),
        (s_hi, hi),
        Stopping {
            // Δε′ = ε′(1 − ε′)Δs ≤ Δs/4.
            x_tolerance: 4e-9,
            max_iterations: 60,
        },
    )?;
    let root = match root {
        Ok(r) => r,
        Err(RootError::NoSignChange { .. }) => return Err(below()),
        Err(e) => return Err(CalcError::from_root("tilting_pad_load", e)),
    };
    // The secant's last evaluated point is the answer's film, unless it stopped at once on the
    // bracket's other end: solve that one again.
    if last.borrow().as_ref().map(|l| l.eccentricity) != Some(unstretch(root.x)) {
        residual_at(root.x)?;
    }
    let done = last
        .into_inner()
        .expect("the search evaluated at least the bracket's ends");
    Ok((done, root.report))
}

#[cfg(test)]
#[path = "tilting_pad_film_tests.rs"]
mod tests;
