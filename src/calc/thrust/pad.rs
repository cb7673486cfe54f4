//! One pad solved at its operating point: a fixed pad's film (at its load-maximising ratio when
//! asked) or a tilting pad's equilibrium, made dimensional with its effects decided. The pad
//! rooms and the whole bearing share it.
//!
//! Each is solved in its flow regime ([`in_regime`]): laminar, or — where the turbulence effect
//! applies — turbulent at the trailing-edge Reynolds number its own operating point sets.

use std::cell::Cell;

use super::crowned;
use super::long_pad;
use super::operating::{
    self, Conditions, Given, Operating, TurbulenceLaw, TRANSITION_END_REYNOLDS, TURBULENT_REYNOLDS,
};
use super::performance::{self, evaluate, Evaluated, Method, RATIOS};
use super::pivot::{equilibrium, Equilibrium, Pivot};
use super::profile::Profile;
use crate::calc::turbulence::{missana_friction_factor, Flow};
use crate::calc::{Budget, CalcError};
use crate::effects::{Criterion, Decision, Mode};
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
    let mu = c.viscosity_pa_s(c.inlet_temperature_c);
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

/// A fixed pad of shape `profile`, its film ratio chosen by `choice`, in its flow regime;
/// with `crown` (δ, m) a plane pad crowned as a tilting pad is ([`Profile::Crowned`]), at its
/// given film ratio.
pub fn fixed(
    profile: Profile,
    choice: RatioChoice,
    crown: Option<f64>,
    method: Method,
    c: &Conditions,
    budget: &Budget,
) -> Result<SolvedPad, CalcError> {
    check_viscosity(c)?;
    in_regime(c, budget, |flow, c| match crown {
        None => fixed_in(profile, choice, flow, method, c, budget),
        Some(crown) => crowned_fixed_in(profile.ratio(), crown, flow, method, c, budget),
    })
}

/// A fixed plane pad of film ratio `ratio` crowned by `crown` (δ, m) in a `flow`: the crown
/// ratio k = δ/h2 is known from a given film; under a given load it is the unknown
/// ([`Machined::Crown`]).
fn crowned_fixed_in(
    ratio: f64,
    crown: f64,
    flow: Flow,
    method: Method,
    c: &Conditions,
    budget: &Budget,
) -> Result<SolvedPad, CalcError> {
    match c.given {
        Given::OutletFilm(h2) => {
            let profile = Profile::Crowned {
                ratio,
                crown: crown / h2,
            };
            if profile.minimum() <= 0.0 {
                return Err(CalcError::impossible(
                    "/crown_m",
                    format!("a crown of {crown:e} m over a trailing-edge film of {h2:e} m at h1/h2 = {ratio} touches the runner: δ/h2 must stay below (√(h1/h2) + 1)²/4 = {:.4}", crown_touching(ratio)),
                ));
            }
            at_ratio(profile, flow, None, method, c, budget)
        }
        Given::Load(_) => with_machined(Machined::Crown { ratio, crown }, flow, method, c, budget),
    }
}

/// The crown ratio δ/h2 at which a crowned pad of film ratio a first touches the runner:
/// the minimum of h̄ = a − (a − 1) x̄ − 4 k x̄(1 − x̄), a − (a − 1 + 4k)²/(16k) at the vertex, is
/// zero at k = (√a + 1)²/4 (the other root, (√a − 1)²/4, puts the vertex off the pad).
pub fn crown_touching(ratio: f64) -> f64 {
    (ratio.sqrt() + 1.0).powi(2) / 4.0
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
            Given::Load(_) => {
                return with_machined(Machined::Depth { profile, depth }, flow, method, c, budget)
            }
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

/// A length fixed in metres that sets a fixed pad's film under its load: the machined depth
/// d = h1 − h2 (the film ratio a is the unknown, h2 = d/(a − 1)) or the crown δ at a given
/// ratio (u = ln(δ/h2) is the unknown, h2 = δ/eᵘ).
#[derive(Debug, Clone, Copy)]
enum Machined {
    Depth { profile: Profile, depth: f64 },
    Crown { ratio: f64, crown: f64 },
}

/// The thinnest crown ratio δ/h2 searched under a load (a crown of 1e-14 of the film is a flat
/// pad to round-off).
const CROWN_RATIO_MIN: f64 = 1e-14;

impl Machined {
    /// d or δ, m.
    fn length(self) -> f64 {
        match self {
            Machined::Depth { depth, .. } => depth,
            Machined::Crown { crown, .. } => crown,
        }
    }

    /// The unknown's bracket: the film ratios a pad may have; ln k from [`CROWN_RATIO_MIN`] to
    /// 1 % short of the crown that touches the runner ([`crown_touching`]).
    fn bracket(self) -> (f64, f64) {
        match self {
            Machined::Depth { .. } => RATIOS,
            Machined::Crown { ratio, .. } => {
                (CROWN_RATIO_MIN.ln(), (0.99 * crown_touching(ratio)).ln())
            }
        }
    }

    /// The film at the unknown `s`, and h2/length there.
    fn at(self, s: f64) -> (Profile, f64) {
        match self {
            Machined::Depth { profile, .. } => (profile.with_ratio(s), 1.0 / (s - 1.0)),
            Machined::Crown { ratio, .. } => (
                Profile::Crowned {
                    ratio,
                    crown: s.exp(),
                },
                (-s).exp(),
            ),
        }
    }

    /// The refusal when the load cannot be balanced in the bracket (`light`: even its low end
    /// carries more).
    fn refusal(self, light: bool) -> CalcError {
        match self {
            Machined::Depth { depth, .. } => {
                let which = if light {
                    "below 1.01: the depth is too shallow for so light a load"
                } else {
                    "above 10: the depth is too deep for so heavy a load"
                };
                CalcError::impossible(
                    "/profile/depth_m",
                    format!("with a depth of {depth:e} m this load needs h1/h2 {which}"),
                )
            }
            Machined::Crown { ratio, crown } => {
                let why = if light {
                    format!("the load is so light that the film exceeds {:e} times the crown: the crown is lost in it (omit crown_m)", 1.0 / CROWN_RATIO_MIN)
                } else {
                    format!("the load needs a film so thin that the crown touches the runner (δ/h2 reaches 0.99 × (√(h1/h2) + 1)²/4 = {:.4}): lower the crown or the load, or raise the film ratio", 0.99 * crown_touching(ratio))
                };
                CalcError::impossible(
                    "/crown_m",
                    format!("a crown of {crown:e} m at h1/h2 = {ratio}: {why}"),
                )
            }
        }
    }
}

/// A fixed pad whose film is set by a length fixed in metres under its load (Khonsari &
/// Booser §7.4's iteration for a machined depth, Ex 7.1, solved; a crown likewise): at
/// viscosity μ the unknown s balances W̄(s) (length/h2(s))² = W length²/(μ U B² L) — h2 carrying
/// W — a bracketed root (W̄ h2⁻² rises as the film thins); with the thermal effect the
/// viscosity's temperature and s are iterated to a fixed point under the driver (the film at
/// μ(T_eff) must give back T_eff).
fn with_machined(
    machined: Machined,
    flow: Flow,
    method: Method,
    c: &Conditions,
    budget: &Budget,
) -> Result<SolvedPad, CalcError> {
    let Given::Load(load) = c.given else {
        unreachable!("with_machined is for a given load")
    };
    let (pad, u) = (c.pad, c.sliding_speed_m_s);
    let l_over_b = pad.l_over_b();
    let length = machined.length();
    let evaluations = Cell::new(0u32);
    let unknown_at = |mu: f64| -> Result<f64, CalcError> {
        let target = load * length * length / (mu * u * pad.breadth_m.powi(2) * pad.length_m);
        let failure = Cell::new(None);
        let balance = |s: f64| {
            let (profile, film) = machined.at(s);
            match evaluate(profile, flow, l_over_b, method, budget) {
                Ok(e) => {
                    evaluations.set(evaluations.get() + 1);
                    e.performance.load / film.powi(2) - target
                }
                Err(e) => {
                    failure.set(Some(e));
                    0.0
                }
            }
        };
        let (lo, hi) = machined.bracket();
        let (at_lo, at_hi) = (balance(lo), balance(hi));
        if let Some(e) = failure.take() {
            return Err(e.into());
        }
        if at_lo > 0.0 || at_hi < 0.0 {
            return Err(machined.refusal(at_lo > 0.0));
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
            .map_err(|e| match machined {
                Machined::Depth { .. } => CalcError::from_root("thrust_depth_ratio", e),
                Machined::Crown { .. } => CalcError::from_root("thrust_crown_ratio", e),
            })?
            .x)
    };
    let mut unknown = unknown_at(c.viscosity_pa_s(c.inlet_temperature_c))?;
    let mut failure = None;
    let driver = match machined {
        Machined::Depth { .. } => Driver::new(
            "thrust_depth_temperature_fixed_point",
            IterationUnit::Evaluations,
            50,
            budget,
        ),
        Machined::Crown { .. } => Driver::new(
            "thrust_crown_temperature_fixed_point",
            IterationUnit::Evaluations,
            50,
            budget,
        ),
    };
    let run = driver.run(|_| {
        let solved = match at_ratio(machined.at(unknown).0, flow, None, method, c, budget) {
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
        let next = match unknown_at(c.viscosity_pa_s(solved.operating.effective_temperature_c)) {
            Ok(r) => r,
            Err(e) => {
                failure = Some(e);
                return Verdict::Stalled(f64::NAN);
            }
        };
        // Relative in a (≥ 1.01), absolute in ln k near k = 1.
        let change = (next - unknown).abs() / unknown.abs().max(1.0);
        unknown = next;
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
        None => in_regime(c, budget, |flow, c| {
            tilting_in(pivot, flow, method, c, budget)
        }),
        Some(crown) => in_regime(c, budget, |flow, c| {
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
    solve: impl Fn(Flow, &Conditions) -> Result<SolvedPad, CalcError>,
) -> Result<SolvedPad, CalcError> {
    let laminar = solve(Flow::Laminar, c)?;
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
    if c.effects.turbulence_law == TurbulenceLaw::Missana {
        return missana(laminar, c, solve);
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
        let solved = match solve(
            Flow::Turbulent {
                reference_reynolds: x.exp(),
            },
            c,
        ) {
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

/// The texts' empirical turbulent pad (Khonsari & Booser §7.11): at the `laminar` pad's
/// pad-average Re = ρ U h_mean/μ the friction factor f = 0.026/Re^0.25 (Eq. 7.20) gives the
/// power loss E_t = f (ρ U²/2) U B L (Eq. 7.17); where E_t exceeds the laminar loss by X, the
/// pad is solved again laminar at the viscosity × (1 + X), the texts' "effective" viscosity for
/// Table 7.2's film and flows, and carries E_t as its power loss (friction E_t/U, rise
/// E_t/(ρ c_p Q₁)). One step, as the texts take it: a rough approximation, they say, which is
/// why Ng–Pan's film stays the default.
fn missana(
    laminar: SolvedPad,
    c: &Conditions,
    solve: impl Fn(Flow, &Conditions) -> Result<SolvedPad, CalcError>,
) -> Result<SolvedPad, CalcError> {
    let op = &laminar.operating;
    let re = op.reynolds_number;
    let f = missana_friction_factor(re);
    let u = c.sliding_speed_m_s;
    let rho = c.lubricant.density_kg_m3(op.effective_temperature_c);
    let empirical = f * 0.5 * rho * u * u * u * c.pad.area_m2();
    let factor = (empirical / op.power_loss_w).max(1.0);
    let thick = Conditions {
        viscosity_factor: c.viscosity_factor * factor,
        ..c.clone()
    };
    let mut solved = solve(Flow::Laminar, &thick)?;
    let o = &mut solved.operating;
    let t = o.effective_temperature_c;
    let heat = c.lubricant.density_kg_m3(t) * c.lubricant.specific_heat_j_kg_k(t);
    // The larger of the two losses is the one to expect (§7.11).
    let power = empirical.max(o.power_loss_w);
    o.power_loss_w = power;
    o.friction_force_n = power / u;
    o.temperature_rise_k = power / (heat * o.inlet_flow_m3_s);
    // The Reynolds numbers are the real oil's (the criterion's), not the effective viscosity's.
    o.reynolds_number = re;
    o.outlet_reynolds_number = op.outlet_reynolds_number;
    let reason = format!("turbulent film by Khonsari & Booser §7.11's empirical rule: friction factor f = 0.026/Re^0.25 = {f:.4e} (Eq. 7.20) at the laminar pad-average Re = ρ U h_mean/μ = {re:.4e}, power loss f (ρ U²/2) U B L = {empirical:.4e} W (Eq. 7.17) against the laminar {:.4e} W, the larger carried; film and flows at the viscosity × {factor:.4} (the texts' effective viscosity)", op.power_loss_w);
    for (name, d) in o.notes.decisions.iter_mut() {
        if *name == "turbulence" {
            *d = Decision {
                applied: true,
                reason,
                criterion: Some(Criterion {
                    name: "pad_reynolds_number",
                    value: re,
                    threshold: TURBULENT_REYNOLDS,
                }),
                model: Some("missana"),
                mode: d.mode,
            };
            break;
        }
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
