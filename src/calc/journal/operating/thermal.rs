//! Heat: the effective temperature the viscosity is taken at (Khonsari & Booser Eq. 8.63/8.64)
//! and Jang & Khonsari's THD temperatures.

use std::f64::consts::PI;

use super::{BushTemperatures, Case, Notes, Operating, MAX_TEMPERATURE_RISE_K};
use crate::calc::journal::eccentricity::EccentricityRatio;
use crate::calc::{Budget, CalcError};
use crate::numerics::roots::{brent, RootError, Stopping};

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

/// Effective temperature: T solves T = T_in + k ΔT(μ(T)) — a bracketed root on [T_in, T_in + k ΔT_iso]
/// (the rise falls as the oil thins, so the bracket holds).
pub(super) fn effective_temperature(
    case: &Case,
    t_in: f64,
    rise_iso: f64,
    budget: &Budget,
) -> Result<Operating, CalcError> {
    let k = case.effective_fraction();
    let mut failure = None;
    let mut last: Option<Operating> = None;
    let f = |t: f64| -> f64 {
        match case.operate(t, budget) {
            Ok(op) => {
                let rise = case.temperature_rise(&op).unwrap_or(0.0);
                let g = t - t_in - k * rise;
                last = Some(op);
                g
            }
            // Too hot for the model (the thinned oil cannot carry the load, or the viscosity law
            // has no value there): the effective temperature lies below.
            Err(CalcError::Impossible { .. }) if t > t_in => 1e3,
            Err(e) => {
                failure.get_or_insert(e);
                f64::NAN
            }
        }
    };
    let root = brent(
        f,
        t_in,
        t_in + rise_iso.min(MAX_TEMPERATURE_RISE_K),
        Stopping {
            x_tolerance: 1e-3,
            max_iterations: 60,
        },
    );
    if let Some(e) = failure {
        return Err(e);
    }
    match root {
        Ok(r) => case
            .operate(r.x, budget)
            .or_else(|_| last.ok_or(CalcError::Internal("thermal".into()))),
        Err(e @ RootError::NotConverged { .. }) => {
            Err(CalcError::from_root("brent_effective_temperature", e))
        }
        Err(e) => Err(CalcError::impossible(
            "/inlet_temperature_c",
            format!(
                "no effective temperature in [{t_in:.2}, {:.2}] °C: {e:?}",
                t_in + rise_iso
            ),
        )),
    }
}
