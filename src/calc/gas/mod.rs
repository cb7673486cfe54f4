//! Gas bearings (Khonsari & Booser ch. 11; Stachowiak & Batchelor §4.8, §6.5).
//!
//! - `gas_spec`: the shared `gas` object (viscosity, absolute ambient pressure, gas constant,
//!   temperature, mean free path) and its parsed model [`Gas`], with the slip-flow decision;
//! - `aerostatic_pad`: the `/v1/gas-bearings/aerostatic-pad` room (wire); `recess_pad`: its
//!   model, the circular recessed pad's isothermal radial flow;
//! - `foil_journal`: the `/v1/gas-bearings/foil-journal` room (wire); `foil`: its model, the
//!   bump-foil journal's limiting pressure and load as ω → ∞;
//! - `journal`: the `/v1/gas-bearings/journal` room (request, response, the load search);
//! - `journal_dynamics`: its film's frequency-dependent stiffness and damping, and the rigid
//!   rotor's whirl threshold;
//! - `journal_film`: the plain 360° gas journal's film and its performance;
//! - `method`: fidelity levels and meshes of a gas film, with the Richardson pair;
//! - `pivoted_pad`: a crowned gas sector pad balanced on its pivot for a clearance or a load
//!   (the tilting-pad thrust bearing's pad); `sector_pad`: that pad's film and performance;
//! - `slider`: the `/v1/gas-bearings/slider` room (request, response);
//! - `slider_film`: the plane slider's film (finite or infinitely wide) and its performance;
//! - `tilting_pad_journal`: the `/v1/gas-bearings/tilting-pad-journal` room (wire);
//!   `tilting_pad_film`: its model, the three pivoted pads' films, tilts and load balance;
//! - `tilting_pad_thrust`: the `/v1/gas-bearings/tilting-pad-thrust` room (wire); its model is
//!   `pivoted_pad`.

pub mod aerostatic_pad;
pub mod cost;
pub mod foil;
pub mod foil_journal;
pub mod gas_spec;
pub mod journal;
pub mod journal_dynamics;
pub mod journal_film;
pub mod method;
pub mod pivoted_pad;
pub mod recess_pad;
pub mod sector_pad;
pub mod slider;
pub mod slider_film;
pub mod tilting_pad_film;
pub mod tilting_pad_journal;
pub mod tilting_pad_thrust;

pub use gas_spec::{Gas, GasSpec, NamedGas};
