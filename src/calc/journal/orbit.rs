//! The journal's orbit under a dynamic load: Newton's law for the journal centre with the short
//! film's force (`moving_film`) or the finite film's (`finite_moving_film`, an impedance table
//! from the Reynolds solver), integrated by the stiff Radau IIA integrator (`numerics::ode`)
//! until the orbit repeats itself over a load period, for a set time, or until an eccentricity
//! is reached (Harnoy §18.5, Eqs 18-29 to 18-34 in Cartesian form, spec B.1.3–B.1.5).
//!
//! Frame and signs as `moving_film`: bearing-fixed, x horizontal, y up, the journal turning
//! counter-clockwise. Time is the journal's rotation angle τ = ω_j t; positions are r̄ = r/C;
//! forces F̄ = F C²/(μ R ω_j L³); the mass m̄ = m C ω_j²/F_s = m C³ ω_j/(μ R L³) (Eq. 18-30 with
//! its lost μ restored).
//!
//! - With mass: the state (x̄, ȳ, u, v), m̄ (u̇, v̇) = F̄_film(r̄, w̄) + F̄_load(τ). Cartesian, so
//!   the centre (ε = 0) is an ordinary point (the polar form divides by ε).
//! - Massless (m̄ = 0): the state (x̄, ȳ) and the velocity from Booker's mobility, the squeeze
//!   vector at which the film carries the load.
//!
//! A state at or beyond contact (ε ≥ 1 − 10⁻⁹; for the finite film beyond its table's top) is
//! outside the film model: the integrator retries smaller, and a journal that still reaches it
//! halts there (the caller reports contact).
//!
//! The steady orbit: the run goes period by period (each period one integration that lands on
//! its end) until the journal's position at the period's end differs from the last by less than
//! the orbit tolerance; the last period's orbit is the result.

use std::f64::consts::PI;

use std::sync::Arc;

use nalgebra::{SVector, Vector2, Vector4};

use super::finite_moving_film::ImpedanceTable;
use super::load_law::LoadLaw;
use super::moving_film::{squeeze_vector, ShortFilm};
use crate::calc::Budget;
use crate::fidelity::{IterationUnit, SolverReport, StopReason, TimeIntegration};
use crate::numerics::ode::{
    self, Failure, Flow, Halted, Integrated, Method, Rate, RateError, Settings, Step,
};
use crate::numerics::optimise::brent_minimise;

/// The film an orbit runs on: the short film's closed forms, or the finite film's impedance
/// table (built once per request from the Reynolds solver) with Ω̄ = (ω_j + ω_b)/ω_j.
#[derive(Debug, Clone, PartialEq)]
pub enum OrbitFilm {
    Short(ShortFilm),
    Finite {
        table: Arc<ImpedanceTable>,
        speed_sum: f64,
    },
}

impl OrbitFilm {
    /// Ω̄, which turns the velocity into the squeeze vector.
    pub fn speed_sum(&self) -> f64 {
        match self {
            OrbitFilm::Short(f) => f.speed_sum,
            OrbitFilm::Finite { speed_sum, .. } => *speed_sum,
        }
    }

    /// F̄ at r̄ with squeeze vector w̄; None outside the model (contact, or beyond the table).
    pub fn force(&self, position: [f64; 2], squeeze: [f64; 2]) -> Option<[f64; 2]> {
        match self {
            OrbitFilm::Short(f) => f.force(position, squeeze),
            OrbitFilm::Finite { table, .. } => table.force(position, squeeze),
        }
    }

    /// The mobility: the squeeze vector at which the film carries `load`.
    pub fn squeeze_for(&self, position: [f64; 2], load: [f64; 2]) -> Option<[f64; 2]> {
        match self {
            OrbitFilm::Short(f) => f.squeeze_for(position, load),
            OrbitFilm::Finite { table, .. } => table.squeeze_for(position, load),
        }
    }

    /// The peak film pressure p̄.
    pub fn peak_pressure(&self, position: [f64; 2], squeeze: [f64; 2]) -> f64 {
        match self {
            OrbitFilm::Short(f) => f.peak_pressure(position, squeeze),
            OrbitFilm::Finite { table, .. } => table.peak_pressure(position, squeeze),
        }
    }

    /// The largest ε the film answers for.
    pub fn reach(&self) -> f64 {
        match self {
            OrbitFilm::Short(_) => super::moving_film::CONTACT,
            OrbitFilm::Finite { table, .. } => table.top(),
        }
    }
}

/// The problem in the integrator's units.
#[derive(Debug, Clone, PartialEq)]
pub struct Problem {
    pub film: OrbitFilm,
    /// m̄; 0 for the massless (mobility) journal.
    pub mass: f64,
    pub load: LoadLaw,
    /// F_s = μ R ω_j L³/C², N: F̄ = F/F_s.
    pub force_scale: f64,
}

/// The scales of the integrator's units for a journal of radius R, length L and clearance C
/// turning at ω in oil of viscosity μ: forces over F_s = μ R ω L³/C² (N), masses as
/// m̄ = m C ω²/F_s (the short bearing's groups, Booker's mobility units).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Scales {
    /// F_s, N.
    pub force: f64,
    /// C ω², m/s²: m̄ = m C ω²/F_s.
    acceleration: f64,
}

impl Scales {
    pub fn of(viscosity: f64, radius: f64, length: f64, clearance: f64, omega: f64) -> Self {
        Scales {
            force: viscosity * radius * omega * length.powi(3) / (clearance * clearance),
            acceleration: clearance * omega * omega,
        }
    }

    /// m̄ of a mass in kg (0 stays 0: the massless journal).
    pub fn mass(&self, kg: f64) -> f64 {
        kg * self.acceleration / self.force
    }
}

/// When the run ends.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Until {
    /// The orbit maps onto itself over one load period within `tolerance` (in r̄), within
    /// `max_periods`.
    SteadyOrbit { tolerance: f64, max_periods: u32 },
    /// A time τ.
    Time(f64),
    /// The eccentricity ratio reaches `target`, or the orbit settles below it (one load period
    /// maps onto itself within `settled_within`, in r̄: it never will), or τ passes `horizon`.
    Eccentricity {
        target: f64,
        horizon: f64,
        settled_within: f64,
    },
}

/// The initial state (r̄, dr̄/dτ).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Start {
    pub position: [f64; 2],
    pub velocity: [f64; 2],
}

/// What the orbit did over the window the result describes (the last period of a steady orbit,
/// the whole run otherwise).
#[derive(Debug, Clone, PartialEq)]
pub struct Window {
    pub from: f64,
    pub to: f64,
    pub max_eccentricity: f64,
    /// τ and direction (rad, from +x) of the largest eccentricity.
    pub time_of_max: f64,
    pub direction_of_max: f64,
    pub min_eccentricity: f64,
    /// The largest p̄ at the accepted steps' ends.
    pub peak_pressure: f64,
    /// The mean of 1/√(1 − ε²) over the window (the Couette dissipation's factor).
    pub mean_couette_factor: f64,
    /// Samples (τ, x̄, ȳ) at equal times over the window, when asked for.
    pub samples: Vec<(f64, f64, f64)>,
}

/// A finished orbit.
#[derive(Debug, Clone, PartialEq)]
pub struct Orbit {
    pub window: Window,
    /// The largest ε over the whole run and its τ.
    pub peak_eccentricity: f64,
    pub time_of_peak: f64,
    /// τ and state at the end.
    pub end: f64,
    pub position: [f64; 2],
    /// The orbit repeated: a steady-orbit run that settled, or a run to a target that settled
    /// below it.
    pub steady: bool,
    /// Periods integrated (for a steady orbit: until it repeated).
    pub periods: u32,
    /// τ at which the target eccentricity was reached.
    pub time_to_target: Option<f64>,
    /// The last period map's change |Δr̄| (steady orbit runs; a run to a target that settled).
    pub period_residual: Option<f64>,
    pub report: SolverReport,
}

/// Why no orbit.
#[derive(Debug, Clone, PartialEq)]
pub enum OrbitError {
    /// The journal reached the wall at τ (the film could not carry the load cycle).
    Contact { time: f64, eccentricity: f64 },
    /// The integrator was capped or ran out of time.
    Stopped(SolverReport),
}

impl OrbitError {
    /// A halted integration: contact when it stalled within 1 % of the film's reach in ε (the
    /// wall stopped it), or used up the run's steps with the film below a thousandth of the
    /// clearance (a load so far beyond the film's that only its stiffness near the wall held
    /// it off); else the integrator's report, with the work of the run's `earlier`
    /// integrations. The 0.999 rule judges only a run that its step cap stopped: one that ends
    /// its periods with a peak beyond 0.999 is a result, warned of its thin film (so a whirl
    /// that does not repeat may end either way at different fidelities).
    pub(crate) fn halted<const N: usize>(h: Halted<N>, reach: f64, earlier: &Tally) -> Self {
        let e = h.y[0].hypot(h.y[1]);
        let stalled_at_wall = h.stopped.reason() == StopReason::Stalled && e > 0.99 * reach;
        let capped_at_wall = h.stopped.reason() == StopReason::IterationCap && e > 0.999;
        if stalled_at_wall || capped_at_wall {
            OrbitError::Contact {
                time: h.t,
                eccentricity: e,
            }
        } else {
            OrbitError::Stopped(earlier.with_earlier(h.stopped.report))
        }
    }
}

/// The integrator's tolerance for a fidelity's relative tolerance: absolute as relative on r̄
/// (order one), the steps at most a fiftieth of a revolution so that every load cycle is seen.
pub(crate) fn settings(relative: f64) -> Settings {
    Settings {
        method: Method::RadauIia5,
        relative,
        absolute: relative,
        max_step: 2.0 * PI / 50.0,
        max_steps: 2_000_000,
    }
}

/// Time steps a run to a steady orbit may take over all its load periods: a few seconds. A
/// film driven to within nanometres of contact by a load cycle far beyond what it carries is
/// so stiff that its orbit would take millions; it ends capped (contact, see
/// [`OrbitError::halted`]) instead of running to the deadline.
pub(crate) const STEADY_RUN_STEPS: u32 = 500_000;

/// `settings` for the next load period of a run to a steady orbit that has taken `taken`
/// steps.
pub(crate) fn next_period(settings: Settings, taken: u32) -> Settings {
    Settings {
        max_steps: STEADY_RUN_STEPS.saturating_sub(taken).max(1),
        ..settings
    }
}

/// The rate of the journal with mass: (u, v, F̄/m̄).
struct WithMass<'a>(&'a Problem);

impl Rate<4> for WithMass<'_> {
    type Error = ();
    fn rate(&mut self, t: f64, y: &Vector4<f64>) -> Result<Vector4<f64>, RateError<()>> {
        let p = self.0;
        let r = [y[0], y[1]];
        let w = squeeze_vector(r, [y[2], y[3]], p.film.speed_sum());
        let film = p.film.force(r, w).ok_or(RateError::Outside)?;
        let load = p.load.force(t);
        let m = p.mass;
        Ok(Vector4::new(
            y[2],
            y[3],
            (film[0] + load[0] / p.force_scale) / m,
            (film[1] + load[1] / p.force_scale) / m,
        ))
    }
}

/// The massless journal's rate: the mobility velocity.
struct Massless<'a>(&'a Problem);

impl Problem {
    /// The massless journal's velocity dr̄/dτ at τ and r̄ (Booker's mobility): the squeeze
    /// vector at which the film carries the load, plus the film's mean rotation,
    /// v̄ = w̄ + ½Ω̄ k × r̄; None outside the film's model.
    pub fn mobility_velocity(&self, t: f64, r: [f64; 2]) -> Option<[f64; 2]> {
        let load = self.load.force(t);
        let w = self
            .film
            .squeeze_for(r, [load[0] / self.force_scale, load[1] / self.force_scale])?;
        let half = 0.5 * self.film.speed_sum();
        Some([w[0] - half * r[1], w[1] + half * r[0]])
    }
}

impl Rate<2> for Massless<'_> {
    type Error = ();
    fn rate(&mut self, t: f64, y: &Vector2<f64>) -> Result<Vector2<f64>, RateError<()>> {
        let v = self
            .0
            .mobility_velocity(t, [y[0], y[1]])
            .ok_or(RateError::Outside)?;
        Ok(Vector2::new(v[0], v[1]))
    }
}

/// The orbit from `start` under `until`, at relative tolerance `relative`, with `samples`
/// samples of the result's window (0: none).
pub fn run(
    problem: &Problem,
    start: Start,
    until: Until,
    relative: f64,
    samples: usize,
    budget: &Budget,
) -> Result<Orbit, OrbitError> {
    if problem.mass > 0.0 {
        let y0 = Vector4::new(
            start.position[0],
            start.position[1],
            start.velocity[0],
            start.velocity[1],
        );
        march(
            &mut WithMass(problem),
            problem,
            y0,
            until,
            relative,
            samples,
            budget,
        )
    } else {
        let y0 = Vector2::new(start.position[0], start.position[1]);
        march(
            &mut Massless(problem),
            problem,
            y0,
            until,
            relative,
            samples,
            budget,
        )
    }
}

/// Totals over a run's integrations.
#[derive(Default)]
pub(crate) struct Tally {
    pub steps: u32,
    pub rejected: u32,
    pub evaluations: u32,
}

impl Tally {
    /// Count one finished integration's work.
    pub(crate) fn add<const N: usize>(&mut self, done: &Integrated<N>) {
        self.steps += done.report.iterations;
        self.rejected += done.work.rejected;
        self.evaluations += done.work.rate_evaluations;
    }

    /// A halted integration's report with the run's earlier integrations' work added: the
    /// steps, evaluations and rejections of the whole run.
    fn with_earlier(&self, mut report: SolverReport) -> SolverReport {
        report.iterations += self.steps;
        report.evaluations = Some(report.evaluations.unwrap_or(0) + self.evaluations);
        if let Some(integration) = report.time_integration.as_mut() {
            integration.rejected_steps += self.rejected;
        }
        report
    }
}

/// One integration's end: τ, the state, its window, its steps (kept for sampling) and whether
/// the target eccentricity stopped it.
struct Leg<const N: usize> {
    t: f64,
    y: SVector<f64, N>,
    window: Window,
    kept: Vec<Step<N>>,
    reached: bool,
    /// The period map's change when a run to a target settled below it.
    settled: Option<f64>,
}

/// A run's target eccentricity, and the period map's change below which it has settled short
/// of it.
#[derive(Debug, Clone, Copy)]
struct Target {
    eccentricity: f64,
    settled_within: f64,
}

/// Running statistics of one window.
struct Tracker<'a> {
    window: Window,
    couette_integral: f64,
    film: &'a OrbitFilm,
}

fn eccentricity<const N: usize>(y: &SVector<f64, N>) -> f64 {
    y[0].hypot(y[1])
}

impl<'a> Tracker<'a> {
    fn new(from: f64, film: &'a OrbitFilm) -> Self {
        Tracker {
            window: Window {
                from,
                to: from,
                max_eccentricity: 0.0,
                time_of_max: from,
                direction_of_max: 0.0,
                min_eccentricity: f64::INFINITY,
                peak_pressure: 0.0,
                mean_couette_factor: 0.0,
                samples: Vec::new(),
            },
            couette_integral: 0.0,
            film,
        }
    }

    /// Take in one accepted step: extrema of ε refined on the dense output, the Couette factor
    /// by Simpson's rule, the pressure at the step's end.
    fn add<const N: usize>(&mut self, step: &Step<N>) {
        let w = &mut self.window;
        if w.min_eccentricity.is_infinite() {
            let e0 = eccentricity(&step.y0);
            w.min_eccentricity = e0;
            w.max_eccentricity = e0;
            w.direction_of_max = step.y0[1].atan2(step.y0[0]);
        }
        let extremes = step.extremes(eccentricity);
        if extremes.max > w.max_eccentricity {
            let y = step.at(extremes.time_of_max);
            w.max_eccentricity = extremes.max;
            w.time_of_max = extremes.time_of_max;
            w.direction_of_max = y[1].atan2(y[0]);
        }
        w.min_eccentricity = w.min_eccentricity.min(extremes.min);
        let e = |t: f64| eccentricity(&step.at(t));
        let (t0, t1) = (step.t0, step.t1);
        let (e0, em, e1) = (e(t0), e(0.5 * (t0 + t1)), e(t1));
        let factor = |e: f64| 1.0 / (1.0 - (e * e).min(1.0 - 1e-18)).sqrt();
        self.couette_integral += (t1 - t0) / 6.0 * (factor(e0) + 4.0 * factor(em) + factor(e1));
        let velocity = if N == 4 {
            [step.y1[2], step.y1[3]]
        } else {
            [step.f1[0], step.f1[1]]
        };
        let r = [step.y1[0], step.y1[1]];
        let p = self
            .film
            .peak_pressure(r, squeeze_vector(r, velocity, self.film.speed_sum()));
        w.peak_pressure = w.peak_pressure.max(p);
        w.to = t1;
    }

    fn finish(mut self) -> Window {
        let span = self.window.to - self.window.from;
        self.window.mean_couette_factor = if span > 0.0 {
            self.couette_integral / span
        } else {
            1.0
        };
        self.window
    }
}

#[allow(clippy::too_many_arguments)]
fn march<const N: usize, R: Rate<N, Error = ()>>(
    rate: &mut R,
    problem: &Problem,
    y0: SVector<f64, N>,
    until: Until,
    relative: f64,
    samples: usize,
    budget: &Budget,
) -> Result<Orbit, OrbitError> {
    let settings = settings(relative);
    let steady_run = matches!(until, Until::SteadyOrbit { .. });
    let period = problem.load.period();
    let mut tally = Tally::default();
    let mut peak = (eccentricity(&y0), 0.0);
    let mut t = 0.0;
    let mut y = y0;
    let mut periods = 0;
    let mut steady = false;
    let mut residual = None;
    let mut time_to_target = None;
    // One integration of [t, t_end], tracking a window; returns the end state.
    let mut leg = |t: f64,
                   y: SVector<f64, N>,
                   t_end: f64,
                   target: Option<Target>,
                   tally: &mut Tally,
                   peak: &mut (f64, f64)|
     -> Result<Leg<N>, OrbitError> {
        let mut tracker = Tracker::new(t, &problem.film);
        let mut kept: Vec<Step<N>> = Vec::new();
        let mut reached = false;
        // The settling test of a run to a target: the position at each period's end.
        let mut mark = (t + period, [y[0], y[1]]);
        let mut settled = None;
        let observe = |step: &Step<N>| {
            if let Some(Target {
                eccentricity: target,
                settled_within,
            }) = target
            {
                if eccentricity(&step.y1) >= target {
                    let (tt, _) = brent_minimise(
                        |s| (eccentricity(&step.at(s)) - target).abs(),
                        step.t0,
                        step.t1,
                        1e-12 * (step.t1 - step.t0),
                    );
                    let cut = Step {
                        t1: tt,
                        y1: step.at(tt),
                        ..*step
                    };
                    tracker.add(&cut);
                    reached = true;
                    return Flow::StopAt(tt);
                }
                while step.t1 >= mark.0 {
                    let at = step.at(mark.0);
                    let change = (at[0] - mark.1[0]).hypot(at[1] - mark.1[1]);
                    if change <= settled_within {
                        let cut = Step {
                            t1: mark.0,
                            y1: at,
                            ..*step
                        };
                        tracker.add(&cut);
                        if samples > 0 {
                            kept.push(cut);
                        }
                        settled = Some(change);
                        return Flow::StopAt(mark.0);
                    }
                    mark = (mark.0 + period, [at[0], at[1]]);
                }
            }
            tracker.add(step);
            if samples > 0 {
                kept.push(*step);
            }
            Flow::Continue
        };
        let settings = if steady_run {
            next_period(settings, tally.steps)
        } else {
            settings
        };
        let done = ode::integrate(rate, t, y, t_end, &settings, observe, budget);
        let done = match done {
            Ok(d) => d,
            Err(Failure::Halted(h)) => {
                return Err(OrbitError::halted(*h, problem.film.reach(), tally));
            }
            Err(Failure::Rate(())) => unreachable!("the orbit's rates do not fail"),
        };
        tally.add(&done);
        let window = tracker.finish();
        if window.max_eccentricity > peak.0 {
            *peak = (window.max_eccentricity, window.time_of_max);
        }
        Ok(Leg {
            t: done.t,
            y: done.y,
            window,
            kept,
            reached,
            settled,
        })
    };
    let (window, kept) = match until {
        Until::Time(end) => {
            let l = leg(t, y, end, None, &mut tally, &mut peak)?;
            (t, y) = (l.t, l.y);
            periods = (end / period).ceil() as u32;
            (l.window, l.kept)
        }
        Until::Eccentricity {
            target,
            horizon,
            settled_within,
        } => {
            let target = Target {
                eccentricity: target,
                settled_within,
            };
            let l = leg(t, y, horizon, Some(target), &mut tally, &mut peak)?;
            (t, y) = (l.t, l.y);
            time_to_target = l.reached.then_some(l.t);
            steady = l.settled.is_some();
            residual = l.settled;
            periods = (l.t / period).ceil() as u32;
            (l.window, l.kept)
        }
        Until::SteadyOrbit {
            tolerance,
            max_periods,
        } => loop {
            let l = leg(t, y, t + period, None, &mut tally, &mut peak)?;
            periods += 1;
            let change = (l.y[0] - y[0]).hypot(l.y[1] - y[1]);
            residual = Some(change);
            (t, y) = (l.t, l.y);
            if change <= tolerance {
                steady = true;
                break (l.window, l.kept);
            }
            if periods >= max_periods {
                break (l.window, l.kept);
            }
        },
    };
    let sampled = sample(&kept, &window, samples);
    let report = SolverReport {
        method: settings.method.name().to_owned(),
        fidelity: crate::fidelity::Level::Standard,
        grid: None,
        iterations: tally.steps,
        iterations_unit: IterationUnit::TimeSteps,
        evaluations: Some(tally.evaluations),
        stop_reason: StopReason::Converged,
        residual,
        error_estimate: None,
        film_solves: None,
        time_integration: Some(Box::new(TimeIntegration {
            rejected_steps: tally.rejected,
            relative_tolerance: relative,
        })),
        elapsed_ms: 0.0,
    };
    Ok(Orbit {
        window: Window {
            samples: sampled,
            ..window
        },
        peak_eccentricity: peak.0,
        time_of_peak: peak.1,
        end: t,
        position: [y[0], y[1]],
        steady,
        periods,
        time_to_target,
        period_residual: residual,
        report,
    })
}

/// `count` samples (τ, x̄, ȳ) at equal times over the window from the kept steps' dense output.
fn sample<const N: usize>(
    steps: &[Step<N>],
    window: &Window,
    count: usize,
) -> Vec<(f64, f64, f64)> {
    if count == 0 || steps.is_empty() {
        return Vec::new();
    }
    let span = window.to - window.from;
    let mut out = Vec::with_capacity(count);
    let mut k = 0;
    for i in 0..count {
        let t = window.from + span * i as f64 / (count - 1).max(1) as f64;
        while k + 1 < steps.len() && steps[k].t1 < t {
            k += 1;
        }
        let y = steps[k].at(t);
        out.push((t, y[0], y[1]));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::calc::journal::moving_film::ShortArc;

    /// Ocvirk's steady load W̄(ε) = ε[16ε² + π²(1 − ε²)]^½/(4(1 − ε²)²) (spec B.1.2).
    fn ocvirk_load(eps: f64) -> f64 {
        let q = 1.0 - eps * eps;
        eps * (16.0 * eps * eps + PI * PI * q).sqrt() / (4.0 * q * q)
    }

    fn ocvirk_eccentricity(load: f64) -> f64 {
        crate::numerics::roots::brent(
            |e| ocvirk_load(e) - load,
            0.0,
            1.0 - 1e-12,
            crate::numerics::roots::Stopping {
                x_tolerance: 1e-15,
                max_iterations: 200,
            },
        )
        .unwrap()
        .x
    }

    fn problem(arc: ShortArc, mass: f64, load: LoadLaw) -> Problem {
        Problem {
            film: OrbitFilm::Short(ShortFilm {
                arc,
                speed_sum: 1.0,
            }),
            mass,
            load,
            force_scale: 1.0,
        }
    }

    fn steady_orbit(p: &Problem, start: [f64; 2], relative: f64) -> Orbit {
        run(
            p,
            Start {
                position: start,
                velocity: [0.0, 0.0],
            },
            Until::SteadyOrbit {
                tolerance: 1e-7,
                max_periods: 400,
            },
            relative,
            0,
            &Budget::unlimited(),
        )
        .unwrap()
    }

    #[test]
    fn a_constant_load_settles_at_ocvirks_equilibrium_with_and_without_mass() {
        // W̄ = 5 downward: ε from Ocvirk, attitude tan ψ = π√(1−ε²)/(4ε) ahead of the load.
        let load = LoadLaw::Constant { force: [0.0, -5.0] };
        let eps = ocvirk_eccentricity(5.0);
        let psi = (PI * (1.0 - eps * eps).sqrt() / (4.0 * eps)).atan();
        for arc in [ShortArc::PiFilm, ShortArc::FixedArc] {
            for mass in [0.0, 0.5] {
                let orbit = steady_orbit(&problem(arc, mass, load.clone()), [0.0, 0.0], 1e-9);
                assert!(orbit.steady, "{arc:?} {mass}");
                let [x, y] = orbit.position;
                assert!(
                    (x.hypot(y) - eps).abs() < 1e-6,
                    "{arc:?} {mass}: {}",
                    x.hypot(y)
                );
                let angle = y.atan2(x);
                assert!((angle - (-0.5 * PI + psi)).abs() < 1e-5, "{arc:?} {mass}");
            }
        }
    }

    #[test]
    fn rotating_loads_give_the_closed_form_circles_and_half_speed_has_no_orbit() {
        // Massless journal under a load turning at s·ω: in the load's frame the film sees the
        // steady bearing at the effective speed (1 − 2s), so |1 − 2s|·W̄_Ocvirk(ε) = F̄.
        for s in [1.0, 0.25] {
            let f = 3.0;
            let load = LoadLaw::Rotating {
                magnitude: f,
                speed_ratio: s,
                start: -0.5 * PI,
            };
            let orbit = steady_orbit(&problem(ShortArc::PiFilm, 0.0, load), [0.0, 0.0], 1e-9);
            let want = ocvirk_eccentricity(f / (1.0f64 - 2.0 * s).abs());
            let w = &orbit.window;
            assert!(orbit.steady, "s = {s}");
            assert!(
                (w.max_eccentricity - want).abs() < 1e-6,
                "s = {s}: {} vs {want}",
                w.max_eccentricity
            );
            assert!((w.min_eccentricity - want).abs() < 1e-6, "a circle");
        }
        let half = LoadLaw::Rotating {
            magnitude: 3.0,
            speed_ratio: 0.5,
            start: -0.5 * PI,
        };
        let reached = run(
            &problem(ShortArc::PiFilm, 0.0, half),
            Start {
                position: [0.0, 0.0],
                velocity: [0.0, 0.0],
            },
            Until::Eccentricity {
                target: 0.95,
                horizon: 2000.0,
                settled_within: 1e-7,
            },
            1e-8,
            0,
            &Budget::unlimited(),
        )
        .unwrap();
        assert!(
            reached.time_to_target.is_some(),
            "half-speed load: the journal spirals out"
        );
    }

    #[test]
    fn a_small_mass_follows_the_mobility_solution() {
        let load = LoadLaw::Sinusoidal {
            steady: 10.0,
            amplitude: 5.0,
            frequency_ratio: 1.0,
            direction: -0.5 * PI,
        };
        let massless = steady_orbit(
            &problem(ShortArc::PiFilm, 0.0, load.clone()),
            [0.0, -0.5],
            1e-9,
        );
        let light = steady_orbit(&problem(ShortArc::PiFilm, 1e-4, load), [0.0, -0.5], 1e-9);
        assert_same_orbit(&massless, &light);
    }

    /// Two steady orbits' ε extremes agree within 10⁻³ and their peak pressures within 1 %.
    fn assert_same_orbit(massless: &Orbit, light: &Orbit) {
        let (a, b) = (&massless.window, &light.window);
        assert!(massless.steady && light.steady);
        assert!(
            (a.max_eccentricity - b.max_eccentricity).abs() < 1e-3,
            "{} {}",
            a.max_eccentricity,
            b.max_eccentricity
        );
        assert!((a.min_eccentricity - b.min_eccentricity).abs() < 1e-3);
        assert!(a.peak_pressure > 0.0 && (a.peak_pressure / b.peak_pressure - 1.0).abs() < 1e-2);
    }

    /// The finite film at L/D = 0.5 on the fast mesh and table, as an orbit's film.
    fn finite_problem(mass: f64, load: LoadLaw) -> Problem {
        use crate::calc::journal::film::Mesh;
        use crate::calc::journal::finite_moving_film::{
            FiniteSqueezeFilm, ImpedanceTable, TableDensity,
        };
        let film = FiniteSqueezeFilm {
            l_over_d: 0.5,
            mesh: Mesh {
                circumferential: 48,
                axial_half: 6,
            },
        };
        let density = TableDensity {
            step: 0.12,
            columns: 36,
            top: 0.995,
        };
        let table = ImpedanceTable::build(film, density, &Budget::unlimited()).unwrap();
        Problem {
            film: OrbitFilm::Finite {
                table: Arc::new(table),
                speed_sum: 1.0,
            },
            mass,
            load,
            force_scale: 1.0,
        }
    }

    #[test]
    fn the_finite_film_turns_a_rotating_load_into_the_steady_films_circle() {
        // Massless journal, load turning at s·ω: in the load's frame the film is the steady
        // bearing at the effective speed (1 − 2s) (spec B.1.3; the squeeze vector is
        // −½(1 − 2s) k × r̄), so the circle's radius is the root of |1 − 2s|·W̄(ε) = F̄ with
        // W̄ the same film's steady force (mirrored when 1 − 2s < 0: the film is symmetric).
        let p = finite_problem(0.0, LoadLaw::Constant { force: [0.0, 0.0] });
        let steady = |e: f64| {
            let r = [e, 0.0];
            let f = p.film.force(r, squeeze_vector(r, [0.0, 0.0], 1.0)).unwrap();
            f[0].hypot(f[1])
        };
        for s in [1.0, 0.25] {
            let f = 2.0;
            let want = crate::numerics::roots::brent(
                |e| (1.0f64 - 2.0 * s).abs() * steady(e) - f,
                1e-9,
                0.99,
                crate::numerics::roots::Stopping {
                    x_tolerance: 1e-14,
                    max_iterations: 200,
                },
            )
            .unwrap()
            .x;
            let load = LoadLaw::Rotating {
                magnitude: f,
                speed_ratio: s,
                start: -0.5 * PI,
            };
            let orbit = steady_orbit(&Problem { load, ..p.clone() }, [0.0, 0.0], 1e-9);
            let w = &orbit.window;
            assert!(orbit.steady, "s = {s}");
            assert!(
                (w.max_eccentricity - want).abs() < 1e-6
                    && (w.min_eccentricity - want).abs() < 1e-6,
                "s = {s}: {} {} vs {want}",
                w.max_eccentricity,
                w.min_eccentricity
            );
        }
    }

    #[test]
    fn a_light_journal_on_the_finite_film_follows_its_mobility_solution() {
        // m̄ → 0: the journal with mass follows the massless (mobility) orbit on the same film.
        let load = LoadLaw::Sinusoidal {
            steady: 10.0,
            amplitude: 5.0,
            frequency_ratio: 1.0,
            direction: -0.5 * PI,
        };
        let massless = steady_orbit(&finite_problem(0.0, load.clone()), [0.0, -0.5], 1e-9);
        let light = steady_orbit(&finite_problem(1e-4, load), [0.0, -0.5], 1e-9);
        assert_same_orbit(&massless, &light);
    }

    #[test]
    fn harnoys_regular_bearing_locus_matches_the_specs_derived_values() {
        // Spec B-R3 (Fig 18-9, regular bearing, book mode): F̄ = 100 + 100 sin 2τ downward,
        // m̄ = 50, from the static equilibrium at F̄ = 100: ε_static 0.9505, ε_max 0.9604,
        // ε_min 0.9059 (derived by the spec with Radau at 1e-9; ±0.5 %).
        let load = LoadLaw::Sinusoidal {
            steady: 100.0,
            amplitude: 100.0,
            frequency_ratio: 2.0,
            direction: -0.5 * PI,
        };
        let eps = ocvirk_eccentricity(100.0);
        assert!((eps - 0.9505).abs() < 5e-4, "{eps}");
        let psi = (PI * (1.0 - eps * eps).sqrt() / (4.0 * eps)).atan();
        let start = [eps * (psi - 0.5 * PI).cos(), eps * (psi - 0.5 * PI).sin()];
        let orbit = steady_orbit(&problem(ShortArc::FixedArc, 50.0, load), start, 1e-9);
        let w = &orbit.window;
        assert!(orbit.steady);
        assert!(
            (w.max_eccentricity / 0.9604 - 1.0).abs() < 5e-3,
            "{}",
            w.max_eccentricity
        );
        assert!(
            (w.min_eccentricity / 0.9059 - 1.0).abs() < 5e-3,
            "{}",
            w.min_eccentricity
        );
    }

    #[test]
    fn a_light_journal_at_loose_tolerances_stays_within_them_of_a_tight_run() {
        // Convergence study: a light journal (m̄ ≈ 0.1, its squeeze damping rate ~500 per
        // radian, so stiff) started off equilibrium under F̄ = 4.97 + 2.49 sin τ. Each tolerance's
        // end state after 30 rad must lie within a few times the tolerance of the 1e-12 run, and
        // ε_max within it. (A Jacobian differenced from the carried last-stage slope instead of
        // a fresh rate once sent 1e-5 and looser runs into contact here.)
        let load = LoadLaw::Sinusoidal {
            steady: 4.97,
            amplitude: 2.49,
            frequency_ratio: 1.0,
            direction: -0.5 * PI,
        };
        let p = problem(ShortArc::PiFilm, 0.098, load);
        let go = |relative: f64| {
            run(
                &p,
                Start {
                    position: [0.3, -0.6],
                    velocity: [0.0, 0.0],
                },
                Until::Time(30.0),
                relative,
                0,
                &Budget::unlimited(),
            )
            .unwrap()
        };
        let reference = go(1e-12);
        for relative in [1e-4, 1e-6, 1e-8] {
            let o = go(relative);
            let [x, y] = o.position;
            let [xr, yr] = reference.position;
            let end = (x - xr).hypot(y - yr);
            let peak = (o.window.max_eccentricity - reference.window.max_eccentricity).abs();
            assert!(
                end < 10.0 * relative && peak < relative,
                "{relative}: {end} {peak}"
            );
        }
    }
}
