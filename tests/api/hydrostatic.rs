//! Hydrostatic rooms over HTTP: the examples answer; bad input and impossible physics are 422s
//! (problem+json) naming the field with the reason; the design room's two questions; a
//! designed restrictor is the optimum the texts derive.

use serde_json::{json, Value};

use crate::helpers::{assert_all_finite, refused, spawn_app};

const PAD: &str = "/v1/hydrostatic-bearings/pad";
const DESIGN: &str = "/v1/hydrostatic-bearings/design";

fn pad() -> Value {
    json!({
        "pad": {"kind": "circular_step", "recess_radius_m": 0.0635, "outer_radius_m": 0.127},
        "compensation": {"kind": "orifice", "discharge_coefficient": 0.6, "pressure_ratio": "optimum"},
        "lubricant": {"iso_vg": 68, "density_15c_kg_m3": 870},
        "temperature_c": 40, "film_m": 5e-5, "load_n": 1.5e5, "speed_rpm": 300,
    })
}

#[tokio::test]
async fn the_examples_answer_over_http() {
    let app = spawn_app().await;
    for path in [PAD, DESIGN] {
        let example: Value =
            serde_json::from_str(stribeck::calc::find(path).unwrap().example).unwrap();
        let reply = app.post_json(path, &example).await;
        assert_eq!(reply.status, 200, "{path}: {}", reply.text);
        assert_all_finite(&reply.body, "");
        for effect in stribeck::calc::find(path).unwrap().effects {
            assert!(
                reply.body["effects"][effect]["reason"].is_string(),
                "{path} {effect}"
            );
        }
    }
    let reply = app.post_json(PAD, &pad()).await;
    assert_eq!(reply.status, 200, "{}", reply.text);
    let r = &reply.body["result"];
    let m = r["pressure_ratio"].as_f64().unwrap();
    assert!((m - (2.0 - 2f64.sqrt())).abs() < 1e-12);
    // K = 0.586 (3W/h) at the orifice optimum (Eq. 10.35).
    let k = r["stiffness_n_m"].as_f64().unwrap();
    let w = r["load_n"].as_f64().unwrap();
    assert!((k / (3.0 * w / 5e-5) - 0.585_786).abs() < 1e-6);
}

/// The README's water-lubricated pad: its capillary runs at Re 6×10⁴, so `auto` applies the
/// turbulent laws. Checked from the reply alone: the capillary drops Khonsari & Booser's
/// turbulent line loss f (l/d) ρU²/2 with f = 0.184 Re^−0.2 (Eq. 2.36), and the lands, laminar
/// at Re_2h 1230, hold p_r = 6μQ ln(R2/R1)/(πh³) (Eq. 10.6).
#[tokio::test]
async fn a_turbulent_capillary_follows_the_line_loss() {
    let app = spawn_app().await;
    let body = json!({
        "pad": {"kind": "circular_step", "recess_radius_m": 0.025, "outer_radius_m": 0.05},
        "compensation": {"kind": "capillary", "radius_m": 0.001, "length_m": 0.2},
        "lubricant": {"viscosity_pa_s": 0.001, "density_15c_kg_m3": 1000}, "temperature_c": 15,
        "film_m": 1.5e-4, "supply_pressure_pa": 1e6, "speed_rpm": 3000,
    });
    let reply = app.post_json(PAD, &body).await;
    assert_eq!(reply.status, 200, "{}", reply.text);
    assert_all_finite(&reply.body, "");
    let decision = &reply.body["effects"]["turbulence"];
    assert_eq!(decision["applied"], true, "{decision}");
    assert_eq!(decision["model"], "larger_loss_of_laminar_and_turbulent");
    let r = &reply.body["result"];
    let n = |v: &Value| v.as_f64().unwrap();
    let rest = &r["restrictor"];
    let (re, u, drop) = (
        n(&rest["reynolds_number"]),
        n(&rest["mean_velocity_m_s"]),
        n(&rest["pressure_drop_pa"]),
    );
    assert!(re > 2000.0, "{re}");
    let line_loss = 0.184 * re.powf(-0.2) * (0.2 / 0.002) * 1000.0 * u * u / 2.0;
    assert!(
        (drop / line_loss - 1.0).abs() < 1e-12,
        "{drop} vs {line_loss}"
    );
    let (q, pr) = (n(&r["flow_m3_s"]), n(&r["recess_pressure_pa"]));
    assert!(n(&r["land_pressure_flow_reynolds_number"]) < 2000.0);
    let laminar_land = 6.0 * 1e-3 * q * 2f64.ln() / (std::f64::consts::PI * 1.5e-4f64.powi(3));
    assert!(
        (pr / laminar_land - 1.0).abs() < 1e-12,
        "{pr} vs {laminar_land}"
    );
    assert!(((pr + drop) / 1e6 - 1.0).abs() < 1e-12);
}

#[tokio::test]
async fn bad_pads_are_422s_naming_the_field_with_the_reason() {
    let app = spawn_app().await;
    let with = |pointer: &str, value: Value| {
        let mut b = pad();
        let (parent, key) = pointer.rsplit_once('/').unwrap();
        let target = if parent.is_empty() {
            &mut b
        } else {
            b.pointer_mut(parent).unwrap()
        };
        if value.is_null() {
            target.as_object_mut().unwrap().remove(key);
        } else {
            target[key] = value;
        }
        b
    };
    let rows = [
        (
            with("/pad/recess_radius_m", json!(0.2)),
            "/pad/recess_radius_m",
            "below outer_radius_m",
        ),
        (
            with("/pad/recess_radius_m", json!(0.127)),
            "/pad/recess_radius_m",
            "below outer_radius_m",
        ),
        (
            with("/pad/outer_radius_m", json!(0)),
            "/pad/outer_radius_m",
            "> 0",
        ),
        (with("/film_m", json!(0.02)), "/film_m", "1e-2"),
        (with("/film_m", Value::Null), "/film_m", "under-determined"),
        (
            with("/supply_pressure_pa", json!(1e7)),
            "/supply_pressure_pa",
            "over-determined",
        ),
        (
            with("/compensation/radius_m", json!(1e-3)),
            "/compensation/radius_m",
            "not both",
        ),
        (
            with("/compensation/pressure_ratio", json!(1.5)),
            "/compensation/pressure_ratio",
            "between 0 and 1",
        ),
        (
            // The edge fuzzer's finds: a subnormal ratio, efficiency or radius made the pumping
            // power infinite (a 500 in the film-temperature root).
            with("/compensation/pressure_ratio", json!(5e-324)),
            "/compensation/pressure_ratio",
            "between 0 and 1",
        ),
        (
            with("/pump_efficiency", json!(5e-324)),
            "/pump_efficiency",
            "not subnormal",
        ),
        (
            with("/pad/recess_radius_m", json!(5e-324)),
            "/pad/recess_radius_m",
            "not subnormal",
        ),
        (
            // The edge fuzzer's find: R/R₀ = 10/2.2e-308 overflowed ln(R/R₀) (a 500).
            json!({"pad": {"kind": "circular_step", "recess_radius_m": f64::MIN_POSITIVE, "outer_radius_m": 10},
                   "compensation": {"kind": "capillary", "radius_m": 0.000762, "pressure_ratio": "optimum"},
                   "lubricant": {"iso_vg": 68, "density_15c_kg_m3": 870}, "temperature_c": 40,
                   "film_m": 7.62e-05, "load_n": 177929, "speed_rpm": 100}),
            "/pad/recess_radius_m",
            "at least 1e-6 outer_radius_m",
        ),
        (
            // The edge fuzzer's find: an exponential law with β = 1/K leaves no finite film at
            // the root's hot end (1000 °C), a 500 in the film-temperature root.
            json!({"pad": {"kind": "circular_step", "recess_radius_m": 0.0635, "outer_radius_m": 0.127},
                   "compensation": {"kind": "capillary", "radius_m": 0.000762, "pressure_ratio": "optimum"},
                   "lubricant": {"density_15c_kg_m3": 830.4, "exponential": {"reference_viscosity_pa_s": 0.03,
                       "reference_temperature_c": 40.0, "temperature_coefficient_1_k": 1}},
                   "temperature_c": 15, "film_m": 7.62e-05, "load_n": 177929, "speed_rpm": 100}),
            "/temperature_c",
            "thermal runaway",
        ),
        (
            // And a bore too small to pass a representable flow: the isothermal rise was ∞ and
            // the film-temperature root failed at the inlet temperature (a 500).
            json!({"pad": {"kind": "circular_step", "recess_radius_m": 0.025, "outer_radius_m": 0.05},
                   "compensation": {"kind": "capillary", "radius_m": 1e-300, "length_m": 0.2},
                   "lubricant": {"iso_vg": 68}, "temperature_c": 15, "film_m": 0.00015,
                   "supply_pressure_pa": 1e6, "speed_rpm": 3000}),
            "",
            "outside the floating-point range",
        ),
        (
            with("/compensation/discharge_coefficient", Value::Null),
            "/compensation/discharge_coefficient",
            "required",
        ),
        (with("/speed_rpm", json!(-1)), "/speed_rpm", ">= 0"),
        (
            with("/pump_efficiency", json!(1.5)),
            "/pump_efficiency",
            "(0, 1]",
        ),
        (with("/lenght_m", json!(1)), "/lenght_m", "unknown field"),
    ];
    refused(&app, PAD, rows).await;
    // Impossible physics: a load beyond what the supply pressure can carry.
    let mut b = pad();
    b["compensation"] = json!({"kind": "orifice", "discharge_coefficient": 0.6, "radius_m": 3e-4});
    b.as_object_mut().unwrap().remove("film_m");
    b["supply_pressure_pa"] = json!(1e6);
    b["load_n"] = json!(1e6);
    let reply = app.post_json(PAD, &b).await;
    reply.problem(422);
    assert_eq!(reply.pointers(), vec!["/load_n"], "{}", reply.text);
    assert!(reply.text.contains("supply pressure"), "{}", reply.text);
}

#[tokio::test]
async fn the_design_room_answers_both_questions_and_refuses_the_rest() {
    let app = spawn_app().await;
    let base = json!({"load_n": 4.79e5, "lubricant": {"viscosity_pa_s": 0.054}, "pump_efficiency": 0.8,
                      "pad": {"kind": "circular_step", "outer_radius_m": 0.2032}});
    // At speed with a free film: ζ = 3 at the minimum-pumping ratio, with both curves.
    let mut b = base.clone();
    b["speed_rpm"] = json!(600);
    b["include_power_curve"] = json!(true);
    let reply = app.post_json(DESIGN, &b).await;
    assert_eq!(reply.status, 200, "{}", reply.text);
    assert_all_finite(&reply.body, "");
    let d = &reply.body["result"]["minimum_power"];
    assert!((d["power_ratio"].as_f64().unwrap() - 3.0).abs() < 1e-9);
    assert!((d["recess_ratio"].as_f64().unwrap() - 0.533_543).abs() < 1e-6);
    let curve = d["power_curve"]["over_film"].as_array().unwrap();
    let least = curve
        .iter()
        .map(|p| p["total_power_w"].as_f64().unwrap())
        .fold(f64::INFINITY, f64::min);
    assert!(least >= d["total_power_w"].as_f64().unwrap() * (1.0 - 1e-12));
    // At rest without a film: under-determined.
    let reply = app.post_json(DESIGN, &base).await;
    reply.problem(422);
    assert_eq!(reply.pointers(), vec!["/film_m"], "{}", reply.text);
    // Both questions at once, or neither.
    let mut b = base.clone();
    b["oil_lift"] = json!({"diameter_m": 0.5, "length_m": 0.45, "radial_clearance_m": 4e-4, "lift_m": 1e-4, "pocket_count": 2, "pocket_area_m2": 4e-3});
    let reply = app.post_json(DESIGN, &b).await;
    reply.problem(422);
    assert_eq!(reply.pointers(), vec!["/pad", "/oil_lift"]);
    // A lift no smaller than the clearance.
    b.as_object_mut().unwrap().remove("pad");
    b["oil_lift"]["lift_m"] = json!(4e-4);
    let reply = app.post_json(DESIGN, &b).await;
    reply.problem(422);
    assert_eq!(reply.pointers(), vec!["/oil_lift/lift_m"]);
    b["oil_lift"]["lift_m"] = json!(1e-4);
    b["oil_lift"]["lift_zone_length_m"] = json!(0.3);
    let reply = app.post_json(DESIGN, &b).await;
    assert_eq!(reply.status, 200, "{}", reply.text);
    let l = &reply.body["result"]["oil_lift"];
    assert!(l["equilibrium_pressure_pa"].as_f64().unwrap() > 0.0);
    assert!(l["pumping_power_w"].as_f64().unwrap() > 0.0);
}
