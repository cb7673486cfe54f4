//! Contract tests of the whirl room, through the registry's path: the example, `/plain`'s
//! stability block for the same bearing, and the full film's answer.

use serde_json::{json, Value};

use super::*;
use crate::calc::journal::plain::PlainJournal;
use crate::calc::testing::{self, assert_rel, result_field, warning_codes};

/// The example answers with every block a speed and a mass ask for, and its verdict agrees
/// with its margins.
#[test]
fn the_example_gives_threshold_verdict_and_coefficients() {
    let request: Value = serde_json::from_str(Whirl::EXAMPLE).expect("the example is JSON");
    let v = testing::ok::<Whirl>(&request);
    let r = &v["result"];
    for field in [
        "threshold_mass_kg",
        "threshold_speed_rpm",
        "eccentricity_ratio_at_threshold",
        "whirl_frequency_ratio",
        "eccentricity_ratio",
        "attitude_angle_deg",
        "mass_margin",
        "speed_margin",
        "growth_rate_per_s",
    ] {
        assert!(r[field].is_f64(), "{field} missing in {r}");
    }
    let stable = r["stable"].as_bool().unwrap();
    assert_eq!(stable, result_field(&v, "mass_margin") > 1.0, "{r}");
    assert_eq!(stable, result_field(&v, "speed_margin") > 1.0, "{r}");
    assert_eq!(stable, result_field(&v, "growth_rate_per_s") < 0.0, "{r}");
    assert_eq!(r["coefficients"]["frame"], FRAME);
    assert_eq!(v["solver"]["fidelity"], "fast");
}

/// The bearing of Khonsari & Booser Ex 8.6 (D = 5 in, L/D = 1/2, C = 0.005 in, 5400 rev/min,
/// μ = 2e-6 reyn, 2500 lbf per bearing, m = 5000 lb/g), as `/plain` and as `/whirl` take it.
fn ex_8_6() -> (Value, Value) {
    let geometry = json!({"diameter_m": 0.127, "length_m": 0.0635, "radial_clearance_m": 0.000127});
    let lubricant = json!({"viscosity_pa_s": 0.01378951});
    let plain = json!({
        "geometry": geometry, "speed_rpm": 5400, "lubricant": lubricant, "load_n": 11120.56,
        "rotor_mass_kg": 2267.962, "effects": {"thermal": "off", "turbulence": "off"},
        "fidelity": "fast",
    });
    let whirl = json!({
        "geometry": geometry, "speed_rpm": 5400, "lubricant": lubricant, "load_n": 11120.56,
        "journal_mass_kg": 2267.962, "film_model": "finite", "fidelity": "fast",
    });
    (plain, whirl)
}

/// `/plain`'s stability block and `/whirl` give the same numbers for the same bearing: the
/// coefficients, the critical mass parameter and whirl ratio at the operating point (the same
/// film, to rounding), the verdict, and the threshold speed (both searched on the `fast`
/// mesh, each to 10⁻³ in ln ε: 0.5 %). Finite film at `fast`, and the short bearing's
/// closed form against `/plain`'s `closed_form: short`.
#[test]
fn whirl_agrees_with_plains_stability_block() {
    let (mut plain, mut whirl) = ex_8_6();
    for closed in [false, true] {
        if closed {
            plain["fidelity"] = "closed_form".into();
            plain["closed_form"] = "short".into();
            whirl["film_model"] = "short_pi_film".into();
        }
        let p = testing::ok::<PlainJournal>(&plain);
        let w = testing::ok::<Whirl>(&whirl);
        let (ps, pc, wr) = (
            &p["result"]["stability"],
            &p["result"]["dynamic_coefficients"],
            &w["result"],
        );
        let what = if closed { "short" } else { "finite" };
        assert_rel(
            wr["eccentricity_ratio"].as_f64().unwrap(),
            p["result"]["eccentricity_ratio"].as_f64().unwrap(),
            1e-9,
            what,
        );
        for i in 0..4 {
            for block in ["stiffness_dimensionless", "damping_dimensionless"] {
                assert_rel(
                    wr["coefficients"][block][i].as_f64().unwrap(),
                    pc[block][i].as_f64().unwrap(),
                    1e-9,
                    &format!("{what} {block}[{i}]"),
                );
            }
        }
        for k in ["kxx", "kxy", "cxx", "cyy"] {
            assert_rel(
                wr["coefficients"][k].as_f64().unwrap(),
                pc[k].as_f64().unwrap(),
                1e-9,
                &format!("{what} {k}"),
            );
        }
        for k in ["critical_mass_parameter", "whirl_frequency_ratio"] {
            assert_rel(
                wr[k].as_f64().unwrap(),
                ps[k].as_f64().unwrap(),
                1e-9,
                &format!("{what} {k}"),
            );
        }
        assert_eq!(wr["stable"], ps["stable_at_operating_speed"], "{what}");
        assert_rel(
            wr["threshold_speed_rpm"].as_f64().unwrap(),
            ps["threshold_speed_rpm"].as_f64().unwrap(),
            5e-3,
            &format!("{what} threshold speed"),
        );
        // The mass margin is M̄_c over the rotor's mass parameter.
        assert_rel(
            wr["mass_margin"].as_f64().unwrap(),
            ps["critical_mass_parameter"].as_f64().unwrap()
                / ps["mass_parameter"].as_f64().unwrap(),
            1e-9,
            &format!("{what} mass margin"),
        );
    }
}

/// The full film answers 200 with a threshold of 0 and says why; its whirl ratio is 1/2.
#[test]
fn the_full_film_whirls_at_every_speed() {
    let (_, mut whirl) = ex_8_6();
    whirl["film_model"] = "short_full".into();
    let v = testing::ok::<Whirl>(&whirl);
    assert_eq!(result_field(&v, "threshold_mass_kg"), 0.0);
    assert_eq!(result_field(&v, "threshold_speed_rpm"), 0.0);
    assert_eq!(result_field(&v, "whirl_frequency_ratio"), 0.5);
    assert_eq!(v["result"]["stable"], false);
    let codes = warning_codes(&v);
    assert!(
        codes.contains(&"whirls_at_every_speed".to_owned()),
        "{codes:?}"
    );
    assert!(codes.contains(&"oil_whirl".to_owned()), "{codes:?}");
}

/// A request without speed or mass, and a closed-form fidelity for the finite film, are
/// refused with the field to fix.
#[test]
fn underdetermined_and_closed_form_finite_are_refused() {
    let (_, whirl) = ex_8_6();
    let mut neither = whirl.clone();
    neither.as_object_mut().unwrap().remove("speed_rpm");
    neither.as_object_mut().unwrap().remove("journal_mass_kg");
    assert_eq!(testing::invalid_pointers::<Whirl>(&neither), ["/speed_rpm"]);
    let mut closed = whirl;
    closed["fidelity"] = "closed_form".into();
    assert_eq!(testing::invalid_pointers::<Whirl>(&closed), ["/fidelity"]);
}

/// `confirm`: Ex 8.6's bearing on the short π film, given a speed (around the threshold mass
/// there) and given only a mass (around it, at the threshold speed): the lighter rotor settles,
/// the heavier whirls, and the simulated growth rates are the eigenvalues' within 0.1 %. The
/// full and finite films have nothing to simulate and are refused at `/confirm`.
#[test]
fn confirm_simulates_both_sides_of_the_threshold() {
    let (_, mut whirl) = ex_8_6();
    whirl["film_model"] = "short_pi_film".into();
    whirl["confirm"] = true.into();
    let mut mass_only = whirl.clone();
    mass_only.as_object_mut().unwrap().remove("speed_rpm");
    for request in [whirl.clone(), mass_only] {
        let v = testing::ok::<Whirl>(&request);
        let c = &v["result"]["confirmation"];
        assert_eq!(c["agrees"], true, "{c}");
        for side in ["below", "above"] {
            let s = &c[side];
            assert_rel(
                s["simulated_growth_rate_per_s"].as_f64().unwrap(),
                s["linear_growth_rate_per_s"].as_f64().unwrap(),
                1e-3,
                side,
            );
        }
        let threshold = c["threshold_mass_kg"].as_f64().unwrap();
        assert_rel(
            c["below"]["mass_kg"].as_f64().unwrap(),
            0.8 * threshold,
            1e-12,
            "mass",
        );
    }
    let mut refused = whirl.clone();
    refused["film_model"] = "short_full".into();
    assert_eq!(testing::invalid_pointers::<Whirl>(&refused), ["/confirm"]);
}

/// `confirm` on the finite film (Ex 8.6's bearing): the orbit runs on the impedance table built
/// from the same Reynolds film on the same mesh. At every level the lighter rotor settles and
/// the heavier whirls. The simulated rates follow the eigenvalues to the table's interpolation
/// error in the force's derivatives: within 15 % at `fast` (seen 13 %), 3 % at `standard` (seen
/// 1.6 %). At `high` only the verdict is asserted: its eigenvalue comes from coefficients
/// Richardson-extrapolated from two meshes, its table from the finer mesh alone (seen 15–25 %;
/// the rates are ±3 1/s against ω = 565 rad/s, a difference of 0.1 % in the coefficients).
#[test]
fn confirm_on_the_finite_film_runs_on_its_impedance_table() {
    let (_, mut whirl) = ex_8_6();
    whirl["confirm"] = true.into();
    whirl["film_model"] = "finite".into();
    for (fidelity, within) in [
        ("fast", Some(0.15)),
        ("standard", Some(0.03)),
        ("high", None),
    ] {
        whirl["fidelity"] = fidelity.into();
        let v = testing::ok::<Whirl>(&whirl);
        let c = &v["result"]["confirmation"];
        assert_eq!(c["agrees"], true, "{fidelity}: {c}");
        for side in ["below", "above"] {
            let s = &c[side];
            let linear = s["linear_growth_rate_per_s"].as_f64().unwrap();
            let simulated = s["simulated_growth_rate_per_s"].as_f64().unwrap();
            assert_eq!(linear < 0.0, side == "below", "{fidelity} {side}");
            if let Some(tolerance) = within {
                assert_rel(simulated, linear, tolerance, &format!("{fidelity} {side}"));
            }
        }
    }
}
