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

use super::closed_form::{
    self, speed_refusal, FilmCase, FilmEffects, FilmSolution, Formula, Formulas, MAX_ROUGHNESS_M,
};
use super::formulas::Regime;
use crate::calc::contact::hertz::{
    contact_of, method_of, BodySpec, ClosedFormFit, LineSpec, Method,
};
use crate::calc::lubricant::{validity, LubricantSpec};
use crate::calc::quantity::{Celsius, NonNegative, Positive};
use crate::calc::surface::roughness::LubricationRegime;
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::effects::Mode;
use crate::fidelity::{FidelityRequest, Level};

pub struct EhlFilm;

/// Largest slide-to-roll ratio |u₁ − u₂|/ū: 2 is pure sliding (one surface still).
const MAX_SLIDE_ROLL: f64 = 2.0;
/// Lightest load the film formulas take, N.
const MIN_LOAD_N: f64 = 1e-6;
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
    /// Normal load F pressing the bodies together, N (1e-6 … 1e12); for a line contact the
    /// total load on `line.length_m`.
    #[schema(value_type = f64, minimum = 1e-6, maximum = 1e12, example = 4513.0)]
    pub load_n: Positive,
    /// Mean entrainment speed ū = (u₁ + u₂)/2 of the two surfaces relative to the contact,
    /// along x, m/s (1e-9 … 1000). The MEAN, not the sum: a ball bearing's inner-race
    /// contact entrains at ū = (d_e² − d²)|ω_i − ω_o|/(4d_e) (Hamrock eq. 21.98).
    #[schema(value_type = f64, minimum = 1e-9, maximum = 1000.0, example = 6.252)]
    pub entrainment_speed_m_s: Positive,
    /// The lubricant; it must have a pressure–viscosity law (Barus α, or a Roelands Z from
    /// which α = Z·5.1e-9·(ln η₀ + 9.67), Khonsari eq. 2.13).
    pub lubricant: LubricantSpec,
    /// Temperature of the oil entering the contact, °C: η₀ and α are taken here; required
    /// unless the lubricant's viscosity is a constant.
    #[schema(value_type = Option<f64>, minimum = -273.0, maximum = 1000.0, example = 40.0)]
    pub temperature_c: Option<Celsius>,
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
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1.0, example = 0.0005)]
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

impl Validate for EhlFilmInput {
    type Valid = FilmCase;
    fn validate(self) -> Result<FilmCase, Vec<FieldError>> {
        let mut errors = Vec::new();
        // The Hertz part, refused with the same pointers (the request's body1, body2, load_n,
        // line, fidelity, closed_form) and in the same order as the Hertz room.
        let method = method_of(self.fidelity, self.closed_form);
        let hertz = contact_of(
            &self.body1,
            &self.body2,
            self.load_n,
            self.line,
            *method.as_ref().unwrap_or(&Method::Exact),
        )
        .map_err(|mut e| errors.append(&mut e))
        .ok();
        let hertz = match method {
            Ok(_) => hertz,
            Err(e) => {
                errors.push(e);
                None
            }
        };
        if self.load_n.get() < MIN_LOAD_N {
            errors.push(FieldError::new(
                "/load_n",
                format!("must be within [{MIN_LOAD_N:e}, 1e12] N (a micronewton: below it the film formulas' load group underflows), got {}", self.load_n.get()),
            ));
        }
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
        let effects = FilmEffects {
            thermal: self.effects.thermal,
            starvation: self.effects.starvation,
            mixed_lubrication: self.effects.mixed_lubrication,
        };
        for refusal in effects.refusals(meniscus_m.is_some(), self.line.is_some()) {
            errors.push(FieldError::new(
                format!("/effects/{}", refusal.effect()),
                refusal.message(),
            ));
        }
        match (
            errors.is_empty(),
            hertz,
            lubricant,
            pressure_law,
            temperature,
        ) {
            (true, Some(hertz), Some(lubricant), Some(pressure_law), Some(temperature_c)) => {
                Ok(FilmCase {
                    contact: hertz,
                    load_n: self.load_n.get(),
                    line_length_m: self.line.map(|l| l.length_m.get()),
                    speed_m_s: speed,
                    lubricant,
                    pressure_law,
                    temperature_c,
                    composite_roughness_m,
                    slide_roll_ratio,
                    meniscus_m,
                    effects,
                })
            }
            _ => Err(errors),
        }
    }
}

/// The mean entrainment speed ū, checked against the film model's range (shared with the
/// numerical EHL room).
pub(super) fn entrainment_speed(speed: Positive, errors: &mut Vec<FieldError>) -> f64 {
    let speed = speed.get();
    if let Some(why) = speed_refusal(speed) {
        errors.push(FieldError::new("/entrainment_speed_m_s", why));
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

/// √(σ₁² + σ₂²), or the composite given; pushes an error and returns None when the
/// description is incomplete, ambiguous or zero.
fn composite_roughness(r: RoughnessSpec, errors: &mut Vec<FieldError>) -> Option<f64> {
    let get = |v: Option<NonNegative>| v.map(NonNegative::get);
    const BODIES: [&str; 2] = ["body1_rms_m", "body2_rms_m"];
    for (name, v) in BODIES
        .into_iter()
        .zip([get(r.body1_rms_m), get(r.body2_rms_m)])
    {
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
        (Some(s1), Some(s2), None) => match closed_form::composite_roughness([s1, s2]) {
            Ok(sigma) => Some(sigma),
            Err((body, why)) => {
                errors.push(FieldError::new(format!("/roughness/{}", BODIES[body]), why));
                None
            }
        },
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
    const DESCRIPTION: &'static str = include_str!("film.md");
    const FIDELITY: &'static [Level] = &[Level::ClosedForm, Level::Standard];
    const EFFECTS: &'static [&'static str] = &["thermal", "starvation", "mixed_lubrication"];
    const EXAMPLE: &'static str = r#"{"body1": {"radius_x_m": 0.00635, "radius_y_m": 0.00635, "elastic_modulus_pa": 2e11, "poisson_ratio": 0.3}, "body2": {"radius_x_m": 0.0261455, "radius_y_m": -0.006604, "elastic_modulus_pa": 2e11, "poisson_ratio": 0.3}, "load_n": 4513, "entrainment_speed_m_s": 6.252, "lubricant": {"viscosity_pa_s": 0.04, "pressure_viscosity_coefficient_1_pa": 2.3e-8}, "temperature_c": 40, "roughness": {"body1_rms_m": 6.25e-8, "body2_rms_m": 1.75e-7}}"#;

    type Input = EhlFilmInput;
    type Output = EhlFilmOutput;

    fn run(case: FilmCase, ctx: &mut Context) -> Result<EhlFilmOutput, CalcError> {
        let film = closed_form::solve(&case)?;
        ctx.record(&film.notes);
        ctx.report(film.contact.report.clone());
        Ok(EhlFilmOutput::of(&film, &case))
    }
}

impl FormulaFilm {
    fn of(f: &Formula) -> Self {
        FormulaFilm::new(f.central_m, f.min_m, f.source)
    }
}

impl FilmFormulas {
    fn of(f: &Formulas) -> Self {
        let of = |f: &Option<Formula>| f.as_ref().map(FormulaFilm::of);
        FilmFormulas {
            hamrock_dowson_hard: of(&f.hamrock_dowson_hard),
            hamrock_dowson_soft: of(&f.hamrock_dowson_soft),
            isoviscous_rigid: of(&f.isoviscous_rigid),
            piezoviscous_rigid: of(&f.piezoviscous_rigid),
            isoviscous_elastic: of(&f.isoviscous_elastic),
            piezoviscous_elastic: of(&f.piezoviscous_elastic),
            pan_hamrock: of(&f.pan_hamrock),
            dowson_higginson: of(&f.dowson_higginson),
            hamrock_dowson_line_limit: of(&f.hamrock_dowson_line_limit),
            moes: of(&f.moes),
        }
    }
}

impl EhlFilmOutput {
    /// The response for a solved film case.
    pub fn of(film: &FilmSolution, case: &FilmCase) -> Self {
        let hertz = &film.contact;
        EhlFilmOutput {
            contact: hertz.contact_name().to_owned(),
            central_film_thickness_m: film.central_film_m,
            min_film_thickness_m: film.min_film_m,
            film_formula: film.formula.to_owned(),
            regime: film.regime,
            speed_parameter: film.groups.u,
            materials_parameter: film.groups.g,
            load_parameter: film.groups.w,
            line_load_parameter: film.line_load,
            ellipticity: film.ellipticity,
            radius_ratio: film.radius_ratio,
            viscosity_parameter: film.reduced.map(|r| r.0),
            elasticity_parameter: film.reduced.map(|r| r.1),
            moes_load_parameter: film.moes.map(|m| m.0),
            moes_material_parameter: film.moes.map(|m| m.1),
            reduced_radius_x_m: hertz.reduced_radius_x_m,
            reduced_radius_y_m: hertz.reduced_radius_y_m,
            effective_modulus_pa: hertz.effective_modulus_pa,
            max_hertz_pressure_pa: hertz.max_pressure_pa,
            viscosity_pa_s: film.viscosity_pa_s,
            pressure_viscosity_coefficient_1_pa: film.alpha_1_pa,
            thermal_reduction_factor: film.thermal_factor,
            starvation_factor_central: film.starvation_factors.0,
            starvation_factor_min: film.starvation_factors.1,
            composite_roughness_m: case.composite_roughness_m,
            film_parameter_lambda: film.lambda,
            lubrication_regime: film.lambda.map(LubricationRegime::of),
            formulas: FilmFormulas::of(&film.formulas),
        }
    }
}

#[cfg(test)]
#[path = "film_tests.rs"]
mod tests;
