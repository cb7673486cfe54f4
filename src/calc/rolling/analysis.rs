//! `POST /v1/rolling-bearings/analysis`: the whole chain for one operating point of a ball
//! bearing — internal load distribution → Hertz at both raceways of the most loaded ball →
//! kinematics and entrainment speeds → EHL film and Λ at both raceways → κ and the modified
//! life — each step by the room that also answers it alone, so the numbers are theirs.

use serde::{Deserialize, Serialize};
use serde_json::Value;
use utoipa::ToSchema;

use super::bearing_spec::{BallBearingSpec, MaterialSpec, RollerBearingSpec};
use super::iso281::LifeCase;
use super::iso76::StaticCapacityCase;
use super::kinematics::{self, ContactAngle, KinematicsCase, KinematicsOutput};
use super::life::{self, BearingKind, ContaminationFactor, LifeInput, LifeOutput, Reliability};
use super::load_distribution::{
    self, parse_at, ContactAngleMode, LoadDistributionEffects, LoadDistributionOutput,
    LoadDistributionRequest, Loading,
};
use super::static_capacity::{self, StaticCapacity, StaticCapacityOutput, StaticLoading};
use crate::calc::contact::ehl::closed_form::{self, FilmCase, FilmEffects};
use crate::calc::contact::ehl::film::EhlFilmOutput;
use crate::calc::contact::hertz::{Body, Contact, Field, Method, Shape};
use crate::calc::lubricant::model::PressureLaw;
use crate::calc::lubricant::validity;
use crate::calc::lubricant::{Lubricant, LubricantSpec};
use crate::calc::quantity::{Celsius, NonNegative, Positive, RingSpeed};
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::effects::{Decision, Mode};
use crate::fidelity::Level;

pub struct Analysis;

/// The largest R_q a rolling surface may be given, m (finished raceways and balls are 0.02–0.3 µm).
const MAX_RACE_RMS_M: f64 = 1e-5;

/// RMS roughness of the ball and the two raceways.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct RaceRoughness {
    /// Ball R_q, m (0 … 1e-5).
    #[schema(value_type = f64, minimum = 0.0, maximum = 1e-5, example = 6.25e-8)]
    pub ball_rms_m: NonNegative,
    /// Inner raceway R_q, m (0 … 1e-5).
    #[schema(value_type = f64, minimum = 0.0, maximum = 1e-5, example = 1.75e-7)]
    pub inner_race_rms_m: NonNegative,
    /// Outer raceway R_q, m (0 … 1e-5).
    #[schema(value_type = f64, minimum = 0.0, maximum = 1e-5, example = 1.75e-7)]
    pub outer_race_rms_m: NonNegative,
}

/// Request: a ball bearing at one operating point.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct AnalysisInput {
    /// The bearing (as for `/v1/rolling-bearings/load-distribution`).
    #[schema(value_type = BallBearingSpec)]
    pub bearing: Value,
    /// Radial load F_r, N (0 … 1e9).
    #[schema(value_type = f64, minimum = 0.0, maximum = 1e9, example = 8900.0)]
    pub radial_load_n: NonNegative,
    /// Axial load F_a, N (0 … 1e9; default 0).
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 1e9, example = 0.0)]
    pub axial_load_n: Option<NonNegative>,
    /// Inner-ring speed, rev/min (signed, |n| ≤ 1e6).
    #[schema(minimum = -1e6, maximum = 1e6, example = 2000.0)]
    pub inner_ring_speed_rpm: f64,
    /// Outer-ring speed, rev/min (signed, |n| ≤ 1e6; default 0).
    #[schema(minimum = -1e6, maximum = 1e6, example = 0.0)]
    pub outer_ring_speed_rpm: Option<f64>,
    /// The lubricant, with a pressure–viscosity law (for the EHL films).
    pub lubricant: LubricantSpec,
    /// Operating temperature of the oil in the contacts, °C.
    #[schema(value_type = f64, minimum = -273.0, maximum = 1000.0, example = 70.0)]
    pub temperature_c: Celsius,
    /// Basic dynamic load rating C, N (catalogue).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 1e10, example = 35700.0)]
    pub dynamic_load_rating_n: Positive,
    /// Equivalent dynamic load P, N; default F_r when F_a = 0, else give it (or X and Y).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e10, example = 8900.0)]
    pub equivalent_load_n: Option<Positive>,
    /// Radial factor X for P = X F_r + Y F_a (with `y_factor`).
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 10.0, example = 0.56)]
    pub x_factor: Option<NonNegative>,
    /// Axial factor Y for P = X F_r + Y F_a (with `x_factor`).
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 10.0, example = 1.5)]
    pub y_factor: Option<NonNegative>,
    /// Reliability, %, within [1, 100) (default 90).
    #[schema(minimum = 1.0, exclusive_maximum = 100.0, example = 90.0)]
    pub reliability_percent: Option<f64>,
    /// Contamination factor e_C (0 … 1), with `fatigue_load_limit_n`, for ISO 281's a_ISO.
    #[schema(minimum = 0.0, maximum = 1.0, example = 0.5)]
    pub contamination_factor: Option<f64>,
    /// Fatigue load limit C_u, N, with `contamination_factor`.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e10, example = 1000.0)]
    pub fatigue_load_limit_n: Option<Positive>,
    pub roughness: Option<RaceRoughness>,
    /// Bore d, m (< pitch diameter), for the speed limit d·n (Khonsari & Booser Table 14.5);
    /// absent: the pitch diameter stands in (conservative, d_m > d).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 100.0, example = 0.05)]
    pub bore_diameter_m: Option<Positive>,
    /// How the bearing is lubricated, for the speed limit: `grease_or_bath` (d·n ≤ 300 000 mm·rpm)
    /// or `circulating_oil` (500 000); absent: both limits are judged.
    pub lubrication_method: Option<AnalysisLubricationMethod>,
    /// Misalignment of the inner ring against the outer, rad (0 … 0.1), for the limit of
    /// Khonsari & Booser Table 14.8 (deep groove 12–16′) and Table 13.1 (angular contact 2′).
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 0.1, example = 0.002)]
    pub misalignment_rad: Option<NonNegative>,
    /// Distance from the contact centre upstream to the inlet oil meniscus, m (> 0), passed to
    /// both raceway films for their starvation effect (`/v1/contacts/ehl-film`).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1.0, example = 0.0005)]
    pub inlet_meniscus_distance_m: Option<Positive>,
    /// The raceway films' effects (`thermal` inlet heating, `starvation`, `mixed_lubrication`:
    /// `auto`, `on`, `off`), passed to `/v1/contacts/ehl-film` for both raceways.
    #[serde(default)]
    pub film_effects: AnalysisFilmEffects,
}

/// The films' effects the chain passes on (the EHL film room's own).
#[derive(Debug, Clone, Copy, Default, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct AnalysisFilmEffects {
    #[serde(default)]
    pub thermal: Mode,
    #[serde(default)]
    pub starvation: Mode,
    #[serde(default)]
    pub mixed_lubrication: Mode,
}

/// Lubrication method for the speed limit (Khonsari & Booser Table 14.5).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum AnalysisLubricationMethod {
    GreaseOrBath,
    CirculatingOil,
}

/// d·n limits of ball bearings, mm·rpm (Khonsari & Booser Table 14.5): grease or oil bath,
/// circulating oil.
const DN_GREASE_OR_BATH: f64 = 3.0e5;
const DN_CIRCULATING_OIL: f64 = 5.0e5;
/// 52100 through-hardened steel: dimensional stabilisation needed above about 125 °C
/// (Khonsari & Booser §14.12, Table 14.7).
const STABILISATION_C: f64 = 125.0;
/// Misalignment limits, rad: deep-groove 12′ (Table 14.8: 12–16′), angular contact 2′ (Table 13.1).
const MISALIGNMENT_DEEP_GROOVE_RAD: f64 = 12.0 / 60.0 * std::f64::consts::PI / 180.0;
const MISALIGNMENT_ANGULAR_RAD: f64 = 2.0 / 60.0 * std::f64::consts::PI / 180.0;
/// Load classes of ball bearings by P/C (Table 14.6: heavy above 15 %) and the minimum load
/// 0.01 C below which the balls may skid (RB-6).
const HEAVY_LOAD_RATIO: f64 = 0.15;
const MINIMUM_LOAD_RATIO: f64 = 0.01;
/// Rollers: heavy above 18 % (Table 14.6), minimum 0.02 C (RB-6), misalignment 3′ (Table 14.8).
const HEAVY_LOAD_RATIO_ROLLER: f64 = 0.18;
const MINIMUM_LOAD_RATIO_ROLLER: f64 = 0.02;
const MISALIGNMENT_ROLLER_RAD: f64 = 3.0 / 60.0 * std::f64::consts::PI / 180.0;

/// The bearing of the chain, as the request gave it (its wire spec, parsed once): the steps read
/// their dimensions and materials from it.
#[derive(Debug, Clone, Copy)]
enum ChainBearing {
    Ball(BallBearingSpec),
    Roller(RollerBearingSpec),
}

impl ChainBearing {
    /// Rolling-element diameter D, m.
    fn element_diameter_m(&self) -> Positive {
        match self {
            ChainBearing::Ball(b) => b.ball_diameter_m,
            ChainBearing::Roller(r) => r.roller_diameter_m,
        }
    }

    fn pitch_diameter_m(&self) -> Positive {
        match self {
            ChainBearing::Ball(b) => b.pitch_diameter_m,
            ChainBearing::Roller(r) => r.pitch_diameter_m,
        }
    }

    fn element_count(&self) -> u32 {
        match self {
            ChainBearing::Ball(b) => b.ball_count,
            ChainBearing::Roller(r) => r.roller_count,
        }
    }

    /// The rolling elements' material and the rings'.
    fn materials(&self) -> (MaterialSpec, MaterialSpec) {
        match self {
            ChainBearing::Ball(b) => (b.ball, b.rings),
            ChainBearing::Roller(r) => (r.rollers, r.rings),
        }
    }
}

/// The validated chain: the typed cases of the steps that need no earlier result, and what the
/// later steps are built from.
#[derive(Debug, Clone)]
pub struct AnalysisCase {
    load_distribution: LoadDistributionRequest,
    /// The static-capacity step's case, or why it refused (a warning, not a 422: ISO 76 rates
    /// not every contact angle).
    static_capacity: Result<StaticCapacityCase, Vec<FieldError>>,
    life: LifeCase,
    bearing: ChainBearing,
    /// The lubricant and its pressure–viscosity law, for the films.
    film_lubricant: Lubricant,
    pressure_law: PressureLaw,
    temperature_c: f64,
    speed: RingSpeed,
    roughness: Option<RaceRoughness>,
    kinematic_viscosity_mm2_s: f64,
    bore_m: Option<f64>,
    lubrication_method: Option<AnalysisLubricationMethod>,
    misalignment_rad: Option<f64>,
    angular_contact: bool,
    /// A cylindrical roller bearing: line contacts, roller life exponent, roller limits.
    roller: bool,
    meniscus: Option<Positive>,
    film_effects: AnalysisFilmEffects,
}

impl Validate for AnalysisInput {
    type Valid = AnalysisCase;
    fn validate(mut self) -> Result<AnalysisCase, Vec<FieldError>> {
        let mut errors = Vec::new();
        let outer_rpm = self.outer_ring_speed_rpm.unwrap_or(0.0);
        for (v, p) in [
            (self.inner_ring_speed_rpm, "/inner_ring_speed_rpm"),
            (outer_rpm, "/outer_ring_speed_rpm"),
        ] {
            if !(v.is_finite() && v.abs() <= 1e6) {
                errors.push(FieldError::new(
                    p,
                    "must be a finite speed within ±1e6 rev/min",
                ));
            }
        }
        if self.inner_ring_speed_rpm == outer_rpm {
            errors.push(FieldError::new(
                "/inner_ring_speed_rpm",
                "the rings must turn relative to each other",
            ));
        }
        if let Some(r) = &self.roughness {
            for (v, field) in [
                (r.ball_rms_m, "ball_rms_m"),
                (r.inner_race_rms_m, "inner_race_rms_m"),
                (r.outer_race_rms_m, "outer_race_rms_m"),
            ] {
                if v.get() > MAX_RACE_RMS_M {
                    errors.push(FieldError::new(
                        format!("/roughness/{field}"),
                        format!("must be at most {MAX_RACE_RMS_M} m"),
                    ));
                }
            }
        }
        let roller = self.bearing.get("roller_diameter_m").is_some();
        let bearing = std::mem::take(&mut self.bearing);
        let spec = if roller {
            parse_at::<RollerBearingSpec>(bearing, "/bearing").map(ChainBearing::Roller)
        } else {
            parse_at::<BallBearingSpec>(bearing, "/bearing").map(ChainBearing::Ball)
        };
        let pitch_m = spec.as_ref().ok().map(|b| b.pitch_diameter_m().get());
        if let (Some(bore), Some(pitch)) = (self.bore_diameter_m, pitch_m) {
            if bore.get() >= pitch {
                errors.push(FieldError::new(
                    "/bore_diameter_m",
                    format!(
                        "the bore must be smaller than the pitch diameter {pitch} m, got {}",
                        bore.get()
                    ),
                ));
            }
        }
        if let Some(m) = self.misalignment_rad {
            if m.get() > 0.1 {
                errors.push(FieldError::new(
                    "/misalignment_rad",
                    format!("must be within [0, 0.1] rad, got {}", m.get()),
                ));
            }
        }
        let bearing_angle = match &spec {
            Ok(ChainBearing::Ball(b)) => b.free_contact_angle_deg.unwrap_or(0.0),
            _ => 0.0,
        };
        let axial_load_n = self.axial_load_n.unwrap_or(NonNegative::ZERO);
        let loading = Loading {
            radial_load_n: self.radial_load_n,
            axial_load_n,
            contact_angle_mode: ContactAngleMode::Varying,
            moment_n_m: None,
            inner_ring_speed_rpm: Some(self.inner_ring_speed_rpm),
            outer_ring_speed_rpm: Some(outer_rpm),
            effects: LoadDistributionEffects::default(),
        };
        let static_loading = StaticLoading {
            radial_load_n: self.radial_load_n,
            axial_load_n: Some(axial_load_n),
            x0_factor: None,
            y0_factor: None,
            static_load_rating_n: None,
            rotating: None,
            operation: Default::default(),
            quiet_running: Default::default(),
        };
        // The load distribution's and the static capacity's cases, from the bearing validated
        // once; their pointers are this request's (the fields share their names).
        let (load_distribution, static_capacity) = match &spec {
            Ok(ChainBearing::Ball(b)) => {
                let valid = b.validate_at("/bearing");
                (
                    loading.ball(valid.clone()),
                    static_loading.ball(bearing_angle, valid),
                )
            }
            Ok(ChainBearing::Roller(r)) => {
                let valid = r.validate_at("/bearing");
                (loading.roller(valid.clone()), static_loading.roller(valid))
            }
            Err(e) => (Err(e.clone()), Err(e.clone())),
        };
        let lubricant = self.lubricant.clone().parse("/lubricant");
        let t = self.temperature_c.get();
        let nu = lubricant
            .as_ref()
            .map(|l| l.kinematic_mm2_s(t))
            .unwrap_or(f64::NAN);
        if let Ok(l) = &lubricant {
            if l.pressure_law.is_none() {
                errors.push(FieldError::new(
                    "/lubricant",
                    "the EHL films need a pressure–viscosity law: give pressure_viscosity_coefficient_1_pa or roelands_pressure_viscosity_index",
                ));
            }
        }
        let life = self.life_input(roller, outer_rpm, pitch_m, nu, &mut errors);
        let life = if errors.is_empty() && nu.is_finite() {
            let equivalent_given = self.equivalent_load_n.is_some();
            life.map(|input| {
                input
                    .validate()
                    .map_err(|e| life_pointers(e, equivalent_given))
            })
        } else {
            None
        };
        for r in [
            load_distribution.as_ref().err(),
            lubricant.as_ref().err(),
            life.as_ref().and_then(|l| l.as_ref().err()),
        ]
        .into_iter()
        .flatten()
        {
            errors.extend(r.iter().cloned());
        }
        let film_lubricant = lubricant
            .ok()
            .and_then(|l| l.pressure_law.map(|law| (l, law)));
        match (
            errors.is_empty(),
            load_distribution,
            spec,
            life,
            film_lubricant,
        ) {
            (
                true,
                Ok(load_distribution),
                Ok(bearing),
                Some(Ok(life)),
                Some((film_lubricant, pressure_law)),
            ) => Ok(AnalysisCase {
                load_distribution,
                static_capacity,
                life,
                bearing,
                film_lubricant,
                pressure_law,
                temperature_c: t,
                speed: RingSpeed::new(self.inner_ring_speed_rpm, outer_rpm),
                roughness: self.roughness,
                kinematic_viscosity_mm2_s: nu,
                bore_m: self.bore_diameter_m.map(Positive::get),
                lubrication_method: self.lubrication_method,
                misalignment_rad: self.misalignment_rad.map(NonNegative::get),
                angular_contact: bearing_angle > 0.0,
                roller,
                meniscus: self.inlet_meniscus_distance_m,
                film_effects: self.film_effects,
            }),
            (true, ..) => Err(vec![FieldError::new(
                "/temperature_c",
                format!("the lubricant's kinematic viscosity at {t} °C is not a finite number"),
            )]),
            _ => Err(errors),
        }
    }
}

impl AnalysisInput {
    /// The life step's request from this one's fields (None, with the errors pushed, where
    /// they do not make one).
    fn life_input(
        &self,
        roller: bool,
        outer_rpm: f64,
        pitch_m: Option<f64>,
        nu: f64,
        errors: &mut Vec<FieldError>,
    ) -> Option<LifeInput> {
        let before = errors.len();
        let speed = (self.inner_ring_speed_rpm - outer_rpm)
            .abs()
            .max(f64::MIN_POSITIVE);
        let mut life = LifeInput {
            bearing_kind: if roller {
                BearingKind::Roller
            } else {
                BearingKind::Ball
            },
            dynamic_load_rating_n: self.dynamic_load_rating_n,
            equivalent_load_n: None,
            radial_load_n: None,
            axial_load_n: None,
            x_factor: None,
            y_factor: None,
            duty_cycle: None,
            speed_rpm: Positive::try_from(speed).ok(),
            reliability_percent: None,
            reliability_factor: None,
            weibull_slope: None,
            operating_viscosity_mm2_s: None,
            pitch_diameter_m: pitch_m.and_then(|d| Positive::try_from(d).ok()),
            kappa: None,
            contamination_factor: None,
            fatigue_load_limit_n: None,
        };
        let f_a = self.axial_load_n.map_or(0.0, NonNegative::get);
        match (self.equivalent_load_n, self.x_factor, self.y_factor) {
            (Some(p), None, None) => life.equivalent_load_n = Some(p),
            (None, Some(x), Some(y)) => {
                life.radial_load_n = Some(self.radial_load_n);
                life.axial_load_n = self.axial_load_n.or(Some(NonNegative::ZERO));
                life.x_factor = Some(x);
                life.y_factor = Some(y);
            }
            (None, None, None) if f_a == 0.0 => {
                life.equivalent_load_n =
                    Positive::try_from(self.radial_load_n.get().max(f64::MIN_POSITIVE)).ok()
            }
            _ => errors.push(FieldError::new(
                "/equivalent_load_n",
                "give equivalent_load_n, or x_factor with y_factor; P defaults to F_r only without axial load",
            )),
        }
        if let Some(r) = self.reliability_percent {
            match Reliability::try_from(r) {
                Ok(r) => life.reliability_percent = Some(r),
                Err(m) => errors.push(FieldError::new("/reliability_percent", m)),
            }
        }
        match (self.contamination_factor, self.fatigue_load_limit_n) {
            (Some(e), Some(cu)) => {
                match ContaminationFactor::try_from(e) {
                    Ok(e) => life.contamination_factor = Some(e),
                    Err(m) => errors.push(FieldError::new("/contamination_factor", m)),
                }
                life.fatigue_load_limit_n = Some(cu);
                life.operating_viscosity_mm2_s = Positive::try_from(nu).ok();
            }
            (None, None) => {}
            _ => errors.push(FieldError::new(
                "/contamination_factor",
                "give contamination_factor with fatigue_load_limit_n",
            )),
        }
        (errors.len() == before).then_some(life)
    }
}

/// The life step's pointers, moved onto the fields of this request they come from (P is the
/// request's `equivalent_load_n` where given, else built from `radial_load_n`).
fn life_pointers(errors: Vec<FieldError>, equivalent_given: bool) -> Vec<FieldError> {
    errors
        .into_iter()
        .map(|e| {
            let pointer = match e.pointer.as_str() {
                "/equivalent_load_n" if !equivalent_given => "/radial_load_n".to_owned(),
                "/speed_rpm" => "/inner_ring_speed_rpm".to_owned(),
                "/pitch_diameter_m" => "/bearing/pitch_diameter_m".to_owned(),
                "/operating_viscosity_mm2_s" | "/kappa" => "/lubricant".to_owned(),
                other => other.to_owned(),
            };
            FieldError::new(pointer, e.message)
        })
        .collect()
}

/// A step that refused the input the chain built for it (a 422 of the chain, naming the step).
fn refused(path: &str, errors: &[FieldError]) -> CalcError {
    let (pointer, message) = errors
        .first()
        .map_or(("", ""), |e| (e.pointer.as_str(), e.message.as_str()));
    CalcError::impossible(
        "",
        format!("a step of the chain ({path}) refused its input at {pointer}: {message}"),
    )
}

/// One raceway's film step: the raceway's radii, the element's load and entrainment speed, and
/// the raceway's roughness (with its field's name).
struct FilmStep {
    race_x_m: f64,
    race_y_m: Option<f64>,
    load_n: f64,
    speed_m_s: f64,
    race_rms: Option<(NonNegative, &'static str)>,
}

impl FilmStep {
    /// The film case of the closed-form film model, built from the chain's typed values; its
    /// refusals point into this request.
    fn case(&self, case: &AnalysisCase, ball: f64) -> Result<FilmCase, CalcError> {
        let (element, rings) = case.bearing.materials();
        let body = |radius_x: f64, radius_y: Option<f64>, material: MaterialSpec| Body {
            radius_x_m: Some(radius_x),
            radius_y_m: radius_y,
            modulus_pa: material.elastic_modulus_pa.get(),
            poisson_ratio: material.poisson_ratio.get(),
        };
        let line_length_m = match &case.bearing {
            ChainBearing::Roller(r) => Some(r.roller_effective_length_m.get()),
            ChainBearing::Ball(_) => None,
        };
        let load_n = self.load_n.max(f64::MIN_POSITIVE);
        let contact = Contact::new(
            [
                body(ball / 2.0, (!case.roller).then_some(ball / 2.0), element),
                body(self.race_x_m, self.race_y_m, rings),
            ],
            load_n,
            line_length_m.map_or(Shape::Point, |length_m| Shape::Line { length_m }),
            Method::Exact,
        )
        .map_err(|errors| {
            let e = &errors[0];
            film_refused(&contact_pointer(e.field, case.roller), &e.message)
        })?;
        let speed_m_s = self.speed_m_s.abs().max(1e-9);
        if let Some(why) = closed_form::speed_refusal(speed_m_s) {
            return Err(film_refused(
                "/inner_ring_speed_rpm",
                &format!("the entrainment speed {why}"),
            ));
        }
        let composite_roughness_m = match (case.roughness, self.race_rms) {
            (Some(r), Some((race, race_field))) => {
                let fields = ["ball_rms_m", race_field];
                let sigma = closed_form::composite_roughness([r.ball_rms_m.get(), race.get()])
                    .map_err(|(surface, why)| {
                        film_refused(&format!("/roughness/{}", fields[surface]), &why)
                    })?;
                Some(sigma)
            }
            _ => None,
        };
        let effects = FilmEffects {
            thermal: case.film_effects.thermal,
            starvation: case.film_effects.starvation,
            mixed_lubrication: case.film_effects.mixed_lubrication,
        };
        if let Some(refusal) = effects
            .refusals(case.meniscus.is_some(), line_length_m.is_some())
            .first()
        {
            return Err(film_refused(
                &format!("/film_effects/{}", refusal.effect()),
                refusal.message(),
            ));
        }
        Ok(FilmCase {
            contact,
            load_n,
            line_length_m,
            speed_m_s,
            lubricant: case.film_lubricant.clone(),
            pressure_law: case.pressure_law,
            temperature_c: case.temperature_c,
            composite_roughness_m,
            slide_roll_ratio: 0.0,
            meniscus_m: case.meniscus.map(Positive::get),
            effects,
        })
    }

    /// The raceway's film from the closed-form film model: its warnings and effect decisions
    /// passed to `step`, its refusals pointing into this request.
    fn solve(
        &self,
        case: &AnalysisCase,
        ball: f64,
        step: &mut Context,
    ) -> Result<EhlFilmOutput, CalcError> {
        let film_case = self.case(case, ball)?;
        let film = closed_form::solve(&film_case).map_err(|e| match e {
            CalcError::Impossible { pointer, message } => CalcError::Impossible {
                pointer: film_pointer(&pointer),
                message,
            },
            other => other,
        })?;
        step.record(&film.notes);
        Ok(EhlFilmOutput::of(&film, &film_case))
    }
}

/// A film step that refused the case the chain built for it: a 422 at the field of this
/// request it comes from.
fn film_refused(pointer: &str, message: &str) -> CalcError {
    CalcError::impossible(
        pointer,
        format!("a step of the chain (the EHL film) refused its input: {message}"),
    )
}

/// The field of this request a film's contact refusal comes from (body 1 is the rolling
/// element, body 2 the raceway).
fn contact_pointer(field: Field, roller: bool) -> String {
    let element = if roller { "rollers" } else { "ball" };
    match field {
        Field::Radius { .. } => "/bearing".to_owned(),
        Field::Modulus { body } | Field::PoissonRatio { body } => {
            let material = if body == 1 { element } else { "rings" };
            let name = if matches!(field, Field::Modulus { .. }) {
                "elastic_modulus_pa"
            } else {
                "poisson_ratio"
            };
            format!("/bearing/{material}/{name}")
        }
        Field::Load => "/radial_load_n".to_owned(),
        Field::Length => "/bearing/roller_effective_length_m".to_owned(),
    }
}

/// The film model's refusal pointers (the film room's fields), moved onto this request's.
fn film_pointer(pointer: &str) -> String {
    match pointer {
        "/entrainment_speed_m_s" => "/inner_ring_speed_rpm".to_owned(),
        "/load_n" => "/radial_load_n".to_owned(),
        p if p.starts_with("/body") => "/bearing".to_owned(),
        other => other.to_owned(),
    }
}

/// Result: each step's own result.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct AnalysisOutput {
    /// Ball loads, load zone and raceway contacts of the most loaded ball.
    pub load_distribution: LoadDistributionOutput,
    /// ISO 76 static load rating C0 and the static safety factor under the operating loads
    /// (`/v1/rolling-bearings/static-capacity`); absent, with a warning, where ISO 76 gives no
    /// X0, Y0 for the bearing's nominal contact angle.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub static_capacity: Option<StaticCapacityOutput>,
    /// Speeds at the most loaded ball's contact angle.
    pub kinematics: KinematicsOutput,
    /// EHL film at the inner raceway of the most loaded ball.
    pub inner_film: EhlFilmOutput,
    /// EHL film at the outer raceway of the most loaded ball.
    pub outer_film: EhlFilmOutput,
    /// L10, a1, a_ISO and the modified life.
    pub life: LifeOutput,
    /// Operating kinematic viscosity ν at `temperature_c`, mm²/s.
    pub operating_viscosity_mm2_s: f64,
    /// Viscosity ratio κ = ν/ν1 (ν1 the rated viscosity, ISO 281), dimensionless.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub kappa: Option<f64>,
    /// The smaller film parameter of the two raceways, Λ = h_min/σ, dimensionless.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub min_film_parameter_lambda: Option<f64>,
    /// Speed factor d·n, bore in mm × relative ring speed in rpm (Khonsari & Booser Table 14.5);
    /// the pitch diameter stands in when no bore is given.
    pub speed_dn_mm_rpm: f64,
    /// d_m·n, pitch diameter in mm × rpm (the measure of Khonsari & Booser Fig. 14.13).
    pub pitch_dn_mm_rpm: f64,
}

/// The chain's limit checks, as warnings (Khonsari & Booser §14.10–14.13, Tables 13.1,
/// 14.5–14.8, RB-6); returns (d·n, d_m·n).
fn limits(case: &AnalysisCase, pitch_m: f64, life: &LifeOutput, ctx: &mut Context) -> (f64, f64) {
    let n = case.speed.relative_rpm().abs();
    let pitch_dn = pitch_m * 1e3 * n;
    let dn = case.bore_m.map_or(pitch_dn, |d| d * 1e3 * n);
    let what = if case.bore_m.is_some() {
        "d·n"
    } else {
        "d_m·n (no bore given: the pitch diameter stands in, a conservative d·n)"
    };
    let (limit, method) = match case.lubrication_method {
        Some(AnalysisLubricationMethod::CirculatingOil) => (DN_CIRCULATING_OIL, "circulating oil"),
        Some(AnalysisLubricationMethod::GreaseOrBath) | None => {
            (DN_GREASE_OR_BATH, "grease or an oil bath")
        }
    };
    if dn > limit {
        ctx.warn(
            "speed_above_dn_limit",
            format!(
                "{what} = {dn:.0} mm·rpm exceeds the {limit:.0} of ball and cylindrical roller bearings with {method} (Khonsari & Booser Table 14.5{}); d_m·n = {pitch_dn:.0}: precision bearings, better cooling or a special design (about 2 × the catalogue limit) are needed",
                if case.lubrication_method.is_none() && dn <= DN_CIRCULATING_OIL {
                    "; within the 500 000 of circulating oil"
                } else {
                    ""
                }
            ),
        );
    }
    let t = case.temperature_c;
    validity::warn_hot_oil(ctx, "the bearing", t);
    if t > STABILISATION_C {
        ctx.warn(
            "temperature_above_steel_stabilisation",
            format!("{t} °C: 52100 bearing steel needs dimensional stabilisation above about 125 °C (limit 140–175 °C, Khonsari & Booser §14.12, Table 14.7)"),
        );
    }
    if let Some(m) = case.misalignment_rad {
        let (limit, kind) = if case.roller {
            (
                MISALIGNMENT_ROLLER_RAD,
                "cylindrical roller bearings (Table 14.8: 3–4′)",
            )
        } else if case.angular_contact {
            (
                MISALIGNMENT_ANGULAR_RAD,
                "angular-contact ball bearings (Table 13.1: ±2′)",
            )
        } else {
            (
                MISALIGNMENT_DEEP_GROOVE_RAD,
                "deep-groove ball bearings (Table 14.8: 12–16′)",
            )
        };
        if m > limit {
            ctx.warn(
                "misalignment_above_limit",
                format!(
                    "the misalignment {:.2}′ exceeds the limit of {kind} (Khonsari & Booser): expect life loss and cage wear",
                    m.to_degrees() * 60.0
                ),
            );
        }
    }
    let p_over_c = 1.0 / life.load_ratio;
    let (heavy, minimum, kind) = if case.roller {
        (HEAVY_LOAD_RATIO_ROLLER, MINIMUM_LOAD_RATIO_ROLLER, "roller")
    } else {
        (HEAVY_LOAD_RATIO, MINIMUM_LOAD_RATIO, "ball")
    };
    if p_over_c > heavy {
        ctx.warn(
            "heavy_load_class",
            format!("P/C = {p_over_c:.3} is a heavy load for a {kind} bearing (above {heavy}, Khonsari & Booser Table 14.6); with a heavy press fit 0.25–0.3 C risks cracking the ring"),
        );
    } else if p_over_c < minimum {
        ctx.warn(
            "below_minimum_load",
            format!("P/C = {p_over_c:.4} is below the minimum load {minimum} C of {kind} bearings (Khonsari & Booser RB-6): the rolling elements may skid; consider a preload"),
        );
    }
    (dn, pitch_dn)
}

impl Calculation for Analysis {
    const PATH: &'static str = "/v1/rolling-bearings/analysis";
    const SUMMARY: &'static str = "Ball or cylindrical roller bearing at one operating point: load distribution, static capacity, contact stresses, films, κ, life and limits";
    const DESCRIPTION: &'static str = include_str!("analysis.md");
    const FIDELITY: &'static [Level] = &[Level::ClosedForm];
    const EFFECTS: &'static [&'static str] = &[
        "thermal",
        "starvation",
        "mixed_lubrication",
        "centrifugal",
        "gyroscopic",
    ];
    const EXAMPLE: &'static str = r#"{"bearing": {"ball_diameter_m": 0.0127, "pitch_diameter_m": 0.065, "ball_count": 9, "inner_groove_radius_m": 0.006604, "outer_groove_radius_m": 0.006604, "diametral_clearance_m": 1.5e-5, "ball": {"elastic_modulus_pa": 2.08e11, "poisson_ratio": 0.3}, "rings": {"elastic_modulus_pa": 2.08e11, "poisson_ratio": 0.3}}, "radial_load_n": 8900, "inner_ring_speed_rpm": 2000, "lubricant": {"kinematic_viscosity_40c_mm2_s": 68, "kinematic_viscosity_100c_mm2_s": 8.6, "density_15c_kg_m3": 880, "pressure_viscosity_coefficient_1_pa": 2.0e-8}, "temperature_c": 70, "dynamic_load_rating_n": 35700, "contamination_factor": 0.5, "fatigue_load_limit_n": 1000, "roughness": {"ball_rms_m": 6.25e-8, "inner_race_rms_m": 1.75e-7, "outer_race_rms_m": 1.75e-7}}"#;

    type Input = AnalysisInput;
    type Output = AnalysisOutput;

    fn run(case: AnalysisCase, ctx: &mut Context) -> Result<AnalysisOutput, CalcError> {
        let mut step = ctx.child();
        let load_distribution = load_distribution::solve(case.load_distribution, &mut step)?;
        absorb(ctx, &mut step, "load distribution");
        if let Some(report) = step.report.take() {
            ctx.report(report);
        }

        let static_capacity = {
            let mut step = ctx.child();
            let rated = match &case.static_capacity {
                Ok(static_case) => static_capacity::solve(static_case, &mut step),
                Err(errors) => Err(refused(StaticCapacity::PATH, errors)),
            };
            match rated {
                Ok(out) => {
                    absorb(ctx, &mut step, "static capacity");
                    Some(out)
                }
                Err(CalcError::Impossible { message, .. }) => {
                    ctx.warn(
                        "static_capacity_not_rated",
                        format!("static capacity: {message}"),
                    );
                    None
                }
                Err(e) => return Err(e),
            }
        };

        let ball = case.bearing.element_diameter_m().get();
        let pitch = case.bearing.pitch_diameter_m().get();
        let most_loaded = load_distribution
            .element_loads
            .iter()
            .max_by(|a, b| a.load_n.total_cmp(&b.load_n))
            .ok_or_else(|| CalcError::Internal("no balls".into()))?;
        // The sign of a contact angle says only which groove shoulder the ball leans on; the
        // kinematics and the raceway radii take its magnitude (a symmetric solve can leave a
        // round-off −0).
        let alpha_deg = contact_angle_magnitude(most_loaded.contact_angle_deg);
        let alpha = alpha_deg.to_radians();
        let q_max = load_distribution.max_element_load_n;
        // With the centrifugal ball loads the outer contacts carry more, at their own angle:
        // the outer film sits at the ball with the largest outer load.
        let (q_outer, alpha_outer) = load_distribution
            .element_loads
            .iter()
            .filter_map(|b| Some((b.outer_load_n?, b.outer_contact_angle_deg?)))
            .max_by(|a, b| a.0.total_cmp(&b.0))
            .map_or((q_max, alpha), |(q, a)| {
                (q, contact_angle_magnitude(a).to_radians())
            });

        let kinematics_case = ContactAngle::try_from(alpha_deg)
            .map_err(|m| vec![FieldError::new("/contact_angle_deg", m)])
            .and_then(|angle| {
                KinematicsCase::new(
                    case.bearing.element_diameter_m(),
                    case.bearing.pitch_diameter_m(),
                    case.bearing.element_count(),
                    Some(angle),
                    case.speed,
                )
            })
            .map_err(|errors| refused(super::kinematics::Kinematics::PATH, &errors))?;
        let mut step = ctx.child();
        let kinematics = kinematics::solve(&kinematics_case, &mut step);
        absorb(ctx, &mut step, "kinematics");

        // A roller is a cylinder along y on straight raceways: a line contact over the effective
        // length (the texts' roller films, Hamrock A-R2); a ball meets the grooves' concave
        // radii across the rolling direction.
        let (inner_groove, outer_groove) = match &case.bearing {
            ChainBearing::Ball(b) => (
                Some(-b.inner_groove_radius_m.get()),
                Some(-b.outer_groove_radius_m.get()),
            ),
            ChainBearing::Roller(_) => (None, None),
        };
        let cos = alpha.cos();
        let inner_x = (pitch - ball * cos) / (2.0 * cos);
        let cos_o = alpha_outer.cos();
        let outer_x = -(pitch + ball * cos_o) / (2.0 * cos_o);
        let inner = FilmStep {
            race_x_m: inner_x,
            race_y_m: inner_groove,
            load_n: q_max,
            speed_m_s: kinematics.inner_contact_entrainment_speed_m_s,
            race_rms: case
                .roughness
                .map(|r| (r.inner_race_rms_m, "inner_race_rms_m")),
        };
        let outer = FilmStep {
            race_x_m: outer_x,
            race_y_m: outer_groove,
            load_n: q_outer,
            speed_m_s: kinematics.outer_contact_entrainment_speed_m_s,
            race_rms: case
                .roughness
                .map(|r| (r.outer_race_rms_m, "outer_race_rms_m")),
        };
        let mut inner_ctx = ctx.child();
        let inner_film = inner.solve(&case, ball, &mut inner_ctx)?;
        let mut outer_ctx = ctx.child();
        let outer_film = outer.solve(&case, ball, &mut outer_ctx)?;
        merge_films(ctx, &inner_ctx, &outer_ctx);
        absorb(ctx, &mut inner_ctx, "inner raceway film");
        absorb(ctx, &mut outer_ctx, "outer raceway film");

        let mut step = ctx.child();
        let life = life::life(&case.life, &mut step);
        absorb(ctx, &mut step, "life");
        let limits = limits(&case, pitch, &life, ctx);
        let kappa = life
            .rated_viscosity_mm2_s
            .map(|nu1| case.kinematic_viscosity_mm2_s / nu1);
        let lambda = match (
            inner_film.film_parameter_lambda,
            outer_film.film_parameter_lambda,
        ) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, b) => a.or(b),
        };
        Ok(AnalysisOutput {
            load_distribution,
            static_capacity,
            kinematics,
            inner_film,
            outer_film,
            life,
            operating_viscosity_mm2_s: case.kinematic_viscosity_mm2_s,
            kappa,
            min_film_parameter_lambda: lambda,
            speed_dn_mm_rpm: limits.0,
            pitch_dn_mm_rpm: limits.1,
        })
    }
}

/// A contact angle's magnitude within [0°, 90°]: the load distribution's angle is the line of
/// contact's direction, so −0° can come back as 180° (seen at 1e6 rev/min, where the inner
/// contact unloads) and 95° is the line 85° the other way.
fn contact_angle_magnitude(deg: f64) -> f64 {
    let a = deg.abs() % 180.0;
    if a > 90.0 {
        180.0 - a
    } else {
        a
    }
}

/// Fold a step's warnings into the chain's (naming the step), and its effect decisions where the
/// chain has none under that name yet.
fn absorb(ctx: &mut Context, step: &mut Context, step_name: &str) {
    for w in step.warnings.drain(..) {
        ctx.warn(w.code, format!("{step_name}: {}", w.message));
    }
    for (name, decision) in std::mem::take(&mut step.effects) {
        ctx.effects.entry(name).or_insert(decision);
    }
}

/// The films' effects over both raceways: applied where either applies, both reasons kept.
fn merge_films(ctx: &mut Context, inner: &Context, outer: &Context) {
    for (name, a) in &inner.effects {
        let merged = match outer.effects.get(name) {
            Some(b) => Decision {
                applied: a.applied || b.applied,
                mode: a.mode,
                reason: format!("inner raceway: {}; outer raceway: {}", a.reason, b.reason),
                criterion: a.criterion.clone(),
                model: a.model,
            },
            None => a.clone(),
        };
        ctx.decide(name, merged);
    }
}

#[cfg(test)]
#[path = "analysis_tests.rs"]
mod tests;
