//! Contact rooms through the whole request path (parse, validate, compute, serialise), release,
//! one core. The issue's budget: Hertz and the film formulas under 20 µs; the numerical line
//! contact at default fidelity under 50 ms at M = 50, L = 10.
//! `cargo bench --bench contact`.

use std::hint::black_box;
use std::time::{Duration, Instant};

use criterion::{criterion_group, criterion_main, Bencher, Criterion};
use stribeck::calc::contact::{ehl::film::EhlFilm, hertz::Hertz};
use stribeck::calc::{find, Calculation, Context, Validate};

/// One request to `path` through its whole path, under a deadline of `seconds`.
fn request(path: &str, body: String, seconds: u64) -> impl FnMut(&mut Bencher) {
    let entry = find(path).expect("registered");
    move |b| {
        b.iter(|| {
            let far = Instant::now() + Duration::from_secs(seconds);
            (entry.execute)(black_box(body.as_bytes()), far, Default::default()).expect("computes")
        })
    }
}

/// The calculation alone, from a validated case (no JSON in or out): the formulas' own cost.
fn compute<C: Calculation>(c: &mut Criterion, name: &str)
where
    <C::Input as Validate>::Valid: Clone,
{
    let input: C::Input = serde_json::from_str(C::EXAMPLE).expect("the example parses");
    let case = input.validate().expect("the example is valid");
    c.bench_function(name, |b| {
        b.iter(|| {
            let mut ctx =
                Context::new(Instant::now() + Duration::from_secs(10), Default::default());
            C::run(black_box(case.clone()), &mut ctx).expect("computes")
        })
    });
}

fn contact(c: &mut Criterion) {
    compute::<Hertz>(c, "hertz, exact ellipticity, calculation only");
    compute::<EhlFilm>(c, "EHL film formulas, calculation only");
    let hertz = find("/v1/contacts/hertz").unwrap().example;
    c.bench_function(
        "hertz, exact ellipticity (standard)",
        request("/v1/contacts/hertz", hertz.to_owned(), 10),
    );
    let closed = hertz.replacen('{', r#"{"fidelity": "closed_form", "#, 1);
    c.bench_function(
        "hertz, Hamrock–Dowson fits (closed_form)",
        request("/v1/contacts/hertz", closed, 10),
    );
    let film = find("/v1/contacts/ehl-film").unwrap().example;
    c.bench_function(
        "EHL film formulas, ball–inner race",
        request("/v1/contacts/ehl-film", film.to_owned(), 10),
    );
    // M = 50, L = 10 on the steel roller pair of the accuracy report (R_x = 10 mm, ū = 2 m/s,
    // η₀ = 0.05 Pa·s): W′ = M√(2U), α = L/((2U)^¼ E′).
    let e_prime: f64 = 2.1e11 / (1.0 - 0.09);
    let two_u: f64 = 2.0 * 0.05 * 2.0 / (e_prime * 0.01);
    let load = 50.0 * two_u.sqrt() * e_prime * 0.01 * 0.01;
    let alpha = 10.0 / (two_u.powf(0.25) * e_prime);
    let mut group = c.benchmark_group("slow");
    group.sample_size(20);
    let line = format!(
        r#"{{"body1": {{"radius_x_m": 0.02, "elastic_modulus_pa": 2.1e11, "poisson_ratio": 0.3}}, "body2": {{"radius_x_m": 0.02, "elastic_modulus_pa": 2.1e11, "poisson_ratio": 0.3}}, "load_n": {load}, "line": {{"length_m": 0.01}}, "entrainment_speed_m_s": 2.0, "lubricant": {{"viscosity_pa_s": 0.05, "pressure_viscosity_coefficient_1_pa": {alpha}}}, "temperature_c": 40}}"#
    );
    group.bench_function(
        "numerical EHL line contact, M = 50, L = 10 (standard)",
        request("/v1/contacts/ehl", line, 10),
    );
    // The point contact on 128² cells (129² nodes): a steel ball (R = 10 mm) on a flat at
    // M = 100, L = 10, W = M(2U)^¾.
    let load = 100.0 * two_u.powf(0.75) * e_prime * 0.01 * 0.01;
    let point = format!(
        r#"{{"body1": {{"radius_x_m": 0.01, "radius_y_m": 0.01, "elastic_modulus_pa": 2.1e11, "poisson_ratio": 0.3}}, "body2": {{"elastic_modulus_pa": 2.1e11, "poisson_ratio": 0.3}}, "load_n": {load}, "entrainment_speed_m_s": 2.0, "lubricant": {{"viscosity_pa_s": 0.05, "pressure_viscosity_coefficient_1_pa": {alpha}}}, "temperature_c": 40}}"#
    );
    group.sample_size(10);
    group.bench_function(
        "numerical EHL point contact, 129 x 129 nodes, M = 100, L = 10 (standard)",
        request("/v1/contacts/ehl", point, 30),
    );
    group.finish();
}

criterion_group!(benches, contact);
criterion_main!(benches);
