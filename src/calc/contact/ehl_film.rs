//! `POST /v1/contacts/ehl-film`: the film thickness of a lubricated (elastohydrodynamic)
//! contact from the closed-form fits — Hamrock–Dowson for point and elliptical contacts, hard
//! and soft, the four-regime formulas, and the Pan–Hamrock, Dowson–Higginson and Moes fits for
//! line contacts — with the film parameter Λ and the optional inlet-heating and starvation
//! reductions.
//!
//! The contact (radii, moduli, ellipticity, R_x, R_y, E′, p_max) is the Hertz room's: the same
//! body objects, validated and solved by [`super::hertz`], so both rooms agree to the last digit.
//!
//! Conventions (the texts differ; every field states the one it uses):
//! - The entrainment (rolling) direction is the request's x. R_x is the reduced radius along
//!   it, 1/R_x = 1/r₁ₓ + 1/r₂ₓ (Hamrock's R_x; Stachowiak's HD "R′" is this R_x, *not* his
//!   Hertz R′ = (1/R_x + 1/R_y)⁻¹, which is half of it for a ball on a flat).
//! - E′ = 2/[(1 − ν₁²)/E₁ + (1 − ν₂²)/E₂], i.e. 1/E′ = ½Σ(1 − ν²)/E (Hamrock, Stachowiak ch. 7,
//!   Khonsari): 2.2 × 10¹¹ Pa for steel, twice Johnson's E*.
//! - ū is the *mean* entrainment speed (u₁ + u₂)/2 (Hamrock eq. 21.55, Stachowiak §7.4,
//!   Khonsari eq. 15.12), not the sum that Stachowiak's ch. 4 Reynolds equation uses.
//! - Ellipticity k = D_y/D_x, the contact's width across the rolling direction over its length
//!   along it (Hamrock's k). It is the Hertz κ ≥ 1 when the major axis lies across the rolling
//!   direction (ball bearings) and 1/κ < 1 when it lies along it.
//!
//! Dimensionless groups (Hamrock eqs 21.52–21.56): U = η₀ū/(E′R_x), G = αE′, W = F/(E′R_x²),
//! H = h/R_x. Point contact (Hamrock eqs 21.57, 21.58; Stachowiak eqs 7.26, 7.27):
//! hard H_min = 3.63 U^0.68 G^0.49 W^−0.073 (1 − e^−0.68k),
//! H_c = 2.69 U^0.67 G^0.53 W^−0.067 (1 − 0.61 e^−0.73k); soft H_min = 7.43 U^0.65 W^−0.21
//! (1 − 0.85 e^−0.31k). Regimes (Hamrock §21.3.5, eqs 21.59–21.67; Stachowiak §7.4 gives the
//! central films too) in the reduced groups Ĥ = H(W/U)², g_v = GW³/U², g_e = W^(8/3)/U².

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::hertz::{BodySpec, ClosedFormFit, Hertz, HertzCase, HertzInput, HertzOutput, LineSpec};
use crate::calc::lubricant::model::{PressureLaw, TemperatureLaw};
use crate::calc::lubricant::{Lubricant, LubricantSpec};
use crate::calc::quantity::{Celsius, NonNegative, Positive};
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::effects::{Criterion, Decision, Mode};
use crate::fidelity::{FidelityRequest, Level};

pub struct EhlFilm;

/// Highest entrainment speed accepted, m/s (beyond it the closed forms have no footing at all).
const MAX_SPEED_M_S: f64 = 1e3;
/// Largest slide-to-roll ratio |u₁ − u₂|/ū: 2 is pure sliding (one surface still).
const MAX_SLIDE_ROLL: f64 = 2.0;
/// Ellipticities the hard-EHL fit was made over (34 cases, k = 1 … 8: Hamrock §21.3.3).
pub(crate) const HARD_FIT_ELLIPTICITY: (f64, f64) = (1.0, 8.0);
/// Ellipticities of the soft-EHL fit (17 cases, k = 1 … 12: Hamrock §21.3.4).
const SOFT_FIT_ELLIPTICITY: (f64, f64) = (1.0, 12.0);
/// U and W of the hard-EHL fit: the texts say "U over about 2 decades, W over 1 decade" from
/// the base case U = 0.168 × 10⁻¹¹, W = 0.111 × 10⁻⁶ (Hamrock Figs 21.70–21.71, Stachowiak
/// Figs 7.17–7.19, G = 4522); the upper ends are that statement, not a table (verify against
/// Hamrock & Dowson 1977, J. Lubr. Technol. 99:264).
const HARD_FIT_SPEED: (f64, f64) = (1.683e-12, 1.683e-10);
const HARD_FIT_LOAD: (f64, f64) = (1.106e-7, 1.106e-6);
/// Stachowiak §7.4: the isothermal fits overestimate the film above about 1 µm and 10 m/s,
/// where the inlet heats.
const INLET_HEATING_FILM_M: f64 = 1e-6;
const INLET_HEATING_SPEED_M_S: f64 = 10.0;
/// `auto` applies the inlet-heating reduction when it thins the film by more than this fraction.
const THERMAL_THRESHOLD: f64 = 0.05;
/// Film parameter above which the surfaces are fully separated (Hamrock §21.3.6; Khonsari
/// FE-7; Stachowiak §7.5: Λ ≥ 3 minimal wear).
const FULL_FILM_LAMBDA: f64 = 3.0;
/// Below this Λ the asperities carry most of the load (boundary lubrication; Khonsari FE-7).
const BOUNDARY_LAMBDA: f64 = 1.0;

/// Surface roughness: both bodies' RMS roughness, or the composite.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct RoughnessSpec {
    /// RMS roughness R_q of body 1, m (≥ 0, at most 1e-4), with `body2_rms_m`.
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 1e-4, example = 6.25e-8)]
    pub body1_rms_m: Option<NonNegative>,
    /// RMS roughness R_q of body 2, m (≥ 0, at most 1e-4), with `body1_rms_m`.
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 1e-4, example = 1.75e-7)]
    pub body2_rms_m: Option<NonNegative>,
    /// Composite RMS roughness √(σ₁² + σ₂²), m (> 0, at most 1.5e-4), instead of the two.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1.5e-4, example = 1.86e-7)]
    pub composite_rms_m: Option<Positive>,
}

const MAX_ROUGHNESS_M: f64 = 1e-4;

/// Effects this calculation understands.
#[derive(Debug, Clone, Copy, Default, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct EhlEffects {
    /// Inlet shear heating: the film times the thermal reduction factor of Gupta et al. (1992),
    /// φ_T = [1 − 13.2 (p_max/E′) L^0.42] / [1 + 0.213 (1 + 2.23 s^0.83) L^0.64] with the thermal
    /// loading parameter L = (−∂η/∂T) ū²/k_f and the slide-to-roll ratio s (the texts name the
    /// effect but give no formula: Stachowiak §7.4, Khonsari §15.6). `auto` applies it when it
    /// thins the film by more than 5 %; needs a viscosity–temperature law.
    #[serde(default)]
    pub thermal: Mode,
    /// Starvation from the inlet meniscus distance (Hamrock & Dowson 1977, point contacts):
    /// applied when `inlet_meniscus_distance_m` is inside the critical inlet distance; not
    /// applicable without that input or for a line contact.
    #[serde(default)]
    pub starvation: Mode,
    /// Mixed lubrication: judged from the film parameter Λ (full film Λ > 3, mixed 1–3,
    /// boundary < 1). The films are the smooth-surface films: there is no mixed-EHL film model
    /// in the texts (Khonsari FE-9), so `on` is refused; `auto` reports Λ and warns below 3.
    #[serde(default)]
    pub mixed_lubrication: Mode,
}

/// Request: two lubricated bodies in rolling (and sliding) contact.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct EhlFilmInput {
    /// The first body, as in `/v1/contacts/hertz`; x is the entrainment (rolling) direction.
    pub body1: BodySpec,
    /// The second body.
    pub body2: BodySpec,
    /// Normal load F pressing the bodies together, N (> 0, at most 1e12); for a line contact
    /// the total load on `line.length_m`.
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 1e12, example = 4513.0)]
    pub load_n: Positive,
    /// Mean entrainment speed ū = (u₁ + u₂)/2 of the two surfaces relative to the contact,
    /// along x, m/s (> 0, at most 1000). The MEAN, not the sum: a ball bearing's inner-race
    /// contact entrains at ū = (d_e² − d²)|ω_i − ω_o|/(4d_e) (Hamrock eq. 21.98).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 1000.0, example = 6.252)]
    pub entrainment_speed_m_s: Positive,
    /// The lubricant; it must have a pressure–viscosity law (Barus α, or a Roelands Z from
    /// which α = Z·5.1e-9·(ln η₀ + 9.67), Khonsari eq. 2.13).
    pub lubricant: LubricantSpec,
    /// Temperature of the oil entering the contact, °C: η₀ and α are taken here.
    #[schema(value_type = f64, minimum = -273.0, maximum = 1000.0, example = 40.0)]
    pub temperature_c: Celsius,
    /// Present for a line contact of cylinders with axes along y (as in the Hertz room).
    pub line: Option<LineSpec>,
    /// Surface roughness, for the film parameter Λ = h_min/√(σ₁² + σ₂²).
    pub roughness: Option<RoughnessSpec>,
    /// Slide-to-roll ratio s = |u₁ − u₂|/ū, dimensionless, 0 … 2 (default 0, pure rolling);
    /// used only by the inlet-heating effect.
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 2.0, example = 0.0)]
    pub slide_roll_ratio: Option<NonNegative>,
    /// Distance from the contact centre upstream to the inlet oil meniscus, m (> 0, beyond the
    /// Hertz semi-axis along x); enables the starvation effect (point contacts).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, example = 0.0005)]
    pub inlet_meniscus_distance_m: Option<Positive>,
    /// How the Hertz ellipticity is found: `standard` (default, exact) or `closed_form` (the
    /// curve fits chosen by `closed_form`). The film formulas are closed forms either way.
    #[serde(default)]
    pub fidelity: FidelityRequest,
    /// With `fidelity: closed_form`: `hamrock_dowson` (default; k = 1.0339 α_r^0.636, the
    /// k of Khonsari eq. 15.19 and of Hamrock's ball-bearing example) or `hamrock_brewe`
    /// (k = α_r^(2/π), Hamrock eq. 21.53).
    pub closed_form: Option<ClosedFormFit>,
    #[serde(default)]
    pub effects: EhlEffects,
}

/// The validated case.
#[derive(Debug, Clone)]
pub struct EhlCase {
    hertz: HertzCase,
    load_n: f64,
    /// Line contacts: the length L, m.
    line_length_m: Option<f64>,
    speed_m_s: f64,
    lubricant: Lubricant,
    pressure_law: PressureLaw,
    temperature_c: f64,
    composite_roughness_m: Option<f64>,
    slide_roll_ratio: f64,
    meniscus_m: Option<f64>,
    effects: EhlEffects,
}

impl Validate for EhlFilmInput {
    type Valid = EhlCase;
    fn validate(self) -> Result<EhlCase, Vec<FieldError>> {
        let mut errors = Vec::new();
        let hertz = HertzInput {
            body1: self.body1,
            body2: self.body2,
            load_n: self.load_n,
            line: self.line,
            fidelity: self.fidelity,
            closed_form: self.closed_form,
        }
        .validate()
        .map_err(|mut e| errors.append(&mut e))
        .ok();
        let speed = entrainment_speed(self.entrainment_speed_m_s, &mut errors);
        let lubricant = self
            .lubricant
            .parse("/lubricant")
            .map_err(|mut e| errors.append(&mut e))
            .ok();
        let pressure_law = lubricant.as_ref().and_then(|l| l.pressure_law);
        if lubricant.is_some() && pressure_law.is_none() {
            errors.push(FieldError::new(
                "/lubricant",
                "an EHL film needs a pressure–viscosity law: give pressure_viscosity_coefficient_1_pa (Barus α) or roelands_pressure_viscosity_index (Z)",
            ));
        }
        let composite_roughness_m = self
            .roughness
            .and_then(|r| composite_roughness(r, &mut errors));
        let slide_roll_ratio = slide_roll_ratio(self.slide_roll_ratio, &mut errors);
        let meniscus_m = self.inlet_meniscus_distance_m.map(Positive::get);
        if self.effects.starvation == Mode::On && meniscus_m.is_none() {
            errors.push(FieldError::new(
                "/effects/starvation",
                "starvation needs inlet_meniscus_distance_m (the distance from the contact centre to the inlet meniscus)",
            ));
        }
        if self.effects.starvation == Mode::On && self.line.is_some() {
            errors.push(FieldError::new(
                "/effects/starvation",
                "the meniscus starvation formulas here are for point contacts (Hamrock & Dowson 1977); none is implemented for a line contact",
            ));
        }
        if self.effects.mixed_lubrication == Mode::On {
            errors.push(FieldError::new(
                "/effects/mixed_lubrication",
                "no mixed-EHL film model is implemented (the texts give none: Khonsari FE-9); use auto, which reports Λ and the lubrication regime",
            ));
        }
        match (errors.is_empty(), hertz, lubricant, pressure_law) {
            (true, Some(hertz), Some(lubricant), Some(pressure_law)) => Ok(EhlCase {
                hertz,
                load_n: self.load_n.get(),
                line_length_m: self.line.map(|l| l.length_m.get()),
                speed_m_s: speed,
                lubricant,
                pressure_law,
                temperature_c: self.temperature_c.get(),
                composite_roughness_m,
                slide_roll_ratio,
                meniscus_m,
                effects: self.effects,
            }),
            _ => Err(errors),
        }
    }
}

/// The mean entrainment speed ū, checked against [`MAX_SPEED_M_S`] (shared with the numerical
/// EHL room).
pub(super) fn entrainment_speed(speed: Positive, errors: &mut Vec<FieldError>) -> f64 {
    let speed = speed.get();
    if speed > MAX_SPEED_M_S {
        errors.push(FieldError::new(
            "/entrainment_speed_m_s",
            format!("must be at most {MAX_SPEED_M_S} m/s, got {speed}"),
        ));
    }
    speed
}

/// The slide-to-roll ratio (default 0, pure rolling), checked against [`MAX_SLIDE_ROLL`].
pub(super) fn slide_roll_ratio(ratio: Option<NonNegative>, errors: &mut Vec<FieldError>) -> f64 {
    let ratio = ratio.map_or(0.0, NonNegative::get);
    if ratio > MAX_SLIDE_ROLL {
        errors.push(FieldError::new(
            "/slide_roll_ratio",
            format!("must be within [0, {MAX_SLIDE_ROLL}] (2 is pure sliding), got {ratio}"),
        ));
    }
    ratio
}

/// η₀ at the inlet temperature, or a 422 where the lubricant's law has no value there.
pub(super) fn inlet_viscosity(lubricant: &Lubricant, t: f64) -> Result<f64, CalcError> {
    let eta0 = lubricant.viscosity_pa_s(t);
    if eta0.is_finite() && eta0 > 0.0 {
        Ok(eta0)
    } else {
        Err(CalcError::impossible(
            "/temperature_c",
            format!("the lubricant's viscosity law has no finite positive value at {t} °C"),
        ))
    }
}

/// √(σ₁² + σ₂²), or the composite given; pushes an error and returns None when the
/// description is incomplete, ambiguous or zero.
fn composite_roughness(r: RoughnessSpec, errors: &mut Vec<FieldError>) -> Option<f64> {
    let get = |v: Option<NonNegative>| v.map(NonNegative::get);
    for (name, v) in [
        ("body1_rms_m", get(r.body1_rms_m)),
        ("body2_rms_m", get(r.body2_rms_m)),
    ] {
        if v.is_some_and(|v| v > MAX_ROUGHNESS_M) {
            errors.push(FieldError::new(
                format!("/roughness/{name}"),
                format!("must be at most {MAX_ROUGHNESS_M} m"),
            ));
            return None;
        }
    }
    match (get(r.body1_rms_m), get(r.body2_rms_m), r.composite_rms_m) {
        (None, None, Some(c)) if c.get() <= 1.5 * MAX_ROUGHNESS_M => Some(c.get()),
        (None, None, Some(_)) => {
            errors.push(FieldError::new(
                "/roughness/composite_rms_m",
                format!("must be at most {} m", 1.5 * MAX_ROUGHNESS_M),
            ));
            None
        }
        (Some(s1), Some(s2), None) if s1 > 0.0 || s2 > 0.0 => Some(s1.hypot(s2)),
        (Some(_), Some(_), None) => {
            errors.push(FieldError::new(
                "/roughness/body1_rms_m",
                "both surfaces perfectly smooth: Λ is infinite; omit roughness",
            ));
            None
        }
        (b1, _, None) => {
            let missing = if b1.is_none() { "body1" } else { "body2" };
            errors.push(FieldError::new(
                format!("/roughness/{missing}_rms_m"),
                "give both bodies' RMS roughness (0 for a smooth one), or composite_rms_m alone",
            ));
            None
        }
        (_, _, Some(_)) => {
            errors.push(FieldError::new(
                "/roughness/composite_rms_m",
                "give either composite_rms_m or the two bodies' roughness, not both",
            ));
            None
        }
    }
}

/// Fluid-film lubrication regime of the Hamrock–Dowson map.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, ToSchema)]
#[serde(rename_all = "kebab-case")]
pub enum Regime {
    IsoviscousRigid,
    PiezoviscousRigid,
    IsoviscousElastic,
    PiezoviscousElastic,
}

impl Regime {
    /// The regime from whether elastic deformation and piezoviscosity each count. See
    /// [`point_regime`].
    fn of(elastic: bool, piezoviscous: bool) -> Self {
        match (piezoviscous, elastic) {
            (false, false) => Regime::IsoviscousRigid,
            (true, false) => Regime::PiezoviscousRigid,
            (false, true) => Regime::IsoviscousElastic,
            (true, true) => Regime::PiezoviscousElastic,
        }
    }

    fn name(self) -> &'static str {
        match self {
            Regime::IsoviscousRigid => "isoviscous-rigid",
            Regime::PiezoviscousRigid => "piezoviscous-rigid",
            Regime::IsoviscousElastic => "isoviscous-elastic",
            Regime::PiezoviscousElastic => "piezoviscous-elastic",
        }
    }
}

/// Whether the asperities touch, from Λ.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, ToSchema)]
#[serde(rename_all = "kebab-case")]
pub enum LubricationRegime {
    /// Λ > 3: full separation, no life reduction (Hamrock §21.3.6; Khonsari FE-7).
    FullFilm,
    /// 1 ≤ Λ ≤ 3: mixed, asperities share the load (surface distress, glazing: Stachowiak §7.5).
    Mixed,
    /// Λ < 1: boundary lubrication, smearing and wear (Stachowiak §7.5; Khonsari FE-7).
    Boundary,
}

impl LubricationRegime {
    fn of(lambda: f64) -> Self {
        if lambda > FULL_FILM_LAMBDA {
            LubricationRegime::FullFilm
        } else if lambda >= BOUNDARY_LAMBDA {
            LubricationRegime::Mixed
        } else {
            LubricationRegime::Boundary
        }
    }
}

/// One formula's films, isothermal and fully flooded.
#[derive(Debug, Clone, PartialEq, Serialize, ToSchema)]
pub struct FormulaFilm {
    /// Central film thickness h_c, m; absent when the formula gives only the minimum.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = 6.9e-7)]
    pub central_film_thickness_m: Option<f64>,
    /// Minimum film thickness h_min, m; absent when the formula gives only the central film.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = 5.6e-7)]
    pub min_film_thickness_m: Option<f64>,
    /// The formula and where it is printed.
    pub source: String,
}

impl FormulaFilm {
    fn new(central: Option<f64>, min: Option<f64>, source: &str) -> Self {
        FormulaFilm {
            central_film_thickness_m: central,
            min_film_thickness_m: min,
            source: source.to_owned(),
        }
    }
}

/// Every film formula that applies to the contact's shape, evaluated so they can be compared
/// (isothermal, fully flooded, smooth; each valid only in its own regime and fitted range).
#[derive(Debug, Clone, Default, Serialize, ToSchema)]
pub struct FilmFormulas {
    /// Point: Hamrock–Dowson hard EHL (piezoviscous–elastic).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub hamrock_dowson_hard: Option<FormulaFilm>,
    /// Point: Hamrock–Dowson soft EHL (isoviscous–elastic, elastomers).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub hamrock_dowson_soft: Option<FormulaFilm>,
    /// Point: the four regime formulas in the reduced groups.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub isoviscous_rigid: Option<FormulaFilm>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub piezoviscous_rigid: Option<FormulaFilm>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub isoviscous_elastic: Option<FormulaFilm>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub piezoviscous_elastic: Option<FormulaFilm>,
    /// Line: Pan & Hamrock (1989), hard EHL.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pan_hamrock: Option<FormulaFilm>,
    /// Line: Dowson–Higginson minimum film.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dowson_higginson: Option<FormulaFilm>,
    /// Line: the point-contact Hamrock–Dowson formulas with k → ∞ and W = F/(E′R_x²), the
    /// texts' own usage for rollers and cams.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub hamrock_dowson_line_limit: Option<FormulaFilm>,
    /// Line: Moes (1992) central film, all four regimes in one formula.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub moes: Option<FormulaFilm>,
}

/// Result.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct EhlFilmOutput {
    /// `point` (circular or elliptical) or `line`.
    #[schema(example = "point")]
    pub contact: String,
    /// Central film thickness h_c, m, from the formula named in `film_formula`, times the
    /// inlet-heating and starvation factors when those effects apply.
    #[schema(example = 6.9e-7)]
    pub central_film_thickness_m: f64,
    /// Minimum film thickness h_min, m (same formula and factors).
    #[schema(example = 5.6e-7)]
    pub min_film_thickness_m: f64,
    /// Which entry of `formulas` gave the two films: the one for the regime (point:
    /// `hamrock_dowson_hard` when piezoviscous–elastic, `hamrock_dowson_soft` when
    /// isoviscous–elastic, the regime formula when rigid; line: `pan_hamrock` when
    /// piezoviscous–elastic, else `moes`, whose central film then stands for both).
    #[schema(example = "hamrock_dowson_hard")]
    pub film_formula: String,
    /// Fluid-film regime: `isoviscous-rigid`, `piezoviscous-rigid`, `isoviscous-elastic` or
    /// `piezoviscous-elastic`. Elastic when Ĥ_ie > Ĥ_ir; then piezoviscous when Ĥ_pve > Ĥ_ie,
    /// or for a rigid contact when Ĥ_pvr > Ĥ_ir (boundaries where adjacent regime formulas are
    /// equal; for a line contact the same rule on Moes' asymptotes).
    pub regime: Regime,
    /// Speed parameter U = η₀ū/(E′R_x), dimensionless (ū the mean entrainment speed).
    #[schema(example = 2.227e-10)]
    pub speed_parameter: f64,
    /// Materials parameter G = αE′, dimensionless.
    #[schema(example = 5055.0)]
    pub materials_parameter: f64,
    /// Load parameter W = F/(E′R_x²), dimensionless (also for a line contact, as the texts use
    /// it in the k → ∞ limit).
    #[schema(example = 7.863e-4)]
    pub load_parameter: f64,
    /// Line contacts: load per unit length W′ = F/(L E′ R_x), dimensionless (Pan–Hamrock,
    /// Dowson–Higginson, Moes).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = 3.2e-5)]
    pub line_load_parameter: Option<f64>,
    /// Point contacts: ellipticity k = D_y/D_x (across over along the rolling direction),
    /// dimensionless; < 1 when the contact is longer along the rolling direction.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = 9.42)]
    pub ellipticity: Option<f64>,
    /// Point contacts: α_r = R_y/R_x, dimensionless (the isoviscous–rigid formula's radius ratio).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = 32.3)]
    pub radius_ratio: Option<f64>,
    /// Point contacts: reduced viscosity parameter g_v = GW³/U², dimensionless.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub viscosity_parameter: Option<f64>,
    /// Point contacts: reduced elasticity parameter g_e = W^(8/3)/U², dimensionless.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub elasticity_parameter: Option<f64>,
    /// Line contacts: Moes' load parameter M = W′(2U)^(−1/2), dimensionless.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub moes_load_parameter: Option<f64>,
    /// Line contacts: Moes' material parameter L = G(2U)^(1/4), dimensionless.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub moes_material_parameter: Option<f64>,
    /// Reduced radius along the rolling direction R_x, m.
    #[schema(example = 0.00511)]
    pub reduced_radius_x_m: f64,
    /// Reduced radius across it R_y, m; point contacts.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = 0.165)]
    pub reduced_radius_y_m: Option<f64>,
    /// E′ = 2/[(1 − ν₁²)/E₁ + (1 − ν₂²)/E₂], Pa (Hamrock's E′; Johnson's E* is E′/2).
    #[schema(example = 2.198e11)]
    pub effective_modulus_pa: f64,
    /// Maximum Hertz pressure of the dry contact, Pa.
    #[schema(example = 2.0e9)]
    pub max_hertz_pressure_pa: f64,
    /// η₀ at `temperature_c` and atmospheric pressure, Pa·s.
    #[schema(example = 0.04)]
    pub viscosity_pa_s: f64,
    /// Pressure–viscosity coefficient α, 1/Pa (Barus α, or from Roelands' Z).
    #[schema(example = 2.3e-8)]
    pub pressure_viscosity_coefficient_1_pa: f64,
    /// The inlet-heating factor φ_T applied to both films (1 when not applied).
    #[schema(example = 1.0)]
    pub thermal_reduction_factor: f64,
    /// The starvation factors applied to the central and the minimum film (1 when not applied).
    #[schema(example = 1.0)]
    pub starvation_factor_central: f64,
    /// The starvation factor applied to the minimum film (1 when not applied).
    #[schema(example = 1.0)]
    pub starvation_factor_min: f64,
    /// Composite RMS roughness √(σ₁² + σ₂²), m; with `roughness`.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = 1.86e-7)]
    pub composite_roughness_m: Option<f64>,
    /// Film parameter Λ = h_min/√(σ₁² + σ₂²), dimensionless; with `roughness`.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = 3.0)]
    pub film_parameter_lambda: Option<f64>,
    /// `full-film` (Λ > 3), `mixed` (1 ≤ Λ ≤ 3) or `boundary` (Λ < 1); with `roughness`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lubrication_regime: Option<LubricationRegime>,
    /// Every applicable formula, isothermal and flooded, for comparison.
    pub formulas: FilmFormulas,
}

impl Calculation for EhlFilm {
    const PATH: &'static str = "/v1/contacts/ehl-film";
    const SUMMARY: &'static str = "EHL film thickness (Hamrock–Dowson, soft EHL, regimes, line-contact fits), film parameter Λ, inlet heating and starvation";
    const DESCRIPTION: &'static str = "Closed-form elastohydrodynamic film thickness of two lubricated bodies (the Hertz room's body objects: signed principal radii, \
E and ν). Conventions: x is the entrainment (rolling) direction; R_x = (1/r₁ₓ + 1/r₂ₓ)⁻¹ along it (Hamrock's R_x and Stachowiak's Hamrock–Dowson R′ — not \
Stachowiak's Hertz R′ = (1/R_x + 1/R_y)⁻¹); E′ = 2/[(1 − ν₁²)/E₁ + (1 − ν₂²)/E₂] (1/E′ = ½Σ(1 − ν²)/E, Hamrock, Stachowiak ch. 7, Khonsari; twice Johnson's E*); \
ū = (u₁ + u₂)/2 is the MEAN entrainment speed; k = D_y/D_x from the exact Hertz ellipticity (`standard`) or its fits (`closed_form`). \
Groups (Hamrock eqs 21.52–21.56): U = η₀ū/(E′R_x), G = αE′, W = F/(E′R_x²), H = h/R_x; α from Barus or from Roelands' Z as α = Z·5.1e-9(ln η₀ + 9.67). \
Point contact: hard EHL H_min = 3.63 U^0.68 G^0.49 W^−0.073 (1 − e^−0.68k) (Hamrock eq. 21.57, Stachowiak eq. 7.27, Khonsari eq. 15.14), \
H_c = 2.69 U^0.67 G^0.53 W^−0.067 (1 − 0.61e^−0.73k) (Stachowiak eq. 7.26); soft EHL H_min = 7.43 U^0.65 W^−0.21 (1 − 0.85e^−0.31k) (Hamrock eq. 21.58). \
Regimes in Ĥ = H(W/U)², g_v = GW³/U², g_e = W^(8/3)/U² (Hamrock eqs 21.59–21.67, Stachowiak §7.4): isoviscous–rigid, piezoviscous–rigid, \
isoviscous–elastic, piezoviscous–elastic; the texts draw the map without a numeric rule, so here a contact is elastic when Ĥ_ie > Ĥ_ir, and then piezoviscous \
when Ĥ_pve > Ĥ_ie, or for a rigid one when Ĥ_pvr > Ĥ_ir (boundaries where adjacent regime formulas are equal). Line contact (`line`): Pan–Hamrock (1989) H_min = 1.714 W′^−0.128 U^0.694 G^0.568, H_c = 2.922 W′^−0.166 U^0.692 G^0.470 (primary \
paper, verify); Dowson–Higginson H_min = 2.65 G^0.54 U^0.7 W′^−0.13 (Khonsari eq. 15.10); the texts' k → ∞ limit of the point formulas with W = F/(E′R_x²) \
(Hamrock's roller example, Stachowiak Problems 7.4, 7.13, 7.15); Moes (1992) central film over all regimes (primary paper, verify); W′ = F/(L E′ R_x). \
Film parameter Λ = h_min/√(σ₁² + σ₂²): full film Λ > 3, mixed 1–3, boundary < 1 (Hamrock §21.3.6, Khonsari §15.6, Stachowiak §7.5). \
Effects: inlet shear heating by the Gupta et al. (1992) factor with L = (−∂η/∂T)ū²/k_f (verify), starvation from the inlet meniscus distance \
(Hamrock & Dowson 1977, verify), mixed lubrication judged from Λ. Warnings outside the fitted ranges (hard k 1–8, soft k 1–12, U and W decades).";
    const FIDELITY: &'static [Level] = &[Level::ClosedForm, Level::Standard];
    const EFFECTS: &'static [&'static str] = &["thermal", "starvation", "mixed_lubrication"];
    const EXAMPLE: &'static str = r#"{"body1": {"radius_x_m": 0.00635, "radius_y_m": 0.00635, "elastic_modulus_pa": 2e11, "poisson_ratio": 0.3}, "body2": {"radius_x_m": 0.0261455, "radius_y_m": -0.006604, "elastic_modulus_pa": 2e11, "poisson_ratio": 0.3}, "load_n": 4513, "entrainment_speed_m_s": 6.252, "lubricant": {"viscosity_pa_s": 0.04, "pressure_viscosity_coefficient_1_pa": 2.3e-8}, "temperature_c": 40, "roughness": {"body1_rms_m": 6.25e-8, "body2_rms_m": 1.75e-7}}"#;

    type Input = EhlFilmInput;
    type Output = EhlFilmOutput;

    fn run(case: EhlCase, ctx: &mut Context) -> Result<EhlFilmOutput, CalcError> {
        let hertz = Hertz::run(case.hertz, ctx)?;
        // The dry contact's approach is not part of a film calculation.
        ctx.warnings
            .retain(|w| w.code != "approach_undefined_for_flat");
        let eta0 = inlet_viscosity(&case.lubricant, case.temperature_c)?;
        let alpha = case.pressure_law.alpha_1_pa(eta0);
        if !(alpha.is_finite() && alpha > 0.0) {
            return Err(CalcError::impossible(
                "/lubricant",
                format!("Roelands' α = Z·5.1e-9(ln η₀ + 9.67) is not positive at η₀ = {eta0:.4e} Pa·s (needs η₀ > 6.3e-5 Pa·s); give the Barus coefficient for so thin a fluid"),
            ));
        }
        let e = hertz.effective_modulus_pa;
        let rx = hertz.reduced_radius_x_m;
        let groups = Groups {
            u: eta0 * case.speed_m_s / (e * rx),
            g: alpha * e,
            w: case.load_n / (e * rx * rx),
        };
        let films = match case.line_length_m {
            None => point_films(&groups, &hertz, ctx),
            Some(length_m) => line_films(&groups, length_m, rx, ctx),
        };
        let mut central = films.central_h * rx;
        let mut min = films.min_h * rx;
        let thermal = thermal_factor(&case, &hertz, eta0, ctx)?;
        let (starve_c, starve_min) = starvation_factors(&case, &hertz, &films, ctx)?;
        central *= thermal * starve_c;
        min *= thermal * starve_min;
        if thermal == 1.0
            && central > INLET_HEATING_FILM_M
            && case.speed_m_s > INLET_HEATING_SPEED_M_S
        {
            ctx.warn(
                "inlet_heating_likely",
                format!("h_c = {central:.3e} m above 1 µm at ū = {} m/s above 10 m/s: the isothermal fits overestimate the film here (Stachowiak §7.4); consider effects.thermal on", case.speed_m_s),
            );
        }
        let lambda = case.composite_roughness_m.map(|s| min / s);
        mixed_lubrication(&case, lambda, ctx);
        Ok(EhlFilmOutput {
            contact: hertz.contact.clone(),
            central_film_thickness_m: central,
            min_film_thickness_m: min,
            film_formula: films.formula.to_owned(),
            regime: films.regime,
            speed_parameter: groups.u,
            materials_parameter: groups.g,
            load_parameter: groups.w,
            line_load_parameter: films.line_load,
            ellipticity: films.ellipticity,
            radius_ratio: films.radius_ratio,
            viscosity_parameter: films.reduced.map(|r| r.0),
            elasticity_parameter: films.reduced.map(|r| r.1),
            moes_load_parameter: films.moes.map(|m| m.0),
            moes_material_parameter: films.moes.map(|m| m.1),
            reduced_radius_x_m: rx,
            reduced_radius_y_m: hertz.reduced_radius_y_m,
            effective_modulus_pa: e,
            max_hertz_pressure_pa: hertz.max_pressure_pa,
            viscosity_pa_s: eta0,
            pressure_viscosity_coefficient_1_pa: alpha,
            thermal_reduction_factor: thermal,
            starvation_factor_central: starve_c,
            starvation_factor_min: starve_min,
            composite_roughness_m: case.composite_roughness_m,
            film_parameter_lambda: lambda,
            lubrication_regime: lambda.map(LubricationRegime::of),
            formulas: films.formulas,
        })
    }
}

/// The Hamrock–Dowson dimensionless groups U, G, W (all positive and finite for valid input).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Groups {
    pub u: f64,
    pub g: f64,
    pub w: f64,
}

impl Groups {
    /// Reduced viscosity parameter g_v = GW³/U² (Hamrock eq. 21.60).
    pub fn viscosity_parameter(&self) -> f64 {
        self.g * self.w.powi(3) / (self.u * self.u)
    }

    /// Reduced elasticity parameter g_e = W^(8/3)/U² (Hamrock eq. 21.61).
    pub fn elasticity_parameter(&self) -> f64 {
        self.w.powf(8.0 / 3.0) / (self.u * self.u)
    }

    /// H from a reduced film Ĥ = H(W/U)² (Hamrock eq. 21.59).
    pub fn film_from_reduced(&self, reduced: f64) -> f64 {
        reduced * (self.u / self.w).powi(2)
    }
}

/// Hamrock–Dowson hard-EHL minimum film H_min = h_min/R_x (Hamrock eq. 21.57).
pub fn hard_min_film(g: &Groups, k: f64) -> f64 {
    3.63 * g.u.powf(0.68) * g.g.powf(0.49) * g.w.powf(-0.073) * (1.0 - (-0.68 * k).exp())
}

/// Hamrock–Dowson hard-EHL central film H_c = h_c/R_x (Stachowiak eq. 7.26).
pub fn hard_central_film(g: &Groups, k: f64) -> f64 {
    2.69 * g.u.powf(0.67) * g.g.powf(0.53) * g.w.powf(-0.067) * (1.0 - 0.61 * (-0.73 * k).exp())
}

/// Hamrock–Dowson soft-EHL minimum film (Hamrock eq. 21.58; no G: negligible piezoviscosity).
pub fn soft_min_film(g: &Groups, k: f64) -> f64 {
    7.43 * g.u.powf(0.65) * g.w.powf(-0.21) * (1.0 - 0.85 * (-0.31 * k).exp())
}

/// The reduced films Ĥ of the four regimes of an elliptical contact (Hamrock eqs 21.62–21.67;
/// the central films of the elastic regimes from Stachowiak §7.4).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RegimeFilms {
    /// Isoviscous–rigid Ĥ (minimum = central).
    pub isoviscous_rigid: f64,
    /// Piezoviscous–rigid Ĥ (minimum = central).
    pub piezoviscous_rigid: f64,
    /// Isoviscous–elastic Ĥ_min and Ĥ_c.
    pub isoviscous_elastic: (f64, f64),
    /// Piezoviscous–elastic Ĥ_min and Ĥ_c.
    pub piezoviscous_elastic: (f64, f64),
}

/// Ĥ of the four regimes for reduced groups g_v, g_e, ellipticity k and radius ratio
/// α_r = R_y/R_x: Ĥ_ir = 128 α_r λ_b² [0.131 atan(α_r/2) + 1.683]², λ_b = (1 + 2/(3α_r))⁻¹
/// (eqs 21.62–21.64, with the exact α_r as Stachowiak advises rather than α_r ≈ k^(π/2));
/// Ĥ_pvr = 1.66 g_v^⅔ (1 − e^−0.68k); Ĥ_ie = 8.70 g_e^0.67 (1 − 0.85e^−0.31k),
/// Ĥ_ie,c = 11.15 g_e^0.67 (1 − 0.72e^−0.28k); Ĥ_pve = 3.42 g_v^0.49 g_e^0.17 (1 − e^−0.68k),
/// Ĥ_pve,c = 3.61 g_v^0.53 g_e^0.13 (1 − 0.61e^−0.73k).
pub fn regime_films(gv: f64, ge: f64, k: f64, radius_ratio: f64) -> RegimeFilms {
    let lambda_b = 1.0 / (1.0 + 2.0 / (3.0 * radius_ratio));
    let bracket = 0.131 * (radius_ratio / 2.0).atan() + 1.683;
    RegimeFilms {
        isoviscous_rigid: 128.0 * radius_ratio * lambda_b * lambda_b * bracket * bracket,
        piezoviscous_rigid: 1.66 * gv.powf(2.0 / 3.0) * (1.0 - (-0.68 * k).exp()),
        isoviscous_elastic: (
            8.70 * ge.powf(0.67) * (1.0 - 0.85 * (-0.31 * k).exp()),
            11.15 * ge.powf(0.67) * (1.0 - 0.72 * (-0.28 * k).exp()),
        ),
        piezoviscous_elastic: (
            3.42 * gv.powf(0.49) * ge.powf(0.17) * (1.0 - (-0.68 * k).exp()),
            3.61 * gv.powf(0.53) * ge.powf(0.13) * (1.0 - 0.61 * (-0.73 * k).exp()),
        ),
    }
}

/// The regime of an elliptical contact. The texts draw the map (Hamrock Figs 21.72–21.74,
/// Stachowiak Fig. 7.20) but give no numeric rule (spec A.1.6, a gap), so this is a design
/// decision (verify against Hamrock & Dowson 1979): an effect counts when including it raises
/// the film, judged between adjacent regimes. Elastic when Ĥ_ie > Ĥ_ir (the IR–IE boundary where
/// those formulas are equal); then piezoviscous when Ĥ_pve > Ĥ_ie (IE–PE boundary), or, for a
/// rigid contact, when Ĥ_pvr > Ĥ_ir (IR–PR boundary). Comparing Ĥ_pvr with Ĥ_pve directly
/// would call a heavily loaded ball bearing (Hamrock's own example, g_v ≈ 5 × 10¹³)
/// piezoviscous–rigid, because Ĥ_pvr grows as W² without bound; this rule gives
/// piezoviscous–elastic for it and for the Hamrock–Dowson base case (spec A-R5).
pub fn point_regime(films: &RegimeFilms) -> Regime {
    let elastic = films.isoviscous_elastic.0 > films.isoviscous_rigid;
    let piezoviscous = if elastic {
        films.piezoviscous_elastic.0 > films.isoviscous_elastic.0
    } else {
        films.piezoviscous_rigid > films.isoviscous_rigid
    };
    Regime::of(elastic, piezoviscous)
}

/// Pan & Hamrock (1989), line contact, H_min = 1.714 W′^−0.128 U^0.694 G^0.568 and
/// H_c = 2.922 W′^−0.166 U^0.692 G^0.470 (J. Tribol. 111:246; not in the texts: verify).
pub fn pan_hamrock(g: &Groups, line_load: f64) -> (f64, f64) {
    (
        2.922 * line_load.powf(-0.166) * g.u.powf(0.692) * g.g.powf(0.470),
        1.714 * line_load.powf(-0.128) * g.u.powf(0.694) * g.g.powf(0.568),
    )
}

/// Dowson–Higginson line-contact minimum film H_min = 2.65 G^0.54 U^0.7 W′^−0.13
/// (Khonsari & Booser eq. 15.10).
pub fn dowson_higginson(g: &Groups, line_load: f64) -> f64 {
    2.65 * g.g.powf(0.54) * g.u.powf(0.7) * line_load.powf(-0.13)
}

/// Moes' line-contact asymptotes in M = W′(2U)^(−1/2), L = G(2U)^(1/4) (the factor 2: Moes
/// uses the sum speed), film H_M = H (2U)^(−1/2): rigid–isoviscous 3M⁻¹, elastic–isoviscous
/// 2.621 M^(−1/5), rigid–piezoviscous 1.287 L^(2/3), elastic–piezoviscous 1.311 M^(−1/8) L^(3/4)
/// (Moes 1992; Venner & Lubrecht 2000 §8; not in the texts: verify).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MoesAsymptotes {
    pub rigid_isoviscous: f64,
    pub elastic_isoviscous: f64,
    pub rigid_piezoviscous: f64,
    pub elastic_piezoviscous: f64,
}

impl MoesAsymptotes {
    pub fn new(m: f64, l: f64) -> Self {
        MoesAsymptotes {
            rigid_isoviscous: 3.0 / m,
            elastic_isoviscous: 2.621 * m.powf(-0.2),
            rigid_piezoviscous: 1.287 * l.powf(2.0 / 3.0),
            elastic_piezoviscous: 1.311 * m.powf(-0.125) * l.powf(0.75),
        }
    }

    /// Moes' central film H_M = {[H_RI^(7/3) + H_EI^(7/3)]^(3s/7) +
    /// [H_RP^(−7/2) + H_EP^(−7/2)]^(−2s/7)}^(1/s), s = 1.5 [1 + exp(−1.2 H_EI/H_RI)].
    pub fn central(&self) -> f64 {
        let s = 1.5 * (1.0 + (-1.2 * self.elastic_isoviscous / self.rigid_isoviscous).exp());
        let iso = (self.rigid_isoviscous.powf(7.0 / 3.0) + self.elastic_isoviscous.powf(7.0 / 3.0))
            .powf(3.0 * s / 7.0);
        let piezo = (self.rigid_piezoviscous.powf(-3.5) + self.elastic_piezoviscous.powf(-3.5))
            .powf(-2.0 * s / 7.0);
        (iso + piezo).powf(1.0 / s)
    }

    /// The same rule as [`point_regime`], on the asymptotes.
    pub fn regime(&self) -> Regime {
        let elastic = self.elastic_isoviscous > self.rigid_isoviscous;
        let piezoviscous = if elastic {
            self.elastic_piezoviscous > self.elastic_isoviscous
        } else {
            self.rigid_piezoviscous > self.rigid_isoviscous
        };
        Regime::of(elastic, piezoviscous)
    }
}

/// What the shape-specific part hands back: dimensionless films (H = h/R_x) before effects.
struct Films {
    central_h: f64,
    min_h: f64,
    formula: &'static str,
    regime: Regime,
    ellipticity: Option<f64>,
    radius_ratio: Option<f64>,
    /// (g_v, g_e)
    reduced: Option<(f64, f64)>,
    /// (M, L)
    moes: Option<(f64, f64)>,
    line_load: Option<f64>,
    formulas: FilmFormulas,
}

/// Ellipticity k = D_y/D_x of the Hertz contact: κ when the major axis lies across the
/// rolling direction (or a circle), 1/κ when along it.
fn rolling_ellipticity(hertz: &HertzOutput) -> f64 {
    let kappa = hertz.ellipticity.unwrap_or(1.0);
    if hertz.major_axis_along == "x" {
        1.0 / kappa
    } else {
        kappa
    }
}

fn point_films(g: &Groups, hertz: &HertzOutput, ctx: &mut Context) -> Films {
    let rx = hertz.reduced_radius_x_m;
    let k = rolling_ellipticity(hertz);
    let radius_ratio = hertz.reduced_radius_y_m.map_or(1.0, |ry| ry / rx);
    let (gv, ge) = (g.viscosity_parameter(), g.elasticity_parameter());
    let r = regime_films(gv, ge, k, radius_ratio);
    let regime = point_regime(&r);
    let h = |reduced: f64| g.film_from_reduced(reduced) * rx;
    let hard = (hard_central_film(g, k), hard_min_film(g, k));
    let soft_central = g.film_from_reduced(r.isoviscous_elastic.1);
    let soft = (soft_central, soft_min_film(g, k));
    let formulas = FilmFormulas {
        hamrock_dowson_hard: Some(FormulaFilm::new(
            Some(hard.0 * rx),
            Some(hard.1 * rx),
            "Hamrock–Dowson hard EHL: H_c = 2.69 U^0.67 G^0.53 W^−0.067 (1 − 0.61e^−0.73k) (Stachowiak eq. 7.26), H_min = 3.63 U^0.68 G^0.49 W^−0.073 (1 − e^−0.68k) (Hamrock eq. 21.57)",
        )),
        hamrock_dowson_soft: Some(FormulaFilm::new(
            Some(soft.0 * rx),
            Some(soft.1 * rx),
            "Hamrock–Dowson soft EHL: H_min = 7.43 U^0.65 W^−0.21 (1 − 0.85e^−0.31k) (Hamrock eq. 21.58); H_c from Ĥ_c = 11.15 g_e^0.67 (1 − 0.72e^−0.28k) (Stachowiak §7.4)",
        )),
        isoviscous_rigid: Some(FormulaFilm::new(
            Some(h(r.isoviscous_rigid)),
            Some(h(r.isoviscous_rigid)),
            "Ĥ = 128 α_r λ_b² [0.131 atan(α_r/2) + 1.683]², λ_b = (1 + 2/(3α_r))⁻¹ (Hamrock eqs 21.62–21.64)",
        )),
        piezoviscous_rigid: Some(FormulaFilm::new(
            Some(h(r.piezoviscous_rigid)),
            Some(h(r.piezoviscous_rigid)),
            "Ĥ = 1.66 g_v^(2/3) (1 − e^−0.68k) (Hamrock eq. 21.65)",
        )),
        isoviscous_elastic: Some(FormulaFilm::new(
            Some(h(r.isoviscous_elastic.1)),
            Some(h(r.isoviscous_elastic.0)),
            "Ĥ_min = 8.70 g_e^0.67 (1 − 0.85e^−0.31k) (Hamrock eq. 21.66), Ĥ_c = 11.15 g_e^0.67 (1 − 0.72e^−0.28k) (Stachowiak §7.4)",
        )),
        piezoviscous_elastic: Some(FormulaFilm::new(
            Some(h(r.piezoviscous_elastic.1)),
            Some(h(r.piezoviscous_elastic.0)),
            "Ĥ_min = 3.42 g_v^0.49 g_e^0.17 (1 − e^−0.68k) (Hamrock eq. 21.67), Ĥ_c = 3.61 g_v^0.53 g_e^0.13 (1 − 0.61e^−0.73k) (Stachowiak §7.4)",
        )),
        ..FilmFormulas::default()
    };
    let (formula, (central_h, min_h)) = match regime {
        Regime::PiezoviscousElastic => ("hamrock_dowson_hard", hard),
        Regime::IsoviscousElastic => ("hamrock_dowson_soft", soft),
        Regime::PiezoviscousRigid => {
            let f = g.film_from_reduced(r.piezoviscous_rigid);
            ("piezoviscous_rigid", (f, f))
        }
        Regime::IsoviscousRigid => {
            let f = g.film_from_reduced(r.isoviscous_rigid);
            ("isoviscous_rigid", (f, f))
        }
    };
    warn_outside_fit(g, k, regime, ctx);
    Films {
        central_h,
        min_h,
        formula,
        regime,
        ellipticity: Some(k),
        radius_ratio: Some(radius_ratio),
        reduced: Some((gv, ge)),
        moes: None,
        line_load: None,
        formulas,
    }
}

/// Range warnings for the point-contact fit in use.
fn warn_outside_fit(g: &Groups, k: f64, regime: Regime, ctx: &mut Context) {
    let mut out = Vec::new();
    let within = |(lo, hi): (f64, f64), x: f64| (lo..=hi).contains(&x);
    match regime {
        Regime::PiezoviscousElastic => {
            if !within(HARD_FIT_ELLIPTICITY, k) {
                out.push(format!("k = {k:.3} outside 1–8"));
            }
            if !within(HARD_FIT_SPEED, g.u) {
                out.push(format!(
                    "U = {:.3e} outside {:.3e}–{:.3e}",
                    g.u, HARD_FIT_SPEED.0, HARD_FIT_SPEED.1
                ));
            }
            if !within(HARD_FIT_LOAD, g.w) {
                out.push(format!(
                    "W = {:.3e} outside {:.3e}–{:.3e}",
                    g.w, HARD_FIT_LOAD.0, HARD_FIT_LOAD.1
                ));
            }
        }
        Regime::IsoviscousElastic if !within(SOFT_FIT_ELLIPTICITY, k) => {
            out.push(format!("k = {k:.3} outside 1–12"));
        }
        _ => {}
    }
    if !out.is_empty() {
        ctx.warn(
            "outside_fitted_range",
            format!(
                "the {} film formula is used outside the range it was fitted over ({}): the result is an extrapolation (Hamrock §21.3.3–21.3.4)",
                regime.name(),
                out.join("; ")
            ),
        );
    }
}

fn line_films(g: &Groups, length_m: f64, rx: f64, ctx: &mut Context) -> Films {
    // W′ = F/(L E′ R_x) = W R_x/L.
    let line_load = g.w * rx / length_m;
    let two_u = 2.0 * g.u;
    let (m, l) = (line_load / two_u.sqrt(), g.g * two_u.powf(0.25));
    let moes = MoesAsymptotes::new(m, l);
    let moes_central = moes.central() * two_u.sqrt();
    let regime = moes.regime();
    let (ph_central, ph_min) = pan_hamrock(g, line_load);
    // k → ∞: the ellipticity factors are 1.
    let limit = (
        hard_central_film(g, f64::INFINITY),
        hard_min_film(g, f64::INFINITY),
    );
    let formulas = FilmFormulas {
        pan_hamrock: Some(FormulaFilm::new(
            Some(ph_central * rx),
            Some(ph_min * rx),
            "Pan & Hamrock (1989) J. Tribol. 111:246: H_c = 2.922 W′^−0.166 U^0.692 G^0.470, H_min = 1.714 W′^−0.128 U^0.694 G^0.568 (verify)",
        )),
        dowson_higginson: Some(FormulaFilm::new(
            None,
            Some(dowson_higginson(g, line_load) * rx),
            "Dowson–Higginson: H_min = 2.65 G^0.54 U^0.7 W′^−0.13 (Khonsari & Booser eq. 15.10)",
        )),
        hamrock_dowson_line_limit: Some(FormulaFilm::new(
            Some(limit.0 * rx),
            Some(limit.1 * rx),
            "Hamrock–Dowson point formulas with k → ∞ and W = F/(E′R_x²) (Hamrock's roller example; Stachowiak Problems 7.4, 7.13, 7.15)",
        )),
        moes: Some(FormulaFilm::new(
            Some(moes_central * rx),
            None,
            "Moes (1992) central film over the four regimes, M = W′(2U)^−½, L = G(2U)^¼ (Venner & Lubrecht 2000; verify)",
        )),
        ..FilmFormulas::default()
    };
    let (formula, central_h, min_h) = if regime == Regime::PiezoviscousElastic {
        ("pan_hamrock", ph_central, ph_min)
    } else {
        ctx.warn(
            "line_minimum_film_not_resolved",
            format!("the contact is {}: the line-contact fits with a minimum film are piezoviscous–elastic fits, so Moes' central film stands for both films (exact for a rigid regime, an overestimate of h_min in the isoviscous–elastic one)", regime.name()),
        );
        ("moes", moes_central, moes_central)
    };
    Films {
        central_h,
        min_h,
        formula,
        regime,
        ellipticity: None,
        radius_ratio: None,
        reduced: None,
        moes: Some((m, l)),
        line_load: Some(line_load),
        formulas,
    }
}

/// Gupta et al. (1992) thermal reduction factor φ_T = [1 − 13.2 (p_h/E′) L^0.42] /
/// [1 + 0.213 (1 + 2.23 s^0.83) L^0.64] with L = (−∂η/∂T) ū²/k_f (Tribol. Trans. 35:269; the
/// texts name inlet heating without a formula: verify). Returns 1 when not applied.
fn thermal_factor(
    case: &EhlCase,
    hertz: &HertzOutput,
    eta0: f64,
    ctx: &mut Context,
) -> Result<f64, CalcError> {
    let mode = case.effects.thermal;
    let what = "inlet shear heating (Gupta et al. thermal reduction factor)";
    if mode == Mode::Off {
        ctx.decide(
            "thermal",
            Decision::not_applicable(mode, format!("{what}: requested off")),
        );
        return Ok(1.0);
    }
    let lub = &case.lubricant;
    if let TemperatureLaw::Constant { .. } = lub.temperature_law {
        if mode == Mode::On {
            return Err(CalcError::impossible(
                "/lubricant",
                "the inlet-heating effect needs a viscosity–temperature law; this lubricant has a constant viscosity",
            ));
        }
        ctx.decide(
            "thermal",
            Decision::not_applicable(
                mode,
                format!(
                    "{what}: the lubricant has a constant viscosity, so no temperature law to heat"
                ),
            ),
        );
        return Ok(1.0);
    }
    let t = case.temperature_c;
    let slope = (lub.viscosity_pa_s(t + 0.5) - lub.viscosity_pa_s(t - 0.5)).abs();
    let conductivity = lub.thermal_conductivity_w_m_k(t);
    let loading = slope * case.speed_m_s.powi(2) / conductivity;
    let s = case.slide_roll_ratio;
    let numerator =
        1.0 - 13.2 * (hertz.max_pressure_pa / hertz.effective_modulus_pa) * loading.powf(0.42);
    let phi = numerator / (1.0 + 0.213 * (1.0 + 2.23 * s.powf(0.83)) * loading.powf(0.64));
    if !(phi.is_finite() && phi > 0.0) {
        return Err(CalcError::impossible(
            "/entrainment_speed_m_s",
            format!("the thermal loading parameter L = (−∂η/∂T)ū²/k = {loading:.3e} (η₀ = {eta0:.3e} Pa·s) is beyond the Gupta correlation: it gives no positive film; set effects.thermal off for the isothermal film"),
        ));
    }
    let decision = Decision::decide(
        mode,
        Criterion {
            name: "thermal_film_reduction",
            value: 1.0 - phi,
            threshold: THERMAL_THRESHOLD,
        },
        what,
    );
    let applied = decision.applied;
    ctx.decide("thermal", decision);
    Ok(if applied { phi } else { 1.0 })
}

/// Hamrock & Dowson's (1977) fully-flooded inlet distance m̄*_c = 1 + 3.06 H^0.58 over the
/// semi-axis a along the rolling direction, for the central film in the units H = h R_x/a²
/// (see [`starvation_factors`]).
pub(crate) fn fully_flooded_meniscus(film: f64) -> f64 {
    1.0 + 3.06 * film.powf(0.58)
}

/// Hamrock & Dowson (1977, J. Lubr. Technol. 99:15, point contacts; not in the texts: verify):
/// with m̄ = m/b the meniscus distance over the Hertz semi-axis along the rolling direction,
/// the film is starved below m̄*_c = 1 + 3.06 [(R_x/b)² H_c]^0.58 and
/// m̄*_min = 1 + 3.34 [(R_x/b)² H_min]^0.56, to H_c [(m̄ − 1)/(m̄*_c − 1)]^0.29 and
/// H_min [(m̄ − 1)/(m̄*_min − 1)]^0.25. Returns (central, minimum) factors, 1 when not applied.
fn starvation_factors(
    case: &EhlCase,
    hertz: &HertzOutput,
    films: &Films,
    ctx: &mut Context,
) -> Result<(f64, f64), CalcError> {
    let mode = case.effects.starvation;
    let what = "starvation (Hamrock–Dowson inlet meniscus)";
    let Some(meniscus) = case.meniscus_m else {
        ctx.decide(
            "starvation",
            Decision::not_applicable(
                mode,
                format!(
                    "{what}: no inlet_meniscus_distance_m given; the film is taken fully flooded"
                ),
            ),
        );
        return Ok((1.0, 1.0));
    };
    let b = match (hertz.semi_minor_axis_m, hertz.semi_major_axis_m) {
        (Some(_), Some(major)) if hertz.major_axis_along == "x" => major,
        (Some(minor), _) => minor,
        _ => {
            ctx.decide(
                "starvation",
                Decision::not_applicable(mode, format!("{what}: the meniscus formulas are for point contacts; none is implemented for a line contact")),
            );
            return Ok((1.0, 1.0));
        }
    };
    if mode == Mode::Off {
        ctx.decide(
            "starvation",
            Decision::not_applicable(mode, format!("{what}: requested off")),
        );
        return Ok((1.0, 1.0));
    }
    let m_bar = meniscus / b;
    if m_bar <= 1.0 {
        return Err(CalcError::impossible(
            "/inlet_meniscus_distance_m",
            format!("the meniscus must lie upstream of the Hertz zone: {meniscus:.3e} m is within the semi-axis b = {b:.3e} m along x"),
        ));
    }
    let scale = (hertz.reduced_radius_x_m / b).powi(2);
    let critical_c = fully_flooded_meniscus(scale * films.central_h);
    let critical_min = 1.0 + 3.34 * (scale * films.min_h).powf(0.56);
    let decision = Decision::decide(
        mode,
        Criterion {
            name: "critical_to_actual_meniscus_ratio",
            value: critical_c.max(critical_min) / m_bar,
            threshold: 1.0,
        },
        what,
    );
    let applied = decision.applied;
    ctx.decide("starvation", decision);
    if !applied {
        return Ok((1.0, 1.0));
    }
    let factor = |critical: f64, exponent: f64| {
        if m_bar < critical {
            ((m_bar - 1.0) / (critical - 1.0)).powf(exponent)
        } else {
            1.0
        }
    };
    Ok((factor(critical_c, 0.29), factor(critical_min, 0.25)))
}

/// Report the mixed-lubrication effect from Λ; warn below Λ = 3 unless it is off.
fn mixed_lubrication(case: &EhlCase, lambda: Option<f64>, ctx: &mut Context) {
    let mode = case.effects.mixed_lubrication;
    let what = "mixed lubrication";
    let decision = match (mode, lambda) {
        (Mode::Off, _) => Decision::not_applicable(mode, format!("{what}: requested off")),
        (_, None) => Decision::not_applicable(
            mode,
            format!("{what}: no roughness given, so no film parameter Λ"),
        ),
        (_, Some(lambda)) => {
            let regime = LubricationRegime::of(lambda);
            if regime != LubricationRegime::FullFilm {
                ctx.warn(
                    "film_below_roughness",
                    format!("Λ = {lambda:.3} ≤ 3: the asperities touch ({} lubrication); the films are smooth-surface films and the surfaces share the load (Hamrock §21.3.6, Khonsari §15.6)", if regime == LubricationRegime::Mixed { "mixed" } else { "boundary" }),
                );
            }
            Decision {
                applied: false,
                mode,
                reason: format!("{what}: Λ = {lambda:.4} against full film above {FULL_FILM_LAMBDA}; reported, not modelled (no mixed-EHL film formula in the texts)"),
                criterion: Some(Criterion {
                    name: "film_parameter_lambda",
                    value: lambda,
                    threshold: FULL_FILM_LAMBDA,
                }),
                model: None,
            }
        }
    };
    ctx.decide("mixed_lubrication", decision);
}

#[cfg(test)]
mod tests {

    use proptest::prelude::*;
    use serde_json::{json, Value};

    use super::*;
    use crate::calc::Failure;

    fn post(request: &Value) -> Result<Value, Failure> {
        crate::calc::testing::post::<EhlFilm>(request)
    }

    fn ok(request: &Value) -> Value {
        crate::calc::testing::ok::<EhlFilm>(request)
    }

    fn get(v: &Value, pointer: &str) -> f64 {
        v.pointer(pointer)
            .and_then(Value::as_f64)
            .unwrap_or_else(|| panic!("{pointer} missing in {v}"))
    }

    fn pointers(request: &Value) -> Vec<String> {
        match post(request) {
            Err(Failure::Invalid(errors)) => errors.into_iter().map(|e| e.pointer).collect(),
            Err(Failure::Calc(CalcError::Impossible { pointer, .. })) => vec![pointer],
            other => panic!("{request}: expected a 422, got {other:?}"),
        }
    }

    fn assert_rel(got: f64, want: f64, tol: f64, what: &str) {
        assert!(
            ((got - want) / want).abs() <= tol,
            "{what}: got {got}, want {want} ± {tol}"
        );
    }

    fn steel(rx: Option<f64>, ry: Option<f64>) -> Value {
        let mut b = json!({"elastic_modulus_pa": 2.1e11, "poisson_ratio": 0.3});
        if let Some(r) = rx {
            b["radius_x_m"] = json!(r);
        }
        if let Some(r) = ry {
            b["radius_y_m"] = json!(r);
        }
        b
    }

    /// A 12.7 mm ball on a 6210-like inner raceway, mineral oil.
    fn bearing(load: f64, speed: f64, viscosity: f64) -> Value {
        json!({
            "body1": steel(Some(0.00635), Some(0.00635)),
            "body2": steel(Some(0.0261455), Some(-0.006604)),
            "load_n": load, "entrainment_speed_m_s": speed,
            "lubricant": {"viscosity_pa_s": viscosity, "pressure_viscosity_coefficient_1_pa": 2.2e-8},
            "temperature_c": 40.0
        })
    }

    fn roller(load: f64, speed: f64, viscosity: f64) -> Value {
        json!({
            "body1": steel(Some(0.008), None), "body2": steel(Some(0.032), None),
            "load_n": load, "entrainment_speed_m_s": speed, "line": {"length_m": 0.016},
            "lubricant": {"viscosity_pa_s": viscosity, "pressure_viscosity_coefficient_1_pa": 2.2e-8},
            "temperature_c": 40.0
        })
    }

    /// Every case under tests/data/contact for this room, through the same path as HTTP.
    #[test]
    fn reference_cases_match_their_sources() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/contact");
        let mut seen = 0;
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            let case: Value =
                serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
            if case["path"] != EhlFilm::PATH {
                continue;
            }
            seen += 1;
            let v = ok(&case["request"]);
            for want in case["expected"].as_array().unwrap() {
                let pointer = want["pointer"].as_str().unwrap();
                let tol = want["rel_tol"].as_f64().unwrap();
                let what = format!("{}: {pointer}", path.display());
                assert_rel(
                    get(&v, pointer),
                    want["value"].as_f64().unwrap(),
                    tol,
                    &what,
                );
            }
        }
        assert!(seen >= 7, "found {seen} EHL reference cases");
    }

    #[test]
    fn reduced_groups_invert_and_reproduce_the_hamrock_dowson_base_case() {
        // Spec A-R5: k = 1.25, U = 0.168e-11, W = 0.111e-6, G = 4522: H_min = 4.072e-6,
        // Ĥ = 1.777e4, g_v = 2.191e6, g_e = 1.008e5, Ĥ_pve = 1.776e4 (derived, verified).
        let g = Groups {
            u: 0.168e-11,
            g: 4522.0,
            w: 0.111e-6,
        };
        let h = hard_min_film(&g, 1.25);
        assert_rel(h, 4.072e-6, 1e-3, "H_min");
        assert_rel(h / g.film_from_reduced(1.0), 1.777e4, 1e-3, "Ĥ");
        assert_rel(g.viscosity_parameter(), 2.191e6, 1e-3, "g_v");
        assert_rel(g.elasticity_parameter(), 1.008e5, 1e-3, "g_e");
        let r = regime_films(
            g.viscosity_parameter(),
            g.elasticity_parameter(),
            1.25,
            1.25f64.powf(std::f64::consts::FRAC_PI_2),
        );
        assert_rel(r.piezoviscous_elastic.0, 1.776e4, 1e-3, "Ĥ_pve");
        assert_eq!(point_regime(&r), Regime::PiezoviscousElastic);
        // Hamrock eq. 21.59: Ĥ = H (W/U)² exactly inverts.
        let x = 3.7e-5;
        assert_rel(
            g.film_from_reduced(x * (g.w / g.u).powi(2)),
            x,
            1e-14,
            "inverse",
        );
    }

    #[test]
    fn isoviscous_rigid_film_matches_the_spec_values() {
        // Spec A.1.6: Ĥ_ir = 140.1 at α_r = 1 and 15 725 at α_r = 36.
        assert_rel(
            regime_films(1.0, 1.0, 1.0, 1.0).isoviscous_rigid,
            140.1,
            1e-3,
            "α_r 1",
        );
        assert_rel(
            regime_films(1.0, 1.0, 9.0, 36.0).isoviscous_rigid,
            15_725.0,
            1e-3,
            "α_r 36",
        );
    }

    #[test]
    fn regime_formulas_agree_with_the_direct_fits() {
        // Spec A.1.6: Ĥ_pve within 3.3 % of eq. 21.57 on the texts' examples (A-R3 inner and
        // outer, A-R5).
        for (u, gg, w, k) in [
            (2.227e-10, 5055.0, 7.863e-4, 9.42),
            (1.499e-10, 5055.0, 3.564e-4, 7.09),
            (0.168e-11, 4522.0, 0.111e-6, 1.25),
        ] {
            let g = Groups { u, g: gg, w };
            let r = regime_films(g.viscosity_parameter(), g.elasticity_parameter(), k, 10.0);
            let pve = g.film_from_reduced(r.piezoviscous_elastic.0);
            assert_rel(pve, hard_min_film(&g, k), 0.034, "Ĥ_pve vs 21.57");
        }
        // Ĥ_ie = 8.70 g_e^0.67 is 8.70 U^0.66 W^−0.213 against 21.58's 7.43 U^0.65 W^−0.21:
        // within 3 % over soft-EHL groups (U 1e-8 … 1e-7, W 1e-3 … 1e-2); the ratio drifts as U^0.01.
        for (u, w) in [(1e-8, 1e-3), (1e-8, 1e-2), (1e-7, 1e-3), (1e-7, 1e-2)] {
            let g = Groups { u, g: 1.0, w };
            let r = regime_films(g.viscosity_parameter(), g.elasticity_parameter(), 3.0, 5.6);
            let ie = g.film_from_reduced(r.isoviscous_elastic.0);
            assert_rel(ie, soft_min_film(&g, 3.0), 0.03, "Ĥ_ie vs 21.58");
        }
    }

    #[test]
    fn regimes_are_identified_on_constructed_cases() {
        let regime = |u: f64, gg: f64, w: f64, k: f64| {
            let g = Groups { u, g: gg, w };
            point_regime(&regime_films(
                g.viscosity_parameter(),
                g.elasticity_parameter(),
                k,
                k.powf(std::f64::consts::FRAC_PI_2),
            ))
        };
        // Heavily loaded steel ball bearing (A-R3): hard EHL.
        assert_eq!(
            regime(2.227e-10, 5055.0, 7.863e-4, 9.42),
            Regime::PiezoviscousElastic
        );
        // Elastomer (E′ ~ 1e7 Pa, α E′ ≈ 0.2): soft EHL.
        assert_eq!(regime(1e-6, 0.2, 1e-2, 1.0), Regime::IsoviscousElastic);
        // Lightly loaded, fast, stiff and thin oil: neither effect counts.
        assert_eq!(regime(1e-8, 100.0, 1e-9, 1.0), Regime::IsoviscousRigid);
        // Strongly piezoviscous, very light load on stiff bodies.
        assert_eq!(regime(1e-11, 5000.0, 4e-8, 1.0), Regime::PiezoviscousRigid);
        assert_eq!(regime(1e-11, 5000.0, 2e-8, 1.0), Regime::IsoviscousRigid);
    }

    #[test]
    fn moes_reduces_to_its_dominant_asymptote() {
        // Rigid–isoviscous (Martin): M → 0, L → 0.
        let a = MoesAsymptotes::new(1e-3, 1e-3);
        assert_rel(a.central(), a.rigid_isoviscous, 1e-3, "RI");
        assert_eq!(a.regime(), Regime::IsoviscousRigid);
        // Elastic–piezoviscous: M and L large.
        let a = MoesAsymptotes::new(1e4, 20.0);
        assert_rel(a.central(), a.elastic_piezoviscous, 0.02, "EP");
        assert_eq!(a.regime(), Regime::PiezoviscousElastic);
        // Elastic–isoviscous: M large, L → 0.
        let a = MoesAsymptotes::new(1e4, 1e-3);
        assert_rel(a.central(), a.elastic_isoviscous, 1e-3, "EI");
        assert_eq!(a.regime(), Regime::IsoviscousElastic);
    }

    #[test]
    fn line_contact_fits_agree_in_the_hard_regime() {
        // A-R2 inner race: the three minimum-film fits within 20 % of one another. The central
        // films differ more: Moes (close to the Dowson–Toyoda 3.06 U^0.69 G^0.56 W′^−0.1 here)
        // is 37 % above Pan–Hamrock, whose G^0.470 is the weakest of the fits.
        let v = ok(&roller(4800.0, 10.061, 0.01));
        assert_eq!(v["result"]["regime"], "piezoviscous-elastic");
        assert_eq!(v["result"]["film_formula"], "pan_hamrock");
        let f = |name: &str, film: &str| {
            get(
                &v,
                &format!("/result/formulas/{name}/{film}_film_thickness_m"),
            )
        };
        let ph = f("pan_hamrock", "min");
        assert_rel(f("dowson_higginson", "min"), ph, 0.2, "DH vs PH");
        assert_rel(f("hamrock_dowson_line_limit", "min"), ph, 0.2, "HD ∞ vs PH");
        assert_rel(
            f("moes", "central"),
            f("pan_hamrock", "central"),
            0.4,
            "Moes vs PH",
        );
        assert_eq!(get(&v, "/result/min_film_thickness_m"), ph);
        assert_rel(
            get(&v, "/result/line_load_parameter"),
            4800.0 / (0.016 * get(&v, "/result/effective_modulus_pa") * 0.0064),
            1e-12,
            "W′",
        );
        assert!(v["result"].get("ellipticity").is_none());
    }

    #[test]
    fn the_headline_is_the_regime_formula_and_every_formula_is_reported() {
        let v = ok(&bearing(4513.0, 6.252, 0.04));
        let r = &v["result"];
        assert_eq!(r["regime"], "piezoviscous-elastic");
        assert_eq!(r["film_formula"], "hamrock_dowson_hard");
        for name in [
            "hamrock_dowson_hard",
            "hamrock_dowson_soft",
            "isoviscous_rigid",
            "piezoviscous_rigid",
            "isoviscous_elastic",
            "piezoviscous_elastic",
        ] {
            for film in ["central", "min"] {
                let x = get(
                    &v,
                    &format!("/result/formulas/{name}/{film}_film_thickness_m"),
                );
                assert!(x.is_finite() && x > 0.0, "{name} {film}: {x}");
            }
        }
        assert_eq!(
            get(&v, "/result/min_film_thickness_m"),
            get(
                &v,
                "/result/formulas/hamrock_dowson_hard/min_film_thickness_m"
            )
        );
        // Hamrock: the minimum film sits in the side lobes, below the central film.
        assert!(
            get(&v, "/result/min_film_thickness_m") < get(&v, "/result/central_film_thickness_m")
        );
        // No roughness: no Λ, and the effect says why.
        assert!(r.get("film_parameter_lambda").is_none());
        assert_eq!(v["effects"]["mixed_lubrication"]["applied"], false);
        assert_eq!(v["effects"]["thermal"]["applied"], false);
        assert_eq!(v["effects"]["starvation"]["applied"], false);
        // Extrapolation warning: W = 7.9e-4 is far above the fitted decade.
        assert!(v["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .any(|w| w["code"] == "outside_fitted_range"));
    }

    #[test]
    fn a_soft_contact_uses_the_soft_formula() {
        // Rubber ball (E = 10 MPa) on glass-like flat, water-glycol-like fluid with a tiny α.
        let rubber = json!({"radius_x_m": 0.01, "radius_y_m": 0.01, "elastic_modulus_pa": 1e7, "poisson_ratio": 0.49});
        let v = ok(&json!({
            "body1": rubber, "body2": {"elastic_modulus_pa": 7e10, "poisson_ratio": 0.22},
            "load_n": 1.0, "entrainment_speed_m_s": 0.1, "temperature_c": 25.0,
            "lubricant": {"viscosity_pa_s": 0.05, "pressure_viscosity_coefficient_1_pa": 1e-8}
        }));
        assert_eq!(v["result"]["regime"], "isoviscous-elastic");
        assert_eq!(v["result"]["film_formula"], "hamrock_dowson_soft");
        assert_eq!(
            get(&v, "/result/min_film_thickness_m"),
            get(
                &v,
                "/result/formulas/hamrock_dowson_soft/min_film_thickness_m"
            )
        );
    }

    #[test]
    fn ellipticity_follows_the_rolling_direction() {
        // The same ball and groove, rolled across the groove: k < 1.
        let mut across = bearing(1000.0, 5.0, 0.04);
        across["body2"] = steel(Some(-0.006604), Some(0.0261455));
        let along = ok(&bearing(1000.0, 5.0, 0.04));
        let across = ok(&across);
        let (k1, k2) = (
            get(&along, "/result/ellipticity"),
            get(&across, "/result/ellipticity"),
        );
        assert!(k1 > 1.0 && k2 < 1.0);
        assert_rel(k1 * k2, 1.0, 1e-12, "k and 1/k");
        assert_rel(
            get(&along, "/result/radius_ratio") * get(&across, "/result/radius_ratio"),
            1.0,
            1e-12,
            "α_r",
        );
        assert!(across["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .any(|w| w["code"] == "outside_fitted_range"));
    }

    #[test]
    fn roelands_z_gives_the_khonsari_alpha() {
        // α = Z·5.1e-9·(ln η₀ + 9.67) (Khonsari eq. 2.13), η₀ = 0.04 Pa·s, Z = 0.6.
        let mut r = bearing(1000.0, 5.0, 0.04);
        r["lubricant"] = json!({"viscosity_pa_s": 0.04, "roelands_pressure_viscosity_index": 0.6});
        let v = ok(&r);
        let want = 0.6 / 196.1e6 * (0.04f64.ln() + 9.67);
        assert_rel(
            get(&v, "/result/pressure_viscosity_coefficient_1_pa"),
            want,
            1e-12,
            "α",
        );
    }

    #[test]
    fn inlet_heating_thins_a_fast_film() {
        let mut r = bearing(2000.0, 30.0, 0.0);
        r["lubricant"] = json!({"iso_vg": 68, "pressure_viscosity_coefficient_1_pa": 2.2e-8});
        r["slide_roll_ratio"] = json!(0.1);
        let v = ok(&r);
        let phi = get(&v, "/result/thermal_reduction_factor");
        assert!(phi > 0.0 && phi < 0.95, "φ_T = {phi}");
        assert_eq!(v["effects"]["thermal"]["applied"], true);
        assert_rel(
            get(&v, "/result/min_film_thickness_m"),
            phi * get(
                &v,
                "/result/formulas/hamrock_dowson_hard/min_film_thickness_m",
            ),
            1e-12,
            "h_min φ_T",
        );
        r["effects"] = json!({"thermal": "off"});
        let off = ok(&r);
        assert_eq!(get(&off, "/result/thermal_reduction_factor"), 1.0);
        assert!(off["effects"]["thermal"].get("criterion").is_none());
        // Slow: auto leaves it out, but reports the number.
        let mut slow = r.clone();
        slow["entrainment_speed_m_s"] = json!(0.05);
        slow["effects"] = json!({});
        let slow = ok(&slow);
        assert_eq!(slow["effects"]["thermal"]["applied"], false);
        assert!(get(&slow, "/effects/thermal/criterion/value") < THERMAL_THRESHOLD);
    }

    #[test]
    fn a_short_meniscus_starves_the_film() {
        let flooded = ok(&bearing(1000.0, 5.0, 0.04));
        let mut r = bearing(1000.0, 5.0, 0.04);
        r["inlet_meniscus_distance_m"] = json!(1.0);
        let far = ok(&r);
        assert_eq!(far["effects"]["starvation"]["applied"], false);
        assert_eq!(
            get(&far, "/result/min_film_thickness_m"),
            get(&flooded, "/result/min_film_thickness_m")
        );
        r["inlet_meniscus_distance_m"] = json!(2.5e-4);
        let near = ok(&r);
        assert_eq!(near["effects"]["starvation"]["applied"], true);
        let (fc, fm) = (
            get(&near, "/result/starvation_factor_central"),
            get(&near, "/result/starvation_factor_min"),
        );
        assert!(fc < 1.0 && fm < 1.0 && fc > 0.0 && fm > 0.0, "{fc} {fm}");
        assert_rel(
            get(&near, "/result/min_film_thickness_m"),
            fm * get(&flooded, "/result/min_film_thickness_m"),
            1e-12,
            "starved",
        );
        // Inside the Hertz zone: refused.
        r["inlet_meniscus_distance_m"] = json!(1e-6);
        assert_eq!(pointers(&r), ["/inlet_meniscus_distance_m"]);
    }

    #[test]
    fn roughness_gives_lambda_and_the_lubrication_regime() {
        let mut r = bearing(4513.0, 6.252, 0.04);
        r["roughness"] = json!({"composite_rms_m": 1e-6});
        let v = ok(&r);
        let lambda = get(&v, "/result/film_parameter_lambda");
        assert_rel(
            lambda,
            get(&v, "/result/min_film_thickness_m") / 1e-6,
            1e-14,
            "Λ",
        );
        assert_eq!(v["result"]["lubrication_regime"], "boundary");
        assert_eq!(
            get(&v, "/effects/mixed_lubrication/criterion/value"),
            lambda
        );
        assert!(v["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .any(|w| w["code"] == "film_below_roughness"));
        r["roughness"] = json!({"body1_rms_m": 0.0, "body2_rms_m": 1e-8});
        let v = ok(&r);
        assert_eq!(v["result"]["lubrication_regime"], "full-film");
        assert_rel(get(&v, "/result/composite_roughness_m"), 1e-8, 1e-14, "σ");
    }

    #[test]
    fn bad_input_is_refused_with_its_pointer() {
        let base = bearing(1000.0, 5.0, 0.04);
        let with = |pointer: &str, value: Value| {
            let mut r = base.clone();
            let (parent, key) = pointer.rsplit_once('/').unwrap();
            let target = if parent.is_empty() {
                &mut r
            } else {
                r.pointer_mut(parent).unwrap()
            };
            target[key] = value;
            r
        };
        let rows: Vec<(Value, &str, &str)> = vec![
            (
                with("/lubricant", json!({"viscosity_pa_s": 0.04})),
                "/lubricant",
                "no pressure–viscosity law",
            ),
            (
                with("/entrainment_speed_m_s", json!(0.0)),
                "/entrainment_speed_m_s",
                "zero speed",
            ),
            (
                with("/entrainment_speed_m_s", json!(5000.0)),
                "/entrainment_speed_m_s",
                "too fast",
            ),
            (with("/load_n", json!(-1.0)), "/load_n", "negative load"),
            (
                with("/body1/poisson_ratio", json!(0.7)),
                "/body1/poisson_ratio",
                "ν > 0.5",
            ),
            (
                with("/body2/radius_x_m", json!(-0.005)),
                "/body2/radius_x_m",
                "concave tighter than the ball",
            ),
            (
                with("/roughness", json!({"body1_rms_m": 1e-7})),
                "/roughness/body2_rms_m",
                "one body's roughness",
            ),
            (
                with(
                    "/roughness",
                    json!({"body1_rms_m": 1e-7, "body2_rms_m": 1e-7, "composite_rms_m": 1e-7}),
                ),
                "/roughness/composite_rms_m",
                "both forms",
            ),
            (
                with(
                    "/roughness",
                    json!({"body1_rms_m": 0.0, "body2_rms_m": 0.0}),
                ),
                "/roughness/body1_rms_m",
                "both smooth",
            ),
            (
                with("/roughness", json!({"composite_rms_m": 0.0})),
                "/roughness/composite_rms_m",
                "zero composite",
            ),
            (
                with("/slide_roll_ratio", json!(3.0)),
                "/slide_roll_ratio",
                "slide-roll > 2",
            ),
            (
                with("/effects", json!({"starvation": "on"})),
                "/effects/starvation",
                "starvation without a meniscus",
            ),
            (
                with("/effects", json!({"mixed_lubrication": "on"})),
                "/effects/mixed_lubrication",
                "no mixed model",
            ),
            (
                with("/effects", json!({"thermal": "on"})),
                "/lubricant",
                "thermal on, constant viscosity",
            ),
            (with("/fidelity", json!("high")), "/fidelity", "no grid"),
            (with("/temprature_c", json!(40.0)), "/temprature_c", "typo"),
            (
                with("/temperature_c", json!(-300.0)),
                "/temperature_c",
                "below absolute zero",
            ),
        ];
        for (request, pointer, why) in rows {
            let got = pointers(&request);
            assert!(got.iter().any(|p| p == pointer), "{why}: {got:?}");
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]

        #[test]
        fn point_films_are_finite_and_monotone(
            log_load in 1.0f64..4.0,
            log_speed in -1.0f64..1.5,
            log_visc in -2.0f64..-0.5,
        ) {
            let (w, u, eta) = (10f64.powf(log_load), 10f64.powf(log_speed), 10f64.powf(log_visc));
            let film = |v: &Value, f: &str| get(v, &format!("/result/formulas/hamrock_dowson_hard/{f}_film_thickness_m"));
            let base = ok(&bearing(w, u, eta));
            for f in ["central", "min"] {
                let h = film(&base, f);
                prop_assert!(h.is_finite() && h > 0.0);
                // Faster and more viscous: thicker (U^0.67–0.68); heavier: thinner, but weakly
                // (W^−0.067–0.073: doubling the load costs at most 5 %).
                prop_assert!(film(&ok(&bearing(w, 1.5 * u, eta)), f) > h);
                prop_assert!(film(&ok(&bearing(w, u, 1.5 * eta)), f) > h);
                let heavier = film(&ok(&bearing(2.0 * w, u, eta)), f) / h;
                prop_assert!(heavier < 1.0 && heavier > 0.95, "{}", heavier);
            }
            let h = get(&base, "/result/min_film_thickness_m");
            prop_assert!(h.is_finite() && h > 0.0);
        }

        #[test]
        fn line_films_are_finite_and_monotone(
            log_load in 2.0f64..4.5,
            log_speed in -1.0f64..1.5,
            log_visc in -2.0f64..-0.5,
        ) {
            let (w, u, eta) = (10f64.powf(log_load), 10f64.powf(log_speed), 10f64.powf(log_visc));
            let base = ok(&roller(w, u, eta));
            for name in ["pan_hamrock", "dowson_higginson", "hamrock_dowson_line_limit"] {
                let film = |v: &Value| get(v, &format!("/result/formulas/{name}/min_film_thickness_m"));
                let h = film(&base);
                prop_assert!(h.is_finite() && h > 0.0);
                prop_assert!(film(&ok(&roller(w, 1.5 * u, eta))) > h);
                prop_assert!(film(&ok(&roller(w, u, 1.5 * eta))) > h);
                let heavier = film(&ok(&roller(2.0 * w, u, eta))) / h;
                prop_assert!(heavier < 1.0 && heavier > 0.9, "{}: {}", name, heavier);
            }
            let moes = get(&base, "/result/formulas/moes/central_film_thickness_m");
            prop_assert!(moes.is_finite() && moes > 0.0);
            prop_assert!(get(&ok(&roller(w, 1.5 * u, eta)), "/result/formulas/moes/central_film_thickness_m") > moes);
        }
    }
}
