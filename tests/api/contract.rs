//! The contract every calculation keeps: the envelope on success, problem+json with the right
//! status on every failure, unknown fields rejected, request ids on every response.

use serde_json::json;

use crate::helpers::{assert_all_finite, spawn_app, spawn_with, test_config};

const PATH: &str = "/v1/lubricants/viscosity";

fn good_request() -> serde_json::Value {
    json!({"lubricant": {"viscosity_pa_s": 0.03}, "temperatures_c": [40.0]})
}

#[tokio::test]
async fn a_result_comes_in_its_envelope() {
    let app = spawn_app().await;
    let r = app.post_json(PATH, &good_request()).await;
    assert_eq!(r.status, 200, "{}", r.text);
    assert_eq!(r.content_type, "application/json");
    for key in ["result", "effects", "solver", "warnings"] {
        assert!(r.body.get(key).is_some(), "missing {key}: {}", r.text);
    }
    assert_eq!(r.body["solver"]["fidelity"], "closed_form");
    assert!(r.body["solver"]["elapsed_ms"].as_f64().unwrap() >= 0.0);
    for effect in ["piezoviscosity", "compressibility"] {
        let d = &r.body["effects"][effect];
        assert!(
            d["applied"].is_boolean() && d["reason"].is_string(),
            "{effect}: {}",
            r.text
        );
    }
    assert_all_finite(&r.body, "");
    assert!(
        r.headers.get("x-request-id").is_some(),
        "every response carries its request id"
    );
}

#[tokio::test]
async fn unreadable_json_is_400() {
    let app = spawn_app().await;
    let r = app
        .post_raw(
            PATH,
            b"{\"lubricant\": ".to_vec(),
            Some("application/json"),
            &[],
        )
        .await;
    r.problem(400);
    let r = app
        .post_raw(PATH, b"not json".to_vec(), Some("application/json"), &[])
        .await;
    r.problem(400);
}

#[tokio::test]
async fn a_body_that_is_not_json_is_415() {
    let app = spawn_app().await;
    let body = serde_json::to_vec(&good_request()).unwrap();
    app.post_raw(PATH, body.clone(), Some("text/plain"), &[])
        .await
        .problem(415);
    app.post_raw(PATH, body, None, &[]).await.problem(415);
}

#[tokio::test]
async fn a_body_over_the_limit_is_413() {
    let app = spawn_with(
        stribeck::config::Config {
            max_body_bytes: 2000,
            ..test_config()
        },
        None,
    )
    .await;
    let temps: Vec<f64> = (0..1000).map(f64::from).collect();
    let body = json!({"lubricant": {"viscosity_pa_s": 0.03}, "temperatures_c": temps});
    app.post_json(PATH, &body).await.problem(413);
    // The same server still answers small bodies.
    assert_eq!(app.post_json(PATH, &good_request()).await.status, 200);
}

/// (request, pointer, why): invalid inputs answer 422 naming the field.
#[tokio::test]
async fn invalid_input_is_422_with_a_pointer() {
    let app = spawn_app().await;
    let cases = [
        (
            json!({"lubricant": {"viscosity_pa_s": 0.03}, "temperatures_c": [40.0], "lenght_m": 1}),
            "/lenght_m",
            "unknown top-level field",
        ),
        (
            json!({"lubricant": {"viscosty_pa_s": 0.03}, "temperatures_c": [40.0]}),
            "/lubricant/viscosty_pa_s",
            "typo in a nested field",
        ),
        (
            json!({"lubricant": {"viscosity_pa_s": 0.03}}),
            "/temperatures_c",
            "missing field",
        ),
        (
            json!({"lubricant": {"viscosity_pa_s": -1.0}, "temperatures_c": [40.0]}),
            "/lubricant/viscosity_pa_s",
            "negative viscosity",
        ),
        (
            // Regression (schemathesis): a denormal viscosity made μ/ρ underflow to 0 and a 500.
            json!({"lubricant": {"viscosity_pa_s": 5e-324}, "temperatures_c": [0.0]}),
            "/lubricant/viscosity_pa_s",
            "denormal viscosity",
        ),
        (
            json!({"lubricant": {"viscosity_pa_s": 0.0}, "temperatures_c": [40.0]}),
            "/lubricant/viscosity_pa_s",
            "zero viscosity",
        ),
        (
            json!({"lubricant": {"viscosity_pa_s": 0.03}, "temperatures_c": [40.0, -300.0]}),
            "/temperatures_c/1",
            "below absolute zero",
        ),
        (
            json!({"lubricant": {"viscosity_pa_s": 0.03}, "temperatures_c": [40.0], "pressures_pa": [-1.0]}),
            "/pressures_pa/0",
            "negative pressure",
        ),
        (
            json!({"lubricant": {"viscosity_pa_s": 0.03}, "temperatures_c": [40.0], "pressures_pa": [6e9]}),
            "/pressures_pa/0",
            "pressure above range",
        ),
        (
            json!({"lubricant": {"viscosity_pa_s": 0.03}, "temperatures_c": []}),
            "/temperatures_c",
            "no temperatures",
        ),
        (
            json!({"lubricant": {}, "temperatures_c": [40.0]}),
            "/lubricant",
            "no viscosity description",
        ),
        (
            json!({"lubricant": {"viscosity_pa_s": 0.03, "iso_vg": 32}, "temperatures_c": [40.0]}),
            "/lubricant",
            "two viscosity descriptions",
        ),
        (
            json!({"lubricant": {"iso_vg": 33}, "temperatures_c": [40.0]}),
            "/lubricant/iso_vg",
            "not an ISO grade",
        ),
        (
            json!({"lubricant": {"kinematic_viscosity_40c_mm2_s": 5.0, "kinematic_viscosity_100c_mm2_s": 30.0}, "temperatures_c": [40.0]}),
            "/lubricant/kinematic_viscosity_100c_mm2_s",
            "viscosity rising with temperature",
        ),
        (
            json!({"lubricant": {"kinematic_viscosity_40c_mm2_s": 32.0}, "temperatures_c": [40.0]}),
            "/lubricant/kinematic_viscosity_100c_mm2_s",
            "one Walther point",
        ),
        (
            json!({"lubricant": {"viscosity_pa_s": 0.03, "pressure_viscosity_coefficient_1_pa": 2e-8, "roelands_pressure_viscosity_index": 0.6}, "temperatures_c": [40.0]}),
            "/lubricant/roelands_pressure_viscosity_index",
            "two pressure laws",
        ),
        (
            json!({"lubricant": {"viscosity_pa_s": 0.03}, "temperatures_c": [40.0], "effects": {"piezoviscosity": "on"}}),
            "/effects/piezoviscosity",
            "effect on without the law it needs",
        ),
        (
            json!({"lubricant": {"viscosity_pa_s": 0.03}, "temperatures_c": [40.0], "effects": {"thermal": "on"}}),
            "/effects/thermal",
            "effect this calculation does not know",
        ),
        (
            json!({"lubricant": {"vogel": {"points": [{"temperature_c": 20.0, "viscosity_pa_s": 0.01}, {"temperature_c": 60.0, "viscosity_pa_s": 0.02}, {"temperature_c": 100.0, "viscosity_pa_s": 0.05}]}}, "temperatures_c": [40.0]}),
            "/lubricant/vogel/points",
            "Vogel points rising with temperature",
        ),
        (
            json!({"lubricant": {"vogel": {"points": [{"temperature_c": 100.0, "viscosity_pa_s": 0.0099}, {"temperature_c": 60.0, "viscosity_pa_s": 0.0351}, {"temperature_c": 20.0, "viscosity_pa_s": 0.387}]}}, "temperatures_c": [-100.0]}),
            "/temperatures_c/0",
            "below Vogel's divergence temperature",
        ),
        (
            json!({"lubricant": {"viscosity_pa_s": 1e-5, "roelands_pressure_viscosity_index": 0.6}, "temperatures_c": [40.0], "pressures_pa": [1e8]}),
            "/temperatures_c/0",
            "Roelands for a fluid too thin for it",
        ),
    ];
    for (body, pointer, why) in cases {
        let r = app.post_json(PATH, &body).await;
        r.problem(422);
        assert!(
            r.pointers().iter().any(|p| p == pointer),
            "{why}: want {pointer}, got {:?} ({})",
            r.pointers(),
            r.text
        );
    }
}

#[tokio::test]
async fn unknown_paths_and_methods_are_problems() {
    let app = spawn_app().await;
    app.post_json("/v1/lubricants/viscosityy", &good_request())
        .await
        .problem(404);
    let wrong_method = app.get(PATH).await;
    wrong_method.problem(405);
    assert!(
        wrong_method.text.contains("take POST"),
        "{}",
        wrong_method.text
    );
    // The service's own routes are GET: a POST to them says so, not "calculations take POST".
    let health = app.post_json("/health", &good_request()).await;
    health.problem(405);
    assert!(health.text.contains("GET only"), "{}", health.text);
}
