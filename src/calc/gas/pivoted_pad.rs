//! A crowned sector pad ([`super::sector_pad`]) on a point pivot: the pitch and roll at which the
//! film's pressure has no moment about the pivot, and the clearance at which the pad carries its
//! load (Khonsari & Booser §11.4 after Shapiro & Colsher 1968).
//!
//! **Equilibrium.** For a clearance: the pitch from rest by a bracketed secant on the pitch
//! moment with the roll at 0, then both moments to zero by Broyden's method from a
//! finite-difference Jacobian, the steps halved where they would close the film. For a load:
//! the clearance by a bracketed secant on ln(C_L/C_L,target) in ln C (C_L falls as C grows,
//! toward the Λ → ∞ limit P H = const as C → 0, which bounds what the pad can carry), each
//! trial balanced from the last one's tilt and Jacobian. Every film is solved by Newton from
//! the last one's field.

use std::cell::RefCell;

use super::method::{Mesh, Method};
use super::sector_pad::{grid, performance, PadFilm, PadPerformance, Sector, Tilt};
use crate::calc::{Budget, CalcError};
use crate::fidelity::SolverReport;
use crate::numerics::reynolds_gas::{self, FarEdge, GasGrid, GasProblem, GasStopping, Metric};
use crate::numerics::richardson::{extrapolate, fine_error};
use crate::numerics::roots::{secant_fallible, Stopping};

/// A pad solved at one tilt.
#[derive(Debug, Clone)]
pub struct PadSolve {
    pub film: PadFilm,
    pub tilt: Tilt,
    pub grid: GasGrid,
    pub p: Vec<f64>,
    pub performance: PadPerformance,
    /// Its Newton run's report.
    pub report: SolverReport,
}

/// ∂(pitch moment, roll moment)/∂(pitch, roll), row-major.
type Jacobian = [[f64; 2]; 2];

/// The thinnest film H_min the pitch search from rest may go to (the grids are graded for the
/// boundary layers, not for a pad about to touch).
const MARCH_FILM_FLOOR: f64 = 0.02;
/// Where the pitch search from rest starts, as a share of the way to touching: an aligned flat
/// pad carries nothing, and its zero moment is no equilibrium.
const START_SHARE: f64 = 0.05;
/// The balance's tolerance on the pressure's centre's distance from the pivot, r_o.
const BALANCE_TOLERANCE: f64 = 1e-10;
/// Broyden steps per balance before the Jacobian is measured afresh (once).
const BROYDEN_STEPS: u32 = 40;

/// The searches' state: the last solved field (every solve starts from it, interpolated onto
/// its grid), the last balance's Jacobian, and the Newton steps spent.
struct Solver<'a> {
    mesh: Mesh,
    half: bool,
    budget: &'a Budget,
    last: RefCell<Option<PadSolve>>,
    jacobian: RefCell<Option<Jacobian>>,
    newton_steps: RefCell<u32>,
}

impl<'a> Solver<'a> {
    /// Solve the film at tilt `t`; None when the film would touch the runner.
    fn solve(&self, film: &PadFilm, t: Tilt) -> Result<Option<PadSolve>, CalcError> {
        // A NaN film (no number anywhere) counts as touching.
        let thinnest = film.thinnest(t).0;
        if thinnest.is_nan() || thinnest <= 0.0 {
            return Ok(None);
        }
        let grid = grid(film, self.mesh, self.half);
        let start = self
            .last
            .borrow()
            .as_ref()
            .map(|s| reynolds_gas::prolong(&s.grid, &s.p, &grid));
        let problem = GasProblem {
            far_edge: FarEdge::Held,
            metric: Metric::Polar,
            ..GasProblem::new(&grid, film.bearing_number, film.knudsen_number, |x, y| {
                film.height(t, x, y)
            })
        };
        let solved = reynolds_gas::solve(
            &grid,
            &problem,
            start.as_deref(),
            GasStopping::default(),
            self.budget,
        )?;
        *self.newton_steps.borrow_mut() += solved.report.iterations;
        let performance = performance(film, t, &grid, &solved.p);
        let done = PadSolve {
            film: *film,
            tilt: t,
            grid,
            p: solved.p,
            performance,
            report: solved.report,
        };
        *self.last.borrow_mut() = Some(done.clone());
        Ok(Some(done))
    }

    /// The pitch that zeroes the pitch moment with the roll held at 0, from rest.
    fn pitch_from_rest(&self, film: &PadFilm) -> Result<f64, CalcError> {
        let (back, front) = film.pitches_to_film(MARCH_FILM_FLOOR);
        // NaN where the film would touch: the march steps past it, the secant refuses it.
        let moment = |m: f64| -> Result<f64, CalcError> {
            let tilt = Tilt {
                pitch: m,
                roll: 0.0,
            };
            Ok(self
                .solve(film, tilt)?
                .map_or(f64::NAN, |s| s.performance.pitch_moment))
        };
        let m0 = START_SHARE * front;
        let g0 = moment(m0)?;
        // March toward touching on the side the moment asks (a positive moment, the pressure
        // behind the pivot, asks for less pitch) until it changes sign.
        let end = if g0 > 0.0 { back } else { front };
        let (mut a, mut ga) = (m0, g0);
        let mut bracket = None;
        for share in [0.3, 0.6, 0.85, 0.95, 1.0] {
            let m = m0 + share * (end - m0);
            let g = moment(m)?;
            if g * g0 <= 0.0 {
                bracket = Some(((a, ga), (m, g)));
                break;
            }
            (a, ga) = (m, g);
        }
        let Some((lo, hi)) = bracket else {
            return Err(no_equilibrium(film, g0));
        };
        let root = secant_fallible(
            moment,
            lo,
            hi,
            Stopping {
                x_tolerance: 1e-6 * (front - back),
                max_iterations: 60,
            },
        )?;
        root.map(|r| r.x)
            .map_err(|e| CalcError::from_root("pivoted_pad_pitch", e))
    }

    /// The moments at tilt `t` over the load (the pressure centre's offsets from the pivot),
    /// None where the film would touch or pulls the pad.
    fn offsets(&self, film: &PadFilm, t: Tilt) -> Result<Option<[f64; 2]>, CalcError> {
        Ok(self.solve(film, t)?.and_then(|s| {
            let p = s.performance;
            (p.load > 0.0).then(|| [p.pitch_moment / p.load, p.roll_moment / p.load])
        }))
    }

    /// The finite-difference Jacobian of [`Solver::offsets`] at `t` (whose offsets are `f`).
    fn measure(&self, film: &PadFilm, t: Tilt, f: [f64; 2]) -> Result<Jacobian, CalcError> {
        let h = 1e-4 * (1.0 + t.pitch.abs());
        let mut j = [[0.0; 2]; 2];
        for (col, step) in [
            (
                0,
                Tilt {
                    pitch: h,
                    roll: 0.0,
                },
            ),
            (
                1,
                Tilt {
                    pitch: 0.0,
                    roll: h,
                },
            ),
        ] {
            let probe = Tilt {
                pitch: t.pitch + step.pitch,
                roll: t.roll + step.roll,
            };
            let g = self.offsets(film, probe)?.ok_or_else(|| touching(film))?;
            for row in 0..2 {
                j[row][col] = (g[row] - f[row]) / h;
            }
        }
        Ok(j)
    }

    /// Pitch and roll with no moment about the pivot, by Broyden's method from `guess` (from
    /// rest when None) and the last balance's Jacobian when there is one.
    fn balance(&self, film: &PadFilm, guess: Option<Tilt>) -> Result<PadSolve, CalcError> {
        let mut t = match guess {
            Some(t) => t,
            None => Tilt {
                pitch: self.pitch_from_rest(film)?,
                roll: 0.0,
            },
        };
        let mut f = self.offsets(film, t)?.ok_or_else(|| unusable(film, t))?;
        let carried = *self.jacobian.borrow();
        let mut j = match carried {
            Some(j) => j,
            None => self.measure(film, t, f)?,
        };
        // Whether `j` was measured at `t` (not carried or updated).
        let mut fresh = carried.is_none();
        let size = |f: [f64; 2]| f[0].abs().max(f[1].abs());
        let mut steps = 0;
        while size(f) > BALANCE_TOLERANCE {
            steps += 1;
            if steps > BROYDEN_STEPS {
                return Err(CalcError::NotConverged {
                    method: "pivoted_pad_broyden",
                    iterations: steps,
                    residual: size(f),
                });
            }
            let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
            if !(det.is_finite() && det != 0.0) {
                if fresh {
                    return Err(unusable(film, t));
                }
                j = self.measure(film, t, f)?;
                fresh = true;
                continue;
            }
            let dx = [
                -(j[1][1] * f[0] - j[0][1] * f[1]) / det,
                -(-j[1][0] * f[0] + j[0][0] * f[1]) / det,
            ];
            // Backtrack until the offsets shrink (a step that would close the film, or leave
            // the film pulling, counts as no step).
            let mut scale = 1.0;
            let accepted = loop {
                let trial = Tilt {
                    pitch: t.pitch + scale * dx[0],
                    roll: t.roll + scale * dx[1],
                };
                match self.offsets(film, trial)? {
                    Some(g) if g.iter().all(|v| v.is_finite()) && size(g) < size(f) => {
                        break Some((trial, g))
                    }
                    _ if scale > 1.0 / 64.0 => scale *= 0.5,
                    _ => break None,
                }
            };
            match accepted {
                Some((trial, g)) => {
                    // Broyden's update of the Jacobian along the step.
                    let s = [trial.pitch - t.pitch, trial.roll - t.roll];
                    let y = [g[0] - f[0], g[1] - f[1]];
                    let ss = s[0] * s[0] + s[1] * s[1];
                    for row in 0..2 {
                        let r = y[row] - (j[row][0] * s[0] + j[row][1] * s[1]);
                        j[row][0] += r * s[0] / ss;
                        j[row][1] += r * s[1] / ss;
                    }
                    (t, f, fresh) = (trial, g, false);
                }
                None if !fresh => {
                    j = self.measure(film, t, f)?;
                    fresh = true;
                }
                None => {
                    return Err(CalcError::impossible(
                        "/pivot_angle_fraction",
                        format!(
                            "the pad has no equilibrium on this pivot: no pitch and roll centre the film's pressure on it (it stays {:.2e} r_o along and {:.2e} r_o across the pad from it): move the pivot, or crown the pad",
                            f[0], f[1]
                        ),
                    ))
                }
            }
        }
        *self.jacobian.borrow_mut() = Some(j);
        let done = self
            .last
            .borrow()
            .clone()
            .filter(|s| s.tilt == t)
            .map_or_else(|| self.solve(film, t).map(Option::unwrap), Ok)?;
        if done.performance.load <= 0.0 {
            return Err(CalcError::impossible(
                "/pivot_angle_fraction",
                format!(
                    "on this pivot the pad balances only with the film pulling it toward the runner (W/(p_a r_o²) = {:.3e}): move the pivot toward the trailing edge",
                    done.performance.load
                ),
            ));
        }
        Ok(done)
    }
}

/// The 422 of a pivot without an equilibrium (`g0` the pitch moment near rest).
fn no_equilibrium(film: &PadFilm, g0: f64) -> CalcError {
    let s = &film.sector;
    CalcError::impossible(
        "/pivot_angle_fraction",
        format!(
            "the pad has no equilibrium on a pivot at {:.3} of its angle: the film's pressure stays {} the pivot at every pitch that keeps the film clear of the runner{}",
            s.pivot_angle / s.angle,
            if g0 > 0.0 { "behind" } else { "ahead of" },
            if film.crown == 0.0 { " (a flat gas pad's centre of pressure moves toward 2/3 of its breadth as the bearing number grows: a crown lets a pivot nearer the middle carry load)" } else { "" }
        ),
    )
}

/// The 422 of a tilt the balance needs but cannot use: the film closes there, or pulls the pad
/// toward the runner (no load to balance).
fn unusable(film: &PadFilm, t: Tilt) -> CalcError {
    if film.thinnest(t).0 <= 0.0 {
        touching(film)
    } else {
        CalcError::impossible(
            "/pivot_angle_fraction",
            "the pad has no equilibrium on this pivot: where its pressure is centred on the pivot the film carries no load (move the pivot toward the trailing edge, or crown the pad)",
        )
    }
}

/// The 422 of a balance that would close the film.
fn touching(film: &PadFilm) -> CalcError {
    CalcError::impossible(
        "/crown_m",
        format!(
            "the pad touches the runner before it balances on its pivot (crown δ/C = {:.3}, Λ = {:.3e})",
            film.crown, film.bearing_number
        ),
    )
}

/// What sets the film at a clearance: the dimensional scales of the bearing number, crown and
/// slip.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PadScales {
    pub sector: Sector,
    /// 6μω r_o²/p_a, m²: Λ C².
    pub bearing_number_m2: f64,
    /// Crown δ, m.
    pub crown_m: f64,
    /// λ_a, m, when slip applies (Kn = λ_a/C).
    pub mean_free_path_m: Option<f64>,
}

impl PadScales {
    /// The film at clearance C.
    pub fn film(&self, clearance_m: f64) -> PadFilm {
        PadFilm {
            sector: self.sector,
            bearing_number: self.bearing_number_m2 / (clearance_m * clearance_m),
            crown: self.crown_m / clearance_m,
            knudsen_number: self.mean_free_path_m.map_or(0.0, |l| l / clearance_m),
        }
    }

    /// The clearance at bearing number Λ.
    pub fn clearance_at(&self, bearing_number: f64) -> f64 {
        (self.bearing_number_m2 / bearing_number).sqrt()
    }

    /// The load search's range of ln C: the clearances in [`CLEARANCE_RANGE_M`] whose bearing
    /// numbers lie in [`LOAD_SEARCH_BEARING_NUMBERS`]; None when there are none.
    pub fn load_search_range(&self) -> Option<(f64, f64)> {
        let lo = self
            .clearance_at(LOAD_SEARCH_BEARING_NUMBERS.0)
            .max(CLEARANCE_RANGE_M.0);
        let hi = self
            .clearance_at(LOAD_SEARCH_BEARING_NUMBERS.1)
            .min(CLEARANCE_RANGE_M.1);
        (lo.is_finite() && hi.is_finite() && lo > 0.0 && lo < hi).then(|| (lo.ln(), hi.ln()))
    }
}

/// The pad in equilibrium on one mesh.
#[derive(Debug, Clone)]
pub struct Balanced {
    pub clearance_m: f64,
    pub solve: PadSolve,
    jacobian: Option<Jacobian>,
    /// Newton steps of every film solve of the searches.
    pub newton_steps: u32,
}

/// The pad at clearance C in equilibrium on `mesh` (`half`: every other node of it), from a
/// nearby balanced pad's tilt, Jacobian and field.
fn balanced_at_clearance(
    scales: &PadScales,
    clearance_m: f64,
    (mesh, half): (Mesh, bool),
    near: Option<&Balanced>,
    budget: &Budget,
) -> Result<Balanced, CalcError> {
    let film = scales.film(clearance_m);
    // From the nearby pad's tilt and Jacobian, or from rest; either way from its field.
    let attempt = |warm: bool| {
        let solver = Solver {
            mesh,
            half,
            budget,
            last: RefCell::new(near.map(|b| b.solve.clone())),
            jacobian: RefCell::new(near.and_then(|b| b.jacobian).filter(|_| warm)),
            newton_steps: RefCell::new(0),
        };
        let solve = solver.balance(&film, near.map(|b| b.solve.tilt).filter(|_| warm))?;
        Ok(Balanced {
            clearance_m,
            solve,
            jacobian: solver.jacobian.into_inner(),
            newton_steps: solver.newton_steps.into_inner(),
        })
    };
    match attempt(near.is_some()) {
        // A nearby tilt can lie where this film closes, or lead Broyden astray: from rest again.
        Err(CalcError::Impossible { .. } | CalcError::NotConverged { .. }) if near.is_some() => {
            attempt(false)
        }
        done => done,
    }
}

/// The load search's range of bearing numbers: from the largest the solver takes down to 0.01
/// (where the pad carries a few thousandths of p_a r_o²).
pub const LOAD_SEARCH_BEARING_NUMBERS: (f64, f64) = (super::method::MAX_BEARING_NUMBER, 1e-2);
/// The clearances a pad may run at, m.
pub const CLEARANCE_RANGE_M: (f64, f64) = (1e-8, 1e-3);
/// The bearing number the load search starts from, without a nearby pad.
const LOAD_SEARCH_START: f64 = 100.0;

/// The pad in equilibrium under C_L = W/(p_a r_o²) on `mesh`, from a nearby balanced pad (or
/// from the clearance at which Λ = 100).
fn balanced_at_load(
    scales: &PadScales,
    target: f64,
    mesh: (Mesh, bool),
    near: Option<&Balanced>,
    budget: &Budget,
) -> Result<Balanced, CalcError> {
    let last: RefCell<Option<Balanced>> = RefCell::new(near.cloned());
    let steps = RefCell::new(0u32);
    // ln(C_L/C_L,target) at u = ln C: falls as u grows.
    let residual = |u: f64| -> Result<f64, CalcError> {
        let previous = last.borrow().clone();
        let b = balanced_at_clearance(scales, u.exp(), mesh, previous.as_ref(), budget)?;
        *steps.borrow_mut() += b.newton_steps;
        let w = b.solve.performance.load;
        *last.borrow_mut() = Some(b);
        Ok(w.ln() - target.ln())
    };
    let (u_min, u_max) = scales.load_search_range().ok_or_else(|| {
        CalcError::impossible(
            "/speed_rpm",
            "no clearance within the model's range gives a bearing number the film can be solved at",
        )
    })?;
    let start = near
        .map_or_else(
            || scales.clearance_at(LOAD_SEARCH_START).ln(),
            |b| b.clearance_m.ln(),
        )
        .clamp(u_min, u_max);
    // A pad without an equilibrium at the start may have one on a thicker film (a flat pad's
    // centre of pressure moves aft as Λ grows): from rest, start again at Λ = 1.
    let (u0, r0) = match residual(start) {
        Err(CalcError::Impossible { pointer, .. })
            if pointer == "/pivot_angle_fraction" && near.is_none() =>
        {
            let u0 = scales.clearance_at(1.0).ln().clamp(u_min, u_max);
            (u0, residual(u0)?)
        }
        first => (start, first?),
    };
    // Step ln C (by 2 % near a guess, by ln 2 from rest) toward the target until the residual
    // changes sign, doubling the step.
    let mut step = if near.is_some() {
        0.02
    } else {
        std::f64::consts::LN_2
    };
    let (mut a, mut ra) = (u0, r0);
    let bracket = loop {
        let u = (a + if ra > 0.0 { step } else { -step }).clamp(u_min, u_max);
        if u == a {
            break None;
        }
        let r = residual(u)?;
        if r * ra <= 0.0 {
            break Some(((a, ra), (u, r)));
        }
        (a, ra) = (u, r);
        step *= 2.0;
    };
    let Some((lo, hi)) = bracket else {
        let carried = (target.ln() + ra).exp();
        return Err(CalcError::impossible(
            "/load_n",
            if ra < 0.0 {
                format!(
                    "each pad carries at most W/(p_a r_o²) = {carried:.4} (at the clearance {:.3e} m, Λ = {:.3e}, the thinnest the search takes); the load asks {target:.4}: add pads or area",
                    a.exp(),
                    scales.film(a.exp()).bearing_number
                )
            } else {
                format!(
                    "the load W/(p_a r_o²) = {target:.3e} per pad is below what the pad carries at the clearance {:.3e} m, Λ = {:.3e} ({carried:.3e}): the film would be thicker than the model's range",
                    a.exp(),
                    scales.film(a.exp()).bearing_number
                )
            },
        ));
    };
    let root = secant_fallible(
        residual,
        lo,
        hi,
        Stopping {
            x_tolerance: 1e-9,
            max_iterations: 60,
        },
    )?
    .map_err(|e| CalcError::from_root("pivoted_pad_clearance", e))?;
    // The secant's last evaluation is its answer, unless the search ended on a bracket end it
    // had evaluated earlier: balance there again.
    let mut done = last.into_inner().expect("the search balanced pads");
    if done.clearance_m != root.x.exp() {
        done = balanced_at_clearance(scales, root.x.exp(), mesh, Some(&done), budget)?;
        *steps.borrow_mut() += done.newton_steps;
    }
    done.newton_steps = steps.into_inner();
    Ok(done)
}

/// What the request gives: the clearance C (m), or C_L = W/(p_a r_o²) per pad.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PadGiven {
    Clearance(f64),
    Load(f64),
}

/// The pad in equilibrium by a method: on its mesh, and with Richardson also on the half mesh
/// first (whose answer starts the fine search), extrapolated.
#[derive(Debug, Clone)]
pub struct PadEvaluated {
    /// C, m (extrapolated when the load is given).
    pub clearance_m: f64,
    /// The tilt (extrapolated).
    pub tilt: Tilt,
    /// The film at that clearance (Λ, κ, Kn).
    pub film: PadFilm,
    pub performance: PadPerformance,
    /// Relative error estimate: the larger of C_L's and h_min's (a third of the two meshes'
    /// difference), with Richardson.
    pub error_estimate: Option<f64>,
    /// The fine mesh's equilibrium.
    pub fine: Balanced,
    /// The half mesh's, with Richardson.
    pub coarse: Option<Balanced>,
    /// Newton steps over both meshes.
    pub newton_steps: u32,
}

impl PadEvaluated {
    /// h_min (m), and where it is (θ, R).
    pub fn thinnest_m(&self) -> (f64, f64, f64) {
        let (h, theta, r) = self.film.thinnest(self.tilt);
        (h * self.clearance_m, theta, r)
    }
}

/// The pad by `method`, from the balanced pads of a nearby evaluation when given (the same pad
/// with another film law: its searches start where that one's ended).
pub fn evaluate(
    scales: &PadScales,
    given: PadGiven,
    method: Method,
    warm: Option<&PadEvaluated>,
    budget: &Budget,
) -> Result<PadEvaluated, CalcError> {
    let on = |half: bool, near: Option<&Balanced>| match given {
        PadGiven::Clearance(c) => {
            balanced_at_clearance(scales, c, (method.mesh, half), near, budget)
        }
        PadGiven::Load(w) => balanced_at_load(scales, w, (method.mesh, half), near, budget),
    };
    let coarse = if method.richardson {
        Some(on(true, warm.and_then(|w| w.coarse.as_ref()))?)
    } else {
        None
    };
    let fine = on(false, coarse.as_ref().or(warm.map(|w| &w.fine)))?;
    let f = &fine.solve;
    let Some(coarse) = coarse else {
        return Ok(PadEvaluated {
            clearance_m: fine.clearance_m,
            tilt: f.tilt,
            film: f.film,
            performance: f.performance,
            error_estimate: None,
            newton_steps: fine.newton_steps,
            fine,
            coarse: None,
        });
    };
    let c = &coarse.solve;
    let x = |a: f64, b: f64| extrapolate(a, b);
    let clearance_m = x(coarse.clearance_m, fine.clearance_m);
    let tilt = Tilt {
        pitch: x(c.tilt.pitch, f.tilt.pitch),
        roll: x(c.tilt.roll, f.tilt.roll),
    };
    let film = scales.film(clearance_m);
    let (cp, fp) = (c.performance, f.performance);
    let performance = PadPerformance {
        load: x(cp.load, fp.load),
        pitch_moment: fp.pitch_moment,
        roll_moment: fp.roll_moment,
        friction_runner: x(cp.friction_runner, fp.friction_runner),
        friction_pad: x(cp.friction_pad, fp.friction_pad),
        max_pressure: fp.max_pressure,
    };
    let h_min = |b: &Balanced| b.solve.film.thinnest(b.solve.tilt).0 * b.clearance_m;
    let extrapolated_h_min = film.thinnest(tilt).0 * clearance_m;
    let error_estimate = Some(
        (fine_error(h_min(&coarse), h_min(&fine)) / extrapolated_h_min)
            .abs()
            .max((fine_error(cp.load, fp.load) / performance.load).abs()),
    );
    Ok(PadEvaluated {
        clearance_m,
        tilt,
        film,
        performance,
        error_estimate,
        newton_steps: fine.newton_steps + coarse.newton_steps,
        fine,
        coarse: Some(coarse),
    })
}

#[cfg(test)]
#[path = "pivoted_pad_tests.rs"]
mod tests;
