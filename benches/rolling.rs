//! Rolling-bearing rooms through the whole request path (release, one core). The issue's budget:
//! one load distribution with per-ball Hertz under 200 µs; the whole analysis chain under 1 ms.
//! `cargo bench --bench rolling`.

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::{criterion_group, criterion_main, Criterion};
use stribeck::calc::find;

fn rolling(c: &mut Criterion) {
    for (name, path) in [
        (
            "load distribution (example)",
            "/v1/rolling-bearings/load-distribution",
        ),
        ("analysis chain (example)", "/v1/rolling-bearings/analysis"),
        ("life (example)", "/v1/rolling-bearings/life"),
        ("kinematics (example)", "/v1/rolling-bearings/kinematics"),
        (
            "static capacity (example)",
            "/v1/rolling-bearings/static-capacity",
        ),
    ] {
        let entry = find(path).expect("registered");
        c.bench_function(name, |b| {
            b.iter(|| {
                let far = Instant::now() + Duration::from_secs(10);
                (entry.execute)(black_box(entry.example.as_bytes()), far, Default::default())
                    .expect("computes")
            })
        });
    }
}

/// The general equilibrium: a tilting moment and the ball-by-ball model at speed (centrifugal
/// and gyroscopic), and a crowned cylindrical roller bearing.
fn rolling_general(c: &mut Criterion) {
    let entry = find("/v1/rolling-bearings/load-distribution").expect("registered");
    for (name, body) in [
        (
            "load distribution, 7220 at 12 000 rpm with moment",
            r#"{"bearing": {"ball_diameter_m": 0.02381, "pitch_diameter_m": 0.14, "ball_count": 16, "inner_groove_radius_m": 0.01238, "outer_groove_radius_m": 0.01262, "diametral_clearance_m": 0, "free_contact_angle_deg": 40, "ball": {"elastic_modulus_pa": 2.08e11, "poisson_ratio": 0.3, "density_kg_m3": 7800}, "rings": {"elastic_modulus_pa": 2.08e11, "poisson_ratio": 0.3}}, "radial_load_n": 5000, "axial_load_n": 20000, "moment_n_m": 100, "inner_ring_speed_rpm": 12000}"#,
        ),
        (
            "load distribution, crowned roller bearing",
            r#"{"bearing": {"roller_diameter_m": 0.01, "roller_effective_length_m": 0.009601, "pitch_diameter_m": 0.0650115, "roller_count": 14, "diametral_clearance_m": 4.1e-5, "profile": {"crown_radius_m": 1.0}, "rollers": {"elastic_modulus_pa": 2.0e11, "poisson_ratio": 0.3}, "rings": {"elastic_modulus_pa": 2.0e11, "poisson_ratio": 0.3}}, "radial_load_n": 6000, "axial_load_n": 0}"#,
        ),
    ] {
        c.bench_function(name, |b| {
            b.iter(|| {
                let far = Instant::now() + Duration::from_secs(10);
                (entry.execute)(black_box(body.as_bytes()), far, Default::default())
                    .expect("computes")
            })
        });
    }
}

criterion_group!(benches, rolling, rolling_general);
criterion_main!(benches);
