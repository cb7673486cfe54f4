//! `POST /v1/squeeze-films/journal`: a journal pressed into its bearing by a constant load
//! without rotating (a piston pin, a bearing under a shock load): the time for the eccentricity
//! ratio to grow from ε₁ to ε₂, the approach speeds and the films at both ends (Khonsari &
//! Booser §9.5–9.6, Ex 9.2 and 9.4). `closed_form`: the infinitely long bearing (Table 9.2,
//! 360° or 180° film); otherwise the finite bearing numerically ([`super::finite_journal`]).
//! With `speed_rpm` the journal also turns (Ex 9.5): the path of [`super::rotating_journal`].
//!
//! This file is the wire (request, validation, response); the physics is
//! [`super::long_journal`], [`super::finite_journal`] and [`super::rotating_journal`].

use std::f64::consts::PI;

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::finite_journal::{self, Numerical};
use super::long_journal::{self, FilmExtent};
use super::rotating_journal::{self, Approach, RotatingFilm, TurningJournal};
use crate::calc::journal::finite_moving_film::TableDensity;
use crate::calc::journal::moving_film::ShortArc;
use crate::calc::journal::plain::{grid_mesh, GeometrySpec};
use crate::calc::lubricant::isoviscous::{self, Viscosity};
use crate::calc::lubricant::LubricantSpec;
use crate::calc::quantity::{Celsius, NonNegative, Positive};
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::effects::{Decision, Mode};
use crate::fidelity::{FidelityRequest, Level, SolverReport};

pub struct SqueezeJournal;

/// Largest final eccentricity ratio: h_min = 0.001 C (as the journal room).
const MAX_ECCENTRICITY: f64 = 0.999;
/// Load range, N.
const MAX_LOAD_N: f64 = 1e12;
/// Smallest load, N: below it the squeeze times leave the floating-point range.
const MIN_LOAD_N: f64 = 1e-6;
/// Largest speed, rev/min (as `/v1/journal-bearings/dynamic`).
const MAX_SPEED_RPM: f64 = 1e6;
/// Slowest speed taken as turning, rev/min: below it the journal turns less than a
/// microradian a second, and its force scale μRωL³/C² nears the floating-point floor.
const MIN_TURNING_RPM: f64 = 1e-6;
/// Loosest step tolerance of a turning journal's path (as `/v1/journal-bearings/dynamic`).
const MAX_STEP_TOLERANCE: f64 = 1e-4;
/// Samples of the closed form's path.
const CLOSED_FORM_PATH_POINTS: usize = 21;

/// The squeezed film.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum SqueezeFilm {
    /// Full 360° film, negative pressures kept (a film that cannot rupture: submerged at a
    /// high ambient pressure).
    Full,
    /// Cavitated: the closing side only carries pressure (closed form: the 180° film of Table
    /// 9.2; numerical: the Reynolds condition p ≥ 0, Table 9.3's "negative pressures clipped").
    #[default]
    Cavitated,
}

/// Request.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct SqueezeJournalInput {
    pub geometry: GeometrySpec,
    pub lubricant: LubricantSpec,
    /// Film temperature, °C (−273 … 1000): where the viscosity is taken; required unless the
    /// lubricant has a constant `viscosity_pa_s`.
    #[schema(value_type = Option<f64>, minimum = -273.0, maximum = 1000.0, example = 65.6)]
    pub temperature_c: Option<Celsius>,
    /// Constant load W pressing the journal into the bearing, N (1e-6 … 1e12).
    #[schema(value_type = f64, minimum = 1e-6, maximum = 1e12, example = 5589.8)]
    pub load_n: Positive,
    /// Eccentricity ratio at the start ε₁ = e/C, dimensionless (0 … below the final one).
    #[schema(minimum = 0.0, exclusive_maximum = 0.999, example = 0.5)]
    pub initial_eccentricity_ratio: f64,
    /// Eccentricity ratio at the end ε₂, dimensionless (above the initial one, at most 0.999).
    #[schema(minimum = 0.0, maximum = 0.999, example = 0.9)]
    pub final_eccentricity_ratio: f64,
    /// Journal speed, rev/min (0 … 1e6; default 0). From 1e-6 the journal turns while squeezed
    /// (Khonsari & Booser Ex 9.5): its path under the load is the massless journal's orbit,
    /// on the short bearing's film at `closed_form` and on the finite cavitated film otherwise;
    /// a slower one is taken as still, with a warning.
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 1e6, example = 0.0)]
    pub speed_rpm: Option<NonNegative>,
    /// `cavitated` (default) or `full`.
    #[serde(default)]
    pub film: SqueezeFilm,
    /// `closed_form` (the infinitely long bearing, Table 9.2: no side leakage), `fast`,
    /// `standard` (default), `high`, or `{"grid": [circumferential 16…1024 (even), half-length
    /// axial 2…256], "tolerance": 1e-10…1e-2}` (the tolerance is the time quadrature's
    /// relative one).
    #[serde(default)]
    pub fidelity: FidelityRequest,
    /// Include the path: ε, time, approach speed, film and W̄ at the quadrature's panel ends
    /// (numerical; one more film solve per point) or at 21 points (closed form).
    #[serde(default)]
    #[schema(example = false)]
    pub include_field: bool,
}

/// How the squeeze is computed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Method {
    /// The infinitely long bearing.
    Long,
    Finite(Numerical),
    /// The turning journal's path at ω (rad/s) on `film`, integrated to step tolerance
    /// `tolerance`.
    Rotating {
        omega: f64,
        film: RotatingFilm,
        tolerance: f64,
        level: Level,
    },
}

/// The parsed request.
#[derive(Debug, Clone, PartialEq)]
pub struct SqueezeJournalCase {
    pub diameter_m: f64,
    pub length_m: f64,
    pub radial_clearance_m: f64,
    pub viscosity: Viscosity,
    pub load_n: f64,
    pub initial_eccentricity_ratio: f64,
    pub final_eccentricity_ratio: f64,
    pub film: FilmExtent,
    pub method: Method,
    pub include_field: bool,
    /// The speed asked for, rev/min (above 0 and below [`MIN_TURNING_RPM`]: taken as still).
    pub speed_rpm: f64,
}

impl Validate for SqueezeJournalInput {
    type Valid = SqueezeJournalCase;
    fn validate(self) -> Result<SqueezeJournalCase, Vec<FieldError>> {
        let mut errors = Vec::new();
        let (d, l, c) = self.geometry.check(&mut errors);
        let l_over_d = l / d;
        let viscosity = isoviscous::viscosity(self.lubricant, self.temperature_c, &mut errors);
        let load = self.load_n.get();
        if !(MIN_LOAD_N..=MAX_LOAD_N).contains(&load) {
            errors.push(FieldError::new(
                "/load_n",
                format!("must be within [{MIN_LOAD_N:e}, {MAX_LOAD_N:e}] N, got {load}"),
            ));
        }
        let (e1, e2) = (
            self.initial_eccentricity_ratio,
            self.final_eccentricity_ratio,
        );
        if !(e1.is_finite() && (0.0..MAX_ECCENTRICITY).contains(&e1)) {
            errors.push(FieldError::new(
                "/initial_eccentricity_ratio",
                format!("must be within [0, {MAX_ECCENTRICITY}), got {e1}"),
            ));
        }
        if !(e2.is_finite() && e2 <= MAX_ECCENTRICITY) {
            errors.push(FieldError::new(
                "/final_eccentricity_ratio",
                format!("must be at most {MAX_ECCENTRICITY} (ε ≥ 1 means the journal touches the bearing), got {e2}"),
            ));
        } else if e2 <= e1 {
            errors.push(FieldError::new(
                "/final_eccentricity_ratio",
                "must exceed initial_eccentricity_ratio (the load closes the film)",
            ));
        }
        let rpm = self.speed_rpm.map_or(0.0, |n| n.get());
        if rpm > MAX_SPEED_RPM {
            errors.push(FieldError::new(
                "/speed_rpm",
                format!("must be within [0, {MAX_SPEED_RPM:e}] rev/min, got {rpm}"),
            ));
        }
        let method = match self.fidelity {
            FidelityRequest::Level(Level::ClosedForm) => Some(Method::Long),
            FidelityRequest::Level(level) => {
                Some(Method::Finite(Numerical::at(level, None, None, l_over_d)))
            }
            FidelityRequest::Custom(custom) => {
                let mesh = grid_mesh(custom.grid, &mut errors);
                if let Some(t) = custom.tolerance {
                    if !(1e-10..=1e-2).contains(&t) {
                        errors.push(FieldError::new(
                            "/fidelity/tolerance",
                            "must be within [1e-10, 1e-2]",
                        ));
                    }
                }
                Some(Method::Finite(Numerical::at(
                    Level::Standard,
                    mesh,
                    custom.tolerance,
                    l_over_d,
                )))
            }
        };
        let method = match method {
            Some(squeeze) if rpm >= MIN_TURNING_RPM => {
                let given = match self.fidelity {
                    FidelityRequest::Custom(custom) => custom.tolerance,
                    FidelityRequest::Level(_) => None,
                };
                rotating(squeeze, rpm, self.film, given, &mut errors)
            }
            other => other,
        };
        match (errors.is_empty(), viscosity, method) {
            (true, Some(viscosity), Some(method)) => Ok(SqueezeJournalCase {
                diameter_m: d,
                length_m: l,
                radial_clearance_m: c,
                viscosity,
                load_n: load,
                initial_eccentricity_ratio: e1,
                final_eccentricity_ratio: e2,
                film: match self.film {
                    SqueezeFilm::Full => FilmExtent::Full,
                    SqueezeFilm::Cavitated => FilmExtent::Cavitated,
                },
                method,
                include_field: self.include_field,
                speed_rpm: rpm,
            }),
            _ => Err(errors),
        }
    }
}

/// The turning journal's method from the still one's: `closed_form` the short bearing's film
/// (full or π film), otherwise the finite cavitated film on the level's (or the given) mesh,
/// at the orbit room's step tolerances (1e-6, 1e-7, 1e-9; a given tolerance, at most 1e-4, is
/// the step's).
fn rotating(
    still: Method,
    rpm: f64,
    film: SqueezeFilm,
    given_tolerance: Option<f64>,
    errors: &mut Vec<FieldError>,
) -> Option<Method> {
    if given_tolerance.is_some_and(|t| t > MAX_STEP_TOLERANCE) {
        errors.push(FieldError::new(
            "/fidelity/tolerance",
            format!("a turning journal's tolerance is the path's step tolerance: must be within [1e-10, {MAX_STEP_TOLERANCE:e}]"),
        ));
    }
    let omega = rpm * PI / 30.0;
    let (film, tolerance, level) = match (still, film) {
        (Method::Long, SqueezeFilm::Full) => {
            (RotatingFilm::Short(ShortArc::Full), 1e-7, Level::ClosedForm)
        }
        (Method::Long, SqueezeFilm::Cavitated) => (
            RotatingFilm::Short(ShortArc::PiFilm),
            1e-7,
            Level::ClosedForm,
        ),
        (Method::Finite(_), SqueezeFilm::Full) => {
            errors.push(FieldError::new(
                "/film",
                "a turning journal's finite film is the cavitated one (the Reynolds condition): give film \"cavitated\", or fidelity \"closed_form\" for the short bearing's full film",
            ));
            return None;
        }
        (Method::Finite(numerical), SqueezeFilm::Cavitated) => {
            let tolerance = match numerical.level {
                Level::Fast => 1e-6,
                Level::High => 1e-9,
                _ => 1e-7,
            };
            let film = RotatingFilm::Finite {
                mesh: numerical.mesh,
                density: TableDensity::at(numerical.level),
            };
            (film, tolerance, numerical.level)
        }
        (Method::Rotating { .. }, _) => return Some(still),
    };
    Some(Method::Rotating {
        omega,
        film,
        tolerance: given_tolerance.unwrap_or(tolerance),
        level,
    })
}

/// One point of the squeeze's path.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct PathPoint {
    /// ε, dimensionless.
    pub eccentricity_ratio: f64,
    /// Time since ε₁, s.
    pub time_s: f64,
    /// Approach speed V = C dε/dt, m/s.
    pub approach_speed_m_s: f64,
    /// h_min = C (1 − ε), m.
    pub min_film_m: f64,
    /// W̄ = W C³/(μ L R³ V), dimensionless.
    pub load_coefficient: f64,
}

/// Result.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct SqueezeJournalOutput {
    /// Time for ε to grow from ε₁ to ε₂ under the load, s.
    pub time_s: f64,
    /// Approach speed V = C dε/dt at ε₁, m/s.
    pub approach_speed_initial_m_s: f64,
    /// Approach speed at ε₂, m/s.
    pub approach_speed_final_m_s: f64,
    /// h_min = C (1 − ε₁), m.
    pub min_film_initial_m: f64,
    /// h_min = C (1 − ε₂), m.
    pub min_film_final_m: f64,
    /// W̄ = W C³/(μ L R³ V) at ε₁ (Table 9.3's load coefficient), dimensionless.
    pub load_coefficient_initial: f64,
    /// W̄ at ε₂, dimensionless.
    pub load_coefficient_final: f64,
    /// Viscosity used, Pa·s.
    pub viscosity_pa_s: f64,
    /// With rotation: W̄ = C²W/(μR²LU), U = Rω (Khonsari & Booser Ex 9.5's load number, the
    /// constant of its χ chart), dimensionless.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rotating_load_number: Option<f64>,
    /// The closed form at `fidelity: closed_form`: `long_360_full_film` or
    /// `long_180_film` (still), `short_360_full_film` or `short_pi_film` (turning); absent for
    /// the numerical solution.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub approximation: Option<String>,
    /// The path, with `include_field`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub path: Option<Vec<PathPoint>>,
}

impl Calculation for SqueezeJournal {
    const PATH: &'static str = "/v1/squeeze-films/journal";
    const SUMMARY: &'static str = "Squeeze film of a journal pressed into its bearing, still or turning: time from ε₁ to ε₂, approach speeds, films (infinitely long, short or finite, full or cavitated)";
    const DESCRIPTION: &'static str = include_str!("journal.md");
    const FIDELITY: &'static [Level] =
        &[Level::ClosedForm, Level::Fast, Level::Standard, Level::High];
    const EFFECTS: &'static [&'static str] = &["cavitation"];
    const EXAMPLE: &'static str = r#"{"geometry": {"diameter_m": 0.0381, "length_m": 0.0381, "radial_clearance_m": 2.54e-5}, "lubricant": {"viscosity_pa_s": 0.014479}, "load_n": 5589.8, "initial_eccentricity_ratio": 0.5, "final_eccentricity_ratio": 0.9, "film": "cavitated", "fidelity": "fast"}"#;

    type Input = SqueezeJournalInput;
    type Output = SqueezeJournalOutput;

    fn run(case: SqueezeJournalCase, ctx: &mut Context) -> Result<SqueezeJournalOutput, CalcError> {
        for (code, message) in &case.viscosity.assumptions {
            ctx.warn(code, message.clone());
        }
        if case.speed_rpm > 0.0 && case.speed_rpm < MIN_TURNING_RPM {
            ctx.warn(
                "rotation_negligible",
                format!("speed_rpm {:e} is below {MIN_TURNING_RPM:e} rev/min: the journal is taken as still (the turning path tends to the still one as ω → 0)", case.speed_rpm),
            );
        }
        let mu = case.viscosity.pa_s;
        let (r, l, c, w) = (
            0.5 * case.diameter_m,
            case.length_m,
            case.radial_clearance_m,
            case.load_n,
        );
        let (e1, e2) = (
            case.initial_eccentricity_ratio,
            case.final_eccentricity_ratio,
        );
        // W = μ V L R³/C³ · W̄: V from W̄, and Δt = (μ L R³/(W C²)) ∫ W̄ dε.
        let speed = |load_coefficient: f64| w * c.powi(3) / (mu * l * r.powi(3) * load_coefficient);
        let time_scale = mu * l * r.powi(3) / (w * c * c);
        let cavitated = case.film == FilmExtent::Cavitated;
        let (integral, w1, w2, samples, approximation) = match case.method {
            Method::Long => {
                let extent = case.film;
                let load_integral = |e: f64| long_journal::load_integral(e, extent);
                let samples = case.include_field.then(|| {
                    let (s1, s2) = (-(-e1).ln_1p(), -(-e2).ln_1p());
                    (0..CLOSED_FORM_PATH_POINTS)
                        .map(|k| {
                            let s =
                                s1 + (s2 - s1) * k as f64 / (CLOSED_FORM_PATH_POINTS - 1) as f64;
                            let e = if k + 1 == CLOSED_FORM_PATH_POINTS {
                                e2
                            } else {
                                -(-s).exp_m1()
                            };
                            (
                                e,
                                load_integral(e) - load_integral(e1),
                                long_journal::load_coefficient(e, extent),
                            )
                        })
                        .collect::<Vec<_>>()
                });
                ctx.report(SolverReport::closed_form("closed_form"));
                (
                    load_integral(e2) - load_integral(e1),
                    long_journal::load_coefficient(e1, extent),
                    long_journal::load_coefficient(e2, extent),
                    samples,
                    Some(if cavitated {
                        "long_180_film"
                    } else {
                        "long_360_full_film"
                    }),
                )
            }
            Method::Rotating {
                omega,
                film,
                tolerance,
                level,
            } => return turning(&case, omega, film, tolerance, level, ctx),
            Method::Finite(numerical) => {
                let s = finite_journal::squeeze(
                    e1,
                    e2,
                    l / case.diameter_m,
                    case.film,
                    numerical,
                    case.include_field,
                    &ctx.budget(),
                )?;
                ctx.report(s.report);
                (s.load_integral, s.load_initial, s.load_final, s.path, None)
            }
        };
        decide_film(
            ctx,
            case.film,
            cavitated.then_some(match case.method {
                Method::Long => "half_film",
                _ => "reynolds",
            }),
        );
        let time = time_scale * integral;
        in_range(
            &[time, speed(w1), speed(w2), time_scale],
            "load, viscosity and geometry",
        )?;
        Ok(SqueezeJournalOutput {
            time_s: time,
            approach_speed_initial_m_s: speed(w1),
            approach_speed_final_m_s: speed(w2),
            min_film_initial_m: c * (1.0 - e1),
            min_film_final_m: c * (1.0 - e2),
            load_coefficient_initial: w1,
            load_coefficient_final: w2,
            viscosity_pa_s: mu,
            rotating_load_number: None,
            approximation: approximation.map(String::from),
            path: samples.map(|points| {
                points
                    .into_iter()
                    .map(|(e, partial, wbar)| PathPoint {
                        eccentricity_ratio: e,
                        time_s: time_scale * partial,
                        approach_speed_m_s: speed(wbar),
                        min_film_m: c * (1.0 - e),
                        load_coefficient: wbar,
                    })
                    .collect()
            }),
        })
    }
}

/// The film is the request's choice (`film`), not a criterion's: reported as on or off, with
/// the cavitated film's model.
fn decide_film(ctx: &mut Context, film: FilmExtent, model: Option<&'static str>) {
    let cavitated = film == FilmExtent::Cavitated;
    ctx.decide(
        "cavitation",
        Decision {
            applied: cavitated,
            mode: if cavitated { Mode::On } else { Mode::Off },
            reason: if cavitated {
                "film: cavitated — the opening side holds no tension (p ≥ 0)".into()
            } else {
                "film: full — negative pressures kept on the opening side".into()
            },
            criterion: None,
            model,
        },
    );
}

/// The time, the speeds and the scales all finite and positive, or the 422 that says which
/// inputs (`what`) left the floating-point range.
fn in_range(values: &[f64], what: &str) -> Result<(), CalcError> {
    if values.iter().all(|v| v.is_finite() && *v > 0.0) {
        Ok(())
    } else {
        Err(CalcError::impossible(
            "",
            format!("this combination of {what} takes the squeeze time or the approach speeds outside the floating-point range"),
        ))
    }
}

/// The turning journal (Ex 9.5): its path to ε₂, or the verdict that it settles short of it.
fn turning(
    case: &SqueezeJournalCase,
    omega: f64,
    film: RotatingFilm,
    tolerance: f64,
    level: Level,
    ctx: &mut Context,
) -> Result<SqueezeJournalOutput, CalcError> {
    let started = std::time::Instant::now();
    let mu = case.viscosity.pa_s;
    let (r, l, c, w) = (
        0.5 * case.diameter_m,
        case.length_m,
        case.radial_clearance_m,
        case.load_n,
    );
    let (e1, e2) = (
        case.initial_eccentricity_ratio,
        case.final_eccentricity_ratio,
    );
    let journal = TurningJournal {
        radius_m: r,
        length_m: l,
        clearance_m: c,
        viscosity_pa_s: mu,
        omega,
        load_n: w,
    };
    let l_over_d = l / case.diameter_m;
    let (approximation, model) = match film {
        RotatingFilm::Short(arc) => {
            if l_over_d > 0.5 {
                ctx.warn(
                    "short_bearing_beyond_validity",
                    format!("L/D = {l_over_d:.3}: the short bearing's film overestimates the load capacity above L/D ≈ 0.5 (Ocvirk), so the journal closes too slowly; the finite film (fast, standard, high) holds at any L/D"),
                );
            }
            match arc {
                ShortArc::Full => (Some("short_360_full_film"), None),
                _ => (Some("short_pi_film"), Some("pi_film")),
            }
        }
        RotatingFilm::Finite { .. } => (None, Some("reynolds")),
    };
    if case.include_field {
        ctx.warn(
            "path_not_available",
            "a turning journal's path is an orbit: `/v1/journal-bearings/dynamic` with `include_orbit` samples it",
        );
    }
    decide_film(ctx, case.film, model);
    let budget = ctx.budget();
    let (time_s, speed_initial_m_s, speed_final_m_s, report) =
        match rotating_journal::approach(journal, e1, e2, film, tolerance, &budget)? {
            Approach::Reached {
                time_s,
                speed_initial_m_s,
                speed_final_m_s,
                report,
            } => (time_s, speed_initial_m_s, speed_final_m_s, report),
            Approach::Settles { eccentricity_ratio } => {
                return Err(CalcError::impossible(
                    "/final_eccentricity_ratio",
                    format!("the turning journal never reaches ε₂ = {e2}: its film carries the load at ε = {eccentricity_ratio:.4}, where it settles (the rotation's wedge holds what the squeeze would not)"),
                ))
            }
        };
    let mut report = report.at(level);
    if let RotatingFilm::Finite { mesh, .. } = film {
        report = report
            .named("radau_iia5_on_finite_volume_active_set_impedance_table")
            .on_grid(vec![mesh.circumferential as u32, mesh.axial_half as u32])
            .with_film_solves(budget.field_solves());
    }
    report.elapsed_ms = started.elapsed().as_secs_f64() * 1e3;
    ctx.report(report);
    // W̄ = W C³/(μ L R³ V) at the radial approach speed.
    let coefficient = |v: f64| w * c.powi(3) / (mu * l * r.powi(3) * v);
    let (w1, w2) = (coefficient(speed_initial_m_s), coefficient(speed_final_m_s));
    in_range(
        &[time_s, speed_initial_m_s, speed_final_m_s, w1, w2],
        "load, speed, viscosity and geometry",
    )?;
    Ok(SqueezeJournalOutput {
        time_s,
        approach_speed_initial_m_s: speed_initial_m_s,
        approach_speed_final_m_s: speed_final_m_s,
        min_film_initial_m: c * (1.0 - e1),
        min_film_final_m: c * (1.0 - e2),
        load_coefficient_initial: w1,
        load_coefficient_final: w2,
        viscosity_pa_s: mu,
        rotating_load_number: Some(c * c * w / (mu * r * r * l * r * omega)),
        approximation: approximation.map(String::from),
        path: None,
    })
}

#[cfg(test)]
#[path = "journal_tests.rs"]
mod tests;
