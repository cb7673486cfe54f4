//! Gas bearings (Khonsari & Booser ch. 11; Stachowiak & Batchelor §4.8, §6.5).
//!
//! - `gas_spec`: the shared `gas` object (viscosity, absolute ambient pressure, gas constant,
//!   temperature, mean free path) and its parsed model [`Gas`], with the slip-flow decision.

pub mod gas_spec;

pub use gas_spec::{Gas, GasSpec, NamedGas};
