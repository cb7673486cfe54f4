//! The numeric ranges the OpenAPI document states, enforced on every request as sent (issue 12,
//! items 2 and 4: a bound the document states and a room ignores is a contract a generated
//! client cannot trust). A room's own validation runs first and keeps its specific messages;
//! this check then refuses any number outside its schema's `minimum`/`maximum` (inclusive or
//! exclusive), so that a range written once, as a schema attribute, is the range enforced.
//!
//! The walk follows `$ref`, `allOf`, and of a `oneOf`/`anyOf` the one variant the value fits
//! (by JSON kind, declared keys and single-valued tags); where several fit, it does not guess
//! and leaves the value to the room.

use std::collections::BTreeMap;

use serde_json::Value;

use super::FieldError;

/// The numbers of `request` outside the ranges its input schema `input` states, the schema and
/// those it references looked up in `components` (by name, as JSON).
pub fn violations(
    components: &BTreeMap<String, Value>,
    input: &str,
    request: &Value,
) -> Vec<FieldError> {
    let mut out = Vec::new();
    let root = serde_json::json!({ "$ref": format!("#/components/schemas/{input}") });
    walk(components, &root, request, "", &mut out);
    out
}

fn walk(
    doc: &BTreeMap<String, Value>,
    schema: &Value,
    value: &Value,
    pointer: &str,
    out: &mut Vec<FieldError>,
) {
    for s in alternatives(doc, schema, value) {
        match value {
            Value::Number(n) => {
                if let Some(why) = n.as_f64().and_then(|x| outside(s, x)) {
                    if !out.iter().any(|e| e.pointer == pointer) {
                        out.push(FieldError::new(pointer, why));
                    }
                }
            }
            Value::Object(fields) => {
                if let Some(props) = s.get("properties").and_then(Value::as_object) {
                    for (k, v) in fields {
                        if let Some(p) = props.get(k) {
                            walk(doc, p, v, &format!("{pointer}/{k}"), out);
                        }
                    }
                }
            }
            Value::Array(items) => {
                if let Some(item) = s.get("items") {
                    for (i, v) in items.iter().enumerate() {
                        walk(doc, item, v, &format!("{pointer}/{i}"), out);
                    }
                }
            }
            _ => {}
        }
    }
}

/// Why `x` breaks the bounds `schema` states, if it does.
fn outside(schema: &Value, x: f64) -> Option<String> {
    let bound = |key: &str| schema.get(key).and_then(Value::as_f64);
    let below = bound("minimum")
        .filter(|&m| x < m)
        .map(|m| format!("≥ {m:e}"));
    let below = below.or_else(|| {
        bound("exclusiveMinimum")
            .filter(|&m| x <= m)
            .map(|m| format!("> {m:e}"))
    });
    let above = bound("maximum")
        .filter(|&m| x > m)
        .map(|m| format!("≤ {m:e}"));
    let above = above.or_else(|| {
        bound("exclusiveMaximum")
            .filter(|&m| x >= m)
            .map(|m| format!("< {m:e}"))
    });
    let broken = below.or(above)?;
    let range = [
        bound("minimum").map(|m| format!("≥ {m:e}")),
        bound("exclusiveMinimum").map(|m| format!("> {m:e}")),
        bound("maximum").map(|m| format!("≤ {m:e}")),
        bound("exclusiveMaximum").map(|m| format!("< {m:e}")),
    ];
    let range: Vec<String> = range.into_iter().flatten().collect();
    Some(format!(
        "must be {} (the documented range; {broken} is broken), got {x:e}",
        range.join(" and ")
    ))
}

/// Follow a `$ref` to its component.
fn resolve<'a>(doc: &'a BTreeMap<String, Value>, schema: &'a Value) -> &'a Value {
    match schema.get("$ref").and_then(Value::as_str) {
        Some(r) => match doc.get(r.trim_start_matches("#/components/schemas/")) {
            Some(target) => resolve(doc, target),
            None => schema,
        },
        None => schema,
    }
}

/// The sub-schemas a value must meet: the schema itself, its `allOf` parts, and of its
/// `oneOf`/`anyOf` variants the single one the value fits.
fn alternatives<'a>(
    doc: &'a BTreeMap<String, Value>,
    schema: &'a Value,
    value: &Value,
) -> Vec<&'a Value> {
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
            if let [only] = fitting[..] {
                out.extend(alternatives(doc, only, value));
            }
        }
    }
    out
}

/// Whether `value` can be an instance of `schema`, judged by its JSON kind, and for an object
/// by its keys (all declared) and any single-valued `enum`/`const` tag.
fn fits(doc: &BTreeMap<String, Value>, schema: &Value, value: &Value) -> bool {
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
        Value::Number(n) if (n.is_i64() || n.is_u64()) && kinds.contains(&"integer") => "integer",
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

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn a_number_outside_its_documented_range_is_named_with_the_range() {
        // The EHL film's load: 1e-6 … 1e12 N.
        use crate::calc::{contact::ehl::film::EhlFilm, Calculation};
        let mut body: Value = serde_json::from_str(EhlFilm::EXAMPLE).unwrap();
        assert!(violations(
            crate::calc::registry::schema_components(),
            "EhlFilmInput",
            &body
        )
        .is_empty());
        body["load_n"] = json!(2e12);
        let v = violations(
            crate::calc::registry::schema_components(),
            "EhlFilmInput",
            &body,
        );
        assert_eq!(v.len(), 1, "{v:?}");
        assert_eq!(v[0].pointer, "/load_n");
        assert!(v[0].message.contains("≤ 1e12"), "{}", v[0].message);
        // Nested, through a `$ref`: a body's Poisson ratio (−1, 0.5].
        body["load_n"] = json!(10.0);
        body["body1"]["poisson_ratio"] = json!(0.7);
        let v = violations(
            crate::calc::registry::schema_components(),
            "EhlFilmInput",
            &body,
        );
        assert_eq!(v[0].pointer, "/body1/poisson_ratio", "{v:?}");
    }
}
