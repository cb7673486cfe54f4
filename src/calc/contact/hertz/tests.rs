//! The Hertz room's tests: physics against the texts, the contract through the registry.

use super::model::{exact_ellipse, radius_ratio_of, MAX_ELLIPTICITY, MAX_RADIUS_RATIO};
use super::subsurface::{ellipse_axis_stresses, line_axis_stresses};
use super::Hertz;
use crate::calc::Calculation;
use crate::calc::Failure;
use proptest::prelude::*;
use serde_json::{json, Value};

/// The whole path: parse, validate, run, serialise.
fn post(request: &Value) -> Result<Value, Failure> {
    crate::calc::testing::post::<Hertz>(request)
}

fn ok(request: &Value) -> Value {
    crate::calc::testing::ok::<Hertz>(request)
}

fn pointers(request: &Value) -> Vec<String> {
    match post(request) {
        Err(Failure::Invalid(errors)) => errors.into_iter().map(|e| e.pointer).collect(),
        other => panic!("{request}: expected 422, got {other:?}"),
    }
}

fn body(rx: Option<f64>, ry: Option<f64>, e: f64, nu: f64) -> Value {
    let mut b = json!({"elastic_modulus_pa": e, "poisson_ratio": nu});
    if let Some(r) = rx {
        b["radius_x_m"] = json!(r);
    }
    if let Some(r) = ry {
        b["radius_y_m"] = json!(r);
    }
    b
}

fn steel(rx: Option<f64>, ry: Option<f64>) -> Value {
    body(rx, ry, 2.1e11, 0.3)
}

fn get(v: &Value, field: &str) -> f64 {
    v["result"][field]
        .as_f64()
        .unwrap_or_else(|| panic!("{field} missing in {v}"))
}

#[track_caller]
fn assert_rel(got: f64, want: f64, rel: f64, what: &str) {
    assert!(
        ((got - want) / want).abs() <= rel,
        "{what}: got {got:e}, want {want:e} ± {rel}"
    );
}

#[test]
fn the_example_runs() {
    let v = ok(&serde_json::from_str(Hertz::EXAMPLE).unwrap());
    assert_eq!(v["solver"]["fidelity"], "standard");
}

#[test]
fn stachowiak_two_balls() {
    // Stachowiak & Batchelor §7.3 (spec R7.1): W = 5 N, R_A = 10 mm, R_B = 15 mm, steel.
    let v = ok(
        &json!({"body1": steel(Some(0.01), Some(0.01)), "body2": steel(Some(0.015), Some(0.015)), "load_n": 5.0}),
    );
    assert_rel(get(&v, "reduced_radius_m"), 3e-3, 1e-12, "R'");
    assert_rel(get(&v, "effective_modulus_pa"), 2.1e11 / 0.91, 1e-12, "E'");
    assert_rel(get(&v, "semi_major_axis_m"), 5.7989e-5, 1e-4, "a");
    assert_rel(get(&v, "semi_minor_axis_m"), 5.7989e-5, 1e-4, "b");
    assert_rel(get(&v, "max_pressure_pa"), 709.94e6, 1e-4, "p_max");
    assert_rel(get(&v, "mean_pressure_pa"), 473.29e6, 1e-4, "p_avg");
    // 5.603e-7 with the book's rounded 1.0397 for (π/2)(9/π³)^⅓ = 1.03993.
    assert_rel(get(&v, "approach_m"), 5.603e-7, 5e-4, "δ");
    assert_eq!(get(&v, "ellipticity"), 1.0);
    assert_eq!(v["result"]["major_axis_along"], "circle");
}

#[test]
fn stachowiak_parallel_cylinders_per_length() {
    // Stachowiak & Batchelor §7.3 (spec R7.3): W = 5 N on 2l = 10 mm, R_A = 10, R_B = 15 mm.
    let v = ok(
        &json!({"body1": steel(Some(0.01), None), "body2": steel(Some(0.015), None), "load_n": 5.0, "line": {"length_m": 0.01}}),
    );
    assert_eq!(v["result"]["contact"], "line");
    assert_rel(get(&v, "half_width_m"), 5.7536e-6, 1e-4, "b");
    assert_rel(get(&v, "max_pressure_pa"), 55.32e6, 2e-4, "p_max");
    assert_rel(get(&v, "mean_pressure_pa"), 43.45e6, 2e-4, "p_avg");
    // The book prints 2.40e-8 with 0.319 for 1/π in δ = (W/(πE′l))[…]; exact 1/π: 2.3972e-8.
    assert_rel(get(&v, "approach_m"), 2.40e-8, 2e-3, "δ");
    // McEwen: τ₁ = 0.300 p_max at 0.786 b (Stachowiak Table 7.2, Khonsari §14.3).
    let p = get(&v, "max_pressure_pa");
    let b = get(&v, "half_width_m");
    assert_rel(get(&v, "max_shear_stress_pa") / p, 0.3004, 1e-3, "τ₁/p");
    assert_rel(get(&v, "max_shear_depth_m") / b, 0.7861, 1e-3, "z/b");
    assert!(v["result"].get("ellipticity").is_none());
}

#[test]
fn stachowiak_crossed_wires_are_circular() {
    // Spec R7.4: two wires R = 1.5 mm crossed at 90°, W = 5 N.
    let v = ok(
        &json!({"body1": steel(Some(0.0015), None), "body2": steel(None, Some(0.0015)), "load_n": 5.0}),
    );
    assert_rel(get(&v, "semi_major_axis_m"), 3.6531e-5, 1e-4, "a");
    assert_rel(get(&v, "max_pressure_pa"), 1788.9e6, 1e-4, "p_max");
    assert_rel(get(&v, "mean_pressure_pa"), 1192.6e6, 1e-4, "p_avg");
}

fn grooved_ring(fidelity: &str) -> Value {
    // Spec R7.5: ball R = 15 mm in a groove −30 mm of a ring −60 mm, W = 50 N.
    json!({"body1": steel(Some(0.015), Some(0.015)), "body2": steel(Some(-0.03), Some(-0.06)), "load_n": 50.0, "fidelity": fidelity})
}

#[test]
fn stachowiak_ball_in_grooved_ring_by_hamrock_dowson() {
    let v = ok(&grooved_ring("closed_form"));
    assert_eq!(v["solver"]["method"], "hamrock_dowson_fit");
    assert_rel(get(&v, "ellipticity"), 1.33805, 1e-5, "κ̄");
    assert_rel(get(&v, "elliptic_integral_e"), 1.39817, 1e-5, "Ē");
    assert_rel(get(&v, "elliptic_integral_k"), 1.77191, 1e-5, "F̄");
    assert_rel(get(&v, "semi_major_axis_m"), 2.3165e-4, 2e-4, "a");
    assert_rel(get(&v, "semi_minor_axis_m"), 1.7312e-4, 2e-4, "b");
    assert_rel(get(&v, "max_pressure_pa"), 595.29e6, 2e-4, "p_max");
    assert_rel(get(&v, "mean_pressure_pa"), 396.86e6, 2e-4, "p_avg");
    assert_rel(get(&v, "approach_m"), 1.583e-6, 5e-4, "δ");
    // The groove (x) is the more conforming direction: R_x = 30 mm > R_y = 20 mm.
    assert_eq!(v["result"]["major_axis_along"], "x");
    assert_rel(get(&v, "radius_ratio"), 1.5, 1e-12, "α_r");
}

#[test]
fn stachowiak_ball_in_grooved_ring_exact() {
    let v = ok(&grooved_ring("standard"));
    assert_eq!(v["solver"]["method"], "hertz_exact_brent_agm");
    assert!(v["solver"]["residual"].as_f64().unwrap() < 1e-12);
    assert_rel(get(&v, "ellipticity"), 1.310, 5e-4, "κ exact");
    let hd = ok(&grooved_ring("closed_form"));
    for f in [
        "semi_major_axis_m",
        "semi_minor_axis_m",
        "max_pressure_pa",
        "approach_m",
    ] {
        assert_rel(get(&hd, f), get(&v, f), 0.03, f);
    }
}

/// Hamrock Table 21.8 bodies; E′ = 2.197e11 Pa from E = 2.197e11 × (1 − 0.3²), ν = 0.3.
fn table_21_8(case: &str, fidelity: &str) -> Value {
    let m = |rx: Option<f64>, ry: Option<f64>| body(rx, ry, 2.197e11 * 0.91, 0.3);
    let (b1, b2, w) = match case {
        "wheel_rail" => (m(Some(0.5019), None), m(None, Some(0.30)), 1.0e5),
        "ball_plane" => (m(Some(0.00635), Some(0.00635)), m(None, None), 222.4111),
        _ => (
            m(Some(0.00635), Some(0.00635)),
            m(Some(-0.0389), Some(-0.0066)),
            222.4111,
        ),
    };
    let mut r = json!({"body1": b1, "body2": b2, "load_n": w, "fidelity": fidelity});
    if fidelity == "closed_form" {
        r["closed_form"] = json!("hamrock_brewe");
    }
    r
}

#[test]
fn hamrock_table_21_8_by_hamrock_brewe() {
    // (case, k, 𝓔, 𝓚, D_y cm, D_x cm, δ cm, σ_max N/cm²). Wheel/rail: the table's x is
    // the rolling direction with α_r < 1, so its D_x is our major axis; δ = 0.0108 cm
    // needs the k the printed α_r < 1 formula drops (spec A.1.1 erratum).
    let rows = [
        (
            "wheel_rail",
            1.0 / 0.7206,
            1.3412,
            1.8645,
            1.4997,
            1.0807,
            0.0108,
            1.1784e5,
        ),
        (
            "ball_plane",
            1.0,
            std::f64::consts::FRAC_PI_2,
            std::f64::consts::FRAC_PI_2,
            0.0426,
            0.0426,
            7.13e-4,
            2.34e5,
        ),
        (
            "ball_outer_race",
            7.1738,
            1.0258,
            3.3375,
            0.1810,
            0.0252,
            3.57e-4,
            9.30e4,
        ),
    ];
    for (case, k, e, kk, major_cm, minor_cm, delta_cm, p_ncm2) in rows {
        let v = ok(&table_21_8(case, "closed_form"));
        assert_rel(get(&v, "ellipticity"), k, 1e-3, case);
        assert_rel(get(&v, "elliptic_integral_e"), e, 1e-3, case);
        assert_rel(get(&v, "elliptic_integral_k"), kk, 1e-3, case);
        assert_rel(get(&v, "semi_major_axis_m"), major_cm / 200.0, 3e-3, case);
        assert_rel(get(&v, "semi_minor_axis_m"), minor_cm / 200.0, 3e-3, case);
        assert_rel(get(&v, "approach_m"), delta_cm / 100.0, 5e-3, case);
        assert_rel(get(&v, "max_pressure_pa"), p_ncm2 * 1e4, 3e-3, case);
    }
    assert_eq!(
        ok(&table_21_8("wheel_rail", "closed_form"))["result"]["major_axis_along"],
        "x"
    );
}

#[test]
fn hamrock_table_21_8_exact() {
    // Spec A-R1: exact wheel/rail δ = 0.010592 cm; ball/outer race κ = 7.365, D_y = 0.1842 cm.
    let v = ok(&table_21_8("wheel_rail", "standard"));
    assert_rel(get(&v, "approach_m"), 1.0592e-4, 1e-3, "δ wheel/rail");
    let v = ok(&table_21_8("ball_outer_race", "standard"));
    assert_rel(get(&v, "ellipticity"), 7.365, 1e-3, "κ");
    assert_rel(get(&v, "semi_major_axis_m"), 0.1842e-2 / 2.0, 1e-3, "a");
    let v = ok(&table_21_8("ball_plane", "standard"));
    assert_eq!(get(&v, "ellipticity"), 1.0);
    assert_rel(get(&v, "semi_major_axis_m"), 0.0426e-2 / 2.0, 3e-3, "a");
}

/// Hamrock §21.3.6 deep-groove ball bearing (spec A-R3): d = 12.7 mm, d_e = 65 mm,
/// r = 6.604 mm, E = 2e11, ν = 0.3, most-loaded ball F_max = 4513 N.
fn deep_groove(race: &str, fidelity: &str) -> Value {
    let race_x = if race == "inner" { 0.026 } else { -0.03885 };
    json!({
        "body1": body(Some(0.00635), Some(0.00635), 2e11, 0.3),
        "body2": body(Some(race_x), Some(-0.006604), 2e11, 0.3),
        "load_n": 4513.0, "fidelity": fidelity
    })
}

#[test]
fn hamrock_deep_groove_ball_bearing() {
    let v = ok(&deep_groove("inner", "closed_form"));
    assert_rel(get(&v, "reduced_radius_x_m"), 0.00511, 2e-3, "R_x,i");
    assert_rel(get(&v, "reduced_radius_y_m"), 0.165, 2e-3, "R_y");
    assert_rel(get(&v, "radius_ratio"), 32.35, 2e-3, "α_r,i");
    assert_rel(get(&v, "ellipticity"), 9.42, 2e-3, "k_i");
    assert_rel(get(&v, "elliptic_integral_e"), 1.0188, 1e-3, "𝓔_i");
    assert_rel(get(&v, "elliptic_integral_k"), 3.6205, 1e-3, "𝓚_i");
    assert_rel(get(&v, "approach_m"), 2.731e-5, 2e-3, "δ_i stage 4");
    assert_rel(get(&v, "effective_modulus_pa"), 2.198e11, 1e-3, "E'");
    // Exact Hertz against the source's fitted stage-4 δ (spec A-R3: "within about 1 %";
    // the outer is 1.8 % below, the source having mixed k_o = 7.09 from the 2/π fit).
    for (race, delta) in [("inner", 2.731e-5), ("outer", 2.707e-5)] {
        let v = ok(&deep_groove(race, "standard"));
        assert_rel(get(&v, "approach_m"), delta, 0.02, race);
    }
}

/// Khonsari & Booser Ex 14.2: most-loaded ball of a 6210, Q = 1500 N, E′ = 219 000 N/mm²,
/// ball D = 12.7 mm, raceways d_i = 57.291 / d_o = 82.709 mm, groove radii 6.6 mm.
fn bearing_6210(race: &str) -> Value {
    let e = 2.19e11 * 0.91;
    let race_x = if race == "inner" {
        0.0286455
    } else {
        -0.0413545
    };
    json!({
        "body1": body(Some(0.00635), Some(0.00635), e, 0.3),
        "body2": body(Some(race_x), Some(-0.0066), e, 0.3),
        "load_n": 1500.0
    })
}

#[test]
fn khonsari_6210_raceway_contacts() {
    // Spec Ex 14.2 "recomp. exact" (the printed δ = 0.0278 / 0.0240 mm used exponent 1/3,
    // and b_outer 0.243 is a transposition of 0.234: erratum E-11).
    for (race, sum, a, b, delta, p) in [
        ("inner", 198.35, 1.794e-3, 0.1935e-3, 0.01320e-3, 2063e6),
        ("outer", 139.26, 1.744e-3, 0.2351e-3, 0.01276e-3, 1747e6),
    ] {
        let v = ok(&bearing_6210(race));
        assert_rel(get(&v, "curvature_sum_1_m"), sum, 2e-4, race);
        assert_rel(get(&v, "semi_major_axis_m"), a, 2e-3, race);
        assert_rel(get(&v, "semi_minor_axis_m"), b, 2e-3, race);
        assert_rel(get(&v, "approach_m"), delta, 2e-3, race);
        assert_rel(get(&v, "max_pressure_pa"), p, 2e-3, race);
        // §14.3: τ₁ ≈ 0.30–0.33 p_max at about 0.76–0.77 b for b/a ≈ 0.1.
        let ratio = get(&v, "max_shear_stress_pa") / p;
        let depth = get(&v, "max_shear_depth_m") / b;
        assert!((0.29..=0.33).contains(&ratio), "{race}: τ₁/p = {ratio}");
        assert!((0.70..=0.80).contains(&depth), "{race}: z/b = {depth}");
    }
}

#[test]
fn circular_subsurface_stresses_match_johnson() {
    // Johnson §3.4: ν = 0.3, τ₁ = 0.31 p₀ at z = 0.48a; von Mises about 0.62 p₀ near 0.48a.
    let v = ok(
        &json!({"body1": steel(Some(0.01), Some(0.01)), "body2": steel(None, None), "load_n": 100.0}),
    );
    let (p, a) = (get(&v, "max_pressure_pa"), get(&v, "semi_major_axis_m"));
    assert_rel(get(&v, "max_shear_stress_pa") / p, 0.31, 0.01, "τ₁/p₀");
    assert_rel(get(&v, "max_shear_depth_m") / a, 0.48, 0.01, "z/a");
    let vm = get(&v, "max_von_mises_pa") / p;
    assert!((0.6..0.65).contains(&vm), "σ_vm/p₀ = {vm}");
}

#[test]
fn axis_stresses_reduce_to_the_axisymmetric_closed_form() {
    // Johnson eq. 3.45: σ_r/p₀ = −(1 + ν)(1 − ζ atan(1/ζ)) + 1/(2(1 + ζ²)), σ_z/p₀ = −1/(1 + ζ²).
    for nu in [-0.5, 0.0, 0.3, 0.5] {
        for zeta in [0.0, 0.1, 0.48, 1.0, 3.0] {
            let s = ellipse_axis_stresses(1.0, zeta, nu);
            let atan = if zeta == 0.0 {
                0.0
            } else {
                zeta * (1.0 / zeta).atan()
            };
            let sr = -(1.0 + nu) * (1.0 - atan) + 0.5 / (1.0 + zeta * zeta);
            let sz = -1.0 / (1.0 + zeta * zeta);
            for (got, want) in [(s[0], sr), (s[1], sr), (s[2], sz)] {
                assert!(
                    (got - want).abs() < 1e-13,
                    "ν {nu} ζ {zeta}: {got} vs {want}"
                );
            }
        }
    }
}

#[test]
fn axis_stresses_tend_to_the_line_contact() {
    for zeta in [0.0, 0.3, 0.786, 2.0] {
        let e = ellipse_axis_stresses(1e7, zeta, 0.3);
        let l = line_axis_stresses(zeta, 0.3);
        for (got, want) in [(e[0], l[0]), (e[1], l[1]), (e[2], l[2])] {
            assert!((got - want).abs() < 1e-5, "ζ {zeta}: {got} vs {want}");
        }
    }
}

#[test]
fn axis_stresses_at_the_centre_of_an_ellipse() {
    // σ_a(0) = −p₀[2ν + (1 − 2ν) b/(a + b)], σ_b(0) = −p₀[2ν + (1 − 2ν) a/(a + b)].
    for (kappa, nu) in [(3.0, 0.3), (12.0, 0.25), (1.5, 0.5)] {
        let s = ellipse_axis_stresses(kappa, 0.0, nu);
        let along_a = -(2.0 * nu + (1.0 - 2.0 * nu) / (kappa + 1.0));
        let along_b = -(2.0 * nu + (1.0 - 2.0 * nu) * kappa / (kappa + 1.0));
        assert!((s[0] - along_a).abs() < 1e-13 && (s[1] - along_b).abs() < 1e-13);
        assert!((s[2] + 1.0).abs() < 1e-15);
    }
}

#[test]
fn the_exact_ellipticity_inverts_the_radius_ratio() {
    for kappa in [1.0, 1.000_001, 1.31, 7.365, 100.0, 1e4, 9e5] {
        let (alpha, _) = radius_ratio_of(kappa);
        let (ellipse, _) = exact_ellipse(alpha).unwrap();
        assert_rel(ellipse.ellipticity, kappa, 1e-10, "κ");
    }
    assert!(radius_ratio_of(MAX_ELLIPTICITY).0 > MAX_RADIUS_RATIO);
}

#[test]
fn a_conforming_groove_close_to_osculation_still_solves() {
    // Ball d = 12.7 mm in a groove of conformity f = r/d → 0.5⁺, flat raceway.
    for f in [0.52, 0.501, 0.5001, 0.500_001] {
        let r = ok(
            &json!({"body1": steel(Some(0.00635), Some(0.00635)), "body2": steel(None, Some(-f * 0.0127)), "load_n": 1000.0}),
        );
        let kappa = get(&r, "ellipticity");
        assert!(kappa > 5.0 && kappa.is_finite(), "f = {f}: κ = {kappa}");
        assert_eq!(r["result"]["major_axis_along"], "y");
    }
}

#[test]
fn bad_input_is_refused_with_its_pointer() {
    let ball = steel(Some(0.01), Some(0.01));
    let rows: Vec<(Value, &str, &str)> = vec![
        (
            json!({"body1": ball, "body2": steel(None, None), "load_n": -1.0}),
            "/load_n",
            "negative load",
        ),
        (
            json!({"body1": ball, "body2": steel(None, None), "load_n": 0.0}),
            "/load_n",
            "zero load",
        ),
        (
            json!({"body1": body(Some(0.01), None, 2e11, 0.6), "body2": ball, "load_n": 1.0}),
            "/body1/poisson_ratio",
            "ν > 0.5",
        ),
        (
            json!({"body1": body(Some(0.01), None, 2e11, -1.0), "body2": ball, "load_n": 1.0}),
            "/body1/poisson_ratio",
            "ν = −1",
        ),
        (
            json!({"body1": ball, "body2": body(None, None, 0.0, 0.3), "load_n": 1.0}),
            "/body2/elastic_modulus_pa",
            "E = 0",
        ),
        (
            json!({"body1": ball, "body2": body(None, None, -2e11, 0.3), "load_n": 1.0}),
            "/body2/elastic_modulus_pa",
            "E < 0",
        ),
        (
            json!({"body1": ball, "body2": steel(Some(-0.01), Some(-0.02)), "load_n": 1.0}),
            "/body2/radius_x_m",
            "osculating groove",
        ),
        (
            json!({"body1": ball, "body2": steel(Some(-0.005), Some(-0.02)), "load_n": 1.0}),
            "/body2/radius_x_m",
            "concave tighter than the ball",
        ),
        (
            json!({"body1": steel(Some(-0.01), Some(-0.01)), "body2": steel(None, None), "load_n": 1.0}),
            "/body1/radius_x_m",
            "concave on flat",
        ),
        (
            json!({"body1": steel(Some(0.01), None), "body2": steel(None, None), "load_n": 1.0}),
            "/body1/radius_y_m",
            "cylinder on flat without line",
        ),
        (
            json!({"body1": ball, "body2": steel(None, None), "load_n": 1.0, "line": {"length_m": 0.01}}),
            "/body1/radius_y_m",
            "radius_y in a line contact",
        ),
        (
            json!({"body1": steel(None, None), "body2": steel(None, None), "load_n": 1.0, "line": {"length_m": 0.01}}),
            "/body1/radius_x_m",
            "flat on flat",
        ),
        (
            json!({"body1": ball, "body2": steel(None, None), "load_n": 1.0, "fidelity": "high"}),
            "/fidelity",
            "fidelity high",
        ),
        (
            json!({"body1": ball, "body2": steel(None, None), "load_n": 1.0, "closed_form": "hamrock_brewe"}),
            "/closed_form",
            "fit without closed_form",
        ),
        (
            json!({"body1": ball, "body2": steel(None, None), "lood_n": 1.0}),
            "/lood_n",
            "typo",
        ),
        (
            json!({"body1": steel(Some(0.0), None), "body2": steel(None, None), "load_n": 1.0}),
            "/body1/radius_x_m",
            "zero radius",
        ),
        (
            json!({"body1": steel(Some(0.01), Some(1e10)), "body2": steel(None, None), "load_n": 1.0}),
            "/body1/radius_y_m",
            "ratio beyond 1e9",
        ),
    ];
    for (request, pointer, why) in rows {
        let got = pointers(&request);
        assert!(got.iter().any(|p| p == pointer), "{why}: {got:?}");
    }
}

#[test]
fn the_concave_refusal_says_why() {
    let r = json!({"body1": steel(Some(0.01), Some(0.01)), "body2": steel(Some(-0.01), Some(-0.02)), "load_n": 1.0});
    let Err(Failure::Invalid(errors)) = post(&r) else {
        panic!()
    };
    assert!(
        errors[0].message.contains("osculation"),
        "{}",
        errors[0].message
    );
}

#[test]
fn a_line_contact_against_a_flat_has_no_approach() {
    let v = ok(
        &json!({"body1": steel(Some(0.01), None), "body2": steel(None, None), "load_n": 100.0, "line": {"length_m": 0.01}}),
    );
    assert!(v["result"].get("approach_m").is_none());
    assert_eq!(v["warnings"][0]["code"], "approach_undefined_for_flat");
}

#[test]
fn dissimilar_poisson_ratios_give_two_subsurface_fields() {
    let v = ok(
        &json!({"body1": body(Some(0.01), Some(0.01), 2.1e11, 0.3), "body2": body(None, None, 7e10, 0.45), "load_n": 10.0}),
    );
    let s = v["result"]["subsurface"].as_array().unwrap();
    assert_eq!(s.len(), 2);
    let t1 = s[0]["max_shear_stress_pa"].as_f64().unwrap();
    let t2 = s[1]["max_shear_stress_pa"].as_f64().unwrap();
    // Under a circle τ₁ = ½[1.5/(1 + ζ²) − (1 + ν)(1 − ζ atan(1/ζ))] p₀ falls as ν rises.
    assert!(
        t1 > t2,
        "ν = 0.3 has the larger τ₁ under a circle: {t1} vs {t2}"
    );
    assert_eq!(get(&v, "max_shear_stress_pa"), t1);
}

fn random_case(ratio: f64, load: f64, fidelity: &str) -> Value {
    json!({"body1": steel(Some(0.01), Some(0.01 * ratio)), "body2": steel(None, None), "load_n": load, "fidelity": fidelity})
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    #[test]
    fn outputs_are_finite_positive_and_consistent(
        log_ratio in -3.0f64..3.0,
        log_load in -2.0f64..4.0,
        exact in any::<bool>(),
    ) {
        let fidelity = if exact { "standard" } else { "closed_form" };
        let w = 10f64.powf(log_load);
        let v = ok(&random_case(10f64.powf(log_ratio), w, fidelity));
        for f in ["max_pressure_pa", "mean_pressure_pa", "semi_major_axis_m", "semi_minor_axis_m",
                  "approach_m", "max_shear_stress_pa", "max_shear_depth_m", "max_von_mises_pa",
                  "max_von_mises_depth_m", "curvature_sum_1_m", "reduced_radius_m", "effective_modulus_pa"] {
            let x = get(&v, f);
            prop_assert!(x.is_finite() && x > 0.0, "{} = {}", f, x);
        }
        let (a, b, p) = (get(&v, "semi_major_axis_m"), get(&v, "semi_minor_axis_m"), get(&v, "max_pressure_pa"));
        prop_assert!(get(&v, "ellipticity") >= 1.0 && a >= b);
        let total = 2.0 / 3.0 * std::f64::consts::PI * a * b * p;
        prop_assert!(((total - w) / w).abs() < 1e-12);
        // p_max ∝ W^⅓, δ ∝ W^⅔: a thousandfold load, tenfold pressure, hundredfold approach.
        let v2 = ok(&random_case(10f64.powf(log_ratio), 1e3 * w, fidelity));
        prop_assert!((get(&v2, "max_pressure_pa") / p / 10.0 - 1.0).abs() < 1e-10);
        prop_assert!((get(&v2, "approach_m") / get(&v, "approach_m") / 100.0 - 1.0).abs() < 1e-10);
    }

    #[test]
    fn conforming_grooves_stay_finite(excess in 1e-6f64..0.1, log_load in -1.0f64..5.0) {
        // Groove radius / ball diameter f = 0.5 + excess on an inner raceway.
        let f = 0.5 + excess;
        let v = ok(&json!({"body1": steel(Some(0.00635), Some(0.00635)), "body2": steel(Some(0.026), Some(-f * 0.0127)),
                           "load_n": 10f64.powf(log_load)}));
        for field in ["max_pressure_pa", "semi_major_axis_m", "semi_minor_axis_m", "approach_m", "max_shear_stress_pa", "ellipticity"] {
            let x = get(&v, field);
            prop_assert!(x.is_finite() && x > 0.0, "{} = {}", field, x);
        }
    }

    #[test]
    fn the_fits_are_within_three_percent_over_their_range(log_ratio in 0.0f64..60f64.log10(), brewe in any::<bool>()) {
        let alpha = 10f64.powf(log_ratio);
        let exact = ok(&random_case(alpha, 100.0, "standard"));
        let mut request = random_case(alpha, 100.0, "closed_form");
        if brewe {
            request["closed_form"] = json!("hamrock_brewe");
        }
        let fit = ok(&request);
        prop_assert!(fit["warnings"].as_array().unwrap().iter().all(|w| w["code"] != "fit_outside_range"));
        // Hamrock–Dowson's δ is 5.4 % low at α_r = 1 (its 𝓚(1) = 1.5277, not π/2).
        let delta_tol = if !brewe && alpha < 1.5 { 0.055 } else { 0.03 };
        for (f, tol) in [("semi_major_axis_m", 0.03), ("semi_minor_axis_m", 0.03), ("max_pressure_pa", 0.03), ("approach_m", delta_tol)] {
            let (e, c) = (get(&exact, f), get(&fit, f));
            prop_assert!(((c - e) / e).abs() < tol, "α_r {}: {} fit {} exact {}", alpha, f, c, e);
        }
    }

    #[test]
    fn line_contact_scales_with_load_per_length(log_load in 0.0f64..6.0, length in 1e-3f64..1.0) {
        let w = 10f64.powf(log_load);
        let line = |w: f64, l: f64| ok(&json!({"body1": steel(Some(0.01), None), "body2": steel(Some(-0.05), None),
                                                "load_n": w, "line": {"length_m": l}}));
        let v = line(w, length);
        let (b, p) = (get(&v, "half_width_m"), get(&v, "max_pressure_pa"));
        prop_assert!(((std::f64::consts::PI / 2.0 * b * p * length - w) / w).abs() < 1e-12);
        let doubled = line(2.0 * w, 2.0 * length);
        prop_assert!((get(&doubled, "max_pressure_pa") / p - 1.0).abs() < 1e-12);
        prop_assert!(get(&v, "approach_m") > 0.0);
    }
}

/// The model from Rust: a cylinder on a flat has no approach, and says so as data (the room
/// passes it on; the EHL rooms do not).
#[test]
fn the_model_returns_its_warnings_as_data() {
    use super::{Body, Contact, Method, Shape, APPROACH_UNDEFINED_FOR_FLAT};
    let cylinder = |r: Option<f64>| Body {
        radius_x_m: r,
        radius_y_m: None,
        modulus_pa: 2.1e11,
        poisson_ratio: 0.3,
    };
    let contact = Contact::new(
        [cylinder(Some(0.01)), cylinder(None)],
        1000.0,
        Shape::Line { length_m: 0.01 },
        Method::Exact,
    )
    .unwrap();
    let s = contact.solve().unwrap();
    assert!(s.approach_m.is_none() && s.half_width_m().is_some());
    assert!(s
        .warnings
        .iter()
        .any(|w| w.code == APPROACH_UNDEFINED_FOR_FLAT));
    assert_eq!(s.warnings_but_approach().count(), s.warnings.len() - 1);
    let room = ok(
        &json!({"body1": steel(Some(0.01), None), "body2": steel(None, None), "load_n": 1000.0, "line": {"length_m": 0.01}}),
    );
    assert_eq!(get(&room, "max_pressure_pa"), s.max_pressure_pa);
}

/// The model's refusals name typed fields; the room turns them into the request's pointers.
#[test]
fn the_model_refuses_with_typed_fields() {
    use super::{Axis, Body, Contact, Field, Method, Shape};
    let body = |rx: Option<f64>, ry: Option<f64>| Body {
        radius_x_m: rx,
        radius_y_m: ry,
        modulus_pa: 2.1e11,
        poisson_ratio: 0.3,
    };
    let refused = Contact::new(
        [
            body(Some(0.01), Some(0.01)),
            body(Some(-0.005), Some(-0.005)),
        ],
        10.0,
        Shape::Point,
        Method::Exact,
    )
    .unwrap_err();
    assert!(refused.iter().any(|e| e.field
        == Field::Radius {
            body: 2,
            axis: Axis::X
        }));
    assert_eq!(refused[0].field.hertz_pointer(), "/body2/radius_x_m");
}

/// Schemathesis's find: a line 8.8e307 m long under 2e-78 N against a 2e151 m radius left the
/// floating-point range (a 500, then a 422 from the overflow guard). The documented ranges now
/// refuse it at its first field, before any arithmetic.
#[test]
fn results_beyond_the_floating_point_range_are_422s() {
    let request = json!({
        "body1": {"poisson_ratio": 0.0379, "elastic_modulus_pa": 4.17e12},
        "body2": {"poisson_ratio": -1.4e-45, "elastic_modulus_pa": 8.64e12, "radius_x_m": 2.035e151},
        "load_n": 2.067e-78, "line": {"length_m": 8.79e307}
    });
    match post(&request) {
        Err(Failure::Invalid(errors)) => {
            let at: Vec<&str> = errors.iter().map(|e| e.pointer.as_str()).collect();
            assert_eq!(at, ["/body2/radius_x_m"], "{errors:?}");
        }
        other => panic!("expected a 422, got {other:?}"),
    }
}
