//! The OpenAPI document's numeric bounds and the rooms' validation agree (issue 12, item 4: the
//! schema said `seals.f1` ≥ 0.1 while 0.05 was accepted). For every registered example, every
//! number in it whose schema carries `minimum`, `maximum` or an exclusive bound is moved just
//! outside the bound: the room must refuse it with a 422 that points at that field. A bound the
//! document states and the room ignores is a contract a generated client cannot trust.

use serde_json::Value;
use std::time::Instant;

use stribeck::calc::{CalcError, Entry, Failure, REGISTRY};

/// One number of an example, its pointer, whether the schema says integer, and the values just
/// outside its schema's bounds (none: unbounded).
pub(crate) struct Bounded {
    pub(crate) pointer: String,
    pub(crate) integer: bool,
    pub(crate) outside: Vec<f64>,
}

/// Follow a `$ref` to its component.
fn resolve<'a>(doc: &'a Value, schema: &'a Value) -> &'a Value {
    match schema.get("$ref").and_then(Value::as_str) {
        Some(r) => {
            let name = r.trim_start_matches("#/components/schemas/");
            resolve(doc, &doc["components"]["schemas"][name])
        }
        None => schema,
    }
}

/// The sub-schemas a value may match: the schema itself, its `allOf` parts, and of its
/// `oneOf`/`anyOf` variants (an `Option<T>` is `oneOf [null, T]`) those the value fits.
fn alternatives<'a>(doc: &'a Value, schema: &'a Value, value: &Value) -> Vec<&'a Value> {
    let schema = resolve(doc, schema);
    let mut out = vec![schema];
    if let Some(parts) = schema.get("allOf").and_then(Value::as_array) {
        for p in parts {
            out.extend(alternatives(doc, p, value));
        }
    }
    for key in ["oneOf", "anyOf"] {
        if let Some(variants) = schema.get(key).and_then(Value::as_array) {
            let fitting: Vec<&Value> = variants.iter().filter(|v| fits(doc, v, value)).collect();
            if fitting.len() == 1 {
                out.extend(alternatives(doc, fitting[0], value));
            }
        }
    }
    out
}

/// Whether `value` can be an instance of `schema`, judged by its JSON kind, and for an object
/// by its keys (all declared) and any single-valued `enum`/`const` tag.
fn fits(doc: &Value, schema: &Value, value: &Value) -> bool {
    let schema = resolve(doc, schema);
    if schema.get("oneOf").is_some() || schema.get("allOf").is_some() {
        return alternatives(doc, schema, value).len() > 1;
    }
    let kinds: Vec<&str> = match &schema["type"] {
        Value::String(t) => vec![t.as_str()],
        Value::Array(ts) => ts.iter().filter_map(Value::as_str).collect(),
        _ => return true,
    };
    let kind = match value {
        Value::Null => "null",
        Value::Bool(_) => "boolean",
        Value::Number(n) if n.is_i64() || n.is_u64() => {
            if kinds.contains(&"integer") {
                "integer"
            } else {
                "number"
            }
        }
        Value::Number(_) => "number",
        Value::String(_) => "string",
        Value::Array(_) => "array",
        Value::Object(_) => "object",
    };
    if !kinds.contains(&kind) {
        return false;
    }
    match (value, schema.get("properties").and_then(Value::as_object)) {
        (Value::Object(fields), Some(props)) => fields.iter().all(|(k, v)| {
            props.get(k).is_some_and(|p| {
                let p = resolve(doc, p);
                match (p.get("enum").and_then(Value::as_array), p.get("const")) {
                    (Some(options), _) if options.len() == 1 => &options[0] == v,
                    (_, Some(c)) => c == v,
                    _ => true,
                }
            })
        }),
        _ => true,
    }
}

/// Every number in `value`, whose schema is `schema`, under `pointer`, with its bounds.
pub(crate) fn collect(
    doc: &Value,
    schema: &Value,
    value: &Value,
    pointer: &str,
    out: &mut Vec<Bounded>,
) {
    for s in alternatives(doc, schema, value) {
        match value {
            Value::Number(n) => {
                let x = n.as_f64().unwrap();
                let integer = s["type"] == "integer"
                    || s["type"]
                        .as_array()
                        .is_some_and(|ts| ts.iter().any(|t| t == "integer"));
                let step = |b: f64| {
                    if integer {
                        1.0
                    } else {
                        (b.abs() * 1e-6).max(1e-300)
                    }
                };
                let mut outside = Vec::new();
                if let Some(m) = s.get("minimum").and_then(Value::as_f64) {
                    outside.push(m - step(m));
                }
                if let Some(m) = s.get("exclusiveMinimum").and_then(Value::as_f64) {
                    outside.push(m);
                }
                if let Some(m) = s.get("maximum").and_then(Value::as_f64) {
                    outside.push(m + step(m));
                }
                if let Some(m) = s.get("exclusiveMaximum").and_then(Value::as_f64) {
                    outside.push(m);
                }
                match out.iter_mut().find(|b| b.pointer == pointer) {
                    Some(b) => {
                        b.integer |= integer;
                        b.outside.extend(outside);
                    }
                    None if x.is_finite() => out.push(Bounded {
                        pointer: pointer.to_owned(),
                        integer,
                        outside,
                    }),
                    None => {}
                }
            }
            Value::Object(fields) => {
                if let Some(props) = s.get("properties").and_then(Value::as_object) {
                    for (k, v) in fields {
                        if let Some(p) = props.get(k) {
                            collect(doc, p, v, &format!("{pointer}/{k}"), out);
                        }
                    }
                }
            }
            Value::Array(items) => {
                if let Some(item) = s.get("items") {
                    for (i, v) in items.iter().enumerate() {
                        collect(doc, item, v, &format!("{pointer}/{i}"), out);
                    }
                }
            }
            _ => {}
        }
    }
}

/// The example a schema gives for a property: its own, its component's (an `Option<T>` is
/// `oneOf [null, T]`), or an object of its fields' examples.
fn example_of(doc: &Value, prop: &Value) -> Option<Value> {
    let prop = resolve(doc, prop);
    if let Some(e) = prop.get("example") {
        return Some(e.clone());
    }
    if let Some(props) = prop.get("properties").and_then(Value::as_object) {
        // An object without an example of its own: its fields' examples.
        let fields: serde_json::Map<String, Value> = props
            .iter()
            .filter_map(|(k, p)| example_of(doc, p).map(|e| (k.clone(), e)))
            .collect();
        return (!fields.is_empty()).then_some(Value::Object(fields));
    }
    prop.get("oneOf")?
        .as_array()?
        .iter()
        .find_map(|v| example_of(doc, v))
}

/// Fields the example leaves out, as (object pointer, name, the schema's example value), at
/// every object of `value`: optional inputs get their bounds checked too.
fn absent(
    doc: &Value,
    schema: &Value,
    value: &Value,
    pointer: &str,
    out: &mut Vec<(String, String, Value)>,
) {
    for s in alternatives(doc, schema, value) {
        if let (Value::Object(fields), Some(props)) =
            (value, s.get("properties").and_then(Value::as_object))
        {
            for (k, p) in props {
                match fields.get(k) {
                    Some(v) => absent(doc, p, v, &format!("{pointer}/{k}"), out),
                    None => {
                        if let Some(e) = example_of(doc, p) {
                            out.push((pointer.to_owned(), k.clone(), e));
                        }
                    }
                }
            }
        }
    }
}

/// The example, and the example with each field it leaves out that the room then accepts.
pub(crate) fn bodies(doc: &Value, entry: &Entry, schema: &Value, far: Instant) -> Vec<Value> {
    let example: Value = serde_json::from_str(entry.example).unwrap();
    let mut missing = Vec::new();
    absent(doc, schema, &example, "", &mut missing);
    let mut out = vec![example.clone()];
    for (at, key, value) in missing {
        let mut body = example.clone();
        body.pointer_mut(&at).unwrap()[&key] = value;
        let bytes = serde_json::to_vec(&body).unwrap();
        if (entry.execute)(&bytes, far, Default::default()).is_ok() {
            out.push(body);
        }
    }
    out
}

pub(crate) fn set(value: &mut Value, pointer: &str, x: impl Into<Value>) {
    *value.pointer_mut(pointer).unwrap() = x.into();
}

/// Where a refusal points, if it is a 422 that points anywhere.
fn pointers(failure: &Failure) -> Vec<String> {
    match failure {
        Failure::Invalid(errors) => errors.iter().map(|e| e.pointer.clone()).collect(),
        Failure::Calc(CalcError::Impossible { pointer, .. }) => vec![pointer.clone()],
        _ => Vec::new(),
    }
}

#[test]
fn every_bound_the_document_states_is_enforced() {
    let doc: Value = serde_json::from_str(&stribeck::http::openapi::document_json()).unwrap();
    let far = Instant::now() + std::time::Duration::from_secs(600);
    let mut mismatches = Vec::new();
    let mut checked = 0;
    for entry in REGISTRY {
        let (input, _) = (entry.schema_names)();
        let schema = serde_json::json!({ "$ref": format!("#/components/schemas/{input}") });
        let mut bounded = Vec::new();
        for example in bodies(&doc, entry, &schema, far) {
            let mut found = Vec::new();
            collect(&doc, &schema, &example, "", &mut found);
            for b in found.into_iter().filter(|b| !b.outside.is_empty()) {
                if !bounded
                    .iter()
                    .any(|(_, c): &(Value, Bounded)| c.pointer == b.pointer)
                {
                    bounded.push((example.clone(), b));
                }
            }
        }
        for (example, b) in bounded {
            for x in &b.outside {
                let mut body = example.clone();
                set(&mut body, &b.pointer, *x);
                checked += 1;
                let bytes = serde_json::to_vec(&body).unwrap();
                match (entry.execute)(&bytes, far, Default::default()) {
                    // At the field, or at a union it sits in (an untagged enum's parse error
                    // points at the enum: `/fidelity` for `/fidelity/grid/0`).
                    Err(f)
                        if pointers(&f).iter().any(|p| {
                            p == &b.pointer
                                || (!p.is_empty() && b.pointer.starts_with(&format!("{p}/")))
                        }) => {}
                    Err(f) => mismatches.push(format!(
                        "{} {} = {x}: refused elsewhere: {:?}",
                        entry.path,
                        b.pointer,
                        pointers(&f)
                    )),
                    Ok(_) => {
                        mismatches.push(format!("{} {} = {x}: accepted", entry.path, b.pointer))
                    }
                }
            }
        }
    }
    assert!(checked > 200, "only {checked} bounds found");
    assert!(
        mismatches.is_empty(),
        "{} of {checked} out-of-bound values not refused at their field:\n{}",
        mismatches.len(),
        mismatches.join("\n")
    );
}

/// The numeric fields of `schema` (a component named `at`) with a bound missing on a side
/// (issue 12, item 2: every input gets a physical range, documented).
fn unranged(doc: &Value, schema: &Value, at: &str, seen: &mut Vec<String>, out: &mut Vec<String>) {
    if let Some(r) = schema.get("$ref").and_then(Value::as_str) {
        let name = r.trim_start_matches("#/components/schemas/");
        if !seen.iter().any(|s| s == name) {
            seen.push(name.to_owned());
            unranged(doc, &doc["components"]["schemas"][name], name, seen, out);
        }
        return;
    }
    for key in ["oneOf", "anyOf", "allOf"] {
        for v in schema
            .get(key)
            .and_then(Value::as_array)
            .into_iter()
            .flatten()
        {
            unranged(doc, v, at, seen, out);
        }
    }
    let kinds: Vec<&str> = match &schema["type"] {
        Value::String(t) => vec![t.as_str()],
        Value::Array(ts) => ts.iter().filter_map(Value::as_str).collect(),
        _ => Vec::new(),
    };
    if kinds.iter().any(|k| *k == "number" || *k == "integer") {
        let has = |keys: [&str; 2]| keys.iter().any(|k| schema.get(*k).is_some());
        if !(has(["minimum", "exclusiveMinimum"]) && has(["maximum", "exclusiveMaximum"])) {
            out.push(at.to_owned());
        }
    }
    for (k, p) in schema
        .get("properties")
        .and_then(Value::as_object)
        .into_iter()
        .flatten()
    {
        unranged(doc, p, &format!("{at}/{k}"), seen, out);
    }
    if let Some(item) = schema.get("items").filter(|i| i.is_object()) {
        unranged(doc, item, &format!("{at}[]"), seen, out);
    }
}

#[test]
fn every_numeric_input_documents_its_range() {
    let doc: Value = serde_json::from_str(&stribeck::http::openapi::document_json()).unwrap();
    let (mut seen, mut found) = (Vec::new(), Vec::new());
    for entry in REGISTRY {
        let (input, _) = (entry.schema_names)();
        let root = serde_json::json!({ "$ref": format!("#/components/schemas/{input}") });
        unranged(&doc, &root, "", &mut seen, &mut found);
    }
    found.sort();
    found.dedup();
    assert!(
        found.is_empty(),
        "numeric inputs without a documented range: {found:?}"
    );
}
