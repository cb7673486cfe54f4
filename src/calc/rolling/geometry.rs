//! The internal geometry of a ball bearing (model), shared by the rooms that load one: the
//! validated bearing (the requests' `bearing` object and its validation are the wire file
//! `bearing_spec.rs`) and the two raceway contacts evaluated by the Hertz model's exact point
//! contact ([`crate::calc::contact::hertz`]).
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

use crate::calc::contact::hertz::{Body, Contact, Invalid, Method, Shape, Solution};
use crate::calc::quantity::{PoissonRatio, Positive};
use crate::calc::{CalcError, Warning};

/// Elastic constants of a solid (the ball's or the rings'), validated.
#[derive(Debug, Clone, Copy)]
pub struct Material {
    pub elastic_modulus_pa: Positive,
    pub poisson_ratio: PoissonRatio,
    /// Density ρ, kg/m³, when given.
    pub density_kg_m3: Option<Positive>,
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
    pub(super) ball: Material,
    pub(super) rings: Material,
    /// BD, m: the distance between the groove curvature centres of an unloaded ball in contact.
    pub curvature_centre_distance_m: f64,
    /// r₀, m: the radial distance between the groove curvature centres of concentric rings.
    pub radial_centre_offset_m: f64,
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
    pub fn ball_material(&self) -> Material {
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
    pub(super) fn hertz_contact(
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
        let body = |rx: f64, ry: f64, m: Material| Body {
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
