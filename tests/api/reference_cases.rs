//! Reference cases from tests/data: request, expected values addressed by JSON pointer, tolerance
//! and source. A case from a text whose printed value is a misprint uses the spec's corrected
//! value and says so in its `source`.

use serde::Deserialize;
use serde_json::Value;

use crate::helpers::{assert_all_finite, case_files, spawn_app};

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Case {
    source: String,
    path: String,
    request: Value,
    expected: Vec<Expected>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Expected {
    /// JSON pointer into the response, e.g. `/result/points/0/density_kg_m3`.
    pointer: String,
    value: f64,
    #[serde(default)]
    rel_tol: Option<f64>,
    #[serde(default)]
    abs_tol: Option<f64>,
}

#[tokio::test]
async fn every_reference_case_matches_its_source() {
    let app = spawn_app().await;
    let files = case_files();
    assert!(
        files.len() >= 10,
        "expected the reference cases under tests/data, found {}",
        files.len()
    );
    let mut failures = Vec::new();
    for file in &files {
        let case: Case = serde_json::from_str(&std::fs::read_to_string(file).unwrap())
            .unwrap_or_else(|e| panic!("{}: {e}", file.display()));
        let reply = app.post_json(&case.path, &case.request).await;
        assert_eq!(reply.status, 200, "{}: {}", file.display(), reply.text);
        assert_all_finite(&reply.body, "");
        for want in &case.expected {
            let got = reply
                .body
                .pointer(&want.pointer)
                .and_then(Value::as_f64)
                .unwrap_or(f64::NAN);
            let ok = match (want.rel_tol, want.abs_tol) {
                (Some(rel), _) => ((got - want.value) / want.value).abs() <= rel,
                (None, Some(abs)) => (got - want.value).abs() <= abs,
                (None, None) => got == want.value,
            };
            if !ok {
                failures.push(format!(
                    "{} {}: got {got}, want {} (rel {:?}, abs {:?}) — {}",
                    file.file_name().unwrap().to_string_lossy(),
                    want.pointer,
                    want.value,
                    want.rel_tol,
                    want.abs_tol,
                    case.source
                ));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
