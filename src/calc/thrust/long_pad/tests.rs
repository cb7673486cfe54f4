use super::*;
use crate::calc::turbulence::{turbulent_flow_factors, turbulent_shear_factor};
use crate::numerics::optimise::brent_minimise;

fn close(what: &str, got: f64, want: f64, relative: f64) {
    assert!(
        (got - want).abs() <= relative * want.abs(),
        "{what}: got {got}, want {want} (±{relative:e} relative)"
    );
}

/// The plane pad's closed forms, Khonsari & Booser Table 6.2 (per unit width, λ = h1/h2).
fn plane_closed_form(l: f64) -> (f64, f64, f64, f64, f64) {
    let ln = l.ln();
    let load = 6.0 * (ln - 2.0 * (l - 1.0) / (l + 1.0)) / (l - 1.0).powi(2);
    let friction = (4.0 * ln - 6.0 * (l - 1.0) / (l + 1.0)) / (l - 1.0);
    let x_cp = 0.5
        * (2.0 * l / (l - 1.0)
            - (l * l - 1.0 - 2.0 * l * ln) / ((l * l - 1.0) * ln - 2.0 * (l - 1.0).powi(2)));
    let hm = 2.0 * l / (l + 1.0);
    // P̄ = 6 (λ − h̄)(h̄ − 1)/(h̄² (λ² − 1)), largest at h̄ = h̄_m.
    let p_max = 6.0 * (l - hm) * (hm - 1.0) / (hm * hm * (l * l - 1.0));
    (load, friction, x_cp, 0.5 * hm, p_max)
}

#[test]
fn plane_pad_matches_table_6_2_closed_forms() {
    for l in [1.01, 1.2, 1.5, 2.0, 2.2, 3.0, 4.0, 6.0, 10.0] {
        let got = performance(Profile::PlaneInclined { ratio: l }, Flow::Laminar);
        let (load, friction, x_cp, flow, p_max) = plane_closed_form(l);
        // The closed forms lose digits to cancellation near λ = 1 (ln λ − 2(λ−1)/(λ+1) ~ (λ−1)³).
        let tol = if l < 1.1 { 1e-7 } else { 1e-12 };
        close(&format!("W̄ at λ = {l}"), got.load, load, tol);
        close(&format!("F̄ at λ = {l}"), got.friction, friction, tol);
        close(
            &format!("x̄_cp at λ = {l}"),
            got.center_of_pressure,
            x_cp,
            tol,
        );
        close(&format!("Q̄ at λ = {l}"), got.inlet_flow, flow, 1e-13);
        close(&format!("P̄_max at λ = {l}"), got.max_pressure, p_max, 1e-9);
    }
}

#[test]
fn plane_pad_optimum_is_stachowiak_r4_1() {
    // Stachowiak & Batchelor §4.3 (spec R4.1): the load peaks at K = h1/h0 − 1 = 1.189 with
    // 6W* = W̄ = 0.160243; at K = 1.2, W* = 0.026707 and F* = 0.75319.
    let (ratio, neg) = brent_minimise(
        |a| -performance(Profile::PlaneInclined { ratio: a }, Flow::Laminar).load,
        1.5,
        3.0,
        1e-10,
    );
    assert!((ratio - 2.189).abs() < 5e-4, "optimum λ {ratio}");
    close("W̄ at the optimum", -neg, 0.160243, 1e-5);
    let at = performance(Profile::PlaneInclined { ratio: 2.2 }, Flow::Laminar);
    close("W* at K = 1.2", at.load / 6.0, 0.026707, 2e-5);
    close("F* at K = 1.2", at.friction, 0.75319, 1e-5);
}

#[test]
fn plane_pad_pivot_matches_stachowiak_table_4_2() {
    // Table 4.2: the centre of pressure measured from the trailing edge, X/B, against
    // K = h1/h0 − 1 (spec R4.2: all 15 entries reproduced to 3 decimals).
    let table = [
        (0.2, 0.482),
        (0.4, 0.466),
        (0.6, 0.453),
        (0.8, 0.442),
        (1.0, 0.431),
        (1.2, 0.422),
        (1.4, 0.414),
        (1.6, 0.406),
        (1.8, 0.399),
        (2.0, 0.393),
        (2.2, 0.387),
        (2.4, 0.381),
        (2.6, 0.376),
        (2.8, 0.371),
        (3.0, 0.366),
    ];
    for (k, from_trailing) in table {
        let got = 1.0
            - performance(Profile::PlaneInclined { ratio: 1.0 + k }, Flow::Laminar)
                .center_of_pressure;
        assert!(
            (got - from_trailing).abs() <= 0.0005 + 1e-12,
            "X/B at K = {k}: got {got:.5}, table {from_trailing}"
        );
    }
}

#[test]
fn rayleigh_step_matches_its_closed_form_and_optimum() {
    // Khonsari & Booser §6.7 (Eq. 6.53–6.73): W̄ = 3 b2 (1 − b2)(λ − 1)/(b2 λ³ + 1 − b2) with
    // b2 = B2/B the thin (outlet) length; Stachowiak & Batchelor B3: p_max = 6 U η (h1 − h0) /
    // (h1³/B1 + h0³/B2).
    for (l, s) in [(1.5, 0.3), (1.866, 0.718), (2.5, 0.55), (4.0, 0.8)] {
        let got = performance(
            Profile::Step {
                ratio: l,
                step_position: s,
            },
            Flow::Laminar,
        );
        let b2 = 1.0 - s;
        let load = 3.0 * b2 * (1.0 - b2) * (l - 1.0) / (b2 * l.powi(3) + 1.0 - b2);
        close("step W̄", got.load, load, 1e-12);
        let p_max = 6.0 * (l - 1.0) / (l.powi(3) / s + 1.0 / b2);
        close("step P̄_max", got.max_pressure, p_max, 1e-12);
        close("step x̄ of the peak", got.max_pressure_position, s, 1e-12);
        // A triangle: the centre of pressure is its centroid.
        close("step x̄_cp", got.center_of_pressure, (s + 1.0) / 3.0, 1e-12);
    }
    // The optimum (spec: λ = 1.86603, B1/B2 = 2.54904, C_L = 0.206267).
    let optimum = 1.0 + 3f64.sqrt() / 2.0;
    let b1_over_b2 = optimum.powf(1.5);
    let got = performance(
        Profile::Step {
            ratio: optimum,
            step_position: b1_over_b2 / (1.0 + b1_over_b2),
        },
        Flow::Laminar,
    );
    close("optimum step W̄", got.load, 0.206267, 2e-6);
}

#[test]
fn stachowiak_problem_4_23_step_load_and_runner_friction() {
    // Spec R4.11: B1 = 0.6 B, B2 = 0.4 B, B = 0.2 m, h0 = 15 µm, Δh = 5 µm, η = 5 mPa·s,
    // U = 10 m/s: W/L = 1.37799 MN/m, p_max = 13.78 MPa. Friction (the book's 719.89 N/m is
    // wrong): the spec recomputes 532 and 601 N/m on the two surfaces, 566.7 N/m of it Couette;
    // the runner carries the Couette shear plus (h1 − h2) p_max/2 = 601.1 N/m (its friction is
    // the one whose power E = F U Table 7.2's K_f gives), the pad 532.
    let (b, h2, eta, u) = (0.2, 15e-6, 5e-3, 10.0);
    let got = performance(
        Profile::Step {
            ratio: 20.0 / 15.0,
            step_position: 0.6,
        },
        Flow::Laminar,
    );
    close(
        "W/L",
        got.load * eta * u * b * b / (h2 * h2),
        1.37799e6,
        1e-5,
    );
    close(
        "p_max",
        got.max_pressure * eta * u * b / (h2 * h2),
        13.78e6,
        5e-4,
    );
    let runner = got.friction * eta * u * b / h2;
    close("F/L on the runner", runner, 601.1, 1e-3);
    let couette = couette_shear(
        Profile::Step {
            ratio: 20.0 / 15.0,
            step_position: 0.6,
        },
        Flow::Laminar,
    ) * eta
        * u
        * b
        / h2;
    close("Couette part", couette, 566.7, 1e-3);
    close("F/L on the pad", 2.0 * couette - runner, 532.0, 1e-3);
}

#[test]
fn tapered_land_optimum_is_stachowiak_r4_6() {
    // Stachowiak & Batchelor §4.3 (spec R4.6): B1/B = 0.8, h1/h0 = 2.25 gives 6W* = 0.1923.
    let got = performance(
        Profile::TaperedLand {
            ratio: 2.25,
            land_fraction: 0.2,
        },
        Flow::Laminar,
    );
    close("tapered-land W̄", got.load, 0.1923, 2e-4);
}

/// The same numbers by brute force: P̄ by a fine cumulative trapezoid of dP̄/dx̄ with h̄_m from
/// the edge condition, then the moments — an independent check of the by-parts identities.
/// A turbulent film at trailing-edge Re₂ scales the Poiseuille flow by g = 12 G_x(Re₂ h̄) and
/// the Couette shear by G_f(Re₂ h̄) (Ng–Pan, Eq. 6.26–6.31; Re₂ = 0 is laminar).
fn brute_force(profile: Profile, re2: f64) -> (f64, f64, f64) {
    let n = 200_000;
    let dx = 1.0 / n as f64;
    let xs: Vec<f64> = (0..=n).map(|i| (i as f64 + 0.5) * dx).take(n).collect();
    let h: Vec<f64> = xs.iter().map(|&x| profile.thickness(x)).collect();
    let g = |h: f64| turbulent_flow_factors(re2 * h).0;
    let i2: f64 = h.iter().map(|&h| h.powi(-2) / g(h)).sum::<f64>() * dx;
    let i3: f64 = h.iter().map(|&h| h.powi(-3) / g(h)).sum::<f64>() * dx;
    let hm = i2 / i3;
    let (mut p, mut load, mut moment, mut friction) = (0.0, 0.0, 0.0, 0.0);
    for (&x, &h) in xs.iter().zip(&h) {
        let dp = 6.0 * (h - hm) / (g(h) * h.powi(3));
        let mid = p + 0.5 * dp * dx;
        load += mid * dx;
        moment += mid * x * dx;
        friction += (turbulent_shear_factor(re2 * h) / h + 0.5 * h * dp) * dx;
        p += dp * dx;
    }
    (load, moment / load, friction)
}

/// The profiles the brute-force and turbulent checks run over.
fn shapes() -> [Profile; 6] {
    [
        Profile::Parabolic { ratio: 2.0 },
        Profile::Parabolic { ratio: 8.0 },
        Profile::TaperedLand {
            ratio: 3.0,
            land_fraction: 0.3,
        },
        Profile::Step {
            ratio: 2.0,
            step_position: 0.4,
        },
        Profile::PlaneInclined { ratio: 2.0 },
        Profile::PlaneInclined { ratio: 10.0 },
    ]
}

fn turbulent(re2: f64) -> Flow {
    Flow::Turbulent {
        reference_reynolds: re2,
    }
}

/// Laminar (Re₂ = 0) and turbulent films against the brute-force integration.
#[test]
fn every_profile_agrees_with_brute_force_integration() {
    for re2 in [0.0, 500.0, 3000.0, 20000.0] {
        let flow = if re2 == 0.0 {
            Flow::Laminar
        } else {
            turbulent(re2)
        };
        for profile in shapes() {
            let got = performance(profile, flow);
            let (load, x_cp, friction) = brute_force(profile, re2);
            let what = format!("{profile:?} at Re₂ = {re2}");
            close(&format!("{what} W̄"), got.load, load, 1e-6);
            close(&format!("{what} x̄_cp"), got.center_of_pressure, x_cp, 1e-6);
            close(&format!("{what} F̄"), got.friction, friction, 1e-6);
        }
    }
}

#[test]
fn a_turbulent_film_at_zero_reynolds_number_is_the_laminar_one_bit_for_bit() {
    for profile in shapes() {
        assert_eq!(
            performance(profile, turbulent(0.0)),
            performance(profile, Flow::Laminar),
            "{profile:?}"
        );
    }
}

#[test]
fn a_turbulent_rayleigh_step_is_the_laminar_closed_form_with_each_lands_conductance() {
    // On each land the film is uniform, so the Ng–Pan factors are constant there and the
    // laminar closed form (Khonsari & Booser §6.7) holds with each land's Poiseuille term
    // scaled: P̄_max = 6 b1 b2 (λ − 1)/(b1 g₁ + b2 g_λ λ³) with g = 12 G_x(Re₂ h̄) (g = 1 is
    // Eq. 6.73), W̄ = P̄_max/2, x̄_cp the triangle's centroid, h̄_m = 1 + P̄_max g₁/(6 b2), and
    // F̄ = b1 G_f(λ)/λ + b2 G_f(1) + (λ − 1) P̄_max/2.
    for re2 in [300.0, 1000.0, 3000.0, 1e4, 1e5] {
        for (l, s) in [(1.5, 0.3), (1.866, 0.718), (2.5, 0.55), (4.0, 0.8)] {
            let got = performance(
                Profile::Step {
                    ratio: l,
                    step_position: s,
                },
                turbulent(re2),
            );
            let (b1, b2) = (s, 1.0 - s);
            let (g1, gl) = (
                turbulent_flow_factors(re2).0,
                turbulent_flow_factors(re2 * l).0,
            );
            let p_max = 6.0 * b1 * b2 * (l - 1.0) / (b1 * g1 + b2 * gl * l.powi(3));
            let what = format!("λ {l}, x̄_s {s}, Re₂ {re2}");
            close(&format!("{what} W̄"), got.load, 0.5 * p_max, 1e-12);
            close(&format!("{what} P̄_max"), got.max_pressure, p_max, 1e-12);
            close(
                &format!("{what} x̄_cp"),
                got.center_of_pressure,
                (s + 1.0) / 3.0,
                1e-12,
            );
            let hm = 1.0 + p_max * g1 / (6.0 * b2);
            close(&format!("{what} Q̄"), got.inlet_flow, 0.5 * hm, 1e-12);
            let friction = b1 * turbulent_shear_factor(re2 * l) / l
                + b2 * turbulent_shear_factor(re2)
                + 0.5 * (l - 1.0) * p_max;
            close(&format!("{what} F̄"), got.friction, friction, 1e-12);
        }
    }
}

#[test]
fn turbulence_raises_load_and_friction_monotonically_with_reynolds_number() {
    // The Ng–Pan factors lower the Poiseuille conductance and raise the Couette shear as Re
    // grows: at a fixed film W̄ and F̄ rise with Re₂, from the laminar values at Re₂ = 0.
    for profile in shapes() {
        let mut last = performance(profile, Flow::Laminar);
        for re2 in [100.0, 300.0, 1000.0, 3000.0, 1e4, 1e5] {
            let got = performance(profile, turbulent(re2));
            assert!(got.load > last.load, "{profile:?} W̄ at Re₂ {re2}");
            assert!(got.friction > last.friction, "{profile:?} F̄ at Re₂ {re2}");
            last = got;
        }
    }
}

/// The closed-form centre of pressure the pivot's root uses agrees with the quadrature's over
/// the film ratios a pad may have.
#[test]
fn the_plane_pads_closed_form_centre_of_pressure_is_the_quadratures() {
    for k in 0..=200 {
        let a = 1.01 * (10.0f64 / 1.01).powf(k as f64 / 200.0);
        let quadrature = performance(Profile::PlaneInclined { ratio: a }, Flow::Laminar);
        close(
            &format!("x_cp at a = {a}"),
            plane_center_of_pressure(a),
            quadrature.center_of_pressure,
            1e-8,
        );
    }
}
