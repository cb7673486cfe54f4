//! `POST /v1/thrust-bearings/fixed-pad`: one fixed (non-pivoted) pad — plane inclined (optionally
//! crowned), step, tapered land or parabolic — from its film or its load: film, friction, power, flows,
//! temperature rise and Table 7.2's coefficients (Khonsari & Booser ch. 6–7; Stachowiak &
//! Batchelor ch. 4).

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::operating::Conditions;
use super::pad::{self, RatioChoice};
use super::pad_spec::{
    self, check_finite, conditions, given, PadEffects, PadResult, PadSpec, PadTurbulenceModel,
};
use super::performance::{Method, RATIOS};
use super::profile::Profile;
use crate::calc::lubricant::LubricantSpec;
use crate::calc::quantity::{Celsius, Positive};
use crate::calc::range_schemas;
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::fidelity::{FidelityRequest, Level};

pub struct FixedPad;

/// A pad's film shape.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum PadProfileKind {
    /// Plane, tapered over the whole breadth (Table 7.2's pads).
    PlaneInclined,
    /// Rayleigh step at `step_position_fraction`.
    Step,
    /// Plane taper, then a flat land of `land_fraction` of B at the trailing edge.
    TaperedLand,
    /// h = h2 + (h1 − h2)(1 − x/B)², tangent to the runner at the trailing edge.
    Parabolic,
    /// Parallel faces: the texts' empirical rule (Khonsari & Booser Eq. 7.14), K_h =
    /// `flat_land_multiplier` × K_h of the 1.2 film-ratio plane pad, K_f = 1, K_q = 0.5; no
    /// film ratio.
    FlatLand,
}

/// The film ratio: a number, or `"optimum"`.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(
    untagged,
    expecting = "a film ratio h1/h2 (a number from 1.01 to 10) or \"optimum\""
)]
pub enum PadFilmRatio {
    /// h1/h2, 1.01 … 10 (from 1 on a crowned pad).
    Value(f64),
    /// The ratio that maximises the load at the given outlet film.
    Optimum(OptimumKeyword),
}

range_schemas::number_or_keyword_schema!(
    PadFilmRatio,
    OptimumKeyword,
    "The film ratio: a number, or `\"optimum\"`.",
    "h1/h2, 1.01 … 10 (from 1 on a crowned pad: `crown_m`).",
    range_schemas::Range {
        minimum: Some(1.0),
        exclusive_minimum: None,
        maximum: Some(10.0),
        exclusive_maximum: None,
    },
    "The ratio that maximises the load at the given outlet film."
);

/// The load-maximising value.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum OptimumKeyword {
    Optimum,
}

/// The pad's film shape along B (uniform across it).
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct PadProfileSpec {
    pub kind: PadProfileKind,
    /// h1/h2 (1.01 … 10; from 1, parallel edges, on a crowned pad), or `"optimum"`: the ratio
    /// that maximises the load for the given h2 and the shape's other proportions (not with a
    /// crown). Give this or `depth_m`.
    #[schema(example = 2.0)]
    pub film_ratio: Option<PadFilmRatio>,
    /// h1 − h2, m (1e-8 … 1e-2): the machined taper depth (or step height), instead of
    /// `film_ratio`. The film ratio then follows from the film: 1 + depth/h2, found with the
    /// load when the load is given (Khonsari & Booser §7.4's design iteration, Ex 7.1).
    #[schema(minimum = 1e-8, maximum = 1e-2, example = 0.00015)]
    pub depth_m: Option<f64>,
    /// `step`: the step's position, x/B from the leading edge (0.05 … 0.95; Archibald's
    /// optimum for a square pad 0.55, the long pad's 0.718).
    #[schema(minimum = 0.05, maximum = 0.95, example = 0.55)]
    pub step_position_fraction: Option<f64>,
    /// `tapered_land`: the flat land's share of B at the trailing edge (0 … 0.9; 0 is the plane
    /// pad; typical 0.2).
    #[schema(minimum = 0.0, maximum = 0.9, example = 0.2)]
    pub land_fraction: Option<f64>,
    /// `flat_land`: the multiplier on the 1.2 film-ratio plane pad's K_h (0.4 … 0.8; default
    /// 0.6, Ex 7.4): about 0.4 for small flat lands at low speed and load, 0.8 for a long
    /// breadth, high speed and load, where the thermal wedge is stronger (§7.8).
    #[schema(minimum = 0.4, maximum = 0.8, example = 0.6)]
    pub flat_land_multiplier: Option<f64>,
}

/// The flat land's default multiplier (Khonsari & Booser Ex 7.4).
const FLAT_LAND_MULTIPLIER: f64 = 0.6;

impl PadProfileSpec {
    /// The shape (with the ratio 2 standing in until a search or the film fixes it) and how its
    /// film ratio is chosen. A `crowned` pad is plane with its film ratio given, from 1.
    pub fn parse(self, crowned: bool, errors: &mut Vec<FieldError>) -> (Profile, RatioChoice) {
        if crowned && self.kind != PadProfileKind::PlaneInclined {
            errors.push(FieldError::new(
                "/profile/kind",
                "a crown (crown_m) is offered on a plane_inclined pad: h/h2 = a − (a − 1)x/B − 4(δ/h2)(x/B)(1 − x/B)",
            ));
        }
        if self.kind == PadProfileKind::FlatLand {
            return (self.flat_land(errors), RatioChoice::Given);
        }
        if self.flat_land_multiplier.is_some() {
            errors.push(FieldError::new(
                "/profile/flat_land_multiplier",
                "applies only to a flat_land profile",
            ));
        }
        let lowest = if crowned { 1.0 } else { RATIOS.0 };
        let (ratio, choice) = match (self.film_ratio, self.depth_m) {
            (Some(PadFilmRatio::Value(r)), None) if (lowest..=RATIOS.1).contains(&r) => {
                (r, RatioChoice::Given)
            }
            (Some(PadFilmRatio::Value(r)), None) => {
                errors.push(FieldError::new(
                    "/profile/film_ratio",
                    format!("must be within [{lowest}, 10] or \"optimum\", got {r}"),
                ));
                (2.0, RatioChoice::Given)
            }
            (Some(PadFilmRatio::Optimum(_)), None) if crowned => {
                errors.push(FieldError::new(
                    "/profile/film_ratio",
                    "a crowned pad takes its film ratio as a number (the load-maximising ratio depends on δ/h2)",
                ));
                (2.0, RatioChoice::Given)
            }
            (None, Some(_)) if crowned => {
                errors.push(FieldError::new(
                    "/profile/depth_m",
                    "a crowned pad takes its film ratio, not a depth",
                ));
                (2.0, RatioChoice::Given)
            }
            (Some(PadFilmRatio::Optimum(_)), None) => (2.0, RatioChoice::Optimum),
            (None, Some(d)) if d.is_finite() && (1e-8..=1e-2).contains(&d) => {
                (2.0, RatioChoice::Depth(d))
            }
            (None, Some(d)) => {
                errors.push(FieldError::new(
                    "/profile/depth_m",
                    format!("must be within [1e-8, 1e-2] m, got {d}"),
                ));
                (2.0, RatioChoice::Given)
            }
            _ => {
                errors.push(FieldError::new(
                    "/profile/film_ratio",
                    "give exactly one of film_ratio and depth_m",
                ));
                (2.0, RatioChoice::Given)
            }
        };
        let mut fraction = |name: &str, value: Option<f64>, range: (f64, f64), needed: bool| {
            let pointer = format!("/profile/{name}");
            match value {
                Some(v) if needed && (range.0..=range.1).contains(&v) => v,
                Some(v) if needed => {
                    errors.push(FieldError::new(
                        pointer,
                        format!("must be within [{}, {}], got {v}", range.0, range.1),
                    ));
                    range.0
                }
                Some(_) => {
                    errors.push(FieldError::new(
                        pointer,
                        format!("applies only to a {} profile", name_of(name)),
                    ));
                    range.0
                }
                None if needed => {
                    errors.push(FieldError::new(
                        pointer,
                        format!("a {} profile needs it", name_of(name)),
                    ));
                    range.0
                }
                None => range.0,
            }
        };
        let step = fraction(
            "step_position_fraction",
            self.step_position_fraction,
            (0.05, 0.95),
            self.kind == PadProfileKind::Step,
        );
        let land = fraction(
            "land_fraction",
            self.land_fraction,
            (0.0, 0.9),
            self.kind == PadProfileKind::TaperedLand,
        );
        let profile = match self.kind {
            PadProfileKind::PlaneInclined => Profile::PlaneInclined { ratio },
            PadProfileKind::Step => Profile::Step {
                ratio,
                step_position: step,
            },
            PadProfileKind::TaperedLand => Profile::TaperedLand {
                ratio,
                land_fraction: land,
            },
            PadProfileKind::Parabolic => Profile::Parabolic { ratio },
            PadProfileKind::FlatLand => unreachable!("parsed above"),
        };
        (profile, choice)
    }

    /// A flat land: parallel faces, only its multiplier.
    fn flat_land(self, errors: &mut Vec<FieldError>) -> Profile {
        let foreign = [
            ("film_ratio", self.film_ratio.is_some()),
            ("depth_m", self.depth_m.is_some()),
            (
                "step_position_fraction",
                self.step_position_fraction.is_some(),
            ),
            ("land_fraction", self.land_fraction.is_some()),
        ];
        for (name, given) in foreign {
            if given {
                errors.push(FieldError::new(
                    format!("/profile/{name}"),
                    "a flat_land profile has parallel faces: give only flat_land_multiplier",
                ));
            }
        }
        let multiplier = self.flat_land_multiplier.unwrap_or(FLAT_LAND_MULTIPLIER);
        if !(0.4..=0.8).contains(&multiplier) {
            errors.push(FieldError::new(
                "/profile/flat_land_multiplier",
                format!("must be within [0.4, 0.8] (the texts' range), got {multiplier}"),
            ));
        }
        Profile::FlatLand { multiplier }
    }
}

/// The warning a flat land's result carries: its numbers are the texts' empirical rule.
pub fn flat_land_warning(profile: Profile) -> Option<String> {
    match profile {
        Profile::FlatLand { multiplier } => Some(format!(
            "a flat land carries load only by a thermal wedge the isoviscous film does not model: its performance is the texts' empirical rule (Khonsari & Booser Eq. 7.14), K_h = {multiplier} × K_h of the 1.2 film-ratio plane pad, K_f = 1, K_q = 0.5 — an estimate, not a film solution"
        )),
        _ => None,
    }
}

fn name_of(field: &str) -> &'static str {
    if field == "step_position_fraction" {
        "step"
    } else {
        "tapered_land"
    }
}

/// Request. Give exactly one of `outlet_film_m` and `load_n`.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct FixedPadInput {
    pub pad: PadSpec,
    pub profile: PadProfileSpec,
    /// Runner speed U relative to the pad (at the mean radius on a thrust bearing), m/s
    /// (> 0, at most 500).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 500.0, example = 44.0)]
    pub sliding_speed_m_s: Positive,
    pub lubricant: LubricantSpec,
    /// Oil inlet temperature, °C (default 40).
    #[schema(value_type = Option<f64>, minimum = -273.0, maximum = 1000.0, example = 49.0)]
    pub inlet_temperature_c: Option<Celsius>,
    /// Trailing-edge film h2, m (1e-8 … 1e-2), instead of `load_n`.
    #[schema(value_type = Option<f64>, minimum = 1e-8, maximum = 1e-2, example = 3e-5)]
    pub outlet_film_m: Option<Positive>,
    /// Load on the pad W, N (1e-6 … 1e9), instead of `outlet_film_m`.
    #[schema(value_type = Option<f64>, minimum = 1e-6, maximum = 1e9, example = 16000.0)]
    pub load_n: Option<Positive>,
    /// Optional parabolic crown over the breadth of a `plane_inclined` pad, m (> 0, at most
    /// 1e-3): the pad's middle stands this far proud of the line through its edges, the
    /// tilting pad's crown (Khonsari & Booser §7.5). A crowned pad with parallel edges
    /// (`film_ratio` 1) carries load on its crown. Numerical fidelities only.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e-3, example = 1e-5)]
    pub crown_m: Option<Positive>,
    /// `closed_form` (the infinitely long pad, whatever L: no side leakage), `fast`,
    /// `standard` (default), `high`, or `{"grid": [cells along B 8…512, cells across half of L
    /// 2…256]}`. Levels and even grids are Richardson-extrapolated from the half mesh.
    #[serde(default)]
    pub fidelity: FidelityRequest,
    #[serde(default)]
    pub effects: PadEffects,
    /// The turbulent film's law where the turbulence effect applies: `ng_pan` (default) or
    /// `missana` (Khonsari & Booser §7.11's f = 0.026/Re^0.25 and effective viscosity).
    #[serde(default)]
    pub turbulence_model: PadTurbulenceModel,
    /// Include the mid-plane pressure profile (numerical fidelities; default false).
    #[serde(default)]
    #[schema(example = false)]
    pub include_field: bool,
}

/// The parsed request.
#[derive(Debug, Clone)]
pub struct Case {
    pub conditions: Conditions,
    pub profile: Profile,
    pub ratio: RatioChoice,
    /// The crown δ, m.
    pub crown_m: Option<f64>,
    pub method: Method,
    pub include_field: bool,
}

impl Validate for FixedPadInput {
    type Valid = Case;
    fn validate(self) -> Result<Case, Vec<FieldError>> {
        let mut errors = Vec::new();
        let pad = self.pad.parse(&mut errors);
        let (profile, ratio) = self.profile.parse(self.crown_m.is_some(), &mut errors);
        let given = given(self.outlet_film_m, self.load_n, true, &mut errors);
        let method = pad_spec::method(self.fidelity, &mut errors);
        let crown_m = pad_spec::crown(self.crown_m, "/crown_m", method, &mut errors);
        let conditions = conditions(
            pad,
            self.sliding_speed_m_s,
            self.lubricant,
            self.inlet_temperature_c,
            given,
            self.effects.with_law(self.turbulence_model),
            &mut errors,
        );
        match conditions {
            Some(conditions) if errors.is_empty() => Ok(Case {
                conditions,
                profile,
                ratio,
                crown_m,
                method,
                include_field: self.include_field,
            }),
            _ => Err(errors),
        }
    }
}

/// Response.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct FixedPadOutput {
    #[serde(flatten)]
    pub pad: PadResult,
}

impl Calculation for FixedPad {
    const PATH: &'static str = "/v1/thrust-bearings/fixed-pad";
    const SUMMARY: &'static str =
        "Fixed thrust pad (plane, step, tapered land, parabolic): film, friction, flows, temperature rise";
    const DESCRIPTION: &'static str = include_str!("fixed_pad.md");
    const FIDELITY: &'static [Level] =
        &[Level::ClosedForm, Level::Fast, Level::Standard, Level::High];
    const EFFECTS: &'static [&'static str] = &["thermal", "turbulence"];
    const EXAMPLE: &'static str = r#"{"pad": {"breadth_m": 0.089, "length_m": 0.087}, "profile": {"kind": "plane_inclined", "film_ratio": 2}, "sliding_speed_m_s": 44, "lubricant": {"iso_vg": 32}, "inlet_temperature_c": 49, "load_n": 16000}"#;

    type Input = FixedPadInput;
    type Output = FixedPadOutput;

    fn run(case: Case, ctx: &mut Context) -> Result<FixedPadOutput, CalcError> {
        let budget = ctx.budget();
        let solved = pad::fixed(
            case.profile,
            case.ratio,
            case.crown_m,
            case.method,
            &case.conditions,
            &budget,
        )?;
        ctx.record(&solved.operating.notes);
        if let Some(message) = flat_land_warning(case.profile) {
            ctx.warn("flat_land_empirical", message);
        }
        ctx.report(solved.report(case.method, &budget));
        let mid_plane = solved
            .evaluated
            .mid_plane
            .as_deref()
            .filter(|_| case.include_field);
        let pad = PadResult::new(&solved.operating, solved.ratio, mid_plane);
        check_finite(&pad)?;
        Ok(FixedPadOutput { pad })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::calc::testing::{invalid_pointers, ok, result_field, warning_codes};
    use serde_json::json;

    /// Ex 7.4's pad (B = 1.06 in, L = 0.625 in, U = 224 in/s, μ = 1.3e-6 reyn) at h2 = 5.6 μm.
    fn pad(profile: serde_json::Value) -> serde_json::Value {
        json!({"pad": {"breadth_m": 0.026924, "length_m": 0.015875}, "profile": profile,
               "sliding_speed_m_s": 5.6896, "lubricant": {"viscosity_pa_s": 8.963e-3},
               "outlet_film_m": 5.6e-6})
    }

    #[test]
    fn a_flat_land_is_the_plane_pads_k_h_times_its_multiplier_with_k_f_1_and_k_q_half() {
        let plane = ok::<FixedPad>(&pad(json!({"kind": "plane_inclined", "film_ratio": 1.2})));
        for m in [0.4, 0.6, 0.8] {
            let flat = ok::<FixedPad>(&pad(
                json!({"kind": "flat_land", "flat_land_multiplier": m}),
            ));
            let k =
                |v: &serde_json::Value, f: &str| v["result"]["coefficients"][f].as_f64().unwrap();
            assert!((k(&flat, "k_h") / (m * k(&plane, "k_h")) - 1.0).abs() < 1e-12);
            assert_eq!(k(&flat, "k_f"), 1.0);
            assert_eq!(k(&flat, "k_q"), 0.5);
            assert!(
                (result_field(&flat, "load_n") / (m * m * result_field(&plane, "load_n")) - 1.0)
                    .abs()
                    < 1e-12
            );
            // Parallel faces: h1 = h2.
            assert_eq!(result_field(&flat, "film_ratio"), 1.0);
            assert!(warning_codes(&flat).contains(&"flat_land_empirical".to_owned()));
        }
        assert!(!warning_codes(&plane).contains(&"flat_land_empirical".to_owned()));
    }

    #[test]
    fn a_flat_land_takes_no_film_ratio_and_its_multiplier_stays_in_the_texts_range() {
        let got =
            invalid_pointers::<FixedPad>(&pad(json!({"kind": "flat_land", "film_ratio": 1.2})));
        assert_eq!(got, ["/profile/film_ratio"]);
        let got = invalid_pointers::<FixedPad>(&pad(
            json!({"kind": "flat_land", "flat_land_multiplier": 0.9}),
        ));
        assert_eq!(got, ["/profile/flat_land_multiplier"]);
        let got = invalid_pointers::<FixedPad>(&pad(
            json!({"kind": "step", "film_ratio": 1.7, "step_position_fraction": 0.55, "flat_land_multiplier": 0.6}),
        ));
        assert_eq!(got, ["/profile/flat_land_multiplier"]);
    }
}
