//! HTTP tests, one binary (one link): each module tests one face of the service against a real
//! server on 127.0.0.1:0.
//!
//! - `admission`: admission by cost: closed forms beside busy solvers, the solvers' queue.
//! - `composite`: the composite bearing: its 422s, the speed split and the start-up over their ranges.
//! - `contract`: the envelope, every error status and its problem+json, request ids.
//! - `limits`: deadline (504), load shedding (503), panics and non-finite results (500), slow
//!   clients (header timeout, 408 body timeout).
//! - `reference_cases`: every case in tests/data, each with its source and tolerance.
//! - `gas`: gas journal and slider: their 422s with reasons and their ranges.
//! - `gas_tilting_thrust`: the tilting-pad gas thrust bearing: example, inverse requests, 422s, range.
//! - `gas_tilting_pad`: the tilting-pad gas journal: its example, 422s naming the field, its range.
//! - `hydrostatic`: hydrostatic pads and design: examples, 422s naming the field, the optima.
//! - `journal`: the plain journal bearing against Tables 8.4 and 8.6 and over its range.
//! - `lubricants`: lubricant rooms' invalid-input tables and properties over their ranges.
//! - `openapi_document`: what the OpenAPI document declares (tags, servers, headers, shared
//!   components) and its 3.0 rendering.
//! - `thrust`: thrust pads over their range: finite, conserving, balanced; errors that name the field.
//! - `sweep`: every number of every example from the smallest positive double to the largest:
//!   a finite success or a 422.
//! - `squeeze`: squeeze-film rooms' 422s and the squeezed journal over its range.
//! - `whirl`: the whirl room's 422s, its README example, and finite answers over its range.
//! - `service`: health, readiness, metrics, the listing, the OpenAPI document and the docs UI.
//! - `shutdown`: the real binary on SIGTERM: the drain, `/ready` and `/health` during it, the
//!   cancelled solve's 503, exit 0.

mod admission;
mod bounds;
mod composite;
mod contract;
mod gas;
mod gas_tilting_pad;
mod gas_tilting_thrust;
mod helpers;
mod hydrostatic;
mod journal;
mod limits;
mod lubricants;
mod openapi_document;
mod reference_cases;
mod service;
mod shutdown;
mod squeeze;
mod sweep;
mod thrust;
mod whirl;
