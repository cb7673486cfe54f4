//! The rooms: one folder per calculation family. Nothing here knows about HTTP; the door
//! (`crate::http`) and the CLI (`stribeck run`) both go through [`execute`].

pub mod composite;
pub mod contact;
pub mod gas;
pub mod grid_cost;
pub mod hydrostatic;
pub mod journal;
pub mod lubricant;
pub mod quantity;
pub mod rolling;
pub mod squeeze;
pub mod surface;
pub mod thrust;
pub mod turbulence;

mod context;
pub(crate) mod range_schemas;
mod registry;
mod schema_bounds;
#[cfg(test)]
pub(crate) mod testing;

pub use crate::numerics::driver::Budget;
pub use context::{CalcError, Context, Notes, Warning};
pub use registry::{
    execute, find, validate_value, Cost, Costing, Entry, Envelope, Executed, Failure, FieldError,
    REGISTRY,
};

use serde::de::DeserializeOwned;
use serde::Serialize;
use utoipa::ToSchema;

use crate::fidelity::Level;

/// Cross-field rules of a request, checked after parsing and before any physics runs.
/// Single-field rules live in the field's type (`Positive`, …); `validate` turns the wire form
/// into the parsed case the physics takes, or lists every invalid field with its JSON pointer.
pub trait Validate: Sized {
    type Valid;
    fn validate(self) -> Result<Self::Valid, Vec<FieldError>>;
}

/// One calculation: a typed input, a typed output and the physics between them.
/// Registered once in [`REGISTRY`]; routes, `/v1/calculations`, the OpenAPI and `stribeck run`
/// all read that list.
pub trait Calculation: 'static {
    /// URL path, e.g. `/v1/lubricants/viscosity`.
    const PATH: &'static str;
    /// One line for the API listing.
    const SUMMARY: &'static str;
    /// A paragraph for the OpenAPI: the models and the sources.
    const DESCRIPTION: &'static str;
    /// Fidelity levels offered.
    const FIDELITY: &'static [Level];
    /// Names of the effects this calculation understands.
    const EFFECTS: &'static [&'static str];
    /// A request that works as pasted (used in the OpenAPI example and the docs).
    const EXAMPLE: &'static str;

    type Input: DeserializeOwned + ToSchema + Validate;
    type Output: Serialize + ToSchema;

    fn run(
        input: <Self::Input as Validate>::Valid,
        ctx: &mut Context,
    ) -> Result<Self::Output, CalcError>;
}
