//! The `bearing` object of the rolling rooms' requests (wire): the ball bearing's and the
//! cylindrical roller bearing's specs, their materials, and their validation into the models
//! `geometry::BallBearing` and `roller::RollerBearing` (every error with a pointer under the
//! bearing's place in the request).

use serde::Deserialize;
use utoipa::ToSchema;

use super::geometry::{BallBearing, Material, Race};
use super::roller::RollerBearing;
use crate::calc::contact::hertz::Field;
use crate::calc::quantity::{PoissonRatio, Positive};
use crate::calc::FieldError;

/// Largest ball or pitch diameter accepted, m.
const MAX_DIAMETER_M: f64 = 100.0;
/// Ball counts accepted: three balls are the fewest that hold a ring radially in every
/// direction.
const BALL_COUNT: (u32, u32) = (3, 1000);
/// Largest free contact angle accepted, degrees: beyond it the bearing is a thrust bearing
/// whose radial behaviour this geometry does not describe.
const MAX_CONTACT_ANGLE_DEG: f64 = 80.0;
/// Largest groove conformity f = r/D accepted (a groove flatter than this is a ball on a
/// nearly flat raceway; the curvature-centre geometry still holds but no bearing is built so).
const MAX_CONFORMITY: f64 = 2.0;
/// Largest interference r₀ − BD accepted, as a fraction of the ball diameter: the contacts of a
/// preload beyond it are far outside Hertz's small-contact assumption.
const MAX_INTERFERENCE: f64 = 0.01;

/// Largest diameter or length accepted, m.
const ROLLER_MAX_SIZE_M: f64 = 100.0;
const ROLLER_COUNT: (u32, u32) = (3, 1000);
/// Largest interference −P_d/2 accepted, as a fraction of the roller diameter.
const ROLLER_MAX_INTERFERENCE: f64 = 0.01;

/// Elastic constants of a solid: the ball's or the rings'.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct MaterialSpec {
    /// Young's modulus E, Pa, 1 … 1e13 (bearing steel 2.08e11, silicon nitride 3.1e11).
    #[schema(value_type = f64, minimum = 1.0, maximum = 1e13, example = 2.08e11)]
    pub elastic_modulus_pa: Positive,
    /// Poisson's ratio ν, dimensionless, −1 < ν ≤ 0.5 (steel 0.3).
    #[schema(value_type = f64, exclusive_minimum = -1.0, maximum = 0.5, example = 0.3)]
    pub poisson_ratio: PoissonRatio,
    /// Density ρ, kg/m³, 1 … 1e5 (bearing steel 7800, silicon nitride 3200); the balls' density
    /// sets their centrifugal force and gyroscopic moment at speed (the rings' is not used). Absent: bearing steel is assumed
    /// (with a warning) for a steel-like modulus, else those effects are not applicable.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e5, example = 7800.0)]
    pub density_kg_m3: Option<Positive>,
}

/// A single-row ball bearing: deep-groove (no `free_contact_angle_deg`: the contact angle
/// follows from the clearance) or angular-contact.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct BallBearingSpec {
    /// Ball diameter D, m (0.1 mm … 100 m, less than the pitch diameter).
    #[schema(value_type = f64, minimum = 1e-4, maximum = 100.0, example = 0.0127)]
    pub ball_diameter_m: Positive,
    /// Pitch diameter d_m, m: the circle through the ball centres, (d_i + d_o)/2 of the raceway
    /// diameters (> ball_diameter_m; 0.1 mm … 100 m).
    #[schema(value_type = f64, minimum = 1e-4, maximum = 100.0, example = 0.07)]
    pub pitch_diameter_m: Positive,
    /// Number of balls Z, 3 … 1000; they must fit on the pitch circle: D < d_m sin(π/Z).
    #[schema(minimum = 3, maximum = 1000, example = 10)]
    pub ball_count: u32,
    /// Inner raceway groove radius r_i, m, > D/2 (conformity f_i = r_i/D within (0.5, 2];
    /// typically 0.515–0.53).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 200.0, example = 0.0066)]
    pub inner_groove_radius_m: Positive,
    /// Outer raceway groove radius r_o, m, > D/2 (f_o = r_o/D within (0.5, 2]).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 200.0, example = 0.0066)]
    pub outer_groove_radius_m: Positive,
    /// Diametral clearance P_d, m: d_o − d_i − 2D of the raceway diameters with the rings
    /// concentric (Khonsari eq. 14.4). Negative: interference, a preloaded bearing (at most
    /// 1 % of D per ball). With `free_contact_angle_deg`, the clearance beyond that angle's
    /// geometry: 0 when the balls touch at exactly that angle once the rings are pushed
    /// axially together.
    #[schema(minimum = -1.0, maximum = 1.0, example = 1.8e-5)]
    pub diametral_clearance_m: f64,
    /// Free contact angle α_g of an angular-contact bearing, degrees, 0 … 80; absent for a
    /// deep-groove bearing, whose free contact angle follows from the clearance:
    /// cos α_f = 1 − P_d/(2BD), B = f_i + f_o − 1.
    #[schema(minimum = 0.0, maximum = 80.0, example = 40.0)]
    pub free_contact_angle_deg: Option<f64>,
    /// The balls' material.
    pub ball: MaterialSpec,
    /// The rings' material (both rings).
    pub rings: MaterialSpec,
}

impl From<MaterialSpec> for Material {
    fn from(m: MaterialSpec) -> Self {
        Material {
            elastic_modulus_pa: m.elastic_modulus_pa,
            poisson_ratio: m.poisson_ratio,
            density_kg_m3: m.density_kg_m3,
        }
    }
}

/// A single-row cylindrical roller bearing (N, NU type) with straight rollers.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct RollerBearingSpec {
    /// Roller diameter D, m (0.1 mm … 100 m, less than the pitch diameter).
    #[schema(value_type = f64, minimum = 1e-4, maximum = 100.0, example = 0.01)]
    pub roller_diameter_m: Positive,
    /// Effective roller length L, m: the length in contact, less corner radii or undercuts
    /// (0.1 mm … 100 m; a smaller size makes the line load underflow).
    #[schema(value_type = f64, minimum = 1e-4, maximum = 100.0, example = 0.009601)]
    pub roller_effective_length_m: Positive,
    /// Pitch diameter d_m = (d_i + d_o)/2 of the raceway diameters, m (0.1 mm … 100 m).
    #[schema(value_type = f64, minimum = 1e-4, maximum = 100.0, example = 0.0650115)]
    pub pitch_diameter_m: Positive,
    /// Number of rollers Z, 3 … 1000; they must fit: D < d_m sin(π/Z).
    #[schema(minimum = 3, maximum = 1000, example = 14)]
    pub roller_count: u32,
    /// Diametral clearance P_d = d_o − d_i − 2D, m (negative: preload, at most 1 % of D per
    /// roller; positive at most D).
    #[schema(minimum = -1.0, maximum = 1.0, example = 4.1e-5)]
    pub diametral_clearance_m: f64,
    /// The rollers' material.
    pub rollers: MaterialSpec,
    /// The rings' material.
    pub rings: MaterialSpec,
    /// The rollers' profile; absent: straight (uncrowned).
    pub profile: Option<RollerProfile>,
}

/// A crowned roller profile: the crown's radius across the roller, along its axis.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct RollerProfile {
    /// Crown radius R along the roller axis, m (≥ the effective length, at most 1e4 m; about
    /// 100 D for cylindrical rollers, Hamrock A.1.8).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 1e4, example = 1.0)]
    pub crown_radius_m: Positive,
}

impl BallBearingSpec {
    /// Validate, with every pointer under `at` (the bearing's place in the request).
    pub fn validate_at(self, at: &str) -> Result<BallBearing, Vec<FieldError>> {
        let mut errors = Vec::new();
        let d = self.ball_diameter_m.get();
        let dm = self.pitch_diameter_m.get();
        let z = self.ball_count;
        for (value, field) in [(d, "ball_diameter_m"), (dm, "pitch_diameter_m")] {
            if value > MAX_DIAMETER_M {
                errors.push(FieldError::new(
                    format!("{at}/{field}"),
                    format!("must be at most {MAX_DIAMETER_M} m, got {value}"),
                ));
            }
        }
        if !(BALL_COUNT.0..=BALL_COUNT.1).contains(&z) {
            errors.push(FieldError::new(
                format!("{at}/ball_count"),
                format!(
                    "must be within [{}, {}], got {z}",
                    BALL_COUNT.0, BALL_COUNT.1
                ),
            ));
        } else if d >= dm * (std::f64::consts::PI / z as f64).sin() {
            errors.push(FieldError::new(
                format!("{at}/ball_count"),
                format!(
                    "{z} balls of diameter {d} m do not fit on a pitch circle of {dm} m: adjacent balls overlap unless D < d_m sin(π/Z) = {:.6e} m",
                    dm * (std::f64::consts::PI / z as f64).sin()
                ),
            ));
        }
        let f_i = self.inner_groove_radius_m.get() / d;
        let f_o = self.outer_groove_radius_m.get() / d;
        for (f, field) in [
            (f_i, "inner_groove_radius_m"),
            (f_o, "outer_groove_radius_m"),
        ] {
            if !(f > 0.5 && f <= MAX_CONFORMITY) {
                errors.push(FieldError::new(
                    format!("{at}/{field}"),
                    format!(
                        "the groove radius must exceed the ball radius D/2 (conformity r/D within (0.5, {MAX_CONFORMITY}]), got r/D = {f:.6}"
                    ),
                ));
            }
        }
        for (material, field) in [(self.ball, "ball"), (self.rings, "rings")] {
            if let Some(rho) = material.density_kg_m3 {
                if rho.get() > 1e5 {
                    errors.push(FieldError::new(
                        format!("{at}/{field}/density_kg_m3"),
                        format!("must be at most 1e5 kg/m³, got {}", rho.get()),
                    ));
                }
            }
        }
        let p_d = self.diametral_clearance_m;
        if !p_d.is_finite() {
            errors.push(FieldError::new(
                format!("{at}/diametral_clearance_m"),
                "must be a finite number",
            ));
        }
        let angle_deg = self.free_contact_angle_deg.unwrap_or(0.0);
        if !(angle_deg.is_finite() && (0.0..=MAX_CONTACT_ANGLE_DEG).contains(&angle_deg)) {
            errors.push(FieldError::new(
                format!("{at}/free_contact_angle_deg"),
                format!("must be within [0, {MAX_CONTACT_ANGLE_DEG}] degrees, got {angle_deg}"),
            ));
        }
        if !errors.is_empty() {
            return Err(errors);
        }
        let bd = (f_i + f_o - 1.0) * d;
        let r0 = bd * angle_deg.to_radians().cos() - 0.5 * p_d;
        if r0 - bd > MAX_INTERFERENCE * d {
            errors.push(FieldError::new(
                format!("{at}/diametral_clearance_m"),
                format!(
                    "the interference r₀ − BD = {:.4e} m per ball exceeds {MAX_INTERFERENCE} D: a preload that large is far outside Hertz's small-contact assumption",
                    r0 - bd
                ),
            ));
        } else if r0 < bd * MAX_CONTACT_ANGLE_DEG.to_radians().cos() {
            errors.push(FieldError::new(
                format!("{at}/diametral_clearance_m"),
                format!(
                    "the clearance gives a free contact angle acos(r₀/BD) above {MAX_CONTACT_ANGLE_DEG}° (r₀ = BD cos α_g − P_d/2 = {r0:.4e} m, BD = {bd:.4e} m): too much clearance for the grooves' total curvature B = f_i + f_o − 1"
                ),
            ));
        }
        if !errors.is_empty() {
            return Err(errors);
        }
        let bearing = BallBearing {
            ball_diameter_m: d,
            pitch_diameter_m: dm,
            ball_count: z as usize,
            inner_conformity: f_i,
            outer_conformity: f_o,
            ball: self.ball.into(),
            rings: self.rings.into(),
            curvature_centre_distance_m: bd,
            radial_centre_offset_m: r0,
        };
        // The Hertz room checks the elastic constants and that each raceway contact is a
        // point contact it can solve; its pointers are mapped onto this object's fields.
        for race in [Race::Inner, Race::Outer] {
            if let Err(hertz) = bearing.hertz_contact(race, bearing.free_contact_angle(), 1.0) {
                for e in hertz {
                    let field = match e.field {
                        Field::Modulus { body: 1 } => "/ball/elastic_modulus_pa",
                        Field::PoissonRatio { body: 1 } => "/ball/poisson_ratio",
                        Field::Modulus { .. } => "/rings/elastic_modulus_pa",
                        Field::PoissonRatio { .. } => "/rings/poisson_ratio",
                        _ if race == Race::Inner => "/inner_groove_radius_m",
                        _ => "/outer_groove_radius_m",
                    };
                    let pointer = format!("{at}{field}");
                    if !errors.iter().any(|x: &FieldError| x.pointer == pointer) {
                        errors.push(FieldError::new(pointer, e.message));
                    }
                }
            }
        }
        if errors.is_empty() {
            Ok(bearing)
        } else {
            Err(errors)
        }
    }
}

impl RollerBearingSpec {
    pub fn validate_at(self, at: &str) -> Result<RollerBearing, Vec<FieldError>> {
        let mut errors = Vec::new();
        let (d, l, dm) = (
            self.roller_diameter_m.get(),
            self.roller_effective_length_m.get(),
            self.pitch_diameter_m.get(),
        );
        for (v, field) in [
            (d, "roller_diameter_m"),
            (l, "roller_effective_length_m"),
            (dm, "pitch_diameter_m"),
        ] {
            if v > ROLLER_MAX_SIZE_M {
                errors.push(FieldError::new(
                    format!("{at}/{field}"),
                    format!("must be at most {ROLLER_MAX_SIZE_M} m, got {v}"),
                ));
            }
        }
        let z = self.roller_count;
        if !(ROLLER_COUNT.0..=ROLLER_COUNT.1).contains(&z) {
            errors.push(FieldError::new(
                format!("{at}/roller_count"),
                format!(
                    "must be within [{}, {}], got {z}",
                    ROLLER_COUNT.0, ROLLER_COUNT.1
                ),
            ));
        } else if d >= dm * (std::f64::consts::PI / z as f64).sin() {
            errors.push(FieldError::new(
                format!("{at}/roller_count"),
                format!(
                    "{z} rollers of diameter {d} m do not fit on a pitch circle of {dm} m: adjacent rollers overlap unless D < d_m sin(π/Z) = {:.6e} m",
                    dm * (std::f64::consts::PI / z as f64).sin()
                ),
            ));
        }
        let p_d = self.diametral_clearance_m;
        if !(p_d.is_finite() && -2.0 * ROLLER_MAX_INTERFERENCE * d <= p_d && p_d <= d) {
            errors.push(FieldError::new(
                format!("{at}/diametral_clearance_m"),
                format!(
                    "must be a finite clearance within [−{} D, D] = [{:.4e}, {d:.4e}] m (a preload beyond 1 % of D per roller is outside Palmgren's law), got {p_d}",
                    2.0 * ROLLER_MAX_INTERFERENCE,
                    -2.0 * ROLLER_MAX_INTERFERENCE * d
                ),
            ));
        }
        for (m, field) in [(self.rollers, "rollers"), (self.rings, "rings")] {
            let e = m.elastic_modulus_pa.get();
            if e > 1e13 {
                errors.push(FieldError::new(
                    format!("{at}/{field}/elastic_modulus_pa"),
                    format!("must be at most 1e13 Pa, got {e}"),
                ));
            }
            if m.density_kg_m3.is_some_and(|r| r.get() > 1e5) {
                errors.push(FieldError::new(
                    format!("{at}/{field}/density_kg_m3"),
                    "must be at most 1e5 kg/m³",
                ));
            }
        }
        if let Some(p) = self.profile {
            let r = p.crown_radius_m.get();
            if !(l..=1e4).contains(&r) {
                errors.push(FieldError::new(
                    format!("{at}/profile/crown_radius_m"),
                    format!("must be within [L, 1e4] m = [{l:.4e}, 1e4] m (a crown sharper than the roller's length is not a cylindrical roller), got {r}"),
                ));
            }
        }
        if errors.is_empty() {
            Ok(RollerBearing {
                roller_diameter_m: d,
                length_m: l,
                pitch_diameter_m: dm,
                roller_count: z as usize,
                clearance_m: p_d,
                crown_radius_m: self.profile.map(|p| p.crown_radius_m.get()),
                rollers: self.rollers.into(),
                rings: self.rings.into(),
            })
        } else {
            Err(errors)
        }
    }
}
