//! Stiffness and damping of the plain gas journal's film, frequency dependent, and the
//! rigid rotor's half-frequency whirl threshold on it (Khonsari & Booser §11.5, Fig. 11.16;
//! the perturbation method of Lund as the liquid room uses it, `journal::dynamics`).
//!
//! **Model.** The journal moves harmonically about equilibrium at the whirl frequency ν: in the
//! film frame (a toward the maximum film, θ = 0; b at θ = 90°, ahead in the direction of
//! rotation) a displacement d = (d_a, d_b) e^{iντ/ω} changes the film by
//! ΔH = −(d_a cos θ + d_b sin θ)/C. With τ = ωt the unsteady compressible Reynolds equation in
//! this room's scaling (θ, y = z/R, P = p/p_a, H = h/C) is
//! ∇·(H³P∇P) = Λ ∂θ(PH) + 2Λ ∂τ(PH): the squeeze term's coefficient is 2Λ (from 12μR²/(p_a C²)),
//! so motion at ν has the squeeze number **σ = 2Λ ν/ω** (Eq. 11.3's σ with the journal's
//! lengths). Its first-order response P₁ solves a complex linear system with the steady Newton
//! Jacobian ([`reynolds_gas::harmonic_response`]), one per direction (cos θ and sin θ are
//! both symmetric about the mid-plane, so the half-length grid serves an aligned journal; a
//! misaligned one's whole-length film is perturbed on its own grid). The film force's
//! response F₁ = Z d defines the impedance Z(ν) = K(ν) + iν C(ν): a gas film's K and C depend
//! on ν (its compressibility stores and returns energy), which the liquid film's do not.
//!
//! **Frame, signs, scaling** (the liquid room's): x along the static load, y perpendicular, 90°
//! ahead in the direction of rotation; a film force f_i = −K_ij δ_j − C_ij δ̇_j acts on the
//! journal; k_ij = K_ij C/W, c_ij = C_ij C ω/W (ω the journal's speed), order [xx, xy, yx, yy].
//! The Sommerfeld number carried is the gas film's S = μ N L D/W (R/C)² = Λ/(12π W̄).

use super::journal_film::{JournalEvaluated, JournalFilm, JournalSolve};
use crate::calc::journal::dynamics::{in_load_frame, whirl, Coefficients};
use crate::calc::{Budget, CalcError};
use crate::numerics::band_lu::Unfactored;
use crate::numerics::reynolds_gas::{self, GasGrid};
use crate::numerics::richardson::{extrapolate, fine_error};
use crate::numerics::roots::{secant_bracketed, RootError, Stopping};
use std::f64::consts::PI;

/// Standard gravity g, m/s², for the gravity-loaded rotor (m = W/g) of Fig. 11.16.
pub const STANDARD_GRAVITY: f64 = 9.80665;

/// The whirl ratio at which a "static" (ν → 0) damping is taken: Im Z/ν is even in ν, so its
/// error there is O(ν²) ≈ 1e-12.
pub const STATIC_WHIRL_RATIO: f64 = 1e-6;

/// Film force (a, b) on the journal of a pressure perturbation `dp` over the grid, per
/// p_a L D: −∫∫ dp (cos θ, sin θ) dθ dy times the film's [`JournalFilm::load_factor`].
fn force(grid: &GasGrid, load_factor: f64, dp: &[f64]) -> [f64; 2] {
    let (mut sc, mut ss) = (0.0, 0.0);
    for i in 0..grid.nx() {
        let (s, c) = grid.x[i].sin_cos();
        for j in 0..grid.y.len() {
            let w = grid.weight(i, j) * dp[grid.at(i, j)];
            sc += w * c;
            ss += w * s;
        }
    }
    [-sc * load_factor, -ss * load_factor]
}

/// The film's impedance in the film frame (a, b), per p_a L D and per C, at one whirl ratio:
/// `stiffness[i][j]` = Re Z_ij = K_ij C/(p_a L D) and `damping[i][j]` = Im Z_ij/γ =
/// C_ij C ω/(p_a L D).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Impedance {
    pub stiffness: [[f64; 2]; 2],
    pub damping: [[f64; 2]; 2],
}

/// The impedance of one solved film at whirl ratio γ = ν/ω = `whirl_ratio` (≥ 0; below
/// [`STATIC_WHIRL_RATIO`] the static limit). One factorisation, counted as a film solve.
pub fn impedance(
    film: &JournalFilm,
    solved: &JournalSolve,
    whirl_ratio: f64,
    budget: &Budget,
) -> Result<Impedance, CalcError> {
    let gamma = whirl_ratio.max(STATIC_WHIRL_RATIO);
    let grid = &solved.grid;
    let problem = super::journal_film::problem(film, grid);
    let sigma = 2.0 * film.bearing_number * gamma;
    // ΔH = A cos θ + B sin θ: A = −d_a/C, B = −d_b/C.
    let cos_shape = |t: f64, _: f64| t.cos();
    let sin_shape = |t: f64, _: f64| t.sin();
    let responses = reynolds_gas::harmonic_response(
        grid,
        &problem,
        &solved.p,
        sigma,
        &[&cos_shape, &sin_shape],
        budget,
    )
    .map_err(|e| match e {
        Unfactored::Stopped => CalcError::DeadlineExceeded,
        Unfactored::Singular(s) => CalcError::Internal(format!(
            "gas film's harmonic system singular at column {}",
            s.column
        )),
    })?;
    budget.count_field_solve();
    // Z_ij = −∂F_i/∂d_j = +∂F_i/∂A_j.
    let mut out = Impedance {
        stiffness: [[0.0; 2]; 2],
        damping: [[0.0; 2]; 2],
    };
    for (j, r) in responses.iter().enumerate() {
        let re = force(grid, film.load_factor(), &r.re);
        let im = force(grid, film.load_factor(), &r.im);
        for i in 0..2 {
            out.stiffness[i][j] = re[i];
            out.damping[i][j] = im[i] / gamma;
        }
    }
    Ok(out)
}

/// The dimensionless coefficients (load frame, k = K C/W, c = C C ω/W) of one solved film at
/// whirl ratio `whirl_ratio` ([`impedance`]).
pub fn coefficients(
    film: &JournalFilm,
    solved: &JournalSolve,
    whirl_ratio: f64,
    budget: &Budget,
) -> Result<Coefficients, CalcError> {
    let Impedance {
        stiffness: k,
        damping: c,
    } = impedance(film, solved, whirl_ratio, budget)?;
    let p = solved.performance;
    let f0 = [p.load_along, -p.load_across];
    let load = f0[0].hypot(f0[1]);
    Ok(Coefficients {
        stiffness: in_load_frame(&k, f0, 1.0 / load),
        damping: in_load_frame(&c, f0, 1.0 / load),
        sommerfeld_number: film.bearing_number / (12.0 * PI * load),
    })
}

/// Coefficients of an evaluated film, Richardson-extrapolated from its half mesh when it has
/// one, with the error estimate: the largest |fine − coarse|/3 over the eight, relative to the
/// largest coefficient of each kind.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Evaluated {
    pub coefficients: Coefficients,
    pub whirl_ratio: f64,
    /// σ = 2Λ ν/ω.
    pub squeeze_number: f64,
    pub error_estimate: Option<f64>,
}

/// [`coefficients`] on the evaluation's meshes.
pub fn evaluated(
    film: &JournalFilm,
    at: &JournalEvaluated,
    whirl_ratio: f64,
    budget: &Budget,
) -> Result<Evaluated, CalcError> {
    let fine = coefficients(film, &at.fine, whirl_ratio, budget)?;
    let squeeze_number = 2.0 * film.bearing_number * whirl_ratio;
    let Some(coarse) = &at.coarse else {
        return Ok(Evaluated {
            coefficients: fine,
            whirl_ratio,
            squeeze_number,
            error_estimate: None,
        });
    };
    let coarse = coefficients(film, coarse, whirl_ratio, budget)?;
    let mut out = fine;
    let mut error: f64 = 0.0;
    for (o, (f, c)) in [
        (&mut out.stiffness, (&fine.stiffness, &coarse.stiffness)),
        (&mut out.damping, (&fine.damping, &coarse.damping)),
    ] {
        let scale = f.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for n in 0..4 {
            o[n] = extrapolate(c[n], f[n]);
            error = error.max(fine_error(c[n], f[n]).abs() / scale);
        }
    }
    out.sommerfeld_number = film.bearing_number / (12.0 * PI * at.performance.load());
    Ok(Evaluated {
        coefficients: out,
        whirl_ratio,
        squeeze_number,
        error_estimate: Some(error),
    })
}

/// The rigid rotor's whirl threshold on the film.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Threshold {
    /// M̄_c = m C ω²/W: a rotor of larger M̄ whirls; 0 when no mass is stable.
    pub critical_mass_parameter: f64,
    /// γ = ν/ω at the threshold.
    pub whirl_ratio: f64,
    /// The coefficients at γ.
    pub at: Evaluated,
    /// Whirl ratios tried.
    pub evaluations: u32,
}

/// The whirl ratios scanned for the threshold's brackets, 0.01 to 2: every sign change of
/// γ_L²(γ) − γ² between neighbours is a crossing (roots closer than a step apart can hide).
pub const WHIRL_RATIO_SCAN: [f64; 13] = [
    0.01, 0.1, 0.2, 0.3, 0.4, 0.45, 0.5, 0.55, 0.6, 0.7, 0.85, 1.0, 2.0,
];

/// The threshold with frequency-dependent coefficients. At the threshold the rotor
/// M̄ x″ + c x′ + k x = 0 (x/C, τ = ωt) has a root s = iγ, so det(k(γ) + iγ c(γ) − M̄ γ² I) = 0.
/// For coefficients frozen at γ this is Lund's pair ([`whirl`]): k_eq(γ) and the whirl ratio
/// γ_L(γ); a crossing is a fixed point γ = γ_L(γ), with M̄ = k_eq/γ² (0 when k_eq ≤ 0: no
/// mass is stable). A gas film's coefficients can give more than one: the threshold is the
/// smallest M̄, the first crossing as the mass grows. The fixed points are bracketed by a scan
/// of γ_L²(γ) − γ² ([`WHIRL_RATIO_SCAN`]; Lund's γ² as computed, continuous where γ_L is not:
/// k_eq changes sign with γ at small Λ) and each refined by a bracketed secant (bisection where
/// a step leaves the bracket). `None`: no fixed point in the range (stable for any mass there).
pub fn threshold(
    film: &JournalFilm,
    at: &JournalEvaluated,
    budget: &Budget,
) -> Result<Option<Threshold>, CalcError> {
    let mut evaluations = 0;
    let mut gap = |gamma: f64| -> Result<(f64, Evaluated), CalcError> {
        evaluations += 1;
        let e = evaluated(film, at, gamma, budget)?;
        Ok((
            whirl(&e.coefficients).whirl_ratio_squared - gamma * gamma,
            e,
        ))
    };
    let mut scan = Vec::with_capacity(WHIRL_RATIO_SCAN.len());
    for &g in &WHIRL_RATIO_SCAN {
        scan.push((g, gap(g)?.0));
    }
    let mut best: Option<(f64, f64, Evaluated)> = None;
    for pair in scan.windows(2) {
        let ((a, fa), (b, fb)) = (pair[0], pair[1]);
        if fa * fb > 0.0 {
            continue;
        }
        let mut failed = None;
        let mut last: Option<Evaluated> = None;
        let root = secant_bracketed(
            |g| match gap(g) {
                Ok((v, e)) => {
                    last = Some(e);
                    v
                }
                Err(err) => {
                    failed = Some(err);
                    f64::NAN
                }
            },
            (a, fa),
            (b, fb),
            Stopping {
                x_tolerance: 1e-6,
                max_iterations: 60,
            },
        );
        if let Some(err) = failed {
            return Err(err);
        }
        let root = match root {
            Ok(r) => r,
            Err(RootError::NoSignChange { .. }) => continue,
            Err(e) => return Err(CalcError::from_root("gas_journal_whirl_threshold", e)),
        };
        // The search's last evaluation need not be at its answer: take the coefficients there.
        let at_root = match last {
            Some(e) if e.whirl_ratio == root.x => e,
            _ => gap(root.x)?.1,
        };
        let k_eq = whirl(&at_root.coefficients).equivalent_stiffness;
        let mass = if k_eq <= 0.0 {
            0.0
        } else {
            k_eq / (root.x * root.x)
        };
        if best.as_ref().is_none_or(|(m, _, _)| mass < *m) {
            best = Some((mass, root.x, at_root));
        }
    }
    Ok(
        best.map(|(critical_mass_parameter, whirl_ratio, at)| Threshold {
            critical_mass_parameter,
            whirl_ratio,
            at,
            evaluations,
        }),
    )
}

#[cfg(test)]
#[path = "journal_dynamics_tests.rs"]
mod tests;
