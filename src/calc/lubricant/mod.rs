//! Lubricant properties (Khonsari & Booser ch. 2; Stachowiak & Batchelor ch. 2), and the shared
//! `lubricant` object every family takes.

pub mod astm_d2270;
pub mod isoviscous;
pub mod model;
pub mod properties;
pub mod spec;
pub mod validity;
pub mod viscosity;
pub mod viscosity_index;

pub use model::Lubricant;
pub use spec::LubricantSpec;
