//! The squeeze rooms' viscosity: the shared `lubricant` object, parsed as every room parses it,
//! taken at the request's `temperature_c` (which a constant viscosity does not need).

use crate::calc::lubricant::model::TemperatureLaw;
use crate::calc::lubricant::LubricantSpec;
use crate::calc::quantity::Celsius;
use crate::calc::FieldError;

/// The viscosity a squeeze film runs at (isoviscous: Khonsari & Booser §9.2), with the
/// lubricant's parsing assumptions, reported as warnings.
#[derive(Debug, Clone, PartialEq)]
pub struct Viscosity {
    /// μ, Pa·s.
    pub pa_s: f64,
    pub assumptions: Vec<(&'static str, String)>,
}

/// μ of `spec` at `temperature`: required for a temperature law, ignored (may be absent) for a
/// constant viscosity. Errors point at `/lubricant/…` or `/temperature_c`.
pub fn viscosity(
    spec: LubricantSpec,
    temperature: Option<Celsius>,
    errors: &mut Vec<FieldError>,
) -> Option<Viscosity> {
    let lubricant = match spec.parse("/lubricant") {
        Ok(l) => l,
        Err(mut e) => {
            errors.append(&mut e);
            return None;
        }
    };
    let t = match (&lubricant.temperature_law, temperature) {
        (TemperatureLaw::Constant { .. }, t) => t.map_or(20.0, Celsius::get),
        (_, Some(t)) => t.get(),
        (_, None) => {
            errors.push(FieldError::new(
                "/temperature_c",
                "required: the lubricant's viscosity depends on temperature",
            ));
            return None;
        }
    };
    if let TemperatureLaw::Vogel { c, .. } = lubricant.temperature_law {
        if t <= c - 273.15 + 1.0 {
            errors.push(FieldError::new(
                "/temperature_c",
                format!(
                    "the Vogel law diverges at its c = {:.2} °C; the temperature must lie above it",
                    c - 273.15
                ),
            ));
            return None;
        }
    }
    let mu = lubricant.viscosity_pa_s(t);
    if !(mu.is_finite() && mu > 0.0) {
        errors.push(FieldError::new(
            "/temperature_c",
            format!("the lubricant's viscosity law has no value at {t} °C"),
        ));
        return None;
    }
    // A squeeze film needs only the viscosity: an assumed density is no assumption of its.
    let mut assumptions: Vec<_> = lubricant
        .assumptions
        .into_iter()
        .filter(|(code, _)| *code != "density_assumed")
        .collect();
    if lubricant.pour_point_c.is_some_and(|pour| t < pour) {
        assumptions.push((
            "below_pour_point",
            format!("{t} °C is below the pour point: the oil does not flow and viscosity laws do not hold"),
        ));
    }
    Some(Viscosity {
        pa_s: mu,
        assumptions,
    })
}
