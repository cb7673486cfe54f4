//! The Hertz contact of two elastic bodies (point, elliptical, line), with the subsurface
//! stresses under the centre.
//!
//! - [`model`]: what other rooms call — [`Contact::new`] checks two [`Body`]s, a load and a
//!   [`Shape`]; [`Contact::solve`] returns a [`Solution`] with its warnings as data.
//! - [`subsurface`]: the stresses on the axis below the centre and their maxima in depth.
//! - `wire`: `POST /v1/contacts/hertz` — the request, its validation, the response
//!   (`hertz.md` is the room's long description).

pub mod model;
pub mod subsurface;
mod wire;

pub use model::{
    Axis, Body, Contact, Field, Fit, Footprint, Invalid, MajorAxis, Method, Shape, Solution,
    APPROACH_UNDEFINED_FOR_FLAT,
};
pub(crate) use wire::{contact_of, method_of};
pub use wire::{
    BodySpec, ClosedFormFit, Hertz, HertzInput, HertzOutput, LineSpec, SubsurfaceStress,
};

#[cfg(test)]
mod tests;
