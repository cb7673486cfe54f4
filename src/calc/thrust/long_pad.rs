//! The infinitely long pad (no side leakage), exact for any [`Profile`] (Khonsari & Booser
//! §6.5–6.7, Eq. 6.52; Stachowiak & Batchelor §4.3).
//!
//! Integrated once, the Reynolds equation is dP̄/dx̄ = 6 (h̄ − h̄_m)/h̄³, and P̄ = 0 at both edges
//! fixes the film at the pressure peak, h̄_m = I₂/I₃ with I_n = ∫₀¹ h̄⁻ⁿ dx̄. By parts, every
//! performance number is then a single integral of a power of h̄:
//!
//! ```text
//! W̄ = ∫P̄ dx̄ = −6 (J₂ − h̄_m J₃),   W̄ x̄_cp = ∫x̄ P̄ dx̄ = −3 (K₂ − h̄_m K₃),
//! F̄ = ∫(1/h̄ + (h̄/2) dP̄/dx̄) dx̄ = 4 I₁ − 3 h̄_m I₂,   Q̄ = h̄_m / 2,
//! ```
//!
//! with J_n = ∫x̄ h̄⁻ⁿ, K_n = ∫x̄² h̄⁻ⁿ; W̄ = W h2²/(μ U B² L), F̄ = F h2/(μ U B L) (the force on
//! the runner), Q̄ = Q/(U L h2). The integrals are Gauss–Legendre sums on the profile's smooth
//! pieces, cut where h̄ changes by a quarter, so they are exact to round-off (the integrands are
//! analytic there, their poles at h̄ = 0 well off each piece).
//!
//! A turbulent film (Ng–Pan, [`Flow`]) scales the Poiseuille flow by g(h̄) = 12 G_x(Re₂ h̄) and
//! the Couette shear by G_f(Re₂ h̄): then dP̄/dx̄ = 6 (h̄ − h̄_m)/(g h̄³), and the same integrals
//! carry the weight 1/g (I_n = ∫ h̄⁻ⁿ/g, and so on), F̄ = ∫ G_f/h̄ + 3 ∫ (h̄⁻¹ − h̄_m h̄⁻²)/g. A
//! laminar film has g = G_f = 1 exactly, so its numbers are the laminar ones bit for bit.

use std::sync::OnceLock;

use super::coefficients::Performance;
use super::profile::Profile;
use crate::calc::turbulence::Flow;
use crate::numerics::quadrature::gauss_legendre;

/// Gauss–Legendre points per sub-piece.
const POINTS: usize = 24;
/// Largest ratio of h̄ across a sub-piece.
const PIECE_RATIO: f64 = 1.25;
/// The Gauss–Legendre rule, computed once.
static RULE: OnceLock<Vec<(f64, f64)>> = OnceLock::new();

/// ∫ f(x̄, h̄(x̄)) dx̄ over [a, b] (inside one smooth piece), for N integrands at once.
fn integrate<const N: usize>(
    profile: Profile,
    a: f64,
    b: f64,
    f: impl Fn(f64, f64) -> [f64; N],
) -> [f64; N] {
    let mut sum = [0.0; N];
    if b <= a {
        return sum;
    }
    // The profiles are monotone on each piece (the end values bound h̄ there) but for a
    // crown, whose thinnest film may lie inside.
    let (h0, h1) = (profile.thickness(a), profile.thickness(b - 1e-15 * (b - a)));
    let thin = match profile {
        Profile::Crowned { .. } => h0.min(h1).min(profile.minimum()),
        _ => h0.min(h1),
    };
    let thick = h0.max(h1);
    let spread = (thick / thin).ln();
    let cuts = ((spread / PIECE_RATIO.ln()).ceil() as usize).max(1);
    let rule = RULE.get_or_init(|| gauss_legendre(POINTS));
    let width = (b - a) / cuts as f64;
    for c in 0..cuts {
        let mid = a + (c as f64 + 0.5) * width;
        for &(t, w) in rule {
            let x = mid + 0.5 * width * t;
            let values = f(x, profile.thickness(x));
            for (s, v) in sum.iter_mut().zip(values) {
                *s += 0.5 * width * w * v;
            }
        }
    }
    sum
}

/// ∫ f over [a, b] ∩ the pad, piece by piece.
fn integrate_pad<const N: usize>(
    profile: Profile,
    a: f64,
    b: f64,
    f: impl Fn(f64, f64) -> [f64; N] + Copy,
) -> [f64; N] {
    let mut sum = [0.0; N];
    for (x0, x1) in profile.pieces() {
        let part = integrate(profile, x0.max(a), x1.min(b), f);
        for (s, v) in sum.iter_mut().zip(part) {
            *s += v;
        }
    }
    sum
}

/// Where h̄ first falls to `h` (the profiles do not rise towards the trailing edge): the pressure
/// peak when `h` is h̄_m.
fn position_of(profile: Profile, h: f64) -> f64 {
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    for _ in 0..64 {
        let mid = 0.5 * (lo + hi);
        if profile.thickness(mid) > h {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// ∫₀¹ G_f dx̄/h̄: the Couette part of the runner's friction F̄, the same for a pad of any
/// length (G_f = 1 when laminar).
pub fn couette_shear(profile: Profile, flow: Flow) -> f64 {
    let [i1] = integrate_pad(profile, 0.0, 1.0, |_, h| [flow.shear_factor(h) / h]);
    i1
}

/// ∫₀¹ h̄ dx̄: the mean film over h2.
pub fn mean_thickness(profile: Profile) -> f64 {
    let [mean] = integrate_pad(profile, 0.0, 1.0, |_, h| [h]);
    mean
}

/// The laminar, infinitely long plane pad's centre of pressure from the leading edge at the
/// film ratio a = h1/h2 above 1 (Khonsari & Booser Table 6.2):
/// x̄_cp = ½[2a/(a − 1) − (a² − 1 − 2a ln a)/((a² − 1) ln a − 2(a − 1)²)]. The pivot's root
/// needs only this; [`performance`]'s quadrature gives the same to about 1e-9 (the closed form
/// cancels as a → 1).
pub fn plane_center_of_pressure(a: f64) -> f64 {
    let ln = a.ln();
    0.5 * (2.0 * a / (a - 1.0)
        - (a * a - 1.0 - 2.0 * a * ln) / ((a * a - 1.0) * ln - 2.0 * (a - 1.0).powi(2)))
}

/// The infinitely long pad's performance, laminar or turbulent. A full film (P̄ = 0 at both
/// edges): not for a [`Profile::Crowned`] pad, whose diverging part cavitates (the rooms solve
/// crowned pads numerically only).
pub fn performance(profile: Profile, flow: Flow) -> Performance {
    // 1/g: the Poiseuille weight of a turbulent film (exactly 1 when laminar).
    let weight = |h: f64| 1.0 / flow.pressure_factors(h).0;
    let [i1, i2, i3, j2, j3, k2, k3] = integrate_pad(profile, 0.0, 1.0, |x, h| {
        let w = weight(h);
        let (r1, r2, r3) = (w / h, w / (h * h), w / (h * h * h));
        [r1, r2, r3, x * r2, x * r3, x * x * r2, x * x * r3]
    });
    let hm = i2 / i3;
    let load = -6.0 * (j2 - hm * j3);
    let first_moment = -3.0 * (k2 - hm * k3);
    let peak = position_of(profile, hm);
    let [rise] = integrate_pad(profile, 0.0, peak, |_, h| {
        [weight(h) * (h - hm) / (h * h * h)]
    });
    // ∫ G_f/h̄ − ∫ 1/(g h̄): zero when laminar, so F̄ is then 4 I₁ − 3 h̄_m I₂ bit for bit.
    let turbulent_shear = match flow {
        Flow::Laminar => 0.0,
        Flow::Turbulent { .. } => couette_shear(profile, flow) - i1,
    };
    Performance {
        load,
        friction: 4.0 * i1 - 3.0 * hm * i2 + turbulent_shear,
        center_of_pressure: first_moment / load,
        max_pressure: 6.0 * rise,
        max_pressure_position: peak,
        inlet_flow: 0.5 * hm,
        side_flow: 0.0,
        outlet_flow: 0.5 * hm,
    }
}

#[cfg(test)]
mod tests;
