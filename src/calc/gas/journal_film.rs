//! A plain (360°, full-film) gas journal bearing's film, dimensionless, in Khonsari & Booser
//! §11.3's scaling (Table 11.4): θ from the line of centres at the maximum film, positive with
//! rotation; y = z/R from a bearing end (ambient pressure) to the mid-plane (symmetry) at
//! y = L/D; H = h/C = 1 + ε cos θ; P = p/p_a absolute; Λ = 6μω(R/C)²/p_a.
//!
//! The film is periodic in θ and has no cavitation (a gas film keeps its sub-ambient pressures).
//! Its pressure level is fixed by the ambient ends: the infinitely long journal, periodic with no
//! ends, is singular (every P H = const is a Λ → ∞ solution), which is why the texts print two
//! different Λ → ∞ forms. The finite film fixes it: integrating the equation over θ and then y
//! from the mid-plane shows ∫ H³P² dθ = ∫ H³ dθ at every y, so the interior's P H = c has
//! c = √(1 + 1.5ε²) (Table 11.4), not the foil section's (1 + ε) (§11.7, P = 1 at the widest gap).
//!
//! A misaligned journal (a tilt ε′ = slope·L/C in the direction θ_δ of the film frame) adds the
//! liquid room's tilt term (Khonsari & Booser Eq. 8.70), H = 1 + ε cos θ − ε′(z/L − ½) cos(θ − θ_δ),
//! taken from that room's film geometry ([`crate::calc::journal::film::Film`]). The tilt is
//! antisymmetric about the mid-plane, so such a film is solved on the whole length, y from
//! one end to the other, both held at ambient ([`FarEdge::Held`]); its grid is the half grid
//! mirrored (2× the axial cells), so that a vanishing tilt gives the half grid's solution.
//! Its pressure then has a moment about the bearing centre: Ausman's misalignment moment
//! (Khonsari & Booser §11.5, Fig. 11.15).

use super::method::{Mesh, Method};
use crate::calc::journal::film::{Film, Misalignment};
use crate::calc::{Budget, CalcError};
use crate::fidelity::{IterationUnit, Level, SolverReport};
use crate::numerics::driver::{Driver, Stopped, Verdict};
use crate::numerics::reynolds_gas::{
    self, graded, graded_both_ends, FarEdge, GasGrid, GasProblem, GasStopping,
};
use crate::numerics::richardson::{extrapolate, fine_error, observed_order_error};
use std::f64::consts::{PI, TAU};

/// The film, dimensionless.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JournalFilm {
    /// ε = e/C, in [0, 1).
    pub eccentricity: f64,
    /// Λ = 6μω(R/C)²/p_a.
    pub bearing_number: f64,
    /// Kn = λ_a/C of the slip factor (0: continuum).
    pub knudsen_number: f64,
    /// L/D (the half-length in y = z/R).
    pub l_over_d: f64,
    /// A misaligned journal: (ε′, θ_δ), the tilt over the clearance (the ends' centres differ by
    /// ε′ C) and its direction in the film frame, rad (the liquid room's
    /// [`Film::tilt`]); None: aligned, solved on the half length.
    pub tilt: Option<(f64, f64)>,
}

impl JournalFilm {
    /// The liquid room's film geometry of this film (H, ∂θH, the centre's offset along the
    /// length) in ȳ = z/L.
    fn geometry(&self) -> Film {
        Film {
            tilt: self.tilt,
            ..Film::steady(self.eccentricity, self.l_over_d)
        }
    }

    /// H at θ and y = z/R from the first end.
    pub fn thickness(&self, theta: f64, y: f64) -> f64 {
        match self.tilt {
            None => 1.0 + self.eccentricity * theta.cos(),
            Some(_) => self.geometry().thickness(theta, 0.5 * y / self.l_over_d),
        }
    }

    /// The smallest H anywhere: 1 − ε aligned, at the worse end when tilted.
    pub fn min_thickness(&self) -> f64 {
        self.geometry().min_thickness()
    }

    /// W̄ = W/(p_a L D) per ∫∫ (P − 1)(…) dθ dy over the grid: 1/(2 L/D) on the half length
    /// (each half carries the same), 1/(4 L/D) on the whole.
    pub fn load_factor(&self) -> f64 {
        let halves = if self.tilt.is_some() { 2.0 } else { 1.0 };
        1.0 / (2.0 * halves * self.l_over_d)
    }
}

/// The dimensionless performance.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct JournalPerformance {
    /// W̄1 = W₁/(p_a L D), along the line of centres (toward the maximum film).
    pub load_along: f64,
    /// W̄2, perpendicular to it, ahead in the direction of rotation.
    pub load_across: f64,
    /// F C/(2π μ U R L) on the journal (moving; 1 at ε = 0).
    pub friction_journal: f64,
    /// The same on the bearing (stationary).
    pub friction_bearing: f64,
    /// Peak P (absolute over ambient).
    pub max_pressure: f64,
    /// Where the peak is, θ in radians.
    pub max_pressure_angle: f64,
    /// The pressure's moment on the journal about the bearing centre, M/(p_a R L²), in the film
    /// frame (toward the maximum film, 90° ahead, z along the spin): ∫∫ (P − 1)(z − L/2)
    /// (sin θ, −cos θ) R dθ dz over R L²; zero when aligned.
    pub moment: [f64; 2],
}

impl JournalPerformance {
    /// W̄ = W/(p_a L D).
    pub fn load(&self) -> f64 {
        self.load_along.hypot(self.load_across)
    }
    /// Attitude angle φ (load line to line of centres), radians.
    pub fn attitude(&self) -> f64 {
        self.load_across.atan2(self.load_along)
    }
    /// The moment in the load frame (x along the load, y 90° ahead in the rotation).
    pub fn moment_in_load_frame(&self) -> [f64; 2] {
        // The load line lies at θ = π − φ in the film frame.
        let (s, c) = (PI - self.attitude()).sin_cos();
        let [a, b] = self.moment;
        [a * c + b * s, -a * s + b * c]
    }
}

/// The cells of a level: around the circumference, across the half-length.
pub fn level_mesh(level: Level) -> Mesh {
    match level {
        Level::Fast => Mesh {
            along: 32,
            across: 8,
        },
        Level::ClosedForm | Level::Standard => Mesh {
            along: 64,
            across: 12,
        },
        Level::High => Mesh {
            along: 128,
            across: 24,
        },
    }
}

/// The stretched eccentricity s = ln(ε/(1 − ε)) in which the load searches run (the plain and the tilting-pad gas journals'): W̄ ∝ ε at small ε
/// (linear theory), so ln W̄ is nearly linear in s there and bends only gently toward ε → 1.
pub fn stretch(e: f64) -> f64 {
    (e / (1.0 - e)).ln()
}

/// ε from the stretched s of [`stretch`].
pub fn unstretch(s: f64) -> f64 {
    1.0 / (1.0 + (-s).exp())
}

/// The grid: θ uniform; y graded toward the bearing end so that its first cell is about
/// 1/(3√Λ) (the end layer's thickness scales as Λ^−½). A tilted film's grid is the half grid
/// and its mirror image about the mid-plane, y from 0 to 2 L/D.
pub fn grid(film: &JournalFilm, mesh: Mesh) -> GasGrid {
    let w = film.l_over_d;
    let finest = 0.33 / film.bearing_number.max(1.0).sqrt();
    let y = match film.tilt {
        None => graded(mesh.across.max(2), finest / w, true)
            .into_iter()
            .map(|v| v * w)
            .collect(),
        Some(_) => graded_both_ends(mesh.across.max(2), finest / (2.0 * w))
            .into_iter()
            .map(|v| v * 2.0 * w)
            .collect(),
    };
    GasGrid {
        x: (0..=mesh.along)
            .map(|k| k as f64 * TAU / mesh.along as f64)
            .collect(),
        y,
        periodic: true,
    }
}

/// The half mesh of `fine`: every other node.
pub fn coarsen(fine: &GasGrid) -> GasGrid {
    let every_other = |v: &[f64]| -> Vec<f64> { v.iter().step_by(2).copied().collect() };
    GasGrid {
        x: every_other(&fine.x),
        y: every_other(&fine.y),
        periodic: true,
    }
}

/// The film on the half mesh's half, started from the half mesh's field at the nodes they share,
/// for a three-mesh error estimate: Richardson's observed order over three meshes
/// ([`observed_order_error`]) sees a pair whose difference vanished by chance, which the pair
/// alone reports as a tiny error (the misaligned journal at Λ 1000, `standard`: 6.8e-5 against
/// 1.2e-4 before). None where the half mesh has an odd count of cells or Newton fails on the
/// quarter (too coarse for the film): the pair's estimate then stands.
fn quarter_mesh(film: &JournalFilm, half: &JournalSolve, budget: &Budget) -> Option<JournalSolve> {
    let g = &half.grid;
    if !g.nx().is_multiple_of(2) || !g.ny().is_multiple_of(2) {
        return None;
    }
    let grid = coarsen(g);
    let start: Vec<f64> = (0..grid.x.len())
        .flat_map(|i| (0..grid.y.len()).map(move |j| half.p[g.at(2 * i, 2 * j)]))
        .collect();
    solve_on(film, grid, Some(&start), budget).ok()
}

/// A film solved on one grid.
#[derive(Debug, Clone)]
pub struct JournalSolve {
    pub grid: GasGrid,
    pub p: Vec<f64>,
    pub performance: JournalPerformance,
    pub report: SolverReport,
}

/// The problem of `film` on `grid` (a tilted film's with both ends held at ambient).
pub fn problem(film: &JournalFilm, grid: &GasGrid) -> GasProblem {
    let problem = GasProblem::new(grid, film.bearing_number, film.knudsen_number, |t, y| {
        film.thickness(t, y)
    });
    GasProblem {
        far_edge: match film.tilt {
            None => FarEdge::Symmetry,
            Some(_) => FarEdge::Held,
        },
        ..problem
    }
}

/// Solve on `grid`, by Newton from `start` when given (a field on this grid near this film).
pub fn solve_on(
    film: &JournalFilm,
    grid: GasGrid,
    start: Option<&[f64]>,
    budget: &Budget,
) -> Result<JournalSolve, Stopped> {
    let problem = problem(film, &grid);
    let solved = reynolds_gas::solve(&grid, &problem, start, GasStopping::default(), budget)?;
    let performance = performance(film, &grid, &solved.p);
    Ok(JournalSolve {
        grid,
        p: solved.p,
        performance,
        report: solved.report,
    })
}

/// Loads, friction, the moment and the peak of a solved field. Over the grid,
/// S_c = ∫∫(P − 1) cos θ dθ dy and S_s likewise with sin θ; W̄1 = −S_c k, W̄2 = S_s k with k the
/// [`JournalFilm::load_factor`]. The journal's friction F̄ = ⟨1/H⟩ + (3/(πΛ)) k ∫∫(P − 1)(−∂θH)
/// (by parts: ∫H ∂θP dθ = −∫(P − 1) ∂θH dθ); aligned, ⟨1/H⟩ = 1/√(1 − ε²) and the pressure
/// term is (3ε/Λ) W̄2/π; tilted, ⟨1/H⟩ is the mean over the length of 1/√(1 − e(z)²), e(z) the
/// section's centre offset. The bearing's friction has the pressure term's other sign. The
/// moment is M/(p_a R L²) = ∫∫ (P − 1)(y − L/D)(sin θ, −cos θ) dθ dy/(2 L/D)² (y = z/R).
pub fn performance(film: &JournalFilm, grid: &GasGrid, p: &[f64]) -> JournalPerformance {
    let (mut sc, mut ss, mut shear) = (0.0, 0.0, 0.0);
    let mut moment = [0.0; 2];
    let (mut max_p, mut max_t) = (f64::MIN, 0.0);
    let w = film.l_over_d;
    let geometry = film.tilt.map(|_| film.geometry());
    for i in 0..grid.nx() {
        let (s, c) = grid.x[i].sin_cos();
        for j in 0..grid.y.len() {
            let weight = grid.weight(i, j);
            let g = p[grid.at(i, j)] - 1.0;
            sc += weight * g * c;
            ss += weight * g * s;
            if let Some(f) = &geometry {
                let arm = grid.y[j] - w;
                moment[0] += weight * g * arm * s;
                moment[1] -= weight * g * arm * c;
                shear -= weight * g * f.slope(grid.x[i], 0.5 * grid.y[j] / w);
            }
            if p[grid.at(i, j)] > max_p {
                max_p = p[grid.at(i, j)];
                max_t = grid.x[i];
            }
        }
    }
    let k = film.load_factor();
    let (along, across) = (-sc * k, ss * k);
    let e = film.eccentricity;
    let (couette, poiseuille) = match &geometry {
        None => (
            1.0 / (1.0 - e * e).sqrt(),
            3.0 * e / film.bearing_number * across / PI,
        ),
        Some(f) => {
            // The trapezoid over the length's nodes (its error is the mesh's, extrapolated).
            let (mut sum, mut length) = (0.0, 0.0);
            for j in 0..grid.y.len() {
                let offset = f.centre_offset(0.5 * grid.y[j] / w);
                sum += grid.cv_y(j) / (1.0 - offset * offset).sqrt();
                length += grid.cv_y(j);
            }
            (sum / length, 3.0 / (PI * film.bearing_number) * shear * k)
        }
    };
    let squared = 4.0 * w * w;
    JournalPerformance {
        load_along: along,
        load_across: across,
        friction_journal: couette + poiseuille,
        friction_bearing: couette - poiseuille,
        max_pressure: max_p,
        max_pressure_angle: max_t,
        moment: [moment[0] / squared, moment[1] / squared],
    }
}

/// The performance by a method: the mesh, and with Richardson the half mesh, extrapolated.
#[derive(Debug, Clone)]
pub struct JournalEvaluated {
    /// ε of the film solved.
    pub eccentricity: f64,
    /// Its tilt (ε′, θ_δ) as placed in the film frame; None: aligned.
    pub tilt: Option<(f64, f64)>,
    pub performance: JournalPerformance,
    /// Relative error estimate of W̄.
    pub error_estimate: Option<f64>,
    /// Relative error estimate of |M| (tilted films).
    pub moment_error_estimate: Option<f64>,
    pub fine: JournalSolve,
    pub coarse: Option<JournalSolve>,
    /// Newton steps and line-search trials over both meshes.
    pub iterations: u32,
    pub evaluations: u32,
}

/// Solve `film` by `method`, starting Newton from `warm` (an earlier evaluation at a nearby
/// eccentricity and the same Λ and grid) when given.
pub fn evaluate(
    film: &JournalFilm,
    method: Method,
    warm: Option<&JournalEvaluated>,
    budget: &Budget,
) -> Result<JournalEvaluated, Stopped> {
    let fine_grid = grid(film, method.mesh);
    let Some(coarse_grid) = method.richardson.then(|| coarsen(&fine_grid)) else {
        let fine = solve_on(film, fine_grid, warm.map(|w| w.fine.p.as_slice()), budget)?;
        let (iterations, evaluations) =
            (fine.report.iterations, fine.report.evaluations.unwrap_or(0));
        return Ok(JournalEvaluated {
            eccentricity: film.eccentricity,
            tilt: film.tilt,
            performance: fine.performance,
            error_estimate: None,
            moment_error_estimate: None,
            fine,
            coarse: None,
            iterations,
            evaluations,
        });
    };
    // The half mesh first (from the warm start's, if any); its field, interpolated, starts the
    // fine Newton unless a warm fine field is at hand.
    let coarse = solve_on(
        film,
        coarse_grid,
        warm.and_then(|w| w.coarse.as_ref()).map(|c| c.p.as_slice()),
        budget,
    )?;
    let start = match warm {
        Some(w) => w.fine.p.clone(),
        None => reynolds_gas::prolong(&coarse.grid, &coarse.p, &fine_grid),
    };
    let fine = solve_on(film, fine_grid, Some(&start), budget)?;
    let quarter = quarter_mesh(film, &coarse, budget);
    let solves = [Some(&fine), Some(&coarse), quarter.as_ref()];
    let iterations = solves.iter().flatten().map(|s| s.report.iterations).sum();
    let evaluations = solves
        .iter()
        .flatten()
        .map(|s| s.report.evaluations.unwrap_or(0))
        .sum();
    let (c, f) = (coarse.performance, fine.performance);
    let performance = JournalPerformance {
        load_along: extrapolate(c.load_along, f.load_along),
        load_across: extrapolate(c.load_across, f.load_across),
        friction_journal: extrapolate(c.friction_journal, f.friction_journal),
        friction_bearing: extrapolate(c.friction_bearing, f.friction_bearing),
        max_pressure: f.max_pressure,
        max_pressure_angle: f.max_pressure_angle,
        moment: [
            extrapolate(c.moment[0], f.moment[0]),
            extrapolate(c.moment[1], f.moment[1]),
        ],
    };
    let q = quarter.as_ref().map(|q| q.performance);
    // The fine value's error: from three meshes where the quarter mesh solved, else the pair's.
    let fine_value_error = |value: &dyn Fn(&JournalPerformance) -> f64| match &q {
        Some(q) => observed_order_error(value(q), value(&c), value(&f), 2.0).0,
        None => fine_error(value(&c), value(&f)).abs(),
    };
    let error_estimate =
        Some(fine_value_error(&|p: &JournalPerformance| p.load()) / performance.load().abs());
    let magnitude = |m: [f64; 2]| m[0].hypot(m[1]);
    let moment_error_estimate = film.tilt.map(|_| {
        fine_value_error(&|p: &JournalPerformance| magnitude(p.moment))
            / magnitude(performance.moment)
    });
    Ok(JournalEvaluated {
        eccentricity: film.eccentricity,
        tilt: film.tilt,
        performance,
        error_estimate,
        moment_error_estimate,
        fine,
        coarse: Some(coarse),
        iterations,
        evaluations,
    })
}

/// Smallest film H_min = h_min/C a misaligned journal may reach: the thinnest film the grids
/// resolve, that of the aligned journal at its largest eccentricity (1 − 0.95).
pub const MIN_FILM: f64 = 0.05;

/// Most placements (film evaluations) of a tilt measured from the load line.
const PLACEMENT_STEPS: u32 = 40;

/// The placement's tolerance on |φ_film(φ) − φ|, rad. Each film is converged to 1e-10 in P, so
/// its attitude carries noise near that level (a warm-started Newton may not move at all for a
/// smaller change of the film): the secant could chase it for many placements. 1e-7 rad is far
/// below the attitude's mesh error (about 1e-3 at `standard`).
const PLACEMENT_TOLERANCE: f64 = 1e-7;

/// The aligned film at `film`'s ε by `method`, its fields mirrored about the mid-plane onto the
/// whole-length grids: a start for the tilted film, whose attitude it gives to O(ε′²) and whose
/// field to O(ε′). None where a mesh does not mirror exactly (then the tilted film starts
/// afresh).
fn aligned_start(
    film: &JournalFilm,
    method: Method,
    budget: &Budget,
) -> Result<Option<JournalEvaluated>, Stopped> {
    let aligned = evaluate(
        &JournalFilm {
            tilt: None,
            ..*film
        },
        method,
        None,
        budget,
    )?;
    let whole = grid(
        &JournalFilm {
            tilt: Some((0.0, 0.0)),
            ..*film
        },
        method.mesh,
    );
    let mirror = |half: &JournalSolve, whole: GasGrid| -> Option<JournalSolve> {
        let ny = half.grid.y.len() - 1;
        if whole.y.len() != 2 * ny + 1 || whole.x.len() != half.grid.x.len() {
            return None;
        }
        let mut p = vec![0.0; whole.x.len() * whole.y.len()];
        for i in 0..whole.x.len() {
            for j in 0..whole.y.len() {
                p[whole.at(i, j)] = half.p[half.grid.at(i, j.min(2 * ny - j))];
            }
        }
        Some(JournalSolve {
            grid: whole,
            p,
            performance: half.performance,
            report: half.report.clone(),
        })
    };
    let coarse = aligned
        .coarse
        .as_ref()
        .and_then(|c| mirror(c, coarsen(&whole)));
    Ok(mirror(&aligned.fine, whole).map(|fine| JournalEvaluated {
        fine,
        coarse,
        tilt: None,
        ..aligned
    }))
}

/// A tilted film (`film` with its tilt given by `misalignment`) by `method`: the tilt's
/// direction in the film frame follows from the attitude φ when it is measured from the load
/// line ([`Misalignment::film_direction`]), and φ from the film. The consistent φ is the root of
/// g(φ) = φ_film(φ) − φ, found by the secant from φ_film of the first placement (the attitude
/// moves with the tilt's direction at second order in ε′ only, so g′ ≈ −1), each film started
/// from the last, the first from the aligned film mirrored onto the whole length
/// ([`aligned_start`]) unless `warm` is given. A tilt measured from the line of centres is
/// placed once. A placement that
/// brings the film below [`MIN_FILM`] anywhere is refused at `/misalignment`.
pub fn evaluate_tilted(
    film: &JournalFilm,
    misalignment: Misalignment,
    method: Method,
    warm: Option<&JournalEvaluated>,
    budget: &Budget,
) -> Result<JournalEvaluated, CalcError> {
    let place = |phi: f64| -> Result<JournalFilm, CalcError> {
        let placed = JournalFilm {
            tilt: Some((misalignment.tilt, misalignment.film_direction(phi))),
            ..*film
        };
        let h = placed.min_thickness();
        if h < MIN_FILM {
            return Err(CalcError::impossible(
                "/misalignment",
                format!(
                    "at ε = {:.4} the misaligned journal's film falls to h_min = {h:.4} C at an end, below the {MIN_FILM} C the grids resolve (0 is contact): reduce the misalignment or the load",
                    film.eccentricity
                ),
            ));
        }
        Ok(placed)
    };
    let start = match warm {
        Some(w) => Some(w.clone()),
        None => aligned_start(film, method, budget)?,
    };
    if misalignment.from_line_of_centres {
        return Ok(evaluate(&place(0.0)?, method, start.as_ref(), budget)?);
    }
    let mut phi = start
        .as_ref()
        .map_or(0.5 * PI, |w| w.performance.attitude());
    let mut last = start;
    let mut previous: Option<(f64, f64)> = None;
    let mut failure = None;
    let outcome = Driver::new(
        "secant_attitude_placement",
        IterationUnit::Evaluations,
        PLACEMENT_STEPS,
        budget,
    )
    .run(|_| {
        let solved = place(phi).and_then(|f| Ok(evaluate(&f, method, last.as_ref(), budget)?));
        let done = match solved {
            Ok(done) => done,
            Err(e) => {
                failure = Some(e);
                return Verdict::Stalled(f64::NAN);
            }
        };
        let turn = done.performance.attitude() - phi;
        let g = turn.sin().atan2(turn.cos());
        last = Some(done);
        if g.abs() <= PLACEMENT_TOLERANCE {
            return Verdict::Converged((), g.abs());
        }
        let next = match previous {
            Some((p0, g0)) if (g - g0).abs() > 1e-14 => phi - g * (phi - p0) / (g - g0),
            _ => phi + g,
        };
        previous = Some((phi, g));
        phi = next;
        Verdict::Continue(g.abs())
    });
    if let Some(e) = failure {
        return Err(e);
    }
    let _settled = outcome?;
    Ok(last.expect("a converged placement solved a film"))
}

#[cfg(test)]
#[path = "journal_film_tests.rs"]
pub(crate) mod tests;

#[cfg(test)]
#[path = "journal_tilt_tests.rs"]
mod tilt_tests;
