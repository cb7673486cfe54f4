//! The flash-temperature room's tests: the conductances against the texts, the room through the registry.

use super::*;
use crate::calc::surface::flash::{conductance, Body, FlashModel, Source};
use crate::calc::testing::{assert_rel, invalid_pointers, ok, result_field};
use proptest::prelude::*;
use serde_json::{json, Value};

fn steel(speed: f64) -> Value {
    json!({"speed_m_s": speed, "thermal_conductivity_w_m_k": 54.0, "thermal_diffusivity_m2_s": 1.474e-5})
}

/// Khonsari & Booser Ex. 3.2.
fn example_3_2() -> Value {
    json!({
        "geometry": {"shape": "circular", "radius_m": 0.01},
        "load_n": 3000.0, "friction_coefficient": 0.1,
        "body_a": steel(0.5), "body_b": steel(0.0)
    })
}

/// Stachowiak & Batchelor §7.6 example: two steel rollers, b from Hertz.
fn two_rollers() -> Value {
    let roller = |u: f64| json!({"speed_m_s": u, "thermal_conductivity_w_m_k": 46.7, "density_kg_m3": 7800.0, "specific_heat_j_kg_k": 460.0});
    json!({
        "geometry": {"shape": "line", "half_width_m": 1.819456736586892e-4, "length_m": 0.01},
        "load_n": 5000.0, "friction_coefficient": 0.2,
        "body_a": roller(2.0), "body_b": roller(1.0), "bulk_temperature_c": 80.0
    })
}

fn body(v: &Value, name: &str, field: &str) -> f64 {
    v["result"][name][field]
        .as_f64()
        .unwrap_or_else(|| panic!("{name}.{field} missing in {v}"))
}

#[test]
fn khonsari_example_3_2_moving_steel_on_a_stationary_pin() {
    let v = ok::<FlashTemperature>(&example_3_2());
    // Spec recomputation: Pe = 169.6, 32.13 and 2.16 W/°C, ΔT = 4.37 °C, 69.4 °C.
    assert_rel(body(&v, "body_a", "peclet_number"), 169.6, 1e-3, "Pe");
    assert_rel(
        body(&v, "body_a", "thermal_conductance_w_k"),
        32.13,
        1e-3,
        "C1",
    );
    assert_rel(
        body(&v, "body_b", "thermal_conductance_w_k"),
        2.16,
        1e-9,
        "C2",
    );
    assert_rel(
        result_field(&v, "flash_temperature_rise_k"),
        4.37,
        2e-3,
        "ΔT",
    );
    assert_rel(
        body(&v, "body_b", "flash_temperature_rise_alone_k"),
        69.4,
        1e-3,
        "all heat in body 2",
    );
    assert_rel(result_field(&v, "heat_flux_w"), 150.0, 1e-12, "Q");
    assert_eq!(v["result"]["model"], "tian_kennedy");
    assert_eq!(v["result"]["body_a"]["regime"], "fast");
    assert_eq!(v["result"]["body_b"]["regime"], "slow");
    assert!(v["result"]["max_flash_temperature_rise_k"].is_null());
}

#[test]
fn stachowiak_two_rollers_follow_table_7_7_and_blok_eq_7_40() {
    let v = ok::<FlashTemperature>(&two_rollers());
    assert_rel(body(&v, "body_a", "peclet_number"), 13.98, 1e-3, "L_A");
    assert_rel(body(&v, "body_b", "peclet_number"), 6.99, 1e-3, "L_B");
    assert_rel(
        body(&v, "body_a", "thermal_diffusivity_m2_s"),
        13.02e-6,
        1e-3,
        "χ",
    );
    // Table 7.7 summed over two fast bodies is eq. 7.40 with 2/√π = 1.128 for 1.11.
    let (mu, w, two_l, b): (f64, f64, f64, f64) = (0.2, 5000.0, 0.01, 1.819456736586892e-4);
    let krs: f64 = 46.7 * 7800.0 * 460.0;
    let eq_7_40 =
        |c: f64| c * mu * w * (2f64.sqrt() - 1.0) / (two_l * (2.0 * b).sqrt() * krs.sqrt());
    let t_max = result_field(&v, "max_flash_temperature_rise_k");
    assert_rel(
        t_max,
        eq_7_40(2.0 / std::f64::consts::PI.sqrt()),
        1e-3,
        "Table 7.7 = eq 7.40 with 1.128",
    );
    assert_rel(eq_7_40(1.11), 186.2, 1e-3, "the book's eq 7.40");
    assert_rel(
        t_max,
        186.2,
        0.017,
        "within the 1.11/1.128 difference of the book",
    );
    assert_rel(
        result_field(&v, "max_surface_temperature_c"),
        80.0 + t_max,
        1e-12,
        "T_c",
    );
    assert!(result_field(&v, "flash_temperature_rise_k") < t_max);
}

#[test]
fn tian_kennedy_meets_archard_fast_at_high_peclet_and_4ak_near_zero() {
    let source = Source::Circular { radius: 0.01 };
    let at = |speed: f64| Body {
        speed,
        conductivity: 54.0,
        diffusivity: 1.474e-5,
    };
    let c = |m, b: &Body| conductance(m, source, b).expect("a formula").mean;
    // L = 1e4: 4.56 against 1/0.308 × √2 = 4.592, their constants 0.7 % apart.
    let fast = at(1e4 * 2.0 * 1.474e-5 / 0.01);
    assert_rel(
        c(FlashModel::TianKennedy, &fast),
        c(FlashModel::Jaeger, &fast),
        0.01,
        "high Pe",
    );
    // Pe → 0: 4.56 √0.66 aK = 3.705 aK against 4aK (eq 3.50), the disc's flux vs isothermal.
    let creep = at(1e-9);
    let ratio = c(FlashModel::TianKennedy, &creep) / c(FlashModel::Jaeger, &creep);
    assert_rel(ratio, 4.56 * 0.66f64.sqrt() / 4.0, 1e-6, "low Pe");
    assert_eq!(
        c(FlashModel::TianKennedy, &at(0.0)),
        c(FlashModel::Jaeger, &at(0.0))
    );
}

#[test]
fn a_stationary_body_under_a_band_takes_no_heat() {
    let mut req = two_rollers();
    req["body_b"]["speed_m_s"] = json!(0.0);
    let v = ok::<FlashTemperature>(&req);
    assert_eq!(body(&v, "body_b", "heat_w"), 0.0);
    assert_rel(body(&v, "body_a", "heat_fraction"), 1.0, 1e-12, "all to A");
    assert!(v["result"]["body_b"]["flash_temperature_rise_alone_k"].is_null());
    assert_eq!(v["warnings"][0]["code"], "stationary_band_source");
}

#[test]
fn square_slow_and_fast_forms_match_table_7_6() {
    // A slow square (L = 0.01) on a fast one (L = 50): both forms by hand.
    let (b, k, chi, mu, w) = (1e-3, 50.0, 1e-5, 0.3, 100.0);
    let (ua, ub) = (1.0, 2e-4);
    let req = json!({
        "geometry": {"shape": "square", "half_width_m": b},
        "load_n": w, "friction_coefficient": mu,
        "body_a": {"speed_m_s": ua, "thermal_conductivity_w_m_k": k, "thermal_diffusivity_m2_s": chi},
        "body_b": {"speed_m_s": ub, "thermal_conductivity_w_m_k": k, "thermal_diffusivity_m2_s": chi}
    });
    let v = ok::<FlashTemperature>(&req);
    let q: f64 = mu * w * (ua - ub) / (4.0 * b * b);
    let ta = 1.064 * q / k * (chi * b / ua).sqrt();
    let tb = 0.946 * q * b / k;
    let tmax_a = 2.0 * q / k * (2.0 * chi * b / (std::f64::consts::PI * ua)).sqrt();
    let tmax_b = 1.122 * q * b / k;
    assert_rel(
        body(&v, "body_a", "flash_temperature_rise_alone_k"),
        ta,
        1e-12,
        "T_fA",
    );
    assert_rel(
        body(&v, "body_b", "flash_temperature_rise_alone_k"),
        tb,
        1e-12,
        "T_fB",
    );
    assert_rel(
        result_field(&v, "flash_temperature_rise_k"),
        1.0 / (1.0 / ta + 1.0 / tb),
        1e-12,
        "eq 7.37",
    );
    assert_rel(
        result_field(&v, "max_flash_temperature_rise_k"),
        1.0 / (1.0 / tmax_a + 1.0 / tmax_b),
        1e-12,
        "eq 7.38",
    );
}

#[test]
fn the_intermediate_peclet_range_is_integrated_between_the_slow_and_fast_forms() {
    // A square on a moving body through L = 0.1 … 5: the integrated mean lies below the slow
    // form and above the fast one, and falls with speed (Stachowiak Table 7.6, Fig. 7.30).
    let mut last = f64::INFINITY;
    for speed in [0.004, 0.01, 0.03, 0.1] {
        let mut r = two_rollers();
        r["geometry"] = json!({"shape": "square", "half_width_m": 1e-3});
        r["body_b"]["speed_m_s"] = json!(0.0);
        r["body_a"]["speed_m_s"] = json!(speed);
        let v = ok::<FlashTemperature>(&r);
        let l = body(&v, "body_a", "peclet_number");
        assert!(0.1 < l && l < 5.0, "L = {l}");
        assert_eq!(
            v["solver"]["method"],
            "jaeger_archard_with_moving_source_quadrature"
        );
        let alone = body(&v, "body_a", "flash_temperature_rise_alone_k");
        let q = v["result"]["heat_flux_w"].as_f64().unwrap();
        let qb_k = q / 4e-6 * 1e-3 / 46.7;
        // Each limiting form overestimates outside its own range: the exact lies below both.
        let (slow, fast) = (0.946 * qb_k, 1.064 / (2.0 * l).sqrt() * qb_k);
        assert!(alone < slow.min(fast), "L = {l}");
        // … and approaches each near its range: within 15 % at L = 0.15 and L = 3.8.
        assert!(l > 0.2 || alone > 0.85 * slow, "L = {l}");
        assert!(l < 3.0 || alone > 0.85 * fast, "L = {l}");
        let per_heat = alone / q;
        assert!(per_heat < last);
        last = per_heat;
    }
}

#[test]
fn refusals_name_the_field() {
    let mut tk_square = two_rollers();
    tk_square["model"] = json!("tian_kennedy");
    let mut missing = example_3_2();
    missing["geometry"] = json!({"shape": "line", "half_width_m": 1e-4});
    let mut both_thermal = example_3_2();
    both_thermal["body_b"]["density_kg_m3"] = json!(7800.0);
    let mut still = example_3_2();
    still["body_a"]["speed_m_s"] = json!(0.0);
    let mut typo = example_3_2();
    typo["lod_n"] = json!(1.0);
    let mut stray = example_3_2();
    stray["geometry"]["length_m"] = json!(0.01);
    let rows: [(&Value, &str, &str); 5] = [
        (&tk_square, "/model", "Tian–Kennedy is circular"),
        (&missing, "/geometry/length_m", "a band needs its length"),
        (
            &both_thermal,
            "/body_b/thermal_diffusivity_m2_s",
            "χ and ρ, σ both",
        ),
        (&still, "/body_a/speed_m_s", "nothing moves"),
        (&stray, "/geometry/length_m", "a circle has no length"),
    ];
    for (req, pointer, why) in rows {
        assert_eq!(
            invalid_pointers::<FlashTemperature>(req),
            vec![pointer.to_owned()],
            "{why}"
        );
    }
    assert!(crate::calc::testing::post::<FlashTemperature>(&typo).is_err());
}

#[test]
fn example_runs() {
    let req: Value = serde_json::from_str(FlashTemperature::EXAMPLE).expect("example is JSON");
    let v = ok::<FlashTemperature>(&req);
    assert_rel(
        result_field(&v, "mean_surface_temperature_c"),
        40.0 + 4.374,
        1e-3,
        "T_b + ΔT",
    );
}

#[test]
fn reference_cases_pass() {
    for case in [
        include_str!("../../../tests/data/contact/kb_ex3_2_flash_temperature_pin.json"),
        include_str!(
            "../../../tests/data/contact/stachowiak_r7_6_flash_temperature_two_rollers.json"
        ),
    ] {
        let case: Value = serde_json::from_str(case).expect("case is JSON");
        assert_eq!(case["path"], FlashTemperature::PATH);
        let v = ok::<FlashTemperature>(&case["request"]);
        for want in case["expected"].as_array().expect("expected list") {
            let pointer = want["pointer"].as_str().expect("pointer");
            let got = v
                .pointer(pointer)
                .and_then(Value::as_f64)
                .unwrap_or(f64::NAN);
            let (value, tol) = (want["value"].as_f64(), want["rel_tol"].as_f64());
            assert_rel(got, value.expect("value"), tol.expect("rel_tol"), pointer);
        }
    }
}

/// A request over the valid ranges: a circular Tian–Kennedy case, or a Jaeger square or
/// band with body A fast (L ≥ 5) and body B fast or stationary.
fn request(shape: u8, load: f64, mu: f64, speed: f64, b_moves: bool) -> Value {
    let geometry = match shape {
        0 => json!({"shape": "circular", "radius_m": 1e-3}),
        1 => json!({"shape": "square", "half_width_m": 1e-3}),
        _ => json!({"shape": "line", "half_width_m": 1e-3, "length_m": 0.02}),
    };
    let b_speed = if b_moves { speed / 3.0 } else { 0.0 };
    json!({
        "geometry": geometry, "load_n": load, "friction_coefficient": mu,
        "body_a": steel(speed), "body_b": steel(b_speed)
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    #[test]
    fn finite_shared_and_monotone(
        shape in 0u8..3, load in 1.0f64..1e5, mu in 0.01f64..1.0,
        // L_A = U·1e-3/(2·1.474e-5) ≥ 5 (and L_B ≥ 5 when B moves at U/3).
        speed in 0.45f64..100.0, b_moves: bool, grow in 1.01f64..3.0,
    ) {
        let run = |l: f64, m: f64, u: f64| ok::<FlashTemperature>(&request(shape, l, m, u, b_moves));
        let v = run(load, mu, speed);
        let t = result_field(&v, "flash_temperature_rise_k");
        prop_assert!(t.is_finite() && t > 0.0);
        let q = result_field(&v, "heat_flux_w");
        let shares = body(&v, "body_a", "heat_w") + body(&v, "body_b", "heat_w");
        prop_assert!((shares / q - 1.0).abs() < 1e-12);
        let fractions = body(&v, "body_a", "heat_fraction") + body(&v, "body_b", "heat_fraction");
        prop_assert!((fractions - 1.0).abs() < 1e-12);
        for bigger in [run(load * grow, mu, speed), run(load, mu * grow, speed), run(load, mu, speed * grow)] {
            prop_assert!(result_field(&bigger, "flash_temperature_rise_k") > t);
        }
    }
}
