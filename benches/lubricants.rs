//! Lubricant rooms through the same path a request takes (parse, validate, compute, serialise):
//! closed forms, so the budget is microseconds. `cargo bench --bench lubricants`.

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::{criterion_group, criterion_main, Criterion};
use stribeck::calc::find;

fn run(path: &str, body: &[u8]) {
    let entry = find(path).expect("registered");
    let far = Instant::now() + Duration::from_secs(10);
    black_box((entry.execute)(black_box(body), far, Default::default()).expect("computes"));
}

fn lubricants(c: &mut Criterion) {
    let viscosity = br#"{"lubricant": {"kinematic_viscosity_40c_mm2_s": 31.0, "kinematic_viscosity_100c_mm2_s": 5.4, "density_15c_kg_m3": 863.0, "roelands_pressure_viscosity_index": 0.68}, "temperatures_c": [65.0], "pressures_pa": [1.0e8]}"#;
    c.bench_function("viscosity, one Walther + Roelands point", |b| {
        b.iter(|| run("/v1/lubricants/viscosity", viscosity))
    });
    let vi = br#"{"kinematic_viscosity_40c_mm2_s": 73.3, "kinematic_viscosity_100c_mm2_s": 8.86}"#;
    c.bench_function("viscosity index (ASTM D2270)", |b| {
        b.iter(|| run("/v1/lubricants/viscosity-index", vi))
    });
    let iso =
        br#"{"lubricant": {"iso_vg": 68, "viscosity_index": 120}, "temperatures_c": [40.0, 80.0]}"#;
    c.bench_function(
        "properties of an ISO VG preset (VI inverse by Brent)",
        |b| b.iter(|| run("/v1/lubricants/properties", iso)),
    );
}

criterion_group!(benches, lubricants);
criterion_main!(benches);
