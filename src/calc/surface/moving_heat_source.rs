//! Surface temperatures of a half-space under a uniform heat flux q over a source moving at a
//! Peclet number L = Uℓ/(2χ), by direct integration of Jaeger's moving-source solutions
//! (Jaeger 1942; Stachowiak & Batchelor §7.6, whose Fig. 7.30 charts these integrals). Lengths
//! are in units of ℓ (the radius of a circle, the half-width along the sliding direction of a
//! rectangle or band); the results are dimensionless: multiply by qℓ/K for a temperature.
//!
//! - Point source, 3D (circles and rectangles): a point heat source moving along x over a
//!   half-space raises the surface by Q e^{−L(ρ − ξ)}/(2πKρ) at distance ρ, ξ its x-offset
//!   ahead of the point (Carslaw & Jaeger §10.7). Integrated over the source in polar
//!   co-ordinates about the field point, the radial integral is closed:
//!   θ = (1/2π) ∫₀^{2π} [1 − e^{−L(1−cos φ)ρ_max(φ)}] / [L(1 − cos φ)] dφ, with ρ_max the
//!   distance to the source's edge along φ.
//! - Line source, 2D (an infinitely long band): θ(X) = (1/π)∫₋₁¹ e^{L(X − X′)} K₀(L|X − X′|) dX′
//!   (Jaeger's band solution; the −ln 2L slow form of Stachowiak Table 7.7 is its L → 0 limit).

use std::f64::consts::PI;

use crate::numerics::optimise::brent_minimise;
use crate::numerics::quadrature::gauss_legendre;

/// The source shapes, in units of ℓ.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Shape {
    /// Radius 1.
    Circle,
    /// Half-sides 1 along x and `half_length` across.
    Rectangle { half_length: f64 },
    /// Half-width 1 along x, infinitely long across.
    Band,
}

/// Mean and maximum surface temperature over the source, in units of qℓ/K.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Temperatures {
    pub mean: f64,
    pub max: f64,
}

/// Distance from (x, y) inside the shape to its edge along direction φ.
fn edge_distance(shape: Shape, x: f64, y: f64, (c, s): (f64, f64)) -> f64 {
    match shape {
        Shape::Circle => {
            let along = x * c + y * s;
            let across = x * s - y * c;
            -along + (1.0 - across * across).max(0.0).sqrt()
        }
        Shape::Rectangle { half_length } => {
            let wall = |position: f64, direction: f64, half: f64| {
                if direction > 1e-15 {
                    (half - position) / direction
                } else if direction < -1e-15 {
                    (-half - position) / direction
                } else {
                    f64::INFINITY
                }
            };
            wall(x, c, 1.0).min(wall(y, s, half_length)).max(0.0)
        }
        Shape::Band => unreachable!("the band is two-dimensional"),
    }
}

/// Directions for the φ integral: the periodic trapezoid rule (spectrally accurate on the
/// smooth parts; the kinks where ρ_max turns a corner cost second order).
const DIRECTIONS: usize = 720;

/// θ at (x, y) for a circle or rectangle, in units of qℓ/K.
fn point_temperature(shape: Shape, peclet: f64, x: f64, y: f64, directions: &[(f64, f64)]) -> f64 {
    let sum: f64 = directions
        .iter()
        .map(|&(c, s)| {
            let reach = edge_distance(shape, x, y, (c, s));
            let decay = peclet * (1.0 - c);
            if decay * reach < 1e-12 {
                reach
            } else {
                -(-decay * reach).exp_m1() / decay
            }
        })
        .sum();
    sum / directions.len() as f64
}

/// e^{z}K₀(z) for z > 0 (Abramowitz & Stegun 9.8.1, 9.8.5, 9.8.6; |error| < 2 × 10⁻⁷ relative).
fn scaled_k0(z: f64) -> f64 {
    if z <= 2.0 {
        let t = (z / 3.75).powi(2);
        let i0 = 1.0
            + t * (3.5156229
                + t * (3.0899424
                    + t * (1.2067492 + t * (0.2659732 + t * (0.0360768 + t * 0.0045813)))));
        let u = z * z / 4.0;
        let k0 = -(z / 2.0).ln() * i0 - 0.57721566
            + u * (0.42278420
                + u * (0.23069756
                    + u * (0.03488590 + u * (0.00262698 + u * (0.00010750 + u * 0.0000074)))));
        k0 * z.exp()
    } else {
        let v = 2.0 / z;
        (1.25331414
            + v * (-0.07832358
                + v * (0.02189568
                    + v * (-0.01062446 + v * (0.00587872 + v * (-0.00251540 + v * 0.00053208))))))
            / z.sqrt()
    }
}

/// θ(X) under the band, in units of qℓ/K: (1/π)∫₋₁¹ e^{L(X−X′)}K₀(L|X−X′|) dX′, each side of
/// X mapped by s = t² to remove the logarithmic singularity.
fn band_temperature(peclet: f64, x: f64, nodes: &[(f64, f64)]) -> f64 {
    // s = |X − X′| ≥ 0; ahead (X′ > X: sign −1) and behind (X′ < X: sign +1).
    let side = |length: f64, sign: f64| {
        let root = length.sqrt();
        nodes
            .iter()
            .map(|&(t, w)| {
                let t = 0.5 * root * (t + 1.0);
                let s = t * t;
                let z = peclet * s;
                let kernel = if z < 1e-300 {
                    0.0
                } else {
                    (sign * z - z).exp() * scaled_k0(z)
                };
                kernel * 2.0 * t * 0.5 * root * w
            })
            .sum::<f64>()
    };
    (side(x + 1.0, 1.0) + side(1.0 - x, -1.0)) / PI
}

/// Mean and maximum temperature of the moving source (`peclet` > 0).
pub fn temperatures(shape: Shape, peclet: f64) -> Temperatures {
    let nodes = gauss_legendre(24);
    match shape {
        Shape::Band => {
            let fine = gauss_legendre(48);
            let field = |x: f64| band_temperature(peclet, x, &fine);
            let mean = nodes.iter().map(|&(x, w)| w * field(x)).sum::<f64>() / 2.0;
            let max = maximum(&field, &nodes);
            Temperatures { mean, max }
        }
        Shape::Circle | Shape::Rectangle { .. } => {
            let directions: Vec<(f64, f64)> = (0..DIRECTIONS)
                .map(|k| {
                    let phi = 2.0 * PI * (k as f64 + 0.5) / DIRECTIONS as f64;
                    (phi.cos(), phi.sin())
                })
                .collect();
            let field = |x: f64, y: f64| point_temperature(shape, peclet, x, y, &directions);
            let mean = match shape {
                Shape::Circle => {
                    // Polar Gauss–Legendre in r (weight r) and φ over the unit disc.
                    let mut sum = 0.0;
                    for &(r, wr) in &nodes {
                        let r = 0.5 * (r + 1.0);
                        for &(p, wp) in &nodes {
                            let phi = PI * (p + 1.0);
                            sum += 0.5 * wr * PI * wp * r * field(r * phi.cos(), r * phi.sin());
                        }
                    }
                    sum / PI
                }
                Shape::Rectangle { half_length } => {
                    let mut sum = 0.0;
                    for &(x, wx) in &nodes {
                        for &(y, wy) in &nodes {
                            sum += wx * wy * field(x, y * half_length);
                        }
                    }
                    sum / 4.0
                }
                Shape::Band => unreachable!(),
            };
            // The hottest point lies on the centre line y = 0.
            let max = maximum(&|x| field(x, 0.0), &nodes);
            Temperatures { mean, max }
        }
    }
}

/// The largest value of `field` on [−1, 1]: the best Gauss node, refined by Brent's method on
/// the intervals either side of it.
fn maximum(field: &dyn Fn(f64) -> f64, nodes: &[(f64, f64)]) -> f64 {
    let (mut best_x, mut best) = (0.0, field(0.0));
    for &(x, _) in nodes {
        let v = field(x);
        if v > best {
            (best_x, best) = (x, v);
        }
    }
    let (_, minus) = brent_minimise(
        |x| -field(x),
        (best_x - 0.15).max(-1.0),
        (best_x + 0.15).min(1.0),
        1e-9,
    );
    best.max(-minus)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bessel_k0_matches_tabulated_values() {
        // Abramowitz & Stegun Table 9.8.
        for (z, k0) in [
            (0.1, 2.427_069_025),
            (1.0, 0.421_024_438),
            (2.0, 0.113_893_873),
            (5.0, 0.003_691_098),
        ] {
            let got = scaled_k0(z) * (-z).exp();
            assert!((got / k0 - 1.0).abs() < 1e-6, "K0({z}) = {got}, table {k0}");
        }
    }

    #[test]
    fn slow_limits_are_steady_conduction() {
        // Stachowiak Table 7.6: the square's slow mean 0.946 and maximum 1.122 (qb/K).
        let square = temperatures(Shape::Rectangle { half_length: 1.0 }, 1e-4);
        assert!(
            (square.mean / 0.946 - 1.0).abs() < 3e-3,
            "square mean {}",
            square.mean
        );
        assert!(
            (square.max / 1.122 - 1.0).abs() < 3e-3,
            "square max {}",
            square.max
        );
        // Uniform flux on a circle: the centre reaches qa/K exactly, the mean 8/(3π) qa/K
        // (Carslaw & Jaeger §10.5; Stachowiak's slow T̄ = 0.25Q/(Ka) is the isothermal disc's
        // 0.785 qa/K, 7.5 % below).
        let circle = temperatures(Shape::Circle, 1e-4);
        assert!((circle.max - 1.0).abs() < 2e-3, "circle max {}", circle.max);
        assert!(
            (circle.mean / (8.0 / (3.0 * PI)) - 1.0).abs() < 2e-3,
            "circle mean {}",
            circle.mean
        );
        // The band: (2/π)(1.616 − ln 2L) and (2/π)(1.116 − ln L) (Table 7.7).
        let l = 1e-3;
        let band = temperatures(Shape::Band, l);
        assert!(
            (band.mean / (2.0 / PI * (1.616 - (2.0 * l).ln())) - 1.0).abs() < 2e-3,
            "band mean {}",
            band.mean
        );
        assert!(
            (band.max / (2.0 / PI * (1.116 - l.ln())) - 1.0).abs() < 2e-3,
            "band max {}",
            band.max
        );
    }

    #[test]
    fn fast_limits_are_one_dimensional_conduction() {
        // Stachowiak Tables 7.5–7.7, fast forms in qℓ/K with χℓ/U = ℓ²/(2L): square and band
        // mean 1.064/√(2L), max 2/√(πL); circle mean 0.308·π/√(2L) (0.308 Q/(Ka)·(χ/(Ua))^½).
        let l = 200.0;
        for shape in [Shape::Rectangle { half_length: 1.0 }, Shape::Band] {
            let t = temperatures(shape, l);
            assert!(
                (t.mean / (1.064 / (2.0 * l).sqrt()) - 1.0).abs() < 0.03,
                "{shape:?} mean {}",
                t.mean
            );
            assert!(
                (t.max / (2.0 / (PI * l).sqrt()) - 1.0).abs() < 0.03,
                "{shape:?} max {}",
                t.max
            );
        }
        let circle = temperatures(Shape::Circle, l);
        assert!(
            (circle.mean / (0.308 * PI / (2.0 * l).sqrt()) - 1.0).abs() < 0.03,
            "circle mean {}",
            circle.mean
        );
    }

    #[test]
    fn temperatures_fall_with_peclet_across_the_intermediate_range() {
        for shape in [
            Shape::Circle,
            Shape::Rectangle { half_length: 1.0 },
            Shape::Band,
        ] {
            let mut last = f64::INFINITY;
            for l in [0.1, 0.3, 1.0, 2.0, 5.0] {
                let t = temperatures(shape, l);
                assert!(
                    t.mean.is_finite() && t.mean < last && t.max >= t.mean,
                    "{shape:?} L = {l}"
                );
                last = t.mean;
            }
        }
    }
}
