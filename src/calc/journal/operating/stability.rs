//! Stiffness and damping at the operating point and the whirl threshold along the equilibrium
//! locus (Lund's rigid-rotor analysis, Jeffcott shaft by Hori's threshold).

use std::f64::consts::PI;

use super::{Case, Notes, Operating, RotorStability, GRAVITY};
use crate::calc::journal::dynamics::{self, Coefficients};
use crate::calc::journal::eccentricity::EccentricityRatio;
use crate::calc::journal::film::FilmModel;
use crate::calc::journal::performance::{self, FilmStart, Method, MAX_ECCENTRICITY};
use crate::calc::journal::threshold;
use crate::calc::{Budget, CalcError};
use crate::fidelity::{IterationUnit, StopReason};
use crate::numerics::driver::{Driver, Verdict};
use crate::numerics::roots::{brent, Stopping};

/// Coefficients at ε for the case's method (None for the long closed form), and S there
/// (`threshold::coefficients`, shared with the `/whirl` room).
pub(super) fn coefficients_at(
    case: &Case,
    method: Method,
    eccentricity: EccentricityRatio,
    physics: FilmModel,
    field: &mut FilmStart,
    budget: &Budget,
) -> Result<Option<Coefficients>, CalcError> {
    threshold::coefficients(
        method,
        eccentricity,
        case.geometry.l_over_d(),
        physics,
        field,
        budget,
    )
}

/// A point of the locus walk or the threshold search as an eccentricity ratio (they stay
/// within [10⁻³, MAX_ECCENTRICITY]).
fn ratio(e: f64) -> Result<EccentricityRatio, CalcError> {
    EccentricityRatio::new(e).ok_or_else(|| CalcError::Internal(format!("stability: ε = {e}")))
}

pub(super) fn dynamic_coefficients(
    case: &Case,
    op: &Operating,
    budget: &Budget,
    notes: &mut Notes,
) -> Result<Option<(Coefficients, RotorStability)>, CalcError> {
    if !case.cavitation() {
        notes.warn(
            "no_dynamics_full_film",
            "stiffness and damping are given for the cavitating film only",
        );
        return Ok(None);
    }
    let eccentricity = op.point.eccentricity_ratio;
    let eps = eccentricity.get();
    let physics = case.physics(op.temperature_c);
    let mut field = FilmStart {
        field: op.point.field.clone(),
        attitude: Some(op.point.attitude_angle),
    };
    let Some(coefficients) =
        coefficients_at(case, case.method, eccentricity, physics, &mut field, budget)?
    else {
        notes.warn("no_dynamics_long_bearing", "the long-bearing closed form has no dynamic coefficients here; use the short form or a numerical fidelity");
        return Ok(None);
    };
    let g = case.geometry;
    let w = op.load_n;
    // Per half-bearing with a circumferential groove: half the rotor on half the load.
    let mass = case
        .rotor_mass_kg
        .map_or(w / GRAVITY, |m| m / case.halves());
    let omega = 2.0 * PI * case.speed_rps();
    let s_op = coefficients.sommerfeld_number;
    let mass_parameter = |omega: f64| mass * g.radial_clearance_m * omega * omega / w;
    // γ = W/(k_s C) with the whole bearing's load and shaft (per half-bearing with a
    // circumferential groove both halve: the same γ).
    let flexibility = case
        .shaft_stiffness_n_m
        .map_or(0.0, |k| case.halves() * w / (k * g.radial_clearance_m));
    let whirl = dynamics::whirl_on_shaft(&coefficients, flexibility);
    let stable_now = whirl
        .critical_mass_parameter
        .is_none_or(|mc| mass_parameter(omega) < mc);

    // Threshold: along the equilibrium locus at fixed load and viscosity, speed is ω(ε) =
    // ω_op S(ε)/S_op; stability margin ln(m̄_c/m̄) changes sign at the threshold.
    // The threshold search walks the locus on the `fast` mesh (a few per cent on the
    // threshold speed, a fraction of the cost); S_op is taken on the same mesh.
    let search = match case.method {
        Method::Numerical { level, stop, .. } => {
            Method::numerical(crate::fidelity::Level::Fast, None, None).with_stop(stop, level)
        }
        m => m,
    };
    // S_op on the search mesh: one film solve, not a set of perturbations (none when the
    // coefficients were taken on that mesh).
    let s_op = match (search, case.method) {
        (Method::Numerical { mesh, .. }, Method::Numerical { mesh: own, .. }) if mesh == own => {
            s_op
        }
        (Method::Numerical { mesh, stop, .. }, _) => {
            let ld = case.geometry.l_over_d();
            let (_, film, _) = performance::positioned_film(
                eccentricity,
                ld,
                physics,
                mesh,
                stop,
                FilmStart {
                    field: None,
                    attitude: Some(op.point.attitude_angle),
                },
                budget,
            )?;
            film.sommerfeld_number()
        }
        _ => s_op,
    };
    // Along the locus the speed changes, and with it a turbulent film's Reynolds number
    // (Re ∝ speed at fixed viscosity): the film at ε has Re = Re_op S(ε; Re)/S_op, a fixed point
    // found from single film solves (S changes little with Re, so it settles in a few steps)
    // before the coefficients are taken there. The turbulence decision itself stays the
    // operating point's (the Ng–Pan factors tend to laminar as Re falls).
    let locus_physics = |e: f64| -> Result<FilmModel, CalcError> {
        let (Some(re_op), Method::Numerical { mesh, stop, .. }) =
            (physics.turbulence_reynolds, search)
        else {
            return Ok(physics);
        };
        let ld = case.geometry.l_over_d();
        let e = ratio(e)?;
        let mut re = re_op;
        let mut failure = None;
        // 10⁻⁴ in Re moves the Ng–Pan factors by far less than the mesh error; a contraction
        // this mild settles in three or four solves, and twelve bound the cost (the last Re is
        // taken at the cap). One iteration: one film solve.
        let run = Driver::new(
            "fixed_point_reynolds_number",
            IterationUnit::Evaluations,
            12,
            budget,
        )
        .run(|_| {
            let with = FilmModel {
                turbulence_reynolds: Some(re),
                ..physics
            };
            match performance::positioned_film(
                e,
                ld,
                with,
                mesh,
                stop,
                FilmStart::default(),
                budget,
            ) {
                Ok((_, film, _)) => {
                    let next = re_op * film.sommerfeld_number() / s_op;
                    let change = (next / re - 1.0).abs();
                    re = next;
                    if change < 1e-4 {
                        Verdict::Converged((), change)
                    } else {
                        Verdict::Continue(change)
                    }
                }
                Err(err) => {
                    failure = Some(err);
                    Verdict::Diverged(f64::NAN)
                }
            }
        });
        if let Some(err) = failure {
            return Err(err);
        }
        match run {
            Err(stopped) if stopped.reason() != StopReason::IterationCap => {
                return Err(stopped.into())
            }
            _ => {}
        }
        Ok(FilmModel {
            turbulence_reynolds: Some(re),
            ..physics
        })
    };
    let failure = std::cell::RefCell::new(None);
    // Each point of the locus starts from the field of the last, and a placed film from the
    // last attitude moved as the short bearing's moves between the two ε (the first from the
    // operating point's).
    let mut locus_field = FilmStart {
        field: None,
        attitude: Some(op.point.attitude_angle),
    };
    let mut last_eps = eps;
    // S at each ε the margin was taken at: the threshold's speed is read from the last.
    let mut locus: Vec<(f64, f64)> = Vec::new();
    let mut margin = |e: f64| -> f64 {
        let ld = case.geometry.l_over_d();
        locus_field.attitude = locus_field
            .attitude
            .map(|phi| performance::shifted_attitude(phi, last_eps, e, ld));
        last_eps = e;
        match locus_physics(e)
            .and_then(|ph| coefficients_at(case, search, ratio(e)?, ph, &mut locus_field, budget))
        {
            Ok(Some(c)) => {
                locus.push((e, c.sommerfeld_number));
                let speed = omega * c.sommerfeld_number / s_op;
                match dynamics::whirl_on_shaft(&c, flexibility).critical_mass_parameter {
                    Some(mc) => (mc / mass_parameter(speed)).ln(),
                    None => 50.0,
                }
            }
            Ok(None) => 50.0,
            // Lighter than this a ported supply outweighs the film: the locus ends here.
            Err(CalcError::Impossible { pointer, .. })
                if pointer == performance::SUPPLY_DOMINATES =>
            {
                f64::NAN
            }
            Err(err) => {
                failure.borrow_mut().get_or_insert(err);
                f64::NAN
            }
        }
    };
    let m0 = if stable_now { 1.0 } else { -1.0 };
    let mut lightest = eps;
    // First, secant steps in ln ε from the short bearing's threshold (its slope for the first
    // step); they must land on the side of the operating point the threshold lies on.
    let seed = threshold::short_bearing_threshold(case.geometry.l_over_d(), eps, |e, s_ratio| {
        let critical = threshold::short_bearing_critical_mass(e, flexibility)
            .map_or(f64::INFINITY, |m| m.max(1e-300));
        mass_parameter(omega * s_ratio) / critical
    });
    let seeded = match seed {
        Some(start) => threshold::secant_threshold(&mut margin, start, budget)?.filter(|&e| {
            if stable_now {
                e < eps
            } else {
                e > eps
            }
        }),
        None => None,
    };
    let threshold_eps = match seeded {
        Some(e) => Some(e),
        None => {
            // Walk the locus towards lighter (stable now) or heavier loads, ε shrinking or
            // growing by 0.6 each step, until the margin changes sign: the bracket of the
            // threshold. One iteration: one margin (a set of coefficients); the walk ends
            // without a bracket where the locus does (ε = 10⁻³ or MAX_ECCENTRICITY, or a
            // margin that cannot be taken), or after ten steps.
            let mut previous = eps;
            let mut k = 0;
            let walk =
                Driver::new("locus_walk", IterationUnit::Evaluations, 10, budget).run(|_| {
                    k += 1;
                    let next = if stable_now {
                        (eps * 0.6f64.powi(k)).max(1e-3)
                    } else {
                        (1.0 - (1.0 - eps) * 0.6f64.powi(k)).min(MAX_ECCENTRICITY)
                    };
                    let width = (next - previous).abs();
                    let m = margin(next);
                    if m.is_nan() {
                        return Verdict::Converged(None, width);
                    }
                    lightest = lightest.min(next);
                    if m.signum() != m0 {
                        return Verdict::Converged(Some((previous, next)), width);
                    }
                    previous = next;
                    if next <= 1e-3 || next >= MAX_ECCENTRICITY {
                        return Verdict::Converged(None, width);
                    }
                    Verdict::Continue(width)
                });
            if let Some(e) = failure.borrow_mut().take() {
                return Err(e);
            }
            let bracket = match walk {
                Ok(found) => found.value,
                Err(stopped) if stopped.reason() == StopReason::IterationCap => None,
                Err(stopped) => return Err(stopped.into()),
            };
            match bracket {
                Some((a, b)) => brent(
                    &mut margin,
                    a.min(b),
                    a.max(b),
                    Stopping {
                        x_tolerance: 1e-3,
                        max_iterations: 40,
                    },
                )
                .ok()
                .map(|r| r.x),
                None => None,
            }
        }
    };
    if let Some(e) = failure.into_inner() {
        return Err(e);
    }
    let threshold_rpm = match threshold_eps {
        Some(e) => {
            let s = match locus.iter().rev().find(|(at, _)| *at == e) {
                Some(&(_, s)) => s,
                None => coefficients_at(
                    case,
                    search,
                    ratio(e)?,
                    locus_physics(e)?,
                    &mut locus_field,
                    budget,
                )?
                .map_or(f64::NAN, |c| c.sommerfeld_number),
            };
            Some(case.speed_rpm * s / s_op).filter(|v| v.is_finite())
        }
        None => None,
    };
    let statement = match (stable_now, threshold_rpm) {
        (true, Some(t)) => format!("stable at {:.0} rev/min; oil whirl sets in at about {t:.0} rev/min (rigid rotor of {mass:.3} kg, load and viscosity held)", case.speed_rpm),
        (true, None) if whirl.critical_mass_parameter.is_none() => format!("stable at every speed: at ε = {eps:.3} the film cannot sustain whirl for any rotor mass"),
        (true, None) => format!("stable at {:.0} rev/min and at every speed up to the lightest load solved (ε = {lightest:.4})", case.speed_rpm),
        (false, Some(t)) => format!("UNSTABLE: oil whirl above about {t:.0} rev/min, below the operating speed {:.0} rev/min", case.speed_rpm),
        (false, None) => format!("UNSTABLE at {:.0} rev/min, and no stable speed was found down to ε = {MAX_ECCENTRICITY}", case.speed_rpm),
    };
    if !stable_now {
        notes.warn("oil_whirl", statement.clone());
    }
    let stability = RotorStability {
        stable_at_operating_speed: stable_now,
        threshold_speed_rpm: threshold_rpm,
        whirl_frequency_ratio: whirl.whirl_frequency_ratio,
        critical_mass_parameter: whirl.critical_mass_parameter,
        critical_speed_rad_s: whirl
            .critical_mass_parameter
            .map(|mc| (mc * w / (mass * g.radial_clearance_m)).sqrt()),
        critical_speed_nd: whirl
            .critical_mass_parameter
            .map(|mc| (mc * w / (mass * GRAVITY)).sqrt()),
        mass_parameter: mass_parameter(omega),
        rotor_mass_kg: mass * case.halves(),
        statement,
    };
    Ok(Some((coefficients, stability)))
}
