//! ISO 76's basic static load rating C0 of a radial ball or cylindrical roller bearing, the
//! static equivalent load P0 and the safety factor s0 (the model of
//! `/v1/rolling-bearings/static-capacity`, whose wire is `static_capacity.rs`; the analysis
//! rates through it too).
//!
//! Model.
//! - C0 is the static radial load that puts a Hertz contact pressure of 4200 MPa at the centre
//!   of the most heavily loaded ball–raceway contact of a radial ball bearing, where the total
//!   permanent deformation of ball and raceway is about 1e-4 of the ball diameter (Khonsari &
//!   Booser §13.10, RB-8; ISO 76:2006 §3.1, the same 4200 MPa quoted by Koyo's and Minebea's
//!   catalogues and UMBRA's ISO 76 summary — 4600 MPa for self-aligning ball bearings, which
//!   this room does not rate; 4000 MPa for roller bearings, below).
//! - The most loaded ball carries Q_max = 5 F_r/(Z cos α), the practical Stribeck rule with
//!   nominal clearance (Khonsari & Booser RI-6; ISO/TR 10657 derives ISO 76's f0 from it), so
//!   C0 = Z Q₀ cos α / 5 = f0 Z D² cos α with f0 = Q₀/(5 D²) and Q₀ the ball load at which the
//!   more highly stressed raceway contact reaches 4200 MPa.
//! - Q₀ comes from the exact Hertz point contact ([`crate::calc::contact::hertz`]) of a ball at
//!   the nominal contact angle α (0 for a deep-groove bearing: `free_contact_angle_deg`
//!   absent) on raceways with ISO 76's reference conformities r_i = 0.52 D, r_o = 0.53 D (the
//!   groove radii for which the standard's f0 is stated: "inner ring raceway groove radius not
//!   larger than 0.52 D_w, outer 0.53 D_w", also in NCK's C0 = f0 i Z D² cos α summary) and the
//!   bearing's own where they are looser (a looser groove raises the pressure, so the
//!   standard's f0 would overrate it). f0 then depends only on γ = D cos α/d_m. The steel is
//!   E = 207 GPa, ν = 0.3 for both bodies: ISO rates bearing steel whatever materials the
//!   request gives. **Verify:** with these constants the evaluation gives f0 = 14.73 at γ = 0,
//!   16.40 at γ = 0.10 and 13.95 at γ = 0.20, the values 14.7, 16.4 and 14.0 recalled from
//!   ISO 76's Table 2 for radial and angular-contact groove ball bearings; the table itself
//!   was not available to check. Independently, the texts' 6210 (Khonsari & Booser Table 13.5
//!   C = 35 700 N × Table 13.11 C0/C = 0.66 → C0 ≈ 23 560 N) is reproduced within 2 %.
//! - Cylindrical roller bearings by the same definition: 4000 MPa (ISO 76 for roller bearings,
//!   UMBRA's and Koyo's summaries) at the more stressed line contact of a roller carrying
//!   Q_max = 5 F_r/Z, on the effective length, steel as above: C0 = Z Q₀/5 =
//!   f0′ (1 − γ) Z L D with f0′ = Q₀/[5 L D (1 − γ)] = π p² (1 − ν²)/(5E) = 44.2 N/mm² at the
//!   inner raceway, the 44 of ISO 76's C0r = 44 (1 − D cos α/d_m) Z L D cos α (**verify**: the
//!   constant as recalled; the evaluation is the definition). P0 = F_r (X0 = 1, Y0 = 0).
//! - P0 = max(X0 F_r + Y0 F_a, F_r) (ISO 76; Minebea's JIS B 1519 summary). X0 = 0.6,
//!   Y0 = 0.5 for a radial-contact (deep-groove) bearing (Khonsari & Booser RB-8; SKF's Y-bearing
//!   page; Minebea). Single-row angular contact: X0 = 0.5 and Y0 by the nominal angle, 15°:
//!   0.46, 20°: 0.42, 25°: 0.38, 30°: 0.33, 35°: 0.29, 40°: 0.26, 45°: 0.22 (ISO 76 Table 4;
//!   15°, 25° and 40° checked against LYC's table, 30° against Khonsari & Booser RB-8's 0.33;
//!   20°, 35°, 45° **verify**), linear between; other angles need `x0_factor`, `y0_factor`.
//! - Guideline minimum s0 for ball bearings (SKF's table, as reproduced by bearing-centre.com;
//!   ISO 76 gives the same kind of guidance): rotating — smooth or normal operation 0.5 / 1 / 2
//!   for low / normal / high demands on quiet running, pronounced shock loads 1.5 / 1.5 / 2;
//!   non-rotating — 0.4 smooth, 0.5 normal, 1 with shock loads. Roller bearings: rotating
//!   1 / 1.5 / 3 smooth, 1 / 1.5 / 3.5 normal, 2.5 / 3 / 4 with shock loads; non-rotating 0.8,
//!   1, 2. Khonsari & Booser RB-8: up to
//!   4 C0 is tolerable where noise and some life loss are acceptable; about 8 C0 may fracture.

use super::roller::ROLLER_STATIC_LIMIT_PA;
use crate::calc::contact::hertz::{Body, Contact, Invalid, Method, Shape};
use crate::calc::CalcError;

/// ISO 76's contact pressure at C0 for (non-self-aligning) ball bearings, Pa.
pub const STATIC_RATING_PRESSURE_PA: f64 = 4.2e9;
/// Stribeck's practical factor: Q_max = 5 F_r/(Z cos α) with nominal clearance.
const STRIBECK_FACTOR: f64 = 5.0;
/// ISO 76's reference groove conformities r/D (inner, outer).
pub(super) const REFERENCE_CONFORMITY: (f64, f64) = (0.52, 0.53);
/// The steel ISO rates: E, Pa, and ν.
const RATING_STEEL: (f64, f64) = (2.07e11, 0.3);
/// Smallest static equivalent load with a safety factor, N (keeps s0 finite for denormal loads).
const MIN_EQUIVALENT_LOAD_N: f64 = 1e-6;
/// Single-row angular-contact ball bearings: (nominal angle °, Y0), X0 = 0.5.
const ANGULAR_Y0: [(f64, f64); 7] = [
    (15.0, 0.46),
    (20.0, 0.42),
    (25.0, 0.38),
    (30.0, 0.33),
    (35.0, 0.29),
    (40.0, 0.26),
    (45.0, 0.22),
];

/// How the bearing runs while the static load acts (for the guideline s0).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Operation {
    /// Smooth, vibration-free.
    Smooth,
    /// Normal operation.
    Normal,
    /// Pronounced shock loads (of unknown size: the guideline is a lower bound).
    Shock,
}

/// Demands on quiet, vibration-free running.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum QuietRunning {
    Unimportant,
    Normal,
    High,
}

/// The raceway that reaches the rating pressure first.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Raceway {
    Inner,
    Outer,
}

impl Raceway {
    /// `inner` or `outer`.
    pub fn name(self) -> &'static str {
        match self {
            Raceway::Inner => "inner",
            Raceway::Outer => "outer",
        }
    }
}

/// The validated case.
#[derive(Debug, Clone, Copy)]
pub struct StaticCapacityCase {
    pub(super) ball_diameter_m: f64,
    pub(super) pitch_diameter_m: f64,
    pub(super) ball_count: usize,
    /// Nominal contact angle, rad.
    pub(super) contact_angle: f64,
    /// Groove conformities the rating is evaluated at (ISO's or looser).
    pub(super) conformity: (f64, f64),
    pub(super) radial_load_n: f64,
    pub(super) axial_load_n: f64,
    pub(super) x0: f64,
    pub(super) y0: f64,
    pub(super) catalogue_rating_n: Option<f64>,
    pub(super) rotating: bool,
    pub(super) operation: Operation,
    pub(super) quiet_running: QuietRunning,
    /// A cylindrical roller bearing: the effective roller length, m (ball_* then describe the
    /// rollers).
    pub(super) roller_length_m: Option<f64>,
}

/// ISO 76's X0, Y0 for a single-row ball bearing at nominal angle `deg`, if tabulated.
pub(super) fn iso_factors(deg: f64) -> Option<(f64, f64)> {
    if deg == 0.0 {
        return Some((0.6, 0.5));
    }
    ANGULAR_Y0.windows(2).find_map(|w| {
        let ((a0, y0), (a1, y1)) = (w[0], w[1]);
        (a0..=a1)
            .contains(&deg)
            .then(|| (0.5, y0 + (y1 - y0) * (deg - a0) / (a1 - a0)))
    })
}

/// ISO 76's rating of a case: C0, P0, s0 and the guideline minimum (the caller warns when s0
/// falls below it or below 1).
#[derive(Debug, Clone, Copy)]
pub struct StaticRating {
    /// Nominal contact angle α, degrees.
    pub contact_angle_deg: f64,
    /// γ = D cos α/d_m.
    pub gamma: f64,
    /// f0 (balls) or f0′ (rollers), N/mm².
    pub static_rating_factor_f0: f64,
    /// The conformities rated at (ball bearings).
    pub rating_conformities: Option<[f64; 2]>,
    /// Q₀, N.
    pub element_load_at_rating_pressure_n: f64,
    pub governing_raceway: Raceway,
    /// C0, N.
    pub basic_static_load_rating_n: f64,
    /// The rating s0 uses (catalogue or C0), N.
    pub rating_used_n: f64,
    pub x0_factor: f64,
    pub y0_factor: f64,
    /// P0, N.
    pub equivalent_static_load_n: f64,
    /// s0 = rating/P0.
    pub static_safety_factor: f64,
    /// Guideline minimum s0.
    pub recommended_min_static_safety_factor: f64,
    /// Pressure at the most loaded contact under P0, Pa.
    pub max_contact_pressure_pa: f64,
}

/// The rating and safety factor of a validated case.
pub fn rate(case: &StaticCapacityCase) -> Result<StaticRating, CalcError> {
    let d = case.ball_diameter_m;
    let cos = case.contact_angle.cos();
    let (inner, outer) = (
        rating_ball_load(case, true)?,
        rating_ball_load(case, false)?,
    );
    let (q0, governing) = if inner <= outer {
        (inner, Raceway::Inner)
    } else {
        (outer, Raceway::Outer)
    };
    let z = case.ball_count as f64;
    let c0 = z * q0 * cos / STRIBECK_FACTOR;
    let roller = case.roller_length_m;
    // Balls: f0 = Q₀/(5 D²); rollers: ISO's 44 = Q₀/(5 L D (1 − γ)), both in N/mm².
    let f0_n_m2 = match roller {
        None => q0 / (STRIBECK_FACTOR * d * d),
        Some(l) => q0 / (STRIBECK_FACTOR * l * d * (1.0 - d * cos / case.pitch_diameter_m)),
    };
    let (limit_pa, pressure_exponent) = match roller {
        None => (STATIC_RATING_PRESSURE_PA, 1.0 / 3.0),
        Some(_) => (ROLLER_STATIC_LIMIT_PA, 0.5),
    };
    let (f_r, f_a) = (case.radial_load_n, case.axial_load_n);
    let p0 = (case.x0 * f_r + case.y0 * f_a).max(f_r);
    if p0.is_nan() || p0 < MIN_EQUIVALENT_LOAD_N {
        return Err(CalcError::impossible(
                if f_r > 0.0 { "/radial_load_n" } else { "/axial_load_n" },
                format!(
                    "the static equivalent load P0 = max(X0 F_r + Y0 F_a, F_r) = {p0:e} N is below {MIN_EQUIVALENT_LOAD_N:e} N: s0 = C0/P0 would exceed any meaningful bound (with Y0 = 0 an axial load alone gives P0 = 0)"
                ),
            ));
    }
    let rating = case.catalogue_rating_n.unwrap_or(c0);
    let s0 = rating / p0;
    let minimum = guideline_minimum(
        roller.is_some(),
        case.rotating,
        case.operation,
        case.quiet_running,
    );
    Ok(StaticRating {
        contact_angle_deg: case.contact_angle.to_degrees(),
        gamma: d * cos / case.pitch_diameter_m,
        static_rating_factor_f0: f0_n_m2 * 1e-6,
        rating_conformities: roller
            .is_none()
            .then_some([case.conformity.0, case.conformity.1]),
        element_load_at_rating_pressure_n: q0,
        governing_raceway: governing,
        basic_static_load_rating_n: c0,
        rating_used_n: rating,
        x0_factor: case.x0,
        y0_factor: case.y0,
        equivalent_static_load_n: p0,
        static_safety_factor: s0,
        recommended_min_static_safety_factor: minimum,
        max_contact_pressure_pa: limit_pa * (p0 / rating).powf(pressure_exponent),
    })
}

/// Q₀ of one raceway: the ball load at which its exact Hertz pressure is 4200 MPa, from the
/// pressure at 1 N (p ∝ Q^⅓).
fn rating_ball_load(case: &StaticCapacityCase, inner: bool) -> Result<f64, CalcError> {
    let d = case.ball_diameter_m;
    if let Some(length) = case.roller_length_m {
        return rating_roller_load(case, length, inner);
    }
    let along = case.pitch_diameter_m / case.contact_angle.cos();
    let (rolling, groove) = if inner {
        (0.5 * (along - d), -case.conformity.0 * d)
    } else {
        (-0.5 * (along + d), -case.conformity.1 * d)
    };
    let body = |rx: f64, ry: f64| Body {
        radius_x_m: Some(rx),
        radius_y_m: Some(ry),
        modulus_pa: RATING_STEEL.0,
        poisson_ratio: RATING_STEEL.1,
    };
    let contact = Contact::new(
        [body(0.5 * d, 0.5 * d), body(rolling, groove)],
        1.0,
        Shape::Point,
        Method::Exact,
    );
    let what = format!(
        "the {} raceway's rating contact is not a Hertz point contact",
        if inner { "inner" } else { "outer" }
    );
    let unit = pressure_at_one_newton(contact, &what)?;
    Ok((STATIC_RATING_PRESSURE_PA / unit).powi(3))
}

/// Q₀ of a roller's line contact on one raceway (rating steel, effective length): the load at
/// which the Hertz pressure is 4000 MPa, from the pressure at 1 N (p ∝ Q^½).
fn rating_roller_load(
    case: &StaticCapacityCase,
    length: f64,
    inner: bool,
) -> Result<f64, CalcError> {
    let d = case.ball_diameter_m;
    let race = if inner {
        0.5 * (case.pitch_diameter_m - d)
    } else {
        -0.5 * (case.pitch_diameter_m + d)
    };
    let body = |r: f64| Body {
        radius_x_m: Some(r),
        radius_y_m: None,
        modulus_pa: RATING_STEEL.0,
        poisson_ratio: RATING_STEEL.1,
    };
    let contact = Contact::new(
        [body(0.5 * d), body(race)],
        1.0,
        Shape::Line { length_m: length },
        Method::Exact,
    );
    let unit = pressure_at_one_newton(
        contact,
        "a roller's rating contact is not a Hertz line contact",
    )?;
    Ok((ROLLER_STATIC_LIMIT_PA / unit).powi(2))
}

/// The Hertz model's maximum pressure for `contact` (loaded with 1 N), Pa; a contact the model
/// refuses is a 422 on the bearing saying `what` and why. The model's warnings are not passed
/// on (the rating contact is ISO's reference, not the user's).
fn pressure_at_one_newton(
    contact: Result<Contact, Vec<Invalid>>,
    what: &str,
) -> Result<f64, CalcError> {
    let contact = contact.map_err(|errors| Invalid::refusal(errors, "/bearing", what))?;
    Ok(contact.solve()?.max_pressure_pa)
}

/// The guideline minimum s0 (SKF's table; see the module doc): ball or roller bearings.
fn guideline_minimum(
    roller: bool,
    rotating: bool,
    operation: Operation,
    quiet: QuietRunning,
) -> f64 {
    use Operation as O;
    use QuietRunning as Q;
    if !rotating {
        return match (operation, roller) {
            (O::Smooth, false) => 0.4,
            (O::Normal, false) => 0.5,
            (O::Shock, false) => 1.0,
            (O::Smooth, true) => 0.8,
            (O::Normal, true) => 1.0,
            (O::Shock, true) => 2.0,
        };
    }
    match (operation, quiet, roller) {
        (O::Shock, Q::Unimportant, false) | (O::Shock, Q::Normal, false) => 1.5,
        (O::Shock, Q::High, false) => 2.0,
        (_, Q::Unimportant, false) => 0.5,
        (_, Q::Normal, false) => 1.0,
        (_, Q::High, false) => 2.0,
        (O::Shock, Q::Unimportant, true) => 2.5,
        (O::Shock, Q::Normal, true) => 3.0,
        (O::Shock, Q::High, true) => 4.0,
        (_, Q::Unimportant, true) => 1.0,
        (_, Q::Normal, true) => 1.5,
        (O::Smooth, Q::High, true) => 3.0,
        (O::Normal, Q::High, true) => 3.5,
    }
}
