//! `POST /v1/composite-bearings/speed-split`: the steady speed split of Harnoy's composite
//! bearing (a rolling bearing and a fluid-film sleeve in series) under a centrifugal pin
//! restraint, and the same bearing with its sleeve held (Harnoy ch. 18, §18.2 and §18.4.1).
//!
//! This file is the wire (request, validation, response) and the parsing the start-up room
//! shares; the physics is [`super::film`], [`super::sleeve`] and [`super::split`].

use std::f64::consts::PI;

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::film::{LoadError, SleeveFilm, MAX_ECCENTRICITY};
use super::sleeve::Restraint;
use super::split::{split, Operating};
use crate::calc::lubricant::isoviscous::{self, Viscosity};
use crate::calc::lubricant::LubricantSpec;
use crate::calc::quantity::{Celsius, NonNegative, Positive};
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::fidelity::{Level, SolverReport};

pub struct SpeedSplit;

/// Largest journal radius and sleeve length, m.
const MAX_SIZE_M: f64 = 10.0;
/// Clearance range: at least 0.1 µm, at most a tenth of the radius (a thin film).
const MIN_CLEARANCE_M: f64 = 1e-7;
const MAX_CLEARANCE_OVER_RADIUS: f64 = 0.1;
/// Largest L/D: the short-bearing film overstates the load increasingly beyond 1/2.
const MAX_L_OVER_D: f64 = 2.0;
pub(super) const SHORT_L_OVER_D: f64 = 0.5;
/// Largest journal speed, rpm.
pub(super) const MAX_SPEED_RPM: f64 = 1e6;
/// Largest load, N.
const MAX_LOAD_N: f64 = 1e9;
/// Ranges of the restraint's factors.
const MAX_FRICTION_COEFFICIENT: f64 = 2.0;
const MAX_PIN_MASS_KG: f64 = 1e4;
const MAX_RESTRAINT_KG_M2: f64 = 1e6;
/// Largest rolling-bearing friction torque, N·m.
const MAX_ROLLING_TORQUE_N_M: f64 = 1e6;
/// Thermal inputs' ranges.
const MAX_WALL_M: f64 = 1.0;
const MAX_DIFFUSIVITY_M2_S: f64 = 1e-2;
/// Below this sleeve speed the rolling bearing's EHL film is poor (Harnoy §18.6, Fig 18-4).
pub(super) const LOW_SLEEVE_RPM: f64 = 30.0;

pub(super) fn rad_s(rpm: f64) -> f64 {
    rpm * PI / 30.0
}

pub(super) fn rpm(rad_s: f64) -> f64 {
    rad_s * 30.0 / PI
}

/// Request.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct CompositeSpeedSplitInput {
    /// Journal radius R, m (0 … 10).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 10.0, example = 0.05)]
    pub journal_radius_m: Positive,
    /// Length L of the sleeve's bore (the film), m (0 … 10; L/D at most 2, the short-bearing
    /// film is meant for L/D ≤ 1/2).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 10.0, example = 0.1)]
    pub sleeve_length_m: Positive,
    /// Radial clearance C between journal and sleeve, m (1e-7 … a tenth of the radius).
    #[schema(value_type = f64, minimum = 1e-7, maximum = 0.1, example = 6e-5)]
    pub radial_clearance_m: Positive,
    pub lubricant: LubricantSpec,
    /// Film temperature, °C (−273 … 1000): where the viscosity is taken; required unless the
    /// lubricant has a constant `viscosity_pa_s`.
    #[schema(value_type = Option<f64>, minimum = -273.0, maximum = 1000.0, example = 40.0)]
    pub temperature_c: Option<Celsius>,
    /// Journal speed ω_j, rpm (0 … 1e6).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 1e6, example = 3500.0)]
    pub journal_speed_rpm: Positive,
    /// Eccentricity ratio ε = e/C of the composite bearing, dimensionless (0 … 0.999); give it
    /// or `load_n`.
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 0.999, example = 0.5)]
    pub eccentricity_ratio: Option<NonNegative>,
    /// Radial load on the journal W, N (0 … 1e9); give it or `eccentricity_ratio`.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e9, example = 20000.0)]
    pub load_n: Option<Positive>,
    /// Boundary friction coefficient f_c between the centrifugal pins and the housing,
    /// dimensionless (0 … 2); with `pin_mass_kg`, `pin_radius_m` and `housing_radius_m`, or
    /// give their product `restraint_coefficient_kg_m2`.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 2.0, example = 0.3)]
    pub pin_friction_coefficient: Option<Positive>,
    /// Total mass of the centrifugal pins m_c, kg (0 … 1e4).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e4, example = 1.5)]
    pub pin_mass_kg: Option<Positive>,
    /// Radius R_m of the circle of the pins' centres when they touch the housing, m (0 … 10,
    /// at most `housing_radius_m`).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 0.085)]
    pub pin_radius_m: Option<Positive>,
    /// Radius R_h of the housing bore the pins rub on, m (0 … 10).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 0.0933)]
    pub housing_radius_m: Option<Positive>,
    /// The restraint's coefficient k = f_c m_c R_m R_h, kg·m² (0 … 1e6): M_f = k ω_b²; instead
    /// of its four factors.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e6, example = 0.0357)]
    pub restraint_coefficient_kg_m2: Option<Positive>,
    /// Friction torque M_r of the rolling bearing, N·m (0 … 1e6; default 0), constant,
    /// opposing the sleeve's rotation; at rest it holds the sleeve while the film's torque is
    /// below it.
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 1e6, example = 0.0)]
    pub rolling_friction_torque_n_m: Option<NonNegative>,
    /// Sleeve wall thickness b = R_o − R_i, m (0 … 1): with `sleeve_thermal_diffusivity_m2_s`,
    /// the sleeve's Péclet number.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1.0, example = 0.01)]
    pub sleeve_wall_thickness_m: Option<Positive>,
    /// Thermal diffusivity α_b = k/(ρ c_p) of the sleeve, m²/s (0 … 1e-2; steel about 1.5e-5).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e-2, example = 1.5e-5)]
    pub sleeve_thermal_diffusivity_m2_s: Option<Positive>,
}

/// What the speed split and the start-up share: the film, the restraint and the journal speed.
#[derive(Debug, Clone, PartialEq)]
pub struct Bearing {
    pub film: SleeveFilm,
    pub restraint: Restraint,
    /// ω_j, rad/s.
    pub journal_speed: f64,
    pub viscosity: Viscosity,
}

/// The fields both rooms take, as they arrive.
pub(super) struct BearingFields {
    pub journal_radius_m: Positive,
    pub sleeve_length_m: Positive,
    pub radial_clearance_m: Positive,
    pub lubricant: LubricantSpec,
    pub temperature_c: Option<Celsius>,
    pub journal_speed_rpm: Positive,
    pub pin_friction_coefficient: Option<Positive>,
    pub pin_mass_kg: Option<Positive>,
    pub pin_radius_m: Option<Positive>,
    pub housing_radius_m: Option<Positive>,
    pub restraint_coefficient_kg_m2: Option<Positive>,
    pub rolling_friction_torque_n_m: Option<NonNegative>,
}

/// k from its four factors or as given; each missing or surplus field named.
fn parse_restraint(f: &BearingFields, errors: &mut Vec<FieldError>) -> Option<f64> {
    let factors = [
        (
            "pin_friction_coefficient",
            f.pin_friction_coefficient,
            MAX_FRICTION_COEFFICIENT,
            "",
        ),
        ("pin_mass_kg", f.pin_mass_kg, MAX_PIN_MASS_KG, " kg"),
        ("pin_radius_m", f.pin_radius_m, MAX_SIZE_M, " m"),
        ("housing_radius_m", f.housing_radius_m, MAX_SIZE_M, " m"),
    ];
    let given = factors.iter().filter(|(_, v, _, _)| v.is_some()).count();
    const EITHER: &str = "give restraint_coefficient_kg_m2, or all of pin_friction_coefficient, pin_mass_kg, pin_radius_m and housing_radius_m";
    match (f.restraint_coefficient_kg_m2, given) {
        (Some(k), 0) => {
            if k.get() > MAX_RESTRAINT_KG_M2 {
                errors.push(FieldError::new(
                    "/restraint_coefficient_kg_m2",
                    format!("must be at most {MAX_RESTRAINT_KG_M2:e} kg·m²"),
                ));
                return None;
            }
            Some(k.get())
        }
        (Some(_), _) => {
            errors.push(FieldError::new(
                "/restraint_coefficient_kg_m2",
                format!("over-determined: {EITHER}, not both"),
            ));
            None
        }
        (None, 4) => {
            let before = errors.len();
            for (name, value, max, unit) in factors {
                if value.is_some_and(|v| v.get() > max) {
                    errors.push(FieldError::new(
                        format!("/{name}"),
                        format!("must be at most {max}{unit}"),
                    ));
                }
            }
            let v: Vec<f64> = factors
                .iter()
                .filter_map(|(_, v, _, _)| v.map(Positive::get))
                .collect();
            if errors.len() == before && v[2] > v[3] {
                errors.push(FieldError::new(
                    "/pin_radius_m",
                    "must be at most housing_radius_m (the pins' centres lie inside the housing bore they rub on)",
                ));
            }
            (errors.len() == before).then(|| v.iter().product())
        }
        (None, _) => {
            for (name, value, _, _) in factors {
                if value.is_none() {
                    errors.push(FieldError::new(
                        format!("/{name}"),
                        format!("under-determined: {EITHER}"),
                    ));
                }
            }
            None
        }
    }
}

/// The film, the restraint and the speed, or every invalid field.
pub(super) fn parse_bearing(f: BearingFields, errors: &mut Vec<FieldError>) -> Option<Bearing> {
    let before = errors.len();
    let (r, l, c) = (
        f.journal_radius_m.get(),
        f.sleeve_length_m.get(),
        f.radial_clearance_m.get(),
    );
    for (name, v) in [("journal_radius_m", r), ("sleeve_length_m", l)] {
        if v > MAX_SIZE_M {
            errors.push(FieldError::new(
                format!("/{name}"),
                format!("must be at most {MAX_SIZE_M} m"),
            ));
        }
    }
    if c < MIN_CLEARANCE_M || c > MAX_CLEARANCE_OVER_RADIUS * r {
        errors.push(FieldError::new(
            "/radial_clearance_m",
            format!(
                "must lie within [{MIN_CLEARANCE_M:e} m, {MAX_CLEARANCE_OVER_RADIUS} × journal_radius_m = {:.4e} m] (a thin film)",
                MAX_CLEARANCE_OVER_RADIUS * r
            ),
        ));
    }
    if r <= MAX_SIZE_M && l / (2.0 * r) > MAX_L_OVER_D * (1.0 + 1e-12) {
        errors.push(FieldError::new(
            "/sleeve_length_m",
            format!(
                "L/D = {:.3} must be at most {MAX_L_OVER_D}: the short-bearing film (meant for L/D ≤ 1/2) does not stretch further",
                l / (2.0 * r)
            ),
        ));
    }
    let n = f.journal_speed_rpm.get();
    if n > MAX_SPEED_RPM {
        errors.push(FieldError::new(
            "/journal_speed_rpm",
            format!("must be at most {MAX_SPEED_RPM:e} rpm"),
        ));
    }
    let rolling = f.rolling_friction_torque_n_m.map_or(0.0, NonNegative::get);
    if rolling > MAX_ROLLING_TORQUE_N_M {
        errors.push(FieldError::new(
            "/rolling_friction_torque_n_m",
            format!("must be at most {MAX_ROLLING_TORQUE_N_M:e} N·m"),
        ));
    }
    let k = parse_restraint(&f, errors);
    let viscosity = isoviscous::viscosity(f.lubricant, f.temperature_c, errors);
    match (errors.len() == before, k, viscosity) {
        (true, Some(k), Some(viscosity)) => Some(Bearing {
            film: SleeveFilm {
                radius: r,
                length: l,
                clearance: c,
                viscosity: viscosity.pa_s,
            },
            restraint: Restraint {
                coefficient: k,
                rolling_torque: rolling,
            },
            journal_speed: rad_s(n),
            viscosity,
        }),
        _ => None,
    }
}

/// The sleeve's wall thickness b and thermal diffusivity α_b for the Péclet number, where both
/// are given (one without the other is named).
pub(super) fn parse_thermal(
    wall: Option<Positive>,
    diffusivity: Option<Positive>,
    errors: &mut Vec<FieldError>,
) -> Option<(f64, f64)> {
    match (wall, diffusivity) {
        (None, None) => None,
        (Some(b), Some(a)) => {
            if b.get() > MAX_WALL_M {
                errors.push(FieldError::new(
                    "/sleeve_wall_thickness_m",
                    format!("must be at most {MAX_WALL_M} m"),
                ));
            }
            if a.get() > MAX_DIFFUSIVITY_M2_S {
                errors.push(FieldError::new(
                    "/sleeve_thermal_diffusivity_m2_s",
                    format!("must be at most {MAX_DIFFUSIVITY_M2_S:e} m²/s"),
                ));
            }
            Some((b.get(), a.get()))
        }
        (Some(_), None) => {
            errors.push(FieldError::new(
                "/sleeve_thermal_diffusivity_m2_s",
                "required with sleeve_wall_thickness_m (the Péclet number takes both)",
            ));
            None
        }
        (None, Some(_)) => {
            errors.push(FieldError::new(
                "/sleeve_wall_thickness_m",
                "required with sleeve_thermal_diffusivity_m2_s (the Péclet number takes both)",
            ));
            None
        }
    }
}

/// The sleeve's modified Péclet number ω_b R_b b/α_b (Eq. 18-40) at sleeve speed ω_b (rad/s),
/// R_b = R + C + b/2 the wall's mean radius, from `(b, α_b)`.
pub(super) fn peclet_number(
    film: &SleeveFilm,
    (wall, diffusivity): (f64, f64),
    sleeve_speed: f64,
) -> f64 {
    let mean_radius = film.radius + film.clearance + 0.5 * wall;
    sleeve_speed * mean_radius * wall / diffusivity
}

/// The parsed request.
#[derive(Debug, Clone, PartialEq)]
pub struct CompositeSpeedSplitCase {
    pub bearing: Bearing,
    pub operating: Operating,
    /// (wall thickness b, m; diffusivity α_b, m²/s), where both are given.
    pub thermal: Option<(f64, f64)>,
}

impl Validate for CompositeSpeedSplitInput {
    type Valid = CompositeSpeedSplitCase;
    fn validate(self) -> Result<CompositeSpeedSplitCase, Vec<FieldError>> {
        let mut errors = Vec::new();
        let operating = match (self.eccentricity_ratio, self.load_n) {
            (Some(e), None) if e.get() > MAX_ECCENTRICITY => {
                errors.push(FieldError::new(
                    "/eccentricity_ratio",
                    format!("must be at most {MAX_ECCENTRICITY} (h_min ≥ C/1000; at 1 the journal touches the sleeve)"),
                ));
                None
            }
            (Some(e), None) => Some(Operating::Eccentricity(e.get())),
            (None, Some(w)) if w.get() > MAX_LOAD_N => {
                errors.push(FieldError::new(
                    "/load_n",
                    format!("must be at most {MAX_LOAD_N:e} N"),
                ));
                None
            }
            (None, Some(w)) => Some(Operating::Load(w.get())),
            _ => {
                errors.push(FieldError::new(
                    "/load_n",
                    "give exactly one of eccentricity_ratio and load_n",
                ));
                None
            }
        };
        let thermal = parse_thermal(
            self.sleeve_wall_thickness_m,
            self.sleeve_thermal_diffusivity_m2_s,
            &mut errors,
        );
        let bearing = parse_bearing(
            BearingFields {
                journal_radius_m: self.journal_radius_m,
                sleeve_length_m: self.sleeve_length_m,
                radial_clearance_m: self.radial_clearance_m,
                lubricant: self.lubricant,
                temperature_c: self.temperature_c,
                journal_speed_rpm: self.journal_speed_rpm,
                pin_friction_coefficient: self.pin_friction_coefficient,
                pin_mass_kg: self.pin_mass_kg,
                pin_radius_m: self.pin_radius_m,
                housing_radius_m: self.housing_radius_m,
                restraint_coefficient_kg_m2: self.restraint_coefficient_kg_m2,
                rolling_friction_torque_n_m: self.rolling_friction_torque_n_m,
            },
            &mut errors,
        );
        match (errors.is_empty(), bearing, operating) {
            (true, Some(bearing), Some(operating)) => Ok(CompositeSpeedSplitCase {
                bearing,
                operating,
                thermal,
            }),
            _ => Err(errors),
        }
    }
}

/// The same bearing with its sleeve held, at the composite's load.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct CompositeFixedSleeve {
    /// Eccentricity ratio ε of the held sleeve at the same load (it may pass 0.999 where the
    /// composite runs near its bound), dimensionless.
    pub eccentricity_ratio: f64,
    /// Minimum film C(1 − ε), m.
    pub min_film_m: f64,
    /// The film's torque 2nω_j on the held sleeve (and on the journal), N·m.
    pub hydrodynamic_torque_n_m: f64,
    /// Power dissipated in the film, M_h ω_j, W.
    pub power_w: f64,
}

/// Result.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct CompositeSpeedSplitOutput {
    /// Steady sleeve speed ω_b, rpm.
    pub sleeve_speed_rpm: f64,
    /// ξ = ω_b/ω_j, dimensionless (0 … 1; 0 when the rolling bearing's friction holds the
    /// sleeve).
    pub speed_ratio: f64,
    /// The film's torque on the sleeve (and on the journal) M_h, N·m.
    pub hydrodynamic_torque_n_m: f64,
    /// The pins' friction torque M_f = k ω_b², N·m.
    pub pin_torque_n_m: f64,
    /// The torque the rolling bearing takes, N·m: M_r while the sleeve turns, the film's whole
    /// torque while it holds the sleeve.
    pub rolling_friction_torque_n_m: f64,
    /// Power dissipated in the film M_h (ω_j − ω_b), W.
    pub hydrodynamic_power_w: f64,
    /// Power dissipated at the pins M_f ω_b, W.
    pub pin_power_w: f64,
    /// Power dissipated in the rolling bearing M_r ω_b, W.
    pub rolling_power_w: f64,
    /// Power the journal delivers M_h ω_j, W: the sum of the three.
    pub total_power_w: f64,
    /// Eccentricity ratio ε, dimensionless.
    pub eccentricity_ratio: f64,
    /// Minimum film C(1 − ε), m.
    pub min_film_m: f64,
    /// The load the film carries W, N (the request's, where it gives one).
    pub load_n: f64,
    /// Attitude angle between the load line and the line of centres, degrees (the short
    /// bearing's: tan ψ = π√(1 − ε²)/(4ε)).
    pub attitude_angle_deg: f64,
    /// The restraint's coefficient k = f_c m_c R_m R_h used, kg·m².
    pub restraint_coefficient_kg_m2: f64,
    /// The film's heat flux over a held sleeve's at the same film, (ω_j − ω_b)/ω_j (Eq. 18-42),
    /// dimensionless.
    pub heat_flux_ratio: f64,
    /// Modified Péclet number ω_b R_b b/α_b of the sleeve (Eq. 18-40; R_b = R + C + b/2),
    /// dimensionless, with `sleeve_wall_thickness_m` and `sleeve_thermal_diffusivity_m2_s`:
    /// ≫ 1 means an axisymmetric sleeve temperature.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sleeve_peclet_number: Option<f64>,
    /// The same bearing with the sleeve held, at the same load.
    pub fixed_sleeve: CompositeFixedSleeve,
    /// min_film_m over the held sleeve's, dimensionless (> 1: the composite's film is thicker).
    pub min_film_ratio: f64,
}

/// A load the film cannot carry, as a 422 on `pointer`.
pub(super) fn load_error(pointer: &str, load: f64, error: LoadError) -> CalcError {
    match error {
        LoadError::TooHeavy { max_load } => CalcError::impossible(
            pointer,
            format!(
                "the film cannot carry {load:.6e} N: at ε = {MAX_ECCENTRICITY} (h_min = C/1000) it carries {max_load:.6e} N; raise the speed, the viscosity or the sleeve length, or lower the load"
            ),
        ),
        LoadError::Search(e) => CalcError::from_root("composite_load_search", e),
    }
}

impl Calculation for SpeedSplit {
    const PATH: &'static str = "/v1/composite-bearings/speed-split";
    const SUMMARY: &'static str = "Composite bearing (rolling bearing and fluid-film sleeve in series, Harnoy): steady sleeve speed under a centrifugal pin restraint, torques, powers, film, and the same bearing with the sleeve held";
    const DESCRIPTION: &'static str = include_str!("speed_split.md");
    const FIDELITY: &'static [Level] = &[Level::ClosedForm];
    const EFFECTS: &'static [&'static str] = &[];
    const EXAMPLE: &'static str = r#"{"journal_radius_m": 0.05, "sleeve_length_m": 0.1, "radial_clearance_m": 6e-5, "lubricant": {"viscosity_pa_s": 0.03}, "journal_speed_rpm": 3500, "eccentricity_ratio": 0.5, "restraint_coefficient_kg_m2": 0.0357, "sleeve_wall_thickness_m": 0.01, "sleeve_thermal_diffusivity_m2_s": 1.5e-5}"#;

    type Input = CompositeSpeedSplitInput;
    type Output = CompositeSpeedSplitOutput;

    fn run(
        case: CompositeSpeedSplitCase,
        ctx: &mut Context,
    ) -> Result<CompositeSpeedSplitOutput, CalcError> {
        let Bearing {
            film,
            restraint,
            journal_speed: wj,
            viscosity,
        } = case.bearing;
        for (code, message) in &viscosity.assumptions {
            ctx.warn(code, message.clone());
        }
        let pointer = match case.operating {
            Operating::Load(_) => "/load_n",
            Operating::Eccentricity(_) => "/eccentricity_ratio",
        };
        let s = split(&film, &restraint, wj, case.operating).map_err(|e| {
            let load = match case.operating {
                Operating::Load(w) => w,
                Operating::Eccentricity(_) => f64::NAN,
            };
            load_error(pointer, load, e)
        })?;
        ctx.report(SolverReport::closed_form_search(
            "closed_form_load_search",
            s.evaluations,
        ));
        let c = s.composite;
        let wb = c.speed_ratio * wj;
        let pin = restraint.pin_torque(wb);
        let rolling = if c.speed_ratio > 0.0 {
            restraint.rolling_torque
        } else {
            c.torque
        };
        let l_over_d = film.length / (2.0 * film.radius);
        if l_over_d > SHORT_L_OVER_D {
            ctx.warn(
                "short_bearing_beyond_range",
                format!("L/D = {l_over_d:.3} exceeds 1/2: the short-bearing film overstates the load (its trends hold to about L/D = 1)"),
            );
        }
        if c.speed_ratio == 0.0 {
            ctx.warn(
                "sleeve_held",
                format!(
                    "the rolling bearing's friction torque {:.4e} N·m is at least the film's torque on a held sleeve ({:.4e} N·m): the sleeve stands and the bearing runs as a plain journal bearing",
                    restraint.rolling_torque, c.torque
                ),
            );
        } else if rpm(wb) < LOW_SLEEVE_RPM {
            ctx.warn(
                "low_sleeve_speed",
                format!("the sleeve turns at {:.1} rpm: below about {LOW_SLEEVE_RPM} rpm the rolling bearing's EHL film is poor and its friction higher (Harnoy §18.6, Fig 18-4)", rpm(wb)),
            );
        }
        if s.fixed.eccentricity > MAX_ECCENTRICITY {
            ctx.warn(
                "fixed_sleeve_near_contact",
                format!("with the sleeve held the journal would run at ε = {:.5}, beyond {MAX_ECCENTRICITY}: h_min below C/1000", s.fixed.eccentricity),
            );
        }
        let min_film = film.clearance * (1.0 - c.eccentricity);
        let fixed_film = film.clearance * (1.0 - s.fixed.eccentricity);
        let peclet = case
            .thermal
            .map(|thermal| peclet_number(&film, thermal, wb));
        let output = CompositeSpeedSplitOutput {
            sleeve_speed_rpm: rpm(wb),
            speed_ratio: c.speed_ratio,
            hydrodynamic_torque_n_m: c.torque,
            pin_torque_n_m: pin,
            rolling_friction_torque_n_m: rolling,
            hydrodynamic_power_w: c.torque * (wj - wb),
            pin_power_w: pin * wb,
            rolling_power_w: rolling * wb,
            total_power_w: c.torque * wj,
            eccentricity_ratio: c.eccentricity,
            min_film_m: min_film,
            load_n: c.load,
            attitude_angle_deg: SleeveFilm::attitude_angle(c.eccentricity).to_degrees(),
            restraint_coefficient_kg_m2: restraint.coefficient,
            heat_flux_ratio: 1.0 - c.speed_ratio,
            sleeve_peclet_number: peclet,
            fixed_sleeve: CompositeFixedSleeve {
                eccentricity_ratio: s.fixed.eccentricity,
                min_film_m: fixed_film,
                hydrodynamic_torque_n_m: s.fixed.torque,
                power_w: s.fixed.torque * wj,
            },
            min_film_ratio: min_film / fixed_film,
        };
        CalcError::finite_or_out_of_range(output, "the speed, viscosity, clearance and sizes")
    }
}

#[cfg(test)]
#[path = "speed_split_tests.rs"]
mod tests;
