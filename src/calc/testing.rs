//! Helpers for the rooms' unit tests: one request through the whole path of one calculation
//! (parse, validate, run, serialise), as the door and the CLI run it.

use std::time::{Duration, Instant};

use serde_json::Value;

use super::{execute, Calculation, Failure};

/// The envelope of `request` run by `C`, as JSON.
pub fn post<C: Calculation>(request: &Value) -> Result<Value, Failure> {
    let body = serde_json::to_vec(request).expect("a JSON value serialises");
    let deadline = Instant::now() + Duration::from_secs(30);
    execute::<C>(&body, deadline, Default::default())
        .map(|done| serde_json::from_slice(&done.body).expect("the envelope is JSON"))
}

/// As [`post`], for a request that must succeed.
pub fn ok<C: Calculation>(request: &Value) -> Value {
    post::<C>(request).unwrap_or_else(|e| panic!("{request}: {e:?}"))
}

/// The JSON pointers of a request that must be refused as invalid (422).
pub fn invalid_pointers<C: Calculation>(request: &Value) -> Vec<String> {
    match post::<C>(request) {
        Err(Failure::Invalid(errors)) => errors.into_iter().map(|e| e.pointer).collect(),
        other => panic!("{request}: expected 422, got {other:?}"),
    }
}

/// `result.<field>` of an envelope.
pub fn result_field(v: &Value, field: &str) -> f64 {
    v["result"][field]
        .as_f64()
        .unwrap_or_else(|| panic!("{field} missing in {v}"))
}

/// The codes of an envelope's warnings, in order.
pub fn warning_codes(v: &Value) -> Vec<String> {
    v["warnings"]
        .as_array()
        .unwrap_or_else(|| panic!("no warnings list in {v}"))
        .iter()
        .map(|w| w["code"].as_str().unwrap().to_owned())
        .collect()
}

/// |got/want − 1| ≤ rel.
pub fn assert_rel(got: f64, want: f64, rel: f64, what: &str) {
    assert!(
        ((got - want) / want).abs() <= rel,
        "{what}: got {got}, want {want} ±{rel}"
    );
}
