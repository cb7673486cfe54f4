//! Contacts of curved bodies: the dry Hertz contact ([`hertz`]), its lubricated form
//! ([`ehl`]: closed-form films and the numerical solution) and the flash temperature of a
//! sliding contact ([`flash_temperature`], wire of the surface model
//! [`crate::calc::surface::flash`]). Each room is a wire file over a model (Hamrock ch. 21;
//! Stachowiak & Batchelor ch. 7; Khonsari & Booser ch. 14–15; Johnson, *Contact Mechanics*).

pub mod ehl;
pub mod flash_temperature;
pub mod hertz;
