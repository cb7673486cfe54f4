//! Spawn the real service on 127.0.0.1:0 and talk to it over HTTP.

use serde_json::Value;
use stribeck::calc::Entry;
use stribeck::config::Config;
use stribeck::http::{self, AppState};

pub struct TestApp {
    pub base: String,
    pub client: reqwest::Client,
}

pub struct Reply {
    pub status: u16,
    pub content_type: String,
    pub headers: reqwest::header::HeaderMap,
    pub body: Value,
    pub text: String,
}

/// A config for tests: defaults, on an ephemeral port.
pub fn test_config() -> Config {
    Config {
        addr: ([127, 0, 0, 1], 0).into(),
        ..Config::default()
    }
}

pub async fn spawn_app() -> TestApp {
    spawn_with(test_config(), None).await
}

pub async fn spawn_with(config: Config, calculations: Option<&'static [Entry]>) -> TestApp {
    let listener = tokio::net::TcpListener::bind("127.0.0.1:0").await.unwrap();
    let base = format!("http://{}", listener.local_addr().unwrap());
    let header_timeout = config.header_timeout;
    let state = AppState::new(config);
    let app = match calculations {
        Some(list) => http::router_with(state, list),
        None => http::router_with_state(state),
    };
    // The binary's own accept loop (header timeout included), never stopped.
    let forever = std::future::pending();
    tokio::spawn(http::serve::serve(listener, app, header_timeout, forever));
    TestApp {
        base,
        client: reqwest::Client::new(),
    }
}

impl TestApp {
    pub async fn post_json(&self, path: &str, body: &Value) -> Reply {
        self.post_raw(
            path,
            serde_json::to_vec(body).unwrap(),
            Some("application/json"),
            &[],
        )
        .await
    }

    pub async fn post_raw(
        &self,
        path: &str,
        body: Vec<u8>,
        content_type: Option<&str>,
        headers: &[(&str, &str)],
    ) -> Reply {
        let mut req = self.client.post(format!("{}{path}", self.base)).body(body);
        if let Some(ct) = content_type {
            req = req.header("content-type", ct);
        }
        for (k, v) in headers {
            req = req.header(*k, *v);
        }
        Reply::from(req.send().await.expect("request sent")).await
    }

    pub async fn get(&self, path: &str) -> Reply {
        Reply::from(
            self.client
                .get(format!("{}{path}", self.base))
                .send()
                .await
                .unwrap(),
        )
        .await
    }
}

impl Reply {
    async fn from(res: reqwest::Response) -> Reply {
        let status = res.status().as_u16();
        let headers = res.headers().clone();
        let content_type = headers
            .get("content-type")
            .and_then(|v| v.to_str().ok())
            .unwrap_or("")
            .to_owned();
        let text = res.text().await.unwrap();
        let body = serde_json::from_str(&text).unwrap_or(Value::Null);
        Reply {
            status,
            content_type,
            headers,
            body,
            text,
        }
    }

    /// Assert a problem+json answer with this status, and return its body.
    pub fn problem(&self, status: u16) -> &Value {
        assert_eq!(self.status, status, "body: {}", self.text);
        assert_eq!(
            self.content_type, "application/problem+json",
            "body: {}",
            self.text
        );
        assert_eq!(self.body["status"], status);
        assert!(
            self.body["type"].is_string()
                && self.body["title"].is_string()
                && self.body["detail"].is_string()
        );
        &self.body
    }

    /// The pointers named in a 422's `errors`.
    pub fn pointers(&self) -> Vec<String> {
        self.body["errors"]
            .as_array()
            .map(|a| {
                a.iter()
                    .filter_map(|e| e["pointer"].as_str().map(str::to_owned))
                    .collect()
            })
            .unwrap_or_default()
    }
}

/// Every number in a JSON value is finite, and no value is null.
pub fn assert_all_finite(v: &Value, at: &str) {
    match v {
        Value::Null => panic!("null at {at}"),
        Value::Number(n) => assert!(n.as_f64().is_some_and(f64::is_finite), "non-finite at {at}"),
        Value::Array(a) => a
            .iter()
            .enumerate()
            .for_each(|(i, x)| assert_all_finite(x, &format!("{at}/{i}"))),
        Value::Object(o) => o
            .iter()
            .for_each(|(k, x)| assert_all_finite(x, &format!("{at}/{k}"))),
        _ => {}
    }
}

/// Each body answered 422 with an error at its pointer whose message says why.
pub async fn refused<const N: usize>(app: &TestApp, path: &str, rows: [(Value, &str, &str); N]) {
    for (body, pointer, why) in rows {
        let reply = app.post_json(path, &body).await;
        let problem = reply.problem(422);
        let errors = problem["errors"].as_array().unwrap();
        assert!(
            errors
                .iter()
                .any(|e| e["pointer"] == pointer && e["message"].as_str().unwrap().contains(why)),
            "{body}: want {pointer} ({why}), got {}",
            reply.text
        );
    }
}

/// `body` with `patch`'s top-level fields set, a null removing the field.
pub fn patched(mut body: Value, patch: &Value) -> Value {
    for (k, v) in patch.as_object().unwrap() {
        if v.is_null() {
            body.as_object_mut().unwrap().remove(k);
        } else {
            body[k] = v.clone();
        }
    }
    body
}

/// A room's OpenAPI example, [`patched`].
pub fn example_patched(path: &str, patch: &Value) -> Value {
    let example = serde_json::from_str(stribeck::calc::find(path).unwrap().example).unwrap();
    patched(example, patch)
}

/// `body` solved on `path` in process, under the server's default deadline from now (what the
/// server gives a request it admits at once).
pub fn under_server_deadline(path: &str, body: &Value) -> Result<Value, stribeck::calc::Failure> {
    let entry = stribeck::calc::find(path).expect("registered");
    let deadline = std::time::Instant::now() + Config::default().deadline;
    (entry.execute)(
        &serde_json::to_vec(body).unwrap(),
        deadline,
        Default::default(),
    )
    .map(|done| serde_json::from_slice(&done.body).expect("the envelope is JSON"))
}

/// A grid refused before any solve because its film solves outlast the deadline: a 422 naming
/// `/fidelity/grid` whose reason gives `estimate` (e.g. "about 14.6 s at least") and the
/// factorisations it counts (`work`, e.g. "261888 unknowns with a band of 256").
pub fn refused_by_cost(
    outcome: Result<Value, stribeck::calc::Failure>,
    estimate: &str,
    work: &str,
) {
    use stribeck::calc::{CalcError, Failure};
    match outcome {
        Err(Failure::Calc(CalcError::Impossible { pointer, message })) => {
            assert_eq!(pointer, "/fidelity/grid", "{message}");
            assert!(
                message.contains(estimate)
                    && message.contains(work)
                    && message.contains("the request's deadline leaves"),
                "want {estimate:?} and {work:?}, got {message}"
            );
        }
        Err(e) => panic!("expected a 422 naming the grid, got {e:?}"),
        Ok(v) => panic!(
            "expected a 422 naming the grid, got a result: {}",
            v["solver"]
        ),
    }
}
