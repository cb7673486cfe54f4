//! Stribeck: tribology calculations — bearing design and lubrication engineering — over HTTP.
//!
//! `calc` holds the rooms (one per calculation family), `numerics` the shared kernels, `http`
//! the door. `calc` and `numerics` never touch HTTP; the CLI (`stribeck run`) uses the same
//! [`calc::execute`] path as the server.

pub mod calc;
pub mod config;
pub mod effects;
pub mod fidelity;
pub mod http;
pub mod numerics;
pub mod telemetry;
pub mod validation;
