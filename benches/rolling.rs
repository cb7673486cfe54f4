//! Rolling-bearing rooms through the whole request path (release, one core). The budget:
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

criterion_group!(benches, rolling);
criterion_main!(benches);
