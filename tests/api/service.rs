//! The service around the calculations: health, readiness, metrics, the listing, the committed
//! OpenAPI document and the docs UI.

use serde_json::Value;

use crate::helpers::spawn_app;

#[tokio::test]
async fn health_and_ready_answer() {
    let app = spawn_app().await;
    assert_eq!(
        app.get("/health").await.body,
        serde_json::json!({"status": "ok"})
    );
    assert_eq!(
        app.get("/ready").await.body,
        serde_json::json!({"status": "ready"})
    );
}

/// A request id the client sends comes back on the response (the document says so).
#[tokio::test]
async fn a_client_request_id_is_echoed() {
    let app = spawn_app().await;
    let r = app
        .post_raw(
            "/v1/lubricants/viscosity-index",
            b"{}".to_vec(),
            Some("application/json"),
            &[("x-request-id", "design-run-42")],
        )
        .await;
    assert_eq!(r.status, 422);
    assert_eq!(r.headers["x-request-id"], "design-run-42");
}

#[tokio::test]
async fn metrics_count_requests_by_route_and_status() {
    let app = spawn_app().await;
    let body = serde_json::json!({"kinematic_viscosity_40c_mm2_s": 73.3, "kinematic_viscosity_100c_mm2_s": 8.86});
    app.post_json("/v1/lubricants/viscosity-index", &body).await;
    app.post_json("/v1/lubricants/viscosity-index", &serde_json::json!({}))
        .await;
    let m = app.get("/metrics").await;
    assert!(m.content_type.starts_with("text/plain"));
    for line in [
        "stribeck_requests_total{path=\"/v1/lubricants/viscosity-index\",status=\"200\"} 1",
        "stribeck_requests_total{path=\"/v1/lubricants/viscosity-index\",status=\"422\"} 1",
        "stribeck_solver_duration_seconds_count{path=\"/v1/lubricants/viscosity-index\"} 1",
        "stribeck_request_duration_seconds_count{path=\"/v1/lubricants/viscosity-index\"} 2",
    ] {
        assert!(m.text.contains(line), "missing {line}\n{}", m.text);
    }
}

#[tokio::test]
async fn the_listing_names_every_calculation_with_a_working_example() {
    let app = spawn_app().await;
    let list = app.get("/v1/calculations").await;
    let calcs = list.body["calculations"].as_array().unwrap();
    assert_eq!(calcs.len(), stribeck::calc::REGISTRY.len());
    for c in calcs {
        let path = c["path"].as_str().unwrap();
        assert!(!c["fidelity_levels"].as_array().unwrap().is_empty());
        let r = app.post_json(path, &c["example"]).await;
        assert_eq!(r.status, 200, "{path}: {}", r.text);
    }
}

#[tokio::test]
async fn the_served_openapi_is_the_committed_one() {
    let app = spawn_app().await;
    let served = app.get("/openapi.json").await.body;
    let committed_text = committed("openapi.json");
    let committed: Value = serde_json::from_str(&committed_text).unwrap();
    let regenerate = "openapi/openapi.json drifted from the code: regenerate with `cargo run -- openapi > openapi/openapi.json`";
    assert!(served == committed, "{regenerate}");
    assert!(
        committed_text == stribeck::http::openapi::document_json(),
        "{regenerate}"
    );
    assert!(served["openapi"].as_str().unwrap().starts_with("3.1"));
}

/// The 3.0 rendering is committed beside the 3.1 document, and drifts with it.
#[test]
fn the_committed_openapi_30_is_the_generated_one() {
    assert!(
        committed("openapi-3.0.json") == stribeck::http::openapi::document_30_json(),
        "openapi/openapi-3.0.json drifted from the code: regenerate with `cargo run -- openapi --version 3.0 > openapi/openapi-3.0.json`"
    );
}

fn committed(file: &str) -> String {
    let path = format!("{}/openapi/{file}", env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// Every property of every schema says what it is (unit and range live in the description, or
/// in minimum/maximum); every request field that takes a value also carries an example.
#[tokio::test]
async fn every_request_field_is_documented() {
    let doc: Value = serde_json::from_str(&stribeck::http::openapi::document_json()).unwrap();
    let schemas = doc["components"]["schemas"].as_object().unwrap();
    let mut undocumented = Vec::new();
    for (name, schema) in schemas {
        let Some(props) = schema["properties"].as_object() else {
            continue;
        };
        for (field, prop) in props {
            let has_doc = prop
                .get("description")
                .is_some_and(|d| !d.as_str().unwrap_or("").is_empty());
            let is_ref = prop.get("$ref").is_some()
                || prop.get("oneOf").is_some()
                || prop.get("allOf").is_some();
            if !has_doc && !is_ref {
                undocumented.push(format!("{name}.{field}"));
            }
            let is_request =
                name.ends_with("Input") || name.ends_with("Spec") || name == "VogelPoint";
            if is_request && !is_ref && prop.get("example").is_none() {
                undocumented.push(format!("{name}.{field} (no example)"));
            }
        }
    }
    assert!(
        undocumented.is_empty(),
        "fields without a description: {undocumented:?}"
    );
}

#[tokio::test]
async fn the_docs_ui_is_served_from_the_binary() {
    let app = spawn_app().await;
    // `/docs` redirects to `/docs/`, whose relative links resolve under it.
    let page = app.get("/docs").await;
    assert_eq!(page.status, 200);
    assert!(
        page.text.to_lowercase().contains("swagger") && page.text.contains("/openapi.json"),
        "{}",
        &page.text[..page.text.len().min(300)]
    );
    // Every script and stylesheet the page references is served from the binary with its type.
    let assets: Vec<&str> = page
        .text
        .split('"')
        .filter(|s| s.starts_with("./"))
        .collect();
    for kind in [".js", ".css"] {
        assert!(
            assets.iter().any(|a| a.ends_with(kind)),
            "{kind} in {assets:?}"
        );
    }
    for asset in assets {
        let reply = app.get(&format!("/docs/{}", &asset[2..])).await;
        assert_eq!(reply.status, 200, "{asset}");
        let kind = if asset.ends_with(".js") {
            "javascript"
        } else {
            "css"
        };
        assert!(
            reply.content_type.contains(kind),
            "{asset}: {}",
            reply.content_type
        );
        assert!(
            reply.text.len() > 100_000,
            "{asset} is embedded, not fetched from a CDN"
        );
    }
}

/// The released binary logs one access line per request at the default level, plain text when
/// its stderr is not a terminal (issue 12, item 15: nothing was logged for a 200 or a 4xx, and
/// file logs carried ANSI colour codes).
#[test]
fn the_server_logs_one_plain_access_line_per_request() {
    use std::io::{Read, Write};
    let port = std::net::TcpListener::bind("127.0.0.1:0")
        .unwrap()
        .local_addr()
        .unwrap()
        .port();
    let log = std::env::temp_dir().join(format!("stribeck-access-{port}.log"));
    let mut server = std::process::Command::new(env!("CARGO_BIN_EXE_stribeck"))
        .arg("serve")
        .env("STRIBECK_ADDR", format!("127.0.0.1:{port}"))
        .env_remove("RUST_LOG")
        .stderr(std::fs::File::create(&log).unwrap())
        .spawn()
        .unwrap();
    let send = |request: &str| -> Option<String> {
        let mut stream = std::net::TcpStream::connect(("127.0.0.1", port)).ok()?;
        stream.write_all(request.as_bytes()).ok()?;
        let mut reply = String::new();
        stream.read_to_string(&mut reply).ok()?;
        Some(reply)
    };
    let health = "GET /health HTTP/1.1\r\nhost: x\r\nconnection: close\r\n\r\n";
    let mut up = None;
    for _ in 0..100 {
        up = send(health);
        if up.is_some() {
            break;
        }
        std::thread::sleep(std::time::Duration::from_millis(50));
    }
    assert!(up.unwrap().starts_with("HTTP/1.1 200"));
    let body = "{}";
    let bad = send(&format!("POST /v1/contacts/hertz HTTP/1.1\r\nhost: x\r\ncontent-type: application/json\r\ncontent-length: {}\r\nconnection: close\r\n\r\n{body}", body.len())).unwrap();
    assert!(bad.starts_with("HTTP/1.1 422"), "{bad}");
    server.kill().unwrap();
    server.wait().unwrap();
    let text = std::fs::read_to_string(&log).unwrap();
    let _ = std::fs::remove_file(&log);
    assert!(
        !text.contains('\u{1b}'),
        "colour codes in a file log:\n{text}"
    );
    let served: Vec<&str> = text.lines().filter(|l| l.contains("served")).collect();
    assert!(
        served
            .iter()
            .any(|l| l.contains("status=200") && l.contains("/health")),
        "{text}"
    );
    assert!(
        served.iter().any(|l| l.contains("status=422")
            && l.contains("/v1/contacts/hertz")
            && l.contains("id=")),
        "{text}"
    );
}
