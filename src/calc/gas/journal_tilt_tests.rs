//! The misaligned gas journal: a vanishing tilt against the half-length film, small-ε linear
//! theory (Ausman's perturbation, in Khonsari & Booser's normalisation of Fig. 11.15), the
//! Λ → 0 limit against the liquid room's tilted full film, the Richardson estimate of the
//! moment, and the refusal of a film that touches.

use super::tests::{film, incompressible_film, method, reference, C};
use super::*;
use crate::calc::journal::film::{self as liquid, FilmModel};
use crate::numerics::reynolds as incompressible;
use crate::numerics::reynolds::Stopping;

fn tilted(e: f64, lambda: f64, l_over_d: f64, tilt: f64, direction: f64) -> JournalFilm {
    JournalFilm {
        tilt: Some((tilt, direction)),
        ..film(e, lambda, l_over_d)
    }
}

fn magnitude(m: [f64; 2]) -> f64 {
    m[0].hypot(m[1])
}

/// Ausman's M̄ = 12 C M/(π p_a R L³ β) = 12 |M|/(π p_a R L² ε′) of a performance.
fn moment_coefficient(p: &JournalPerformance, tilt: f64) -> f64 {
    12.0 * magnitude(p.moment) / (PI * tilt)
}

/// Ausman's small-ε moment coefficient by linear theory. At ε → 0 the tilt alone makes
/// H = 1 + a(u) cos θ′, a = −ε′u/(2w), u = y − w, w = L/D, θ′ = θ − θ_δ; P = 1 + Re(g(u) e^{iθ′})
/// with g″ − (1 + iΛ) g = iΛ a, g(±w) = 0: g = c (u − w sinh κu/sinh κw), κ = √(1 + iΛ),
/// c = iΛ ε′/(2w(1 + iΛ)). The moment is π p_a R³ |∫ g u du| with
/// ∫ g u du = c (2w³/3 − 2w²/(κ tanh κw) + 2w/κ²), so M̄ = 3 |∫ g u du|/(ε′ w²), tending to 1
/// as Λ → ∞.
fn linear_moment_coefficient(lambda: f64, w: f64) -> f64 {
    let k = C(1.0, lambda).sqrt();
    let c = C(0.0, lambda).div(C(2.0 * w, 2.0 * w * lambda));
    let ktanh = k.mul(k.mul(C(w, 0.0)).tanh());
    let integral = C(2.0 * w * w * w / 3.0, 0.0)
        .add(C(-2.0 * w * w, 0.0).div(ktanh))
        .add(C(2.0 * w, 0.0).div(k.mul(k)));
    3.0 * c.mul(integral).abs() / (w * w)
}

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

/// A tilt placed against the load line, `direction` from it (rad).
fn from_load_line(tilt: f64, direction: f64) -> Misalignment {
    Misalignment {
        tilt,
        direction,
        from_line_of_centres: false,
    }
}

/// (a) A vanishing tilt: the whole-length film (the half grid mirrored, both ends held) is the
/// half-length film (symmetry plane), to the Newton tolerance, with no moment.
#[test]
fn a_vanishing_tilt_solves_the_half_length_film_on_the_whole_length() {
    let budget = Budget::unlimited();
    for (e, lambda) in [(0.6, 5.0), (0.3, 0.1), (0.8, 200.0)] {
        let half = evaluate(
            &film(e, lambda, 1.0),
            method(Level::Standard),
            None,
            &budget,
        )
        .unwrap();
        let whole = evaluate(
            &tilted(e, lambda, 1.0, 0.0, 1.0),
            method(Level::Standard),
            None,
            &budget,
        )
        .unwrap();
        let (a, b) = (half.performance, whole.performance);
        for (x, y, what) in [
            (a.load_along, b.load_along, "W̄1"),
            (a.load_across, b.load_across, "W̄2"),
            (a.friction_journal, b.friction_journal, "F̄ journal"),
            (a.friction_bearing, b.friction_bearing, "F̄ bearing"),
            (a.max_pressure, b.max_pressure, "P max"),
        ] {
            assert!(rel(y, x) < 1e-9, "ε {e} Λ {lambda} {what}: {y} vs {x}");
        }
        assert!(magnitude(b.moment) < 1e-12 * a.load(), "{:?}", b.moment);
        // Node by node: the whole grid's first half is the half grid, its second the mirror.
        let (g, h) = (&whole.fine.grid, &half.fine.grid);
        let ny = h.y.len() - 1;
        assert_eq!(g.y.len(), 2 * ny + 1);
        for i in 0..=g.nx() {
            for j in 0..=ny {
                let p = half.fine.p[h.at(i, j)];
                assert!((whole.fine.p[g.at(i, j)] - p).abs() < 1e-9 * p);
                assert!((whole.fine.p[g.at(i, 2 * ny - j)] - p).abs() < 1e-9 * p);
            }
        }
    }
}

/// (a) The moment vanishes linearly with the tilt: M/ε′ is the same for ε′ = 1e-3, 2e-3 and
/// 4e-3 (M is odd in ε′, the film mirrored end for end, so M/ε′ = a + O(ε′²)), and the load
/// moves only at second order.
#[test]
fn the_moment_is_linear_in_a_small_tilt() {
    let budget = Budget::unlimited();
    for (e, lambda) in [(0.4, 0.42), (0.6, 10.0)] {
        let aligned = evaluate(&film(e, lambda, 1.0), method(Level::Fast), None, &budget)
            .unwrap()
            .performance;
        let per_tilt: Vec<[f64; 2]> = [1e-3, 2e-3, 4e-3]
            .iter()
            .map(|&t| {
                let p = evaluate(
                    &tilted(e, lambda, 1.0, t, 2.0),
                    method(Level::Fast),
                    None,
                    &budget,
                )
                .unwrap()
                .performance;
                assert!(
                    rel(p.load(), aligned.load()) < 1e-4,
                    "{} vs {}",
                    p.load(),
                    aligned.load()
                );
                [p.moment[0] / t, p.moment[1] / t]
            })
            .collect();
        let m = magnitude(per_tilt[0]);
        assert!(m > 0.0);
        for q in &per_tilt[1..] {
            let d = magnitude([q[0] - per_tilt[0][0], q[1] - per_tilt[0][1]]);
            assert!(d < 1e-4 * m, "ε {e} Λ {lambda}: {q:?} vs {:?}", per_tilt[0]);
        }
    }
}

/// At small ε and small tilt the moment is Ausman's perturbation result, the basis of Fig.
/// 11.15, in Khonsari & Booser's normalisation M̄ = 12 C M/(π p_a R L³ β)
/// ([`linear_moment_coefficient`]), for L/D 0.5–2 and Λ from 0.42 (Ex 11.4) to 100.
#[test]
fn small_eccentricity_follows_ausmans_linear_theory() {
    let budget = Budget::unlimited();
    for (lambda, w) in [(0.42, 1.0), (1.0, 0.5), (10.0, 1.0), (100.0, 2.0)] {
        let want = linear_moment_coefficient(lambda, w);
        let tilt = 1e-3;
        let got = evaluate(
            &tilted(1e-4, lambda, w, tilt, 1.0),
            method(Level::High),
            None,
            &budget,
        )
        .unwrap();
        let m = moment_coefficient(&got.performance, tilt);
        assert!(rel(m, want) < 3e-3, "Λ {lambda} L/D {w}: M̄ {m} vs {want}");
    }
    // The normalisation's limits: M̄ → 0 with Λ, → 1 as Λ → ∞.
    assert!(linear_moment_coefficient(1e-3, 1.0) < 1e-3);
    assert!((linear_moment_coefficient(1e6, 1.0) - 1.0).abs() < 5e-3);
}

/// The gas film's moment and load per Λ against an incompressible film's (`want`: its moment
/// M/(p_a R L²) and W̄, per Λ), to 5e-3 of each.
fn assert_small_bearing_number_limit(
    gas: &JournalPerformance,
    lambda: f64,
    (moment, load): ([f64; 2], f64),
    whose: &str,
) {
    let got = gas.moment.map(|v| v / lambda);
    let scale = magnitude(moment);
    assert!(scale > 0.0);
    for k in 0..2 {
        assert!(
            (got[k] - moment[k]).abs() < 5e-3 * scale,
            "M/Λ {got:?} vs {whose} {moment:?}"
        );
    }
    let w = gas.load() / lambda;
    assert!(rel(w, load) < 5e-3, "W̄/Λ {w} vs {whose} {load}");
}

/// (b) Λ → 0: (P − 1)/Λ tends to the incompressible full film, so M/(p_a R L²)/Λ tends to the
/// liquid room's tilted full (Sommerfeld, no cavitation) film's moment over 12π (its pressure
/// scale μ N_s (R/C)² is p_a Λ/(12π)). The liquid film starts at h_max held at P̄ = 0; with the
/// tilt in the plane of the line of centres (θ_δ = 0 or π) the film is even in θ, its pressure
/// odd, and P̄ = 0 there anyway: the same film as the gas journal's periodic one.
#[test]
fn small_bearing_numbers_give_the_liquid_rooms_tilted_full_film() {
    let budget = Budget::unlimited();
    let lambda = 1e-3;
    for (e, tilt, direction) in [(0.5, 0.5, PI), (0.3, 1.0, 0.0)] {
        let gas = evaluate(
            &tilted(e, lambda, 1.0, tilt, direction),
            method(Level::High),
            None,
            &budget,
        )
        .unwrap()
        .performance;
        let liquid_film = liquid::Film {
            physics: FilmModel {
                cavitation: false,
                ..FilmModel::REYNOLDS
            },
            tilt: Some((tilt, direction)),
            ..liquid::Film::steady(e, 1.0)
        };
        let (solution, _) = liquid::solve(
            liquid_film,
            liquid::Mesh {
                circumferential: 256,
                axial_half: 32,
            },
            Stopping {
                tolerance: 1e-11,
                max_sweeps: 200_000,
            },
            None,
            &budget,
        )
        .unwrap();
        let want = solution.moment.map(|v| v / (12.0 * PI));
        // The force too: the liquid's ∫∫P̄ over the whole length per 12π against W̄/Λ.
        let w_liquid = solution.load_radial.hypot(solution.load_tangential) / (12.0 * PI) / 2.0;
        assert_small_bearing_number_limit(&gas, lambda, (want, w_liquid), "the liquid room's");
    }
}

/// (b) Λ → 0 with a tilt out of the line of centres' plane (where the liquid room's film, held
/// at P̄ = 0 along h_max, is not the periodic one): against the incompressible periodic full film
/// of the whole length solved directly on the basement (`numerics::reynolds`, one banded solve,
/// both ends at p = 0), ∂θ(H³∂θp) + ∂y(H³∂yp) = ∂θH with the tilted H: M/(p_a R L²)/Λ is
/// ∫∫ p (y − L/D)(sin θ, −cos θ) dθ dy/(2 L/D)², and W̄/Λ its force over 4 L/D.
#[test]
fn an_oblique_tilt_at_small_bearing_numbers_is_the_incompressible_periodic_film() {
    let budget = Budget::unlimited();
    let lambda = 1e-3;
    for (e, tilt, direction, w) in [(0.4, 0.6, 2.0, 1.0), (0.2, 1.2, -0.7, 0.5)] {
        let f = tilted(e, lambda, w, tilt, direction);
        let gas = evaluate(&f, method(Level::High), None, &budget)
            .unwrap()
            .performance;
        let h = |t: f64, y: f64| f.thickness(t, y);
        let (n, m) = (256, 64);
        let (grid, p) = incompressible_film(&h, 1.0, None, w, (n, m), true);
        let (mut force, mut moment) = ([0.0; 2], [0.0; 2]);
        for i in 0..n {
            let (s, c) = grid.x[i].sin_cos();
            for j in 0..=m {
                let v = grid.cv_x(i) * grid.cv_y(j) * p[incompressible::at(&grid, i, j)];
                let arm = grid.y(j) - w;
                force[0] -= v * c;
                force[1] -= v * s;
                moment[0] += v * arm * s;
                moment[1] -= v * arm * c;
            }
        }
        let want = moment.map(|v| v / (4.0 * w * w));
        let w_want = magnitude(force) / (4.0 * w);
        assert_small_bearing_number_limit(&gas, lambda, (want, w_want), "the basement's");
    }
}

/// (d) The moment's Richardson estimate bounds its error against a fine reference, from Λ = 1
/// to 100, and the fidelity levels converge.
#[test]
fn the_moment_error_estimate_brackets_its_error() {
    let budget = Budget::unlimited();
    for lambda in [1.0, 10.0, 100.0] {
        let f = tilted(0.5, lambda, 1.0, 0.5, 0.5 * PI);
        let reference = reference(&f, &budget).performance.moment;
        let mut errors = Vec::new();
        for level in [Level::Fast, Level::Standard, Level::High] {
            let got = evaluate(&f, method(level), None, &budget).unwrap();
            let m = got.performance.moment;
            let err = magnitude([m[0] - reference[0], m[1] - reference[1]]) / magnitude(reference);
            let estimate = got.moment_error_estimate.unwrap();
            println!("Λ {lambda} {level:?}: moment error {err:.2e}, estimate {estimate:.2e}");
            assert!(
                err <= estimate.max(2e-4),
                "Λ {lambda} {level:?}: error {err:e} above the estimate {estimate:e}"
            );
            errors.push(err);
        }
        assert!(errors[2] < errors[0], "{errors:?}");
    }
}

/// Placed against the load line, the tilt's direction is consistent with the film's attitude;
/// the opposite tilt mirrors the film end for end (the same force, the moment reversed); a
/// tilt that brings the film below [`MIN_FILM`] is refused at `/misalignment`.
#[test]
fn a_tilt_is_placed_against_the_attitude_and_a_touching_one_refused() {
    let budget = Budget::unlimited();
    let f = film(0.5, 2.0, 1.0);
    let a = evaluate_tilted(
        &f,
        from_load_line(0.6, 0.5),
        method(Level::Fast),
        None,
        &budget,
    )
    .unwrap();
    let (t, dir) = a.tilt.unwrap();
    assert_eq!(t, 0.6);
    let want = from_load_line(0.6, 0.5).film_direction(a.performance.attitude());
    assert!((dir - want).abs() < 1e-9, "{dir} vs {want}");
    let b = evaluate_tilted(
        &f,
        from_load_line(0.6, 0.5 - PI),
        method(Level::Fast),
        None,
        &budget,
    )
    .unwrap();
    let (pa, pb) = (a.performance, b.performance);
    assert!(rel(pb.load(), pa.load()) < 1e-8);
    assert!((pb.attitude() - pa.attitude()).abs() < 1e-8);
    for k in 0..2 {
        assert!((pa.moment[k] + pb.moment[k]).abs() < 1e-8 * magnitude(pa.moment));
    }
    // Towards h_min from the line of centres at ε = 0.6: the end's film 1 − 0.6 − 0.4 = 0.
    let touching = Misalignment {
        tilt: 0.8,
        direction: 0.0,
        from_line_of_centres: true,
    };
    let refused = evaluate_tilted(
        &film(0.6, 2.0, 1.0),
        touching,
        method(Level::Fast),
        None,
        &budget,
    );
    assert!(
        matches!(&refused, Err(CalcError::Impossible { pointer, .. }) if pointer == "/misalignment"),
        "{refused:?}"
    );
}

/// Ausman's chart is a small-ε perturbation result, said to hold to ε ≈ 0.5. At Ex 11.4's
/// Λ = 0.413 and L/D = 1 with a small tilt, the full film's M̄ stays within 3 % of the linear
/// theory up to ε = 0.4 (0.0250–0.0254 against 0.0251), is 16 % above it at 0.5 and twice it
/// at 0.6: the moment then grows with the thinning film as the load does.
#[test]
fn ausmans_small_eccentricity_moment_holds_to_about_half_the_clearance() {
    let budget = Budget::unlimited();
    let (lambda, tilt) = (0.413, 1e-3);
    let linear = linear_moment_coefficient(lambda, 1.0);
    let at = |e: f64| {
        let got = evaluate_tilted(
            &film(e, lambda, 1.0),
            from_load_line(tilt, 0.0),
            method(Level::Standard),
            None,
            &budget,
        )
        .unwrap();
        moment_coefficient(&got.performance, tilt)
    };
    for e in [0.1, 0.2, 0.3, 0.4] {
        let m = at(e);
        assert!(rel(m, linear) < 0.03, "ε {e}: M̄ {m} vs {linear}");
    }
    let (half, more) = (at(0.5), at(0.6));
    assert!(
        half > linear && rel(half, linear) < 0.2,
        "{half} vs {linear}"
    );
    assert!(more > 1.5 * linear, "{more} vs {linear}");
}
