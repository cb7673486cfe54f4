//! The quasi-static equilibrium of a ball bearing's inner ring (the model of
//! `/v1/rolling-bearings/load-distribution`; the equations are in that module's documentation):
//! the classic two-unknown equilibrium of a ring held square ([`classic`]: Brent on the pure
//! radial or pure axial balance, else safeguarded Newton on the elastic energy), the general one
//! with free tilt or the balls' own positions at speed ([`general`], through
//! [`super::ball_equilibrium`]), and the one-dimensional load balance the roller bearing shares.

use super::ball_equilibrium::{BallState, Balls, Gyro, Problem, SeriesLaw};
use super::geometry::BallBearing;
use crate::calc::quantity::RingSpeed;
use crate::calc::{CalcError, Context};
use crate::effects::Mode;
use crate::fidelity::{IterationUnit, SolverReport};
use crate::numerics::dense;
use crate::numerics::driver::{Budget, Driver, Stopped};
use crate::numerics::newton::{self, armijo, residual_falls, LineSearch, NewtonSystem};
use crate::numerics::roots::{brent, grow_bracket, Root, Stopping};

/// Force balance, relative to the load scale, at which the equilibrium is accepted.
const TOLERANCE: f64 = 1e-9;
/// Newton iterations allowed (each with up to [`MAX_HALVINGS`] backtracking steps).
const MAX_ITERATIONS: u32 = 200;
const MAX_HALVINGS: u32 = 60;
/// Traction the outer contact can give before the ball spins there (a dry-ish 0.1; EHL
/// traction coefficients are lower still).
const TRACTION_LIMIT: f64 = 0.1;

/// How the contact angles respond to the load (the request's `contact_angle_mode`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum AngleMode {
    /// Each ball's contact angle follows the ring displacement.
    Varying,
    /// Every contact stays at the free contact angle.
    Fixed,
}

/// A ball bearing's validated load case.
#[derive(Debug, Clone, Copy)]
pub struct LoadDistributionCase {
    pub(super) bearing: BallBearing,
    pub(super) radial_load_n: f64,
    pub(super) axial_load_n: f64,
    pub(super) mode: AngleMode,
    pub(super) moment_n_m: Option<f64>,
    pub(super) speed: RingSpeed,
    /// The modes of the centrifugal and gyroscopic effects.
    pub(super) centrifugal: Mode,
    pub(super) gyroscopic: Mode,
}

/// Brent iterations allowed in the one-dimensional cases.
pub(super) const MAX_BRENT_ITERATIONS: u32 = 200;

/// The one-dimensional load balance: `force` is negative (or zero) at 0 and turns positive as the
/// ring is pushed in; `hi` is doubled (at most 200 times) until it does, then Brent's method
/// finds the root. `method` names the solve in its report and in a not-converged answer.
pub(super) fn load_balance_root(
    mut force: impl FnMut(f64) -> f64,
    hi: f64,
    method: &'static str,
    budget: &Budget,
) -> Result<Root, CalcError> {
    let hi = grow_bracket(&mut force, hi)
        .map_err(|_| CalcError::Internal(format!("{method}: no bracket")))?;
    if !budget.alive() {
        return Err(CalcError::DeadlineExceeded);
    }
    let stop = Stopping {
        x_tolerance: 0.0,
        max_iterations: MAX_BRENT_ITERATIONS,
    };
    let mut root = brent(force, 0.0, hi, stop).map_err(|e| CalcError::from_root(method, e))?;
    root.report = root.report.named(method);
    Ok(root)
}

/// A root whose force balance, `residual` (relative to the load scale), is still above
/// `tolerance`: the balance stalled there (Brent closed its bracket on a force that round-off
/// keeps from balancing). The report is the root's, with that residual.
pub(super) fn balanced(
    root: &Root,
    residual: f64,
    tolerance: f64,
) -> Result<SolverReport, Stopped> {
    let report = root.report.clone().with_residual(residual);
    if residual > tolerance {
        return Err(Stopped::stalled(report));
    }
    Ok(report)
}

/// ℜ = d_m/2 + (f_i − ½)D cos α_f, m: the radius of the inner groove curvature centres, the
/// lever arm of the balls' axial forces about the tilt axis (Harris).
pub(super) fn tilt_arm(b: &BallBearing) -> f64 {
    0.5 * b.pitch_diameter_m
        + (b.inner_conformity - 0.5) * b.ball_diameter_m * b.free_contact_angle().cos()
}

/// The solved equilibrium, whichever solver found it.
pub(super) struct Equilibrium {
    pub(super) balls: Vec<BallState>,
    /// δ_r, δ_a (report convention), θ.
    pub(super) displacement: [f64; 3],
    pub(super) load_zone_factor: Option<f64>,
    pub(super) half_angle: f64,
    pub(super) report: SolverReport,
    pub(super) centrifugal_n: Option<f64>,
    pub(super) gyroscopic: bool,
}

/// The ball model at speed: F_c on every ball, the gyroscopic inputs, each contact's stiffness.
pub(super) struct SpeedModel {
    pub(super) centrifugal_n: f64,
    pub(super) gyro: Option<Gyro>,
    pub(super) k_i: f64,
    pub(super) k_o: f64,
}

/// The load scale: |F|, |M|/ℜ, or the preload Z Q₀, N.
pub(super) fn load_scale(case: &LoadDistributionCase, k_n: f64) -> f64 {
    let b = &case.bearing;
    let preload = b.ball_count as f64 * k_n * b.interference_m().powf(1.5);
    case.radial_load_n
        .hypot(case.axial_load_n)
        .max(case.moment_n_m.unwrap_or(0.0).abs() / tilt_arm(b))
        .max(preload)
}

/// The classic two-unknown equilibrium (ring held square, no speed effects).
pub(super) fn classic(
    case: &LoadDistributionCase,
    k_n: f64,
    ctx: &mut Context,
) -> Result<Equilibrium, CalcError> {
    let rings = Rings::new(case, k_n);
    rings.check_existence(case)?;
    let (u, report) = rings.equilibrium(&ctx.budget())?;
    rings.check_geometry(u)?;
    let (d0, d_pi) = (
        rings.signed_deflection(u, 1.0),
        rings.signed_deflection(u, -1.0),
    );
    Ok(Equilibrium {
        balls: rings
            .balls(u)
            .into_iter()
            .map(|b| BallState {
                inner_load: b.load,
                inner_angle: b.angle,
                outer_load: b.load,
                outer_angle: b.angle,
                friction_n: 0.0,
            })
            .collect(),
        displacement: [u[0], rings.axial_displacement(u), 0.0],
        load_zone_factor: (u[0] > 0.0 && d0 > d_pi).then(|| d0 / (d0 - d_pi)),
        half_angle: rings.load_zone_half_angle(u),
        report,
        centrifugal_n: None,
        gyroscopic: false,
    })
}

/// The general equilibrium: free tilt and/or every ball's own position at speed.
pub(super) fn general(
    case: &LoadDistributionCase,
    k_n: f64,
    speed: Option<SpeedModel>,
    ctx: &mut Context,
) -> Result<Equilibrium, CalcError> {
    let b = &case.bearing;
    let alpha_f = b.free_contact_angle();
    let arm = tilt_arm(b);
    let moment = case.moment_n_m.unwrap_or(0.0);
    let balls = match &speed {
        Some(s) => Balls::Free {
            k_i: s.k_i,
            k_o: s.k_o,
            centrifugal_n: s.centrifugal_n,
            gyro: s.gyro,
        },
        None => Balls::Series {
            k_n,
            law: match case.mode {
                AngleMode::Varying => SeriesLaw::Varying,
                AngleMode::Fixed => {
                    // Only reached without a moment (refused at the door) and without the
                    // speed effects (which need varying angles).
                    let (sin, cos) = alpha_f.sin_cos();
                    SeriesLaw::Fixed { sin, cos }
                }
            },
        },
    };
    let z = b.ball_count;
    let scale = load_scale(case, k_n).max(speed.as_ref().map_or(0.0, |s| s.centrifugal_n));
    let problem = Problem {
        ball_diameter_m: b.ball_diameter_m,
        pitch_diameter_m: b.pitch_diameter_m,
        bd: b.curvature_centre_distance_m,
        r0: b.radial_centre_offset_m,
        a0: b.axial_centre_offset_m(),
        arm,
        inner_offset: (b.inner_conformity - 0.5) * b.ball_diameter_m,
        outer_offset: (b.outer_conformity - 0.5) * b.ball_diameter_m,
        cosines: (0..z)
            .map(|j| (std::f64::consts::TAU * j as f64 / z as f64).cos())
            .collect(),
        balls,
        tilt_free: case.moment_n_m.is_some(),
        load: [case.radial_load_n, case.axial_load_n, moment],
        scale,
        delta_scale: (scale / (z as f64 * k_n)).powf(2.0 / 3.0),
    };
    let solution = problem.solve(&ctx.budget())?;
    let d = solution.displacement;
    if matches!(case.mode, AngleMode::Varying) && d[0] >= b.radial_centre_offset_m {
        return Err(CalcError::impossible(
            "/radial_load_n",
            format!(
                "the radial displacement {:.4e} m would carry the raceway curvature centres past each other (r₀ = {:.4e} m): a load this large is far beyond the bearing's static capacity and the rigid-ring Hertz model",
                d[0], b.radial_centre_offset_m
            ),
        ));
    }
    if speed.as_ref().is_some_and(|s| s.gyro.is_some()) {
        if let Some((j, ball)) = solution.balls.iter().enumerate().find(|(_, ball)| {
            ball.outer_load > 0.0 && ball.friction_n.abs() > TRACTION_LIMIT * ball.outer_load
        }) {
            ctx.warn(
                "gyroscopic_spin_likely",
                format!(
                    "ball {j} needs a friction force {:.4e} N at its outer contact to hold its gyroscopic moment, more than {TRACTION_LIMIT} of its load {:.4e} N: the ball will spin (pivot) there, which outer-race control does not describe",
                    ball.friction_n.abs(),
                    ball.outer_load
                ),
            );
        }
    }
    let (d0, d_pi) = (
        problem.signed_deflection(d, 1.0),
        problem.signed_deflection(d, -1.0),
    );
    Ok(Equilibrium {
        half_angle: problem.load_zone_half_angle(d),
        load_zone_factor: (d[0] > 0.0 && d0 > d_pi).then(|| d0 / (d0 - d_pi)),
        displacement: d,
        centrifugal_n: speed.as_ref().map(|s| s.centrifugal_n),
        gyroscopic: speed.as_ref().is_some_and(|s| s.gyro.is_some()),
        balls: solution.balls,
        report: solution.report,
    })
}

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
            AngleMode::Varying => Law::Varying { r0 },
            AngleMode::Fixed => {
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
    fn equilibrium(&self, budget: &Budget) -> Result<([f64; 2], SolverReport), CalcError> {
        let [f_r, f_a] = self.load;
        let axial_symmetric = match self.law {
            Law::Varying { .. } => true,
            Law::Fixed { sin, .. } => sin == 0.0,
        };
        if f_r == 0.0 && f_a == 0.0 {
            // A preloaded bearing at rest: the concentric position, every ball equally loaded.
            let u = [0.0, 0.0];
            let at_rest = Driver::new("symmetric", IterationUnit::None, 0, budget)
                .converged_at_start(u, self.residual(self.local(u).gradient));
            return Ok((u, at_rest.report));
        }
        // u_a = 0: contact angles 0 (varying) or δ_a = 0 (fixed), the symmetric position.
        if f_r == 0.0 {
            return self.one_dimensional(1, budget);
        }
        if f_a == 0.0 && axial_symmetric {
            return self.one_dimensional(0, budget);
        }
        self.newton(budget)
    }

    /// Brent's method on one component of the force balance along axis k, the other unknown
    /// held at 0 where symmetry puts it. The force along k grows monotonically with u_k
    /// (convex energy), from about −F_k at u_k = 0 (the symmetric ring carries no net force).
    fn one_dimensional(
        &self,
        k: usize,
        budget: &Budget,
    ) -> Result<([f64; 2], SolverReport), CalcError> {
        const METHOD: &str = "brent_ball_load_balance";
        let at = |x: f64| {
            let mut u = [0.0, 0.0];
            u[k] = x;
            u
        };
        let force = |x: f64| self.local(at(x)).gradient[k];
        let at_rest = self.residual(self.local(at(0.0)).gradient);
        if force(0.0) >= 0.0 && at_rest <= TOLERANCE {
            // A load below round-off of a heavy preload.
            let done = Driver::new(
                METHOD,
                IterationUnit::RootSearchSteps,
                MAX_BRENT_ITERATIONS,
                budget,
            )
            .converged_at_start(at(0.0), at_rest);
            return Ok((done.value, done.report));
        }
        // Past the clearance (or the end play), then doubled until the balls carry the load.
        let hi = self.a0 + self.bd + self.delta_scale;
        let root = load_balance_root(force, hi, METHOD, budget)?;
        let u = at(root.x);
        let report = balanced(&root, self.residual(self.local(u).gradient), TOLERANCE)?;
        Ok((u, report))
    }

    /// Safeguarded Newton on Π ([`Energy`]): analytic Hessian, Levenberg shift when it is
    /// singular, a gradient step where no ball is loaded, Armijo backtracking on Π.
    fn newton(&self, budget: &Budget) -> Result<([f64; 2], SolverReport), CalcError> {
        // Start with the ring pushed along the load by twice the characteristic deflection
        // from the position where the unloaded balls touch.
        let f = self.load[0].hypot(self.load[1]);
        let push = 2.0 * self.delta_scale;
        let start = match self.law {
            Law::Varying { .. } => [push * self.load[0] / f, self.a0 + push * self.load[1] / f],
            Law::Fixed { .. } => [push * self.load[0] / f, push * self.load[1] / f],
        };
        let driver = Driver::new(
            "newton_energy_line_search",
            IterationUnit::NewtonSteps,
            MAX_ITERATIONS,
            budget,
        )
        .check_every(8);
        let line = LineSearch {
            max_halvings: MAX_HALVINGS,
            take_shortest: false,
        };
        let run = newton::solve(
            &Energy { rings: self, push },
            start,
            TOLERANCE,
            line,
            &driver,
        )?;
        Ok((run.value.0, run.report))
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

/// The ring system's elastic energy Π for [`newton::solve`]: the unknowns u, Π with its
/// gradient and Hessian ([`Local`]), the residual |∇Π|/scale.
struct Energy<'a> {
    rings: &'a Rings,
    /// The length of a gradient step where no ball is loaded (twice the characteristic
    /// deflection), m.
    push: f64,
}

impl NewtonSystem for Energy<'_> {
    type Point = [f64; 2];
    type Eval = Local;
    type Step = [f64; 2];

    fn evaluate(&self, u: &[f64; 2]) -> Local {
        self.rings.local(*u)
    }

    fn residual(&self, at: &Local) -> f64 {
        self.rings.residual(at.gradient)
    }

    /// The Newton step on the Hessian with a 10⁻¹² Levenberg shift of its trace; where no ball
    /// is loaded (a zero Hessian), a gradient step of length `push`.
    fn direction(&self, _u: &[f64; 2], at: &Local) -> Option<[f64; 2]> {
        let g = at.gradient;
        let [h_rr, h_ra, h_aa] = at.hessian;
        let trace = h_rr + h_aa;
        if trace > 0.0 {
            let shift = 1e-12 * trace;
            let (a, b, c) = (h_rr + shift, h_ra, h_aa + shift);
            dense::solve([[a, b], [b, c]], [-g[0], -g[1]])
        } else {
            let norm = g[0].hypot(g[1]);
            Some([-g[0] / norm * self.push, -g[1] / norm * self.push])
        }
    }

    fn slope(&self, at: &Local, step: &[f64; 2]) -> Option<f64> {
        Some(at.gradient[0] * step[0] + at.gradient[1] * step[1])
    }

    fn advance(&self, u: &[f64; 2], step: &[f64; 2], t: f64) -> [f64; 2] {
        [u[0] + t * step[0], u[1] + t * step[1]]
    }

    /// Armijo on Π; near the minimum Π's decrease (∝ residual²) sinks below its round-off, and
    /// a step that shrinks the force residual is taken instead.
    fn accepts(&self, here: &Local, trial: &Local, t: f64, slope: Option<f64>) -> bool {
        armijo(here.energy, trial.energy, t, slope.unwrap_or(f64::NAN))
            || residual_falls(self.residual(here), self.residual(trial), t)
    }
}
