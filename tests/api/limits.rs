//! The service protects itself: a late calculation is stopped (504), a flood is shed (503), a
//! panicking or non-finite calculation answers 500 without internals, a slow client's connection
//! is closed (head) or answered 408 (body), and the server keeps serving.

use serde::{Deserialize, Serialize};
use serde_json::json;
use stribeck::calc::{CalcError, Calculation, Context, Entry, FieldError, Validate};
use stribeck::config::Config;
use stribeck::fidelity::Level;
use utoipa::ToSchema;

use crate::helpers::{spawn_app, spawn_with, test_config, TestApp};

const PATH: &str = "/v1/lubricants/viscosity";

/// The largest grid the viscosity room accepts: 1000 temperatures × 100 pressures, 100 000
/// points, all under a Roelands law — a solver run of tens of milliseconds.
fn heavy_request() -> serde_json::Value {
    let temps: Vec<f64> = (0..1000).map(|i| 20.0 + 0.1 * f64::from(i)).collect();
    let pressures: Vec<f64> = (0..100).map(|i| 1e7 * f64::from(i)).collect();
    json!({
        "lubricant": {"kinematic_viscosity_40c_mm2_s": 32.0, "kinematic_viscosity_100c_mm2_s": 5.4, "roelands_pressure_viscosity_index": 0.6},
        "temperatures_c": temps,
        "pressures_pa": pressures
    })
}

#[tokio::test]
async fn a_calculation_past_its_deadline_is_504_and_the_server_keeps_serving() {
    let app = spawn_app().await;
    let body = serde_json::to_vec(&heavy_request()).unwrap();
    let r = app
        .post_raw(
            PATH,
            body,
            Some("application/json"),
            &[("x-stribeck-deadline-ms", "1")],
        )
        .await;
    r.problem(504);
    // Still serving, calculations included.
    assert_eq!(app.get("/health").await.status, 200);
    let ok = app
        .post_json(
            PATH,
            &json!({"lubricant": {"viscosity_pa_s": 0.03}, "temperatures_c": [40.0]}),
        )
        .await;
    assert_eq!(ok.status, 200, "{}", ok.text);
    let full = app.post_json(PATH, &heavy_request()).await;
    assert_eq!(
        full.status, 200,
        "without the short deadline the same request completes"
    );
    assert_eq!(
        full.body["result"]["points"].as_array().unwrap().len(),
        100_000
    );
}

/// A deadline header that is not a whole number of milliseconds is a 400 naming the header
/// (issue 12, item 8: it was ignored and the solve ran under the server's deadline).
#[tokio::test]
async fn a_malformed_deadline_header_is_a_400_that_names_it() {
    let app = spawn_app().await;
    let body = serde_json::to_vec(
        &json!({"lubricant": {"viscosity_pa_s": 0.03}, "temperatures_c": [40.0]}),
    )
    .unwrap();
    for bad in ["abc", "-5", "1.5", "", "1e3"] {
        let r = app
            .post_raw(
                PATH,
                body.clone(),
                Some("application/json"),
                &[("x-stribeck-deadline-ms", bad)],
            )
            .await;
        let problem = r.problem(400);
        let detail = problem["detail"].as_str().unwrap();
        assert!(
            detail.contains("x-stribeck-deadline-ms") && detail.contains("milliseconds"),
            "{bad:?}: {detail}"
        );
    }
    for good in ["250", " 250 ", "0", "99999999999"] {
        let r = app
            .post_raw(
                PATH,
                body.clone(),
                Some("application/json"),
                &[("x-stribeck-deadline-ms", good)],
            )
            .await;
        assert!(
            r.status == 200 || (good == "0" && r.status == 504),
            "{good:?}: {} {}",
            r.status,
            r.text
        );
    }
}

#[tokio::test]
async fn a_flood_past_the_light_limit_is_shed_with_503() {
    let app = spawn_with(
        Config {
            light_limit: 2,
            ..test_config()
        },
        None,
    )
    .await;
    let body = serde_json::to_vec(&heavy_request()).unwrap();
    let replies = futures_join(&app, &body, 16).await;
    let shed = replies.iter().filter(|r| r.status == 503).count();
    let ok = replies.iter().filter(|r| r.status == 200).count();
    assert_eq!(
        shed + ok,
        replies.len(),
        "only 200 or 503: {:?}",
        replies.iter().map(|r| r.status).collect::<Vec<_>>()
    );
    assert!(shed >= 1 && ok >= 1, "{ok} ok, {shed} shed");
    for r in replies.iter().filter(|r| r.status == 503) {
        r.problem(503);
        assert!(r.headers.get("retry-after").is_some());
    }
}

async fn futures_join(
    app: &crate::helpers::TestApp,
    body: &[u8],
    n: usize,
) -> Vec<crate::helpers::Reply> {
    let mut tasks = tokio::task::JoinSet::new();
    for _ in 0..n {
        let client = app.client.clone();
        let url = format!("{}{PATH}", app.base);
        let body = body.to_vec();
        tasks.spawn(async move {
            client
                .post(url)
                .header("content-type", "application/json")
                .body(body)
                .send()
                .await
                .unwrap()
        });
    }
    let mut out = Vec::new();
    while let Some(res) = tasks.join_next().await {
        let res = res.unwrap();
        let status = res.status().as_u16();
        let headers = res.headers().clone();
        let text = res.text().await.unwrap();
        out.push(crate::helpers::Reply {
            status,
            content_type: headers
                .get("content-type")
                .and_then(|v| v.to_str().ok())
                .unwrap_or("")
                .to_owned(),
            body: serde_json::from_str(&text).unwrap_or_default(),
            headers,
            text,
        });
    }
    out
}

/// A calculation that misbehaves on purpose, to reach the paths no real one should.
struct Misbehaving;

#[derive(Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
struct MisbehaveInput {
    /// `panic` or `nan`.
    how: String,
}

impl Validate for MisbehaveInput {
    type Valid = String;
    fn validate(self) -> Result<String, Vec<FieldError>> {
        Ok(self.how)
    }
}

#[derive(Serialize, ToSchema)]
struct MisbehaveOutput {
    value: f64,
}

impl Calculation for Misbehaving {
    const PATH: &'static str = "/v1/test/misbehave";
    const SUMMARY: &'static str = "test only";
    const DESCRIPTION: &'static str = "test only";
    const FIDELITY: &'static [Level] = &[Level::ClosedForm];
    const EFFECTS: &'static [&'static str] = &[];
    const EXAMPLE: &'static str = r#"{"how": "nan"}"#;
    type Input = MisbehaveInput;
    type Output = MisbehaveOutput;
    fn run(how: String, _: &mut Context) -> Result<MisbehaveOutput, CalcError> {
        if how == "panic" {
            panic!("secret internal detail 0xDEADBEEF");
        }
        Ok(MisbehaveOutput { value: f64::NAN })
    }
}

static MISBEHAVING: &[Entry] = &[Entry::of::<Misbehaving>()];

#[tokio::test]
async fn a_panic_is_500_without_internals_and_the_server_survives() {
    let app = spawn_with(test_config(), Some(MISBEHAVING)).await;
    let r = app
        .post_json(Misbehaving::PATH, &json!({"how": "panic"}))
        .await;
    r.problem(500);
    assert!(
        !r.text.contains("DEADBEEF") && !r.text.contains("secret"),
        "{}",
        r.text
    );
    assert_eq!(app.get("/health").await.status, 200);
}

#[tokio::test]
async fn a_non_finite_result_never_reaches_the_client() {
    let app = spawn_with(test_config(), Some(MISBEHAVING)).await;
    let r = app
        .post_json(Misbehaving::PATH, &json!({"how": "nan"}))
        .await;
    r.problem(500);
    assert!(
        !r.text.to_lowercase().contains("nan") && !r.text.contains("null"),
        "{}",
        r.text
    );
}

#[tokio::test]
async fn stribeck_run_uses_the_same_path() {
    // The registry entry the CLI calls gives the same envelope as HTTP.
    let app = spawn_app().await;
    let body =
        json!({"kinematic_viscosity_40c_mm2_s": 73.3, "kinematic_viscosity_100c_mm2_s": 8.86});
    let http = app.post_json("/v1/lubricants/viscosity-index", &body).await;
    let entry = stribeck::calc::find("/v1/lubricants/viscosity-index").unwrap();
    let far = std::time::Instant::now() + std::time::Duration::from_secs(10);
    let direct =
        (entry.execute)(&serde_json::to_vec(&body).unwrap(), far, Default::default()).unwrap();
    let direct: serde_json::Value = serde_json::from_slice(&direct.body).unwrap();
    assert_eq!(http.body["result"], direct["result"]);
}

/// A raw connection to the test server that sent `bytes` and then stalls.
async fn stalled_client(app: &crate::helpers::TestApp, bytes: &str) -> tokio::net::TcpStream {
    use tokio::io::AsyncWriteExt;
    let addr = app.base.trim_start_matches("http://");
    let mut stream = tokio::net::TcpStream::connect(addr).await.unwrap();
    stream.write_all(bytes.as_bytes()).await.unwrap();
    stream
}

/// Everything the server sends until it closes the connection (or 20 s pass: a failure).
async fn read_until_closed(stream: &mut tokio::net::TcpStream) -> String {
    use tokio::io::AsyncReadExt;
    let mut reply = Vec::new();
    let read = tokio::time::timeout(
        std::time::Duration::from_secs(20),
        stream.read_to_end(&mut reply),
    )
    .await;
    assert!(read.is_ok(), "the connection is still open after 20 s");
    String::from_utf8_lossy(&reply).into_owned()
}

/// A server on `config` sent `start` and then nothing: its reply up to the close, and how long
/// that took.
async fn stall(config: Config, start: &str) -> (TestApp, String, std::time::Duration) {
    let app = spawn_with(config, None).await;
    let started = std::time::Instant::now();
    let mut stream = stalled_client(&app, start).await;
    let reply = read_until_closed(&mut stream).await;
    (app, reply, started.elapsed())
}

/// A request head that never ends is cut off after the header timeout (issue 12, item 13: 300
/// such connections stayed open for over 35 s).
#[tokio::test]
async fn a_partial_request_head_is_closed_after_the_header_timeout() {
    let (app, reply, took) = stall(
        Config {
            header_timeout: std::time::Duration::from_millis(300),
            ..test_config()
        },
        "POST /v1/lubricants/viscosity HTTP/1.1\r\nhost: x\r\n",
    )
    .await;
    assert!(
        took >= std::time::Duration::from_millis(250),
        "closed before the timeout"
    );
    assert!(
        reply.is_empty() || reply.starts_with("HTTP/1.1 408"),
        "{reply}"
    );
    // The server still serves.
    assert_eq!(app.get("/health").await.status, 200);
}

/// A body that stops short of its Content-Length answers 408 after the body timeout.
#[tokio::test]
async fn a_partial_body_answers_408_after_the_body_timeout() {
    let (_app, reply, took) = stall(
        Config {
            body_timeout: std::time::Duration::from_millis(300),
            ..test_config()
        },
        "POST /v1/lubricants/viscosity HTTP/1.1\r\nhost: x\r\ncontent-type: application/json\r\ncontent-length: 100\r\n\r\n{\"lubricant\"",
    )
    .await;
    assert!(
        took >= std::time::Duration::from_millis(250),
        "answered before the timeout"
    );
    assert!(reply.starts_with("HTTP/1.1 408"), "{reply}");
    assert!(reply.contains("application/problem+json"), "{reply}");
    assert!(reply.contains("problems/body-timeout"), "{reply}");
    assert!(reply.contains("300 ms"), "{reply}");
}
