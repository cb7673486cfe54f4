//! Thrust pads: the speed targets (release, one core).
//! - a fixed pad at `standard`: under 2 ms;
//! - a tilting-pad equilibrium at `standard`: under 20 ms;
//! - a closed form (the infinitely long pad): under 20 µs;
//! - a whole sector-pad bearing (the README's, tilting pads): under 50 ms.
//!
//! The crowned pad (a central pivot) nests the pivot's root in the load balance's; the turbulent pads (a large, fast pad: B = L = 0.3 m at 80 m/s, pad-average Re ≈ 830) solve
//! the pad once laminar and then a few times for the turbulent film's Re₂ fixed point.
//!
//! Each is the whole request through the room (parse, validate, physics, envelope).
//! `cargo bench --bench thrust`.

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

fn thrust(c: &mut Criterion) {
    let fixed = "/v1/thrust-bearings/fixed-pad";
    let tilting = "/v1/thrust-bearings/tilting-pad";
    let pad = r#""pad": {"breadth_m": 0.089, "length_m": 0.087}, "sliding_speed_m_s": 44, "lubricant": {"iso_vg": 32}, "inlet_temperature_c": 49, "load_n": 16000"#;
    for fidelity in ["closed_form", "standard"] {
        request(
            c,
            &format!("fixed pad, plane h1/h2 = 2, thermal, {fidelity}"),
            fixed,
            &format!(
                r#"{{{pad}, "profile": {{"kind": "plane_inclined", "film_ratio": 2}}, "fidelity": "{fidelity}"}}"#
            ),
        );
    }
    for fidelity in ["closed_form", "standard"] {
        request(
            c,
            &format!("tilting pad, pivot 0.6, thermal, {fidelity}"),
            tilting,
            &format!(r#"{{{pad}, "pivot_position_fraction": 0.6, "fidelity": "{fidelity}"}}"#),
        );
    }
    request(
        c,
        "tilting pad, central pivot, crown 20 µm, thermal, standard",
        tilting,
        &format!(
            r#"{{{pad}, "pivot_position_fraction": 0.5, "crown_m": 2e-5, "fidelity": "standard"}}"#
        ),
    );
    let large = r#""pad": {"breadth_m": 0.3, "length_m": 0.3}, "sliding_speed_m_s": 80, "lubricant": {"iso_vg": 32}, "inlet_temperature_c": 50, "load_n": 300000, "effects": {"turbulence": "on"}, "fidelity": "standard""#;
    request(
        c,
        "fixed pad, plane h1/h2 = 2, thermal, turbulent, standard",
        fixed,
        &format!(r#"{{{large}, "profile": {{"kind": "plane_inclined", "film_ratio": 2}}}}"#),
    );
    request(
        c,
        "tilting pad, pivot 0.6, thermal, turbulent, standard",
        tilting,
        &format!(r#"{{{large}, "pivot_position_fraction": 0.6}}"#),
    );
    let bearing = stribeck::calc::find("/v1/thrust-bearings/bearing")
        .unwrap()
        .example;
    request(
        c,
        "whole bearing, 7 tilting pads, thermal, standard",
        "/v1/thrust-bearings/bearing",
        bearing,
    );
}

criterion_group!(benches, thrust);
criterion_main!(benches);
