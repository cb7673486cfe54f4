//! The whirl room over HTTP: its 422s name the field and say why, the README's curl example
//! answers as documented, and over loads, speeds, masses and film models every answer is
//! finite or a 422 with the reason — never a NaN, never a 500.

use proptest::prelude::*;
use serde_json::{json, Value};
use stribeck::calc::{find, Failure};

use crate::helpers::{assert_all_finite, patched, spawn_app};

const PATH: &str = "/v1/journal-bearings/whirl";

fn run(body: &Value) -> Result<Value, Failure> {
    let entry = find(PATH).expect("registered");
    let far = std::time::Instant::now() + std::time::Duration::from_secs(120);
    (entry.execute)(&serde_json::to_vec(body).unwrap(), far, Default::default())
        .map(|done| serde_json::from_slice(&done.body).unwrap())
}

/// The README's example: D = 100 mm, L/D = 1/2, ISO VG 32 at 50 °C, 2 kN, 6000 rev/min,
/// 150 kg.
fn readme() -> Value {
    json!({"geometry": {"diameter_m": 0.1, "length_m": 0.05, "radial_clearance_m": 0.0001},
           "lubricant": {"iso_vg": 32}, "temperature_c": 50, "load_n": 2000,
           "speed_rpm": 6000, "journal_mass_kg": 150, "film_model": "finite", "fidelity": "fast"})
}

/// A finite film's grid whose solves the server's deadline cannot pay for is refused before
/// any solve, naming the grid with the estimate ([1024, 256] ran into a 504 after 10 s); the
/// README's grid is solved.
#[test]
fn a_grid_beyond_the_deadline_is_refused_with_its_estimate() {
    let entry = find(PATH).expect("registered");
    let deadline = stribeck::config::Config::default().deadline;
    let within = |grid: [u32; 2]| {
        let mut body = readme();
        body["fidelity"] = json!({ "grid": grid });
        (entry.execute)(
            &serde_json::to_vec(&body).unwrap(),
            std::time::Instant::now() + deadline,
            Default::default(),
        )
    };
    match within([1024, 256]) {
        Err(Failure::Calc(stribeck::calc::CalcError::Impossible { pointer, message })) => {
            assert_eq!(pointer, "/fidelity/grid");
            assert!(message.contains("s at least"), "{message}");
        }
        Err(e) => panic!("expected a 422 naming the grid, got {e:?}"),
        Ok(_) => panic!("expected a 422 naming the grid, got a result"),
    }
    assert!(within([48, 6]).is_ok());
}

/// Invalid requests, one row each: (patch, the pointer the 422 names, why).
#[tokio::test]
async fn invalid_requests_are_422s_naming_the_field() {
    let app = spawn_app().await;
    let rows: Vec<(Value, &str, &str)> = vec![
        (
            json!({"speed_rpm": null, "journal_mass_kg": null}),
            "/speed_rpm",
            "neither speed nor mass",
        ),
        (json!({"speed_rpm": 0.0}), "/speed_rpm", "a speed of 0"),
        (json!({"speed_rpm": 2e6}), "/speed_rpm", "above 1e6 rev/min"),
        (
            json!({"journal_mass_kg": -1.0}),
            "/journal_mass_kg",
            "a negative mass",
        ),
        (
            json!({"journal_mass_kg": 1e10}),
            "/journal_mass_kg",
            "above 1e9 kg",
        ),
        (json!({"load_n": 0.0}), "/load_n", "no load"),
        (json!({"load_n": 1e13}), "/load_n", "above 1e12 N"),
        (
            json!({"film_model": "long"}),
            "/film_model",
            "an unknown film model",
        ),
        (
            json!({"fidelity": "closed_form"}),
            "/fidelity",
            "the finite film has no closed form",
        ),
        (
            json!({"fidelity": {"grid": [7, 3]}}),
            "/fidelity/grid",
            "a grid out of range",
        ),
        (
            json!({"temperature_c": -300.0}),
            "/temperature_c",
            "below absolute zero",
        ),
        (
            json!({"geometry": {"diameter_m": 0.1, "length_m": 0.001, "radial_clearance_m": 1e-4}}),
            "/geometry/length_m",
            "L/D below 0.05",
        ),
        (
            json!({"geometry": {"diameter_m": 0.1, "length_m": 0.05, "radial_clearance_m": 0.01}}),
            "/geometry/radial_clearance_m",
            "R/C below 50",
        ),
        (
            json!({"geometry": {"diameter_m": 0.1, "lenght_m": 0.05, "radial_clearance_m": 1e-4}}),
            "/geometry/lenght_m",
            "a typo",
        ),
        (
            json!({"rotor_mass_kg": 10.0}),
            "/rotor_mass_kg",
            "/plain's name for the mass",
        ),
    ];
    for (patch, pointer, why) in rows {
        let body = patched(readme(), &patch);
        let reply = app.post_json(PATH, &body).await;
        assert_eq!(reply.status, 422, "{why}: {}", reply.text);
        assert!(
            reply.pointers().iter().any(|p| p == pointer),
            "{why}: want {pointer}, got {:?}",
            reply.pointers()
        );
    }
    // A load no equilibrium carries at this speed: 422 with the reason, on the load.
    let mut heavy = readme();
    heavy["load_n"] = json!(1e12);
    let reply = app.post_json(PATH, &heavy).await;
    assert_eq!(reply.status, 422, "{}", reply.text);
    assert!(reply.text.contains("load_n"), "{}", reply.text);
}

/// The README's example: the numbers its row quotes (to the digits it quotes).
#[tokio::test]
async fn the_readme_example_answers_as_documented() {
    let app = spawn_app().await;
    let reply = app.post_json(PATH, &readme()).await;
    assert_eq!(reply.status, 200, "{}", reply.text);
    assert_all_finite(&reply.body, "");
    let r = &reply.body["result"];
    let num = |k: &str| r[k].as_f64().unwrap_or_else(|| panic!("{k} in {r}"));
    assert_eq!(r["stable"], true);
    for (field, quoted) in [
        ("threshold_mass_kg", 331.4),
        ("threshold_speed_rpm", 9025.0),
        ("eccentricity_ratio", 0.316),
        ("whirl_frequency_ratio", 0.508),
    ] {
        let got = num(field);
        assert!(
            (got / quoted - 1.0).abs() < 2e-3,
            "{field}: {got}, README {quoted}"
        );
    }
    assert_eq!(reply.body["solver"]["fidelity"], "fast");
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    /// Loads over eight decades, speeds over five, masses over nine, every film model: a
    /// finite answer (threshold, coefficients, verdict) or a 422 naming the load or the speed
    /// (no equilibrium in the model's range) — never a NaN, never a 500.
    #[test]
    fn every_answer_is_finite_or_a_reasoned_422(
        log_load in -2.0..6.0f64,
        log_speed in 1.0..5.5f64,
        log_mass in -3.0..6.0f64,
        ask in 0..3u8,
        model in 0..4usize,
        l_over_d in 0.1..2.0f64,
    ) {
        let film = ["short_pi_film", "short_fixed_arc", "short_full", "finite"][model];
        let mut body = json!({
            "geometry": {"diameter_m": 0.1, "length_m": 0.1 * l_over_d, "radial_clearance_m": 1e-4},
            "lubricant": {"viscosity_pa_s": 0.02}, "load_n": 10f64.powf(log_load),
            "film_model": film,
            "fidelity": "fast",
        });
        if ask != 1 { body["speed_rpm"] = json!(10f64.powf(log_speed)); }
        if ask != 0 { body["journal_mass_kg"] = json!(10f64.powf(log_mass)); }
        match run(&body) {
            Ok(v) => {
                assert_all_finite(&v, "");
                let r = &v["result"];
                prop_assert!(r["statement"].as_str().is_some_and(|s| !s.is_empty()));
                if ask != 1 {
                    prop_assert!(r["eccentricity_ratio"].is_f64(), "{r}");
                    prop_assert!(r["coefficients"]["kxx"].is_f64(), "{r}");
                }
                if ask == 2 {
                    prop_assert!(r["stable"].is_boolean(), "{r}");
                }
            }
            Err(Failure::Calc(stribeck::calc::CalcError::Impossible { pointer, message })) => {
                prop_assert!(pointer == "/load_n" || pointer == "/speed_rpm", "{pointer}: {message}");
            }
            Err(other) => prop_assert!(false, "{body}: {other:?}"),
        }
    }
}
