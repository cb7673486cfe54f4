//! `POST /v1/rolling-bearings/load-distribution`: how a ball bearing shares a combined radial
//! and axial load among its balls — the quasi-static equilibrium of the inner ring against a
//! fixed outer ring, every ball summed discretely, with the exact Hertz contacts of the most
//! loaded ball.
//!
//! Model (Harris; Hamrock's handbook §21.3.6; Khonsari & Booser §14.4, RI-6). Rigid rings, ball
//! j at azimuth ψ_j = 2πj/Z (ψ = 0 on the radial load line). The ring moves by δ_r along the
//! load line and δ_a axially; the groove curvature centres of ball j are then
//! - `varying` (default): A_j = √[(a₀ + δ_a)² + (r₀ + δ_r cos ψ_j)²] apart, the contact angle
//!   following from sin α_j = (a₀ + δ_a)/A_j (with r₀ = BD cos α₀, a₀ = BD sin α₀ this is
//!   Harris's A_j = √[(BD sin α₀ + δ_a)² + (BD cos α₀ + δ_r cos ψ_j)²]);
//! - `fixed`: the same distance linearised about the unloaded position,
//!   A_j = A₀ + δ_a sin α_f + δ_r cos α_f cos ψ_j, every contact at the free angle α_f (the
//!   classic δ_ψ = δ_a sin α + δ_r cos α cos ψ, Khonsari eq. 14.21; A₀ − BD is the preload).
//!
//! (r₀, a₀, α_f: see [`super::geometry`]; δ_a is measured from the position where the unloaded
//! balls touch at α_f, or from the concentric position of a preloaded bearing.) The contact
//! deflection is δ_j = A_j − BD, loaded only where positive, and Q_j = K_n δ_j^{3/2} with K_n
//! of both raceway contacts in series from the exact Hertz solution at α_f (over 0–40° it
//! changes by about 0.1 % for a 6210-like bearing: the inner contact stiffens as the outer
//! softens). Equilibrium: Σ Q_j cos α_j cos ψ_j = F_r, Σ Q_j sin α_j = F_a.
//!
//! Solution. The forces are the gradient of the elastic energy U = Σ (2/5) K_n δ_j₊^{5/2},
//! which is convex in (δ_r, δ_a) (δ_j is a norm of an affine map, or affine), so the
//! equilibrium is the minimum of Π = U − F_r δ_r − F_a δ_a. A Newton step on the 2 × 2 analytic
//! Hessian with Armijo backtracking on Π finds it from any start (a gradient step where no ball
//! is loaded, a Levenberg shift where the Hessian is singular). Pure radial (F_a = 0, where
//! symmetry puts every contact angle at 0) and pure axial loads (δ_r = 0) are one-dimensional
//! and bracketed by Brent's method. Convergence: |force residual| ≤ 1e-9 of the load scale
//! max(|F|, Z Q₀), with Q₀ the balls' preload (0 unless preloaded).

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::geometry::{BallBearing, BallBearingSpec, Race};
use crate::calc::contact::hertz::HertzOutput;
use crate::calc::quantity::NonNegative;
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::effects::{Decision, Mode};
use crate::fidelity::{Level, SolverReport};
use crate::numerics::roots::{brent, RootError, Stopping};

pub struct LoadDistribution;

/// Largest load accepted, N.
const MAX_LOAD_N: f64 = 1e9;
/// Force balance, relative to the load scale, at which the equilibrium is accepted.
const TOLERANCE: f64 = 1e-9;
/// Newton iterations allowed (each with up to [`MAX_HALVINGS`] backtracking steps).
const MAX_ITERATIONS: u32 = 200;
const MAX_HALVINGS: u32 = 60;
/// Brent iterations allowed in the one-dimensional cases.
const MAX_BRENT_ITERATIONS: u32 = 200;
/// ISO 76's static-capacity contact pressure for ball bearings (4200 MPa): above it permanent
/// deformation of about 1e-4 D is expected.
const STATIC_LIMIT_PA: f64 = 4.2e9;

/// How the contact angles respond to the load.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum ContactAngleMode {
    /// Each ball's contact angle follows the ring displacement (exact curvature-centre
    /// geometry); needed for deep-groove bearings with clearance under axial load.
    #[default]
    Varying,
    /// Every contact stays at the free contact angle (the classic ε theory); a bearing with a
    /// free angle α_f > 0 then needs F_a > F_r tan α_f, one with α_f = 0 carries no axial load.
    Fixed,
}

/// Request.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct LoadDistributionInput {
    pub bearing: BallBearingSpec,
    /// Radial load F_r on the inner ring, N, 0 … 1e9.
    #[schema(value_type = f64, minimum = 0.0, maximum = 1e9, example = 3000.0)]
    pub radial_load_n: NonNegative,
    /// Axial (thrust) load F_a on the inner ring, N, 0 … 1e9, pressing the balls towards the
    /// side of the free contact angle.
    #[schema(value_type = f64, minimum = 0.0, maximum = 1e9, example = 0.0)]
    pub axial_load_n: NonNegative,
    /// `varying` (default) or `fixed`.
    #[serde(default)]
    pub contact_angle_mode: ContactAngleMode,
}

/// The validated case.
#[derive(Debug, Clone, Copy)]
pub struct LoadDistributionCase {
    bearing: BallBearing,
    radial_load_n: f64,
    axial_load_n: f64,
    mode: ContactAngleMode,
}

impl Validate for LoadDistributionInput {
    type Valid = LoadDistributionCase;
    fn validate(self) -> Result<LoadDistributionCase, Vec<FieldError>> {
        let bearing = self.bearing.validate_at("/bearing");
        let mut errors = bearing.as_ref().err().cloned().unwrap_or_default();
        let (f_r, f_a) = (self.radial_load_n.get(), self.axial_load_n.get());
        for (f, pointer) in [(f_r, "/radial_load_n"), (f_a, "/axial_load_n")] {
            if f > MAX_LOAD_N {
                errors.push(FieldError::new(
                    pointer,
                    format!("must be at most {MAX_LOAD_N:e} N, got {f}"),
                ));
            }
        }
        match bearing {
            Ok(bearing) if errors.is_empty() => {
                if f_r == 0.0 && f_a == 0.0 && bearing.interference_m() == 0.0 {
                    return Err(vec![FieldError::new(
                        "/radial_load_n",
                        "give a radial or an axial load: an unloaded bearing without preload has no load distribution (its ring floats in the clearance)",
                    )]);
                }
                Ok(LoadDistributionCase {
                    bearing,
                    radial_load_n: f_r,
                    axial_load_n: f_a,
                    mode: self.contact_angle_mode,
                })
            }
            _ => Err(errors),
        }
    }
}

/// One ball's share.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct BallLoad {
    /// Azimuth ψ_j = 360 j/Z, degrees, 0 … 360, measured from the radial load line.
    #[schema(minimum = 0.0, maximum = 360.0, example = 36.0)]
    pub azimuth_deg: f64,
    /// Normal contact load Q_j, N, ≥ 0 (0: outside the load zone).
    #[schema(minimum = 0.0, example = 1100.0)]
    pub load_n: f64,
    /// Contact angle α_j, degrees (the free contact angle for an unloaded ball in `varying`
    /// mode is the geometric angle of its curvature-centre line).
    #[schema(minimum = -90.0, maximum = 90.0, example = 0.0)]
    pub contact_angle_deg: f64,
}

/// The Hertz contact of the most loaded ball on one raceway.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct RacewayContact {
    /// Maximum contact pressure p_max, Pa.
    #[schema(example = 2.0e9)]
    pub max_pressure_pa: f64,
    /// Semi-major axis a of the contact ellipse (across the rolling direction), m.
    #[schema(example = 1.8e-3)]
    pub semi_major_axis_m: f64,
    /// Semi-minor axis b (along the rolling direction), m.
    #[schema(example = 1.9e-4)]
    pub semi_minor_axis_m: f64,
    /// Elastic approach δ of ball and raceway at this contact, m.
    #[schema(example = 1.3e-5)]
    pub approach_m: f64,
}

impl RacewayContact {
    fn from_hertz(h: &HertzOutput) -> Result<Self, CalcError> {
        match (h.semi_major_axis_m, h.semi_minor_axis_m, h.approach_m) {
            (Some(a), Some(b), Some(approach)) => Ok(RacewayContact {
                max_pressure_pa: h.max_pressure_pa,
                semi_major_axis_m: a,
                semi_minor_axis_m: b,
                approach_m: approach,
            }),
            _ => Err(CalcError::Internal(
                "a raceway contact came back without its ellipse".to_owned(),
            )),
        }
    }
}

/// Result.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct LoadDistributionOutput {
    /// Largest ball load Q_max, N.
    #[schema(example = 1380.0)]
    pub max_ball_load_n: f64,
    /// Load-zone factor ε = δ(0)/[δ(0) − δ(π)], dimensionless, with δ(ψ) = A(ψ) − BD the signed
    /// (unclipped) contact deflection at azimuth ψ: the fraction of the pitch diameter along
    /// the load line over which the balls are loaded. In `fixed` mode this is the classic
    /// ε = ½(1 + δ_a tan α/δ_r) (less the clearance term); under pure radial load
    /// ε = ½(1 − P_d/(2δ_r)). ε > 1: every ball loaded. Absent when δ_r = 0 (pure axial load or
    /// an unloaded preloaded bearing: ε → ∞).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(minimum = 0.0, example = 0.44)]
    pub load_zone_factor: Option<f64>,
    /// Load-zone half angle ψ_l, degrees, 0 … 180: the azimuth at which δ(ψ) = 0 on the
    /// continuous pitch circle (180: every ball loaded).
    #[schema(minimum = 0.0, maximum = 180.0, example = 83.0)]
    pub load_zone_half_angle_deg: f64,
    /// Balls carrying load (Q_j > 0).
    #[schema(minimum = 1, example = 5)]
    pub loaded_ball_count: u32,
    /// Every ball, j = 0 … Z − 1.
    pub ball_loads: Vec<BallLoad>,
    /// Radial displacement δ_r of the inner ring along the load line, m (from the concentric
    /// position).
    #[schema(example = 2.0e-5)]
    pub radial_displacement_m: f64,
    /// Axial displacement δ_a of the inner ring, m, along F_a, from the position where the
    /// unloaded balls touch at the free contact angle (a preloaded bearing: from the centred
    /// position). Under pure radial load with clearance in `varying` mode it is −BD sin α_f:
    /// the ring centres itself in the grooves.
    #[schema(example = 0.0)]
    pub axial_displacement_m: f64,
    /// Free contact angle α_f, degrees: cos α_f = r₀/BD (deep groove: 1 − P_d/(2BD)); 0 for a
    /// preloaded bearing.
    #[schema(minimum = 0.0, maximum = 80.0, example = 10.9)]
    pub free_contact_angle_deg: f64,
    /// End play (axial play) of the unloaded bearing, 2BD sin α_f = √(4BDP_d − P_d²) for a deep
    /// groove (Khonsari eq. 14.5), m; 0 when preloaded.
    #[schema(minimum = 0.0, example = 1.89e-4)]
    pub end_play_m: f64,
    /// Load–deflection constant K_n of one ball between both raceways, N/m^1.5 (Q = K_n δ^1.5).
    #[schema(example = 1.1e10)]
    pub contact_stiffness_n_m1_5: f64,
    /// Static safety factor against the 4200 MPa contact-pressure criterion of the static load
    /// rating (Khonsari & Booser RB-8: permanent deformation 1e-4 D): the factor by which the load
    /// could grow before the more loaded raceway reaches it, (4200 MPa/p_max)³ (p ∝ Q^⅓).
    #[schema(example = 2.5)]
    pub static_safety_factor: f64,
    /// Inner raceway contact of the most loaded ball (exact Hertz at its load and angle).
    pub inner_contact: RacewayContact,
    /// Outer raceway contact of the most loaded ball.
    pub outer_contact: RacewayContact,
}

impl Calculation for LoadDistribution {
    const PATH: &'static str = "/v1/rolling-bearings/load-distribution";
    const SUMMARY: &'static str =
        "Ball-bearing load distribution: ball loads, contact angles, load zone and ring displacements under combined radial and axial load";
    const DESCRIPTION: &'static str = "Quasi-static equilibrium of the inner ring of a single-row ball bearing (deep-groove or \
angular-contact, clearance or preload) under a radial load F_r and an axial load F_a, rigid rings, every ball summed discretely at \
ψ_j = 2πj/Z (Harris; Hamrock §21.3.6; Khonsari & Booser §14.4). Groove curvature centres BD apart unloaded (B = f_i + f_o − 1); \
concentric rings put them r₀ = BD cos α_g − P_d/2 apart radially, the free contact angle is cos α_f = r₀/BD. `varying` (default): \
A_j = √[(a₀ + δ_a)² + (r₀ + δ_r cos ψ_j)²], sin α_j = (a₀ + δ_a)/A_j; `fixed`: A_j = A₀ + δ_a sin α_f + δ_r cos α_f cos ψ_j. \
δ_j = A_j − BD ≥ 0, Q_j = K_n δ_j^1.5 with K_n = [K_i^(−2/3) + K_o^(−2/3)]^(−3/2) from the exact Hertz contacts at α_f. \
Σ Q_j cos α_j cos ψ_j = F_r and Σ Q_j sin α_j = F_a are solved as the minimum of the convex elastic energy less the work of the \
loads: safeguarded Newton (analytic 2 × 2 Hessian, Armijo backtracking) or, for pure radial or pure axial loads, Brent's method; \
force balance to 1e-9 of the load. Load-zone factor ε = δ(0)/[δ(0) − δ(π)] (classic ½(1 + δ_a tan α/δ_r) at fixed angle). \
Zero clearance, pure radial: Q_max = 4.37 F_r/Z for many balls (Stribeck); pure axial: Q = F_a/(Z sin α). Centrifugal and \
gyroscopic ball loads are not modelled (no speed).";
    const FIDELITY: &'static [Level] = &[Level::Standard];
    const EFFECTS: &'static [&'static str] = &["centrifugal", "gyroscopic"];
    const EXAMPLE: &'static str = r#"{"bearing": {"ball_diameter_m": 0.0127, "pitch_diameter_m": 0.07, "ball_count": 10, "inner_groove_radius_m": 0.0066, "outer_groove_radius_m": 0.0066, "diametral_clearance_m": 1.8e-5, "ball": {"elastic_modulus_pa": 2.08e11, "poisson_ratio": 0.3}, "rings": {"elastic_modulus_pa": 2.08e11, "poisson_ratio": 0.3}}, "radial_load_n": 3000, "axial_load_n": 1000}"#;

    type Input = LoadDistributionInput;
    type Output = LoadDistributionOutput;

    fn run(
        case: LoadDistributionCase,
        ctx: &mut Context,
    ) -> Result<LoadDistributionOutput, CalcError> {
        for effect in EFFECTS_NOT_MODELLED {
            ctx.decide(effect.0, Decision::not_applicable(Mode::Auto, effect.1));
        }
        let bearing = &case.bearing;
        let alpha_f = bearing.free_contact_angle();
        let k_n = bearing.contact_stiffness(alpha_f, ctx)?;
        let rings = Rings::new(&case, k_n);
        rings.check_existence(&case)?;
        let (u, report) = rings.equilibrium(ctx)?;
        let balls = rings.balls(u);
        let (q_max, alpha_max) = balls.iter().fold((0.0, alpha_f), |m, b| {
            if b.load > m.0 {
                (b.load, b.angle)
            } else {
                m
            }
        });
        if q_max <= 0.0 {
            return Err(CalcError::Internal(
                "an equilibrium without a loaded ball".to_owned(),
            ));
        }
        rings.check_geometry(u)?;
        let inner = bearing.raceway_contact(Race::Inner, alpha_max, q_max, ctx)?;
        let outer = bearing.raceway_contact(Race::Outer, alpha_max, q_max, ctx)?;
        let p_max = inner.max_pressure_pa.max(outer.max_pressure_pa);
        if p_max > STATIC_LIMIT_PA {
            ctx.warn(
                "static_capacity_exceeded",
                format!(
                    "the most loaded ball's contact pressure {:.0} MPa exceeds the 4200 MPa of ISO 76's static load rating for ball bearings: permanent raceway deformation beyond 1e-4 D is expected, and rigid-ring Hertz theory is stretched",
                    p_max / 1e6
                ),
            );
        }
        ctx.report(report);
        let (d0, d_pi) = (
            rings.signed_deflection(u, 1.0),
            rings.signed_deflection(u, -1.0),
        );
        let z = bearing.ball_count;
        Ok(LoadDistributionOutput {
            max_ball_load_n: q_max,
            load_zone_factor: (u[0] > 0.0 && d0 > d_pi).then(|| d0 / (d0 - d_pi)),
            load_zone_half_angle_deg: rings.load_zone_half_angle(u).to_degrees(),
            loaded_ball_count: balls.iter().filter(|b| b.load > 0.0).count() as u32,
            ball_loads: balls
                .iter()
                .enumerate()
                .map(|(j, b)| BallLoad {
                    azimuth_deg: 360.0 * j as f64 / z as f64,
                    load_n: b.load,
                    contact_angle_deg: b.angle.to_degrees(),
                })
                .collect(),
            radial_displacement_m: u[0],
            axial_displacement_m: rings.axial_displacement(u),
            free_contact_angle_deg: alpha_f.to_degrees(),
            end_play_m: bearing.end_play_m(),
            contact_stiffness_n_m1_5: k_n,
            static_safety_factor: (STATIC_LIMIT_PA / p_max).powi(3),
            inner_contact: RacewayContact::from_hertz(&inner)?,
            outer_contact: RacewayContact::from_hertz(&outer)?,
        })
    }
}

const EFFECTS_NOT_MODELLED: [(&str, &str); 2] = [
    ("centrifugal", "not modelled: a quasi-static equilibrium without speed; the ball's centrifugal force F_c = ½ m d_m ω_m² (Khonsari & Booser RI-9, significant from about 5000–20 000 rpm) would load the outer contacts more and part the inner and outer contact angles"),
    ("gyroscopic", "not modelled: the gyroscopic moment on the balls and race control need the speeds and a friction model (Hamrock §21.3: a separate high-speed analysis)"),
];

/// One ball at equilibrium.
struct Ball {
    load: f64,
    angle: f64,
}

/// The approach law of the chosen mode.
#[derive(Debug, Clone, Copy)]
enum Law {
    /// A_j = hypot(u_a, r₀ + u_r cos ψ_j), with u_a = a₀ + δ_a the axial offset of the
    /// curvature centres.
    Varying { r0: f64 },
    /// A_j = A₀ + u_a sin α_f + u_r cos α_f cos ψ_j, with u_a = δ_a.
    Fixed { a0: f64, sin: f64, cos: f64 },
}

/// The ring system the equilibrium is solved on, in the unknowns u = [u_r, u_a] (u_r = δ_r).
struct Rings {
    law: Law,
    /// cos ψ_j.
    cosines: Vec<f64>,
    /// BD, m.
    bd: f64,
    /// a₀, m (the reference of δ_a).
    a0: f64,
    k_n: f64,
    /// Applied load [F_r, F_a], N.
    load: [f64; 2],
    /// Load scale of the residual, N.
    scale: f64,
    /// Characteristic contact deflection, m: the approach under an even share of the load.
    delta_scale: f64,
}

/// Energy, gradient and Hessian of Π at a point.
struct Local {
    energy: f64,
    gradient: [f64; 2],
    hessian: [f64; 3],
}

impl Rings {
    fn new(case: &LoadDistributionCase, k_n: f64) -> Self {
        let b = &case.bearing;
        let z = b.ball_count;
        let (bd, r0, a0) = (
            b.curvature_centre_distance_m,
            b.radial_centre_offset_m,
            b.axial_centre_offset_m(),
        );
        let law = match case.mode {
            ContactAngleMode::Varying => Law::Varying { r0 },
            ContactAngleMode::Fixed => {
                let a = a0.hypot(r0);
                Law::Fixed {
                    a0: a,
                    sin: a0 / a,
                    cos: r0 / a,
                }
            }
        };
        let load = [case.radial_load_n, case.axial_load_n];
        let preload = z as f64 * k_n * b.interference_m().powf(1.5);
        let scale = load[0].hypot(load[1]).max(preload);
        Rings {
            law,
            cosines: (0..z)
                .map(|j| (std::f64::consts::TAU * j as f64 / z as f64).cos())
                .collect(),
            bd,
            a0,
            k_n,
            load,
            scale,
            delta_scale: (scale / (z as f64 * k_n)).powf(2.0 / 3.0),
        }
    }

    /// At a fixed contact angle the balls' normals span only the cone between (±cos α, sin α):
    /// an equilibrium needs F_a ≥ F_r tan α, and no axial load at α = 0.
    fn check_existence(&self, case: &LoadDistributionCase) -> Result<(), CalcError> {
        let Law::Fixed { sin, cos, .. } = self.law else {
            return Ok(());
        };
        let [f_r, f_a] = self.load;
        if sin == 0.0 && f_a > 0.0 {
            return Err(CalcError::impossible(
                "/axial_load_n",
                "at a fixed contact angle of 0 (a preloaded or zero-clearance deep-groove bearing) the balls carry no axial load: use contact_angle_mode varying, where the contact angles grow under the axial load",
            ));
        }
        if f_a * cos < f_r * sin {
            let alpha = case.bearing.free_contact_angle().to_degrees();
            return Err(CalcError::impossible(
                "/axial_load_n",
                format!(
                    "at a fixed contact angle α = {alpha:.4}° a single-row bearing carries F_r only with F_a ≥ F_r tan α = {:.6e} N (the classic ε theory's ε ≥ 0): below that the ring lifts off every ball. Use contact_angle_mode varying, where the contact angles fall under radial load, or raise the axial load",
                    f_r * sin / cos
                ),
            ));
        }
        Ok(())
    }

    /// Signed approach A − BD of a ball at cos ψ = c.
    fn signed_deflection(&self, u: [f64; 2], c: f64) -> f64 {
        self.distance(u, c) - self.bd
    }

    fn distance(&self, u: [f64; 2], c: f64) -> f64 {
        match self.law {
            Law::Varying { r0 } => u[1].hypot(r0 + u[0] * c),
            Law::Fixed { a0, sin, cos } => a0 + u[1] * sin + u[0] * cos * c,
        }
    }

    /// Π, ∇Π and ∇²Π (as [h_rr, h_ra, h_aa]) at u.
    fn local(&self, u: [f64; 2]) -> Local {
        let mut l = Local {
            energy: -self.load[0] * u[0] - self.load[1] * u[1],
            gradient: [-self.load[0], -self.load[1]],
            hessian: [0.0; 3],
        };
        let h = &mut l.hessian;
        for &c in &self.cosines {
            let (a, n, curvature) = match self.law {
                Law::Varying { r0 } => {
                    let x = r0 + u[0] * c;
                    let a = u[1].hypot(x);
                    // ∇A = (x c, u_a)/A; ∇²A = [c² u_a², −c x u_a, x²]/A³.
                    let a3 = a * a * a;
                    (
                        a,
                        [x * c / a, u[1] / a],
                        [c * c * u[1] * u[1] / a3, -c * x * u[1] / a3, x * x / a3],
                    )
                }
                Law::Fixed { a0, sin, cos } => {
                    (a0 + u[1] * sin + u[0] * cos * c, [cos * c, sin], [0.0; 3])
                }
            };
            let delta = a - self.bd;
            if delta <= 0.0 {
                continue;
            }
            let root = delta.sqrt();
            let q = self.k_n * delta * root;
            let dq = 1.5 * self.k_n * root;
            l.energy += 0.4 * q * delta;
            l.gradient[0] += q * n[0];
            l.gradient[1] += q * n[1];
            h[0] += dq * n[0] * n[0] + q * curvature[0];
            h[1] += dq * n[0] * n[1] + q * curvature[1];
            h[2] += dq * n[1] * n[1] + q * curvature[2];
        }
        l
    }

    fn residual(&self, g: [f64; 2]) -> f64 {
        g[0].hypot(g[1]) / self.scale
    }

    /// The equilibrium u and the solver's report.
    fn equilibrium(&self, ctx: &Context) -> Result<([f64; 2], SolverReport), CalcError> {
        let [f_r, f_a] = self.load;
        let axial_symmetric = match self.law {
            Law::Varying { .. } => true,
            Law::Fixed { sin, .. } => sin == 0.0,
        };
        if f_r == 0.0 && f_a == 0.0 {
            // A preloaded bearing at rest: the concentric position, every ball equally loaded.
            let u = [0.0, 0.0];
            return Ok((
                u,
                report("symmetric", 0, self.residual(self.local(u).gradient)),
            ));
        }
        // u_a = 0: contact angles 0 (varying) or δ_a = 0 (fixed), the symmetric position.
        if f_r == 0.0 {
            return self.one_dimensional(1, ctx);
        }
        if f_a == 0.0 && axial_symmetric {
            return self.one_dimensional(0, ctx);
        }
        self.newton(ctx)
    }

    /// Brent's method on one component of the force balance along axis k, the other unknown
    /// held at 0 where symmetry puts it. The force along k grows monotonically with u_k
    /// (convex energy), from about −F_k at u_k = 0 (the symmetric ring carries no net force).
    fn one_dimensional(
        &self,
        k: usize,
        ctx: &Context,
    ) -> Result<([f64; 2], SolverReport), CalcError> {
        let at = |x: f64| {
            let mut u = [0.0, 0.0];
            u[k] = x;
            u
        };
        let force = |x: f64| self.local(at(x)).gradient[k];
        let at_rest = self.residual(self.local(at(0.0)).gradient);
        if force(0.0) >= 0.0 && at_rest <= TOLERANCE {
            // A load below round-off of a heavy preload.
            return Ok((at(0.0), report("brent_ball_load_balance", 0, at_rest)));
        }
        // Past the clearance (or the end play), then doubled until the balls carry the load.
        let mut hi = self.a0 + self.bd + self.delta_scale;
        let mut grown = 0;
        while force(hi) <= 0.0 {
            hi *= 2.0;
            grown += 1;
            if grown > 200 || !hi.is_finite() {
                return Err(CalcError::Internal(
                    "no bracket for the one-dimensional equilibrium".to_owned(),
                ));
            }
        }
        ctx.check_deadline()?;
        let stop = Stopping {
            x_tolerance: 0.0,
            max_iterations: MAX_BRENT_ITERATIONS,
        };
        let root = brent(force, 0.0, hi, stop).map_err(|e| match e {
            RootError::NotConverged { iterations, width } => CalcError::NotConverged {
                method: "brent_ball_load_balance",
                iterations,
                residual: width,
            },
            other => CalcError::Internal(format!("load balance bracket: {other:?}")),
        })?;
        let u = at(root.x);
        let residual = self.residual(self.local(u).gradient);
        if residual > TOLERANCE {
            return Err(CalcError::NotConverged {
                method: "brent_ball_load_balance",
                iterations: root.iterations,
                residual,
            });
        }
        Ok((
            u,
            report("brent_ball_load_balance", root.iterations, residual),
        ))
    }

    /// Safeguarded Newton on Π: analytic Hessian, Levenberg shift when it is singular, a
    /// gradient step where no ball is loaded, Armijo backtracking on Π.
    fn newton(&self, ctx: &Context) -> Result<([f64; 2], SolverReport), CalcError> {
        // Start with the ring pushed along the load by twice the characteristic deflection
        // from the position where the unloaded balls touch.
        let f = self.load[0].hypot(self.load[1]);
        let push = 2.0 * self.delta_scale;
        let mut u = match self.law {
            Law::Varying { .. } => [push * self.load[0] / f, self.a0 + push * self.load[1] / f],
            Law::Fixed { .. } => [push * self.load[0] / f, push * self.load[1] / f],
        };
        let mut here = self.local(u);
        let mut residual = self.residual(here.gradient);
        for iteration in 1..=MAX_ITERATIONS {
            if residual <= TOLERANCE {
                return Ok((
                    u,
                    report("newton_energy_line_search", iteration - 1, residual),
                ));
            }
            if iteration % 8 == 0 {
                ctx.check_deadline()?;
            }
            let g = here.gradient;
            let [h_rr, h_ra, h_aa] = here.hessian;
            let trace = h_rr + h_aa;
            let step = if trace > 0.0 {
                let shift = 1e-12 * trace;
                let (a, b, c) = (h_rr + shift, h_ra, h_aa + shift);
                let det = a * c - b * b;
                [-(c * g[0] - b * g[1]) / det, -(a * g[1] - b * g[0]) / det]
            } else {
                let norm = g[0].hypot(g[1]);
                [-g[0] / norm * push, -g[1] / norm * push]
            };
            let slope = g[0] * step[0] + g[1] * step[1];
            if slope >= 0.0 || slope.is_nan() {
                return Err(CalcError::NotConverged {
                    method: "newton_energy_line_search",
                    iterations: iteration,
                    residual,
                });
            }
            let mut t = 1.0;
            let mut accepted = None;
            for _ in 0..=MAX_HALVINGS {
                let trial = [u[0] + t * step[0], u[1] + t * step[1]];
                let next = self.local(trial);
                // Armijo on Π; near the minimum Π's decrease (∝ residual²) sinks below its
                // round-off, and a step that shrinks the force residual is taken instead.
                let decreases = next.energy <= here.energy + 1e-4 * t * slope;
                let balances = self.residual(next.gradient) <= (1.0 - 1e-4 * t) * residual;
                if decreases || balances {
                    accepted = Some((trial, next));
                    break;
                }
                t *= 0.5;
            }
            let Some((trial, next)) = accepted else {
                return Err(CalcError::NotConverged {
                    method: "newton_energy_line_search",
                    iterations: iteration,
                    residual,
                });
            };
            u = trial;
            here = next;
            residual = self.residual(here.gradient);
            if !residual.is_finite() {
                return Err(CalcError::NotConverged {
                    method: "newton_energy_line_search",
                    iterations: iteration,
                    residual,
                });
            }
        }
        if residual <= TOLERANCE {
            return Ok((
                u,
                report("newton_energy_line_search", MAX_ITERATIONS, residual),
            ));
        }
        Err(CalcError::NotConverged {
            method: "newton_energy_line_search",
            iterations: MAX_ITERATIONS,
            residual,
        })
    }

    fn balls(&self, u: [f64; 2]) -> Vec<Ball> {
        self.cosines
            .iter()
            .map(|&c| {
                let delta = self.signed_deflection(u, c).max(0.0);
                let angle = match self.law {
                    Law::Varying { r0 } => u[1].atan2(r0 + u[0] * c),
                    Law::Fixed { sin, cos, .. } => sin.atan2(cos),
                };
                Ball {
                    load: self.k_n * delta * delta.sqrt(),
                    angle,
                }
            })
            .collect()
    }

    /// The curvature centres of a ball must stay on their own sides: r₀ + δ_r cos ψ > 0.
    fn check_geometry(&self, u: [f64; 2]) -> Result<(), CalcError> {
        if let Law::Varying { r0 } = self.law {
            if u[0] >= r0 {
                return Err(CalcError::impossible(
                    "/radial_load_n",
                    format!(
                        "the radial displacement {:.4e} m would carry the raceway curvature centres past each other (r₀ = {r0:.4e} m): a load this large is far beyond the bearing's static capacity and the rigid-ring Hertz model",
                        u[0]
                    ),
                ));
            }
        }
        Ok(())
    }

    /// δ_a of the report: from a₀ in `varying` mode (u_a is the curvature centres' offset).
    fn axial_displacement(&self, u: [f64; 2]) -> f64 {
        match self.law {
            Law::Varying { .. } => u[1] - self.a0,
            Law::Fixed { .. } => u[1],
        }
    }

    /// ψ_l where δ(ψ) = 0 on the continuous circle, rad, within [0, π]: varying,
    /// (r₀ + δ_r cos ψ_l)² = B²D² − u_a²; fixed, A₀ + δ_a sin α + δ_r cos α cos ψ_l = BD.
    fn load_zone_half_angle(&self, u: [f64; 2]) -> f64 {
        let (d0, d_pi) = (
            self.signed_deflection(u, 1.0),
            self.signed_deflection(u, -1.0),
        );
        if d_pi >= 0.0 {
            return std::f64::consts::PI;
        }
        if d0 <= 0.0 {
            return 0.0;
        }
        // Here δ changes sign between ψ = 0 and π, so δ_r > 0 and, varying, |u_a| < BD.
        let c = match self.law {
            Law::Varying { r0 } => ((self.bd - u[1]) * (self.bd + u[1])).sqrt() - r0,
            Law::Fixed { a0, sin, .. } => self.bd - a0 - u[1] * sin,
        } / (u[0] * self.radial_projection());
        c.clamp(-1.0, 1.0).acos()
    }

    /// cos α of the fixed law's radial term (1 for the varying law, whose cos ψ multiplies δ_r).
    fn radial_projection(&self) -> f64 {
        match self.law {
            Law::Varying { .. } => 1.0,
            Law::Fixed { cos, .. } => cos,
        }
    }
}

fn report(method: &str, iterations: u32, residual: f64) -> SolverReport {
    SolverReport {
        method: method.to_owned(),
        fidelity: Level::Standard,
        grid: None,
        iterations,
        residual: Some(residual),
        error_estimate: None,
        elapsed_ms: 0.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::calc::Failure;
    use proptest::prelude::*;
    use serde_json::{json, Value};

    fn post(request: &Value) -> Result<Value, Failure> {
        crate::calc::testing::post::<LoadDistribution>(request)
    }

    fn ok(request: &Value) -> Value {
        crate::calc::testing::ok::<LoadDistribution>(request)
    }

    fn get(v: &Value, pointer: &str) -> f64 {
        v.pointer(pointer)
            .and_then(Value::as_f64)
            .unwrap_or_else(|| panic!("{pointer} missing in {v}"))
    }

    fn assert_rel(got: f64, want: f64, tol: f64, what: &str) {
        assert!(
            ((got - want) / want).abs() <= tol,
            "{what}: got {got}, want {want} ±{tol}"
        );
    }

    fn steel(e: f64) -> Value {
        json!({"elastic_modulus_pa": e, "poisson_ratio": 0.3})
    }

    /// A ball bearing, lengths in mm.
    fn bearing(d: f64, dm: f64, z: u32, f: f64, clearance_mm: f64, e: f64) -> Value {
        json!({
            "ball_diameter_m": d * 1e-3, "pitch_diameter_m": dm * 1e-3, "ball_count": z,
            "inner_groove_radius_m": f * d * 1e-3, "outer_groove_radius_m": f * d * 1e-3,
            "diametral_clearance_m": clearance_mm * 1e-3, "ball": steel(e), "rings": steel(e)
        })
    }

    /// Khonsari & Booser Ex 14.1: 6210, D = 12.7 mm, d_m = 70 mm, Z = 10, r = 6.6 mm,
    /// P_d = 0.018 mm, E′ = 219 GPa.
    fn bearing_6210(clearance_mm: f64) -> Value {
        let mut b = bearing(12.7, 70.0, 10, 0.52, clearance_mm, 2.19e11 * 0.91);
        b["inner_groove_radius_m"] = json!(6.6e-3);
        b["outer_groove_radius_m"] = json!(6.6e-3);
        b
    }

    fn request(bearing: Value, f_r: f64, f_a: f64, mode: &str) -> Value {
        json!({"bearing": bearing, "radial_load_n": f_r, "axial_load_n": f_a, "contact_angle_mode": mode})
    }

    /// Σ Q cos α cos ψ and Σ Q sin α from the reported ball loads.
    fn resultant(v: &Value) -> (f64, f64) {
        let balls = v["result"]["ball_loads"].as_array().unwrap();
        balls.iter().fold((0.0, 0.0), |(r, a), b| {
            let q = b["load_n"].as_f64().unwrap();
            let alpha = b["contact_angle_deg"].as_f64().unwrap().to_radians();
            let psi = b["azimuth_deg"].as_f64().unwrap().to_radians();
            (r + q * alpha.cos() * psi.cos(), a + q * alpha.sin())
        })
    }

    fn loads(v: &Value) -> Vec<f64> {
        v["result"]["ball_loads"]
            .as_array()
            .unwrap()
            .iter()
            .map(|b| b["load_n"].as_f64().unwrap())
            .collect()
    }

    #[test]
    fn zero_clearance_radial_load_gives_stribecks_constant() {
        // Spec §2.4: Z/Σ(Q_j/Q_max) cos ψ_j = Z/Σ cos^{5/2} ψ_j over the loaded half.
        for (z, want) in [
            (8, 4.346),
            (10, 4.379),
            (12, 4.364),
            (16, 4.368),
            (20, 4.369),
        ] {
            let dm = 12.7 * z as f64 / 1.5;
            for mode in ["varying", "fixed"] {
                let v = ok(&request(
                    bearing(12.7, dm, z, 0.52, 0.0, 2.08e11),
                    5000.0,
                    0.0,
                    mode,
                ));
                let factor = get(&v, "/result/max_ball_load_n") * z as f64 / 5000.0;
                assert!((factor - want).abs() < 6e-4, "Z {z} {mode}: {factor}");
                assert_rel(get(&v, "/result/load_zone_factor"), 0.5, 1e-12, "ε");
                assert_rel(
                    get(&v, "/result/load_zone_half_angle_deg"),
                    90.0,
                    1e-12,
                    "ψ_l",
                );
            }
        }
    }

    #[test]
    fn pure_axial_load_is_shared_equally() {
        // Q = F_a/(Z sin α): at the free angle (fixed) or at the loaded angle (varying).
        let mut b = bearing(23.81, 140.0, 16, 0.52, 0.0, 2.08e11);
        b["free_contact_angle_deg"] = json!(40.0);
        let fixed = ok(&request(b.clone(), 0.0, 24000.0, "fixed"));
        for q in loads(&fixed) {
            assert_rel(
                q,
                24000.0 / (16.0 * 40f64.to_radians().sin()),
                1e-12,
                "fixed Q",
            );
        }
        assert!(fixed["result"].get("load_zone_factor").is_none());
        assert_eq!(get(&fixed, "/result/load_zone_half_angle_deg"), 180.0);
        let varying = ok(&request(b, 0.0, 24000.0, "varying"));
        let alpha = get(&varying, "/result/ball_loads/0/contact_angle_deg");
        assert!(
            alpha > 40.0,
            "the contact angle grows under thrust: {alpha}"
        );
        for q in loads(&varying) {
            assert_rel(
                q,
                24000.0 / (16.0 * alpha.to_radians().sin()),
                1e-12,
                "varying Q",
            );
        }
        // A deep-groove bearing with clearance carries thrust at angles above its free angle.
        let v = ok(&request(bearing_6210(0.018), 0.0, 2000.0, "varying"));
        let alpha = get(&v, "/result/ball_loads/3/contact_angle_deg");
        assert!(alpha > get(&v, "/result/free_contact_angle_deg"));
        assert_rel(
            get(&v, "/result/max_ball_load_n"),
            2000.0 / (10.0 * alpha.to_radians().sin()),
            1e-12,
            "Q",
        );
    }

    #[test]
    fn hamrock_deep_groove_example() {
        // Spec A-R3: d_i = 52.291, d_o = 77.706, d = 12.7 mm, n = 9, r = 6.604 mm, P_d = 15 µm,
        // E = 200 GPa, ν = 0.3, F_r = 8900 N. The handbook's Stribeck iteration (continuous
        // integral, the older Hamrock–Dowson fits) converges to Z = 4.564, F_max = 4513 N; the
        // same integral with exact Hertz gives 4515.5 N. The nine balls summed discretely carry
        // 0.16 % more: 4522.6 N.
        let mut b = bearing(12.7, 64.9985, 9, 0.52, 0.015, 2e11);
        b["inner_groove_radius_m"] = json!(6.604e-3);
        b["outer_groove_radius_m"] = json!(6.604e-3);
        let v = ok(&request(b, 8900.0, 0.0, "varying"));
        let q = get(&v, "/result/max_ball_load_n");
        assert_rel(q, 4513.0, 3e-3, "F_max vs the handbook");
        assert_rel(q, 4522.6, 2e-4, "F_max, discrete sum");
        assert_rel(9.0 * q / 8900.0, 4.564, 3e-3, "Stribeck Z");
        // Derived in the spec: β_f = 9.858°, P_e = 0.1739 mm; the contact angles fall to 0.
        assert_rel(
            get(&v, "/result/free_contact_angle_deg"),
            9.858,
            1e-3,
            "β_f",
        );
        assert_rel(get(&v, "/result/end_play_m"), 1.739e-4, 2e-3, "P_e");
        assert_eq!(get(&v, "/result/ball_loads/0/contact_angle_deg"), 0.0);
        // δ = δ_i + δ_o at the most loaded ball: 5.438e-5 m printed (within 1 % exact).
        let approach = get(&v, "/result/inner_contact/approach_m")
            + get(&v, "/result/outer_contact/approach_m");
        assert_rel(approach, 5.438e-5, 0.01, "δ");
        assert_rel(
            approach,
            get(&v, "/result/radial_displacement_m") - 7.5e-6,
            2e-3,
            "δ = δ_r − P_d/2",
        );
    }

    #[test]
    fn khonsari_6210_chain() {
        // Ex 14.1: end play P_e = 0.1889 mm (f = 6.6/12.7). Ex 14.2 (corrected, exact):
        // Q = 1500 N gives inner/outer p = 2063/1747 MPa, a = 1.794/1.744 mm,
        // b = 0.1935/0.2351 mm, δ = 0.01320/0.01276 mm; Hertz scales p, a, b ∝ Q^⅓, δ ∝ Q^⅔,
        // checked here at the discrete equilibrium's Q_max under F_r = 3000 N.
        let v = ok(&request(bearing_6210(0.018), 3000.0, 0.0, "varying"));
        assert_rel(get(&v, "/result/end_play_m"), 0.1889e-3, 1e-3, "P_e");
        let q = get(&v, "/result/max_ball_load_n");
        // Between Stribeck's 4.37 F_r/Z (no clearance) and the classic design rule 5 F_r/Z.
        assert!(q > 4.37 * 300.0 && q < 5.0 * 300.0, "Q_max = {q}");
        let s = (q / 1500.0).cbrt();
        for (race, p, a, b, delta) in [
            ("inner", 2063e6, 1.794e-3, 0.1935e-3, 0.01320e-3),
            ("outer", 1747e6, 1.744e-3, 0.2351e-3, 0.01276e-3),
        ] {
            let c = |f: &str| get(&v, &format!("/result/{race}_contact/{f}"));
            assert_rel(c("max_pressure_pa"), p * s, 2e-3, race);
            assert_rel(c("semi_major_axis_m"), a * s, 2e-3, race);
            assert_rel(c("semi_minor_axis_m"), b * s, 2e-3, race);
            assert_rel(c("approach_m"), delta * s * s, 2e-3, race);
        }
        // Clearance: ε = ½(1 − P_d/(2δ_r)) < ½.
        let eps = get(&v, "/result/load_zone_factor");
        let d_r = get(&v, "/result/radial_displacement_m");
        assert_rel(eps, 0.5 * (1.0 - 0.018e-3 / (2.0 * d_r)), 1e-9, "ε");
    }

    /// Ex 14.5: 7220, F_r = 20 000 N, F_a = 24 000 N, Z = 16, α = 40° constant (D = 23.81 mm,
    /// d_m = 140 mm from Ex 15.2; the groove radii do not enter at a fixed angle).
    fn bearing_7220() -> Value {
        let mut b = bearing(23.81, 140.0, 16, 0.52, 0.0, 2.08e11);
        b["free_contact_angle_deg"] = json!(40.0);
        b
    }

    #[test]
    fn khonsari_7220_combined_load() {
        let v = ok(&request(bearing_7220(), 20000.0, 24000.0, "fixed"));
        assert_rel(get(&v, "/result/max_ball_load_n"), 6374.0, 5e-3, "Q_max");
        assert_rel(get(&v, "/result/load_zone_factor"), 0.799, 5e-3, "ε");
        let q = loads(&v);
        for (j, want) in [5924.0, 4704.0, 3064.0, 1459.0, 315.0].iter().enumerate() {
            let tol = if j == 4 { 0.03 } else { 0.01 };
            assert_rel(q[j + 1], *want, tol, &format!("Q_{}", j + 1));
            assert_rel(q[15 - j], q[j + 1], 1e-9, "symmetry");
        }
        assert!(q[6..=10].iter().all(|&x| x == 0.0));
        // Ball loads follow Q_max [1 − (1 − cos ψ)/(2ε)]^{3/2} exactly at a fixed angle.
        let eps = get(&v, "/result/load_zone_factor");
        let psi = 2.0 * std::f64::consts::PI / 16.0;
        assert_rel(
            q[2],
            q[0] * (1.0 - (1.0 - (2.0 * psi).cos()) / (2.0 * eps)).powf(1.5),
            1e-9,
            "Q(ψ)",
        );
        // Varying angles: the radial displacement tilts the curvature-centre lines, below 40° on
        // the load line and above it opposite; at these small deflections Q_max moves by < 1 %.
        let varying = ok(&request(bearing_7220(), 20000.0, 24000.0, "varying"));
        assert!(get(&varying, "/result/ball_loads/0/contact_angle_deg") < 40.0);
        assert!(get(&varying, "/result/ball_loads/8/contact_angle_deg") > 40.0);
        assert_rel(
            get(&varying, "/result/max_ball_load_n"),
            q[0],
            0.01,
            "varying Q_max",
        );
    }

    #[test]
    fn a_preloaded_bearing_at_rest_loads_every_ball() {
        let v = ok(&request(bearing_6210(-0.01), 0.0, 0.0, "varying"));
        let q = loads(&v);
        assert!(q.iter().all(|&x| x > 0.0 && (x - q[0]).abs() < 1e-9 * q[0]));
        assert_eq!(get(&v, "/result/loaded_ball_count"), 10.0);
        assert_eq!(get(&v, "/result/radial_displacement_m"), 0.0);
        assert_eq!(get(&v, "/result/end_play_m"), 0.0);
        let k = get(&v, "/result/contact_stiffness_n_m1_5");
        assert_rel(q[0], k * 5e-6f64.powf(1.5), 1e-12, "Q = K (−P_d/2)^1.5");
        // Under load the preload keeps every ball loaded.
        let v = ok(&request(bearing_6210(-0.01), 500.0, 0.0, "varying"));
        assert_eq!(get(&v, "/result/loaded_ball_count"), 10.0);
        assert!(get(&v, "/result/load_zone_factor") > 1.0);
        assert_eq!(get(&v, "/result/load_zone_half_angle_deg"), 180.0);
    }

    #[test]
    fn a_light_radial_load_with_clearance_loads_one_ball() {
        let v = ok(&request(bearing_6210(0.018), 1.0, 0.0, "varying"));
        assert_eq!(get(&v, "/result/loaded_ball_count"), 1.0);
        assert_rel(get(&v, "/result/max_ball_load_n"), 1.0, 1e-9, "Q = F_r");
        // Combined, in both modes: a heavy thrust with a light radial load loads every ball.
        for mode in ["varying", "fixed"] {
            let v = ok(&request(bearing_7220(), 100.0, 50000.0, mode));
            assert_eq!(get(&v, "/result/loaded_ball_count"), 16.0, "{mode}");
            assert!(get(&v, "/result/load_zone_factor") > 1.0);
        }
    }

    #[test]
    fn loads_over_five_decades_converge() {
        for mode in ["varying", "fixed"] {
            for f in [1.0, 10.0, 100.0, 1e3, 1e4, 1e5] {
                for (f_r, f_a) in [(f, 0.0), (0.0, f), (f, f), (f, 3.0 * f)] {
                    if mode == "fixed" && f_a < f_r {
                        continue;
                    }
                    let b = if mode == "fixed" {
                        bearing_7220()
                    } else {
                        bearing_6210(0.018)
                    };
                    let v = ok(&request(b, f_r, f_a, mode));
                    let (r, a) = resultant(&v);
                    let scale = f_r.hypot(f_a);
                    assert!(
                        (r - f_r).hypot(a - f_a) <= 1e-9 * scale,
                        "{mode} {f_r} {f_a}: {r} {a}"
                    );
                    assert!(get(&v, "/solver/residual") <= 1e-9);
                }
            }
        }
    }

    #[test]
    fn effects_are_reported_not_modelled() {
        let v = ok(&request(bearing_6210(0.018), 3000.0, 500.0, "varying"));
        for effect in ["centrifugal", "gyroscopic"] {
            assert_eq!(v["effects"][effect]["applied"], false);
        }
    }

    #[test]
    fn a_heavy_load_warns_of_the_static_capacity() {
        let v = ok(&request(bearing_6210(0.018), 60000.0, 0.0, "varying"));
        assert!(v["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .any(|w| w["code"] == "static_capacity_exceeded"));
    }

    fn pointer_of(request: &Value) -> String {
        match post(request) {
            Err(Failure::Invalid(errors)) => errors[0].pointer.clone(),
            Err(Failure::Calc(CalcError::Impossible { pointer, .. })) => pointer,
            other => panic!("{request}: expected 422, got {other:?}"),
        }
    }

    #[test]
    fn bad_input_is_refused_with_its_pointer() {
        let with = |field: &str, value: Value| {
            let mut b = bearing_6210(0.018);
            b[field] = value;
            request(b, 1000.0, 0.0, "varying")
        };
        let rows: Vec<(Value, &str, &str)> = vec![
            (
                with("inner_groove_radius_m", json!(6.0e-3)),
                "/bearing/inner_groove_radius_m",
                "groove tighter than the ball",
            ),
            (
                with("outer_groove_radius_m", json!(6.35e-3)),
                "/bearing/outer_groove_radius_m",
                "osculating groove",
            ),
            (
                with("ball_count", json!(40)),
                "/bearing/ball_count",
                "balls overlap",
            ),
            (
                with("ball_count", json!(2)),
                "/bearing/ball_count",
                "two balls",
            ),
            (
                with("pitch_diameter_m", json!(0.01)),
                "/bearing/ball_count",
                "pitch below the ball",
            ),
            (
                with("diametral_clearance_m", json!(-0.001)),
                "/bearing/diametral_clearance_m",
                "interference beyond 1 % D",
            ),
            (
                with("diametral_clearance_m", json!(0.002)),
                "/bearing/diametral_clearance_m",
                "free angle beyond 80°",
            ),
            (
                with("free_contact_angle_deg", json!(85.0)),
                "/bearing/free_contact_angle_deg",
                "thrust angle",
            ),
            (
                with(
                    "ball",
                    json!({"elastic_modulus_pa": 0.0, "poisson_ratio": 0.3}),
                ),
                "/bearing/ball/elastic_modulus_pa",
                "E = 0",
            ),
            (
                with(
                    "rings",
                    json!({"elastic_modulus_pa": 2e11, "poisson_ratio": 0.6}),
                ),
                "/bearing/rings/poisson_ratio",
                "ν > 0.5",
            ),
            (
                with(
                    "rings",
                    json!({"elastic_modulus_pa": 2e14, "poisson_ratio": 0.3}),
                ),
                "/bearing/rings/elastic_modulus_pa",
                "E beyond 1e13",
            ),
            (
                request(bearing_6210(0.018), -1.0, 0.0, "varying"),
                "/radial_load_n",
                "negative load",
            ),
            (
                request(bearing_6210(0.018), 0.0, 0.0, "varying"),
                "/radial_load_n",
                "no load, no preload",
            ),
            (
                request(bearing_6210(0.018), 2e9, 0.0, "varying"),
                "/radial_load_n",
                "load beyond 1e9",
            ),
            (
                json!({"bearing": bearing_6210(0.018), "radial_lood_n": 1.0, "axial_load_n": 0.0}),
                "/radial_lood_n",
                "typo",
            ),
            (
                request(bearing_6210(0.018), 1000.0, 0.0, "fixed"),
                "/axial_load_n",
                "fixed angle, pure radial, α_f > 0",
            ),
            (
                request(bearing_6210(0.0), 1000.0, 100.0, "fixed"),
                "/axial_load_n",
                "fixed angle 0 with thrust",
            ),
            (
                request(bearing_7220(), 20000.0, 10000.0, "fixed"),
                "/axial_load_n",
                "F_a < F_r tan α",
            ),
        ];
        for (request, pointer, why) in rows {
            assert_eq!(pointer_of(&request), pointer, "{why}");
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(48))]

        #[test]
        fn equilibrium_holds_and_outputs_are_finite(
            log_fr in -1.0f64..4.5,
            log_ratio in -3.0f64..2.0,
            clearance_um in -8.0f64..40.0,
            z in 6u32..20,
            angle in prop_oneof![Just(None), (5.0f64..45.0).prop_map(Some)],
            fixed in any::<bool>(),
        ) {
            let f_r = 10f64.powf(log_fr);
            let f_a = f_r * 10f64.powf(log_ratio);
            let mut b = bearing(10.0, 10.0 * z as f64 / 2.0, z, 0.52, clearance_um * 1e-3, 2.08e11);
            if let Some(a) = angle {
                b["free_contact_angle_deg"] = json!(a);
            }
            let mode = if fixed { "fixed" } else { "varying" };
            let v = match post(&request(b, f_r, f_a, mode)) {
                Ok(v) => v,
                // The fixed-angle existence condition, and only that, may refuse.
                Err(Failure::Calc(CalcError::Impossible { pointer, .. })) if fixed => {
                    prop_assert_eq!(pointer, "/axial_load_n");
                    return Ok(());
                }
                Err(e) => panic!("{e:?}"),
            };
            let (r, a) = resultant(&v);
            // The solver's load scale: max(|F|, Z Q₀); a preloaded bearing's ball loads bound Z Q₀.
            let scale = f_r.hypot(f_a).max(loads(&v).iter().sum::<f64>());
            prop_assert!((r - f_r).hypot(a - f_a) <= 1e-9 * scale, "{} {}: {} {}", f_r, f_a, r, a);
            for p in ["/result/max_ball_load_n", "/result/radial_displacement_m", "/result/axial_displacement_m",
                      "/result/load_zone_half_angle_deg", "/result/inner_contact/max_pressure_pa",
                      "/result/outer_contact/approach_m", "/solver/residual"] {
                prop_assert!(get(&v, p).is_finite(), "{}", p);
            }
        }

        #[test]
        fn max_ball_load_grows_with_radial_load(log_fr in 0.0f64..4.0, f_a in 0.0f64..2000.0, clearance_um in 0.0f64..30.0) {
            let f_r = 10f64.powf(log_fr);
            let q = |f: f64| get(&ok(&request(bearing_6210(clearance_um * 1e-3), f, f_a, "varying")), "/result/max_ball_load_n");
            prop_assert!(q(1.1 * f_r) > q(f_r));
        }

        #[test]
        fn load_zone_grows_with_axial_over_radial_load(log_ratio in -2.0f64..1.0, fixed in any::<bool>()) {
            let f_r = 5000.0;
            let (b, mode, base) = if fixed {
                (bearing_7220(), "fixed", 5000.0 * 40f64.to_radians().tan())
            } else {
                (bearing_6210(0.018), "varying", 0.0)
            };
            let f_a = base + f_r * 10f64.powf(log_ratio);
            let eps = |f: f64| get(&ok(&request(b.clone(), f_r, f, mode)), "/result/load_zone_factor");
            prop_assert!(eps(1.2 * f_a) > eps(f_a));
        }
    }

    /// The static safety factor is the cube of the pressure margin: at the load that brings the
    /// most loaded contact to 4200 MPa it is 1, and it scales as 1/Q_max (p ∝ Q^⅓).
    #[test]
    fn static_safety_factor_is_the_cubed_pressure_margin() {
        let example: Value = serde_json::from_str(LoadDistribution::EXAMPLE).unwrap();
        let v = ok(&example);
        let p = get(&v, "/result/inner_contact/max_pressure_pa")
            .max(get(&v, "/result/outer_contact/max_pressure_pa"));
        let s0 = get(&v, "/result/static_safety_factor");
        assert!((s0 - (STATIC_LIMIT_PA / p).powi(3)).abs() < 1e-9 * s0);
        assert!(s0 > 1.0);
    }
}
