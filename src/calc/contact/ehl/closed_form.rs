//! The closed-form EHL film calculation — what `/v1/contacts/ehl-film` computes after
//! validation, typed: [`solve`] takes a [`FilmCase`] (a checked Hertz [`Contact`], the load,
//! speed, lubricant and effect modes) and returns a [`FilmSolution`] with the films, the
//! groups, the correction factors, Λ, every formula's films, and the effect decisions and
//! warnings as data. Composed rooms (the rolling analysis) call it with typed values.
//!
//! The formulas are [`super::formulas`], the corrections [`super::corrections`], the film
//! parameter Λ [`crate::calc::surface::roughness`].

use super::corrections::{
    fully_flooded_meniscus, fully_flooded_meniscus_min, gupta_thermal_factor, starvation_factor,
    thermal_loading, THERMAL_THRESHOLD,
};
use super::formulas::{
    dowson_higginson, hard_central_film, hard_min_film, outside_fit, pan_hamrock, point_regime,
    regime_films, soft_min_film, Groups, MoesAsymptotes, Regime,
};
use crate::calc::contact::hertz::{Contact, MajorAxis, Solution};
use crate::calc::lubricant::model::{PressureLaw, TemperatureLaw};
use crate::calc::lubricant::{validity, Lubricant};
use crate::calc::surface::roughness::{
    composite_rms, film_parameter, LubricationRegime, FULL_FILM_LAMBDA,
};
use crate::calc::{CalcError, Notes};
use crate::effects::{Criterion, Decision, Mode};

/// Stachowiak §7.4: the isothermal fits overestimate the film above about 1 µm and 10 m/s,
/// where the inlet heats.
const INLET_HEATING_FILM_M: f64 = 1e-6;
const INLET_HEATING_SPEED_M_S: f64 = 10.0;

/// Highest entrainment speed the film model takes, m/s (beyond it the closed forms have no
/// footing at all).
pub const MAX_SPEED_M_S: f64 = 1e3;
/// Lowest entrainment speed the film model takes, m/s: a nanometre a second (below it the
/// dimensionless groups underflow).
pub const MIN_SPEED_M_S: f64 = 1e-9;
/// A film above this fraction of R_x is not thin (the lubrication approximation fails).
const THIN_FILM_FRACTION: f64 = 0.01;
/// Largest RMS roughness of one surface, m.
pub const MAX_ROUGHNESS_M: f64 = 1e-4;

/// Why the film model refuses an entrainment speed (the caller names the field).
pub fn speed_refusal(speed_m_s: f64) -> Option<String> {
    (!(MIN_SPEED_M_S..=MAX_SPEED_M_S).contains(&speed_m_s)).then(|| {
        format!("must be within [{MIN_SPEED_M_S:e}, {MAX_SPEED_M_S}] m/s, got {speed_m_s}")
    })
}

/// The composite roughness of two surfaces' RMS roughness, or which surface (0 or 1) is refused
/// and why.
pub fn composite_roughness(sigma_m: [f64; 2]) -> Result<f64, (usize, String)> {
    for (i, v) in sigma_m.into_iter().enumerate() {
        if v > MAX_ROUGHNESS_M {
            return Err((i, format!("must be at most {MAX_ROUGHNESS_M} m")));
        }
    }
    if sigma_m[0] > 0.0 || sigma_m[1] > 0.0 {
        Ok(composite_rms(sigma_m[0], sigma_m[1]))
    } else {
        Err((
            0,
            "both surfaces perfectly smooth: Λ is infinite; omit roughness".to_owned(),
        ))
    }
}

/// The effect modes of a film calculation.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct FilmEffects {
    /// Inlet shear heating (Gupta et al.); needs a viscosity–temperature law.
    pub thermal: Mode,
    /// Starvation from the inlet meniscus (point contacts; needs `meniscus_m`).
    pub starvation: Mode,
    /// Mixed lubrication, judged from Λ (reported, not modelled: `On` is not a case).
    pub mixed_lubrication: Mode,
}

/// An effect the film model cannot apply as asked.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EffectRefusal {
    StarvationWithoutMeniscus,
    StarvationOfALine,
    MixedLubricationOn,
}

impl EffectRefusal {
    /// The effect's field name.
    pub fn effect(self) -> &'static str {
        match self {
            EffectRefusal::StarvationWithoutMeniscus | EffectRefusal::StarvationOfALine => {
                "starvation"
            }
            EffectRefusal::MixedLubricationOn => "mixed_lubrication",
        }
    }

    pub fn message(self) -> &'static str {
        match self {
            EffectRefusal::StarvationWithoutMeniscus => "starvation needs inlet_meniscus_distance_m (the distance from the contact centre to the inlet meniscus)",
            EffectRefusal::StarvationOfALine => "the meniscus starvation formulas here are for point contacts (Hamrock & Dowson 1977); none is implemented for a line contact",
            EffectRefusal::MixedLubricationOn => "no mixed-EHL film model is implemented (the texts give none: Khonsari FE-9); use auto, which reports Λ and the lubrication regime",
        }
    }
}

impl FilmEffects {
    /// What the modes ask that the model cannot do, for a case with or without a meniscus
    /// distance, point or line.
    pub fn refusals(&self, has_meniscus: bool, line: bool) -> Vec<EffectRefusal> {
        let mut out = Vec::new();
        if self.starvation == Mode::On && !has_meniscus {
            out.push(EffectRefusal::StarvationWithoutMeniscus);
        }
        if self.starvation == Mode::On && line {
            out.push(EffectRefusal::StarvationOfALine);
        }
        if self.mixed_lubrication == Mode::On {
            out.push(EffectRefusal::MixedLubricationOn);
        }
        out
    }
}

/// A checked film case. The wire builds it from a request; other rooms build it from Rust.
#[derive(Debug, Clone)]
pub struct FilmCase {
    /// The dry contact (a line contact when its shape is a line).
    pub contact: Contact,
    /// Normal load F, N (the contact's).
    pub load_n: f64,
    /// Line contacts: the length L, m.
    pub line_length_m: Option<f64>,
    /// Mean entrainment speed ū, m/s.
    pub speed_m_s: f64,
    pub lubricant: Lubricant,
    /// The lubricant's pressure–viscosity law.
    pub pressure_law: PressureLaw,
    /// Inlet oil temperature, °C.
    pub temperature_c: f64,
    /// Composite RMS roughness √(σ₁² + σ₂²), m, for Λ.
    pub composite_roughness_m: Option<f64>,
    /// Slide-to-roll ratio s, 0 … 2.
    pub slide_roll_ratio: f64,
    /// Distance from the contact centre to the inlet meniscus, m.
    pub meniscus_m: Option<f64>,
    pub effects: FilmEffects,
}

/// One formula's films, isothermal and fully flooded, m.
#[derive(Debug, Clone, PartialEq)]
pub struct Formula {
    pub central_m: Option<f64>,
    pub min_m: Option<f64>,
    /// The formula and where it is printed.
    pub source: &'static str,
}

impl Formula {
    fn new(central: Option<f64>, min: Option<f64>, source: &'static str) -> Self {
        Formula {
            central_m: central,
            min_m: min,
            source,
        }
    }
}

/// Every film formula that applies to the contact's shape (point: the first six; line: the
/// last four).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Formulas {
    pub hamrock_dowson_hard: Option<Formula>,
    pub hamrock_dowson_soft: Option<Formula>,
    pub isoviscous_rigid: Option<Formula>,
    pub piezoviscous_rigid: Option<Formula>,
    pub isoviscous_elastic: Option<Formula>,
    pub piezoviscous_elastic: Option<Formula>,
    pub pan_hamrock: Option<Formula>,
    pub dowson_higginson: Option<Formula>,
    pub hamrock_dowson_line_limit: Option<Formula>,
    pub moes: Option<Formula>,
}

/// A solved film case.
#[derive(Debug, Clone)]
pub struct FilmSolution {
    /// The dry Hertz contact (its own warnings are in [`FilmSolution::warnings`]; its solver
    /// report is the film's).
    pub contact: Solution,
    /// Central and minimum film, m, with the correction factors applied.
    pub central_film_m: f64,
    pub min_film_m: f64,
    /// The entry of `formulas` that gave the films.
    pub formula: &'static str,
    pub regime: Regime,
    /// U, G, W.
    pub groups: Groups,
    /// Line contacts: W′ = F/(L E′ R_x).
    pub line_load: Option<f64>,
    /// Point contacts: k = D_y/D_x and α_r = R_y/R_x.
    pub ellipticity: Option<f64>,
    pub radius_ratio: Option<f64>,
    /// Point contacts: (g_v, g_e).
    pub reduced: Option<(f64, f64)>,
    /// Line contacts: Moes' (M, L).
    pub moes: Option<(f64, f64)>,
    /// η₀ at the inlet temperature, Pa·s, and α, 1/Pa.
    pub viscosity_pa_s: f64,
    pub alpha_1_pa: f64,
    /// φ_T (1 when not applied).
    pub thermal_factor: f64,
    /// Starvation factors (central, minimum), 1 when not applied.
    pub starvation_factors: (f64, f64),
    /// Λ = h_min/σ, with roughness.
    pub lambda: Option<f64>,
    pub formulas: Formulas,
    /// The decisions on `thermal`, `starvation` and `mixed_lubrication`, and the warnings, in
    /// order: the dry contact's (but for its approach, which a film does not report), then the
    /// film's.
    pub notes: Notes,
}

/// η₀ at the inlet temperature, or a 422 where the lubricant's law has no value there.
pub fn inlet_viscosity(lubricant: &Lubricant, t: f64) -> Result<f64, CalcError> {
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

/// The film of a checked case: the dry contact, the groups, the regime's formula, the
/// inlet-heating and starvation factors, Λ. Refusals (a Roelands α that is not positive, a
/// thermal effect asked of a constant viscosity, a meniscus inside the contact) carry the film
/// request's pointers.
pub fn solve(case: &FilmCase) -> Result<FilmSolution, CalcError> {
    let hertz = case.contact.solve()?;
    let mut notes = Notes::default();
    // The dry contact's approach is not part of a film calculation: its warning is not passed
    // on (the film room never reported it); the others are.
    notes
        .warnings
        .extend(hertz.warnings_but_approach().cloned());
    let eta0 = inlet_viscosity(&case.lubricant, case.temperature_c)?;
    if let Some((code, message)) = validity::hot_oil("the inlet oil", case.temperature_c) {
        notes.warn(code, message);
    }
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
        None => point_films(&groups, &hertz, &mut notes),
        Some(length_m) => line_films(&groups, length_m, rx, &mut notes),
    };
    let mut central = films.central_h * rx;
    let mut min = films.min_h * rx;
    let thermal = thermal_factor(case, &hertz, eta0, &mut notes)?;
    let (starve_c, starve_min) = starvation_factors(case, &hertz, &films, &mut notes)?;
    central *= thermal * starve_c;
    min *= thermal * starve_min;
    if thermal == 1.0 && central > INLET_HEATING_FILM_M && case.speed_m_s > INLET_HEATING_SPEED_M_S
    {
        notes.warn(
            "inlet_heating_likely",
            format!("h_c = {central:.3e} m above 1 µm at ū = {} m/s above 10 m/s: the isothermal fits overestimate the film here (Stachowiak §7.4); consider effects.thermal on", case.speed_m_s),
        );
    }
    warn_film_shape(central, min, rx, &mut notes);
    let lambda = case.composite_roughness_m.map(|s| film_parameter(min, s));
    mixed_lubrication(case, lambda, &mut notes);
    Ok(FilmSolution {
        contact: hertz,
        central_film_m: central,
        min_film_m: min,
        formula: films.formula,
        regime: films.regime,
        groups,
        line_load: films.line_load,
        ellipticity: films.ellipticity,
        radius_ratio: films.radius_ratio,
        reduced: films.reduced,
        moes: films.moes,
        viscosity_pa_s: eta0,
        alpha_1_pa: alpha,
        thermal_factor: thermal,
        starvation_factors: (starve_c, starve_min),
        lambda,
        formulas: films.formulas,
        notes,
    })
}

/// Warnings for films no formula can mean (issue 12, item 2): a film that is not thin against
/// the contact's radius breaks the lubrication approximation every formula rests on (a feather
/// load or a crawling speed in the rigid regimes), and a minimum film above the central one is
/// two fits extrapolated past each other.
fn warn_film_shape(central: f64, min: f64, rx: f64, notes: &mut Notes) {
    if central > THIN_FILM_FRACTION * rx {
        notes.warn(
            "film_not_thin",
            format!("h_c = {central:.3e} m exceeds {THIN_FILM_FRACTION} R_x = {:.3e} m: the lubrication approximation behind the film formulas needs h ≪ R (Hamrock §21.2), so this film is not a result; the bodies are effectively apart", THIN_FILM_FRACTION * rx),
        );
    }
    if min > central {
        notes.warn(
            "min_film_above_central",
            format!("h_min = {min:.3e} m above h_c = {central:.3e} m: the two fits are extrapolated far outside their range and disagree; neither is reliable here"),
        );
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
    formulas: Formulas,
}

/// Ellipticity k = D_y/D_x of the Hertz contact: κ when the major axis lies across the
/// rolling direction (or a circle), 1/κ when along it.
fn rolling_ellipticity(hertz: &Solution) -> f64 {
    let kappa = hertz.ellipticity().unwrap_or(1.0);
    if hertz.major_axis() == MajorAxis::X {
        1.0 / kappa
    } else {
        kappa
    }
}

fn point_films(g: &Groups, hertz: &Solution, notes: &mut Notes) -> Films {
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
    let formulas = Formulas {
        hamrock_dowson_hard: Some(Formula::new(
            Some(hard.0 * rx),
            Some(hard.1 * rx),
            "Hamrock–Dowson hard EHL: H_c = 2.69 U^0.67 G^0.53 W^−0.067 (1 − 0.61e^−0.73k) (Stachowiak eq. 7.26), H_min = 3.63 U^0.68 G^0.49 W^−0.073 (1 − e^−0.68k) (Hamrock eq. 21.57)",
        )),
        hamrock_dowson_soft: Some(Formula::new(
            Some(soft.0 * rx),
            Some(soft.1 * rx),
            "Hamrock–Dowson soft EHL: H_min = 7.43 U^0.65 W^−0.21 (1 − 0.85e^−0.31k) (Hamrock eq. 21.58); H_c from Ĥ_c = 11.15 g_e^0.67 (1 − 0.72e^−0.28k) (Stachowiak §7.4)",
        )),
        isoviscous_rigid: Some(Formula::new(
            Some(h(r.isoviscous_rigid)),
            Some(h(r.isoviscous_rigid)),
            "Ĥ = 128 α_r λ_b² [0.131 atan(α_r/2) + 1.683]², λ_b = (1 + 2/(3α_r))⁻¹ (Hamrock eqs 21.62–21.64)",
        )),
        piezoviscous_rigid: Some(Formula::new(
            Some(h(r.piezoviscous_rigid)),
            Some(h(r.piezoviscous_rigid)),
            "Ĥ = 1.66 g_v^(2/3) (1 − e^−0.68k) (Hamrock eq. 21.65)",
        )),
        isoviscous_elastic: Some(Formula::new(
            Some(h(r.isoviscous_elastic.1)),
            Some(h(r.isoviscous_elastic.0)),
            "Ĥ_min = 8.70 g_e^0.67 (1 − 0.85e^−0.31k) (Hamrock eq. 21.66), Ĥ_c = 11.15 g_e^0.67 (1 − 0.72e^−0.28k) (Stachowiak §7.4)",
        )),
        piezoviscous_elastic: Some(Formula::new(
            Some(h(r.piezoviscous_elastic.1)),
            Some(h(r.piezoviscous_elastic.0)),
            "Ĥ_min = 3.42 g_v^0.49 g_e^0.17 (1 − e^−0.68k) (Hamrock eq. 21.67), Ĥ_c = 3.61 g_v^0.53 g_e^0.13 (1 − 0.61e^−0.73k) (Stachowiak §7.4)",
        )),
        ..Formulas::default()
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
    notes.warnings.extend(outside_fit(g, k, regime));
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

fn line_films(g: &Groups, length_m: f64, rx: f64, notes: &mut Notes) -> Films {
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
    let formulas = Formulas {
        pan_hamrock: Some(Formula::new(
            Some(ph_central * rx),
            Some(ph_min * rx),
            "Pan & Hamrock (1989) J. Tribol. 111:246: H_c = 2.922 W′^−0.166 U^0.692 G^0.470, H_min = 1.714 W′^−0.128 U^0.694 G^0.568 (verify)",
        )),
        dowson_higginson: Some(Formula::new(
            None,
            Some(dowson_higginson(g, line_load) * rx),
            "Dowson–Higginson: H_min = 2.65 G^0.54 U^0.7 W′^−0.13 (Khonsari & Booser eq. 15.10)",
        )),
        hamrock_dowson_line_limit: Some(Formula::new(
            Some(limit.0 * rx),
            Some(limit.1 * rx),
            "Hamrock–Dowson point formulas with k → ∞ and W = F/(E′R_x²) (Hamrock's roller example; Stachowiak Problems 7.4, 7.13, 7.15)",
        )),
        moes: Some(Formula::new(
            Some(moes_central * rx),
            None,
            "Moes (1992) central film over the four regimes, M = W′(2U)^−½, L = G(2U)^¼ (Venner & Lubrecht 2000; verify)",
        )),
        ..Formulas::default()
    };
    let (formula, central_h, min_h) = if regime == Regime::PiezoviscousElastic {
        ("pan_hamrock", ph_central, ph_min)
    } else {
        notes.warn(
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

/// The inlet-heating effect: decided from the Gupta et al. factor
/// ([`gupta_thermal_factor`]) against [`THERMAL_THRESHOLD`]. Returns 1 when not applied.
fn thermal_factor(
    case: &FilmCase,
    hertz: &Solution,
    eta0: f64,
    notes: &mut Notes,
) -> Result<f64, CalcError> {
    let mode = case.effects.thermal;
    let what = "inlet shear heating (Gupta et al. thermal reduction factor)";
    if mode == Mode::Off {
        notes.decide(
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
        notes.decide(
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
    let loading = thermal_loading(slope, case.speed_m_s, conductivity);
    let phi = gupta_thermal_factor(
        hertz.max_pressure_pa / hertz.effective_modulus_pa,
        loading,
        case.slide_roll_ratio,
    );
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
    notes.decide("thermal", decision);
    Ok(if applied { phi } else { 1.0 })
}

/// The starvation effect (Hamrock & Dowson 1977, point contacts): with m̄ = m/b the meniscus
/// distance over the Hertz semi-axis b along the rolling direction, the films are starved
/// below m̄*_c = 1 + 3.06 [(R_x/b)² H_c]^0.58 and m̄*_min = 1 + 3.34 [(R_x/b)² H_min]^0.56
/// ([`starvation_factor`]). Returns (central, minimum) factors, 1 when not applied.
fn starvation_factors(
    case: &FilmCase,
    hertz: &Solution,
    films: &Films,
    notes: &mut Notes,
) -> Result<(f64, f64), CalcError> {
    let mode = case.effects.starvation;
    let what = "starvation (Hamrock–Dowson inlet meniscus)";
    let Some(meniscus) = case.meniscus_m else {
        notes.decide(
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
    let b = match hertz.semi_axes_m() {
        Some((major, _)) if hertz.major_axis() == MajorAxis::X => major,
        Some((_, minor)) => minor,
        None => {
            notes.decide(
                "starvation",
                Decision::not_applicable(mode, format!("{what}: the meniscus formulas are for point contacts; none is implemented for a line contact")),
            );
            return Ok((1.0, 1.0));
        }
    };
    if mode == Mode::Off {
        notes.decide(
            "starvation",
            Decision::not_applicable(mode, format!("{what}: requested off")),
        );
        return Ok((1.0, 1.0));
    }
    let meniscus_ratio = meniscus / b;
    if meniscus_ratio <= 1.0 {
        return Err(CalcError::impossible(
            "/inlet_meniscus_distance_m",
            format!("the meniscus must lie upstream of the Hertz zone: {meniscus:.3e} m is within the semi-axis b = {b:.3e} m along x"),
        ));
    }
    let scale = (hertz.reduced_radius_x_m / b).powi(2);
    let critical_c = fully_flooded_meniscus(scale * films.central_h);
    let critical_min = fully_flooded_meniscus_min(scale * films.min_h);
    let decision = Decision::decide(
        mode,
        Criterion {
            name: "critical_to_actual_meniscus_ratio",
            value: critical_c.max(critical_min) / meniscus_ratio,
            threshold: 1.0,
        },
        what,
    );
    let applied = decision.applied;
    notes.decide("starvation", decision);
    if !applied {
        return Ok((1.0, 1.0));
    }
    Ok((
        starvation_factor(meniscus_ratio, critical_c, 0.29),
        starvation_factor(meniscus_ratio, critical_min, 0.25),
    ))
}

/// Report the mixed-lubrication effect from Λ; warn below Λ = 3 unless it is off.
fn mixed_lubrication(case: &FilmCase, lambda: Option<f64>, notes: &mut Notes) {
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
                notes.warn(
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
    notes.decide("mixed_lubrication", decision);
}
