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
//! - `slider`: the `/v1/gas-bearings/slider` room (request, response);
//! - `slider_film`: the plane slider's film (finite or infinitely wide) and its performance;
//! - `tilting_pad_journal`: the `/v1/gas-bearings/tilting-pad-journal` room (wire);
//!   `tilting_pad_film`: its model, the three pivoted pads' films, tilts and load balance.

pub mod aerostatic_pad;
pub mod foil;
pub mod foil_journal;
pub mod gas_spec;
pub mod journal;
pub mod journal_dynamics;
pub mod journal_film;
pub mod method;
pub mod recess_pad;
pub mod slider;
pub mod slider_film;
pub mod tilting_pad_film;
pub mod tilting_pad_journal;

pub use gas_spec::{Gas, GasSpec, NamedGas};
