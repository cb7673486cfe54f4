//! Thrust and pad bearings (Khonsari & Booser ch. 6–7; Stachowiak & Batchelor ch. 4).
//!
//! - `bearing`: the `/v1/thrust-bearings/bearing` room; `sector`: its sectors and design rules;
//! - `fixed_pad`: the `/v1/thrust-bearings/fixed-pad` room (request, response);
//! - `tilting_pad`: the `/v1/thrust-bearings/tilting-pad` room; `pivot`: its equilibrium;
//!   `crowned`: a crowned pad's, 2-D in (h1/h2, h2);
//! - `pad_spec`: the wire parts every pad room shares (pad, effects, fidelity, result);
//! - `pad`: one pad solved at its operating point (fixed, or tilting in equilibrium);
//! - `operating`: a pad at its operating point, dimensional, effects decided;
//! - `coefficients`: a pad's dimensionless performance (W̄, F̄, flows, x_cp, P̄_max);
//! - `performance`: dimensionless performance by closed form or numerics, the optimum ratio;
//! - `long_pad`: the infinitely long pad, exact;
//! - `film`: the finite pad's numerical film (finite-volume Reynolds, exact active-set solve);
//! - `thd`: Jang & Khonsari's THD temperature fits for a plane pad;
//! - `profile`: a fixed pad's film shape (plane, step, tapered land, parabolic);
//! - `parasitic`: the `/v1/thrust-bearings/parasitic-losses` room (surface drag, through-flow).

pub mod bearing;
pub mod coefficients;
pub mod crowned;
pub mod film;
pub mod fixed_pad;
pub mod long_pad;
pub mod operating;
pub mod pad;
pub mod pad_spec;
pub mod parasitic;
pub mod performance;
pub mod pivot;
pub mod profile;
pub mod sector;
pub mod thd;
pub mod tilting_pad;
