use serde_json::{json, Value};

use super::*;
use crate::calc::testing::{invalid_pointers, ok, result_field};

fn example() -> Value {
    serde_json::from_str(TiltingPadGasJournal::EXAMPLE).unwrap()
}

fn with(extra: Value) -> Value {
    let mut body = example();
    for (k, v) in extra.as_object().unwrap() {
        body[k] = v.clone();
    }
    body
}

#[test]
fn the_example_answers_with_three_pads_whose_shares_add_to_one() {
    let v = ok::<TiltingPadGasJournal>(&example());
    let r = &v["result"];
    let pads = r["pads"].as_array().unwrap();
    assert_eq!(pads.len(), 3);
    let share: f64 = pads.iter().map(|p| p["load_share"].as_f64().unwrap()).sum();
    assert!((share - 1.0).abs() < 1e-9, "{share}");
    // Pads 1 and 2 mirror each other about the load line: the same free tilt τ, so their
    // rigid tilts differ by the journal's share, δ1 − δ2 = 2 C′ ε′ sin 120°/R.
    let (c_prime, e) = (
        result_field(&v, "pivot_clearance_m"),
        result_field(&v, "eccentricity_ratio"),
    );
    let tilt = |i: usize| pads[i]["tilt_rad"].as_f64().unwrap();
    let mirror = 2.0 * c_prime * e * (2.0 * std::f64::consts::FRAC_PI_3).sin() / 0.00635;
    assert!(
        (tilt(0) - tilt(1) - mirror).abs() < 1e-9 * mirror,
        "{} − {} against {mirror}",
        tilt(0),
        tilt(1)
    );
    // The given load is carried.
    assert!((result_field(&v, "load_n") - 11.12).abs() < 1e-6 * 11.12);
    let sum: f64 = pads
        .iter()
        .map(|p| p["friction_force_n"].as_f64().unwrap())
        .sum();
    assert!((result_field(&v, "friction_force_n") - sum).abs() < 1e-12);
    let omega = 200000.0 * std::f64::consts::PI / 30.0;
    let power = result_field(&v, "power_loss_w");
    assert!((power - sum * 0.00635 * omega).abs() < 1e-9 * power);
}

#[test]
fn bad_pad_geometry_is_refused_on_its_field() {
    let rows = [
        (json!({"preload_factor": 1.0}), "/preload_factor"),
        (json!({"preload_factor": 0.0}), "/preload_factor"),
        (json!({"pads": {"arc_deg": 125.0}}), "/pads/arc_deg"),
        (json!({"pads": {"pivot_offset": 1.0}}), "/pads/pivot_offset"),
        (
            json!({"pads": {"pivot_offset": -0.1}}),
            "/pads/pivot_offset",
        ),
        (
            json!({"load_n": null, "eccentricity_ratio": 1.0}),
            "/eccentricity_ratio",
        ),
        (json!({"eccentricity_ratio": 0.5}), "/load_n"),
    ];
    for (body, pointer) in rows {
        assert_eq!(
            invalid_pointers::<TiltingPadGasJournal>(&with(body.clone())),
            vec![pointer.to_owned()],
            "{body}"
        );
    }
}

#[test]
fn ex_11_6_friction_sum_and_power_from_the_chart_frictions() {
    // Ex 11.6 steps 6–7 with the chart's F1 = F2 = 0.95, F3 = 1.7 and C from Λ = 1.5:
    // Σ F_f = p_a C L (2F1 + F3) = 1.603e-2 lbf and 9.49 W (spec E-23: the book's 1.73e-2 lbf and
    // 10.2 W are misprints).
    let (pa, c, l, r) = (103421.36, 1.50816e-5, 0.0127, 0.00635);
    let omega = 200000.0 * std::f64::consts::PI / 30.0;
    let (force, torque, power) = friction_totals(&[0.95, 0.95, 1.7], pa, c, l, r, omega);
    let lbf = 4.4482216152605;
    assert!(
        (force / lbf - 1.603e-2).abs() < 1e-3 * 1.603e-2,
        "{}",
        force / lbf
    );
    assert!((torque - force * r).abs() < 1e-15);
    // The book's 746 R N ΣF/63000 (hp to W at 746) gives 9.49 W; Ω R ΣF is 9.484 W.
    assert!((power - 9.49).abs() < 5e-3 * 9.49, "{power}");
}
