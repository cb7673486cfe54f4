//! `POST /v1/contacts/ehl`: numerical elastohydrodynamic lubrication of a line or a point
//! (circular or elliptical) contact — Reynolds with Barus or Roelands viscosity and
//! Dowson–Higginson density, half-space elastic deformation, load balance and cavitation by
//! complementarity. Line contacts by a fully coupled Newton method on nested grids
//! ([`line`]), point contacts by FAS multigrid ([`point`]), both with Richardson
//! extrapolation; traction from the converged field on request.
//!
//! Conventions are the film-formula room's (`/v1/contacts/ehl-film`): E′ = 2/Σ(1 − ν²)/E,
//! R_x the reduced radius along the entrainment direction x, ū the mean surface speed, U =
//! η₀ū/(E′R_x), G = αE′. Moes' groups: line M = W′(2U)^(−1/2), L = G(2U)^(1/4) with W′ =
//! w/(E′R_x); point M = W(2U)^(−3/4), L = G(2U)^(1/4) with W = F/(E′R_x²).

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::closed_form::inlet_viscosity;
use super::film::{entrainment_speed, slide_roll_ratio};
use super::fluid::Fluid;
use super::formulas::{
    dowson_higginson, hard_central_film, hard_min_film, pan_hamrock, point_regime, regime_films,
    Groups, MoesAsymptotes, Regime, HARD_FIT_ELLIPTICITY,
};
use super::line::LineProblem;
use super::point::{self, HertzEllipse, PointProblem};
use super::solve::{solve_line, solve_point, Cells, PointGrids};
use super::traction::{self, ShearLaw, TractionLaw};
use crate::calc::contact::hertz::{
    contact_of, BodySpec, Contact, LineSpec, MajorAxis, Method, Solution,
};
use crate::calc::lubricant::model::PressureLaw;
use crate::calc::lubricant::{validity, Lubricant, LubricantSpec};
use crate::calc::quantity::{Celsius, NonNegative, Positive};
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::effects::{Criterion, Decision, Mode};
use crate::fidelity::{FidelityRequest, Level};

pub struct Ehl;

/// Moes' load parameter range the line solver accepts: below 0.1 the contact is a rigid
/// hydrodynamic one (no EHL), above 10⁴ the Hertz zone is beyond any affordable grid.
const MOES_M_RANGE: (f64, f64) = (0.1, 1e4);
/// The point solver's range of M (its definition W(2U)^(−3/4)): below 1 the film is many
/// times the Hertz radius's gap (rigid–hydrodynamic); above 5000 the Hertz zone needs more
/// than 1024 cells across.
const POINT_MOES_M_RANGE: (f64, f64) = (1.0, 5000.0);
/// Cells per direction of the point solver's first grid per fidelity level (fast, standard,
/// high), and of the finest it steps up to; the explicit range.
const POINT_CELLS: [usize; 3] = [64, 128, 256];
const POINT_FINEST_CELLS: [usize; 3] = [128, 512, 1024];
/// Estimated relative errors of the fine grid's central and minimum films (bounds on the
/// extrapolated films') above which a point solve steps up to a grid twice as fine, and on its
/// finest grid is warned about, per level.
const POINT_CENTRAL_TOLERANCE: [f64; 3] = [0.1, 0.03, 0.01];
const POINT_MIN_TOLERANCE: [f64; 3] = [0.1, 0.02, 0.005];
const POINT_CUSTOM_CELLS: (u32, u32) = (64, 1024);
/// Moes' material parameter range (L = 0 is isoviscous; the Moes map ends at about 25).
const MOES_L_MAX: f64 = 50.0;
/// Cells (coarse, fine) of the nested grids per fidelity level.
const FAST_CELLS: usize = 64;
const STANDARD_CELLS: usize = 128;
const HIGH_CELLS: usize = 256;
/// Explicit grids: the fine cell count.
const CUSTOM_CELLS: (u32, u32) = (32, 2048);
/// Relative central-film error estimate (of the fine grid, before extrapolation) above which
/// the solve goes on to finer grids, per level: fast, standard, high.
const REFINE_ABOVE: [f64; 3] = [0.05, 0.01, 0.002];
/// αp_h above which a Barus law is warned about: e^15 ≈ 3 × 10⁶ in viscosity, where Barus and
/// Roelands part by orders of magnitude.
const BARUS_LIMIT: f64 = 15.0;
/// Density rise ρ(p_h)/ρ₀ − 1 above which `auto` applies compressibility.
const COMPRESSIBILITY_THRESHOLD: f64 = 0.01;
/// αp_h above which `auto` applies piezoviscosity (below it η changes by < 10 % over the
/// contact: the isoviscous regimes).
const PIEZOVISCOSITY_THRESHOLD: f64 = 0.1;

/// Effects this calculation understands.
#[derive(Debug, Clone, Copy, Default, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct NumericalEhlEffects {
    /// Dowson–Higginson density ρ/ρ₀ = 1 + 0.6p/(1 + 1.7p), p in GPa (Khonsari eq. 2.20).
    /// `auto` applies it when the density rises by more than 1 % at the Hertz pressure.
    #[serde(default)]
    pub compressibility: Mode,
    /// The lubricant's pressure–viscosity law (Barus or Roelands). `auto` applies it when
    /// αp_h > 0.1; `off` solves the isoviscous problem.
    #[serde(default)]
    pub piezoviscosity: Mode,
}

/// Shear law for traction.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum TractionModel {
    /// τ = ηγ̇ (overflows for realistic αp_h: Stachowiak §7.7; bounded here only by the
    /// limiting shear stress if given).
    Newtonian,
    /// Eyring: τ = τ₀ asinh(ηγ̇/τ₀) (Stachowiak eq. 7.52).
    Eyring,
}

/// Traction request: the sliding shear integrated over the converged film.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct NumericalEhlTractionSpec {
    pub model: TractionModel,
    /// Eyring stress τ₀, Pa (> 0, at most 1e9; typically 2–20 MPa for mineral oils), required
    /// by `eyring`.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e9, example = 5e6)]
    pub eyring_stress_pa: Option<Positive>,
    /// Limiting shear stress as a fraction of the local pressure, τ_L = γp (0 < γ ≤ 1;
    /// typically 0.05–0.1): the shear stress is capped at it (Stachowiak §7.7 describes the
    /// limit without a formula; the proportional form is the common one).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1.0, example = 0.08)]
    pub limiting_shear_coefficient: Option<Positive>,
}

/// Request: a lubricated contact rolling along x — a line contact of two cylinders (axes
/// along y) when `line` is given, else a point contact (circular or elliptical) of the two
/// bodies' principal curvatures.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct NumericalEhlInput {
    /// The first body, as in `/v1/contacts/hertz` (for a line contact a cylinder:
    /// `radius_y_m` absent).
    pub body1: BodySpec,
    /// The second body.
    pub body2: BodySpec,
    /// Normal load on the contact (a line contact carries it over its length), N (> 0, at
    /// most 1e12).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 1e12, example = 5000.0)]
    pub load_n: Positive,
    /// The contact length of a line contact; absent for a point contact.
    pub line: Option<LineSpec>,
    /// Mean entrainment speed ū = (u₁ + u₂)/2 along x, m/s (1e-9 … 1000): the mean, not
    /// the sum.
    #[schema(value_type = f64, minimum = 1e-9, maximum = 1000.0, example = 2.0)]
    pub entrainment_speed_m_s: Positive,
    /// The lubricant; it needs a pressure–viscosity law (Barus α or Roelands Z) unless
    /// `effects.piezoviscosity` is `off`.
    pub lubricant: LubricantSpec,
    /// Temperature of the oil entering the contact, °C (isothermal solution: η₀ is taken here);
    /// required unless the lubricant's viscosity is a constant.
    #[schema(value_type = Option<f64>, minimum = -273.0, maximum = 1000.0, example = 40.0)]
    pub temperature_c: Option<Celsius>,
    /// Slide-to-roll ratio s = |u₁ − u₂|/ū, 0 … 2 (default 0); the sliding speed is sū.
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 2.0, example = 0.05)]
    pub slide_roll_ratio: Option<NonNegative>,
    /// Traction from the converged film, on request (needs a slide-to-roll ratio > 0).
    pub traction: Option<NumericalEhlTractionSpec>,
    /// `fast`, `standard` (default) or `high`. Line: nested grids of 64/128, 128/256 or
    /// 256/512 cells with Richardson extrapolation, refined further while the estimated error
    /// of the fine grid's central film exceeds 5 %, 1 % or 0.2 %; or `{"grid": [cells, 1]}`
    /// for an explicit fine grid (32 … 2048 cells, the coarse grid half of it). Point: 64²,
    /// 128² or 256² cells (65², 129², 257² nodes) extrapolated with the grids of half and a
    /// quarter as many, stepped up to grids twice as fine (up to 128², 512² or 1024²) while the
    /// estimated error of the central or the minimum film exceeds the level's 10 %/10 %,
    /// 3 %/2 % or 1 %/0.5 % (warnings `grid_stepped_up`, and `grid_limited` when the finest
    /// grid or the deadline leaves it above); or `{"grid": [n, n]}` with n a power of two,
    /// 64 … 1024, not stepped up.
    #[serde(default)]
    pub fidelity: FidelityRequest,
    /// Return the pressure and film profiles along x as `profiles` (default false; the name
    /// the journal-bearing room uses for its field).
    #[serde(default)]
    #[schema(example = false)]
    pub include_field: bool,
    #[serde(default)]
    pub effects: NumericalEhlEffects,
}

/// The validated case.
#[derive(Debug, Clone)]
pub struct NumericalEhlCase {
    hertz: Contact,
    load_n: f64,
    /// The line contact's length; None for a point contact.
    length_m: Option<f64>,
    speed_m_s: f64,
    lubricant: Lubricant,
    temperature_c: f64,
    slide_roll_ratio: f64,
    traction: Option<NumericalEhlTractionSpec>,
    grids: Grids,
    include_field: bool,
    effects: NumericalEhlEffects,
}

/// The grids a request asks for: the line solver's nested pairs, or the point solver's grids
/// with the level's error tolerances.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Grids {
    Line(Cells),
    Point(PointGrids),
}

impl Validate for NumericalEhlInput {
    type Valid = NumericalEhlCase;
    fn validate(self) -> Result<NumericalEhlCase, Vec<FieldError>> {
        let mut errors = Vec::new();
        // The Hertz part (exact ellipticity), refused with the request's own pointers.
        let hertz = contact_of(
            &self.body1,
            &self.body2,
            self.load_n,
            self.line,
            Method::Exact,
        )
        .map_err(|mut e| errors.append(&mut e))
        .ok();
        let speed = entrainment_speed(self.entrainment_speed_m_s, &mut errors);
        let lubricant = self
            .lubricant
            .parse("/lubricant")
            .map_err(|mut e| errors.append(&mut e))
            .ok();
        let temperature = lubricant.as_ref().and_then(|l| {
            validity::operating_temperature(l, self.temperature_c)
                .map_err(|e| errors.push(e))
                .ok()
        });
        if let Some(l) = &lubricant {
            if l.pressure_law.is_none() && self.effects.piezoviscosity != Mode::Off {
                errors.push(FieldError::new(
                    "/lubricant",
                    "an EHL solution needs a pressure–viscosity law: give pressure_viscosity_coefficient_1_pa (Barus α) or roelands_pressure_viscosity_index (Z), or set effects.piezoviscosity to off",
                ));
            }
        }
        let slide_roll_ratio = slide_roll_ratio(self.slide_roll_ratio, &mut errors);
        if let Some(t) = self.traction {
            if slide_roll_ratio == 0.0 {
                errors.push(FieldError::new(
                    "/traction",
                    "traction needs sliding: give slide_roll_ratio > 0",
                ));
            }
            if t.model == TractionModel::Eyring && t.eyring_stress_pa.is_none() {
                errors.push(FieldError::new(
                    "/traction/eyring_stress_pa",
                    "the Eyring model needs the Eyring stress τ₀ (typically 2–20 MPa)",
                ));
            }
            if t.eyring_stress_pa.is_some_and(|s| s.get() > 1e9) {
                errors.push(FieldError::new(
                    "/traction/eyring_stress_pa",
                    "must be at most 1e9 Pa",
                ));
            }
            if t.limiting_shear_coefficient.is_some_and(|s| s.get() > 1.0) {
                errors.push(FieldError::new(
                    "/traction/limiting_shear_coefficient",
                    "must be within (0, 1]",
                ));
            }
        }
        let grids = if self.line.is_some() {
            line_cells(self.fidelity, &mut errors).map(Grids::Line)
        } else {
            point_grids(self.fidelity, &mut errors)
        };
        match (errors.is_empty(), hertz, lubricant, grids, temperature) {
            (true, Some(hertz), Some(lubricant), Some(grids), Some(temperature_c)) => {
                Ok(NumericalEhlCase {
                    hertz,
                    load_n: self.load_n.get(),
                    length_m: self.line.map(|l| l.length_m.get()),
                    speed_m_s: speed,
                    lubricant,
                    temperature_c,
                    slide_roll_ratio,
                    traction: self.traction,
                    grids,
                    include_field: self.include_field,
                    effects: self.effects,
                })
            }
            _ => Err(errors),
        }
    }
}

/// The line solver's grids for a fidelity request.
fn line_cells(fidelity: FidelityRequest, errors: &mut Vec<FieldError>) -> Option<Cells> {
    match fidelity {
        FidelityRequest::Level(Level::ClosedForm) => {
            refuse_closed_form(errors);
            None
        }
        FidelityRequest::Level(level) => {
            let (fine, tolerance) = match level {
                Level::Fast => (2 * FAST_CELLS, REFINE_ABOVE[0]),
                Level::High => (2 * HIGH_CELLS, REFINE_ABOVE[2]),
                _ => (2 * STANDARD_CELLS, REFINE_ABOVE[1]),
            };
            Some(Cells {
                level,
                fine,
                finest: (fine * 4).max(1024),
                tolerance,
            })
        }
        FidelityRequest::Custom(custom) if custom.tolerance.is_some() => {
            errors.push(FieldError::new(
                "/fidelity/tolerance",
                "the Newton solve always converges to a scaled residual of 1e-10; give only a grid",
            ));
            None
        }
        FidelityRequest::Custom(custom) => match custom.grid {
            Some([n, 1]) if (CUSTOM_CELLS.0..=CUSTOM_CELLS.1).contains(&n) && n % 2 == 0 => {
                Some(Cells {
                    level: Level::Standard,
                    fine: n as usize,
                    finest: n as usize,
                    tolerance: REFINE_ABOVE[1],
                })
            }
            _ => {
                errors.push(FieldError::new(
                    "/fidelity/grid",
                    format!(
                        "must be [cells, 1] with an even cell count in {}…{}",
                        CUSTOM_CELLS.0, CUSTOM_CELLS.1
                    ),
                ));
                None
            }
        },
    }
}

fn refuse_closed_form(errors: &mut Vec<FieldError>) {
    errors.push(FieldError::new(
        "/fidelity",
        "the numerical EHL solver has fast, standard and high levels; the closed-form films are at /v1/contacts/ehl-film",
    ));
}

/// The point solver's grid for a fidelity request.
fn point_grids(fidelity: FidelityRequest, errors: &mut Vec<FieldError>) -> Option<Grids> {
    let level = |level: Level, i: usize| {
        Some(Grids::Point(PointGrids {
            level,
            cells: POINT_CELLS[i],
            finest: POINT_FINEST_CELLS[i],
            central_tolerance: POINT_CENTRAL_TOLERANCE[i],
            min_tolerance: POINT_MIN_TOLERANCE[i],
            domain_scale: 1.0,
        }))
    };
    match fidelity {
        FidelityRequest::Level(Level::Fast) => level(Level::Fast, 0),
        FidelityRequest::Level(Level::Standard) => level(Level::Standard, 1),
        FidelityRequest::Level(Level::High) => level(Level::High, 2),
        FidelityRequest::Level(Level::ClosedForm) => {
            refuse_closed_form(errors);
            None
        }
        FidelityRequest::Custom(custom) if custom.tolerance.is_some() => {
            errors.push(FieldError::new(
                "/fidelity/tolerance",
                "the multigrid cycles run to a fixed algebraic tolerance far below the grid's error; give only a grid",
            ));
            None
        }
        FidelityRequest::Custom(custom) => match custom.grid {
            Some([n, m])
                if n == m
                    && n.is_power_of_two()
                    && (POINT_CUSTOM_CELLS.0..=POINT_CUSTOM_CELLS.1).contains(&n) =>
            {
                Some(Grids::Point(PointGrids {
                    level: Level::Standard,
                    cells: n as usize,
                    finest: n as usize,
                    central_tolerance: POINT_CENTRAL_TOLERANCE[1],
                    min_tolerance: POINT_MIN_TOLERANCE[1],
                    domain_scale: 1.0,
                }))
            }
            _ => {
                errors.push(FieldError::new(
                    "/fidelity/grid",
                    format!(
                        "a point contact takes [n, n] cells with n a power of two in {}…{}",
                        POINT_CUSTOM_CELLS.0, POINT_CUSTOM_CELLS.1
                    ),
                ));
                None
            }
        },
    }
}

/// A point contact solved on an explicit `cells`² grid (a power of two, at least 64), which
/// may be finer than the wire's 1024², to `high`'s tolerances, with the domain's inlet and
/// sides at `domain_scale` times the wire's: the accuracy bench's reference (2048² takes tens
/// of seconds and about 1 GB, beyond a request's deadline and memory; a widened domain leaves
/// no truncation for the wire's correction to be checked against). `body` is a request the
/// wire accepts; its fidelity is replaced. Returns the response's `result`, `solver` and
/// `warnings` as the wire would, or the refusal.
#[doc(hidden)]
pub fn point_reference(
    body: &[u8],
    cells: usize,
    domain_scale: f64,
    deadline: std::time::Instant,
) -> Result<serde_json::Value, CalcError> {
    let invalid =
        |why: String| CalcError::Internal(format!("not a point-contact reference: {why}"));
    let input: NumericalEhlInput =
        serde_json::from_slice(body).map_err(|e| invalid(e.to_string()))?;
    let mut case = input.validate().map_err(|e| invalid(format!("{e:?}")))?;
    if case.length_m.is_some() || !cells.is_power_of_two() || cells < point::MIN_CELLS {
        return Err(invalid(format!("{cells}² cells for a point contact")));
    }
    case.grids = Grids::Point(PointGrids {
        level: Level::High,
        cells,
        finest: cells,
        central_tolerance: POINT_CENTRAL_TOLERANCE[2],
        min_tolerance: POINT_MIN_TOLERANCE[2],
        domain_scale,
    });
    let mut ctx = Context::new(
        deadline,
        std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false)),
    );
    let result = Ehl::run(case, &mut ctx)?;
    Ok(serde_json::json!({
        "result": result,
        "solver": ctx.report,
        "warnings": ctx.warnings,
    }))
}

/// Profiles along x (a point contact's along its centre line y = 0).
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct NumericalEhlProfiles {
    /// Positions along x from the contact centre, m (the entrainment is towards +x).
    pub x_m: Vec<f64>,
    /// Pressure at each position, Pa.
    pub pressure_pa: Vec<f64>,
    /// Film thickness at each position, m.
    pub film_m: Vec<f64>,
}

/// Traction from the converged film.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct NumericalEhlTraction {
    pub model: TractionModel,
    /// Sliding (shear) traction force over the contact (a line contact's whole length), N.
    pub traction_force_n: f64,
    /// Traction coefficient F_t/F.
    pub traction_coefficient: f64,
    /// Share of the load carried where the limiting shear stress caps τ (0 without it).
    pub limited_load_fraction: f64,
}

/// A closed-form film to compare with.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct NumericalEhlFormula {
    /// Line: `pan_hamrock_central`, `pan_hamrock_min`, `dowson_higginson_min` or
    /// `moes_central`. Point: `hamrock_dowson_central` and `hamrock_dowson_min` (the hard-EHL
    /// fits, Stachowiak eq. 7.26, Hamrock eq. 21.57), or for an isoviscous solve
    /// `hamrock_isoviscous_elastic_central` and `hamrock_isoviscous_rigid`.
    pub formula: String,
    /// The formula's film, m.
    pub film_m: f64,
    /// (numerical − formula)/formula.
    pub deviation: f64,
}

/// Result.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct NumericalEhlOutput {
    /// `line` or `point`.
    #[schema(example = "line")]
    pub contact: String,
    /// Film at the contact centre x = 0, m.
    pub central_film_thickness_m: f64,
    /// Smallest film, m (in the outlet constriction under heavy load; in a point contact the
    /// horseshoe's side lobes).
    pub min_film_thickness_m: f64,
    /// Point contact: the estimated relative error of the central film (the fine grid's, from
    /// the levels' films with their observed order, plus what the multigrid cycles left, plus
    /// the uncertainty of the domain's truncation; it bounds the extrapolated film's). At
    /// `standard` and `high` the films are corrected for the truncation of the inlet's and the
    /// sides' pressure by the solver's domain (up to 1 % at light loads): the film's change
    /// when the domain is doubled, measured on a coarse pair of grids that share their nodes.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub central_film_error_estimate: Option<f64>,
    /// Point contact: the estimated relative error of the minimum film, as the central's.
    /// `solver.error_estimate` is the larger of the two.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub min_film_error_estimate: Option<f64>,
    /// Point contact: the lateral position y of the smallest film, m (one of the two
    /// symmetric side lobes).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub min_film_position_y_m: Option<f64>,
    /// Highest pressure, Pa (the outlet spike when there is one).
    pub max_pressure_pa: f64,
    /// Where the highest pressure is, m from the centre.
    pub max_pressure_position_m: f64,
    /// Where the film cavitates (the outlet meniscus), m from the centre.
    pub cavitation_position_m: f64,
    /// Hertz half-width b of the dry contact under the same load, m; for a point contact the
    /// semi-axis along x.
    pub hertz_half_width_m: f64,
    /// Point contact: the Hertz semi-axis across the entrainment direction (along y), m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub hertz_semi_axis_y_m: Option<f64>,
    /// Hertz maximum pressure p_h of the dry contact, Pa.
    pub hertz_pressure_pa: f64,
    /// Moes' load parameter: line M = W′(2U)^(−1/2), point M = W(2U)^(−3/4).
    pub moes_load_parameter: f64,
    /// Moes' material parameter L = G(2U)^(1/4) (0 for an isoviscous solve).
    pub moes_material_parameter: f64,
    /// Speed parameter U = η₀ū/(E′R_x).
    pub speed_parameter: f64,
    /// Materials parameter G = αE′ (0 for an isoviscous solve).
    pub materials_parameter: f64,
    /// Load parameter: line W′ = w/(E′R_x) with w = F/length; point W = F/(E′R_x²).
    pub load_parameter: f64,
    /// E′ = 2/Σ(1 − ν²)/E, Pa.
    pub effective_modulus_pa: f64,
    /// R_x, the reduced radius along the entrainment direction, m.
    pub reduced_radius_x_m: f64,
    /// η₀ at the inlet temperature and ambient pressure, Pa·s.
    pub viscosity_pa_s: f64,
    /// The closed-form films of `/v1/contacts/ehl-film` beside the numerical ones (the
    /// published band: the fits scatter by about ±10 % among themselves).
    pub formulas: Vec<NumericalEhlFormula>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub traction: Option<NumericalEhlTraction>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub profiles: Option<NumericalEhlProfiles>,
}

impl Calculation for Ehl {
    const PATH: &'static str = "/v1/contacts/ehl";
    const SUMMARY: &'static str =
        "Numerical EHL of a line or point contact: film, pressure spike, horseshoe, traction";
    const DESCRIPTION: &'static str = include_str!("numerical.md");
    const FIDELITY: &'static [Level] = &[Level::Fast, Level::Standard, Level::High];
    const EFFECTS: &'static [&'static str] = &["compressibility", "piezoviscosity"];
    const EXAMPLE: &'static str = r#"{"body1": {"radius_x_m": 0.02, "elastic_modulus_pa": 2.1e11, "poisson_ratio": 0.3}, "body2": {"radius_x_m": 0.02, "elastic_modulus_pa": 2.1e11, "poisson_ratio": 0.3}, "load_n": 5000, "line": {"length_m": 0.01}, "entrainment_speed_m_s": 2.0, "lubricant": {"viscosity_pa_s": 0.05, "roelands_pressure_viscosity_index": 0.6}, "temperature_c": 40, "slide_roll_ratio": 0.05, "traction": {"model": "eyring", "eyring_stress_pa": 5e6, "limiting_shear_coefficient": 0.08}}"#;

    type Input = NumericalEhlInput;
    type Output = NumericalEhlOutput;

    fn run(case: NumericalEhlCase, ctx: &mut Context) -> Result<NumericalEhlOutput, CalcError> {
        let hertz = case.hertz.solve()?;
        // The dry contact's approach is not part of an EHL solution: its warning is not passed
        // on; the others are, with the dry contact's report until the solver's replaces it.
        for w in hertz.warnings_but_approach() {
            ctx.warn(w.code, w.message.clone());
        }
        ctx.report(hertz.report.clone());
        let eta0 = inlet_viscosity(&case.lubricant, case.temperature_c)?;
        validity::warn_hot_oil(ctx, "the inlet oil", case.temperature_c);
        let ph = hertz.max_pressure_pa;
        let law = pressure_law(&case, eta0, ph, ctx)?;
        if let Some(PressureLaw::Barus { alpha_1_pa }) = law {
            if alpha_1_pa * ph > BARUS_LIMIT {
                ctx.warn(
                    "barus_beyond_its_range",
                    format!("αp_h = {:.1}: Barus' exponential overstates the viscosity at {:.2} GPa by orders of magnitude (Khonsari §2.6 limits it to about 0.07 GPa, Roelands to moderate pressures); the film, set in the inlet, is little affected, but the pressure spike and the traction are — prefer a Roelands Z", alpha_1_pa * ph, ph * 1e-9),
                );
            }
        }
        let rise = Fluid {
            law: PressureLaw::Barus { alpha_1_pa: 0.0 },
            eta0_pa_s: eta0,
            hertz_pressure_pa: ph,
            compressible: true,
        }
        .density(1.0)
        .0 - 1.0;
        let compressible = decide(
            ctx,
            "compressibility",
            case.effects.compressibility,
            Criterion {
                name: "density_rise_at_hertz_pressure",
                value: rise,
                threshold: COMPRESSIBILITY_THRESHOLD,
            },
            "Dowson–Higginson density",
        );
        let fluid = Fluid {
            law: law.unwrap_or(PressureLaw::Barus { alpha_1_pa: 0.0 }),
            eta0_pa_s: eta0,
            hertz_pressure_pa: ph,
            compressible,
        };
        let alpha = law.map_or(0.0, |l| l.alpha_1_pa(eta0));
        match (case.grids, case.length_m) {
            (Grids::Line(cells), Some(length)) => {
                line_contact(&case, &hertz, fluid, alpha, cells, length, ctx)
            }
            (Grids::Point(grids), None) => point_contact(&case, &hertz, fluid, alpha, grids, ctx),
            _ => Err(CalcError::Internal(
                "the grids do not match the contact".to_owned(),
            )),
        }
    }
}

/// The line contact: Moes' map check, the nested Newton solves, films and traction.
fn line_contact(
    case: &NumericalEhlCase,
    hertz: &Solution,
    fluid: Fluid,
    alpha: f64,
    cells: Cells,
    length_m: f64,
    ctx: &mut Context,
) -> Result<NumericalEhlOutput, CalcError> {
    let (e, rx, ph) = (
        hertz.effective_modulus_pa,
        hertz.reduced_radius_x_m,
        fluid.hertz_pressure_pa,
    );
    let b = hertz.half_width_m().unwrap_or(f64::NAN);
    let groups = Groups {
        u: fluid.eta0_pa_s * case.speed_m_s / (e * rx),
        g: alpha * e,
        w: case.load_n / length_m / (e * rx),
    };
    let two_u = 2.0 * groups.u;
    let (m, l) = (groups.w / two_u.sqrt(), groups.g * two_u.powf(0.25));
    if !(MOES_M_RANGE.0..=MOES_M_RANGE.1).contains(&m) || l > MOES_L_MAX {
        return Err(CalcError::impossible(
            "/load_n",
            format!("Moes' M = {m:.4e} and L = {l:.4e} are outside the solver's map (M {}…{}, L ≤ {MOES_L_MAX}): below M = 0.1 the contact is rigid–hydrodynamic, above 10⁴ the Hertz zone cannot be resolved", MOES_M_RANGE.0, MOES_M_RANGE.1),
        ));
    }
    let moes_h = MoesAsymptotes::new(m, l).central();
    let problem = LineProblem::at_moes(fluid, m, l);
    let solved = solve_line(&problem, cells, &ctx.budget())?;
    for w in &solved.warnings {
        ctx.warn(w.code, w.message.clone());
    }
    ctx.report(solved.report.clone());
    let scale = b * b / rx;
    let fine = &solved.fine;
    let (p_index, p_max) = peak(&fine.pressure);
    let cavitation = cavitation_point(&fine.x, &fine.pressure);
    let central = solved.central * scale;
    let min = solved.min * scale;
    let (ph_central, ph_min) = pan_hamrock(&groups, groups.w);
    let mut formulas = vec![compare(rx, "moes_central", moes_h * two_u.sqrt(), central)];
    if alpha > 0.0 {
        formulas.push(compare(rx, "pan_hamrock_central", ph_central, central));
        formulas.push(compare(rx, "pan_hamrock_min", ph_min, min));
        formulas.push(compare(
            rx,
            "dowson_higginson_min",
            dowson_higginson(&groups, groups.w),
            min,
        ));
    }
    let n = fine.x.len();
    let cells_iter = (0..n).map(|i| {
        let width = 0.5 * (fine.x[(i + 1).min(n - 1)] - fine.x[i.saturating_sub(1)]) * b;
        (fine.pressure[i], fine.film[i] * scale, width * length_m)
    });
    let traction = case
        .traction
        .map(|spec| traction(&spec, &fluid, cells_iter, case));
    warn_traction(&traction, ctx);
    let profiles = case.include_field.then(|| NumericalEhlProfiles {
        x_m: fine.x.iter().map(|x| x * b).collect(),
        pressure_pa: fine.pressure.iter().map(|p| p * ph).collect(),
        film_m: fine.film.iter().map(|h| h * scale).collect(),
    });
    Ok(NumericalEhlOutput {
        contact: "line".to_owned(),
        central_film_thickness_m: central,
        min_film_thickness_m: min,
        central_film_error_estimate: None,
        min_film_error_estimate: None,
        min_film_position_y_m: None,
        max_pressure_pa: p_max * ph,
        max_pressure_position_m: fine.x[p_index] * b,
        cavitation_position_m: cavitation * b,
        hertz_half_width_m: b,
        hertz_semi_axis_y_m: None,
        hertz_pressure_pa: ph,
        moes_load_parameter: m,
        moes_material_parameter: l,
        speed_parameter: groups.u,
        materials_parameter: groups.g,
        load_parameter: groups.w,
        effective_modulus_pa: e,
        reduced_radius_x_m: rx,
        viscosity_pa_s: fluid.eta0_pa_s,
        formulas,
        traction,
        profiles,
    })
}

/// A closed-form film h/R_x beside a numerical film in m.
fn compare(rx: f64, formula: &str, h: f64, numerical: f64) -> NumericalEhlFormula {
    NumericalEhlFormula {
        formula: formula.to_owned(),
        film_m: h * rx,
        deviation: numerical / (h * rx) - 1.0,
    }
}

/// The point contact: the Hertz ellipse in the solver's units, Moes' map check, the multigrid
/// solve on the requested grid and the grid of half as many cells, Richardson's extrapolation,
/// films, formulas and traction.
fn point_contact(
    case: &NumericalEhlCase,
    hertz: &Solution,
    fluid: Fluid,
    alpha: f64,
    grids: PointGrids,
    ctx: &mut Context,
) -> Result<NumericalEhlOutput, CalcError> {
    let (e, rx, ph) = (
        hertz.effective_modulus_pa,
        hertz.reduced_radius_x_m,
        fluid.hertz_pressure_pa,
    );
    let ry = hertz.reduced_radius_y_m.unwrap_or(f64::INFINITY);
    let (major, minor) = hertz.semi_axes_m().unwrap_or((f64::NAN, f64::NAN));
    // a along the entrainment direction x, b across it.
    let (a, b) = if hertz.major_axis() == MajorAxis::X {
        (major, minor)
    } else {
        (minor, major)
    };
    let groups = Groups {
        u: fluid.eta0_pa_s * case.speed_m_s / (e * rx),
        g: alpha * e,
        w: case.load_n / (e * rx * rx),
    };
    let two_u = 2.0 * groups.u;
    let (m, l) = (groups.w * two_u.powf(-0.75), groups.g * two_u.powf(0.25));
    if !(POINT_MOES_M_RANGE.0..=POINT_MOES_M_RANGE.1).contains(&m) || l > MOES_L_MAX {
        return Err(CalcError::impossible(
            "/load_n",
            format!("Moes' M = {m:.4e} and L = {l:.4e} (point contact: M = W(2U)^−¾) are outside the point solver's map (M {}…{}, L ≤ {MOES_L_MAX}): below M = 1 the contact is rigid–hydrodynamic, above 5000 the Hertz zone cannot be resolved", POINT_MOES_M_RANGE.0, POINT_MOES_M_RANGE.1),
        ));
    }
    let k = b / a;
    let radius_ratio = if ry.is_finite() { ry / rx } else { 1e9 };
    let regimes = regime_films(
        groups.viscosity_parameter(),
        groups.elasticity_parameter(),
        k,
        radius_ratio,
    );
    let reduced_guess = match point_regime(&regimes) {
        Regime::IsoviscousRigid => regimes.isoviscous_rigid,
        Regime::PiezoviscousRigid => regimes.piezoviscous_rigid,
        Regime::IsoviscousElastic => regimes.isoviscous_elastic.1,
        Regime::PiezoviscousElastic => regimes.piezoviscous_elastic.1,
    };
    // H = hR_x/a².
    let unit = a * a / rx;
    let film_guess = groups.film_from_reduced(reduced_guess) * rx / unit;
    let ellipse = HertzEllipse {
        a,
        b,
        rx,
        ry,
        e_prime: e,
    };
    let problem =
        PointProblem::new(fluid, &ellipse, case.speed_m_s, film_guess).widened(grids.domain_scale);
    let run = solve_point(&problem, grids, &ctx.budget())?;
    for w in &run.warnings {
        ctx.warn(w.code, w.message.clone());
    }
    ctx.report(run.report.clone());
    let (fine, central, min, min_y) = (&run.fine, run.central, run.min, run.min_y);
    let nx = fine.x.len();
    let (p_index, p_max) = peak(&fine.pressure);
    // The centre line y = 0 is the middle row of the grid.
    let centre_row = fine.y.len() / 2;
    let row = |field: &[f64]| field[centre_row * nx..(centre_row + 1) * nx].to_vec();
    let centre_pressure = row(&fine.pressure);
    let cavitation = cavitation_point(&fine.x, &centre_pressure);
    let film_m = |h: f64| h * unit;
    let formulas = if alpha > 0.0 {
        if !(HARD_FIT_ELLIPTICITY.0..=HARD_FIT_ELLIPTICITY.1).contains(&k) {
            ctx.warn(
                "outside_fitted_range",
                format!("the Hamrock–Dowson fits in `formulas` were made for k = {}–{} (entrainment across the major axis at k > 1); at k = {k:.3} their deviations are indicative only (Hamrock §21.3.3)", HARD_FIT_ELLIPTICITY.0, HARD_FIT_ELLIPTICITY.1),
            );
        }
        vec![
            compare(
                rx,
                "hamrock_dowson_central",
                hard_central_film(&groups, k),
                film_m(central),
            ),
            compare(
                rx,
                "hamrock_dowson_min",
                hard_min_film(&groups, k),
                film_m(min),
            ),
        ]
    } else {
        vec![
            compare(
                rx,
                "hamrock_isoviscous_elastic_central",
                groups.film_from_reduced(regimes.isoviscous_elastic.1),
                film_m(central),
            ),
            compare(
                rx,
                "hamrock_isoviscous_rigid",
                groups.film_from_reduced(regimes.isoviscous_rigid),
                film_m(central),
            ),
        ]
    };
    let (hx, hy) = (fine.x[1] - fine.x[0], fine.y[1] - fine.y[0]);
    let cell_area = hx * a * hy * b;
    let cells_iter =
        (0..fine.pressure.len()).map(|k| (fine.pressure[k], film_m(fine.film[k]), cell_area));
    let traction = case
        .traction
        .map(|spec| traction(&spec, &fluid, cells_iter, case));
    warn_traction(&traction, ctx);
    let profiles = case.include_field.then(|| NumericalEhlProfiles {
        x_m: fine.x.iter().map(|x| x * a).collect(),
        pressure_pa: centre_pressure.iter().map(|p| p * ph).collect(),
        film_m: row(&fine.film).into_iter().map(film_m).collect(),
    });
    Ok(NumericalEhlOutput {
        contact: "point".to_owned(),
        central_film_thickness_m: film_m(central),
        min_film_thickness_m: film_m(min),
        central_film_error_estimate: Some(run.central_error),
        min_film_error_estimate: Some(run.min_error),
        min_film_position_y_m: Some(min_y * b),
        max_pressure_pa: p_max * ph,
        max_pressure_position_m: fine.x[p_index % nx] * a,
        cavitation_position_m: cavitation * a,
        hertz_half_width_m: a,
        hertz_semi_axis_y_m: Some(b),
        hertz_pressure_pa: ph,
        moes_load_parameter: m,
        moes_material_parameter: l,
        speed_parameter: groups.u,
        materials_parameter: groups.g,
        load_parameter: groups.w,
        effective_modulus_pa: e,
        reduced_radius_x_m: rx,
        viscosity_pa_s: fluid.eta0_pa_s,
        formulas,
        traction,
        profiles,
    })
}

/// The index and value of the highest pressure.
fn peak(pressure: &[f64]) -> (usize, f64) {
    pressure
        .iter()
        .copied()
        .enumerate()
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .unwrap_or((0, 0.0))
}

/// Where a pressure profile along `x` ends: the node after its last pressurised one (the
/// outlet meniscus), or the domain's end.
fn cavitation_point(x: &[f64], pressure: &[f64]) -> f64 {
    let last = x.len() - 1;
    pressure
        .iter()
        .rposition(|&p| p > 0.0)
        .map_or(x[last], |i| x[(i + 1).min(last)])
}

fn warn_traction(traction: &Option<NumericalEhlTraction>, ctx: &mut Context) {
    if let Some(t) = traction.as_ref().filter(|t| t.traction_coefficient > 1.0) {
        ctx.warn(
            "traction_exceeds_load",
            format!("the traction coefficient {:.3e} exceeds 1: the {:?} shear law with the pressure–viscosity law overflows in the Hertz zone (Stachowiak §7.7); use the Eyring model and/or a limiting shear stress", t.traction_coefficient, t.model),
        );
    }
}

fn decide(ctx: &mut Context, effect: &'static str, mode: Mode, c: Criterion, what: &str) -> bool {
    let decision = Decision::decide(mode, c, what);
    let applied = decision.applied;
    ctx.decide(effect, decision);
    applied
}

/// The pressure–viscosity law to solve with (None: isoviscous), after the piezoviscosity
/// decision.
fn pressure_law(
    case: &NumericalEhlCase,
    eta0: f64,
    ph: f64,
    ctx: &mut Context,
) -> Result<Option<PressureLaw>, CalcError> {
    let Some(law) = case.lubricant.pressure_law else {
        ctx.decide(
            "piezoviscosity",
            Decision::not_applicable(
                Mode::Off,
                "piezoviscosity: requested off and the lubricant has no pressure–viscosity law",
            ),
        );
        return Ok(None);
    };
    let alpha = law.alpha_1_pa(eta0);
    if let PressureLaw::Roelands { .. } = law {
        if !(alpha.is_finite() && alpha > 0.0) {
            return Err(CalcError::impossible(
                "/lubricant",
                format!("Roelands' law needs η₀ > 6.3e-5 Pa·s (log₁₀η₀[mPa·s] + 1.2 > 0); η₀ = {eta0:.4e} Pa·s: give the Barus coefficient for so thin a fluid"),
            ));
        }
    }
    let applied = decide(
        ctx,
        "piezoviscosity",
        case.effects.piezoviscosity,
        Criterion {
            name: "alpha_times_hertz_pressure",
            value: alpha * ph,
            threshold: PIEZOVISCOSITY_THRESHOLD,
        },
        law.name(),
    );
    Ok(applied.then_some(law))
}

/// The traction of the converged film for the request's traction law.
fn traction(
    spec: &NumericalEhlTractionSpec,
    fluid: &Fluid,
    cells: impl Iterator<Item = (f64, f64, f64)>,
    case: &NumericalEhlCase,
) -> NumericalEhlTraction {
    let shear = match (spec.model, spec.eyring_stress_pa) {
        (TractionModel::Eyring, Some(t0)) => ShearLaw::Eyring {
            stress_pa: t0.get(),
        },
        _ => ShearLaw::Newtonian,
    };
    let law = TractionLaw {
        shear,
        limiting_shear_coefficient: spec.limiting_shear_coefficient.map(|g| g.get()),
    };
    let sliding = case.slide_roll_ratio * case.speed_m_s;
    let t = traction::traction(&law, fluid, sliding, case.load_n, cells);
    NumericalEhlTraction {
        model: spec.model,
        traction_force_n: t.force_n,
        traction_coefficient: t.coefficient,
        limited_load_fraction: t.limited_load_fraction,
    }
}

#[cfg(test)]
#[path = "numerical_tests.rs"]
mod tests;
