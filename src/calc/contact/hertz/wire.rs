//! `POST /v1/contacts/hertz`: the Hertz contact of two elastic bodies — circular, elliptical
//! (including conforming ball-in-groove and crossed-cylinder contacts) and line — with the
//! contact size, pressures, mutual approach and the subsurface stresses below the centre. The
//! wire: the request, its validation into a [`Contact`], and the [`Solution`] as the response.
//! The conventions and the physics are the model's ([`super::model`]).

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::model::{Body, Contact, Fit, Footprint, Method, Shape, Solution};
use super::subsurface::BodyStresses;
use crate::calc::quantity::{PoissonRatio, Positive, Radius};
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::fidelity::{FidelityRequest, Level};

pub struct Hertz;

/// One body: its two principal radii of curvature at the contact and its elastic constants.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct BodySpec {
    /// Principal radius of curvature in the x direction (the rolling direction, by habit), m:
    /// positive convex, negative concave, 1e-9 ≤ |r| ≤ 1e9; absent for a flat (a very large
    /// radius works too). For a line contact: the cylinder's radius (axis along y).
    #[schema(value_type = Option<f64>, minimum = -1e9, maximum = 1e9, example = 0.015)]
    pub radius_x_m: Option<Radius>,
    /// Principal radius of curvature in the y direction, m (same signs, absent for a flat).
    /// Must be absent for a line contact: the cylinders are straight along y.
    #[schema(value_type = Option<f64>, minimum = -1e9, maximum = 1e9, example = 0.015)]
    pub radius_y_m: Option<Radius>,
    /// Young's modulus E, Pa, 1 … 1e13 (steel 2.1e11).
    #[schema(value_type = f64, minimum = 1.0, maximum = 1e13, example = 2.1e11)]
    pub elastic_modulus_pa: Positive,
    /// Poisson's ratio ν, dimensionless, −1 < ν ≤ 0.5 (steel 0.3).
    #[schema(value_type = f64, exclusive_minimum = -1.0, maximum = 0.5, example = 0.3)]
    pub poisson_ratio: PoissonRatio,
}

/// A line (rectangular) contact of cylinders with parallel axes along y.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct LineSpec {
    /// Effective contact length L along the cylinder axes, m (> 0); the load is carried
    /// uniformly over it (crowned rollers: the length less the crowning and corner radii).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 100.0, example = 0.01)]
    pub length_m: Positive,
}

/// The curve fits `fidelity: closed_form` uses for κ, 𝓔 and 𝓚 (α_r = R_y/R_x ≥ 1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum ClosedFormFit {
    /// Hamrock & Dowson (1981): κ = 1.0339 α_r^0.636, 𝓔 = 1.0003 + 0.5968/α_r,
    /// 𝓚 = 1.5277 + 0.6023 ln α_r (Stachowiak & Batchelor Table 7.4).
    #[default]
    HamrockDowson,
    /// Hamrock & Brewe (1983): κ = α_r^(2/π), 𝓔 = 1 + (π/2 − 1)/α_r,
    /// 𝓚 = π/2 + (π/2 − 1) ln α_r (Hamrock Table 21.7, the basis of Table 21.8).
    HamrockBrewe,
}

/// Request: two bodies pressed together by a normal load.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct HertzInput {
    pub body1: BodySpec,
    pub body2: BodySpec,
    /// Normal load W pressing the bodies together, N, > 0 and at most 1e12 (for a line
    /// contact: the total load on `line.length_m`).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 1e12, example = 50.0)]
    pub load_n: Positive,
    /// Present for a line contact of cylinders with axes along y; absent for a point
    /// (circular or elliptical) contact.
    pub line: Option<LineSpec>,
    /// `standard` (default): exact, κ from the radius ratio by a bracketed solve with exact
    /// elliptic integrals; `closed_form`: the curve fits chosen by `closed_form`. A line contact
    /// is exact either way.
    #[serde(default)]
    pub fidelity: FidelityRequest,
    /// Which fits `fidelity: closed_form` uses (default `hamrock_dowson`); only with that
    /// fidelity.
    pub closed_form: Option<ClosedFormFit>,
}

/// Subsurface stresses under the centre in one body.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct SubsurfaceStress {
    /// Which body: 1 or 2.
    #[schema(minimum = 1, maximum = 2, example = 1)]
    pub body: u8,
    /// Its Poisson's ratio, dimensionless (the stresses depend on it; the pressure does not).
    #[schema(example = 0.3)]
    pub poisson_ratio: f64,
    /// Largest principal shear stress τ₁ = (σ₁ − σ₃)/2 on the axis below the centre, Pa, ≥ 0.
    #[schema(example = 1.9e8)]
    pub max_shear_stress_pa: f64,
    /// Its depth below the surface, m (0: at the surface).
    #[schema(example = 8.3e-5)]
    pub max_shear_depth_m: f64,
    /// Largest von Mises equivalent stress on the axis below the centre, Pa, ≥ 0.
    #[schema(example = 3.5e8)]
    pub max_von_mises_pa: f64,
    /// Its depth below the surface, m.
    #[schema(example = 8.0e-5)]
    pub max_von_mises_depth_m: f64,
}

/// Result. Point contacts give the semi-axes, line contacts the half-width.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct HertzOutput {
    /// `point` (circular or elliptical) or `line`.
    #[schema(example = "point")]
    pub contact: String,
    /// Maximum contact pressure p_max at the centre, Pa: 3W/(2πab) (point), 2W′/(πb) (line).
    #[schema(example = 5.9e8)]
    pub max_pressure_pa: f64,
    /// Mean contact pressure W/area, Pa: ⅔ p_max (point), π/4 p_max (line).
    #[schema(example = 3.9e8)]
    pub mean_pressure_pa: f64,
    /// Semi-major axis a of the contact ellipse (the radius of a circle), m; point contacts.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = 2.3e-4)]
    pub semi_major_axis_m: Option<f64>,
    /// Semi-minor axis b of the contact ellipse, m; point contacts.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = 1.8e-4)]
    pub semi_minor_axis_m: Option<f64>,
    /// Half-width b of the contact band (along x), m; line contacts.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = 5.75e-6)]
    pub half_width_m: Option<f64>,
    /// Contact area πab (point) or 2bL (line), m².
    #[schema(example = 1.3e-7)]
    pub contact_area_m2: f64,
    /// Mutual approach δ of distant points of the two bodies, m. Point contact:
    /// δ = 𝓚[(9/(2𝓔R))(W/(πκE′))²]^⅓. Line contact (a 2-D half-space has no finite approach):
    /// the approach of the two cylinders' axes by Hamrock eq. 21.51 (= Stachowiak Table 7.2),
    /// δ = (2W′/(πE′))[2/3 + ln(2|r₁|/b) + ln(2|r₂|/b)], with |r| for a concave ring; absent
    /// when a body is flat (the logarithm diverges; a warning says so).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = 1.6e-6)]
    pub approach_m: Option<f64>,
    /// Ellipticity κ = a/b ≥ 1, dimensionless (the fit's κ at `closed_form`); point contacts.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(minimum = 1.0, example = 1.31)]
    pub ellipticity: Option<f64>,
    /// Complete elliptic integral of the first kind 𝓚(m), m = 1 − 1/κ² (the fit's value at
    /// `closed_form`), dimensionless; point contacts.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = 1.77)]
    pub elliptic_integral_k: Option<f64>,
    /// Complete elliptic integral of the second kind 𝓔(m), dimensionless; point contacts.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = 1.40)]
    pub elliptic_integral_e: Option<f64>,
    /// Radius ratio α_r = R_y/R_x ≥ 1 in the frame where 1/R_x ≥ 1/R_y (Hamrock's α), dimensionless;
    /// point contacts.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(minimum = 1.0, example = 1.5)]
    pub radius_ratio: Option<f64>,
    /// The request's direction the major axis lies along: `x`, `y`, or `circle` when a = b
    /// (the major axis lies along the direction of the smaller curvature sum).
    #[schema(example = "x")]
    pub major_axis_along: String,
    /// Load per unit length W′ = W/L, N/m; line contacts.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = 500.0)]
    pub load_per_length_n_m: Option<f64>,
    /// Largest principal shear stress τ₁ = (σ₁ − σ₃)/2 below the centre, Pa (the larger of the
    /// two bodies'; not the orthogonal shear τ_yz, which peaks off the axis). Exact stresses on
    /// the axis, maximised in depth.
    #[schema(example = 1.9e8)]
    pub max_shear_stress_pa: f64,
    /// Depth of `max_shear_stress_pa` below the surface, m.
    #[schema(example = 8.3e-5)]
    pub max_shear_depth_m: f64,
    /// Largest von Mises stress below the centre, Pa (the larger of the two bodies').
    #[schema(example = 3.5e8)]
    pub max_von_mises_pa: f64,
    /// Depth of `max_von_mises_pa` below the surface, m.
    #[schema(example = 8.0e-5)]
    pub max_von_mises_depth_m: f64,
    /// The subsurface maxima in each body (they differ when the Poisson's ratios do).
    pub subsurface: Vec<SubsurfaceStress>,
    /// Curvature sum 1/R = 1/R_x + 1/R_y, 1/m (Khonsari's Σρ; 1/R_x for a line).
    #[schema(example = 83.3)]
    pub curvature_sum_1_m: f64,
    /// Curvature difference Γ = R|1/R_x − 1/R_y|, dimensionless, 0 (circle) … 1 (line)
    /// (Hamrock's Γ, Khonsari's F(ρ)).
    #[schema(minimum = 0.0, maximum = 1.0, example = 0.2)]
    pub curvature_difference: f64,
    /// Reduced radius in the request's x direction, R_x = 1/(1/r₁ₓ + 1/r₂ₓ), m.
    #[schema(example = 0.03)]
    pub reduced_radius_x_m: f64,
    /// Reduced radius in the request's y direction, m; absent for a line contact (infinite).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = 0.02)]
    pub reduced_radius_y_m: Option<f64>,
    /// Reduced radius R = 1/(1/R_x + 1/R_y), m (Stachowiak's R′; R_x for a line).
    #[schema(example = 0.012)]
    pub reduced_radius_m: f64,
    /// Effective modulus E′ = 2/[(1 − ν₁²)/E₁ + (1 − ν₂²)/E₂], Pa (Hamrock's and Stachowiak's
    /// E′, 2.31e11 for steel with E = 2.1e11, ν = 0.3; Johnson's E* is E′/2).
    #[schema(example = 2.308e11)]
    pub effective_modulus_pa: f64,
}

impl Calculation for Hertz {
    const PATH: &'static str = "/v1/contacts/hertz";
    const SUMMARY: &'static str =
        "Hertz contact: point, elliptical and line contacts, with subsurface shear and von Mises stresses";
    const DESCRIPTION: &'static str = include_str!("hertz.md");
    const FIDELITY: &'static [Level] = &[Level::ClosedForm, Level::Standard];
    const EFFECTS: &'static [&'static str] = &[];
    const EXAMPLE: &'static str = r#"{"body1": {"radius_x_m": 0.015, "radius_y_m": 0.015, "elastic_modulus_pa": 2.1e11, "poisson_ratio": 0.3}, "body2": {"radius_x_m": -0.03, "radius_y_m": -0.06, "elastic_modulus_pa": 2.1e11, "poisson_ratio": 0.3}, "load_n": 50}"#;

    type Input = HertzInput;
    type Output = HertzOutput;

    fn run(case: Contact, ctx: &mut Context) -> Result<HertzOutput, CalcError> {
        CalcError::finite_or_out_of_range(
            HertzOutput::reported(&case.solve()?, ctx),
            "the load, the radii and the line's length",
        )
    }
}

impl From<ClosedFormFit> for Fit {
    fn from(fit: ClosedFormFit) -> Fit {
        match fit {
            ClosedFormFit::HamrockDowson => Fit::HamrockDowson,
            ClosedFormFit::HamrockBrewe => Fit::HamrockBrewe,
        }
    }
}

impl BodySpec {
    /// The body as the model takes it.
    pub fn body(&self) -> Body {
        Body {
            radius_x_m: self.radius_x_m.map(Radius::get),
            radius_y_m: self.radius_y_m.map(Radius::get),
            modulus_pa: self.elastic_modulus_pa.get(),
            poisson_ratio: self.poisson_ratio.get(),
        }
    }
}

/// How κ is found for a request's `fidelity` and `closed_form`: the fits at `closed_form`,
/// exact at `standard`; anything else is refused with its pointer.
pub(crate) fn method_of(
    fidelity: FidelityRequest,
    closed_form: Option<ClosedFormFit>,
) -> Result<Method, FieldError> {
    match (fidelity, closed_form) {
        (FidelityRequest::Level(Level::ClosedForm), fit) => {
            Ok(Method::Fit(fit.unwrap_or_default().into()))
        }
        (FidelityRequest::Level(Level::Standard), None) => Ok(Method::Exact),
        (FidelityRequest::Level(Level::Standard), Some(_)) => Err(FieldError::new(
            "/closed_form",
            "chooses the curve fits of fidelity closed_form; the standard fidelity is exact",
        )),
        _ => Err(FieldError::new(
            "/fidelity",
            "this calculation offers closed_form (curve fits) and standard (exact to round-off); there is no grid to refine",
        )),
    }
}

/// The contact of a request holding `body1`, `body2`, `load_n` and `line` at the top level
/// (this room's and both EHL rooms'): the model's refusals with their pointers.
pub(crate) fn contact_of(
    body1: &BodySpec,
    body2: &BodySpec,
    load_n: Positive,
    line: Option<LineSpec>,
    method: Method,
) -> Result<Contact, Vec<FieldError>> {
    let shape = match line {
        Some(line) => Shape::Line {
            length_m: line.length_m.get(),
        },
        None => Shape::Point,
    };
    Contact::new([body1.body(), body2.body()], load_n.get(), shape, method).map_err(|invalid| {
        invalid
            .into_iter()
            .map(|e| FieldError::new(e.field.hertz_pointer(), e.message))
            .collect()
    })
}

impl Validate for HertzInput {
    type Valid = Contact;
    fn validate(self) -> Result<Contact, Vec<FieldError>> {
        let method = method_of(self.fidelity, self.closed_form);
        let contact = contact_of(
            &self.body1,
            &self.body2,
            self.load_n,
            self.line,
            *method.as_ref().unwrap_or(&Method::Exact),
        );
        match (contact, method) {
            (Ok(contact), Ok(_)) => Ok(contact),
            (contact, method) => {
                let mut errors = contact.err().unwrap_or_default();
                errors.extend(method.err());
                Err(errors)
            }
        }
    }
}

impl SubsurfaceStress {
    fn of(s: &BodyStresses) -> SubsurfaceStress {
        SubsurfaceStress {
            body: s.body,
            poisson_ratio: s.poisson_ratio,
            max_shear_stress_pa: s.max_shear_stress_pa,
            max_shear_depth_m: s.max_shear_depth_m,
            max_von_mises_pa: s.max_von_mises_pa,
            max_von_mises_depth_m: s.max_von_mises_depth_m,
        }
    }
}

impl HertzOutput {
    /// The response for a solved contact, its warnings and solver report passed to `ctx`.
    pub fn reported(solution: &Solution, ctx: &mut Context) -> HertzOutput {
        for warning in &solution.warnings {
            ctx.warn(warning.code, warning.message.clone());
        }
        ctx.report(solution.report.clone());
        HertzOutput::from_solution(solution)
    }

    /// The response for a solved contact.
    pub fn from_solution(s: &Solution) -> HertzOutput {
        let (ellipse, line) = match s.footprint {
            Footprint::Ellipse {
                semi_major_axis_m,
                semi_minor_axis_m,
                ellipticity,
                elliptic_integral_k,
                elliptic_integral_e,
                radius_ratio,
                ..
            } => (
                Some((
                    semi_major_axis_m,
                    semi_minor_axis_m,
                    ellipticity,
                    elliptic_integral_k,
                    elliptic_integral_e,
                    radius_ratio,
                )),
                None,
            ),
            Footprint::Line {
                half_width_m,
                load_per_length_n_m,
            } => (None, Some((half_width_m, load_per_length_n_m))),
        };
        HertzOutput {
            contact: s.contact_name().to_owned(),
            max_pressure_pa: s.max_pressure_pa,
            mean_pressure_pa: s.mean_pressure_pa,
            semi_major_axis_m: ellipse.map(|e| e.0),
            semi_minor_axis_m: ellipse.map(|e| e.1),
            half_width_m: line.map(|l| l.0),
            contact_area_m2: s.contact_area_m2,
            approach_m: s.approach_m,
            ellipticity: ellipse.map(|e| e.2),
            elliptic_integral_k: ellipse.map(|e| e.3),
            elliptic_integral_e: ellipse.map(|e| e.4),
            radius_ratio: ellipse.map(|e| e.5),
            major_axis_along: s.major_axis().name().to_owned(),
            load_per_length_n_m: line.map(|l| l.1),
            max_shear_stress_pa: s.subsurface.shear.0,
            max_shear_depth_m: s.subsurface.shear.1,
            max_von_mises_pa: s.subsurface.von_mises.0,
            max_von_mises_depth_m: s.subsurface.von_mises.1,
            subsurface: s
                .subsurface
                .per_body
                .iter()
                .map(SubsurfaceStress::of)
                .collect(),
            curvature_sum_1_m: s.curvature_sum_1_m,
            curvature_difference: s.curvature_difference,
            reduced_radius_x_m: s.reduced_radius_x_m,
            reduced_radius_y_m: s.reduced_radius_y_m,
            reduced_radius_m: s.reduced_radius_m,
            effective_modulus_pa: s.effective_modulus_pa,
        }
    }
}
