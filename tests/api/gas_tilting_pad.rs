//! The tilting-pad gas journal over HTTP: its example, the 422s naming the field (preload
//! outside 0 < C′/C < 1, overlapping pads, a pivot off the pad, a pad that touches, a load beyond
//! reach), and its range (Λ 0.1–100, C′/C 0.1–0.9, ε′ 0.05–0.9): finite, positive pivot films,
//! the load rising with ε′.

use proptest::prelude::*;
use serde_json::{json, Value};
use stribeck::calc::Failure;

use crate::gas::run;
use crate::helpers::{
    assert_all_finite, example_patched, refused, refused_by_cost, spawn_app, under_server_deadline,
};

const PATH: &str = "/v1/gas-bearings/tilting-pad-journal";

fn example(extra: Value) -> Value {
    example_patched(PATH, &extra)
}

/// An explicit grid whose pads' film solves the server's deadline cannot pay for is refused
/// before any solve, a 422 naming the grid with the estimate (issue 16: the example on
/// [512, 128] ran into a 504); a grid finer than `high` within it answers.
#[test]
fn a_grid_beyond_the_deadline_is_refused_with_its_estimate() {
    refused_by_cost(
        under_server_deadline(PATH, &example(json!({"fidelity": {"grid": [512, 128]}}))),
        "would take about 54.7 s at least",
        "65408 unknowns with a band of 128",
    );
    let body = example(
        json!({"load_n": null, "eccentricity_ratio": 0.5, "fidelity": {"grid": [128, 32]}}),
    );
    let v = under_server_deadline(PATH, &body).unwrap_or_else(|e| panic!("{e:?}"));
    assert_eq!(v["solver"]["grid"], json!([128, 32]));
    assert!(v["result"]["load_n"].as_f64().unwrap() > 0.0);
}

#[tokio::test]
async fn the_tilting_pad_journal_answers_its_example_and_refuses_bad_pads_by_field() {
    let app = spawn_app().await;
    let reply = app.post_json(PATH, &example(json!({}))).await;
    assert_eq!(reply.status, 200, "{}", reply.text);
    assert_all_finite(&reply.body, "");
    assert_eq!(reply.body["solver"]["stop_reason"], "converged");
    assert!(reply.body["solver"]["error_estimate"].as_f64().unwrap() < 1e-2);
    let r = &reply.body["result"];
    assert_eq!(r["pads"].as_array().unwrap().len(), 3);
    assert!((r["load_n"].as_f64().unwrap() - 11.12).abs() < 1e-6);
    let rows = [
        (json!({"preload_factor": 1.0}), "/preload_factor", "(0, 1)"),
        (json!({"preload_factor": -0.2}), "/preload_factor", "(0, 1)"),
        (
            json!({"pads": {"arc_deg": 130}}),
            "/pads/arc_deg",
            "overlap",
        ),
        (
            json!({"pads": {"pivot_offset": 1.2}}),
            "/pads/pivot_offset",
            "on the pad",
        ),
        (
            json!({"load_n": null, "eccentricity_ratio": 1.0}),
            "/eccentricity_ratio",
            "touches",
        ),
        (json!({"eccentricity_ratio": 0.5}), "/load_n", "exactly one"),
        (json!({"load_n": 1e4}), "/load_n", "at most"),
        (
            json!({"fidelity": "closed_form"}),
            "/fidelity",
            "no closed form",
        ),
    ];
    refused(
        &app,
        PATH,
        rows.map(|(extra, p, why)| (example(extra), p, why)),
    )
    .await;
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(16))]

    /// Over Λ 0.1–100, C′/C 0.1–0.9 and ε′ 0.05–0.85: a converged, finite bearing whose pivot
    /// films are positive and whose load rises with ε′, or a 422; never a 500.
    #[test]
    fn tilting_pad_gas_journals_are_finite_and_their_load_rises_with_eccentricity(
        log_lambda in -1.0f64..2.0,
        preload in 0.1f64..0.9,
        e in 0.05f64..0.85,
    ) {
        let (d, c, mu, pa): (f64, f64, f64, f64) = (0.02, 1e-5, 1.85e-5, 101325.0);
        let omega = 10f64.powf(log_lambda) * pa / (6.0 * mu * (0.5 * d / c).powi(2));
        let body = |e: f64| json!({
            "geometry": {"diameter_m": d, "length_m": d, "radial_clearance_m": c},
            "preload_factor": preload,
            "speed_rpm": omega * 30.0 / std::f64::consts::PI,
            "gas": {"viscosity_pa_s": mu, "ambient_pressure_pa": pa},
            "eccentricity_ratio": e,
            "fidelity": "fast"
        });
        match (run(PATH, &body(e)), run(PATH, &body(e + 0.05))) {
            (Ok(lo), Ok(hi)) => {
                assert_all_finite(&lo, "");
                let w = |v: &Value| v["result"]["load_coefficient"].as_f64().unwrap();
                prop_assert!(w(&lo) > 0.0 && w(&hi) > w(&lo), "{} vs {}", w(&hi), w(&lo));
                for pad in lo["result"]["pads"].as_array().unwrap() {
                    prop_assert!(pad["pivot_film_m"].as_f64().unwrap() > 0.0);
                    prop_assert!(pad["min_film_m"].as_f64().unwrap() > 0.0);
                }
            }
            (Err(Failure::Calc(err)), _) | (_, Err(Failure::Calc(err))) => {
                prop_assert!(!matches!(err, stribeck::calc::CalcError::Internal(_)), "{err:?}");
            }
            (Err(other), _) | (_, Err(other)) => prop_assert!(false, "{other:?}"),
        }
    }
}
