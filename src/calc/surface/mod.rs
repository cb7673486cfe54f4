//! Surface physics shared by the film and contact families: what happens where two surfaces
//! meet, whatever carries the load between them.
//!
//! Here now:
//! - [`roughness`]: the composite roughness of two surfaces, the film parameter Λ and the
//!   lubrication regime it implies (full film, mixed, boundary) — read by the EHL film room and
//!   by any film room that compares its film with the roughness.
//! - [`moving_heat_source`]: the flash-temperature kernels of a heat source sliding over a
//!   half-space (Jaeger; Tian & Kennedy), and [`flash`]: the flash temperature of a sliding
//!   contact built on them (the `/v1/contacts/flash-temperature` room is its wire).
//!
//! What will live here (one home for what every film and contact room may use): friction
//! (boundary and mixed friction coefficients, traction laws shared beyond EHL), wear (Archard
//! and its kin), and rough contact (asperity models: Greenwood–Williamson, the load the
//! asperities share in mixed lubrication). Each is a model file: plain types and functions, no
//! serde, no `Context`; the rooms that expose them on a URL hold the wire.

pub mod flash;
pub mod moving_heat_source;
pub mod roughness;
