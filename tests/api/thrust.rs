//! Thrust pads over their whole valid range: every answer is a finite result or a 422 with its
//! reason, never a 500; the load falls as the film thickens; a tilting pad's centre of pressure
//! sits on its pivot; the flows balance.

use proptest::prelude::*;
use serde_json::{json, Value};
use stribeck::calc::{find, CalcError, Failure};

use crate::helpers::spawn_app;

const FIXED: &str = "/v1/thrust-bearings/fixed-pad";
const TILTING: &str = "/v1/thrust-bearings/tilting-pad";
const BEARING: &str = "/v1/thrust-bearings/bearing";

fn run(path: &str, body: &Value) -> Result<Value, Failure> {
    let entry = find(path).expect("registered");
    let far = std::time::Instant::now() + std::time::Duration::from_secs(60);
    (entry.execute)(&serde_json::to_vec(body).unwrap(), far, Default::default())
        .map(|done| serde_json::from_slice(&done.body).expect("the envelope is JSON"))
}

fn number(v: &Value, pointer: &str) -> f64 {
    v.pointer(pointer)
        .and_then(Value::as_f64)
        .unwrap_or_else(|| panic!("{pointer} missing in {v}"))
}

/// Every number of a result is finite.
fn assert_finite(v: &Value) {
    match v {
        Value::Number(n) => assert!(n.as_f64().is_some_and(f64::is_finite), "{v}"),
        Value::Array(a) => a.iter().for_each(assert_finite),
        Value::Object(o) => o.values().for_each(assert_finite),
        _ => {}
    }
}

fn profile() -> impl Strategy<Value = Value> {
    prop_oneof![
        (1.01f64..10.0).prop_map(|r| json!({"kind": "plane_inclined", "film_ratio": r})),
        (1.01f64..10.0, 0.05f64..0.95).prop_map(
            |(r, s)| json!({"kind": "step", "film_ratio": r, "step_position_fraction": s})
        ),
        (1.01f64..10.0, 0.0f64..0.9).prop_map(
            |(r, f)| json!({"kind": "tapered_land", "film_ratio": r, "land_fraction": f})
        ),
        (1.01f64..10.0).prop_map(|r| json!({"kind": "parabolic", "film_ratio": r})),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// Over the whole range of shapes, aspect ratios (L/B 0.1–10), films and speeds: a finite
    /// result whose flows balance and whose centre of pressure lies on the pad, or a 422.
    #[test]
    fn fixed_pads_are_finite_and_conserve_mass(
        profile in profile(),
        breadth in 0.005f64..1.0,
        aspect in 0.1f64..10.0,
        speed in 1e-3f64..500.0,
        film in 1e-8f64..1e-2,
        fidelity in prop_oneof![Just(json!("closed_form")), Just(json!("fast")), Just(json!("standard"))],
        thermal in prop_oneof![Just("auto"), Just("off")],
    ) {
        let body = json!({
            "pad": {"breadth_m": breadth, "length_m": (breadth * aspect).min(10.0)},
            "profile": profile, "sliding_speed_m_s": speed, "lubricant": {"iso_vg": 68},
            "outlet_film_m": film, "fidelity": fidelity, "effects": {"thermal": thermal},
        });
        let got = run(FIXED, &body);
        match got {
            Ok(v) => {
                assert_finite(&v);
                let (q1, q2, qs) = (number(&v, "/result/inlet_flow_m3_s"), number(&v, "/result/outlet_flow_m3_s"), number(&v, "/result/side_flow_m3_s"));
                prop_assert!((q1 - q2 - qs).abs() <= 1e-9 * q1, "{q1} {q2} {qs}");
                let x = number(&v, "/result/center_of_pressure_fraction");
                prop_assert!(x > 0.0 && x < 1.0);
                prop_assert!(number(&v, "/result/load_n") > 0.0);
                prop_assert!(number(&v, "/result/friction_force_n") > 0.0);
            }
            Err(Failure::Calc(CalcError::Internal(cause))) => panic!("internal error: {cause}"),
            Err(_) => {}
        }
    }

    /// A tilting pad's moment about its pivot vanishes: the centre of pressure is the pivot.
    #[test]
    fn tilting_pads_balance_their_moment(
        pivot in 0.52f64..0.68,
        aspect in 0.25f64..4.0,
        load in 1.0f64..1e5,
    ) {
        let body = json!({
            "pad": {"breadth_m": 0.05, "length_m": 0.05 * aspect}, "pivot_position_fraction": pivot,
            "sliding_speed_m_s": 20, "lubricant": {"iso_vg": 32}, "load_n": load, "fidelity": "fast",
        });
        let v = match run(TILTING, &body) {
            Ok(v) => v,
            // A small pad under a heavy load may heat beyond any oil.
            Err(Failure::Calc(CalcError::Impossible { message, .. })) if message.contains("thermal runaway") => return Ok(()),
            Err(other) => panic!("{other:?}"),
        };
        assert_finite(&v);
        prop_assert!((number(&v, "/result/center_of_pressure_fraction") - pivot).abs() < 1e-8);
        prop_assert!((number(&v, "/result/load_n") / load - 1.0).abs() < 1e-9);
        prop_assert!(number(&v, "/result/film_ratio_per_pivot_fraction") > 0.0);
    }
}

#[test]
fn the_load_falls_as_the_film_thickens_over_six_decades() {
    // Over 1e-8 … 1e-2 m, isothermal and with the thermal effect on a temperature-dependent
    // oil; the thinnest films heat beyond any oil (a 422 that says so), the rest answer. The
    // pad is twice as long as broad: outside Jang & Khonsari's fits, T_eff = T_in + ΔT.
    for thermal in ["off", "on"] {
        let mut last = f64::INFINITY;
        let mut refused = 0;
        for i in 0..=24 {
            let film = 1e-8 * 10f64.powf(i as f64 / 4.0);
            let body = json!({
                "pad": {"breadth_m": 0.1, "length_m": 0.2},
                "profile": {"kind": "plane_inclined", "film_ratio": 2}, "sliding_speed_m_s": 20,
                "lubricant": {"iso_vg": 46}, "outlet_film_m": film, "effects": {"thermal": thermal},
            });
            let v = match run(FIXED, &body) {
                Ok(v) => v,
                Err(Failure::Calc(CalcError::Impossible { message, .. }))
                    if thermal == "on" && last.is_infinite() =>
                {
                    assert!(message.contains("thermal runaway"), "{message}");
                    refused += 1;
                    continue;
                }
                other => panic!("{thermal} at h2 = {film}: {other:?}"),
            };
            let load = number(&v, "/result/load_n");
            assert!(load < last, "{thermal} at h2 = {film}: {load} after {last}");
            let t = number(&v, "/result/effective_temperature_c");
            let rise = number(&v, "/result/temperature_rise_k");
            if thermal == "on" {
                assert!(
                    (t - 40.0 - rise).abs() < 1e-6 * (1.0 + rise),
                    "T_eff = T_in + ΔT"
                );
            }
            last = load;
        }
        assert!(refused <= 12, "{refused} films refused");
    }
}

#[tokio::test]
async fn the_examples_answer_over_http() {
    let app = spawn_app().await;
    for path in [FIXED, TILTING] {
        let example: Value = serde_json::from_str(find(path).unwrap().example).unwrap();
        let r = app.post_json(path, &example).await;
        assert_eq!(r.status, 200, "{path}: {}", r.text);
        assert!((number(&r.body, "/result/load_n") / 16000.0 - 1.0).abs() < 1e-12);
        assert!(r.body["solver"]["film_solves"].as_u64().unwrap() >= 2);
    }
    let example: Value = serde_json::from_str(find(BEARING).unwrap().example).unwrap();
    let r = app.post_json(BEARING, &example).await;
    assert_eq!(r.status, 200, "{}", r.text);
    let per_pad = number(&r.body, "/result/load_per_pad_n");
    assert!((7.0 * per_pad / 111_200.0 - 1.0).abs() < 1e-12);
    assert!((number(&r.body, "/result/pad/load_n") / per_pad - 1.0).abs() < 1e-12);
    let power = number(&r.body, "/result/power_loss_w");
    assert!((power / (7.0 * number(&r.body, "/result/pad/power_loss_w")) - 1.0).abs() < 1e-12);
    assert_eq!(r.body["result"]["checks"].as_array().unwrap().len(), 4);
    assert_eq!(r.body["result"]["checks_passed"], true);
}

#[test]
fn bearing_requests_name_the_field() {
    let base = json!({
        "inner_radius_m": 0.073, "outer_radius_m": 0.16, "pad_count": 7,
        "pads": {"kind": "tilting", "pivot_position_fraction": 0.6}, "speed_rpm": 3600,
        "load_n": 111200, "lubricant": {"iso_vg": 32},
    });
    let with = |pointer: &str, value: Value| {
        let mut b = base.clone();
        let (parent, key) = pointer.rsplit_once('/').unwrap();
        b.pointer_mut(parent).unwrap()[key] = value;
        b
    };
    for (body, pointer) in [
        (with("/inner_radius_m", json!(0.2)), "/inner_radius_m"),
        (with("/pad_angle_deg", json!(60)), "/pad_angle_deg"),
        (with("/pad_angle_deg", json!(1)), "/pad_angle_deg"),
        (
            with(
                "/pads/profile",
                json!({"kind": "parabolic", "film_ratio": 2}),
            ),
            "/pads/profile",
        ),
        (with("/pads", json!({"kind": "fixed"})), "/pads/profile"),
        (
            with(
                "/pads",
                json!({"kind": "fixed", "profile": {"kind": "step", "film_ratio": 2}}),
            ),
            "/pads/profile/step_position_fraction",
        ),
        (
            with("/surface_roughness_ra_m", json!([1e-3, 0])),
            "/surface_roughness_ra_m",
        ),
    ] {
        match run(BEARING, &body) {
            Err(Failure::Invalid(errors)) => assert!(
                errors.iter().any(|e| e.pointer == pointer),
                "{pointer}: {errors:?}"
            ),
            other => panic!("{pointer}: {other:?}"),
        }
    }
    match run(BEARING, &with("/pads/pivot_position_fraction", json!(0.5))) {
        Err(Failure::Calc(CalcError::Impossible { pointer, .. })) => {
            assert_eq!(pointer, "/pads/pivot_position_fraction")
        }
        other => panic!("{other:?}"),
    }
    // An overloaded bearing answers with its failed checks, not an error.
    let v = run(BEARING, &with("/load_n", json!(2e6))).unwrap();
    assert_eq!(v["result"]["checks_passed"], false);
}

#[test]
fn bad_requests_name_the_field() {
    let base = json!({
        "pad": {"breadth_m": 0.1, "length_m": 0.1},
        "profile": {"kind": "step", "film_ratio": 2, "step_position_fraction": 0.6},
        "sliding_speed_m_s": 10, "lubricant": {"iso_vg": 32}, "load_n": 1000,
    });
    let with = |pointer: &str, value: Value| {
        let mut b = base.clone();
        let (parent, key) = pointer.rsplit_once('/').unwrap();
        b.pointer_mut(parent).unwrap()[key] = value;
        b
    };
    let cases = [
        (with("/outlet_film_m", json!(1e-5)), "/load_n"),
        (
            with("/profile/film_ratio", json!(12)),
            "/profile/film_ratio",
        ),
        (
            with("/profile/film_ratio", json!("best")),
            "/profile/film_ratio",
        ),
        (
            with("/profile/land_fraction", json!(0.2)),
            "/profile/land_fraction",
        ),
        (
            with("/profile/step_position_fraction", json!(0.99)),
            "/profile/step_position_fraction",
        ),
        (with("/pad/length_m", json!(5.0)), "/pad/length_m"),
        (
            with("/fidelity", json!({"tolerance": 1e-8})),
            "/fidelity/tolerance",
        ),
        (with("/fidelity", json!({"grid": [4, 4]})), "/fidelity/grid"),
        (with("/profile/depth_m", json!(1e-5)), "/profile/film_ratio"),
    ];
    for (body, pointer) in cases {
        match run(FIXED, &body) {
            Err(Failure::Invalid(errors)) => assert!(
                errors.iter().any(|e| e.pointer == pointer),
                "{pointer}: {errors:?}"
            ),
            other => panic!("{pointer}: {other:?}"),
        }
    }
    // A machined depth: with the film given the ratio is 1 + depth/h2; a depth too shallow for
    // the load is refused on the depth.
    let mut depth = base.clone();
    depth["profile"] = json!({"kind": "plane_inclined", "depth_m": 2e-5});
    depth.as_object_mut().unwrap().remove("load_n");
    depth["outlet_film_m"] = json!(1e-5);
    let v = run(FIXED, &depth).unwrap();
    assert!((number(&v, "/result/film_ratio") - 3.0).abs() < 1e-12);
    depth.as_object_mut().unwrap().remove("outlet_film_m");
    depth["load_n"] = json!(1e-3);
    match run(FIXED, &depth) {
        Err(Failure::Calc(CalcError::Impossible { pointer, message })) => {
            assert_eq!(pointer, "/profile/depth_m");
            assert!(message.contains("too shallow"), "{message}");
        }
        other => panic!("{other:?}"),
    }
    let central = json!({
        "pad": {"breadth_m": 0.1, "length_m": 0.1}, "pivot_position_fraction": 0.5,
        "sliding_speed_m_s": 10, "lubricant": {"iso_vg": 32}, "load_n": 1000,
    });
    match run(TILTING, &central) {
        Err(Failure::Calc(CalcError::Impossible { pointer, message })) => {
            assert_eq!(pointer, "/pivot_position_fraction");
            assert!(message.contains("no useful load"), "{message}");
        }
        other => panic!("{other:?}"),
    }
}

/// The turbulent pad film (Ng–Pan, Khonsari & Booser Eq. 6.26–6.31 and §7.11): `auto` applies
/// it above a pad-average Reynolds number of 580 and reports why, with the number and the
/// trailing-edge Re₂ it was solved at; `off` is the laminar pad bit for bit (its dimensionless
/// numbers are those of the same pad at a creeping speed); at the same film the turbulent pad
/// carries more load and loses more power; as Re → 0 `on` tends to the laminar pad.
#[test]
fn turbulent_pad_film_is_decided_reported_and_tends_to_laminar() {
    let pad = |mode: &str, speed: f64, viscosity: f64| {
        json!({
            "pad": {"breadth_m": 0.3, "length_m": 0.3},
            "profile": {"kind": "plane_inclined", "film_ratio": 2}, "sliding_speed_m_s": speed,
            "lubricant": {"viscosity_pa_s": viscosity, "density_15c_kg_m3": 870.0},
            "outlet_film_m": 1e-4, "effects": {"turbulence": mode, "thermal": "off"},
        })
    };
    let turbulent = run(FIXED, &pad("auto", 80.0, 0.005)).unwrap();
    let laminar = run(FIXED, &pad("off", 80.0, 0.005)).unwrap();
    let d = &turbulent["effects"]["turbulence"];
    assert_eq!(d["applied"], true, "{d}");
    assert_eq!(d["model"], "ng_pan", "{d}");
    let criterion = number(d, "/criterion/value");
    assert!(criterion > 580.0, "{d}");
    assert_eq!(criterion, number(&turbulent, "/result/reynolds_number"));
    // ρ U h2/μ with ρ at 40 °C a little under its 15 °C value: about 1.4e3.
    let re2 = number(&turbulent, "/result/outlet_reynolds_number");
    assert!((1.3e3..1.4e3).contains(&re2), "Re₂ {re2}");
    let reason = d["reason"].as_str().unwrap();
    assert!(reason.contains(&format!("{re2:.4e}")), "{reason}");
    assert!(reason.contains(&format!("{criterion:.4e}")), "{reason}");
    let off = &laminar["effects"]["turbulence"];
    assert_eq!(off["applied"], false, "{off}");
    assert_eq!(number(off, "/criterion/value"), criterion);
    let (t, l) = (&turbulent["result"], &laminar["result"]);
    assert!(number(t, "/load_n") > 1.2 * number(l, "/load_n"));
    assert!(number(t, "/power_loss_w") > 1.5 * number(l, "/power_loss_w"));
    // Off: the laminar pad, bit for bit (W̄ and K_f do not depend on speed when laminar).
    let creeping = run(FIXED, &pad("auto", 1e-3, 0.005)).unwrap();
    assert_eq!(creeping["effects"]["turbulence"]["applied"], false);
    assert_eq!(l["coefficients"], creeping["result"]["coefficients"]);
    // Re ≈ 0.02: the Ng–Pan factors are 1 to 1e-4.
    let on = run(FIXED, &pad("on", 1.0, 5.0)).unwrap();
    assert_eq!(on["effects"]["turbulence"]["applied"], true);
    for field in ["load", "k_f", "k_q"] {
        let (a, b) = (
            number(&on, &format!("/result/coefficients/{field}")),
            number(&creeping, &format!("/result/coefficients/{field}")),
        );
        assert!((a / b - 1.0).abs() < 1e-4, "{field}: {a} vs {b}");
    }
}

/// At a fixed film, the turbulent pad's W̄ rises monotonically with the speed's Reynolds
/// number (the laminar W̄ would not change), and a tilting pad in a turbulent film still
/// balances its load and its moment about the pivot.
#[test]
fn turbulent_load_rises_with_reynolds_number_and_tilting_pads_balance() {
    let mut last = 0.0;
    for speed in [1.0, 10.0, 30.0, 60.0, 100.0, 200.0] {
        let body = json!({
            "pad": {"breadth_m": 0.3, "length_m": 0.3},
            "profile": {"kind": "plane_inclined", "film_ratio": 2}, "sliding_speed_m_s": speed,
            "lubricant": {"viscosity_pa_s": 0.005, "density_15c_kg_m3": 870.0},
            "outlet_film_m": 1e-4, "effects": {"turbulence": "on", "thermal": "off"},
        });
        let v = run(FIXED, &body).unwrap();
        let load = number(&v, "/result/coefficients/load");
        assert!(load > last, "W̄ {load} at {speed} m/s after {last}");
        last = load;
    }
    for pivot in [0.55, 0.6, 0.65] {
        let body = json!({
            "pad": {"breadth_m": 0.3, "length_m": 0.3}, "pivot_position_fraction": pivot,
            "sliding_speed_m_s": 80, "lubricant": {"iso_vg": 32}, "inlet_temperature_c": 50,
            "load_n": 300000, "effects": {"turbulence": "on"}, "fidelity": "fast",
        });
        let v = run(TILTING, &body).unwrap();
        assert_eq!(v["effects"]["turbulence"]["applied"], true);
        assert!((number(&v, "/result/center_of_pressure_fraction") - pivot).abs() < 1e-8);
        assert!((number(&v, "/result/load_n") / 3e5 - 1.0).abs() < 1e-9);
    }
}

/// A crowned tilting pad (Khonsari & Booser §7.5): pivoted at mid-pad it carries its load (the
/// flat pad's 422 stays without a crown), its centre of pressure on the pivot; as the crown
/// vanishes an offset pivot's answer tends to the flat pad's; the crown's bad inputs name it.
#[test]
fn a_crowned_pad_carries_load_on_a_central_pivot_and_tends_to_the_flat_pad() {
    let pad = |pivot: f64, crown: Option<f64>, fidelity: &str| {
        let mut body = json!({
            "pad": {"breadth_m": 0.089, "length_m": 0.087}, "pivot_position_fraction": pivot,
            "sliding_speed_m_s": 44, "lubricant": {"iso_vg": 32}, "inlet_temperature_c": 49,
            "load_n": 16000, "fidelity": fidelity,
        });
        if let Some(crown) = crown {
            body["crown_m"] = json!(crown);
        }
        body
    };
    match run(TILTING, &pad(0.5, None, "fast")) {
        Err(Failure::Calc(CalcError::Impossible { pointer, message })) => {
            assert_eq!(pointer, "/pivot_position_fraction");
            assert!(message.contains("carries no useful load"), "{message}");
        }
        other => panic!("{other:?}"),
    }
    for crown in [1e-5, 2e-5, 4e-5] {
        let v = run(TILTING, &pad(0.5, Some(crown), "fast")).unwrap();
        assert_finite(&v);
        assert!((number(&v, "/result/center_of_pressure_fraction") - 0.5).abs() < 1e-8);
        assert!((number(&v, "/result/load_n") / 16000.0 - 1.0).abs() < 1e-9);
        let (h2, h_min) = (
            number(&v, "/result/outlet_film_m"),
            number(&v, "/result/minimum_film_m"),
        );
        assert!(h_min <= h2 && h_min > 0.5 * h2, "h_min {h_min}, h2 {h2}");
        assert!(number(&v, "/result/film_ratio") > 1.0);
    }
    // Crown → 0 at a pivot of 0.6: the flat pad's equilibrium (isothermal: a crowned pad is not
    // plane, so its effective temperature is T_in + ΔT rather than Jang & Khonsari's fit).
    let isothermal = |mut body: Value| {
        body["effects"] = json!({"thermal": "off"});
        body
    };
    let flat = run(TILTING, &isothermal(pad(0.6, None, "fast"))).unwrap();
    let crowned = run(TILTING, &isothermal(pad(0.6, Some(1e-10), "fast"))).unwrap();
    for field in [
        "/result/film_ratio",
        "/result/outlet_film_m",
        "/result/power_loss_w",
    ] {
        let (a, b) = (number(&crowned, field), number(&flat, field));
        assert!((a / b - 1.0).abs() < 1e-4, "{field}: {a} vs {b}");
    }
    for (body, pointer) in [
        (pad(0.5, Some(2e-3), "fast"), "/crown_m"),
        (pad(0.5, Some(2e-5), "closed_form"), "/fidelity"),
    ] {
        match run(TILTING, &body) {
            Err(Failure::Invalid(errors)) => assert!(
                errors.iter().any(|e| e.pointer == pointer),
                "{pointer}: {errors:?}"
            ),
            other => panic!("{pointer}: {other:?}"),
        }
    }
}

/// A crowned fixed pad (the tilting pad's crown, Khonsari & Booser §7.5, on a fixed plane pad):
/// as the crown vanishes it is the flat pad, from its film to 1e-12 and from its load to 1e-9;
/// with parallel edges (film ratio 1, which a flat pad may not have: it would carry nothing) it
/// carries its load on the crown, the thinnest film at mid-pad; the crown's bad inputs name it.
#[test]
fn a_crowned_fixed_pad_tends_to_the_flat_pad_and_carries_load_with_parallel_edges() {
    let pad = |ratio: f64, crown: Option<f64>, given: Value| {
        let mut body = json!({
            "pad": {"breadth_m": 0.089, "length_m": 0.087},
            "profile": {"kind": "plane_inclined", "film_ratio": ratio},
            "sliding_speed_m_s": 44, "lubricant": {"iso_vg": 32}, "inlet_temperature_c": 49,
            "fidelity": "fast", "effects": {"thermal": "off"},
        });
        for (k, v) in given.as_object().unwrap() {
            body[k] = v.clone();
        }
        if let Some(crown) = crown {
            body["crown_m"] = json!(crown);
        }
        body
    };
    let fields = [
        "/result/load_n",
        "/result/outlet_film_m",
        "/result/friction_force_n",
        "/result/center_of_pressure_fraction",
        "/result/max_pressure_pa",
        "/result/inlet_flow_m3_s",
        "/result/side_flow_m3_s",
        "/result/temperature_rise_k",
    ];
    for (given, crown, tolerance) in [
        (json!({"outlet_film_m": 3e-5}), 1e-18, 1e-12),
        (json!({"load_n": 16000}), 1e-16, 1e-9),
    ] {
        let flat = run(FIXED, &pad(2.0, None, given.clone())).unwrap();
        let crowned = run(FIXED, &pad(2.0, Some(crown), given.clone())).unwrap();
        for field in fields {
            let (a, b) = (number(&crowned, field), number(&flat, field));
            assert!(
                (a / b - 1.0).abs() < tolerance,
                "{given}: {field}: {a} vs {b}"
            );
        }
    }
    // Parallel edges: refused flat (outside the film ratios a flat pad may have), carried crowned.
    match run(FIXED, &pad(1.0, None, json!({"outlet_film_m": 2e-5}))) {
        Err(Failure::Invalid(errors)) => {
            assert!(errors.iter().any(|e| e.pointer == "/profile/film_ratio"))
        }
        other => panic!("{other:?}"),
    }
    let mut last = 0.0;
    for crown in [2e-6, 5e-6, 1e-5] {
        let v = run(
            FIXED,
            &pad(1.0, Some(crown), json!({"outlet_film_m": 2e-5})),
        )
        .unwrap();
        assert_finite(&v);
        let load = number(&v, "/result/load_n");
        assert!(load > last, "crown {crown}: {load} after {last}");
        last = load;
        // The film converges to mid-pad and cavitates behind it: the pressure's centre is ahead.
        assert!(number(&v, "/result/center_of_pressure_fraction") < 0.5);
    }
    let v = run(FIXED, &pad(1.0, Some(1e-5), json!({"load_n": 5000}))).unwrap();
    assert!((number(&v, "/result/load_n") / 5000.0 - 1.0).abs() < 1e-9);
    let h2 = number(&v, "/result/outlet_film_m");
    assert!(h2 > 1e-5, "h2 {h2}: the crown stays below the film here");
    for (body, pointer, invalid) in [
        (
            pad(2.0, Some(2e-3), json!({"load_n": 5000})),
            "/crown_m",
            true,
        ),
        (
            {
                let mut b = pad(2.0, Some(1e-5), json!({"load_n": 5000}));
                b["fidelity"] = json!("closed_form");
                b
            },
            "/fidelity",
            true,
        ),
        (
            {
                let mut b = pad(2.0, Some(1e-5), json!({"load_n": 5000}));
                b["profile"] =
                    json!({"kind": "step", "film_ratio": 2, "step_position_fraction": 0.7});
                b
            },
            "/profile/kind",
            true,
        ),
        (
            {
                let mut b = pad(2.0, Some(1e-5), json!({"load_n": 5000}));
                b["profile"]["film_ratio"] = json!("optimum");
                b
            },
            "/profile/film_ratio",
            true,
        ),
        // A film as thin as the crown's touch point: the crown would touch the runner.
        (
            pad(1.0, Some(1e-5), json!({"outlet_film_m": 1e-5})),
            "/crown_m",
            false,
        ),
        (
            pad(1.0, Some(1e-4), json!({"load_n": 1e8})),
            "/crown_m",
            false,
        ),
    ] {
        match run(FIXED, &body) {
            Err(Failure::Invalid(errors)) if invalid => assert!(
                errors.iter().any(|e| e.pointer == pointer),
                "{pointer}: {errors:?}"
            ),
            Err(Failure::Calc(CalcError::Impossible {
                pointer: p,
                message,
            })) if !invalid => {
                assert_eq!(p, pointer, "{message}");
                assert!(message.contains("touches the runner"), "{message}");
            }
            other => panic!("{pointer}: {other:?}"),
        }
    }
}

/// A whole bearing of crowned pads: centrally pivoted tilting pads carry the load their flat
/// twins refuse, and crowned fixed pads with parallel edges carry theirs; the minimum-film check
/// reads the thinnest film, inside the pad, and a pad's crown refusal points at the bearing's
/// field.
#[test]
fn a_bearing_of_crowned_pads_carries_its_load() {
    let bearing = |pads: Value| {
        json!({
            "inner_radius_m": 0.073, "outer_radius_m": 0.16, "pad_count": 7,
            "pad_angle_deg": 43.7, "pads": pads, "speed_rpm": 3600, "load_n": 111200,
            "lubricant": {"iso_vg": 32}, "inlet_temperature_c": 49, "fidelity": "fast",
        })
    };
    let tilting = json!({"kind": "tilting", "pivot_position_fraction": 0.5});
    match run(BEARING, &bearing(tilting.clone())) {
        Err(Failure::Calc(CalcError::Impossible { pointer, .. })) => {
            assert_eq!(pointer, "/pads/pivot_position_fraction")
        }
        other => panic!("{other:?}"),
    }
    let mut crowned_tilting = tilting;
    crowned_tilting["crown_m"] = json!(2e-5);
    let fixed = json!({"kind": "fixed", "profile": {"kind": "plane_inclined", "film_ratio": 1},
                       "crown_m": 2e-5});
    for pads in [crowned_tilting, fixed] {
        let v = run(BEARING, &bearing(pads.clone())).unwrap();
        assert_finite(&v);
        assert!((number(&v, "/result/load_per_pad_n") * 7.0 / 111200.0 - 1.0).abs() < 1e-9);
        let (h_min, h2) = (
            number(&v, "/result/min_film_m"),
            number(&v, "/result/pad/outlet_film_m"),
        );
        assert!(h_min < h2 && h_min > 0.0, "{pads}: h_min {h_min}, h2 {h2}");
        assert_eq!(number(&v, "/result/checks/0/value"), h_min);
    }
    let heavy = json!({"kind": "fixed", "profile": {"kind": "plane_inclined", "film_ratio": 1},
                       "crown_m": 1e-3});
    let mut body = bearing(heavy);
    body["load_n"] = json!(1e10);
    match run(BEARING, &body) {
        Err(Failure::Calc(CalcError::Impossible { pointer, .. })) => {
            assert_eq!(pointer, "/pads/crown_m")
        }
        other => panic!("{other:?}"),
    }
}

/// The crowned central pivot over the texts' range of crowns, δ/h_min from 0.5 to 2 (Khonsari &
/// Booser §7.5), and on to the fold where its equilibrium branch ends: above δ/h2 ≈ 1 a second,
/// pinched equilibrium appears near the film ratio at which the crown touches and meets the
/// main one at a fold; the pad follows the main branch (the film ratio rises as the pivot moves
/// back) and refuses a crown past the fold, naming it.
#[test]
fn a_crowned_central_pivot_spans_the_texts_crown_range_up_to_its_fold() {
    let pad = |crown: f64| {
        json!({
            "pad": {"breadth_m": 0.089, "length_m": 0.087}, "pivot_position_fraction": 0.5,
            "sliding_speed_m_s": 44, "lubricant": {"iso_vg": 32}, "inlet_temperature_c": 49,
            "load_n": 16000, "crown_m": crown, "fidelity": "fast",
            "effects": {"thermal": "off"},
        })
    };
    let mut spans: Vec<f64> = Vec::new();
    for crown in [5e-6, 1e-5, 2e-5, 4e-5, 6e-5, 8e-5, 1e-4, 1.2e-4, 1.4e-4] {
        let v = run(TILTING, &pad(crown)).unwrap();
        assert_finite(&v);
        assert!((number(&v, "/result/center_of_pressure_fraction") - 0.5).abs() < 1e-8);
        assert!((number(&v, "/result/load_n") / 16000.0 - 1.0).abs() < 1e-9);
        // The main branch: the film ratio rises as the pivot moves back.
        assert!(
            number(&v, "/result/film_ratio_per_pivot_fraction") > 0.0,
            "crown {crown}"
        );
        let over_min = crown / number(&v, "/result/minimum_film_m");
        assert!(
            spans.last().is_none_or(|&last| over_min > last),
            "crown {crown}: {over_min} after {spans:?}"
        );
        spans.push(over_min);
    }
    // Measured: δ/h_min from 0.108 to 3.56 (δ/h2 from 0.108 to 1.52).
    assert!(spans[0] < 0.5 && spans[spans.len() - 1] > 2.0, "{spans:?}");
    // Past the fold (near δ/h2 = 1.62, δ/h_min = 7.0 on the fast mesh): refused, naming it.
    match run(TILTING, &pad(5e-4)) {
        Err(Failure::Calc(CalcError::Impossible { pointer, message })) => {
            assert_eq!(pointer, "/crown_m");
            assert!(message.contains("fold near δ/h2 = 1.6"), "{message}");
        }
        other => panic!("{other:?}"),
    }
}

/// The texts' empirical turbulent pad (Khonsari & Booser §7.11, `turbulence_model: missana`):
/// the power loss is f (ρ U²/2) U B L (Eq. 7.17) with f = 0.026/Re^0.25 (Eq. 7.20) at the
/// laminar pad-average Re, checked against the formula; the film is the laminar pad's at the
/// viscosity multiplied by that loss over the laminar one (under a load, h2 grows by its square
/// root); the effect says which law and the Re.
#[test]
fn the_empirical_turbulent_friction_of_section_7_11_matches_its_formula() {
    let pad = |mode: &str, model: &str| {
        json!({
            "pad": {"breadth_m": 0.3, "length_m": 0.3},
            "profile": {"kind": "plane_inclined", "film_ratio": 2}, "sliding_speed_m_s": 80.0,
            "lubricant": {"viscosity_pa_s": 0.005, "density_15c_kg_m3": 870.0},
            "load_n": 3e4, "effects": {"turbulence": mode, "thermal": "off"},
            "turbulence_model": model,
        })
    };
    let laminar = run(FIXED, &pad("off", "missana")).unwrap();
    let empirical = run(FIXED, &pad("auto", "missana")).unwrap();
    let ng_pan = run(FIXED, &pad("auto", "ng_pan")).unwrap();
    let d = &empirical["effects"]["turbulence"];
    assert_eq!(d["applied"], true, "{d}");
    assert_eq!(d["model"], "missana", "{d}");
    let re = number(&laminar, "/result/reynolds_number");
    assert!(re > 580.0, "Re {re}");
    assert_eq!(number(d, "/criterion/value"), re);
    assert!(
        d["reason"].as_str().unwrap().contains(&format!("{re:.4e}")),
        "{d}"
    );
    // ρ at the 40 °C inlet (Eq. 2.19), U = 80 m/s, B L = 0.09 m².
    let rho = 870.0 * (1.0 - 0.00063 * (40.0 - 15.0));
    let want = 0.026 / re.powf(0.25) * 0.5 * rho * 80f64.powi(3) * 0.09;
    let power = number(&empirical, "/result/power_loss_w");
    assert!((power / want - 1.0).abs() < 1e-12, "{power} vs {want}");
    assert!((number(&empirical, "/result/friction_force_n") * 80.0 / power - 1.0).abs() < 1e-12);
    let factor = want / number(&laminar, "/result/power_loss_w");
    assert!(factor > 1.0, "the turbulent loss is the larger: × {factor}");
    let (h_t, h_l) = (
        number(&empirical, "/result/outlet_film_m"),
        number(&laminar, "/result/outlet_film_m"),
    );
    assert!(
        (h_t / (h_l * factor.sqrt()) - 1.0).abs() < 1e-9,
        "{h_t} vs {h_l} × √{factor}"
    );
    assert!(
        (number(&empirical, "/result/effective_viscosity_pa_s") / (0.005 * factor) - 1.0).abs()
            < 1e-12
    );
    // The two laws on the same pad: both above the laminar loss (measured ratios in the report).
    let ng = number(&ng_pan, "/result/power_loss_w");
    // Measured (Re 3245): laminar 13.3 kW, Ng–Pan 36.9 kW, Missana 68.0 kW (its 0.026 carries
    // parasitic losses, §7.11); h2 158, 266 and 357 µm.
    assert!(ng > number(&laminar, "/result/power_loss_w"));
}

/// The bearing reports how far the texts' mapping of its sector pads to the rectangle at the
/// mean radius lies from the sector solved in polar coordinates: Ex 7.2's pads (L/R_m = 0.75)
/// carry about half a percent less as sectors; the infinitely long pad reports nothing.
#[test]
fn the_bearing_reports_its_sector_mapping_deviation() {
    let bearing = |fidelity: &str| {
        json!({
            "inner_radius_m": 0.073, "outer_radius_m": 0.16, "pad_count": 7,
            "pad_angle_deg": 43.7, "pads": {"kind": "tilting", "pivot_position_fraction": 0.6},
            "speed_rpm": 3600, "load_n": 111200, "lubricant": {"iso_vg": 32},
            "inlet_temperature_c": 49, "fidelity": fidelity,
        })
    };
    for fidelity in ["fast", "standard"] {
        let v = run(BEARING, &bearing(fidelity)).unwrap();
        let d = number(&v, "/result/sector_load_deviation");
        assert!((-0.01..-0.002).contains(&d), "{fidelity}: {d}");
    }
    let v = run(BEARING, &bearing("closed_form")).unwrap();
    assert!(v["result"].get("sector_load_deviation").is_none());
}

/// Ex 7.4's flat-land motor bearing as a whole bearing (6 lands between 1.75 and 3.00 in,
/// 150 lbf, 1800 rpm): the unit load (about 37 psi) is checked against Table 7.1's range for
/// flat lands, 20–100 psi, not the tapered land's 150–400.
#[test]
fn a_flat_land_bearing_is_checked_against_the_flat_lands_unit_load() {
    let request = json!({
        "inner_radius_m": 0.022225, "outer_radius_m": 0.0381, "pad_count": 6,
        "pads": {"kind": "fixed", "profile": {"kind": "flat_land"}}, "speed_rpm": 1800,
        "load_n": 667.2, "lubricant": {"viscosity_pa_s": 0.00896}, "inlet_temperature_c": 40,
    });
    let v = run(BEARING, &request).unwrap();
    let checks = v["result"]["checks"].as_array().unwrap();
    let unit = checks.iter().find(|c| c["name"] == "unit_load").unwrap();
    let psi = unit["value"].as_f64().unwrap() / 6894.757;
    assert!((20.0..=100.0).contains(&psi), "{psi} psi");
    assert_eq!(unit["passed"], json!(true), "{unit}");
    assert!(
        unit["rule"].as_str().unwrap().contains("flat land"),
        "{unit}"
    );
}
