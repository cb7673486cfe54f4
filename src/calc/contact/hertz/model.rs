//! The Hertz model: what other rooms call. Plain types (two [`Body`]s with signed principal
//! radii, E and ν; a load; a point or line [`Shape`]; a [`Method`] for κ) in, a [`Solution`]
//! (semi-axes or half-width, pressures, approach, ellipticity, subsurface maxima, and the
//! warnings as data) out. No serde, no `Context`: the wire room (`wire.rs`) and the composed
//! rooms (EHL, rolling) decide what to do with the warnings and the solver report.
//!
//! Conventions (the texts differ; these are the ones every field states):
//! - Radii are signed: convex > 0, concave < 0, a flat is an absent radius. x and y are the
//!   request's two principal directions, common to both bodies (aligned principal planes).
//! - Curvature sums 1/R_x = 1/r₁ₓ + 1/r₂ₓ, 1/R_y = 1/r₁ᵧ + 1/r₂ᵧ; 1/R = 1/R_x + 1/R_y
//!   (R is Stachowiak's R′, 1/R is Khonsari's Σρ); curvature difference Γ = R |1/R_x − 1/R_y|
//!   (Hamrock's Γ, Khonsari's F(ρ)); radius ratio α_r = R_y/R_x in the frame where
//!   1/R_x ≥ 1/R_y, so α_r ≥ 1 (Hamrock eq. 21.33; Stachowiak swaps the axes the same way).
//! - E′ = 2/[(1 − ν₁²)/E₁ + (1 − ν₂²)/E₂] (Hamrock, Stachowiak, Khonsari: 2.2 × 10¹¹ Pa for
//!   steel), twice Johnson's E*.
//! - Ellipticity κ = a/b ≥ 1 (semi-major over semi-minor), m = 1 − 1/κ² the parameter of the
//!   complete elliptic integrals 𝓚(m), 𝓔(m) (see [`crate::numerics::elliptic`]).
//!
//! Point contact (Hamrock eqs 21.33–21.47 with exact 𝓚, 𝓔; Khonsari eqs 14.7–14.12):
//! α_r = (κ²𝓔 − 𝓚)/(𝓚 − 𝓔), a = (6κ²𝓔WR/(πE′))^⅓, b = (6𝓔WR/(πκE′))^⅓,
//! δ = 𝓚[(9/(2𝓔R))(W/(πκE′))²]^⅓, p_max = 3W/(2πab). [`Method::Exact`] solves the first
//! equation for κ by Brent's method in ln κ; [`Method::Fit`] takes κ, 𝓔, 𝓚 from curve fits.
//! Line contact (Hamrock eqs 21.48–21.51): b = (8W′R_x/(πE′))^½, p_max = 2W′/(πb) with W′ the
//! load per unit length.

use super::subsurface::{ellipse_axis_stresses, line_axis_stresses, subsurface, Subsurface};
use crate::calc::{CalcError, Warning};
use crate::fidelity::SolverReport;
use crate::numerics::elliptic::{carlson_rd, complete_from_complement};
use crate::numerics::roots::{brent, Stopping};

/// Largest radius ratio α_r = R_y/R_x accepted for a point contact. Beyond it the contact is a
/// line for any practical purpose, or the surfaces are within 10⁻⁹ of osculation and the
/// curvature sum is rounding noise.
pub(crate) const MAX_RADIUS_RATIO: f64 = 1e9;
/// Largest ellipticity the exact solve brackets: α_r(10⁶) ≈ 7 × 10¹⁰ > [`MAX_RADIUS_RATIO`].
pub(crate) const MAX_ELLIPTICITY: f64 = 1e6;
/// Radius ratios over which the curve fits are used: measured against the exact solution
/// (tests), Hamrock–Dowson gives a, b and p_max within 3 % for 1 ≤ α_r ≤ 60 and δ within 3 % for
/// 1.5 ≤ α_r ≤ 60 (5.4 % low at α_r = 1, where its 𝓚 = 1.5277 falls short of π/2);
/// Hamrock–Brewe is exact at α_r = 1 and within 3 % on all four up to α_r = 60. Beyond, both
/// drift (Hamrock–Dowson: p_max −4 % at α_r = 300, −7 % at 1000).
const FIT_RANGE: (f64, f64) = (1.0, 60.0);
/// Hertz assumes the contact is small against the radii (half-space approximation); a
/// semi-axis above this fraction of a radius in its direction draws a warning.
const SMALL_CONTACT: f64 = 0.1;
pub(crate) const MAX_MODULUS_PA: f64 = 1e13;
pub(crate) const MIN_MODULUS_PA: f64 = 1.0;
pub(crate) const MAX_LOAD_N: f64 = 1e12;

/// One of the two principal directions common to both bodies.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Axis {
    X,
    Y,
}

impl Axis {
    pub fn name(self) -> &'static str {
        match self {
            Axis::X => "x",
            Axis::Y => "y",
        }
    }
}

/// One body as the physics takes it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Body {
    /// Signed principal radius in x, m (convex > 0, concave < 0; None: flat).
    pub radius_x_m: Option<f64>,
    /// Signed principal radius in y, m (None: flat; None for a line contact's cylinders).
    pub radius_y_m: Option<f64>,
    /// Young's modulus E, Pa.
    pub modulus_pa: f64,
    /// Poisson's ratio ν.
    pub poisson_ratio: f64,
}

impl Body {
    /// The signed radius along `axis`, m (None: flat).
    pub fn radius(&self, axis: Axis) -> Option<f64> {
        match axis {
            Axis::X => self.radius_x_m,
            Axis::Y => self.radius_y_m,
        }
    }

    fn curvature(&self, axis: Axis) -> f64 {
        let r = match axis {
            Axis::X => self.radius_x_m,
            Axis::Y => self.radius_y_m,
        };
        r.map_or(0.0, |r| 1.0 / r)
    }
}

/// The curve fits for κ, 𝓔 and 𝓚 (α_r = R_y/R_x ≥ 1).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Fit {
    /// Hamrock & Dowson (1981): κ = 1.0339 α_r^0.636, 𝓔 = 1.0003 + 0.5968/α_r,
    /// 𝓚 = 1.5277 + 0.6023 ln α_r (Stachowiak & Batchelor Table 7.4).
    HamrockDowson,
    /// Hamrock & Brewe (1983): κ = α_r^(2/π), 𝓔 = 1 + (π/2 − 1)/α_r,
    /// 𝓚 = π/2 + (π/2 − 1) ln α_r (Hamrock Table 21.7).
    HamrockBrewe,
}

/// How κ, 𝓔 and 𝓚 of a point contact are obtained.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Method {
    Exact,
    Fit(Fit),
}

/// Point or line contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shape {
    Point,
    /// Cylinders with parallel axes along y, the load carried uniformly over `length_m`.
    Line {
        length_m: f64,
    },
}

/// A checked Hertz contact: two bodies pressed together by a normal load. Build it with
/// [`Contact::new`], which refuses what Hertz theory cannot solve; then [`Contact::solve`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Contact {
    bodies: [Body; 2],
    load_n: f64,
    shape: Shape,
    method: Method,
}

/// Which input a refusal is about.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Field {
    /// A body's radius (`body` is 1 or 2).
    Radius {
        body: u8,
        axis: Axis,
    },
    Modulus {
        body: u8,
    },
    PoissonRatio {
        body: u8,
    },
    Load,
    /// The line contact's length.
    Length,
}

impl Field {
    /// The field in the Hertz room's request (`/body1/radius_x_m`, `/load_n`, …): the wire's
    /// pointer, and what composed rooms quote in their own messages.
    pub fn hertz_pointer(self) -> String {
        match self {
            Field::Radius { body, axis } => format!("/body{body}/radius_{}_m", axis.name()),
            Field::Modulus { body } => format!("/body{body}/elastic_modulus_pa"),
            Field::PoissonRatio { body } => format!("/body{body}/poisson_ratio"),
            Field::Load => "/load_n".to_owned(),
            Field::Length => "/line/length_m".to_owned(),
        }
    }
}

/// Why [`Contact::new`] refused an input.
#[derive(Debug, Clone, PartialEq)]
pub struct Invalid {
    pub field: Field,
    pub message: String,
}

impl Invalid {
    fn new(field: Field, message: impl Into<String>) -> Self {
        Invalid {
            field,
            message: message.into(),
        }
    }

    /// A composed room's refusal of a contact it built itself (the contact is not a Hertz
    /// contact): a 422 on `pointer` saying `what`, then every refused field with the Hertz
    /// room's name for it.
    pub fn refusal(errors: Vec<Invalid>, pointer: &str, what: &str) -> CalcError {
        let detail: Vec<String> = errors
            .into_iter()
            .map(|e| format!("{}: {}", e.field.hertz_pointer(), e.message))
            .collect();
        CalcError::impossible(pointer, format!("{what}: {}", detail.join("; ")))
    }
}

/// A signed principal radius must be finite with |r| ≥ 1 nm (a flat is an absent radius): the
/// rule of [`crate::calc::quantity::Radius`].
fn check_radius(v: f64) -> Result<f64, String> {
    crate::calc::quantity::Radius::try_from(v).map(|r| r.get())
}

/// Poisson's ratio ν within (−1, 0.5]: the rule of [`crate::calc::quantity::PoissonRatio`].
fn check_poisson_ratio(v: f64) -> Result<f64, String> {
    crate::calc::quantity::PoissonRatio::try_from(v).map(|r| r.get())
}

/// A finite number > 0 (the same rule and words as [`crate::calc::quantity::Positive`]).
fn check_positive(v: f64) -> Result<f64, String> {
    crate::calc::quantity::Positive::try_from(v).map(|p| p.get())
}

impl Contact {
    /// Check a contact. First each value on its own (radii, E, ν, load, length: what the wire
    /// parses before it validates; all such refusals are returned together), then what spans
    /// them: E within [1, 1e13] Pa, W ≤ 1e12 N, a positive curvature sum in each direction
    /// (why not, in words), no y radius on a line contact's cylinders, and a point contact's
    /// radius ratio ≤ 1e9.
    pub fn new(
        bodies: [Body; 2],
        load_n: f64,
        shape: Shape,
        method: Method,
    ) -> Result<Contact, Vec<Invalid>> {
        let mut errors = Vec::new();
        for (b, body) in bodies.iter().zip(1u8..) {
            for axis in [Axis::X, Axis::Y] {
                if let Some(Err(m)) = b.radius(axis).map(check_radius) {
                    errors.push(Invalid::new(Field::Radius { body, axis }, m));
                }
            }
            if let Err(m) = check_positive(b.modulus_pa) {
                errors.push(Invalid::new(Field::Modulus { body }, m));
            }
            if let Err(m) = check_poisson_ratio(b.poisson_ratio) {
                errors.push(Invalid::new(Field::PoissonRatio { body }, m));
            }
        }
        if let Err(m) = check_positive(load_n) {
            errors.push(Invalid::new(Field::Load, m));
        }
        if let Shape::Line { length_m } = shape {
            if let Err(m) = check_positive(length_m) {
                errors.push(Invalid::new(Field::Length, m));
            }
        }
        if !errors.is_empty() {
            return Err(errors);
        }
        for (b, body) in bodies.iter().zip(1u8..) {
            let e = b.modulus_pa;
            if !(MIN_MODULUS_PA..=MAX_MODULUS_PA).contains(&e) {
                errors.push(Invalid::new(
                    Field::Modulus { body },
                    format!("must be within [{MIN_MODULUS_PA}, {MAX_MODULUS_PA:e}] Pa, got {e}"),
                ));
            }
        }
        if load_n > MAX_LOAD_N {
            errors.push(Invalid::new(
                Field::Load,
                format!("must be at most {MAX_LOAD_N:e} N"),
            ));
        }
        match shape {
            Shape::Line { .. } => {
                for (b, body) in bodies.iter().zip(1u8..) {
                    if b.radius_y_m.is_some() {
                        errors.push(Invalid::new(
                            Field::Radius {
                                body,
                                axis: Axis::Y,
                            },
                            "a line contact is between cylinders straight along y: omit radius_y_m",
                        ));
                    }
                }
                check_curvature_sum(&bodies, Axis::X, true, &mut errors);
            }
            Shape::Point => {
                let x_ok = check_curvature_sum(&bodies, Axis::X, false, &mut errors);
                let y_ok = check_curvature_sum(&bodies, Axis::Y, false, &mut errors);
                if x_ok && y_ok {
                    check_radius_ratio(&bodies, &mut errors);
                }
            }
        }
        if errors.is_empty() {
            Ok(Contact {
                bodies,
                load_n,
                shape,
                method,
            })
        } else {
            Err(errors)
        }
    }

    pub fn bodies(&self) -> &[Body; 2] {
        &self.bodies
    }

    pub fn load_n(&self) -> f64 {
        self.load_n
    }

    pub fn shape(&self) -> Shape {
        self.shape
    }

    fn poisson_ratios(&self) -> [f64; 2] {
        self.bodies.map(|b| b.poisson_ratio)
    }

    /// Solve the contact: the exact or fitted ellipse, or the line; the subsurface maxima; the
    /// warnings (fit outside its range, contact not small against a radius, no approach against
    /// a flat) as data, in the order the room has always given them.
    pub fn solve(&self) -> Result<Solution, CalcError> {
        match self.shape {
            Shape::Point => point_contact(self),
            Shape::Line { length_m } => Ok(line_contact(self, length_m)),
        }
    }
}

/// Which direction the major axis of the contact ellipse lies along.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MajorAxis {
    X,
    Y,
    /// a = b.
    Circle,
}

impl MajorAxis {
    /// `x`, `y` or `circle`.
    pub fn name(self) -> &'static str {
        match self {
            MajorAxis::X => "x",
            MajorAxis::Y => "y",
            MajorAxis::Circle => "circle",
        }
    }
}

/// The contact's footprint: an ellipse (circle) or a band.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Footprint {
    Ellipse {
        /// Semi-major axis a, m.
        semi_major_axis_m: f64,
        /// Semi-minor axis b, m.
        semi_minor_axis_m: f64,
        /// κ = a/b ≥ 1 (the fit's κ with [`Method::Fit`]).
        ellipticity: f64,
        /// 𝓚(m), m = 1 − 1/κ².
        elliptic_integral_k: f64,
        /// 𝓔(m).
        elliptic_integral_e: f64,
        /// α_r = R_y/R_x ≥ 1 in the frame where 1/R_x ≥ 1/R_y.
        radius_ratio: f64,
        major_axis: MajorAxis,
    },
    Line {
        /// Half-width b of the band (along x), m.
        half_width_m: f64,
        /// W′ = W/L, N/m.
        load_per_length_n_m: f64,
    },
}

/// A solved Hertz contact.
#[derive(Debug, Clone, PartialEq)]
pub struct Solution {
    pub footprint: Footprint,
    /// p_max at the centre, Pa.
    pub max_pressure_pa: f64,
    /// W/area, Pa.
    pub mean_pressure_pa: f64,
    /// πab or 2bL, m².
    pub contact_area_m2: f64,
    /// Mutual approach δ, m; None for a line contact against a flat (a warning says why).
    pub approach_m: Option<f64>,
    /// Subsurface maxima on the axis below the centre.
    pub subsurface: Subsurface,
    /// 1/R = 1/R_x + 1/R_y (1/R_x for a line), 1/m.
    pub curvature_sum_1_m: f64,
    /// Γ = R|1/R_x − 1/R_y|, 0 (circle) … 1 (line).
    pub curvature_difference: f64,
    /// R_x in the request's x direction, m.
    pub reduced_radius_x_m: f64,
    /// R_y, m; None for a line contact (infinite).
    pub reduced_radius_y_m: Option<f64>,
    /// R = 1/(1/R_x + 1/R_y) (R_x for a line), m.
    pub reduced_radius_m: f64,
    /// E′, Pa.
    pub effective_modulus_pa: f64,
    /// How κ was found (Brent's iterations and residual, or the fit's name).
    pub report: SolverReport,
    /// The model's warnings, in order; the caller decides which to pass on.
    pub warnings: Vec<Warning>,
}

impl Solution {
    /// The warnings but the one about a line contact's approach against a flat: what rooms
    /// that do not report the approach pass on (the EHL rooms never reported it).
    pub fn warnings_but_approach(&self) -> impl Iterator<Item = &Warning> {
        self.warnings
            .iter()
            .filter(|w| w.code != APPROACH_UNDEFINED_FOR_FLAT)
    }

    /// `point` or `line`.
    pub fn contact_name(&self) -> &'static str {
        match self.footprint {
            Footprint::Ellipse { .. } => "point",
            Footprint::Line { .. } => "line",
        }
    }

    /// (a, b) of a point contact; None for a line.
    pub fn semi_axes_m(&self) -> Option<(f64, f64)> {
        match self.footprint {
            Footprint::Ellipse {
                semi_major_axis_m,
                semi_minor_axis_m,
                ..
            } => Some((semi_major_axis_m, semi_minor_axis_m)),
            Footprint::Line { .. } => None,
        }
    }

    /// The half-width of a line contact; None for a point.
    pub fn half_width_m(&self) -> Option<f64> {
        match self.footprint {
            Footprint::Line { half_width_m, .. } => Some(half_width_m),
            Footprint::Ellipse { .. } => None,
        }
    }

    /// κ = a/b of a point contact; None for a line.
    pub fn ellipticity(&self) -> Option<f64> {
        match self.footprint {
            Footprint::Ellipse { ellipticity, .. } => Some(ellipticity),
            Footprint::Line { .. } => None,
        }
    }

    /// The direction the major axis lies along (`Y` for a line: the band runs along y).
    pub fn major_axis(&self) -> MajorAxis {
        match self.footprint {
            Footprint::Ellipse { major_axis, .. } => major_axis,
            Footprint::Line { .. } => MajorAxis::Y,
        }
    }
}

/// The curvature sum along `axis` must be positive for the bodies to touch first at a point
/// (or along a line). Returns whether it is; otherwise pushes an error that says why.
fn check_curvature_sum(
    bodies: &[Body; 2],
    axis: Axis,
    line: bool,
    errors: &mut Vec<Invalid>,
) -> bool {
    let r = [bodies[0].radius(axis), bodies[1].radius(axis)];
    let sum: f64 = r.iter().flatten().map(|r| 1.0 / r).sum();
    if sum > 0.0 {
        return true;
    }
    let d = axis.name();
    let field = |i: usize| Field::Radius {
        body: i as u8 + 1,
        axis,
    };
    let concave = r.map(|r| r.is_some_and(|r| r < 0.0));
    let (pointer, message) = match concave {
        [false, false] if line => (
            field(0),
            "both surfaces are flat across the line (no radius_x_m): flat on flat is not a Hertz contact".to_owned(),
        ),
        [false, false] => (
            field(0),
            format!(
                "both surfaces are flat along {d}: a point contact needs a positive curvature sum in x and in y; a cylinder on a flat or parallel cylinders make a line contact (give `line`, with the cylinder axes along y)"
            ),
        ),
        [true, true] => (
            field(1),
            format!("both surfaces are concave along {d}: two concave surfaces cannot touch at a point or along a line"),
        ),
        [c0, _] => {
            let c = if c0 { 0 } else { 1 };
            let rc = r[c].unwrap_or(f64::NAN);
            match r[1 - c] {
                None => (
                    field(c),
                    format!(
                        "a concave surface (radius {rc} m along {d}) against a flat touches at its rims, not at a point: the curvature sum is negative"
                    ),
                ),
                Some(rv) => (
                    field(c),
                    format!(
                        "the concave radius {rc} m along {d} must be larger in magnitude than the convex radius {rv} m it holds: the curvature sum 1/r₁ + 1/r₂ = {sum:.6e} 1/m is not positive, so the convex body would touch the concave one along a curve (|r| equal: osculation, a conforming contact) or would not fit inside it, never first at a single point as Hertz theory assumes"
                    ),
                ),
            }
        }
    };
    errors.push(Invalid::new(pointer, message));
    false
}

/// A point contact whose radius ratio exceeds [`MAX_RADIUS_RATIO`] is refused.
fn check_radius_ratio(bodies: &[Body; 2], errors: &mut Vec<Invalid>) {
    let sum = |axis| -> f64 {
        [bodies[0].radius(axis), bodies[1].radius(axis)]
            .iter()
            .flatten()
            .map(|r| 1.0 / r)
            .sum()
    };
    let (sx, sy) = (sum(Axis::X), sum(Axis::Y));
    let ratio = sx.max(sy) / sx.min(sy);
    if ratio > MAX_RADIUS_RATIO {
        let weak = if sx < sy { Axis::X } else { Axis::Y };
        let i = if bodies[1].radius(weak).is_some_and(|r| r < 0.0) {
            2
        } else {
            1
        };
        errors.push(Invalid::new(
            Field::Radius {
                body: i,
                axis: weak,
            },
            format!(
                "the radius ratio of the point contact is {ratio:.3e} (more than {MAX_RADIUS_RATIO:e}): the curvature sum along {} is too small against the other, so the contact is a line (give `line`) or the surfaces are too close to osculation for a point-contact solution",
                weak.name()
            ),
        ));
    }
}

/// E′ = 2/[(1 − ν₁²)/E₁ + (1 − ν₂²)/E₂], Pa.
fn effective_modulus(bodies: &[Body; 2]) -> f64 {
    let compliance: f64 = bodies
        .iter()
        .map(|b| (1.0 - b.poisson_ratio * b.poisson_ratio) / b.modulus_pa)
        .sum();
    2.0 / compliance
}

/// κ, 𝓔 and 𝓚 of an elliptical contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Ellipse {
    pub(crate) ellipticity: f64,
    pub(crate) first_kind: f64,
    pub(crate) second_kind: f64,
}

/// α_r as a function of κ, from the complementary parameter m₁ = 1/κ²:
/// α_r = (κ²𝓔 − 𝓚)/(𝓚 − 𝓔) = (𝓚 − 𝓓)/(m₁𝓓) with 𝓓 = (𝓚 − 𝓔)/m = R_D(0, m₁, 1)/3, a form
/// without the cancellation of 𝓚 − 𝓔 at κ → 1 (both → π/2).
pub(crate) fn radius_ratio_of(ellipticity: f64) -> (f64, Ellipse) {
    let m1 = 1.0 / (ellipticity * ellipticity);
    let (k, e) = complete_from_complement(m1);
    let d = carlson_rd(0.0, m1, 1.0) / 3.0;
    let ellipse = Ellipse {
        ellipticity,
        first_kind: k,
        second_kind: e,
    };
    ((k - d) / (m1 * d), ellipse)
}

/// The exact κ for a radius ratio α_r ≥ 1: Brent's method on ln α_r(κ) − ln α_r over
/// ln κ ∈ [0, ln 10⁶] (α_r spans nine decades; its logarithm is smooth and monotone in ln κ).
pub(crate) fn exact_ellipse(radius_ratio: f64) -> Result<(Ellipse, SolverReport), CalcError> {
    let target = radius_ratio.ln();
    let stop = Stopping {
        x_tolerance: 1e-14,
        max_iterations: 200,
    };
    // At κ = 1 the ratio is exactly 1 (a circle), while (𝓚 − 𝓓)/(m₁𝓓) rounds to 1 + 2⁻⁵²:
    // the lower end is taken exactly so that a circle is found at κ = 1, not refused.
    let root = brent(
        |t| {
            if t == 0.0 {
                -target
            } else {
                radius_ratio_of(t.exp()).0.ln() - target
            }
        },
        0.0,
        MAX_ELLIPTICITY.ln(),
        stop,
    )
    .map_err(|e| CalcError::from_root("brent_ellipticity", e))?;
    let (achieved, ellipse) = radius_ratio_of(root.x.exp());
    // The driver's report of the search; its residual is the ratio's relative miss at the root
    // (what the ellipse is judged by), not the search's last bracket width.
    let report = root
        .report
        .named("hertz_exact_brent_agm")
        .with_residual((achieved / radius_ratio - 1.0).abs());
    Ok((ellipse, report))
}

/// κ, 𝓔, 𝓚 from a curve fit, α_r ≥ 1.
fn fitted_ellipse(radius_ratio: f64, fit: Fit) -> Ellipse {
    use std::f64::consts::FRAC_PI_2;
    let (ellipticity, second_kind, first_kind) = match fit {
        Fit::HamrockDowson => (
            1.0339 * radius_ratio.powf(0.636),
            1.0003 + 0.5968 / radius_ratio,
            1.5277 + 0.6023 * radius_ratio.ln(),
        ),
        Fit::HamrockBrewe => (
            radius_ratio.powf(2.0 / std::f64::consts::PI),
            1.0 + (FRAC_PI_2 - 1.0) / radius_ratio,
            FRAC_PI_2 + (FRAC_PI_2 - 1.0) * radius_ratio.ln(),
        ),
    };
    Ellipse {
        ellipticity,
        first_kind,
        second_kind,
    }
}

fn point_contact(case: &Contact) -> Result<Solution, CalcError> {
    let mut warnings = Vec::new();
    let [b1, b2] = case.bodies;
    let sx = b1.curvature(Axis::X) + b2.curvature(Axis::X);
    let sy = b1.curvature(Axis::Y) + b2.curvature(Axis::Y);
    let sum = sx + sy;
    let radius = 1.0 / sum;
    let alpha = sx.max(sy) / sx.min(sy);
    let e_eff = effective_modulus(&case.bodies);
    let w = case.load_n;
    let (ellipse, report) = match case.method {
        Method::Exact => exact_ellipse(alpha)?,
        Method::Fit(fit) => {
            if !(FIT_RANGE.0..=FIT_RANGE.1).contains(&alpha) {
                warnings.push(Warning {
                    code: "fit_outside_range",
                    message: format!(
                        "radius ratio α_r = {alpha:.4e} is outside [{}, {}], where the curve fits hold to a few percent; use fidelity standard",
                        FIT_RANGE.0, FIT_RANGE.1
                    ),
                });
            }
            let method = match fit {
                Fit::HamrockDowson => "hamrock_dowson_fit",
                Fit::HamrockBrewe => "hamrock_brewe_fit",
            };
            (
                fitted_ellipse(alpha, fit),
                SolverReport::closed_form(method),
            )
        }
    };
    let Ellipse {
        ellipticity: kappa,
        first_kind: big_k,
        second_kind: big_e,
    } = ellipse;
    use std::f64::consts::PI;
    let a = (6.0 * kappa * kappa * big_e * w * radius / (PI * e_eff)).cbrt();
    let b = (6.0 * big_e * w * radius / (PI * kappa * e_eff)).cbrt();
    let approach = big_k * (4.5 / (big_e * radius) * (w / (PI * kappa * e_eff)).powi(2)).cbrt();
    let p_max = 1.5 * w / (PI * a * b);
    // The major axis lies along the direction of the smaller curvature sum.
    let (major, minor) = if sx > sy {
        (Some(Axis::Y), Axis::X)
    } else if sy > sx {
        (Some(Axis::X), Axis::Y)
    } else {
        (None, Axis::X)
    };
    warnings.extend(warn_if_large(&case.bodies, minor, b));
    warnings.extend(warn_if_large(&case.bodies, major.unwrap_or(Axis::Y), a));
    let stresses = subsurface(case.poisson_ratios(), p_max, b, |zeta, nu| {
        ellipse_axis_stresses(a / b, zeta, nu)
    });
    Ok(Solution {
        footprint: Footprint::Ellipse {
            semi_major_axis_m: a,
            semi_minor_axis_m: b,
            ellipticity: kappa,
            elliptic_integral_k: big_k,
            elliptic_integral_e: big_e,
            radius_ratio: alpha,
            major_axis: match major {
                Some(Axis::X) => MajorAxis::X,
                Some(Axis::Y) => MajorAxis::Y,
                None => MajorAxis::Circle,
            },
        },
        max_pressure_pa: p_max,
        mean_pressure_pa: w / (PI * a * b),
        contact_area_m2: PI * a * b,
        approach_m: Some(approach),
        subsurface: stresses,
        curvature_sum_1_m: sum,
        curvature_difference: (sx - sy).abs() / sum,
        reduced_radius_x_m: 1.0 / sx,
        reduced_radius_y_m: Some(1.0 / sy),
        reduced_radius_m: radius,
        effective_modulus_pa: e_eff,
        report,
        warnings,
    })
}

fn line_contact(case: &Contact, length_m: f64) -> Solution {
    use std::f64::consts::PI;
    let mut warnings = Vec::new();
    let [b1, b2] = case.bodies;
    let sx = b1.curvature(Axis::X) + b2.curvature(Axis::X);
    let r_x = 1.0 / sx;
    let e_eff = effective_modulus(&case.bodies);
    let w_per_l = case.load_n / length_m;
    let b = (8.0 * w_per_l * r_x / (PI * e_eff)).sqrt();
    let p_max = 2.0 * w_per_l / (PI * b);
    let approach = match (b1.radius_x_m, b2.radius_x_m) {
        (Some(r1), Some(r2)) => Some(
            2.0 * w_per_l / (PI * e_eff)
                * (2.0 / 3.0 + (2.0 * r1.abs() / b).ln() + (2.0 * r2.abs() / b).ln()),
        ),
        _ => {
            warnings.push(Warning {
                code: APPROACH_UNDEFINED_FOR_FLAT,
                message: "the approach of a line contact is finite only between cylinders (Hamrock eq. 21.51 takes the logarithm of each radius over b); against a flat it depends on the flat body's thickness and support, so approach_m is omitted".to_owned(),
            });
            None
        }
    };
    warnings.extend(warn_if_large(&case.bodies, Axis::X, b));
    let stresses = subsurface(case.poisson_ratios(), p_max, b, line_axis_stresses);
    Solution {
        footprint: Footprint::Line {
            half_width_m: b,
            load_per_length_n_m: w_per_l,
        },
        max_pressure_pa: p_max,
        mean_pressure_pa: w_per_l / (2.0 * b),
        contact_area_m2: 2.0 * b * length_m,
        approach_m: approach,
        subsurface: stresses,
        curvature_sum_1_m: sx,
        curvature_difference: 1.0,
        reduced_radius_x_m: r_x,
        reduced_radius_y_m: None,
        reduced_radius_m: r_x,
        effective_modulus_pa: e_eff,
        report: SolverReport::closed_form("hertz_line_closed_form"),
        warnings,
    }
}

/// The code of the warning that a line contact against a flat has no approach (callers that
/// do not report the approach leave it out).
pub const APPROACH_UNDEFINED_FOR_FLAT: &str = "approach_undefined_for_flat";

/// A warning when a semi-axis is not small against a radius in its direction.
fn warn_if_large(bodies: &[Body; 2], axis: Axis, semi_axis: f64) -> Option<Warning> {
    let smallest = bodies
        .iter()
        .filter_map(|b| match axis {
            Axis::X => b.radius_x_m,
            Axis::Y => b.radius_y_m,
        })
        .map(f64::abs)
        .fold(f64::INFINITY, f64::min);
    let ratio = semi_axis / smallest;
    (ratio > SMALL_CONTACT).then(|| Warning {
        code: "contact_not_small",
        message: format!(
            "the contact's semi-axis along {} is {ratio:.3} of the smallest body radius there; Hertz theory treats each body as a half-space, which needs it small (Johnson §4.1; flagged above {SMALL_CONTACT}). Ball-in-groove contacts commonly reach 0.2–0.4 and are still designed by Hertz, with that loss of accuracy",
            axis.name()
        ),
    })
}
