//! Errors as `application/problem+json` (RFC 9457). One `match` maps every failure to its status;
//! a 500 names nothing internal (the cause rides along as a response extension and is logged).

use axum::http::{header, HeaderValue, StatusCode};
use axum::response::{IntoResponse, Response};
use serde::Serialize;
use utoipa::ToSchema;

use crate::calc::{CalcError, Failure, FieldError};
use crate::fidelity::{IterationUnit, StopReason};

/// A problem report (RFC 9457).
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct Problem {
    /// A URI naming the kind of problem, e.g. `https://stribeck.dev/problems/invalid-input`.
    #[serde(rename = "type")]
    pub kind: String,
    /// Short summary of the kind of problem.
    pub title: String,
    /// The HTTP status code.
    pub status: u16,
    /// What went wrong in this request.
    pub detail: String,
    /// For invalid input: every invalid field with its JSON pointer.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub errors: Vec<FieldError>,
    /// For a solver that did not converge: its final residual.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub residual: Option<f64>,
    /// For a solver that did not converge: why it stopped (`iteration_cap`, `stalled`,
    /// `diverged`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stop_reason: Option<StopReason>,
    /// For a solver that did not converge: its iterations, and what one iteration is.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub iterations: Option<u32>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub iterations_unit: Option<IterationUnit>,
    /// For 503: seconds to wait before retrying.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub retry_after_s: Option<u32>,
}

/// The cause of a 500, for the logging middleware; never sent to the client.
#[derive(Debug, Clone)]
pub struct InternalCause(pub String);

impl Problem {
    pub fn new(status: StatusCode, slug: &str, title: &str, detail: impl Into<String>) -> Problem {
        Problem {
            kind: format!("https://stribeck.dev/problems/{slug}"),
            title: title.to_owned(),
            status: status.as_u16(),
            detail: detail.into(),
            errors: Vec::new(),
            residual: None,
            stop_reason: None,
            iterations: None,
            iterations_unit: None,
            retry_after_s: None,
        }
    }

    pub fn not_found(path: &str) -> Problem {
        Problem::new(
            StatusCode::NOT_FOUND,
            "not-found",
            "Not found",
            format!("no resource at {path}; GET /v1/calculations lists them"),
        )
    }

    /// 503: the calculation was not admitted (`detail` says which limit was reached).
    pub fn overloaded(detail: impl Into<String>) -> Problem {
        let mut p = Problem::new(
            StatusCode::SERVICE_UNAVAILABLE,
            "overloaded",
            "Service overloaded",
            detail,
        );
        p.retry_after_s = Some(1);
        p
    }

    /// 503: the replica shut down before the calculation finished (it was cancelled at the
    /// end of the drain); another replica can take the retry.
    pub fn shutting_down() -> Problem {
        let mut p = Problem::new(
            StatusCode::SERVICE_UNAVAILABLE,
            "shutting-down",
            "Shutting down",
            "this replica shut down before the calculation finished; retry, another replica will take it",
        );
        p.retry_after_s = Some(1);
        p
    }

    /// 408: the request body did not arrive whole within `STRIBECK_BODY_TIMEOUT_MS`.
    pub fn body_timeout(limit: std::time::Duration) -> Problem {
        Problem::new(
            StatusCode::REQUEST_TIMEOUT,
            "body-timeout",
            "Request body timeout",
            format!(
                "the request body did not arrive whole within {} ms",
                limit.as_millis()
            ),
        )
    }

    pub fn internal() -> Problem {
        Problem::new(
            StatusCode::INTERNAL_SERVER_ERROR,
            "internal",
            "Internal error",
            "the calculation failed on our side; it has been logged",
        )
    }

    /// The problem for a failed calculation, and the internal cause to log for a 500.
    pub fn from_failure(failure: Failure) -> (Problem, Option<String>) {
        match failure {
            Failure::Unreadable(detail) => (
                Problem::new(
                    StatusCode::BAD_REQUEST,
                    "unreadable",
                    "Unreadable request body",
                    detail,
                ),
                None,
            ),
            Failure::Invalid(errors) => {
                let detail = errors
                    .iter()
                    .map(|e| {
                        format!(
                            "{}: {}",
                            if e.pointer.is_empty() {
                                "(body)"
                            } else {
                                &e.pointer
                            },
                            e.message
                        )
                    })
                    .collect::<Vec<_>>()
                    .join("; ");
                let mut p = Problem::new(
                    StatusCode::UNPROCESSABLE_ENTITY,
                    "invalid-input",
                    "Invalid input",
                    detail,
                );
                p.errors = errors;
                (p, None)
            }
            Failure::Calc(CalcError::Impossible { pointer, message }) => {
                let mut p = Problem::new(
                    StatusCode::UNPROCESSABLE_ENTITY,
                    "outside-model",
                    "Physically impossible or outside the model",
                    message.clone(),
                );
                p.errors = vec![FieldError { pointer, message }];
                (p, None)
            }
            Failure::Calc(e @ CalcError::NotConverged { residual, .. }) => {
                let mut p = Problem::new(
                    StatusCode::UNPROCESSABLE_ENTITY,
                    "not-converged",
                    "Solver did not converge",
                    e.to_string(),
                );
                p.residual = Some(residual).filter(|r| r.is_finite());
                (p, None)
            }
            Failure::Calc(e @ CalcError::Stopped(_)) => {
                let mut p = Problem::new(
                    StatusCode::UNPROCESSABLE_ENTITY,
                    "not-converged",
                    "Solver did not converge",
                    e.to_string(),
                );
                if let CalcError::Stopped(report) = e {
                    p.residual = report.residual.filter(|r| r.is_finite());
                    p.stop_reason = Some(report.stop_reason);
                    p.iterations = Some(report.iterations);
                    p.iterations_unit = Some(report.iterations_unit);
                }
                (p, None)
            }
            Failure::Calc(CalcError::DeadlineExceeded) => (Problem::deadline(), None),
            Failure::Calc(CalcError::Internal(cause)) => (Problem::internal(), Some(cause)),
        }
    }

    pub fn deadline() -> Problem {
        Problem::new(
            StatusCode::GATEWAY_TIMEOUT,
            "deadline-exceeded",
            "Deadline exceeded",
            "the calculation did not finish within the server's deadline and was stopped; lower the fidelity or the size of the request",
        )
    }
}

impl IntoResponse for Problem {
    fn into_response(self) -> Response {
        let status = StatusCode::from_u16(self.status).unwrap_or(StatusCode::INTERNAL_SERVER_ERROR);
        let retry = self.retry_after_s;
        let body = serde_json::to_vec(&self).unwrap_or_else(|_| b"{}".to_vec());
        let mut res = (status, body).into_response();
        res.headers_mut().insert(
            header::CONTENT_TYPE,
            HeaderValue::from_static("application/problem+json"),
        );
        if let Some(s) = retry {
            res.headers_mut()
                .insert(header::RETRY_AFTER, HeaderValue::from(s));
        }
        res
    }
}
