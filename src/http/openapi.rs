//! The OpenAPI 3.1 document (and its 3.0 rendering, `openapi30`), assembled from the registry so it cannot drift from the routes, and
//! the docs UI (swagger-ui, its assets embedded in the binary). Only what the page loads is
//! embedded: the bundle and its stylesheet (1.6 MB), not the release's other bundles and source
//! maps (9 MB more) that serving its whole `dist/` folder would carry.

use std::sync::OnceLock;

use axum::http::header;
use axum::response::{Html, IntoResponse, Redirect, Response};
use axum::routing::get;
use axum::{Json, Router};
use std::collections::BTreeMap;

use utoipa::openapi::header::HeaderBuilder;
use utoipa::openapi::info::LicenseBuilder;
use utoipa::openapi::path::{
    HttpMethod, OperationBuilder, Parameter, ParameterBuilder, ParameterIn, PathItem,
};
use utoipa::openapi::request_body::RequestBodyBuilder;
use utoipa::openapi::schema::{ArrayBuilder, KnownFormat, ObjectBuilder, Ref, SchemaFormat, Type};
use utoipa::openapi::server::ServerBuilder;
use utoipa::openapi::tag::TagBuilder;
use utoipa::openapi::{
    ComponentsBuilder, ContentBuilder, InfoBuilder, OpenApi, OpenApiBuilder, PathsBuilder, RefOr,
    Required, ResponseBuilder, Schema,
};
use utoipa::{PartialSchema, ToSchema};

use super::meta::{CalculationInfo, CalculationList, HealthStatus, ReadyStatus};
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

/// The OpenAPI 3.0 rendering (`openapi/openapi-3.0.json`), for generators that read only 3.0.
pub fn document_30_json() -> String {
    let doc = serde_json::to_value(document()).expect("the OpenAPI document serialises");
    let doc = super::openapi30::convert(&doc).unwrap_or_else(|e| panic!("{e}"));
    let mut s = serde_json::to_string_pretty(&doc).expect("JSON serialises");
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

/// The request header a client may send to lower the deadline (`http::calculate`).
const DEADLINE_HEADER: &str = super::calculate::DEADLINE_HEADER;
/// The request id: kept from the request when the client sends one, assigned otherwise, and
/// returned on every response (`http::router`'s request-id layers).
const REQUEST_ID_HEADER: &str = "x-request-id";

/// One tag per family (the URL's second segment), and `service` for the rest. An operation's tag
/// is taken from its path; a test checks each one is declared here.
pub const TAGS: &[(&str, &str)] = &[
    ("lubricants", "Lubricant properties: viscosity against temperature and pressure, viscosity index, density and thermal properties."),
    ("journal-bearings", "Hydrodynamic journal bearings: steady operation (closed forms and the Reynolds grid), dynamic loads and orbits, oil whirl."),
    ("thrust-bearings", "Hydrodynamic thrust bearings: fixed and tilting pads, a whole pad bearing with its design checks, and the parasitic losses outside the films."),
    ("contacts", "Concentrated contacts: Hertz, elastohydrodynamic film formulas and the numerical EHL solve, flash temperature."),
    ("rolling-bearings", "Rolling bearings: kinematics, ISO 281 life, load distribution, ISO 76 static capacity, friction, grease life, and the analysis that composes them."),
    ("squeeze-films", "Squeeze films: parallel plates, the squeezed journal and the piston ring."),
    ("gas-bearings", "Gas-lubricated bearings: self-acting journal and slider, aerostatic pad, foil journal."),
    ("hydrostatic-bearings", "Externally pressurised (hydrostatic) pads and their design for minimum power or oil lift."),
    ("composite-bearings", "Harnoy's composite bearing (a rolling bearing and a fluid-film sleeve in series): speed split, start-up, orbit."),
    ("service", "The service around the calculations: health, readiness, metrics and the calculation listing."),
];

/// The tag of a calculation at `path` (`/v1/<family>/<calculation>`).
fn family_tag(path: &str) -> &str {
    path.split('/').nth(2).unwrap_or("service")
}

/// A response with `x-request-id`, which every response carries.
fn response(description: &str) -> ResponseBuilder {
    ResponseBuilder::new().description(description).header(
        REQUEST_ID_HEADER,
        HeaderBuilder::new()
            .schema(String::schema())
            .description(Some(
                "The request's id: the one the request sent, or one the server assigned. The server's log names it.",
            ))
            .build(),
    )
}

fn problem_response(description: &str) -> ResponseBuilder {
    response(description).content(
        "application/problem+json",
        ContentBuilder::new()
            .schema(Some(schema_ref("Problem")))
            .build(),
    )
}

fn json_response(description: &str, schema: RefOr<Schema>) -> ResponseBuilder {
    response(description).content(
        "application/json",
        ContentBuilder::new().schema(Some(schema)).build(),
    )
}

/// The optional `x-request-id` request header, which every route honours.
fn request_id_parameter() -> Parameter {
    ParameterBuilder::new()
        .name(REQUEST_ID_HEADER)
        .parameter_in(ParameterIn::Header)
        .required(Required::False)
        .description(Some("An id for this request, echoed on the response and named in the server's log; without one the server assigns one."))
        .schema(Some(String::schema()))
        .example(Some(serde_json::json!("design-run-42")))
        .build()
}

/// The optional deadline header of every calculation (`http::calculate::deadline_for`).
fn deadline_parameter() -> Parameter {
    ParameterBuilder::new()
        .name(DEADLINE_HEADER)
        .parameter_in(ParameterIn::Header)
        .required(Required::False)
        .description(Some("Lower this request's deadline to this many milliseconds (0 counts as 1); it never raises the server's (`STRIBECK_DEADLINE_MS`, 10 000 ms by default). A calculation still running at the deadline is stopped and answered 504. A value that is not a whole number of milliseconds is a 400 naming the header."))
        .schema(Some(
            ObjectBuilder::new()
                .schema_type(Type::Integer)
                .format(Some(SchemaFormat::KnownFormat(KnownFormat::Int64)))
                .minimum(Some(0)),
        ))
        .example(Some(serde_json::json!(2000)))
        .build()
}

/// The envelope around one calculation's output.
fn envelope(output: &str) -> Schema {
    ObjectBuilder::new()
        .property("result", schema_ref(output))
        .property("effects", schema_ref(EFFECT_DECISIONS))
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

/// The name of the one `effects` schema every envelope shares.
const EFFECT_DECISIONS: &str = "EffectDecisions";

/// The envelope's `effects`: one property per effect any calculation knows, each a `Decision`.
/// A response holds exactly the effects its calculation lists (`GET /v1/calculations`), so
/// none is required here.
fn effect_decisions(entries: &[Entry]) -> Schema {
    let mut reported_by: BTreeMap<&str, Vec<&str>> = BTreeMap::new();
    for entry in entries {
        for effect in entry.effects {
            reported_by.entry(effect).or_default().push(entry.path);
        }
    }
    let mut schema = ObjectBuilder::new().description(Some(
        "Every effect the calculation knows, applied or not, with the reason: the effects its listing names, and no others.",
    ));
    for (effect, paths) in reported_by {
        schema = schema.property(
            effect,
            Ref::builder()
                .ref_location_from_schema_name(Decision::name())
                .description(Some(format!("Reported by {}.", paths.join(", ")))),
        );
    }
    schema.into()
}

/// The 503 of a calculation, as its admission class has it (`http::admission`).
fn shed_text(entry: &Entry) -> String {
    let retry = "Or the replica is shutting down and cancelled the calculation at the end of its drain (`shutting-down`). Retry after the Retry-After delay (seconds).";
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

/// A calculation's shed answer: problem+json with the `Retry-After` header `Problem::overloaded`
/// and `Problem::shutting_down` set.
fn shed_response(entry: &Entry) -> ResponseBuilder {
    problem_response(&shed_text(entry)).header(
        "Retry-After",
        HeaderBuilder::new()
            .schema(
                ObjectBuilder::new()
                    .schema_type(Type::Integer)
                    .format(Some(SchemaFormat::KnownFormat(KnownFormat::Int32)))
                    .minimum(Some(0)),
            )
            .description(Some(
                "Seconds to wait before retrying (RFC 9110 §10.2.3); the body's `retry_after_s`.",
            ))
            .build(),
    )
}

/// Two different types under one component name would silently overwrite each other in the
/// document (and break the responses' schema): refuse to build it.
fn assert_unique_schema_names(schemas: &[(String, RefOr<Schema>)]) {
    let mut seen: BTreeMap<&str, String> = BTreeMap::new();
    for (name, schema) in schemas {
        let text = serde_json::to_string(schema).unwrap_or_default();
        if let Some(previous) = seen.insert(name, text.clone()) {
            assert!(previous == text, "two different schemas are named {name}: rename one (utoipa component names are global)");
        }
    }
}

/// The operation of one calculation.
fn calculation_operation(entry: &Entry, input: &str, envelope_name: &str) -> OperationBuilder {
    let example: serde_json::Value =
        serde_json::from_str(entry.example).expect("registered examples are JSON");
    let body = RequestBodyBuilder::new()
        .required(Some(Required::True))
        .content(
            "application/json",
            ContentBuilder::new()
                .schema(Some(schema_ref(input)))
                .example(Some(example))
                .build(),
        )
        .build();
    OperationBuilder::new()
        .operation_id(Some(entry.path.trim_start_matches("/v1/").replace(['/', '-'], "_")))
        .tag(family_tag(entry.path))
        .summary(Some(entry.summary))
        .description(Some(format!(
            "{}\n\nFidelity levels: {}. Effects: {}.",
            entry.description,
            entry.fidelity.iter().map(|l| format!("{l:?}")).collect::<Vec<_>>().join(", "),
            if entry.effects.is_empty() { "none".to_owned() } else { entry.effects.join(", ") }
        )))
        .parameter(deadline_parameter())
        .parameter(request_id_parameter())
        .request_body(Some(body))
        .response("200", json_response("The result in its envelope.", schema_ref(envelope_name)))
        .response("400", problem_response("The body is not JSON, or the deadline header is not a whole number of milliseconds."))
        .response("408", problem_response("The body did not arrive whole within the body timeout (STRIBECK_BODY_TIMEOUT_MS)."))
        .response("413", problem_response("The body exceeds the size limit."))
        .response("415", problem_response("The body is not sent as application/json."))
        .response("422", problem_response("Invalid input (each field named by a JSON pointer), a physically impossible case, or a solver that did not converge."))
        .response("500", problem_response("An internal error; nothing internal is disclosed."))
        .response("503", shed_response(entry))
        .response("504", problem_response("The calculation passed its deadline and was stopped."))
}

/// A `GET` of the service (tag `service`).
fn service_get(id: &str, summary: &str) -> OperationBuilder {
    OperationBuilder::new()
        .operation_id(Some(id))
        .tag("service")
        .summary(Some(summary))
        .parameter(request_id_parameter())
}

/// The service's own paths.
fn service_paths(paths: PathsBuilder) -> PathsBuilder {
    let get = |op: OperationBuilder| PathItem::new(HttpMethod::Get, op);
    paths
        .path(
            "/health",
            get(service_get("health", "The process is up")
                .response("200", json_response("Up.", schema_ref("HealthStatus")))),
        )
        .path(
            "/ready",
            get(
                service_get("ready", "The replica takes traffic (503 while draining)")
                    .response("200", json_response("Ready.", schema_ref("ReadyStatus")))
                    .response("503", problem_response("Shutting down.")),
            ),
        )
        .path(
            "/metrics",
            get(service_get("metrics", "Prometheus metrics").response(
                "200",
                response("Prometheus text exposition format.").content(
                    "text/plain",
                    ContentBuilder::new().schema(Some(String::schema())).build(),
                ),
            )),
        )
        .path(
            "/v1/calculations",
            get(service_get(
                "list_calculations",
                "Every calculation with its fidelity levels and effects",
            )
            .response(
                "200",
                json_response("The list.", schema_ref("CalculationList")),
            )),
        )
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
    push(HealthStatus::name(), HealthStatus::schema());
    push(ReadyStatus::name(), ReadyStatus::schema());
    // The report's own parts (its units, stop reasons and step control).
    SolverReport::schemas(&mut schemas);
    schemas.push((
        EFFECT_DECISIONS.to_owned(),
        effect_decisions(REGISTRY).into(),
    ));

    let mut paths = PathsBuilder::new();
    for entry in REGISTRY {
        (entry.schemas)(&mut schemas);
        let (input, output) = (entry.schema_names)();
        let envelope_name = format!("{output}Envelope");
        schemas.push((envelope_name.clone(), envelope(&output).into()));
        let op = calculation_operation(entry, &input, &envelope_name);
        paths = paths.path(entry.path, PathItem::new(HttpMethod::Post, op));
    }
    assert_unique_schema_names(&schemas[..]);

    OpenApiBuilder::new()
        .info(
            InfoBuilder::new()
                .title("Stribeck")
                .version(env!("CARGO_PKG_VERSION"))
                .description(Some(DESCRIPTION))
                .license(Some(
                    LicenseBuilder::new()
                        .name(env!("CARGO_PKG_LICENSE"))
                        .url(Some("https://www.apache.org/licenses/LICENSE-2.0"))
                        .build(),
                )),
        )
        .servers(Some([
            ServerBuilder::new()
                .url("/")
                .description(Some("The server this document was fetched from"))
                .build(),
            ServerBuilder::new()
                .url("http://127.0.0.1:8080")
                .description(Some(
                    "`stribeck serve` on this machine (its default address)",
                ))
                .build(),
        ]))
        .tags(Some(TAGS.iter().map(|(name, description)| {
            TagBuilder::new()
                .name(*name)
                .description(Some(*description))
                .build()
        })))
        .paths(service_paths(paths))
        .components(Some(
            ComponentsBuilder::new().schemas_from_iter(schemas).build(),
        ))
        .build()
}
