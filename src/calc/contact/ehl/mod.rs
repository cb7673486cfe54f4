//! Elastohydrodynamic lubrication: the closed-form film room and the numerical room, and what
//! both read.
//!
//! - [`film`]: wire of `POST /v1/contacts/ehl-film` (`film.md` its long description); the
//!   calculation itself is [`closed_form`] (`closed_form::solve(&FilmCase) -> FilmSolution`),
//!   which composed rooms call typed.
//! - [`numerical`]: wire of `POST /v1/contacts/ehl`; its model [`solve`] drives the solvers
//!   (the line grids refined under `numerics::refine`, the point grid fall-back and step-up,
//!   Richardson's films with the point films' error estimates, and the reports): [`line`] (coupled Newton on one grid, under `numerics::newton`),
//!   [`point`] (FAS multigrid, its cycles under the solver driver), [`fluid`]
//!   (viscosity and density in the solvers' units), [`traction`] (sliding traction of the
//!   converged film).
//! - [`formulas`]: Hamrock–Dowson (hard, soft, the four regimes and the regime rule),
//!   Pan–Hamrock, Dowson–Higginson, Moes; [`corrections`]: the inlet-heating (Gupta) and
//!   starvation (Hamrock–Dowson meniscus) factors. The film parameter Λ is surface physics
//!   ([`crate::calc::surface::roughness`]).

pub mod closed_form;
pub mod corrections;
pub mod film;
pub mod fluid;
pub mod formulas;
pub mod line;
pub mod numerical;
pub mod point;
pub mod solve;
pub mod traction;

pub use numerical::Ehl;
