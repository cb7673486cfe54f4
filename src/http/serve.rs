//! The accept loop and the shutdown sequence.
//!
//! Each connection is HTTP/1 on hyper with a header read timeout (`STRIBECK_HEADER_TIMEOUT_MS`):
//! a client that opens a connection and sends its request head slowly, or never finishes it,
//! is disconnected, so a few hundred such sockets cannot pin the service. The body's timeout
//! (408) is the handler's (`calculate`).
//!
//! Shutdown on SIGTERM/SIGINT ([`run`]): `/ready` answers 503 (and `/health` 200) while the
//! listener keeps accepting, until nothing is in flight or `STRIBECK_DRAIN_MS` has passed; then
//! every solve still running or queued is cancelled and answered 503 `shutting-down`, the
//! connections close once their responses are written, and the process exits 0.

use std::future::Future;
use std::time::Duration;

use axum::extract::Request;
use axum::Router;
use hyper_util::rt::{TokioIo, TokioTimer};
use hyper_util::server::graceful::GracefulShutdown;
use tokio::net::TcpListener;
use tower::ServiceExt;

use super::AppState;

/// How long connections may take to write their last responses once the solves are cancelled.
const CLOSE_GRACE: Duration = Duration::from_secs(5);

/// Serve `app` on `listener` until `stop` resolves; then stop accepting and wait (at most
/// [`CLOSE_GRACE`]) for the open connections to finish the requests they carry.
pub async fn serve(
    listener: TcpListener,
    app: Router,
    header_timeout: Duration,
    stop: impl Future<Output = ()>,
) {
    let graceful = GracefulShutdown::new();
    let mut stop = std::pin::pin!(stop);
    loop {
        let stream = tokio::select! {
            accepted = listener.accept() => match accepted {
                Ok((stream, _peer)) => stream,
                Err(e) => {
                    // Out of file descriptors and the like: back off instead of spinning.
                    tracing::warn!("accept failed: {e}");
                    tokio::time::sleep(Duration::from_millis(50)).await;
                    continue;
                }
            },
            () = &mut stop => break,
        };
        let app = app.clone();
        let service = hyper::service::service_fn(move |req: Request<hyper::body::Incoming>| {
            app.clone().oneshot(req.map(axum::body::Body::new))
        });
        let conn = hyper::server::conn::http1::Builder::new()
            .timer(TokioTimer::new())
            .header_read_timeout(header_timeout)
            .serve_connection(TokioIo::new(stream), service);
        let conn = graceful.watch(conn);
        tokio::spawn(async move {
            // A client that hangs up or times out its head is not an error of ours.
            if let Err(e) = conn.await {
                tracing::debug!("connection closed: {e}");
            }
        });
    }
    if tokio::time::timeout(CLOSE_GRACE, graceful.shutdown())
        .await
        .is_err()
    {
        tracing::warn!("connections still open {CLOSE_GRACE:?} after shutdown; closing them");
    }
}

/// Serve `state`'s service on `listener` until `signal` resolves, then drain (see the module
/// documentation). Returns when the process may exit.
pub async fn run(
    listener: TcpListener,
    state: AppState,
    signal: impl Future<Output = ()> + Send + 'static,
) {
    let app = super::router_with_state(state.clone());
    let header_timeout = state.config.header_timeout;
    let drain = state.drain.clone();
    let limit = state.config.drain;
    let stop = async move {
        signal.await;
        drain.start();
        tracing::info!(
            in_flight = drain.in_flight(),
            "shutting down: draining for at most {limit:?}"
        );
        if tokio::time::timeout(limit, drain.idle()).await.is_err() {
            tracing::warn!(
                in_flight = drain.in_flight(),
                "drain time is up; cancelling what is still running or queued"
            );
            drain.cancel_all();
        }
    };
    serve(listener, app, header_timeout, stop).await;
}
