//! `POST /v1/thrust-bearings/tilting-pad`: one pivoted (tilting) plane pad under its load — the
//! tilt at which the film's centre of pressure lies on the pivot, then film, friction, flows
//! and temperature rise as for a fixed pad (Khonsari & Booser §7.5; Stachowiak & Batchelor
//! §4.3, Table 4.2); optionally crowned, which lets a central pivot carry load.

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::fixed_pad::OptimumKeyword;
use super::operating::Conditions;
use super::pad;
use super::pad_spec::{
    self, check_finite, conditions, given, PadEffects, PadResult, PadSpec, PadTurbulenceModel,
};
use super::performance::Method;
use super::pivot::Pivot;
use super::profile::Profile;
use crate::calc::lubricant::LubricantSpec;
use crate::calc::quantity::{Celsius, Positive};
use crate::calc::range_schemas;
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::fidelity::{FidelityRequest, Level};

pub struct TiltingPad;

/// Where the pivot is: a number, or `"optimum"`.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(
    untagged,
    expecting = "a pivot position x/B from the leading edge (a number above 0.5, at most 0.95) or \"optimum\""
)]
pub enum PivotPosition {
    /// x/B from the leading edge.
    Value(f64),
    /// Where the centre of pressure lies at the load-maximising film ratio (about 0.58).
    Optimum(OptimumKeyword),
}

range_schemas::number_or_keyword_schema!(
    PivotPosition,
    OptimumKeyword,
    "Where the pivot is: a number, or `\"optimum\"`.",
    "x/B from the leading edge, within (0, 0.95] (a flat pad carries load above 0.5, a crowned one from 0.5).",
    range_schemas::Range {
        minimum: None,
        exclusive_minimum: Some(0.0),
        maximum: Some(0.95),
        exclusive_maximum: None,
    },
    "Where the centre of pressure lies at the load-maximising film ratio (about 0.58)."
);

/// Request.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct TiltingPadInput {
    pub pad: PadSpec,
    /// The pivot's position along B, a fraction from the leading edge (above 0.5 … 0.95), or
    /// `"optimum"`. A flat pad pivoted at or ahead of mid-pad carries no load in the isoviscous
    /// film: refused with the reason; a crowned pad (`crown_m`) carries load on a central pivot.
    #[schema(example = 0.6)]
    pub pivot_position_fraction: PivotPosition,
    /// Runner speed U relative to the pad, m/s (> 0, at most 500).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 500.0, example = 44.0)]
    pub sliding_speed_m_s: Positive,
    pub lubricant: LubricantSpec,
    /// Oil inlet temperature, °C (default 40).
    #[schema(value_type = Option<f64>, minimum = -273.0, maximum = 1000.0, example = 49.0)]
    pub inlet_temperature_c: Option<Celsius>,
    /// Load on the pad W, N (1e-6 … 1e9).
    #[schema(value_type = f64, minimum = 1e-6, maximum = 1e9, example = 16000.0)]
    pub load_n: Positive,
    /// Optional parabolic crown over the breadth, m (> 0, at most 1e-3): the pad's middle stands
    /// this far proud of the line through its edges (Khonsari & Booser §7.5: 0.5–2 times the
    /// minimum film lets a centrally pivoted pad carry load). Numerical fidelities only.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e-3, example = 2e-5)]
    pub crown_m: Option<Positive>,
    /// `closed_form` (the infinitely long pad), `fast`, `standard` (default), `high`, or
    /// `{"grid": [cells along B 8…512, cells across half of L 2…256]}`.
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
    pub pivot: Pivot,
    /// The crown δ, m.
    pub crown_m: Option<f64>,
    pub method: Method,
    pub include_field: bool,
}

impl Validate for TiltingPadInput {
    type Valid = Case;
    fn validate(self) -> Result<Case, Vec<FieldError>> {
        let mut errors = Vec::new();
        let pad = self.pad.parse(&mut errors);
        let pivot = match self.pivot_position_fraction {
            PivotPosition::Value(x) if x.is_finite() && x > 0.0 && x <= 0.95 => Pivot::At(x),
            PivotPosition::Value(x) => {
                errors.push(FieldError::new(
                    "/pivot_position_fraction",
                    format!("must be within (0, 0.95] of B from the leading edge (above 0.5 to carry load), got {x}"),
                ));
                Pivot::Optimum
            }
            PivotPosition::Optimum(_) => Pivot::Optimum,
        };
        let given = given(None, Some(self.load_n), false, &mut errors);
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
                pivot,
                crown_m,
                method,
                include_field: self.include_field,
            }),
            _ => Err(errors),
        }
    }
}

/// Response: the pad's equilibrium, then everything a fixed pad reports.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct TiltingPadOutput {
    /// The pivot, x/B from the leading edge (resolved when `"optimum"` was asked).
    pub pivot_position_fraction: f64,
    /// Film at the pivot, m.
    pub pivot_film_m: f64,
    /// The thinnest film, m: the trailing-edge film but on a crowned pad whose crown outweighs
    /// its tilt.
    pub minimum_film_m: f64,
    /// The pad's tilt (h1 − h2)/B, rad.
    pub tilt_rad: f64,
    /// d(h1/h2)/d(x_p/B): how the film ratio moves with the pivot (a crowned pad's at its
    /// crown-to-film ratio held).
    pub film_ratio_per_pivot_fraction: f64,
    /// dh2/d(x_p/B) at this load, m: how the trailing-edge film moves with the pivot (a
    /// crowned pad's at its crown-to-film ratio held).
    pub outlet_film_per_pivot_fraction_m: f64,
    #[serde(flatten)]
    pub pad: PadResult,
}

impl Calculation for TiltingPad {
    const PATH: &'static str = "/v1/thrust-bearings/tilting-pad";
    const SUMMARY: &'static str =
        "Tilting (pivoted) thrust pad: pivot equilibrium, film, friction, flows, temperature rise";
    const DESCRIPTION: &'static str = include_str!("tilting_pad.md");
    const FIDELITY: &'static [Level] =
        &[Level::ClosedForm, Level::Fast, Level::Standard, Level::High];
    const EFFECTS: &'static [&'static str] = &["thermal", "turbulence"];
    const EXAMPLE: &'static str = r#"{"pad": {"breadth_m": 0.089, "length_m": 0.087}, "pivot_position_fraction": 0.6, "sliding_speed_m_s": 44, "lubricant": {"iso_vg": 32}, "inlet_temperature_c": 49, "load_n": 16000}"#;

    type Input = TiltingPadInput;
    type Output = TiltingPadOutput;

    fn run(case: Case, ctx: &mut Context) -> Result<TiltingPadOutput, CalcError> {
        let budget = ctx.budget();
        let solved = pad::tilting(
            case.pivot,
            case.crown_m,
            case.method,
            &case.conditions,
            &budget,
        )?;
        ctx.record(&solved.operating.notes);
        ctx.report(solved.report(case.method, &budget));
        let mid_plane = solved
            .evaluated
            .mid_plane
            .as_deref()
            .filter(|_| case.include_field);
        let result = PadResult::new(&solved.operating, solved.ratio, mid_plane);
        check_finite(&result)?;
        let eq = solved
            .equilibrium
            .as_ref()
            .expect("a tilting pad's equilibrium");
        let h2 = solved.operating.outlet_film_m;
        // At a fixed load h2 ∝ √W̄, so dh2/da = h2 (dW̄/da)/(2 W̄).
        let per_pivot = 0.5 * h2 * eq.load_slope * eq.ratio_per_pivot;
        let profile = match case.crown_m {
            Some(crown) => Profile::Crowned {
                ratio: eq.ratio,
                crown: crown / h2,
            },
            None => Profile::PlaneInclined { ratio: eq.ratio },
        };
        Ok(TiltingPadOutput {
            pivot_position_fraction: eq.pivot,
            pivot_film_m: h2 * profile.thickness(eq.pivot),
            minimum_film_m: h2 * profile.minimum(),
            tilt_rad: (eq.ratio - 1.0) * h2 / case.conditions.pad.breadth_m,
            film_ratio_per_pivot_fraction: eq.ratio_per_pivot,
            outlet_film_per_pivot_fraction_m: per_pivot,
            pad: result,
        })
    }
}
