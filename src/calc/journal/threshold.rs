//! The whirl threshold of a rigid rotor on a plain 360° journal bearing: the `/whirl` room's
//! model, and the pieces of the threshold search along the equilibrium locus that `/plain`'s
//! stability block shares with it.
//!
//! **Rotor.** A rigid rotor of mass m on this bearing, displaced by small x about the static
//! equilibrium: m ẍ + C ẋ + K x = 0 (x along the static load, y 90° ahead of it in the direction
//! of rotation; the film force on the journal is f = −K x − C ẋ). In τ = ωt and x/C:
//! M̄ x″ + c x′ + k x = 0 with k = K C/W, c = C C ω/W and the mass parameter M̄ = m C ω²/W. Its
//! threshold is where the quartic det(M̄ s² + c s + k) has a pair of roots on the imaginary axis:
//! Routh–Hurwitz's Δ₃ = 0, which is Lund's critical mass parameter M̄_c = k_eq/γ² with the whirl
//! frequency ratio γ (`dynamics::whirl`, `dynamics::routh_hurwitz_stable`); the tests check it
//! against the eigenvalues of the 4×4 system.
//!
//! **Film models.** Coefficients by the model the request names:
//! - `short_pi_film`: the short (Ocvirk) bearing, pressure kept where the wedge-and-squeeze drive
//!   is positive — the π film whose ends move with the squeeze velocity;
//! - `short_fixed_arc`: the short bearing with pressure kept on the fixed arc [0, π] from h_max.
//!   The two have the **same** linearised coefficients (and the same S): at equilibrium the
//!   drive, and with it the integrand, vanishes at both ends of the arc, so the ends' motion
//!   is second order (`closed_form` tests differentiate both films). They differ only in the
//!   nonlinear orbit (the `/dynamic` room).
//! - `short_full`: the full (Sommerfeld) short film, negative pressures kept. Its direct
//!   stiffnesses vanish (`closed_form::short_full_sommerfeld_dynamic_coefficients`), so k_eq = 0
//!   and the massless rotor already whirls at exactly half speed: **no rotor mass is stable at
//!   any speed**. The room answers 200 with the threshold at 0 (`threshold_mass_kg` 0,
//!   `threshold_speed_rpm` 0), `stable: false` where a verdict is asked, and the warning
//!   `whirls_at_every_speed`: the request is valid and the answer is definite — an engineer
//!   asking about a film that cannot rupture (a submerged bearing) wants that answer, not an
//!   error.
//! - `finite`: the journal room's Reynolds solver with the Reynolds (Swift–Stieber) cavitation
//!   condition, coefficients by perturbation of the converged film (`dynamics::perturbation`),
//!   on the fidelity's mesh.
//!
//! **Given a speed**, the equilibrium ε comes from the load (S = μ N_s L D (R/C)²/W,
//! `performance::equilibrium`), the coefficients from ε, and the threshold mass directly:
//! m_c = M̄_c W/(C ω²). **Given a mass**, the threshold speed is where the rotor's M̄ meets M̄_c
//! along the equilibrium locus at fixed load and viscosity. Speed and ε are one-to-one there
//! (N_s = S(ε) W/(μ L D (R/C)²), S falling monotonically with ε), so the root search runs in
//! x = ln ε rather than in speed: each step then costs one set of coefficients, not an
//! equilibrium search and a set of coefficients. The margin ln(M̄_c/M̄) changes sign at the
//! threshold; closed forms take Brent over the whole locus, the finite film secant steps from
//! the short bearing's root and a scan and Brent where they do not settle.

use std::cell::RefCell;
use std::f64::consts::PI;

use super::closed_form::{self, Boundary};
use super::dynamics::{self, Coefficients, Whirl};
use super::eccentricity::EccentricityRatio;
use super::film::FilmModel;
use super::performance::{
    self, Approximation, FilmStart, Method, MAX_ECCENTRICITY, MIN_ECCENTRICITY,
};
use crate::calc::{Budget, CalcError};
use crate::fidelity::{IterationUnit, Level, SolverReport, StopReason};
use crate::numerics::driver::{Driver, Verdict};
use crate::numerics::roots::{brent, brent_bracketed, Stopping};

/// Coefficients at ε for `method` (None for the long closed form, which has none here), with S
/// there. A short closed form takes the half-Sommerfeld film when `physics` cavitates, the
/// full film otherwise; a numerical method perturbs the converged film (`field`: the film's
/// field on the method's mesh, where the solve starts, and which it leaves there).
pub fn coefficients(
    method: Method,
    eccentricity: EccentricityRatio,
    l_over_d: f64,
    physics: FilmModel,
    field: &mut FilmStart,
    budget: &Budget,
) -> Result<Option<Coefficients>, CalcError> {
    let eps = eccentricity.get();
    match method {
        Method::ClosedForm(Approximation::Short) => {
            // The short bearing's cavitated film is the half-Sommerfeld one.
            let (boundary, (stiffness, damping)) = if physics.cavitation || physics.half_sommerfeld
            {
                (
                    Boundary::HalfSommerfeld,
                    closed_form::short_bearing_dynamic_coefficients(eps),
                )
            } else {
                (
                    Boundary::FullSommerfeld,
                    closed_form::short_full_sommerfeld_dynamic_coefficients(eps),
                )
            };
            let s = closed_form::short_bearing(eps, l_over_d, boundary)
                .map_or(f64::NAN, |p| p.sommerfeld_number);
            Ok(Some(Coefficients {
                stiffness,
                damping,
                sommerfeld_number: s,
            }))
        }
        Method::ClosedForm(Approximation::Long) => Ok(None),
        Method::Numerical { mesh, stop, .. } => {
            dynamics::perturbation(eccentricity, l_over_d, physics, mesh, stop, field, budget)
                .map(Some)
        }
    }
}

/// The short (π-film) bearing's critical mass parameter at ε from its closed-form
/// coefficients, with a shaft of flexibility γ in series; None when its film cannot whirl.
pub(crate) fn short_bearing_critical_mass(eps: f64, flexibility: f64) -> Option<f64> {
    let (stiffness, damping) = closed_form::short_bearing_dynamic_coefficients(eps);
    let c = Coefficients {
        stiffness,
        damping,
        sommerfeld_number: f64::NAN,
    };
    dynamics::whirl_on_shaft(&c, flexibility).critical_mass_parameter
}

/// Where the short bearing's locus crosses its threshold — ln ε, and the slope of its margin
/// ln(m̄_c/m̄) in ln ε there — from `ratio(ε, S(ε)/S(ε_ref))` = m̄/m̄_c (closed forms only,
/// microseconds); None when it does not cross between 10⁻³ and MAX_ECCENTRICITY.
pub(crate) fn short_bearing_threshold(
    l_over_d: f64,
    eps_ref: f64,
    ratio: impl Fn(f64, f64) -> f64,
) -> Option<(f64, f64)> {
    let s = |e: f64| {
        closed_form::short_bearing(e, l_over_d, Boundary::HalfSommerfeld)
            .map_or(f64::NAN, |p| p.sommerfeld_number)
    };
    let s_ref = s(eps_ref);
    let margin = |x: f64| {
        let e = x.exp();
        (-ratio(e, s(e) / s_ref).ln()).clamp(-50.0, 50.0)
    };
    let root = brent(
        margin,
        1e-3f64.ln(),
        MAX_ECCENTRICITY.ln(),
        Stopping {
            x_tolerance: 1e-4,
            max_iterations: 100,
        },
    )
    .ok()?;
    let h = 1e-3;
    let slope = (margin(root.x + h) - margin(root.x - h)) / (2.0 * h);
    slope.is_finite().then_some((root.x, slope))
}

/// Secant steps on the margin in x = ln ε from `(x, slope)` until the next step is below
/// 10⁻³ (ε to 0.1 %): the threshold ε, or None when the steps leave the locus or do not settle
/// in eight (the caller then brackets the root another way).
pub(crate) fn secant_threshold(
    margin: &mut impl FnMut(f64) -> f64,
    (x0, slope0): (f64, f64),
    budget: &Budget,
) -> Result<Option<f64>, CalcError> {
    let bounds = (1e-3f64.ln(), MAX_ECCENTRICITY.ln());
    let (mut xa, mut ma) = (x0, margin(x0.exp()));
    let mut xb = (xa - ma / slope0).clamp(bounds.0, bounds.1);
    let mut mb = margin(xb.exp());
    let run = Driver::new(
        "secant_whirl_threshold",
        IterationUnit::RootSearchSteps,
        8,
        budget,
    )
    .run(|_| {
        let slope = (mb - ma) / (xb - xa);
        if !(ma.is_finite() && mb.is_finite() && slope.is_finite() && slope != 0.0) {
            return Verdict::Stalled(f64::NAN);
        }
        let step = -mb / slope;
        if step.abs() < 1e-3 {
            return Verdict::Converged(xb, step.abs());
        }
        (xa, ma) = (xb, mb);
        xb = (xb + step).clamp(bounds.0, bounds.1);
        if xb == xa {
            return Verdict::Stalled(step.abs());
        }
        mb = margin(xb.exp());
        Verdict::Continue(step.abs())
    });
    match run {
        Ok(found) => Ok(Some(found.value.exp())),
        Err(stopped) if stopped.reason() == StopReason::Deadline => Err(stopped.into()),
        Err(_) => Ok(None),
    }
}

/// The film model of a whirl analysis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum WhirlFilm {
    /// Short bearing, half-Sommerfeld film on the moving π arc.
    ShortPiFilm,
    /// Short bearing, half-Sommerfeld film on the fixed arc [0, π] from h_max.
    ShortFixedArc,
    /// Short bearing, full Sommerfeld film (no cavitation).
    ShortFull,
    /// The finite bearing's Reynolds film with cavitation, by this numerical method.
    Finite(Method),
}

impl WhirlFilm {
    pub fn method(self) -> Method {
        match self {
            WhirlFilm::Finite(m) => m,
            _ => Method::ClosedForm(Approximation::Short),
        }
    }

    pub fn physics(self) -> FilmModel {
        FilmModel {
            cavitation: self != WhirlFilm::ShortFull,
            ..FilmModel::REYNOLDS
        }
    }

    /// The lightest ε the model's locus is followed to: the closed forms hold to
    /// [`MIN_ECCENTRICITY`], the perturbed film is taken from 10⁻³ (as `/plain` does).
    fn lightest(self) -> f64 {
        match self {
            WhirlFilm::Finite(_) => 1e-3,
            _ => MIN_ECCENTRICITY,
        }
    }
}

/// A rigid rotor on one plain bearing under a steady load, isoviscous.
#[derive(Debug, Clone, Copy)]
pub struct Rotor {
    pub diameter_m: f64,
    pub length_m: f64,
    pub radial_clearance_m: f64,
    pub viscosity_pa_s: f64,
    /// The static load on this bearing, N.
    pub load_n: f64,
    pub film: WhirlFilm,
}

/// The film at one point of the equilibrium locus.
#[derive(Debug, Clone, Copy)]
pub struct FilmState {
    pub eccentricity_ratio: f64,
    /// φ from the load line to the line of centres, rad (at a solved equilibrium only).
    pub attitude_angle_rad: Option<f64>,
    /// The speed the load and viscosity put the journal at this ε, rev/min.
    pub speed_rpm: f64,
    pub coefficients: Coefficients,
    pub whirl: Whirl,
}

/// At a given speed.
#[derive(Debug, Clone, Copy)]
pub struct AtSpeed {
    pub state: FilmState,
    /// The rotor mass on this bearing at which it whirls at this speed, kg: M̄_c W/(C ω²);
    /// None: no mass whirls (M̄_c infinite); 0: every mass does.
    pub threshold_mass_kg: Option<f64>,
}

/// The speed at which a given mass starts to whirl.
#[derive(Debug, Clone, Copy)]
pub enum SpeedThreshold {
    /// Stable below `state.speed_rpm`, whirling above.
    Found(FilmState),
    /// The film whirls at every speed (k_eq = 0: the full film).
    EverySpeed,
    /// Stable at every speed the locus was followed to (up to this speed, rev/min, at its
    /// lightest ε).
    StableUpTo(f64),
    /// Whirling at every speed down to this one, rev/min (the heaviest ε solved).
    UnstableDownTo(f64),
}

/// The stability of one rotor at one speed, from the eigenvalues of its 4×4 system.
#[derive(Debug, Clone, Copy)]
pub struct RotorVerdict {
    pub stable: bool,
    /// Growth rate of the least damped mode, 1/s (negative: it decays).
    pub growth_rate_per_s: f64,
    /// Its frequency over the running speed.
    pub frequency_ratio: f64,
}

impl Rotor {
    pub fn l_over_d(&self) -> f64 {
        self.length_m / self.diameter_m
    }

    /// S at 1 rev/min: S = μ N_s L D (R/C)²/W is linear in the speed.
    pub fn sommerfeld_per_rpm(&self) -> f64 {
        let r_over_c = 0.5 * self.diameter_m / self.radial_clearance_m;
        self.viscosity_pa_s / 60.0 * self.length_m * self.diameter_m * r_over_c * r_over_c
            / self.load_n
    }

    fn omega(speed_rpm: f64) -> f64 {
        2.0 * PI * speed_rpm / 60.0
    }

    /// M̄ = m C ω²/W.
    pub fn mass_parameter(&self, mass_kg: f64, speed_rpm: f64) -> f64 {
        mass_kg * self.radial_clearance_m * Self::omega(speed_rpm).powi(2) / self.load_n
    }

    /// The mass whose M̄ at `speed_rpm` is `mass_parameter`, kg.
    pub fn mass_of(&self, mass_parameter: f64, speed_rpm: f64) -> f64 {
        mass_parameter * self.load_n / (self.radial_clearance_m * Self::omega(speed_rpm).powi(2))
    }

    /// K_ij = k_ij W/C (N/m) and C_ij = c_ij W/(C ω) (N·s/m) at `speed_rpm`.
    pub fn dimensional(&self, c: &Coefficients, speed_rpm: f64) -> ([f64; 4], [f64; 4]) {
        let (w, cl) = (self.load_n, self.radial_clearance_m);
        let omega = Self::omega(speed_rpm);
        (
            c.stiffness.map(|k| k * w / cl),
            c.damping.map(|d| d * w / (cl * omega)),
        )
    }

    fn state(&self, eps: f64, attitude: Option<f64>, c: Coefficients) -> FilmState {
        FilmState {
            eccentricity_ratio: eps,
            attitude_angle_rad: attitude,
            speed_rpm: c.sommerfeld_number / self.sommerfeld_per_rpm(),
            coefficients: c,
            whirl: dynamics::whirl(&c),
        }
    }

    fn coefficients_at(
        &self,
        eps: f64,
        field: &mut FilmStart,
        budget: &Budget,
    ) -> Result<Coefficients, CalcError> {
        let e = EccentricityRatio::new(eps)
            .ok_or_else(|| CalcError::Internal(format!("whirl: ε = {eps}")))?;
        coefficients(
            self.film.method(),
            e,
            self.l_over_d(),
            self.film.physics(),
            field,
            budget,
        )?
        .ok_or_else(|| CalcError::Internal("whirl: no coefficients for the long bearing".into()))
    }

    /// The equilibrium at `speed_rpm` and the threshold mass there, with the search's S
    /// evaluations.
    pub fn at_speed(&self, speed_rpm: f64, budget: &Budget) -> Result<(AtSpeed, u32), CalcError> {
        let s = speed_rpm * self.sommerfeld_per_rpm();
        let (point, evaluations) = performance::equilibrium(
            s,
            self.l_over_d(),
            self.film.method(),
            self.film.physics(),
            budget,
        )?;
        let eps = point.eccentricity_ratio.get();
        let mut field = FilmStart {
            field: point.field.clone(),
            attitude: Some(point.attitude_angle),
        };
        let mut c = self.coefficients_at(eps, &mut field, budget)?;
        // The equilibrium's S (extrapolated at `high`) puts the state at the speed asked.
        c.sommerfeld_number = s;
        let state = self.state(eps, Some(point.attitude_angle), c);
        let threshold_mass_kg = state
            .whirl
            .critical_mass_parameter
            .map(|mc| self.mass_of(mc, speed_rpm));
        Ok((
            AtSpeed {
                state,
                threshold_mass_kg,
            },
            evaluations,
        ))
    }

    /// The eigenvalue verdict for a rotor of `mass_kg` in `state` (at its speed).
    pub fn verdict(&self, state: &FilmState, mass_kg: f64) -> RotorVerdict {
        let mass_parameter = self.mass_parameter(mass_kg, state.speed_rpm);
        let (growth, frequency) = dynamics::least_stable_mode(&state.coefficients, mass_parameter);
        RotorVerdict {
            stable: growth < 0.0,
            growth_rate_per_s: growth * Self::omega(state.speed_rpm),
            frequency_ratio: frequency,
        }
    }

    /// The speed at which a rotor of `mass_kg` on this bearing starts to whirl, with the
    /// coefficient sets the search took.
    pub fn threshold_speed(
        &self,
        mass_kg: f64,
        budget: &Budget,
    ) -> Result<(SpeedThreshold, u32), CalcError> {
        if self.film == WhirlFilm::ShortFull {
            return Ok((SpeedThreshold::EverySpeed, 0));
        }
        let spr = self.sommerfeld_per_rpm();
        let failure = RefCell::new(None);
        let evaluations = RefCell::new(0u32);
        let mut field = FilmStart::default();
        // The last state the margin was taken at: the threshold's is the root's.
        let last = RefCell::new(None::<FilmState>);
        let mut margin = |eps: f64| -> f64 {
            *evaluations.borrow_mut() += 1;
            match self.coefficients_at(eps, &mut field, budget) {
                Ok(c) => {
                    let state = self.state(eps, None, c);
                    let m = self.mass_parameter(mass_kg, state.speed_rpm);
                    *last.borrow_mut() = Some(state);
                    match state.whirl.critical_mass_parameter {
                        Some(mc) => (mc / m).ln().clamp(-50.0, 50.0),
                        None => 50.0,
                    }
                }
                Err(err) => {
                    failure.borrow_mut().get_or_insert(err);
                    f64::NAN
                }
            }
        };
        let (lo, hi) = (self.film.lightest(), MAX_ECCENTRICITY);
        let root = match self.film {
            WhirlFilm::Finite(_) => {
                // Seed: the short bearing's root (its S scaled to this bearing's speeds at a
                // reference ε of 0.5), then secant steps on the finite film.
                let eps_ref = 0.5;
                let s_ref =
                    closed_form::short_bearing(eps_ref, self.l_over_d(), Boundary::HalfSommerfeld)
                        .map_or(f64::NAN, |p| p.sommerfeld_number);
                let seed = short_bearing_threshold(self.l_over_d(), eps_ref, |e, s_ratio| {
                    let critical = short_bearing_critical_mass(e, 0.0)
                        .map_or(f64::INFINITY, |m| m.max(1e-300));
                    self.mass_parameter(mass_kg, s_ref * s_ratio / spr) / critical
                });
                let seeded = match seed {
                    Some(start) => secant_threshold(&mut margin, start, budget)?,
                    None => None,
                };
                if let Some(err) = failure.borrow_mut().take() {
                    return Err(err);
                }
                match seeded {
                    Some(e) => Bracketed::Root(e),
                    None => scan_and_bracket(&mut margin, lo, hi, budget)?,
                }
            }
            _ => scan_and_bracket(&mut margin, lo, hi, budget)?,
        };
        if let Some(err) = failure.into_inner() {
            return Err(err);
        }
        let outcome = match root {
            Bracketed::Root(eps) => {
                let state = match *last.borrow() {
                    Some(s) if s.eccentricity_ratio == eps => s,
                    _ => {
                        let c = self.coefficients_at(eps, &mut field, budget)?;
                        self.state(eps, None, c)
                    }
                };
                SpeedThreshold::Found(state)
            }
            Bracketed::StableAt(eps) | Bracketed::UnstableAt(eps) => {
                let c = self.coefficients_at(eps, &mut field, budget)?;
                let speed = c.sommerfeld_number / spr;
                if matches!(root, Bracketed::StableAt(_)) {
                    SpeedThreshold::StableUpTo(speed)
                } else {
                    SpeedThreshold::UnstableDownTo(speed)
                }
            }
        };
        Ok((outcome, evaluations.into_inner()))
    }

    /// The solver block: the closed form's evaluations, or the finite film's coefficient sets
    /// on its mesh.
    pub fn report(&self, evaluations: u32, film_solves: u32) -> SolverReport {
        match self.film.method() {
            Method::Numerical { level, mesh, .. } => SolverReport::closed_form_search(
                "perturbed_reynolds_film_lund_threshold",
                evaluations,
            )
            .at(level)
            .on_grid(vec![mesh.circumferential as u32, mesh.axial_half as u32])
            .with_film_solves(film_solves),
            Method::ClosedForm(_) => {
                SolverReport::closed_form_search("short_bearing_lund_threshold", evaluations)
                    .at(Level::ClosedForm)
            }
        }
    }
}

/// How a search over the locus ended.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Bracketed {
    Root(f64),
    /// No sign change: the margin is positive (stable) even at this, the lightest ε.
    StableAt(f64),
    /// No sign change: negative (whirling) even at this, the heaviest ε.
    UnstableAt(f64),
}

/// The margin's root in x = ln ε over [lo, hi]: twelve points evenly in ln ε from the heavy end
/// towards the light one, to the first sign change (the threshold nearest the heavy end: the
/// lowest speed at which the rotor whirls), then Brent to 10⁻⁴ in ln ε in that cell. One
/// iteration of the scan is one margin (a set of coefficients).
fn scan_and_bracket(
    margin: &mut impl FnMut(f64) -> f64,
    lo: f64,
    hi: f64,
    budget: &Budget,
) -> Result<Bracketed, CalcError> {
    const POINTS: u32 = 12;
    let (xl, xh) = (lo.ln(), hi.ln());
    let at = |k: u32| xh + (xl - xh) * f64::from(k) / f64::from(POINTS - 1);
    let m_hi = margin(hi);
    if m_hi.is_nan() {
        return Err(CalcError::Internal(
            "whirl: no margin at the heaviest ε".into(),
        ));
    }
    if m_hi < 0.0 {
        return Ok(Bracketed::UnstableAt(hi));
    }
    let mut previous = (xh, m_hi);
    let mut k = 0;
    let scan = Driver::new(
        "whirl_threshold_scan",
        IterationUnit::Evaluations,
        POINTS,
        budget,
    )
    .run(|_| {
        k += 1;
        let x = at(k);
        let m = margin(x.exp());
        if m.is_nan() {
            return Verdict::Diverged(f64::NAN);
        }
        if m < 0.0 {
            return Verdict::Converged(Some((previous, (x, m))), (previous.0 - x).abs());
        }
        previous = (x, m);
        if k + 1 >= POINTS {
            return Verdict::Converged(None, 0.0);
        }
        Verdict::Continue((previous.0 - x).abs())
    });
    let cell = match scan {
        Ok(found) => found.value,
        Err(stopped) if stopped.reason() == StopReason::Deadline => return Err(stopped.into()),
        Err(stopped) => {
            return Err(CalcError::Internal(format!(
                "whirl: the locus scan stopped ({:?})",
                stopped.reason()
            )))
        }
    };
    let Some((a, b)) = cell else {
        return Ok(Bracketed::StableAt(lo));
    };
    let root = brent_bracketed(
        |x| margin(x.exp()),
        b,
        a,
        Stopping {
            x_tolerance: 1e-4,
            max_iterations: 60,
        },
    )
    .map_err(|e| CalcError::from_root("whirl_threshold_brent", e))?;
    Ok(Bracketed::Root(root.x.exp()))
}

#[cfg(test)]
mod tests;
