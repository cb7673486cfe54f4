//! A hydrostatic pad's geometry as the film sees it: the effective area A_eff (W = A_eff·p_r),
//! the flow coefficient B̄ (Q = B̄ h³ p_r/μ), the land friction per unit μω/h or μU/h, the
//! lengths the validity checks need, and the lands as the turbulent film law sees them
//! (`lands`). Parallel film, isoviscous, deep recess, laminar unless turbulence applies
//! (Khonsari & Booser §10.3, §10.7, Prob. 10.4; Stachowiak & Batchelor §6.2–6.3).

use std::f64::consts::PI;

use super::lands::{Film, Lands, RadialLand, Slit};

/// A pad, dimensions in metres.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Geometry {
    /// Circular pad with a central circular recess: recess radius R1 < outer radius R2
    /// (Khonsari & Booser Eq. 10.4–10.14; Stachowiak & Batchelor Eq. 6.4–6.12).
    CircularStep {
        recess_radius: f64,
        outer_radius: f64,
    },
    /// Annular pad with an annular recess R2 … R3 between an inner land R1 … R2 and an outer land
    /// R3 … R4: each land is the circular step's land, solved with its own log profile.
    Annular {
        inner_radius: f64,
        recess_inner_radius: f64,
        recess_outer_radius: f64,
        outer_radius: f64,
    },
    /// Rectangular recess b × L (b along x) surrounded by a land of width l on every side.
    /// Long-recess exact (Khonsari & Booser Prob. 10.4, L ≫ l: p = p_r(1 − x/l)); the ends
    /// by the usual approximation: a linear drop across each land strip, each corner square a
    /// pyramid (load l²p_r/3), and the flow through the strips at their mean lengths (b + l and
    /// L + l). The approximation tends to Prob. 10.4 as L/l → ∞.
    Rectangular {
        recess_length: f64,
        recess_width: f64,
        land_width: f64,
    },
    /// Multi-recess pads and partial journals that the texts give only as Loeb–Rippel charts
    /// (Khonsari & Booser Fig. 10.9): the projected area A with the pressure factor
    /// P_f = A/A_eff and the flow factor q_f (Q = q_f (W/A) h³/(12μ)), read off the chart by the
    /// user (Eq. 10.36–10.40).
    PerformanceFactors {
        projected_area: f64,
        pressure_factor: f64,
        flow_factor: f64,
    },
}

/// How the lands' viscous drag is expressed for this geometry.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Drag {
    /// A rotating runner over lands (R_i, R_o) (a second land of zero width where there is one
    /// land): laminar, T = μ ω Σ π(R_o⁴ − R_i⁴)/(2h) (Couette shear, recess neglected:
    /// Khonsari & Booser Eq. 10.14).
    Torque([(f64, f64); 2]),
    /// A sliding runner: force F = μ U c/h with c = the land area (Couette shear).
    Force(f64),
    /// The geometry gives no friction (Loeb–Rippel factors carry none).
    None,
}

impl Geometry {
    pub fn name(&self) -> &'static str {
        match self {
            Geometry::CircularStep { .. } => "circular_step",
            Geometry::Annular { .. } => "annular",
            Geometry::Rectangular { .. } => "rectangular",
            Geometry::PerformanceFactors { .. } => "performance_factors",
        }
    }

    /// A_eff, m²: W = A_eff p_r.
    pub fn effective_area(&self) -> f64 {
        match *self {
            Geometry::CircularStep {
                recess_radius,
                outer_radius,
            } => outer_land_area(recess_radius, outer_radius),
            Geometry::Annular {
                inner_radius,
                recess_inner_radius,
                recess_outer_radius,
                outer_radius,
            } => {
                outer_land_area(recess_outer_radius, outer_radius)
                    - outer_land_area(inner_radius, recess_inner_radius)
            }
            Geometry::Rectangular {
                recess_length: b,
                recess_width: w,
                land_width: l,
            } => b * w + l * (b + w) + 4.0 * l * l / 3.0,
            Geometry::PerformanceFactors {
                projected_area,
                pressure_factor,
                ..
            } => projected_area / pressure_factor,
        }
    }

    /// B̄, dimensionless: Q = B̄ h³ p_r/μ (Stachowiak & Batchelor Eq. 6.19's B̄; Khonsari &
    /// Booser's C2 = B̄/μ).
    pub fn flow_coefficient(&self) -> f64 {
        match *self {
            Geometry::CircularStep {
                recess_radius,
                outer_radius,
            } => PI / (6.0 * (outer_radius / recess_radius).ln()),
            Geometry::Annular {
                inner_radius,
                recess_inner_radius,
                recess_outer_radius,
                outer_radius,
            } => {
                PI / 6.0
                    * (1.0 / (outer_radius / recess_outer_radius).ln()
                        + 1.0 / (recess_inner_radius / inner_radius).ln())
            }
            Geometry::Rectangular {
                recess_length: b,
                recess_width: w,
                land_width: l,
            } => 2.0 * ((b + l) + (w + l)) / (12.0 * l),
            Geometry::PerformanceFactors {
                pressure_factor,
                flow_factor,
                ..
            } => flow_factor / (12.0 * pressure_factor),
        }
    }

    /// The laminar lands at film viscosity μ: Q = B̄ s/μ, A_eff fixed.
    pub fn laminar_lands(&self, mu: f64) -> Lands {
        Lands::Laminar(Film {
            area: self.effective_area(),
            c2: self.flow_coefficient() / mu,
        })
    }

    /// The lands with the slit law where the flow is turbulent (see `lands`). Chart factors
    /// stay laminar: the charts give no land to apply it to.
    pub fn turbulent_lands(&self, slit: Slit) -> Lands {
        match *self {
            Geometry::CircularStep {
                recess_radius,
                outer_radius,
            } => Lands::Radial {
                slit,
                outward: RadialLand {
                    inner: recess_radius,
                    outer: outer_radius,
                },
                inward: None,
            },
            Geometry::Annular {
                inner_radius,
                recess_inner_radius,
                recess_outer_radius,
                outer_radius,
            } => Lands::Radial {
                slit,
                outward: RadialLand {
                    inner: recess_outer_radius,
                    outer: outer_radius,
                },
                inward: Some(RadialLand {
                    inner: inner_radius,
                    outer: recess_inner_radius,
                }),
            },
            Geometry::Rectangular {
                recess_length: b,
                recess_width: w,
                land_width: l,
            } => Lands::Strips {
                slit,
                width: 2.0 * ((b + l) + (w + l)),
                length: l,
                area: self.effective_area(),
            },
            Geometry::PerformanceFactors { .. } => self.laminar_lands(slit.mu),
        }
    }

    /// The land drag of this pad.
    pub fn drag(&self) -> Drag {
        match *self {
            Geometry::CircularStep {
                recess_radius,
                outer_radius,
            } => Drag::Torque([
                (recess_radius, outer_radius),
                (recess_radius, recess_radius),
            ]),
            Geometry::Annular {
                inner_radius,
                recess_inner_radius,
                recess_outer_radius,
                outer_radius,
            } => Drag::Torque([
                (inner_radius, recess_inner_radius),
                (recess_outer_radius, outer_radius),
            ]),
            Geometry::Rectangular {
                recess_length: b,
                recess_width: w,
                land_width: l,
            } => Drag::Force((b + 2.0 * l) * (w + 2.0 * l) - b * w),
            Geometry::PerformanceFactors { .. } => Drag::None,
        }
    }

    /// The narrowest land, m: the film must be thin against it (None for chart factors).
    pub fn narrowest_land(&self) -> Option<f64> {
        match *self {
            Geometry::CircularStep {
                recess_radius,
                outer_radius,
            } => Some(outer_radius - recess_radius),
            Geometry::Annular {
                inner_radius,
                recess_inner_radius,
                recess_outer_radius,
                outer_radius,
            } => Some((recess_inner_radius - inner_radius).min(outer_radius - recess_outer_radius)),
            Geometry::Rectangular { land_width, .. } => Some(land_width),
            Geometry::PerformanceFactors { .. } => None,
        }
    }

    /// The largest flow per unit width Q′ on the lands at a total flow Q, m²/s (for the land
    /// Reynolds number 2ρQ′/μ; None for chart factors): at the recess edge of an outward land;
    /// on an annulus, the larger of the outer land's at its recess edge and the inner land's at
    /// its bore (Q shared by the lands' laminar conductances); across the rectangular pad's
    /// strips, uniform.
    pub fn peak_flow_per_width(&self, q: f64) -> Option<f64> {
        match *self {
            Geometry::CircularStep { recess_radius, .. } => Some(q / (2.0 * PI * recess_radius)),
            Geometry::Annular {
                inner_radius,
                recess_inner_radius,
                recess_outer_radius,
                outer_radius,
            } => {
                let inner = 1.0 / (recess_inner_radius / inner_radius).ln();
                let outer = 1.0 / (outer_radius / recess_outer_radius).ln();
                let share = |g: f64| q * g / (inner + outer);
                Some(
                    (share(outer) / (2.0 * PI * recess_outer_radius))
                        .max(share(inner) / (2.0 * PI * inner_radius)),
                )
            }
            Geometry::Rectangular {
                recess_length: b,
                recess_width: w,
                land_width: l,
            } => Some(q / (2.0 * ((b + l) + (w + l)))),
            Geometry::PerformanceFactors { .. } => None,
        }
    }

    /// The largest radius the runner turns at, m (rotating pads).
    pub fn outer_radius(&self) -> Option<f64> {
        match *self {
            Geometry::CircularStep { outer_radius, .. }
            | Geometry::Annular { outer_radius, .. } => Some(outer_radius),
            _ => None,
        }
    }

    /// The pad's projected (whole) area, m².
    pub fn projected_area(&self) -> f64 {
        match *self {
            Geometry::CircularStep { outer_radius, .. } => PI * outer_radius * outer_radius,
            Geometry::Annular {
                inner_radius,
                outer_radius,
                ..
            } => PI * (outer_radius * outer_radius - inner_radius * inner_radius),
            Geometry::Rectangular {
                recess_length: b,
                recess_width: w,
                land_width: l,
            } => (b + 2.0 * l) * (w + 2.0 * l),
            Geometry::PerformanceFactors { projected_area, .. } => projected_area,
        }
    }
}

/// ∫ p dA / p_r over a recess of radius a and its outer land a … b: π(b² − a²)/(2 ln(b/a))
/// (Khonsari & Booser Eq. 10.5). The annulus's inner land subtracts the same form: the inner
/// land a … b carries πb² − π(b² − a²)/(2 ln(b/a)) over the disc it surrounds.
fn outer_land_area(a: f64, b: f64) -> f64 {
    PI * (b * b - a * a) / (2.0 * (b / a).ln())
}

/// Khonsari & Booser's Loeb–Rippel factors of a circular step (Eq. 10.43): P_f, q_f and, with
/// pump efficiency η, H_f = P_f q_f/η (Eq. 10.42).
pub fn circular_step_factors(ratio: f64) -> (f64, f64) {
    let ln = (1.0 / ratio).ln();
    let d = 1.0 - ratio * ratio;
    (2.0 * ln / d, 4.0 * PI / d)
}

/// The recess ratio R1/R2 that minimises a circular step's pumping power at a fixed load, film
/// and outer radius: the non-trivial root of ln(R2/R1) = ¼[(R2/R1)² − 1] (Khonsari & Booser
/// Eq. 10.19; 0.53354, printed 0.53). Bracketed on (0.05, 0.95), away from the trivial root 1
/// (spec H-7).
pub fn minimum_pumping_ratio() -> f64 {
    use crate::numerics::roots::{brent, Stopping};
    let f = |x: f64| (1.0 / x).ln() - 0.25 * (1.0 / (x * x) - 1.0);
    let stop = Stopping {
        x_tolerance: 1e-15,
        max_iterations: 100,
    };
    brent(f, 0.05, 0.95, stop).map_or(0.533_543, |root| root.x)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The exact pressure field of each pad integrated by a fine midpoint rule: A_eff = ∫p/p_r dA.
    #[test]
    fn effective_areas_integrate_their_pressure_fields() {
        let (r1, r2) = (0.03, 0.07);
        let n = 200_000;
        let mut load = PI * r1 * r1;
        let dr = (r2 - r1) / n as f64;
        for i in 0..n {
            let r = r1 + (i as f64 + 0.5) * dr;
            load += 2.0 * PI * r * (r2 / r).ln() / (r2 / r1).ln() * dr;
        }
        let g = Geometry::CircularStep {
            recess_radius: r1,
            outer_radius: r2,
        };
        assert!((g.effective_area() / load - 1.0).abs() < 1e-9);
        // Annulus: inner land 0.02 … 0.03, recess 0.03 … 0.05, outer land 0.05 … 0.07.
        let (a, b, c, d) = (0.02, 0.03, 0.05, 0.07);
        let mut load = PI * (c * c - b * b);
        let land = |ri: f64, ro: f64, p: &dyn Fn(f64) -> f64| {
            let dr = (ro - ri) / n as f64;
            (0..n)
                .map(|i| {
                    let r = ri + (i as f64 + 0.5) * dr;
                    2.0 * PI * r * p(r) * dr
                })
                .sum::<f64>()
        };
        load += land(a, b, &|r| (r / a).ln() / (b / a).ln());
        load += land(c, d, &|r| (d / r).ln() / (d / c).ln());
        let g = Geometry::Annular {
            inner_radius: a,
            recess_inner_radius: b,
            recess_outer_radius: c,
            outer_radius: d,
        };
        assert!((g.effective_area() / load - 1.0).abs() < 1e-9);
    }

    /// The annulus's flow is the two lands' flows: Q = 2πr h³/(12μ)|dp/dr| on each.
    #[test]
    fn annular_flow_is_both_lands() {
        let (a, b, c, d) = (0.02, 0.03, 0.05, 0.07);
        let g = Geometry::Annular {
            inner_radius: a,
            recess_inner_radius: b,
            recess_outer_radius: c,
            outer_radius: d,
        };
        // Outer land: dp/dr = −p_r/(r ln(d/c)); inner: p_r/(r ln(b/a)).
        let q = 2.0 * PI / 12.0 * (1.0 / (d / c).ln() + 1.0 / (b / a).ln());
        assert!((g.flow_coefficient() / q - 1.0).abs() < 1e-14);
    }

    /// A long rectangular recess tends to Prob. 10.4: W = p_r L(b + l), Q = L h³ p_r/(6 μ l).
    #[test]
    fn rectangular_tends_to_the_long_recess() {
        let (b, l) = (0.1, 0.025);
        for w in [10.0, 100.0, 1000.0] {
            let g = Geometry::Rectangular {
                recess_length: b,
                recess_width: w,
                land_width: l,
            };
            let err_w = g.effective_area() / (w * (b + l)) - 1.0;
            let err_q = g.flow_coefficient() / (w / (6.0 * l)) - 1.0;
            assert!(err_w.abs() < 1.5 * l / w, "{w}: {err_w}");
            assert!(err_q.abs() < 1.5 * (b + 2.0 * l) / w, "{w}: {err_q}");
        }
    }

    /// Eq. 10.43's factors are A/A_eff and 12 P_f B̄ of the circular step.
    #[test]
    fn circular_factors_agree_with_the_geometry() {
        let x = 0.5;
        let g = Geometry::CircularStep {
            recess_radius: x,
            outer_radius: 1.0,
        };
        let (pf, qf) = circular_step_factors(x);
        assert!((pf - PI / g.effective_area()).abs() < 1e-14);
        assert!((qf - 12.0 * pf * g.flow_coefficient()).abs() < 1e-12);
        let f = Geometry::PerformanceFactors {
            projected_area: PI,
            pressure_factor: pf,
            flow_factor: qf,
        };
        assert!((f.effective_area() / g.effective_area() - 1.0).abs() < 1e-14);
        assert!((f.flow_coefficient() / g.flow_coefficient() - 1.0).abs() < 1e-14);
    }

    /// Spec T2/H-7: the minimum-pumping ratio 0.53354 (book 0.53), and it minimises
    /// H_f ∝ ln(1/x)/(1 − x²)² found by golden-section search independently of Eq. 10.19.
    #[test]
    fn minimum_pumping_ratio_is_0_5335() {
        let x = minimum_pumping_ratio();
        assert!((x - 0.53354).abs() < 1e-5, "{x}");
        let power = |x: f64| (1.0 / x).ln() / (1.0 - x * x).powi(2);
        let (found, _) = crate::numerics::optimise::brent_minimise(power, 0.05, 0.95, 1e-10);
        assert!((found - x).abs() < 1e-7, "{found} vs {x}");
    }
}
