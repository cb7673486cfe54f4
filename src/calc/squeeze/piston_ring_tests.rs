//! The piston-ring room's tests: the example through the whole path, the path and the boundary
//! warning, and the 422s.

use super::*;
use crate::calc::testing::{invalid_pointers, ok, result_field, warning_codes};
use serde_json::{json, Value};

fn example() -> Value {
    serde_json::from_str(PistonRingSqueeze::EXAMPLE).unwrap()
}

#[test]
fn the_example_converges_to_a_cycle_with_its_film_least_near_top_dead_centre() {
    let mut request = example();
    request["include_field"] = json!(true);
    let v = ok::<PistonRingSqueeze>(&request);
    let h_min = result_field(&v, "min_film_m");
    let h_max = result_field(&v, "max_film_m");
    assert!(
        0.0 < h_min && h_min < h_max && h_max < 14.9e-6,
        "{h_min} {h_max}"
    );
    // Table 9.5: K = E t_r / r² = 70e9 × 3.8e-3 / 0.04445².
    let k = result_field(&v, "ring_stiffness_pa_per_m");
    assert!((k / (70e9 * 3.8e-3 / 0.04445f64.powi(2)) - 1.0).abs() < 1e-12);
    let path = v["result"]["path"].as_array().unwrap();
    assert_eq!(path.len(), 721);
    let first = path[0]["min_film_m"].as_f64().unwrap();
    let last = path[720]["min_film_m"].as_f64().unwrap();
    assert!((last / first - 1.0).abs() < 1e-3, "{first} vs {last}");
    // The mean power is the mean of the path's powers.
    let mean: f64 = path[..720]
        .iter()
        .map(|p| p["power_loss_w"].as_f64().unwrap())
        .sum::<f64>()
        / 720.0;
    assert!((mean / result_field(&v, "mean_power_loss_w") - 1.0).abs() < 1e-12);
    assert!(result_field(&v, "cycles") >= 2.0);
    assert_eq!(v["solver"]["method"], "piston_ring_radau_iia5_shooting");
}

#[test]
fn a_two_stroke_cycle_repeats_over_360_degrees() {
    let mut request = example();
    request["engine"]["cycle_deg"] = json!(360.0);
    request["gas_pressure"] = json!([{"crank_angle_deg": 0, "pressure_pa": 3e6},
                                     {"crank_angle_deg": 30, "pressure_pa": 2e6},
                                     {"crank_angle_deg": 120, "pressure_pa": 3e5},
                                     {"crank_angle_deg": 240, "pressure_pa": 2e5}]);
    request["include_field"] = json!(true);
    let v = ok::<PistonRingSqueeze>(&request);
    let path = v["result"]["path"].as_array().unwrap();
    assert_eq!(path.len(), 361);
    let (first, last) = (
        path[0]["min_film_m"].as_f64().unwrap(),
        path[360]["min_film_m"].as_f64().unwrap(),
    );
    assert!((last / first - 1.0).abs() < 1e-3, "{first} vs {last}");
    assert!(result_field(&v, "min_film_crank_angle_deg") < 360.0);
}

#[test]
fn a_film_below_the_roughness_is_boundary_lubricated_and_says_so() {
    let mut request = example();
    request["composite_roughness_m"] = json!(5e-6);
    request["include_field"] = json!(true);
    let v = ok::<PistonRingSqueeze>(&request);
    assert!(warning_codes(&v).contains(&"film_below_roughness".to_owned()));
    assert!(result_field(&v, "boundary_lubrication_deg") > 0.0);
    let path = v["result"]["path"].as_array().unwrap();
    let boundary: Vec<&Value> = path.iter().filter(|p| p["regime"] == "boundary").collect();
    assert!(!boundary.is_empty());
    for p in boundary {
        // F = μ_c W against the motion, E = |F U|.
        let (f, w, u, e) = (
            p["friction_force_n"].as_f64().unwrap(),
            p["film_load_n"].as_f64().unwrap(),
            p["piston_speed_m_s"].as_f64().unwrap(),
            p["power_loss_w"].as_f64().unwrap(),
        );
        assert!((f.abs() - 0.08 * w.max(0.0)).abs() <= 1e-9 * f.abs().max(1e-30));
        assert!(f * u <= 0.0);
        assert!((e - (f * u).abs()).abs() <= 1e-9 * e.max(1e-30));
    }
}

#[test]
fn bad_geometry_and_settings_are_refused_with_their_fields() {
    let cases: &[(&str, Value, &str)] = &[
        ("/ring/crown_height_m", json!(-1e-6), "δ₀ < 0"),
        ("/ring/crown_height_m", json!(0.0), "a flat face"),
        ("/ring/width_m", json!(0.0), "a ≤ 0"),
        ("/engine/rod_length_m", json!(0.03), "rod ≤ crank"),
        ("/engine/cycle_deg", json!(540.0), "neither 2- nor 4-stroke"),
        ("/bottom_pressure_fraction", json!(1.5), "fraction above 1"),
        ("/fidelity", json!("closed_form"), "no closed form"),
        ("/ring/lenght_m", json!(1.0), "unknown field"),
    ];
    for (pointer, value, why) in cases {
        let mut request = example();
        let path: Vec<&str> = pointer.trim_start_matches('/').split('/').collect();
        match path.as_slice() {
            [field] => request[*field] = value.clone(),
            [outer, field] => request[*outer][*field] = value.clone(),
            _ => unreachable!(),
        }
        let got = invalid_pointers::<PistonRingSqueeze>(&request);
        let want = if *pointer == "/ring/lenght_m" {
            "/ring"
        } else {
            pointer
        };
        assert!(
            got.iter().any(|p| p.starts_with(want)),
            "{why}: {got:?} lacks {pointer}"
        );
    }
    let mut request = example();
    request["gas_pressure"] = json!([{"crank_angle_deg": 10, "pressure_pa": 1e6},
                                     {"crank_angle_deg": 5, "pressure_pa": 1e6},
                                     {"crank_angle_deg": 20, "pressure_pa": 1e6}]);
    assert!(invalid_pointers::<PistonRingSqueeze>(&request).contains(&"/gas_pressure".to_owned()));
}
