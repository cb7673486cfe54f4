//! Stiffness and damping of the oil film by perturbing the converged film, and the rigid-rotor
//! stability threshold (Lund's linearised whirl analysis; Khonsari & Booser §8.16 defines the
//! coefficients, the threshold follows Lund 1966 as the text cites it).
//!
//! Perturbation: the journal centre is displaced by ±δ and moved at ±δ̇ along each axis about
//! equilibrium; the film keeps its equilibrium grid and its feed line at the equilibrium h_max
//! (the groove is fixed in the bearing). A Reynolds-condition film answers linearly: the
//! pressure's derivative solves the equilibrium's own free-node operator with the perturbed
//! equations' residual as the right side (Lund's first-order perturbation equations; at the
//! Reynolds condition p = ∂p/∂n = 0 the rupture line's movement is second order), one
//! factorisation for all four derivatives. A mass-conserving film re-solves pressure and film
//! content in each perturbed film from the equilibrium field (ports stay where the bearing
//! holds them), with the squeeze term weighted by the content (∂(θ_f h)/∂t ≈ θ_f ∂h/∂t: the
//! content's own rate is neglected). Central differences in both.
//!
//! Frame: x along the static load, y perpendicular to it, 90° ahead in the direction of rotation.
//! Dimensionless k_ij = K_ij C/W, c_ij = C_ij C ω/W, order [xx, xy, yx, yy]; a force
//! f_i = −K_ij δ_j − C_ij δ̇_j acts on the journal.

use std::f64::consts::PI;

use super::eccentricity::EccentricityRatio;
use super::film::{self, Film, FilmModel, FilmSolution, Mesh, Response};
use super::performance::{positioned_film, FilmStart};
use crate::calc::{Budget, CalcError};
use crate::numerics::reynolds::Stopping;

/// Dimensionless stiffness and damping in the load frame, [xx, xy, yx, yy].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Coefficients {
    pub stiffness: [f64; 4],
    pub damping: [f64; 4],
    /// S of the equilibrium film they were taken about.
    pub sommerfeld_number: f64,
}

/// Force on the journal in the film frame (a towards h_max, b 90° ahead), per μ N_s (R/C)² R L.
fn force(f: &FilmSolution) -> [f64; 2] {
    [f.load_radial, -f.load_tangential]
}

/// Coefficients at eccentricity ratio `eps` by perturbation of the numerical film. `start` is
/// where the equilibrium solve starts (a converged field on `mesh` makes that solve a check; a
/// nearby placed film's attitude starts its attitude search), and holds the equilibrium's
/// field and attitude after.
pub fn perturbation(
    eccentricity: EccentricityRatio,
    l_over_d: f64,
    physics: FilmModel,
    mesh: Mesh,
    stop: Stopping,
    start: &mut FilmStart,
    budget: &Budget,
) -> Result<Coefficients, CalcError> {
    let (base, equilibrium, solved) = positioned_film(
        eccentricity,
        l_over_d,
        physics,
        mesh,
        stop,
        std::mem::take(start),
        budget,
    )?;
    start.attitude = Some(equilibrium.attitude_angle());
    let field = start.field.insert(solved);
    let f0 = force(&equilibrium);
    let s = 2.0 / f0[0].hypot(f0[1]);
    let (k, c) = if physics.has_content() {
        let delta = film::perturbation_step(eccentricity.get());
        resolved_derivatives(base, mesh, stop, field, delta, budget)?
    } else {
        // The linear response: one factorisation, counted as a film solve.
        budget.count_field_solve();
        linear_derivatives(base, mesh, field.clone())?
    };
    Ok(Coefficients {
        stiffness: in_load_frame(&k, f0, s / 2.0),
        damping: in_load_frame(&c, f0, s / 2.0 * 2.0 * PI),
        sommerfeld_number: s,
    })
}

/// A film-frame matrix `m` (a toward h_max, b 90° ahead in the direction of rotation) in the
/// load frame of the film force `film_force` on the journal (x along the load W = −F, y = x
/// turned 90° with the rotation), times `scale`, as [xx, xy, yx, yy].
pub fn in_load_frame(m: &[[f64; 2]; 2], film_force: [f64; 2], scale: f64) -> [f64; 4] {
    let norm = film_force[0].hypot(film_force[1]);
    let x = [-film_force[0] / norm, -film_force[1] / norm];
    let axes = [x, [-x[1], x[0]]];
    let mut out = [0.0; 4];
    for (p, u) in axes.iter().enumerate() {
        for (q, v) in axes.iter().enumerate() {
            let mut sum = 0.0;
            for i in 0..2 {
                for j in 0..2 {
                    sum += u[i] * m[i][j] * v[j];
                }
            }
            out[2 * p + q] = scale * sum;
        }
    }
    out
}

/// The film `film` with its offset (`shape`) and rate (`rate`) along axis j set (0: A, the cos
/// term; 1: B).
fn perturbed(film: Film, j: usize, shape: f64, rate: f64) -> Film {
    let mut f = film;
    if j == 0 {
        f.cos_offset = shape;
        f.cos_rate = rate;
    } else {
        f.sin_offset = shape;
        f.sin_rate = rate;
    }
    f
}

/// ∂F/∂(A, B) and ∂F/∂(Ȧ, Ḃ) in the film frame by the linear response of the Reynolds film
/// (one factorisation, four right sides).
fn linear_derivatives(base: Film, mesh: Mesh, field: Vec<f64>) -> Result<Derivatives, CalcError> {
    let response = Response::at(&base, mesh, field).map_err(|e| {
        CalcError::Internal(format!(
            "film operator not positive definite at row {}",
            e.row
        ))
    })?;
    let mut k = [[0.0; 2]; 2];
    let mut c = [[0.0; 2]; 2];
    for j in 0..2 {
        let shape = response.shape_derivative(j == 0);
        let motion = response.squeeze_derivative(j == 0);
        // Force components [a, b] = [radial, −tangential].
        for (i, sign) in [1.0, -1.0].into_iter().enumerate() {
            k[i][j] = sign * shape[i];
            c[i][j] = sign * motion[i];
        }
    }
    Ok((k, c))
}

/// As [`linear_derivatives`] for a mass-conserving film, by central differences of re-solved
/// films (pressure and content), each started from the equilibrium field.
fn resolved_derivatives(
    base: Film,
    mesh: Mesh,
    stop: Stopping,
    field: &[f64],
    delta: f64,
    budget: &Budget,
) -> Result<Derivatives, CalcError> {
    let rate = 2.0 * PI * delta;
    // The perturbed forces differ from the base by O(δ): solve them well below that.
    let stop = Stopping {
        tolerance: stop.tolerance.min(1e-11),
        max_sweeps: stop.max_sweeps.max(200_000),
    };
    let solve_at = |film: Film| -> Result<[f64; 2], CalcError> {
        let (f, _) = film::solve(film, mesh, stop, Some(field.to_vec()), budget)?;
        Ok(force(&f))
    };
    let mut k = [[0.0; 2]; 2];
    let mut c = [[0.0; 2]; 2];
    for j in 0..2 {
        let plus = solve_at(perturbed(base, j, delta, 0.0))?;
        let minus = solve_at(perturbed(base, j, -delta, 0.0))?;
        let vplus = solve_at(perturbed(base, j, 0.0, rate))?;
        let vminus = solve_at(perturbed(base, j, 0.0, -rate))?;
        for i in 0..2 {
            // K = −∂F/∂d = +∂F/∂A; C = −∂F/∂ḋ = +∂F/∂Ȧ.
            k[i][j] = (plus[i] - minus[i]) / (2.0 * delta);
            c[i][j] = (vplus[i] - vminus[i]) / (2.0 * rate);
        }
    }
    Ok((k, c))
}

/// ∂F_i/∂(A, B)_j and ∂F_i/∂(Ȧ, Ḃ)_j.
type Derivatives = ([[f64; 2]; 2], [[f64; 2]; 2]);

/// Lund's rigid-rotor stability numbers from dimensionless coefficients.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Whirl {
    /// Equivalent stiffness k_eq, dimensionless.
    pub equivalent_stiffness: f64,
    /// Whirl frequency ratio γ = ω_whirl/ω at the threshold; None when the film cannot whirl.
    pub whirl_frequency_ratio: Option<f64>,
    /// Critical mass parameter m C ω²/W at the threshold; None: stable for any mass; 0 when
    /// k_eq ≤ 0 (no mass is stable).
    pub critical_mass_parameter: Option<f64>,
    /// Lund's γ² as computed, of either sign (γ² ≤ 0: the film cannot whirl); continuous in
    /// the coefficients, where `whirl_frequency_ratio` is not.
    pub whirl_ratio_squared: f64,
}

/// k_eq = (k_xx c_yy + k_yy c_xx − k_xy c_yx − k_yx c_xy)/(c_xx + c_yy),
/// γ² = [(k_xx − k_eq)(k_yy − k_eq) − k_xy k_yx]/(c_xx c_yy − c_xy c_yx), m̄_c = k_eq/γ².
pub fn whirl(c: &Coefficients) -> Whirl {
    whirl_on_shaft(c, 0.0)
}

/// As [`whirl`], for a rotor on a shaft of flexibility γ = W/(k_s C) in series with the film (a
/// Jeffcott rotor): at the threshold the film acts as the real stiffness k_eq at the whirl
/// frequency, the shaft in series gives k_eq/(1 + γ k_eq), so m̄_c = k_eq/(γ_w² (1 + γ k_eq)).
/// This is Hori's Routh–Hurwitz threshold as Stachowiak & Batchelor §5.6.4 print it,
/// ω*_c² = A1 A3 A5²/[(A1² + A2 A5² − A1 A4 A5)(A5 + γ A1)] (A1 = k_eq A5, A5 = c_xx + c_yy).
pub fn whirl_on_shaft(c: &Coefficients, shaft_flexibility: f64) -> Whirl {
    let [kxx, kxy, kyx, kyy] = c.stiffness;
    let [cxx, cxy, cyx, cyy] = c.damping;
    let k_eq = (kxx * cyy + kyy * cxx - kxy * cyx - kyx * cxy) / (cxx + cyy);
    let gamma2 = ((kxx - k_eq) * (kyy - k_eq) - kxy * kyx) / (cxx * cyy - cxy * cyx);
    let unstable_possible = gamma2.is_finite() && gamma2 > 0.0 && k_eq > 0.0;
    Whirl {
        equivalent_stiffness: k_eq,
        // k_eq = 0 (the full film's): the massless rotor's pair sits on the imaginary axis at
        // γ, the frequency every mass whirls at as it leaves it.
        whirl_frequency_ratio: (gamma2.is_finite() && gamma2 > 0.0 && k_eq >= 0.0)
            .then(|| gamma2.sqrt()),
        // k_eq ≤ 0: no positive mass is stable (the critical mass is 0).
        critical_mass_parameter: if k_eq <= 0.0 {
            Some(0.0)
        } else {
            unstable_possible.then(|| k_eq / gamma2 / (1.0 + shaft_flexibility * k_eq))
        },
        whirl_ratio_squared: gamma2,
    }
}

/// The rigid rotor on the film, m ẍ + C ẋ + K x = 0, in τ = ωt and x/C: M̄ x″ + c x′ + k x = 0
/// with M̄ = m C ω²/W (the mass parameter) and the dimensionless k, c. Its characteristic
/// polynomial det(M̄ s² + c s + k) = a₄s⁴ + a₃s³ + a₂s² + a₁s + a₀ (s in units of ω), as
/// [a₀, a₁, a₂, a₃, a₄]: a₄ = M̄², a₃ = M̄ (c_xx + c_yy), a₂ = M̄ (k_xx + k_yy) + c_xx c_yy −
/// c_xy c_yx, a₁ = k_xx c_yy + k_yy c_xx − k_xy c_yx − k_yx c_xy, a₀ = k_xx k_yy − k_xy k_yx.
pub fn characteristic_polynomial(c: &Coefficients, mass_parameter: f64) -> [f64; 5] {
    let [kxx, kxy, kyx, kyy] = c.stiffness;
    let [cxx, cxy, cyx, cyy] = c.damping;
    let m = mass_parameter;
    [
        kxx * kyy - kxy * kyx,
        kxx * cyy + kyy * cxx - kxy * cyx - kyx * cxy,
        m * (kxx + kyy) + cxx * cyy - cxy * cyx,
        m * (cxx + cyy),
        m * m,
    ]
}

/// Routh–Hurwitz for the quartic of [`characteristic_polynomial`]: every root has a negative
/// real part iff every aᵢ > 0 and Δ₃ = a₃a₂a₁ − a₄a₁² − a₀a₃² > 0. Δ₃ is M̄ times a linear
/// function of M̄ that vanishes at Lund's critical mass parameter k_eq/γ² ([`whirl`]): the
/// same threshold, written as a test of one rotor.
pub fn routh_hurwitz_stable(c: &Coefficients, mass_parameter: f64) -> bool {
    let [a0, a1, a2, a3, a4] = characteristic_polynomial(c, mass_parameter);
    let delta3 = a3 * a2 * a1 - a4 * a1 * a1 - a0 * a3 * a3;
    [a0, a1, a2, a3, a4].iter().all(|&a| a > 0.0) && delta3 > 0.0
}

/// The four eigenvalues s of the rotor–film system in units of ω (growth rate Re s · ω, whirl
/// frequency |Im s| · ω), from the 4×4 first-order form z′ = A z, z = (x, y, x′, y′),
/// A = [[0, I], [−k/M̄, −c/M̄]] (nalgebra's real Schur form). `mass_parameter` > 0.
pub fn rotor_eigenvalues(c: &Coefficients, mass_parameter: f64) -> [nalgebra::Complex<f64>; 4] {
    let m = mass_parameter;
    let [kxx, kxy, kyx, kyy] = c.stiffness;
    let [cxx, cxy, cyx, cyy] = c.damping;
    #[rustfmt::skip]
    let a = nalgebra::Matrix4::new(
        0.0, 0.0, 1.0, 0.0,
        0.0, 0.0, 0.0, 1.0,
        -kxx / m, -kxy / m, -cxx / m, -cxy / m,
        -kyx / m, -kyy / m, -cyx / m, -cyy / m,
    );
    let values = a.complex_eigenvalues();
    [values[0], values[1], values[2], values[3]]
}

/// The least damped mode of [`rotor_eigenvalues`]: (Re s, |Im s|) of the eigenvalue with the
/// largest real part, in units of ω.
pub fn least_stable_mode(c: &Coefficients, mass_parameter: f64) -> (f64, f64) {
    rotor_eigenvalues(c, mass_parameter)
        .into_iter()
        .max_by(|a, b| a.re.total_cmp(&b.re))
        .map_or((f64::NAN, f64::NAN), |s| (s.re, s.im.abs()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::calc::journal::closed_form;

    const STOP: Stopping = Stopping {
        tolerance: 1e-10,
        max_sweeps: 100_000,
    };

    /// At small L/D the finite film tends to the short bearing: its coefficients approach the
    /// Ocvirk closed forms (π film; our film uses the Reynolds condition, which at L/D = 1/8
    /// differs from the π film by a few per cent).
    #[test]
    fn short_bearing_limit() {
        for eps in [0.3, 0.5, 0.7] {
            let num = perturbation(
                EccentricityRatio::new(eps).unwrap(),
                0.125,
                FilmModel::REYNOLDS,
                Mesh {
                    circumferential: 144,
                    axial_half: 12,
                },
                STOP,
                &mut FilmStart::default(),
                &Budget::unlimited(),
            )
            .unwrap();
            let (k, c) = closed_form::short_bearing_dynamic_coefficients(eps);
            for i in 0..4 {
                let scale = k.iter().map(|v| v.abs()).fold(0.0, f64::max);
                assert!(
                    (num.stiffness[i] - k[i]).abs() <= 0.08 * scale,
                    "ε {eps} k[{i}]: {} vs {}",
                    num.stiffness[i],
                    k[i]
                );
                let scale = c.iter().map(|v| v.abs()).fold(0.0, f64::max);
                assert!(
                    (num.damping[i] - c[i]).abs() <= 0.08 * scale,
                    "ε {eps} c[{i}]: {} vs {}",
                    num.damping[i],
                    c[i]
                );
            }
        }
    }

    /// Damping is symmetric (c_xy = c_yx) for the full-film-free Reynolds film only approximately;
    /// the direct terms are positive and the rotor–film system has the familiar shape: positive
    /// direct stiffness and damping, a threshold at light load (small ε), none at heavy load.
    #[test]
    fn light_loads_whirl_and_heavy_loads_do_not() {
        let mesh = Mesh {
            circumferential: 96,
            axial_half: 12,
        };
        let light = perturbation(
            EccentricityRatio::new(0.2).unwrap(),
            1.0,
            FilmModel::REYNOLDS,
            mesh,
            STOP,
            &mut FilmStart::default(),
            &Budget::unlimited(),
        )
        .unwrap();
        assert!(light.stiffness[0] > 0.0 && light.damping[0] > 0.0 && light.damping[3] > 0.0);
        let w = whirl(&light);
        let gamma = w
            .whirl_frequency_ratio
            .expect("a lightly loaded plain bearing can whirl");
        assert!(
            gamma > 0.4 && gamma < 0.5,
            "half-frequency whirl, got {gamma}"
        );
        let heavy = perturbation(
            EccentricityRatio::new(0.9).unwrap(),
            1.0,
            FilmModel::REYNOLDS,
            mesh,
            STOP,
            &mut FilmStart::default(),
            &Budget::unlimited(),
        )
        .unwrap();
        let w = whirl(&heavy);
        assert!(w.critical_mass_parameter.is_none_or(|m| m > 50.0), "{w:?}");
    }

    /// With mass-conserving cavitation the perturbed films re-solve pressure and content: fed at
    /// h_max they give the Reynolds film's coefficients (rupture obeys the same condition, and
    /// the squeeze acts only where the film is full), fed opposite the load they stay finite
    /// with positive direct terms, and the equilibrium they were taken about is the JFO one.
    #[test]
    fn mass_conserving_films_have_consistent_coefficients() {
        use crate::calc::journal::film::{FeedLine, Supply};
        let mesh = Mesh {
            circumferential: 96,
            axial_half: 12,
        };
        for eps in [0.3, 0.7] {
            let reynolds = perturbation(
                EccentricityRatio::new(eps).unwrap(),
                1.0,
                FilmModel::REYNOLDS,
                mesh,
                STOP,
                &mut FilmStart::default(),
                &Budget::unlimited(),
            )
            .unwrap();
            let jfo = |feed| FilmModel {
                mass_conserving: Some(Supply::line(feed)),
                ..FilmModel::REYNOLDS
            };
            let flooded = perturbation(
                EccentricityRatio::new(eps).unwrap(),
                1.0,
                jfo(FeedLine::MaxFilm),
                mesh,
                STOP,
                &mut FilmStart::default(),
                &Budget::unlimited(),
            )
            .unwrap();
            let scale = |m: &[f64; 4]| m.iter().map(|v| v.abs()).fold(0.0, f64::max);
            for i in 0..4 {
                let (k, c) = (reynolds.stiffness, reynolds.damping);
                assert!(
                    (flooded.stiffness[i] - k[i]).abs() < 0.01 * scale(&k),
                    "ε {eps} k[{i}]: {} vs {}",
                    flooded.stiffness[i],
                    k[i]
                );
                assert!(
                    (flooded.damping[i] - c[i]).abs() < 0.01 * scale(&c),
                    "ε {eps} c[{i}]: {} vs {}",
                    flooded.damping[i],
                    c[i]
                );
            }
            let top = perturbation(
                EccentricityRatio::new(eps).unwrap(),
                1.0,
                jfo(FeedLine::OppositeLoad),
                mesh,
                STOP,
                &mut FilmStart::default(),
                &Budget::unlimited(),
            )
            .unwrap();
            assert!(top
                .stiffness
                .iter()
                .chain(&top.damping)
                .all(|v| v.is_finite()));
            assert!(top.stiffness[0] > 0.0 && top.damping[0] > 0.0 && top.damping[3] > 0.0);
            assert!(top.sommerfeld_number > reynolds.sommerfeld_number);
            let w = whirl(&top);
            assert!(w.equivalent_stiffness.is_finite());
        }
    }

    /// The shaft-in-series threshold is the text's Routh–Hurwitz expression (Stachowiak &
    /// Batchelor Eq. in §5.6.4), and with a rigid shaft it is Lund's.
    #[test]
    fn flexible_shaft_threshold_is_horis() {
        let c = Coefficients {
            stiffness: [5.0482, 3.6960, -0.0475, 1.1953],
            damping: [7.8693, 1.4988, 1.4982, 0.9243],
            sommerfeld_number: 0.1,
        };
        let ([kxx, kxy, kyx, kyy], [cxx, cxy, cyx, cyy]) = (c.stiffness, c.damping);
        let a1 = kxx * cyy - kxy * cyx - kyx * cxy + kyy * cxx;
        let a2 = kxx * kyy - kxy * kyx;
        let a3 = cxx * cyy - cxy * cyx;
        let a4 = kxx + kyy;
        let a5 = cxx + cyy;
        for gamma in [0.0, 0.1, 1.0] {
            let text =
                a1 * a3 * a5 * a5 / ((a1 * a1 + a2 * a5 * a5 - a1 * a4 * a5) * (a5 + gamma * a1));
            let ours = whirl_on_shaft(&c, gamma).critical_mass_parameter.unwrap();
            assert!(
                (ours / text - 1.0).abs() < 1e-12,
                "γ {gamma}: {ours} vs {text}"
            );
        }
        // The printed STABILITY example: ω*_c = 2.059 from its (11 × 11) coefficients, γ = 0.1.
        let w = whirl_on_shaft(&c, 0.1)
            .critical_mass_parameter
            .unwrap()
            .sqrt();
        assert!((w - 2.059).abs() < 1e-3, "{w}");
        assert_eq!(whirl(&c), whirl_on_shaft(&c, 0.0));
    }
}
