//! Harnoy's composite bearing: a rolling bearing and a fluid-film sleeve in series (Harnoy,
//! *Bearing Design in Machinery*, ch. 18; spec PART B, with its corrections).
//!
//! - `speed_split`: the `/v1/composite-bearings/speed-split` room (wire); its models `film`
//!   (the short film with a turning sleeve: load on the speed sum, torque on the difference),
//!   `sleeve` (the pin and rolling-bearing restraint, the steady speed in closed form) and
//!   `split` (the steady split at an eccentricity or a load, the held sleeve beside it).
//! - `start_up`: the `/v1/composite-bearings/start-up` room (wire); its model `start` (the
//!   rolling phase, break-away and the sleeve's run-down to its steady speed).
//! - `orbit`: the `/v1/composite-bearings/orbit` room (wire); its model `locus` (the journal's
//!   orbit with the sleeve's speed as a fifth state), the held sleeve by `journal::orbit`.

pub mod film;
pub mod locus;
pub mod orbit;
pub mod sleeve;
pub mod speed_split;
pub mod split;
pub mod start;
pub mod start_up;
