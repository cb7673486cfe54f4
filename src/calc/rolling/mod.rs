//! Rolling-element bearings: the kinematics of balls and rollers between two rings (cage and
//! spin speeds, defect frequencies, entrainment speeds for EHL), the internal load distribution
//! of ball bearings (with tilting moment and the centrifugal and gyroscopic ball loads at
//! speed) and of cylindrical roller bearings, the static capacity (ISO 76 C0, P0, s0), and the
//! fatigue life of a bearing (basic rating life L10, reliability factor a1, ISO 281's life
//! modification factor a_ISO and the modified life).
//!
//! Sources: Hamrock's handbook chapter 21 (kinematics, eqs 21.93–21.98; fatigue life and the
//! Weibull reliability relation), Khonsari & Booser chapters 13–14 (RB-3…RB-7, RI-7, Ex 13.1–13.4,
//! the 6210 defect frequencies), and ISO 281:2007 for a_ISO and the rated viscosity ν1 (outside
//! the texts; each constant cites where it was checked).
//!
//! Layout. Wire files (serde, `Validate`, `impl Calculation`): `analysis`, `friction`,
//! `grease_life`, `kinematics`, `life`, `load_distribution`, `static_capacity` are the rooms
//! (each with its description in `<room>.md` and long tests in `<room>_tests.rs`);
//! `bearing_spec` is the requests' shared `bearing` object (ball and roller bearing specs,
//! materials) and its validation. Model files (plain types and functions): `geometry` holds the
//! ball bearing's internal geometry and raceway contacts, `ring_equilibrium` and
//! `ball_equilibrium` solve the ball bearing's equilibrium, `roller` the roller bearing's,
//! `iso76` computes the static rating (C0, P0, s0) and `iso281` the fatigue lives.

pub mod analysis;
mod ball_equilibrium;
mod bearing_spec;
pub mod friction;
pub mod geometry;
pub mod grease_life;
mod iso281;
mod iso76;
pub mod kinematics;
pub mod life;
pub mod load_distribution;
mod ring_equilibrium;
pub mod roller;
pub mod static_capacity;
