//! Gas bearings: the speed targets (release, one core; the whole request through the room:
//! parse, validate, both meshes of the Richardson pair, continuation in Λ, envelope).
//! - the gas journal at `standard`, at a given ε: under 20 ms for Λ ≤ 100, under 100 ms at
//!   Λ = 1000;
//! - the gas journal by load (W = 300 N at Λ = 10, slip applied): 21.3 ms, 32 film solves (Brent
//!   on W̄(ε) took 28.3 ms, 48);
//! - the gas journal at `standard` with `dynamics` (ε = 0.6; coefficients at ν = ω and the
//!   whirl threshold: a 13-point scan of the whirl ratio and a secant per crossing, each ratio
//!   one harmonic band LU on each mesh): 45 ms at Λ = 1, 80 ms at Λ = 10 (the steady film alone
//!   2.0 and 2.5 ms);
//! - the misaligned gas journal at `standard` (ε = 0.6, ε′ = 0.5 in the load plane, auto slip
//!   applied): 51 ms at Λ = 1, 43 ms at Λ = 10 (the aligned film mirrored, then 2–4 placements
//!   of the tilt against the attitude, continuum and slip; each Newton step on the whole length
//!   costs 8× the half length's);
//! - the gas slider at `standard` (finite and infinitely wide): under 5 ms;
//! - the aerostatic pad and the foil journal (closed forms with one adaptive quadrature each);
//! - the tilting-pad journal at `standard` (Ex 11.6's bearing): 45 ms by load (6 secant steps
//!   in stretched ε′, 206 film solves; a plain secant in ε′ from C_LT(0) = 0 took 12 steps,
//!   322 solves, 78 ms), 9.6 ms at the ε′ found (two pads' tilt searches from cold);
//! - the tilting-pad thrust bearing (Ex 11.2's pads, slip applied by `auto`): 83 ms by load
//!   (the clearance searched on both meshes, then again with slip from there), 13 ms at the
//!   book's clearance.
//!
//! `cargo bench --bench gas`.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use stribeck::calc::find;

fn request(c: &mut Criterion, name: &str, path: &str, body: &str) {
    let entry = find(path).unwrap();
    let far = std::time::Instant::now() + std::time::Duration::from_secs(3600);
    c.bench_function(name, |b| {
        b.iter(|| (entry.execute)(black_box(body.as_bytes()), far, Default::default()).unwrap())
    });
}

fn gas(c: &mut Criterion) {
    let (mu, pa): (f64, f64) = (1.85e-5, 101_325.0);
    let (d, cl) = (0.05f64, 5e-6f64);
    for lambda in [1.0, 10.0, 100.0, 1000.0] {
        let omega = lambda * pa / (6.0 * mu * (0.5 * d / cl).powi(2));
        let rpm = omega * 30.0 / std::f64::consts::PI;
        request(
            c,
            &format!("gas journal L/D = 1, ε = 0.6, Λ = {lambda}, standard"),
            "/v1/gas-bearings/journal",
            &format!(
                r#"{{"geometry": {{"diameter_m": {d}, "length_m": {d}, "radial_clearance_m": {cl}}}, "speed_rpm": {rpm}, "gas": {{"viscosity_pa_s": {mu}, "ambient_pressure_pa": {pa}}}, "eccentricity_ratio": 0.6}}"#
            ),
        );
    }
    // By load: the secant in stretched ε (ε ≈ 0.59; `auto` applies slip at Kn = 0.034, so the
    // search runs on the continuum film and again with slip).
    let omega = 10.0 * pa / (6.0 * mu * (0.5 * d / cl).powi(2));
    let rpm = omega * 30.0 / std::f64::consts::PI;
    request(
        c,
        "gas journal L/D = 1, W = 300 N (ε ≈ 0.59), Λ = 10, standard, by load",
        "/v1/gas-bearings/journal",
        &format!(
            r#"{{"geometry": {{"diameter_m": {d}, "length_m": {d}, "radial_clearance_m": {cl}}}, "speed_rpm": {rpm}, "gas": {{"viscosity_pa_s": {mu}, "ambient_pressure_pa": {pa}}}, "load_n": 300}}"#
        ),
    );
    // With dynamics: the coefficients at ν = ω and the whirl threshold (a secant over the whirl
    // ratio, one band LU of the doubled harmonic system per ratio and mesh).
    for lambda in [1.0, 10.0] {
        let omega = lambda * pa / (6.0 * mu * (0.5 * d / cl).powi(2));
        let rpm = omega * 30.0 / std::f64::consts::PI;
        request(
            c,
            &format!("gas journal L/D = 1, ε = 0.6, Λ = {lambda}, standard, with dynamics"),
            "/v1/gas-bearings/journal",
            &format!(
                r#"{{"geometry": {{"diameter_m": {d}, "length_m": {d}, "radial_clearance_m": {cl}}}, "speed_rpm": {rpm}, "gas": {{"viscosity_pa_s": {mu}, "ambient_pressure_pa": {pa}}}, "eccentricity_ratio": 0.6, "dynamics": {{}}}}"#
            ),
        );
    }
    // Misaligned: the whole-length film (twice the axial cells), the tilt placed against the
    // attitude (a secant on φ), ε′ = βL/C = 0.5 in the load plane.
    for lambda in [1.0, 10.0] {
        let omega = lambda * pa / (6.0 * mu * (0.5 * d / cl).powi(2));
        let rpm = omega * 30.0 / std::f64::consts::PI;
        let slope = 0.5 * cl / d;
        request(
            c,
            &format!("gas journal L/D = 1, ε = 0.6, Λ = {lambda}, standard, misaligned ε′ = 0.5"),
            "/v1/gas-bearings/journal",
            &format!(
                r#"{{"geometry": {{"diameter_m": {d}, "length_m": {d}, "radial_clearance_m": {cl}}}, "speed_rpm": {rpm}, "gas": {{"viscosity_pa_s": {mu}, "ambient_pressure_pa": {pa}}}, "eccentricity_ratio": 0.6, "misalignment": {{"slope_rad": {slope}}}}}"#
            ),
        );
    }
    for (name, pad) in [
        ("L/B = 1", r#"{"breadth_m": 0.02, "length_m": 0.02}"#),
        ("infinitely wide", r#"{"breadth_m": 0.02}"#),
    ] {
        request(
            c,
            &format!("gas slider {name}, h1/h2 = 2, Λ = 8.8, standard"),
            "/v1/gas-bearings/slider",
            &format!(
                r#"{{"pad": {pad}, "inlet_film_m": 1e-5, "outlet_film_m": 5e-6, "sliding_speed_m_s": 10, "gas": {{"name": "air"}}}}"#
            ),
        );
    }
    for path in [
        "/v1/gas-bearings/aerostatic-pad",
        "/v1/gas-bearings/foil-journal",
    ] {
        let entry = find(path).unwrap();
        request(c, &format!("{path} (its example)"), path, entry.example);
    }
    // The tilting-pad journal (Ex 11.6's bearing, its example): by load (a secant in ε′, each
    // step two pads' tilt searches, each tilt both meshes), and at the ε′ found.
    let path = "/v1/gas-bearings/tilting-pad-journal";
    let example = find(path).unwrap().example;
    request(
        c,
        "tilting-pad gas journal (Ex 11.6), C_LT = 1.333, Λ = 1.5, standard, by load",
        path,
        example,
    );
    request(
        c,
        "tilting-pad gas journal (Ex 11.6), ε′ = 0.58, Λ = 1.5, standard",
        path,
        &example.replace(r#""load_n": 11.12"#, r#""eccentricity_ratio": 0.58"#),
    );
    // The tilting-pad thrust bearing (Ex 11.2's): by load (the clearance searched) and at a
    // clearance (each pad balanced in pitch and roll only).
    let path = "/v1/gas-bearings/tilting-pad-thrust";
    let example = find(path).unwrap().example;
    request(
        c,
        "gas tilting-pad thrust, Ex 11.2, by load, standard",
        path,
        example,
    );
    request(
        c,
        "gas tilting-pad thrust, Ex 11.2, at C = 10.5 µm (Λ = 250), standard",
        path,
        &example.replace(r#""load_n": 2001.7"#, r#""clearance_m": 1.0505e-5"#),
    );
    request(
        c,
        "gas slider L/B = 1, h1/h2 = 2, Λ = 1000, standard",
        "/v1/gas-bearings/slider",
        r#"{"pad": {"breadth_m": 0.2, "length_m": 0.2}, "inlet_film_m": 1e-5, "outlet_film_m": 5e-6, "sliding_speed_m_s": 114.1, "gas": {"viscosity_pa_s": 1.85e-5}, "effects": {"slip_flow": "off"}}"#,
    );
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(20);
    targets = gas
}
criterion_main!(benches);
