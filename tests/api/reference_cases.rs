//! Reference cases from tests/data over HTTP: request, expected values addressed by JSON
//! pointer, tolerance and source (the format of `stribeck::validation`, which also renders them
//! as docs/validation.md). A case from a text whose printed value is a misprint uses the spec's
//! corrected value and says so in its `source`.

use serde_json::Value;
use stribeck::validation::{case_files, Case};

use crate::helpers::{assert_all_finite, spawn_app};

#[tokio::test]
async fn every_reference_case_matches_its_source() {
    let app = spawn_app().await;
    let files =
        case_files(&std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data")).unwrap();
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
            if !want.holds(got) {
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
