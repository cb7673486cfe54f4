//! The viscosity of an isoviscous room (squeeze films, dynamically loaded journals, the composite
//! bearing): the shared `lubricant` object, parsed as every room parses it, taken at the
//! request's `temperature_c` (which a constant viscosity does not need).

use super::validity;
use super::LubricantSpec;
use crate::calc::quantity::Celsius;
use crate::calc::FieldError;

/// The viscosity an isoviscous film runs at (Khonsari & Booser §9.2), with the
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
    let t = match validity::operating_temperature(&lubricant, temperature) {
        Ok(t) => t,
        Err(e) => {
            errors.push(e);
            return None;
        }
    };
    let mu = lubricant.viscosity_pa_s(t);
    if !(mu.is_finite() && mu > 0.0) {
        errors.push(FieldError::new(
            "/temperature_c",
            format!("the lubricant's viscosity law has no value at {t} °C"),
        ));
        return None;
    }
    // An isoviscous film needs only the viscosity: an assumed density is no assumption of its.
    let mut assumptions: Vec<_> = lubricant
        .assumptions
        .into_iter()
        .filter(|(code, _)| *code != "density_assumed")
        .collect();
    assumptions.extend(validity::hot_oil("the oil", t));
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
