use super::*;
use crate::calc::testing::{invalid_pointers, ok, post, warning_codes};
use crate::calc::Failure;
use crate::fidelity::StopReason;
use proptest::prelude::*;
use serde_json::{json, Value};

fn example() -> Value {
    serde_json::from_str(CompositeOrbit::EXAMPLE).unwrap()
}

fn field(v: &Value, pointer: &str) -> f64 {
    v.pointer(pointer)
        .and_then(Value::as_f64)
        .unwrap_or_else(|| panic!("{pointer} missing: {v}"))
}

#[test]
fn the_example_settles_with_a_thicker_film_than_the_held_sleeve() {
    let mut body = example();
    body["include_orbit"] = json!(true);
    body["sleeve_wall_thickness_m"] = json!(0.01);
    body["sleeve_thermal_diffusivity_m2_s"] = json!(1.5e-5);
    let v = ok::<CompositeOrbit>(&body);
    let result = &v["result"];
    assert_eq!(result["composite"]["steady_orbit"], json!(true), "{v}");
    assert_eq!(result["regular"]["steady_orbit"], json!(true), "{v}");
    let (c_max, r_max) = (
        field(result, "/composite/max_eccentricity_ratio"),
        field(result, "/regular/max_eccentricity_ratio"),
    );
    assert!(0.0 < c_max && c_max < r_max && r_max < 1.0, "{v}");
    let ratio = field(result, "/min_film_ratio");
    let films = field(result, "/composite/min_film_m") / field(result, "/regular/min_film_m");
    assert!(ratio > 1.0 && (ratio / films - 1.0).abs() < 1e-12);
    let (lo, hi, mean) = (
        field(result, "/composite/min_speed_ratio"),
        field(result, "/composite/max_speed_ratio"),
        field(result, "/composite/mean_speed_ratio"),
    );
    assert!(0.0 < lo && lo <= mean && mean <= hi && hi < 1.0, "{v}");
    assert!((field(result, "/composite/mean_heat_flux_ratio") - (1.0 - mean)).abs() < 1e-15);
    assert!(field(result, "/sleeve_peclet_number") > 0.0);
    for block in ["composite", "regular"] {
        let orbit = result[block]["orbit"].as_array().unwrap();
        assert_eq!(orbit.len(), ORBIT_POINTS);
        let largest = orbit
            .iter()
            .map(|p| p["eccentricity_ratio"].as_f64().unwrap())
            .fold(0.0, f64::max);
        let max = field(result, &format!("/{block}/max_eccentricity_ratio"));
        assert!(
            largest <= max + 1e-9 && largest > max - 1e-3,
            "{block}: {largest} {max}"
        );
    }
    let xi = result["composite"]["orbit"].as_array().unwrap();
    assert!(xi
        .iter()
        .all(|p| (lo - 1e-9..=hi + 1e-9).contains(&p["speed_ratio"].as_f64().unwrap())));
    assert_eq!(v["solver"]["iterations_unit"], json!("time_steps"));
    assert!(warning_codes(&v).is_empty(), "{v}");
}

#[test]
fn the_fidelity_ladder_agrees() {
    let at = |level: &str| {
        let mut body = example();
        body["fidelity"] = json!(level);
        field(
            &ok::<CompositeOrbit>(&body)["result"],
            "/composite/max_eccentricity_ratio",
        )
    };
    let high = at("high");
    assert!((at("standard") - high).abs() < 1e-6);
    assert!((at("fast") - high).abs() < 1e-5);
}

#[test]
fn a_half_speed_load_no_plain_bearing_carries_rides_on_the_turning_sleeve() {
    // A load turning at half the journal's speed cancels a plain bearing's effective speed
    // 1 − 2·½ (half-frequency whirl, spec B.1.2): the held sleeve spirals towards the wall,
    // the composite's effective speed is ξ > 0 and it settles on a circle.
    let mut body = example();
    body["journal_mass_kg"] = json!(0);
    body["film_model"] = json!("short_pi_film");
    body["load"] = json!({"kind": "rotating", "magnitude_n": 2000, "speed_ratio": 0.5,
        "direction_at_start_deg": -90});
    body["fidelity"] = json!("high");
    let v = ok::<CompositeOrbit>(&body);
    let result = &v["result"];
    assert_eq!(result["composite"]["steady_orbit"], json!(true), "{v}");
    let c_max = field(result, "/composite/max_eccentricity_ratio");
    assert!(
        (c_max - field(result, "/composite/min_eccentricity_ratio")).abs() < 1e-5,
        "a circle"
    );
    let regular = &result["regular"];
    assert!(
        regular["steady_orbit"] == json!(false) || regular.get("contact_time_s").is_some(),
        "{v}"
    );
    assert!(field(result, "/regular/max_eccentricity_ratio") > c_max);
}

#[test]
fn invalid_requests_name_their_fields() {
    let rows: [(&str, Value, &str); 9] = [
        ("journal_speed_rpm", json!(5e-324), "/journal_speed_rpm"),
        ("journal_mass_kg", json!(5e-324), "/journal_mass_kg"),
        (
            "sleeve_inertia_kg_m2",
            json!(1e-12),
            "/sleeve_inertia_kg_m2",
        ),
        ("sleeve_inertia_kg_m2", json!(0), "/sleeve_inertia_kg_m2"),
        (
            "load",
            json!({"kind": "sinusoidal", "static_n": 1, "amplitude_n": 1, "frequency_ratio": 0, "direction_deg": 0}),
            "/load/frequency_ratio",
        ),
        // A load period of 200 revolutions ran past the deadline (a bound scan's 504).
        (
            "load",
            json!({"kind": "sinusoidal", "static_n": 1, "amplitude_n": 1, "frequency_ratio": 5e-3, "direction_deg": 0}),
            "/load/frequency_ratio",
        ),
        ("film_model", json!("short_full"), "/film_model"),
        ("fidelity", json!("closed_form"), "/fidelity"),
        (
            "sleeve_wall_thickness_m",
            json!(0.01),
            "/sleeve_thermal_diffusivity_m2_s",
        ),
    ];
    for (name, value, pointer) in rows {
        let mut body = example();
        body[name] = value;
        assert_eq!(
            invalid_pointers::<CompositeOrbit>(&body),
            vec![pointer.to_owned()],
            "{name}"
        );
    }
    let mut body = example();
    body.as_object_mut()
        .unwrap()
        .remove("restraint_coefficient_kg_m2");
    assert_eq!(invalid_pointers::<CompositeOrbit>(&body).len(), 4);
}

#[test]
fn a_crushing_load_rides_on_root_two_times_the_held_sleeves_film_and_beyond_that_is_a_422() {
    // Near contact the short film carries W̄ ∝ (1 − ε)⁻² and a sleeve with no restraint to
    // speak of turns with the journal (ξ → 1): twice the speed sum, so h_min grows by √2.
    let mut body = example();
    body["load"] = json!({"kind": "constant", "magnitude_n": 1e9, "direction_deg": -90});
    body["journal_speed_rpm"] = json!(1e-3);
    let v = ok::<CompositeOrbit>(&body);
    let result = &v["result"];
    assert!(field(result, "/composite/min_speed_ratio") > 1.0 - 1e-6);
    let ratio = field(result, "/min_film_ratio");
    assert!((ratio / 2f64.sqrt() - 1.0).abs() < 1e-4, "{ratio}");
    assert!(field(result, "/composite/min_film_m") < 1e-10);
    assert!(warning_codes(&v).contains(&"film_thinner_than_1_percent_of_clearance".to_owned()));
    // At 1e-6 rpm still (ε = 1 − 9e-9 and 1 − 6e-9): the same √2.
    body["journal_speed_rpm"] = json!(1e-6);
    let v = ok::<CompositeOrbit>(&body);
    let ratio = field(&v["result"], "/min_film_ratio");
    assert!((ratio / 2f64.sqrt() - 1.0).abs() < 1e-4, "{ratio}");
    // A tenth of the length: F_s falls a thousandfold, and no film short of h_min = 1e-9 C
    // carries 1 GN.
    body["sleeve_length_m"] = json!(0.002);
    match post::<CompositeOrbit>(&body) {
        Err(Failure::Calc(CalcError::Impossible { pointer, .. })) => assert_eq!(pointer, "/load"),
        other => panic!("{other:?}"),
    }
}

#[test]
fn a_load_cycle_far_beyond_the_film_is_contact_not_a_run_to_the_deadline() {
    // ±1 GN twice a revolution drives the journal to within 1e-5 C of the wall, where the
    // film is so stiff that the orbit took millions of steps and ran to the deadline (a bound
    // scan's 504); the run's step cap now ends it there, a 422 naming the load.
    let mut body = example();
    body["load"] = json!({"kind": "sinusoidal", "static_n": 1e4, "amplitude_n": 1e9,
        "frequency_ratio": 2, "direction_deg": -90});
    match post::<CompositeOrbit>(&body) {
        Err(Failure::Calc(CalcError::Impossible { pointer, message })) => {
            assert_eq!(pointer, "/load");
            assert!(message.contains("reaches the wall"), "{message}");
        }
        other => panic!("{other:?}"),
    }
}

#[test]
fn a_whirl_that_does_not_repeat_within_the_runs_steps_is_a_422_with_the_whole_runs_report() {
    // CI's proptest draw: a 2.6 kg journal under 22.8 kN rotating at 1.55 ω on the fixed arc,
    // its sleeve nearly free, whirls without repeating; the run ends at its step budget
    // (orbit::STEADY_RUN_STEPS over all its load periods), and the report counts every period's
    // steps at the requested fidelity, not the last period's alone.
    let mut body = example();
    body["fidelity"] = json!("fast");
    body["journal_mass_kg"] = json!(2.6041);
    body["sleeve_inertia_kg_m2"] = json!(1e-2);
    body["restraint_coefficient_kg_m2"] = json!(1.0032e-6);
    body["load"] = json!({"kind": "rotating", "magnitude_n": 22813.0, "speed_ratio": 1.5471,
        "direction_at_start_deg": 0});
    match post::<CompositeOrbit>(&body) {
        Err(Failure::Calc(CalcError::Stopped(report))) => {
            assert_eq!(report.stop_reason, StopReason::IterationCap);
            assert_eq!(
                report.iterations,
                crate::calc::journal::orbit::STEADY_RUN_STEPS
            );
            assert_eq!(report.fidelity, crate::fidelity::Level::Fast);
        }
        other => panic!("{other:?}"),
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(12))]
    #[test]
    fn every_locus_is_finite_inside_the_clearance_with_the_sleeve_between_rest_and_the_journal(
        load_exp in 1.0f64..5.0,
        mass_exp in -1.0f64..1.0,
        massless in any::<bool>(),
        pi_film in any::<bool>(),
        kind in 0usize..3,
        ratio in 0.25f64..3.0,
        inertia_exp in -6.0f64..-2.0,
        restraint_exp in -7.0f64..-2.0,
    ) {
        // With the pins opposing the sleeve's motion and the film driving it towards the
        // journal's speed, ξ stays within [0, 1] whatever the load. (Masses up to 10 kg here:
        // m̄ ≤ 0.1, below the whirl that heavier journals run into — a whirling orbit takes the
        // full 400 periods, seconds in a debug build.)
        let magnitude = 10f64.powf(load_exp);
        let mut body = example();
        body["fidelity"] = json!("fast");
        body["journal_mass_kg"] = json!(if massless { 0.0 } else { 10f64.powf(mass_exp) });
        body["film_model"] = json!(if pi_film { "short_pi_film" } else { "short_fixed_arc" });
        body["sleeve_inertia_kg_m2"] = json!(10f64.powf(inertia_exp));
        body["restraint_coefficient_kg_m2"] = json!(10f64.powf(restraint_exp));
        body["load"] = match kind {
            0 => json!({"kind": "constant", "magnitude_n": magnitude, "direction_deg": -90}),
            1 => json!({"kind": "rotating", "magnitude_n": magnitude, "speed_ratio": ratio, "direction_at_start_deg": 0}),
            _ => json!({"kind": "sinusoidal", "static_n": magnitude, "amplitude_n": magnitude, "frequency_ratio": ratio, "direction_deg": -90}),
        };
        // Under a 5 s deadline: light journals on the fixed arc can whirl out to ε ≈ 0.998,
        // where both loci take their 400 periods at a million steps (tens of seconds in a
        // debug build): a 504 then, never a number.
        let request = serde_json::to_vec(&body).unwrap();
        let deadline = std::time::Instant::now() + std::time::Duration::from_secs(5);
        let reply = crate::calc::execute::<CompositeOrbit>(&request, deadline, Default::default())
            .map(|done| serde_json::from_slice::<Value>(&done.body).unwrap());
        match reply {
            Ok(v) => {
                let r = &v["result"];
                for block in ["composite", "regular"] {
                    let max = field(r, &format!("/{block}/max_eccentricity_ratio"));
                    // The held sleeve may reach the wall: then it has no orbit, no minimum.
                    let min = r[block]["min_eccentricity_ratio"].as_f64().unwrap_or(0.0);
                    prop_assert!(0.0 <= min && min <= max && max < 1.0, "{v}");
                    let film = field(r, &format!("/{block}/min_film_m"));
                    prop_assert!(film > 0.0, "{}", film);
                }
                let (lo, hi) = (field(r, "/composite/min_speed_ratio"), field(r, "/composite/max_speed_ratio"));
                prop_assert!(0.0 <= lo && lo <= hi && hi <= 1.0, "{v}");
            }
            Err(Failure::Calc(CalcError::Impossible { .. })) => {}
            // A light journal whose sleeve runs nearly free (ξ → 1) can whirl out towards the
            // wall on the fixed arc; where the integrator's steps then underflow short of the
            // contact band, or a whirl does not repeat within the run's steps, it is a 422
            // with its report, never a number.
            Err(Failure::Calc(CalcError::Stopped(report))) => {
                prop_assert!(
                    matches!(report.stop_reason, StopReason::Stalled | StopReason::IterationCap),
                    "{report:?}"
                );
            }
            Err(Failure::Calc(CalcError::DeadlineExceeded)) => {}
            Err(other) => prop_assert!(false, "{body}: {other:?}"),
        }
    }
}
