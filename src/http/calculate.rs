//! The generic handler: content type, body (read under `body_timeout`), admission by cost
//! (`admission`), the blocking pool under a deadline, and the mapping of every outcome to a
//! response. A solve is cancelled (its flag set) when its deadline passes, when the drain time
//! is up at shutdown (503 `shutting-down`), and when its client goes away (the handler future is
//! dropped), so no core keeps working for nobody.

use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

use axum::body::{Body, Bytes};
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
    body: Body,
) -> Response {
    let _in_flight = state.drain.enter();
    if !is_json(&headers) {
        return Problem::new(
            StatusCode::UNSUPPORTED_MEDIA_TYPE,
            "unsupported-media-type",
            "Unsupported media type",
            "send the request body as JSON with Content-Type: application/json",
        )
        .into_response();
    }
    let body = match read_body(body, &state).await {
        Ok(b) => b,
        Err(problem) => return problem.into_response(),
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
    let key = solve_key(entry, &body);
    let admitted = tokio::select! {
        admitted = state.admission.admit(cost, deadline, &key) => admitted,
        () = state.drain.cancelled() => return Problem::shutting_down().into_response(),
    };
    let ticket = match admitted {
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

    let cancelled = CancelOnDrop(Arc::new(AtomicBool::new(false)));
    let flag = cancelled.0.clone();
    let span = tracing::Span::current();
    // The ticket moves into the task: a request that timed out still holds its permit until its
    // solver has seen the cancellation, so admission counts real work.
    let task = tokio::task::spawn_blocking(move || {
        let _ticket = ticket;
        span.in_scope(|| (entry.execute)(&body, deadline, flag))
    });
    let outcome = tokio::select! {
        outcome = tokio::time::timeout(remaining, task).instrument(tracing::Span::current()) => outcome,
        () = state.drain.cancelled() => return Problem::shutting_down().into_response(),
    };
    match outcome {
        Err(_elapsed) => Problem::deadline().into_response(),
        Ok(Err(join)) => {
            let mut res = Problem::internal().into_response();
            res.extensions_mut()
                .insert(InternalCause(format!("solver task failed: {join}")));
            res
        }
        Ok(Ok(Ok(done))) => {
            state
                .admission
                .record(&key, Duration::from_secs_f64(done.solver_ms.max(0.0) / 1e3));
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

/// Sets a solve's cancel flag when the handler ends, however it ends: with a response, or
/// dropped because the client went away or the drain time is up. The solver sees it at its next
/// budget check and gives its permit back.
struct CancelOnDrop(Arc<AtomicBool>);

impl Drop for CancelOnDrop {
    fn drop(&mut self) {
        self.0.store(true, Ordering::Relaxed);
    }
}

/// The whole body, at most `max_body_bytes` (else 413), within `body_timeout` (else 408).
async fn read_body(body: Body, state: &AppState) -> Result<Bytes, Problem> {
    use http_body_util::{BodyExt, LengthLimitError, Limited};
    let limit = state.config.max_body_bytes;
    let read = Limited::new(body, limit).collect();
    match tokio::time::timeout(state.config.body_timeout, read).await {
        Err(_elapsed) => Err(Problem::body_timeout(state.config.body_timeout)),
        Ok(Ok(collected)) => Ok(collected.to_bytes()),
        Ok(Err(e)) if e.is::<LengthLimitError>() => Err(Problem::new(
            StatusCode::PAYLOAD_TOO_LARGE,
            "body-too-large",
            "Request body too large",
            format!("the body exceeds {limit} bytes"),
        )),
        Ok(Err(e)) => Err(Problem::new(
            StatusCode::BAD_REQUEST,
            "unreadable",
            "Unreadable request body",
            format!("reading the body failed: {e}"),
        )),
    }
}

/// What the admission averages solve times by: the calculation and the body's `fidelity`.
fn solve_key(entry: &Entry, body: &[u8]) -> String {
    #[derive(serde::Deserialize)]
    struct Fidelity {
        fidelity: Option<serde_json::Value>,
    }
    let fidelity = serde_json::from_slice::<Fidelity>(body)
        .ok()
        .and_then(|f| f.fidelity)
        .map_or_else(String::new, |f| f.to_string());
    format!("{} {fidelity}", entry.path)
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
