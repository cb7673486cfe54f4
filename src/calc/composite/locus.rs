//! The composite bearing's journal locus under a dynamic load: the journal's orbit coupled to
//! the sleeve unit's speed (Harnoy ch. 18 §18.5, Eqs. 18-14 to 18-16 and 18-29 to 18-36; spec
//! PART B.1.3–B.1.5 with its corrections).
//!
//! Frame, signs and scalings as the journal's orbit (`journal::orbit`, `journal::moving_film`):
//! bearing-fixed, x horizontal, y up, the journal turning counter-clockwise; time τ = ω_j t;
//! r̄ = r/C; F̄ = F C²/(μ R ω_j L³); m̄ = m C³ ω_j/(μ R L³). The fifth state is the sleeve's speed
//! ratio ξ = ω_b/ω_j, positive with the journal.
//!
//! - **Journal**: m̄ (u̇, v̇) = F̄_film(r̄, w̄; 1 + ξ) + F̄_load(τ), the short film of
//!   `moving_film` with the speed sum Ω̄ = 1 + ξ (the film sees ω_j + ω_b: its Couette load and
//!   the squeeze vector w̄ = v̄ − ½(1 + ξ) k × r̄ both carry it). Massless (m̄ = 0): the velocity
//!   is Booker's mobility at that speed sum.
//! - **Sleeve** (Eq. 18-16 with I_eq restored, B.1.4): I_eq dω_b/dt = M_h − M_f − M_r with the
//!   speed-split room's torque model — the quasi-steady Petroff-type film torque M_h = 2n(ε)(ω_j
//!   − ω_b) of `film::SleeveFilm`, the pins' M_f = k ω_b|ω_b| of `sleeve::Restraint` (−ξ|ξ|H₂,
//!   spec B.3 item 4) and the rolling bearing's Coulomb torque M_r (regularised over |ξ| < 10⁻⁶
//!   as in the start-up, so a held sleeve can stand). Dimensionless:
//!   dξ/dτ = (1 − ξ) H₁ 2π/√(1 − ε²) − H₂ ξ|ξ| − H_r sgn ξ,
//!   H₁ = L μ R³/(C I_eq ω_j), H₂ = k/I_eq, H_r = M_r/(I_eq ω_j²).
//! - **Start**: the static equilibrium at the load at τ = 0, solved jointly with the sleeve's
//!   steady speed at that ε (B.1.5): (1 + ξ(ε)) W̄_Ocvirk(ε) = F̄(0), the eccentricity turned
//!   ahead of the load by Ocvirk's attitude, at rest.
//! - **Steady orbit**: period by period (each period one integration landing on its end), until
//!   the state at the period's end — position and ξ — repeats within the tolerance.
//!
//! The integrator is `numerics::ode`'s Radau IIA. A journal at or beyond contact
//! (ε ≥ 1 − 10⁻⁹) is outside the film model: the integrator retries smaller, and a journal that
//! still reaches the wall halts there (the caller reports contact).

use std::f64::consts::PI;

use nalgebra::{SVector, Vector3, Vector5};

use super::film::{LoadError, SleeveFilm, COMPARISON_MAX_ECCENTRICITY};
use super::sleeve::Restraint;
use crate::calc::journal::load_law::LoadLaw;
use crate::calc::journal::moving_film::{squeeze_vector, ShortArc, ShortFilm, CONTACT};
use crate::calc::journal::orbit::{self, OrbitError, Tally};
use crate::fidelity::{SolverReport, TimeIntegration};
use crate::numerics::driver::Budget;
use crate::numerics::ode::{self, Failure, Flow, Rate, RateError, Step};

/// Half-width of the band of ξ over which the rolling bearing's Coulomb torque is regularised.
const STICK: f64 = 1e-6;

/// The sleeve equation's dimensionless groups.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SleeveGroups {
    /// H₁ = L μ R³/(C I_eq ω_j): the film's drive.
    pub drive: f64,
    /// H₂ = k/I_eq: the pins' restraint.
    pub restraint: f64,
    /// H_r = M_r/(I_eq ω_j²): the rolling bearing's friction.
    pub rolling: f64,
}

impl SleeveGroups {
    /// The groups of a film, a restraint and an inertia I_eq (kg·m²) at journal speed ω_j (rad/s).
    pub fn of(film: &SleeveFilm, restraint: &Restraint, inertia: f64, journal_speed: f64) -> Self {
        SleeveGroups {
            drive: film.length * film.viscosity * film.radius.powi(3)
                / (film.clearance * inertia * journal_speed),
            restraint: restraint.coefficient / inertia,
            rolling: restraint.rolling_torque / (inertia * journal_speed * journal_speed),
        }
    }

    /// dξ/dτ at eccentricity ratio ε and speed ratio ξ.
    pub fn acceleration(&self, eps: f64, xi: f64) -> f64 {
        let coulomb = (xi / STICK).clamp(-1.0, 1.0);
        (1.0 - xi) * self.drive * 2.0 * PI / (1.0 - eps * eps).sqrt()
            - self.restraint * xi * xi.abs()
            - self.rolling * coulomb
    }

    /// The steady ξ at ε: the speed split's closed form ([`Restraint::steady_speed_ratio`]) in
    /// these units (n = π H₁/√(1 − ε²), ω_j = 1, k = H₂, M_r = H_r).
    pub fn steady_speed_ratio(&self, eps: f64) -> f64 {
        Restraint {
            coefficient: self.restraint,
            rolling_torque: self.rolling,
        }
        .steady_speed_ratio(PI * self.drive / (1.0 - eps * eps).sqrt(), 1.0)
    }
}

/// The problem in the integrator's units.
#[derive(Debug, Clone, PartialEq)]
pub struct Problem {
    pub arc: ShortArc,
    /// m̄; 0 for the massless (mobility) journal.
    pub mass: f64,
    pub load: LoadLaw,
    /// F_s = μ R ω_j L³/C², N: F̄ = F/F_s.
    pub force_scale: f64,
    pub sleeve: SleeveGroups,
}

/// A static equilibrium: the journal's position r̄ and the sleeve's speed ratio.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Equilibrium {
    pub position: [f64; 2],
    pub speed_ratio: f64,
}

impl Problem {
    /// The load at τ in the film's units.
    fn load_at(&self, tau: f64) -> [f64; 2] {
        let f = self.load.force(tau);
        [f[0] / self.force_scale, f[1] / self.force_scale]
    }

    /// The static equilibrium under the load at τ = 0 with the sleeve turning at its steady
    /// speed (`held`: at ξ = 0, the regular bearing): one bracketed root of (1 + ξ(ε)) W̄(ε) =
    /// |F̄| in the logit of ε (the speed split's load search on the film in these units), the
    /// eccentricity turned ahead of the load by Ocvirk's attitude. The half films' static force
    /// is Ocvirk's.
    pub fn equilibrium(&self, held: bool) -> Result<Equilibrium, LoadError> {
        let load = self.load_at(0.0);
        let magnitude = load[0].hypot(load[1]);
        let ratio = |eps: f64| {
            if held {
                0.0
            } else {
                self.sleeve.steady_speed_ratio(eps)
            }
        };
        if magnitude == 0.0 {
            return Ok(Equilibrium {
                position: [0.0, 0.0],
                speed_ratio: ratio(0.0),
            });
        }
        let unit = SleeveFilm {
            radius: 1.0,
            length: 1.0,
            clearance: 1.0,
            viscosity: 1.0,
        };
        let eps = unit
            .eccentricity_for(magnitude, COMPARISON_MAX_ECCENTRICITY, |e| 1.0 + ratio(e))?
            .eccentricity;
        let angle = load[1].atan2(load[0]) + SleeveFilm::attitude_angle(eps);
        Ok(Equilibrium {
            position: [eps * angle.cos(), eps * angle.sin()],
            speed_ratio: ratio(eps),
        })
    }

    fn film(&self, xi: f64) -> ShortFilm {
        ShortFilm {
            arc: self.arc,
            speed_sum: 1.0 + xi,
        }
    }
}

/// The rate with mass: state (x̄, ȳ, u, v, ξ).
struct WithMass<'a>(&'a Problem);

impl Rate<5> for WithMass<'_> {
    type Error = ();
    fn rate(&mut self, t: f64, y: &Vector5<f64>) -> Result<Vector5<f64>, RateError<()>> {
        let p = self.0;
        let (r, xi) = ([y[0], y[1]], y[4]);
        let w = squeeze_vector(r, [y[2], y[3]], 1.0 + xi);
        let film = p.film(xi).force(r, w).ok_or(RateError::Outside)?;
        let load = p.load_at(t);
        Ok(Vector5::new(
            y[2],
            y[3],
            (film[0] + load[0]) / p.mass,
            (film[1] + load[1]) / p.mass,
            p.sleeve.acceleration(r[0].hypot(r[1]), xi),
        ))
    }
}

/// The massless rate: state (x̄, ȳ, ξ), the velocity from the mobility at speed sum 1 + ξ.
struct Massless<'a>(&'a Problem);

impl Rate<3> for Massless<'_> {
    type Error = ();
    fn rate(&mut self, t: f64, y: &Vector3<f64>) -> Result<Vector3<f64>, RateError<()>> {
        let p = self.0;
        let (r, xi) = ([y[0], y[1]], y[2]);
        let w = p
            .film(xi)
            .squeeze_for(r, p.load_at(t))
            .ok_or(RateError::Outside)?;
        // v̄ = w̄ + ½(1 + ξ) k × r̄.
        let half = 0.5 * (1.0 + xi);
        Ok(Vector3::new(
            w[0] - half * r[1],
            w[1] + half * r[0],
            p.sleeve.acceleration(r[0].hypot(r[1]), xi),
        ))
    }
}

/// When the run ends: the state after one load period repeats within `tolerance` (|Δr̄| and
/// |Δξ|), within `max_periods`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settling {
    pub tolerance: f64,
    pub max_periods: u32,
}

/// One sample of the locus: τ, x̄, ȳ, ξ.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    pub time: f64,
    pub position: [f64; 2],
    pub speed_ratio: f64,
}

/// What the locus did over its last load period.
#[derive(Debug, Clone, PartialEq)]
pub struct Window {
    pub from: f64,
    pub to: f64,
    pub max_eccentricity: f64,
    /// τ and direction (rad, from +x) of the largest eccentricity.
    pub time_of_max: f64,
    pub direction_of_max: f64,
    pub min_eccentricity: f64,
    pub min_speed_ratio: f64,
    pub max_speed_ratio: f64,
    /// The mean of ξ over the window (Simpson's rule on each step).
    pub mean_speed_ratio: f64,
    /// Samples at equal times over the window, when asked for.
    pub samples: Vec<Sample>,
}

/// A finished locus.
#[derive(Debug, Clone, PartialEq)]
pub struct Locus {
    pub start: Equilibrium,
    pub window: Window,
    pub steady: bool,
    /// Load periods integrated.
    pub periods: u32,
    /// The last period map's change (the larger of |Δr̄| and |Δξ|).
    pub period_residual: f64,
    pub report: SolverReport,
}

/// The composite locus from `start` (at rest; [`Problem::equilibrium`] for the text's start) to
/// a steady orbit (or `max_periods`), at relative tolerance `relative`, with `samples` samples
/// of the last period (0: none).
pub fn run(
    problem: &Problem,
    start: Equilibrium,
    settling: Settling,
    relative: f64,
    samples: usize,
    budget: &Budget,
) -> Result<Locus, OrbitError> {
    let [x, y] = start.position;
    let xi = start.speed_ratio;
    let run = if problem.mass > 0.0 {
        let y0 = Vector5::new(x, y, 0.0, 0.0, xi);
        march(
            &mut WithMass(problem),
            problem,
            y0,
            settling,
            relative,
            samples,
            budget,
        )
    } else {
        let y0 = Vector3::new(x, y, xi);
        march(
            &mut Massless(problem),
            problem,
            y0,
            settling,
            relative,
            samples,
            budget,
        )
    };
    run.map(|(window, steady, periods, period_residual, report)| Locus {
        start,
        window,
        steady,
        periods,
        period_residual,
        report,
    })
}

fn eccentricity<const N: usize>(y: &SVector<f64, N>) -> f64 {
    y[0].hypot(y[1])
}

/// Running statistics of one period; ξ is the state's last component.
struct Tracker {
    window: Window,
    speed_integral: f64,
}

impl Tracker {
    fn new<const N: usize>(from: f64, y: &SVector<f64, N>) -> Self {
        Tracker {
            window: Window {
                from,
                to: from,
                max_eccentricity: eccentricity(y),
                time_of_max: from,
                direction_of_max: y[1].atan2(y[0]),
                min_eccentricity: eccentricity(y),
                min_speed_ratio: y[N - 1],
                max_speed_ratio: y[N - 1],
                mean_speed_ratio: y[N - 1],
                samples: Vec::new(),
            },
            speed_integral: 0.0,
        }
    }

    fn add<const N: usize>(&mut self, step: &Step<N>) {
        let w = &mut self.window;
        let e = step.extremes(eccentricity);
        if e.max > w.max_eccentricity {
            let y = step.at(e.time_of_max);
            w.max_eccentricity = e.max;
            w.time_of_max = e.time_of_max;
            w.direction_of_max = y[1].atan2(y[0]);
        }
        w.min_eccentricity = w.min_eccentricity.min(e.min);
        let xi = step.extremes(|y| y[N - 1]);
        w.max_speed_ratio = w.max_speed_ratio.max(xi.max);
        w.min_speed_ratio = w.min_speed_ratio.min(xi.min);
        let (t0, t1) = (step.t0, step.t1);
        let mid = step.at(0.5 * (t0 + t1))[N - 1];
        self.speed_integral += (t1 - t0) / 6.0 * (step.y0[N - 1] + 4.0 * mid + step.y1[N - 1]);
        w.to = t1;
    }

    fn finish(mut self) -> Window {
        let span = self.window.to - self.window.from;
        if span > 0.0 {
            self.window.mean_speed_ratio = self.speed_integral / span;
        }
        self.window
    }
}

/// The last period's window, whether it repeated, the periods, the last change, the report.
type Marched = (Window, bool, u32, f64, SolverReport);

fn march<const N: usize, R: Rate<N, Error = ()>>(
    rate: &mut R,
    problem: &Problem,
    y0: SVector<f64, N>,
    settling: Settling,
    relative: f64,
    samples: usize,
    budget: &Budget,
) -> Result<Marched, OrbitError> {
    // The journal's orbit's settings: r̄ and ξ are both of order one.
    let settings = orbit::settings(relative);
    let period = problem.load.period();
    let (mut t, mut y) = (0.0, y0);
    let mut tally = Tally::default();
    let mut periods = 0;
    loop {
        let mut tracker = Tracker::new(t, &y);
        let mut kept: Vec<Step<N>> = Vec::new();
        let observe = |step: &Step<N>| {
            tracker.add(step);
            if samples > 0 {
                kept.push(*step);
            }
            Flow::Continue
        };
        let settings = orbit::next_period(settings, tally.steps);
        let done = match ode::integrate(rate, t, y, t + period, &settings, observe, budget) {
            Ok(done) => done,
            Err(Failure::Halted(h)) => return Err(OrbitError::halted(*h, CONTACT, &tally)),
            Err(Failure::Rate(())) => unreachable!("the locus's rates do not fail"),
        };
        tally.add(&done);
        periods += 1;
        let change = (done.y[0] - y[0])
            .hypot(done.y[1] - y[1])
            .max((done.y[N - 1] - y[N - 1]).abs());
        (t, y) = (done.t, done.y);
        let steady = change <= settling.tolerance;
        if steady || periods >= settling.max_periods {
            let mut window = tracker.finish();
            window.samples = sample(&kept, &window, samples);
            // The last integration's report, with the whole run's work.
            let report = SolverReport {
                iterations: tally.steps,
                evaluations: Some(tally.evaluations),
                residual: Some(change),
                time_integration: Some(Box::new(TimeIntegration {
                    rejected_steps: tally.rejected,
                    relative_tolerance: relative,
                })),
                ..done.report
            };
            return Ok((window, steady, periods, change, report));
        }
    }
}

/// `count` samples at equal times over the window from the kept steps' dense output.
fn sample<const N: usize>(steps: &[Step<N>], window: &Window, count: usize) -> Vec<Sample> {
    if count == 0 || steps.is_empty() {
        return Vec::new();
    }
    let span = window.to - window.from;
    let mut k = 0;
    (0..count)
        .map(|i| {
            let t = window.from + span * i as f64 / (count - 1).max(1) as f64;
            while k + 1 < steps.len() && steps[k].t1 < t {
                k += 1;
            }
            let y = steps[k].at(t);
            Sample {
                time: t,
                position: [y[0], y[1]],
                speed_ratio: y[N - 1],
            }
        })
        .collect()
}

#[cfg(test)]
#[path = "locus_tests.rs"]
mod tests;
