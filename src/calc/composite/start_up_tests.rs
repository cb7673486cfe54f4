use std::f64::consts::PI;

use serde_json::{json, Value};

use super::*;
use crate::calc::composite::film::{SleeveFilm, MAX_ECCENTRICITY};
use crate::calc::composite::sleeve::Restraint;
use crate::calc::composite::split::{split, Operating};
use crate::calc::composite::start::StartUp;
use crate::calc::testing::{invalid_pointers, ok, result_field, warning_codes};

fn example(extra: Value) -> Value {
    let mut body: Value = serde_json::from_str(StartUpRoom::EXAMPLE).unwrap();
    for (k, v) in extra.as_object().unwrap() {
        if v.is_null() {
            body.as_object_mut().unwrap().remove(k);
        } else {
            body[k] = v.clone();
        }
    }
    body
}

/// The example's model: Table 18-1's bearing under 20 kN, ramped to 3500 rpm in 2 s.
fn model(traction: f64, rolling_torque: f64) -> StartUp {
    StartUp {
        film: SleeveFilm {
            radius: 0.05,
            length: 0.1,
            clearance: 6e-5,
            viscosity: 0.03,
        },
        restraint: Restraint {
            coefficient: 0.0357,
            rolling_torque,
        },
        load: 20_000.0,
        journal_speed: 3500.0 * PI / 30.0,
        ramp_time: 2.0,
        inertia: 0.01,
        traction_coefficient: traction,
    }
}

/// Break-away in closed form: t* = √((f_t W R − M_r − I a)/k)/a with a = ω_J/t_r; the steady
/// speed is the speed split's at the same load; the sleeve ends in its band, after the ramp.
#[test]
fn the_example_breaks_away_where_the_closed_form_says_and_settles_at_the_split() {
    let v = ok::<StartUpRoom>(&example(json!({})));
    let s = model(0.005, 0.0);
    let a = s.journal_speed / s.ramp_time;
    let t_star = ((0.005 * 20_000.0 * 0.05 - 0.01 * a) / 0.0357).sqrt() / a;
    let got = result_field(&v, "breakaway_time_s");
    assert!((got / t_star - 1.0).abs() < 1e-12, "{got} vs {t_star}");
    let speed = result_field(&v, "breakaway_journal_speed_rpm");
    assert!((speed / (t_star / 2.0 * 3500.0) - 1.0).abs() < 1e-12);
    let steady = split(
        &s.film,
        &s.restraint,
        s.journal_speed,
        Operating::Load(s.load),
    )
    .unwrap();
    let want = steady.composite.speed_ratio * 3500.0;
    let got = result_field(&v, "steady_sleeve_speed_rpm");
    assert!((got / want - 1.0).abs() < 1e-12, "{got} vs {want}");
    let settle = result_field(&v, "settling_time_s");
    let end = result_field(&v, "end_time_s");
    assert!(settle > 0.0 && settle < end, "{settle} {end}");
    let history = v["result"]["history"].as_array().unwrap();
    assert_eq!(history.len(), 11);
    assert_eq!(history[0]["sleeve_speed_rpm"], 0.0);
    let last = history[10]["sleeve_speed_rpm"].as_f64().unwrap();
    assert!((last / want - 1.0).abs() < 1e-3, "{last} vs {want}");
    assert_eq!(v["solver"]["method"], "sdirk4_l_stable");
    assert_eq!(v["solver"]["stop_reason"], "converged");
    assert!(v["solver"]["time_integration"]["rejected_steps"].is_number());
}

/// Spec B-R2 at break-away: the rolling film (speed sum 2ω_j) is the film a held sleeve has at
/// twice the journal speed.
#[test]
fn the_rolling_film_at_breakaway_is_a_held_sleeve_at_twice_the_speed() {
    let v = ok::<StartUpRoom>(&example(json!({})));
    let s = model(0.005, 0.0);
    let w = result_field(&v, "breakaway_journal_speed_rpm") * PI / 30.0;
    let held = s
        .film
        .eccentricity_for(s.load, MAX_ECCENTRICITY, |_| 2.0 * w)
        .unwrap()
        .eccentricity;
    let got = result_field(&v, "eccentricity_at_breakaway");
    assert!((got - held).abs() < 1e-12, "{got} vs {held}");
    let film = result_field(&v, "min_film_at_breakaway_m");
    assert!((film / (6e-5 * (1.0 - held)) - 1.0).abs() < 1e-12);
}

/// The sliding phase against a fine classical Runge–Kutta run of the same equation (10⁵ steps
/// over the ramp): the sleeve speed at the ramp's end agrees to 1e-6.
#[test]
fn the_sliding_phase_matches_a_fine_explicit_run() {
    for m_r in [0.0, 2.0] {
        let s = model(0.005, m_r);
        let t0 = s.breakaway().time().unwrap();
        let f = |t: f64, w: f64| s.sleeve_acceleration(t, w).unwrap();
        let n = 100_000;
        let h = (s.ramp_time - t0) / f64::from(n);
        let (mut t, mut w) = (t0, s.journal_speed_at(t0));
        for _ in 0..n {
            let k1 = f(t, w);
            let k2 = f(t + 0.5 * h, w + 0.5 * h * k1);
            let k3 = f(t + 0.5 * h, w + 0.5 * h * k2);
            let k4 = f(t + h, w + h * k3);
            w += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
            t += h;
        }
        let v = ok::<StartUpRoom>(&example(json!({"rolling_friction_torque_n_m": m_r})));
        let got = result_field(&v, "sleeve_speed_at_ramp_end_rpm") * PI / 30.0;
        assert!((got / w - 1.0).abs() < 1e-6, "M_r {m_r}: {got} vs {w}");
    }
}

/// No traction to speak of: the sleeve slides from rest (break-away at 0 rpm); ample traction:
/// it rolls on at the journal's speed, with a warning and no settling time.
#[test]
fn the_limits_of_the_rolling_phase() {
    let v = ok::<StartUpRoom>(&example(json!({"rolling_traction_coefficient": 1e-9})));
    assert_eq!(result_field(&v, "breakaway_journal_speed_rpm"), 0.0);
    assert!(result_field(&v, "settling_time_s") > 0.0);
    assert!(warning_codes(&v).contains(&"breakaway_before_full_film".to_owned()));
    let v = ok::<StartUpRoom>(&example(
        json!({"rolling_traction_coefficient": 1.0, "restraint_coefficient_kg_m2": 0.001}),
    ));
    assert!(v["result"]["breakaway_time_s"].is_null());
    assert!(v["result"]["settling_time_s"].is_null());
    assert_eq!(result_field(&v, "steady_sleeve_speed_rpm"), 3500.0);
    assert_eq!(result_field(&v, "sleeve_speed_at_ramp_end_rpm"), 3500.0);
    assert!(warning_codes(&v).contains(&"sleeve_rolls_on".to_owned()));
}

/// A rolling bearing that holds the steady sleeve: it breaks away at once, slows and stands.
#[test]
fn a_stiff_rolling_bearing_stops_the_sleeve() {
    let v = ok::<StartUpRoom>(&example(json!({"rolling_friction_torque_n_m": 100.0})));
    assert_eq!(result_field(&v, "steady_sleeve_speed_rpm"), 0.0);
    assert_eq!(result_field(&v, "breakaway_time_s"), 0.0);
    let history = v["result"]["history"].as_array().unwrap();
    let last = history.last().unwrap()["sleeve_speed_rpm"]
        .as_f64()
        .unwrap();
    assert!(last.abs() < 35.0, "{last}");
}

#[test]
fn invalid_requests_name_their_fields() {
    let rows = [
        (json!({"ramp_time_s": 1e-9}), "/ramp_time_s"),
        (
            json!({"sleeve_inertia_kg_m2": 0.0}),
            "/sleeve_inertia_kg_m2",
        ),
        (
            json!({"rolling_traction_coefficient": 3.0}),
            "/rolling_traction_coefficient",
        ),
        (json!({"history_points": 1}), "/history_points"),
        (json!({"load_n": null}), "/load_n"),
        (json!({"eccentricity_ratio": 0.5}), "/eccentricity_ratio"),
        (json!({"restraint_coefficient_kg_m2": null}), "/pin_mass_kg"),
    ];
    for (extra, pointer) in rows {
        let pointers = invalid_pointers::<StartUpRoom>(&example(extra.clone()));
        assert!(
            pointers.iter().any(|p| p == pointer),
            "{extra}: {pointers:?}"
        );
    }
}

/// The edge fuzzer's find: at the smallest load and journal speed (2.2e-308 N and rpm) the load
/// search's residual at ε = 1e-12 was ln 0 (a 500). Now the film carries the load at a small
/// eccentricity, every number finite.
#[test]
fn the_smallest_load_and_speed_answer() {
    let tiny = f64::MIN_POSITIVE;
    let r = ok::<StartUpRoom>(&example(json!({"journal_speed_rpm": tiny, "load_n": tiny})));
    let eps = result_field(&r, "steady_eccentricity_ratio");
    assert!(eps > 1e-12 && eps < 0.1, "ε = {eps}");
    let ratio = result_field(&r, "steady_speed_ratio");
    assert!((0.0..=1.0).contains(&ratio), "{ratio}");
}
