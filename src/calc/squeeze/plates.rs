//! `POST /v1/squeeze-films/plates`: the squeeze film between rigid surfaces approaching each
//! other — parallel plates (disk, annulus, rectangle, ellipse) and a sphere or a cylinder
//! approaching a flat. Either the load at an approach speed and film, or the time to squeeze
//! the film from one thickness to another under a constant load (Khonsari & Booser §9.3–9.5).
//!
//! This file is the wire (request, validation, response); the physics is [`super::shapes`].

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::shapes::Shape;
use crate::calc::lubricant::isoviscous::{self, Viscosity};
use crate::calc::lubricant::LubricantSpec;
use crate::calc::quantity::{Celsius, Positive};
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::fidelity::{Level, SolverReport};
use crate::numerics::quadrature::IntegralError;

pub struct SqueezePlates;

/// Largest dimension accepted, m.
const MAX_SIZE_M: f64 = 10.0;
/// Film range, m: below 0.1 nm the film is not a continuum; above 1 cm it is not a film.
const MIN_FILM_M: f64 = 1e-10;
const MAX_FILM_M: f64 = 1e-2;
/// A plate's film is at most this share of its smallest in-plane size (Reynolds' thin film).
const MAX_FILM_OVER_SIZE: f64 = 0.1;
/// Largest approach speed, m/s, and load, N.
const MAX_SPEED_M_S: f64 = 100.0;
const MAX_LOAD_N: f64 = 1e12;
/// Smallest load, N: below it the squeeze times leave the floating-point range.
const MIN_LOAD_N: f64 = 1e-6;
/// Smallest final-to-initial film ratio of a squeeze.
const MIN_FILM_RATIO: f64 = 1e-6;

/// The squeezed pair.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum ShapeKind {
    /// Parallel circular disks (`radius_m`).
    CircularDisk,
    /// Parallel concentric annuli (`inner_radius_m`, `outer_radius_m`).
    Annulus,
    /// Parallel rectangular plates (`length_m`, `width_m`).
    Rectangle,
    /// Parallel elliptical plates (`semi_major_m`, `semi_minor_m`).
    Ellipse,
    /// A sphere approaching a flat (`radius_m`); the film is the smallest gap.
    SphereOnFlat,
    /// A cylinder approaching a flat, its axis parallel to it (`radius_m`, `length_m`); the
    /// film is the smallest gap.
    CylinderOnFlat,
}

/// The shape and its dimensions: give exactly the fields its `kind` names.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct ShapeSpec {
    pub kind: ShapeKind,
    /// Radius R, m (0 … 10): `circular_disk`, `sphere_on_flat`, `cylinder_on_flat`.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 0.05)]
    pub radius_m: Option<Positive>,
    /// Inner radius R_i, m (0 … 10, below `outer_radius_m`): `annulus`.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 0.047)]
    pub inner_radius_m: Option<Positive>,
    /// Outer radius R_o, m (0 … 10): `annulus`.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 0.06)]
    pub outer_radius_m: Option<Positive>,
    /// Length, m (0 … 10): `rectangle` (one side) and `cylinder_on_flat` (along its axis).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 0.05)]
    pub length_m: Option<Positive>,
    /// Width, m (0 … 10): `rectangle` (the other side).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 0.05)]
    pub width_m: Option<Positive>,
    /// Semi-major axis a, m (0 … 10, at least `semi_minor_m`): `ellipse`.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 0.075)]
    pub semi_major_m: Option<Positive>,
    /// Semi-minor axis b, m (0 … 10): `ellipse`.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 0.0375)]
    pub semi_minor_m: Option<Positive>,
}

/// Request. Give `approach_speed_m_s` with `film_m` (→ the load), or `load_n` with
/// `initial_film_m` and `final_film_m` (→ the squeeze time).
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct PlatesInput {
    pub shape: ShapeSpec,
    pub lubricant: LubricantSpec,
    /// Film temperature, °C (−273 … 1000): where the viscosity is taken; required unless the
    /// lubricant has a constant `viscosity_pa_s`.
    #[schema(value_type = Option<f64>, minimum = -273.0, maximum = 1000.0, example = 40.0)]
    pub temperature_c: Option<Celsius>,
    /// Approach speed V = −dh/dt, m/s (0 … 100; positive while the surfaces close), with
    /// `film_m`.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 100.0, example = 0.01)]
    pub approach_speed_m_s: Option<Positive>,
    /// Film thickness h (the smallest gap for a sphere or cylinder), m (1e-10 … 0.01; at most
    /// a tenth of a plate's smallest size, at most the radius of a sphere or cylinder), with
    /// `approach_speed_m_s`.
    #[schema(value_type = Option<f64>, minimum = 1e-10, maximum = 0.01, example = 2.5e-5)]
    pub film_m: Option<Positive>,
    /// Constant load W pressing the surfaces together, N (1e-6 … 1e12), with `initial_film_m`
    /// and `final_film_m`.
    #[schema(value_type = Option<f64>, minimum = 1e-6, maximum = 1e12, example = 5462.0)]
    pub load_n: Option<Positive>,
    /// Film at the start of the squeeze h₁, m (1e-10 … 0.01, limits as `film_m`).
    #[schema(value_type = Option<f64>, minimum = 1e-10, maximum = 0.01, example = 2.5e-5)]
    pub initial_film_m: Option<Positive>,
    /// Film at the end h₂, m (below `initial_film_m`, at least 1e-6 of it).
    #[schema(value_type = Option<f64>, minimum = 1e-10, maximum = 0.01, example = 5e-6)]
    pub final_film_m: Option<Positive>,
}

/// What the request gives.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Given {
    /// The approach speed V at film h: the load follows.
    Speed { speed: f64, film: f64 },
    /// A constant load and the films h₁ > h₂: the squeeze time follows.
    Load {
        load: f64,
        initial_film: f64,
        final_film: f64,
    },
}

/// The parsed request.
#[derive(Debug, Clone, PartialEq)]
pub struct PlatesCase {
    pub shape: Shape,
    pub viscosity: Viscosity,
    pub given: Given,
}

/// The shape's dimensions, each field named where it is missing or foreign to the kind.
fn parse_shape(spec: &ShapeSpec, errors: &mut Vec<FieldError>) -> Option<Shape> {
    let fields = [
        ("radius_m", spec.radius_m),
        ("inner_radius_m", spec.inner_radius_m),
        ("outer_radius_m", spec.outer_radius_m),
        ("length_m", spec.length_m),
        ("width_m", spec.width_m),
        ("semi_major_m", spec.semi_major_m),
        ("semi_minor_m", spec.semi_minor_m),
    ];
    let wanted: &[&str] = match spec.kind {
        ShapeKind::CircularDisk | ShapeKind::SphereOnFlat => &["radius_m"],
        ShapeKind::Annulus => &["inner_radius_m", "outer_radius_m"],
        ShapeKind::Rectangle => &["length_m", "width_m"],
        ShapeKind::Ellipse => &["semi_major_m", "semi_minor_m"],
        ShapeKind::CylinderOnFlat => &["radius_m", "length_m"],
    };
    let before = errors.len();
    let mut values = Vec::new();
    for (name, value) in fields {
        let pointer = format!("/shape/{name}");
        match (wanted.contains(&name), value) {
            (true, None) => errors.push(FieldError::new(pointer, "required for this kind")),
            (false, Some(_)) => {
                errors.push(FieldError::new(
                    pointer,
                    format!(
                        "not a dimension of this kind (it takes {})",
                        wanted.join(", ")
                    ),
                ));
            }
            (true, Some(v)) if v.get() > MAX_SIZE_M => errors.push(FieldError::new(
                pointer,
                format!("must be at most {MAX_SIZE_M} m"),
            )),
            (true, Some(v)) => values.push(v.get()),
            (false, None) => {}
        }
    }
    if errors.len() > before {
        return None;
    }
    let shape = match (spec.kind, values.as_slice()) {
        (ShapeKind::CircularDisk, &[radius]) => Shape::CircularDisk { radius },
        (ShapeKind::SphereOnFlat, &[radius]) => Shape::SphereOnFlat { radius },
        (ShapeKind::Annulus, &[inner_radius, outer_radius]) => {
            if inner_radius >= outer_radius {
                errors.push(FieldError::new(
                    "/shape/inner_radius_m",
                    "must be below outer_radius_m",
                ));
                return None;
            }
            Shape::Annulus {
                inner_radius,
                outer_radius,
            }
        }
        (ShapeKind::Rectangle, &[length, width]) => Shape::Rectangle { length, width },
        (ShapeKind::Ellipse, &[semi_major, semi_minor]) => {
            if semi_minor > semi_major {
                errors.push(FieldError::new(
                    "/shape/semi_minor_m",
                    "must be at most semi_major_m",
                ));
                return None;
            }
            Shape::Ellipse {
                semi_major,
                semi_minor,
            }
        }
        (ShapeKind::CylinderOnFlat, &[radius, length]) => Shape::CylinderOnFlat { radius, length },
        _ => return None,
    };
    Some(shape)
}

/// The largest film the shape's model covers, m, and why.
fn film_limit(shape: &Shape) -> (f64, &'static str) {
    let plate = |size: f64| {
        (
            MAX_FILM_OVER_SIZE * size,
            "a tenth of the plate's smallest size (thin film)",
        )
    };
    let (limit, why) = match *shape {
        Shape::CircularDisk { radius } => plate(2.0 * radius),
        Shape::Annulus {
            inner_radius,
            outer_radius,
        } => plate(outer_radius - inner_radius),
        Shape::Rectangle { length, width } => plate(length.min(width)),
        Shape::Ellipse { semi_minor, .. } => plate(2.0 * semi_minor),
        Shape::SphereOnFlat { radius } | Shape::CylinderOnFlat { radius, .. } => (
            radius,
            "the body's radius (the exact forms assume a film thin against it)",
        ),
    };
    if limit < MAX_FILM_M {
        (limit, why)
    } else {
        (MAX_FILM_M, "0.01 m")
    }
}

fn check_film(
    pointer: &str,
    h: Option<Positive>,
    limit: (f64, &str),
    errors: &mut Vec<FieldError>,
) {
    if let Some(h) = h.map(Positive::get) {
        if h < MIN_FILM_M {
            errors.push(FieldError::new(
                pointer,
                format!("must be at least {MIN_FILM_M:e} m (below it the film is not a continuum)"),
            ));
        } else if h > limit.0 {
            errors.push(FieldError::new(
                pointer,
                format!("must be at most {:.4e} m: {}", limit.0, limit.1),
            ));
        }
    }
}

impl Validate for PlatesInput {
    type Valid = PlatesCase;
    fn validate(self) -> Result<PlatesCase, Vec<FieldError>> {
        let mut errors = Vec::new();
        let shape = parse_shape(&self.shape, &mut errors);
        let viscosity = isoviscous::viscosity(self.lubricant, self.temperature_c, &mut errors);
        let limit = shape.as_ref().map_or((MAX_FILM_M, "0.01 m"), film_limit);
        check_film("/film_m", self.film_m, limit, &mut errors);
        check_film("/initial_film_m", self.initial_film_m, limit, &mut errors);
        check_film("/final_film_m", self.final_film_m, limit, &mut errors);
        if self
            .approach_speed_m_s
            .is_some_and(|v| v.get() > MAX_SPEED_M_S)
        {
            errors.push(FieldError::new(
                "/approach_speed_m_s",
                format!("must be at most {MAX_SPEED_M_S} m/s"),
            ));
        }
        if self
            .load_n
            .is_some_and(|w| !(MIN_LOAD_N..=MAX_LOAD_N).contains(&w.get()))
        {
            errors.push(FieldError::new(
                "/load_n",
                format!("must be within [{MIN_LOAD_N:e}, {MAX_LOAD_N:e}] N"),
            ));
        }
        let speed_set = [
            ("approach_speed_m_s", self.approach_speed_m_s),
            ("film_m", self.film_m),
        ];
        let load_set = [
            ("load_n", self.load_n),
            ("initial_film_m", self.initial_film_m),
            ("final_film_m", self.final_film_m),
        ];
        let given = |set: &[(&str, Option<Positive>)]| set.iter().any(|(_, v)| v.is_some());
        const EITHER: &str = "give approach_speed_m_s with film_m (→ load), or load_n with initial_film_m and final_film_m (→ squeeze time)";
        let given = match (given(&speed_set), given(&load_set)) {
            (true, true) => {
                for (name, value) in speed_set.iter().chain(&load_set) {
                    if value.is_some() {
                        errors.push(FieldError::new(
                            format!("/{name}"),
                            format!("over-determined: {EITHER}, not both"),
                        ));
                    }
                }
                None
            }
            (false, false) => {
                for name in ["approach_speed_m_s", "load_n"] {
                    errors.push(FieldError::new(
                        format!("/{name}"),
                        format!("under-determined: {EITHER}"),
                    ));
                }
                None
            }
            (true, false) => match (self.approach_speed_m_s, self.film_m) {
                (Some(v), Some(h)) => Some(Given::Speed {
                    speed: v.get(),
                    film: h.get(),
                }),
                _ => {
                    missing(&speed_set, "approach_speed_m_s with film_m", &mut errors);
                    None
                }
            },
            (false, true) => match (self.load_n, self.initial_film_m, self.final_film_m) {
                (Some(w), Some(h1), Some(h2)) => {
                    let (h1, h2) = (h1.get(), h2.get());
                    if h2 >= h1 {
                        errors.push(FieldError::new(
                            "/final_film_m",
                            "must be below initial_film_m (a squeeze thins the film)",
                        ));
                    } else if h2 < MIN_FILM_RATIO * h1 {
                        errors.push(FieldError::new(
                            "/final_film_m",
                            format!("must be at least {MIN_FILM_RATIO:e} of initial_film_m"),
                        ));
                    }
                    Some(Given::Load {
                        load: w.get(),
                        initial_film: h1,
                        final_film: h2,
                    })
                }
                _ => {
                    missing(
                        &load_set,
                        "load_n with initial_film_m and final_film_m",
                        &mut errors,
                    );
                    None
                }
            },
        };
        match (errors.is_empty(), shape, viscosity, given) {
            (true, Some(shape), Some(viscosity), Some(given)) => Ok(PlatesCase {
                shape,
                viscosity,
                given,
            }),
            _ => Err(errors),
        }
    }
}

/// A 422 for each field of a partly given set.
fn missing(set: &[(&str, Option<Positive>)], what: &str, errors: &mut Vec<FieldError>) {
    for (name, value) in set {
        if value.is_none() {
            errors.push(FieldError::new(
                format!("/{name}"),
                format!("under-determined: required ({what})"),
            ));
        }
    }
}

/// Result: the load at the given speed, or the squeeze time under the given load.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct PlatesOutput {
    /// The shape's kind.
    #[schema(example = "annulus")]
    pub shape: String,
    /// Viscosity used, Pa·s.
    pub viscosity_pa_s: f64,
    /// Squeezed area A of a plate, m²; absent for a sphere or cylinder.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub area_m2: Option<f64>,
    /// Shape factor K of Khonsari & Booser Eq. 9.13 (Table 9.1), dimensionless:
    /// Δt = K μ A²/W (1/h₂² − 1/h₁²); absent for a sphere or cylinder.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub shape_factor: Option<f64>,
    /// The load W, N: carried at the given approach speed, or the given constant load.
    pub load_n: f64,
    /// Peak film pressure at the given speed and film, Pa (with `approach_speed_m_s`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_pressure_pa: Option<f64>,
    /// Time to squeeze the film from `initial_film_m` to `final_film_m` under the load, s.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub time_s: Option<f64>,
    /// Approach speed at the initial film, m/s.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub approach_speed_initial_m_s: Option<f64>,
    /// Approach speed at the final film, m/s.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub approach_speed_final_m_s: Option<f64>,
    /// Peak film pressure at the initial film, Pa.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_pressure_initial_pa: Option<f64>,
    /// Peak film pressure at the final film, Pa.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_pressure_final_pa: Option<f64>,
}

impl Calculation for SqueezePlates {
    const PATH: &'static str = "/v1/squeeze-films/plates";
    const SUMMARY: &'static str = "Squeeze film between plates (disk, annulus, rectangle, ellipse) or a sphere or cylinder and a flat: load at an approach speed, or squeeze time under a load";
    const DESCRIPTION: &'static str = include_str!("plates.md");
    const FIDELITY: &'static [Level] = &[Level::ClosedForm];
    const EFFECTS: &'static [&'static str] = &[];
    const EXAMPLE: &'static str = r#"{"shape": {"kind": "annulus", "inner_radius_m": 0.047, "outer_radius_m": 0.06}, "lubricant": {"viscosity_pa_s": 0.006}, "load_n": 5462.4, "initial_film_m": 2.5e-5, "final_film_m": 5e-6}"#;

    type Input = PlatesInput;
    type Output = PlatesOutput;

    fn run(case: PlatesCase, ctx: &mut Context) -> Result<PlatesOutput, CalcError> {
        let PlatesCase {
            shape,
            viscosity,
            given,
        } = case;
        for (code, message) in &viscosity.assumptions {
            ctx.warn(code, message.clone());
        }
        let mu = viscosity.pa_s;
        let mut out = PlatesOutput {
            shape: shape.name().to_owned(),
            viscosity_pa_s: mu,
            area_m2: shape.area(),
            shape_factor: shape.shape_factor(),
            load_n: 0.0,
            max_pressure_pa: None,
            time_s: None,
            approach_speed_initial_m_s: None,
            approach_speed_final_m_s: None,
            max_pressure_initial_pa: None,
            max_pressure_final_pa: None,
        };
        let mut report = SolverReport::closed_form("closed_form");
        match given {
            Given::Speed { speed, film } => {
                out.load_n = mu * speed * shape.load_coefficient(film);
                out.max_pressure_pa = Some(mu * speed * shape.max_pressure_coefficient(film));
            }
            Given::Load {
                load,
                initial_film,
                final_film,
            } => {
                let (integral, quadrature) = shape
                    .time_integral(initial_film, final_film, &ctx.budget())
                    .map_err(|e| match e {
                        IntegralError::Stopped(stopped) => CalcError::from(stopped),
                        IntegralError::Integrand(()) => {
                            CalcError::Internal("squeeze-time integrand".into())
                        }
                    })?;
                if let Some(q) = quadrature {
                    report = q
                        .report
                        .named("exact_load_gauss_kronrod_time")
                        .at(Level::ClosedForm)
                        .with_error_estimate(Some(q.error / q.value.abs()));
                }
                let speed = |h: f64| load / (mu * shape.load_coefficient(h));
                let pressure = |h: f64| mu * speed(h) * shape.max_pressure_coefficient(h);
                out.load_n = load;
                out.time_s = Some(mu / load * integral);
                out.approach_speed_initial_m_s = Some(speed(initial_film));
                out.approach_speed_final_m_s = Some(speed(final_film));
                out.max_pressure_initial_pa = Some(pressure(initial_film));
                out.max_pressure_final_pa = Some(pressure(final_film));
            }
        }
        ctx.report(report);
        let numbers: Vec<f64> = [
            Some(out.load_n),
            out.max_pressure_pa,
            out.time_s,
            out.approach_speed_initial_m_s,
            out.approach_speed_final_m_s,
            out.max_pressure_initial_pa,
            out.max_pressure_final_pa,
        ]
        .into_iter()
        .flatten()
        .collect();
        CalcError::unless_finite(&numbers)?;
        Ok(out)
    }
}

#[cfg(test)]
#[path = "plates_tests.rs"]
mod tests;
