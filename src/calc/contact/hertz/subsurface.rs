//! Subsurface stresses under the centre of a Hertz contact: the exact principal stresses on the
//! axis below an ellipse (Boussinesq potentials in closed form) and below a line (McEwen), and
//! their maxima in depth for the principal shear and the von Mises stress in each body.

use crate::numerics::elliptic::carlson_rd;
use crate::numerics::optimise::brent_minimise;

/// Principal stresses on the z-axis under the Hertz pressure p = p₀√(1 − x²/a² − y²/b²),
/// over p₀, at ζ = z/b, for κ = a/b ≥ 1: [σ along a, σ along b, σ_z] (compression negative;
/// no shear on the axis, by symmetry).
///
/// From the Boussinesq potentials ψ = ∬p ln(ρ + z), φ = ∂ψ/∂z = ∬p/ρ (Johnson eq. 3.20):
/// σ_i = (1/2π)[2ν φ_z − z φ_ii − (1 − 2ν) ψ_ii], σ_z = (1/2π)[φ_z − z φ_zz]. For the Hertz
/// pressure φ = (πp₀ab/2)∫_λ^∞ [1 − x²/(a²+w) − y²/(b²+w) − z²/w] dw/Δ(w),
/// Δ² = (a²+w)(b²+w)w, λ = z² on the axis (Johnson §3.6), so that on the axis
/// φ_xx = −πp₀ab I_a, I_a = ∫_λ^∞ dw/((a²+w)Δ) = (2/3)R_D(λ, b²+λ, a²+λ), and by integrating
/// φ_xx in z, ψ_xx = πp₀ab (J_a − z I_a), J_a = ∫_λ^∞ dw/((a²+w)^{3/2}(b²+w)^{1/2})
/// = 2/(A + √(AB)), A = a²+λ, B = b²+λ (likewise with a ↔ b). Harmonicity gives
/// z I₀ = 2/√(AB) − z(I_a + I_b) for the φ_z term and σ_z = −p₀ab/√(AB). Checked against
/// the axisymmetric closed form (κ = 1), McEwen's line contact (κ → ∞) and the exact centre
/// values σ_i(0) = −p₀[2ν + (1 − 2ν) b_i/(a + b)] in the tests.
pub(crate) fn ellipse_axis_stresses(kappa: f64, zeta: f64, nu: f64) -> [f64; 3] {
    let lambda = zeta * zeta;
    let big_a = kappa * kappa + lambda;
    let big_b = 1.0 + lambda;
    let root = (big_a * big_b).sqrt();
    let i_a = 2.0 / 3.0 * carlson_rd(lambda, big_b, big_a);
    let i_b = 2.0 / 3.0 * carlson_rd(lambda, big_a, big_b);
    let j_a = 2.0 / (big_a + root);
    let j_b = 2.0 / (big_b + root);
    let z_i0 = 2.0 / root - zeta * (i_a + i_b);
    let half_ab = 0.5 * kappa;
    let along = |i: f64, j: f64| {
        half_ab * (-2.0 * nu * z_i0 + zeta * i - (1.0 - 2.0 * nu) * (j - zeta * i))
    };
    [along(i_a, j_a), along(i_b, j_b), -kappa / root]
}

/// Principal stresses on the axis below a line contact over p₀ at ζ = z/b (plane strain,
/// McEwen 1949; Johnson eq. 4.49): [σ_y = ν(σ_x + σ_z) along the axes, σ_x across,
/// σ_z = −1/√(1 + ζ²)], σ_x = −[(1 + 2ζ²)/√(1 + ζ²) − 2ζ].
pub(crate) fn line_axis_stresses(zeta: f64, nu: f64) -> [f64; 3] {
    let s = (1.0 + zeta * zeta).sqrt();
    let sigma_x = -((1.0 + 2.0 * zeta * zeta) / s - 2.0 * zeta);
    let sigma_z = -1.0 / s;
    [nu * (sigma_x + sigma_z), sigma_x, sigma_z]
}

fn principal_shear(s: [f64; 3]) -> f64 {
    let max = s[0].max(s[1]).max(s[2]);
    let min = s[0].min(s[1]).min(s[2]);
    0.5 * (max - min)
}

fn von_mises(s: [f64; 3]) -> f64 {
    (0.5 * ((s[0] - s[1]).powi(2) + (s[1] - s[2]).powi(2) + (s[2] - s[0]).powi(2))).sqrt()
}

/// The subsurface maxima on the axis below the centre.
#[derive(Debug, Clone, PartialEq)]
pub struct Subsurface {
    /// (stress Pa, depth m) of the largest principal shear τ₁ over both bodies.
    pub shear: (f64, f64),
    /// (stress Pa, depth m) of the largest von Mises stress over both bodies.
    pub von_mises: (f64, f64),
    /// The maxima in each body (they differ when the Poisson's ratios do).
    pub per_body: Vec<BodyStresses>,
}

/// Subsurface maxima under the centre in one body.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyStresses {
    /// Which body: 1 or 2.
    pub body: u8,
    /// Its Poisson's ratio ν.
    pub poisson_ratio: f64,
    /// Largest principal shear stress τ₁ = (σ₁ − σ₃)/2 on the axis, Pa, and its depth, m.
    pub max_shear_stress_pa: f64,
    pub max_shear_depth_m: f64,
    /// Largest von Mises stress on the axis, Pa, and its depth, m.
    pub max_von_mises_pa: f64,
    pub max_von_mises_depth_m: f64,
}

/// The maxima of τ₁ and von Mises along the axis in each body (of Poisson's ratios ν₁, ν₂), scaled by p_max and the depth
/// scale b (the semi-minor axis or the half-width). Bodies of equal ν share one search.
pub(super) fn subsurface(
    poisson_ratios: [f64; 2],
    p_max: f64,
    b: f64,
    stresses: impl Fn(f64, f64) -> [f64; 3],
) -> Subsurface {
    let mut searched: Vec<(f64, [(f64, f64); 2])> = Vec::with_capacity(2);
    let per_body: Vec<BodyStresses> = poisson_ratios
        .iter()
        .zip(1u8..)
        .map(|(&nu, index)| {
            let maxima = match searched.iter().find(|(n, _)| *n == nu) {
                Some((_, m)) => *m,
                None => {
                    let m = maximise_in_depth(|z| {
                        let s = stresses(z, nu);
                        [principal_shear(s), von_mises(s)]
                    });
                    searched.push((nu, m));
                    m
                }
            };
            let [(tau, tau_depth), (vm, vm_depth)] = maxima;
            BodyStresses {
                body: index,
                poisson_ratio: nu,
                max_shear_stress_pa: tau * p_max,
                max_shear_depth_m: tau_depth * b,
                max_von_mises_pa: vm * p_max,
                max_von_mises_depth_m: vm_depth * b,
            }
        })
        .collect();
    let pick = |f: fn(&BodyStresses) -> (f64, f64)| {
        per_body.iter().map(f).fold(
            (f64::NEG_INFINITY, 0.0),
            |m, s| if s.0 > m.0 { s } else { m },
        )
    };
    Subsurface {
        shear: pick(|s| (s.max_shear_stress_pa, s.max_shear_depth_m)),
        von_mises: pick(|s| (s.max_von_mises_pa, s.max_von_mises_depth_m)),
        per_body,
    }
}

/// The maxima of the two components of f over ζ ∈ [0, 4] (depths in units of b; every Hertz
/// maximum lies within 0.8b for −1 < ν ≤ 0.5, or at the surface): one scan on 16 intervals
/// shared by both, then Brent's minimiser on −f over the two intervals around each best node to
/// 10⁻⁷ in ζ. Returns (maximum, depth) per component.
fn maximise_in_depth(f: impl Fn(f64) -> [f64; 2]) -> [(f64, f64); 2] {
    const DEPTH: f64 = 4.0;
    const SCAN: usize = 16;
    let h = DEPTH / SCAN as f64;
    let first = f(0.0);
    let mut best = [(0usize, first[0]), (0usize, first[1])];
    for i in 1..=SCAN {
        let v = f(i as f64 * h);
        for k in 0..2 {
            if v[k] > best[k].1 {
                best[k] = (i, v[k]);
            }
        }
    }
    let refine = |k: usize| -> (f64, f64) {
        let (best_i, best_v) = best[k];
        let lo = best_i.saturating_sub(1) as f64 * h;
        let hi = (best_i + 1).min(SCAN) as f64 * h;
        let (x, minus) = brent_minimise(|z| -f(z)[k], lo, hi, 1e-7);
        if -minus >= best_v {
            (-minus, x)
        } else {
            (best_v, best_i as f64 * h)
        }
    };
    [refine(0), refine(1)]
}
