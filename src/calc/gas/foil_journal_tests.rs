use proptest::prelude::*;
use serde_json::{json, Value};

use super::*;
use crate::calc::testing::{assert_rel, invalid_pointers, ok, result_field};

fn example() -> Value {
    serde_json::from_str(FoilJournal::EXAMPLE).unwrap()
}

/// Khonsari & Booser Table 11.5's foil bearing at ε_f = 1.2: α = 0.2053 from its bumps, and
/// the spec's values derived from Eqs. 11.21–11.22 (§2.4): W/(p_a L R) = 5.162, h_min/C = 0.4993.
#[test]
fn table_11_5_bearing_at_eccentricity_1_2() {
    let v = ok::<FoilJournal>(&example());
    assert_rel(result_field(&v, "compliance"), 0.2053, 1e-3, "α");
    assert_rel(
        result_field(&v, "load_per_ambient_pressure_l_r"),
        5.162,
        1e-3,
        "W/(p_a L R)",
    );
    assert_rel(
        result_field(&v, "min_film_m") / 66e-6,
        0.4993,
        1e-3,
        "h_min/C",
    );
    let w = result_field(&v, "limiting_load_n");
    assert_rel(w, 5.162 * 101_325.0 * 0.062 * 0.035, 1e-3, "W∞");
    assert_rel(
        result_field(&v, "load_dimensionless"),
        w / (101_325.0 * 0.062 * 0.07),
        1e-12,
        "W/(p_a L D)",
    );
}

/// DellaCorte–Valco in its own units: L = D = 1 in at 10 krpm with D = 1 lbf/(in³·krpm) is
/// 10 lbf.
#[test]
fn rule_of_thumb_in_its_units() {
    let v = ok::<FoilJournal>(&json!({
        "geometry": {"diameter_m": 0.0254, "length_m": 0.0254, "radial_clearance_m": 2.54e-5},
        "gas": {"name": "air"}, "eccentricity_ratio": 0.5,
        "speed_rpm": 10000, "dellacorte_coefficient": 1.0
    }));
    assert_rel(
        result_field(&v, "rule_of_thumb_load_n"),
        44.482216,
        1e-6,
        "W",
    );
    // Without a foil the bore is rigid: the rigid limit at ε = 0.5 is 2.916 p_a L R.
    assert_rel(
        result_field(&v, "load_per_ambient_pressure_l_r"),
        2.916,
        5e-4,
        "rigid",
    );
    assert_eq!(result_field(&v, "max_foil_deflection_m"), 0.0);
}

#[test]
fn impossible_requests_are_refused_naming_the_field() {
    let rigid = |e: f64| {
        json!({"geometry": {"diameter_m": 0.07, "length_m": 0.062, "radial_clearance_m": 6.6e-5},
               "gas": {"name": "air"}, "eccentricity_ratio": e})
    };
    assert_eq!(
        invalid_pointers::<FoilJournal>(&rigid(1.0)),
        vec!["/eccentricity_ratio"]
    );
    let mut both = example();
    both["foil"]["compliance"] = json!(0.2);
    assert_eq!(
        invalid_pointers::<FoilJournal>(&both),
        vec!["/foil/compliance"]
    );
    let mut partial = example();
    partial["foil"] = json!({"thickness_m": 7.6e-5});
    assert_eq!(
        invalid_pointers::<FoilJournal>(&partial),
        vec![
            "/foil/bump_pitch_m",
            "/foil/bump_length_m",
            "/foil/elastic_modulus_pa",
            "/foil/poisson_ratio"
        ]
    );
    let mut no_speed = example();
    no_speed.as_object_mut().unwrap().remove("speed_rpm");
    assert_eq!(
        invalid_pointers::<FoilJournal>(&no_speed),
        vec!["/speed_rpm"]
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Over the valid range: finite, the film open, the load rising with ε_f, and never above
    /// the rigid bore's at the same ε (below 1).
    #[test]
    fn limiting_load_is_finite_and_monotone(e in 0.0f64..19.0, alpha in 0.0f64..100.0) {
        let e = if alpha == 0.0 { e.min(0.98) } else { e };
        let body = |e: f64, alpha: f64| json!({
            "geometry": {"diameter_m": 0.07, "length_m": 0.062, "radial_clearance_m": 6.6e-5},
            "foil": {"compliance": alpha}, "gas": {"name": "air"}, "eccentricity_ratio": e
        });
        let v = ok::<FoilJournal>(&body(e, alpha));
        for f in ["limiting_load_n", "max_pressure_pa", "min_film_m", "max_foil_deflection_m"] {
            prop_assert!(result_field(&v, f).is_finite());
        }
        prop_assert!(result_field(&v, "min_film_m") > 0.0);
        let w = result_field(&v, "limiting_load_n");
        let w_more = result_field(&ok::<FoilJournal>(&body(e + 0.01, alpha)), "limiting_load_n");
        prop_assert!(w_more > w);
        if e < 0.98 {
            let rigid = result_field(&ok::<FoilJournal>(&body(e, 0.0)), "limiting_load_n");
            prop_assert!(w <= rigid * (1.0 + 1e-12));
        }
    }
}
