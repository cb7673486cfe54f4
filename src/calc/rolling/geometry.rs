//! The internal geometry of a ball bearing, shared by the rooms that load one: the `bearing`
//! object of the requests, its validation, and the two raceway contacts evaluated by the Hertz
//! room's exact point contact ([`crate::calc::contact::hertz`]).
//!
//! Conventions (Harris; Hamrock §21.3; Khonsari & Booser §14.1, RI-1, RI-2, RB-9):
//! - Groove conformities f_i = r_i/D, f_o = r_o/D (> ½); total curvature B = f_i + f_o − 1; the
//!   raceway groove curvature centres are BD apart when a ball touches both raceways unloaded.
//! - Concentric rings hold the curvature centres r₀ = BD cos α_g − P_d/2 apart radially, with
//!   P_d the diametral clearance (negative: interference) and α_g the angular-contact angle the
//!   groove geometry gives (0 for a deep-groove bearing). With r₀ ≤ BD the balls touch when the
//!   rings are pushed axially by a₀ = √(B²D² − r₀²): the free contact angle is
//!   cos α_f = r₀/BD (= 1 − P_d/(2BD) for a deep-groove bearing, Khonsari eq. 14.5's geometry)
//!   and the end play is 2a₀ = √(4BDP_d − P_d²) (RB-9). With r₀ > BD every ball is compressed
//!   by r₀ − BD in the concentric position: a preloaded bearing (α_f = 0, a₀ = 0).
//! - Raceway radii of a ball at contact angle α: inner ½(d_m/cos α − D) (convex), outer
//!   −½(d_m/cos α + D) (concave), grooves −f_i D and −f_o D across the rolling direction (RI-1).

use serde::Deserialize;
use utoipa::ToSchema;

use crate::calc::contact::hertz::{Body, Contact, Field, Invalid, Method, Shape, Solution};
use crate::calc::quantity::{PoissonRatio, Positive};
use crate::calc::{CalcError, FieldError, Warning};

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
    /// Ball diameter D, m (> 0, at most 100, less than the pitch diameter).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 100.0, example = 0.0127)]
    pub ball_diameter_m: Positive,
    /// Pitch diameter d_m, m: the circle through the ball centres, (d_i + d_o)/2 of the raceway
    /// diameters (> ball_diameter_m, at most 100).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 100.0, example = 0.07)]
    pub pitch_diameter_m: Positive,
    /// Number of balls Z, 3 … 1000; they must fit on the pitch circle: D < d_m sin(π/Z).
    #[schema(minimum = 3, maximum = 1000, example = 10)]
    pub ball_count: u32,
    /// Inner raceway groove radius r_i, m, > D/2 (conformity f_i = r_i/D within (0.5, 2];
    /// typically 0.515–0.53).
    #[schema(value_type = f64, exclusive_minimum = 0.0, example = 0.0066)]
    pub inner_groove_radius_m: Positive,
    /// Outer raceway groove radius r_o, m, > D/2 (f_o = r_o/D within (0.5, 2]).
    #[schema(value_type = f64, exclusive_minimum = 0.0, example = 0.0066)]
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

/// A raceway: which ring the ball touches.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Race {
    Inner,
    Outer,
}

/// A validated ball bearing.
#[derive(Debug, Clone, Copy)]
pub struct BallBearing {
    pub ball_diameter_m: f64,
    pub pitch_diameter_m: f64,
    pub ball_count: usize,
    /// f_i = r_i/D and f_o = r_o/D, dimensionless.
    pub inner_conformity: f64,
    pub outer_conformity: f64,
    ball: MaterialSpec,
    rings: MaterialSpec,
    /// BD, m: the distance between the groove curvature centres of an unloaded ball in contact.
    pub curvature_centre_distance_m: f64,
    /// r₀, m: the radial distance between the groove curvature centres of concentric rings.
    pub radial_centre_offset_m: f64,
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
            ball: self.ball,
            rings: self.rings,
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

impl BallBearing {
    /// Free contact angle α_f, rad: cos α_f = r₀/BD, 0 for a preloaded bearing.
    pub fn free_contact_angle(&self) -> f64 {
        (self.radial_centre_offset_m / self.curvature_centre_distance_m)
            .min(1.0)
            .acos()
    }

    /// a₀ = √(B²D² − r₀²), m: the axial offset of the curvature centres at which the unloaded
    /// balls touch both raceways (0 for a preloaded bearing).
    pub fn axial_centre_offset_m(&self) -> f64 {
        let (bd, r0) = (
            self.curvature_centre_distance_m,
            self.radial_centre_offset_m,
        );
        ((bd - r0) * (bd + r0)).max(0.0).sqrt()
    }

    /// The balls' material.
    pub fn ball_material(&self) -> MaterialSpec {
        self.ball
    }

    /// End play 2a₀, m: the axial travel of one ring against the other, unloaded (RB-9).
    pub fn end_play_m(&self) -> f64 {
        2.0 * self.axial_centre_offset_m()
    }

    /// Compression r₀ − BD of every ball with the rings concentric, m (0 unless preloaded).
    pub fn interference_m(&self) -> f64 {
        (self.radial_centre_offset_m - self.curvature_centre_distance_m).max(0.0)
    }

    /// The Hertz contact of a ball on `race` at contact angle α (rad) under `load_n`, checked
    /// by the Hertz model (its refusals name the Hertz model's fields: body 1 the ball, body 2
    /// the raceway).
    fn hertz_contact(
        &self,
        race: Race,
        contact_angle: f64,
        load_n: f64,
    ) -> Result<Contact, Vec<Invalid>> {
        let d = self.ball_diameter_m;
        let along = self.pitch_diameter_m / contact_angle.cos();
        let (rolling, groove, material) = match race {
            Race::Inner => (0.5 * (along - d), -self.inner_conformity * d, self.rings),
            Race::Outer => (-0.5 * (along + d), -self.outer_conformity * d, self.rings),
        };
        let body = |rx: f64, ry: f64, m: MaterialSpec| Body {
            radius_x_m: Some(rx),
            radius_y_m: Some(ry),
            modulus_pa: m.elastic_modulus_pa.get(),
            poisson_ratio: m.poisson_ratio.get(),
        };
        let ball = 0.5 * d;
        Contact::new(
            [body(ball, ball, self.ball), body(rolling, groove, material)],
            load_n,
            Shape::Point,
            Method::Exact,
        )
    }

    /// The exact Hertz contact of a ball on `race` at contact angle α (rad) under `load_n` > 0,
    /// from the Hertz model, with the model's warnings in the solution.
    pub fn raceway_solution(
        &self,
        race: Race,
        contact_angle: f64,
        load_n: f64,
    ) -> Result<Solution, CalcError> {
        let contact = self
            .hertz_contact(race, contact_angle, load_n)
            .map_err(|errors| {
                Invalid::refusal(
                    errors,
                    "/bearing",
                    &format!(
                        "the {race:?} raceway contact at contact angle {:.4}° and load {load_n:.6e} N is not a Hertz point contact",
                        contact_angle.to_degrees()
                    ),
                )
            })?;
        contact.solve()
    }

    /// Load–deflection constant K of one ball on `race` at contact angle α (rad), N/m^1.5:
    /// Q = K δ^{3/2}, from the exact Hertz approach at 1 N (with the Hertz model's warnings).
    pub fn raceway_stiffness(
        &self,
        race: Race,
        contact_angle: f64,
    ) -> Result<Stiffness, CalcError> {
        let contact = self.raceway_solution(race, contact_angle, 1.0)?;
        let approach = contact
            .approach_m
            .ok_or_else(|| CalcError::Internal("a point contact without an approach".to_owned()))?;
        Ok(Stiffness {
            k: approach.powf(-1.5),
            warnings: contact.warnings,
        })
    }

    /// Load–deflection constant K_n of one ball between both raceways at contact angle α (rad),
    /// N/m^1.5: Q = K_n δ^{3/2} with δ = δ_i + δ_o the total elastic approach, i.e.
    /// K_n = [K_i^{−2/3} + K_o^{−2/3}]^{−3/2} (Hamrock eq. 21.101 with the exponents 2/3, 3/2).
    /// Since δ ∝ Q^{2/3} exactly, each K is read from the exact Hertz approach at 1 N.
    pub fn contact_stiffness(&self, contact_angle: f64) -> Result<Stiffness, CalcError> {
        let mut approach = 0.0;
        let mut warnings = Vec::new();
        for race in [Race::Inner, Race::Outer] {
            let contact = self.raceway_solution(race, contact_angle, 1.0)?;
            approach += contact.approach_m.ok_or_else(|| {
                CalcError::Internal("a point contact without an approach".to_owned())
            })?;
            warnings.extend(contact.warnings);
        }
        Ok(Stiffness {
            k: approach.powf(-1.5),
            warnings,
        })
    }
}

/// A load–deflection constant and the Hertz model's warnings on the way to it, in order.
#[derive(Debug, Clone)]
pub struct Stiffness {
    pub k: f64,
    pub warnings: Vec<Warning>,
}
