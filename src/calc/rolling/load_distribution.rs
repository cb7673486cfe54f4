//! `POST /v1/rolling-bearings/load-distribution`: how a ball bearing shares a combined radial
//! and axial load among its balls — the quasi-static equilibrium of the inner ring against a
//! fixed outer ring, every ball summed discretely, with the exact Hertz contacts of the most
//! loaded ball.
//!
//! Model (Harris; Hamrock's handbook §21.3.6; Khonsari & Booser §14.4, RI-6). Rigid rings, ball
//! j at azimuth ψ_j = 2πj/Z (ψ = 0 on the radial load line). The ring moves by δ_r along the
//! load line and δ_a axially; the groove curvature centres of ball j are then
//! - `varying` (default): A_j = √[(a₀ + δ_a)² + (r₀ + δ_r cos ψ_j)²] apart, the contact angle
//!   following from sin α_j = (a₀ + δ_a)/A_j (with r₀ = BD cos α₀, a₀ = BD sin α₀ this is
//!   Harris's A_j = √[(BD sin α₀ + δ_a)² + (BD cos α₀ + δ_r cos ψ_j)²]);
//! - `fixed`: the same distance linearised about the unloaded position,
//!   A_j = A₀ + δ_a sin α_f + δ_r cos α_f cos ψ_j, every contact at the free angle α_f (the
//!   classic δ_ψ = δ_a sin α + δ_r cos α cos ψ, Khonsari eq. 14.21; A₀ − BD is the preload).
//!
//! (r₀, a₀, α_f: see [`super::geometry`]; δ_a is measured from the position where the unloaded
//! balls touch at α_f, or from the concentric position of a preloaded bearing.) The contact
//! deflection is δ_j = A_j − BD, loaded only where positive, and Q_j = K_n δ_j^{3/2} with K_n
//! of both raceway contacts in series from the exact Hertz solution at α_f (over 0–40° it
//! changes by about 0.1 % for a 6210-like bearing: the inner contact stiffens as the outer
//! softens). Equilibrium: Σ Q_j cos α_j cos ψ_j = F_r, Σ Q_j sin α_j = F_a.
//!
//! Solution. The forces are the gradient of the elastic energy U = Σ (2/5) K_n δ_j₊^{5/2},
//! which is convex in (δ_r, δ_a) (δ_j is a norm of an affine map, or affine), so the
//! equilibrium is the minimum of Π = U − F_r δ_r − F_a δ_a. A Newton step on the 2 × 2 analytic
//! Hessian with Armijo backtracking on Π finds it from any start (a gradient step where no ball
//! is loaded, a Levenberg shift where the Hessian is singular). Pure radial (F_a = 0, where
//! symmetry puts every contact angle at 0) and pure axial loads (δ_r = 0) are one-dimensional
//! and bracketed by Brent's method. Convergence: |force residual| ≤ 1e-9 of the load scale
//! max(|F|, Z Q₀), with Q₀ the balls' preload (0 unless preloaded).
//!
//! This file is the wire (request, validation, effect decisions, output); the solvers are in
//! [`super::ring_equilibrium`] and [`super::ball_equilibrium`], the roller bearing in
//! [`super::roller`].

use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};
use serde_json::Value;
use utoipa::ToSchema;

use super::ball_equilibrium::Gyro;
use super::bearing_spec::{BallBearingSpec, RollerBearingSpec};
use super::geometry::{BallBearing, Race};
use super::ring_equilibrium::{
    classic, general, load_scale, tilt_arm, AngleMode, LoadDistributionCase, SpeedModel,
};
use super::roller::{self, RollerBearing, RollerCase, ROLLER_STATIC_LIMIT_PA};
use crate::calc::contact::hertz::{Footprint, Solution};
use crate::calc::quantity::{NonNegative, RingSpeed};
use crate::calc::registry;
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate, Warning};
use crate::effects::{Criterion, Decision, Mode};
use crate::fidelity::Level;

pub struct LoadDistribution;

/// Largest load accepted, N.
const MAX_LOAD_N: f64 = 1e9;
/// ISO 76's static-capacity contact pressure for ball bearings (4200 MPa): above it permanent
/// deformation of about 1e-4 D is expected.
const STATIC_LIMIT_PA: f64 = 4.2e9;
/// Largest ring speed accepted, rpm.
const MAX_SPEED_RPM: f64 = 1e6;
/// Largest tilting moment accepted, N·m.
const MAX_MOMENT_N_M: f64 = 1e9;
/// `auto` applies the centrifugal force above this fraction of the mean ball load.
const CENTRIFUGAL_THRESHOLD: f64 = 0.01;
/// `auto` applies the gyroscopic friction above this fraction of the mean ball load.
const GYROSCOPIC_THRESHOLD: f64 = 0.01;
/// Bearing steel's density (AISI 52100), kg/m³, assumed for a steel-like ball without one.
const STEEL_DENSITY_KG_M3: f64 = 7800.0;

/// How the contact angles respond to the load.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum ContactAngleMode {
    /// Each ball's contact angle follows the ring displacement (exact curvature-centre
    /// geometry); needed for deep-groove bearings with clearance under axial load.
    #[default]
    Varying,
    /// Every contact stays at the free contact angle (the classic ε theory); a bearing with a
    /// free angle α_f > 0 then needs F_a > F_r tan α_f, one with α_f = 0 carries no axial load.
    Fixed,
}

/// Effects this calculation understands.
#[derive(Debug, Clone, Copy, Default, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct LoadDistributionEffects {
    /// The balls' centrifugal force F_c = ½ m d_m ω_m² (Khonsari & Booser RI-9; ω_m the cage
    /// speed): each ball then finds its own place between the grooves and the outer contact
    /// carries more than the inner. `auto` applies it when F_c exceeds 1 % of the mean ball
    /// load (|F|/Z, or the preload); needs a ring speed.
    #[serde(default)]
    pub centrifugal: Mode,
    /// The balls' gyroscopic moment J ω_R ω_m sin β, taken by friction at the outer contact
    /// (outer-race control). `auto` applies it when that friction force exceeds 1 % of the mean
    /// ball load; needs the centrifugal force applied (it is the same ball model).
    #[serde(default)]
    pub gyroscopic: Mode,
}

/// The `bearing` object: a ball bearing or a cylindrical roller bearing, told apart by their
/// fields (`ball_diameter_m` or `roller_diameter_m`). Only the schema reads this type; requests
/// are dispatched on the field so that errors keep their full JSON pointer.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(untagged)]
#[allow(dead_code)]
pub enum LoadDistributionBearing {
    Ball(BallBearingSpec),
    CylindricalRoller(RollerBearingSpec),
}

/// Request.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct LoadDistributionInput {
    /// A ball bearing (deep-groove or angular-contact) or a cylindrical roller bearing (its
    /// fields start `roller_`).
    #[schema(value_type = LoadDistributionBearing)]
    pub bearing: Value,
    /// Radial load F_r on the inner ring, N, 0 … 1e9.
    #[schema(value_type = f64, minimum = 0.0, maximum = 1e9, example = 3000.0)]
    pub radial_load_n: NonNegative,
    /// Axial (thrust) load F_a on the inner ring, N, 0 … 1e9, pressing the balls towards the
    /// side of the free contact angle.
    #[schema(value_type = f64, minimum = 0.0, maximum = 1e9, example = 0.0)]
    pub axial_load_n: NonNegative,
    /// `varying` (default) or `fixed`.
    #[serde(default)]
    pub contact_angle_mode: ContactAngleMode,
    /// Tilting moment M on the inner ring, N·m, |M| ≤ 1e9, about the axis through the bearing
    /// centre perpendicular to the radial load; positive presses the balls at ψ = 0 harder
    /// along F_a. Given (even 0): the ring tilts freely (three degrees of freedom). Absent: the
    /// ring is held square and `tilting_moment_n_m` reports the moment that takes.
    #[schema(minimum = -1e9, maximum = 1e9, example = 50.0)]
    pub moment_n_m: Option<f64>,
    /// Inner-ring speed, rev/min (signed, |n| ≤ 1e6; default 0), for the centrifugal and
    /// gyroscopic effects.
    #[schema(minimum = -1e6, maximum = 1e6, example = 10000.0)]
    pub inner_ring_speed_rpm: Option<f64>,
    /// Outer-ring speed, rev/min (signed, |n| ≤ 1e6; default 0).
    #[schema(minimum = -1e6, maximum = 1e6, example = 0.0)]
    pub outer_ring_speed_rpm: Option<f64>,
    #[serde(default)]
    pub effects: LoadDistributionEffects,
}

/// What the room runs: a ball bearing's case or a roller bearing's.
#[derive(Debug, Clone, Copy)]
pub enum LoadDistributionRequest {
    Ball(LoadDistributionCase),
    Roller(RollerCase),
}

/// Parse `value` as `T`, the pointers of its errors under `at`.
pub(super) fn parse_at<T: DeserializeOwned>(value: Value, at: &str) -> Result<T, Vec<FieldError>> {
    serde_path_to_error::deserialize(value).map_err(|e| vec![registry::field_error(at, &e)])
}

/// The request's load case, typed: everything but the bearing. The pointers of its errors are
/// the load-distribution request's, which the analysis request shares.
#[derive(Debug, Clone, Copy)]
pub(super) struct Loading {
    pub radial_load_n: NonNegative,
    pub axial_load_n: NonNegative,
    pub contact_angle_mode: ContactAngleMode,
    pub moment_n_m: Option<f64>,
    pub inner_ring_speed_rpm: Option<f64>,
    pub outer_ring_speed_rpm: Option<f64>,
    pub effects: LoadDistributionEffects,
}

impl LoadDistributionInput {
    fn loading(&self) -> Loading {
        Loading {
            radial_load_n: self.radial_load_n,
            axial_load_n: self.axial_load_n,
            contact_angle_mode: self.contact_angle_mode,
            moment_n_m: self.moment_n_m,
            inner_ring_speed_rpm: self.inner_ring_speed_rpm,
            outer_ring_speed_rpm: self.outer_ring_speed_rpm,
            effects: self.effects,
        }
    }
}

impl Loading {
    /// A roller bearing's request: radial load only, no speed effects.
    pub(super) fn roller(
        self,
        bearing: Result<RollerBearing, Vec<FieldError>>,
    ) -> Result<LoadDistributionRequest, Vec<FieldError>> {
        let mut errors = bearing.as_ref().err().cloned().unwrap_or_default();
        let f_r = self.radial_load_n.get();
        if f_r > MAX_LOAD_N {
            errors.push(FieldError::new(
                "/radial_load_n",
                format!("must be at most {MAX_LOAD_N:e} N, got {f_r}"),
            ));
        }
        if self.axial_load_n.get() > 0.0 {
            errors.push(FieldError::new(
                "/axial_load_n",
                "a cylindrical roller bearing (N, NU type) carries no axial load in this model: give 0",
            ));
        }
        if self.moment_n_m.is_some() {
            errors.push(FieldError::new(
                "/moment_n_m",
                "a tilting moment on a cylindrical roller bearing (edge loading along the rollers) is not modelled",
            ));
        }
        for (mode, pointer) in [
            (self.effects.centrifugal, "/effects/centrifugal"),
            (self.effects.gyroscopic, "/effects/gyroscopic"),
        ] {
            if mode == Mode::On {
                errors.push(FieldError::new(
                    pointer,
                    "the roller bearing model has no speed effects: the rollers' centrifugal force is not modelled",
                ));
            }
        }
        match bearing {
            Ok(bearing) if errors.is_empty() => {
                if f_r == 0.0 && bearing.clearance_m >= 0.0 {
                    return Err(vec![FieldError::new(
                        "/radial_load_n",
                        "give a radial load: an unloaded roller bearing without preload has no load distribution",
                    )]);
                }
                Ok(LoadDistributionRequest::Roller(RollerCase {
                    bearing,
                    radial_load_n: f_r,
                }))
            }
            _ => Err(errors),
        }
    }
}

impl Validate for LoadDistributionInput {
    type Valid = LoadDistributionRequest;
    fn validate(self) -> Result<LoadDistributionRequest, Vec<FieldError>> {
        let loading = self.loading();
        if self.bearing.get("roller_diameter_m").is_some() {
            let spec: RollerBearingSpec = parse_at(self.bearing, "/bearing")?;
            return loading.roller(spec.validate_at("/bearing"));
        }
        loading.ball(
            parse_at::<BallBearingSpec>(self.bearing, "/bearing")
                .and_then(|spec| spec.validate_at("/bearing")),
        )
    }
}

impl Loading {
    /// A ball bearing's request.
    pub(super) fn ball(
        self,
        bearing: Result<BallBearing, Vec<FieldError>>,
    ) -> Result<LoadDistributionRequest, Vec<FieldError>> {
        let mut errors = bearing.as_ref().err().cloned().unwrap_or_default();
        let (f_r, f_a) = (self.radial_load_n.get(), self.axial_load_n.get());
        for (f, pointer) in [(f_r, "/radial_load_n"), (f_a, "/axial_load_n")] {
            if f > MAX_LOAD_N {
                errors.push(FieldError::new(
                    pointer,
                    format!("must be at most {MAX_LOAD_N:e} N, got {f}"),
                ));
            }
        }
        if let Some(m) = self.moment_n_m {
            if !(m.is_finite() && m.abs() <= MAX_MOMENT_N_M) {
                errors.push(FieldError::new(
                    "/moment_n_m",
                    format!("must be a finite moment within ±{MAX_MOMENT_N_M:e} N·m"),
                ));
            }
        }
        let (inner_rpm, outer_rpm) = (
            self.inner_ring_speed_rpm.unwrap_or(0.0),
            self.outer_ring_speed_rpm.unwrap_or(0.0),
        );
        for (v, p) in [
            (inner_rpm, "/inner_ring_speed_rpm"),
            (outer_rpm, "/outer_ring_speed_rpm"),
        ] {
            if !(v.is_finite() && v.abs() <= MAX_SPEED_RPM) {
                errors.push(FieldError::new(
                    p,
                    format!("must be a finite speed within ±{MAX_SPEED_RPM:e} rev/min"),
                ));
            }
        }
        let effects = self.effects;
        if effects.centrifugal == Mode::On && inner_rpm == 0.0 && outer_rpm == 0.0 {
            errors.push(FieldError::new(
                "/inner_ring_speed_rpm",
                "effects.centrifugal on needs a ring speed",
            ));
        }
        if effects.gyroscopic == Mode::On && effects.centrifugal == Mode::Off {
            errors.push(FieldError::new(
                "/effects/gyroscopic",
                "the gyroscopic friction acts in the ball-by-ball equilibrium of the centrifugal effect: it cannot be on with centrifugal off",
            ));
        }
        if self.contact_angle_mode == ContactAngleMode::Fixed
            && (effects.centrifugal == Mode::On || effects.gyroscopic == Mode::On)
        {
            errors.push(FieldError::new(
                "/contact_angle_mode",
                "the centrifugal and gyroscopic ball loads part the inner and outer contact angles: they need contact_angle_mode varying",
            ));
        }
        if self.contact_angle_mode == ContactAngleMode::Fixed && self.moment_n_m.is_some() {
            errors.push(FieldError::new(
                "/moment_n_m",
                "at a fixed contact angle the balls' moment is tied to the radial load (Σ Q sin α ℜ cos ψ = ℜ F_r tan α): a free ring has no equilibrium under any other moment; use contact_angle_mode varying",
            ));
        }
        let moment = self.moment_n_m.unwrap_or(0.0);
        match bearing {
            Ok(bearing) if errors.is_empty() => {
                if f_r == 0.0 && f_a == 0.0 && moment == 0.0 && bearing.interference_m() == 0.0 {
                    return Err(vec![FieldError::new(
                        "/radial_load_n",
                        "give a radial or an axial load or a moment: an unloaded bearing without preload has no load distribution (its ring floats in the clearance)",
                    )]);
                }
                Ok(LoadDistributionRequest::Ball(LoadDistributionCase {
                    bearing,
                    radial_load_n: f_r,
                    axial_load_n: f_a,
                    mode: match self.contact_angle_mode {
                        ContactAngleMode::Varying => AngleMode::Varying,
                        ContactAngleMode::Fixed => AngleMode::Fixed,
                    },
                    moment_n_m: self.moment_n_m,
                    speed: RingSpeed::new(inner_rpm, outer_rpm),
                    centrifugal: effects.centrifugal,
                    gyroscopic: effects.gyroscopic,
                }))
            }
            _ => Err(errors),
        }
    }
}

/// One rolling element's share (a ball's or a roller's).
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct ElementLoad {
    /// Azimuth ψ_j = 360 j/Z, degrees, 0 … 360, measured from the radial load line.
    #[schema(minimum = 0.0, maximum = 360.0, example = 36.0)]
    pub azimuth_deg: f64,
    /// Normal contact load Q_j, N, ≥ 0 (0: outside the load zone).
    #[schema(minimum = 0.0, example = 1100.0)]
    pub load_n: f64,
    /// Contact angle α_j, degrees (the free contact angle for an unloaded ball in `varying`
    /// mode is the geometric angle of its curvature-centre line).
    #[schema(minimum = -90.0, maximum = 90.0, example = 0.0)]
    pub contact_angle_deg: f64,
    /// With the centrifugal effect: the outer contact's load Q_o, N (`load_n` is then the
    /// inner contact's, `contact_angle_deg` the inner contact angle).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(minimum = 0.0, example = 1150.0)]
    pub outer_load_n: Option<f64>,
    /// With the centrifugal effect: the outer contact angle α_o, degrees.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(minimum = -90.0, maximum = 90.0, example = 0.0)]
    pub outer_contact_angle_deg: Option<f64>,
    /// With the gyroscopic effect: the friction force at the outer contact, N, along
    /// τ = (−cos α_o, sin α_o) in the ball's (axial, radial) plane; it supplies the gyroscopic
    /// moment J ω_R ω_m sin β = f D/2.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = 2.0)]
    pub gyroscopic_friction_n: Option<f64>,
}

/// The Hertz contact of the most loaded ball (roller) on one raceway; for a roller's line
/// contact the semi-major axis is half the effective length and the semi-minor axis the
/// half-width.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct RacewayContact {
    /// Maximum contact pressure p_max, Pa.
    #[schema(example = 2.0e9)]
    pub max_pressure_pa: f64,
    /// Semi-major axis a of the contact ellipse (across the rolling direction), m.
    #[schema(example = 1.8e-3)]
    pub semi_major_axis_m: f64,
    /// Semi-minor axis b (along the rolling direction), m.
    #[schema(example = 1.9e-4)]
    pub semi_minor_axis_m: f64,
    /// Elastic approach δ of ball and raceway at this contact, m.
    #[schema(example = 1.3e-5)]
    pub approach_m: f64,
}

impl RacewayContact {
    /// The contact of the Hertz model's solution (an ellipse with its approach).
    fn of(h: &Solution) -> Result<Self, CalcError> {
        match (&h.footprint, h.approach_m) {
            (
                &Footprint::Ellipse {
                    semi_major_axis_m: a,
                    semi_minor_axis_m: b,
                    ..
                },
                Some(approach),
            ) => Ok(RacewayContact {
                max_pressure_pa: h.max_pressure_pa,
                semi_major_axis_m: a,
                semi_minor_axis_m: b,
                approach_m: approach,
            }),
            _ => Err(CalcError::Internal(
                "a raceway contact came back without its ellipse".to_owned(),
            )),
        }
    }
}

/// Result.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct LoadDistributionOutput {
    /// Largest rolling-element (ball or roller) load Q_max, N.
    #[schema(example = 1380.0)]
    pub max_element_load_n: f64,
    /// Load-zone factor ε = δ(0)/[δ(0) − δ(π)], dimensionless, with δ(ψ) = A(ψ) − BD the signed
    /// (unclipped) contact deflection at azimuth ψ: the fraction of the pitch diameter along
    /// the load line over which the balls are loaded. In `fixed` mode this is the classic
    /// ε = ½(1 + δ_a tan α/δ_r) (less the clearance term); under pure radial load
    /// ε = ½(1 − P_d/(2δ_r)). ε > 1: every ball loaded. Absent when δ_r = 0 (pure axial load or
    /// an unloaded preloaded bearing: ε → ∞).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(minimum = 0.0, example = 0.44)]
    pub load_zone_factor: Option<f64>,
    /// Load-zone half angle ψ_l, degrees, 0 … 180: the azimuth at which δ(ψ) = 0 on the
    /// continuous pitch circle (180: every ball loaded). It is the arc around ψ = 0; a ring
    /// under a tilting moment can also load a second arc about ψ = 180°, which
    /// `loaded_element_count` and `element_loads` include and this angle does not.
    #[schema(minimum = 0.0, maximum = 180.0, example = 83.0)]
    pub load_zone_half_angle_deg: f64,
    /// Rolling elements (balls or rollers) carrying load (Q_j > 0).
    #[schema(minimum = 1, example = 5)]
    pub loaded_element_count: u32,
    /// Every rolling element, j = 0 … Z − 1.
    pub element_loads: Vec<ElementLoad>,
    /// Radial displacement δ_r of the inner ring along the load line, m (from the concentric
    /// position).
    #[schema(example = 2.0e-5)]
    pub radial_displacement_m: f64,
    /// Axial displacement δ_a of the inner ring, m, along F_a, from the position where the
    /// unloaded balls touch at the free contact angle (a preloaded bearing: from the centred
    /// position). Under pure radial load with clearance in `varying` mode it is −BD sin α_f:
    /// the ring centres itself in the grooves.
    #[schema(example = 0.0)]
    pub axial_displacement_m: f64,
    /// Free contact angle α_f, degrees: cos α_f = r₀/BD (deep groove: 1 − P_d/(2BD)); 0 for a
    /// preloaded bearing.
    #[schema(minimum = 0.0, maximum = 80.0, example = 10.9)]
    pub free_contact_angle_deg: f64,
    /// End play (axial play) of the unloaded bearing, 2BD sin α_f = √(4BDP_d − P_d²) for a deep
    /// groove (Khonsari eq. 14.5), m; 0 when preloaded.
    #[schema(minimum = 0.0, example = 1.89e-4)]
    pub end_play_m: f64,
    /// Load–deflection constant K_n of one ball between both raceways, N/m^1.5 (Q = K_n δ^1.5);
    /// ball bearings.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = 1.1e10)]
    pub contact_stiffness_n_m1_5: Option<f64>,
    /// Load–deflection constant K_n of one roller between both raceways, N/m^(10/9)
    /// (Q = K_n δ^(10/9), Palmgren's law); roller bearings.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = 1.0e9)]
    pub roller_contact_stiffness_n_m10_9: Option<f64>,
    /// Static safety factor against the 4200 MPa contact-pressure criterion of the static load
    /// rating (Khonsari & Booser RB-8: permanent deformation 1e-4 D): the factor by which the load
    /// could grow before the more loaded raceway reaches it, (4200 MPa/p_max)³ (p ∝ Q^⅓); for a
    /// roller bearing ISO 76's 4000 MPa and line contact, (4000 MPa/p_max)² (p ∝ Q^½). At the
    /// solved loads, so it differs from the static-capacity room's ISO s0 = C0/P0 (P0 from X0,
    /// Y0 and the rule Q_max = 5F_r/Z).
    #[schema(example = 2.5)]
    pub static_safety_factor: f64,
    /// Tilt θ of the inner ring, rad (0 when the ring is held square: no `moment_n_m`).
    #[schema(example = 0.0)]
    pub tilt_rad: f64,
    /// Moment of the ball loads on the inner ring, Σ Q_j sin α_j ℜ cos ψ_j, N·m (ℜ the radius
    /// of the inner groove curvature centres): the applied `moment_n_m` when the ring tilts
    /// freely, else the moment the mounting takes to hold it square.
    #[schema(example = 0.0)]
    pub tilting_moment_n_m: f64,
    /// With the centrifugal effect: F_c = ½ m d_m ω_m² on every ball, N.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = 25.0)]
    pub centrifugal_force_n: Option<f64>,
    /// With the centrifugal effect: the largest outer contact load, N.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = 1400.0)]
    pub max_outer_ball_load_n: Option<f64>,
    /// With the gyroscopic effect: the largest friction force the outer contacts supply to
    /// hold the balls' gyroscopic moments, N.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = 5.0)]
    pub max_gyroscopic_friction_n: Option<f64>,
    /// Inner raceway contact of the most loaded ball (exact Hertz at its load and angle).
    pub inner_contact: RacewayContact,
    /// Outer raceway contact of the most loaded ball (with the centrifugal effect: of the ball
    /// with the largest outer load, at its outer contact angle).
    pub outer_contact: RacewayContact,
    /// Deprecated: `max_element_load_n` under its name of release 0.1 (every element a ball).
    /// Sent until the next release, then removed.
    #[schema(deprecated, example = 1380.0)]
    pub max_ball_load_n: f64,
    /// Deprecated: `loaded_element_count` under its name of release 0.1. Sent until the next
    /// release, then removed.
    #[schema(deprecated, minimum = 1, example = 5)]
    pub loaded_ball_count: u32,
    /// Deprecated: `element_loads` under its name of release 0.1. Sent until the next release,
    /// then removed.
    #[schema(deprecated)]
    pub ball_loads: Vec<ElementLoad>,
}

impl Calculation for LoadDistribution {
    const PATH: &'static str = "/v1/rolling-bearings/load-distribution";
    const SUMMARY: &'static str =
        "Ball- and cylindrical-roller-bearing load distribution: element loads, contact angles, load zone and ring displacements under combined load, moment and speed";
    const DESCRIPTION: &'static str = include_str!("load_distribution.md");
    const FIDELITY: &'static [Level] = &[Level::Standard];
    const EFFECTS: &'static [&'static str] = &["centrifugal", "gyroscopic"];
    const EXAMPLE: &'static str = r#"{"bearing": {"ball_diameter_m": 0.0127, "pitch_diameter_m": 0.07, "ball_count": 10, "inner_groove_radius_m": 0.0066, "outer_groove_radius_m": 0.0066, "diametral_clearance_m": 1.8e-5, "ball": {"elastic_modulus_pa": 2.08e11, "poisson_ratio": 0.3}, "rings": {"elastic_modulus_pa": 2.08e11, "poisson_ratio": 0.3}}, "radial_load_n": 3000, "axial_load_n": 1000}"#;

    type Input = LoadDistributionInput;
    type Output = LoadDistributionOutput;

    fn run(
        request: LoadDistributionRequest,
        ctx: &mut Context,
    ) -> Result<LoadDistributionOutput, CalcError> {
        solve(request, ctx)
    }
}

/// The load distribution of a validated case (the room's answer; the analysis calls it too).
pub(super) fn solve(
    request: LoadDistributionRequest,
    ctx: &mut Context,
) -> Result<LoadDistributionOutput, CalcError> {
    let case = match request {
        LoadDistributionRequest::Ball(case) => case,
        LoadDistributionRequest::Roller(case) => return roller_run(case, ctx),
    };
    let bearing = &case.bearing;
    let alpha_f = bearing.free_contact_angle();
    let stiffness = bearing.contact_stiffness(alpha_f)?;
    pass_on(ctx, &stiffness.warnings);
    let k_n = stiffness.k;
    let speed = speed_model(&case, k_n, ctx)?;
    let eq = if case.moment_n_m.is_none() && speed.is_none() {
        classic(&case, k_n, ctx)?
    } else {
        general(&case, k_n, speed, ctx)?
    };
    let inner_max = eq.balls.iter().fold((0.0, alpha_f), |m, b| {
        if b.inner_load > m.0 {
            (b.inner_load, b.inner_angle)
        } else {
            m
        }
    });
    let outer_max = eq.balls.iter().fold((0.0, alpha_f), |m, b| {
        if b.outer_load > m.0 {
            (b.outer_load, b.outer_angle)
        } else {
            m
        }
    });
    if inner_max.0 <= 0.0 {
        return Err(CalcError::Internal(
            "an equilibrium without a loaded ball".to_owned(),
        ));
    }
    let inner = bearing.raceway_solution(Race::Inner, inner_max.1, inner_max.0)?;
    pass_on(ctx, &inner.warnings);
    let outer = bearing.raceway_solution(Race::Outer, outer_max.1, outer_max.0)?;
    pass_on(ctx, &outer.warnings);
    let p_max = inner.max_pressure_pa.max(outer.max_pressure_pa);
    if p_max > STATIC_LIMIT_PA {
        ctx.warn(
                "static_capacity_exceeded",
                format!(
                    "the most loaded ball's contact pressure {:.0} MPa exceeds the 4200 MPa of ISO 76's static load rating for ball bearings: permanent raceway deformation beyond 1e-4 D is expected, and rigid-ring Hertz theory is stretched",
                    p_max / 1e6
                ),
            );
    }
    ctx.report(eq.report.clone());
    let z = bearing.ball_count;
    let arm = tilt_arm(bearing);
    let free = eq.centrifugal_n.is_some();
    let tilting_moment = eq
        .balls
        .iter()
        .enumerate()
        .map(|(j, b)| {
            b.inner_load
                * b.inner_angle.sin()
                * arm
                * (std::f64::consts::TAU * j as f64 / z as f64).cos()
        })
        .sum();
    let element_loads: Vec<ElementLoad> = eq
        .balls
        .iter()
        .enumerate()
        .map(|(j, b)| ElementLoad {
            azimuth_deg: 360.0 * j as f64 / z as f64,
            load_n: b.inner_load,
            contact_angle_deg: b.inner_angle.to_degrees(),
            outer_load_n: free.then_some(b.outer_load),
            outer_contact_angle_deg: free.then(|| b.outer_angle.to_degrees()),
            gyroscopic_friction_n: eq.gyroscopic.then_some(b.friction_n),
        })
        .collect();
    let loaded = eq.balls.iter().filter(|b| b.inner_load > 0.0).count() as u32;
    Ok(LoadDistributionOutput {
        max_element_load_n: inner_max.0,
        load_zone_factor: eq.load_zone_factor,
        load_zone_half_angle_deg: eq.half_angle.to_degrees(),
        loaded_element_count: loaded,
        element_loads: element_loads.clone(),
        radial_displacement_m: eq.displacement[0],
        axial_displacement_m: eq.displacement[1],
        free_contact_angle_deg: alpha_f.to_degrees(),
        end_play_m: bearing.end_play_m(),
        contact_stiffness_n_m1_5: Some(k_n),
        roller_contact_stiffness_n_m10_9: None,
        static_safety_factor: (STATIC_LIMIT_PA / p_max).powi(3),
        tilt_rad: eq.displacement[2],
        tilting_moment_n_m: tilting_moment,
        centrifugal_force_n: eq.centrifugal_n,
        max_outer_ball_load_n: free.then_some(outer_max.0),
        max_gyroscopic_friction_n: eq.gyroscopic.then(|| {
            eq.balls
                .iter()
                .map(|b| b.friction_n.abs())
                .fold(0.0, f64::max)
        }),
        inner_contact: RacewayContact::of(&inner)?,
        outer_contact: RacewayContact::of(&outer)?,
        max_ball_load_n: inner_max.0,
        loaded_ball_count: loaded,
        ball_loads: element_loads,
    })
}

/// A cylindrical roller bearing's load distribution (see [`super::roller`]).
fn roller_run(case: RollerCase, ctx: &mut Context) -> Result<LoadDistributionOutput, CalcError> {
    for name in ["centrifugal", "gyroscopic"] {
        ctx.decide(
            name,
            Decision::not_applicable(
                Mode::Auto,
                "not modelled for roller bearings: the rollers' centrifugal force and gyroscopic moment need a roller model at speed",
            ),
        );
    }
    let b = &case.bearing;
    let eq = roller::equilibrium(&case, &ctx.budget())?;
    let q_max = eq.loads.iter().copied().fold(0.0, f64::max);
    if q_max <= 0.0 {
        return Err(CalcError::Internal(
            "an equilibrium without a loaded roller".to_owned(),
        ));
    }
    // The most loaded lamina (the middle one of a crowned roller) sets the pressure: its line
    // load over its width; the contact reaches as far along the roller as laminae are loaded.
    let laminae = b.laminae();
    let (_, lamina_loads) = b.roller_load(eq.max_approach_m, &laminae);
    let width = b.length_m / laminae.len() as f64;
    let q_lamina = lamina_loads.iter().copied().fold(0.0, f64::max);
    let reach = laminae
        .iter()
        .zip(&lamina_loads)
        .filter(|(_, &q)| q > 0.0)
        .map(|(l, _)| l.0.abs() + 0.5 * width)
        .fold(0.0, f64::max);
    let contact = |inner: bool, ctx: &mut Context| -> Result<RacewayContact, CalcError> {
        let h = b.raceway_solution(inner, q_lamina, width)?;
        pass_on(ctx, &h.warnings);
        match (&h.footprint, h.approach_m) {
            (&Footprint::Line { half_width_m, .. }, Some(approach)) => Ok(RacewayContact {
                max_pressure_pa: h.max_pressure_pa,
                semi_major_axis_m: reach,
                semi_minor_axis_m: half_width_m,
                approach_m: approach,
            }),
            _ => Err(CalcError::Internal(
                "a roller's line contact came back without its half-width".to_owned(),
            )),
        }
    };
    let inner = contact(true, ctx)?;
    let outer = contact(false, ctx)?;
    let p_max = inner.max_pressure_pa.max(outer.max_pressure_pa);
    if p_max > ROLLER_STATIC_LIMIT_PA {
        ctx.warn(
            "static_capacity_exceeded",
            format!(
                "the most loaded roller's contact pressure {:.0} MPa exceeds the 4000 MPa of ISO 76's static load rating for roller bearings: permanent deformation beyond 1e-4 D is expected",
                p_max / 1e6
            ),
        );
    }
    ctx.report(eq.report);
    let z = b.roller_count;
    let (d_r, half) = (eq.radial_displacement_m, 0.5 * b.clearance_m);
    let half_angle = if half <= -d_r {
        std::f64::consts::PI
    } else if d_r > 0.0 {
        (half / d_r).clamp(-1.0, 1.0).acos()
    } else {
        0.0
    };
    let element_loads: Vec<ElementLoad> = eq
        .loads
        .iter()
        .enumerate()
        .map(|(j, &q)| ElementLoad {
            azimuth_deg: 360.0 * j as f64 / z as f64,
            load_n: q,
            contact_angle_deg: 0.0,
            outer_load_n: None,
            outer_contact_angle_deg: None,
            gyroscopic_friction_n: None,
        })
        .collect();
    let loaded = eq.loads.iter().filter(|&&q| q > 0.0).count() as u32;
    Ok(LoadDistributionOutput {
        max_element_load_n: q_max,
        load_zone_factor: (d_r > 0.0).then(|| (d_r - half) / (2.0 * d_r)),
        load_zone_half_angle_deg: half_angle.to_degrees(),
        loaded_element_count: loaded,
        element_loads: element_loads.clone(),
        radial_displacement_m: d_r,
        axial_displacement_m: 0.0,
        free_contact_angle_deg: 0.0,
        end_play_m: 0.0,
        contact_stiffness_n_m1_5: None,
        roller_contact_stiffness_n_m10_9: Some(eq.stiffness),
        static_safety_factor: (ROLLER_STATIC_LIMIT_PA / p_max).powi(2),
        tilt_rad: 0.0,
        tilting_moment_n_m: 0.0,
        centrifugal_force_n: None,
        max_outer_ball_load_n: None,
        max_gyroscopic_friction_n: None,
        inner_contact: inner,
        outer_contact: outer,
        max_ball_load_n: q_max,
        loaded_ball_count: loaded,
        ball_loads: element_loads,
    })
}

/// Decide the centrifugal and gyroscopic effects; the ball model when they apply.
fn speed_model(
    case: &LoadDistributionCase,
    k_n: f64,
    ctx: &mut Context,
) -> Result<Option<SpeedModel>, CalcError> {
    let (c_mode, g_mode) = (case.centrifugal, case.gyroscopic);
    if case.speed.at_rest() {
        for (name, mode) in [("centrifugal", c_mode), ("gyroscopic", g_mode)] {
            ctx.decide(
                name,
                Decision::not_applicable(
                    mode,
                    "no ring speed given (inner_ring_speed_rpm, outer_ring_speed_rpm): a quasi-static equilibrium at rest",
                ),
            );
        }
        return Ok(None);
    }
    let b = &case.bearing;
    let (d, dm) = (b.ball_diameter_m, b.pitch_diameter_m);
    let alpha_f = b.free_contact_angle();
    let ball = b.ball_material();
    let e = ball.elastic_modulus_pa.get();
    let (density, assumed) = match ball.density_kg_m3 {
        Some(rho) => (rho.get(), false),
        None if (1.8e11..=2.4e11).contains(&e) => (STEEL_DENSITY_KG_M3, true),
        None => {
            let reason = "needs the balls' density: give bearing.ball.density_kg_m3 (a ball that is not steel-like has no default)";
            for (name, mode) in [("centrifugal", c_mode), ("gyroscopic", g_mode)] {
                if mode == Mode::On {
                    return Err(CalcError::impossible("/bearing/ball/density_kg_m3", reason));
                }
                ctx.decide(name, Decision::not_applicable(mode, reason));
            }
            return Ok(None);
        }
    };
    let rad = std::f64::consts::TAU / 60.0;
    let (w_i, w_o) = (case.speed.inner_rpm * rad, case.speed.outer_rpm * rad);
    let gc = d * alpha_f.cos() / dm;
    let cage = 0.5 * (w_i * (1.0 - gc) + w_o * (1.0 + gc));
    let mass = density * std::f64::consts::PI * d.powi(3) / 6.0;
    let f_c = 0.5 * mass * dm * cage * cage;
    let mean_ball_load = load_scale(case, k_n) / b.ball_count as f64;
    let dn = dm * 1e3 * case.speed.relative_rpm().abs();
    let what = format!(
        "centrifugal ball force F_c = ½ m d_m ω_m² = {f_c:.4e} N at the cage speed {:.0} rpm (d_m·n = {dn:.3e} mm·rpm; Khonsari & Booser RI-9: significant from about 5000–20 000 rpm, size dependent), against the mean ball load {mean_ball_load:.4e} N",
        cage / rad
    );
    let criterion = Criterion {
        name: "centrifugal_to_mean_ball_load_ratio",
        value: f_c / mean_ball_load,
        threshold: CENTRIFUGAL_THRESHOLD,
    };
    let fixed = case.mode == AngleMode::Fixed;
    let mut centrifugal = Decision::decide(c_mode, criterion, &what);
    if fixed {
        centrifugal = Decision::not_applicable(
            c_mode,
            "contact_angle_mode fixed: the centrifugal force parts the inner and outer contact angles, which the fixed-angle theory cannot",
        );
    }
    // The gyroscopic friction at the free contact angle (outer-race control); under a pure
    // radial load without moment symmetry puts every contact angle at 0, and the moment with it.
    let inertia = mass * d * d / 10.0;
    let symmetric = case.axial_load_n == 0.0 && case.moment_n_m.unwrap_or(0.0) == 0.0;
    let alpha_g = if symmetric { 0.0 } else { alpha_f };
    let (s, c) = alpha_g.sin_cos();
    let kappa = s.hypot(dm / d + c);
    let beta = s.atan2(dm / d + c) - alpha_g;
    let gamma = d / dm;
    let relative = (w_i - w_o) * (1.0 - gamma * c)
        / (1.0 - gamma * c + gamma * kappa * (alpha_g + beta).cos());
    let moment = inertia * (-relative * kappa) * (w_o + relative) * beta.sin();
    let g_criterion = Criterion {
        name: "gyroscopic_friction_to_mean_ball_load_ratio",
        value: (2.0 * moment / d).abs() / mean_ball_load,
        threshold: GYROSCOPIC_THRESHOLD,
    };
    let g_what = format!(
        "gyroscopic moment J ω_R ω_m sin β = {moment:.4e} N·m at the contact angle {:.3}° (the free angle; 0 under a pure radial load by symmetry), held by friction 2M/D at the outer contact (outer-race control)",
        alpha_g.to_degrees()
    );
    let mut gyroscopic = Decision::decide(g_mode, g_criterion, &g_what);
    // A gyroscopic effect that applies (on, or auto past its own criterion) brings the ball
    // model it acts in, unless centrifugal is explicitly off.
    if gyroscopic.applied && !centrifugal.applied && !fixed && c_mode != Mode::Off {
        centrifugal.applied = true;
        centrifugal.reason = format!(
            "{}; applied because the gyroscopic effect applies (one ball model)",
            centrifugal.reason
        );
    }
    if gyroscopic.applied && !centrifugal.applied {
        gyroscopic = Decision::not_applicable(
            g_mode,
            format!("{}; not applied: it acts in the ball-by-ball equilibrium of the centrifugal effect, which is not applied", gyroscopic.reason),
        );
    }
    let applied = centrifugal.applied;
    let gyro_applied = gyroscopic.applied;
    ctx.decide("centrifugal", centrifugal);
    ctx.decide("gyroscopic", gyroscopic);
    if !applied {
        return Ok(None);
    }
    if assumed {
        ctx.warn(
            "ball_density_assumed",
            format!("the balls' density is assumed {STEEL_DENSITY_KG_M3} kg/m³ (bearing steel): give bearing.ball.density_kg_m3"),
        );
    }
    let mut stiffness = |race: Race| -> Result<f64, CalcError> {
        let s = b.raceway_stiffness(race, alpha_f)?;
        pass_on(ctx, &s.warnings);
        Ok(s.k)
    };
    Ok(Some(SpeedModel {
        centrifugal_n: f_c,
        gyro: gyro_applied.then_some(Gyro {
            inertia_kg_m2: inertia,
            inner_rad_s: w_i,
            outer_rad_s: w_o,
        }),
        k_i: stiffness(Race::Inner)?,
        k_o: stiffness(Race::Outer)?,
    }))
}

/// Pass a model's warnings on to the response, in order.
fn pass_on(ctx: &mut Context, warnings: &[Warning]) {
    for w in warnings {
        ctx.warn(w.code, w.message.clone());
    }
}

#[cfg(test)]
#[path = "load_distribution_tests.rs"]
mod tests;
