//! `POST /v1/rolling-bearings/analysis`: the whole chain for one operating point of a ball
//! bearing — internal load distribution → Hertz at both raceways of the most loaded ball →
//! kinematics and entrainment speeds → EHL film and Λ at both raceways → κ and the modified
//! life — each step by the room that also answers it alone, so the numbers are theirs.

use serde::{Deserialize, Serialize};
use serde_json::{json, Value};
use utoipa::ToSchema;

use super::geometry::BallBearingSpec;
use super::kinematics::{Kinematics, KinematicsOutput};
use super::life::{Life, LifeOutput};
use super::load_distribution::{LoadDistribution, LoadDistributionOutput};
use super::static_capacity::{StaticCapacity, StaticCapacityOutput};
use crate::calc::contact::ehl_film::{EhlFilm, EhlFilmOutput};
use crate::calc::lubricant::LubricantSpec;
use crate::calc::quantity::{Celsius, NonNegative, Positive};
use crate::calc::{validate_value, CalcError, Calculation, Context, FieldError, Validate};
use crate::effects::{Decision, Mode};
use crate::fidelity::Level;

pub struct Analysis;

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
    /// Radial load F_r, N (≥ 0).
    #[schema(value_type = f64, minimum = 0.0, example = 8900.0)]
    pub radial_load_n: NonNegative,
    /// Axial load F_a, N (≥ 0; default 0).
    #[schema(value_type = Option<f64>, minimum = 0.0, example = 0.0)]
    pub axial_load_n: Option<NonNegative>,
    /// Inner-ring speed, rev/min (signed, |n| ≤ 1e6).
    #[schema(minimum = -1e6, maximum = 1e6, example = 2000.0)]
    pub inner_ring_speed_rpm: f64,
    /// Outer-ring speed, rev/min (signed, |n| ≤ 1e6; default 0).
    #[schema(minimum = -1e6, maximum = 1e6, example = 0.0)]
    pub outer_ring_speed_rpm: Option<f64>,
    /// The lubricant, with a pressure–viscosity law (for the EHL films).
    #[schema(value_type = LubricantSpec)]
    pub lubricant: Value,
    /// Operating temperature of the oil in the contacts, °C.
    #[schema(value_type = f64, minimum = -273.0, maximum = 1000.0, example = 70.0)]
    pub temperature_c: Celsius,
    /// Basic dynamic load rating C, N (catalogue).
    #[schema(value_type = f64, exclusive_minimum = 0.0, example = 35700.0)]
    pub dynamic_load_rating_n: Positive,
    /// Equivalent dynamic load P, N; default F_r when F_a = 0, else give it (or X and Y).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, example = 8900.0)]
    pub equivalent_load_n: Option<Positive>,
    /// Radial factor X for P = X F_r + Y F_a (with `y_factor`).
    #[schema(value_type = Option<f64>, minimum = 0.0, example = 0.56)]
    pub x_factor: Option<NonNegative>,
    /// Axial factor Y for P = X F_r + Y F_a (with `x_factor`).
    #[schema(value_type = Option<f64>, minimum = 0.0, example = 1.5)]
    pub y_factor: Option<NonNegative>,
    /// Reliability, % (default 90).
    #[schema(minimum = 0.0, maximum = 100.0, example = 90.0)]
    pub reliability_percent: Option<f64>,
    /// Contamination factor e_C (0 … 1), with `fatigue_load_limit_n`, for ISO 281's a_ISO.
    #[schema(minimum = 0.0, maximum = 1.0, example = 0.5)]
    pub contamination_factor: Option<f64>,
    /// Fatigue load limit C_u, N, with `contamination_factor`.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, example = 1000.0)]
    pub fatigue_load_limit_n: Option<Positive>,
    pub roughness: Option<RaceRoughness>,
    /// Bore d, m (< pitch diameter), for the speed limit d·n (Khonsari & Booser Table 14.5);
    /// absent: the pitch diameter stands in (conservative, d_m > d).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, example = 0.05)]
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
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, example = 0.0005)]
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
/// (Khonsari & Booser §14.12); mineral oil's limit 150 °C (Table 14.7).
const STABILISATION_C: f64 = 125.0;
const MINERAL_OIL_LIMIT_C: f64 = 150.0;
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

/// The validated chain: the requests of the steps that need no earlier result, and what the
/// later steps are built from.
#[derive(Debug, Clone)]
pub struct AnalysisCase {
    load_distribution: <<LoadDistribution as Calculation>::Input as Validate>::Valid,
    static_request: Value,
    life_request: Value,
    bearing: Value,
    lubricant: Value,
    temperature_c: f64,
    inner_rpm: f64,
    outer_rpm: f64,
    roughness: Option<RaceRoughness>,
    kinematic_viscosity_mm2_s: f64,
    bore_m: Option<f64>,
    lubrication_method: Option<AnalysisLubricationMethod>,
    misalignment_rad: Option<f64>,
    angular_contact: bool,
    /// A cylindrical roller bearing: line contacts, roller life exponent, roller limits.
    roller: bool,
    meniscus_m: Option<f64>,
    film_effects: AnalysisFilmEffects,
}

impl Validate for AnalysisInput {
    type Valid = AnalysisCase;
    fn validate(self) -> Result<AnalysisCase, Vec<FieldError>> {
        let mut errors = Vec::new();
        let (f_r, f_a) = (
            self.radial_load_n.get(),
            self.axial_load_n.map_or(0.0, NonNegative::get),
        );
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
        let pitch_m = self.bearing.get("pitch_diameter_m").and_then(Value::as_f64);
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
        let bearing_angle = self
            .bearing
            .get("free_contact_angle_deg")
            .and_then(Value::as_f64)
            .unwrap_or(0.0);
        let roller = self.bearing.get("roller_diameter_m").is_some();
        let load_distribution = validate_value::<LoadDistribution>(json!({
            "bearing": self.bearing, "radial_load_n": f_r, "axial_load_n": f_a,
            "inner_ring_speed_rpm": self.inner_ring_speed_rpm, "outer_ring_speed_rpm": outer_rpm,
        }));
        let lubricant =
            serde_path_to_error::deserialize::<_, LubricantSpec>(self.lubricant.clone())
                .map_err(|e| {
                    vec![FieldError::new(
                        format!("/lubricant{}", json_pointer(e.path())),
                        e.inner().to_string(),
                    )]
                })
                .and_then(|spec| spec.parse("/lubricant"));
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
        let bearing_pitch = self
            .bearing
            .get("pitch_diameter_m")
            .cloned()
            .unwrap_or(Value::Null);
        let mut life = json!({
            "bearing_kind": if roller { "roller" } else { "ball" },
            "dynamic_load_rating_n": self.dynamic_load_rating_n.get(),
            "speed_rpm": (self.inner_ring_speed_rpm - outer_rpm).abs().max(f64::MIN_POSITIVE),
            "pitch_diameter_m": bearing_pitch,
        });
        match (self.equivalent_load_n, self.x_factor, self.y_factor) {
            (Some(p), None, None) => life["equivalent_load_n"] = json!(p.get()),
            (None, Some(x), Some(y)) => {
                life["radial_load_n"] = json!(f_r);
                life["axial_load_n"] = json!(f_a);
                life["x_factor"] = json!(x.get());
                life["y_factor"] = json!(y.get());
            }
            (None, None, None) if f_a == 0.0 => life["equivalent_load_n"] = json!(f_r.max(f64::MIN_POSITIVE)),
            _ => errors.push(FieldError::new(
                "/equivalent_load_n",
                "give equivalent_load_n, or x_factor with y_factor; P defaults to F_r only without axial load",
            )),
        }
        if let Some(r) = self.reliability_percent {
            life["reliability_percent"] = json!(r);
        }
        match (self.contamination_factor, self.fatigue_load_limit_n) {
            (Some(e), Some(cu)) => {
                life["contamination_factor"] = json!(e);
                life["fatigue_load_limit_n"] = json!(cu.get());
                life["operating_viscosity_mm2_s"] = json!(nu);
            }
            (None, None) => {}
            _ => errors.push(FieldError::new(
                "/contamination_factor",
                "give contamination_factor with fatigue_load_limit_n",
            )),
        }
        let life_check = if errors.is_empty() && nu.is_finite() {
            validate_value::<Life>(life.clone()).map(|_| ())
        } else {
            Ok(())
        };
        for r in [
            load_distribution.as_ref().err(),
            lubricant.as_ref().err(),
            life_check.as_ref().err(),
        ]
        .into_iter()
        .flatten()
        {
            errors.extend(r.iter().cloned());
        }
        match (errors.is_empty(), load_distribution) {
            (true, Ok(load_distribution)) => Ok(AnalysisCase {
                load_distribution,
                static_request: json!({"bearing": self.bearing, "radial_load_n": f_r, "axial_load_n": f_a}),
                life_request: life,
                bearing: self.bearing,
                lubricant: self.lubricant,
                temperature_c: t,
                inner_rpm: self.inner_ring_speed_rpm,
                outer_rpm,
                roughness: self.roughness,
                kinematic_viscosity_mm2_s: nu,
                bore_m: self.bore_diameter_m.map(Positive::get),
                lubrication_method: self.lubrication_method,
                misalignment_rad: self.misalignment_rad.map(NonNegative::get),
                angular_contact: bearing_angle > 0.0,
                roller,
                meniscus_m: self.inlet_meniscus_distance_m.map(Positive::get),
                film_effects: self.film_effects,
            }),
            _ => Err(errors),
        }
    }
}

fn json_pointer(path: &serde_path_to_error::Path) -> String {
    path.iter().map(|s| format!("/{s}")).collect()
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
    let n = (case.inner_rpm - case.outer_rpm).abs();
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
    if t > MINERAL_OIL_LIMIT_C {
        ctx.warn(
            "temperature_above_mineral_oil_limit",
            format!("{t} °C exceeds the 150 °C limit of mineral oils (and 110–150 °C of petroleum greases; Khonsari & Booser Table 14.7): a synthetic lubricant is needed"),
        );
    }
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
        let load_distribution = LoadDistribution::run(case.load_distribution, &mut step)?;
        absorb(ctx, &mut step, "load distribution");
        if let Some(report) = step.report.take() {
            ctx.report(report);
        }

        let static_capacity = {
            let mut step = ctx.child();
            match sub_in::<StaticCapacity>(case.static_request.clone(), &mut step) {
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

        let element_key = if case.roller {
            "roller_diameter_m"
        } else {
            "ball_diameter_m"
        };
        let ball = case.bearing[element_key].as_f64().unwrap_or(f64::NAN);
        let count = if case.roller {
            case.bearing["roller_count"].clone()
        } else {
            case.bearing["ball_count"].clone()
        };
        let pitch = case.bearing["pitch_diameter_m"]
            .as_f64()
            .unwrap_or(f64::NAN);
        let most_loaded = load_distribution
            .ball_loads
            .iter()
            .max_by(|a, b| a.load_n.total_cmp(&b.load_n))
            .ok_or_else(|| CalcError::Internal("no balls".into()))?;
        // The sign of a contact angle says only which groove shoulder the ball leans on; the
        // kinematics and the raceway radii take its magnitude (a symmetric solve can leave a
        // round-off −0).
        let alpha_deg = most_loaded.contact_angle_deg.abs();
        let alpha = alpha_deg.to_radians();
        let q_max = load_distribution.max_ball_load_n;
        // With the centrifugal ball loads the outer contacts carry more, at their own angle:
        // the outer film sits at the ball with the largest outer load.
        let (q_outer, alpha_outer) = load_distribution
            .ball_loads
            .iter()
            .filter_map(|b| Some((b.outer_load_n?, b.outer_contact_angle_deg?)))
            .max_by(|a, b| a.0.total_cmp(&b.0))
            .map_or((q_max, alpha), |(q, a)| (q, a.abs().to_radians()));

        let kinematics_request = json!({
            "ball_diameter_m": ball, "pitch_diameter_m": pitch,
            "ball_count": count, "contact_angle_deg": alpha_deg,
            "inner_ring_speed_rpm": case.inner_rpm, "outer_ring_speed_rpm": case.outer_rpm,
        });
        let kinematics = sub::<Kinematics>(kinematics_request, ctx, "kinematics")?;

        let material = |key: &str| case.bearing[key].clone();
        let element = material(if case.roller { "rollers" } else { "ball" });
        // A roller is a cylinder along y on straight raceways: a line contact over the effective
        // length (the texts' roller films, Hamrock A-R2); a ball meets the grooves' concave
        // radii across the rolling direction.
        let ball_body = if case.roller {
            json!({"radius_x_m": ball / 2.0,
                "elastic_modulus_pa": element["elastic_modulus_pa"], "poisson_ratio": element["poisson_ratio"]})
        } else {
            json!({"radius_x_m": ball / 2.0, "radius_y_m": ball / 2.0,
                "elastic_modulus_pa": element["elastic_modulus_pa"], "poisson_ratio": element["poisson_ratio"]})
        };
        let race = |radius_x: f64, groove: &str| {
            let mut body = json!({"radius_x_m": radius_x,
                "elastic_modulus_pa": material("rings")["elastic_modulus_pa"], "poisson_ratio": material("rings")["poisson_ratio"]});
            if !case.roller {
                body["radius_y_m"] = json!(-case.bearing[groove].as_f64().unwrap_or(f64::NAN));
            }
            body
        };
        let film = |race_body: Value, load: f64, speed: f64, race_rms: Option<f64>| {
            let mut request = json!({
                "body1": ball_body, "body2": race_body, "load_n": load.max(f64::MIN_POSITIVE),
                "entrainment_speed_m_s": speed.abs().max(1e-9), "lubricant": case.lubricant, "temperature_c": case.temperature_c,
                "effects": {"thermal": case.film_effects.thermal, "starvation": case.film_effects.starvation,
                            "mixed_lubrication": case.film_effects.mixed_lubrication},
            });
            if let Some(m) = case.meniscus_m {
                request["inlet_meniscus_distance_m"] = json!(m);
            }
            if case.roller {
                request["line"] = json!({"length_m": case.bearing["roller_effective_length_m"]});
            }
            if let (Some(r), Some(race)) = (case.roughness, race_rms) {
                request["roughness"] =
                    json!({"body1_rms_m": r.ball_rms_m.get(), "body2_rms_m": race});
            }
            request
        };
        let cos = alpha.cos();
        let inner_race = race((pitch - ball * cos) / (2.0 * cos), "inner_groove_radius_m");
        let cos_o = alpha_outer.cos();
        let outer_race = race(
            -(pitch + ball * cos_o) / (2.0 * cos_o),
            "outer_groove_radius_m",
        );
        let mut inner_ctx = ctx.child();
        let inner_film = sub_in::<EhlFilm>(
            film(
                inner_race,
                q_max,
                kinematics.inner_contact_entrainment_speed_m_s,
                case.roughness.map(|r| r.inner_race_rms_m.get()),
            ),
            &mut inner_ctx,
        )?;
        let mut outer_ctx = ctx.child();
        let outer_film = sub_in::<EhlFilm>(
            film(
                outer_race,
                q_outer,
                kinematics.outer_contact_entrainment_speed_m_s,
                case.roughness.map(|r| r.outer_race_rms_m.get()),
            ),
            &mut outer_ctx,
        )?;
        merge_films(ctx, &inner_ctx, &outer_ctx);
        absorb(ctx, &mut inner_ctx, "inner raceway film");
        absorb(ctx, &mut outer_ctx, "outer raceway film");

        let life = sub::<Life>(case.life_request.clone(), ctx, "life")?;
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

/// Run one step in its own context, its warnings folded into ours.
fn sub<C: Calculation>(
    request: Value,
    ctx: &mut Context,
    step_name: &str,
) -> Result<C::Output, CalcError> {
    let mut step = ctx.child();
    let out = sub_in::<C>(request, &mut step)?;
    absorb(ctx, &mut step, step_name);
    Ok(out)
}

fn sub_in<C: Calculation>(request: Value, step: &mut Context) -> Result<C::Output, CalcError> {
    let case = validate_value::<C>(request).map_err(|errors| {
        let e = errors.into_iter().next().map_or_else(
            || ("".to_owned(), String::new()),
            |e| (e.pointer, e.message),
        );
        CalcError::impossible(
            "",
            format!(
                "a step of the chain ({}) refused its input at {}: {}",
                C::PATH,
                e.0,
                e.1
            ),
        )
    })?;
    C::run(case, step)
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
mod tests {
    use super::*;
    use crate::calc::testing::{invalid_pointers, ok};

    fn example() -> Value {
        serde_json::from_str(Analysis::EXAMPLE).unwrap()
    }

    /// The chain's numbers are its steps': the same requests to the rooms alone give the same
    /// results, and the films sit at the most loaded ball with its load and speeds.
    #[test]
    fn the_chain_is_its_rooms() {
        let v = ok::<Analysis>(&example());
        let r = &v["result"];
        let alone = ok::<LoadDistribution>(&json!({
            "bearing": example()["bearing"], "radial_load_n": 8900.0, "axial_load_n": 0.0,
            "inner_ring_speed_rpm": 2000.0, "outer_ring_speed_rpm": 0.0,
        }));
        assert_eq!(r["load_distribution"], alone["result"]);
        let static_alone = ok::<StaticCapacity>(
            &json!({"bearing": example()["bearing"], "radial_load_n": 8900.0, "axial_load_n": 0.0}),
        );
        assert_eq!(r["static_capacity"], static_alone["result"]);
        let q = r["load_distribution"]["max_ball_load_n"].as_f64().unwrap();
        // The film's Hertz pressure at Q_max equals the load distribution's inner contact.
        let p_film = r["inner_film"]["max_hertz_pressure_pa"].as_f64().unwrap();
        let p_ld = r["load_distribution"]["inner_contact"]["max_pressure_pa"]
            .as_f64()
            .unwrap();
        assert!(
            (p_film / p_ld - 1.0).abs() < 1e-3,
            "{p_film} vs {p_ld} at Q = {q}"
        );
        let kappa = r["kappa"].as_f64().unwrap();
        assert!((kappa - r["life"]["kappa"].as_f64().unwrap()).abs() < 1e-9);
        assert!(r["min_film_parameter_lambda"].as_f64().unwrap() > 0.0);
        for effect in ["thermal", "starvation", "mixed_lubrication"] {
            assert!(
                v["effects"][effect]["reason"]
                    .as_str()
                    .unwrap()
                    .contains("inner raceway"),
                "{effect}"
            );
        }
    }

    /// At speed the chain's load distribution is the ball-by-ball one: the outer film sits at
    /// the largest outer load, which exceeds the inner by about F_c.
    #[test]
    fn at_speed_the_outer_film_carries_the_centrifugal_force() {
        let mut r = example();
        r["inner_ring_speed_rpm"] = json!(30000.0);
        r["radial_load_n"] = json!(2000.0);
        let v = ok::<Analysis>(&r);
        assert_eq!(v["effects"]["centrifugal"]["applied"], true);
        let ld = &v["result"]["load_distribution"];
        let q_o = ld["max_outer_ball_load_n"].as_f64().unwrap();
        assert!(q_o > ld["max_ball_load_n"].as_f64().unwrap());
        // The film's Hertz pressure at the outer raceway is the load distribution's.
        let p_film = v["result"]["outer_film"]["max_hertz_pressure_pa"]
            .as_f64()
            .unwrap();
        let p_ld = ld["outer_contact"]["max_pressure_pa"].as_f64().unwrap();
        assert!((p_film / p_ld - 1.0).abs() < 1e-3, "{p_film} vs {p_ld}");
    }

    fn codes(v: &Value) -> Vec<String> {
        v["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .map(|w| w["code"].as_str().unwrap().to_owned())
            .collect()
    }

    /// Khonsari & Booser Ex 14.7: a 110 mm shaft at 5000 rpm, pitch diameter 150 mm: d·n =
    /// 550 000 above the 500 000 of circulating oil (d_m·n = 750 000, Fig. 14.13's angular-contact
    /// or cylindrical-roller territory).
    #[test]
    fn khonsari_ex_14_7_speed_limit() {
        let mut r = example();
        r["bearing"] = json!({"ball_diameter_m": 0.022225, "pitch_diameter_m": 0.15, "ball_count": 14,
            "inner_groove_radius_m": 0.52 * 0.022225, "outer_groove_radius_m": 0.52 * 0.022225,
            "diametral_clearance_m": 2e-5,
            "ball": {"elastic_modulus_pa": 2.08e11, "poisson_ratio": 0.3},
            "rings": {"elastic_modulus_pa": 2.08e11, "poisson_ratio": 0.3}});
        r["inner_ring_speed_rpm"] = json!(5000.0);
        r["radial_load_n"] = json!(10000.0);
        r["dynamic_load_rating_n"] = json!(150000.0);
        r["bore_diameter_m"] = json!(0.11);
        r["lubrication_method"] = json!("circulating_oil");
        let v = ok::<Analysis>(&r);
        assert!((v["result"]["speed_dn_mm_rpm"].as_f64().unwrap() - 550000.0).abs() < 1e-6);
        assert!((v["result"]["pitch_dn_mm_rpm"].as_f64().unwrap() - 750000.0).abs() < 1e-6);
        assert!(codes(&v).contains(&"speed_above_dn_limit".to_owned()));
        r["inner_ring_speed_rpm"] = json!(4000.0);
        assert!(!codes(&ok::<Analysis>(&r)).contains(&"speed_above_dn_limit".to_owned()));
    }

    /// Temperature (Table 14.7), misalignment (Tables 14.8, 13.1) and load class (Table 14.6).
    #[test]
    fn limits_warn() {
        let v = ok::<Analysis>(&example());
        // The example: P/C = 8900/35 700 = 0.25, a heavy load.
        assert!(codes(&v).contains(&"heavy_load_class".to_owned()));
        assert!(!codes(&v).contains(&"misalignment_above_limit".to_owned()));
        let mut r = example();
        r["temperature_c"] = json!(160.0);
        r["misalignment_rad"] = json!(0.005); // 17.2′ > 12′
        let c = codes(&ok::<Analysis>(&r));
        for code in [
            "temperature_above_mineral_oil_limit",
            "temperature_above_steel_stabilisation",
            "misalignment_above_limit",
        ] {
            assert!(c.contains(&code.to_owned()), "{code}");
        }
        r["temperature_c"] = json!(70.0);
        r["misalignment_rad"] = json!(0.002); // 6.9′: within 12′, beyond an angular contact's 2′
        assert!(!codes(&ok::<Analysis>(&r)).contains(&"misalignment_above_limit".to_owned()));
        r["bearing"]["free_contact_angle_deg"] = json!(25.0);
        r["axial_load_n"] = json!(3000.0);
        r["equivalent_load_n"] = json!(9000.0);
        assert!(codes(&ok::<Analysis>(&r)).contains(&"misalignment_above_limit".to_owned()));
        let mut bad = example();
        bad["misalignment_rad"] = json!(0.2);
        bad["bore_diameter_m"] = json!(0.2);
        let p = invalid_pointers::<Analysis>(&bad);
        assert!(
            p.contains(&"/misalignment_rad".to_owned())
                && p.contains(&"/bore_diameter_m".to_owned())
        );
    }

    /// The films' effects reach the EHL room: starvation from the meniscus distance (on, and
    /// judged in auto), thermal off on request.
    #[test]
    fn film_effects_pass_through() {
        let mut r = example();
        r["inlet_meniscus_distance_m"] = json!(6e-4);
        r["film_effects"] = json!({"thermal": "off", "starvation": "on"});
        let v = ok::<Analysis>(&r);
        assert_eq!(v["effects"]["thermal"]["applied"], false);
        assert_eq!(v["effects"]["thermal"]["mode"], "off");
        assert_eq!(
            v["effects"]["starvation"]["applied"], true,
            "{}",
            v["effects"]["starvation"]
        );
        let mut flooded = example();
        flooded["film_effects"] = json!({"thermal": "off"});
        let flooded = ok::<Analysis>(&flooded);
        let h = |v: &Value| {
            v["result"]["inner_film"]["min_film_thickness_m"]
                .as_f64()
                .unwrap()
        };
        assert!(h(&v) <= h(&flooded));
        // In auto, that meniscus lies beyond both critical distances: reported, not applied.
        r["film_effects"] = json!({"starvation": "auto"});
        let auto = ok::<Analysis>(&r);
        assert_eq!(auto["effects"]["starvation"]["applied"], false);
        assert!(
            auto["effects"]["starvation"]["criterion"]["value"]
                .as_f64()
                .unwrap()
                > 0.0
        );
    }

    /// Hamrock's A-R2 cylindrical roller bearing through the chain: d_i = 64, d_o = 96 mm,
    /// D = l = 16 mm, n = 9, F_r = 10 800 N, ω_i = 524 rad/s, η₀ = 0.01 Pa·s, ξ = 2.2e-8 m²/N,
    /// E = 207.5 GPa, ν = 0.3. Source (spec A-R2, verified): u = 10.061 m/s, inner
    /// h_min = 0.3233 µm, outer 0.3905 µm with the point formula at k → ∞ and F_max = 4800 N
    /// (4 F_r/n). The chain's Q_max comes from the discrete 10/9 law (about 4934 N): the films
    /// scale by (Q/4800)^−0.073, under 0.3 %, inside the source's ±1 %.
    #[test]
    fn hamrock_a_r2_roller_chain() {
        let steel = json!({"elastic_modulus_pa": 2.075e11, "poisson_ratio": 0.3});
        let r = json!({
            "bearing": {"roller_diameter_m": 0.016, "roller_effective_length_m": 0.016,
                "pitch_diameter_m": 0.08, "roller_count": 9, "diametral_clearance_m": 0.0,
                "rollers": steel, "rings": steel},
            "radial_load_n": 10800.0,
            "inner_ring_speed_rpm": 524.0 * 60.0 / std::f64::consts::TAU,
            "lubricant": {"viscosity_pa_s": 0.01, "pressure_viscosity_coefficient_1_pa": 2.2e-8},
            "temperature_c": 40.0,
            "dynamic_load_rating_n": 100000.0,
        });
        let v = ok::<Analysis>(&r);
        let res = &v["result"];
        let f = |film: &str| {
            res[film]["formulas"]["hamrock_dowson_line_limit"]["min_film_thickness_m"]
                .as_f64()
                .unwrap()
        };
        let q = res["load_distribution"]["max_ball_load_n"]
            .as_f64()
            .unwrap();
        let s = (q / 4800.0).powf(-0.073);
        assert!(
            (f("inner_film") / (0.3233e-6 * s) - 1.0).abs() < 0.01,
            "{}",
            f("inner_film")
        );
        assert!(
            (f("outer_film") / (0.3905e-6 * s) - 1.0).abs() < 0.01,
            "{}",
            f("outer_film")
        );
        assert!(
            (res["kinematics"]["inner_contact_entrainment_speed_m_s"]
                .as_f64()
                .unwrap()
                / 10.061
                - 1.0)
                .abs()
                < 1e-3
        );
        assert_eq!(res["life"]["life_exponent"].as_f64().unwrap(), 10.0 / 3.0);
        assert!(
            res["static_capacity"]["basic_static_load_rating_n"]
                .as_f64()
                .unwrap()
                > 0.0
        );
        assert_eq!(res["inner_film"]["contact"], "line");
    }

    /// ISO 76 tabulates no X0, Y0 for a 10° angular-contact bearing: the chain runs on and says
    /// why its static block is missing.
    #[test]
    fn an_unrated_angle_drops_the_static_block_with_a_warning() {
        let mut r = example();
        r["bearing"]["free_contact_angle_deg"] = json!(10.0);
        let v = ok::<Analysis>(&r);
        assert!(v["result"].get("static_capacity").is_none());
        assert!(v["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .any(|w| w["code"] == "static_capacity_not_rated"));
    }

    #[test]
    fn invalid_steps_name_their_fields() {
        let mut bad = example();
        bad["bearing"]["ball_count"] = json!(0);
        assert!(invalid_pointers::<Analysis>(&bad)
            .iter()
            .any(|p| p.starts_with("/bearing")));
        let mut no_law = example();
        no_law["lubricant"] = json!({"viscosity_pa_s": 0.02});
        assert_eq!(invalid_pointers::<Analysis>(&no_law), vec!["/lubricant"]);
        let mut axial = example();
        axial["axial_load_n"] = json!(2000.0);
        assert!(invalid_pointers::<Analysis>(&axial).contains(&"/equivalent_load_n".to_owned()));
        let mut typo = example();
        typo["lubricant"]["viscosty_pa_s"] = json!(1.0);
        assert!(invalid_pointers::<Analysis>(&typo)
            .iter()
            .any(|p| p == "/lubricant/viscosty_pa_s"));
    }
}
