//! Hydrostatic bearings (Khonsari & Booser ch. 10; Stachowiak & Batchelor ch. 6; spec
//! khonsari-booser-ch9-17 HS-1 to HS-8, stachowiak-batchelor-ch2-7 D1–D4).
//!
//! - `pad`: the `/v1/hydrostatic-bearings/pad` room (wire);
//! - `design`: the `/v1/hydrostatic-bearings/design` room (wire): minimum power, oil lift;
//! - `operating`: a pad at its operating point: the determinate set solved, stiffness, effects;
//! - `point`: the operating point itself (film, load, pressures, flow);
//! - `geometry`: A_eff, the flow coefficient and the land drag of each pad kind;
//! - `lands`: the lands' film law, laminar or with the turbulent slit law;
//! - `restrictor`: constant flow, capillary, orifice: laws, sizes, optimum pressure ratios;
//! - `power`: pumping, land friction, temperature rise;
//! - `optimum`: the circular step's minimum-power recess ratio and film;
//! - `lift`: the oil lift of a large journal bearing at start-up (Fuller, Elwell).

pub mod design;
pub mod geometry;
pub mod lands;
pub mod lift;
pub mod operating;
pub mod optimum;
pub mod pad;
pub mod point;
pub mod power;
pub mod restrictor;
