//! Contract tests of the plain-bearing room, through the registry's path.

use serde_json::Value;
use utoipa::PartialSchema;

use super::*;
use crate::calc::testing;

/// Effects are named once: the effects the room decides at run time (the README example) are
/// the ones `EFFECTS` lists, and the request's `effects` object has a field for each of them.
#[test]
fn decided_effects_match_the_list_and_the_request_fields() {
    let request: Value = serde_json::from_str(PlainJournal::EXAMPLE).expect("the example is JSON");
    let envelope = testing::ok::<PlainJournal>(&request);
    let mut decided: Vec<&str> = envelope["effects"]
        .as_object()
        .expect("an effects object")
        .keys()
        .map(String::as_str)
        .collect();
    decided.sort_unstable();
    let mut listed = PlainJournal::EFFECTS.to_vec();
    listed.sort_unstable();
    assert_eq!(decided, listed);

    let schema = serde_json::to_value(JournalEffects::schema()).expect("a schema serialises");
    let mut fields: Vec<&str> = schema["properties"]
        .as_object()
        .expect("the effects schema has properties")
        .keys()
        .map(String::as_str)
        .collect();
    fields.sort_unstable();
    assert_eq!(fields, listed);
}

/// Misalignment is an effect like the others: `off` solves the aligned journal whatever the
/// request's `misalignment` gives, and says so; `on` without a misalignment is not applicable.
#[test]
fn misalignment_off_solves_the_aligned_journal() {
    let mut request: Value = serde_json::from_str(PlainJournal::EXAMPLE).expect("JSON");
    request["fidelity"] = "fast".into();
    request["dynamics"] = false.into();
    let aligned = testing::ok::<PlainJournal>(&request);
    request["effects"] = serde_json::json!({"misalignment": "on"});
    let on_without = testing::ok::<PlainJournal>(&request);
    assert_eq!(on_without["effects"]["misalignment"]["applied"], false);
    assert_eq!(on_without["effects"]["misalignment"]["mode"], "on");
    request["misalignment"] = serde_json::json!({"slope_rad": 0.0001});
    request["effects"] = serde_json::json!({"misalignment": "off"});
    let off = testing::ok::<PlainJournal>(&request);
    let decision = &off["effects"]["misalignment"];
    assert_eq!(
        (&decision["applied"], &decision["mode"]),
        (&false.into(), &"off".into())
    );
    assert!(decision["reason"]
        .as_str()
        .is_some_and(|r| r.contains("not applied")));
    assert!(off["result"].get("misalignment_moment").is_none());
    assert_eq!(off["result"], aligned["result"]);
}

/// The heat balance holds in every answer and an overload is refused: the README bearing with
/// its load swept over ten decades either balances (T_eff = T_in + ΔT, Eq. 8.63, at the load it
/// was asked) or answers 422 on `/load_n` — never a 200 from the edge of the eccentricity range;
/// an overload's answer names the largest load with an equilibrium, and that load is carried.
#[test]
fn the_heat_balance_holds_or_the_load_is_refused() {
    let mut refused = 0;
    for k in 0..=40 {
        let load = 10f64.powf(-1.0 + 0.25 * f64::from(k));
        let request = serde_json::json!({
            "geometry": {"diameter_m": 0.1, "length_m": 0.1, "radial_clearance_m": 0.0001},
            "speed_rpm": 3000, "lubricant": {"iso_vg": 32}, "load_n": load,
            "inlet_temperature_c": 40, "fidelity": "fast", "dynamics": false
        });
        match testing::post::<PlainJournal>(&request) {
            Ok(v) => {
                let t = testing::result_field(&v, "effective_temperature_c");
                let rise = testing::result_field(&v, "temperature_rise_k");
                assert!(
                    (t - 40.0 - rise).abs() < 1e-3 * rise.max(1.0),
                    "W {load}: T {t}, ΔT {rise}"
                );
                let w = testing::result_field(&v, "load_n");
                assert!((w / load - 1.0).abs() < 1e-9, "W {load}: carried {w}");
            }
            Err(e) => {
                let text = format!("{e:?}");
                assert!(text.contains("/load_n"), "W {load}: {text}");
                if load > 1e3 {
                    // An overload names the largest load the bearing carries, and that load
                    // (a little below) has its equilibrium.
                    let largest: f64 = text
                        .split("at most about ")
                        .nth(1)
                        .and_then(|t| t.split(" N").next())
                        .and_then(|n| n.parse().ok())
                        .unwrap_or_else(|| panic!("W {load}: no largest load in {text}"));
                    assert!(largest < load, "W {load}: largest {largest}");
                    let mut below = request.clone();
                    below["load_n"] = serde_json::json!(0.99 * largest);
                    let v = testing::ok::<PlainJournal>(&below);
                    assert!(testing::result_field(&v, "eccentricity_ratio") > 0.99);
                }
                refused += 1;
            }
        }
    }
    assert!(refused > 0 && refused < 41, "{refused} of 41 refused");
}

/// `half_sommerfeld` is Gümbel's film at every fidelity: the closed forms' half-Sommerfeld
/// boundaries (Table 8.5 short, Table 8.2 long: φ = atan[π√(1 − ε²)/(2ε)]), and the numerical film
/// carrying less than the Reynolds condition (it drops the pressure the Reynolds film builds up
/// to its rupture line); the effect names the model.
#[test]
fn half_sommerfeld_is_guembel_s_film_at_every_fidelity() {
    let body = |ld: f64, fidelity: &str, model: &str| {
        serde_json::json!({
            "geometry": {"diameter_m": 0.1, "length_m": 0.1 * ld, "radial_clearance_m": 1e-4},
            "speed_rpm": 3000, "lubricant": {"viscosity_pa_s": 0.02}, "eccentricity_ratio": 0.6,
            "fidelity": fidelity, "effects": {"cavitation": model}
        })
    };
    let long = testing::ok::<PlainJournal>(&body(4.0, "closed_form", "half_sommerfeld"));
    assert_eq!(long["result"]["approximation"], "long_half_sommerfeld");
    assert_eq!(long["effects"]["cavitation"]["model"], "half_sommerfeld");
    let phi = (std::f64::consts::PI * (1.0f64 - 0.36).sqrt())
        .atan2(1.2)
        .to_degrees();
    testing::assert_rel(
        testing::result_field(&long, "attitude_angle_deg"),
        phi,
        1e-9,
        "long half-Sommerfeld φ",
    );
    let short = testing::ok::<PlainJournal>(&body(0.25, "closed_form", "half_sommerfeld"));
    assert_eq!(short["result"]["approximation"], "short_half_sommerfeld");
    let s = |model: &str| {
        testing::result_field(
            &testing::ok::<PlainJournal>(&body(1.0, "fast", model)),
            "sommerfeld_number",
        )
    };
    let (gumbel, reynolds) = (s("half_sommerfeld"), s("reynolds"));
    assert!(gumbel > 1.1 * reynolds, "{gumbel} {reynolds}");
}
