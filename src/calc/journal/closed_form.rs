//! Closed-form plain 360° journal bearings: the infinitely long bearing (ILA) with the full
//! Sommerfeld, half Sommerfeld and Reynolds (Swift–Stieber) boundary conditions, the infinitely
//! short (Ocvirk) bearing, Petroff's concentric friction, and the linearised stiffness and damping
//! of the short bearing with the π film.
//!
//! Sources: Khonsari & Booser, *Applied Tribology*, 3rd ed., ch. 8 — §8.2–8.8 and Tables 8.2–8.4
//! (long bearing), §8.9–8.11 and Table 8.5 (short bearing), Eq. 8.38–8.44 and Table 8.6 (the
//! conventions of [`Performance`]); dynamic coefficients from Childs, *Turbomachinery
//! Rotordynamics* (1993), ch. 3, as restated by Friswell, Penny, Garvey & Lees, *Dynamics of
//! Rotating Machines* (2010), §5.5.
//!
//! Geometry (G1): h = C(1 + ε cos θ), θ from h_max in the direction of rotation. Every result is
//! dimensionless; the eccentricity ratio ε = e/C must lie in (0, 1). All outputs stay finite
//! there (the tests sweep ε from 1e-4 to 0.9999); at ε → 0 the Sommerfeld number grows as 1/ε.

use std::f64::consts::PI;

use crate::numerics::roots::{brent, Stopping};

/// Boundary condition on the film's divergent part.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Boundary {
    /// The whole 360° film carries pressure, negative in the divergent half (no cavitation).
    FullSommerfeld,
    /// The negative half of the full-Sommerfeld pressure is dropped: film from θ = 0 to π.
    HalfSommerfeld,
    /// Swift–Stieber: the film ruptures where p = dp/dθ = 0 (long bearing only).
    Reynolds,
}

/// Dimensionless performance of a plain 360° journal bearing at one eccentricity ratio,
/// in Table 8.6 conventions (N_s in rev/s, angles from h_max in the direction of rotation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Performance {
    /// S = μ N_s L D (R/C)² / W.
    pub sommerfeld_number: f64,
    /// Angle between the load line and the line of centres, rad.
    pub attitude_angle_rad: f64,
    /// (R/C)·f on the journal surface, shear over the full circumference:
    /// (ε/2) sin φ + 2π² S / √(1 − ε²) (G5).
    pub friction_parameter: f64,
    /// (p_max − p_s)(C/R)²/(μ N_s), N_s in rev/s: 2π × Table 8.4's ω-based P̄_max.
    pub max_pressure_nd: f64,
    /// Angle of the peak pressure from h_max, rad.
    pub max_pressure_angle_rad: f64,
    /// Film rupture angle from h_max, rad; `None` for the full Sommerfeld film.
    pub cavitation_angle_rad: Option<f64>,
    /// Q_L / ((π/2) N_s D L C), both ends: 0 for the long bearing, 2ε for the short bearing.
    pub side_leakage_nd: f64,
}

/// Infinitely long bearing (ILA, §8.2–8.8).
///
/// With W̄ = W/(μ R ω L (R/C)²) and S = 1/(π W̄):
/// - full Sommerfeld (Table 8.2): S = √(1 − ε²)(2 + ε²)/(12π² ε), φ = 90°;
/// - half Sommerfeld (Table 8.2): S = (2 + ε²)(1 − ε²)/{6π ε [π²(1 − ε²) + 4ε²]^½},
///   φ = atan[π √(1 − ε²)/(2ε)], rupture at θ = π;
/// - Reynolds (§8.7, Table 8.4): the rupture angle from a bracketed root-find in the Sommerfeld
///   variable γ (one root in (π, 2π) for every ε), then S, φ and the peak in closed form; the peak
///   sits at θ_max = 2π − θ_cav.
///
/// Both Sommerfeld films share the positive pressure lobe, so their peak is the same:
/// P̄_max = 3ε(4 − ε²)(4 − 5ε² + ε⁴)^½ / [2(1 − ε²)²(2 + ε²)] at θ = acos[−3ε/(2 + ε²)]
/// (Table 8.2, ω-based; reported ×2π). There is no side leakage.
pub fn long_bearing(eps: f64, boundary: Boundary) -> Performance {
    debug_assert!(
        eps > 0.0 && eps < 1.0,
        "eccentricity ratio {eps} outside (0, 1)"
    );
    let e2 = eps * eps;
    match boundary {
        Boundary::FullSommerfeld => assemble(
            eps,
            (1.0 - e2).sqrt() * (2.0 + e2) / (12.0 * PI * PI * eps),
            PI / 2.0,
            sommerfeld_long_peak(eps),
            None,
            0.0,
        ),
        Boundary::HalfSommerfeld => assemble(
            eps,
            (2.0 + e2) * (1.0 - e2) / (6.0 * PI * eps * (PI * PI * (1.0 - e2) + 4.0 * e2).sqrt()),
            (PI * (1.0 - e2).sqrt()).atan2(2.0 * eps),
            sommerfeld_long_peak(eps),
            Some(PI),
            0.0,
        ),
        Boundary::Reynolds => reynolds_long_bearing(eps),
    }
}

/// Infinitely short bearing (Ocvirk, ISA, §8.9–8.11) at length/diameter `l_over_d`.
/// Boundary::Reynolds is not defined for the short bearing: return None for it.
/// `None` also when `l_over_d` is not a finite number > 0.
///
/// Table 8.5, with (D/L)² carrying the length: S·(L/D)² depends on ε only.
/// - full Sommerfeld: S = (D/L)²(1 − ε²)^{3/2}/(2π² ε), φ = 90°;
/// - half Sommerfeld: S = (D/L)²(1 − ε²)²/{π ε [π²(1 − ε²) + 16ε²]^½},
///   φ = atan[π √(1 − ε²)/(4ε)], rupture at θ = π.
///
/// Peak (mid-plane, Table 8.5): P̄ = (R/(μU))(C/L)² p = (3/4) ε sin θ_m/(1 + ε cos θ_m)³ at
/// θ_m = acos{[1 − √(1 + 24ε²)]/(4ε)}; Table 8.6's scale is 8π(L/D)² times Table 8.5's.
/// Side leakage (Eq. 8.33): Q = ε U L C, so Q̄_L = 2ε. It is the flow leaving the convergent half;
/// for the full Sommerfeld film the divergent half draws the same amount back in.
///
/// Friction uses the journal-surface identity (G5), including the pressure-flow term (ε/2) sin φ;
/// the text's short-bearing F (§8.11) keeps the Couette term only.
///
/// Valid for L/D ≤ 1/2; gives trends up to L/D = 1 (§8.9). It overestimates the load of a
/// finite bearing, increasingly with ε (S about 5 % low at L/D = 1/4, ε = 0.5, against Table 8.6).
pub fn short_bearing(eps: f64, l_over_d: f64, boundary: Boundary) -> Option<Performance> {
    debug_assert!(
        eps > 0.0 && eps < 1.0,
        "eccentricity ratio {eps} outside (0, 1)"
    );
    if !l_over_d.is_finite() || l_over_d <= 0.0 {
        return None;
    }
    let e2 = eps * eps;
    let d_over_l_squared = (1.0 / l_over_d).powi(2);
    let (sommerfeld_number, attitude_angle_rad, cavitation_angle_rad) = match boundary {
        Boundary::FullSommerfeld => (
            d_over_l_squared * (1.0 - e2).powf(1.5) / (2.0 * PI * PI * eps),
            PI / 2.0,
            None,
        ),
        Boundary::HalfSommerfeld => (
            d_over_l_squared * (1.0 - e2).powi(2)
                / (PI * eps * (PI * PI * (1.0 - e2) + 16.0 * e2).sqrt()),
            (PI * (1.0 - e2).sqrt()).atan2(4.0 * eps),
            Some(PI),
        ),
        Boundary::Reynolds => return None,
    };
    Some(assemble(
        eps,
        sommerfeld_number,
        attitude_angle_rad,
        ocvirk_peak(eps, l_over_d),
        cavitation_angle_rad,
        2.0 * eps,
    ))
}

/// Petroff: (R/C)·f = 2π² S for a concentric journal (§5.5, Eq. 5.27 power loss; the ε → 0 limit
/// of the G5 identity).
pub fn petroff_friction_parameter(sommerfeld_number: f64) -> f64 {
    2.0 * PI * PI * sommerfeld_number
}

/// Linearised stiffness and damping of the short (Ocvirk) bearing with the half-Sommerfeld (π) film,
/// dimensionless: k_ij = K_ij C / W, c_ij = C_ij C ω / W, in the frame x along the static load
/// (towards the load, i.e. downward for a weight), y perpendicular to it, 90° ahead in the direction of rotation.
/// Ordering [xx, xy, yx, yy].
///
/// Force on the journal ΔF_i = −K_ij Δx_j − C_ij Δẋ_j. With A₀ = [π²(1 − ε²) + 16ε²]^{−3/2}:
///
/// ```text
/// k_xx = 4 A₀ [π²(1 + 2ε²) + 32ε²(1 + ε²)/(1 − ε²)]
/// k_xy = π A₀ [π²(1 − ε²)(1 + 2ε²) + 32ε²(1 + ε²)] / (ε √(1 − ε²))
/// k_yx = −π A₀ [π²(1 − ε²)² − 16ε⁴] / (ε √(1 − ε²))
/// k_yy = 4 A₀ [π²(2 − ε²) + 16ε²]
/// c_xx = 2π A₀ [π²(1 − ε²)² + 48ε²] / (ε √(1 − ε²))
/// c_xy = c_yx = 8 A₀ [π²(1 + 2ε²) − 16ε²]
/// c_yy = 2π A₀ √(1 − ε²) [π²(1 + 2ε²) − 16ε²] / ε
/// ```
///
/// Source: the short-bearing coefficients of Childs, *Turbomachinery Rotordynamics* (1993), ch. 3,
/// as tabulated by Friswell, Penny, Garvey & Lees, *Dynamics of Rotating Machines* (2010), §5.5
/// (a_uu … b_vv). Those read in a frame with v along the static load and u 90° behind it in the
/// direction of rotation (the finite-difference test below pins this down). In ours (x = v, y = −u): k_xx = a_vv, k_xy = −a_vu, k_yx = −a_uv, k_yy = a_uu,
/// c_xx = b_vv, c_xy = c_yx = −b_uv, c_yy = b_uu. Note the grouping in k_xx: only the 32ε² term
/// carries 1/(1 − ε²). The tests re-derive all eight by differentiating the π-film short-bearing
/// forces (pressure kept on 0 < θ < π from h_max, with the squeeze term) at the static position.
///
/// Finite for ε in (0, 1); the cross-coupled stiffnesses and the damping grow as 1/ε when
/// ε → 0 because W → 0. Same validity as [`short_bearing`] (L/D ≤ 1/2).
pub fn short_bearing_dynamic_coefficients(eps: f64) -> ([f64; 4], [f64; 4]) {
    debug_assert!(
        eps > 0.0 && eps < 1.0,
        "eccentricity ratio {eps} outside (0, 1)"
    );
    let e2 = eps * eps;
    let pi2 = PI * PI;
    let root = (1.0 - e2).sqrt();
    let a0 = (pi2 * (1.0 - e2) + 16.0 * e2).powf(-1.5);
    let stiffness = [
        4.0 * a0 * (pi2 * (1.0 + 2.0 * e2) + 32.0 * e2 * (1.0 + e2) / (1.0 - e2)),
        PI * a0 * (pi2 * (1.0 - e2) * (1.0 + 2.0 * e2) + 32.0 * e2 * (1.0 + e2)) / (eps * root),
        -PI * a0 * (pi2 * (1.0 - e2).powi(2) - 16.0 * e2 * e2) / (eps * root),
        4.0 * a0 * (pi2 * (2.0 - e2) + 16.0 * e2),
    ];
    let cross_damping = 8.0 * a0 * (pi2 * (1.0 + 2.0 * e2) - 16.0 * e2);
    let damping = [
        2.0 * PI * a0 * (pi2 * (1.0 - e2).powi(2) + 48.0 * e2) / (eps * root),
        cross_damping,
        cross_damping,
        2.0 * PI * a0 * root * (pi2 * (1.0 + 2.0 * e2) - 16.0 * e2) / eps,
    ];
    (stiffness, damping)
}

/// Linearised stiffness and damping of the short bearing with the full (Sommerfeld, 2π) film,
/// dimensionless and in the frame of [`short_bearing_dynamic_coefficients`] (x along the load,
/// y 90° ahead in the direction of rotation; k_ij = K_ij C/W, c_ij = C_ij C ω/W):
///
/// ```text
/// k_xx = k_yy = 0,   k_xy = (1 + 2ε²)/[ε (1 − ε²)],   k_yx = −1/ε,
/// c_xx = 2/ε,        c_yy = 2 (1 + 2ε²)/[ε (1 − ε²)], c_xy = c_yx = 0.
/// ```
///
/// Derived here (no text prints them): the short-bearing film with squeeze, ∫p dz ∝ G/h̄³ with
/// G the wedge-and-squeeze drive, integrated over the whole circle, where the Sommerfeld
/// integrals ∫sin²θ/h̄³ = π/(1 − ε²)^{3/2} and ∫cos²θ/h̄³ = π(1 + 2ε²)/(1 − ε²)^{5/2}, and
/// ∫sin²θ cos θ/h̄⁴ by parts, give every term; the load is W ∝ (ε/2)∫sin²θ/h̄³. The tests
/// differentiate the integrated force numerically. The direct stiffnesses vanish (the full film
/// pushes only at 90° to a displacement), so Lund's equivalent stiffness is 0 and the rotor
/// whirls at exactly half speed for every mass: there is no stable speed (see
/// `journal::threshold`). At ε → 0 they are the π film's light-load limits.
pub fn short_full_sommerfeld_dynamic_coefficients(eps: f64) -> ([f64; 4], [f64; 4]) {
    debug_assert!(
        eps > 0.0 && eps < 1.0,
        "eccentricity ratio {eps} outside (0, 1)"
    );
    let e2 = eps * eps;
    let grown = (1.0 + 2.0 * e2) / (eps * (1.0 - e2));
    (
        [0.0, grown, -1.0 / eps, 0.0],
        [2.0 / eps, 0.0, 0.0, 2.0 * grown],
    )
}

/// Table 8.4's pressure scale is μω(R/C)²; Table 8.6's is μN_s(R/C)² = μω(R/C)²/(2π).
const OMEGA_TO_REV_PER_S: f64 = 2.0 * PI;

/// The peak film pressure in Table 8.6's N_s-based scale, and its angle from h_max (rad).
struct PressurePeak {
    nd: f64,
    angle_rad: f64,
}

/// Gathers one row; friction from the journal-surface identity (G5, §8.12):
/// (R/C)·f = (ε/2) sin φ + 2π² S/√(1 − ε²) — Couette shear 2π²S/√(1 − ε²) over the full
/// circumference plus the pressure-flow shear, which integrates by parts to (ε/2)·W sin φ·(C/R).
fn assemble(
    eps: f64,
    sommerfeld_number: f64,
    attitude_angle_rad: f64,
    peak: PressurePeak,
    cavitation_angle_rad: Option<f64>,
    side_leakage_nd: f64,
) -> Performance {
    Performance {
        sommerfeld_number,
        attitude_angle_rad,
        friction_parameter: 0.5 * eps * attitude_angle_rad.sin()
            + petroff_friction_parameter(sommerfeld_number) / (1.0 - eps * eps).sqrt(),
        max_pressure_nd: peak.nd,
        max_pressure_angle_rad: peak.angle_rad,
        cavitation_angle_rad,
        side_leakage_nd,
    }
}

/// Peak of the long-bearing full-Sommerfeld pressure (Table 8.2), shared by the half film.
/// 4 − 5ε² + ε⁴ is written (1 − ε²)(4 − ε²).
fn sommerfeld_long_peak(eps: f64) -> PressurePeak {
    let e2 = eps * eps;
    let nd_omega = 3.0 * eps * (4.0 - e2) * ((1.0 - e2) * (4.0 - e2)).sqrt()
        / (2.0 * (1.0 - e2).powi(2) * (2.0 + e2));
    PressurePeak {
        nd: OMEGA_TO_REV_PER_S * nd_omega,
        angle_rad: (-3.0 * eps / (2.0 + e2)).acos(),
    }
}

/// Peak of the short-bearing pressure on the mid-plane (Table 8.5), in Table 8.6's scale:
/// p (C/R)²/(μN_s) = 2π (L/R)² P̄ = 6π (L/D)² ε sin θ_m/(1 + ε cos θ_m)³, where θ_m solves
/// 2ε cos²θ − cos θ − 3ε = 0: cos θ_m = [1 − √(1 + 24ε²)]/(4ε), written −6ε/[1 + √(1 + 24ε²)]
/// to avoid the cancellation at small ε.
fn ocvirk_peak(eps: f64, l_over_d: f64) -> PressurePeak {
    let cos_peak = -6.0 * eps / (1.0 + (1.0 + 24.0 * eps * eps).sqrt());
    let sin_peak = (1.0 - cos_peak * cos_peak).sqrt();
    PressurePeak {
        nd: 6.0 * PI * l_over_d * l_over_d * eps * sin_peak / (1.0 + eps * cos_peak).powi(3),
        angle_rad: cos_peak.acos(),
    }
}

/// Long bearing with the Reynolds (Swift–Stieber) condition (§8.7, Table 8.4), from the rupture
/// angle γ_c of the Sommerfeld substitution. The text's
///
/// ```text
/// S = (1 − ε²)(1 − ε cos γ_c) / {3π [ε²(1 − cos γ_c)⁴ + 4(1 − ε²)(γ_c cos γ_c − sin γ_c)²]^½}
/// φ = atan{2 √(1 − ε²)(sin γ_c − γ_c cos γ_c) / [ε (1 − cos γ_c)²]}
/// ```
///
/// are evaluated with 2(sin γ_c − γ_c cos γ_c) = ε(γ_c − sin γ_c cos γ_c) (the rupture
/// condition), which takes the common factor ε out and keeps both finite as ε → 0.
///
/// The peak: dP̄/dθ = 6(h̄ − h̄_c)/h̄³ vanishes where h̄ = h̄_c, i.e. at γ = 2π − γ_c on the
/// convergent side, so P̄_max = P̄(2π − γ_c) and θ_max = 2π − θ_cav (Table 8.4: 106.7° + 253.3°).
fn reynolds_long_bearing(eps: f64) -> Performance {
    let e2 = eps * eps;
    let gamma_cav = reynolds_rupture_gamma(eps);
    let (sin_c, cos_c) = gamma_cav.sin_cos();
    let arc = gamma_cav - sin_c * cos_c;
    let opening = (1.0 - cos_c).powi(2);
    let sommerfeld_number = (1.0 - e2) * (1.0 - eps * cos_c)
        / (3.0 * PI * eps * (opening * opening + (1.0 - e2) * arc * arc).sqrt());
    let attitude_angle_rad = ((1.0 - e2).sqrt() * arc).atan2(opening);
    let gamma_peak = 2.0 * PI - gamma_cav;
    let peak = PressurePeak {
        nd: OMEGA_TO_REV_PER_S * reynolds_pressure_nd(eps, gamma_peak, gamma_cav),
        angle_rad: theta_from_gamma(eps, gamma_peak),
    };
    assemble(
        eps,
        sommerfeld_number,
        attitude_angle_rad,
        peak,
        Some(theta_from_gamma(eps, gamma_cav)),
        0.0,
    )
}

/// Rupture angle γ_c ∈ (π, 2π) of the Reynolds condition in the Sommerfeld variable (§8.7):
/// ε(γ − sin γ cos γ) = 2(sin γ − γ cos γ), the text's ε(2γ − 2 sin γ cos γ) = 4 sin γ − 4γ cos γ.
///
/// The residual g(γ) = ε(γ − sin γ cos γ) − 2(sin γ − γ cos γ) is π(ε − 2) < 0 at π and
/// 2π(ε + 2) > 0 at 2π, and g′(γ) = 2 sin γ (ε sin γ − γ) > 0 on (π, 2π): one root, bracketed for
/// every ε in [0, 1). Brent, to 1e-14 rad.
fn reynolds_rupture_gamma(eps: f64) -> f64 {
    let residual = |gamma: f64| {
        let (sin_g, cos_g) = gamma.sin_cos();
        eps * (gamma - sin_g * cos_g) - 2.0 * (sin_g - gamma * cos_g)
    };
    let stop = Stopping {
        x_tolerance: 1e-14,
        max_iterations: 100,
    };
    // The bracket always holds one root; only a NaN ε fails, and NaN then flows through like
    // every other formula here.
    brent(residual, PI, 2.0 * PI, stop).map_or(f64::NAN, |root| root.x)
}

/// Long-bearing pressure with the film's flow set by γ_c (G2, §8.7), ω-based:
/// P̄(γ) = 6(1 − ε²)^{−3/2} {γ − ε sin γ − [(2 + ε²)γ − 4ε sin γ + ε² sin γ cos γ]/[2(1 − ε cos γ_c)]},
/// from ∫dθ/h̄² and ∫dθ/h̄³ in the Sommerfeld variable, with P̄(0) = 0 and dP̄/dθ = 0 at γ_c.
fn reynolds_pressure_nd(eps: f64, gamma: f64, gamma_cav: f64) -> f64 {
    let e2 = eps * eps;
    let (sin_g, cos_g) = gamma.sin_cos();
    let flow_film = 1.0 - eps * gamma_cav.cos();
    6.0 * (1.0 - e2).powf(-1.5)
        * (gamma
            - eps * sin_g
            - ((2.0 + e2) * gamma - 4.0 * eps * sin_g + e2 * sin_g * cos_g) / (2.0 * flow_film))
}

/// Physical angle θ ∈ [0, 2π) of the Sommerfeld variable γ (G2): cos γ = (ε + cos θ)/(1 + ε cos θ)
/// inverts to cos θ = (cos γ − ε)/(1 − ε cos γ), sin θ = √(1 − ε²) sin γ/(1 − ε cos γ);
/// atan2 keeps the branch (θ and γ lie in the same half turn).
fn theta_from_gamma(eps: f64, gamma: f64) -> f64 {
    let (sin_g, cos_g) = gamma.sin_cos();
    ((1.0 - eps * eps).sqrt() * sin_g)
        .atan2(cos_g - eps)
        .rem_euclid(2.0 * PI)
}

#[cfg(test)]
mod tests;
