//! Lubricant rooms over their whole valid input range: every answer is a finite result or a 4xx,
//! never a 500; viscosity falls with temperature and rises with pressure; VI is continuous
//! across its two procedures.

use proptest::prelude::*;
use serde_json::{json, Value};
use stribeck::calc::{find, CalcError, Failure};

fn run(path: &str, body: &Value) -> Result<Value, Failure> {
    let entry = find(path).expect("registered");
    let far = std::time::Instant::now() + std::time::Duration::from_secs(30);
    (entry.execute)(&serde_json::to_vec(body).unwrap(), far, Default::default())
        .map(|done| serde_json::from_slice(&done.body).expect("the envelope is JSON"))
}

fn assert_no_internal(r: &Result<Value, Failure>) {
    if let Err(Failure::Calc(CalcError::Internal(cause))) = r {
        panic!("internal error: {cause}");
    }
}

fn lubricant() -> impl Strategy<Value = Value> {
    let walther = (2.5f64..1e5, 0.02f64..0.9).prop_map(|(nu40, ratio)| {
        json!({"kinematic_viscosity_40c_mm2_s": nu40, "kinematic_viscosity_100c_mm2_s": (nu40 * ratio).max(2.0).min(nu40 * 0.99)})
    });
    let constant = (1e-5f64..1e4).prop_map(|mu| json!({"viscosity_pa_s": mu}));
    let iso = (0usize..20, 0.0f64..200.0).prop_map(|(i, vi)| {
        let grades = [
            2, 3, 5, 7, 10, 15, 22, 32, 46, 68, 100, 150, 220, 320, 460, 680, 1000, 1500, 2200,
            3200,
        ];
        json!({"iso_vg": grades[i], "viscosity_index": vi})
    });
    let exponential = (1e-4f64..10.0, -20.0f64..150.0, 0.0f64..0.1).prop_map(|(mu, t, b)| {
        json!({"exponential": {"reference_viscosity_pa_s": mu, "reference_temperature_c": t, "temperature_coefficient_1_k": b}})
    });
    let pressure = prop_oneof![
        Just(json!({})),
        (1e-9f64..1e-7).prop_map(|a| json!({"pressure_viscosity_coefficient_1_pa": a})),
        (0.05f64..1.5).prop_map(|z| json!({"roelands_pressure_viscosity_index": z})),
    ];
    (prop_oneof![walther, constant, iso, exponential], pressure).prop_map(|(mut l, p)| {
        for (k, v) in p.as_object().unwrap() {
            l[k] = v.clone();
        }
        l
    })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, ..ProptestConfig::default() })]

    #[test]
    fn viscosity_is_finite_monotone_or_refused(lub in lubricant(), t0 in -60.0f64..300.0, dt in 1.0f64..100.0, p in 0.0f64..5e9) {
        let body = json!({"lubricant": lub, "temperatures_c": [t0, t0 + dt], "pressures_pa": [0.0, p]});
        let r = run("/v1/lubricants/viscosity", &body);
        assert_no_internal(&r);
        if let Ok(v) = r {
            let pts = v["result"]["points"].as_array().unwrap();
            let mu = |i: usize| pts[i]["dynamic_viscosity_pa_s"].as_f64().unwrap();
            for i in 0..4 { prop_assert!(mu(i).is_finite() && mu(i) > 0.0); }
            // Temperature: points 0 (t0, 0) and 2 (t0 + dt, 0).
            prop_assert!(mu(2) <= mu(0) * (1.0 + 1e-12), "viscosity rose with temperature: {lub}");
            // Pressure: points 0 (t0, 0) and 1 (t0, p).
            prop_assert!(mu(1) >= mu(0) * (1.0 - 1e-12), "viscosity fell with pressure: {lub}");
        }
    }

    #[test]
    fn properties_are_finite_or_refused(lub in lubricant(), t in -60.0f64..300.0) {
        let r = run("/v1/lubricants/properties", &json!({"lubricant": lub, "temperatures_c": [t]}));
        assert_no_internal(&r);
    }

    #[test]
    fn viscosity_index_is_finite_or_refused(nu100 in 1.0f64..2e3, ratio in 1.01f64..200.0) {
        let body = json!({"kinematic_viscosity_40c_mm2_s": nu100 * ratio, "kinematic_viscosity_100c_mm2_s": nu100});
        let r = run("/v1/lubricants/viscosity-index", &body);
        assert_no_internal(&r);
        match r {
            Ok(v) => prop_assert!(nu100 >= 2.0 && v["result"]["viscosity_index"].as_f64().unwrap().is_finite()),
            Err(_) => prop_assert!(nu100 < 2.0 || nu100 * ratio > 1e6 || nu100 > 1e5),
        }
    }

    /// At fixed ν100 a thinner 40 °C oil has the higher VI: VI falls as ν40 rises, across both
    /// procedures and the table/quadratic boundary at 70 mm²/s.
    #[test]
    fn viscosity_index_falls_as_nu40_rises(nu100 in 2.0f64..150.0, r1 in 1.05f64..30.0, dr in 0.01f64..5.0) {
        let vi = |nu40: f64| run("/v1/lubricants/viscosity-index", &json!({"kinematic_viscosity_40c_mm2_s": nu40, "kinematic_viscosity_100c_mm2_s": nu100}))
            .map(|v| v["result"]["viscosity_index"].as_f64().unwrap());
        if let (Ok(a), Ok(b)) = (vi(nu100 * r1), vi(nu100 * (r1 + dr))) {
            prop_assert!(b < a, "VI({}) = {a}, VI({}) = {b}", nu100 * r1, nu100 * (r1 + dr));
        }
    }
}

/// An ISO VG preset states its assumptions, and its ν40 is the grade.
#[test]
fn iso_vg_preset_is_the_grade_midpoint_with_stated_assumptions() {
    let v = run(
        "/v1/lubricants/viscosity",
        &json!({"lubricant": {"iso_vg": 68}, "temperatures_c": [40.0]}),
    )
    .unwrap();
    let nu = v["result"]["points"][0]["kinematic_viscosity_mm2_s"]
        .as_f64()
        .unwrap();
    assert!((nu - 68.0).abs() < 1e-9, "{nu}");
    let codes: Vec<&str> = v["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .map(|w| w["code"].as_str().unwrap())
        .collect();
    assert!(
        codes.contains(&"iso_vg_preset") && codes.contains(&"density_assumed"),
        "{codes:?}"
    );
    // The preset's VI is the requested one (default 100).
    let vi = run(
        "/v1/lubricants/viscosity-index",
        &json!({"lubricant": {"iso_vg": 68}}),
    )
    .unwrap();
    assert!((vi["result"]["viscosity_index"].as_f64().unwrap() - 100.0).abs() < 1e-6);
}

#[test]
fn validity_warnings_name_the_model_limits() {
    let codes = |body: Value| -> Vec<String> {
        let v = run("/v1/lubricants/viscosity", &body).unwrap();
        v["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .map(|w| w["code"].as_str().unwrap().to_owned())
            .collect()
    };
    let barus = codes(
        json!({"lubricant": {"viscosity_pa_s": 0.03, "pressure_viscosity_coefficient_1_pa": 2e-8, "density_15c_kg_m3": 870.0}, "temperatures_c": [40.0], "pressures_pa": [1e8]}),
    );
    assert!(
        barus.contains(&"barus_above_70_mpa".to_owned()),
        "{barus:?}"
    );
    let thin = codes(
        json!({"lubricant": {"kinematic_viscosity_40c_mm2_s": 8.0, "kinematic_viscosity_100c_mm2_s": 2.3, "density_15c_kg_m3": 870.0}, "temperatures_c": [150.0]}),
    );
    assert!(
        thin.contains(&"walther_below_2_mm2_s".to_owned()),
        "{thin:?}"
    );
    let cold = codes(
        json!({"lubricant": {"kinematic_viscosity_40c_mm2_s": 32.0, "kinematic_viscosity_100c_mm2_s": 5.4, "density_15c_kg_m3": 870.0, "pour_point_c": -9.0}, "temperatures_c": [-20.0]}),
    );
    assert!(cold.contains(&"below_pour_point".to_owned()), "{cold:?}");
}

/// Piezoviscosity: not applicable without a law, applied with one above 1 %, not at zero pressure,
/// and off costs nothing (the viscosity stays the ambient one).
#[test]
fn piezoviscosity_is_decided_and_reported() {
    let base = json!({"viscosity_pa_s": 0.03, "density_15c_kg_m3": 870.0});
    let with_law = json!({"viscosity_pa_s": 0.03, "density_15c_kg_m3": 870.0, "pressure_viscosity_coefficient_1_pa": 2e-8});
    let decision = |lub: &Value, p: f64, mode: &str| {
        let v = run("/v1/lubricants/viscosity", &json!({"lubricant": lub, "temperatures_c": [40.0], "pressures_pa": [p], "effects": {"piezoviscosity": mode}})).unwrap();
        (
            v["effects"]["piezoviscosity"].clone(),
            v["result"]["points"][0]["dynamic_viscosity_pa_s"]
                .as_f64()
                .unwrap(),
        )
    };
    let (d, _) = decision(&base, 1e8, "auto");
    assert_eq!(d["applied"], false);
    assert!(d["reason"].as_str().unwrap().contains("no pressure"));
    let (d, mu) = decision(&with_law, 1e7, "auto");
    assert_eq!(d["applied"], true);
    assert_eq!(d["criterion"]["name"], "viscosity_rise_at_max_pressure");
    assert!((mu - 0.03 * (0.2f64).exp()).abs() < 1e-12);
    let (d, mu) = decision(&with_law, 1e5, "auto");
    assert_eq!(d["applied"], false, "a 0.2 % rise is negligible");
    assert_eq!(mu, 0.03);
    let (d, mu) = decision(&with_law, 1e8, "off");
    assert_eq!((d["applied"].clone(), mu), (json!(false), 0.03));
}

/// Every room that takes its oil at a temperature says when that oil runs hotter than oils
/// last (issue 12, item 5: a journal at 1000 °C inlet answered without a word): above 150 °C
/// the mineral oils' limit, above 230 °C the synthetics' (Khonsari & Booser Table 14.7). Each
/// registered example gets its temperature fields (or `temperature_c` where the room takes
/// one) set hot; a room answers with the warning, or refuses the temperature itself.
#[test]
fn every_room_warns_of_oil_above_its_temperature_limit() {
    let mut warned = Vec::new();
    // Grease life is a grease's: Eq. 15.34 has its own fitted range (75–175 °C), which it warns of.
    for entry in stribeck::calc::REGISTRY
        .iter()
        .filter(|e| e.path != "/v1/rolling-bearings/grease-life")
    {
        let example: Value = serde_json::from_str(entry.example).unwrap();
        let fields: Vec<&str> = ["temperature_c", "inlet_temperature_c", "temperatures_c"]
            .into_iter()
            .filter(|k| example.get(*k).is_some())
            .collect();
        let fields = if fields.is_empty() {
            vec!["temperature_c"]
        } else {
            fields
        };
        for (t, code) in [
            (160.0, "temperature_above_mineral_oil_limit"),
            (400.0, "temperature_above_oil_limit"),
        ] {
            let mut body = example.clone();
            for k in &fields {
                body[*k] = if *k == "temperatures_c" {
                    json!([40.0, t])
                } else {
                    json!(t)
                };
            }
            match run(entry.path, &body) {
                Ok(v) => {
                    let codes: Vec<&str> = v["warnings"]
                        .as_array()
                        .unwrap()
                        .iter()
                        .map(|w| w["code"].as_str().unwrap())
                        .collect();
                    assert!(codes.contains(&code), "{} at {t} °C: {codes:?}", entry.path);
                    warned.push((entry.path, t));
                }
                // A room without a temperature, or with its own narrower range.
                Err(Failure::Invalid(errors)) => assert!(
                    errors
                        .iter()
                        .any(|e| fields.iter().any(|k| e.pointer == format!("/{k}"))),
                    "{}: {errors:?}",
                    entry.path
                ),
                Err(other) => panic!("{} at {t} °C: {other:?}", entry.path),
            }
        }
    }
    // The lubricant, journal, thrust, EHL, rolling-analysis, squeeze, hydrostatic, dynamic,
    // whirl and composite rooms.
    assert!(warned.len() >= 2 * 18, "{warned:?}");
}

/// Roelands' law at 5 GPa gives 1.35e20 Pa·s: an extrapolation past the 0.5–3 GPa of EHL
/// contacts (issue 12, item 5), which the viscosity room now says; at 1 GPa it does not.
#[test]
fn a_pressure_beyond_the_piezoviscous_range_warns() {
    let body = |p: f64| {
        json!({"lubricant": {"kinematic_viscosity_40c_mm2_s": 31.0, "kinematic_viscosity_100c_mm2_s": 5.4, "roelands_pressure_viscosity_index": 0.68},
               "temperatures_c": [40.0], "pressures_pa": [0.0, p]})
    };
    let codes = |v: Value| -> Vec<String> {
        v["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .map(|w| w["code"].as_str().unwrap().to_owned())
            .collect()
    };
    let hot = run("/v1/lubricants/viscosity", &body(5e9)).unwrap();
    assert!(codes(hot).contains(&"pressure_beyond_piezoviscous_range".to_owned()));
    let fine = run("/v1/lubricants/viscosity", &body(1e9)).unwrap();
    assert!(!codes(fine).contains(&"pressure_beyond_piezoviscous_range".to_owned()));
}

/// An EHL film with a constant viscosity needs no temperature (issue 12, item 10); a
/// temperature law still does, and says so at /temperature_c.
#[test]
fn ehl_rooms_take_a_constant_viscosity_without_a_temperature() {
    for path in ["/v1/contacts/ehl-film", "/v1/contacts/ehl"] {
        let mut body: Value = serde_json::from_str(find(path).unwrap().example).unwrap();
        let with = run(path, &body).unwrap();
        body.as_object_mut().unwrap().remove("temperature_c");
        let without = run(path, &body).unwrap();
        assert_eq!(with["result"], without["result"], "{path}");
        body["lubricant"] = json!({"kinematic_viscosity_40c_mm2_s": 31.0, "kinematic_viscosity_100c_mm2_s": 5.4, "roelands_pressure_viscosity_index": 0.68});
        match run(path, &body) {
            Err(Failure::Invalid(errors)) => {
                assert_eq!(errors[0].pointer, "/temperature_c", "{path}");
                assert!(errors[0].message.contains("required"), "{path}");
            }
            other => panic!("{path}: {other:?}"),
        }
    }
}
