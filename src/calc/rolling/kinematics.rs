//! `POST /v1/rolling-bearings/kinematics`: cage and ball speeds, bearing defect frequencies and
//! the rolling (entrainment) speeds at the inner and outer contacts of a ball or roller bearing
//! with either ring, both rings or counter-rotating rings turning.
//!
//! Model (Hamrock eqs 21.93–21.98; Khonsari & Booser §14.5, §14.7, eqs 14.27–14.37): pure
//! rolling at both contacts, the same contact angle α at both races, the ball's spin axis
//! perpendicular to the line through its two contacts ("race-control-free"); no gyroscopic or
//! centrifugal effects, no skidding. With D the ball (roller) diameter, d_m the pitch diameter,
//! γ = D cos α / d_m and ring speeds n_i, n_o (signed, same positive sense):
//! - cage n_c = ½[n_i(1 − γ) + n_o(1 + γ)];
//! - rings relative to the cage: n_i − n_c = ½(n_i − n_o)(1 + γ), n_o − n_c = −½(n_i − n_o)(1 − γ);
//! - ball spin about its own axis relative to the cage (Khonsari's f_r):
//!   n_b = (d_m/2D)(1 − γ²)(n_i − n_o);
//! - the same spin seen from the fixed frame (Hamrock eq 21.94):
//!   n_b,abs = (d_m/2D)[n_i(1 − γ) − n_o(1 + γ)] = n_b − n_c cos α;
//! - entrainment (mean rolling) speed, the same at both contacts:
//!   ū = (π d_m/120)|n_i − n_o|(1 − γ²) m/s with n in rpm (Hamrock's u = |ω_i − ω_o|(d_e/4)(1 − γ²)).
//!
//! Defect frequencies are magnitudes in Hz: FTF = |n_c|/60; BPFO = Z|n_o − n_c|/60;
//! BPFI = Z|n_i − n_c|/60; BSF = |n_b|/60 (the ball's spin relative to the cage). Some sources
//! call 2·BSF the ball defect frequency (a defect striking both races once per spin): it is
//! reported separately as `ball_defect_frequency_hz`.

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use crate::calc::quantity::{Positive, RingSpeed};
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::fidelity::Level;

pub struct Kinematics;

/// Largest diameter accepted, m.
const MAX_DIAMETER_M: f64 = 100.0;
/// Largest ring speed magnitude accepted, rpm.
const MAX_SPEED_RPM: f64 = 1e7;
/// Largest number of rolling elements accepted.
const MAX_BALL_COUNT: u32 = 10_000;

/// One ring's speed in rpm as the request gives it: finite, signed (positive in the sense the
/// request chooses), |n| ≤ 1e7.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(try_from = "f64")]
pub struct RingRpm(f64);

impl RingRpm {
    pub fn get(self) -> f64 {
        self.0
    }
}

impl TryFrom<f64> for RingRpm {
    type Error = String;
    fn try_from(v: f64) -> Result<Self, String> {
        if v.is_finite() && v.abs() <= MAX_SPEED_RPM {
            Ok(RingRpm(v))
        } else {
            Err(format!(
                "must be a finite speed in rpm with |n| ≤ {MAX_SPEED_RPM:e}, got {v}"
            ))
        }
    }
}

/// A contact angle in degrees within [0, 90].
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(try_from = "f64")]
pub struct ContactAngle(f64);

impl TryFrom<f64> for ContactAngle {
    type Error = String;
    fn try_from(v: f64) -> Result<Self, String> {
        if v.is_finite() && (0.0..=90.0).contains(&v) {
            Ok(ContactAngle(v))
        } else {
            Err(format!(
                "must be a contact angle in degrees within [0, 90], got {v}"
            ))
        }
    }
}

/// Request: the bearing's geometry and the two ring speeds.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct KinematicsInput {
    /// Ball (or mean roller) diameter D, m, > 0 and less than the pitch diameter.
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 100.0, example = 0.0127)]
    pub ball_diameter_m: Positive,
    /// Pitch diameter d_m (Hamrock's d_e), m: the diameter of the circle through the ball
    /// centres, (d_i + d_o)/2 of the raceway contact diameters; > ball_diameter_m.
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 100.0, example = 0.07)]
    pub pitch_diameter_m: Positive,
    /// Number of balls (rollers) Z, 1 … 10000.
    #[schema(minimum = 1, maximum = 10000, example = 10)]
    pub ball_count: u32,
    /// Contact angle α, degrees, 0 … 90 (0 for radial deep-groove and cylindrical roller
    /// bearings, 90 for a thrust bearing); default 0.
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 90.0, example = 0.0)]
    pub contact_angle_deg: Option<ContactAngle>,
    /// Inner ring speed n_i, rpm, signed (|n| ≤ 1e7); default 0. Rings turning the opposite
    /// way have opposite signs.
    #[schema(value_type = Option<f64>, minimum = -1e7, maximum = 1e7, example = 1800.0)]
    pub inner_ring_speed_rpm: Option<RingRpm>,
    /// Outer ring speed n_o, rpm, signed in the same sense as the inner ring's (|n| ≤ 1e7);
    /// default 0.
    #[schema(value_type = Option<f64>, minimum = -1e7, maximum = 1e7, example = 0.0)]
    pub outer_ring_speed_rpm: Option<RingRpm>,
}

/// The validated case.
#[derive(Debug, Clone, Copy)]
pub struct KinematicsCase {
    ball_diameter_m: f64,
    pitch_diameter_m: f64,
    ball_count: u32,
    contact_angle_rad: f64,
    speed: RingSpeed,
}

impl Validate for KinematicsInput {
    type Valid = KinematicsCase;
    fn validate(self) -> Result<KinematicsCase, Vec<FieldError>> {
        KinematicsCase::new(
            self.ball_diameter_m,
            self.pitch_diameter_m,
            self.ball_count,
            self.contact_angle_deg,
            RingSpeed::new(
                self.inner_ring_speed_rpm.map_or(0.0, RingRpm::get),
                self.outer_ring_speed_rpm.map_or(0.0, RingRpm::get),
            ),
        )
    }
}

impl KinematicsCase {
    /// A case from typed values; the pointers of its errors are the kinematics request's.
    pub(super) fn new(
        ball_diameter_m: Positive,
        pitch_diameter_m: Positive,
        ball_count: u32,
        contact_angle_deg: Option<ContactAngle>,
        speed: RingSpeed,
    ) -> Result<KinematicsCase, Vec<FieldError>> {
        let mut errors = Vec::new();
        let d = ball_diameter_m.get();
        let dm = pitch_diameter_m.get();
        for (value, pointer) in [(d, "/ball_diameter_m"), (dm, "/pitch_diameter_m")] {
            if value > MAX_DIAMETER_M {
                errors.push(FieldError::new(
                    pointer,
                    format!("must be at most {MAX_DIAMETER_M} m, got {value}"),
                ));
            }
        }
        if d < 1e-3 * dm || dm < 1e-4 {
            errors.push(FieldError::new(
                "/ball_diameter_m",
                format!("D/d_m must be at least 1e-3 and d_m at least 0.1 mm (real bearings: D/d_m ≈ 0.1–0.35), got D = {d} m, d_m = {dm} m"),
            ));
        }
        if d >= dm {
            errors.push(FieldError::new(
                "/ball_diameter_m",
                format!(
                    "the ball diameter {d} m must be smaller than the pitch diameter {dm} m (the inner raceway diameter d_m − D cos α must stay positive)"
                ),
            ));
        }
        if !(1..=MAX_BALL_COUNT).contains(&ball_count) {
            errors.push(FieldError::new(
                "/ball_count",
                format!("must be within [1, {MAX_BALL_COUNT}], got {ball_count}"),
            ));
        }
        if !errors.is_empty() {
            return Err(errors);
        }
        Ok(KinematicsCase {
            ball_diameter_m: d,
            pitch_diameter_m: dm,
            ball_count,
            contact_angle_rad: contact_angle_deg.map_or(0.0, |a| a.0.to_radians()),
            speed,
        })
    }
}

/// Result. Speeds in rpm are signed in the request's sense; frequencies in Hz are magnitudes.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct KinematicsOutput {
    /// γ = D cos α / d_m, dimensionless (0 ≤ γ < 1).
    #[schema(example = 0.181)]
    pub diameter_ratio: f64,
    /// Cage (ball-set) speed n_c = ½[n_i(1 − γ) + n_o(1 + γ)], rpm, signed.
    #[schema(example = 736.7)]
    pub cage_speed_rpm: f64,
    /// Inner ring speed relative to the cage, n_i − n_c = ½(n_i − n_o)(1 + γ), rpm, signed
    /// (Hamrock's ω_ir).
    #[schema(example = 1063.3)]
    pub inner_ring_speed_relative_to_cage_rpm: f64,
    /// Outer ring speed relative to the cage, n_o − n_c = −½(n_i − n_o)(1 − γ), rpm, signed
    /// (Hamrock's ω_or).
    #[schema(example = -736.7)]
    pub outer_ring_speed_relative_to_cage_rpm: f64,
    /// Ball (roller) spin about its own axis relative to the cage,
    /// n_b = (d_m/2D)(1 − γ²)(n_i − n_o), rpm; positive when the inner ring turns faster than
    /// the outer ring in the positive sense, the ball then turning the other way (Khonsari &
    /// Booser's f_r). BSF is its magnitude in Hz.
    #[schema(example = 4797.4)]
    pub ball_spin_speed_rpm: f64,
    /// The same spin seen from the fixed frame (its component on the ball's axis):
    /// (d_m/2D)[n_i(1 − γ) − n_o(1 + γ)] = n_b − n_c cos α, rpm, same sign convention
    /// (Hamrock eq 21.94).
    #[schema(example = 4060.7)]
    pub ball_spin_speed_absolute_rpm: f64,
    /// Fundamental train (cage) frequency |n_c|/60, Hz, seen from the fixed frame.
    #[schema(example = 12.28)]
    pub ftf_hz: f64,
    /// Ball pass frequency, outer race: Z|n_o − n_c|/60, Hz (rate at which balls pass a point
    /// of the outer raceway).
    #[schema(example = 122.8)]
    pub bpfo_hz: f64,
    /// Ball pass frequency, inner race: Z|n_i − n_c|/60, Hz.
    #[schema(example = 177.2)]
    pub bpfi_hz: f64,
    /// Ball spin frequency |n_b|/60, Hz: the ball's spin relative to the cage, once per
    /// revolution of the ball.
    #[schema(example = 79.96)]
    pub bsf_hz: f64,
    /// 2·BSF, Hz: a ball defect striking the inner and the outer race once each per spin
    /// (the convention of sources that call this "the" ball defect frequency).
    #[schema(example = 159.9)]
    pub ball_defect_frequency_hz: f64,
    /// Inner raceway contact diameter d_i = d_m − D cos α, m.
    #[schema(example = 0.0573)]
    pub inner_raceway_diameter_m: f64,
    /// Outer raceway contact diameter d_o = d_m + D cos α, m.
    #[schema(example = 0.0827)]
    pub outer_raceway_diameter_m: f64,
    /// Surface speed of the inner raceway at the contact in the fixed frame, π d_i n_i/60, m/s,
    /// signed.
    #[schema(example = 5.40)]
    pub inner_race_surface_speed_m_s: f64,
    /// Surface speed of the outer raceway at the contact in the fixed frame, π d_o n_o/60, m/s,
    /// signed.
    #[schema(example = 0.0)]
    pub outer_race_surface_speed_m_s: f64,
    /// Orbital speed of the ball centres, π d_m n_c/60, m/s, signed.
    #[schema(example = 2.70)]
    pub ball_center_speed_m_s: f64,
    /// Entrainment (mean rolling) speed ū = (u_race + u_ball)/2 at the inner contact, in the
    /// frame moving with the contact (the cage), m/s, ≥ 0: π d_i |n_i − n_c|/60. Under pure
    /// rolling u_race = u_ball = ū (no sliding). The speed EHL film formulas take.
    #[schema(example = 3.19)]
    pub inner_contact_entrainment_speed_m_s: f64,
    /// Entrainment speed at the outer contact, π d_o |n_o − n_c|/60, m/s, ≥ 0; equal to the inner
    /// contact's: (π d_m/120)|n_i − n_o|(1 − γ²).
    #[schema(example = 3.19)]
    pub outer_contact_entrainment_speed_m_s: f64,
}

impl Calculation for Kinematics {
    const PATH: &'static str = "/v1/rolling-bearings/kinematics";
    const SUMMARY: &'static str =
        "Rolling-bearing kinematics: cage and ball spin speeds, defect frequencies (FTF, BPFO, BPFI, BSF), entrainment speeds";
    const DESCRIPTION: &'static str = include_str!("kinematics.md");
    const FIDELITY: &'static [Level] = &[Level::ClosedForm];
    const EFFECTS: &'static [&'static str] = &[];
    const EXAMPLE: &'static str = r#"{"ball_diameter_m": 0.0127, "pitch_diameter_m": 0.07, "ball_count": 10, "contact_angle_deg": 0, "inner_ring_speed_rpm": 1800, "outer_ring_speed_rpm": 0}"#;

    type Input = KinematicsInput;
    type Output = KinematicsOutput;

    fn run(case: KinematicsCase, ctx: &mut Context) -> Result<KinematicsOutput, CalcError> {
        Ok(solve(&case, ctx))
    }
}

/// The speeds of a validated case, with a warning when the rings do not turn relative to each
/// other (the room's answer; the analysis calls it too).
pub(super) fn solve(case: &KinematicsCase, ctx: &mut Context) -> KinematicsOutput {
    if case.speed.inner_rpm == case.speed.outer_rpm {
        ctx.warn(
                "no_relative_rotation",
                format!(
                    "both rings turn at {} rpm: the bearing turns as a rigid body, with no rolling, spin or defect frequencies (only the cage frequency)",
                    case.speed.inner_rpm
                ),
            );
    }
    kinematics(case)
}

/// The closed forms of the module documentation.
fn kinematics(case: &KinematicsCase) -> KinematicsOutput {
    let d = case.ball_diameter_m;
    let dm = case.pitch_diameter_m;
    let cos_a = case.contact_angle_rad.cos();
    let gamma = d * cos_a / dm;
    let (ni, no) = (case.speed.inner_rpm, case.speed.outer_rpm);
    let z = f64::from(case.ball_count);
    let cage = 0.5 * (ni * (1.0 - gamma) + no * (1.0 + gamma));
    let inner_rel = 0.5 * (ni - no) * (1.0 + gamma);
    let outer_rel = -0.5 * (ni - no) * (1.0 - gamma);
    let spin = dm / (2.0 * d) * (1.0 - gamma * gamma) * (ni - no);
    let spin_absolute = dm / (2.0 * d) * (ni * (1.0 - gamma) - no * (1.0 + gamma));
    let di = dm - d * cos_a;
    let dout = dm + d * cos_a;
    let surface = |diameter: f64, rpm: f64| std::f64::consts::PI * diameter * rpm / 60.0;
    let bsf = spin.abs() / 60.0;
    KinematicsOutput {
        diameter_ratio: gamma,
        cage_speed_rpm: cage,
        inner_ring_speed_relative_to_cage_rpm: inner_rel,
        outer_ring_speed_relative_to_cage_rpm: outer_rel,
        ball_spin_speed_rpm: spin,
        ball_spin_speed_absolute_rpm: spin_absolute,
        ftf_hz: cage.abs() / 60.0,
        bpfo_hz: z * outer_rel.abs() / 60.0,
        bpfi_hz: z * inner_rel.abs() / 60.0,
        bsf_hz: bsf,
        ball_defect_frequency_hz: 2.0 * bsf,
        inner_raceway_diameter_m: di,
        outer_raceway_diameter_m: dout,
        inner_race_surface_speed_m_s: surface(di, ni),
        outer_race_surface_speed_m_s: surface(dout, no),
        ball_center_speed_m_s: surface(dm, cage),
        inner_contact_entrainment_speed_m_s: surface(di, inner_rel.abs()),
        outer_contact_entrainment_speed_m_s: surface(dout, outer_rel.abs()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use proptest::prelude::*;
    use serde_json::{json, Value};

    fn ok(request: &Value) -> Value {
        crate::calc::testing::ok::<Kinematics>(request)
    }

    fn pointers(request: &Value) -> Vec<String> {
        crate::calc::testing::invalid_pointers::<Kinematics>(request)
    }

    use crate::calc::testing::{assert_rel, result_field as get};

    /// rad/s → rpm.
    fn rpm(rad_s: f64) -> f64 {
        rad_s * 60.0 / (2.0 * std::f64::consts::PI)
    }

    #[test]
    fn the_example_runs() {
        let v: Value = serde_json::from_str(Kinematics::EXAMPLE).unwrap();
        let r = ok(&v);
        assert_eq!(r["solver"]["fidelity"], "closed_form");
    }

    /// Khonsari & Booser 6210 defect frequencies (spec ch9-17 §2.4): Z = 10, D = 12.7 mm,
    /// d_m = 70 mm, α = 0, outer ring fixed, per unit inner-ring frequency N (here N = 1 Hz).
    #[test]
    fn khonsari_6210_defect_frequencies() {
        let r = ok(&json!({
            "ball_diameter_m": 0.0127, "pitch_diameter_m": 0.07, "ball_count": 10,
            "inner_ring_speed_rpm": 60.0
        }));
        assert_rel(get(&r, "ftf_hz"), 0.40929, 1e-4, "FTF");
        assert_rel(
            get(&r, "inner_ring_speed_relative_to_cage_rpm") / 60.0,
            0.59071,
            1e-4,
            "f_ci",
        );
        assert_rel(get(&r, "bpfo_hz"), 4.0929, 1e-4, "BPFO");
        assert_rel(get(&r, "bpfi_hz"), 5.9071, 1e-4, "BPFI");
        assert_rel(get(&r, "bsf_hz"), 2.6652, 1e-4, "BSF");
        assert_rel(get(&r, "ball_defect_frequency_hz"), 5.3304, 1e-4, "2 BSF");
    }

    /// Khonsari & Booser Ex 15.4 corrected (spec erratum E-12): the 6210 at 900 rpm has the
    /// kinematic entrainment speed (π d_m n/120)(1 − (D/d_m)²) = 1595 mm/s.
    #[test]
    fn khonsari_ex15_4_entrainment_speed() {
        let r = ok(&json!({
            "ball_diameter_m": 0.0127, "pitch_diameter_m": 0.07, "ball_count": 10,
            "inner_ring_speed_rpm": 900.0
        }));
        assert_rel(
            get(&r, "inner_contact_entrainment_speed_m_s"),
            1.595,
            1e-3,
            "ū inner",
        );
        assert_rel(
            get(&r, "outer_contact_entrainment_speed_m_s"),
            1.595,
            1e-3,
            "ū outer",
        );
    }

    /// Hamrock A-R2 (cylindrical roller bearing): d_i = 64, d_o = 96, d = 16 mm, ω_i = 524 rad/s
    /// → d_e = 80 mm, u = 10.061 m/s.
    #[test]
    fn hamrock_cylindrical_roller_bearing_entrainment() {
        let r = ok(&json!({
            "ball_diameter_m": 0.016, "pitch_diameter_m": 0.08, "ball_count": 9,
            "inner_ring_speed_rpm": rpm(524.0)
        }));
        assert_rel(
            get(&r, "inner_contact_entrainment_speed_m_s"),
            10.061,
            2e-4,
            "u",
        );
        assert_rel(get(&r, "inner_raceway_diameter_m"), 0.064, 1e-12, "d_i");
        assert_rel(get(&r, "outer_raceway_diameter_m"), 0.096, 1e-12, "d_o");
    }

    /// Hamrock A-R3 (deep-groove ball bearing): d_i = 52.291, d_o = 77.706, d = 12.7 mm,
    /// ω_i = 400 rad/s → d_e = 65 mm (printed), u = 6.252 m/s; derived cage 160.92 rad/s and
    /// ball spin (eq 21.94, fixed frame) 823.6 rad/s.
    #[test]
    fn hamrock_deep_groove_ball_bearing_speeds() {
        let r = ok(&json!({
            "ball_diameter_m": 0.0127, "pitch_diameter_m": 0.065, "ball_count": 9,
            "inner_ring_speed_rpm": rpm(400.0)
        }));
        assert_rel(
            get(&r, "inner_contact_entrainment_speed_m_s"),
            6.252,
            2e-4,
            "u",
        );
        assert_rel(get(&r, "cage_speed_rpm"), rpm(160.92), 1e-4, "cage");
        assert_rel(
            get(&r, "ball_spin_speed_absolute_rpm"),
            rpm(823.6),
            1e-4,
            "spin (fixed frame)",
        );
    }

    #[test]
    fn outer_ring_rotation_drives_the_cage_at_half_one_plus_gamma() {
        let r = ok(&json!({
            "ball_diameter_m": 0.0127, "pitch_diameter_m": 0.07, "ball_count": 10,
            "outer_ring_speed_rpm": 1000.0
        }));
        let gamma = 0.0127 / 0.07;
        assert_rel(
            get(&r, "cage_speed_rpm"),
            500.0 * (1.0 + gamma),
            1e-12,
            "n_c",
        );
        // The inner ring now turns backwards relative to the outer: the spin changes sign.
        assert!(get(&r, "ball_spin_speed_rpm") < 0.0);
        assert_rel(
            get(&r, "ftf_hz"),
            500.0 * (1.0 + gamma) / 60.0,
            1e-12,
            "FTF",
        );
    }

    #[test]
    fn counter_rotation_adds_the_speeds() {
        let base = json!({"ball_diameter_m": 0.01, "pitch_diameter_m": 0.05, "ball_count": 8,
                          "contact_angle_deg": 25.0});
        let mut a = base.clone();
        a["inner_ring_speed_rpm"] = json!(3000.0);
        a["outer_ring_speed_rpm"] = json!(-1000.0);
        let mut b = base.clone();
        b["inner_ring_speed_rpm"] = json!(4000.0);
        let (ra, rb) = (ok(&a), ok(&b));
        // Relative motion is what rolls: the same spin, ring passes and entrainment speed.
        for field in [
            "ball_spin_speed_rpm",
            "bpfo_hz",
            "bpfi_hz",
            "bsf_hz",
            "inner_contact_entrainment_speed_m_s",
        ] {
            assert_rel(get(&ra, field), get(&rb, field), 1e-12, field);
        }
        // …while the cage differs by the outer ring's speed.
        assert_rel(
            get(&rb, "cage_speed_rpm") - get(&ra, "cage_speed_rpm"),
            1000.0,
            1e-12,
            "cage shift",
        );
    }

    #[test]
    fn equal_ring_speeds_turn_as_a_rigid_body() {
        let r = ok(&json!({
            "ball_diameter_m": 0.01, "pitch_diameter_m": 0.05, "ball_count": 8,
            "inner_ring_speed_rpm": 1200.0, "outer_ring_speed_rpm": 1200.0
        }));
        assert_eq!(get(&r, "cage_speed_rpm"), 1200.0);
        assert_eq!(get(&r, "bpfo_hz"), 0.0);
        assert_eq!(get(&r, "inner_contact_entrainment_speed_m_s"), 0.0);
        assert_eq!(r["warnings"][0]["code"], "no_relative_rotation");
    }

    #[test]
    fn bad_input_is_refused_with_its_pointer() {
        let good = json!({"ball_diameter_m": 0.01, "pitch_diameter_m": 0.05, "ball_count": 8,
                          "inner_ring_speed_rpm": 1000.0});
        let with = |key: &str, value: Value| {
            let mut v = good.clone();
            v[key] = value;
            v
        };
        let rows: Vec<(Value, &str, &str)> = vec![
            (
                with("ball_diameter_m", json!(0.0)),
                "/ball_diameter_m",
                "D = 0",
            ),
            (
                with("ball_diameter_m", json!(-0.01)),
                "/ball_diameter_m",
                "D < 0",
            ),
            (
                with("ball_diameter_m", json!(0.05)),
                "/ball_diameter_m",
                "D = d_m",
            ),
            (
                with("pitch_diameter_m", json!(0.0)),
                "/pitch_diameter_m",
                "d_m = 0",
            ),
            (
                with("pitch_diameter_m", json!(1000.0)),
                "/pitch_diameter_m",
                "d_m huge",
            ),
            (with("ball_count", json!(0)), "/ball_count", "Z = 0"),
            (with("ball_count", json!(-3)), "/ball_count", "Z < 0"),
            (
                with("ball_count", json!(2.5)),
                "/ball_count",
                "Z fractional",
            ),
            (
                with("contact_angle_deg", json!(-5.0)),
                "/contact_angle_deg",
                "α < 0",
            ),
            (
                with("contact_angle_deg", json!(95.0)),
                "/contact_angle_deg",
                "α > 90",
            ),
            (
                with("inner_ring_speed_rpm", json!(1e9)),
                "/inner_ring_speed_rpm",
                "n huge",
            ),
            (
                with("outer_ring_speed_rpm", json!("fast")),
                "/outer_ring_speed_rpm",
                "n text",
            ),
            (
                with("inner_ring_sped_rpm", json!(1.0)),
                "/inner_ring_sped_rpm",
                "typo",
            ),
            (
                // Regression (schemathesis, CI): a denormal ball diameter gave a non-finite
                // result and a 500.
                with("ball_diameter_m", json!(5e-324)),
                "/ball_diameter_m",
                "D/d_m vanishing",
            ),
        ];
        for (body, pointer, why) in rows {
            let got = pointers(&body);
            assert!(
                got.iter().any(|p| p == pointer),
                "{why}: expected {pointer}, got {got:?}"
            );
        }
        let missing = json!({"ball_diameter_m": 0.01, "ball_count": 8});
        assert_eq!(pointers(&missing), vec!["/pitch_diameter_m"]);
    }

    fn random_case(d: f64, ratio: f64, z: u32, alpha: f64, ni: f64, no: f64) -> KinematicsCase {
        KinematicsCase {
            ball_diameter_m: d,
            pitch_diameter_m: d / ratio,
            ball_count: z,
            contact_angle_rad: alpha.to_radians(),
            speed: RingSpeed::new(ni, no),
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(256))]

        #[test]
        fn identities_hold_over_random_geometries(
            d in 1e-4f64..0.2, ratio in 0.01f64..0.9, z in 1u32..100, alpha in 0.0f64..90.0,
            ni in -2e4f64..2e4, no in -2e4f64..2e4,
        ) {
            let case = random_case(d, ratio, z, alpha, ni, no);
            let k = kinematics(&case);
            let scale = 1.0 + ni.abs() + no.abs();
            // BPFO + BPFI = Z|n_i − n_o|/60.
            let sum = f64::from(z) * (ni - no).abs() / 60.0;
            prop_assert!((k.bpfo_hz + k.bpfi_hz - sum).abs() <= 1e-9 * scale * f64::from(z));
            // Rings relative to the cage differ by n_i − n_o.
            prop_assert!((k.inner_ring_speed_relative_to_cage_rpm - k.outer_ring_speed_relative_to_cage_rpm - (ni - no)).abs() <= 1e-9 * scale);
            // Pure rolling: the same entrainment speed at both contacts, and it matches the closed form.
            let gamma = k.diameter_ratio;
            let u = std::f64::consts::PI * case.pitch_diameter_m / 120.0 * (ni - no).abs() * (1.0 - gamma * gamma);
            prop_assert!((k.inner_contact_entrainment_speed_m_s - u).abs() <= 1e-9 * (1.0 + u));
            prop_assert!((k.outer_contact_entrainment_speed_m_s - u).abs() <= 1e-9 * (1.0 + u));
            // The ball's surface speed at the inner contact equals the race's there (no slip):
            // |n_b|·D/2 (rpm·m) = |n_i − n_c|·d_i/2.
            let ball = k.ball_spin_speed_rpm.abs() * case.ball_diameter_m;
            let race = k.inner_ring_speed_relative_to_cage_rpm.abs() * k.inner_raceway_diameter_m;
            prop_assert!((ball - race).abs() <= 1e-9 * (1.0 + race));
            // Spin seen from the fixed frame = relative spin − n_c cos α.
            let cos_a = case.contact_angle_rad.cos();
            prop_assert!((k.ball_spin_speed_absolute_rpm - (k.ball_spin_speed_rpm - k.cage_speed_rpm * cos_a)).abs() <= 1e-6 * scale / ratio);
            // The cage turns between the rings.
            prop_assert!(k.cage_speed_rpm >= ni.min(no) - 1e-9 * scale && k.cage_speed_rpm <= ni.max(no) + 1e-9 * scale);
            prop_assert!((k.ball_defect_frequency_hz - 2.0 * k.bsf_hz).abs() <= 1e-12 * (1.0 + k.bsf_hz));
            for v in [k.cage_speed_rpm, k.ball_spin_speed_rpm, k.ball_spin_speed_absolute_rpm, k.ftf_hz,
                      k.bpfo_hz, k.bpfi_hz, k.bsf_hz, k.ball_center_speed_m_s,
                      k.inner_race_surface_speed_m_s, k.outer_race_surface_speed_m_s] {
                prop_assert!(v.is_finite());
            }
        }

        #[test]
        fn cage_speed_for_outer_ring_rotation(d in 1e-3f64..0.1, ratio in 0.01f64..0.9, no in -1e4f64..1e4) {
            let k = kinematics(&random_case(d, ratio, 12, 0.0, 0.0, no));
            prop_assert!((k.cage_speed_rpm - 0.5 * no * (1.0 + ratio)).abs() <= 1e-9 * (1.0 + no.abs()));
        }
    }
}
