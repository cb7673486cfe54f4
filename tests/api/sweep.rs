//! Every number of every request, from the smallest positive double to the largest (issue 12,
//! item 2: `load_n` 1e-200 on the EHL film and `length_m` 5e-324 on a Hertz line contact were
//! 500s, and just above them came 200s with absurd films and temperatures). For every
//! registered example (and the example with each optional field it leaves out), each number is
//! set in turn to every value of a ladder of decades; the room must answer a success whose
//! numbers are all finite, or a 422 — never a 400 for a schema-valid number, never an internal
//! error, never a panic, and never its deadline (a hang).

use serde_json::Value;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::time::{Duration, Instant};

use stribeck::calc::{CalcError, Costing, Entry, Failure, REGISTRY};

use crate::bounds::{bodies, collect, set};
use crate::helpers::assert_all_finite;

/// Positive doubles from the smallest subnormal to the largest, about every few decades.
const LADDER: [f64; 21] = [
    5e-324,
    f64::MIN_POSITIVE,
    1e-250,
    1e-200,
    1e-150,
    1e-100,
    1e-50,
    1e-20,
    1e-10,
    1e-6,
    1e-3,
    0.5,
    1.0,
    1e3,
    1e6,
    1e10,
    1e20,
    1e50,
    1e100,
    1e200,
    f64::MAX,
];

/// The ladder's extremes and decades for the numerical solves (each value is a whole solve;
/// the orbits integrate thousands of revolutions): the tiny and huge numbers the issue found.
const NUMERICAL_LADDER: [f64; 11] = [
    5e-324,
    f64::MIN_POSITIVE,
    1e-200,
    1e-100,
    1e-20,
    1e-6,
    1.0,
    1e6,
    1e20,
    1e100,
    f64::MAX,
];

/// Counts for integer fields, from the fewest to the largest a JSON integer holds.
const COUNTS: [u64; 9] = [0, 1, 2, 3, 10, 1000, 1_000_000, u32::MAX as u64, u64::MAX];

/// How long one request may take before the sweep calls it a hang.
const HANG: Duration = Duration::from_secs(60);

/// What a request answered, when it is not what a client may expect of a schema-valid number.
fn defect(entry: &Entry, body: &Value) -> Option<String> {
    let bytes = serde_json::to_vec(body).unwrap();
    let run = catch_unwind(AssertUnwindSafe(|| {
        (entry.execute)(&bytes, Instant::now() + HANG, Default::default())
    }));
    match run {
        Err(_) => Some("panicked".to_owned()),
        Ok(Ok(executed)) => {
            let v: Value = match serde_json::from_slice(&executed.body) {
                Ok(v) => v,
                Err(e) => return Some(format!("unreadable success body: {e}")),
            };
            catch_unwind(|| assert_all_finite(&v, ""))
                .err()
                .map(|_| "a non-finite number in a success".to_owned())
        }
        Ok(Err(Failure::Invalid(_))) => None,
        Ok(Err(Failure::Calc(
            CalcError::Impossible { .. } | CalcError::NotConverged { .. } | CalcError::Stopped(_),
        ))) => None,
        Ok(Err(Failure::Unreadable(detail))) => Some(format!("400: {detail}")),
        Ok(Err(Failure::Calc(CalcError::DeadlineExceeded))) => {
            Some(format!("no answer within {HANG:?}"))
        }
        Ok(Err(Failure::Calc(CalcError::Internal(cause)))) => Some(format!("500: {cause}")),
    }
}

#[test]
fn every_number_from_the_smallest_double_to_the_largest_is_answered() {
    let doc: Value = serde_json::from_str(&stribeck::http::openapi::document_json()).unwrap();
    let far = Instant::now() + Duration::from_secs(600);
    let mut defects = Vec::new();
    let mut checked = 0;
    let mut slowest = (Duration::ZERO, String::new());
    for entry in REGISTRY {
        let (input, _) = (entry.schema_names)();
        let schema = serde_json::json!({ "$ref": format!("#/components/schemas/{input}") });
        let mut swept: Vec<String> = Vec::new();
        for example in bodies(&doc, entry, &schema, far) {
            let mut numbers = Vec::new();
            collect(&doc, &schema, &example, "", &mut numbers);
            for n in numbers {
                if swept.contains(&n.pointer) {
                    continue;
                }
                swept.push(n.pointer.clone());
                let ladder: &[f64] = match entry.costing {
                    Costing::Light => &LADDER,
                    Costing::Numerical => &NUMERICAL_LADDER,
                };
                let values: Vec<Value> = if n.integer {
                    COUNTS.iter().map(|&c| serde_json::json!(c)).collect()
                } else {
                    ladder.iter().map(|&x| serde_json::json!(x)).collect()
                };
                for value in values {
                    let mut body = example.clone();
                    set(&mut body, &n.pointer, value.clone());
                    checked += 1;
                    let started = Instant::now();
                    if let Some(what) = defect(entry, &body) {
                        defects.push(format!("{} {} = {value}: {what}", entry.path, n.pointer));
                    }
                    let took = started.elapsed();
                    if took > slowest.0 {
                        slowest = (took, format!("{} {} = {value}", entry.path, n.pointer));
                    }
                }
            }
        }
    }
    eprintln!(
        "swept {checked} values; slowest {:?} at {}",
        slowest.0, slowest.1
    );
    assert!(checked > 5000, "only {checked} values swept");
    assert!(
        defects.is_empty(),
        "{} of {checked} swept values answered wrongly:\n{}",
        defects.len(),
        defects.join("\n")
    );
}
