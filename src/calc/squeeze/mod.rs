//! Squeeze films (Khonsari & Booser ch. 9; spec khonsari-booser-ch9-17 SQ-0 to SQ-7).
//!
//! - `plates`: the `/v1/squeeze-films/plates` room (wire); `shapes`: its model — plates, a
//!   sphere and a cylinder approaching a flat, closed forms;
//! - `lubricant`: the viscosity both rooms take from the shared `lubricant` object.

mod lubricant;
pub mod plates;
pub mod shapes;
