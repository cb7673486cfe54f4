//! Heat: the effective temperature the viscosity is taken at (Khonsari & Booser Eq. 8.63/8.64)
//! and Jang & Khonsari's THD temperatures.

use std::f64::consts::PI;

use super::{BushTemperatures, Case, Notes, Operating, MAX_TEMPERATURE_RISE_K};
use crate::calc::journal::eccentricity::EccentricityRatio;
use crate::calc::journal::performance::{self, Balance, Point, MAX_ECCENTRICITY};
use crate::calc::{Budget, CalcError};
use crate::numerics::roots::{brent, brent_outcome, RootError, Stopping};

/// Jang & Khonsari's THD fits for the maximum bush and the shaft temperature (Khonsari & Booser
/// Eq. 8.65, Table 8.11): T̄ = β (T − T_in), κ1 = (α_t μ_i β U/(k R))(R/C)², κ2 = U (μ_i β/k)^½,
/// T̄_max = exp[a + b/√κ1 + c/√κ2], T̄_shaft = 1/[a + b/√κ1 + c/κ2²], the region by the isothermal ε.
/// β is −d ln μ/dT at the inlet (exact for the exponential law).
pub(super) fn thd_temperatures(
    notes: &mut Notes,
    case: &Case,
    t_in: f64,
    eccentricity: EccentricityRatio,
) -> Option<BushTemperatures> {
    let eps = eccentricity.get();
    let lub = &case.lubricant;
    let g = case.geometry;
    let mu = lub.viscosity_pa_s(t_in);
    let beta = (lub.viscosity_pa_s(t_in - 0.5) / lub.viscosity_pa_s(t_in + 0.5)).ln();
    let k = lub.thermal_conductivity_w_m_k(t_in);
    let diffusivity = k / (lub.density_kg_m3(t_in) * lub.specific_heat_j_kg_k(t_in));
    let u = PI * g.diameter_m * case.speed_rps();
    let r = 0.5 * g.diameter_m;
    let kappa1 = diffusivity * mu * beta * u / (k * r) * g.r_over_c().powi(2);
    let kappa2 = u * (mu * beta / k).sqrt();
    if !(beta > 0.0 && kappa1.is_finite() && kappa2.is_finite()) {
        return None;
    }
    let (max, shaft) = match eps {
        e if e < 0.3 => ((1.63105, -0.20250, -0.84050), (0.14092, 0.24303, 0.10054)),
        e if e <= 0.7 => ((1.68517, -0.19962, -1.04999), (0.04734, 0.39751, 0.11007)),
        _ => ((1.79973, -0.13627, -1.25216), (0.06200, 0.38264, 0.10102)),
    };
    let t_max = (max.0 + max.1 / kappa1.sqrt() + max.2 / kappa2.sqrt()).exp();
    let t_shaft = 1.0 / (shaft.0 + shaft.1 / kappa1.sqrt() + shaft.2 / (kappa2 * kappa2));
    let in_range = (0.001..=0.5).contains(&kappa1)
        && (0.01..=5.0).contains(&kappa2)
        && (0.1..=0.9).contains(&eps);
    if !in_range || (g.l_over_d() - 1.0).abs() > 0.5 {
        notes.warn(
            "thd_fit_outside_range",
            format!("Jang–Khonsari's THD fits hold for L/D ≈ 1, 0.001 ≤ κ1 ≤ 0.5, 0.01 ≤ κ2 ≤ 5, 0.1 ≤ ε ≤ 0.9; here L/D = {:.2}, κ1 = {kappa1:.3e}, κ2 = {kappa2:.3e}, ε = {eps:.3}", g.l_over_d()),
        );
    }
    (t_max.is_finite() && t_shaft.is_finite() && t_shaft > 0.0).then(|| BushTemperatures {
        max_c: t_in + t_max / beta,
        shaft_c: t_in + t_shaft / beta,
    })
}

/// The effective temperature and the equilibrium together, for a film whose model does not
/// depend on the temperature (laminar, no ported supply): one root in ε. At ε the film gives
/// S(ε), hence the viscosity that carries the load, μ = S W/(N_s L D (R/C)²), hence the
/// temperature T(ε) of that viscosity; the balance is T_in + k ΔT(ε) − T(ε) (Eq. 8.63/8.64),
/// which falls as ε grows (a hotter, thinner oil runs more eccentric and its rise falls), from
/// k ΔT_iso at the isothermal ε (and stays k ΔT below it, where the oil would have to be colder
/// than the inlet: the search starts a unit of ln(ε/(1 − ε)) below the isothermal ε, which
/// may come from a coarser mesh). No root below ε = 0.999 means the film cannot carry the load
/// at the temperature it would run at.
pub(super) fn thermal_equilibrium(
    case: &Case,
    t_in: f64,
    w: f64,
    isothermal: &Operating,
    budget: &Budget,
) -> Result<Operating, CalcError> {
    let balance = HeatBalance {
        case,
        t_in,
        w,
        budget,
    };
    let l_over_d = case.geometry.l_over_d();
    let below = performance::shifted_eccentricity(isothermal.point.eccentricity_ratio.get(), -1.0);
    let (point, _, evaluations) = performance::balance(
        &balance,
        below.max(performance::MIN_ECCENTRICITY),
        l_over_d,
        case.method,
        case.physics(t_in),
        budget,
    )?;
    let op = balance.operating(point)?;
    Ok(Operating { evaluations, ..op })
}

/// The heat balance at the given load (see [`thermal_equilibrium`]).
struct HeatBalance<'a> {
    case: &'a Case,
    t_in: f64,
    w: f64,
    budget: &'a Budget,
}

impl HeatBalance<'_> {
    /// The largest load with a thermal equilibrium: the one whose balance holds at
    /// ε = MAX_ECCENTRICITY (one film solve there, then a root in ln W on the closed heat
    /// balance; the balance rises with the load). None when it cannot be taken.
    fn largest_load(&self) -> Option<f64> {
        let case = self.case;
        let eps = EccentricityRatio::new(MAX_ECCENTRICITY)?;
        let point = performance::at_eccentricity(
            eps,
            case.geometry.l_over_d(),
            case.method,
            case.physics(self.t_in),
            self.budget,
        )
        .ok()?;
        let balance_at = |ln_w: f64| {
            HeatBalance {
                w: ln_w.exp(),
                ..*self
            }
            .residual(&point)
            .unwrap_or(f64::NAN)
        };
        brent(
            balance_at,
            (self.w * 1e-12).ln(),
            self.w.ln(),
            Stopping {
                x_tolerance: 1e-6,
                max_iterations: 100,
            },
        )
        .ok()
        .map(|r| r.x.exp())
    }

    /// The operating point at the temperature whose viscosity carries the load with `point`'s
    /// S; an error when that temperature lies beyond the search's reach.
    fn operating(&self, point: Point) -> Result<Operating, CalcError> {
        let lub = &self.case.lubricant;
        let mu = point.sommerfeld_number * self.w / self.case.load_scale(1.0);
        let hottest = self.t_in + MAX_TEMPERATURE_RISE_K;
        let ln_mu = mu.ln();
        let gap = |t: f64| lub.viscosity_pa_s(t).ln() - ln_mu;
        let too_hot = || {
            CalcError::impossible(
                "/load_n",
                format!("the film carries this load only with the oil thinner than at {hottest:.0} °C ({MAX_TEMPERATURE_RISE_K:.0} K above the inlet): the load is too high for the bearing at this speed and oil"),
            )
        };
        let beyond = gap(hottest);
        if beyond.is_nan() || beyond >= 0.0 {
            return Err(too_hot());
        }
        let t = if gap(self.t_in) <= 0.0 {
            self.t_in
        } else {
            brent(
                gap,
                self.t_in,
                hottest,
                Stopping {
                    x_tolerance: 1e-9,
                    max_iterations: 100,
                },
            )
            .map_err(|e| CalcError::from_root("brent_viscosity_temperature", e))?
            .x
        };
        Ok(Operating {
            point,
            load_n: self.w,
            viscosity_pa_s: mu,
            temperature_c: t,
            evaluations: 0,
        })
    }
}

impl Balance for HeatBalance<'_> {
    fn residual(&self, point: &Point) -> Result<f64, CalcError> {
        let op = match self.operating(point.clone()) {
            Ok(op) => op,
            // Hotter than the search reaches: past the balance.
            Err(CalcError::Impossible { .. }) => return Ok(-MAX_TEMPERATURE_RISE_K),
            Err(e) => return Err(e),
        };
        let rise = self.case.temperature_rise(&op).unwrap_or(0.0);
        Ok(self.t_in + self.case.effective_fraction() * rise - op.temperature_c)
    }

    fn out_of_reach(&self, _at_start: f64, at_end: f64) -> CalcError {
        let largest = self
            .largest_load()
            .filter(|&w| at_end > 0.0 && w < self.w)
            .map(|w| format!(" (it carries at most about {w:.4e} N here, at ε = {MAX_ECCENTRICITY} and its effective temperature)"))
            .unwrap_or_default();
        CalcError::impossible(
            "/load_n",
            format!("no thermal equilibrium below ε = {MAX_ECCENTRICITY}: even there the friction heat would warm the oil {at_end:.1} K above the temperature at which the film carries the load; the load is too high for this bearing at this speed and oil{largest}"),
        )
    }
}

/// Effective temperature: T solves T = T_in + k ΔT(μ(T)) — a bracketed root on [T_in, T_in + k ΔT_iso]
/// (the rise falls as the oil thins, so the bracket holds), each trial an equilibrium search:
/// for films whose model depends on the temperature (turbulent, or fed through ports at a
/// supply pressure whose dimensionless value follows μ) or a given eccentricity.
pub(super) fn effective_temperature(
    case: &Case,
    t_in: f64,
    rise_iso: f64,
    budget: &Budget,
) -> Result<Operating, CalcError> {
    let k = case.effective_fraction();
    let mut last: Option<Operating> = None;
    let f = |t: f64| -> Result<f64, CalcError> {
        match case.operate(t, budget) {
            Ok(op) => {
                let rise = case.temperature_rise(&op).unwrap_or(0.0);
                let g = t - t_in - k * rise;
                last = Some(op);
                Ok(g)
            }
            // Too hot for the model (the thinned oil cannot carry the load, or the viscosity law
            // has no value there): the effective temperature lies below.
            Err(CalcError::Impossible { .. }) if t > t_in => Ok(1e3),
            Err(e) => Err(e),
        }
    };
    let root = brent_outcome(
        f,
        t_in,
        t_in + rise_iso.min(MAX_TEMPERATURE_RISE_K),
        Stopping {
            x_tolerance: 1e-3,
            max_iterations: 60,
        },
    )?;
    match root {
        Ok(r) => case
            .operate(r.x, budget)
            .or_else(|_| last.ok_or(CalcError::Internal("thermal".into()))),
        Err(e @ RootError::NotConverged { .. }) => {
            Err(CalcError::from_root("brent_effective_temperature", e))
        }
        // Still heating at the bracket's hot end: the oil would have to run hotter than the
        // model allows before the heat balance closes.
        Err(RootError::NoSignChange { b, fb, .. }) if fb < 0.0 => Err(CalcError::impossible(
            "/speed_rpm",
            format!(
                "thermal runaway: even with the oil at {b:.0} °C ({:.0} K above the inlet) the friction heat would warm it {:.0} K above the inlet, so no effective temperature balances the heat; the speed is too high for this load, oil, clearance and feed",
                b - t_in,
                b - t_in - fb
            ),
        )),
        Err(_) => Err(CalcError::impossible(
            "/inlet_temperature_c",
            format!(
                "no effective temperature balances the friction heat between {t_in:.1} and {:.1} °C",
                t_in + rise_iso.min(MAX_TEMPERATURE_RISE_K)
            ),
        )),
    }
}
