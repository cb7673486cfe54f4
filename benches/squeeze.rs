//! Squeeze films: the rooms' requests (release, one core).
//! - the plates room (a closed form: Ex 9.1's annulus, the squeeze time): microseconds;
//! - the squeezed journal (Ex 9.4's pin, ε 0.5 → 0.9, cavitated) at `closed_form` (the
//!   infinitely long bearing), `fast` and `standard` (the finite film and the time quadrature);
//! - a long pin's full (periodic) film, L/D = 5, at `standard` and `high`.
//!
//! Each is the whole request through the room (parse, validate, physics, envelope).
//! `cargo bench --bench squeeze`.

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

fn squeeze(c: &mut Criterion) {
    request(
        c,
        "plates: annulus squeeze time (Ex 9.1)",
        "/v1/squeeze-films/plates",
        r#"{"shape": {"kind": "annulus", "inner_radius_m": 0.047, "outer_radius_m": 0.06}, "lubricant": {"viscosity_pa_s": 0.006}, "load_n": 5462.4, "initial_film_m": 2.5e-5, "final_film_m": 5e-6}"#,
    );
    for fidelity in ["closed_form", "fast", "standard"] {
        request(
            c,
            &format!("journal: Ex 9.4 pin, ε 0.5 → 0.9, cavitated, {fidelity}"),
            "/v1/squeeze-films/journal",
            &format!(
                r#"{{"geometry": {{"diameter_m": 0.0381, "length_m": 0.0381, "radial_clearance_m": 2.54e-5}}, "lubricant": {{"viscosity_pa_s": 0.014479}}, "load_n": 5589.8, "initial_eccentricity_ratio": 0.5, "final_eccentricity_ratio": 0.9, "film": "cavitated", "fidelity": "{fidelity}"}}"#
            ),
        );
    }
    // The full film (negative pressures kept) of a long pin, L/D = 5: the periodic film, one
    // band solve per quadrature node (it was SOR: about 1.0 s at standard and 8.3 s at high).
    for fidelity in ["standard", "high"] {
        request(
            c,
            &format!("journal: L/D 5 pin, ε 0.5 → 0.9, full film, {fidelity}"),
            "/v1/squeeze-films/journal",
            &format!(
                r#"{{"geometry": {{"diameter_m": 0.0381, "length_m": 0.1905, "radial_clearance_m": 2.54e-5}}, "lubricant": {{"viscosity_pa_s": 0.014479}}, "load_n": 5589.8, "initial_eccentricity_ratio": 0.5, "final_eccentricity_ratio": 0.9, "film": "full", "fidelity": "{fidelity}"}}"#
            ),
        );
    }
}

criterion_group! {
    name = benches;
    // `standard` takes about 20 ms a request: 20 samples keep the run near a minute.
    config = Criterion::default().sample_size(20);
    targets = squeeze
}
criterion_main!(benches);
