//! `POST /v1/hydrostatic-bearings/pad`: one externally pressurised pad — circular step,
//! annular, rectangular, or any pad by its Loeb–Rippel factors — fed at constant flow or
//! through a capillary or an orifice (given, or designed for a pressure ratio), from any
//! determinate pair of film, load, supply pressure and flow (Khonsari & Booser ch. 10;
//! Stachowiak & Batchelor ch. 6).
//!
//! This file is the wire; the physics is [`super::operating`] with [`super::geometry`],
//! [`super::restrictor`] and [`super::power`].

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::geometry::Geometry;
use super::operating::{self, Case, Compensation, Effects, Known, Operating, Sizing};
use super::power::Motion;
use crate::calc::lubricant::LubricantSpec;
use crate::calc::quantity::{ratio_within, Celsius, NonNegative, Positive};
use crate::calc::range_schemas;
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::effects::Mode;
use crate::fidelity::{Level, SolverReport};

pub struct HydrostaticPad;

/// Largest pad dimension, m.
const MAX_SIZE_M: f64 = 10.0;
/// Film range, m.
const FILM_M: (f64, f64) = (1e-8, 1e-2);
/// The film must stay below this share of the narrowest land (thin film).
const MAX_FILM_OVER_LAND: f64 = 0.1;
/// Smallest recess radius of a circular step pad, as a share of its outer radius.
const MIN_RADIUS_RATIO: f64 = 1e-6;
const LOAD_N: (f64, f64) = (1e-6, 1e10);
const PRESSURE_PA: (f64, f64) = (1.0, 1e10);
const FLOW_M3_S: (f64, f64) = (1e-15, 10.0);
const MAX_SPEED_RPM: f64 = 1e5;
const MAX_SLIDING_M_S: f64 = 500.0;

/// The pad's shape.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum HydrostaticPadKind {
    /// Circular pad, central circular recess (`recess_radius_m`, `outer_radius_m`).
    CircularStep,
    /// Annular pad, annular recess between an inner and an outer land (`inner_radius_m`,
    /// `recess_inner_radius_m`, `recess_outer_radius_m`, `outer_radius_m`).
    Annular,
    /// Rectangular recess with a land of equal width all round (`recess_length_m`,
    /// `recess_width_m`, `land_width_m`).
    Rectangular,
    /// Any pad by its Loeb–Rippel performance factors read off Khonsari & Booser Fig. 10.9
    /// (multi-recess pads, the 120° partial journal): `projected_area_m2`, `pressure_factor`,
    /// `flow_factor`.
    PerformanceFactors,
}

/// The pad: give exactly the fields its `kind` names.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct HydrostaticPadSpec {
    pub kind: HydrostaticPadKind,
    /// `circular_step`: recess radius R1, m (from 1e-6 times `outer_radius_m` to below it).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 0.0635)]
    pub recess_radius_m: Option<Positive>,
    /// `circular_step`, `annular`: outer radius of the pad, m (> 0, at most 10).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 0.127)]
    pub outer_radius_m: Option<Positive>,
    /// `annular`: inner radius of the inner land R1, m.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 0.05)]
    pub inner_radius_m: Option<Positive>,
    /// `annular`: inner radius of the recess R2, m (above `inner_radius_m`).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 0.07)]
    pub recess_inner_radius_m: Option<Positive>,
    /// `annular`: outer radius of the recess R3, m (above `recess_inner_radius_m`, below
    /// `outer_radius_m`).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 0.1)]
    pub recess_outer_radius_m: Option<Positive>,
    /// `rectangular`: recess length b, m (along the sliding direction).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 0.1016)]
    pub recess_length_m: Option<Positive>,
    /// `rectangular`: recess width L, m.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 0.3)]
    pub recess_width_m: Option<Positive>,
    /// `rectangular`: land width l on every side of the recess, m.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 0.0254)]
    pub land_width_m: Option<Positive>,
    /// `performance_factors`: the projected area A the factors refer to, m² (the 120° partial
    /// journal: (√3/2)D², chord × length as Khonsari & Booser Ex 10.3).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 100.0, example = 0.002235)]
    pub projected_area_m2: Option<Positive>,
    /// `performance_factors`: pressure factor P_f = A/A_eff (p_s = P_f W/A, Eq. 10.37),
    /// dimensionless, ≥ 1.
    #[schema(value_type = Option<f64>, minimum = 1.0, maximum = 1000.0, example = 3.5)]
    pub pressure_factor: Option<Positive>,
    /// `performance_factors`: flow factor q_f (Q = q_f (W/A) h³/(12μ), Eq. 10.39),
    /// dimensionless, > 0.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e6, example = 12.0)]
    pub flow_factor: Option<Positive>,
}

/// What feeds the recess.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum HydrostaticCompensationKind {
    /// A constant-flow pump per pad (`flow_m3_s` optional: the flow may be what is solved).
    ConstantFlow,
    /// A capillary: `radius_m` with `length_m`, or `radius_m` with `pressure_ratio` (the
    /// length is then designed).
    Capillary,
    /// An orifice: `discharge_coefficient` with `radius_m`, or with `pressure_ratio` (the
    /// radius is then designed).
    Orifice,
}

/// The pressure ratio: a number, or `"optimum"`.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(
    untagged,
    expecting = "a pressure ratio p_r/p_s (a number in (0, 1)) or \"optimum\""
)]
pub enum HydrostaticPressureRatio {
    /// m = p_r/p_s, within (0, 1).
    Value(f64),
    /// The stiffness-maximising ratio: ½ (capillary), 2 − √2 (orifice).
    Optimum(HydrostaticOptimum),
}

range_schemas::number_or_keyword_schema!(
    HydrostaticPressureRatio,
    HydrostaticOptimum,
    "The recess-to-supply pressure ratio: a number, or `\"optimum\"`.",
    "m = p_r/p_s, within (0, 1).",
    range_schemas::Range {
        minimum: None,
        exclusive_minimum: Some(0.0),
        maximum: None,
        exclusive_maximum: Some(1.0),
    },
    "The stiffness-maximising ratio: ½ (capillary), 2 − √2 (orifice)."
);

/// The stiffness-maximising value.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum HydrostaticOptimum {
    Optimum,
}

/// The compensation: give exactly the fields its `kind` names.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct HydrostaticCompensationSpec {
    pub kind: HydrostaticCompensationKind,
    /// `constant_flow`: the pump's flow Q, m³/s (1e-15 … 10). May instead be given at the top
    /// level (any compensation), or left to be solved.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 4.4e-5)]
    pub flow_m3_s: Option<Positive>,
    /// `capillary` (required), `orifice` (or `pressure_ratio`): bore radius, m (> 0, at most
    /// 0.05).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 0.05, example = 7.62e-4)]
    pub radius_m: Option<Positive>,
    /// `capillary`: length l_c, m (> 0, at most 100), or `pressure_ratio` instead.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 100.0, example = 0.396)]
    pub length_m: Option<Positive>,
    /// `orifice`: discharge coefficient C_D, dimensionless (0 … 1; about 0.6–0.7 at high
    /// Reynolds number, down to 0.3 near Re = 2: Khonsari & Booser §10.5).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1.0, example = 0.6)]
    pub discharge_coefficient: Option<Positive>,
    /// `capillary`, `orifice`: design the restrictor for this recess-to-supply pressure ratio
    /// m = p_r/p_s (0 … 1, exclusive), or `"optimum"` — the ratio that maximises the stiffness
    /// at a given supply pressure: ½ (capillary, Eq. 10.28), 2 − √2 = 0.5858 (orifice, Eq.
    /// 10.35). Replaces the capillary's `length_m` or the orifice's `radius_m`.
    pub pressure_ratio: Option<HydrostaticPressureRatio>,
}

/// Effects a pad understands.
#[derive(Debug, Clone, Copy, Default, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct HydrostaticEffects {
    /// The film's viscosity at its mean temperature T_in + ΔT/2, ΔT = E_total/(ρ c_p Q)
    /// (Khonsari & Booser §10.3), solved as a root in T (model `mean_film_temperature`; the
    /// restrictor stays at the inlet temperature). `auto` applies it when the isothermal rise
    /// lowers the film viscosity by more than 5 %. Not applicable to a constant viscosity.
    #[serde(default)]
    pub thermal: Mode,
    /// Turbulence in the capillary and on the lands, decided on the laminar point: the
    /// capillary's Reynolds number against 2000 (Stachowiak & Batchelor §6.4; Khonsari & Booser
    /// allow 2500), the lands' pressure flow's where its flow per unit width peaks (hydraulic
    /// diameter 2h) against 2000 (Khonsari & Booser §16.1) and their shear's (ρUh/μ at the
    /// fastest edge) against 580 (§7.11). Applied (model `larger_loss_of_laminar_and_turbulent`):
    /// the capillary is laminar to Re 2000 and follows Khonsari & Booser's turbulent line loss
    /// beyond (Eq. 2.36, Darcy f = 0.184 Re^−0.2); the lands' pressure flow and their shear take
    /// the larger loss of the laminar law and the slit law (Eq. 16.2) or the surface drag
    /// (Eq. 7.17–7.18) at every point (§7.11's rule). Chart-factor pads keep laminar lands. `on`
    /// applies the laws at any Reynolds number (where the flow is laminar they are the laminar
    /// closed forms). (Inertia at the recess edge: the texts give no model, so the pad does not
    /// offer it.)
    #[serde(default)]
    pub turbulence: Mode,
}

/// Request. Give exactly two of `film_m`, `load_n`, `supply_pressure_pa` and the flow
/// (`flow_m3_s`, at the top level or in a constant-flow `compensation`); `load_n` with
/// `supply_pressure_pa` needs a sized restrictor (with constant flow or a designed restrictor
/// they fix each other, not the film).
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct HydrostaticPadInput {
    pub pad: HydrostaticPadSpec,
    pub compensation: HydrostaticCompensationSpec,
    pub lubricant: LubricantSpec,
    /// Oil supply temperature, °C (−273 … 1000; default 40): where the viscosity and density
    /// are taken (the film's, with the thermal effect, at its mean temperature).
    #[schema(value_type = Option<f64>, minimum = -273.0, maximum = 1000.0, example = 40.0)]
    pub temperature_c: Option<Celsius>,
    /// Film thickness h over the lands, m (1e-8 … 1e-2, below a tenth of the narrowest land).
    #[schema(value_type = Option<f64>, minimum = 1e-8, maximum = 1e-2, example = 7.62e-5)]
    pub film_m: Option<Positive>,
    /// Load W on the pad, N (1e-6 … 1e10).
    #[schema(value_type = Option<f64>, minimum = 1e-6, maximum = 1e10, example = 177928.0)]
    pub load_n: Option<Positive>,
    /// Supply pressure p_s (gauge), Pa (1 … 1e10): the pump's delivery pressure, before the
    /// restrictor (the recess pressure with constant flow).
    #[schema(value_type = Option<f64>, minimum = 1.0, maximum = 1e10, example = 1.3e7)]
    pub supply_pressure_pa: Option<Positive>,
    /// Flow Q, m³/s (1e-15 … 10), for any compensation (or `compensation.flow_m3_s`).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 4.4e-5)]
    pub flow_m3_s: Option<Positive>,
    /// Pump efficiency η_p, dimensionless (0 … 1; default 1): pumping power p_s Q/η_p.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1.0, example = 0.8)]
    pub pump_efficiency: Option<Positive>,
    /// Runner speed, rpm (0 … 1e5), for the lands' friction on a `circular_step` or `annular`
    /// pad; default 0.
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 1e5, example = 0.0)]
    pub speed_rpm: Option<NonNegative>,
    /// Runner sliding speed over a `rectangular` pad, m/s (0 … 500); default 0.
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 500.0, example = 0.0)]
    pub sliding_speed_m_s: Option<NonNegative>,
    #[serde(default)]
    pub effects: HydrostaticEffects,
}

/// The pad's dimensions, each field named where it is missing, foreign or out of order.
fn parse_pad(spec: &HydrostaticPadSpec, errors: &mut Vec<FieldError>) -> Option<Geometry> {
    use HydrostaticPadKind as K;
    let fields = [
        ("recess_radius_m", spec.recess_radius_m),
        ("outer_radius_m", spec.outer_radius_m),
        ("inner_radius_m", spec.inner_radius_m),
        ("recess_inner_radius_m", spec.recess_inner_radius_m),
        ("recess_outer_radius_m", spec.recess_outer_radius_m),
        ("recess_length_m", spec.recess_length_m),
        ("recess_width_m", spec.recess_width_m),
        ("land_width_m", spec.land_width_m),
        ("projected_area_m2", spec.projected_area_m2),
        ("pressure_factor", spec.pressure_factor),
        ("flow_factor", spec.flow_factor),
    ];
    let wanted: &[&str] = match spec.kind {
        K::CircularStep => &["recess_radius_m", "outer_radius_m"],
        K::Annular => &[
            "outer_radius_m",
            "inner_radius_m",
            "recess_inner_radius_m",
            "recess_outer_radius_m",
        ],
        K::Rectangular => &["recess_length_m", "recess_width_m", "land_width_m"],
        K::PerformanceFactors => &["projected_area_m2", "pressure_factor", "flow_factor"],
    };
    let before = errors.len();
    let mut values = Vec::new();
    for (name, value) in fields {
        let pointer = || format!("/pad/{name}");
        match (wanted.contains(&name), value) {
            (true, None) => errors.push(FieldError::new(pointer(), "required for this kind")),
            (false, Some(_)) => errors.push(FieldError::new(
                pointer(),
                format!(
                    "not a dimension of this kind (it takes {})",
                    wanted.join(", ")
                ),
            )),
            (true, Some(v)) => {
                let v = v.get();
                let max = match name {
                    "projected_area_m2" => 100.0,
                    "pressure_factor" => 1000.0,
                    "flow_factor" => 1e6,
                    _ => MAX_SIZE_M,
                };
                if v > max {
                    errors.push(FieldError::new(pointer(), format!("must be at most {max}")));
                } else if name == "pressure_factor" && v < 1.0 {
                    errors.push(FieldError::new(
                        pointer(),
                        format!(
                            "must be at least 1 (A_eff cannot exceed the projected area), got {v}"
                        ),
                    ));
                } else {
                    values.push(v);
                }
            }
            (false, None) => {}
        }
    }
    if errors.len() > before {
        return None;
    }
    // Radii must differ by more than rounding: ln(R2/R1) divides the load and the flow.
    let apart = |inner: f64, outer: f64| inner < outer * (1.0 - 1e-6);
    match (spec.kind, values.as_slice()) {
        (K::CircularStep, &[recess_radius, outer_radius]) => {
            // ln(R/R₀) overflows once R/R₀ passes 1.8e308 (a 500); a recess below a millionth of
            // the pad is no recess.
            if recess_radius < outer_radius * MIN_RADIUS_RATIO {
                errors.push(FieldError::new(
                    "/pad/recess_radius_m",
                    format!(
                        "must be at least {MIN_RADIUS_RATIO:e} outer_radius_m ({outer_radius} m), got {recess_radius:e}"
                    ),
                ));
                return None;
            }
            if !apart(recess_radius, outer_radius) {
                errors.push(FieldError::new(
                    "/pad/recess_radius_m",
                    format!(
                        "must be below outer_radius_m ({outer_radius} m): the pad needs a land"
                    ),
                ));
                return None;
            }
            Some(Geometry::CircularStep {
                recess_radius,
                outer_radius,
            })
        }
        (K::Annular, &[outer_radius, inner_radius, recess_inner_radius, recess_outer_radius]) => {
            let order = [
                (
                    "recess_inner_radius_m",
                    inner_radius,
                    recess_inner_radius,
                    "inner_radius_m",
                ),
                (
                    "recess_outer_radius_m",
                    recess_inner_radius,
                    recess_outer_radius,
                    "recess_inner_radius_m",
                ),
                (
                    "outer_radius_m",
                    recess_outer_radius,
                    outer_radius,
                    "recess_outer_radius_m",
                ),
            ];
            for (name, below, value, other) in order {
                if !apart(below, value) {
                    errors.push(FieldError::new(
                        format!("/pad/{name}"),
                        format!("must be above {other} ({below} m)"),
                    ));
                }
            }
            if errors.len() > before {
                return None;
            }
            Some(Geometry::Annular {
                inner_radius,
                recess_inner_radius,
                recess_outer_radius,
                outer_radius,
            })
        }
        (K::Rectangular, &[recess_length, recess_width, land_width]) => {
            Some(Geometry::Rectangular {
                recess_length,
                recess_width,
                land_width,
            })
        }
        (K::PerformanceFactors, &[projected_area, pressure_factor, flow_factor]) => {
            Some(Geometry::PerformanceFactors {
                projected_area,
                pressure_factor,
                flow_factor,
            })
        }
        _ => None,
    }
}

/// The compensation, each field named where it is missing or foreign.
fn parse_compensation(
    spec: &HydrostaticCompensationSpec,
    errors: &mut Vec<FieldError>,
) -> Option<Compensation> {
    use HydrostaticCompensationKind as K;
    let before = errors.len();
    let foreign = |name: &str, present: bool, errors: &mut Vec<FieldError>, why: &str| {
        if present {
            errors.push(FieldError::new(
                format!("/compensation/{name}"),
                why.to_owned(),
            ));
        }
    };
    let ratio = match spec.pressure_ratio {
        None => None,
        // Normal: a subnormal m (5e-324) made p_s = p_r/m infinite (a 500).
        Some(HydrostaticPressureRatio::Value(m)) if m.is_normal() && m > 0.0 && m < 1.0 => Some(m),
        Some(HydrostaticPressureRatio::Value(m)) => {
            errors.push(FieldError::new(
                "/compensation/pressure_ratio",
                format!(
                    "must lie strictly between 0 and 1 (p_r below p_s; at least 2.2e-308), or be \"optimum\"; got {m}"
                ),
            ));
            None
        }
        Some(HydrostaticPressureRatio::Optimum(_)) => match spec.kind {
            K::Capillary => Some(0.5),
            K::Orifice => Some(2.0 - std::f64::consts::SQRT_2),
            K::ConstantFlow => None,
        },
    };
    let comp = match spec.kind {
        K::ConstantFlow => {
            let why = "a constant-flow pad has no restrictor";
            foreign("radius_m", spec.radius_m.is_some(), errors, why);
            foreign("length_m", spec.length_m.is_some(), errors, why);
            foreign(
                "discharge_coefficient",
                spec.discharge_coefficient.is_some(),
                errors,
                why,
            );
            foreign("pressure_ratio", spec.pressure_ratio.is_some(), errors, why);
            Compensation::ConstantFlow
        }
        K::Capillary => {
            foreign(
                "discharge_coefficient",
                spec.discharge_coefficient.is_some(),
                errors,
                "a capillary has no discharge coefficient (that is an orifice's)",
            );
            foreign(
                "flow_m3_s",
                spec.flow_m3_s.is_some(),
                errors,
                "the flow is the pad's, not the restrictor's: give it at the top level",
            );
            let radius = match spec.radius_m.map(Positive::get) {
                Some(r) if r <= 0.05 => r,
                Some(r) => {
                    errors.push(FieldError::new(
                        "/compensation/radius_m",
                        format!("must be at most 0.05 m, got {r}"),
                    ));
                    return None;
                }
                None => {
                    errors.push(FieldError::new(
                        "/compensation/radius_m",
                        "required for a capillary",
                    ));
                    return None;
                }
            };
            let sizing = match (spec.length_m.map(Positive::get), ratio) {
                (Some(l), None) if l <= 100.0 => Sizing::Given(l),
                (Some(l), None) => {
                    errors.push(FieldError::new(
                        "/compensation/length_m",
                        format!("must be at most 100 m, got {l}"),
                    ));
                    return None;
                }
                (None, Some(m)) => Sizing::Ratio(m),
                (Some(_), Some(_)) => {
                    errors.push(FieldError::new(
                        "/compensation/length_m",
                        "give length_m or pressure_ratio, not both (the ratio designs the length)",
                    ));
                    return None;
                }
                (None, None) => {
                    if spec.pressure_ratio.is_none() {
                        errors.push(FieldError::new(
                            "/compensation/length_m",
                            "give length_m, or pressure_ratio to design it",
                        ));
                    }
                    return None;
                }
            };
            Compensation::Capillary { radius, sizing }
        }
        K::Orifice => {
            foreign(
                "length_m",
                spec.length_m.is_some(),
                errors,
                "an orifice has no length (a capillary has)",
            );
            foreign(
                "flow_m3_s",
                spec.flow_m3_s.is_some(),
                errors,
                "the flow is the pad's, not the restrictor's: give it at the top level",
            );
            let cd = match spec.discharge_coefficient.map(Positive::get) {
                Some(c) if c <= 1.0 => c,
                Some(c) => {
                    errors.push(FieldError::new(
                        "/compensation/discharge_coefficient",
                        format!("must be at most 1, got {c}"),
                    ));
                    return None;
                }
                None => {
                    errors.push(FieldError::new(
                        "/compensation/discharge_coefficient",
                        "required for an orifice (about 0.6–0.7; Khonsari & Booser §10.5)",
                    ));
                    return None;
                }
            };
            let sizing = match (spec.radius_m.map(Positive::get), ratio) {
                (Some(r), None) if r <= 0.05 => Sizing::Given(r),
                (Some(r), None) => {
                    errors.push(FieldError::new(
                        "/compensation/radius_m",
                        format!("must be at most 0.05 m, got {r}"),
                    ));
                    return None;
                }
                (None, Some(m)) => Sizing::Ratio(m),
                (Some(_), Some(_)) => {
                    errors.push(FieldError::new(
                        "/compensation/radius_m",
                        "give radius_m or pressure_ratio, not both (the ratio designs the radius)",
                    ));
                    return None;
                }
                (None, None) => {
                    if spec.pressure_ratio.is_none() {
                        errors.push(FieldError::new(
                            "/compensation/radius_m",
                            "give radius_m, or pressure_ratio to design it",
                        ));
                    }
                    return None;
                }
            };
            Compensation::Orifice {
                discharge_coefficient: cd,
                sizing,
            }
        }
    };
    (errors.len() == before).then_some(comp)
}

/// The two given quantities, or a 422 that names the fields.
fn parse_known(
    input: &HydrostaticPadInput,
    compensation: Option<Compensation>,
    errors: &mut Vec<FieldError>,
) -> Option<Known> {
    let flow = match (input.flow_m3_s, input.compensation.flow_m3_s) {
        (Some(_), Some(_)) => {
            errors.push(FieldError::new(
                "/compensation/flow_m3_s",
                "give the flow once: flow_m3_s at the top level or in compensation, not both",
            ));
            return None;
        }
        (Some(q), None) => Some(("/flow_m3_s", q.get())),
        (None, Some(q)) => Some(("/compensation/flow_m3_s", q.get())),
        (None, None) => None,
    };
    let film = input.film_m.map(|h| ("/film_m", h.get()));
    let load = input.load_n.map(|w| ("/load_n", w.get()));
    let supply = input
        .supply_pressure_pa
        .map(|p| ("/supply_pressure_pa", p.get()));
    let before = errors.len();
    let mut check = |v: Option<(&str, f64)>, (lo, hi): (f64, f64), unit: &str| {
        if let Some((pointer, x)) = v {
            if !(lo..=hi).contains(&x) {
                errors.push(FieldError::new(
                    pointer,
                    format!("must be within [{lo:e}, {hi:e}] {unit}, got {x}"),
                ));
            }
        }
    };
    check(film, FILM_M, "m");
    check(load, LOAD_N, "N");
    check(supply, PRESSURE_PA, "Pa");
    check(flow, FLOW_M3_S, "m³/s");
    if errors.len() > before {
        return None;
    }
    let given: Vec<(&str, f64)> = [film, load, supply, flow].into_iter().flatten().collect();
    const SET: &str = "two of film_m, load_n, supply_pressure_pa and flow_m3_s";
    if given.len() != 2 {
        let (what, pointers): (&str, Vec<&str>) = if given.len() > 2 {
            ("over-determined", given.iter().map(|g| g.0).collect())
        } else {
            let present: Vec<&str> = given.iter().map(|g| g.0).collect();
            (
                "under-determined",
                ["/film_m", "/load_n", "/supply_pressure_pa", "/flow_m3_s"]
                    .into_iter()
                    .filter(|p| !present.iter().any(|q| q.ends_with(&p[1..])))
                    .collect(),
            )
        };
        for pointer in pointers {
            errors.push(FieldError::new(
                pointer,
                format!("{what}: give exactly {SET} (got {})", given.len()),
            ));
        }
        return None;
    }
    let known = match (film, load, supply, flow) {
        (Some(h), Some(w), None, None) => Known::FilmLoad(h.1, w.1),
        (Some(h), None, Some(p), None) => Known::FilmSupply(h.1, p.1),
        (Some(h), None, None, Some(q)) => Known::FilmFlow(h.1, q.1),
        (None, Some(w), Some(p), None) => Known::LoadSupply(w.1, p.1),
        (None, Some(w), None, Some(q)) => Known::LoadFlow(w.1, q.1),
        (None, None, Some(p), Some(q)) => Known::SupplyFlow(p.1, q.1),
        _ => return None,
    };
    if let (Known::LoadSupply(..), Some(c)) = (known, compensation) {
        let free = match c {
            Compensation::ConstantFlow => {
                Some("with constant flow the supply pressure is the recess pressure")
            }
            Compensation::Capillary {
                sizing: Sizing::Ratio(_),
                ..
            }
            | Compensation::Orifice {
                sizing: Sizing::Ratio(_),
                ..
            } => Some(
                "with the restrictor designed for a pressure ratio the recess pressure is m·p_s",
            ),
            _ => None,
        };
        if let Some(why) = free {
            for pointer in ["/load_n", "/supply_pressure_pa"] {
                errors.push(FieldError::new(
                    pointer,
                    format!("under-determined: {why}, so load and supply pressure fix each other (W = A_eff·p_r), not the film; give film_m or flow_m3_s instead of one of them"),
                ));
            }
            return None;
        }
    }
    Some(known)
}

impl Validate for HydrostaticPadInput {
    type Valid = Case;
    fn validate(self) -> Result<Case, Vec<FieldError>> {
        let mut errors = Vec::new();
        let geometry = parse_pad(&self.pad, &mut errors);
        let compensation = parse_compensation(&self.compensation, &mut errors);
        let known = parse_known(&self, compensation, &mut errors);
        if let (Some(g), Some(h)) = (geometry, self.film_m) {
            if let Some(land) = g.narrowest_land() {
                if !ratio_within(h.get() / land, 0.0, MAX_FILM_OVER_LAND) {
                    errors.push(FieldError::new(
                        "/film_m",
                        format!("must be below a tenth of the narrowest land ({land:.6e} m): not a thin film"),
                    ));
                }
            }
        }
        let rotating = matches!(
            geometry,
            Some(Geometry::CircularStep { .. } | Geometry::Annular { .. })
        );
        let motion = match (
            self.speed_rpm.map(NonNegative::get),
            self.sliding_speed_m_s.map(NonNegative::get),
        ) {
            (Some(_), Some(_)) => {
                errors.push(FieldError::new("/sliding_speed_m_s", "give speed_rpm (a turning runner) or sliding_speed_m_s (a sliding one), not both"));
                Motion::Still
            }
            (Some(n), None) if n > MAX_SPEED_RPM => {
                errors.push(FieldError::new(
                    "/speed_rpm",
                    format!("must be at most {MAX_SPEED_RPM} rpm, got {n}"),
                ));
                Motion::Still
            }
            (Some(n), None)
                if matches!(geometry, Some(Geometry::Rectangular { .. })) && n > 0.0 =>
            {
                errors.push(FieldError::new(
                    "/speed_rpm",
                    "a rectangular pad's runner slides: give sliding_speed_m_s",
                ));
                Motion::Still
            }
            (Some(n), None) => Motion::Rotating {
                omega: n * std::f64::consts::PI / 30.0,
            },
            (None, Some(u)) if u > MAX_SLIDING_M_S => {
                errors.push(FieldError::new(
                    "/sliding_speed_m_s",
                    format!("must be at most {MAX_SLIDING_M_S} m/s, got {u}"),
                ));
                Motion::Still
            }
            (None, Some(u)) if rotating && u > 0.0 => {
                errors.push(FieldError::new(
                    "/sliding_speed_m_s",
                    "a circular or annular pad's runner turns: give speed_rpm",
                ));
                Motion::Still
            }
            (None, Some(u)) => Motion::Sliding { speed: u },
            (None, None) => Motion::Still,
        };
        let motion = match motion {
            Motion::Rotating { omega } | Motion::Sliding { speed: omega } if omega == 0.0 => {
                Motion::Still
            }
            m => m,
        };
        if let Some(eta) = self.pump_efficiency.map(Positive::get).filter(|&e| e > 1.0) {
            errors.push(FieldError::new(
                "/pump_efficiency",
                format!("must be within (0, 1], got {eta}"),
            ));
        }
        let lubricant = match self.lubricant.parse("/lubricant") {
            Ok(l) => Some(l),
            Err(mut e) => {
                errors.append(&mut e);
                None
            }
        };
        let t_in = self.temperature_c.map_or(40.0, Celsius::get);
        if let Some(l) = &lubricant {
            let mu = l.viscosity_pa_s(t_in);
            if !(mu.is_finite() && mu > 0.0) {
                errors.push(FieldError::new(
                    "/temperature_c",
                    format!("the lubricant's viscosity law has no value at {t_in} °C"),
                ));
            }
        }
        match (geometry, compensation, known, lubricant) {
            (Some(geometry), Some(compensation), Some(known), Some(lubricant))
                if errors.is_empty() =>
            {
                Ok(Case {
                    geometry,
                    compensation,
                    known,
                    motion,
                    pump_efficiency: self.pump_efficiency.map_or(1.0, Positive::get).min(1.0),
                    lubricant,
                    inlet_temperature_c: t_in,
                    effects: Effects {
                        thermal: self.effects.thermal,
                        turbulence: self.effects.turbulence,
                    },
                })
            }
            _ => {
                if errors.is_empty() {
                    errors.push(FieldError::new("", "invalid request"));
                }
                Err(errors)
            }
        }
    }
}

/// The restrictor as built and the flow through it.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct HydrostaticRestrictorResult {
    /// `constant_flow`, `capillary` or `orifice`.
    #[schema(example = "capillary")]
    pub kind: &'static str,
    /// Whether the size below was designed from `pressure_ratio` (else it was given).
    pub designed: bool,
    /// Bore radius (capillary, orifice), m: given, or designed (orifice).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub radius_m: Option<f64>,
    /// Capillary length l_c = π R_c⁴/(8 μ K_c), m: given, or designed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub length_m: Option<f64>,
    /// Capillary l_c/(2R_c), dimensionless (Hagen–Poiseuille wants > 100).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub length_to_diameter: Option<f64>,
    /// Orifice discharge coefficient C_D.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub discharge_coefficient: Option<f64>,
    /// Capillary conductance K_c = Q/(p_s − p_r), m³/(s·Pa) (Eq. 10.21).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub conductance_m3_s_pa: Option<f64>,
    /// Orifice coefficient k_o = π R_o² C_D √(2/ρ), m³/(s·Pa^½) (Eq. 10.32).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub orifice_coefficient_m3_s_sqrt_pa: Option<f64>,
    /// p_s − p_r, Pa.
    pub pressure_drop_pa: f64,
    /// Mean velocity in the bore Q/(πR²), m/s.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub mean_velocity_m_s: Option<f64>,
    /// Bore Reynolds number ρ U 2R/μ (mass density, inlet temperature).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub reynolds_number: Option<f64>,
}

/// The pad's Loeb–Rippel factors at this point (Khonsari & Booser Eq. 10.37–10.42).
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct HydrostaticPerformanceFactors {
    /// P_f = A/A_eff = p_r A/W, dimensionless.
    pub pressure_factor: f64,
    /// q_f = Q 12μ/((W/A) h³), dimensionless.
    pub flow_factor: f64,
    /// H_f = P_f q_f/η_p: the bearing's pumping power P_r Q/η_p over (W/A)² h³/(12μ).
    pub power_factor: f64,
}

/// Result.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct HydrostaticPadOutput {
    /// The pad's kind.
    #[schema(example = "circular_step")]
    pub pad_kind: &'static str,
    /// A_eff = W/p_r, m².
    pub effective_area_m2: f64,
    /// The pad's projected area, m².
    pub projected_area_m2: f64,
    /// B̄ = Q μ/(h³ p_r), dimensionless.
    pub flow_coefficient: f64,
    /// Recess pressure p_r (gauge), Pa.
    pub recess_pressure_pa: f64,
    /// Supply pressure p_s (gauge), Pa.
    pub supply_pressure_pa: f64,
    /// m = p_r/p_s, dimensionless (1 at constant flow).
    pub pressure_ratio: f64,
    /// Load W, N.
    pub load_n: f64,
    /// Film over the lands h, m.
    pub film_thickness_m: f64,
    /// Flow Q, m³/s.
    pub flow_m3_s: f64,
    /// −dW/dh at fixed supply pressure (fixed flow at constant flow), N/m.
    pub stiffness_n_m: f64,
    /// p_s Q/η_p, W.
    pub pumping_power_w: f64,
    /// Land friction torque (circular, annular pads), N·m.
    pub friction_torque_n_m: f64,
    /// Land friction force (rectangular pads), N.
    pub friction_force_n: f64,
    /// Land friction power, W.
    pub friction_power_w: f64,
    /// Pumping + friction power, W.
    pub total_power_w: f64,
    /// ζ = friction power/pumping power, dimensionless (≥ 1: a high-speed bearing).
    pub power_ratio: f64,
    /// ΔT = total power/(ρ c_p Q), K (Khonsari & Booser §10.3).
    pub temperature_rise_k: f64,
    /// Where the film's viscosity was taken, °C.
    pub film_temperature_c: f64,
    /// The film's viscosity, Pa·s.
    pub viscosity_pa_s: f64,
    /// The lands' pressure flow's Reynolds number 2ρQ′/μ where the flow per unit width Q′ peaks
    /// (the recess edge of an outward land, an annulus's bore; hydraulic diameter 2h; laminar
    /// below 2000), dimensionless; absent for performance factors.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub land_pressure_flow_reynolds_number: Option<f64>,
    /// The lands' shear flow's film Reynolds number ρUh/μ at the fastest edge (laminar below
    /// 580), dimensionless; absent for performance factors.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub land_shear_reynolds_number: Option<f64>,
    pub restrictor: HydrostaticRestrictorResult,
    pub performance_factors: HydrostaticPerformanceFactors,
}

impl HydrostaticPadOutput {
    fn new(op: &Operating, geometry: &Geometry, eta: f64) -> Self {
        let p = &op.point;
        let r = &op.restrictor;
        let area = geometry.projected_area();
        let unit = p.load / area;
        let pressure_factor = area / op.effective_area;
        let flow_factor = p.flow * 12.0 * op.film_viscosity_pa_s / (unit * p.film.powi(3));
        let orifice = r.kind == super::restrictor::Kind::Orifice;
        HydrostaticPadOutput {
            pad_kind: geometry.name(),
            effective_area_m2: op.effective_area,
            projected_area_m2: area,
            flow_coefficient: op.flow_coefficient,
            recess_pressure_pa: p.recess,
            supply_pressure_pa: p.supply,
            pressure_ratio: p.ratio(),
            load_n: p.load,
            film_thickness_m: p.film,
            flow_m3_s: p.flow,
            stiffness_n_m: op.stiffness,
            pumping_power_w: op.power.pumping,
            friction_torque_n_m: op.power.friction_torque,
            friction_force_n: op.power.friction_force,
            friction_power_w: op.power.friction,
            total_power_w: op.power.total,
            power_ratio: op.power.power_ratio,
            temperature_rise_k: op.power.temperature_rise,
            film_temperature_c: op.film_temperature_c,
            viscosity_pa_s: op.film_viscosity_pa_s,
            land_pressure_flow_reynolds_number: op.land_pressure_flow_reynolds_number,
            land_shear_reynolds_number: op.land_shear_reynolds_number,
            restrictor: HydrostaticRestrictorResult {
                kind: r.kind.name(),
                designed: false,
                radius_m: r.radius,
                length_m: r.length,
                length_to_diameter: r.length.zip(r.radius).map(|(l, rad)| l / (2.0 * rad)),
                discharge_coefficient: r.discharge_coefficient,
                conductance_m3_s_pa: r.conductance.filter(|_| !orifice),
                orifice_coefficient_m3_s_sqrt_pa: r.conductance.filter(|_| orifice),
                pressure_drop_pa: r.pressure_drop,
                mean_velocity_m_s: r.mean_velocity,
                reynolds_number: r.reynolds_number,
            },
            performance_factors: HydrostaticPerformanceFactors {
                pressure_factor,
                flow_factor,
                power_factor: pressure_factor * flow_factor / eta,
            },
        }
    }

    /// Every number, to refuse a result outside the floating-point range.
    fn numbers(&self) -> Vec<f64> {
        let r = &self.restrictor;
        let f = &self.performance_factors;
        let mut v = vec![
            self.effective_area_m2,
            self.projected_area_m2,
            self.flow_coefficient,
            self.recess_pressure_pa,
            self.supply_pressure_pa,
            self.pressure_ratio,
            self.load_n,
            self.film_thickness_m,
            self.flow_m3_s,
            self.stiffness_n_m,
            self.pumping_power_w,
            self.friction_torque_n_m,
            self.friction_force_n,
            self.friction_power_w,
            self.total_power_w,
            self.power_ratio,
            self.temperature_rise_k,
            self.film_temperature_c,
            self.viscosity_pa_s,
            r.pressure_drop_pa,
            f.pressure_factor,
            f.flow_factor,
            f.power_factor,
        ];
        v.extend(
            [
                self.land_pressure_flow_reynolds_number,
                self.land_shear_reynolds_number,
                r.radius_m,
                r.length_m,
                r.length_to_diameter,
                r.discharge_coefficient,
                r.conductance_m3_s_pa,
                r.orifice_coefficient_m3_s_sqrt_pa,
                r.mean_velocity_m_s,
                r.reynolds_number,
            ]
            .into_iter()
            .flatten(),
        );
        v
    }
}

/// The pointer a refusal of a solved quantity names: the given field that is not the film.
fn blame(known: Known) -> &'static str {
    match known {
        Known::FilmLoad(..) | Known::LoadSupply(..) | Known::LoadFlow(..) => "/load_n",
        Known::FilmSupply(..) | Known::SupplyFlow(..) => "/supply_pressure_pa",
        Known::FilmFlow(..) => "/flow_m3_s",
    }
}

impl Calculation for HydrostaticPad {
    const PATH: &'static str = "/v1/hydrostatic-bearings/pad";
    const SUMMARY: &'static str = "Hydrostatic pad (circular step, annular, rectangular, Loeb–Rippel factors) fed at constant flow or through a capillary or orifice: pressures, load, film, flow, stiffness, powers, temperature rise";
    const DESCRIPTION: &'static str = include_str!("pad.md");
    const FIDELITY: &'static [Level] = &[Level::ClosedForm];
    const EFFECTS: &'static [&'static str] = &["thermal", "turbulence"];
    const EXAMPLE: &'static str = r#"{"pad": {"kind": "circular_step", "recess_radius_m": 0.0635, "outer_radius_m": 0.127}, "compensation": {"kind": "capillary", "radius_m": 0.000762, "pressure_ratio": "optimum"}, "lubricant": {"viscosity_pa_s": 0.048263, "density_15c_kg_m3": 830.4}, "temperature_c": 15, "film_m": 7.62e-5, "load_n": 177929, "speed_rpm": 100}"#;

    type Input = HydrostaticPadInput;
    type Output = HydrostaticPadOutput;

    fn run(case: Case, ctx: &mut Context) -> Result<HydrostaticPadOutput, CalcError> {
        let op = operating::operate(&case)?;
        ctx.record(&op.notes);
        let h = op.point.film;
        if !(FILM_M.0..=FILM_M.1).contains(&h) {
            return Err(CalcError::impossible(
                blame(case.known),
                format!(
                    "this set gives a film of {h:.6e} m, outside the model's [{:e}, {:e}] m",
                    FILM_M.0, FILM_M.1
                ),
            ));
        }
        if let Some(land) = case.geometry.narrowest_land() {
            if h > MAX_FILM_OVER_LAND * land * (1.0 + 1e-12) {
                return Err(CalcError::impossible(
                    blame(case.known),
                    format!("this set gives a film of {h:.6e} m, above a tenth of the narrowest land ({land:.6e} m): not a thin film"),
                ));
            }
        }
        let mut out = HydrostaticPadOutput::new(&op, &case.geometry, case.pump_efficiency);
        out.restrictor.designed = matches!(
            case.compensation,
            Compensation::Capillary {
                sizing: Sizing::Ratio(_),
                ..
            } | Compensation::Orifice {
                sizing: Sizing::Ratio(_),
                ..
            }
        );
        // A closed form, or with the thermal effect a Brent root in the film temperature whose
        // every evaluation is the whole closed form; turbulent, the point and its stiffness are
        // Brent roots of the flow balance, whose evaluations count (each may hold a land's own
        // root for its flow; none where the lands give the point directly, a central recess at
        // a given flow).
        ctx.report(match (op.thermal_evaluations, op.turbulent) {
            (0, false) => SolverReport::closed_form("hydrostatic_closed_form"),
            (0, true) => SolverReport::closed_form_search(
                "hydrostatic_turbulent_brent",
                op.balance_evaluations,
            ),
            (n, false) => {
                SolverReport::closed_form_search("hydrostatic_closed_form_thermal_brent", n)
            }
            (n, true) => SolverReport::closed_form_search("hydrostatic_turbulent_thermal_brent", n),
        });
        CalcError::unless_finite(&out.numbers())?;
        Ok(out)
    }
}

#[cfg(test)]
#[path = "tests.rs"]
mod tests;

#[cfg(test)]
#[path = "turbulent_tests.rs"]
mod turbulent_tests;
