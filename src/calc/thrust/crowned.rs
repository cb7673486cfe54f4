//! A crowned tilting pad in equilibrium under its load (Khonsari & Booser §7.5: a crown of
//! 0.5–2 h_min lets a centrally pivoted pad carry load).
//!
//! The crown δ is fixed in metres, so the film's shape h̄ = h/h2 depends on k = δ/h2 as well as
//! on a = h1/h2 ([`Profile::Crowned`]), and the equilibrium is two-dimensional in (a, h2): the
//! moment about the pivot, x̄_cp(a, k) = x̄_p, and the load balance, h2 = δ/k =
//! (W̄(a, k) μ U B² L/W)^½ at the effective viscosity. A damped 2-D Newton on (a, ln k)
//! ([`newton`]) solves both at once in a few pad solves; where it does not converge to the
//! branch the bracketed search follows, the bracketed nested search ([`bracketed`]) answers.
//!
//! The branch: above δ/h2 ≈ 1 a second, pinched equilibrium appears near the film ratio at
//! which the crown touches the runner (the centre of pressure falls, then rises, with h1/h2), and
//! the two meet at a fold — for a central pivot on a square pad near δ/h2 = 1.62, δ/h_min = 7,
//! h1/h2 = 3.0, well past the texts' crowns of 0.5–2 h_min. Both searches follow the main
//! branch (the film ratio rising as the pivot moves back) to the fold and refuse a load or
//! crown past it, naming where it lies.

use std::cell::Cell;

use super::long_pad;
use super::operating::{self, Conditions, Operating};
use super::performance::{evaluate, Method};
use super::pivot::{equilibrium as pivot_equilibrium, settled, Equilibrium, Pivot};
use super::profile::Profile;
use crate::calc::turbulence::Flow;
use crate::calc::{Budget, CalcError};
use crate::fidelity::IterationUnit;
use crate::numerics::driver::Driver;
use crate::numerics::newton::{self, residual_falls, LineSearch, NewtonSystem};
use crate::numerics::roots::{brent_bracketed, Stopping};

/// A pad crowned by `crown` (δ, m) tilting about `pivot` under its load, in a `flow`: Newton
/// first (a pivot at a position), the bracketed search where Newton does not answer.
pub fn equilibrium(
    pivot: Pivot,
    crown: f64,
    flow: Flow,
    method: Method,
    c: &Conditions,
    budget: &Budget,
) -> Result<(Equilibrium, Operating), CalcError> {
    if let Pivot::At(x_p) = pivot {
        if let Some(found) = newton(x_p, crown, flow, method, c, budget)? {
            return Ok(found);
        }
    }
    bracketed(pivot, crown, flow, method, c, budget)
}

/// The load balance and the moment at (a, ln k), with what was solved there.
type Balanced = ([f64; 2], super::performance::Evaluated, Operating);

/// The 2-D system: residuals r₁ = x̄_cp − x̄_p (a fraction of B) and r₂ = ln h2' − ln(δ/k) (the
/// load balance in ln h2); unknowns (a, ln k). A point whose film touches the runner, or whose
/// solve fails, evaluates to nothing (an infinite residual the line search backs away from).
struct Balance<'a> {
    pivot: f64,
    crown: f64,
    flow: Flow,
    method: Method,
    conditions: &'a Conditions,
    budget: &'a Budget,
    evaluations: Cell<u32>,
}

impl Balance<'_> {
    fn shape(x: &[f64; 2]) -> Profile {
        Profile::Crowned {
            ratio: x[0],
            crown: x[1].exp(),
        }
    }
}

impl NewtonSystem for Balance<'_> {
    type Point = [f64; 2];
    type Eval = Option<Balanced>;
    type Step = [f64; 2];

    fn evaluate(&self, x: &[f64; 2]) -> Option<Balanced> {
        let profile = Balance::shape(x);
        if !(x[0] >= 1.0
            && x[0] <= 10.0
            && x[1].exp() <= CROWN_RATIO_MAX
            && profile.minimum() > 0.0)
        {
            return None;
        }
        self.evaluations.set(self.evaluations.get() + 1);
        let c = self.conditions;
        let evaluated = evaluate(
            profile,
            self.flow,
            c.pad.l_over_b(),
            self.method,
            self.budget,
        )
        .ok()?;
        let operating = operating::operate(
            &evaluated,
            x[0],
            long_pad::mean_thickness(profile),
            false,
            self.flow,
            c,
        )
        .ok()?;
        let r = [
            evaluated.performance.center_of_pressure - self.pivot,
            operating.outlet_film_m.ln() - (self.crown.ln() - x[1]),
        ];
        r.iter()
            .all(|v| v.is_finite())
            .then_some((r, evaluated, operating))
    }

    fn residual(&self, at: &Option<Balanced>) -> f64 {
        at.as_ref()
            .map_or(f64::INFINITY, |(r, ..)| r[0].abs().max(r[1].abs()))
    }

    /// −J⁻¹ r with J by forward differences (steps 1e-6 in a relative and in ln k), the step
    /// shortened to move a by at most half itself and ln k by at most 1.
    fn direction(&self, x: &[f64; 2], at: &Option<Balanced>) -> Option<[f64; 2]> {
        let (r, ..) = at.as_ref()?;
        let (ha, hu) = (1e-6 * x[0], 1e-6);
        let (ea, eu) = (
            self.evaluate(&[x[0] + ha, x[1]])?,
            self.evaluate(&[x[0], x[1] + hu])?,
        );
        let j = [
            [(ea.0[0] - r[0]) / ha, (eu.0[0] - r[0]) / hu],
            [(ea.0[1] - r[1]) / ha, (eu.0[1] - r[1]) / hu],
        ];
        let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
        if !(det.is_finite() && det != 0.0) {
            return None;
        }
        let step = [
            -(j[1][1] * r[0] - j[0][1] * r[1]) / det,
            -(j[0][0] * r[1] - j[1][0] * r[0]) / det,
        ];
        let shrink = (0.5 * x[0] / step[0].abs())
            .min(1.0 / step[1].abs())
            .min(1.0);
        step.iter()
            .all(|v| v.is_finite())
            .then_some([shrink * step[0], shrink * step[1]])
    }

    fn advance(&self, x: &[f64; 2], step: &[f64; 2], t: f64) -> [f64; 2] {
        [x[0] + t * step[0], x[1] + t * step[1]]
    }

    fn accepts(
        &self,
        here: &Option<Balanced>,
        trial: &Option<Balanced>,
        t: f64,
        _: Option<f64>,
    ) -> bool {
        residual_falls(self.residual(here), self.residual(trial), t)
    }
}

/// Newton on (a, ln k) from a = 2, k = ½ to a residual of 1e-10 (the pivot to 1e-10 of B, h2
/// to 1e-10 relative), under the driver (at most 40 steps of at most 8 halvings). None when it
/// stalls, reaches its cap, settles outside the bracketed search's range (k ≤ 8, a ≥ 1) or on
/// the pinched branch (where the film ratio falls as the pivot moves back): the bracketed
/// search then answers. Each step costs three pad solves (the point and the
/// Jacobian's two) and its line search's trials.
fn newton(
    x_p: f64,
    crown: f64,
    flow: Flow,
    method: Method,
    c: &Conditions,
    budget: &Budget,
) -> Result<Option<(Equilibrium, Operating)>, CalcError> {
    let system = Balance {
        pivot: x_p,
        crown,
        flow,
        method,
        conditions: c,
        budget,
        evaluations: Cell::new(0),
    };
    let driver = Driver::new("crowned_pad_newton", IterationUnit::NewtonSteps, 40, budget);
    let line = LineSearch {
        max_halvings: 8,
        take_shortest: false,
    };
    let solved = match newton::solve(&system, [2.0, CROWN_RATIO_START.ln()], 1e-10, line, &driver) {
        Ok(solved) => solved,
        Err(stopped) if stopped.reason() == crate::fidelity::StopReason::Deadline => {
            return Err(stopped.into())
        }
        Err(_) => return Ok(None),
    };
    let (x, at) = solved.value;
    let Some((_, _, operating)) = at else {
        return Ok(None);
    };
    let profile = Balance::shape(&x);
    let mut eq = settled(profile, x_p, flow, c.pad.l_over_b(), method, budget)?;
    if eq.ratio_per_pivot <= 0.0 {
        // The pinched branch (x̄_cp falling with a), which the bracketed search leaves aside.
        return Ok(None);
    }
    eq.evaluations += system.evaluations.get();
    Ok(Some((eq, operating)))
}

/// The crown ratio δ/h2 the load balance's bracket starts from.
const CROWN_RATIO_START: f64 = 0.5;
/// The thinnest crown ratio the bracket reaches before it gives up (a crown of 1e-8 of the film
/// is a flat pad).
const CROWN_RATIO_MIN: f64 = 1e-8;
/// The thickest crown ratio searched. Well before it a pivot's equilibrium branch ends: above
/// about δ/h2 = 1 a second, pinched equilibrium appears near the film ratio at which the crown
/// touches, the two meet at a fold (a central pivot on a square pad: between δ/h2 = 1.5 and 2,
/// δ/h_min above 3) and beyond it the centre of pressure lies behind the pivot for every film
/// ratio.
const CROWN_RATIO_MAX: f64 = 8.0;
/// The bracket grows above δ/h2 = ½ by this factor.
const CROWN_RATIO_GROWTH: f64 = 1.5;
/// How closely, in ln(δ/h2), the fold is located when a load needs a crown ratio past it.
const FOLD_TOLERANCE: f64 = 1e-3;

/// Whether `e` says the pivot has no equilibrium at this crown ratio (the branch has ended).
fn branch_ended(e: &CalcError) -> bool {
    matches!(e, CalcError::Impossible { pointer, .. } if pointer == "/pivot_position_fraction")
}

/// The bracketed nested search: δ is fixed in metres, so the film's shape h̄ = h/h2 depends on k = δ/h2 as well as on
/// a = h1/h2, and the equilibrium is two-dimensional in (a, h2). It is solved nested: at a given
/// k the pivot fixes a (the bracketed root on the moment, [`equilibrium`]), and the load then
/// gives back h2' = (W̄(a, k) μ U B² L/W)^½ at the effective viscosity ([`operating::operate`],
/// with the thermal effect); the load balance is the root of g(ln k) = ln h2' − ln(δ/k).
/// g rises with k (a relatively larger crown carries more, and h2 = δ/k falls) and tends to −∞
/// as k → 0 (a flat pad's h2' is finite, a central pivot's tends to 0): the bracket grows from
/// k = ½ — down by quarters, or up by half again — until g changes sign, then Brent's method
/// finds the root in ln k. Above k ≈ 1 the pivot's equilibrium follows its main branch
/// ([`pivot_equilibrium`]) to the fold where it ends; a load that needs a crown ratio past the
/// fold (g < 0 up to it, located by bisection) is refused with the fold's δ/h2 and δ/h_min.
fn bracketed(
    pivot: Pivot,
    crown: f64,
    flow: Flow,
    method: Method,
    c: &Conditions,
    budget: &Budget,
) -> Result<(Equilibrium, Operating), CalcError> {
    let l_over_b = c.pad.l_over_b();
    let evaluations = Cell::new(0u32);
    // The pad in equilibrium at crown ratio k = e^u, at its operating point.
    let at = |u: f64| -> Result<(Equilibrium, Operating), CalcError> {
        let shape = Profile::Crowned {
            ratio: 2.0,
            crown: u.exp(),
        };
        let eq = pivot_equilibrium(pivot, shape, flow, l_over_b, method, budget)?;
        evaluations.set(evaluations.get() + eq.evaluations);
        let profile = shape.with_ratio(eq.ratio);
        let operating = operating::operate(
            &eq.evaluated,
            eq.ratio,
            long_pad::mean_thickness(profile),
            false,
            flow,
            c,
        )?;
        Ok((eq, operating))
    };
    let balance = |u: f64| -> Result<f64, CalcError> {
        let (_, op) = at(u)?;
        Ok(op.outlet_film_m.ln() - (crown.ln() - u))
    };
    let mut lo = (CROWN_RATIO_START.ln(), balance(CROWN_RATIO_START.ln())?);
    let mut hi = lo;
    while lo.1 > 0.0 {
        let k = lo.0.exp() / 4.0;
        if k < CROWN_RATIO_MIN {
            return Err(CalcError::impossible(
                "/crown_m",
                format!("a crown of {crown:e} m is lost in this film: the pad carries its load on a film over 1e8 times the crown; it is a flat pad (omit crown_m)"),
            ));
        }
        hi = lo;
        lo = (k.ln(), balance(k.ln())?);
    }
    while hi.1 < 0.0 {
        let k = hi.0.exp();
        if k >= CROWN_RATIO_MAX {
            return Err(CalcError::impossible(
                "/crown_m",
                format!("a crown of {crown:e} m is too high for this load about this pivot: the load needs a trailing-edge film thinner than 1/{CROWN_RATIO_MAX} of the crown; lower the crown or the load"),
            ));
        }
        let next = (k * CROWN_RATIO_GROWTH).min(CROWN_RATIO_MAX).ln();
        match balance(next) {
            Ok(g) => (lo, hi) = (hi, (next, g)),
            Err(e) if branch_ended(&e) => {
                (lo, hi) = fold_bracket(hi, next, crown, &balance, &at)?;
            }
            Err(e) => return Err(e),
        }
    }
    let mut failure = None;
    let root = brent_bracketed(
        |u| match balance(u) {
            Ok(g) => g,
            Err(e) => {
                failure = Some(e);
                0.0
            }
        },
        lo,
        hi,
        Stopping {
            x_tolerance: 1e-10,
            max_iterations: 100,
        },
    );
    if let Some(e) = failure {
        return Err(e);
    }
    let root = root.map_err(|e| CalcError::from_root("crowned_pad_load_balance", e))?;
    let (mut eq, operating) = at(root.x)?;
    eq.evaluations = evaluations.get();
    Ok((eq, operating))
}

/// (ln k, g(ln k)): a point of the load balance.
type Point = (f64, f64);

/// The load balance's bracket when the growing bracket steps past the fold at `past` (ln k):
/// bisection in ln k between the last crown ratio with an equilibrium, `good` (g < 0 there),
/// and `past`, until g ≥ 0 at one with an equilibrium (the bracket) or the fold is located to
/// [`FOLD_TOLERANCE`] (the refusal: the load is too heavy for the crown about this pivot).
fn fold_bracket(
    good: Point,
    past: f64,
    crown: f64,
    balance: &impl Fn(f64) -> Result<f64, CalcError>,
    at: &impl Fn(f64) -> Result<(Equilibrium, Operating), CalcError>,
) -> Result<(Point, Point), CalcError> {
    let (mut good, mut past) = (good, past);
    while past - good.0 > FOLD_TOLERANCE {
        let mid = 0.5 * (good.0 + past);
        match balance(mid) {
            Ok(g) if g >= 0.0 => return Ok((good, (mid, g))),
            Ok(g) => good = (mid, g),
            Err(e) if branch_ended(&e) => past = mid,
            Err(e) => return Err(e),
        }
    }
    let (eq, op) = at(good.0)?;
    let k = good.0.exp();
    let over_min = k / Profile::Crowned {
        ratio: eq.ratio,
        crown: k,
    }
    .minimum();
    // At a fixed shape the load carried goes as h2⁻²: at h2 = δ/k it is W e^{2g}.
    let most = op.load_n * (2.0 * good.1).exp();
    Err(CalcError::impossible(
        "/crown_m",
        format!("a crown of {crown:e} m is too high for this load about this pivot: the pad's equilibrium branch ends at a fold near δ/h2 = {k:.4} (δ/h_min = {over_min:.3}, h1/h2 = {:.4}), where the crowned pad carries about {most:.4e} N at most; beyond it the centre of pressure lies behind the pivot for every tilt. Lower the crown or the load", eq.ratio),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::calc::thrust::tilting_pad::TiltingPadInput;
    use crate::calc::Validate;
    use crate::fidelity::Level;

    /// Newton and the bracketed nested search find the same equilibrium (the pivot and the
    /// load balanced), Newton with a tenth of the pad solves.
    #[test]
    fn newton_and_the_bracketed_search_agree() {
        let input: TiltingPadInput = serde_json::from_value(serde_json::json!({
            "pad": {"breadth_m": 0.089, "length_m": 0.087}, "pivot_position_fraction": 0.5,
            "sliding_speed_m_s": 44, "lubricant": {"iso_vg": 32}, "inlet_temperature_c": 49,
            "load_n": 16000, "crown_m": 2e-5,
        }))
        .unwrap();
        let c = input.validate().unwrap().conditions;
        let (budget, method) = (Budget::unlimited(), Method::level(Level::Fast));
        // (0.5, 1e-4) and (0.5, 1.2e-4) settle above δ/h2 = 1, on the main branch past the
        // pinched one's appearance.
        for (x_p, crown) in [
            (0.5, 1e-5),
            (0.5, 3e-5),
            (0.55, 2e-5),
            (0.6, 1e-6),
            (0.5, 1e-4),
            (0.5, 1.2e-4),
        ] {
            let (fast, fast_op) = newton(x_p, crown, Flow::Laminar, method, &c, &budget)
                .unwrap()
                .expect("Newton converges");
            let (slow, slow_op) =
                bracketed(Pivot::At(x_p), crown, Flow::Laminar, method, &c, &budget).unwrap();
            let what = format!("pivot {x_p}, crown {crown}");
            assert!((fast.ratio / slow.ratio - 1.0).abs() < 1e-7, "{what}: a");
            let (h_fast, h_slow) = (fast_op.outlet_film_m, slow_op.outlet_film_m);
            assert!((h_fast / h_slow - 1.0).abs() < 1e-7, "{what}: h2");
            assert!((fast.evaluated.performance.center_of_pressure - x_p).abs() < 1e-9);
            assert!(
                (fast_op.load_n / 16000.0 - 1.0).abs() < 1e-9,
                "{what}: load"
            );
            assert!(fast.evaluations * 4 < slow.evaluations, "{what}: cost");
        }
    }
}
