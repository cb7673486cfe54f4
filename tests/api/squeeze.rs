//! Squeeze films over HTTP: the 422s that name an under- or over-determined request, and the
//! squeezed journal over its whole valid range (finite, monotone, converged or a 422 with the
//! reason — never a 500).

use proptest::prelude::*;
use serde_json::{json, Value};
use stribeck::calc::{find, Failure};

use crate::helpers::{assert_all_finite, spawn_app};

const PLATES: &str = "/v1/squeeze-films/plates";
const JOURNAL: &str = "/v1/squeeze-films/journal";

#[tokio::test]
async fn under_and_over_determined_plates_are_422s_naming_the_fields() {
    let app = spawn_app().await;
    let disk = json!({"kind": "circular_disk", "radius_m": 0.05});
    let rows = [
        (
            json!({"shape": disk, "lubricant": {"viscosity_pa_s": 0.01}, "approach_speed_m_s": 0.01}),
            vec!["/film_m"],
        ),
        (
            json!({"shape": disk, "lubricant": {"viscosity_pa_s": 0.01}, "approach_speed_m_s": 0.01, "film_m": 1e-5, "initial_film_m": 2e-5}),
            vec!["/approach_speed_m_s", "/film_m", "/initial_film_m"],
        ),
    ];
    for (body, want) in rows {
        let reply = app.post_json(PLATES, &body).await;
        assert_eq!(reply.status, 422, "{}", reply.text);
        assert!(reply.content_type.starts_with("application/problem+json"));
        let got: Vec<&str> = reply.body["errors"]
            .as_array()
            .unwrap()
            .iter()
            .map(|e| e["pointer"].as_str().unwrap())
            .collect();
        assert_eq!(got, want, "{}", reply.text);
    }
    let reply = app
        .post_json(
            JOURNAL,
            &json!({"geometry": {"diameter_m": 0.04, "length_m": 0.04, "radial_clearance_m": 2e-5},
                    "lubricant": {"viscosity_pa_s": 0.01}, "load_n": 1000.0,
                    "initial_eccentricity_ratio": 0.2, "final_eccentricity_ratio": 0.8,
                    "speed_rpm": 200.0}),
        )
        .await;
    // Turning at 200 rev/min the film carries 1 kN at ε = 0.783: the journal settles short of 0.8.
    assert_eq!(reply.status, 422, "{}", reply.text);
    assert!(
        reply.text.contains("ε = 0.7832, where it settles"),
        "{}",
        reply.text
    );
}

fn run(body: &Value) -> Result<Value, Failure> {
    let entry = find(JOURNAL).expect("registered");
    let far = std::time::Instant::now() + std::time::Duration::from_secs(120);
    (entry.execute)(&serde_json::to_vec(body).unwrap(), far, Default::default())
        .map(|done| serde_json::from_slice(&done.body).unwrap())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// L/D over the journal room's range, ε₁ from 0, ε₂ up to 0.999, both films, the closed
    /// form and the `fast` film: every answer is finite, the time grows with ε₂ and the
    /// approach slows down as the film closes.
    #[test]
    fn squeeze_times_are_finite_and_grow_towards_contact(
        l_over_d in 0.05..5.0f64,
        e1 in 0.0..0.95f64,
        reach in 0.05..1.0f64,
        full in any::<bool>(),
        closed in any::<bool>(),
    ) {
        let e2 = e1 + reach * (0.999 - e1);
        let body = |e2: f64| json!({
            "geometry": {"diameter_m": 0.05, "length_m": 0.05 * l_over_d, "radial_clearance_m": 5e-5},
            "lubricant": {"viscosity_pa_s": 0.02}, "load_n": 2000.0,
            "initial_eccentricity_ratio": e1, "final_eccentricity_ratio": e2,
            "film": if full { "full" } else { "cavitated" },
            "fidelity": if closed { "closed_form" } else { "fast" }
        });
        let near = run(&body(e1 + 0.5 * (e2 - e1))).unwrap();
        let far = run(&body(e2)).unwrap();
        assert_all_finite(&far, "");
        let t = |v: &Value| v["result"]["time_s"].as_f64().unwrap();
        prop_assert!(t(&near) > 0.0 && t(&far) > t(&near), "{} {}", t(&near), t(&far));
        let speed = |k: &str| far["result"][k].as_f64().unwrap();
        prop_assert!(speed("approach_speed_final_m_s") < speed("approach_speed_initial_m_s"));
    }

    /// The journal that turns, over ten decades of speed from the slowest taken as turning:
    /// it reaches ε₂ in a finite, positive time, sooner than or as soon as it would reach a
    /// further ε, or settles (or circles) short of ε₂ and says so (never 5xx, never NaN).
    #[test]
    fn a_turning_journal_reaches_the_target_or_says_where_it_settles(
        log_rpm in -6.0..4.0f64,
        l_over_d in 0.1..2.0f64,
        e1 in 0.0..0.9f64,
        reach in 0.1..0.95f64,
        closed in any::<bool>(),
    ) {
        let e2 = e1 + reach * (0.99 - e1);
        let body = |e2: f64| json!({
            "geometry": {"diameter_m": 0.05, "length_m": 0.05 * l_over_d, "radial_clearance_m": 5e-5},
            "lubricant": {"viscosity_pa_s": 0.02}, "load_n": 2000.0,
            "speed_rpm": 10f64.powf(log_rpm),
            "initial_eccentricity_ratio": e1, "final_eccentricity_ratio": e2,
            "film": if closed { "full" } else { "cavitated" },
            "fidelity": if closed { "closed_form" } else { "fast" }
        });
        let time = |e2: f64| match run(&body(e2)) {
            Ok(v) => {
                assert_all_finite(&v, "");
                Some(v["result"]["time_s"].as_f64().unwrap())
            }
            Err(Failure::Calc(e)) => {
                // It settles short of ε₂, or (a full film that whirls without settling) circles
                // for the whole horizon below it.
                let text = format!("{e:?}");
                assert!(
                    text.contains("where it settles") || text.contains("nor settle short of it"),
                    "{text}"
                );
                None
            }
            Err(other) => panic!("{other:?}"),
        };
        let (near, far) = (time(e1 + 0.5 * (e2 - e1)), time(e2));
        if let Some(far) = far {
            let near = near.expect("a journal that reaches ε₂ passes every ε before it");
            prop_assert!(near > 0.0 && far > near, "{near} {far}");
        }
    }
}

#[test]
fn a_denormal_geometry_is_a_422_not_a_panic() {
    // Schemathesis: a diameter of 5e-324 made L/D infinite, and the level's axial cells, which
    // grow with L/D, overflowed before the refusal. A subnormal diameter is now refused at the
    // door (Positive); the smallest normal one still reaches the L/D refusal.
    for (diameter_m, pointer) in [
        (5e-324, "/geometry/diameter_m"),
        (f64::MIN_POSITIVE, "/geometry/length_m"),
    ] {
        let body = json!({
            "geometry": {"diameter_m": diameter_m, "length_m": 0.1, "radial_clearance_m": 0.0001},
            "lubricant": {"viscosity_pa_s": 0.014479}, "load_n": 5589.8,
            "initial_eccentricity_ratio": 0.5, "final_eccentricity_ratio": 0.9,
            "film": "cavitated", "fidelity": "fast",
        });
        let entry = find(JOURNAL).unwrap();
        let far = std::time::Instant::now() + std::time::Duration::from_secs(30);
        match (entry.execute)(&serde_json::to_vec(&body).unwrap(), far, Default::default()) {
            Err(Failure::Invalid(errors)) => {
                assert!(
                    errors.iter().any(|e| e.pointer == pointer),
                    "{diameter_m:e}: {errors:?}"
                )
            }
            other => panic!("{diameter_m:e}: {other:?}"),
        }
    }
}
