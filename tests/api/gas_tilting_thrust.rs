//! The tilting-pad gas thrust bearing over HTTP: its example, the load and clearance requests
//! as each other's inverse, the 422s naming the field with the reason, and its range (a finite
//! balanced pad or a 422, never a 500).

use proptest::prelude::*;
use serde_json::{json, Value};
use stribeck::calc::{CalcError, Failure};

use crate::helpers::{
    assert_all_finite, example_patched, refused, refused_by_cost, spawn_app, under_server_deadline,
};

const PATH: &str = "/v1/gas-bearings/tilting-pad-thrust";

/// The registered example with `extra`'s fields set (null removes one).
fn body(extra: Value) -> Value {
    example_patched(PATH, &extra)
}

#[tokio::test]
async fn the_example_balances_and_the_clearance_gives_the_load_back() {
    let app = spawn_app().await;
    let reply = app
        .post_json(PATH, &body(json!({"fidelity": "fast"})))
        .await;
    assert_eq!(reply.status, 200, "{}", reply.text);
    assert_all_finite(&reply.body, "");
    let r = &reply.body["result"];
    assert_eq!(reply.body["solver"]["stop_reason"], "converged");
    assert!(reply.body["solver"]["residual"].as_f64().unwrap() < 1e-9);
    let load = r["load_n"].as_f64().unwrap();
    assert!((load / 2001.7 - 1.0).abs() < 1e-6, "{load}");
    // C_L = W/(n p_a r_o²).
    let cl = r["load_coefficient"].as_f64().unwrap();
    assert!((cl - 2001.7 / 6.0 / (103421.0 * 0.1016 * 0.1016)).abs() < 1e-6);
    let c = r["clearance_m"].as_f64().unwrap();
    assert!((r["crown_ratio"].as_f64().unwrap() - 1.0505e-5 / c).abs() < 1e-9);
    let h = r["min_film_m"].as_f64().unwrap();
    assert!(h > 0.0 && h < r["pivot_film_m"].as_f64().unwrap());
    // The runner's friction exceeds the pads' (the pressure term shifts it), and the power is
    // the runner's torque at ω.
    let (runner, pads) = (
        r["friction_torque_runner_n_m"].as_f64().unwrap(),
        r["friction_torque_pads_n_m"].as_f64().unwrap(),
    );
    assert!(runner > pads && pads > 0.0);
    let omega = 20000.0 * std::f64::consts::PI / 30.0;
    assert!((r["power_loss_w"].as_f64().unwrap() / (runner * omega) - 1.0).abs() < 1e-12);
    // The clearance asks for the same pad back.
    let reply = app
        .post_json(
            PATH,
            &body(json!({"fidelity": "fast", "load_n": null, "clearance_m": c})),
        )
        .await;
    assert_eq!(reply.status, 200, "{}", reply.text);
    let back = reply.body["result"]["load_n"].as_f64().unwrap();
    assert!((back / load - 1.0).abs() < 2e-2, "{back} vs {load}");
}

/// An explicit grid whose pad's film solves the server's deadline cannot pay for is refused
/// before any solve, a 422 naming the grid with the estimate (issue 16: the example on
/// [512, 128] ran into a 504); a grid finer than `high` within it answers.
#[test]
fn a_grid_beyond_the_deadline_is_refused_with_its_estimate() {
    refused_by_cost(
        under_server_deadline(PATH, &body(json!({"fidelity": {"grid": [512, 128]}}))),
        "would take about 118.6 s at least",
        "130305 unknowns with a band of 255",
    );
    let fine = body(json!({"load_n": null, "clearance_m": 2e-5, "fidelity": {"grid": [160, 32]}}));
    let v = under_server_deadline(PATH, &fine).unwrap_or_else(|e| panic!("{e:?}"));
    assert_eq!(v["solver"]["grid"], json!([160, 32]));
    assert!(v["result"]["load_n"].as_f64().unwrap() > 0.0);
}

#[tokio::test]
async fn bad_tilting_pad_input_is_a_422_with_its_reason() {
    let app = spawn_app().await;
    let rows = [
        (json!({"inner_radius_m": 0.2}), "/inner_radius_m", "r_i/r_o"),
        (json!({"pad_count": 9}), "/pad_angle_deg", "360°"),
        (
            json!({"pivot_radius_m": 0.04}),
            "/pivot_radius_m",
            "between",
        ),
        (
            json!({"pivot_angle_fraction": 0.99}),
            "/pivot_angle_fraction",
            "within",
        ),
        (json!({"clearance_m": 1e-5}), "/clearance_m", "not both"),
        (json!({"load_n": null}), "/load_n", "give"),
        (json!({"load_n": 1e7}), "/load_n", "at most"),
        (
            json!({"crown_m": 0, "pivot_angle_fraction": 0.7, "load_n": null, "clearance_m": 5e-6}),
            "/pivot_angle_fraction",
            "no equilibrium",
        ),
        (
            json!({"gas": {"viscosity_pa_s": 1.8e-5, "ambient_pressure_pa": -1.0}}),
            "/gas/ambient_pressure_pa",
            "> 0",
        ),
    ];
    refused(
        &app,
        PATH,
        rows.map(|(extra, p, why)| (body(extra), p, why)),
    )
    .await;
}

/// One request through the room, as the gas tests send them.
fn run(body: &Value) -> Result<Value, Failure> {
    crate::gas::run(PATH, body)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(8))]

    /// Over Λ from 1 to 1000 (by the clearance), crowns to twice the clearance and pivots from
    /// 0.55 to 0.75 of the angle: a finite pad, or a 422 on the pivot (no equilibrium) or the
    /// crown (the pad would touch); never a 500. A crowned pad (δ ≥ 0.2 C) carries less as its
    /// clearance opens (the same pad: its crown in metres unchanged). A nearly flat one need
    /// not: near the Λ beyond which it has no equilibrium its tilt and load fall to zero, so a
    /// lower Λ (a wider clearance) can carry more — crown 0.023 C, pivot 0.569, Λ 37.8 carries
    /// 33.1 N at C and 37.7 N at 1.05 C, rising smoothly from 0.98 C to 1.1 C (a grid of
    /// crowns 0–0.5 C, pivots 0.55–0.65 and Λ 3–300 found it only at crowns ≤ 0.05 C).
    #[test]
    fn tilting_pads_are_finite_and_carry_less_on_a_thicker_film(
        log_lambda in 0.0f64..3.0,
        crown in 0.0f64..2.0,
        pivot in 0.55f64..0.75,
    ) {
        let (ro, mu, pa, rpm): (f64, f64, f64, f64) = (0.1016, 2.2e-5, 103421.0, 20000.0);
        let omega = rpm * std::f64::consts::PI / 30.0;
        let c = ro * (6.0 * mu * omega / (pa * 10f64.powf(log_lambda))).sqrt();
        let crown_m = crown * c;
        let at = |c: f64| body(json!({
            "load_n": null,
            "clearance_m": c,
            "crown_m": crown_m,
            "pivot_angle_fraction": pivot,
            "fidelity": "fast",
            "effects": {"slip_flow": "off"}
        }));
        match (run(&at(c)), run(&at(1.05 * c))) {
            (Ok(thin), Ok(thick)) => {
                assert_all_finite(&thin, "");
                let w = |v: &Value| v["result"]["load_n"].as_f64().unwrap();
                prop_assert!(w(&thin) > 0.0);
                prop_assert!(w(&thick) > 0.0);
                if crown >= 0.2 {
                    prop_assert!(w(&thick) < w(&thin), "{} vs {}", w(&thick), w(&thin));
                }
            }
            (Err(Failure::Calc(CalcError::Impossible { pointer, .. })), _)
            | (_, Err(Failure::Calc(CalcError::Impossible { pointer, .. }))) => {
                prop_assert!(
                    pointer == "/pivot_angle_fraction" || pointer == "/crown_m",
                    "{pointer}"
                );
            }
            (Err(other), _) | (_, Err(other)) => prop_assert!(false, "{other:?}"),
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(8))]

    /// Loads from a light one to near what the pads carry, on crowned pads with pivots from 0.55
    /// to 0.7 of the angle: the clearance search lands on the load (every trial balanced from
    /// the last one's tilt, or from rest where that fails), or a 422 that names the pivot, the
    /// crown or the load; never a 500.
    #[test]
    fn tilting_pad_loads_are_carried_or_refused_with_the_reason(
        log_load in 1.0f64..3.5,
        crown in 0.0f64..2e-5,
        pivot in 0.55f64..0.7,
    ) {
        let load = 10f64.powf(log_load);
        let reply = run(&body(json!({
            "load_n": load,
            "crown_m": crown,
            "pivot_angle_fraction": pivot,
            "fidelity": "fast",
            "effects": {"slip_flow": "off"}
        })));
        match reply {
            Ok(v) => {
                assert_all_finite(&v, "");
                let carried = v["result"]["load_n"].as_f64().unwrap();
                prop_assert!((carried / load - 1.0).abs() < 1e-6, "{carried} vs {load}");
                prop_assert!(v["result"]["min_film_m"].as_f64().unwrap() > 0.0);
            }
            Err(Failure::Calc(CalcError::Impossible { pointer, .. })) => {
                prop_assert!(
                    ["/pivot_angle_fraction", "/crown_m", "/load_n"].contains(&pointer.as_str()),
                    "{pointer}"
                );
            }
            Err(other) => prop_assert!(false, "{other:?}"),
        }
    }
}

/// A flat pad pivoted at 0.6 has no equilibrium at the load search's usual start (Λ = 100: its
/// centre of pressure lies aft of the pivot there) but has one on a thicker film: a light load
/// is carried at Λ < 1, a heavy one refused on the pivot.
#[tokio::test]
async fn a_flat_pad_carries_a_light_load_on_a_thick_film() {
    let app = spawn_app().await;
    let flat = |load: f64| {
        body(
            json!({"crown_m": 0, "load_n": load, "fidelity": "fast", "effects": {"slip_flow": "off"}}),
        )
    };
    let reply = app.post_json(PATH, &flat(10.0)).await;
    assert_eq!(reply.status, 200, "{}", reply.text);
    let lambda = reply.body["result"]["bearing_number"].as_f64().unwrap();
    assert!(lambda < 1.0, "Λ {lambda}");
    let reply = app.post_json(PATH, &flat(3000.0)).await;
    reply.problem(422);
    assert!(
        reply.text.contains("/pivot_angle_fraction"),
        "{}",
        reply.text
    );
}
