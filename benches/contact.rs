//! Contact rooms through the whole request path (parse, validate, compute, serialise), release,
//! one core. The issue's budget: Hertz and the film formulas under 20 µs.
//! `cargo bench --bench contact`.

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::{criterion_group, criterion_main, Criterion};
use stribeck::calc::find;

fn request(c: &mut Criterion, name: &str, path: &str, body: String) {
    let entry = find(path).expect("registered");
    c.bench_function(name, |b| {
        b.iter(|| {
            let far = Instant::now() + Duration::from_secs(10);
            (entry.execute)(black_box(body.as_bytes()), far, Default::default()).expect("computes")
        })
    });
}

fn contact(c: &mut Criterion) {
    let hertz = find("/v1/contacts/hertz").unwrap().example;
    request(
        c,
        "hertz, exact ellipticity (standard)",
        "/v1/contacts/hertz",
        hertz.to_owned(),
    );
    let closed = hertz.replacen('{', r#"{"fidelity": "closed_form", "#, 1);
    request(
        c,
        "hertz, Hamrock–Dowson fits (closed_form)",
        "/v1/contacts/hertz",
        closed,
    );
    let film = find("/v1/contacts/ehl-film").unwrap().example;
    request(
        c,
        "EHL film formulas, ball–inner race",
        "/v1/contacts/ehl-film",
        film.to_owned(),
    );
}

criterion_group!(benches, contact);
criterion_main!(benches);
