use proptest::prelude::*;
use serde_json::{json, Value};

use super::*;
use crate::calc::testing::{assert_rel, invalid_pointers, ok, result_field};

fn example() -> Value {
    serde_json::from_str(ParasiticLosses::EXAMPLE).unwrap()
}

/// The number at `pointer` under the envelope's result.
fn at(v: &Value, pointer: &str) -> f64 {
    v["result"]
        .pointer(pointer)
        .and_then(Value::as_f64)
        .unwrap()
}

/// Khonsari & Booser Ex 7.6 in SI (the example request: 15 in rim, 3 in wide, 0.25 in gap,
/// 10 000 rpm, 2e-6 reyn = 0.01379 Pa·s, 0.0307 lb/in³ = 849.8 kg/m³ at 15 °C, 100 gpm =
/// 385 in³/s at one velocity head). Book, with its Re misprint corrected (spec): V = 7854 in/s,
/// Re = 78 083, f = 9.572e-4, E_p/A = 18 440 in·lbf/s/in², drag 2.607e6 in·lbf/s (395 hp),
/// through-flow 9.444e5 in·lbf/s (143 hp).
#[test]
fn example_7_6_runner_rim() {
    let v = ok::<ParasiticLosses>(&example());
    let rim = &v["result"]["surfaces"][0];
    let get = |f: &str| rim[f].as_f64().unwrap();
    const W_PER_IN_LBF_S: f64 = 0.0254 * 4.448_221_615_260_5;
    assert_rel(get("surface_speed_m_s"), 7854.0 * 0.0254, 1e-4, "V");
    assert_rel(get("reynolds_number"), 78_083.0, 1e-3, "Re");
    assert_rel(get("friction_factor"), 9.572e-4, 1e-3, "f");
    assert_rel(
        get("power_w") / get("area_m2"),
        18_440.0 * W_PER_IN_LBF_S / (0.0254 * 0.0254),
        1e-3,
        "E_p/A",
    );
    assert_rel(get("power_w"), 2.607e6 * W_PER_IN_LBF_S, 1e-3, "drag");
    assert_rel(
        at(&v, "/through_flow/power_w"),
        9.444e5 * W_PER_IN_LBF_S,
        1e-3,
        "through-flow",
    );
    assert_rel(
        result_field(&v, "total_power_w"),
        (2.607e6 + 9.444e5) * W_PER_IN_LBF_S,
        1e-3,
        "total",
    );
    assert!(v["warnings"].as_array().unwrap().is_empty());
}

/// A face's drag integrated ring by ring equals a midpoint quadrature of Eq. 7.17 over the
/// radius, each ring at its own speed and Reynolds number; a thin annulus is a rim's per-area
/// value at its mean speed.
#[test]
fn a_face_is_eq_7_17_integrated_over_the_radius() {
    let mut request = example();
    request["surfaces"] = json!([{"kind": "face", "inner_diameter_m": 0.1, "outer_diameter_m": 0.381, "gap_m": 0.01}]);
    let v = ok::<ParasiticLosses>(&request);
    let (mu, rho, omega) = (
        result_field(&v, "viscosity_pa_s"),
        result_field(&v, "density_kg_m3"),
        10_000.0 * PI / 30.0,
    );
    let n = 20_000;
    let (ri, ro) = (0.05, 0.1905);
    let dr = (ro - ri) / n as f64;
    let quadrature: f64 = (0..n)
        .map(|k| {
            let r = ri + (k as f64 + 0.5) * dr;
            let speed = omega * r;
            let f = 0.016 / (rho * speed * 0.01 / mu).powf(0.25);
            f * 0.5 * rho * speed.powi(3) * 2.0 * PI * r * dr
        })
        .sum();
    assert_rel(at(&v, "/surfaces/0/power_w"), quadrature, 1e-7, "face");
}

#[test]
fn bad_requests_name_their_fields() {
    let mut request = example();
    request["surfaces"] = json!([{"kind": "face", "inner_diameter_m": 0.4, "outer_diameter_m": 0.381, "gap_m": 0.01},
                                 {"kind": "rim", "diameter_m": 0.381, "width_m": 0.0762, "gap_m": 2.0}]);
    request["through_flow"]["velocity_heads"] = json!(20.0);
    assert_eq!(
        invalid_pointers::<ParasiticLosses>(&request),
        [
            "/surfaces/0/inner_diameter_m",
            "/surfaces/1/gap_m",
            "/through_flow/velocity_heads"
        ]
    );
    // Nothing to compute, and an oil whose viscosity needs the temperature it was not given.
    let nothing = json!({"speed_rpm": 3000, "lubricant": {"iso_vg": 32}});
    assert_eq!(
        invalid_pointers::<ParasiticLosses>(&nothing),
        ["/surfaces", "/temperature_c"]
    );
}

/// A slow, viscous case warns that Eq. 7.18's turbulent drag is outside its range.
#[test]
fn laminar_gaps_warn() {
    let mut request = example();
    request["speed_rpm"] = json!(10.0);
    let v = ok::<ParasiticLosses>(&request);
    assert!(v["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .any(|w| w["code"] == "drag_not_turbulent"));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    /// Over the valid speeds, sizes and gaps: finite, positive, and the drag grows with speed
    /// as V^2.75 (f ∝ V^−¼ times V³), the through-flow as V².
    #[test]
    fn losses_are_finite_and_scale_with_speed(
        log_rpm in 0.0f64..5.69,
        d in 1e-2f64..10.0,
        gap_fraction in 1e-4f64..0.1,
    ) {
        let rpm = 10f64.powf(log_rpm);
        let body = |rpm: f64| json!({"speed_rpm": rpm, "lubricant": {"iso_vg": 32}, "temperature_c": 60,
            "surfaces": [{"kind": "rim", "diameter_m": d, "width_m": 0.2 * d, "gap_m": gap_fraction * d},
                         {"kind": "face", "inner_diameter_m": 0.5 * d, "outer_diameter_m": d, "gap_m": gap_fraction * d}],
            "through_flow": {"flow_m3_s": 1e-3, "diameter_m": d}});
        let (slow, fast) = (ok::<ParasiticLosses>(&body(rpm)), ok::<ParasiticLosses>(&body(2.0 * rpm)));
        for v in [&slow, &fast] {
            let total = result_field(v, "total_power_w");
            prop_assert!(total.is_finite() && total > 0.0);
        }
        let ratio = |f: &str| at(&fast, f) / at(&slow, f);
        prop_assert!((ratio("/drag_power_w") / 2f64.powf(2.75) - 1.0).abs() < 1e-9);
        prop_assert!((ratio("/through_flow/power_w") / 4.0 - 1.0).abs() < 1e-9);
    }
}
