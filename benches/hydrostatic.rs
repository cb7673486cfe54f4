//! Hydrostatic rooms: the closed forms (release, one core). The issue asks for < 20 µs per
//! closed form; each case is the whole request through the room (parse, validate, physics,
//! envelope):
//! - the pad: Ex 10.1 (constant flow), Ex 10.2 (capillary designed for m = ½), an orifice at a
//!   given film and supply pressure (the quadratic root), the thermal effect's root in T, and
//!   the turbulence effect (the README's water pad: Brent on the turbulent capillary; an
//!   annulus in water at a load and supply pressure: Brent nested over the two lands' roots);
//! - the design: Ex 10.1's minimum-pumping ratio (scan + Brent), the free film at speed with
//!   its power curves, Ex 10.4's oil lift.
//!
//! `cargo bench --bench hydrostatic`.

use std::hint::black_box;

use criterion::{criterion_group, criterion_main, Criterion};
use stribeck::calc::find;

fn request(c: &mut Criterion, name: &str, path: &str, body: &str) {
    let entry = find(path).unwrap();
    let far = std::time::Instant::now() + std::time::Duration::from_secs(3600);
    c.bench_function(name, |b| {
        b.iter(|| (entry.execute)(black_box(body.as_bytes()), far, Default::default()).unwrap())
    });
}

const PAD: &str = "/v1/hydrostatic-bearings/pad";
const DESIGN: &str = "/v1/hydrostatic-bearings/design";

fn hydrostatic(c: &mut Criterion) {
    request(
        c,
        "pad: Ex 10.1 circular step, constant flow",
        PAD,
        r#"{"pad": {"kind": "circular_step", "recess_radius_m": 0.107696, "outer_radius_m": 0.2032}, "compensation": {"kind": "constant_flow"}, "lubricant": {"viscosity_pa_s": 0.054124}, "film_m": 7.62e-5, "load_n": 479073, "pump_efficiency": 0.8}"#,
    );
    request(
        c,
        "pad: Ex 10.2 capillary designed for m = 0.5 (the room's example)",
        PAD,
        find(PAD).unwrap().example,
    );
    request(
        c,
        "pad: orifice at a given film and supply pressure",
        PAD,
        r#"{"pad": {"kind": "annular", "inner_radius_m": 0.05, "recess_inner_radius_m": 0.07, "recess_outer_radius_m": 0.1, "outer_radius_m": 0.12}, "compensation": {"kind": "orifice", "radius_m": 3e-4, "discharge_coefficient": 0.6}, "lubricant": {"viscosity_pa_s": 0.03}, "film_m": 4e-5, "supply_pressure_pa": 5e6}"#,
    );
    request(
        c,
        "pad: capillary, thermal effect on (root in the film temperature)",
        PAD,
        r#"{"pad": {"kind": "circular_step", "recess_radius_m": 0.0635, "outer_radius_m": 0.127}, "compensation": {"kind": "capillary", "radius_m": 7.62e-4, "length_m": 0.4}, "lubricant": {"iso_vg": 68}, "film_m": 7.62e-5, "supply_pressure_pa": 1.3e7, "speed_rpm": 3000, "effects": {"thermal": "on"}}"#,
    );
    request(
        c,
        "pad: water, turbulent capillary (the README's), given film and supply pressure",
        PAD,
        r#"{"pad": {"kind": "circular_step", "recess_radius_m": 0.025, "outer_radius_m": 0.05}, "compensation": {"kind": "capillary", "radius_m": 0.001, "length_m": 0.2}, "lubricant": {"viscosity_pa_s": 0.001, "density_15c_kg_m3": 1000}, "temperature_c": 15, "film_m": 1.5e-4, "supply_pressure_pa": 1e6, "speed_rpm": 3000}"#,
    );
    request(
        c,
        "pad: water, annulus with turbulent lands and capillary, given load and supply pressure",
        PAD,
        r#"{"pad": {"kind": "annular", "inner_radius_m": 0.03, "recess_inner_radius_m": 0.05, "recess_outer_radius_m": 0.09, "outer_radius_m": 0.12}, "compensation": {"kind": "capillary", "radius_m": 0.002, "length_m": 0.05}, "lubricant": {"viscosity_pa_s": 0.001, "density_15c_kg_m3": 1000}, "temperature_c": 15, "load_n": 3000, "supply_pressure_pa": 1e6}"#,
    );
    request(
        c,
        "design: Ex 10.1 minimum pumping ratio (the room's example)",
        DESIGN,
        find(DESIGN).unwrap().example,
    );
    request(
        c,
        "design: free film at 600 rpm with both power curves",
        DESIGN,
        r#"{"load_n": 479083, "lubricant": {"viscosity_pa_s": 0.054124}, "pump_efficiency": 0.8, "pad": {"kind": "circular_step", "outer_radius_m": 0.2032}, "speed_rpm": 600, "include_power_curve": true}"#,
    );
    request(
        c,
        "design: Ex 10.4 oil lift",
        DESIGN,
        r#"{"load_n": 444822, "lubricant": {"viscosity_pa_s": 0.048263}, "oil_lift": {"diameter_m": 0.508, "length_m": 0.4572, "radial_clearance_m": 4.064e-4, "lift_m": 1.27e-4, "pocket_count": 3, "pocket_area_m2": 0.00387096}}"#,
    );
}

criterion_group!(benches, hydrostatic);
criterion_main!(benches);
