//! Where the viscosity laws stop holding: warnings for the user, and 422s where a law has no
//! value at all.

use super::model::{Lubricant, PressureLaw, TemperatureLaw};
use crate::calc::quantity::Celsius;
use crate::calc::{CalcError, Context, FieldError};

/// Barus' law holds to about 70 MPa (10 000 psi; Khonsari & Booser §2.5).
pub const BARUS_LIMIT_PA: f64 = 70e6;
/// ASTM D341's two-constant Walther form holds down to about 2 mm²/s.
pub const WALTHER_LOWEST_MM2_S: f64 = 2.0;
/// The pressures the piezoviscous laws were fitted for reach about 3 GPa (EHL contacts run at
/// 0.5–3 GPa; Khonsari & Booser §2.5, §4): beyond, an oil is a glassy solid whose shear
/// strength, not its viscosity, carries the load.
pub const PIEZOVISCOUS_LIMIT_PA: f64 = 3e9;
/// Lubricating oils' temperature limits, °C: mineral oils 150 (petroleum greases 110–150),
/// synthetic oils and greases 230 (Khonsari & Booser Table 14.7).
pub const MINERAL_OIL_LIMIT_C: f64 = 150.0;
pub const SYNTHETIC_OIL_LIMIT_C: f64 = 230.0;

/// The warning for oil at `t` °C above the mineral oils' or the synthetics' temperature limit
/// (Table 14.7), `what` naming the temperature ("the inlet oil", "the film's maximum"); None
/// within them. The laws still give a viscosity there; the oil would not last.
pub fn hot_oil(what: &str, t: f64) -> Option<(&'static str, String)> {
    if t > SYNTHETIC_OIL_LIMIT_C {
        Some((
            "temperature_above_oil_limit",
            format!("{what} at {t:.1} °C is above the {SYNTHETIC_OIL_LIMIT_C} °C limit of synthetic oils and greases (mineral oils {MINERAL_OIL_LIMIT_C} °C; Khonsari & Booser Table 14.7): no lubricating oil lasts there, and its viscosity law is extrapolated"),
        ))
    } else if t > MINERAL_OIL_LIMIT_C {
        Some((
            "temperature_above_mineral_oil_limit",
            format!("{what} at {t:.1} °C exceeds the {MINERAL_OIL_LIMIT_C} °C limit of mineral oils (petroleum greases 110–150 °C; Khonsari & Booser Table 14.7): a synthetic lubricant is needed (limit {SYNTHETIC_OIL_LIMIT_C} °C)"),
        ))
    } else {
        None
    }
}

/// `hot_oil` as a warning of the room.
pub fn warn_hot_oil(ctx: &mut Context, what: &str, t: f64) {
    if let Some((code, message)) = hot_oil(what, t) {
        ctx.warn(code, message);
    }
}

/// The temperature a room takes its lubricant's properties at: `temperature_c` as sent, which a
/// constant viscosity does not need (then 20 °C, seen only by its density and heat
/// properties, which are constant too). Refused at `/temperature_c` when a temperature law needs
/// it and it is absent, or at or below a Vogel law's pole.
pub fn operating_temperature(
    lub: &Lubricant,
    temperature: Option<Celsius>,
) -> Result<f64, FieldError> {
    let t = match (&lub.temperature_law, temperature) {
        (TemperatureLaw::Constant { .. }, t) => t.map_or(20.0, Celsius::get),
        (_, Some(t)) => t.get(),
        (_, None) => {
            return Err(FieldError::new(
                "/temperature_c",
                "required: the lubricant's viscosity depends on temperature",
            ))
        }
    };
    match lub.temperature_law {
        TemperatureLaw::Vogel { c, .. } if t <= c - 273.15 + 1.0 => Err(FieldError::new(
            "/temperature_c",
            format!(
                "the Vogel law diverges at its c = {:.2} °C; the temperature must lie above it",
                c - 273.15
            ),
        )),
        _ => Ok(t),
    }
}

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
    let hottest = temperatures_c
        .iter()
        .copied()
        .fold(f64::NEG_INFINITY, f64::max);
    warn_hot_oil(ctx, "the hottest temperature asked", hottest);
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
