//! `POST /v1/gas-bearings/foil-journal`: the compliant bump-foil journal bearing's limiting load
//! as the speed grows without bound (Khonsari & Booser §11.7), and DellaCorte and Valco's
//! rule-of-thumb load capacity at a speed where the request gives their coefficient.
//!
//! This file is the wire (request, validation, response); the physics is [`super::foil`].

use std::f64::consts::PI;

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::foil::{bump_compliance, LimitingFilm};
use super::gas_spec::{Gas, GasSpec};
use crate::calc::journal::plain::GeometrySpec;
use crate::calc::quantity::{NonNegative, Positive};
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::fidelity::Level;
use crate::numerics::quadrature::IntegralError;

pub struct FoilJournal;

/// Largest eccentricity ratio accepted: a compliant foil lets ε_f pass 1, not without bound.
const MAX_ECCENTRICITY: f64 = 20.0;
/// Largest compliance α accepted.
const MAX_COMPLIANCE: f64 = 100.0;
/// Ranges of the bump foil's thickness, pitch, length (m), modulus (Pa) and Poisson's ratio.
const BUMP_RANGES: [(f64, f64); 5] = [
    (1e-6, 0.01),
    (1e-5, 0.1),
    (1e-5, 0.1),
    (1e6, 1e13),
    (0.0, 0.5),
];
/// Largest speed, rpm, and DellaCorte coefficient, lbf/(in³·krpm).
const MAX_SPEED_RPM: f64 = 1e7;
const MAX_DELLACORTE_COEFFICIENT: f64 = 10.0;
/// Metres per inch and newtons per pound-force (Khonsari & Booser Appendix A).
const M_PER_IN: f64 = 0.0254;
const N_PER_LBF: f64 = 4.448_221_615_260_5;

/// The foil: its compliance α directly, or the bump geometry it follows from (Eq. 11.14).
/// Omit the whole object for a rigid bearing (α = 0).
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct FoilSpec {
    /// Compliance α = (2 p_a s/(C E)) (l/t_B)³ (1 − ν²), dimensionless (0 … 100); instead of
    /// the bump fields.
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 100.0, example = 0.2053)]
    pub compliance: Option<NonNegative>,
    /// Bump foil thickness t_B, m, 1e-6 … 0.01.
    #[schema(value_type = Option<f64>, minimum = 1e-6, maximum = 0.01, example = 7.6e-5)]
    pub thickness_m: Option<Positive>,
    /// Bump pitch s, m, 1e-5 … 0.1.
    #[schema(value_type = Option<f64>, minimum = 1e-5, maximum = 0.1, example = 0.00317)]
    pub bump_pitch_m: Option<Positive>,
    /// Bump length 2l, m, 1e-5 … 0.1 (Table 11.5's "bump length"; the law takes its half l).
    #[schema(value_type = Option<f64>, minimum = 1e-5, maximum = 0.1, example = 0.00254)]
    pub bump_length_m: Option<Positive>,
    /// Young's modulus of the foil E, Pa, 1e6 … 1e13.
    #[schema(value_type = Option<f64>, minimum = 1e6, maximum = 1e13, example = 2e11)]
    pub elastic_modulus_pa: Option<Positive>,
    /// Poisson's ratio of the foil ν (0 … 0.5).
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 0.5, example = 0.31)]
    pub poisson_ratio: Option<NonNegative>,
}

/// Request.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct FoilJournalInput {
    pub geometry: GeometrySpec,
    /// The bump foil; omit for a rigid bore.
    pub foil: Option<FoilSpec>,
    /// The gas (only its ambient pressure enters the limiting load).
    pub gas: GasSpec,
    /// Eccentricity ratio ε_f = e/C (0 … 20; below 1 for a rigid bore: a compliant foil lets
    /// the journal pass the nominal clearance).
    #[schema(value_type = f64, minimum = 0.0, maximum = 20.0, example = 0.8)]
    pub eccentricity_ratio: NonNegative,
    /// Shaft speed, rpm (0 … 1e7): with `dellacorte_coefficient`, the rule-of-thumb load.
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 1e7, example = 30000.0)]
    pub speed_rpm: Option<NonNegative>,
    /// DellaCorte and Valco's load capacity coefficient D, lbf/(in³·krpm) (0 … 10; about 1 for
    /// third-generation bump-foil bearings): W = D (L D)(D Ω) with L, D in inches and Ω in
    /// krpm.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 1.0)]
    pub dellacorte_coefficient: Option<Positive>,
}

/// The parsed request.
#[derive(Debug, Clone)]
pub struct FoilJournalCase {
    pub diameter: f64,
    pub length: f64,
    pub clearance: f64,
    pub compliance: f64,
    pub eccentricity: f64,
    pub gas: Gas,
    /// (speed rpm, DellaCorte coefficient), where both are given.
    pub rule_of_thumb: Option<(f64, f64)>,
}

/// α from the foil object: its `compliance`, or the bump fields (all five).
fn parse_foil(
    foil: Option<FoilSpec>,
    clearance: f64,
    ambient_pressure: Option<f64>,
    errors: &mut Vec<FieldError>,
) -> Option<f64> {
    let Some(f) = foil else {
        return Some(0.0);
    };
    let bumps = [
        ("thickness_m", f.thickness_m.map(Positive::get)),
        ("bump_pitch_m", f.bump_pitch_m.map(Positive::get)),
        ("bump_length_m", f.bump_length_m.map(Positive::get)),
        (
            "elastic_modulus_pa",
            f.elastic_modulus_pa.map(Positive::get),
        ),
        ("poisson_ratio", f.poisson_ratio.map(NonNegative::get)),
    ];
    // The ranges of the bump dimensions (a foil, not a plate or a film), as the schema states.
    let n = errors.len();
    for ((name, value), (lo, hi)) in bumps.iter().zip(BUMP_RANGES) {
        if let Some(v) = value.filter(|v| !(lo..=hi).contains(v)) {
            errors.push(FieldError::new(
                format!("/foil/{name}"),
                format!("must be within [{lo:e}, {hi:e}], got {v}"),
            ));
        }
    }
    if errors.len() > n {
        return None;
    }
    let given = bumps.iter().filter(|(_, v)| v.is_some()).count();
    const EITHER: &str = "give compliance, or all of thickness_m, bump_pitch_m, bump_length_m, elastic_modulus_pa and poisson_ratio";
    let alpha = match (f.compliance, given) {
        (Some(a), 0) => a.get(),
        (None, 5) => {
            let v: Vec<f64> = bumps.iter().filter_map(|(_, v)| *v).collect();
            bump_compliance(
                ambient_pressure?,
                v[1],
                clearance,
                v[3],
                0.5 * v[2],
                v[0],
                v[4],
            )
        }
        (Some(_), _) => {
            errors.push(FieldError::new(
                "/foil/compliance",
                format!("over-determined: {EITHER}, not both"),
            ));
            return None;
        }
        (None, _) => {
            for (name, value) in bumps {
                if value.is_none() {
                    errors.push(FieldError::new(
                        format!("/foil/{name}"),
                        format!("under-determined: {EITHER}"),
                    ));
                }
            }
            return None;
        }
    };
    if !(0.0..=MAX_COMPLIANCE).contains(&alpha) || !alpha.is_finite() {
        errors.push(FieldError::new(
            "/foil",
            format!("the compliance α = {alpha:.4e} must be within [0, {MAX_COMPLIANCE}]"),
        ));
        return None;
    }
    Some(alpha)
}

impl Validate for FoilJournalInput {
    type Valid = FoilJournalCase;
    fn validate(self) -> Result<FoilJournalCase, Vec<FieldError>> {
        let mut errors = Vec::new();
        let (d, l, c) = self.geometry.check(&mut errors);
        let gas = self.gas.parse_into("/gas", &mut errors);
        let alpha = parse_foil(
            self.foil,
            c,
            gas.as_ref().map(|g| g.ambient_pressure_pa),
            &mut errors,
        );
        let e = self.eccentricity_ratio.get();
        if e > MAX_ECCENTRICITY {
            errors.push(FieldError::new(
                "/eccentricity_ratio",
                format!("must be at most {MAX_ECCENTRICITY}"),
            ));
        } else if alpha == Some(0.0) && e >= 1.0 {
            errors.push(FieldError::new(
                "/eccentricity_ratio",
                "must be below 1 for a rigid bore (the journal would touch it); a compliant foil (α > 0) lets it pass 1",
            ));
        }
        if self.speed_rpm.is_some_and(|n| n.get() > MAX_SPEED_RPM) {
            errors.push(FieldError::new(
                "/speed_rpm",
                format!("must be at most {MAX_SPEED_RPM:e} rpm"),
            ));
        }
        if self
            .dellacorte_coefficient
            .is_some_and(|k| k.get() > MAX_DELLACORTE_COEFFICIENT)
        {
            errors.push(FieldError::new(
                "/dellacorte_coefficient",
                format!("must be at most {MAX_DELLACORTE_COEFFICIENT} lbf/(in³·krpm)"),
            ));
        }
        let rule_of_thumb = match (self.speed_rpm, self.dellacorte_coefficient) {
            (Some(n), Some(k)) => Some((n.get(), k.get())),
            (None, Some(_)) => {
                errors.push(FieldError::new(
                    "/speed_rpm",
                    "required with dellacorte_coefficient (the rule of thumb scales with speed)",
                ));
                None
            }
            _ => None,
        };
        match (errors.is_empty(), gas, alpha) {
            (true, Some(gas), Some(compliance)) => Ok(FoilJournalCase {
                diameter: d,
                length: l,
                clearance: c,
                compliance,
                eccentricity: e,
                gas,
                rule_of_thumb,
            }),
            _ => Err(errors),
        }
    }
}

/// Result: the limiting load and its film, and the rule-of-thumb load where asked.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct FoilJournalOutput {
    /// The foil's compliance α used (0: rigid).
    pub compliance: f64,
    /// Limiting load W∞ as ω → ∞ (P̄ h̄ = const, no side leakage), N: an upper bound on what
    /// the bearing carries at this ε_f at any speed.
    pub limiting_load_n: f64,
    /// W∞/(p_a L D), the journal's dimensionless load.
    pub load_dimensionless: f64,
    /// W∞/(p_a L R), the text's normalisation (Eq. 11.22).
    pub load_per_ambient_pressure_l_r: f64,
    /// The load lies on the line of centres: 0°.
    pub attitude_angle_deg: f64,
    /// Largest pressure, Pa absolute, at the narrowest gap (θ = 180°).
    pub max_pressure_pa: f64,
    /// Where the largest pressure sits, degrees from the widest gap: 180.
    pub max_pressure_angle_deg: f64,
    /// Smallest film C h̄(π) = C (1 + ε_f)/P̄(π), m (the foil's deflection included).
    pub min_film_m: f64,
    /// The foil's largest deflection α C (P̄(π) − 1), m.
    pub max_foil_deflection_m: f64,
    /// DellaCorte and Valco's W = D (L D)(D Ω), N (with `speed_rpm` and
    /// `dellacorte_coefficient`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rule_of_thumb_load_n: Option<f64>,
}

impl Calculation for FoilJournal {
    const PATH: &'static str = "/v1/gas-bearings/foil-journal";
    const SUMMARY: &'static str = "Compliant bump-foil gas journal bearing: limiting load as speed grows without bound (rigid or compliant foil), its film and foil deflection; DellaCorte–Valco rule-of-thumb load";
    const DESCRIPTION: &'static str = include_str!("foil_journal.md");
    const FIDELITY: &'static [Level] = &[Level::ClosedForm];
    const EFFECTS: &'static [&'static str] = &[];
    const EXAMPLE: &'static str = r#"{"geometry": {"diameter_m": 0.07, "length_m": 0.062, "radial_clearance_m": 6.6e-5}, "foil": {"thickness_m": 7.6e-5, "bump_pitch_m": 0.00317, "bump_length_m": 0.00254, "elastic_modulus_pa": 2e11, "poisson_ratio": 0.31}, "gas": {"name": "air"}, "eccentricity_ratio": 1.2, "speed_rpm": 30000, "dellacorte_coefficient": 1.0}"#;

    type Input = FoilJournalInput;
    type Output = FoilJournalOutput;

    fn run(case: FoilJournalCase, ctx: &mut Context) -> Result<FoilJournalOutput, CalcError> {
        for (code, message) in &case.gas.assumptions {
            ctx.warn(code, message.clone());
        }
        let film = LimitingFilm {
            eccentricity: case.eccentricity,
            compliance: case.compliance,
        };
        let integral = film.load_coefficient(&ctx.budget()).map_err(|e| match e {
            IntegralError::Stopped(stopped) => CalcError::from(stopped),
            IntegralError::Integrand(never) => match never {},
        })?;
        ctx.report(
            integral
                .report
                .named("limiting_pressure_gauss_kronrod")
                .at(Level::ClosedForm)
                .with_error_estimate(Some(integral.error / integral.value.max(f64::MIN_POSITIVE))),
        );
        let pa = case.gas.ambient_pressure_pa;
        let radius = 0.5 * case.diameter;
        let w_over_plr = integral.value;
        let load = w_over_plr * pa * case.length * radius;
        let p_max = film.pressure(PI);
        ctx.warn(
            "limiting_load",
            "the limiting load is the ω → ∞ asymptote of an infinitely long film (no side leakage): a finite bearing at a finite speed carries less",
        );
        let rule_of_thumb_load_n = case.rule_of_thumb.map(|(rpm, coefficient)| {
            let (l_in, d_in) = (case.length / M_PER_IN, case.diameter / M_PER_IN);
            coefficient * (l_in * d_in) * (d_in * rpm / 1000.0) * N_PER_LBF
        });
        Ok(FoilJournalOutput {
            compliance: case.compliance,
            limiting_load_n: load,
            load_dimensionless: load / (pa * case.length * case.diameter),
            load_per_ambient_pressure_l_r: w_over_plr,
            attitude_angle_deg: 0.0,
            max_pressure_pa: p_max * pa,
            max_pressure_angle_deg: 180.0,
            min_film_m: case.clearance * film.film(PI),
            max_foil_deflection_m: case.compliance * case.clearance * (p_max - 1.0),
            rule_of_thumb_load_n,
        })
    }
}

#[cfg(test)]
#[path = "foil_journal_tests.rs"]
mod tests;
