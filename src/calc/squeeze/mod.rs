//! Squeeze films (Khonsari & Booser ch. 9; spec khonsari-booser-ch9-17 SQ-0 to SQ-8).
//!
//! - `plates`: the `/v1/squeeze-films/plates` room (wire); `shapes`: its model — plates, a
//!   sphere and a cylinder approaching a flat, closed forms;
//! - `journal`: the `/v1/squeeze-films/journal` room (wire); its models `long_journal` (the
//!   infinitely long bearing, closed forms) and `finite_journal` (the finite bearing: the
//!   journal room's numerical film, squeezed, and the time by quadrature); both take their
//!   viscosity from `calc::lubricant::isoviscous`; `rotating_journal` (the journal that turns
//!   while squeezed: the orbit of `calc::journal::orbit` under a constant load);
//! - `piston_ring`: the `/v1/squeeze-films/piston-ring` room (wire); its model `piston_film`
//!   (the crowned compression ring's film over an engine cycle, SQ-8).

pub mod finite_journal;
pub mod journal;
pub mod long_journal;
pub mod piston_film;
pub mod piston_ring;
pub mod plates;
pub mod rotating_journal;
pub mod shapes;
