//! Where the viscosity laws stop holding: warnings for the user, and 422s where a law has no
//! value at all.

use super::model::{Lubricant, PressureLaw, TemperatureLaw};
use crate::calc::{CalcError, Context};

/// Barus' law holds to about 70 MPa (10 000 psi; Khonsari & Booser §2.5).
pub const BARUS_LIMIT_PA: f64 = 70e6;
/// ASTM D341's two-constant Walther form holds down to about 2 mm²/s.
pub const WALTHER_LOWEST_MM2_S: f64 = 2.0;

/// Check every temperature against the law's range: warnings outside validity, a 422 where the
/// law diverges (at or below Vogel's c).
pub fn check_temperatures(
    ctx: &mut Context,
    lub: &Lubricant,
    temperatures_c: &[f64],
) -> Result<(), CalcError> {
    if let TemperatureLaw::Vogel { c, .. } = lub.temperature_law {
        let c_celsius = c - 273.15;
        if let Some(i) = temperatures_c.iter().position(|&t| t <= c_celsius + 1.0) {
            return Err(CalcError::impossible(
                &format!("/temperatures_c/{i}"),
                format!("the Vogel law diverges at its c = {c_celsius:.2} °C; temperatures must lie above it"),
            ));
        }
    }
    if let TemperatureLaw::Walther { .. } = lub.temperature_law {
        if let Some(&t) = temperatures_c
            .iter()
            .find(|&&t| lub.kinematic_mm2_s(t) < WALTHER_LOWEST_MM2_S)
        {
            ctx.warn(
                "walther_below_2_mm2_s",
                format!("at {t} °C the Walther law gives below {WALTHER_LOWEST_MM2_S} mm²/s, where ASTM D341's two-constant form loses accuracy"),
            );
        }
    }
    if let Some(pour) = lub.pour_point_c {
        if let Some(&t) = temperatures_c.iter().find(|&&t| t < pour) {
            ctx.warn(
                "below_pour_point",
                format!("{t} °C is below the pour point {pour} °C: the oil does not flow and viscosity laws do not hold"),
            );
        }
    }
    if let Some(&t) = temperatures_c.iter().find(|&&t| {
        let mu = lub.viscosity_pa_s(t);
        !(mu.is_finite() && mu > 0.0)
    }) {
        return Err(CalcError::impossible(
            "/temperatures_c",
            format!("the viscosity law leaves the floating-point range at {t} °C"),
        ));
    }
    Ok(())
}

/// Roelands' law needs log10 μ0 + 1.2 > 0 (μ0 above 10^-1.2 ≈ 0.063 mPa·s, μ0 in mPa·s); below
/// that its viscosity would fall with pressure.
pub fn check_pressure_law(lub: &Lubricant, temperatures_c: &[f64]) -> Result<(), CalcError> {
    if let Some(PressureLaw::Roelands { .. }) = lub.pressure_law {
        if let Some(i) = temperatures_c
            .iter()
            .position(|&t| (lub.viscosity_pa_s(t) * 1e3).log10() + 1.2 <= 0.0)
        {
            return Err(CalcError::impossible(
                &format!("/temperatures_c/{i}"),
                "Roelands' pressure–viscosity law needs a viscosity above 6.3e-5 Pa·s at the temperature; use the Barus coefficient for so thin a fluid",
            ));
        }
    }
    Ok(())
}
