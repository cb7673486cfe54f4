//! A plain journal bearing's dimensionless performance at one eccentricity ratio, by the method
//! the fidelity asks for, and the equilibrium eccentricity for a given Sommerfeld number.

use std::f64::consts::{FRAC_PI_2, PI};

use super::closed_form::{self, Boundary};
use super::eccentricity::EccentricityRatio;
use super::film::{self, FeedLine, Film, FilmModel, FilmSolution, Mesh};
use crate::calc::{Budget, CalcError};
use crate::fidelity::{IterationUnit, Level, SolverReport, StopReason};
use crate::numerics::driver::{Driver, Verdict};
use crate::numerics::refine::{refine, Judgement, Pair, RefineError, Refined};
use crate::numerics::reynolds::Stopping;
use crate::numerics::richardson;
use crate::numerics::roots::{self, brent, RootError};

/// Highest eccentricity ratio the service solves for: beyond it the minimum film is below 0.1 %
/// of the clearance, where no real bearing runs (and S < 1e-3 even at L/D = 1/4).
pub const MAX_ECCENTRICITY: f64 = 0.999;
/// Lowest eccentricity ratio of an equilibrium search.
pub const MIN_ECCENTRICITY: f64 = 1e-4;

/// The closed-form approximation used at `fidelity: closed_form`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Approximation {
    /// Infinitely short (Ocvirk).
    Short,
    /// Infinitely long.
    Long,
}

/// How to compute.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Method {
    ClosedForm(Approximation),
    /// Finite-length Reynolds on `mesh`; `richardson` extrapolates from the half mesh;
    /// `estimate`: the point's error estimate takes a third mesh (false: the pair's, for a point
    /// that only screens or starts a search).
    Numerical {
        level: Level,
        mesh: Mesh,
        stop: Stopping,
        richardson: bool,
        estimate: bool,
    },
}

impl Method {
    /// The numerical method of a fidelity level, or an explicit mesh / tolerance.
    pub fn numerical(level: Level, mesh: Option<Mesh>, tolerance: Option<f64>) -> Method {
        let (default_mesh, default_tol) = match level {
            Level::Fast => (
                Mesh {
                    circumferential: 48,
                    axial_half: 6,
                },
                1e-6,
            ),
            Level::High => (
                Mesh {
                    circumferential: 192,
                    axial_half: 24,
                },
                1e-10,
            ),
            _ => (
                Mesh {
                    circumferential: 96,
                    axial_half: 12,
                },
                1e-8,
            ),
        };
        Method::Numerical {
            level,
            mesh: mesh.unwrap_or(default_mesh),
            stop: Stopping {
                tolerance: tolerance.unwrap_or(default_tol),
                max_sweeps: 100_000,
            },
            // An explicit mesh that halves exactly and is at least the standard one's size is
            // extrapolated like `high` (coarser pairs are not in the asymptotic range).
            richardson: level == Level::High
                || mesh.is_some_and(|m| {
                    m.halves_exactly() && m.circumferential >= 96 && m.axial_half >= 12
                }),
            estimate: true,
        }
    }
}

impl Method {
    /// The numerical method's mesh (None for a closed form).
    pub fn mesh(self) -> Option<Mesh> {
        match self {
            Method::Numerical { mesh, .. } => Some(mesh),
            Method::ClosedForm(_) => None,
        }
    }

    /// The numerical method on the mesh with half the cells each way, neither extrapolated nor
    /// estimating with a third mesh: the stage that screens or starts a search.
    pub fn coarser(self) -> Method {
        match self {
            Method::Numerical {
                level, mesh, stop, ..
            } => Method::Numerical {
                level,
                mesh: mesh.coarse(),
                stop,
                richardson: false,
                estimate: false,
            },
            m => m,
        }
    }

    /// This numerical method without the third mesh of its error estimate.
    pub fn without_estimate(self) -> Method {
        match self {
            Method::Numerical {
                level,
                mesh,
                stop,
                richardson,
                ..
            } => Method::Numerical {
                level,
                mesh,
                stop,
                richardson,
                estimate: false,
            },
            m => m,
        }
    }

    /// This numerical method with another stopping rule, reported under `level`.
    pub fn with_stop(self, stop: Stopping, level: Level) -> Method {
        match self {
            Method::Numerical {
                mesh,
                richardson,
                estimate,
                ..
            } => Method::Numerical {
                level,
                mesh,
                stop,
                richardson,
                estimate,
            },
            m => m,
        }
    }
}

/// Where a film solve starts: the converged field of a nearby solve on the same mesh, and for a
/// placed film the attitude φ (rad) a nearby solve settled at.
#[derive(Debug, Clone, Default)]
pub struct FilmStart {
    pub field: Option<Vec<f64>>,
    pub attitude: Option<f64>,
}

impl FilmStart {
    /// From a field alone (or from rest).
    #[must_use]
    pub fn field(field: Option<Vec<f64>>) -> Self {
        FilmStart {
            field,
            attitude: None,
        }
    }
}

/// Secant steps on the attitude from a nearby solve's φ before the bracketed search: each
/// step at most this long (rad), at most this many solves.
const ATTITUDE_STEP: f64 = 0.3;
const ATTITUDE_SECANT_SOLVES: usize = 8;

/// The film at ε, positioned. A full bearing is fed at h_max, so the film frame is the bearing's.
/// A partial bearing's arc is fixed on the load line, so the line of centres must be placed: the
/// attitude φ where the film force lies along the load (Stachowiak & Batchelor's attitude
/// iteration in PARTIAL, here a root of the angle between the force and the load). From a
/// nearby solve's φ (`start.attitude`) secant steps find it in three or four solves (the angle
/// falls with φ at a rate near 1: the force turns with the line of centres); from rest, or when
/// they wander, Brent's bracketed search over φ ∈ [0, 135°].
pub fn positioned_film(
    eccentricity: EccentricityRatio,
    l_over_d: f64,
    model: FilmModel,
    mesh: Mesh,
    stop: Stopping,
    start: FilmStart,
    budget: &Budget,
) -> Result<(Film, FilmSolution, Vec<f64>), CalcError> {
    let eps = eccentricity.get();
    let base = Film {
        physics: model,
        ..Film::steady(eps, l_over_d)
    };
    if !placed(&model) {
        let (f, p) = film::solve(base, mesh, stop, start.field, budget)?;
        return Ok((base, f, p));
    }
    let place = |phi: f64| placed_at(base, phi);
    // φ = 0 centres the arc on h_min; φ → 90° puts it all in the converging film. The
    // equilibrium lies between (an arc wholly in the diverging film carries nothing).
    // Light loads on near-full arcs put φ close to (or past) 90°: search up to 135°. A tilted
    // journal touches at some attitudes: the search keeps to the widest interval where it does
    // not (geometry alone, no film solve), so that whether a load is refused does not depend
    // on where the search starts.
    let (lowest, highest) = clear_interval(|phi| place(phi).min_thickness() > TOUCHING, 0.75 * PI)
        .ok_or_else(|| touching(eps))?;
    let narrowed = lowest > 0.0 || highest < 0.75 * PI;
    let mut warm = start.field;
    // The last film solved, at its φ: the answer when the search ends on it.
    let mut last: Option<(f64, FilmSolution, Vec<f64>)> = None;
    // The signed angle from the load line's direction to the load −F at φ.
    let mut mismatch = |phi: f64| -> Result<f64, CalcError> {
        let film = place(phi);
        if film.min_thickness() <= TOUCHING {
            return Err(touching(eps));
        }
        let (f, p) = film::solve(film, mesh, stop, warm.take(), budget)?;
        warm = Some(p.clone());
        let angle = attitude_mismatch(&f, phi);
        last = Some((phi, f, p));
        Ok(angle)
    };
    let x_tolerance = 1e-9;
    let secant = start.attitude.map(|guess| {
        attitude_secant(
            &mut mismatch,
            guess.clamp(lowest, highest),
            (lowest, highest),
            x_tolerance,
        )
    });
    let phi = match secant {
        Some(Ok(Some(phi))) => phi,
        // A deadline is not a wandering secant.
        Some(Err(e @ CalcError::DeadlineExceeded)) => return Err(e),
        _ => {
            match brent_or_failure(&mut mismatch, (lowest, highest), x_tolerance)? {
                Ok(r) => r.x,
                Err(e @ RootError::NotConverged { .. }) => {
                    return Err(CalcError::from_root("brent_attitude", e))
                }
                // Every attitude that balances the load touches.
                Err(_) if narrowed => return Err(touching(eps)),
                Err(_) => {
                    // Not "/misalignment": that pointer means the journal touches.
                    return Err(no_attitude(&model));
                }
            }
        }
    };
    let film = place(phi);
    let (f, p) = match last {
        Some((at, f, p)) if at == phi => (f, p),
        _ => film::solve(film, mesh, stop, warm, budget)?,
    };
    // The search can also settle on the ±180° jump of the angle: only a force on the load line
    // counts.
    let (wa, wb) = (-f.load_radial, f.load_tangential);
    let (da, db) = ((PI - phi).cos(), (PI - phi).sin());
    if wa * da + wb * db <= 0.0 {
        return Err(no_attitude(&model));
    }
    Ok((film, f, p))
}

/// `base` (a steady film of the model) placed at attitude φ: in the film frame the load line
/// sits at θ = π − φ; the arc is centred on it and the misalignment's direction is measured from
/// it. A full film fed opposite the load starts at θ = −φ.
fn placed_at(base: Film, phi: f64) -> Film {
    let model = base.physics;
    let feed_at = model.arc.is_none().then(|| fed_at(&model)).flatten();
    Film {
        span: match model.arc {
            Some(arc) => Some((PI - phi - 0.5 * arc, PI - phi + 0.5 * arc)),
            None => feed_at.map(|offset| (offset - phi, offset + 2.0 * PI - phi)),
        },
        tilt: model.misalignment.map(|m| (m.tilt, m.film_direction(phi))),
        ..base
    }
}

/// The signed angle from the load line's direction to the load −F of a film placed at φ.
fn attitude_mismatch(f: &FilmSolution, phi: f64) -> f64 {
    let (wa, wb) = (-f.load_radial, f.load_tangential);
    let (da, db) = ((PI - phi).cos(), (PI - phi).sin());
    (wa * db - wb * da).atan2(wa * da + wb * db)
}

/// The widest interval of [0, `end`] where `clear` holds, its ends found to 1e-9 by bisection
/// from a scan of 64 steps; None where it holds nowhere on the scan.
fn clear_interval(clear: impl Fn(f64) -> bool, end: f64) -> Option<(f64, f64)> {
    const STEPS: usize = 64;
    let at = |k: usize| end * k as f64 / STEPS as f64;
    let ok: Vec<bool> = (0..=STEPS).map(|k| clear(at(k))).collect();
    // The longest run of clear scan points.
    let (mut best, mut run_start) = (None::<(usize, usize)>, None);
    for (k, &clear_here) in ok.iter().enumerate() {
        match (clear_here, run_start) {
            (true, None) => run_start = Some(k),
            (false, Some(s)) => {
                if best.is_none_or(|(a, b)| k - 1 - s > b - a) {
                    best = Some((s, k - 1));
                }
                run_start = None;
            }
            _ => {}
        }
    }
    if let Some(s) = run_start {
        if best.is_none_or(|(a, b)| STEPS - s > b - a) {
            best = Some((s, STEPS));
        }
    }
    let (a, b) = best?;
    // An end inside [0, end] lies between a clear point and the touching one beside it.
    let edge = |mut inside: f64, mut outside: f64| {
        while (inside - outside).abs() > 1e-9 {
            let mid = 0.5 * (inside + outside);
            if clear(mid) {
                inside = mid;
            } else {
                outside = mid;
            }
        }
        inside
    };
    let lo = if a == 0 { 0.0 } else { edge(at(a), at(a - 1)) };
    let hi = if b == STEPS {
        end
    } else {
        edge(at(b), at(b + 1))
    };
    Some((lo, hi))
}

/// Brent's search (at most 100 steps) for a root of `f` in `bracket`, where an evaluation may
/// fail: the first failure, else the search's answer.
fn brent_or_failure(
    f: impl FnMut(f64) -> Result<f64, CalcError>,
    (lo, hi): (f64, f64),
    x_tolerance: f64,
) -> Result<Result<roots::Root, RootError>, CalcError> {
    let stop = roots::Stopping {
        x_tolerance,
        max_iterations: 100,
    };
    roots::brent_outcome(f, lo, hi, stop)
}

/// Secant steps on the attitude mismatch from `guess`, the first with the slope −1, each at
/// most [`ATTITUDE_STEP`] and kept in `bounds`: the root (the last φ evaluated) when a step
/// falls below `x_tolerance` within [`ATTITUDE_SECANT_SOLVES`] solves, None when the steps
/// wander (the caller's bracketed search takes over), or the solve's error.
fn attitude_secant(
    mismatch: &mut impl FnMut(f64) -> Result<f64, CalcError>,
    guess: f64,
    (lowest, highest): (f64, f64),
    x_tolerance: f64,
) -> Result<Option<f64>, CalcError> {
    let step_to = |from: f64, step: f64| from + step.clamp(-ATTITUDE_STEP, ATTITUDE_STEP);
    let (mut x0, mut f0) = (guess, mismatch(guess)?);
    // A guess already on the root (a converged film solved again): the first step, with the
    // slope −1, would be shorter than the tolerance.
    if f0.abs() < x_tolerance {
        return Ok(Some(guess));
    }
    let mut x1 = step_to(x0, f0).clamp(lowest, highest);
    for _ in 1..ATTITUDE_SECANT_SOLVES {
        if x1 == x0 {
            return Ok((f0 == 0.0).then_some(x0));
        }
        let f1 = mismatch(x1)?;
        let slope = (f1 - f0) / (x1 - x0);
        // Near the root the angle falls with φ; a flat or rising slope is not that branch.
        if !(slope.is_finite() && slope < 0.0) {
            return Ok(None);
        }
        let next = step_to(x1, -f1 / slope);
        if (next - x1).abs() < x_tolerance {
            // A root, not the angle's ±180° jump.
            return Ok((f1.abs() < FRAC_PI_2).then_some(x1));
        }
        if !(lowest..=highest).contains(&next) {
            return Ok(None);
        }
        (x0, f0, x1) = (x1, f1, next);
    }
    Ok(None)
}

/// Where a mass-conserving film fed away from h_max starts, as θ + φ (the load line lies at
/// θ = π − φ): 0 opposite the load, π/2 for the groove at +90° of two; None when fed at h_max.
fn fed_at(model: &FilmModel) -> Option<f64> {
    match model.mass_conserving {
        Some(supply) if model.has_content() => match supply.position {
            FeedLine::MaxFilm => None,
            FeedLine::OppositeLoad => Some(0.0),
            FeedLine::TwoGrooves => Some(0.5 * PI),
        },
        _ => None,
    }
}

/// Whether the film must be placed against the load line (an attitude search): a partial arc,
/// a misaligned journal, or a feed fixed in the bearing away from h_max.
pub fn placed(model: &FilmModel) -> bool {
    model.arc.is_some() || model.misalignment.is_some() || fed_at(model).is_some()
}

/// The film force never lies on the load line at this ε. With a ported supply this happens at
/// light load, where the supply pressure's own push on the journal outweighs the film's
/// (Stachowiak & Batchelor §5.6.3 on GROOVE: no attitude converges when the groove pressure
/// exceeds the hydrodynamic pressure); an equilibrium search then looks at larger ε.
fn no_attitude(model: &FilmModel) -> CalcError {
    if model.port().is_some() {
        CalcError::impossible(
            SUPPLY_DOMINATES,
            "the supply pressure's force on the journal outweighs the film's at this eccentricity: no attitude puts the film force on the load line (a heavier load or a lower supply pressure has an equilibrium)",
        )
    } else {
        CalcError::impossible(
            if model.arc.is_some() { "/arc_deg" } else { "" },
            "no attitude angle puts the film force on the load line at this eccentricity",
        )
    }
}

/// The pointer of [`no_attitude`]'s error for a ported supply.
pub const SUPPLY_DOMINATES: &str = "/feed/supply_pressure_pa";

/// Smallest film (h_min/C) a misaligned journal may reach before it counts as touching.
const TOUCHING: f64 = 1e-3;

fn touching(eps: f64) -> CalcError {
    CalcError::impossible(
        "/misalignment",
        format!("at ε = {eps:.4} the misaligned journal touches the bearing at an end (h_min below 0.1 % of C): reduce the misalignment or the load"),
    )
}

/// One operating point, dimensionless (Table 8.6 conventions).
#[derive(Debug, Clone, PartialEq)]
pub struct Point {
    pub eccentricity_ratio: EccentricityRatio,
    pub sommerfeld_number: f64,
    pub attitude_angle: f64,
    pub friction_parameter: f64,
    pub max_pressure_nd: f64,
    pub max_pressure_angle: f64,
    pub cavitation_angle: Option<f64>,
    pub side_leakage_nd: f64,
    pub inlet_flow_nd: Option<f64>,
    /// h_min/C (at an end when misaligned).
    pub min_film_nd: f64,
    /// (θ, P̄) along the mid-plane, numerical solutions only.
    pub midplane: Option<Vec<(f64, f64)>>,
    /// The film's moment on a misaligned journal in the load frame (x along the load, y 90°
    /// ahead in the rotation, z along the spin), per μ N_s (R/C)² R L²; None when aligned.
    pub moment_nd: Option<[f64; 2]>,
    /// Mass-conserving films: θ_f along the mid-plane, and the cavitated share of the film area.
    pub midplane_content: Option<Vec<f64>>,
    pub cavitated_fraction: Option<f64>,
    /// Numerical work: the film solves' report (the steps of the fine and the coarse mesh,
    /// the fine field's equation residual), the relative error estimate of S, the mesh.
    pub solve: Option<SolverReport>,
    pub error_estimate: Option<f64>,
    pub mesh: Option<Mesh>,
    /// The converged field on `mesh` (numerical solutions): where a further solve about this
    /// point starts.
    pub field: Option<Vec<f64>>,
}

/// (R/C)·f with the journal's shear integrated over the whole film (Khonsari & Booser G5, the
/// convention of Table 8.6: the Couette shear over the full circumference, cavitated or not):
/// (R/C) f = ∫∫ P̄ (−∂h̄/∂θ) / (2 |∫∫ P̄|) + π S ∫∫ G_f/h̄, which for the aligned laminar 360°
/// bearing is (ε/2) sin φ + 2π² S/√(1 − ε²). Turbulent films carry the Ng–Pan G_f (Eq. 6.30).
pub fn friction_parameter(f: &FilmSolution) -> f64 {
    let load = f.load_radial.hypot(f.load_tangential);
    0.5 * f.pressure_shear / load + PI * f.sommerfeld_number() * f.couette_shear
}

/// A vector of the film frame (towards h_max, 90° ahead) in the load frame: x along the load
/// W = −F, y 90° ahead of it in the direction of rotation.
pub fn load_frame(f: &FilmSolution, v: [f64; 2]) -> [f64; 2] {
    let force = [f.load_radial, -f.load_tangential];
    let norm = force[0].hypot(force[1]);
    let x = [-force[0] / norm, -force[1] / norm];
    let y = [-x[1], x[0]];
    [v[0] * x[0] + v[1] * x[1], v[0] * y[0] + v[1] * y[1]]
}

fn from_film(eps: EccentricityRatio, f: &FilmSolution, physics: FilmModel) -> Point {
    let s = f.sommerfeld_number();
    let phi = f.attitude_angle();
    Point {
        eccentricity_ratio: eps,
        sommerfeld_number: s,
        attitude_angle: phi,
        friction_parameter: friction_parameter(f),
        max_pressure_nd: f.max_pressure_nd,
        max_pressure_angle: f.max_pressure_angle,
        cavitation_angle: (physics.cavitation || physics.half_sommerfeld)
            .then_some(f.cavitation_angle),
        side_leakage_nd: f.side_leakage_nd,
        inlet_flow_nd: Some(f.inlet_flow_nd),
        min_film_nd: f.min_thickness,
        midplane: Some(f.midplane.clone()),
        midplane_content: f.midplane_content.clone(),
        moment_nd: physics.misalignment.map(|_| load_frame(f, f.moment)),
        cavitated_fraction: f.cavitated_fraction,
        solve: Some(f.solved.report.clone()),
        error_estimate: None,
        mesh: None,
        field: None,
    }
}

/// Performance at eccentricity ratio `eps` for L/D = `l_over_d`.
pub fn at_eccentricity(
    eps: EccentricityRatio,
    l_over_d: f64,
    method: Method,
    physics: FilmModel,
    budget: &Budget,
) -> Result<Point, CalcError> {
    at_eccentricity_from(
        eps,
        l_over_d,
        method,
        physics,
        &mut Fields::default(),
        budget,
    )
}

/// Converged fields by mesh: where the next solve on that mesh starts (a nearby ε's field
/// starts the active-set iteration close to its answer), and the attitude the last placed film
/// settled at on any mesh (where the next one's search starts).
#[derive(Debug, Default)]
struct Fields {
    /// Per mesh: the field, and the attitude its placed film settled at.
    fields: Vec<(Mesh, Vec<f64>, Option<f64>)>,
    attitude: Option<f64>,
}

impl Fields {
    /// The field kept for `mesh`, and the attitude of that mesh's last placed film (else the
    /// last placed film's on any mesh).
    fn take(&mut self, mesh: Mesh) -> FilmStart {
        let (field, own) = match self.fields.iter().position(|(m, ..)| *m == mesh) {
            Some(k) => {
                let (_, field, own) = self.fields.swap_remove(k);
                (Some(field), own)
            }
            None => (None, None),
        };
        FilmStart {
            field,
            attitude: own.or(self.attitude),
        }
    }

    /// The attitude of `mesh`'s last placed film.
    fn own_attitude(&self, mesh: Mesh) -> Option<f64> {
        self.fields
            .iter()
            .find(|(m, ..)| *m == mesh)
            .and_then(|(.., own)| *own)
    }

    /// The field solved on `mesh`, and its film's attitude when it was placed.
    fn keep(&mut self, mesh: Mesh, field: Vec<f64>, placed_at: Option<f64>) {
        self.fields.retain(|(m, ..)| *m != mesh);
        self.fields.push((mesh, field, placed_at));
        if placed_at.is_some() {
            self.attitude = placed_at;
        }
    }
}

/// As [`at_eccentricity`], each solve starting from the field `fields` hold for its mesh, and
/// leaving its own there.
fn at_eccentricity_from(
    eps: EccentricityRatio,
    l_over_d: f64,
    method: Method,
    physics: FilmModel,
    fields: &mut Fields,
    budget: &Budget,
) -> Result<Point, CalcError> {
    match method {
        Method::ClosedForm(approx) => Ok(closed(eps, l_over_d, approx, physics)),
        Method::Numerical {
            mesh,
            stop,
            richardson,
            estimate,
            ..
        } => {
            // The pair: the mesh with half the cells each way, then the method's mesh, started
            // from the fields kept or (an unplaced film) from the coarse field; one rung of
            // refinement, whose estimate is reported, not acted on (the tolerance is not tested).
            let load_fixed = placed(&physics);
            let film = Film {
                physics,
                ..Film::steady(eps.get(), l_over_d)
            };
            let solve_on = |m: Mesh, start: FilmStart| {
                if load_fixed {
                    positioned_film(eps, l_over_d, physics, m, stop, start, budget)
                        .map(|(_, f, p)| (f, p))
                } else {
                    film::solve(film, m, stop, start.field, budget).map_err(CalcError::from)
                }
            };
            // A placed film's attitude, where the next mesh's search starts.
            let placed_at = |f: &FilmSolution| load_fixed.then(|| f.attitude_angle());
            let half = mesh.coarse();
            // Second-order scheme: the fine mesh's error is about (S_h − S_rh)/(r² − 1), r = 2
            // when the coarse mesh halves both spacings.
            let r = mesh.refinement_ratio();
            let refined = refine(
                half,
                solve_on(half, fields.take(half))?,
                f64::INFINITY,
                |m| (m == half).then_some(mesh),
                |m, (coarse, coarse_field): &(FilmSolution, Vec<f64>)| {
                    // This mesh's own last attitude (a search's, at a nearby ε) before the
                    // coarse mesh's at this ε.
                    let own = fields.own_attitude(m);
                    let mut start = fields.take(m);
                    if start.field.is_none() && !load_fixed {
                        start.field = Some(film::prolonged(&film, half, coarse_field, m));
                    }
                    start.attitude = own.or(placed_at(coarse)).or(start.attitude);
                    solve_on(m, start)
                },
                |(coarse, _), (fine, _)| {
                    let (sf, sc) = (fine.sommerfeld_number(), coarse.sommerfeld_number());
                    Judgement::Resolved(((sf - sc) / (r * r - 1.0) / sf).abs())
                },
            );
            let (Pair { coarse, fine, .. }, pair_error) = match refined {
                Ok(Refined::Converged { pair, error } | Refined::GridLimited { pair, error }) => {
                    (pair, error)
                }
                Ok(Refined::FellBack { failure, .. })
                | Err(RefineError::Failed { failure, .. }) => return Err(failure),
                Err(e) => return Err(CalcError::Internal(format!("mesh pair: {e:?}"))),
            };
            let ((coarse, coarse_field), (fine, fine_field)) = (coarse, fine);
            fields.keep(half, coarse_field, placed_at(&coarse));
            fields.keep(mesh, fine_field.clone(), placed_at(&fine));
            let near = FilmStart {
                field: None,
                attitude: placed_at(&fine),
            };
            // A third mesh guards the pair's estimate against an accidental agreement of the
            // two ([`third_mesh`]).
            let (sf, sc) = (fine.sommerfeld_number(), coarse.sommerfeld_number());
            let error = match (estimate, third_mesh(mesh)) {
                (false, _) => pair_error,
                (true, ThirdMesh::Quarter(quarter)) => {
                    let (third, _) = solve_on(quarter, near)?;
                    three_mesh_estimate([sf, sc, third.sommerfeld_number()], r)
                }
                (true, ThirdMesh::Double(double)) => {
                    let start = FilmStart {
                        field: (!load_fixed)
                            .then(|| film::prolonged(&film, mesh, &fine_field, double)),
                        ..near
                    };
                    let (third, _) = solve_on(double, start)?;
                    order_free_estimate([third.sommerfeld_number(), sf, sc])
                }
            };
            let mut point = from_film(eps, &fine, physics);
            point.error_estimate = Some(error);
            // Richardson's extrapolation needs the same ratio both ways: only exact halvings
            // (the `high` mesh is one) are extrapolated.
            debug_assert!(!richardson || mesh.halves_exactly(), "{mesh:?}");
            if richardson && mesh.halves_exactly() {
                let extrapolate = |f: f64, c: f64| richardson::extrapolate(c, f);
                let film = FilmSolution {
                    load_radial: extrapolate(fine.load_radial, coarse.load_radial),
                    load_tangential: extrapolate(fine.load_tangential, coarse.load_tangential),
                    max_pressure_nd: extrapolate(fine.max_pressure_nd, coarse.max_pressure_nd),
                    side_leakage_nd: extrapolate(fine.side_leakage_nd, coarse.side_leakage_nd),
                    inlet_flow_nd: extrapolate(fine.inlet_flow_nd, coarse.inlet_flow_nd),
                    pressure_shear: extrapolate(fine.pressure_shear, coarse.pressure_shear),
                    moment: [
                        extrapolate(fine.moment[0], coarse.moment[0]),
                        extrapolate(fine.moment[1], coarse.moment[1]),
                    ],
                    ..fine.clone()
                };
                point = Point {
                    error_estimate: point.error_estimate,
                    ..from_film(eps, &film, physics)
                };
            }
            point.solve = Some(fine.solved.clone().after(&coarse.solved).report);
            point.mesh = Some(mesh);
            point.field = Some(fine_field);
            Ok(point)
        }
    }
}

/// The third mesh of a point's error estimate, beside its pair (the mesh and its half).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ThirdMesh {
    /// The next coarser, with the observed order ([`three_mesh_estimate`]): an eighth of the
    /// half mesh's cost.
    Quarter(Mesh),
    /// The next finer, trusting no order ([`order_free_estimate`]): sixteen times the mesh's
    /// band work.
    Double(Mesh),
}

/// The quarter mesh for the levels' meshes and for explicit meshes with more cells than
/// `high`'s; the doubled mesh for other explicit meshes, whose pair may be far from the
/// asymptotic range, and for any mesh too coarse to halve twice (fewer than 48 cells round).
pub fn third_mesh(mesh: Mesh) -> ThirdMesh {
    let [fast, standard, high] = [Level::Fast, Level::Standard, Level::High]
        .map(|level| Method::numerical(level, None, None).mesh());
    let explicit = ![fast, standard, high].contains(&Some(mesh));
    let quarter = mesh.coarse().coarse();
    if quarter.circumferential < 12
        || explicit && high.is_some_and(|high| mesh.cells() <= high.cells())
    {
        ThirdMesh::Double(Mesh {
            circumferential: 2 * mesh.circumferential,
            axial_half: 2 * mesh.axial_half,
        })
    } else {
        ThirdMesh::Quarter(quarter)
    }
}

/// Safety factor on a three-mesh estimate (Roache's grid convergence index with an observed
/// order uses 1.25).
const ESTIMATE_SAFETY: f64 = 1.25;

/// The relative error of the finest of three values on meshes refined by `r` each time
/// ([fine, middle, coarse]). The observed order p = ln(d₂/d₁)/ln r of the successive
/// differences (d₁ the finer pair's) is held to [1, 2] (the scheme's order is 2; a smaller ratio
/// means the meshes are not yet in the asymptotic range, where the estimate must not trust
/// second order); each difference then gives the fine value's error (the finer pair's
/// d₁/(r^p − 1), the coarser's d₂/(r^p − 1) scaled down by r^p), and the larger of the two
/// counts, with a safety factor. Against a converged reference over ε 0.1–0.99 and L/D 0.25–2
/// it bounds the error of every level (docs/accuracy.md).
fn three_mesh_estimate([fine, middle, coarse]: [f64; 3], r: f64) -> f64 {
    let (error, _) = richardson::observed_order_error(coarse, middle, fine, r);
    ESTIMATE_SAFETY * error / fine.abs()
}

/// The relative error of the middle of three values ([fine, middle, coarse], the fine mesh
/// twice as fine as the middle) without trusting an order: the larger of the finer pair's
/// difference taken at first order (2|d₁|, its r/(r − 1) at r = 2) and the coarser pair's whole
/// difference (|d₂|, the middle's error if the error falls at least linearly), with the safety
/// factor. Explicit meshes coarser than the levels' can be far from the asymptotic range, where
/// [`three_mesh_estimate`]'s observed order misleads: on [64, 8] at L/D 0.25, ε 0.9 it reported
/// a 3.6th of the error. Against a converged reference over ε 0.1–0.99 and L/D 0.25–2 this
/// bounds the error of every explicit mesh checked ([24, 6], [64, 8], [60, 20], [96, 16] and
/// [200, 10]), at most 0.68 of it (the test `error_estimates_bound_the_error`; docs/accuracy.md).
fn order_free_estimate([fine, middle, coarse]: [f64; 3]) -> f64 {
    ESTIMATE_SAFETY * (2.0 * (fine - middle).abs()).max((middle - coarse).abs()) / middle.abs()
}

/// The closed form of `physics`'s film: the Reynolds condition (the short bearing has only
/// the half-Sommerfeld one), Gümbel's half-Sommerfeld film, or the full film.
fn closed(
    eccentricity: EccentricityRatio,
    l_over_d: f64,
    approx: Approximation,
    physics: FilmModel,
) -> Point {
    let eps = eccentricity.get();
    let boundary = match (physics.cavitation, physics.half_sommerfeld) {
        (true, _) if approx == Approximation::Long => Boundary::Reynolds,
        (true, _) | (false, true) => Boundary::HalfSommerfeld,
        (false, false) => Boundary::FullSommerfeld,
    };
    let p = match approx {
        Approximation::Long => closed_form::long_bearing(eps, boundary),
        Approximation::Short => closed_form::short_bearing(eps, l_over_d, boundary)
            .expect("the short bearing has full and half films"),
    };
    Point {
        eccentricity_ratio: eccentricity,
        sommerfeld_number: p.sommerfeld_number,
        attitude_angle: p.attitude_angle_rad,
        friction_parameter: p.friction_parameter,
        max_pressure_nd: p.max_pressure_nd,
        max_pressure_angle: p.max_pressure_angle_rad,
        cavitation_angle: p.cavitation_angle_rad,
        side_leakage_nd: p.side_leakage_nd,
        inlet_flow_nd: None,
        min_film_nd: 1.0 - eps,
        midplane: None,
        midplane_content: None,
        cavitated_fraction: None,
        moment_nd: None,
        solve: None,
        error_estimate: None,
        mesh: None,
        field: None,
    }
}

/// The step in u = ln(ε/(1 − ε)) below which a search on the method's own mesh has converged:
/// the secant converges superlinearly, so the root is then good to far better than 1e-8 — the
/// load carried to 1e-8, five decades below the finest mesh's discretisation error.
const FINE_TOLERANCE: f64 = 1e-8;

/// What an equilibrium search balances at ε: a residual of the operating point that falls as ε
/// grows (0 at equilibrium), and the reason when no ε of the bracket balances it.
pub trait Balance {
    fn residual(&self, point: &Point) -> Result<f64, CalcError>;
    /// Why no ε balances: `at_start` and `at_end` are the residuals at the bracket's ends.
    fn out_of_reach(&self, at_start: f64, at_end: f64) -> CalcError;
}

/// The load: ln S(ε) − ln S_target.
struct LoadBalance {
    s_target: f64,
}

impl Balance for LoadBalance {
    fn residual(&self, point: &Point) -> Result<f64, CalcError> {
        Ok(point.sommerfeld_number.ln() - self.s_target.ln())
    }

    fn out_of_reach(&self, fa: f64, fb: f64) -> CalcError {
        let s_target = self.s_target;
        let (s_lo, s_hi) = (s_target * fa.exp(), s_target * fb.exp());
        let message = if s_target > s_lo {
            format!("the Sommerfeld number {s_target:.4e} is above {s_lo:.4e}, the value at ε = {MIN_ECCENTRICITY}: the load is too light for a hydrodynamic equilibrium this model resolves")
        } else {
            format!("the Sommerfeld number {s_target:.4e} is below {s_hi:.4e}, the value at ε = {MAX_ECCENTRICITY}: the load is too high for this bearing (minimum film below 0.1 % of the clearance)")
        };
        CalcError::impossible("/load_n", message)
    }
}

/// The eccentricity ratio at which the bearing carries Sommerfeld number `s_target`, and the
/// film solves the search took ([`balance`] over the whole bracket).
pub fn equilibrium(
    s_target: f64,
    l_over_d: f64,
    method: Method,
    physics: FilmModel,
    budget: &Budget,
) -> Result<(Point, u32), CalcError> {
    let load = LoadBalance { s_target };
    let (point, residual, n) = balance(&load, MIN_ECCENTRICITY, l_over_d, method, physics, budget)?;
    // A root at the edge where a misaligned journal starts to touch carries less than asked.
    if physics.misalignment.is_some() && residual.abs() > 1e-5 {
        return Err(CalcError::impossible(
            "/load_n",
            "the load exceeds what the bearing carries before the journal touches it",
        ));
    }
    Ok((point, n))
}

/// The operating point in [`from_eccentricity`, MAX_ECCENTRICITY] where `target` balances, its
/// residual there, and the film solves the search took.
///
/// The search runs in u = ln(ε/(1 − ε)) — ε crowds towards 1. A closed form is searched by
/// Brent over the bracket. A numerical method starts where the short bearing balances (with its
/// slope), takes safeguarded secant steps on the mesh with half the cells (an eighth of the
/// work) to 10⁻³, then on its own mesh to [`FINE_TOLERANCE`]: the two meshes' residuals differ
/// by a nearly constant amount, so the fine root is a step or three away. Brent over the
/// bracket is the fallback where the steps do not settle.
pub fn balance(
    target: &dyn Balance,
    from_eccentricity: f64,
    l_over_d: f64,
    method: Method,
    physics: FilmModel,
    budget: &Budget,
) -> Result<(Point, f64, u32), CalcError> {
    let bracket = (to_u(from_eccentricity), to_u(MAX_ECCENTRICITY));
    let mut evaluations = 0u32;
    let coarse = match method {
        Method::Numerical { mesh, .. } if mesh.circumferential >= 32 => Some(method.coarser()),
        _ => None,
    };
    let mut searcher = Searcher {
        target,
        l_over_d,
        physics,
        fields: Fields::default(),
        evaluations: &mut evaluations,
    };
    // A numerical search starts where the short-bearing closed form balances (microseconds,
    // and within a fraction of a unit of u), with the closed form's slope for its first step.
    let start = match method {
        Method::Numerical { .. } => searcher.closed_form_start(bracket),
        Method::ClosedForm(_) => None,
    };
    let search =
        |searcher: &mut Searcher, m: Method, tolerance: f64, start: Option<Start>| match start {
            Some(start) => searcher.polish(m, start, bracket, tolerance, budget),
            None => searcher
                .bracketed(m, bracket, tolerance, budget)
                .map(|u| Start { u, slope: None }),
        };
    let u = match coarse {
        // Near the ends of the bracket the two meshes may disagree on whether a root exists:
        // the fine mesh decides.
        // The coarse root need only be near: the meshes' roots differ by a few hundredths.
        Some(coarse) => match search(&mut searcher, coarse, 1e-3, start) {
            Ok(found) => search(&mut searcher, method, FINE_TOLERANCE, Some(found))?.u,
            Err(CalcError::Impossible { .. }) => {
                searcher.bracketed(method, bracket, FINE_TOLERANCE, budget)?
            }
            Err(e) => return Err(e),
        },
        None => search(&mut searcher, method, FINE_TOLERANCE, start)?.u,
    };
    let point = at_eccentricity_from(
        to_eps(u)?,
        l_over_d,
        method,
        physics,
        &mut searcher.fields,
        budget,
    )?;
    let residual = target.residual(&point)?;
    Ok((point, residual, evaluations))
}

/// ε(u) = 1/(1 + e^−u), inside (0, 1) for every u of the search's bracket.
fn to_eps(u: f64) -> Result<EccentricityRatio, CalcError> {
    EccentricityRatio::new(1.0 / (1.0 + (-u).exp()))
        .ok_or_else(|| CalcError::Internal(format!("equilibrium: no ε at u = {u}")))
}

fn to_u(eps: f64) -> f64 {
    (eps / (1.0 - eps)).ln()
}

/// ε moved by `du` along the searches' variable u = ln(ε/(1 − ε)).
pub fn shifted_eccentricity(eps: f64, du: f64) -> f64 {
    1.0 / (1.0 + (-(to_u(eps) + du)).exp())
}

/// A placed film's attitude at ε guessed from its attitude φ0 at ε0: φ0 moved by the aligned
/// short bearing's change of attitude between the two (the line of centres swings towards the
/// load as ε grows, for arcs and tilts much as for the aligned journal).
pub fn shifted_attitude(phi0: f64, eps0: f64, eps: f64, l_over_d: f64) -> f64 {
    let short = |e: f64| match EccentricityRatio::new(e) {
        Some(e) => closed(e, l_over_d, Approximation::Short, FilmModel::REYNOLDS).attitude_angle,
        None => f64::NAN,
    };
    let moved = phi0 + short(eps) - short(eps0);
    if moved.is_finite() {
        moved
    } else {
        phi0
    }
}

/// The balance's residual at ε(u) and the roots of it.
struct Searcher<'a> {
    target: &'a dyn Balance,
    l_over_d: f64,
    physics: FilmModel,
    /// Each probe starts from the last field on its mesh: successive ε are close once the
    /// search homes in.
    fields: Fields,
    evaluations: &'a mut u32,
}

impl Searcher<'_> {
    fn residual(&mut self, method: Method, u: f64, budget: &Budget) -> Result<f64, CalcError> {
        *self.evaluations += 1;
        let eps = to_eps(u)?;
        let point = match method {
            Method::ClosedForm(approx) => closed(eps, self.l_over_d, approx, self.physics),
            // A probe needs the extrapolated value, not its error estimate: the search's answer
            // is solved again with it.
            Method::Numerical {
                richardson: true, ..
            } => at_eccentricity_from(
                eps,
                self.l_over_d,
                method.without_estimate(),
                self.physics,
                &mut self.fields,
                budget,
            )?,
            Method::Numerical { mesh, stop, .. } => {
                let start = self.fields.take(mesh);
                match positioned_film(eps, self.l_over_d, self.physics, mesh, stop, start, budget) {
                    Ok((_, f, p)) => {
                        self.fields.keep(
                            mesh,
                            p,
                            placed(&self.physics).then(|| f.attitude_angle()),
                        );
                        from_film(eps, &f, self.physics)
                    }
                    // A misaligned journal touching at an end carries any load: S → 0, the
                    // far side of every balance.
                    Err(CalcError::Impossible { pointer, .. }) if pointer == "/misalignment" => {
                        return Ok(-50.0)
                    }
                    // The supply outweighs the film: it carries no load here, S → ∞.
                    Err(CalcError::Impossible { pointer, .. }) if pointer == SUPPLY_DOMINATES => {
                        return Ok(50.0)
                    }
                    Err(e) => return Err(e),
                }
            }
        };
        self.target.residual(&point)
    }

    /// Brent over the bracket; no sign change means the load is out of reach: a 422 naming it.
    fn bracketed(
        &mut self,
        method: Method,
        (lo, hi): (f64, f64),
        x_tolerance: f64,
        budget: &Budget,
    ) -> Result<f64, CalcError> {
        let root = brent_or_failure(|u| self.residual(method, u, budget), (lo, hi), x_tolerance)?;
        match root {
            Ok(r) => Ok(r.x),
            Err(RootError::NoSignChange { fa, fb, .. }) => Err(self.target.out_of_reach(fa, fb)),
            Err(e) => Err(CalcError::from_root("brent_equilibrium", e)),
        }
    }

    /// Where the short-bearing closed form balances the target in the bracket, and its slope
    /// there; None when it balances nowhere in it.
    fn closed_form_start(&self, (lo, hi): (f64, f64)) -> Option<Start> {
        let residual = |u: f64| -> f64 {
            let Ok(eps) = to_eps(u) else { return f64::NAN };
            let point = closed(eps, self.l_over_d, Approximation::Short, self.physics);
            self.target.residual(&point).unwrap_or(f64::NAN)
        };
        let root = brent(
            residual,
            lo,
            hi,
            roots::Stopping {
                x_tolerance: 1e-4,
                max_iterations: 100,
            },
        )
        .ok()?;
        let h = 1e-3;
        let slope = (residual(root.x + h) - residual(root.x - h)) / (2.0 * h);
        Some(Start {
            u: root.x,
            slope: (slope.is_finite() && slope < 0.0).then_some(slope),
        })
    }

    /// Secant steps on `method` from `start` (its slope, when known, for the first step), kept
    /// inside the bracket, until a step (taken or next) is shorter than `tolerance`; Brent over
    /// the whole bracket to `tolerance` if they do not settle in 12 steps. The root and the last
    /// slope.
    fn polish(
        &mut self,
        method: Method,
        start: Start,
        bracket: (f64, f64),
        tolerance: f64,
        budget: &Budget,
    ) -> Result<Start, CalcError> {
        if placed(&self.physics) {
            if let Some(found) = self.placed_polish(method, start, bracket, tolerance, budget)? {
                return Ok(found);
            }
        }
        let u0 = start.u;
        let (mut ua, mut fa) = (u0, self.residual(method, u0, budget)?);
        if fa.abs() < 1e-10 {
            return Ok(start);
        }
        // The residual falls with u at roughly the slope of the coarser model; without one, a
        // small first step finds it.
        let first = match start.slope {
            Some(slope) => (-fa / slope).clamp(-2.0, 2.0),
            None => {
                if fa > 0.0 {
                    1e-3
                } else {
                    -1e-3
                }
            }
        };
        let mut ub = (u0 + first).clamp(bracket.0, bracket.1);
        let mut fb = self.residual(method, ub, budget)?;
        let mut slope = f64::NAN;
        // One iteration: one secant step and its film solve. A slope that is not a falling
        // one stalls the steps; the root is then judged below.
        let mut failure = None;
        let run = Driver::new(
            "secant_equilibrium",
            IterationUnit::RootSearchSteps,
            12,
            budget,
        )
        .run(|_| {
            if fb.abs() < 1e-10 {
                return Verdict::Converged(ub, fb.abs());
            }
            slope = (fb - fa) / (ub - ua);
            if !(slope.is_finite() && slope < 0.0) {
                return Verdict::Stalled(fb.abs());
            }
            // The secant converges superlinearly: a next step shorter than the tolerance
            // leaves the root where it is.
            if (fb / slope).abs() < tolerance {
                return Verdict::Converged(ub, (fb / slope).abs());
            }
            let next = (ub - fb / slope).clamp(bracket.0, bracket.1);
            (ua, fa) = (ub, fb);
            ub = next;
            fb = match self.residual(method, ub, budget) {
                Ok(r) => r,
                Err(e) => {
                    failure = Some(e);
                    return Verdict::Diverged(f64::NAN);
                }
            };
            if (ub - ua).abs() < tolerance {
                return Verdict::Converged(ub, (ub - ua).abs());
            }
            Verdict::Continue(fb.abs())
        });
        if let Some(e) = failure {
            return Err(e);
        }
        let found = |u: f64| Start {
            u,
            slope: (slope.is_finite() && slope < 0.0).then_some(slope),
        };
        match run {
            Ok(root) => return Ok(found(root.value)),
            Err(stopped) if stopped.reason() == StopReason::Deadline => return Err(stopped.into()),
            Err(_) => {}
        }
        // The solver's own tolerance bounds how small the residual gets: accept a root good
        // to 1e-7 in the residual (the load to 1e-7), else search the whole bracket on this mesh.
        if fb.abs() < 1e-7 {
            return Ok(found(ub));
        }
        self.bracketed(method, bracket, tolerance, budget)
            .map(|u| Start { u, slope: None })
    }
}

impl Searcher<'_> {
    /// A placed film's equilibrium as one root in (u, φ) of the balance's residual and the
    /// attitude mismatch, each evaluation one film solve, instead of an attitude search inside
    /// every step in u: Broyden's method ([`roots::broyden2`]) from `start`, at the attitude the
    /// last film settled at (from rest, the attitude search at `start` gives it, from the
    /// aligned short bearing's φ). Its first Jacobian is the balance's slope in u (the closed
    /// form's, else the secant's first) and −1 in φ (the force turns with the line of centres);
    /// the film solves update it. Steps are limited as the searches' (2 in u, 0.3 rad) and the
    /// attitude kept in [0, 135°]; a touching trial is infeasible. Converged when the next step
    /// is below `tolerance` in u and in φ (the last film evaluated is the root). None where it
    /// does not settle, at a refusal, or for a method that extrapolates every evaluation: the
    /// nested search then runs as before.
    fn placed_polish(
        &mut self,
        method: Method,
        start: Start,
        bracket: (f64, f64),
        tolerance: f64,
        budget: &Budget,
    ) -> Result<Option<Start>, CalcError> {
        let Method::Numerical {
            mesh,
            stop,
            richardson: false,
            ..
        } = method
        else {
            return Ok(None);
        };
        let (l_over_d, physics) = (self.l_over_d, self.physics);
        // From rest, the aligned short bearing's attitude.
        let phi_start = match self.fields.attitude {
            Some(phi) => phi,
            None => {
                let eps = to_eps(start.u)?;
                closed(eps, l_over_d, Approximation::Short, FilmModel::REYNOLDS).attitude_angle
            }
        };
        let mut evaluate = |[u, phi]: [f64; 2]| -> Result<Option<[f64; 2]>, CalcError> {
            let eps = to_eps(u)?;
            let film = placed_at(
                Film {
                    physics,
                    ..Film::steady(eps.get(), l_over_d)
                },
                phi,
            );
            if film.min_thickness() <= TOUCHING {
                return Ok(None);
            }
            *self.evaluations += 1;
            let (f, p) = film::solve(film, mesh, stop, self.fields.take(mesh).field, budget)?;
            self.fields.keep(mesh, p, Some(phi));
            let residual = match self.target.residual(&from_film(eps, &f, physics)) {
                Ok(r) => r,
                Err(CalcError::Impossible { .. }) => return Ok(None),
                Err(e) => return Err(e),
            };
            Ok(Some([residual, attitude_mismatch(&f, phi)]))
        };
        let x0 = [start.u, phi_start];
        let Some(f0) = evaluate(x0)? else {
            return Ok(None);
        };
        let slope = start.slope.unwrap_or(-1.0);
        let steps = roots::Steps {
            max_step: [2.0, ATTITUDE_STEP],
            bounds: [bracket, (0.0, 0.75 * PI)],
            tolerance: [tolerance, tolerance],
            max_evaluations: 16,
        };
        let found = roots::broyden2(evaluate, x0, f0, [[slope, 0.0], [0.0, -1.0]], steps)?;
        Ok(found.map(|root| Start {
            u: root.x[0],
            slope: Some(root.jacobian[0][0]).filter(|s| s.is_finite() && *s < 0.0),
        }))
    }
}

/// Where a search starts: u, and the residual's slope there when known.
#[derive(Debug, Clone, Copy)]
struct Start {
    u: f64,
    slope: Option<f64>,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_clear_interval_is_the_widest_run_with_its_ends_refined() {
        let end = 0.75 * PI;
        assert_eq!(clear_interval(|_| true, end), Some((0.0, end)));
        assert_eq!(clear_interval(|_| false, end), None);
        // Clear on (0.3, 1.1) and (1.5, 1.6): the first, its ends to 1e-9.
        let (lo, hi) = clear_interval(|x| (0.3 < x && x < 1.1) || (1.5 < x && x < 1.6), end)
            .expect("an interval");
        assert!(
            (lo - 0.3).abs() < 2e-9 && (hi - 1.1).abs() < 2e-9,
            "{lo} {hi}"
        );
        // Clear from the start up to 0.5.
        let (lo, hi) = clear_interval(|x| x < 0.5, end).expect("an interval");
        assert!(lo == 0.0 && (hi - 0.5).abs() < 2e-9, "{hi}");
    }

    /// The two-stage search: a coarse Brent and a few fine secant steps; the load is carried to
    /// 1e-6 and the whole search costs under 20 film solves.
    #[test]
    fn equilibrium_is_cheap_and_exact() {
        let m = Method::numerical(Level::Standard, None, None);
        for s in [0.0447, 0.5, 0.005, 20.0] {
            let (p, n) = equilibrium(s, 1.0, m, FilmModel::REYNOLDS, &Budget::unlimited()).unwrap();
            assert!(
                (p.sommerfeld_number / s - 1.0).abs() < 1e-6,
                "S {s}: {}",
                p.sommerfeld_number
            );
            assert!(n < 20, "S {s}: {n} film solves");
        }
    }

    /// A placed film's equilibrium (a misaligned journal, a 120° arc, both) is one search in
    /// (u, φ): the load carried to 1e-6, in 17–34 film solves at S 0.05–1 (printed by
    /// `--nocapture`); the nested searches, an attitude search inside every step in u, took
    /// 32–69.
    #[test]
    fn a_placed_films_equilibrium_is_one_search() {
        use crate::calc::journal::film::Misalignment;
        let m = Method::numerical(Level::Standard, None, None);
        let tilt = Some(Misalignment {
            tilt: 0.5,
            direction: 0.0,
            from_line_of_centres: false,
        });
        let arc = Some(120f64.to_radians());
        for (name, physics, most) in [
            (
                "misaligned",
                FilmModel {
                    misalignment: tilt,
                    ..FilmModel::REYNOLDS
                },
                25,
            ),
            (
                "120° arc",
                FilmModel {
                    arc,
                    ..FilmModel::REYNOLDS
                },
                34,
            ),
            (
                "both",
                FilmModel {
                    arc,
                    misalignment: tilt,
                    ..FilmModel::REYNOLDS
                },
                36,
            ),
        ] {
            for s in [0.05, 0.2, 1.0] {
                let budget = Budget::unlimited();
                let (p, _) = equilibrium(s, 1.0, m, physics, &budget).unwrap();
                let solves = budget.field_solves();
                println!("{name} S {s}: {solves} film solves");
                assert!(
                    (p.sommerfeld_number / s - 1.0).abs() < 1e-6,
                    "{name} S {s}: {}",
                    p.sommerfeld_number
                );
                assert!(solves <= most, "{name} S {s}: {solves} film solves");
            }
        }
    }

    /// The error estimates bound the error: each level and explicit meshes coarse and fine,
    /// against a Richardson-extrapolated 384 × 48 reference (whose own estimate is allowed
    /// for), over ε 0.1–0.99 and L/D 0.25–2.
    #[test]
    fn error_estimates_bound_the_error() {
        let budget = Budget::unlimited();
        let mesh = |circumferential, axial_half| Mesh {
            circumferential,
            axial_half,
        };
        let reference = Method::numerical(Level::Standard, Some(mesh(384, 48)), None);
        // The levels, and explicit meshes: coarse ones far from the asymptotic range (the
        // issue's [24, 6]; [64, 8] and [60, 20] under-reported 3.6× and 2.2× with the levels'
        // three-mesh estimate), extrapolated ones ([96, 16], [128, 16]), and one beyond `high`.
        let methods = [
            Method::numerical(Level::Fast, None, None),
            Method::numerical(Level::Standard, None, None),
            Method::numerical(Level::High, None, None),
            Method::numerical(Level::Standard, Some(mesh(24, 6)), None),
            Method::numerical(Level::Standard, Some(mesh(64, 8)), None),
            Method::numerical(Level::Standard, Some(mesh(60, 20)), None),
            Method::numerical(Level::Standard, Some(mesh(96, 16)), None),
            Method::numerical(Level::Standard, Some(mesh(128, 16)), None),
            Method::numerical(Level::Standard, Some(mesh(256, 32)), None),
        ];
        for ld in [0.25, 0.5, 1.0, 2.0] {
            for eps in [0.1, 0.3, 0.6, 0.8, 0.9, 0.95, 0.99] {
                let e = EccentricityRatio::new(eps).unwrap();
                let at = |m| at_eccentricity(e, ld, m, FilmModel::REYNOLDS, &budget).unwrap();
                let truth = at(reference);
                let s_ref = truth.sommerfeld_number;
                let slack = truth.error_estimate.unwrap();
                for m in methods {
                    let p = at(m);
                    let error = (p.sommerfeld_number / s_ref - 1.0).abs();
                    let estimate = p.error_estimate.unwrap();
                    assert!(
                        error <= estimate + slack,
                        "L/D {ld} ε {eps} {:?}: error {error:.3e} > estimate {estimate:.3e} (+ {slack:.1e})",
                        m.mesh()
                    );
                }
            }
        }
    }
}
