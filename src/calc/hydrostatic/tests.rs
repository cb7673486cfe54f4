//! The pad room: closed forms against the texts' equations to round-off, the stiffness against a
//! numerical −dW/dh, the optimum pressure ratios found by maximising that numerical stiffness,
//! every determinate set giving the same point, and the whole valid range finite (proptest).

use proptest::prelude::*;
use serde_json::{json, Value};

use super::super::geometry::Geometry;
use super::super::lands::Film;
use super::super::operating::{solve, stiffness, Known};
use super::super::point::Point;
use super::super::restrictor::{Kind, Law};
use super::*;
use crate::calc::testing::{invalid_pointers, ok, post, result_field, warning_codes};
use crate::calc::Failure;
use crate::numerics::optimise::brent_minimise;

const PI: f64 = std::f64::consts::PI;

/// Ex 10.2's pad in SI: R1 = 2.5 in, R2 = 5 in, μ = 7e-6 reyn.
fn ex_10_2() -> (Geometry, f64) {
    (
        Geometry::CircularStep {
            recess_radius: 0.0635,
            outer_radius: 0.127,
        },
        7e-6 * 6_894.757_293_168_361,
    )
}

fn film_of(g: &Geometry, mu: f64) -> Film {
    Film {
        area: g.effective_area(),
        c2: g.flow_coefficient() / mu,
    }
}

/// Khonsari & Booser Eq. 10.4–10.17 evaluated directly, against the room, to round-off.
#[test]
fn circular_step_closed_forms_to_round_off() {
    let (r1, r2, h, w, mu, eta, n): (f64, f64, f64, f64, f64, f64, f64) =
        (0.0635, 0.127, 7.62e-5, 177_928.86, 0.048_263, 0.8, 100.0);
    let v = ok::<HydrostaticPad>(&json!({
        "pad": {"kind": "circular_step", "recess_radius_m": r1, "outer_radius_m": r2},
        "compensation": {"kind": "constant_flow"},
        "lubricant": {"viscosity_pa_s": mu, "density_15c_kg_m3": 850.0, "specific_heat_j_kg_k": 2000.0, "thermal_conductivity_w_m_k": 0.13},
        "temperature_c": 15, "film_m": h, "load_n": w, "pump_efficiency": eta, "speed_rpm": n,
    }));
    let ln = (r2 / r1).ln();
    let ps = 2.0 * w * ln / (PI * (r2 * r2 - r1 * r1)); // Eq. 10.5
    let q = PI * h.powi(3) * ps / (6.0 * mu * ln); // Eq. 10.6
    let omega = n * PI / 30.0;
    let torque = PI * mu * omega * (r2.powi(4) - r1.powi(4)) / (2.0 * h); // Eq. 10.14
    let ep = PI * h.powi(3) * ps * ps / (6.0 * eta * mu * ln); // Eq. 10.17
    let ef = omega * torque; // Eq. 10.15
    let close = |field: &str, want: f64| {
        let got = result_field(&v, field);
        assert!((got / want - 1.0).abs() < 1e-13, "{field}: {got} vs {want}");
    };
    close("supply_pressure_pa", ps);
    close("recess_pressure_pa", ps);
    close("flow_m3_s", q);
    close("load_n", 3.0 * mu * q * (r2 * r2 - r1 * r1) / h.powi(3)); // Eq. 10.7
    close("stiffness_n_m", 3.0 * w / h); // Eq. 10.12
    close("friction_torque_n_m", torque);
    close("pumping_power_w", ep);
    close("friction_power_w", ef);
    close("temperature_rise_k", (ep + ef) / (850.0 * 2000.0 * q));
    // Loeb–Rippel factors of the circular step (Eq. 10.43).
    let x = r1 / r2;
    let pf = 2.0 * ln / (1.0 - x * x);
    let qf = 4.0 * PI / (1.0 - x * x);
    let f = &v["result"]["performance_factors"];
    assert!((f["pressure_factor"].as_f64().unwrap() / pf - 1.0).abs() < 1e-13);
    assert!((f["flow_factor"].as_f64().unwrap() / qf - 1.0).abs() < 1e-13);
    let hf = 8.0 * PI * ln / (1.0 - x * x).powi(2) / eta;
    assert!((f["power_factor"].as_f64().unwrap() / hf - 1.0).abs() < 1e-13);
}

/// Every determinate pair gives back the same point, for each restrictor law.
#[test]
fn every_determinate_set_gives_the_same_point() {
    let (g, mu) = ex_10_2();
    let film = film_of(&g, mu);
    for law in [
        Law::Direct,
        Law::Linear(7e-12),
        Law::Root(2.0e-8),
        Law::Ratio(0.5),
    ] {
        let p = solve(film, law, Known::FilmSupply(7.62e-5, 1.3e7)).unwrap();
        assert_every_set_gives(&p, law, 1e-12, |known| solve(film, law, known), "");
    }
}

/// Every other determinate set at point `p` (solved by `solve`) gives `p` back to `tolerance`;
/// load with supply pressure is refused where they are tied (constant flow, a ratio).
pub(super) fn assert_every_set_gives(
    p: &Point,
    law: Law,
    tolerance: f64,
    solve: impl Fn(Known) -> Result<Point, CalcError>,
    context: &str,
) {
    for known in [
        Known::FilmLoad(p.film, p.load),
        Known::FilmFlow(p.film, p.flow),
        Known::LoadFlow(p.load, p.flow),
        Known::SupplyFlow(p.supply, p.flow),
        Known::LoadSupply(p.load, p.supply),
    ] {
        if let (Law::Direct | Law::Ratio(_), Known::LoadSupply(..)) = (law, known) {
            assert!(solve(known).is_err());
            continue;
        }
        let q = solve(known).unwrap();
        for (a, b, what) in [
            (q.film, p.film, "film"),
            (q.load, p.load, "load"),
            (q.supply, p.supply, "supply"),
            (q.flow, p.flow, "flow"),
            (q.recess, p.recess, "recess"),
        ] {
            assert!(
                (a / b - 1.0).abs() < tolerance,
                "{context} {law:?} {known:?} {what}: {a} vs {b}"
            );
        }
    }
}

/// W(h) at fixed supply pressure (fixed flow at constant flow), differentiated numerically by a
/// fourth-order central difference.
fn numerical_stiffness(film: Film, law: Law, h: f64, supply: f64, flow: f64) -> f64 {
    let load = |h: f64| {
        let known = match law {
            Law::Direct => Known::FilmFlow(h, flow),
            _ => Known::FilmSupply(h, supply),
        };
        solve(film, law, known).unwrap().load
    };
    let d = 1e-3 * h;
    -(-load(h + 2.0 * d) + 8.0 * load(h + d) - 8.0 * load(h - d) + load(h - 2.0 * d)) / (12.0 * d)
}

/// The closed-form stiffness of each restrictor (Eq. 10.12, 10.27, 10.34) against −dW/dh.
#[test]
fn stiffness_is_minus_dw_dh() {
    let (g, mu) = ex_10_2();
    let film = film_of(&g, mu);
    let (h, ps) = (7.62e-5, 1.3e7);
    for (kind, law) in [
        (Kind::ConstantFlow, Law::Direct),
        (Kind::Capillary, Law::Linear(2e-12)),
        (Kind::Capillary, Law::Linear(7e-12)),
        (Kind::Capillary, Law::Linear(3e-11)),
        (Kind::Orifice, Law::Root(5e-9)),
        (Kind::Orifice, Law::Root(2e-8)),
        (Kind::Orifice, Law::Root(1e-7)),
    ] {
        let p = solve(film, law, Known::FilmSupply(h, ps)).unwrap();
        let numeric = numerical_stiffness(film, law, h, ps, p.flow);
        let closed = stiffness(kind, &p);
        assert!(
            (numeric / closed - 1.0).abs() < 1e-8,
            "{kind:?} {law:?} m = {}: {numeric} vs {closed}",
            p.ratio()
        );
    }
}

/// The optimum pressure ratios derived: at a fixed film and supply pressure, the restrictor size
/// (capillary conductance, orifice coefficient) that maximises the numerical −dW/dh gives
/// m = ½ for the capillary and m = 2 − √2 for the orifice — the constants the room uses.
#[test]
fn optimum_pressure_ratios_maximise_the_numerical_stiffness() {
    let (g, mu) = ex_10_2();
    let film = film_of(&g, mu);
    let (h, ps): (f64, f64) = (7.62e-5, 1.3e7);
    let a = film.c2 * h.powi(3);
    for (kind, scale) in [
        (Kind::Capillary, a),
        // k_o² ≈ (c₂h³)² p_s puts m near the middle of (0, 1).
        (Kind::Orifice, a * ps.sqrt()),
    ] {
        let law = |ln_k: f64| match kind {
            Kind::Capillary => Law::Linear(scale * ln_k.exp()),
            _ => Law::Root(scale * ln_k.exp()),
        };
        let minus_k = |ln_k: f64| -numerical_stiffness(film, law(ln_k), h, ps, 0.0);
        let (best, _) = brent_minimise(minus_k, -6.0, 6.0, 1e-9);
        let m = solve(film, law(best), Known::FilmSupply(h, ps))
            .unwrap()
            .ratio();
        let want = kind.optimum_ratio().unwrap();
        assert!((m - want).abs() < 1e-5, "{kind:?}: m = {m}, want {want}");
    }
    // And the closed-form factors peak there: dK/dm = 0 by a symmetric difference.
    for kind in [Kind::Capillary, Kind::Orifice] {
        let m = kind.optimum_ratio().unwrap();
        let k = |m: f64| m * kind.stiffness_factor(m);
        assert!((k(m + 1e-6) - k(m - 1e-6)).abs() < 1e-11, "{kind:?}");
    }
}

/// The designed restrictor reproduces the ratio asked for, and the room's `"optimum"` is the
/// derived value for each.
#[test]
fn designed_restrictors_hit_their_ratio() {
    for (comp, m) in [
        (
            json!({"kind": "capillary", "radius_m": 5e-4, "pressure_ratio": "optimum"}),
            0.5,
        ),
        (
            json!({"kind": "capillary", "radius_m": 5e-4, "pressure_ratio": 0.3}),
            0.3,
        ),
        (
            json!({"kind": "orifice", "discharge_coefficient": 0.6, "pressure_ratio": "optimum"}),
            2.0 - 2f64.sqrt(),
        ),
    ] {
        let body = json!({
            "pad": {"kind": "circular_step", "recess_radius_m": 0.0635, "outer_radius_m": 0.127},
            "compensation": comp, "lubricant": {"iso_vg": 68, "density_15c_kg_m3": 870},
            "film_m": 5e-5, "supply_pressure_pa": 5e6, "effects": {"thermal": "off"},
        });
        let v = ok::<HydrostaticPad>(&body);
        assert!((result_field(&v, "pressure_ratio") - m).abs() < 1e-12);
        assert_eq!(v["result"]["restrictor"]["designed"], true);
        // The designed size, given back, reproduces the point.
        let r = &v["result"]["restrictor"];
        let mut given = body.clone();
        given["compensation"] = match r["kind"].as_str().unwrap() {
            "capillary" => {
                json!({"kind": "capillary", "radius_m": 5e-4, "length_m": r["length_m"]})
            }
            _ => {
                json!({"kind": "orifice", "discharge_coefficient": 0.6, "radius_m": r["radius_m"]})
            }
        };
        let w = ok::<HydrostaticPad>(&given);
        for f in ["load_n", "flow_m3_s", "recess_pressure_pa", "stiffness_n_m"] {
            let (a, b) = (result_field(&v, f), result_field(&w, f));
            assert!((a / b - 1.0).abs() < 1e-10, "{f}: {a} vs {b}");
        }
    }
}

fn base() -> Value {
    json!({
        "pad": {"kind": "circular_step", "recess_radius_m": 0.0635, "outer_radius_m": 0.127},
        "compensation": {"kind": "capillary", "radius_m": 7.62e-4, "length_m": 0.4},
        "lubricant": {"iso_vg": 68},
        "film_m": 7.62e-5, "supply_pressure_pa": 1.3e7,
    })
}

fn with(pointer: &str, value: Value) -> Value {
    let mut b = base();
    let (parent, key) = pointer.rsplit_once('/').unwrap();
    if !parent.is_empty() && b.pointer(parent).is_none() {
        b[&parent[1..]] = json!({});
    }
    let parent = if parent.is_empty() {
        &mut b
    } else {
        b.pointer_mut(parent).unwrap()
    };
    if value.is_null() {
        parent.as_object_mut().unwrap().remove(key);
    } else {
        parent[key] = value;
    }
    b
}

/// Bad input is a 422 that names the field, with the reason.
#[test]
fn bad_requests_name_the_field() {
    let cases: Vec<(Value, &str)> = vec![
        (
            with("/pad/recess_radius_m", json!(0.127)),
            "/pad/recess_radius_m",
        ),
        (
            with("/pad/recess_radius_m", json!(0.2)),
            "/pad/recess_radius_m",
        ),
        (
            with("/pad/recess_radius_m", json!(-1)),
            "/pad/recess_radius_m",
        ),
        (with("/pad/land_width_m", json!(0.01)), "/pad/land_width_m"),
        (
            with("/pad/outer_radius_m", Value::Null),
            "/pad/outer_radius_m",
        ),
        (with("/film_m", json!(0.01)), "/film_m"),
        (with("/film_m", Value::Null), "/film_m"),
        (with("/load_n", json!(1000)), "/load_n"),
        (
            with("/compensation/length_m", Value::Null),
            "/compensation/length_m",
        ),
        (
            with("/compensation/pressure_ratio", json!(0.5)),
            "/compensation/length_m",
        ),
        (
            with("/compensation/discharge_coefficient", json!(0.6)),
            "/compensation/discharge_coefficient",
        ),
        (
            with("/compensation/radius_m", json!(0.1)),
            "/compensation/radius_m",
        ),
        (with("/pump_efficiency", json!(0)), "/pump_efficiency"),
        (with("/sliding_speed_m_s", json!(3)), "/sliding_speed_m_s"),
        (with("/lenght_m", json!(1)), "/lenght_m"),
        (with("/temperature_c", json!(-300)), "/temperature_c"),
    ];
    for (body, pointer) in cases {
        let got = invalid_pointers::<HydrostaticPad>(&body);
        assert!(
            got.iter().any(|p| p == pointer),
            "{pointer}: {got:?} for {body}"
        );
    }
    // Load with supply pressure: under-determined with constant flow or a designed restrictor.
    let mut b = with("/film_m", Value::Null);
    b["load_n"] = json!(1e5);
    b["compensation"] = json!({"kind": "constant_flow"});
    let got = invalid_pointers::<HydrostaticPad>(&b);
    assert!(
        got.contains(&"/load_n".to_owned()) && got.contains(&"/supply_pressure_pa".to_owned()),
        "{got:?}"
    );
    // A constant pressure ratio of 1 or above is refused.
    let mut b = base();
    b["compensation"] =
        json!({"kind": "orifice", "discharge_coefficient": 0.6, "pressure_ratio": 1.2});
    assert!(
        invalid_pointers::<HydrostaticPad>(&b).contains(&"/compensation/pressure_ratio".to_owned())
    );
}

/// Impossible physics is a 422 with its reason: a load the supply cannot carry, a restrictor
/// that alone drops more than the supply, a film that is no thin film.
#[test]
fn impossible_physics_is_refused_with_a_reason() {
    let mut b = with("/film_m", Value::Null);
    b["load_n"] = json!(1e9);
    match post::<HydrostaticPad>(&b) {
        Err(Failure::Calc(CalcError::Impossible { pointer, message })) => {
            assert_eq!(pointer, "/load_n");
            assert!(message.contains("supply pressure"), "{message}");
        }
        other => panic!("{other:?}"),
    }
    let mut b = with("/film_m", Value::Null);
    b["flow_m3_s"] = json!(1.0);
    match post::<HydrostaticPad>(&b) {
        Err(Failure::Calc(CalcError::Impossible { pointer, .. })) => {
            assert_eq!(pointer, "/flow_m3_s")
        }
        other => panic!("{other:?}"),
    }
    let mut b = with("/supply_pressure_pa", Value::Null);
    b["film_m"] = Value::Null;
    b["load_n"] = json!(1e-3);
    b["flow_m3_s"] = json!(1e-3);
    b["compensation"] = json!({"kind": "constant_flow"});
    b.as_object_mut().unwrap().remove("film_m");
    match post::<HydrostaticPad>(&b) {
        Err(Failure::Calc(CalcError::Impossible { message, .. })) => {
            assert!(message.contains("film"), "{message}")
        }
        other => panic!("{other:?}"),
    }
}

/// Warnings: a capillary short and fast enough to leave Hagen–Poiseuille (turbulence off; `auto`
/// applies the turbulent law and still warns, saying so); a high-speed pad.
#[test]
fn out_of_model_flows_are_warned() {
    let mut b = base();
    b["compensation"] = json!({"kind": "capillary", "radius_m": 2e-3, "length_m": 0.05});
    b["film_m"] = json!(2e-4);
    b["lubricant"] = json!({"viscosity_pa_s": 0.001, "density_15c_kg_m3": 1000});
    b["effects"] = json!({"turbulence": "off"});
    let v = ok::<HydrostaticPad>(&b);
    let codes = warning_codes(&v);
    assert!(
        codes.contains(&"restrictor_not_laminar".to_owned()),
        "{codes:?}"
    );
    assert!(codes.contains(&"capillary_short".to_owned()), "{codes:?}");
    assert!(!v["effects"]["turbulence"]["applied"].as_bool().unwrap());
    b["effects"] = json!({"turbulence": "auto"});
    let v = ok::<HydrostaticPad>(&b);
    let codes = warning_codes(&v);
    assert!(v["effects"]["turbulence"]["applied"].as_bool().unwrap());
    let warning = v["warnings"]
        .as_array()
        .unwrap()
        .iter()
        .find(|w| w["code"] == "restrictor_not_laminar")
        .unwrap_or_else(|| panic!("{codes:?}"));
    assert!(warning["message"]
        .as_str()
        .unwrap()
        .contains("turbulent line loss (Khonsari & Booser Eq. 2.36) was applied"));
    let mut b = base();
    b["speed_rpm"] = json!(20000);
    let v = ok::<HydrostaticPad>(&b);
    assert!(warning_codes(&v).contains(&"hydrodynamic_effects".to_owned()));
    assert!(result_field(&v, "power_ratio") > 1.0);
}

/// The thermal effect: the film viscosity at T_in + ΔT/2 exactly (the root), a lower viscosity
/// than isothermal, more flow at the same film and supply.
#[test]
fn thermal_effect_finds_the_mean_film_temperature() {
    let mut b = base();
    b["speed_rpm"] = json!(3000);
    b["effects"] = json!({"thermal": "on"});
    let hot = ok::<HydrostaticPad>(&b);
    b["effects"] = json!({"thermal": "off"});
    let cold = ok::<HydrostaticPad>(&b);
    let t = result_field(&hot, "film_temperature_c");
    let rise = result_field(&hot, "temperature_rise_k");
    assert!((t - 40.0 - rise / 2.0).abs() < 1e-6, "{t} {rise}");
    assert!(result_field(&hot, "viscosity_pa_s") < result_field(&cold, "viscosity_pa_s"));
    assert!(result_field(&hot, "flow_m3_s") > result_field(&cold, "flow_m3_s"));
    assert_eq!(hot["effects"]["thermal"]["model"], "mean_film_temperature");
    // The root's work is reported; the isothermal pad is a closed form.
    assert!(
        hot["solver"]["iterations"].as_u64().unwrap() > 1,
        "{}",
        hot["solver"]
    );
    assert_eq!(cold["solver"]["iterations"], 0);
    // A constant viscosity: not applicable.
    b["lubricant"] = json!({"viscosity_pa_s": 0.05});
    let v = ok::<HydrostaticPad>(&b);
    assert!(!v["effects"]["thermal"]["applied"].as_bool().unwrap());
}

fn pad_kind() -> impl Strategy<Value = Value> {
    prop_oneof![
        (0.005f64..1.0, 0.05f64..0.95).prop_map(|(r2, x)| json!({"kind": "circular_step", "recess_radius_m": r2 * x, "outer_radius_m": r2})),
        (0.01f64..1.0, 0.1f64..0.4, 0.2f64..0.45, 0.55f64..0.8, 0.6f64..0.9).prop_map(|(r4, a, b, c, d)| {
            let (r1, r2, r3) = (r4 * a, r4 * (a + (1.0 - a) * b), r4 * (a + (1.0 - a) * c));
            let r3 = r3.max(r2 * 1.01).min(r4 * d.max(0.999));
            json!({"kind": "annular", "inner_radius_m": r1, "recess_inner_radius_m": r2, "recess_outer_radius_m": r3.min(r4 * 0.99), "outer_radius_m": r4})
        }),
        (0.005f64..0.5, 0.005f64..2.0, 0.002f64..0.1).prop_map(|(b, w, l)| json!({"kind": "rectangular", "recess_length_m": b, "recess_width_m": w, "land_width_m": l})),
        (1e-4f64..1.0, 1.0f64..10.0, 1.0f64..100.0).prop_map(|(a, pf, qf)| json!({"kind": "performance_factors", "projected_area_m2": a, "pressure_factor": pf, "flow_factor": qf})),
    ]
}

fn compensation() -> impl Strategy<Value = Value> {
    prop_oneof![
        Just(json!({"kind": "constant_flow"})),
        (1e-4f64..2e-3, 0.01f64..2.0)
            .prop_map(|(r, l)| json!({"kind": "capillary", "radius_m": r, "length_m": l})),
        (1e-4f64..2e-3, 0.05f64..0.95)
            .prop_map(|(r, m)| json!({"kind": "capillary", "radius_m": r, "pressure_ratio": m})),
        (5e-5f64..2e-3, 0.3f64..0.9).prop_map(
            |(r, c)| json!({"kind": "orifice", "radius_m": r, "discharge_coefficient": c})
        ),
        (0.3f64..0.9).prop_map(
            |c| json!({"kind": "orifice", "discharge_coefficient": c, "pressure_ratio": "optimum"})
        ),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Over the valid range: a finite result in which the restrictor passes the film's flow
    /// (conservation), the load is A_eff p_r, the ratio lies in (0, 1], or a 422 with a
    /// reason — never an internal error.
    #[test]
    fn pads_are_finite_and_conserve_flow(
        pad in pad_kind(),
        comp in compensation(),
        film in 1e-6f64..2e-4,
        supply in 1e5f64..5e7,
        mu in 1e-3f64..1.0,
        rpm in 0.0f64..5000.0,
        thermal in prop_oneof![Just("auto"), Just("off")],
        turbulence in prop_oneof![Just("auto"), Just("on"), Just("off")],
    ) {
        let speed = if pad["kind"] == "rectangular" { json!({"sliding_speed_m_s": rpm / 100.0}) } else { json!({"speed_rpm": rpm}) };
        let mut body = json!({
            "pad": pad, "compensation": comp,
            "lubricant": {"iso_vg": 46, "density_15c_kg_m3": 870},
            "film_m": film, "supply_pressure_pa": supply, "effects": {"thermal": thermal, "turbulence": turbulence},
        });
        if mu > 0.5 { body["lubricant"] = json!({"viscosity_pa_s": mu}); }
        for (k, v) in speed.as_object().unwrap() { body[k] = v.clone(); }
        match post::<HydrostaticPad>(&body) {
            Ok(v) => {
                let r = &v["result"];
                let n = |f: &str| r[f].as_f64().unwrap();
                let (q, ps, pr) = (n("flow_m3_s"), n("supply_pressure_pa"), n("recess_pressure_pa"));
                prop_assert!((n("load_n") / (n("effective_area_m2") * pr) - 1.0).abs() < 1e-12);
                let m = n("pressure_ratio");
                prop_assert!(m > 0.0 && m <= 1.0);
                // A restrictor that drops next to nothing (m → 1) leaves no stiffness, and says so.
                let warned = v["warnings"].as_array().unwrap().iter().any(|w| w["code"] == "restrictor_ineffective");
                prop_assert!(n("stiffness_n_m") > 0.0 || (n("stiffness_n_m") == 0.0 && warned));
                prop_assert!(n("total_power_w") > 0.0);
                // The restrictor passes the film's flow.
                let rest = &r["restrictor"];
                match rest["kind"].as_str().unwrap() {
                    "capillary" => {
                        let (k, drop) = (rest["conductance_m3_s_pa"].as_f64().unwrap(), rest["pressure_drop_pa"].as_f64().unwrap());
                        prop_assert!((k * drop / q - 1.0).abs() < 1e-9);
                        prop_assert!((ps - pr - drop).abs() <= 1e-12 * ps);
                    }
                    "orifice" => {
                        let (k, drop) = (rest["orifice_coefficient_m3_s_sqrt_pa"].as_f64().unwrap(), rest["pressure_drop_pa"].as_f64().unwrap());
                        prop_assert!((k * drop.sqrt() / q - 1.0).abs() < 1e-9);
                        prop_assert!((ps - pr - drop).abs() <= 1e-12 * ps);
                    }
                    _ => prop_assert_eq!(ps, pr),
                }
                // The film passes it too: Q = B̄ h³ p_r/μ.
                prop_assert!((n("flow_coefficient") * n("film_thickness_m").powi(3) * pr / n("viscosity_pa_s") / q - 1.0).abs() < 1e-9);
            }
            Err(Failure::Calc(CalcError::Internal(cause))) => panic!("internal error: {cause}"),
            Err(_) => {}
        }
    }

    /// At a fixed supply pressure (fixed flow at constant flow) the load falls as the film
    /// thickens, for every restrictor, in oil (laminar) and in water (turbulent at thick films,
    /// turbulence on).
    #[test]
    fn load_falls_as_the_film_rises(
        comp in compensation(),
        x in 0.2f64..0.8,
        water in any::<bool>(),
    ) {
        let mut last = f64::INFINITY;
        let constant = comp["kind"] == "constant_flow";
        for i in 0..12 {
            let film = 5e-6 * 1.3f64.powi(i);
            let mut body = json!({
                "pad": {"kind": "circular_step", "recess_radius_m": 0.1 * x, "outer_radius_m": 0.1},
                "compensation": comp.clone(), "lubricant": {"viscosity_pa_s": 0.05, "density_15c_kg_m3": 870},
                "film_m": film,
            });
            if water {
                body["lubricant"] = json!({"viscosity_pa_s": 1e-3, "density_15c_kg_m3": 1000});
                body["effects"] = json!({"turbulence": "on"});
            }
            if constant { body["flow_m3_s"] = json!(1e-5); } else { body["supply_pressure_pa"] = json!(5e6); }
            let v = ok::<HydrostaticPad>(&body);
            let w = result_field(&v, "load_n");
            // A designed restrictor is re-sized at each film: its load is m A_eff p_s, flat in
            // laminar flow; turbulent, A_eff falls as the flow grows (the land's pressure drops
            // sooner where it is turbulent, by the recess).
            if comp.get("pressure_ratio").is_some() && water {
                prop_assert!(w <= last * (1.0 + 1e-9), "{} then {}", last, w);
            } else if comp.get("pressure_ratio").is_some() {
                prop_assert!((w / last - 1.0).abs() < 1e-12 || last.is_infinite());
            } else {
                prop_assert!(w < last, "{} then {}", last, w);
            }
            last = w;
        }
    }
}
