//! The plain bearing's domain result: what the model computes, in SI units and radians; the
//! wire (`plain.rs`) maps it into the response.

use crate::calc::journal::eccentricity::EccentricityRatio;
use crate::calc::journal::feed::Flows;
use crate::fidelity::SolverReport;

use super::Notes;

/// The plain bearing solved: dimensional results in SI units, angles in radians from h_max in
/// the direction of rotation (Table 8.6 conventions; S and P̄ with N_s in rev/s).
#[derive(Debug, Clone)]
pub struct Solution {
    /// Steady load W, N (the whole bearing's).
    pub load_n: f64,
    pub sommerfeld_number: f64,
    pub eccentricity_ratio: EccentricityRatio,
    /// φ, between the load line and the line of centres, rad.
    pub attitude_angle: f64,
    pub min_film_thickness_m: f64,
    /// Peak film pressure, Pa gauge (with the supply pressure unless the film holds it).
    pub max_pressure_pa: f64,
    /// P̄_max = p_max (C/R)²/(μ N_s).
    pub max_pressure_nd: f64,
    /// Angle of the peak, rad.
    pub max_pressure_angle: f64,
    /// Film rupture angle, rad; None for a full film.
    pub cavitation_start_angle: Option<f64>,
    pub cavitated_area_fraction: Option<f64>,
    pub petroff_friction_coefficient: f64,
    pub friction_coefficient: f64,
    /// (R/C) f.
    pub friction_parameter: f64,
    pub friction_torque_n_m: f64,
    pub power_loss_w: f64,
    pub side_leakage_m3_s: f64,
    /// Q_L/((π/2) N_s D L C).
    pub side_leakage_nd: f64,
    pub inlet_flow_m3_s: Option<f64>,
    pub temperature_rise_k: Option<f64>,
    /// Jang & Khonsari's THD temperatures, for temperature-dependent lubricants.
    pub bush_temperatures: Option<BushTemperatures>,
    /// Martin's flows, with a feed (not for a JFO film fed through ports).
    pub flows: Option<Flows>,
    pub effective_temperature_c: f64,
    pub effective_viscosity_pa_s: f64,
    /// Film Reynolds number ρ U C/μ.
    pub reynolds_number: f64,
    /// The closed form used, by name; None for the numerical solution.
    pub approximation: Option<&'static str>,
    pub approximation_note: Option<String>,
    /// Mid-plane pressure profile, when asked and numerical.
    pub pressure_profile: Option<Vec<ProfileNode>>,
    /// The film's moment on a misaligned journal.
    pub moment: Option<Moment>,
    /// Stiffness, damping and stability, when asked and available.
    pub dynamics: Option<Dynamics>,
    pub report: SolverReport,
    pub notes: Notes,
}

/// Jang & Khonsari's maximum bush and shaft temperatures, °C.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BushTemperatures {
    pub max_c: f64,
    pub shaft_c: f64,
}

/// One node of the mid-plane pressure profile.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ProfileNode {
    /// θ from h_max, rad.
    pub angle: f64,
    /// Film pressure, Pa.
    pub pressure_pa: f64,
    /// Film content θ_f (mass-conserving films).
    pub film_content: Option<f64>,
}

/// The film's moment on a misaligned journal, about the bearing centre, in the load frame (x
/// along the static load, y 90° ahead in the rotation, z along the spin).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Moment {
    pub mx_n_m: f64,
    pub my_n_m: f64,
    pub magnitude_n_m: f64,
    /// (M_x, M_y)/(μ N_s (R/C)² R L²).
    pub nd: [f64; 2],
    /// The component against the tilt, N·m (positive: the film resists the misalignment).
    pub restoring_n_m: f64,
}

/// Stiffness and damping in the load frame, [xx, xy, yx, yy], and the rotor's stability.
#[derive(Debug, Clone)]
pub struct Dynamics {
    pub stiffness_n_m: [f64; 4],
    pub damping_n_s_m: [f64; 4],
    /// K_ij C/W.
    pub stiffness_nd: [f64; 4],
    /// C_ij C ω/W.
    pub damping_nd: [f64; 4],
    pub method: CoefficientsMethod,
    pub stability: RotorStability,
}

/// How the dynamic coefficients were obtained.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CoefficientsMethod {
    /// The short (Ocvirk) bearing's closed form with the half-Sommerfeld film.
    ShortBearing,
    /// Perturbation of the converged Reynolds film.
    Perturbation,
    /// Perturbation of the converged mass-conserving (JFO) film.
    PerturbationMassConserving,
}

/// Rigid-rotor stability (Lund's linearised threshold).
#[derive(Debug, Clone)]
pub struct RotorStability {
    pub stable_at_operating_speed: bool,
    pub threshold_speed_rpm: Option<f64>,
    pub whirl_frequency_ratio: Option<f64>,
    /// m C ω²/W at the threshold.
    pub critical_mass_parameter: Option<f64>,
    pub critical_speed_rad_s: Option<f64>,
    /// ω_c (C/g)^½.
    pub critical_speed_nd: Option<f64>,
    /// The rotor's m C ω²/W at the operating speed.
    pub mass_parameter: f64,
    pub rotor_mass_kg: f64,
    /// The verdict in words.
    pub statement: String,
}
