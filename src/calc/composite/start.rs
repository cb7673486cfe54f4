//! The composite bearing's start-up: the journal's speed ramps from rest, the sleeve first rolls
//! with it, breaks away, and runs down to its steady split (Harnoy ch. 18, §18.2.2–18.2.3 and
//! Eqs. 18-12, 18-13; spec PART B.3 item 5).
//!
//! The text gives no start-up law (spec B.3 item 5): it says the sleeve rolls with the journal
//! while the journal–sleeve friction can pass on the restraint, and slides once it cannot.
//! **The modelling choice made here**, consistent with the full-film torque model of the
//! steady split:
//!
//! 1. *Rolling phase.* From rest the journal rolls inside the sleeve bore like an internal gear
//!    (R₁ ≈ R, Eq. 18-2): ω_b = ω_j. To keep the sleeve unit with the journal the contact must
//!    pass the restraint and the sleeve's acceleration, T_req = k ω_j² + M_r + I_eq dω_j/dt.
//!    It can pass at most T_t = f_t W R: the load W pressing journal on sleeve, times a
//!    journal–sleeve traction (static friction) coefficient f_t, an input — the boundary and
//!    mixed friction of the text's Fig 18-4, of which it gives no number.
//! 2. *Break-away* is the first instant T_req > T_t. With the linear ramp ω_j = a t (a =
//!    ω_J/t_r) it is t* = √((T_t − M_r − I_eq a)/k)/a, or 0 when T_t ≤ M_r + I_eq a. If
//!    t* ≥ t_r the sleeve never breaks away (at the ramp's end T_req drops by I_eq a): it rolls
//!    on at the journal's speed, and the steady split is not reached (a warning says so).
//! 3. *Sliding phase.* From ω_b(t*) = ω_j(t*) the full film carries the load and drives the
//!    sleeve: I_eq dω_b/dt = M_h − M_f − M_r (Eq. 18-12 with M_r kept), with the quasi-steady
//!    torque M_h = 2n(ε)(ω_j − ω_b) of Eq. 18-3, M_f = k ω_b|ω_b| (−ξ|ξ|H₂, spec B.3 item 4) and
//!    M_r a Coulomb torque (regularised over |ω_b| < 1e-6 ω_J so the sleeve can stand). ε
//!    follows the load quasi-steadily at the current speed sum ω_j + ω_b (the speed split's
//!    load search; held at 0.999 where the full film cannot carry the load, with a warning).
//!    No return to rolling is modelled: a sliding sleeve needs slip to be driven at all.
//!
//! In the text's dimensionless form the sliding phase is dξ/dt̄ = (1 − ξ)H₁ 2π/√(1 − ε²) −
//! ξ|ξ|H₂ with H₁ = LμR³/(C I_eq ω_j) and H₂ = k/I_eq (Eq. 18-16 with I_eq restored), at a
//! constant journal speed.

use nalgebra::SVector;

use super::film::{LoadError, SleeveFilm, MAX_ECCENTRICITY};
use super::sleeve::Restraint;
use super::split::{split, Operating};
use crate::calc::CalcError;
use crate::fidelity::{SolverReport, TimeIntegration};
use crate::numerics::driver::Budget;
use crate::numerics::ode::{self, Failure, Flow, Method, RateError, Settings, Step};

/// The integrator's tolerances on the sleeve speed over the final journal speed.
const RELATIVE_TOLERANCE: f64 = 1e-8;
const ABSOLUTE_TOLERANCE: f64 = 1e-10;
/// The settling band: ±1 % of the steady sleeve speed.
const BAND: f64 = 0.01;
/// Time constants per settling segment, and the most segments before the run gives up.
const SEGMENT_TIME_CONSTANTS: f64 = 20.0;
const MAX_SEGMENTS: u32 = 50;

/// A start-up: the bearing, its load, the journal's ramp and the sleeve unit's inertia.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StartUp {
    pub film: SleeveFilm,
    pub restraint: Restraint,
    /// W, N.
    pub load: f64,
    /// The journal's final speed ω_J, rad/s.
    pub journal_speed: f64,
    /// t_r, s: ω_j = ω_J t/t_r until t_r, ω_J after.
    pub ramp_time: f64,
    /// I_eq, kg·m².
    pub inertia: f64,
    /// f_t, dimensionless.
    pub traction_coefficient: f64,
}

/// When the rolling phase ends.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Breakaway {
    /// At t = 0: the contact cannot even start the sleeve with the journal.
    AtStart,
    /// At t* ∈ (0, t_r).
    At(f64),
    /// Never: the sleeve rolls at the journal's speed throughout.
    Never,
}

impl Breakaway {
    /// t*, s, where the sleeve breaks away.
    pub fn time(self) -> Option<f64> {
        match self {
            Breakaway::AtStart => Some(0.0),
            Breakaway::At(t) => Some(t),
            Breakaway::Never => None,
        }
    }
}

/// ε at a speed sum, and whether the full film could not carry the load there (ε held at
/// [`MAX_ECCENTRICITY`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct QuasiSteadyFilm {
    pub eccentricity: f64,
    pub beyond_full_film: bool,
}

impl StartUp {
    /// The ramp's angular acceleration a = ω_J/t_r, rad/s².
    pub fn ramp_rate(&self) -> f64 {
        self.journal_speed / self.ramp_time
    }

    /// ω_j(t), rad/s.
    pub fn journal_speed_at(&self, t: f64) -> f64 {
        self.journal_speed * (t / self.ramp_time).clamp(0.0, 1.0)
    }

    /// T_t = f_t W R, N·m: the most the rolling contact passes to the sleeve.
    pub fn transmissible_torque(&self) -> f64 {
        self.traction_coefficient * self.load * self.film.radius
    }

    /// T_req at t < t_r, N·m: what keeps the sleeve rolling with the journal.
    pub fn required_torque(&self, t: f64) -> f64 {
        let w = self.journal_speed_at(t);
        let accel = if t < self.ramp_time {
            self.ramp_rate()
        } else {
            0.0
        };
        self.restraint.pin_torque(w) + self.restraint.rolling_torque + self.inertia * accel
    }

    /// The end of the rolling phase (item 2 of the module doc).
    pub fn breakaway(&self) -> Breakaway {
        let a = self.ramp_rate();
        let spare = self.transmissible_torque() - self.restraint.rolling_torque - self.inertia * a;
        if spare < 0.0 {
            return Breakaway::AtStart;
        }
        let t = (spare / self.restraint.coefficient).sqrt() / a;
        if t < self.ramp_time {
            Breakaway::At(t)
        } else {
            Breakaway::Never
        }
    }

    /// ε of the full film carrying the load at the speed sum ω_j + ω_b, rad/s.
    pub fn film_at(&self, speed_sum: f64) -> Result<QuasiSteadyFilm, LoadError> {
        if speed_sum <= 0.0 {
            return Ok(QuasiSteadyFilm {
                eccentricity: MAX_ECCENTRICITY,
                beyond_full_film: true,
            });
        }
        match self
            .film
            .eccentricity_for(self.load, MAX_ECCENTRICITY, |_| speed_sum)
        {
            Ok(found) => Ok(QuasiSteadyFilm {
                eccentricity: found.eccentricity,
                beyond_full_film: false,
            }),
            Err(LoadError::TooHeavy { .. }) => Ok(QuasiSteadyFilm {
                eccentricity: MAX_ECCENTRICITY,
                beyond_full_film: true,
            }),
            Err(e) => Err(e),
        }
    }

    /// Half-width of the band where the rolling bearing's Coulomb torque is regularised, rad/s.
    fn stick_speed(&self) -> f64 {
        1e-6 * self.journal_speed
    }

    /// dω_b/dt in the sliding phase at time t and sleeve speed ω_b, rad/s² (item 3).
    pub fn sleeve_acceleration(&self, t: f64, sleeve_speed: f64) -> Result<f64, LoadError> {
        let wj = self.journal_speed_at(t);
        let film = self.film_at(wj + sleeve_speed)?;
        let m_h = self.film.torque(film.eccentricity, wj, sleeve_speed);
        let coulomb = (sleeve_speed / self.stick_speed()).clamp(-1.0, 1.0);
        let net =
            m_h - self.restraint.pin_torque(sleeve_speed) - self.restraint.rolling_torque * coulomb;
        Ok(net / self.inertia)
    }
}

/// One point of the start-up.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    /// s.
    pub time: f64,
    /// ω_j, rad/s.
    pub journal_speed: f64,
    /// ω_b, rad/s.
    pub sleeve_speed: f64,
}

/// A simulated start-up.
#[derive(Debug, Clone, PartialEq)]
pub struct Simulation {
    pub breakaway: Breakaway,
    /// The rolling film at break-away (load on 2ω_j).
    pub film_at_breakaway: Option<QuasiSteadyFilm>,
    /// ω_b at the final journal speed, rad/s: the speed split's, or ω_J when the sleeve rolls
    /// on.
    pub steady_sleeve_speed: f64,
    pub steady_eccentricity: f64,
    /// ω_b at t_r, rad/s.
    pub sleeve_speed_at_ramp_end: f64,
    /// The time after which ω_b stays within ±1 % of the steady speed (its last crossing of
    /// the band's edge), s.
    pub settling_time: Option<f64>,
    /// Where the run ends, s.
    pub end_time: f64,
    /// Evenly spaced in time over [0, `end_time`].
    pub history: Vec<Sample>,
    pub warnings: Vec<(&'static str, String)>,
    pub report: SolverReport,
}

/// Why a start-up has no result.
#[derive(Debug, Clone, PartialEq)]
pub enum StartError {
    /// The film cannot carry the load at the final speed (or a search failed).
    Load(LoadError),
    /// The integration stopped (deadline, cap, step underflow) or did not settle.
    Calc(CalcError),
}

/// The sliding phase's record: the integrator's accepted steps, in time order.
struct Record {
    steps: Vec<Step<1>>,
}

impl Record {
    /// ω_b/ω_J at t within the recorded span (the step's Hermite interpolant).
    fn at(&self, t: f64) -> Option<f64> {
        let i = self.steps.partition_point(|s| s.t1 < t);
        self.steps.get(i).map(|s| s.at(t)[0])
    }

    /// The time after which the speed (over ω_J) stays in [target − band, target + band]: the
    /// last crossing of the band's edge, found in the last step that is outside anywhere, by
    /// bisection on its interpolant. None when the record ends outside the band.
    fn settling_time(&self, target: f64, band: f64, entered_rolling: f64) -> Option<f64> {
        let outside = |y: f64| (y - target).abs() > band;
        let last = self.steps.last()?;
        if outside(last.y1[0]) {
            return None;
        }
        // A step is probed at its ends and at eight interior points.
        let probe = |s: &Step<1>| {
            (0..=9).any(|k| outside(s.at(s.t0 + (s.t1 - s.t0) * f64::from(k) / 9.0)[0]))
        };
        match self.steps.iter().rposition(probe) {
            None => Some(entered_rolling),
            Some(i) => {
                let s = &self.steps[i];
                // The crossing from outside to inside within s: bisect on the interpolant
                // from its last outside probe.
                let (mut lo, mut hi) = (s.t0, s.t1);
                for k in (0..=9).rev() {
                    let t = s.t0 + (s.t1 - s.t0) * f64::from(k) / 9.0;
                    if outside(s.at(t)[0]) {
                        lo = t;
                        hi = (t + (s.t1 - s.t0) / 9.0).min(s.t1);
                        break;
                    }
                }
                for _ in 0..60 {
                    let mid = 0.5 * (lo + hi);
                    if outside(s.at(mid)[0]) {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                Some(hi)
            }
        }
    }
}

/// Add one integration's work to the run's report.
fn accumulate(total: &mut Option<SolverReport>, part: SolverReport) {
    match total {
        None => *total = Some(part),
        Some(t) => {
            t.iterations += part.iterations;
            t.evaluations = Some(t.evaluations.unwrap_or(0) + part.evaluations.unwrap_or(0));
            let rejected =
                |r: &SolverReport| r.time_integration.as_ref().map_or(0, |x| x.rejected_steps);
            let sum = rejected(t) + rejected(&part);
            t.time_integration = Some(Box::new(TimeIntegration {
                rejected_steps: sum,
                relative_tolerance: RELATIVE_TOLERANCE,
            }));
            t.residual = part.residual;
            t.stop_reason = part.stop_reason;
        }
    }
}

/// Simulate the start-up (module doc: the rolling phase in closed form, the sliding phase on
/// the L-stable SDIRK integrator) and sample `samples` points of its history.
pub fn simulate(s: &StartUp, budget: &Budget, samples: usize) -> Result<Simulation, StartError> {
    let steady = split(
        &s.film,
        &s.restraint,
        s.journal_speed,
        Operating::Load(s.load),
    )
    .map_err(StartError::Load)?;
    let wj = s.journal_speed;
    let breakaway = s.breakaway();
    let mut warnings = Vec::new();
    let film_at_breakaway = match breakaway.time() {
        Some(t) => {
            let film = s
                .film_at(2.0 * s.journal_speed_at(t))
                .map_err(StartError::Load)?;
            if film.beyond_full_film {
                warnings.push((
                    "breakaway_before_full_film",
                    format!(
                        "at break-away (journal {:.1} rpm) the rolling film cannot carry the load even at ε = {MAX_ECCENTRICITY}: the journal and sleeve still touch (mixed lubrication); the sliding phase holds ε at {MAX_ECCENTRICITY} until the speed sum lifts the journal",
                        s.journal_speed_at(t) * 30.0 / std::f64::consts::PI
                    ),
                ));
            }
            Some(film)
        }
        None => None,
    };
    let Some(t_break) = breakaway.time() else {
        // The sleeve rolls throughout: ω_b = ω_j, in closed form.
        let end = 1.25 * s.ramp_time;
        let film = s.film_at(2.0 * wj).map_err(StartError::Load)?;
        warnings.push((
            "sleeve_rolls_on",
            format!(
                "the rolling contact passes up to f_t W R = {:.4e} N·m, more than keeps the sleeve rolling at full speed ({:.4e} N·m): the sleeve never slides, and the speed split's sliding state (ξ = {:.4}) is not reached from rest",
                s.transmissible_torque(),
                s.required_torque(s.ramp_time),
                steady.composite.speed_ratio
            ),
        ));
        let history = (0..samples)
            .map(|k| {
                let t = end * k as f64 / (samples - 1) as f64;
                let w = s.journal_speed_at(t);
                Sample {
                    time: t,
                    journal_speed: w,
                    sleeve_speed: w,
                }
            })
            .collect();
        return Ok(Simulation {
            breakaway,
            film_at_breakaway,
            steady_sleeve_speed: wj,
            steady_eccentricity: film.eccentricity,
            sleeve_speed_at_ramp_end: wj,
            settling_time: None,
            end_time: end,
            history,
            warnings,
            report: SolverReport::closed_form("composite_rolling_start"),
        });
    };

    let target = steady.composite.speed_ratio;
    let band = BAND * if target > 0.0 { target } else { 1.0 };
    let n_ss = s.film.petroff_coefficient(steady.composite.eccentricity);
    let tau = s.inertia / (2.0 * n_ss + 2.0 * s.restraint.coefficient * target * wj);
    let mut beyond_full_film = false;
    let mut rate = |t: f64, y: &SVector<f64, 1>| -> Result<SVector<f64, 1>, RateError<LoadError>> {
        let wb = y[0] * wj;
        let film = s
            .film_at(s.journal_speed_at(t) + wb)
            .map_err(RateError::Failed)?;
        beyond_full_film |= film.beyond_full_film;
        let a = s.sleeve_acceleration(t, wb).map_err(RateError::Failed)?;
        Ok(SVector::<f64, 1>::new(a / wj))
    };
    let mut record = Record { steps: Vec::new() };
    let mut report: Option<SolverReport> = None;
    let mut t = t_break;
    let mut y = SVector::<f64, 1>::new(s.journal_speed_at(t_break) / wj);
    let mut run = |from: f64,
                   y0: SVector<f64, 1>,
                   to: f64,
                   record: &mut Record,
                   report: &mut Option<SolverReport>|
     -> Result<SVector<f64, 1>, StartError> {
        // The sleeve's scalar equation is mildly stiff: SDIRK's single N × N stages suffice.
        let settings = Settings {
            method: Method::Sdirk4,
            relative: RELATIVE_TOLERANCE,
            absolute: ABSOLUTE_TOLERANCE,
            max_step: (to - from) / 20.0,
            max_steps: 100_000,
        };
        let observe = |step: &Step<1>| {
            record.steps.push(*step);
            Flow::Continue
        };
        match ode::integrate(&mut rate, from, y0, to, &settings, observe, budget) {
            Ok(done) => {
                accumulate(report, done.report);
                Ok(done.y)
            }
            Err(Failure::Rate(e)) => Err(StartError::Load(e)),
            Err(Failure::Halted(h)) => Err(StartError::Calc(CalcError::from(h.stopped))),
        }
    };
    if t < s.ramp_time {
        y = run(t, y, s.ramp_time, &mut record, &mut report)?;
        t = s.ramp_time;
    }
    let at_ramp_end = y[0] * wj;
    let mut segments = 0;
    loop {
        let to = t + SEGMENT_TIME_CONSTANTS * tau;
        y = run(t, y, to, &mut record, &mut report)?;
        t = to;
        segments += 1;
        if (y[0] - target).abs() <= 0.1 * band {
            break;
        }
        if segments >= MAX_SEGMENTS {
            return Err(StartError::Calc(CalcError::impossible(
                "/sleeve_inertia_kg_m2",
                format!(
                    "the sleeve has not settled within {:.4e} s ({} time constants of {tau:.4e} s): its speed is {:.4e} rpm against a steady {:.4e} rpm",
                    t - t_break,
                    f64::from(MAX_SEGMENTS) * SEGMENT_TIME_CONSTANTS,
                    y[0] * wj * 30.0 / std::f64::consts::PI,
                    target * wj * 30.0 / std::f64::consts::PI
                ),
            )));
        }
    }
    if beyond_full_film {
        warnings.push((
            "film_held_at_limit",
            format!("for part of the sliding phase the full film could not carry the load at the speed sum: ε was held at {MAX_ECCENTRICITY} there (the journal touches the sleeve in reality)"),
        ));
    }
    // Inside the band from break-away on: the rolling speed t/t_r entered it at its lower edge.
    let entered_rolling = ((target - band).max(0.0) * s.ramp_time).min(t_break);
    let settling_time = record.settling_time(target, band, entered_rolling);
    let end = t;
    let history = (0..samples)
        .map(|k| {
            let time = end * k as f64 / (samples - 1) as f64;
            let journal = s.journal_speed_at(time);
            let sleeve = if time <= t_break {
                journal
            } else {
                record.at(time).map_or(y[0], |v| v) * wj
            };
            Sample {
                time,
                journal_speed: journal,
                sleeve_speed: sleeve,
            }
        })
        .collect();
    let report = report
        .expect("at least one segment ran")
        .named("sdirk4_l_stable");
    Ok(Simulation {
        breakaway,
        film_at_breakaway,
        steady_sleeve_speed: target * wj,
        steady_eccentricity: steady.composite.eccentricity,
        sleeve_speed_at_ramp_end: at_ramp_end,
        settling_time,
        end_time: end,
        history,
        warnings,
        report,
    })
}

#[cfg(test)]
mod tests {
    use std::f64::consts::PI;

    use super::*;
    use crate::calc::composite::split::{split, Operating};

    fn start(traction: f64, rolling_torque: f64) -> StartUp {
        StartUp {
            film: SleeveFilm {
                radius: 0.05,
                length: 0.1,
                clearance: 6e-5,
                viscosity: 0.03,
            },
            restraint: Restraint {
                coefficient: 0.0357,
                rolling_torque,
            },
            load: 20_000.0,
            journal_speed: 3500.0 * PI / 30.0,
            ramp_time: 2.0,
            inertia: 0.01,
            traction_coefficient: traction,
        }
    }

    /// At t* the required torque equals the transmissible one; before it, it is below.
    #[test]
    fn breakaway_is_where_the_contact_cannot_pass_the_restraint() {
        for (f, m_r) in [(0.005, 0.0), (0.01, 1.0), (0.008, 0.5)] {
            let s = start(f, m_r);
            match s.breakaway() {
                Breakaway::At(t) => {
                    let (need, can) = (s.required_torque(t), s.transmissible_torque());
                    assert!(
                        (need / can - 1.0).abs() < 1e-12,
                        "{f} {m_r}: {need} vs {can}"
                    );
                    assert!(s.required_torque(0.9 * t) < can);
                    assert!(t > 0.0 && t < s.ramp_time);
                }
                other => panic!("{f} {m_r}: {other:?}"),
            }
        }
    }

    /// No traction to speak of: break-away at once; ample traction: the sleeve rolls on.
    #[test]
    fn the_two_limits_of_the_rolling_phase() {
        let s = start(1e-9, 0.0);
        assert_eq!(s.breakaway(), Breakaway::AtStart);
        let s = start(10.0, 0.0);
        assert_eq!(s.breakaway(), Breakaway::Never);
        assert!(s.required_torque(s.ramp_time) < s.transmissible_torque());
    }

    /// The sliding phase's rest point at the final speed is the speed split's steady state
    /// under the same load: the acceleration vanishes there and changes sign about it.
    #[test]
    fn the_sliding_phase_rests_at_the_speed_split() {
        for m_r in [0.0, 3.0] {
            let s = start(0.002, m_r);
            let steady = split(
                &s.film,
                &s.restraint,
                s.journal_speed,
                Operating::Load(s.load),
            )
            .unwrap();
            let wb = steady.composite.speed_ratio * s.journal_speed;
            let t = 2.0 * s.ramp_time;
            let at = s.sleeve_acceleration(t, wb).unwrap();
            let scale = s
                .film
                .torque(steady.composite.eccentricity, s.journal_speed, 0.0)
                / s.inertia;
            assert!(at.abs() < 1e-9 * scale, "{m_r}: {at} vs {scale}");
            assert!(s.sleeve_acceleration(t, 1.01 * wb).unwrap() < 0.0);
            assert!(s.sleeve_acceleration(t, 0.99 * wb).unwrap() > 0.0);
        }
    }

    /// The text's dimensionless sleeve equation (Eq. 18-14 with H₂ = k/I_eq, spec B.1.4) is the
    /// same law: dξ/dt̄ = (1 − ξ)H₁ 2π/√(1 − ε²) − ξ|ξ|H₂ at a constant journal speed.
    #[test]
    fn the_dimensionless_form_agrees() {
        let s = start(0.002, 0.0);
        let (wj, t) = (s.journal_speed, 3.0 * s.ramp_time);
        let f = s.film;
        let h1 = f.length * f.viscosity * f.radius.powi(3) / (f.clearance * s.inertia * wj);
        let h2 = s.restraint.coefficient / s.inertia;
        for xi in [0.05, 0.3, 0.7] {
            let eps = s.film_at(wj * (1.0 + xi)).unwrap().eccentricity;
            let text = (1.0 - xi) * h1 * 2.0 * PI / (1.0 - eps * eps).sqrt() - xi * xi.abs() * h2;
            let ours = s.sleeve_acceleration(t, xi * wj).unwrap() / (wj * wj);
            assert!(
                (ours / text - 1.0).abs() < 1e-12,
                "ξ {xi}: {ours} vs {text}"
            );
        }
    }
}
