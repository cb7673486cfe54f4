//! The piston ring's film against closed forms of its two limits (steady sliding with the
//! Reynolds condition, pure squeeze), and the cycle's periodicity and properties.

use super::*;
use crate::numerics::roots::{self, Stopping};
use proptest::prelude::*;

/// Table 9.5's ring: b = 1.475 mm, δ₀ = 14.9 μm, E = 70 GPa, t_r = 3.8 mm, r = 44.45 mm.
fn table_9_5_ring() -> Ring {
    Ring {
        half_width: 0.5 * 1.475e-3,
        crown_height: 14.9e-6,
        stiffness: 70e9 * 3.8e-3 / 0.04445f64.powi(2),
        tension_pressure: 0.0,
    }
}

/// Table 9.5's engine at 2000 rpm with a constant gas pressure `p` (Pa) above the ring.
fn table_9_5_engine(p: f64, bottom_fraction: f64) -> Engine {
    Engine {
        bore: 0.0889,
        crank_radius: 0.040,
        rod_length: 0.1419,
        omega: 2000.0 * 2.0 * PI / 60.0,
        cycle: 4.0 * PI,
        angles: vec![0.0],
        pressures: vec![p],
        bottom_fraction,
    }
}

/// The closed-form integrals of the parabolic film h = h_m (1 + (ξ/c)²), c = a √(h_m/δ₀),
/// with ξ = c tan φ: ∫dξ/h², ∫dξ/h³, ∫ξ dξ/h², ∫ξ dξ/h³, ∫ξ² dξ/h³ at φ.
struct Parabola {
    h_m: f64,
    c: f64,
}

impl Parabola {
    fn new(ring: &Ring, h_m: f64) -> Self {
        Parabola {
            h_m,
            c: ring.half_width * (h_m / ring.crown_height).sqrt(),
        }
    }
    fn phi(&self, xi: f64) -> f64 {
        (xi / self.c).atan()
    }
    fn i2(&self, p: f64) -> f64 {
        self.c / self.h_m.powi(2) * (p / 2.0 + (2.0 * p).sin() / 4.0)
    }
    fn i3(&self, p: f64) -> f64 {
        self.c / self.h_m.powi(3) * (3.0 * p / 8.0 + (2.0 * p).sin() / 4.0 + (4.0 * p).sin() / 32.0)
    }
    fn j2(&self, p: f64) -> f64 {
        self.c.powi(2) / self.h_m.powi(2) * p.sin().powi(2) / 2.0
    }
    fn j3(&self, p: f64) -> f64 {
        -self.c.powi(2) / self.h_m.powi(3) * p.cos().powi(4) / 4.0
    }
    fn k3(&self, p: f64) -> f64 {
        self.c.powi(3) / self.h_m.powi(3) * (p / 8.0 - (4.0 * p).sin() / 32.0)
    }
}

/// The steady load per unit circumference of the crowned ring sliding at V with both edges at
/// zero pressure and the Reynolds condition at the rupture ξ_c (derived here: dP/dξ =
/// 6μV(h − h*)/h³ from the inlet ξ = −a, P = dP/dξ = 0 at ξ_c so h* = h(ξ_c), and
/// W = −6μV ∫ξ (1/h² − h*/h³) dξ by parts), with ξ_c by Brent.
fn steady_load(ring: &Ring, mu: f64, speed: f64, h_m: f64) -> f64 {
    let f = Parabola::new(ring, h_m);
    let a = ring.half_width;
    let pa = f.phi(-a);
    let h_star = |xc: f64| h_m * (1.0 + (xc / f.c).powi(2));
    let g = |xc: f64| {
        let pc = f.phi(xc);
        (f.i2(pc) - f.i2(pa)) - h_star(xc) * (f.i3(pc) - f.i3(pa))
    };
    let stop = Stopping {
        x_tolerance: 1e-15 * a,
        max_iterations: 200,
    };
    let xc = roots::brent(g, 1e-9 * a, a, stop).expect("a rupture").x;
    let pc = f.phi(xc);
    -6.0 * mu * speed * ((f.j2(pc) - f.j2(pa)) - h_star(xc) * (f.j3(pc) - f.j3(pa)))
}

#[test]
fn steady_sliding_carries_the_crowned_sliders_closed_form_load() {
    let ring = table_9_5_ring();
    let mu = 0.00689;
    let film = Film::new(ring, mu, 800);
    let budget = Budget::unlimited();
    for (speed, h_m) in [(10.0, 2e-6), (5.0, 0.5e-6), (15.0, 8e-6)] {
        let w = steady_load(&ring, mu, speed, h_m);
        assert!(w > 0.0, "W = {w}");
        // The liner runs towards −x: the piston moves down, the top edge trails.
        let solve = |load: f64| {
            film.solve(
                h_m,
                -speed,
                0.0,
                0.0,
                Some(Trailing::Top),
                load,
                &mut Vec::new(),
                &budget,
            )
            .unwrap()
            .squeeze_rate
        };
        // ḣ is linear in the load for a fixed cavity: W(ḣ = 0) from two loads.
        let (r1, r2) = (solve(w), solve(1.02 * w));
        let load_at_rest = w - r1 * (0.02 * w) / (r2 - r1);
        let rel = (load_at_rest - w).abs() / w;
        assert!(
            rel < 2e-3,
            "V {speed}, h_m {h_m}: {load_at_rest} vs {w} ({rel:e})"
        );
    }
}

#[test]
fn pure_squeeze_of_the_parabolic_film_matches_its_closed_form() {
    // U = 0, edges at zero: d/dx(h³P'/12μ) = ḣ, P' = 12μḣx/h³, W = −24μḣ ∫₀ᵃ x²/h³ dx.
    let ring = table_9_5_ring();
    let mu = 0.00689;
    let film = Film::new(ring, mu, 800);
    for h_m in [0.3e-6, 2e-6, 20e-6] {
        let f = Parabola::new(&ring, h_m);
        let w = 5e4;
        let want = -w / (24.0 * mu * f.k3(f.phi(ring.half_width)));
        let got = film
            .solve(
                h_m,
                0.0,
                0.0,
                0.0,
                None,
                w,
                &mut Vec::new(),
                &Budget::unlimited(),
            )
            .unwrap();
        let rel = (got.squeeze_rate - want).abs() / want.abs();
        assert!(
            rel < 1e-4,
            "h_m {h_m}: ḣ {} vs {want} ({rel:e})",
            got.squeeze_rate
        );
        assert!(
            got.shear.abs() < 1e-12 * w,
            "no sliding, no net shear: {}",
            got.shear
        );
        // Dissipation equals the squeeze's work −W ḣ.
        let work = -w * got.squeeze_rate;
        assert!(
            (got.dissipation - work).abs() < 1e-3 * work,
            "{} vs {work}",
            got.dissipation
        );
    }
}

fn numerics(cells: usize, tolerance: f64) -> Numerics {
    Numerics {
        cells,
        tolerance,
        periodicity: 10.0 * tolerance,
    }
}

/// Table 9.5's ring under a firing-cycle gas-pressure table (a plausible shape: Fig 9.25 is not
/// digitised), no boundary friction.
fn gas_loaded_ring() -> PistonRing {
    PistonRing {
        ring: table_9_5_ring(),
        engine: Engine {
            angles: [0.0, 20.0, 60.0, 180.0, 360.0, 540.0, 680.0]
                .map(f64::to_radians)
                .to_vec(),
            pressures: vec![4e6, 6e6, 1.5e6, 2e5, 0.0, 1e5, 1e6],
            ..table_9_5_engine(0.0, 0.5)
        },
        viscosity: 0.00689,
        boundary: None,
    }
}

#[test]
fn the_cycle_repeats_and_does_not_depend_on_the_first_guess() {
    let model = gas_loaded_ring();
    let budget = Budget::unlimited();
    let n = numerics(100, 1e-6);
    let a = model.cycle(14.9e-8, &n, &budget).unwrap();
    let b = model.cycle(14.9e-6, &n, &budget).unwrap();
    let (first, last) = (a.samples[0].min_film, a.samples.last().unwrap().min_film);
    assert!((last / first).ln().abs() <= 1e-5, "{first} vs {last}");
    assert!(a.cycles <= 10, "{} cycles", a.cycles);
    // The cycle's two ends are the same state: the same film solve, whatever the warm start.
    let (s0, s1) = (&a.samples[0], a.samples.last().unwrap());
    assert!(
        (s1.max_pressure / s0.max_pressure - 1.0).abs() < 1e-3,
        "{s0:?} vs {s1:?}"
    );
    let rel = (a.min_film.0 - b.min_film.0).abs() / a.min_film.0;
    assert!(rel < 1e-4, "{:?} vs {:?}", a.min_film, b.min_film);
    assert!((a.mean_power - b.mean_power).abs() < 1e-4 * a.mean_power);
    // The film is thickest near mid-stroke and thinnest near a dead centre (the text).
    let deg = a.min_film.1.to_degrees().rem_euclid(180.0);
    assert!(!(20.0..160.0).contains(&deg), "min at {deg}° of its stroke");
}

#[test]
fn a_warm_start_from_the_other_stroke_leaves_the_film_unchanged() {
    // The down stroke cavitates behind the crown on the top half; its cavity must not survive
    // into the up stroke, whose cavity is on the bottom half (a stale one pins the pressure
    // there and puts a jump in the film, whose dissipation then grows with the grid).
    let film = Film::new(table_9_5_ring(), 0.00689, 200);
    let budget = Budget::unlimited();
    let (h_m, load) = (1e-6, 1.475e-3 * 3e6);
    let mut active = Vec::new();
    let down = film
        .solve(
            h_m,
            -5.0,
            2e6,
            1e6,
            Some(Trailing::Top),
            load,
            &mut active,
            &budget,
        )
        .unwrap();
    assert!(active.iter().any(|&a| a), "the down stroke cavitates");
    let up = |active: &mut Vec<bool>| {
        film.solve(
            h_m,
            5.0,
            2e6,
            1e6,
            Some(Trailing::Bottom),
            load,
            active,
            &budget,
        )
        .unwrap()
    };
    let (warm, cold) = (up(&mut active), up(&mut Vec::new()));
    assert!(active[..100].iter().all(|&a| !a));
    assert_eq!(warm.pressure, cold.pressure);
    assert!(down.squeeze_rate != warm.squeeze_rate);
}

#[test]
fn the_cycles_power_converges_with_the_grid() {
    let model = gas_loaded_ring();
    let budget = Budget::unlimited();
    let coarse = model.cycle(1e-6, &numerics(100, 1e-6), &budget).unwrap();
    let fine = model.cycle(1e-6, &numerics(200, 1e-6), &budget).unwrap();
    let rel = (coarse.mean_power / fine.mean_power - 1.0).abs();
    assert!(rel < 0.02, "{} vs {} W", coarse.mean_power, fine.mean_power);
    for (c, f) in coarse.samples.iter().zip(&fine.samples) {
        assert!(
            (c.power - f.power).abs() <= 0.05 * f.power + 1e-3,
            "{c:?} vs {f:?}"
        );
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(8))]
    /// Equal pressures on both sides: the film stays positive and finite, and its friction
    /// opposes the piston's motion (it is viscous drag only).
    #[test]
    fn friction_opposes_sliding(rpm in 300.0f64..6000.0, tension in 0.0f64..1e6,
                                mu in 0.002f64..0.05) {
        let model = PistonRing {
            ring: Ring { tension_pressure: tension, ..table_9_5_ring() },
            engine: Engine {
                omega: rpm * PI / 30.0,
                ..table_9_5_engine(2e5, 1.0)
            },
            viscosity: mu,
            boundary: None,
        };
        let cycle = model.cycle(1e-6, &numerics(60, 1e-5), &Budget::unlimited()).unwrap();
        for s in &cycle.samples {
            prop_assert!(s.min_film > 0.0 && s.min_film.is_finite());
            prop_assert!(s.friction.is_finite() && s.power >= 0.0);
            prop_assert!(s.friction * s.piston_speed <= 1e-9 * s.power.max(1e-30),
                "θ {}: F {} U {}", s.theta, s.friction, s.piston_speed);
        }
    }
}
