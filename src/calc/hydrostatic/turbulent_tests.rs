//! The turbulence effect: where the flow is laminar the turbulent laws are the closed forms;
//! on turbulent lands every determinate set gives the same point; fully turbulent lands against
//! their own closed forms (Eq. 16.2 integrated over a radial land) and a stiffness derived from
//! them; turbulence raises the resistance and the friction, as Khonsari & Booser §7.11 says.

use serde_json::{json, Value};

use super::super::geometry::Geometry;
use super::super::lands::Slit;
use super::super::operating::{solve_lands, Known};
use super::super::restrictor::{Law, Pipe};
use super::*;
use crate::calc::testing::{ok, result_field};

const PI: f64 = std::f64::consts::PI;

fn pads() -> [Value; 3] {
    [
        json!({"kind": "circular_step", "recess_radius_m": 0.0635, "outer_radius_m": 0.127}),
        json!({"kind": "annular", "inner_radius_m": 0.03, "recess_inner_radius_m": 0.05, "recess_outer_radius_m": 0.09, "outer_radius_m": 0.12}),
        json!({"kind": "rectangular", "recess_length_m": 0.1, "recess_width_m": 0.2, "land_width_m": 0.03}),
    ]
}

fn turbulence(body: &Value, mode: &str) -> Value {
    let mut b = body.clone();
    b["effects"] = json!({"turbulence": mode, "thermal": "off"});
    ok::<HydrostaticPad>(&b)
}

/// A viscous oil at a slow speed is laminar in every element: `on` then gives the closed forms
/// (the roots to 1e-12, the differenced stiffness to 1e-7), for every pad and restrictor.
#[test]
fn turbulent_laws_are_the_closed_forms_where_the_flow_is_laminar() {
    let compensations = [
        json!({"kind": "constant_flow"}),
        json!({"kind": "capillary", "radius_m": 5e-4, "length_m": 0.3}),
        json!({"kind": "capillary", "radius_m": 5e-4, "pressure_ratio": "optimum"}),
        json!({"kind": "orifice", "radius_m": 2e-4, "discharge_coefficient": 0.6}),
    ];
    for pad in pads() {
        for comp in &compensations {
            let mut body = json!({
                "pad": pad, "compensation": comp,
                "lubricant": {"viscosity_pa_s": 0.05, "density_15c_kg_m3": 870},
                "film_m": 5e-5,
            });
            if pad["kind"] == "rectangular" {
                body["sliding_speed_m_s"] = json!(0.5);
            } else {
                body["speed_rpm"] = json!(60);
            }
            if comp["kind"] == "constant_flow" {
                body["flow_m3_s"] = json!(1e-6);
            } else {
                body["supply_pressure_pa"] = json!(2e6);
            }
            let (on, off) = (turbulence(&body, "on"), turbulence(&body, "off"));
            assert!(on["effects"]["turbulence"]["applied"].as_bool().unwrap());
            for (field, tolerance) in [
                ("load_n", 1e-12),
                ("flow_m3_s", 1e-12),
                ("recess_pressure_pa", 1e-12),
                ("supply_pressure_pa", 1e-12),
                ("friction_power_w", 1e-12),
                ("stiffness_n_m", 1e-7),
            ] {
                let (a, b) = (result_field(&on, field), result_field(&off, field));
                assert!(
                    (a / b - 1.0).abs() < tolerance,
                    "{} {}: {field} {a} vs {b}",
                    pad["kind"],
                    comp["kind"]
                );
            }
        }
    }
}

fn water() -> Slit {
    Slit {
        mu: 1e-3,
        rho: 1000.0,
    }
}

/// On turbulent lands (water, Reynolds numbers in the thousands) with a turbulent capillary,
/// an orifice, constant flow and a ratio: the film-and-supply point solved again from every
/// other determinate set.
#[test]
fn every_determinate_set_gives_the_same_turbulent_point() {
    let slit = water();
    let geometries = [
        Geometry::CircularStep {
            recess_radius: 0.0635,
            outer_radius: 0.127,
        },
        Geometry::Annular {
            inner_radius: 0.03,
            recess_inner_radius: 0.05,
            recess_outer_radius: 0.09,
            outer_radius: 0.12,
        },
        Geometry::Rectangular {
            recess_length: 0.1,
            recess_width: 0.2,
            land_width: 0.03,
        },
    ];
    let pipe = Law::Pipe(Pipe {
        radius: 2e-3,
        length: 0.05,
        mu: slit.mu,
        rho: slit.rho,
    });
    for g in geometries {
        let lands = g.turbulent_lands(slit);
        for law in [Law::Direct, pipe, Law::Root(1e-6), Law::Ratio(0.5)] {
            let mut evaluations = 0;
            let p =
                solve_lands(&lands, law, Known::FilmSupply(2e-4, 1e6), &mut evaluations).unwrap();
            // A supply through a restrictor is balanced by a root; p_r = p_s or m p_s is not.
            let direct = matches!(law, Law::Direct | Law::Ratio(_));
            assert_eq!(evaluations == 0, direct, "{g:?} {law:?}: {evaluations}");
            let re = 2.0 * slit.rho * g.peak_flow_per_width(p.flow).unwrap() / slit.mu;
            assert!(re > 2000.0, "{g:?} {law:?}: Re {re}");
            let context = format!("{g:?}");
            let solve = |known| solve_lands(&lands, law, known, &mut 0);
            super::tests::assert_every_set_gives(&p, law, 1e-9, solve, &context);
        }
    }
}

/// A circular step whose whole land is turbulent (r_t beyond R2) has Eq. 16.2 integrated:
/// h³p_r = K (Q/2π)^{7/4} (4/3)(R1^{−3/4} − R2^{−3/4}) and
/// A_eff = π(4/5)(R2^{5/4} − R1^{5/4}) / ((4/3)(R1^{−3/4} − R2^{−3/4})); with Q ∝ (h³p_r)^{4/7}
/// against an orifice's Q ∝ (p_s − p_r)^{1/2} the stiffness at fixed supply is
/// (12/7) A_eff / (h (4/(7p_r) + 1/(2(p_s − p_r)))).
#[test]
fn fully_turbulent_land_in_closed_form() {
    let slit = water();
    let (r1, r2, h) = (0.02_f64, 0.05_f64, 2e-4_f64);
    let body = json!({
        "pad": {"kind": "circular_step", "recess_radius_m": r1, "outer_radius_m": r2},
        "compensation": {"kind": "orifice", "radius_m": 3e-3, "discharge_coefficient": 0.6},
        "lubricant": {"viscosity_pa_s": slit.mu, "density_15c_kg_m3": slit.rho},
        "temperature_c": 15,
        "film_m": h, "supply_pressure_pa": 1e6,
    });
    let v = turbulence(&body, "on");
    let (q, pr, ps) = (
        result_field(&v, "flow_m3_s"),
        result_field(&v, "recess_pressure_pa"),
        result_field(&v, "supply_pressure_pa"),
    );
    // Turbulent to the outer edge: q′ = Q/(2πR2) beyond the crossing 1021 μ/ρ.
    let crossing = (12.0 * SLIT_K.powf(7.0 / 4.0)).powf(4.0 / 3.0) * slit.mu / slit.rho;
    assert!(q / (2.0 * PI * r2) > crossing, "{q}");
    let k = slit.rho.powf(0.75) * slit.mu.powf(0.25) / SLIT_K.powf(1.75);
    let span = 4.0 / 3.0 * (r1.powf(-0.75) - r2.powf(-0.75));
    let want_pr = k * (q / (2.0 * PI)).powf(1.75) * span / h.powi(3);
    assert!((pr / want_pr - 1.0).abs() < 1e-10, "{pr} vs {want_pr}");
    let area = PI * 0.8 * (r2.powf(1.25) - r1.powf(1.25)) / span;
    assert!((result_field(&v, "effective_area_m2") / area - 1.0).abs() < 1e-10);
    let stiffness = 12.0 / 7.0 * area / (h * (4.0 / (7.0 * pr) + 1.0 / (2.0 * (ps - pr))));
    let got = result_field(&v, "stiffness_n_m");
    assert!((got / stiffness - 1.0).abs() < 1e-6, "{got} vs {stiffness}");
}

/// Eq. 16.2's 4.71, for the closed form above.
const SLIT_K: f64 = 4.71;

/// In a turbulent scene (water at a thick film, a fast runner) `auto` applies the laws: at the
/// same film and flow the recess pressure (so the load) and the friction rise above laminar —
/// Khonsari & Booser §7.11: "both fluid-film thickness (load capacity) and power loss are
/// increased" — and the decision names the criterion and the model.
#[test]
fn turbulence_raises_load_and_friction() {
    for pad in pads() {
        let mut body = json!({
            "pad": pad, "compensation": {"kind": "constant_flow"},
            "lubricant": {"viscosity_pa_s": 1e-3, "density_15c_kg_m3": 1000},
            "temperature_c": 15,
            "film_m": 2e-4, "flow_m3_s": 2e-3,
        });
        if pad["kind"] == "rectangular" {
            body["sliding_speed_m_s"] = json!(20);
        } else {
            body["speed_rpm"] = json!(3000);
        }
        let (auto, off) = (turbulence(&body, "auto"), turbulence(&body, "off"));
        let decision = &auto["effects"]["turbulence"];
        assert!(decision["applied"].as_bool().unwrap(), "{decision}");
        assert_eq!(decision["model"], "larger_loss_of_laminar_and_turbulent");
        assert!(decision["criterion"]["value"].as_f64().unwrap() > 1.0);
        let ratio = |f: &str| result_field(&auto, f) / result_field(&off, f);
        assert!(
            ratio("load_n") > 1.05,
            "{}: {}",
            pad["kind"],
            ratio("load_n")
        );
        assert!(ratio("friction_power_w") > 1.05, "{}", pad["kind"]);
        assert!(result_field(&auto, "land_pressure_flow_reynolds_number") > 2000.0);
    }
}

/// `auto` is continuous where it switches. A capillary whose laminar Reynolds number reaches
/// 2000 (water, its length scanned): the turbulent pipe holds Re 2000 between its two drops,
/// so just either side of the switch the pad has the same load, flow and recess pressure. An annulus whose
/// lands' peak Reynolds number reaches 2000 (constant flow): the slit law is still laminar
/// there (it takes over at 2043), so the load is the same.
#[test]
fn auto_is_continuous_where_it_switches() {
    let pad = |length: f64, mode: &str| {
        turbulence(
            &json!({
                "pad": {"kind": "circular_step", "recess_radius_m": 0.025, "outer_radius_m": 0.05},
                "compensation": {"kind": "capillary", "radius_m": 1e-3, "length_m": length},
                "lubricant": {"viscosity_pa_s": 1e-3, "density_15c_kg_m3": 1000},
                "temperature_c": 15, "film_m": 7.5e-5, "supply_pressure_pa": 2e4,
            }),
            mode,
        )
    };
    let re = |v: &Value| {
        v["result"]["restrictor"]["reynolds_number"]
            .as_f64()
            .unwrap()
    };
    // Laminar Re falls as the capillary lengthens: bisect ln l for Re 2000.
    let (mut short, mut long) = (1e-3f64, 10.0f64);
    assert!(re(&pad(short, "off")) > 2000.0 && re(&pad(long, "off")) < 2000.0);
    for _ in 0..60 {
        let mid = (short * long).sqrt();
        if re(&pad(mid, "off")) > 2000.0 {
            short = mid;
        } else {
            long = mid;
        }
    }
    let (turbulent, laminar) = (pad(short, "auto"), pad(long, "auto"));
    assert!(turbulent["effects"]["turbulence"]["applied"]
        .as_bool()
        .unwrap());
    // The turbulent point is a root of the flow balance, and the report counts its evaluations.
    let solver = &turbulent["solver"];
    assert_eq!(solver["method"], "hydrostatic_turbulent_brent");
    assert_eq!(solver["iterations_unit"], "evaluations");
    assert!(solver["iterations"].as_u64().unwrap() > 2, "{solver}");
    assert_eq!(laminar["solver"]["method"], "hydrostatic_closed_form");
    assert!(!laminar["effects"]["turbulence"]["applied"]
        .as_bool()
        .unwrap());
    for field in ["load_n", "flow_m3_s", "recess_pressure_pa"] {
        let (a, b) = (
            result_field(&turbulent, field),
            result_field(&laminar, field),
        );
        assert!((a / b - 1.0).abs() < 1e-6, "{field}: {a} vs {b}");
    }
    // The stiffness has a kink there, not a jump in load: in transition the capillary passes a
    // fixed flow whatever its drop, so it stiffens the pad as constant flow would (3W/h at most).
    let w_over_h = result_field(&turbulent, "load_n") / 7.5e-5;
    for v in [&turbulent, &laminar] {
        let k = result_field(v, "stiffness_n_m");
        assert!(k > 0.0 && k <= 3.0 * w_over_h * (1.0 + 1e-6), "{k}");
    }

    let annulus = json!({"kind": "annular", "inner_radius_m": 0.03, "recess_inner_radius_m": 0.05, "recess_outer_radius_m": 0.09, "outer_radius_m": 0.12});
    let geometry = Geometry::Annular {
        inner_radius: 0.03,
        recess_inner_radius: 0.05,
        recess_outer_radius: 0.09,
        outer_radius: 0.12,
    };
    let q_switch = 2000.0 * 1e-3 / (2.0 * 1000.0) / geometry.peak_flow_per_width(1.0).unwrap();
    let at = |q: f64| {
        turbulence(
            &json!({
                "pad": annulus, "compensation": {"kind": "constant_flow"},
                "lubricant": {"viscosity_pa_s": 1e-3, "density_15c_kg_m3": 1000},
                "temperature_c": 15, "film_m": 2e-4, "flow_m3_s": q,
            }),
            "auto",
        )
    };
    let (below, above) = (at(q_switch * (1.0 - 1e-9)), at(q_switch * (1.0 + 1e-9)));
    assert!(!below["effects"]["turbulence"]["applied"].as_bool().unwrap());
    assert!(above["effects"]["turbulence"]["applied"].as_bool().unwrap());
    let (a, b) = (
        result_field(&above, "load_n"),
        result_field(&below, "load_n"),
    );
    assert!((a / b - 1.0).abs() < 1e-8, "{a} vs {b}");
}

/// A film that the heat thins can be turbulent where the inlet's oil was not: ISO VG 10 on a
/// circular step at 2000 rpm is laminar at 40 °C (the shear Re at 0.92 of 580) but not at its
/// film temperature (1.17), so `auto` applies the turbulent laws there, as `on` does, and says
/// at which temperature it decided; the laminar root that told it so counts in the report.
#[test]
fn auto_decides_turbulence_again_at_the_film_temperature() {
    let body = |turbulence: &str, thermal: &str| {
        ok::<HydrostaticPad>(&json!({
            "pad": {"kind": "circular_step", "recess_radius_m": 0.0635, "outer_radius_m": 0.127},
            "compensation": {"kind": "constant_flow"},
            "lubricant": {"iso_vg": 10},
            "temperature_c": 40, "film_m": 2e-4, "flow_m3_s": 2e-5, "speed_rpm": 2000,
            "effects": {"turbulence": turbulence, "thermal": thermal},
        }))
    };
    let criterion = |v: &Value| {
        v["effects"]["turbulence"]["criterion"]["value"]
            .as_f64()
            .unwrap()
    };
    let cold = body("auto", "off");
    assert!(!cold["effects"]["turbulence"]["applied"].as_bool().unwrap());
    assert!(
        (0.9..1.0).contains(&criterion(&cold)),
        "{}",
        criterion(&cold)
    );
    let (auto, on) = (body("auto", "on"), body("on", "on"));
    let decision = &auto["effects"]["turbulence"];
    assert!(decision["applied"].as_bool().unwrap(), "{decision}");
    assert!(criterion(&auto) > 1.1, "{decision}");
    assert!(decision["reason"]
        .as_str()
        .unwrap()
        .contains("at the film temperature"));
    // The thermal decision reports the turbulent film's criterion, as `on` does.
    assert_eq!(auto["effects"]["thermal"], on["effects"]["thermal"]);
    for field in [
        "load_n",
        "film_temperature_c",
        "friction_power_w",
        "stiffness_n_m",
    ] {
        let (a, b) = (result_field(&auto, field), result_field(&on, field));
        assert!((a / b - 1.0).abs() < 1e-12, "{field}: {a} vs {b}");
    }
    let (t, rise) = (
        result_field(&auto, "film_temperature_c"),
        result_field(&auto, "temperature_rise_k"),
    );
    assert!((t - 40.0 - rise / 2.0).abs() < 1e-6, "{t} {rise}");
    let iterations = |v: &Value| v["solver"]["iterations"].as_u64().unwrap();
    assert!(
        iterations(&auto) > iterations(&on) + 1,
        "{} {}",
        auto["solver"],
        on["solver"]
    );
}
