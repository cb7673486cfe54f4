//! The generated client against the real service: every operation once, typed both ways, and a
//! 422 decoded as a typed `Problem`.

use serde_json::Value;
use stribeck::calc::REGISTRY;
use stribeck::config::Config;
use stribeck_client::types::ViscosityIndexInput;
use stribeck_client::{Client, Error};

/// The `stribeck` library's router on 127.0.0.1, a random port (as `tests/api` spawns it).
async fn spawn_server() -> Client {
    let listener = tokio::net::TcpListener::bind("127.0.0.1:0").await.unwrap();
    let base = format!("http://{}", listener.local_addr().unwrap());
    let app = stribeck::http::router(Config::default());
    tokio::spawn(async move { axum::serve(listener, app).await.unwrap() });
    Client::new(&base)
}

/// One calculation through its typed method: the registered example parsed into the typed
/// input, the typed envelope back as JSON.
async fn calculate(client: &Client, path: &str, example: &str) -> Value {
    macro_rules! typed {
        ($method:ident) => {{
            let input = serde_json::from_str(example).unwrap_or_else(|e| {
                panic!("{path}: the example does not fit the typed input: {e}")
            });
            let envelope = client
                .$method(None, None, &input)
                .await
                .unwrap_or_else(|e| panic!("{path}: {e}"));
            serde_json::to_value(envelope.into_inner()).unwrap()
        }};
    }
    match path {
        "/v1/composite-bearings/orbit" => typed!(composite_bearings_orbit),
        "/v1/composite-bearings/speed-split" => typed!(composite_bearings_speed_split),
        "/v1/composite-bearings/start-up" => typed!(composite_bearings_start_up),
        "/v1/contacts/ehl" => typed!(contacts_ehl),
        "/v1/contacts/ehl-film" => typed!(contacts_ehl_film),
        "/v1/contacts/flash-temperature" => typed!(contacts_flash_temperature),
        "/v1/contacts/hertz" => typed!(contacts_hertz),
        "/v1/gas-bearings/aerostatic-pad" => typed!(gas_bearings_aerostatic_pad),
        "/v1/gas-bearings/foil-journal" => typed!(gas_bearings_foil_journal),
        "/v1/gas-bearings/journal" => typed!(gas_bearings_journal),
        "/v1/gas-bearings/slider" => typed!(gas_bearings_slider),
        "/v1/gas-bearings/tilting-pad-thrust" => typed!(gas_bearings_tilting_pad_thrust),
        "/v1/gas-bearings/tilting-pad-journal" => typed!(gas_bearings_tilting_pad_journal),
        "/v1/hydrostatic-bearings/design" => typed!(hydrostatic_bearings_design),
        "/v1/hydrostatic-bearings/pad" => typed!(hydrostatic_bearings_pad),
        "/v1/journal-bearings/dynamic" => typed!(journal_bearings_dynamic),
        "/v1/journal-bearings/plain" => typed!(journal_bearings_plain),
        "/v1/journal-bearings/whirl" => typed!(journal_bearings_whirl),
        "/v1/lubricants/properties" => typed!(lubricants_properties),
        "/v1/lubricants/viscosity" => typed!(lubricants_viscosity),
        "/v1/lubricants/viscosity-index" => typed!(lubricants_viscosity_index),
        "/v1/rolling-bearings/analysis" => typed!(rolling_bearings_analysis),
        "/v1/rolling-bearings/friction" => typed!(rolling_bearings_friction),
        "/v1/rolling-bearings/grease-life" => typed!(rolling_bearings_grease_life),
        "/v1/rolling-bearings/kinematics" => typed!(rolling_bearings_kinematics),
        "/v1/rolling-bearings/life" => typed!(rolling_bearings_life),
        "/v1/rolling-bearings/load-distribution" => typed!(rolling_bearings_load_distribution),
        "/v1/rolling-bearings/static-capacity" => typed!(rolling_bearings_static_capacity),
        "/v1/squeeze-films/journal" => typed!(squeeze_films_journal),
        "/v1/squeeze-films/piston-ring" => typed!(squeeze_films_piston_ring),
        "/v1/squeeze-films/plates" => typed!(squeeze_films_plates),
        "/v1/thrust-bearings/bearing" => typed!(thrust_bearings_bearing),
        "/v1/thrust-bearings/fixed-pad" => typed!(thrust_bearings_fixed_pad),
        "/v1/thrust-bearings/parasitic-losses" => typed!(thrust_bearings_parasitic_losses),
        "/v1/thrust-bearings/tilting-pad" => typed!(thrust_bearings_tilting_pad),
        other => panic!("{other} has no typed call here: add its operation"),
    }
}

/// Every calculation the service registers answers its example through the typed client, and
/// the typed envelope holds everything the service sent: re-serialised, it equals the
/// envelope the library computes for the same request (less the solver's wall time).
#[tokio::test]
async fn every_calculation_round_trips_typed() {
    let client = spawn_server().await;
    for entry in REGISTRY {
        let mut typed = calculate(&client, entry.path, entry.example).await;
        let far = std::time::Instant::now() + std::time::Duration::from_secs(60);
        let direct = (entry.execute)(entry.example.as_bytes(), far, Default::default())
            .unwrap_or_else(|f| panic!("{}: {f:?}", entry.path));
        let mut direct: Value = serde_json::from_slice(&direct.body).unwrap();
        for envelope in [&mut typed, &mut direct] {
            envelope["solver"]
                .as_object_mut()
                .unwrap()
                .remove("elapsed_ms");
        }
        assert!(
            typed == direct,
            "{}: the typed envelope differs from the service's\n typed: {typed}\nserver: {direct}",
            entry.path
        );
    }
}

#[tokio::test]
async fn the_service_endpoints_answer_typed() {
    let client = spawn_server().await;
    assert_eq!(client.health(None).await.unwrap().status, "ok");
    assert_eq!(client.ready(None).await.unwrap().status, "ready");
    let list = client.list_calculations(Some("client-test")).await.unwrap();
    assert_eq!(list.headers()["x-request-id"], "client-test");
    let paths: Vec<&str> = list.calculations.iter().map(|c| c.path.as_str()).collect();
    let registered: Vec<&str> = REGISTRY.iter().map(|e| e.path).collect();
    assert_eq!(paths, registered);
    // `/metrics` is text: the client hands over the body as a byte stream.
    let mut stream = client.metrics(None).await.unwrap().into_inner_stream();
    let mut body = Vec::new();
    while let Some(chunk) = std::future::poll_fn(|cx| stream.as_mut().poll_next(cx)).await {
        body.extend_from_slice(&chunk.unwrap());
    }
    let text = String::from_utf8(body).unwrap();
    assert!(text.contains("stribeck_requests_total"), "{text}");
}

/// An invalid request comes back as `Error::ErrorResponse` holding the typed problem, with the
/// field's pointer.
#[tokio::test]
async fn a_422_decodes_as_a_typed_problem() {
    let client = spawn_server().await;
    let input = ViscosityIndexInput {
        kinematic_viscosity_40c_mm2_s: Some(-73.3),
        kinematic_viscosity_100c_mm2_s: Some(8.86),
        lubricant: None,
    };
    let err = client
        .lubricants_viscosity_index(None, None, &input)
        .await
        .expect_err("a negative viscosity is refused");
    let Error::ErrorResponse(problem) = err else {
        panic!("not a typed error response: {err}");
    };
    assert_eq!(problem.status().as_u16(), 422);
    assert_eq!(problem.status, 422);
    assert_eq!(problem.type_, "https://stribeck.dev/problems/invalid-input");
    let pointers: Vec<&str> = problem.errors.iter().map(|e| e.pointer.as_str()).collect();
    assert_eq!(pointers, ["/kinematic_viscosity_40c_mm2_s"]);
}
