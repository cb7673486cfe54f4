//! A pad at its operating point: the dimensionless performance made dimensional, the film from
//! the load or the load from the film, and the effects decided (Khonsari & Booser §7.3–7.4,
//! §7.11).
//!
//! With the film ratio fixed, W = W̄ μ U B² L/h2², so a given load fixes h2 = (W̄ μ U B² L/W)^½
//! without a search. The temperature rise is the pad's power carried off by its inlet flow,
//! ΔT = E_p/(ρ c_p Q₁) (Eq. 7.8), and the thermal effect takes the viscosity at the effective
//! temperature T_in + ΔT (the texts' design procedure, §7.4 step 5; Ex 7.1, 7.2): a root in T.
//!
//! The turbulence effect is decided here from the pad-average Reynolds number ρ U h̄_mean/μ
//! (§7.11); a turbulent pad's performance depends on the trailing-edge Re₂ = ρ U h2/μ, which the
//! operating point sets, so [`super::pad`] solves that loop and this reports the flow it was
//! given.

use super::performance::{Evaluated, Performance};
use super::thd;
use crate::calc::lubricant::{validity, Lubricant};
use crate::calc::turbulence::Flow;
use crate::calc::{CalcError, Notes};
use crate::effects::{Criterion, Decision, Mode};
use crate::numerics::roots::{brent, Stopping};

/// A pad's size: B along the sliding direction, L across it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pad {
    pub breadth_m: f64,
    pub length_m: f64,
}

impl Pad {
    pub fn l_over_b(self) -> f64 {
        self.length_m / self.breadth_m
    }
    pub fn area_m2(self) -> f64 {
        self.breadth_m * self.length_m
    }
}

/// What the request fixes: the trailing-edge film or the load.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Given {
    OutletFilm(f64),
    Load(f64),
}

/// The effects a pad understands.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Effects {
    pub thermal: Mode,
    pub turbulence: Mode,
    pub turbulence_law: TurbulenceLaw,
}

/// How a turbulent pad film is computed (Khonsari & Booser §7.11).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum TurbulenceLaw {
    /// The linearised turbulent Reynolds equation: Ng–Pan's G_x, G_y and G_f (Eq. 6.26–6.31).
    #[default]
    NgPan,
    /// The texts' empirical rule: the power loss from the turbulent friction factor
    /// f = 0.026/Re^0.25 (Eq. 7.20) on the pad's area (Eq. 7.17), and the laminar film at the
    /// viscosity multiplied by that loss over the laminar one.
    Missana,
}

/// The running conditions.
#[derive(Debug, Clone, PartialEq)]
pub struct Conditions {
    pub pad: Pad,
    pub sliding_speed_m_s: f64,
    pub lubricant: Lubricant,
    pub inlet_temperature_c: f64,
    pub given: Given,
    pub effects: Effects,
    /// The factor on the lubricant's viscosity: 1, or the texts' turbulent "effective"
    /// viscosity multiplier (§7.11, [`TurbulenceLaw::Missana`]).
    pub viscosity_factor: f64,
}

impl Conditions {
    /// The film's viscosity at t (°C), Pa·s: the lubricant's, times [`Conditions::viscosity_factor`].
    pub fn viscosity_pa_s(&self, t_c: f64) -> f64 {
        self.viscosity_factor * self.lubricant.viscosity_pa_s(t_c)
    }
}

/// Transition to turbulence in a thrust film: pad-average Reynolds number 580–800 (local
/// 1000–1200; Khonsari & Booser §7.11). `auto` applies the turbulent film from the lower end.
pub const TURBULENT_REYNOLDS: f64 = 580.0;
/// The upper end of the transition: between the two the texts advise computing both regimes
/// and expecting the larger power loss (§7.11).
pub const TRANSITION_END_REYNOLDS: f64 = 800.0;
/// The viscosity drop across the isothermal rise above which `auto` applies the thermal effect
/// (as for the journal).
const THERMAL_VISCOSITY_DROP: f64 = 0.05;
/// Babbitt begins to flow at about 150 °C (Khonsari & Booser §7.9).
pub const BABBITT_LIMIT_C: f64 = 150.0;
/// No lubricating oil film survives above this, and the viscosity and density laws do not
/// reach it: an effective temperature beyond is a thermal runaway, refused.
pub const MAX_FILM_TEMPERATURE_C: f64 = 300.0;

/// The pad at its operating point, SI units.
#[derive(Debug, Clone)]
pub struct Operating {
    pub performance: Performance,
    pub load_n: f64,
    pub outlet_film_m: f64,
    pub inlet_film_m: f64,
    pub friction_force_n: f64,
    pub power_loss_w: f64,
    pub max_pressure_pa: f64,
    /// μ U B/h2²: P̄ in pascals.
    pub pressure_scale_pa: f64,
    pub mean_pressure_pa: f64,
    pub inlet_flow_m3_s: f64,
    pub side_flow_m3_s: f64,
    pub outlet_flow_m3_s: f64,
    pub temperature_rise_k: f64,
    pub effective_temperature_c: f64,
    pub max_temperature_c: f64,
    pub effective_viscosity_pa_s: f64,
    /// ρ U h̄_mean/μ at the effective temperature.
    pub reynolds_number: f64,
    /// Re₂ = ρ U h2/μ at the effective temperature: the reference of a turbulent film's local
    /// Re = Re₂ h̄.
    pub outlet_reynolds_number: f64,
    pub notes: Notes,
}

/// The pad of `evaluated` performance (film ratio `ratio`, mean film h̄_mean h2, computed in
/// `flow`) under `c`.
///
/// `plane` says the pad is plane over its whole breadth (a plane fixed pad, or a tilting pad):
/// then, inside the fits' range, its mean and maximum temperatures are Jang & Khonsari's
/// ([`thd`]); elsewhere the mean is T_in + ΔT and the maximum T_in + 2ΔT (§7.3).
pub fn operate(
    evaluated: &Evaluated,
    ratio: f64,
    mean_film: f64,
    plane: bool,
    flow: Flow,
    c: &Conditions,
) -> Result<Operating, CalcError> {
    let p = evaluated.performance;
    if !(p.load > 0.0 && p.inlet_flow > 0.0) {
        return Err(CalcError::impossible(
            "/profile",
            "this film carries no load: the pad needs a converging film",
        ));
    }
    let (pad, u, lub) = (c.pad, c.sliding_speed_m_s, &c.lubricant);
    let (b, l) = (pad.breadth_m, pad.length_m);
    let t_in = c.inlet_temperature_c;
    // The outlet film at viscosity μ.
    let film = |mu: f64| match c.given {
        Given::OutletFilm(h2) => h2,
        Given::Load(w) => (p.load * mu * u * b * b * l / w).sqrt(),
    };
    // ΔT at temperature t (the viscosity and the heat capacity taken there), Eq. 7.8.
    let rise = |t: f64| {
        let mu = c.viscosity_pa_s(t);
        let h2 = film(mu);
        let power = p.friction * mu * u * u * b * l / h2;
        let flow = p.inlet_flow * u * l * h2;
        power / (lub.density_kg_m3(t) * lub.specific_heat_j_kg_k(t) * flow)
    };
    let mut notes = Notes::default();
    let fits = jang_khonsari(plane, ratio, c, &mut notes);
    // The mean and maximum rises at temperature t, and a ceiling of the mean rise.
    let rises = |t: f64| match fits {
        Some(f) => f.temperature_rises((ratio - 1.0) * film(c.viscosity_pa_s(t)), ratio),
        None => {
            let r = rise(t);
            (2.0 * r, r)
        }
    };
    let isothermal_rise = rises(t_in).1;
    let ceiling = match fits {
        Some(f) => thd::rises(ratio, f64::INFINITY, f64::INFINITY).1 / f.beta_1_k,
        None => isothermal_rise,
    };
    let heated = (t_in + isothermal_rise).min(MAX_FILM_TEMPERATURE_C.max(t_in));
    let drop = 1.0 - c.viscosity_pa_s(heated) / c.viscosity_pa_s(t_in);
    let thermal = Decision::decide(
        c.effects.thermal,
        Criterion {
            name: "viscosity_drop_over_rise",
            value: drop,
            threshold: THERMAL_VISCOSITY_DROP,
        },
        if fits.is_some() {
            "effective temperature: Jang & Khonsari's THD mean temperature"
        } else {
            "effective temperature T_in + ΔT"
        },
    );
    let thermal = Decision {
        model: Some(if fits.is_some() {
            "jang_khonsari"
        } else {
            "adiabatic_rise"
        }),
        ..thermal
    };
    let t_eff = if thermal.applied {
        effective_temperature(t_in, ceiling, |t| rises(t).1).ok_or_else(|| {
            let pointer = match c.given {
                Given::OutletFilm(_) => "/outlet_film_m",
                Given::Load(_) => "/load_n",
            };
            CalcError::impossible(
                pointer,
                format!("thermal runaway: the film's own heat would take it above {MAX_FILM_TEMPERATURE_C} °C (isothermal rise {isothermal_rise:.3e} K), where no oil film survives; thicken the film or lighten the load"),
            )
        })?
    } else {
        t_in
    };
    notes.decide("thermal", thermal);
    let mu = c.viscosity_pa_s(t_eff);
    let h2 = film(mu);
    let rho = lub.density_kg_m3(t_eff);
    let reynolds = rho * u * mean_film * h2 / mu;
    let outlet_reynolds = rho * u * h2 / mu;
    notes.decide(
        "turbulence",
        turbulence_decision(c.effects.turbulence, reynolds, flow),
    );
    let load = p.load * mu * u * b * b * l / (h2 * h2);
    let friction = p.friction * mu * u * b * l / h2;
    let inlet_flow = p.inlet_flow * u * l * h2;
    let power = friction * u;
    let rise = power / (rho * lub.specific_heat_j_kg_k(t_eff) * inlet_flow);
    let max_temperature = t_in + rises(t_eff).0;
    if max_temperature > BABBITT_LIMIT_C {
        notes.warn(
            "above_babbitt_limit",
            format!("the estimated maximum film temperature {max_temperature:.0} °C exceeds the {BABBITT_LIMIT_C:.0} °C at which babbitt flows (§7.9)"),
        );
    }
    if let Some((code, message)) = validity::hot_oil("the film's hottest oil", max_temperature) {
        notes.warn(code, message);
    }
    let inlet_film = ratio * h2;
    if inlet_film > 0.01 * b.min(l) {
        notes.warn(
            "thick_film",
            format!("the inlet film {inlet_film:.3e} m is over 1 % of the pad's size: Reynolds' thin-film assumption weakens"),
        );
    }
    Ok(Operating {
        performance: p,
        load_n: load,
        outlet_film_m: h2,
        inlet_film_m: inlet_film,
        friction_force_n: friction,
        power_loss_w: power,
        max_pressure_pa: p.max_pressure * mu * u * b / (h2 * h2),
        pressure_scale_pa: mu * u * b / (h2 * h2),
        mean_pressure_pa: load / pad.area_m2(),
        inlet_flow_m3_s: inlet_flow,
        side_flow_m3_s: p.side_flow * u * l * h2,
        outlet_flow_m3_s: p.outlet_flow * u * l * h2,
        temperature_rise_k: rise,
        effective_temperature_c: t_eff,
        max_temperature_c: max_temperature,
        effective_viscosity_pa_s: mu,
        reynolds_number: reynolds,
        outlet_reynolds_number: outlet_reynolds,
        notes,
    })
}

/// The turbulence decision at pad-average Reynolds number `reynolds` (ρ U h̄_mean/μ against
/// [`TURBULENT_REYNOLDS`]): `auto` and `on` apply it, and a result computed in a turbulent
/// `flow` says so, with its trailing-edge Re₂ and the model.
pub fn turbulence_decision(mode: Mode, reynolds: f64, flow: Flow) -> Decision {
    let decided = Decision::decide(
        mode,
        Criterion {
            name: "pad_reynolds_number",
            value: reynolds,
            threshold: TURBULENT_REYNOLDS,
        },
        "turbulent film",
    );
    match flow {
        Flow::Laminar => decided,
        Flow::Turbulent { reference_reynolds } => Decision {
            applied: true,
            reason: format!(
                "{}; Ng–Pan flow factors G_x, G_y on the pad's Reynolds equation and the Couette shear factor G_f at the local Re = Re₂ h/h2, Re₂ = ρ U h2/μ = {reference_reynolds:.4e} (Khonsari & Booser Eq. 6.26–6.31)",
                decided.reason
            ),
            model: Some("ng_pan"),
            ..decided
        },
    }
}

/// T with T = T_in + ΔT(T), where ΔT never exceeds `ceiling` (the adiabatic ΔT falls as T
/// rises: thinner oil, a dearer heat capacity; Jang & Khonsari's mean rise may grow with T but
/// is bounded by its constant term), so the root lies in [T_in, T_in + ceiling]; none when it
/// lies above [`MAX_FILM_TEMPERATURE_C`] (or the laws give no finite value on the way).
fn effective_temperature(t_in: f64, ceiling: f64, rise: impl Fn(f64) -> f64) -> Option<f64> {
    let g = |t: f64| t - t_in - rise(t);
    let hi = t_in + ceiling;
    if hi <= MAX_FILM_TEMPERATURE_C && g(hi) <= 0.0 {
        return Some(hi);
    }
    let hi = hi.min(MAX_FILM_TEMPERATURE_C);
    if !(hi > t_in && g(hi) > 0.0) {
        return None;
    }
    let stop = Stopping {
        x_tolerance: 1e-9 * (1.0 + hi.abs()),
        max_iterations: 100,
    };
    brent(g, t_in, hi, stop).ok().map(|root| root.x)
}

/// Jang & Khonsari's fits for this pad, when they apply: a plane pad of B/L near 1 with a film
/// ratio in [1.25, 3.25] on an oil whose viscosity falls with temperature (β > 0, taken at the
/// inlet as −d ln μ/dT). Outside B/L = 1 the fits are extrapolated, with a warning.
fn jang_khonsari(
    plane: bool,
    ratio: f64,
    c: &Conditions,
    notes: &mut Notes,
) -> Option<thd::Parameters> {
    let (lub, t_in) = (&c.lubricant, c.inlet_temperature_c);
    let b_over_l = 1.0 / c.pad.l_over_b();
    let beta = -(lub.viscosity_pa_s(t_in + 0.5).ln() - lub.viscosity_pa_s(t_in - 0.5).ln());
    let fits = plane
        && (thd::RATIOS.0..=thd::RATIOS.1).contains(&ratio)
        && (thd::ASPECT_SPREAD.0..=thd::ASPECT_SPREAD.1).contains(&b_over_l)
        && beta.is_finite()
        && beta > 1e-6;
    if !fits {
        return None;
    }
    if (b_over_l - 1.0).abs() > 1e-9 {
        notes.warn(
            "thd_fit_aspect",
            format!("Jang & Khonsari's temperature fits were made for B/L = 1; used at B/L = {b_over_l:.3}"),
        );
    }
    let k = lub.thermal_conductivity_w_m_k(t_in);
    Some(thd::Parameters {
        diffusivity_m2_s: k / (lub.density_kg_m3(t_in) * lub.specific_heat_j_kg_k(t_in)),
        conductivity_w_m_k: k,
        inlet_viscosity_pa_s: c.viscosity_pa_s(t_in),
        beta_1_k: beta,
        speed_m_s: c.sliding_speed_m_s,
        breadth_m: c.pad.breadth_m,
    })
}
