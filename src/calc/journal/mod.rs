//! Hydrodynamic journal bearings (Khonsari & Booser ch. 8; Stachowiak & Batchelor ch. 4–5).
//!
//! - `plain`: the `/v1/journal-bearings/plain` room (request, response);
//! - `dynamic`: the `/v1/journal-bearings/dynamic` room (wire of the orbit);
//! - `operating`: from the parsed case to the dimensional result, effects decided;
//! - `performance`: dimensionless performance at ε by closed form or numerics, equilibrium;
//! - `film`: the numerical film (finite-volume Reynolds with cavitation);
//! - `closed_form`: infinitely short and long bearings;
//! - `cost`: what a film grid costs, so that one the deadline cannot pay for is refused first;
//! - `eccentricity`: the eccentricity ratio ε, checked once;
//! - `dynamics`: stiffness, damping and the whirl threshold;
//! - `moving_film`: the short film's force on a moving journal; `finite_moving_film`: the finite
//!   film's (the Reynolds film squeezed, as an impedance table); `load_law`: dynamic loads;
//!   `orbit`: the journal's orbit under them (stiff time integration);
//! - `threshold`: the whirl threshold along the equilibrium locus (the `/whirl` room's model);
//! - `whirl`: the `/v1/journal-bearings/whirl` room (request, response); `whirl_confirm`: its
//!   threshold confirmed by simulating the orbit below and above it;
//! - `feed`: Martin's feed flows (model); `feed_spec`: the request's `feed` object (wire).

pub mod closed_form;
pub mod cost;
pub mod dynamic;
pub mod dynamics;
pub mod eccentricity;
pub mod feed;
pub mod feed_spec;
pub mod film;
pub mod finite_moving_film;
pub mod load_law;
pub mod moving_film;
pub mod operating;
pub mod orbit;
pub mod performance;
pub mod plain;
pub mod threshold;
pub mod whirl;
pub mod whirl_confirm;
