//! The OpenAPI 3.0 rendering of the 3.1 document, for generators that read only 3.0
//! (progenitor among them: a 3.1 `type: ["number", "null"]` stops it).
//!
//! JSON Schema 2020-12 (3.1) and the 3.0 schema dialect differ in a handful of keywords; this
//! rewrites each one the document uses and refuses any 3.1 form it cannot express, so a new
//! construct in the document fails the drift test instead of slipping through half-converted:
//!
//! | 3.1 | 3.0 |
//! |---|---|
//! | `type: [T, "null"]` | `type: T, nullable: true` |
//! | `oneOf`/`anyOf` with a `{type: "null"}` branch | the other branches, `nullable: true` (one branch: `allOf: [it]`) |
//! | `exclusiveMinimum: x` (a number) | `minimum: x, exclusiveMinimum: true` (and the same for maximum) |
//! | `const: v` | `enum: [v]` |
//! | `examples: [a, …]` | `example: a` |
//! | `license.identifier` | dropped (3.0 has only `name` and `url`) |

use serde_json::{Map, Value};

/// The version string the rendering declares.
pub const VERSION: &str = "3.0.3";

/// A 3.1 construct with no 3.0 form, and where it is.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{pointer}: {what} has no OpenAPI 3.0 form")]
pub struct Untranslatable {
    pub pointer: String,
    pub what: String,
}

/// The 3.0 rendering of a 3.1 document.
pub fn convert(document: &Value) -> Result<Value, Untranslatable> {
    let mut doc = document.clone();
    doc["openapi"] = Value::from(VERSION);
    if let Some(license) = doc
        .pointer_mut("/info/license")
        .and_then(Value::as_object_mut)
    {
        license.remove("identifier");
    }
    if let Some(components) = doc
        .pointer_mut("/components/schemas")
        .and_then(Value::as_object_mut)
    {
        for (name, schema) in components.iter_mut() {
            schemas_within(schema, &format!("/components/schemas/{name}"))?;
        }
    }
    if let Some(paths) = doc.get_mut("paths").and_then(Value::as_object_mut) {
        for (path, item) in paths.iter_mut() {
            let at = format!("/paths/{}", path.replace('~', "~0").replace('/', "~1"));
            walk_schema_holders(item, &at)?;
        }
    }
    Ok(doc)
}

/// Below a path item, every `schema` (of a parameter, a body, a response or a header) is a
/// schema; everything else is OpenAPI structure, left as it is.
fn walk_schema_holders(value: &mut Value, at: &str) -> Result<(), Untranslatable> {
    match value {
        Value::Object(map) => {
            for (key, child) in map.iter_mut() {
                let here = format!("{at}/{key}");
                if key == "schema" {
                    schemas_within(child, &here)?;
                } else if key != "example" && key != "examples" {
                    walk_schema_holders(child, &here)?;
                }
            }
            Ok(())
        }
        Value::Array(items) => items
            .iter_mut()
            .enumerate()
            .try_for_each(|(i, item)| walk_schema_holders(item, &format!("{at}/{i}"))),
        _ => Ok(()),
    }
}

/// Keywords whose value is one schema, a list of schemas, or a map of names to schemas.
const ONE_SCHEMA: &[&str] = &["items", "not", "additionalProperties"];
const SCHEMA_LISTS: &[&str] = &["oneOf", "anyOf", "allOf"];
const SCHEMA_MAPS: &[&str] = &["properties"];

/// Rewrite `schema` and every schema inside it.
fn schemas_within(schema: &mut Value, at: &str) -> Result<(), Untranslatable> {
    let Some(map) = schema.as_object_mut() else {
        return Ok(()); // `additionalProperties: true` and the like
    };
    lift_null_branches(map, at)?;
    for key in ONE_SCHEMA {
        if let Some(child) = map.get_mut(*key) {
            schemas_within(child, &format!("{at}/{key}"))?;
        }
    }
    for key in SCHEMA_LISTS {
        if let Some(Value::Array(children)) = map.get_mut(*key) {
            for (i, child) in children.iter_mut().enumerate() {
                schemas_within(child, &format!("{at}/{key}/{i}"))?;
            }
        }
    }
    for key in SCHEMA_MAPS {
        if let Some(Value::Object(children)) = map.get_mut(*key) {
            for (name, child) in children.iter_mut() {
                schemas_within(child, &format!("{at}/{key}/{name}"))?;
            }
        }
    }
    rewrite(map, at)
}

/// Turn a `oneOf`/`anyOf` with a `{type: "null"}` branch into its other branches and
/// `nullable: true`. Runs before the branches are visited, so the null branch is gone by then.
fn lift_null_branches(map: &mut Map<String, Value>, at: &str) -> Result<(), Untranslatable> {
    for key in ["oneOf", "anyOf"] {
        let Some(Value::Array(branches)) = map.get(key).cloned() else {
            continue;
        };
        let is_null = |b: &Value| b.get("type").is_some_and(|t| t == "null");
        if !branches.iter().any(is_null) {
            continue;
        }
        let mut rest: Vec<Value> = branches.iter().filter(|b| !is_null(b)).cloned().collect();
        map.remove(key);
        match rest.len() {
            0 => {
                return Err(Untranslatable {
                    pointer: at.to_owned(),
                    what: format!("a `{key}` of nothing but null"),
                })
            }
            1 => {
                // A lone `$ref` branch's description would be ignored inside `allOf`: lift it.
                if let Some(description) = rest[0].as_object_mut().and_then(|b| {
                    b.contains_key("$ref")
                        .then(|| b.remove("description"))
                        .flatten()
                }) {
                    map.entry("description").or_insert(description);
                }
                map.insert("allOf".to_owned(), Value::Array(rest));
            }
            _ => {
                map.insert(key.to_owned(), Value::Array(rest));
            }
        }
        map.insert("nullable".to_owned(), Value::Bool(true));
    }
    Ok(())
}

/// Rewrite one schema object's own keywords (its children are done already).
fn rewrite(map: &mut Map<String, Value>, at: &str) -> Result<(), Untranslatable> {
    let untranslatable = |what: String| Untranslatable {
        pointer: at.to_owned(),
        what,
    };
    if let Some(Value::Array(types)) = map.get("type") {
        let nullable = types.iter().any(|t| t == "null");
        let others: Vec<Value> = types.iter().filter(|t| *t != "null").cloned().collect();
        match others.as_slice() {
            [single] => {
                map.insert("type".to_owned(), single.clone());
                if nullable {
                    map.insert("nullable".to_owned(), Value::Bool(true));
                }
            }
            _ => {
                return Err(untranslatable(format!(
                    "`type: {}`",
                    Value::Array(types.clone())
                )))
            }
        }
    }
    if map.get("type").is_some_and(|t| t == "null") {
        return Err(untranslatable(
            "`type: \"null\"` outside a oneOf/anyOf".to_owned(),
        ));
    }
    for (exclusive, inclusive) in [
        ("exclusiveMinimum", "minimum"),
        ("exclusiveMaximum", "maximum"),
    ] {
        let Some(bound) = map.get(exclusive).filter(|b| b.is_number()).cloned() else {
            continue;
        };
        let tighter_inclusive = map.get(inclusive).and_then(Value::as_f64).is_some_and(|i| {
            let b = bound.as_f64().unwrap_or(f64::NAN);
            if inclusive == "minimum" {
                i > b
            } else {
                i < b
            }
        });
        if tighter_inclusive {
            map.remove(exclusive);
        } else {
            map.insert(inclusive.to_owned(), bound);
            map.insert(exclusive.to_owned(), Value::Bool(true));
        }
    }
    if let Some(value) = map.remove("const") {
        map.insert("enum".to_owned(), Value::Array(vec![value]));
    }
    if let Some(examples) = map.remove("examples") {
        match examples {
            Value::Array(list) => {
                if let Some(first) = list.into_iter().next() {
                    map.entry("example").or_insert(first);
                }
            }
            other => return Err(untranslatable(format!("`examples: {other}`"))),
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use serde_json::json;

    use super::*;

    /// A document with one schema `s`, converted; the converted schema.
    fn converted(s: Value) -> Value {
        let doc = json!({"openapi": "3.1.0", "components": {"schemas": {"S": s}}});
        convert(&doc).unwrap()["components"]["schemas"]["S"].clone()
    }

    #[test]
    fn a_nullable_type_becomes_nullable() {
        assert_eq!(
            converted(json!({"type": ["number", "null"], "format": "double"})),
            json!({"type": "number", "format": "double", "nullable": true})
        );
        assert_eq!(
            converted(json!({"type": ["string"]})),
            json!({"type": "string"})
        );
    }

    #[test]
    fn a_null_branch_becomes_nullable_and_its_description_is_kept() {
        assert_eq!(
            converted(json!({"oneOf": [
                {"type": "null"},
                {"$ref": "#/components/schemas/T", "description": "the T"}
            ]})),
            json!({"allOf": [{"$ref": "#/components/schemas/T"}], "description": "the T", "nullable": true})
        );
        assert_eq!(
            converted(
                json!({"anyOf": [{"type": "null"}, {"type": "integer"}, {"type": "string"}]})
            ),
            json!({"anyOf": [{"type": "integer"}, {"type": "string"}], "nullable": true})
        );
    }

    #[test]
    fn numeric_exclusive_bounds_become_boolean() {
        assert_eq!(
            converted(json!({"type": "number", "exclusiveMinimum": 0.0, "exclusiveMaximum": 1.0})),
            json!({"type": "number", "minimum": 0.0, "exclusiveMinimum": true, "maximum": 1.0, "exclusiveMaximum": true})
        );
        // An inclusive bound that is already tighter wins.
        assert_eq!(
            converted(json!({"type": "number", "minimum": 2.0, "exclusiveMinimum": 0.0})),
            json!({"type": "number", "minimum": 2.0})
        );
    }

    #[test]
    fn const_and_examples_take_their_30_forms() {
        assert_eq!(
            converted(json!({"const": "ok", "examples": ["ok", "fine"]})),
            json!({"enum": ["ok"], "example": "ok"})
        );
    }

    #[test]
    fn nested_schemas_are_rewritten_but_examples_are_not() {
        let s = converted(json!({
            "type": "object",
            "properties": {"a": {"type": "array", "items": {"type": ["integer", "null"]}}},
            "additionalProperties": {"type": ["boolean", "null"]},
            "example": {"type": ["data", "null"]}
        }));
        assert_eq!(
            s["properties"]["a"]["items"],
            json!({"type": "integer", "nullable": true})
        );
        assert_eq!(
            s["additionalProperties"],
            json!({"type": "boolean", "nullable": true})
        );
        assert_eq!(s["example"], json!({"type": ["data", "null"]}));
    }

    #[test]
    fn path_schemas_are_rewritten_and_the_version_is_30() {
        let doc = json!({
            "openapi": "3.1.0",
            "info": {"title": "t", "version": "1", "license": {"name": "Apache-2.0", "identifier": "Apache-2.0"}},
            "paths": {"/a": {"post": {"parameters": [
                {"name": "n", "in": "header", "schema": {"type": "integer", "exclusiveMinimum": 0}}
            ]}}}
        });
        let out = convert(&doc).unwrap();
        assert_eq!(out["openapi"], VERSION);
        assert_eq!(out["info"]["license"], json!({"name": "Apache-2.0"}));
        assert_eq!(
            out["paths"]["/a"]["post"]["parameters"][0]["schema"],
            json!({"type": "integer", "minimum": 0, "exclusiveMinimum": true})
        );
    }

    #[test]
    fn forms_without_a_30_equivalent_are_refused_with_their_place() {
        let doc = json!({"components": {"schemas": {"S": {"properties": {"x": {"type": ["integer", "string"]}}}}}});
        let err = convert(&doc).unwrap_err();
        assert_eq!(err.pointer, "/components/schemas/S/properties/x");
        let doc = json!({"components": {"schemas": {"S": {"type": "null"}}}});
        assert!(convert(&doc).is_err());
    }
}
