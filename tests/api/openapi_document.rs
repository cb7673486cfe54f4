//! What the OpenAPI document declares for its users: tags, servers, licence, the headers the
//! server reads and sends, one shared `effects` component, named health and ready schemas, and
//! a 3.0 rendering free of 3.1-only forms.

use std::collections::BTreeSet;

use serde_json::Value;
use stribeck::calc::REGISTRY;
use stribeck::http::openapi::{document_30_json, document_json, TAGS};

fn doc() -> Value {
    serde_json::from_str(&document_json()).unwrap()
}

/// Every operation of the document: (path, method, operation).
fn operations(doc: &Value) -> Vec<(String, String, Value)> {
    let mut ops = Vec::new();
    for (path, item) in doc["paths"].as_object().unwrap() {
        for (method, op) in item.as_object().unwrap() {
            ops.push((path.clone(), method.clone(), op.clone()));
        }
    }
    ops
}

fn is_calculation(path: &str) -> bool {
    REGISTRY.iter().any(|e| e.path == path)
}

#[test]
fn every_operation_has_one_declared_tag_and_every_tag_is_used() {
    let doc = doc();
    let declared: BTreeSet<&str> = doc["tags"]
        .as_array()
        .unwrap()
        .iter()
        .map(|t| {
            let name = t["name"].as_str().unwrap();
            assert!(
                t["description"].as_str().is_some_and(|d| d.len() > 20),
                "tag {name} has no description"
            );
            name
        })
        .collect();
    assert_eq!(declared.len(), TAGS.len());
    let mut used = BTreeSet::new();
    for (path, method, op) in operations(&doc) {
        let tags: Vec<&str> = op["tags"]
            .as_array()
            .unwrap_or_else(|| panic!("{method} {path} has no tags"))
            .iter()
            .map(|t| t.as_str().unwrap())
            .collect();
        assert_eq!(tags.len(), 1, "{method} {path}: {tags:?}");
        assert!(
            declared.contains(tags[0]),
            "{method} {path}: tag {} is not declared",
            tags[0]
        );
        if is_calculation(&path) {
            assert_eq!(path.split('/').nth(2), Some(tags[0]), "{path}");
        } else {
            assert_eq!(tags[0], "service", "{path}");
        }
        used.insert(tags[0].to_owned());
    }
    let declared: BTreeSet<String> = declared.into_iter().map(str::to_owned).collect();
    assert_eq!(used, declared, "a declared tag no operation uses");
}

#[test]
fn servers_and_licence_are_declared() {
    let doc = doc();
    let urls: Vec<&str> = doc["servers"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["url"].as_str().unwrap())
        .collect();
    // The relative server first: tools that fetched the document from a server stay on it.
    assert_eq!(urls, ["/", "http://127.0.0.1:8080"]);
    assert_eq!(doc["info"]["license"]["name"], env!("CARGO_PKG_LICENSE"));
    assert_eq!(doc["info"]["license"]["name"], "Apache-2.0");
    assert!(doc["info"]["license"]["url"]
        .as_str()
        .unwrap()
        .contains("apache.org/licenses/LICENSE-2.0"));
}

/// The headers the server reads (`x-stribeck-deadline-ms` on calculations, `x-request-id`
/// everywhere) and sends (`x-request-id` on every response, `Retry-After` on a shed 503).
#[test]
fn the_headers_the_server_reads_and_sends_are_declared() {
    let doc = doc();
    for (path, method, op) in operations(&doc) {
        let params: BTreeSet<(&str, &str)> = op["parameters"]
            .as_array()
            .unwrap_or_else(|| panic!("{method} {path} declares no parameters"))
            .iter()
            .map(|p| {
                assert_eq!(p["required"], false, "{path}: {p}");
                (p["in"].as_str().unwrap(), p["name"].as_str().unwrap())
            })
            .collect();
        let mut want = BTreeSet::from([("header", "x-request-id")]);
        if is_calculation(&path) {
            want.insert(("header", "x-stribeck-deadline-ms"));
        }
        assert_eq!(params, want, "{method} {path}");
        for (status, response) in op["responses"].as_object().unwrap() {
            let headers = response["headers"].as_object();
            assert!(
                headers.is_some_and(|h| h.contains_key("x-request-id")),
                "{path} {status}: no x-request-id"
            );
            let retry = headers.unwrap().get("Retry-After");
            if status == "503" && is_calculation(&path) {
                let retry = retry.unwrap_or_else(|| panic!("{path} 503: no Retry-After"));
                assert_eq!(retry["schema"]["type"], "integer");
            } else {
                // /ready's 503 (draining) sends none, and nothing else is shed.
                assert!(retry.is_none(), "{path} {status} declares Retry-After");
            }
        }
    }
    let deadline = doc["paths"]["/v1/journal-bearings/plain"]["post"]["parameters"]
        .as_array()
        .unwrap()
        .iter()
        .find(|p| p["name"] == "x-stribeck-deadline-ms")
        .unwrap()
        .clone();
    assert_eq!(deadline["schema"]["type"], "integer");
    assert_eq!(deadline["schema"]["minimum"], 0);
}

/// Every error answer names the one `Problem` schema under `application/problem+json`, so a
/// generated client can type its errors.
#[test]
fn every_error_response_is_a_typed_problem() {
    let doc = doc();
    for (path, _, op) in operations(&doc) {
        for (status, response) in op["responses"].as_object().unwrap() {
            if status.starts_with('2') {
                continue;
            }
            assert_eq!(
                response["content"]["application/problem+json"]["schema"]["$ref"],
                "#/components/schemas/Problem",
                "{path} {status}"
            );
        }
    }
}

/// The envelope's `effects` is one component for all calculations, with one typed property per
/// effect any calculation reports.
#[test]
fn every_envelope_shares_one_effects_component() {
    let doc = doc();
    let schemas = doc["components"]["schemas"].as_object().unwrap();
    let mut envelopes = 0;
    for (name, schema) in schemas {
        if let Some(effects) = schema.pointer("/properties/effects") {
            if name.ends_with("Envelope") {
                envelopes += 1;
                assert_eq!(
                    effects,
                    &serde_json::json!({"$ref": "#/components/schemas/EffectDecisions"}),
                    "{name}"
                );
            }
        }
    }
    assert_eq!(envelopes, REGISTRY.len());
    let decisions = &schemas["EffectDecisions"];
    let known: BTreeSet<&str> = REGISTRY
        .iter()
        .flat_map(|e| e.effects.iter().copied())
        .collect();
    let props = decisions["properties"].as_object().unwrap();
    let declared: BTreeSet<&str> = props.keys().map(String::as_str).collect();
    assert_eq!(declared, known);
    for (effect, prop) in props {
        assert_eq!(prop["$ref"], "#/components/schemas/Decision", "{effect}");
    }
    assert!(decisions.get("required").is_none());
}

#[test]
fn health_and_ready_answer_named_schemas() {
    let doc = doc();
    for (path, schema) in [("/health", "HealthStatus"), ("/ready", "ReadyStatus")] {
        assert_eq!(
            doc["paths"][path]["get"]["responses"]["200"]["content"]["application/json"]["schema"]
                ["$ref"],
            format!("#/components/schemas/{schema}")
        );
        assert_eq!(
            doc["components"]["schemas"][schema]["required"],
            serde_json::json!(["status"])
        );
    }
}

/// The 3.0 rendering: version 3.0.3, no 3.1-only schema forms left anywhere, and the same
/// paths, operations and schema names as the 3.1 document.
#[test]
fn the_30_rendering_has_no_31_forms() {
    let doc30: Value = serde_json::from_str(&document_30_json()).unwrap();
    let doc31 = doc();
    assert_eq!(doc30["openapi"], "3.0.3");
    let mut left = Vec::new();
    find_31_forms(&doc30, "", &mut left);
    assert!(left.is_empty(), "3.1 forms in the 3.0 rendering: {left:?}");
    let keys = |d: &Value, at: &str| -> Vec<String> {
        d.pointer(at)
            .unwrap()
            .as_object()
            .unwrap()
            .keys()
            .cloned()
            .collect()
    };
    assert_eq!(keys(&doc30, "/paths"), keys(&doc31, "/paths"));
    assert_eq!(
        keys(&doc30, "/components/schemas"),
        keys(&doc31, "/components/schemas")
    );
    // A nullable number of the 3.1 document, as 3.0 spells it.
    let residual = &doc30["components"]["schemas"]["Problem"]["properties"]["residual"];
    assert_eq!(residual["type"], "number");
    assert_eq!(residual["nullable"], true);
}

/// Where `v` still uses a form 3.0 lacks (examples are data, not schemas: skipped).
fn find_31_forms(v: &Value, at: &str, out: &mut Vec<String>) {
    match v {
        Value::Object(map) => {
            if map.get("type").is_some_and(|t| t.is_array() || t == "null") {
                out.push(format!("{at}: type {}", map["type"]));
            }
            for bound in ["exclusiveMinimum", "exclusiveMaximum"] {
                if map.get(bound).is_some_and(Value::is_number) {
                    out.push(format!("{at}: numeric {bound}"));
                }
            }
            if map.contains_key("const") {
                out.push(format!("{at}: const"));
            }
            for (k, child) in map {
                if k != "example" {
                    find_31_forms(child, &format!("{at}/{k}"), out);
                }
            }
        }
        Value::Array(items) => items
            .iter()
            .enumerate()
            .for_each(|(i, x)| find_31_forms(x, &format!("{at}/{i}"), out)),
        _ => {}
    }
}
