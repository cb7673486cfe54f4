//! Plain journal bearing: the speed targets (release, one core).
//! - default fidelity at L/D = 1, ε = 0.8: under 2 ms;
//! - equilibrium from load: under 10 ms;
//! - a closed form: under 20 µs;
//! - the README's request (thermal, dynamics and the whirl threshold): fast ≤ 1 ms, standard
//!   ≤ 5 ms, high ≤ 40 ms;
//! - a steady orbit of the short-bearing models (the README's `/dynamic` request): under 50 ms;
//!   of the finite film at `fast`: under 2 s;
//! - a whirl threshold (the README's `/whirl` request on the short film): under 5 ms;
//! - the composite bearing's locus beside the held sleeve's (the README's
//!   `/composite-bearings/orbit` request, Harnoy Fig 18-9, `standard`).
//!
//! `cargo bench --bench journal`.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use stribeck::calc::journal::eccentricity::EccentricityRatio;
use stribeck::calc::journal::film::FilmModel;
use stribeck::calc::journal::performance::{self, Approximation, Method};
use stribeck::calc::Budget;
use stribeck::fidelity::Level;

fn journal(c: &mut Criterion) {
    let standard = Method::numerical(Level::Standard, None, None);
    c.bench_function("film at ε = 0.8, L/D = 1, standard", |b| {
        b.iter(|| {
            performance::at_eccentricity(
                black_box(EccentricityRatio::new(0.8).unwrap()),
                1.0,
                standard,
                FilmModel::REYNOLDS,
                &Budget::unlimited(),
            )
            .unwrap()
        })
    });
    c.bench_function(
        "equilibrium from load, S = 0.0447, L/D = 1, standard",
        |b| {
            b.iter(|| {
                performance::equilibrium(
                    black_box(0.0447),
                    1.0,
                    standard,
                    FilmModel::REYNOLDS,
                    &Budget::unlimited(),
                )
                .unwrap()
            })
        },
    );
    let short = Method::ClosedForm(Approximation::Short);
    c.bench_function("closed form, short bearing at ε = 0.8", |b| {
        b.iter(|| {
            performance::at_eccentricity(
                black_box(EccentricityRatio::new(0.8).unwrap()),
                0.5,
                short,
                FilmModel::REYNOLDS,
                &Budget::unlimited(),
            )
            .unwrap()
        })
    });
    let long = Method::ClosedForm(Approximation::Long);
    c.bench_function("closed form, long bearing (Reynolds) at ε = 0.8", |b| {
        b.iter(|| {
            performance::at_eccentricity(
                black_box(EccentricityRatio::new(0.8).unwrap()),
                2.0,
                long,
                FilmModel::REYNOLDS,
                &Budget::unlimited(),
            )
            .unwrap()
        })
    });
    let entry = stribeck::calc::find("/v1/journal-bearings/plain").unwrap();
    for fidelity in ["fast", "standard", "high"] {
        let request = format!(
            r#"{{"geometry": {{"diameter_m": 0.1, "length_m": 0.1, "radial_clearance_m": 0.0001}}, "speed_rpm": 3000, "lubricant": {{"iso_vg": 32}}, "load_n": 10000, "inlet_temperature_c": 40, "fidelity": "{fidelity}"}}"#
        );
        c.bench_function(
            &format!("README request at {fidelity}: thermal equilibrium, K and C, whirl threshold"),
            |b| {
                b.iter(|| {
                    let far = std::time::Instant::now() + std::time::Duration::from_secs(60);
                    (entry.execute)(black_box(request.as_bytes()), far, Default::default()).unwrap()
                })
            },
        );
    }
    // Placed films (an attitude search per film): misaligned, a partial arc, both.
    // The placed films, and mass-conserving cavitation with its thermal iteration.
    for (name, variant) in [
        (
            "misaligned 0.5 mrad",
            r#""misalignment": {"slope_rad": 0.0005}"#,
        ),
        ("120° arc", r#""arc_deg": 120"#),
        (
            "120° arc, misaligned 0.5 mrad",
            r#""arc_deg": 120, "misalignment": {"slope_rad": 0.0005}"#,
        ),
        ("JFO cavitation", r#""effects": {"cavitation": "jfo"}"#),
    ] {
        let request = format!(
            r#"{{"geometry": {{"diameter_m": 0.1, "length_m": 0.1, "radial_clearance_m": 0.0001}}, "speed_rpm": 3000, "lubricant": {{"iso_vg": 32}}, "load_n": 10000, "inlet_temperature_c": 40, "fidelity": "standard", {variant}}}"#
        );
        c.bench_function(&format!("README request, {name}, at standard"), |b| {
            b.iter(|| {
                let far = std::time::Instant::now() + std::time::Duration::from_secs(60);
                (entry.execute)(black_box(request.as_bytes()), far, Default::default()).unwrap()
            })
        });
    }
    let dynamic = stribeck::calc::find("/v1/journal-bearings/dynamic").unwrap();
    for (film, mass, fidelity) in [
        ("short_pi_film", 20, "standard"),
        ("short_pi_film", 0, "standard"),
        ("short_fixed_arc", 20, "standard"),
        ("finite", 20, "fast"),
    ] {
        let request = format!(
            r#"{{"geometry": {{"diameter_m": 0.1, "length_m": 0.04, "radial_clearance_m": 0.0001}}, "lubricant": {{"viscosity_pa_s": 0.02}}, "speed_rpm": 3000, "journal_mass_kg": {mass}, "load": {{"kind": "sinusoidal", "static_n": 10000, "amplitude_n": 5000, "frequency_ratio": 1, "direction_deg": -90}}, "film_model": "{film}", "fidelity": "{fidelity}"}}"#
        );
        c.bench_function(
            &format!("README /dynamic request, {film}, {mass} kg, {fidelity}: steady orbit"),
            |b| {
                b.iter(|| {
                    let far = std::time::Instant::now() + std::time::Duration::from_secs(60);
                    (dynamic.execute)(black_box(request.as_bytes()), far, Default::default())
                        .unwrap()
                })
            },
        );
    }
    let whirl = stribeck::calc::find("/v1/journal-bearings/whirl").unwrap();
    for (film, fidelity) in [("short_pi_film", "standard"), ("finite", "fast")] {
        let request = format!(
            r#"{{"geometry": {{"diameter_m": 0.1, "length_m": 0.05, "radial_clearance_m": 0.0001}}, "lubricant": {{"iso_vg": 32}}, "temperature_c": 50, "load_n": 2000, "speed_rpm": 6000, "journal_mass_kg": 150, "film_model": "{film}", "fidelity": "{fidelity}"}}"#
        );
        c.bench_function(
            &format!("README /whirl request, {film} at {fidelity}: threshold mass, speed, verdict"),
            |b| {
                b.iter(|| {
                    let far = std::time::Instant::now() + std::time::Duration::from_secs(60);
                    (whirl.execute)(black_box(request.as_bytes()), far, Default::default()).unwrap()
                })
            },
        );
    }
    let composite = stribeck::calc::find("/v1/composite-bearings/orbit").unwrap();
    let request = r#"{"journal_radius_m": 0.05, "sleeve_length_m": 0.02, "radial_clearance_m": 5e-5, "lubricant": {"viscosity_pa_s": 0.01}, "journal_speed_rpm": 3000, "journal_mass_kg": 5092.96, "sleeve_inertia_kg_m2": 1.5915e-5, "restraint_coefficient_kg_m2": 1.5915e-5, "load": {"kind": "sinusoidal", "static_n": 50265.5, "amplitude_n": 50265.5, "frequency_ratio": 2, "direction_deg": -90}, "film_model": "short_fixed_arc"}"#;
    c.bench_function(
        "README /composite-bearings/orbit request (Harnoy Fig 18-9), standard: both loci",
        |b| {
            b.iter(|| {
                let far = std::time::Instant::now() + std::time::Duration::from_secs(60);
                (composite.execute)(black_box(request.as_bytes()), far, Default::default()).unwrap()
            })
        },
    );
}

criterion_group!(benches, journal);
criterion_main!(benches);
