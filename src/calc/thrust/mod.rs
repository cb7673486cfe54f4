//! Thrust and pad bearings (Khonsari & Booser ch. 6–7; Stachowiak & Batchelor ch. 4).
//!
//! - `profile`: a fixed pad's film shape (plane, step, tapered land, parabolic);
//! - `long_pad`: the infinitely long pad, exact;
//! - `film`: the finite pad's numerical film (finite-volume Reynolds, exact active-set solve);
//! - `performance`: dimensionless performance by either, with Richardson's extrapolation.

pub mod film;
pub mod long_pad;
pub mod performance;
pub mod profile;
