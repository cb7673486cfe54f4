//! One pad solved at its operating point: a fixed pad's film (at its load-maximising ratio when
//! asked) or a tilting pad's equilibrium, made dimensional with its effects decided. The pad
//! rooms and the whole bearing share it.
//!
//! Each is solved in its flow regime ([`in_regime`]): laminar, or — where the turbulence effect
//! applies — turbulent at the trailing-edge Reynolds number its own operating point sets.

use std::cell::Cell;

use super::crowned;
use super::long_pad;
use super::operating::{self, Conditions, Given, Operating, TRANSITION_END_REYNOLDS};
use super::performance::{self, evaluate, Evaluated, Method, RATIOS};
use super::pivot::{equilibrium, Equilibrium, Pivot};
use super::profile::Profile;
use crate::calc::turbulence::Flow;
use crate::calc::{Budget, CalcError};
use crate::effects::Mode;
use crate::fidelity::{IterationUnit, SolverReport};
use crate::numerics::driver::{Driver, Verdict};
use crate::numerics::roots::{brent_bracketed, Stopping};

/// A pad at its operating point.
#[derive(Debug, Clone)]
pub struct SolvedPad {
    pub operating: Operating,
    /// h1/h2.
    pub ratio: f64,
    pub evaluated: Evaluated,
    /// The tilting pad's equilibrium.
    pub equilibrium: Option<Equilibrium>,
    /// Evaluations of a search (the optimum ratio, the pivot equilibrium).
    pub evaluations: Option<u32>,
}

impl SolvedPad {
    /// A tilting pad at its equilibrium `eq`, operating as `operating`.
    fn balanced(eq: Equilibrium, operating: Operating) -> SolvedPad {
        SolvedPad {
            operating,
            ratio: eq.ratio,
            evaluated: eq.evaluated.clone(),
            evaluations: Some(eq.evaluations),
            equilibrium: Some(eq),
        }
    }

    /// The solver report: the final film's, with the search's evaluations and the request's
    /// film solves.
    pub fn report(&self, method: Method, budget: &Budget) -> SolverReport {
        let mut report = self.evaluated.report.clone();
        report.evaluations = self.evaluations;
        if matches!(method, Method::LongPad) {
            report
        } else {
            report.with_film_solves(budget.field_solves())
        }
    }
}

/// Refuse an inlet temperature where the lubricant's viscosity law has no value.
fn check_viscosity(c: &Conditions) -> Result<(), CalcError> {
    let mu = c.lubricant.viscosity_pa_s(c.inlet_temperature_c);
    if mu.is_finite() && mu > 0.0 {
        Ok(())
    } else {
        Err(CalcError::impossible(
            "/inlet_temperature_c",
            format!(
                "the lubricant's viscosity law has no finite value at {} °C",
                c.inlet_temperature_c
            ),
        ))
    }
}

/// How a fixed pad's film ratio is chosen.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RatioChoice {
    /// The profile's own ratio.
    Given,
    /// The ratio that maximises W̄.
    Optimum,
    /// A machined depth h1 − h2, m: the ratio is 1 + depth/h2.
    Depth(f64),
}

/// A fixed pad of shape `profile`, its film ratio chosen by `choice`, in its flow regime.
pub fn fixed(
    profile: Profile,
    choice: RatioChoice,
    method: Method,
    c: &Conditions,
    budget: &Budget,
) -> Result<SolvedPad, CalcError> {
    check_viscosity(c)?;
    in_regime(c, budget, |flow| {
        fixed_in(profile, choice, flow, method, c, budget)
    })
}

/// A fixed pad in a given `flow`.
fn fixed_in(
    profile: Profile,
    choice: RatioChoice,
    flow: Flow,
    method: Method,
    c: &Conditions,
    budget: &Budget,
) -> Result<SolvedPad, CalcError> {
    let l_over_b = c.pad.l_over_b();
    let (profile, evaluations) = match choice {
        RatioChoice::Given => (profile, None),
        RatioChoice::Optimum => {
            let (ratio, n) = performance::optimum_ratio(profile, flow, l_over_b, method, budget)?;
            (profile.with_ratio(ratio), Some(n))
        }
        RatioChoice::Depth(depth) => match c.given {
            Given::OutletFilm(h2) => (profile.with_ratio(depth_ratio(depth, h2)?), None),
            Given::Load(_) => return with_depth(profile, depth, flow, method, c, budget),
        },
    };
    at_ratio(profile, flow, evaluations, method, c, budget)
}

/// The pad of a fixed `profile` ratio in a `flow` at its operating point.
fn at_ratio(
    profile: Profile,
    flow: Flow,
    evaluations: Option<u32>,
    method: Method,
    c: &Conditions,
    budget: &Budget,
) -> Result<SolvedPad, CalcError> {
    let l_over_b = c.pad.l_over_b();
    let evaluated = evaluate(profile, flow, l_over_b, method, budget)?;
    let plane = matches!(profile, Profile::PlaneInclined { .. });
    let mut operating = operating::operate(
        &evaluated,
        profile.ratio(),
        long_pad::mean_thickness(profile),
        plane,
        flow,
        c,
    )?;
    warn_long_pad(method, l_over_b, &mut operating);
    Ok(SolvedPad {
        operating,
        ratio: profile.ratio(),
        evaluated,
        equilibrium: None,
        evaluations,
    })
}

/// 1 + depth/h2, inside the film ratios a pad may have.
fn depth_ratio(depth: f64, h2: f64) -> Result<f64, CalcError> {
    let ratio = 1.0 + depth / h2;
    if (RATIOS.0..=RATIOS.1).contains(&ratio) {
        Ok(ratio)
    } else {
        Err(CalcError::impossible(
            "/profile/depth_m",
            format!("a depth of {depth:e} m over a film of {h2:e} m makes h1/h2 = {ratio:.4}, outside [1.01, 10]"),
        ))
    }
}

/// A pad of machined depth d under its load (Khonsari & Booser §7.4's iteration, solved): at
/// viscosity μ the ratio a balances W̄(a) (a − 1)² = W d²/(μ U B² L) — h2 = d/(a − 1) carrying W —
/// a root on a that rises monotonically; with the thermal effect the viscosity's temperature
/// and the ratio are iterated to a fixed point under the driver (the film at μ(T_eff) must give
/// back T_eff).
fn with_depth(
    profile: Profile,
    depth: f64,
    flow: Flow,
    method: Method,
    c: &Conditions,
    budget: &Budget,
) -> Result<SolvedPad, CalcError> {
    let Given::Load(load) = c.given else {
        unreachable!("with_depth is for a given load")
    };
    let (pad, u) = (c.pad, c.sliding_speed_m_s);
    let l_over_b = pad.l_over_b();
    let evaluations = Cell::new(0u32);
    let ratio_at = |mu: f64| -> Result<f64, CalcError> {
        let target = load * depth * depth / (mu * u * pad.breadth_m.powi(2) * pad.length_m);
        let failure = Cell::new(None);
        let balance = |a: f64| match evaluate(profile.with_ratio(a), flow, l_over_b, method, budget)
        {
            Ok(e) => {
                evaluations.set(evaluations.get() + 1);
                e.performance.load * (a - 1.0).powi(2) - target
            }
            Err(e) => {
                failure.set(Some(e));
                0.0
            }
        };
        let (lo, hi) = RATIOS;
        let (at_lo, at_hi) = (balance(lo), balance(hi));
        if let Some(e) = failure.take() {
            return Err(e.into());
        }
        if at_lo > 0.0 || at_hi < 0.0 {
            let which = if at_lo > 0.0 {
                "below 1.01: the depth is too shallow for so light a load"
            } else {
                "above 10: the depth is too deep for so heavy a load"
            };
            return Err(CalcError::impossible(
                "/profile/depth_m",
                format!("with a depth of {depth:e} m this load needs h1/h2 {which}"),
            ));
        }
        let root = brent_bracketed(
            balance,
            (lo, at_lo),
            (hi, at_hi),
            Stopping {
                x_tolerance: 1e-10,
                max_iterations: 100,
            },
        );
        if let Some(e) = failure.take() {
            return Err(e.into());
        }
        Ok(root
            .map_err(|e| CalcError::from_root("thrust_depth_ratio", e))?
            .x)
    };
    let lub = &c.lubricant;
    let mut ratio = ratio_at(lub.viscosity_pa_s(c.inlet_temperature_c))?;
    let mut failure = None;
    let run = Driver::new(
        "thrust_depth_temperature_fixed_point",
        IterationUnit::Evaluations,
        50,
        budget,
    )
    .run(|_| {
        let solved = match at_ratio(profile.with_ratio(ratio), flow, None, method, c, budget) {
            Ok(s) => s,
            Err(e) => {
                failure = Some(e);
                return Verdict::Stalled(f64::NAN);
            }
        };
        if !solved
            .operating
            .notes
            .decisions
            .iter()
            .any(|(name, d)| *name == "thermal" && d.applied)
        {
            return Verdict::Converged(solved, 0.0);
        }
        let next = match ratio_at(lub.viscosity_pa_s(solved.operating.effective_temperature_c)) {
            Ok(r) => r,
            Err(e) => {
                failure = Some(e);
                return Verdict::Stalled(f64::NAN);
            }
        };
        let change = (next - ratio).abs() / ratio;
        ratio = next;
        if change <= 1e-9 {
            Verdict::Converged(solved, change)
        } else {
            Verdict::Continue(change)
        }
    });
    if let Some(e) = failure {
        return Err(e);
    }
    let mut solved = run?.value;
    solved.evaluations = Some(evaluations.get());
    Ok(solved)
}

/// A plane pad, or one crowned by `crown_m` (δ, m), tilting about `pivot`, in its flow
/// regime.
pub fn tilting(
    pivot: Pivot,
    crown_m: Option<f64>,
    method: Method,
    c: &Conditions,
    budget: &Budget,
) -> Result<SolvedPad, CalcError> {
    check_viscosity(c)?;
    match crown_m {
        None => in_regime(c, budget, |flow| tilting_in(pivot, flow, method, c, budget)),
        Some(crown) => in_regime(c, budget, |flow| {
            crowned_in(pivot, crown, flow, method, c, budget)
        }),
    }
}

/// A tilting pad in a given `flow`.
fn tilting_in(
    pivot: Pivot,
    flow: Flow,
    method: Method,
    c: &Conditions,
    budget: &Budget,
) -> Result<SolvedPad, CalcError> {
    let l_over_b = c.pad.l_over_b();
    let eq = equilibrium(
        pivot,
        Profile::PlaneInclined { ratio: 2.0 },
        flow,
        l_over_b,
        method,
        budget,
    )?;
    let profile = Profile::PlaneInclined { ratio: eq.ratio };
    let mut operating = operating::operate(
        &eq.evaluated,
        eq.ratio,
        long_pad::mean_thickness(profile),
        true,
        flow,
        c,
    )?;
    warn_long_pad(method, l_over_b, &mut operating);
    Ok(SolvedPad::balanced(eq, operating))
}

/// A crowned pad tilting about `pivot` in a `flow` ([`crowned::equilibrium`]).
fn crowned_in(
    pivot: Pivot,
    crown: f64,
    flow: Flow,
    method: Method,
    c: &Conditions,
    budget: &Budget,
) -> Result<SolvedPad, CalcError> {
    let (eq, mut operating) = crowned::equilibrium(pivot, crown, flow, method, c, budget)?;
    warn_long_pad(method, c.pad.l_over_b(), &mut operating);
    Ok(SolvedPad::balanced(eq, operating))
}

/// The pad solved by `solve` in its flow regime (Khonsari & Booser §7.11). Laminar first; when
/// the turbulence effect applies at that pad-average Reynolds number (`on`, or `auto` above
/// 580), turbulent: the Ng–Pan film's performance depends on Re₂ = ρ U h2/μ, which the
/// operating point (h2 from the load, μ and ρ at the effective temperature) sets in turn, so
/// Re₂ is the fixed point Re₂ = R(Re₂) of the pad solved at Re₂. Secant steps on
/// g(x) = ln R(eˣ) − x from the laminar Re₂ (a first plain step), under the driver; the map is
/// a contraction (dR/dRe₂ is about ½ well inside turbulence: h2 ∝ √W̄, W̄ ~ Re₂^0.9), so the
/// secant converges in a few pad solves. Off costs nothing: the laminar solve alone.
fn in_regime(
    c: &Conditions,
    budget: &Budget,
    solve: impl Fn(Flow) -> Result<SolvedPad, CalcError>,
) -> Result<SolvedPad, CalcError> {
    let laminar = solve(Flow::Laminar)?;
    let applies = c.effects.turbulence != Mode::Off
        && laminar
            .operating
            .notes
            .decisions
            .iter()
            .any(|(name, d)| *name == "turbulence" && d.applied);
    if !applies {
        return Ok(laminar);
    }
    let mut x = laminar.operating.outlet_reynolds_number.ln();
    let mut previous: Option<(f64, f64)> = None;
    let mut failure = None;
    let run = Driver::new(
        "thrust_turbulent_reynolds_secant",
        IterationUnit::Evaluations,
        50,
        budget,
    )
    .run(|_| {
        let solved = match solve(Flow::Turbulent {
            reference_reynolds: x.exp(),
        }) {
            Ok(s) => s,
            Err(e) => {
                failure = Some(e);
                return Verdict::Stalled(f64::NAN);
            }
        };
        let g = solved.operating.outlet_reynolds_number.ln() - x;
        if g.abs() <= REYNOLDS_TOLERANCE {
            return Verdict::Converged(solved, g.abs());
        }
        let next = match previous {
            Some((xp, gp)) if g != gp => x - g * (x - xp) / (g - gp),
            _ => x + g,
        };
        previous = Some((x, g));
        x = if next.is_finite() { next } else { x + g };
        Verdict::Continue(g.abs())
    });
    if let Some(e) = failure {
        return Err(e);
    }
    let mut solved = run?.value;
    let re = laminar.operating.reynolds_number;
    if re <= TRANSITION_END_REYNOLDS {
        solved.operating.notes.warn(
            "turbulence_transition",
            format!("the laminar pad-average Reynolds number ρ U h_mean/μ = {re:.0} lies in the transition range 580–800 (Khonsari & Booser §7.11): the result is the turbulent film, power loss {:.4e} W against the laminar {:.4e} W; the texts advise expecting the larger", solved.operating.power_loss_w, laminar.operating.power_loss_w),
        );
    }
    Ok(solved)
}

/// |ln R(Re₂) − ln Re₂| at which the turbulent film's Reynolds number is taken as found: the
/// thermal root inside each pad solve leaves about 1e-8 of noise in R, and 1e-7 in Re₂ moves
/// the Ng–Pan factors by under 1e-7.
const REYNOLDS_TOLERANCE: f64 = 1e-7;

/// The infinitely long pad outside its range (B/L ≤ 0.5, Khonsari & Booser §6.5) says so.
fn warn_long_pad(method: Method, l_over_b: f64, operating: &mut Operating) {
    if method == Method::LongPad && l_over_b < 2.0 {
        operating.notes.warn(
            "long_pad_approximation",
            format!("the infinitely long pad ignores side leakage, valid for L/B ≥ 2 (Khonsari & Booser §6.5); at L/B = {l_over_b:.3} it overestimates the load: use a numerical fidelity"),
        );
    }
}
