//! The piston ring's film over an engine cycle (Khonsari & Booser §9.7, Eqs. 9.44–9.59; spec
//! khonsari-booser-ch9-17 SQ-8), Newtonian and isothermal.
//!
//! The ring face is an off-centre parabola, h(x, t) = h_m(t) + δ₀ (x/a)² on x ∈ [−a, a]
//! (Eq. 9.44; x runs from the combustion side towards the crankcase, a the half-width, δ₀ the
//! crown). In the ring's frame the liner slides at U_l = −U_p (U_p the piston's speed towards
//! the crankcase), and the 1-D Reynolds equation with squeeze (Eq. 9.45, F₂ = h³/12μ,
//! F₁/F₀ = h/2) is
//!
//! ```text
//! d/dx(h³/(12μ) dP/dx) = (U_l/2) dh/dx + dh_m/dt,   P(−a) = P_top,  P(+a) = P_bot   (9.46)
//! ```
//!
//! discretised by finite volumes (h³ at the faces, the wedge integrated exactly over each cell,
//! so the discrete film conserves mass). On the divergent half behind the crown the film
//! ruptures: there P ≥ P_div, the pressure at the trailing edge (the text's P_div of Eq. 9.51,
//! the gas that fills the cavity), with the Reynolds condition at the rupture — the linear
//! complementarity problem, solved exactly by a primal–dual active set (each iterate two solves
//! of the symmetric tridiagonal system with one Cholesky factor).
//!
//! The ring moves only radially (Eq. 9.50): its film must carry the gas pressure behind it, the
//! ring's own tension pressure p_e and its elastic response to the deflection h_m as a
//! thin-walled ring, K = E t_r / r² (Pa per metre of deflection):
//! ∫P dx = 2a (P_top + p_e + K h_m). The text's Eq. 9.50 is this with p_e = 0. The film's
//! pressure is linear in dh_m/dt for a given active set, so P = P₀ + ḣ_m P₁ and the equilibrium
//! fixes ḣ_m: the text's bordered tridiagonal system (Eq. 9.53), solved by superposition. That
//! gives the ODE dh_m/dt = f(t, h_m) (Eq. 9.54), integrated over crank angle in ln(h_m/δ₀)
//! (positive films by construction) with the shared stiff integrator (Radau IIA,
//! `numerics::ode`), one stroke at a time (the film's trailing edge changes side at each dead
//! centre, where the rate is not smooth), and shot by fixed-point iteration on h_m(0) until the
//! cycle repeats (the text: "slightly more than one engine cycle").
//!
//! Friction on the ring, Eq. 9.55 (force per unit circumference, along x):
//! ∫(μU_l/h − (h/2) dP/dx) dx over the lubricated cells; power, Eq. 9.59:
//! ∫(μU_l²/h + h³/(12μ) (dP/dx)²) dx (the squeeze's share included). Where h_m is below the
//! composite roughness σ the friction is the boundary one, Eq. 9.56 with the dimensional
//! correction of the spec: F = μ_c π B W(t), W = ∫P dx (Eq. 9.57), against the piston's motion,
//! and E = F|U| (Eq. 9.58).

use std::f64::consts::PI;

use nalgebra::SVector;

use crate::fidelity::{IterationUnit, SolverReport, TimeIntegration};
use crate::numerics::banded::SymmetricBand;
use crate::numerics::driver::{Budget, Driver, Stopped, Verdict};
use crate::numerics::interpolate::periodic_cubic;
use crate::numerics::ode::{self, Failure, Flow, Method, RateError, Settings, Step};

/// Active-set iterations of one film solve before it gives up (a 1-D set settles in a few).
const MAX_ACTIVE_SET_ITERATIONS: u32 = 200;
/// Cycles of the shooting before it gives up.
const MAX_CYCLES: u32 = 40;
/// Attempted integrator steps per stroke.
const MAX_STEPS_PER_STROKE: u32 = 200_000;
/// Samples of the cycle per crank-angle degree (the path, the cycle means).
const SAMPLES_PER_DEGREE: f64 = 1.0;

/// The ring and its face.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ring {
    /// a: half the ring's axial width, m.
    pub half_width: f64,
    /// δ₀: crown height of the parabolic face, m.
    pub crown_height: f64,
    /// K = E t_r / r²: the ring's radial stiffness as a thin-walled ring, Pa per m of deflection.
    pub stiffness: f64,
    /// p_e: the ring's own tension pressure on the liner at zero deflection, Pa.
    pub tension_pressure: f64,
}

/// The slider-crank and the cylinder.
#[derive(Debug, Clone, PartialEq)]
pub struct Engine {
    /// Cylinder bore B, m.
    pub bore: f64,
    /// Crank radius r, m.
    pub crank_radius: f64,
    /// Connecting-rod length l, m (> r).
    pub rod_length: f64,
    /// Crank speed ω, rad/s.
    pub omega: f64,
    /// The cycle in crank angle, rad: 4π (four-stroke) or 2π (two-stroke).
    pub cycle: f64,
    /// Gas pressure above the ring (gauge, Pa) at ascending crank angles (rad) within the cycle;
    /// one point is a constant pressure.
    pub angles: Vec<f64>,
    pub pressures: Vec<f64>,
    /// P_bot / P_top: the pressure below the ring as a share of the one above (Jeng's 1/2).
    pub bottom_fraction: f64,
}

impl Engine {
    /// The piston's speed towards the crankcase, m/s, at crank angle θ from top dead centre of
    /// the power stroke: the slider-crank's U_p = ω r sin θ (1 + r cos θ / √(l² − r² sin² θ)).
    #[must_use]
    pub fn piston_speed(&self, theta: f64) -> f64 {
        let (r, l) = (self.crank_radius, self.rod_length);
        let (s, c) = theta.sin_cos();
        self.omega * r * s * (1.0 + r * c / (l * l - r * r * s * s).sqrt())
    }

    /// The gas pressure above the ring, Pa (the periodic cubic through the table).
    #[must_use]
    pub fn top_pressure(&self, theta: f64) -> f64 {
        periodic_cubic(&self.angles, &self.pressures, self.cycle, theta)
    }
}

/// The boundary-lubrication rule (Eq. 9.56) and where it applies.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Boundary {
    /// Composite roughness σ, m: below it the friction is the boundary one.
    pub roughness: f64,
    /// μ_c, the boundary friction coefficient.
    pub friction_coefficient: f64,
}

/// The numerical settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Numerics {
    /// Cells across the ring face.
    pub cells: usize,
    /// The integrator's relative tolerance (absolute on ln h_m: the same, relative on h_m).
    pub tolerance: f64,
    /// The cycle repeats when |ln h_m(end) − ln h_m(0)| is at most this.
    pub periodicity: f64,
}

/// Which edge of the ring the liner runs towards: the film's trailing edge.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Trailing {
    /// x = −a, the combustion side (the piston moving towards the crankcase).
    Top,
    /// x = +a, the crankcase side.
    Bottom,
}

/// The film across the ring face at one instant.
#[derive(Debug, Clone, PartialEq)]
pub struct Instant {
    /// dh_m/dt, m/s (positive while the film opens).
    pub squeeze_rate: f64,
    /// Nodal pressures from x = −a to x = +a, Pa.
    pub pressure: Vec<f64>,
    /// W = ∫P dx, N per m of circumference (Eq. 9.57).
    pub load: f64,
    /// Viscous force on the ring along x, N per m of circumference (Eq. 9.55).
    pub shear: f64,
    /// Viscous dissipation, W per m of circumference (Eq. 9.59).
    pub dissipation: f64,
}

/// The film solver for one ring face: the grid and the film's fixed parts.
#[derive(Debug, Clone)]
pub struct Film {
    ring: Ring,
    mu: f64,
    cells: usize,
    dx: f64,
    /// The crown's share δ₀ (x/a)² at the faces (face i between nodes i and i + 1).
    crown_faces: Vec<f64>,
}

impl Film {
    #[must_use]
    pub fn new(ring: Ring, mu: f64, cells: usize) -> Film {
        let a = ring.half_width;
        let dx = 2.0 * a / cells as f64;
        let crown = |x: f64| ring.crown_height * (x / a).powi(2);
        Film {
            ring,
            mu,
            cells,
            dx,
            crown_faces: (0..cells)
                .map(|i| crown(-a + (i as f64 + 0.5) * dx))
                .collect(),
        }
    }

    /// The ring's load on the film at film h_m under gas pressure P_top, N per m (Eq. 9.50).
    #[must_use]
    pub fn ring_load(&self, h_m: f64, p_top: f64) -> f64 {
        2.0 * self.ring.half_width
            * (p_top + self.ring.tension_pressure + self.ring.stiffness * h_m)
    }

    /// Solve the film at h_m with the liner at speed `liner_speed` (m/s, along x), edge
    /// pressures `p_top`, `p_bot`, cavitating behind the crown towards `trailing` (none: a full
    /// film), for the squeeze rate at which it carries `load` (N per m). `active` is the last
    /// cavitated set (a warm start; updated).
    #[allow(clippy::too_many_arguments)]
    pub fn solve(
        &self,
        h_m: f64,
        liner_speed: f64,
        p_top: f64,
        p_bot: f64,
        trailing: Option<Trailing>,
        load: f64,
        active: &mut Vec<bool>,
        budget: &Budget,
    ) -> Result<Instant, Stopped> {
        let n = self.cells;
        let dx = self.dx;
        let mu = self.mu;
        let faces: Vec<f64> = self.crown_faces.iter().map(|c| h_m + c).collect();
        // Face conductances h³/(12μ Δx).
        let k: Vec<f64> = faces.iter().map(|h| h.powi(3) / (12.0 * mu * dx)).collect();
        // Wedge source of node i (1 ≤ i < n): −(U_l/2)(h_e − h_w); squeeze source per unit ḣ: −Δx.
        let wedge = |i: usize| -0.5 * liner_speed * (self.crown_faces[i] - self.crown_faces[i - 1]);
        let mid = n / 2;
        let (cavity_pressure, zone): (f64, Box<dyn Fn(usize) -> bool>) = match trailing {
            Some(Trailing::Top) => (p_top, Box::new(move |i| i < mid)),
            Some(Trailing::Bottom) => (p_bot, Box::new(move |i| i > n - mid)),
            None => (0.0, Box::new(|_| false)),
        };
        if active.len() != n + 1 {
            *active = vec![false; n + 1];
        }
        // A warm start from the other stroke keeps nothing outside this stroke's zone.
        for (i, a) in active.iter_mut().enumerate() {
            *a = *a && zone(i);
        }
        let trapezoid = |p: &[f64]| dx * (0.5 * (p[0] + p[n]) + p[1..n].iter().sum::<f64>());
        let driver = Driver::new(
            "piston_ring_film_active_set",
            IterationUnit::Evaluations,
            MAX_ACTIVE_SET_ITERATIONS,
            budget,
        )
        .check_every(16);
        let solved = driver.run(|_| {
            let mut band = SymmetricBand::zeros(n - 1, 1);
            let mut p0 = vec![0.0; n + 1];
            let mut p1 = vec![0.0; n + 1];
            p0[0] = p_top;
            p0[n] = p_bot;
            for i in 1..n {
                let r = i - 1;
                if active[i] {
                    band.set(r, r, 1.0);
                    p0[i] = cavity_pressure;
                    continue;
                }
                band.set(r, r, k[i - 1] + k[i]);
                p0[i] = wedge(i);
                p1[i] = -dx;
                // Known neighbours (an edge or a cavitated node) move to the right-hand side.
                for (j, kf) in [(i - 1, k[i - 1]), (i + 1, k[i])] {
                    if j == 0 {
                        p0[i] += kf * p_top;
                    } else if j == n {
                        p0[i] += kf * p_bot;
                    } else if active[j] {
                        p0[i] += kf * cavity_pressure;
                    } else if j == i + 1 {
                        band.set(r + 1, r, -kf);
                    }
                }
            }
            let Ok(factor) = band.cholesky() else {
                return Verdict::Diverged(f64::NAN);
            };
            factor.solve(&mut p0[1..n]);
            factor.solve(&mut p1[1..n]);
            let (w0, w1) = (trapezoid(&p0), trapezoid(&p1));
            let rate = (load - w0) / w1;
            let p: Vec<f64> = p0.iter().zip(&p1).map(|(a, b)| a + rate * b).collect();
            // The primal–dual update: a free node below the cavity pressure closes, a
            // cavitated node whose multiplier (the row's residual) is negative opens.
            let mut changed = 0usize;
            for i in 1..n {
                if !zone(i) {
                    continue;
                }
                let now = if active[i] {
                    let residual = k[i - 1] * (p[i] - p[i - 1]) + k[i] * (p[i] - p[i + 1])
                        - wedge(i)
                        + rate * dx;
                    residual > 0.0
                } else {
                    p[i] < cavity_pressure
                };
                if now != active[i] {
                    active[i] = now;
                    changed += 1;
                }
            }
            if changed == 0 {
                Verdict::Converged((rate, p, w0 + rate * w1), 0.0)
            } else {
                Verdict::Continue(changed as f64)
            }
        })?;
        let (rate, pressure, carried) = solved.value;
        // A cell is cavitated when both its nodes are (the trailing edge counts with its
        // neighbour).
        let cavitated = |i: usize| {
            active[i]
                || (i == 0 && trailing == Some(Trailing::Top) && active[1])
                || (i == n && trailing == Some(Trailing::Bottom) && active[n - 1])
        };
        let (mut shear, mut dissipation) = (0.0, 0.0);
        for (i, h) in faces.iter().enumerate() {
            if cavitated(i) && cavitated(i + 1) {
                continue;
            }
            let gradient = (pressure[i + 1] - pressure[i]) / dx;
            shear += (mu * liner_speed / h - 0.5 * h * gradient) * dx;
            dissipation += (mu * liner_speed * liner_speed / h
                + h.powi(3) * gradient * gradient / (12.0 * mu))
                * dx;
        }
        Ok(Instant {
            squeeze_rate: rate,
            pressure,
            load: carried,
            shear,
            dissipation,
        })
    }
}

/// The piston ring over its engine's cycle.
#[derive(Debug, Clone, PartialEq)]
pub struct PistonRing {
    pub ring: Ring,
    pub engine: Engine,
    /// Viscosity μ, Pa·s.
    pub viscosity: f64,
    pub boundary: Option<Boundary>,
}

/// One sample of the converged cycle.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    /// Crank angle, rad.
    pub theta: f64,
    pub min_film: f64,
    /// Piston speed towards the crankcase, m/s.
    pub piston_speed: f64,
    pub top_pressure: f64,
    pub bottom_pressure: f64,
    /// dh_m/dt, m/s.
    pub squeeze_velocity: f64,
    /// W = ∫P dx × π B, N (the film's radial load on the whole ring).
    pub load: f64,
    pub max_pressure: f64,
    /// Friction on the ring along the bore axis (positive towards the crankcase), N.
    pub friction: f64,
    /// Power loss, W.
    pub power: f64,
    /// True where h_m < σ and the friction is the boundary one.
    pub boundary: bool,
}

/// The converged cycle.
#[derive(Debug, Clone, PartialEq)]
pub struct Cycle {
    /// h_m and the crank angle (rad) at the cycle's smallest and largest film (dense output).
    pub min_film: (f64, f64),
    pub max_film: (f64, f64),
    /// Samples at every crank-angle degree from 0 to the cycle's end (inclusive).
    pub samples: Vec<Sample>,
    /// Cycle-mean power loss, W.
    pub mean_power: f64,
    /// Cycles integrated (the shooting's iterations).
    pub cycles: u32,
    pub report: SolverReport,
}

/// Why the cycle has no answer.
#[derive(Debug, Clone, PartialEq)]
pub enum CycleError {
    /// A film solve or the shooting stopped (cap, deadline).
    Stopped(Box<Stopped>),
    /// The integrator halted at crank angle θ (rad) with film h_m (m).
    Halted {
        theta: f64,
        min_film: f64,
        stopped: Box<Stopped>,
    },
}

/// What one integrated cycle gives.
struct CycleRun {
    end_film: f64,
    min_film: (f64, f64),
    max_film: (f64, f64),
    /// (θ, h_m) at the sample angles.
    films: Vec<(f64, f64)>,
    steps: u32,
    rejected: u32,
    evaluations: u32,
}

impl PistonRing {
    /// The rate d ln(h_m/δ₀)/dθ at crank angle θ in a stroke whose trailing edge is `trailing`.
    fn log_rate(
        &self,
        film: &Film,
        theta: f64,
        h_m: f64,
        trailing: Trailing,
        active: &mut Vec<bool>,
        budget: &Budget,
    ) -> Result<(Instant, f64), Stopped> {
        let e = &self.engine;
        let p_top = e.top_pressure(theta);
        let p_bot = e.bottom_fraction * p_top;
        let u = e.piston_speed(theta);
        let solved = film.solve(
            h_m,
            -u,
            p_top,
            p_bot,
            Some(trailing),
            film.ring_load(h_m, p_top),
            active,
            budget,
        )?;
        let rate = solved.squeeze_rate / (e.omega * h_m);
        Ok((solved, rate))
    }

    /// One cycle from h_m(0) = `start`, stroke by stroke.
    fn run_cycle(
        &self,
        film: &Film,
        start: f64,
        numerics: &Numerics,
        budget: &Budget,
    ) -> Result<CycleRun, CycleError> {
        let delta = self.ring.crown_height;
        let strokes = (self.engine.cycle / PI).round() as usize;
        let sample_step = (1.0 / SAMPLES_PER_DEGREE).to_radians();
        let samples = (self.engine.cycle / sample_step).round() as usize;
        let mut run = CycleRun {
            end_film: start,
            min_film: (start, 0.0),
            max_film: (start, 0.0),
            films: vec![(0.0, start)],
            steps: 0,
            rejected: 0,
            evaluations: 0,
        };
        let mut y = SVector::<f64, 1>::new((start / delta).ln());
        let mut active = Vec::new();
        let settings = Settings {
            method: Method::RadauIia5,
            relative: numerics.tolerance,
            absolute: numerics.tolerance,
            max_step: PI / 8.0,
            max_steps: MAX_STEPS_PER_STROKE,
        };
        for k in 0..strokes {
            let trailing = if k % 2 == 0 {
                Trailing::Top
            } else {
                Trailing::Bottom
            };
            let (t0, t1) = (k as f64 * PI, (k + 1) as f64 * PI);
            let mut rate = |t: f64, y: &SVector<f64, 1>| {
                let h_m = delta * y[0].exp();
                if !(h_m.is_finite() && h_m > 0.0 && y[0].abs() < 60.0) {
                    return Err(RateError::Outside);
                }
                match self.log_rate(film, t, h_m, trailing, &mut active, budget) {
                    Ok((_, r)) if r.is_finite() => Ok(SVector::<f64, 1>::new(r)),
                    Ok(_) => Err(RateError::Outside),
                    Err(stopped) => Err(RateError::Failed(stopped)),
                }
            };
            let (min_film, max_film, films) =
                (&mut run.min_film, &mut run.max_film, &mut run.films);
            let observe = |step: &Step<1>| {
                let ext = step.extremes(|y| y[0]);
                let (lo, hi) = (delta * ext.min.exp(), delta * ext.max.exp());
                if lo < min_film.0 {
                    *min_film = (lo, ext.time_of_min);
                }
                if hi > max_film.0 {
                    *max_film = (hi, ext.time_of_max);
                }
                loop {
                    let next = films.len();
                    let theta = next as f64 * sample_step;
                    if next > samples || theta > step.t1 + 1e-12 {
                        break;
                    }
                    films.push((theta, delta * step.at(theta.min(step.t1))[0].exp()));
                }
                Flow::Continue
            };
            let done = ode::integrate(&mut rate, t0, y, t1, &settings, observe, budget);
            match done {
                Ok(d) => {
                    y = d.y;
                    run.steps += d.report.iterations;
                    run.rejected += d.work.rejected;
                    run.evaluations += d.work.rate_evaluations;
                }
                Err(Failure::Rate(stopped)) => return Err(CycleError::Stopped(Box::new(stopped))),
                Err(Failure::Halted(h)) => {
                    return Err(CycleError::Halted {
                        theta: h.t,
                        min_film: delta * h.y[0].exp(),
                        stopped: Box::new(h.stopped),
                    })
                }
            }
        }
        run.end_film = delta * y[0].exp();
        run.films.truncate(samples + 1);
        Ok(run)
    }

    /// The periodic cycle: h_m(0) shot by fixed-point iteration from `guess` until the cycle
    /// repeats, then the samples of the last cycle.
    pub fn cycle(
        &self,
        guess: f64,
        numerics: &Numerics,
        budget: &Budget,
    ) -> Result<Cycle, CycleError> {
        let film = Film::new(self.ring, self.viscosity, numerics.cells);
        let mut start = guess;
        let mut last: Option<CycleRun> = None;
        let (mut steps, mut rejected, mut evaluations) = (0u32, 0u32, 0u32);
        let mut failure = None;
        let driver = Driver::new(
            "piston_ring_cycle_shooting",
            IterationUnit::Evaluations,
            MAX_CYCLES,
            budget,
        );
        let shot = driver.run(|counter| {
            let run = match self.run_cycle(&film, start, numerics, budget) {
                Ok(run) => run,
                Err(e) => {
                    failure = Some(e);
                    return Verdict::Stalled(f64::NAN);
                }
            };
            counter.evaluated(run.evaluations);
            steps += run.steps;
            rejected += run.rejected;
            evaluations += run.evaluations;
            let residual = (run.end_film / start).ln().abs();
            start = run.end_film;
            last = Some(run);
            if residual <= numerics.periodicity {
                Verdict::Converged((), residual)
            } else {
                Verdict::Continue(residual)
            }
        });
        if let Some(e) = failure {
            return Err(e);
        }
        let shot = shot.map_err(|s| CycleError::Stopped(Box::new(s)))?;
        let run = last.expect("a converged shooting ran a cycle");
        let mut active = Vec::new();
        let mut samples = Vec::with_capacity(run.films.len());
        for &(theta, h_m) in &run.films {
            let trailing = if (theta / PI).floor() as i64 % 2 == 0 {
                Trailing::Top
            } else {
                Trailing::Bottom
            };
            let (instant, _) = self
                .log_rate(&film, theta, h_m, trailing, &mut active, budget)
                .map_err(|s| CycleError::Stopped(Box::new(s)))?;
            samples.push(self.sample(theta, h_m, &instant));
        }
        let m = samples.len() - 1;
        let mean_power = samples[..m].iter().map(|s| s.power).sum::<f64>() / m as f64;
        let report = SolverReport {
            method: "piston_ring_radau_iia5_shooting".to_owned(),
            iterations: steps,
            iterations_unit: IterationUnit::TimeSteps,
            evaluations: Some(evaluations),
            time_integration: Some(Box::new(TimeIntegration {
                rejected_steps: rejected,
                relative_tolerance: numerics.tolerance,
            })),
            grid: Some(vec![numerics.cells as u32]),
            residual: shot.report.residual,
            ..shot.report
        };
        Ok(Cycle {
            min_film: run.min_film,
            max_film: run.max_film,
            samples,
            mean_power,
            cycles: shot.report.iterations,
            report,
        })
    }

    /// The sample at θ from the film there.
    fn sample(&self, theta: f64, h_m: f64, instant: &Instant) -> Sample {
        let e = &self.engine;
        let circumference = PI * e.bore;
        let u = e.piston_speed(theta);
        let p_top = e.top_pressure(theta);
        let boundary = self.boundary.filter(|b| h_m < b.roughness);
        let (friction, power) = match boundary {
            Some(b) => {
                let f = b.friction_coefficient * circumference * instant.load.max(0.0);
                (-u.signum() * f, f * u.abs())
            }
            None => (
                circumference * instant.shear,
                circumference * instant.dissipation,
            ),
        };
        Sample {
            theta,
            min_film: h_m,
            piston_speed: u,
            top_pressure: p_top,
            bottom_pressure: e.bottom_fraction * p_top,
            squeeze_velocity: instant.squeeze_rate,
            load: circumference * instant.load,
            max_pressure: instant.pressure.iter().copied().fold(f64::MIN, f64::max),
            friction,
            power,
            boundary: boundary.is_some(),
        }
    }
}

#[cfg(test)]
#[path = "piston_film_tests.rs"]
mod tests;
