//! One pad solved at its operating point: a fixed pad's film (at its load-maximising ratio when
//! asked) or a tilting pad's equilibrium, made dimensional with its effects decided. The pad
//! rooms and the whole bearing share it.

use super::long_pad;
use super::operating::{self, Conditions, Operating};
use super::performance::{self, evaluate, Evaluated, Method};
use super::pivot::{equilibrium, Equilibrium, Pivot};
use super::profile::Profile;
use crate::calc::{Budget, CalcError};
use crate::fidelity::SolverReport;

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

/// A fixed pad of shape `profile` (its ratio optimised when `optimum`).
pub fn fixed(
    profile: Profile,
    optimum: bool,
    method: Method,
    c: &Conditions,
    budget: &Budget,
) -> Result<SolvedPad, CalcError> {
    check_viscosity(c)?;
    let l_over_b = c.pad.l_over_b();
    let (profile, evaluations) = if optimum {
        let (ratio, n) = performance::optimum_ratio(profile, l_over_b, method, budget)?;
        (profile.with_ratio(ratio), Some(n))
    } else {
        (profile, None)
    };
    let evaluated = evaluate(profile, l_over_b, method, budget)?;
    let plane = matches!(profile, Profile::PlaneInclined { .. });
    let mut operating = operating::operate(
        &evaluated,
        profile.ratio(),
        long_pad::mean_thickness(profile),
        plane,
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

/// A plane pad tilting about `pivot`.
pub fn tilting(
    pivot: Pivot,
    method: Method,
    c: &Conditions,
    budget: &Budget,
) -> Result<SolvedPad, CalcError> {
    check_viscosity(c)?;
    let l_over_b = c.pad.l_over_b();
    let eq = equilibrium(pivot, l_over_b, method, budget)?;
    let profile = Profile::PlaneInclined { ratio: eq.ratio };
    let mut operating = operating::operate(
        &eq.evaluated,
        eq.ratio,
        long_pad::mean_thickness(profile),
        true,
        c,
    )?;
    warn_long_pad(method, l_over_b, &mut operating);
    Ok(SolvedPad {
        operating,
        ratio: eq.ratio,
        evaluated: eq.evaluated.clone(),
        evaluations: Some(eq.evaluations),
        equilibrium: Some(eq),
    })
}

/// The infinitely long pad outside its range (B/L ≤ 0.5, Khonsari & Booser §6.5) says so.
fn warn_long_pad(method: Method, l_over_b: f64, operating: &mut Operating) {
    if method == Method::LongPad && l_over_b < 2.0 {
        operating.notes.warn(
            "long_pad_approximation",
            format!("the infinitely long pad ignores side leakage, valid for L/B ≥ 2 (Khonsari & Booser §6.5); at L/B = {l_over_b:.3} it overestimates the load: use a numerical fidelity"),
        );
    }
}
