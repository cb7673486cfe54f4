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
