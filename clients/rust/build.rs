//! Generate the client from `openapi/openapi-3.0.json` (progenitor reads OpenAPI 3.0 only).
//!
//! progenitor types a response body only when its media type is `application/json`
//! (progenitor-impl 0.15, `method.rs`); any other body, `application/problem+json` included,
//! comes back as raw bytes. The service's errors are `application/problem+json`, which is JSON,
//! so the document handed to progenitor names those bodies `application/json`: every 4xx/5xx
//! then decodes as the typed `types::Problem`. The committed document is left as the server
//! answers. Nothing else is changed.

use std::path::Path;

const SPEC: &str = "../../openapi/openapi-3.0.json";

fn main() {
    println!("cargo:rerun-if-changed={SPEC}");
    let text = std::fs::read_to_string(SPEC).unwrap_or_else(|e| panic!("{SPEC}: {e}"));
    let mut doc: serde_json::Value = serde_json::from_str(&text).expect("the document is JSON");
    problem_bodies_as_json(&mut doc);
    let spec: openapiv3::OpenAPI = serde_json::from_value(doc).expect("an OpenAPI 3.0 document");
    let mut generator = progenitor::Generator::default();
    let tokens = generator
        .generate_tokens(&spec)
        .unwrap_or_else(|e| panic!("progenitor: {e}"));
    let ast = syn::parse2(tokens).expect("progenitor's output parses");
    let out = Path::new(&std::env::var("OUT_DIR").expect("cargo sets OUT_DIR")).join("codegen.rs");
    std::fs::write(&out, prettyplease::unparse(&ast)).expect("OUT_DIR is writable");
}

/// Rename every response's `application/problem+json` content to `application/json`.
fn problem_bodies_as_json(doc: &mut serde_json::Value) {
    let Some(paths) = doc.get_mut("paths").and_then(|p| p.as_object_mut()) else {
        return;
    };
    for item in paths.values_mut() {
        for op in item
            .as_object_mut()
            .into_iter()
            .flat_map(|i| i.values_mut())
        {
            let responses = op.get_mut("responses").and_then(|r| r.as_object_mut());
            for response in responses.into_iter().flat_map(|r| r.values_mut()) {
                let content = response.get_mut("content").and_then(|c| c.as_object_mut());
                if let Some(content) = content {
                    if let Some(problem) = content.remove("application/problem+json") {
                        content.insert("application/json".to_owned(), problem);
                    }
                }
            }
        }
    }
}
