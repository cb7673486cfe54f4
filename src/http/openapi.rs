//! The OpenAPI 3.1 document, assembled from the registry so it cannot drift from the routes, and
//! the docs UI (swagger-ui, its assets embedded in the binary). Only what the page loads is
//! embedded: the bundle and its stylesheet (1.6 MB), not the release's other bundles and source
//! maps (9 MB more) that serving its whole `dist/` folder would carry.

use std::sync::OnceLock;

use axum::http::header;
use axum::response::{Html, IntoResponse, Redirect, Response};
use axum::routing::get;
use axum::{Json, Router};
use utoipa::openapi::path::{HttpMethod, OperationBuilder, PathItem};
use utoipa::openapi::request_body::RequestBodyBuilder;
use utoipa::openapi::schema::{ArrayBuilder, ObjectBuilder, Ref};
use utoipa::openapi::{
    ComponentsBuilder, ContentBuilder, InfoBuilder, OpenApi, OpenApiBuilder, PathsBuilder, RefOr,
    Required, ResponseBuilder, Schema,
};
use utoipa::{PartialSchema, ToSchema};

use super::meta::{CalculationInfo, CalculationList};
use super::AppState;
use super::Problem;
use crate::calc::{Costing, Entry, FieldError, Warning, REGISTRY};
use crate::effects::{Criterion, Decision, Mode};
use crate::fidelity::{Level, SolverReport};

const DESCRIPTION: &str = "Stribeck: bearing design and lubrication engineering over HTTP.\n\n\
Units are SI and named in each field (`_m`, `_pa`, `_pa_s`, `_c` for °C, `_rpm`). Every calculation answers with \
`{result, effects, solver, warnings}`; errors are `application/problem+json` (RFC 9457) with a JSON pointer per invalid field. \
No response carries NaN, infinity or null: absent values are omitted. A client may lower the server's deadline for one \
request with the `x-stribeck-deadline-ms` header.";

/// The document, built once.
pub fn document() -> &'static OpenApi {
    static DOC: OnceLock<OpenApi> = OnceLock::new();
    DOC.get_or_init(build)
}

/// The committed form: pretty JSON with a trailing newline.
pub fn document_json() -> String {
    let mut s = serde_json::to_string_pretty(document()).expect("the OpenAPI document serialises");
    s.push('\n');
    s
}

/// The docs UI's page: Swagger UI's base layout on `/openapi.json`. It loads the two files
/// below and nothing else (build.rs unpacks exactly those from the vendored release).
const DOCS_PAGE: &str = r##"<!DOCTYPE html>
<html lang="en">
<head>
  <meta charset="UTF-8">
  <title>Stribeck API</title>
  <link rel="stylesheet" type="text/css" href="./swagger-ui.css">
  <style>html { box-sizing: border-box; overflow-y: scroll; } *, *:before, *:after { box-sizing: inherit; } body { margin: 0; background: #fafafa; }</style>
</head>
<body>
  <div id="swagger-ui"></div>
  <script src="./swagger-ui-bundle.js" charset="UTF-8"></script>
  <script>
    window.onload = function () {
      window.ui = SwaggerUIBundle({
        url: "/openapi.json",
        dom_id: "#swagger-ui",
        deepLinking: true,
        presets: [SwaggerUIBundle.presets.apis],
        layout: "BaseLayout",
      });
    };
  </script>
</body>
</html>
"##;
const SWAGGER_UI_BUNDLE: &[u8] = include_bytes!(concat!(env!("OUT_DIR"), "/swagger-ui-bundle.js"));
const SWAGGER_UI_CSS: &[u8] = include_bytes!(concat!(env!("OUT_DIR"), "/swagger-ui.css"));

/// `/docs` (swagger-ui) and `/openapi.json`. `/docs` redirects to `/docs/` so the page's
/// relative links resolve under it.
pub fn docs_router() -> Router<AppState> {
    fn asset(content_type: &'static str, bytes: &'static [u8]) -> Response {
        ([(header::CONTENT_TYPE, content_type)], bytes).into_response()
    }
    Router::new()
        .route("/docs", get(|| async { Redirect::to("/docs/") }))
        .route("/docs/", get(|| async { Html(DOCS_PAGE) }))
        .route(
            "/docs/swagger-ui-bundle.js",
            get(|| async { asset("text/javascript; charset=utf-8", SWAGGER_UI_BUNDLE) }),
        )
        .route(
            "/docs/swagger-ui.css",
            get(|| async { asset("text/css; charset=utf-8", SWAGGER_UI_CSS) }),
        )
        .route("/openapi.json", get(|| async { Json(document()) }))
}

fn schema_ref(name: &str) -> RefOr<Schema> {
    RefOr::Ref(Ref::from_schema_name(name))
}

fn problem_response(description: &str) -> utoipa::openapi::Response {
    ResponseBuilder::new()
        .description(description)
        .content(
            "application/problem+json",
            ContentBuilder::new()
                .schema(Some(schema_ref("Problem")))
                .build(),
        )
        .build()
}

fn json_response(description: &str, schema: RefOr<Schema>) -> utoipa::openapi::Response {
    ResponseBuilder::new()
        .description(description)
        .content(
            "application/json",
            ContentBuilder::new().schema(Some(schema)).build(),
        )
        .build()
}

/// The envelope around one calculation's output.
fn envelope(output: &str) -> Schema {
    ObjectBuilder::new()
        .property("result", schema_ref(output))
        .property(
            "effects",
            ObjectBuilder::new()
                .description(Some("Every effect the calculation knows, applied or not, with the reason."))
                .additional_properties(Some(schema_ref("Decision"))),
        )
        .property("solver", schema_ref("SolverReport"))
        .property(
            "warnings",
            ArrayBuilder::new()
                .description(Some("Notes on a valid result: a model used outside its source's range, an assumed property."))
                .items(schema_ref("Warning")),
        )
        .required("result")
        .required("effects")
        .required("solver")
        .required("warnings")
        .into()
}

/// Two different types under one component name would silently overwrite each other in the
/// document (and break the responses' schema): refuse to build it.
/// The 503 of a calculation, as its admission class has it (`http::admission`).
fn shed_text(entry: &Entry) -> String {
    let retry = "Retry after the Retry-After delay (seconds).";
    match entry.costing {
        Costing::Light => {
            format!("The replica is full: too many calculations are in progress. {retry}")
        }
        Costing::Numerical => {
            let closed = if entry.fidelity.contains(&Level::ClosedForm) {
                " `fidelity: closed_form` needs no solver."
            } else {
                ""
            };
            format!("The replica is full: every solver stayed busy through the short queue wait, or the queue was full.{closed} {retry}")
        }
    }
}

fn assert_unique_schema_names(schemas: &[(String, RefOr<Schema>)], _rooms_from: usize) {
    let mut seen: std::collections::BTreeMap<&str, String> = std::collections::BTreeMap::new();
    for (name, schema) in schemas {
        let text = serde_json::to_string(schema).unwrap_or_default();
        if let Some(previous) = seen.insert(name, text.clone()) {
            assert!(previous == text, "two different schemas are named {name}: rename one (utoipa component names are global)");
        }
    }
}

fn build() -> OpenApi {
    let mut schemas: Vec<(String, RefOr<Schema>)> = Vec::new();
    let mut push = |name: std::borrow::Cow<'static, str>, schema: RefOr<Schema>| {
        schemas.push((name.into_owned(), schema))
    };
    push(Problem::name(), Problem::schema());
    push(FieldError::name(), FieldError::schema());
    push(Warning::name(), Warning::schema());
    push(Decision::name(), Decision::schema());
    push(Criterion::name(), Criterion::schema());
    push(Mode::name(), Mode::schema());
    push(Level::name(), Level::schema());
    push(SolverReport::name(), SolverReport::schema());
    push(CalculationInfo::name(), CalculationInfo::schema());
    push(CalculationList::name(), CalculationList::schema());
    // The report's own parts (its units, stop reasons and step control).
    SolverReport::schemas(&mut schemas);

    let mut paths = PathsBuilder::new();
    let before_rooms = schemas.len();
    for entry in REGISTRY {
        (entry.schemas)(&mut schemas);
        let (input, output) = (entry.schema_names)();
        let envelope_name = format!("{output}Envelope");
        schemas.push((envelope_name.clone(), envelope(&output).into()));
        let example: serde_json::Value =
            serde_json::from_str(entry.example).expect("registered examples are JSON");
        let body = RequestBodyBuilder::new()
            .required(Some(Required::True))
            .content(
                "application/json",
                ContentBuilder::new()
                    .schema(Some(schema_ref(&input)))
                    .example(Some(example))
                    .build(),
            )
            .build();
        let op = OperationBuilder::new()
            .operation_id(Some(entry.path.trim_start_matches("/v1/").replace(['/', '-'], "_")))
            .tag(entry.path.split('/').nth(2).unwrap_or("calculations"))
            .summary(Some(entry.summary))
            .description(Some(format!(
                "{}\n\nFidelity levels: {}. Effects: {}.",
                entry.description,
                entry.fidelity.iter().map(|l| format!("{l:?}")).collect::<Vec<_>>().join(", "),
                if entry.effects.is_empty() { "none".to_owned() } else { entry.effects.join(", ") }
            )))
            .request_body(Some(body))
            .response("200", json_response("The result in its envelope.", schema_ref(&envelope_name)))
            .response("400", problem_response("The body is not JSON."))
            .response("413", problem_response("The body exceeds the size limit."))
            .response("415", problem_response("The body is not sent as application/json."))
            .response("422", problem_response("Invalid input (each field named by a JSON pointer), a physically impossible case, or a solver that did not converge."))
            .response("500", problem_response("An internal error; nothing internal is disclosed."))
            .response("503", problem_response(&shed_text(entry)))
            .response("504", problem_response("The calculation passed its deadline and was stopped."));
        paths = paths.path(entry.path, PathItem::new(HttpMethod::Post, op));
    }
    assert_unique_schema_names(&schemas[..], before_rooms);
    let get = |id: &str, summary: &str, response: utoipa::openapi::Response| {
        PathItem::new(
            HttpMethod::Get,
            OperationBuilder::new()
                .operation_id(Some(id))
                .tag("service")
                .summary(Some(summary))
                .response("200", response),
        )
    };
    let status_object = || -> RefOr<Schema> {
        ObjectBuilder::new()
            .property(
                "status",
                ObjectBuilder::new().schema_type(utoipa::openapi::Type::String),
            )
            .required("status")
            .into()
    };
    paths = paths
        .path(
            "/health",
            get(
                "health",
                "The process is up",
                json_response("Up.", status_object()),
            ),
        )
        .path(
            "/ready",
            PathItem::new(
                HttpMethod::Get,
                OperationBuilder::new()
                    .operation_id(Some("ready"))
                    .tag("service")
                    .summary(Some("The replica takes traffic (503 while draining)"))
                    .response("200", json_response("Ready.", status_object()))
                    .response("503", problem_response("Shutting down.")),
            ),
        )
        .path(
            "/metrics",
            get(
                "metrics",
                "Prometheus metrics",
                ResponseBuilder::new()
                    .description("Prometheus text exposition format.")
                    .content(
                        "text/plain",
                        ContentBuilder::new().schema(Some(String::schema())).build(),
                    )
                    .build(),
            ),
        )
        .path(
            "/v1/calculations",
            get(
                "list_calculations",
                "Every calculation with its fidelity levels and effects",
                json_response("The list.", schema_ref("CalculationList")),
            ),
        );

    OpenApiBuilder::new()
        .info(
            InfoBuilder::new()
                .title("Stribeck")
                .version(env!("CARGO_PKG_VERSION"))
                .description(Some(DESCRIPTION)),
        )
        .paths(paths)
        .components(Some(
            ComponentsBuilder::new().schemas_from_iter(schemas).build(),
        ))
        .build()
}
