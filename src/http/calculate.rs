//! The generic handler: content type, body, admission by cost (`admission`), the blocking pool
//! under a deadline, and the mapping of every outcome to a response.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

use axum::body::Bytes;
use axum::extract::rejection::BytesRejection;
use axum::extract::State;
use axum::http::{header, HeaderMap, HeaderValue, StatusCode};
use axum::response::{IntoResponse, Response};
use tracing::Instrument;

use super::admission::{cost_label, Outcome};
use super::{AppState, InternalCause, Problem, SolverSeconds};
use crate::calc::Entry;

/// Header a client may send to lower (never raise) the deadline for one request, in ms.
pub const DEADLINE_HEADER: &str = "x-stribeck-deadline-ms";

pub async fn run(
    entry: &'static Entry,
    State(state): State<AppState>,
    headers: HeaderMap,
    body: Result<Bytes, BytesRejection>,
) -> Response {
    if !is_json(&headers) {
        return Problem::new(
            StatusCode::UNSUPPORTED_MEDIA_TYPE,
            "unsupported-media-type",
            "Unsupported media type",
            "send the request body as JSON with Content-Type: application/json",
        )
        .into_response();
    }
    let body = match body {
        Ok(b) => b,
        Err(rejection) if rejection.status() == StatusCode::PAYLOAD_TOO_LARGE => {
            return Problem::new(
                StatusCode::PAYLOAD_TOO_LARGE,
                "body-too-large",
                "Request body too large",
                format!("the body exceeds {} bytes", state.config.max_body_bytes),
            )
            .into_response()
        }
        Err(rejection) => {
            return Problem::new(
                StatusCode::BAD_REQUEST,
                "unreadable",
                "Unreadable request body",
                rejection.body_text(),
            )
            .into_response()
        }
    };
    // The deadline runs from arrival: time spent waiting for a solver permit counts against it.
    let arrived = Instant::now();
    let deadline = match deadline_for(&state, &headers) {
        Ok(d) => arrived + d,
        Err(detail) => {
            return Problem::new(
                StatusCode::BAD_REQUEST,
                "invalid-header",
                "Invalid header",
                detail,
            )
            .into_response()
        }
    };
    let cost = entry.cost(&body);
    let ticket = match state.admission.admit(cost, deadline).await {
        Ok(ticket) => ticket,
        Err(refusal) => {
            state
                .metrics
                .record_admission(cost_label(cost), refusal.outcome.label());
            return Problem::overloaded(refusal.detail).into_response();
        }
    };
    state
        .metrics
        .record_admission(cost_label(cost), ticket.outcome.label());
    if ticket.outcome == Outcome::Queued {
        tracing::debug!(waited_ms = %arrived.elapsed().as_millis(), "admitted after queueing");
    }
    let remaining = deadline.saturating_duration_since(Instant::now());

    let cancelled = Arc::new(AtomicBool::new(false));
    let flag = cancelled.clone();
    let span = tracing::Span::current();
    // The ticket moves into the task: a request that timed out still holds its permit until its
    // solver has seen the cancellation, so admission counts real work.
    let task = tokio::task::spawn_blocking(move || {
        let _ticket = ticket;
        span.in_scope(|| (entry.execute)(&body, deadline, flag))
    });
    let outcome = tokio::time::timeout(remaining, task)
        .instrument(tracing::Span::current())
        .await;
    match outcome {
        Err(_elapsed) => {
            cancelled.store(true, Ordering::Relaxed);
            Problem::deadline().into_response()
        }
        Ok(Err(join)) => {
            let mut res = Problem::internal().into_response();
            res.extensions_mut()
                .insert(InternalCause(format!("solver task failed: {join}")));
            res
        }
        Ok(Ok(Ok(done))) => {
            let mut res = (StatusCode::OK, done.body).into_response();
            res.headers_mut().insert(
                header::CONTENT_TYPE,
                HeaderValue::from_static("application/json"),
            );
            res.extensions_mut()
                .insert(SolverSeconds(done.solver_ms / 1e3));
            res
        }
        Ok(Ok(Err(failure))) => {
            let (problem, cause) = Problem::from_failure(failure);
            let mut res = problem.into_response();
            if let Some(cause) = cause {
                res.extensions_mut().insert(InternalCause(cause));
            }
            res
        }
    }
}

fn is_json(headers: &HeaderMap) -> bool {
    headers
        .get(header::CONTENT_TYPE)
        .and_then(|v| v.to_str().ok())
        .and_then(|v| v.split(';').next())
        .map(|m| {
            let m = m.trim().to_ascii_lowercase();
            m == "application/json" || (m.starts_with("application/") && m.ends_with("+json"))
        })
        .unwrap_or(false)
}

/// The server's deadline, or the client's if it asked for less; a header that is not a whole
/// number of milliseconds is a 400 (ignoring it would run the solve under a deadline the
/// client did not ask for); the error is the 400's detail.
fn deadline_for(state: &AppState, headers: &HeaderMap) -> Result<Duration, String> {
    let Some(value) = headers.get(DEADLINE_HEADER) else {
        return Ok(state.config.deadline);
    };
    let asked = value
        .to_str()
        .ok()
        .and_then(|v| v.trim().parse::<u64>().ok())
        .map(|ms| Duration::from_millis(ms.max(1)))
        .ok_or_else(|| {
            format!(
                "{DEADLINE_HEADER} must be a whole number of milliseconds (the server's own deadline, {} ms, caps it); got {:?}",
                state.config.deadline.as_millis(),
                String::from_utf8_lossy(value.as_bytes())
            )
        })?;
    Ok(asked.min(state.config.deadline))
}
