//! The service's own endpoints: health, readiness, metrics, the calculation listing, and the
//! problem answers for unknown routes and methods.

use axum::extract::State;
use axum::http::{header, StatusCode, Uri};
use axum::response::{IntoResponse, Response};
use axum::Json;
use serde::Serialize;
use utoipa::ToSchema;

use super::{AppState, Problem};
use crate::calc::REGISTRY;
use crate::fidelity::Level;

/// The answer of `GET /health`.
#[derive(Debug, Serialize, ToSchema)]
pub struct HealthStatus {
    /// Always `ok`: the process answers.
    #[schema(example = "ok")]
    pub status: &'static str,
}

/// The answer of `GET /ready` while the replica takes traffic.
#[derive(Debug, Serialize, ToSchema)]
pub struct ReadyStatus {
    /// Always `ready`; once shutdown has begun the endpoint answers 503 instead.
    #[schema(example = "ready")]
    pub status: &'static str,
}

/// `GET /health`: the process is up.
pub async fn health() -> Json<HealthStatus> {
    Json(HealthStatus { status: "ok" })
}

/// `GET /ready`: the replica takes traffic (503 once shutdown has begun).
pub async fn ready(State(state): State<AppState>) -> Response {
    if !state.drain.is_draining() {
        Json(ReadyStatus { status: "ready" }).into_response()
    } else {
        Problem::new(
            StatusCode::SERVICE_UNAVAILABLE,
            "shutting-down",
            "Shutting down",
            "this replica is draining",
        )
        .into_response()
    }
}

/// `GET /metrics`: Prometheus text format.
pub async fn metrics(State(state): State<AppState>) -> Response {
    ([(header::CONTENT_TYPE, "text/plain; version=0.0.4")], {
        let mut text = state.metrics.render();
        state.admission.render(&mut text);
        text
    })
        .into_response()
}

/// One calculation in the listing.
#[derive(Debug, Serialize, ToSchema)]
pub struct CalculationInfo {
    /// The calculation's URL path.
    #[schema(example = "/v1/lubricants/viscosity")]
    pub path: &'static str,
    /// HTTP method (always POST with a JSON body).
    #[schema(example = "POST")]
    pub method: &'static str,
    /// What it computes, in one line.
    pub summary: &'static str,
    /// Fidelity levels it accepts.
    pub fidelity_levels: Vec<Level>,
    /// Effects the calculation understands, each `auto`/`on`/`off` under `effects` in the request.
    pub effects: Vec<&'static str>,
    /// A request body that works as pasted.
    #[schema(value_type = Object)]
    pub example: serde_json::Value,
}

/// The listing.
#[derive(Debug, Serialize, ToSchema)]
pub struct CalculationList {
    /// Every calculation the service offers.
    pub calculations: Vec<CalculationInfo>,
}

pub fn calculation_list() -> CalculationList {
    CalculationList {
        calculations: REGISTRY
            .iter()
            .map(|e| CalculationInfo {
                path: e.path,
                method: "POST",
                summary: e.summary,
                fidelity_levels: e.fidelity.to_vec(),
                effects: e.effects.to_vec(),
                example: serde_json::from_str(e.example).unwrap_or_default(),
            })
            .collect(),
    }
}

/// `GET /v1/calculations`.
pub async fn calculations() -> Json<CalculationList> {
    Json(calculation_list())
}

pub async fn not_found(uri: Uri) -> Problem {
    Problem::not_found(uri.path())
}

pub async fn method_not_allowed(uri: Uri) -> Problem {
    Problem::new(
        StatusCode::METHOD_NOT_ALLOWED,
        "method-not-allowed",
        "Method not allowed",
        if uri.path().starts_with("/v1/") && uri.path() != "/v1/calculations" {
            format!(
                "{} does not take this method; calculations take POST with a JSON body",
                uri.path()
            )
        } else {
            format!("{} takes GET only", uri.path())
        },
    )
}
