//! A typed Rust client for Stribeck, generated at build time by progenitor from the service's
//! OpenAPI 3.0 rendering (`openapi/openapi-3.0.json`; see `build.rs`).
//!
//! One method per operation, named by its operation id (`POST /v1/journal-bearings/plain` is
//! [`Client::journal_bearings_plain`]); request and response bodies are the document's schemas
//! in [`types`]. Every error answer decodes as a typed [`Problem`] (RFC 9457):
//!
//! ```no_run
//! # async fn demo(input: &stribeck_client::types::ViscosityIndexInput) {
//! let client = stribeck_client::Client::new("http://127.0.0.1:8080");
//! match client.lubricants_viscosity_index(None, None, input).await {
//!     Ok(envelope) => println!("VI {}", envelope.result.viscosity_index),
//!     Err(stribeck_client::Error::ErrorResponse(problem)) => {
//!         for field in &problem.errors {
//!             eprintln!("{}: {}", field.pointer, field.message);
//!         }
//!     }
//!     Err(other) => eprintln!("{other}"),
//! }
//! # }
//! ```
//!
//! The two optional arguments before the body are the request headers `x-request-id` and
//! `x-stribeck-deadline-ms`.

include!(concat!(env!("OUT_DIR"), "/codegen.rs"));

/// A problem report (RFC 9457): what every 4xx and 5xx answer carries.
pub use types::Problem;
