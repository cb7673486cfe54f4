//! The gas film's coefficients against finite differences of its own steady loads, the
//! incompressible film as Λ → 0, their frequency dependence and mesh convergence; the whirl
//! threshold against its defining determinant.

use super::*;
use crate::calc::gas::journal_film::tests::{film, incompressible_force};
use crate::calc::gas::journal_film::{self, level_mesh};
use crate::calc::gas::method::{Mesh, Method};
use crate::fidelity::Level;
use crate::numerics::reynolds_gas::GasStopping;

fn solved(f: &JournalFilm, along: usize, across: usize) -> JournalSolve {
    let grid = journal_film::grid(f, Mesh { along, across });
    journal_film::solve_on(f, grid, None, &Budget::unlimited()).unwrap()
}

fn standard(f: &JournalFilm) -> JournalEvaluated {
    let method = Method {
        level: Level::Standard,
        mesh: level_mesh(Level::Standard),
        richardson: true,
    };
    journal_film::evaluate(f, method, None, &Budget::unlimited()).unwrap()
}

fn max_abs(m: &[[f64; 2]; 2]) -> f64 {
    m.iter().flatten().fold(0.0f64, |a, v| a.max(v.abs()))
}

/// The steady film force (a, b) per p_a L D of the film H = 1 + ε cos θ + t·dh on `s`'s grid,
/// Newton from `s`'s field to 1e-13.
fn steady_force(
    f: &JournalFilm,
    s: &JournalSolve,
    t: f64,
    dh: &dyn Fn(f64, f64) -> f64,
) -> [f64; 2] {
    let problem = journal_film::problem(f, &s.grid).shifted(&s.grid, t, dh);
    let stop = GasStopping {
        tolerance: 1e-13,
        ..GasStopping::default()
    };
    let p = reynolds_gas::solve(&s.grid, &problem, Some(&s.p), stop, &Budget::unlimited())
        .unwrap()
        .p;
    let dp: Vec<f64> = p.iter().map(|v| v - 1.0).collect();
    force(&s.grid, f.load_factor(), &dp)
}

/// (a) ν → 0: the stiffness is the derivative of the steady load, by central differences of
/// re-solved films in ε (A = Δε) and in the line of centres' angle (B = ε Δφ), on the same grid.
#[test]
fn static_stiffness_is_the_derivative_of_the_steady_load() {
    for (e, lambda) in [(0.3, 0.5), (0.6, 5.0), (0.5, 100.0)] {
        let f = film(e, lambda, 1.0);
        let s = solved(&f, 32, 8);
        let z = impedance(&f, &s, 0.0, &Budget::unlimited()).unwrap();
        let d = 1e-5;
        let shapes: [&dyn Fn(f64, f64) -> f64; 2] = [&|t, _| t.cos(), &|t, _| t.sin()];
        let scale = max_abs(&z.stiffness);
        for (j, dh) in shapes.iter().enumerate() {
            let plus = steady_force(&f, &s, d, dh);
            let minus = steady_force(&f, &s, -d, dh);
            for i in 0..2 {
                let fd = (plus[i] - minus[i]) / (2.0 * d);
                let k = z.stiffness[i][j];
                assert!(
                    (k - fd).abs() < 1e-6 * scale,
                    "ε {e} Λ {lambda} K[{i}][{j}]: {k} vs finite difference {fd}"
                );
            }
        }
    }
}

/// (b) Λ → 0: P = 1 + ΛΠ with Π the incompressible full (Sommerfeld, uncavitated) film of
/// ∇·(H³∇Π) = ∂θH + 2∂τH; the gas impedance over Λ tends to that film's, stiffness by
/// central differences of its load, damping from the squeeze source 2 ∂τH (frequency
/// independent). Both films on fine meshes: the difference is the two schemes' discretisation
/// error (central in θ both; uniform against graded y) and O(Λ).
#[test]
fn small_bearing_numbers_give_the_incompressible_full_film() {
    for (e, l_over_d) in [(0.3, 1.0), (0.6, 0.5)] {
        let lambda = 1e-4;
        let f = film(e, lambda, l_over_d);
        let s = solved(&f, 128, 24);
        let mesh = (256, 48);
        let h0 = move |t: f64, _: f64| 1.0 + e * t.cos();
        let shapes: [fn(f64) -> f64; 2] = [f64::cos, f64::sin];
        let d = 1e-5;
        let mut k = [[0.0; 2]; 2];
        let mut c = [[0.0; 2]; 2];
        for (j, shape) in shapes.iter().enumerate() {
            let hp = move |t: f64, _: f64| 1.0 + e * t.cos() + d * shape(t);
            let hm = move |t: f64, _: f64| 1.0 + e * t.cos() - d * shape(t);
            let fp = incompressible_force(&hp, 1.0, None, l_over_d, mesh);
            let fm = incompressible_force(&hm, 1.0, None, l_over_d, mesh);
            let squeeze = move |t: f64, _: f64| 2.0 * shape(t);
            let fc = incompressible_force(&h0, 0.0, Some(&squeeze), l_over_d, mesh);
            for i in 0..2 {
                k[i][j] = (fp[i] - fm[i]) / (2.0 * d);
                c[i][j] = fc[i];
            }
        }
        for gamma in [0.0, 0.5, 2.0] {
            let z = impedance(&f, &s, gamma, &Budget::unlimited()).unwrap();
            for (gas, liquid, what) in [(z.stiffness, k, "K"), (z.damping, c, "C")] {
                let scale = max_abs(&liquid);
                for i in 0..2 {
                    for j in 0..2 {
                        let g = gas[i][j] / lambda;
                        assert!(
                            (g - liquid[i][j]).abs() < 3e-3 * scale,
                            "ε {e} L/D {l_over_d} γ {gamma} {what}[{i}][{j}]: gas/Λ {g} vs incompressible {}",
                            liquid[i][j]
                        );
                    }
                }
            }
        }
    }
}

/// (c) The frequency dependence: as σ = 2Λν/ω grows the film cannot leak in the time of a
/// cycle; it acts as a trapped gas spring, stiffer, and its damping falls.
#[test]
fn the_film_stiffens_and_its_damping_falls_with_the_squeeze_number() {
    for (e, lambda) in [(0.3, 1.0), (0.5, 5.0), (0.7, 20.0)] {
        let f = film(e, lambda, 1.0);
        let s = solved(&f, 32, 8);
        let mut last: Option<(f64, f64)> = None;
        for gamma in [2.0, 8.0, 32.0, 128.0] {
            let z = impedance(&f, &s, gamma, &Budget::unlimited()).unwrap();
            let stiff = z.stiffness[0][0] + z.stiffness[1][1];
            let damp = z.damping[0][0] + z.damping[1][1];
            if let Some((k0, c0)) = last {
                assert!(stiff > k0, "ε {e} Λ {lambda} γ {gamma}: {stiff} ≤ {k0}");
                assert!(damp < c0, "ε {e} Λ {lambda} γ {gamma}: {damp} ≥ {c0}");
            }
            last = Some((stiff, damp));
        }
        // The trapped-gas limit: damping ∝ 1/σ², the stiffness levelling off.
        let (k_hi, c_hi) = last.unwrap();
        let z = impedance(&f, &s, 2.0, &Budget::unlimited()).unwrap();
        assert!(c_hi < 0.01 * (z.damping[0][0] + z.damping[1][1]), "{c_hi}");
        let k_mid = {
            let z = impedance(&f, &s, 32.0, &Budget::unlimited()).unwrap();
            z.stiffness[0][0] + z.stiffness[1][1]
        };
        assert!(k_hi - k_mid < 0.1 * (k_mid - (z.stiffness[0][0] + z.stiffness[1][1])));
    }
}

/// (d) The standard mesh's extrapolated coefficients against a fine mesh (256 × 48): the
/// error falls with the mesh, and the Richardson estimate is of its size.
#[test]
fn coefficients_converge_with_the_mesh_and_the_estimate_brackets_the_error() {
    let f = film(0.5, 5.0, 1.0);
    let reference = coefficients(&f, &solved(&f, 256, 48), 0.5, &Budget::unlimited()).unwrap();
    let at = standard(&f);
    let got = evaluated(&f, &at, 0.5, &Budget::unlimited()).unwrap();
    let fine = coefficients(&f, &at.fine, 0.5, &Budget::unlimited()).unwrap();
    let coarse = coefficients(&f, at.coarse.as_ref().unwrap(), 0.5, &Budget::unlimited()).unwrap();
    let err = |c: &Coefficients| {
        let mut e: f64 = 0.0;
        for (a, b) in [
            (c.stiffness, reference.stiffness),
            (c.damping, reference.damping),
        ] {
            let scale = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            for n in 0..4 {
                e = e.max((a[n] - b[n]).abs() / scale);
            }
        }
        e
    };
    let (e_coarse, e_fine, e_extrapolated) = (err(&coarse), err(&fine), err(&got.coefficients));
    let estimate = got.error_estimate.unwrap();
    assert!(e_fine < 0.5 * e_coarse, "{e_fine} vs {e_coarse}");
    assert!(e_extrapolated < e_fine, "{e_extrapolated} vs {e_fine}");
    assert!(
        estimate > 0.3 * e_fine && estimate < 3.0 * e_fine,
        "estimate {estimate} vs the fine mesh's error {e_fine}"
    );
}

/// At the threshold the rotor's characteristic determinant det(k(γ) + iγ c(γ) − M̄γ² I)
/// vanishes with the coefficients at the threshold's own whirl ratio.
#[test]
fn the_threshold_solves_the_frequency_dependent_determinant() {
    for (e, lambda) in [(0.4, 0.42), (0.5, 3.0), (0.3, 1.0)] {
        let f = film(e, lambda, 1.0);
        let at = standard(&f);
        let t = threshold(&f, &at, &Budget::unlimited()).unwrap().unwrap();
        let (g, m) = (t.whirl_ratio, t.critical_mass_parameter);
        let [kxx, kxy, kyx, kyy] = t.at.coefficients.stiffness;
        let [cxx, cxy, cyx, cyy] = t.at.coefficients.damping;
        // (a + ib)(d + ie) − (p + iq)(r + is)
        let (a, b) = (kxx - m * g * g, g * cxx);
        let (dd, ee) = (kyy - m * g * g, g * cyy);
        let (p, q) = (kxy, g * cxy);
        let (r, s) = (kyx, g * cyx);
        let re = a * dd - b * ee - (p * r - q * s);
        let im = a * ee + b * dd - (p * s + q * r);
        let scale = (kxx * kyy).abs() + (kxy * kyx).abs() + (g * g * cxx * cyy).abs();
        assert!(
            re.hypot(im) < 1e-5 * scale,
            "ε {e} Λ {lambda}: |det| {} of {scale}",
            re.hypot(im)
        );
        assert!(m > 0.0 && (0.05..1.0).contains(&g), "M̄ {m}, γ {g}");
    }
}

/// Λ → 0: the film tends to the incompressible full (Sommerfeld) film, whose force in a frame
/// whirling at ω/2 vanishes (k_eq = 0): the critical mass falls to 0 with Λ (about ∝ Λ), and
/// the whirl ratio tends to ½ as ε → 0.
#[test]
fn the_critical_mass_vanishes_with_the_bearing_number() {
    let mass = |e: f64, lambda: f64| {
        let f = film(e, lambda, 1.0);
        let t = threshold(&f, &standard(&f), &Budget::unlimited())
            .unwrap()
            .unwrap();
        (t.critical_mass_parameter, t.whirl_ratio)
    };
    for e in [0.2, 0.5] {
        let (m1, _) = mass(e, 0.5);
        let (m2, _) = mass(e, 0.05);
        let (m3, g3) = mass(e, 0.005);
        assert!(m2 < 0.2 * m1 && m3 < 0.2 * m2, "ε {e}: {m1} {m2} {m3}");
        assert!(m3 > 0.0, "{m3}");
        let ratio = (m2 / 0.05) / (m3 / 0.005);
        assert!((0.8..1.25).contains(&ratio), "ε {e}: M̄/Λ {ratio}");
        assert!((g3 - 0.5).abs() < 0.06, "ε {e}: γ {g3}");
    }
}

/// Lund's threshold is the Routh–Hurwitz boundary of the rotor on coefficients frozen at the
/// threshold's whirl ratio (`journal::dynamics`): stable just below M̄_c, unstable just above.
#[test]
fn the_threshold_is_the_routh_hurwitz_boundary_at_its_whirl_ratio() {
    use crate::calc::journal::dynamics::routh_hurwitz_stable;
    for (e, lambda) in [(0.4, 0.42), (0.3, 3.0)] {
        let f = film(e, lambda, 1.0);
        let t = threshold(&f, &standard(&f), &Budget::unlimited())
            .unwrap()
            .unwrap();
        let m = t.critical_mass_parameter;
        assert!(routh_hurwitz_stable(&t.at.coefficients, 0.99 * m));
        assert!(!routh_hurwitz_stable(&t.at.coefficients, 1.01 * m));
    }
}
