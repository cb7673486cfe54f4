//! Composite bearings over HTTP: the 422s with their reasons (a missing or over-determined
//! restraint, ε ≥ 0.999, a load the film cannot carry; the orbit's), and the speed split over its range
//! (finite; the sleeve speed rising with the journal's, the speed ratio falling with the
//! restraint, the composite's film never thinner than the held sleeve's, the powers adding up).

use proptest::prelude::*;
use serde_json::{json, Value};
use stribeck::calc::{find, CalcError, Failure};

use crate::helpers::{assert_all_finite, example_patched, patched, refused, spawn_app};

const SPLIT: &str = "/v1/composite-bearings/speed-split";
const START: &str = "/v1/composite-bearings/start-up";
const ORBIT: &str = "/v1/composite-bearings/orbit";

fn start(extra: Value) -> Value {
    example_patched(START, &extra)
}

fn split(extra: Value) -> Value {
    let body = json!({
        "journal_radius_m": 0.05, "sleeve_length_m": 0.05, "radial_clearance_m": 5e-5,
        "lubricant": {"viscosity_pa_s": 0.03}, "journal_speed_rpm": 3000,
        "load_n": 5000, "restraint_coefficient_kg_m2": 0.01
    });
    patched(body, &extra)
}

#[tokio::test]
async fn the_composite_orbit_refuses_what_it_cannot_integrate_and_names_the_field() {
    let app = spawn_app().await;
    let orbit = |name: &str, value: Value| {
        let mut body: Value = serde_json::from_str(find(ORBIT).unwrap().example).unwrap();
        body[name] = value;
        body
    };
    let rows = [
        (
            orbit("sleeve_inertia_kg_m2", json!(1e-12)),
            "/sleeve_inertia_kg_m2",
            "within",
        ),
        (
            orbit("film_model", json!("short_full")),
            "/film_model",
            "unknown variant",
        ),
        (
            orbit("fidelity", json!("closed_form")),
            "/fidelity",
            "integrated in time",
        ),
        (
            orbit("journal_mass_kg", json!(5e-324)),
            "/journal_mass_kg",
            "massless",
        ),
    ];
    refused(&app, ORBIT, rows).await;
    // 1 GN at 1e-6 rpm on a 2 mm sleeve: no film short of h_min = 1e-9 C carries it at time 0.
    let mut body = orbit("journal_speed_rpm", json!(1e-6));
    body["sleeve_length_m"] = json!(0.002);
    body["load"] = json!({"kind": "constant", "magnitude_n": 1e9, "direction_deg": -90});
    let reply = app.post_json(ORBIT, &body).await;
    assert!(
        reply.problem(422)["detail"]
            .as_str()
            .unwrap()
            .contains("no static equilibrium"),
        "{}",
        reply.text
    );
}

#[tokio::test]
async fn bad_composite_input_is_a_422_with_its_reason() {
    let app = spawn_app().await;
    let rows = [
        (
            split(json!({"eccentricity_ratio": 0.5})),
            "/load_n",
            "exactly one",
        ),
        (
            split(json!({"load_n": null, "eccentricity_ratio": 0.9995})),
            "/eccentricity_ratio",
            "at most 0.999",
        ),
        (
            split(json!({"load_n": null, "eccentricity_ratio": 1.0})),
            "/eccentricity_ratio",
            "at most 0.999",
        ),
        (
            split(json!({"restraint_coefficient_kg_m2": null})),
            "/pin_mass_kg",
            "under-determined",
        ),
        (
            split(json!({"pin_friction_coefficient": 0.2})),
            "/restraint_coefficient_kg_m2",
            "over-determined",
        ),
        (
            split(
                json!({"restraint_coefficient_kg_m2": null, "pin_friction_coefficient": 0.2,
                         "pin_mass_kg": 1.0, "pin_radius_m": 0.2, "housing_radius_m": 0.1}),
            ),
            "/pin_radius_m",
            "housing_radius_m",
        ),
        (
            split(
                json!({"restraint_coefficient_kg_m2": null, "pin_friction_coefficient": 3.0,
                         "pin_mass_kg": 1.0, "pin_radius_m": 0.08, "housing_radius_m": 0.1}),
            ),
            "/pin_friction_coefficient",
            "at most 2",
        ),
        (
            split(json!({"radial_clearance_m": -5e-5})),
            "/radial_clearance_m",
            "> 0",
        ),
        (
            split(json!({"radial_clearance_m": 0.01})),
            "/radial_clearance_m",
            "thin film",
        ),
        (
            split(json!({"sleeve_length_m": 0.5})),
            "/sleeve_length_m",
            "L/D",
        ),
        (
            split(json!({"journal_speed_rpm": 2e6})),
            "/journal_speed_rpm",
            "at most",
        ),
        (
            split(json!({"rolling_friction_torque_n_m": -1.0})),
            "/rolling_friction_torque_n_m",
            ">= 0",
        ),
        (
            split(json!({"sleeve_wall_thickness_m": 0.01})),
            "/sleeve_thermal_diffusivity_m2_s",
            "required",
        ),
        (
            split(json!({"lubricant": {"iso_vg": 46}})),
            "/temperature_c",
            "required",
        ),
        (
            split(json!({"lenght_m": 0.05})),
            "/lenght_m",
            "unknown field",
        ),
    ];
    refused(&app, SPLIT, rows).await;
    // A load the film cannot carry below ε = 0.999 names the load and says how much it can.
    let reply = app
        .post_json(
            SPLIT,
            &split(json!({"load_n": 1e8, "journal_speed_rpm": 1.0})),
        )
        .await;
    reply.problem(422);
    assert!(
        reply.text.contains("/load_n") && reply.text.contains("cannot carry"),
        "{}",
        reply.text
    );
}

#[tokio::test]
async fn bad_start_up_input_is_a_422_with_its_reason() {
    let app = spawn_app().await;
    let rows = [
        (start(json!({"ramp_time_s": 0.0})), "/ramp_time_s", "> 0"),
        (
            start(json!({"ramp_time_s": 1e-9})),
            "/ramp_time_s",
            "within",
        ),
        (
            start(json!({"sleeve_inertia_kg_m2": null})),
            "/sleeve_inertia_kg_m2",
            "missing",
        ),
        (
            start(json!({"rolling_traction_coefficient": 5.0})),
            "/rolling_traction_coefficient",
            "within",
        ),
        (
            start(json!({"history_points": 5000})),
            "/history_points",
            "within",
        ),
        (
            start(json!({"eccentricity_ratio": 0.5})),
            "/eccentricity_ratio",
            "unknown field",
        ),
        (
            start(json!({"load_n": 1e8, "journal_speed_rpm": 1.0})),
            "/load_n",
            "cannot carry",
        ),
    ];
    for (body, pointer, why) in rows {
        let reply = app.post_json(START, &body).await;
        reply.problem(422);
        assert!(
            reply.text.contains(pointer) && reply.text.contains(why),
            "{body}: want {pointer} ({why}), got {}",
            reply.text
        );
    }
}

#[tokio::test]
async fn the_start_up_example_answers_over_http() {
    let app = spawn_app().await;
    let reply = app.post_json(START, &start(json!({}))).await;
    assert_eq!(reply.status, 200, "{}", reply.text);
    assert_all_finite(&reply.body, "");
    let r = &reply.body["result"];
    for field in [
        "breakaway_journal_speed_rpm",
        "breakaway_time_s",
        "steady_sleeve_speed_rpm",
        "sleeve_speed_at_ramp_end_rpm",
        "settling_time_s",
    ] {
        assert!(r[field].is_number(), "{field}: {r}");
    }
    assert_eq!(r["history"].as_array().unwrap().len(), 11);
    // The start-up's steady sleeve speed is the speed split's at the same load.
    let split_body = start(json!({"sleeve_inertia_kg_m2": null, "ramp_time_s": null,
        "rolling_traction_coefficient": null, "history_points": null}));
    let reply = app.post_json(SPLIT, &split_body).await;
    assert_eq!(reply.status, 200, "{}", reply.text);
    let want = reply.body["result"]["sleeve_speed_rpm"].as_f64().unwrap();
    let got = r["steady_sleeve_speed_rpm"].as_f64().unwrap();
    assert!((got / want - 1.0).abs() < 1e-12, "{got} vs {want}");
}

#[tokio::test]
async fn the_speed_split_example_answers_over_http() {
    let app = spawn_app().await;
    let example: Value = serde_json::from_str(find(SPLIT).unwrap().example).unwrap();
    let reply = app.post_json(SPLIT, &example).await;
    assert_eq!(reply.status, 200, "{}", reply.text);
    assert_all_finite(&reply.body, "");
    let r = &reply.body["result"];
    for field in [
        "sleeve_speed_rpm",
        "speed_ratio",
        "hydrodynamic_torque_n_m",
        "pin_torque_n_m",
        "hydrodynamic_power_w",
        "pin_power_w",
        "eccentricity_ratio",
        "min_film_m",
        "sleeve_peclet_number",
    ] {
        assert!(r[field].is_number(), "{field}: {r}");
    }
    for field in ["eccentricity_ratio", "min_film_m"] {
        assert!(r["fixed_sleeve"][field].is_number(), "{field}: {r}");
    }
}

fn run(path: &str, body: &Value) -> Result<Value, Failure> {
    let entry = find(path).expect("registered");
    let far = std::time::Instant::now() + std::time::Duration::from_secs(60);
    (entry.execute)(&serde_json::to_vec(body).unwrap(), far, Default::default())
        .map(|done| serde_json::from_slice(&done.body).expect("the envelope is JSON"))
}

fn field(v: &Value, name: &str) -> f64 {
    v["result"][name].as_f64().unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Over speeds 10–1e5 rpm, loads 1–1e6 N, restraints 1e-6–10 kg·m², rolling torques up to
    /// 10 N·m and L/D 0.1–1: a finite result or a 422 that the load cannot be carried, never a
    /// 500. Where both neighbours answer: the sleeve speed rises with the journal speed, the
    /// speed ratio falls as the restraint grows, the composite's film is at least the held
    /// sleeve's, and the film, pin and rolling powers add up to the journal's.
    #[test]
    fn speed_splits_are_finite_and_monotone(
        log_rpm in 1.0f64..5.0,
        log_load in 0.0f64..6.0,
        log_k in -6.0f64..1.0,
        rolling in prop_oneof![Just(0.0), 0.0f64..10.0],
        l_over_d in 0.1f64..1.0,
    ) {
        let body = |rpm: f64, k: f64| split(json!({
            "sleeve_length_m": l_over_d * 0.1,
            "journal_speed_rpm": rpm,
            "load_n": 10f64.powf(log_load),
            "restraint_coefficient_kg_m2": k,
            "rolling_friction_torque_n_m": rolling,
        }));
        let (rpm, k) = (10f64.powf(log_rpm), 10f64.powf(log_k));
        let base = run(SPLIT, &body(rpm, k));
        let faster = run(SPLIT, &body(1.2 * rpm, k));
        let stiffer = run(SPLIT, &body(rpm, 2.0 * k));
        match (base, faster, stiffer) {
            (Ok(base), Ok(faster), Ok(stiffer)) => {
                for v in [&base, &faster, &stiffer] {
                    assert_all_finite(v, "");
                    let xi = field(v, "speed_ratio");
                    prop_assert!((0.0..1.0).contains(&xi), "{xi}");
                    prop_assert!(field(v, "min_film_ratio") >= 1.0 - 1e-9);
                    let parts = field(v, "hydrodynamic_power_w") + field(v, "pin_power_w")
                        + field(v, "rolling_power_w");
                    let total = field(v, "total_power_w");
                    prop_assert!((parts - total).abs() <= 1e-9 * total, "{parts} vs {total}");
                }
                prop_assert!(
                    field(&faster, "sleeve_speed_rpm") >= field(&base, "sleeve_speed_rpm"),
                    "{} vs {}", field(&faster, "sleeve_speed_rpm"), field(&base, "sleeve_speed_rpm")
                );
                prop_assert!(field(&faster, "eccentricity_ratio") <= field(&base, "eccentricity_ratio") + 1e-12);
                prop_assert!(field(&stiffer, "speed_ratio") <= field(&base, "speed_ratio"));
            }
            (Err(Failure::Calc(err)), _, _) | (_, Err(Failure::Calc(err)), _) | (_, _, Err(Failure::Calc(err))) => {
                let heavy = matches!(&err, CalcError::Impossible { pointer, message }
                    if pointer == "/load_n" && message.contains("cannot carry"));
                prop_assert!(heavy, "{err:?}");
            }
            (Err(other), _, _) | (_, Err(other), _) | (_, _, Err(other)) => prop_assert!(false, "{other:?}"),
        }
    }

    /// Start-ups over traction, restraint, inertia, ramp and rolling torque: a finite result
    /// (or a 422 that the load cannot be carried), never a 500; more traction never breaks
    /// away sooner; the history starts at rest and ends in the settling band.
    #[test]
    fn start_ups_are_finite_and_monotone(
        log_traction in -4.0f64..0.0,
        log_k in -3.0f64..0.0,
        log_inertia in -4.0f64..0.0,
        log_ramp in -1.0f64..1.0,
        rolling in prop_oneof![Just(0.0), 0.0f64..5.0],
    ) {
        let body = |traction: f64| start(json!({
            "rolling_traction_coefficient": traction,
            "restraint_coefficient_kg_m2": 10f64.powf(log_k),
            "sleeve_inertia_kg_m2": 10f64.powf(log_inertia),
            "ramp_time_s": 10f64.powf(log_ramp),
            "rolling_friction_torque_n_m": rolling,
        }));
        let traction = 10f64.powf(log_traction);
        match (run(START, &body(traction)), run(START, &body(1.5 * traction))) {
            (Ok(lo), Ok(hi)) => {
                for v in [&lo, &hi] {
                    assert_all_finite(v, "");
                    let history = v["result"]["history"].as_array().unwrap();
                    prop_assert_eq!(history[0]["sleeve_speed_rpm"].as_f64(), Some(0.0));
                    let steady = field(v, "steady_sleeve_speed_rpm");
                    let last = history.last().unwrap()["sleeve_speed_rpm"].as_f64().unwrap();
                    let band = 0.01 * if steady > 0.0 { steady } else { 3500.0 };
                    prop_assert!((last - steady).abs() <= band, "{} vs {}", last, steady);
                }
                let t = |v: &Value| v["result"]["breakaway_time_s"].as_f64().unwrap_or(f64::INFINITY);
                prop_assert!(t(&hi) >= t(&lo), "{} vs {}", t(&hi), t(&lo));
            }
            (Err(Failure::Calc(err)), _) | (_, Err(Failure::Calc(err))) => {
                prop_assert!(!matches!(err, CalcError::Internal(_)), "{err:?}");
            }
            (Err(other), _) | (_, Err(other)) => prop_assert!(false, "{other:?}"),
        }
    }
}
