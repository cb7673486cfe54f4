//! Dry elastic contact of curved bodies: the Hertz point, elliptical and line contacts, with the
//! subsurface stresses under them (Hamrock ch. 21.3.1; Stachowiak & Batchelor §7.3; Khonsari &
//! Booser §14.2–14.3; Johnson, *Contact Mechanics*, ch. 3–4).

pub mod ehl;
pub mod ehl_film;
pub mod flash_temperature;
pub mod hertz;
pub mod moving_heat_source;
