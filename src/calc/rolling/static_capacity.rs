//! `POST /v1/rolling-bearings/static-capacity`: the basic static load rating C0 of a radial
//! ball or cylindrical roller bearing from its internal geometry (ISO 76), the static equivalent
//! load P0 and the static safety factor s0 = C0/P0 against the usual guideline values.
//!
//! Model.
//! - C0 is the static radial load that puts a Hertz contact pressure of 4200 MPa at the centre
//!   of the most heavily loaded ball–raceway contact of a radial ball bearing, where the total
//!   permanent deformation of ball and raceway is about 1e-4 of the ball diameter (Khonsari &
//!   Booser §13.10, RB-8; ISO 76:2006 §3.1, the same 4200 MPa quoted by Koyo's and Minebea's
//!   catalogues and UMBRA's ISO 76 summary — 4600 MPa for self-aligning ball bearings, which
//!   this room does not rate; 4000 MPa for roller bearings, below).
//! - The most loaded ball carries Q_max = 5 F_r/(Z cos α), the practical Stribeck rule with
//!   nominal clearance (Khonsari & Booser RI-6; ISO/TR 10657 derives ISO 76's f0 from it), so
//!   C0 = Z Q₀ cos α / 5 = f0 Z D² cos α with f0 = Q₀/(5 D²) and Q₀ the ball load at which the
//!   more highly stressed raceway contact reaches 4200 MPa.
//! - Q₀ comes from the exact Hertz point contact ([`crate::calc::contact::hertz`]) of a ball at
//!   the nominal contact angle α (0 for a deep-groove bearing: `free_contact_angle_deg`
//!   absent) on raceways with ISO 76's reference conformities r_i = 0.52 D, r_o = 0.53 D (the
//!   groove radii for which the standard's f0 is stated: "inner ring raceway groove radius not
//!   larger than 0.52 D_w, outer 0.53 D_w", also in NCK's C0 = f0 i Z D² cos α summary) and the
//!   bearing's own where they are looser (a looser groove raises the pressure, so the
//!   standard's f0 would overrate it). f0 then depends only on γ = D cos α/d_m. The steel is
//!   E = 207 GPa, ν = 0.3 for both bodies: ISO rates bearing steel whatever materials the
//!   request gives. **Verify:** with these constants the evaluation gives f0 = 14.73 at γ = 0,
//!   16.40 at γ = 0.10 and 13.95 at γ = 0.20, the values 14.7, 16.4 and 14.0 recalled from
//!   ISO 76's Table 2 for radial and angular-contact groove ball bearings; the table itself
//!   was not available to check. Independently, the texts' 6210 (Khonsari & Booser Table 13.5
//!   C = 35 700 N × Table 13.11 C0/C = 0.66 → C0 ≈ 23 560 N) is reproduced within 2 %.
//! - Cylindrical roller bearings by the same definition: 4000 MPa (ISO 76 for roller bearings,
//!   UMBRA's and Koyo's summaries) at the more stressed line contact of a roller carrying
//!   Q_max = 5 F_r/Z, on the effective length, steel as above: C0 = Z Q₀/5 =
//!   f0′ (1 − γ) Z L D with f0′ = Q₀/[5 L D (1 − γ)] = π p² (1 − ν²)/(5E) = 44.2 N/mm² at the
//!   inner raceway, the 44 of ISO 76's C0r = 44 (1 − D cos α/d_m) Z L D cos α (**verify**: the
//!   constant as recalled; the evaluation is the definition). P0 = F_r (X0 = 1, Y0 = 0).
//! - P0 = max(X0 F_r + Y0 F_a, F_r) (ISO 76; Minebea's JIS B 1519 summary). X0 = 0.6,
//!   Y0 = 0.5 for a radial-contact (deep-groove) bearing (Khonsari & Booser RB-8; SKF's Y-bearing
//!   page; Minebea). Single-row angular contact: X0 = 0.5 and Y0 by the nominal angle, 15°:
//!   0.46, 20°: 0.42, 25°: 0.38, 30°: 0.33, 35°: 0.29, 40°: 0.26, 45°: 0.22 (ISO 76 Table 4;
//!   15°, 25° and 40° checked against LYC's table, 30° against Khonsari & Booser RB-8's 0.33;
//!   20°, 35°, 45° **verify**), linear between; other angles need `x0_factor`, `y0_factor`.
//! - Guideline minimum s0 for ball bearings (SKF's table, as reproduced by bearing-centre.com;
//!   ISO 76 gives the same kind of guidance): rotating — smooth or normal operation 0.5 / 1 / 2
//!   for low / normal / high demands on quiet running, pronounced shock loads 1.5 / 1.5 / 2;
//!   non-rotating — 0.4 smooth, 0.5 normal, 1 with shock loads. Roller bearings: rotating
//!   1 / 1.5 / 3 smooth, 1 / 1.5 / 3.5 normal, 2.5 / 3 / 4 with shock loads; non-rotating 0.8,
//!   1, 2. Khonsari & Booser RB-8: up to
//!   4 C0 is tolerable where noise and some life loss are acceptable; about 8 C0 may fracture.

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use serde_json::Value;

use super::geometry::{BallBearing, BallBearingSpec};
use super::load_distribution::{parse_at, LoadDistributionBearing};
use super::roller::{RollerBearing, RollerBearingSpec, ROLLER_STATIC_LIMIT_PA};
use crate::calc::contact::hertz::{Body, Contact, Invalid, Method, Shape};
use crate::calc::quantity::{NonNegative, Positive};
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::fidelity::Level;

pub struct StaticCapacity;

/// ISO 76's contact pressure at C0 for (non-self-aligning) ball bearings, Pa.
pub const STATIC_RATING_PRESSURE_PA: f64 = 4.2e9;
/// Stribeck's practical factor: Q_max = 5 F_r/(Z cos α) with nominal clearance.
const STRIBECK_FACTOR: f64 = 5.0;
/// ISO 76's reference groove conformities r/D (inner, outer).
const REFERENCE_CONFORMITY: (f64, f64) = (0.52, 0.53);
/// The steel ISO rates: E, Pa, and ν.
const RATING_STEEL: (f64, f64) = (2.07e11, 0.3);
/// Largest load accepted, N.
const MAX_LOAD_N: f64 = 1e9;
/// Smallest non-zero load and rating accepted, N: below a micronewton s0 = C0/P0 leaves the
/// floating-point range for no engineering purpose.
const MIN_LOAD_N: f64 = 1e-6;
/// Smallest static equivalent load with a safety factor, N (keeps s0 finite for denormal loads).
const MIN_EQUIVALENT_LOAD_N: f64 = 1e-6;
/// Single-row angular-contact ball bearings: (nominal angle °, Y0), X0 = 0.5.
const ANGULAR_Y0: [(f64, f64); 7] = [
    (15.0, 0.46),
    (20.0, 0.42),
    (25.0, 0.38),
    (30.0, 0.33),
    (35.0, 0.29),
    (40.0, 0.26),
    (45.0, 0.22),
];

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

/// The validated case.
#[derive(Debug, Clone, Copy)]
pub struct StaticCapacityCase {
    ball_diameter_m: f64,
    pitch_diameter_m: f64,
    ball_count: usize,
    /// Nominal contact angle, rad.
    contact_angle: f64,
    /// Groove conformities the rating is evaluated at (ISO's or looser).
    conformity: (f64, f64),
    radial_load_n: f64,
    axial_load_n: f64,
    x0: f64,
    y0: f64,
    catalogue_rating_n: Option<f64>,
    rotating: bool,
    operation: StaticCapacityOperation,
    quiet_running: StaticCapacityQuietRunning,
    /// A cylindrical roller bearing: the effective roller length, m (ball_* then describe the
    /// rollers).
    roller_length_m: Option<f64>,
}

/// ISO 76's X0, Y0 for a single-row ball bearing at nominal angle `deg`, if tabulated.
fn iso_factors(deg: f64) -> Option<(f64, f64)> {
    if deg == 0.0 {
        return Some((0.6, 0.5));
    }
    ANGULAR_Y0.windows(2).find_map(|w| {
        let ((a0, y0), (a1, y1)) = (w[0], w[1]);
        (a0..=a1)
            .contains(&deg)
            .then(|| (0.5, y0 + (y1 - y0) * (deg - a0) / (a1 - a0)))
    })
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
                operation: self.operation,
                quiet_running: self.quiet_running,
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
                operation: self.operation,
                quiet_running: self.quiet_running,
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
    /// Ball (roller) load Q₀ that brings the more stressed raceway contact to 4200 MPa
    /// (4000 MPa for a roller), N.
    #[schema(example = 11600.0)]
    pub ball_load_at_rating_pressure_n: f64,
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
/// too).
pub(super) fn solve(
    case: &StaticCapacityCase,
    ctx: &mut Context,
) -> Result<StaticCapacityOutput, CalcError> {
    let d = case.ball_diameter_m;
    let cos = case.contact_angle.cos();
    let (inner, outer) = (
        rating_ball_load(case, true)?,
        rating_ball_load(case, false)?,
    );
    let (q0, governing) = if inner <= outer {
        (inner, "inner")
    } else {
        (outer, "outer")
    };
    let z = case.ball_count as f64;
    let c0 = z * q0 * cos / STRIBECK_FACTOR;
    let roller = case.roller_length_m;
    // Balls: f0 = Q₀/(5 D²); rollers: ISO's 44 = Q₀/(5 L D (1 − γ)), both in N/mm².
    let f0_n_m2 = match roller {
        None => q0 / (STRIBECK_FACTOR * d * d),
        Some(l) => q0 / (STRIBECK_FACTOR * l * d * (1.0 - d * cos / case.pitch_diameter_m)),
    };
    let (limit_pa, pressure_exponent) = match roller {
        None => (STATIC_RATING_PRESSURE_PA, 1.0 / 3.0),
        Some(_) => (ROLLER_STATIC_LIMIT_PA, 0.5),
    };
    let (f_r, f_a) = (case.radial_load_n, case.axial_load_n);
    let p0 = (case.x0 * f_r + case.y0 * f_a).max(f_r);
    if p0.is_nan() || p0 < MIN_EQUIVALENT_LOAD_N {
        return Err(CalcError::impossible(
                if f_r > 0.0 { "/radial_load_n" } else { "/axial_load_n" },
                format!(
                    "the static equivalent load P0 = max(X0 F_r + Y0 F_a, F_r) = {p0:e} N is below {MIN_EQUIVALENT_LOAD_N:e} N: s0 = C0/P0 would exceed any meaningful bound (with Y0 = 0 an axial load alone gives P0 = 0)"
                ),
            ));
    }
    let rating = case.catalogue_rating_n.unwrap_or(c0);
    let s0 = rating / p0;
    let minimum = guideline_minimum(
        roller.is_some(),
        case.rotating,
        case.operation,
        case.quiet_running,
    );
    warn_on(ctx, s0, minimum);
    Ok(StaticCapacityOutput {
        contact_angle_deg: case.contact_angle.to_degrees(),
        gamma: d * cos / case.pitch_diameter_m,
        static_rating_factor_f0: f0_n_m2 * 1e-6,
        rating_conformities: roller
            .is_none()
            .then_some([case.conformity.0, case.conformity.1]),
        ball_load_at_rating_pressure_n: q0,
        governing_raceway: governing,
        basic_static_load_rating_n: c0,
        rating_used_n: rating,
        x0_factor: case.x0,
        y0_factor: case.y0,
        equivalent_static_load_n: p0,
        static_safety_factor: s0,
        recommended_min_static_safety_factor: minimum,
        max_contact_pressure_pa: limit_pa * (p0 / rating).powf(pressure_exponent),
    })
}

/// Q₀ of one raceway: the ball load at which its exact Hertz pressure is 4200 MPa, from the
/// pressure at 1 N (p ∝ Q^⅓).
fn rating_ball_load(case: &StaticCapacityCase, inner: bool) -> Result<f64, CalcError> {
    let d = case.ball_diameter_m;
    if let Some(length) = case.roller_length_m {
        return rating_roller_load(case, length, inner);
    }
    let along = case.pitch_diameter_m / case.contact_angle.cos();
    let (rolling, groove) = if inner {
        (0.5 * (along - d), -case.conformity.0 * d)
    } else {
        (-0.5 * (along + d), -case.conformity.1 * d)
    };
    let body = |rx: f64, ry: f64| Body {
        radius_x_m: Some(rx),
        radius_y_m: Some(ry),
        modulus_pa: RATING_STEEL.0,
        poisson_ratio: RATING_STEEL.1,
    };
    let contact = Contact::new(
        [body(0.5 * d, 0.5 * d), body(rolling, groove)],
        1.0,
        Shape::Point,
        Method::Exact,
    );
    let what = format!(
        "the {} raceway's rating contact is not a Hertz point contact",
        if inner { "inner" } else { "outer" }
    );
    let unit = pressure_at_one_newton(contact, &what)?;
    Ok((STATIC_RATING_PRESSURE_PA / unit).powi(3))
}

/// Q₀ of a roller's line contact on one raceway (rating steel, effective length): the load at
/// which the Hertz pressure is 4000 MPa, from the pressure at 1 N (p ∝ Q^½).
fn rating_roller_load(
    case: &StaticCapacityCase,
    length: f64,
    inner: bool,
) -> Result<f64, CalcError> {
    let d = case.ball_diameter_m;
    let race = if inner {
        0.5 * (case.pitch_diameter_m - d)
    } else {
        -0.5 * (case.pitch_diameter_m + d)
    };
    let body = |r: f64| Body {
        radius_x_m: Some(r),
        radius_y_m: None,
        modulus_pa: RATING_STEEL.0,
        poisson_ratio: RATING_STEEL.1,
    };
    let contact = Contact::new(
        [body(0.5 * d), body(race)],
        1.0,
        Shape::Line { length_m: length },
        Method::Exact,
    );
    let unit = pressure_at_one_newton(
        contact,
        "a roller's rating contact is not a Hertz line contact",
    )?;
    Ok((ROLLER_STATIC_LIMIT_PA / unit).powi(2))
}

/// The Hertz model's maximum pressure for `contact` (loaded with 1 N), Pa; a contact the model
/// refuses is a 422 on the bearing saying `what` and why. The model's warnings are not passed
/// on (the rating contact is ISO's reference, not the user's).
fn pressure_at_one_newton(
    contact: Result<Contact, Vec<Invalid>>,
    what: &str,
) -> Result<f64, CalcError> {
    let contact = contact.map_err(|errors| Invalid::refusal(errors, "/bearing", what))?;
    Ok(contact.solve()?.max_pressure_pa)
}

/// The guideline minimum s0 (SKF's table; see the module doc): ball or roller bearings.
fn guideline_minimum(
    roller: bool,
    rotating: bool,
    operation: StaticCapacityOperation,
    quiet: StaticCapacityQuietRunning,
) -> f64 {
    use StaticCapacityOperation as O;
    use StaticCapacityQuietRunning as Q;
    if !rotating {
        return match (operation, roller) {
            (O::Smooth, false) => 0.4,
            (O::Normal, false) => 0.5,
            (O::Shock, false) => 1.0,
            (O::Smooth, true) => 0.8,
            (O::Normal, true) => 1.0,
            (O::Shock, true) => 2.0,
        };
    }
    match (operation, quiet, roller) {
        (O::Shock, Q::Unimportant, false) | (O::Shock, Q::Normal, false) => 1.5,
        (O::Shock, Q::High, false) => 2.0,
        (_, Q::Unimportant, false) => 0.5,
        (_, Q::Normal, false) => 1.0,
        (_, Q::High, false) => 2.0,
        (O::Shock, Q::Unimportant, true) => 2.5,
        (O::Shock, Q::Normal, true) => 3.0,
        (O::Shock, Q::High, true) => 4.0,
        (_, Q::Unimportant, true) => 1.0,
        (_, Q::Normal, true) => 1.5,
        (O::Smooth, Q::High, true) => 3.0,
        (O::Normal, Q::High, true) => 3.5,
    }
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
