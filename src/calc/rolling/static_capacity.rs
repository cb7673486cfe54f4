//! `POST /v1/rolling-bearings/static-capacity`: the basic static load rating C0 of a radial
//! ball or cylindrical roller bearing from its internal geometry (ISO 76), the static equivalent
//! load P0 and the static safety factor s0 = C0/P0 against the usual guideline values.
//!
//! The model (the rating, its constants and sources) is `iso76.rs`; this file turns the request
//! into its validated case and its rating into the response, with the warnings.

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use serde_json::Value;

use super::bearing_spec::{BallBearingSpec, RollerBearingSpec};
use super::geometry::BallBearing;
use super::iso76::{
    self, iso_factors, Operation, QuietRunning, StaticCapacityCase, REFERENCE_CONFORMITY,
};
use super::load_distribution::{parse_at, LoadDistributionBearing};
use super::roller::RollerBearing;
use crate::calc::quantity::{NonNegative, Positive};
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::fidelity::Level;

pub struct StaticCapacity;

/// Largest load accepted, N.
const MAX_LOAD_N: f64 = 1e9;
/// Smallest non-zero load and rating accepted, N: below a micronewton s0 = C0/P0 leaves the
/// floating-point range for no engineering purpose.
const MIN_LOAD_N: f64 = 1e-6;

/// How the bearing runs while the static load acts (for the guideline s0).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum StaticCapacityOperation {
    /// Smooth, vibration-free.
    Smooth,
    /// Normal operation (default).
    #[default]
    Normal,
    /// Pronounced shock loads (of unknown size: the guideline is a lower bound).
    Shock,
}

/// Demands on quiet, vibration-free running.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum StaticCapacityQuietRunning {
    Unimportant,
    #[default]
    Normal,
    High,
}

/// Request.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct StaticCapacityInput {
    /// The bearing (as for `/v1/rolling-bearings/load-distribution`): a ball bearing, whose
    /// nominal contact angle is `free_contact_angle_deg` (absent: deep groove, α = 0), or a
    /// cylindrical roller bearing (rated on its effective length, crown ignored).
    #[schema(value_type = LoadDistributionBearing)]
    pub bearing: Value,
    /// Static radial load F_r, N: 0 or 1e-6 … 1e9 (the largest that acts, shocks included).
    #[schema(value_type = f64, minimum = 0.0, maximum = 1e9, example = 3000.0)]
    pub radial_load_n: NonNegative,
    /// Static axial load F_a, N: 0 or 1e-6 … 1e9 (default 0).
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 1e9, example = 1000.0)]
    pub axial_load_n: Option<NonNegative>,
    /// Radial factor X0 of P0 = X0 F_r + Y0 F_a, dimensionless, 0 or 1e-6 … 10 (with `y0_factor`;
    /// default by ISO 76 for the bearing's nominal angle).
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 10.0, example = 0.6)]
    pub x0_factor: Option<NonNegative>,
    /// Axial factor Y0, dimensionless, 0 or 1e-6 … 10 (with `x0_factor`).
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 10.0, example = 0.5)]
    pub y0_factor: Option<NonNegative>,
    /// A catalogue C0r, N (1e-6 … 1e10), to use for s0 instead of the computed rating (both are
    /// reported).
    #[schema(value_type = Option<f64>, minimum = 1e-6, maximum = 1e10, example = 23200.0)]
    pub static_load_rating_n: Option<Positive>,
    /// Whether the bearing rotates under the load (default true).
    #[schema(example = true)]
    pub rotating: Option<bool>,
    /// `smooth`, `normal` (default) or `shock`.
    #[serde(default)]
    pub operation: StaticCapacityOperation,
    /// Demands on quiet running: `unimportant`, `normal` (default) or `high` (rotating bearings).
    #[serde(default)]
    pub quiet_running: StaticCapacityQuietRunning,
}
impl From<StaticCapacityOperation> for Operation {
    fn from(o: StaticCapacityOperation) -> Self {
        match o {
            StaticCapacityOperation::Smooth => Operation::Smooth,
            StaticCapacityOperation::Normal => Operation::Normal,
            StaticCapacityOperation::Shock => Operation::Shock,
        }
    }
}

impl From<StaticCapacityQuietRunning> for QuietRunning {
    fn from(q: StaticCapacityQuietRunning) -> Self {
        match q {
            StaticCapacityQuietRunning::Unimportant => QuietRunning::Unimportant,
            StaticCapacityQuietRunning::Normal => QuietRunning::Normal,
            StaticCapacityQuietRunning::High => QuietRunning::High,
        }
    }
}

/// The request's loads and operation, typed: everything but the bearing. The pointers of its
/// errors are the static-capacity request's, which the analysis request shares.
#[derive(Debug, Clone, Copy)]
pub(super) struct StaticLoading {
    pub radial_load_n: NonNegative,
    pub axial_load_n: Option<NonNegative>,
    pub x0_factor: Option<NonNegative>,
    pub y0_factor: Option<NonNegative>,
    pub static_load_rating_n: Option<Positive>,
    pub rotating: Option<bool>,
    pub operation: StaticCapacityOperation,
    pub quiet_running: StaticCapacityQuietRunning,
}

impl Validate for StaticCapacityInput {
    type Valid = StaticCapacityCase;
    fn validate(self) -> Result<StaticCapacityCase, Vec<FieldError>> {
        let loading = StaticLoading {
            radial_load_n: self.radial_load_n,
            axial_load_n: self.axial_load_n,
            x0_factor: self.x0_factor,
            y0_factor: self.y0_factor,
            static_load_rating_n: self.static_load_rating_n,
            rotating: self.rotating,
            operation: self.operation,
            quiet_running: self.quiet_running,
        };
        if self.bearing.get("roller_diameter_m").is_some() {
            return loading.roller(
                parse_at::<RollerBearingSpec>(self.bearing, "/bearing")
                    .and_then(|b| b.validate_at("/bearing")),
            );
        }
        let spec = parse_at::<BallBearingSpec>(self.bearing, "/bearing");
        let deg = spec
            .as_ref()
            .ok()
            .and_then(|b| b.free_contact_angle_deg)
            .unwrap_or(0.0);
        loading.ball(deg, spec.and_then(|b| b.validate_at("/bearing")))
    }
}

impl StaticLoading {
    /// A ball bearing's case at its nominal contact angle `deg`, degrees.
    pub(super) fn ball(
        self,
        deg: f64,
        bearing: Result<BallBearing, Vec<FieldError>>,
    ) -> Result<StaticCapacityCase, Vec<FieldError>> {
        let mut errors = bearing.as_ref().err().cloned().unwrap_or_default();
        let f_r = self.radial_load_n.get();
        let f_a = self.axial_load_n.map_or(0.0, NonNegative::get);
        for (f, pointer) in [(f_r, "/radial_load_n"), (f_a, "/axial_load_n")] {
            if f > MAX_LOAD_N || (f > 0.0 && f < MIN_LOAD_N) {
                errors.push(FieldError::new(
                    pointer,
                    format!("must be 0 or within [{MIN_LOAD_N:e}, {MAX_LOAD_N:e}] N, got {f}"),
                ));
            }
        }
        if f_r == 0.0 && f_a == 0.0 {
            errors.push(FieldError::new(
                "/radial_load_n",
                "give a radial or an axial load: s0 = C0/P0 needs P0 > 0",
            ));
        }
        if let Some(c0) = self.static_load_rating_n {
            if !(MIN_LOAD_N..=1e10).contains(&c0.get()) {
                errors.push(FieldError::new(
                    "/static_load_rating_n",
                    format!("must be within [{MIN_LOAD_N:e}, 1e10] N, got {}", c0.get()),
                ));
            }
        }
        let factors = match (self.x0_factor, self.y0_factor) {
            (Some(x), Some(y)) => {
                for (v, pointer) in [(x.get(), "/x0_factor"), (y.get(), "/y0_factor")] {
                    if v > 10.0 || (v > 0.0 && v < 1e-6) {
                        errors.push(FieldError::new(
                            pointer,
                            format!("must be 0 or within [1e-6, 10], got {v}"),
                        ));
                    }
                }
                if x.get() == 0.0 && y.get() == 0.0 {
                    errors.push(FieldError::new("/x0_factor", "X0 and Y0 cannot both be 0"));
                }
                Some((x.get(), y.get()))
            }
            (None, None) => {
                let f = iso_factors(deg);
                if f.is_none() && deg.is_finite() {
                    errors.push(FieldError::new(
                        "/x0_factor",
                        format!(
                            "ISO 76 tabulates X0, Y0 for deep-groove bearings (α = 0) and single-row angular-contact bearings of 15°–45°; give x0_factor and y0_factor for a nominal angle of {deg}°"
                        ),
                    ));
                }
                f
            }
            (Some(_), None) => {
                errors.push(FieldError::new(
                    "/y0_factor",
                    "give y0_factor with x0_factor",
                ));
                None
            }
            (None, Some(_)) => {
                errors.push(FieldError::new(
                    "/x0_factor",
                    "give x0_factor with y0_factor",
                ));
                None
            }
        };
        match (bearing, factors) {
            (Ok(b), Some((x0, y0))) if errors.is_empty() => Ok(StaticCapacityCase {
                ball_diameter_m: b.ball_diameter_m,
                pitch_diameter_m: b.pitch_diameter_m,
                ball_count: b.ball_count,
                contact_angle: deg.to_radians(),
                conformity: (
                    b.inner_conformity.max(REFERENCE_CONFORMITY.0),
                    b.outer_conformity.max(REFERENCE_CONFORMITY.1),
                ),
                radial_load_n: f_r,
                axial_load_n: f_a,
                x0,
                y0,
                catalogue_rating_n: self.static_load_rating_n.map(Positive::get),
                rotating: self.rotating.unwrap_or(true),
                operation: self.operation.into(),
                quiet_running: self.quiet_running.into(),
                roller_length_m: None,
            }),
            _ => Err(errors),
        }
    }
}

impl StaticLoading {
    /// A radial cylindrical roller bearing: P0 = F_r (X0 = 1, Y0 = 0, ISO 76 for α = 0), no
    /// axial load.
    pub(super) fn roller(
        self,
        bearing: Result<RollerBearing, Vec<FieldError>>,
    ) -> Result<StaticCapacityCase, Vec<FieldError>> {
        let mut errors = bearing.as_ref().err().cloned().unwrap_or_default();
        let f_r = self.radial_load_n.get();
        if f_r > MAX_LOAD_N || (f_r > 0.0 && f_r < MIN_LOAD_N) {
            errors.push(FieldError::new(
                "/radial_load_n",
                format!("must be within [{MIN_LOAD_N:e}, {MAX_LOAD_N:e}] N, got {f_r}"),
            ));
        }
        if f_r == 0.0 {
            errors.push(FieldError::new(
                "/radial_load_n",
                "give a radial load: s0 = C0/P0 needs P0 = F_r > 0",
            ));
        }
        if self.axial_load_n.is_some_and(|f| f.get() > 0.0) {
            errors.push(FieldError::new(
                "/axial_load_n",
                "a cylindrical roller bearing (N, NU type) is rated for radial load only: give 0",
            ));
        }
        for (v, pointer) in [
            (self.x0_factor, "/x0_factor"),
            (self.y0_factor, "/y0_factor"),
        ] {
            if v.is_some() {
                errors.push(FieldError::new(
                    pointer,
                    "a radial cylindrical roller bearing has P0 = F_r (X0 = 1, Y0 = 0): omit the factors",
                ));
            }
        }
        if let Some(c0) = self.static_load_rating_n {
            if !(MIN_LOAD_N..=1e10).contains(&c0.get()) {
                errors.push(FieldError::new(
                    "/static_load_rating_n",
                    format!("must be within [{MIN_LOAD_N:e}, 1e10] N, got {}", c0.get()),
                ));
            }
        }
        match bearing {
            Ok(b) if errors.is_empty() => Ok(StaticCapacityCase {
                ball_diameter_m: b.roller_diameter_m,
                pitch_diameter_m: b.pitch_diameter_m,
                ball_count: b.roller_count,
                contact_angle: 0.0,
                conformity: (0.0, 0.0),
                radial_load_n: f_r,
                axial_load_n: 0.0,
                x0: 1.0,
                y0: 0.0,
                catalogue_rating_n: self.static_load_rating_n.map(Positive::get),
                rotating: self.rotating.unwrap_or(true),
                operation: self.operation.into(),
                quiet_running: self.quiet_running.into(),
                roller_length_m: Some(b.length_m),
            }),
            _ => Err(errors),
        }
    }
}

/// Result.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct StaticCapacityOutput {
    /// Nominal contact angle α the rating uses, degrees (0 for a deep-groove bearing).
    #[schema(example = 0.0)]
    pub contact_angle_deg: f64,
    /// γ = D cos α/d_m, dimensionless.
    #[schema(example = 0.1814)]
    pub gamma: f64,
    /// ISO 76's factor for this γ, N/mm² (as the standard states it): for a ball bearing
    /// f0 = Q₀/(5 D²) at the conformities used (about 12–17 for groove ball bearings); for a
    /// roller bearing f0′ = Q₀/[5 L D (1 − γ)] (about 44).
    #[schema(example = 14.4)]
    pub static_rating_factor_f0: f64,
    /// Inner and outer groove conformities r/D the rating is evaluated at: ISO's 0.52 and 0.53,
    /// or the bearing's own where looser.
    /// Absent for a roller bearing.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = json!([0.52, 0.53]))]
    pub rating_conformities: Option<[f64; 2]>,
    /// Rolling-element (ball or roller) load Q₀ that brings the more stressed raceway contact
    /// to 4200 MPa (4000 MPa for a roller), N.
    #[schema(example = 11600.0)]
    pub element_load_at_rating_pressure_n: f64,
    /// Which raceway reaches the rating pressure first: `inner` or `outer`.
    #[schema(example = "inner")]
    pub governing_raceway: &'static str,
    /// Basic static radial load rating, N (ISO 76, bearing steel): C0r = f0 Z D² cos α for a
    /// ball bearing, f0′ (1 − γ) Z L D for a cylindrical roller bearing.
    #[schema(example = 23200.0)]
    pub basic_static_load_rating_n: f64,
    /// The rating s0 is computed with: the catalogue's `static_load_rating_n` when given, else
    /// `basic_static_load_rating_n`, N.
    #[schema(example = 23200.0)]
    pub rating_used_n: f64,
    /// X0, dimensionless.
    #[schema(example = 0.6)]
    pub x0_factor: f64,
    /// Y0, dimensionless.
    #[schema(example = 0.5)]
    pub y0_factor: f64,
    /// Static equivalent radial load P0 = max(X0 F_r + Y0 F_a, F_r), N.
    #[schema(example = 3000.0)]
    pub equivalent_static_load_n: f64,
    /// Static safety factor s0 = C0/P0, dimensionless (ISO 76's; the load-distribution room's
    /// `static_safety_factor` is the different (4200 MPa/p_max)³ at the solved ball loads).
    #[schema(example = 7.7)]
    pub static_safety_factor: f64,
    /// Guideline minimum s0 for the stated operation and bearing kind, dimensionless.
    #[schema(example = 1.0)]
    pub recommended_min_static_safety_factor: f64,
    /// Contact pressure at the centre of the most loaded contact under P0, 4200 MPa·(P0/C0)^⅓
    /// (p ∝ Q^⅓), Pa.
    #[schema(example = 2.1e9)]
    pub max_contact_pressure_pa: f64,
    /// Deprecated: `element_load_at_rating_pressure_n` under its name of release 0.1. Sent until
    /// the next release, then removed.
    #[schema(deprecated, example = 11600.0)]
    pub ball_load_at_rating_pressure_n: f64,
}

impl Calculation for StaticCapacity {
    const PATH: &'static str = "/v1/rolling-bearings/static-capacity";
    const SUMMARY: &'static str =
        "Static capacity of ball and cylindrical roller bearings: ISO 76 basic static load rating C0, static equivalent load P0 and safety factor s0";
    const DESCRIPTION: &'static str = include_str!("static_capacity.md");
    const FIDELITY: &'static [Level] = &[Level::ClosedForm];
    const EFFECTS: &'static [&'static str] = &[];
    const EXAMPLE: &'static str = r#"{"bearing": {"ball_diameter_m": 0.0127, "pitch_diameter_m": 0.07, "ball_count": 10, "inner_groove_radius_m": 0.0066, "outer_groove_radius_m": 0.0066, "diametral_clearance_m": 1.8e-5, "ball": {"elastic_modulus_pa": 2.08e11, "poisson_ratio": 0.3}, "rings": {"elastic_modulus_pa": 2.08e11, "poisson_ratio": 0.3}}, "radial_load_n": 3000, "axial_load_n": 1000}"#;

    type Input = StaticCapacityInput;
    type Output = StaticCapacityOutput;

    fn run(case: StaticCapacityCase, ctx: &mut Context) -> Result<StaticCapacityOutput, CalcError> {
        solve(&case, ctx)
    }
}

/// The rating and safety factor of a validated case (the room's answer; the analysis calls it
/// too): the model's rating, with its warnings, as the response.
pub(super) fn solve(
    case: &StaticCapacityCase,
    ctx: &mut Context,
) -> Result<StaticCapacityOutput, CalcError> {
    let r = iso76::rate(case)?;
    warn_on(
        ctx,
        r.static_safety_factor,
        r.recommended_min_static_safety_factor,
    );
    Ok(StaticCapacityOutput {
        contact_angle_deg: r.contact_angle_deg,
        gamma: r.gamma,
        static_rating_factor_f0: r.static_rating_factor_f0,
        rating_conformities: r.rating_conformities,
        element_load_at_rating_pressure_n: r.element_load_at_rating_pressure_n,
        governing_raceway: r.governing_raceway.name(),
        basic_static_load_rating_n: r.basic_static_load_rating_n,
        rating_used_n: r.rating_used_n,
        x0_factor: r.x0_factor,
        y0_factor: r.y0_factor,
        equivalent_static_load_n: r.equivalent_static_load_n,
        static_safety_factor: r.static_safety_factor,
        recommended_min_static_safety_factor: r.recommended_min_static_safety_factor,
        max_contact_pressure_pa: r.max_contact_pressure_pa,
        ball_load_at_rating_pressure_n: r.element_load_at_rating_pressure_n,
    })
}

fn warn_on(ctx: &mut Context, s0: f64, minimum: f64) {
    if s0 < 0.125 {
        ctx.warn(
            "static_load_may_fracture",
            format!(
                "P0 is {:.1} C0: about 8 C0 may fracture rings or balls (Khonsari & Booser §13.10)",
                1.0 / s0
            ),
        );
    } else if s0 < 0.25 {
        ctx.warn(
            "static_load_beyond_4_c0",
            format!(
                "P0 is {:.2} C0, beyond the 4 C0 the texts accept even where noise and some life loss are tolerable (Khonsari & Booser §13.10)",
                1.0 / s0
            ),
        );
    } else if s0 < 1.0 {
        ctx.warn(
            "static_load_above_c0",
            format!(
                "s0 = {s0:.3} < 1: P0 exceeds C0 and the permanent deformation exceeds 1e-4 D; tolerable only where noise and smooth running do not matter (up to 4 C0, Khonsari & Booser §13.10)"
            ),
        );
    }
    if s0 < minimum {
        ctx.warn(
            "static_safety_below_guideline",
            format!(
                "s0 = {s0:.3} is below the guideline minimum {minimum} for this bearing kind in this operation (ISO 76 / SKF guideline values)"
            ),
        );
    }
}

#[cfg(test)]
#[path = "static_capacity_tests.rs"]
mod tests;
