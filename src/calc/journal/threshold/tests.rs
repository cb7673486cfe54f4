//! The whirl threshold against the eigenvalues of the rotor–film system, its limits, and the
//! film models against each other.

use super::*;
use crate::calc::journal::dynamics::{least_stable_mode, rotor_eigenvalues, routh_hurwitz_stable};

fn short(eps: f64) -> Coefficients {
    let (stiffness, damping) = closed_form::short_bearing_dynamic_coefficients(eps);
    Coefficients {
        stiffness,
        damping,
        sommerfeld_number: f64::NAN,
    }
}

fn full(eps: f64) -> Coefficients {
    let (stiffness, damping) = closed_form::short_full_sommerfeld_dynamic_coefficients(eps);
    Coefficients {
        stiffness,
        damping,
        sommerfeld_number: f64::NAN,
    }
}

fn finite(eps: f64, l_over_d: f64) -> Coefficients {
    let Method::Numerical { mesh, stop, .. } = Method::numerical(Level::Standard, None, None)
    else {
        unreachable!()
    };
    dynamics::perturbation(
        EccentricityRatio::new(eps).unwrap(),
        l_over_d,
        FilmModel::REYNOLDS,
        mesh,
        stop,
        &mut crate::calc::journal::performance::FilmStart::default(),
        &Budget::unlimited(),
    )
    .unwrap()
}

/// Lund's critical mass parameter (Routh–Hurwitz's Δ₃ = 0) is where an eigenvalue pair of the
/// 4×4 system m ẍ + C ẋ + K x = 0 crosses the imaginary axis, at the whirl frequency: at M̄_c
/// the least damped pair has Re s = 0 and |Im s| = γ; 1 % lighter every mode decays, 1 %
/// heavier one grows; and the Routh–Hurwitz test of one rotor says the same. Swept over ε for
/// the short bearing, and at three ε for the finite film at L/D = 1.
#[test]
fn lund_threshold_is_where_an_eigenvalue_pair_crosses_the_axis() {
    let short_sweep = [0.01, 0.05, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.74]
        .map(|e| (format!("short ε = {e}"), short(e)));
    let finite_sweep = [0.1, 0.3, 0.5].map(|e| (format!("finite L/D 1 ε = {e}"), finite(e, 1.0)));
    for (what, c) in short_sweep.iter().chain(&finite_sweep) {
        let w = dynamics::whirl(c);
        let mc = w.critical_mass_parameter.expect("these films whirl");
        let gamma = w.whirl_frequency_ratio.expect("a whirl frequency");
        let (re, im) = least_stable_mode(c, mc);
        assert!(re.abs() < 1e-8, "{what}: Re s = {re} at M̄_c = {mc}");
        assert!(
            (im - gamma).abs() < 1e-8,
            "{what}: |Im s| = {im}, γ = {gamma}"
        );
        for (factor, stable) in [(0.99, true), (1.01, false)] {
            let m = factor * mc;
            let grows = rotor_eigenvalues(c, m).iter().any(|s| s.re > 0.0);
            assert_eq!(!grows, stable, "{what}: eigenvalues at {factor} M̄_c");
            assert_eq!(
                routh_hurwitz_stable(c, m),
                stable,
                "{what}: Routh–Hurwitz at {factor} M̄_c"
            );
        }
    }
}

/// The light-load limit: the half-Sommerfeld short bearing whirls at half the running speed
/// as ε → 0 (γ = 0.5 to 10⁻⁶ at ε = 10⁻⁴), with M̄_c → 24/π (k_eq → 6/π, γ² → 1/4).
/// The heavy-load limit: above ε* the film cannot whirl at all (γ² ≤ 0: no mass is unstable).
/// ε* is found here by bisection of γ² and checked by eigenvalues on both sides: ε* = 0.7557
/// (the literature's "about 0.75" for the short π film).
#[test]
fn half_frequency_at_light_load_and_no_whirl_above_a_heavy_eccentricity() {
    let light = dynamics::whirl(&short(1e-4));
    let gamma = light.whirl_frequency_ratio.unwrap();
    assert!((gamma - 0.5).abs() < 1e-6, "γ at ε = 1e-4: {gamma}");
    let mc = light.critical_mass_parameter.unwrap();
    assert!((mc - 24.0 / PI).abs() < 1e-3, "M̄_c at ε = 1e-4: {mc}");

    let whirls = |e: f64| dynamics::whirl(&short(e)).whirl_frequency_ratio.is_some();
    let (mut lo, mut hi) = (0.5, 0.9);
    assert!(whirls(lo) && !whirls(hi));
    while hi - lo > 1e-6 {
        let mid = 0.5 * (lo + hi);
        if whirls(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let eps_star = 0.5 * (lo + hi);
    assert!(
        (eps_star - 0.7557).abs() < 5e-4,
        "the short π film stops whirling at ε = {eps_star}"
    );
    // Above: every mass, from a feather to a locomotive, decays.
    let above = short(eps_star + 0.005);
    for m in [1e-3, 0.1, 1.0, 10.0, 1e3, 1e6] {
        let (re, _) = least_stable_mode(&above, m);
        assert!(re < 0.0, "ε* + 0.005, M̄ = {m}: Re s = {re}");
    }
    // Below: a heavy enough rotor whirls.
    let below = short(eps_star - 0.005);
    let mc = dynamics::whirl(&below).critical_mass_parameter.unwrap();
    assert!(mc > 100.0, "M̄_c just below ε*: {mc}");
    assert!(least_stable_mode(&below, 1.01 * mc).0 > 0.0);
}

/// The full film: k_eq = 0, M̄_c = 0 and γ = 1/2 at every ε, and every mass has a growing
/// mode (the eigenvalues, not only Lund's formula).
#[test]
fn the_full_film_whirls_for_every_mass() {
    for eps in [0.01, 0.1, 0.5, 0.9, 0.99] {
        let c = full(eps);
        let w = dynamics::whirl(&c);
        assert_eq!(w.critical_mass_parameter, Some(0.0), "ε = {eps}");
        let gamma = w.whirl_frequency_ratio.unwrap();
        assert!((gamma - 0.5).abs() < 1e-12, "ε = {eps}: γ = {gamma}");
        for m in [1e-3, 0.1, 1.0, 10.0, 1e3] {
            let (re, im) = least_stable_mode(&c, m);
            assert!(re > 0.0, "ε = {eps}, M̄ = {m}: Re s = {re}");
            assert!(im > 0.0 && im < 0.5 + 1e-9, "ε = {eps}, M̄ = {m}: ν = {im}");
            assert!(!routh_hurwitz_stable(&c, m));
        }
    }
}

/// A narrow bearing: D = 0.1 m, L/D = 0.1, R/C = 500, μ = 0.02 Pa·s, W = 15 N.
fn narrow(film: WhirlFilm) -> Rotor {
    Rotor {
        diameter_m: 0.1,
        length_m: 0.01,
        radial_clearance_m: 1e-4,
        viscosity_pa_s: 0.02,
        load_n: 15.0,
        film,
    }
}

fn standard() -> WhirlFilm {
    WhirlFilm::Finite(Method::numerical(Level::Standard, None, None))
}

/// The two searches invert each other: the threshold speed of the threshold mass at a speed
/// is that speed (closed form to 10⁻⁴, the finite film to 10⁻³: the search's tolerance).
#[test]
fn threshold_mass_and_threshold_speed_invert_each_other() {
    let budget = Budget::unlimited();
    for (film, tolerance) in [(WhirlFilm::ShortPiFilm, 1e-4), (standard(), 2e-3)] {
        let rotor = narrow(film);
        let (at, _) = rotor.at_speed(3000.0, &budget).unwrap();
        let mass = at.threshold_mass_kg.unwrap();
        let (found, _) = rotor.threshold_speed(mass, &budget).unwrap();
        let SpeedThreshold::Found(state) = found else {
            panic!("{film:?}: {found:?}")
        };
        assert!(
            (state.speed_rpm / 3000.0 - 1.0).abs() < tolerance,
            "{film:?}: {} rev/min back from {mass} kg",
            state.speed_rpm
        );
        assert!((state.eccentricity_ratio / at.state.eccentricity_ratio - 1.0).abs() < tolerance);
    }
}

/// `finite` tends to the short bearing as L/D → 0: at L/D = 0.1 the Reynolds-condition film's
/// threshold mass at 3000 rev/min, and the threshold speed of 1.5 times that mass, are within
/// 1 % of the half-Sommerfeld short bearing's (found: 0.34 % and 0.01 %), its whirl ratio
/// within 0.01.
#[test]
fn finite_film_tends_to_the_short_bearing_at_small_length() {
    let budget = Budget::unlimited();
    let (short_at, _) = narrow(WhirlFilm::ShortPiFilm)
        .at_speed(3000.0, &budget)
        .unwrap();
    let (finite_at, _) = narrow(standard()).at_speed(3000.0, &budget).unwrap();
    let (ms, mf) = (
        short_at.threshold_mass_kg.unwrap(),
        finite_at.threshold_mass_kg.unwrap(),
    );
    eprintln!(
        "L/D 0.1 at 3000 rev/min: ε {:.4} / {:.4}, m_c {ms:.4} / {mf:.4} kg, γ {:?} / {:?}",
        short_at.state.eccentricity_ratio,
        finite_at.state.eccentricity_ratio,
        short_at.state.whirl.whirl_frequency_ratio,
        finite_at.state.whirl.whirl_frequency_ratio
    );
    assert!((mf / ms - 1.0).abs() < 0.01, "threshold mass {mf} vs {ms}");
    let (gs, gf) = (
        short_at.state.whirl.whirl_frequency_ratio.unwrap(),
        finite_at.state.whirl.whirl_frequency_ratio.unwrap(),
    );
    assert!((gf - gs).abs() < 0.01, "γ {gf} vs {gs}");
    let speed = |film| match narrow(film).threshold_speed(1.5 * ms, &budget).unwrap().0 {
        SpeedThreshold::Found(s) => s.speed_rpm,
        other => panic!("{other:?}"),
    };
    let (ns, nf) = (speed(WhirlFilm::ShortPiFilm), speed(standard()));
    eprintln!(
        "threshold speed of {:.4} kg: {ns:.1} / {nf:.1} rev/min",
        1.5 * ms
    );
    assert!((nf / ns - 1.0).abs() < 0.01, "threshold speed {nf} vs {ns}");
}

/// The fixed arc and the π film answer alike; the full film's threshold is 0 at every speed.
#[test]
fn film_models_answer_as_documented() {
    let budget = Budget::unlimited();
    let (pi, _) = narrow(WhirlFilm::ShortPiFilm)
        .at_speed(3000.0, &budget)
        .unwrap();
    let (arc, _) = narrow(WhirlFilm::ShortFixedArc)
        .at_speed(3000.0, &budget)
        .unwrap();
    assert_eq!(pi.threshold_mass_kg, arc.threshold_mass_kg);
    assert_eq!(pi.state.coefficients, arc.state.coefficients);
    let full_rotor = narrow(WhirlFilm::ShortFull);
    let (full_at, _) = full_rotor.at_speed(3000.0, &budget).unwrap();
    assert_eq!(full_at.threshold_mass_kg, Some(0.0));
    assert!(matches!(
        full_rotor.threshold_speed(1.0, &budget).unwrap().0,
        SpeedThreshold::EverySpeed
    ));
}
