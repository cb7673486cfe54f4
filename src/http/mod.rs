//! The door: routes, middleware and the one generic handler every calculation goes through.
//! Thin glue: parsing, validation and physics live in `crate::calc`.

pub mod admission;
mod calculate;
pub mod drain;
mod meta;
pub mod metrics;
pub mod openapi;
pub mod openapi30;
mod problem;
pub mod serve;

use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;
use std::time::Instant;

use axum::extract::{DefaultBodyLimit, MatchedPath, Request, State};
use axum::http::{HeaderValue, StatusCode};
use axum::middleware::{self, Next};
use axum::response::{IntoResponse, Response};
use axum::routing::{get, post};
use axum::Router;
use tower::ServiceBuilder;
use tower_http::catch_panic::CatchPanicLayer;
use tower_http::request_id::{
    MakeRequestId, PropagateRequestIdLayer, RequestId, SetRequestIdLayer,
};
use tower_http::trace::TraceLayer;

pub use problem::{InternalCause, Problem};

use crate::calc::{Entry, REGISTRY};
use crate::config::Config;
use admission::Admission;
use drain::Drain;
use metrics::Metrics;

/// Shared state of one server.
#[derive(Clone)]
pub struct AppState {
    pub config: Arc<Config>,
    pub metrics: Arc<Metrics>,
    /// Which calculations run now, wait, or are shed with 503 (by cost).
    pub admission: Arc<Admission>,
    /// Shutdown: `/ready` answers 503 once it has begun, so balancers drain this replica; the
    /// binary cancels what is still in flight when the drain time is up.
    pub drain: Arc<Drain>,
}

impl AppState {
    pub fn new(config: Config) -> AppState {
        AppState {
            admission: Arc::new(Admission::new(&config)),
            config: Arc::new(config),
            metrics: Arc::new(Metrics::default()),
            drain: Arc::new(Drain::default()),
        }
    }
}

/// The whole service for `config`.
pub fn router(config: Config) -> Router {
    router_with_state(AppState::new(config))
}

/// The whole service around an existing state (the binary keeps a handle to drain it).
pub fn router_with_state(state: AppState) -> Router {
    router_with(state, REGISTRY)
}

/// The service with a given list of calculations (tests add their own to reach failure paths
/// no real calculation should have).
pub fn router_with(state: AppState, calculations: &'static [Entry]) -> Router {
    let mut app = Router::new()
        .route("/health", get(meta::health))
        .route("/ready", get(meta::ready))
        .route("/metrics", get(meta::metrics))
        .route("/v1/calculations", get(meta::calculations));
    for entry in calculations {
        app = app.route(
            entry.path,
            post(move |state, headers, body| calculate::run(entry, state, headers, body)),
        );
    }
    let app = app
        .merge(openapi::docs_router())
        .fallback(meta::not_found)
        .method_not_allowed_fallback(meta::method_not_allowed);

    let max_body = state.config.max_body_bytes;
    // Outermost first: the id exists before the span that logs it; panics become a problem
    // response before the observer counts it; the body limit applies to every extractor.
    let layers = ServiceBuilder::new()
        .layer(SetRequestIdLayer::x_request_id(Counter::default()))
        .layer(TraceLayer::new_for_http().make_span_with(|req: &Request| {
            let id = req
                .headers()
                .get("x-request-id")
                .and_then(|v| v.to_str().ok())
                .unwrap_or("-");
            tracing::info_span!("request", id = %id, method = %req.method(), uri = %req.uri())
        })
        // `observe` writes the one access line per request; the layer's own response and
        // failure events (a 503 or 504 at ERROR) are off.
        .on_response(())
        .on_failure(()))
        .layer(PropagateRequestIdLayer::x_request_id())
        .layer(middleware::from_fn_with_state(state.clone(), observe))
        .layer(CatchPanicLayer::custom(|_| {
            Problem::internal().into_response()
        }))
        .layer(DefaultBodyLimit::max(max_body));
    app.layer(layers).with_state(state)
}

/// Request ids: a process-unique counter, prefixed with the start time so restarts differ.
#[derive(Clone)]
struct Counter {
    prefix: u64,
    next: Arc<AtomicU64>,
}

impl Default for Counter {
    fn default() -> Self {
        let prefix = std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map_or(0, |d| d.as_secs() & 0xff_ffff);
        Counter {
            prefix,
            next: Arc::new(AtomicU64::new(1)),
        }
    }
}

impl MakeRequestId for Counter {
    fn make_request_id<B>(&mut self, _: &axum::http::Request<B>) -> Option<RequestId> {
        let n = self.next.fetch_add(1, Ordering::Relaxed);
        HeaderValue::from_str(&format!("{:06x}-{n:08x}", self.prefix))
            .ok()
            .map(RequestId::new)
    }
}

/// Solver time of a calculation response, for the metrics (a response extension).
#[derive(Debug, Clone, Copy)]
pub struct SolverSeconds(pub f64);

/// How loudly a response is logged: a 500 is ours to fix (error); a shed 503 or a deadline 504
/// is the service protecting itself under load (warn); everything else is an access line (info).
fn access_level(status: StatusCode) -> tracing::Level {
    match status.as_u16() {
        503 | 504 => tracing::Level::WARN,
        s if s >= 500 => tracing::Level::ERROR,
        _ => tracing::Level::INFO,
    }
}

/// Count every response, time it, and log one access line for it (inside the request's span,
/// which carries the request id, method and URI), with the internal cause of any 500.
async fn observe(State(state): State<AppState>, req: Request, next: Next) -> Response {
    let route = req
        .extensions()
        .get::<MatchedPath>()
        .map_or_else(|| "unmatched".to_owned(), |p| p.as_str().to_owned());
    let started = Instant::now();
    let res = next.run(req).await;
    let status = res.status();
    let elapsed_ms = started.elapsed().as_secs_f64() * 1e3;
    let cause = res
        .extensions()
        .get::<InternalCause>()
        .map(|c| c.0.as_str());
    match access_level(status) {
        tracing::Level::ERROR => tracing::error!(
            route = %route,
            status = status.as_u16(),
            elapsed_ms,
            cause = cause.unwrap_or("panic or unknown"),
            "internal error"
        ),
        tracing::Level::WARN => {
            tracing::warn!(route = %route, status = status.as_u16(), elapsed_ms, "refused under load")
        }
        _ => tracing::info!(route = %route, status = status.as_u16(), elapsed_ms, "served"),
    }
    let solver = res.extensions().get::<SolverSeconds>().map(|s| s.0);
    state.metrics.record(
        &route,
        status.as_u16(),
        started.elapsed().as_secs_f64(),
        solver,
    );
    res
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn load_refusals_warn_and_only_our_faults_are_errors() {
        for (status, level) in [
            (200, tracing::Level::INFO),
            (400, tracing::Level::INFO),
            (422, tracing::Level::INFO),
            (500, tracing::Level::ERROR),
            (503, tracing::Level::WARN),
            (504, tracing::Level::WARN),
        ] {
            assert_eq!(
                access_level(StatusCode::from_u16(status).unwrap()),
                level,
                "{status}"
            );
        }
    }
}
