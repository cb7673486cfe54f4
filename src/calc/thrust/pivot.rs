//! A pivoted plane pad in equilibrium: it tilts until the film's centre of pressure lies on the
//! pivot, so the pivot fixes the film ratio a = h1/h2 through x̄_cp(a) = x̄_p (Khonsari & Booser
//! §7.5; Stachowiak & Batchelor §4.3, Table 4.2), and the load then fixes h2 as for a fixed pad.
//!
//! x̄_cp rises monotonically from ½ (a → 1: the pressure of a nearly parallel film is symmetric
//! about mid-pad, whatever L/B) towards the trailing edge, so a bracketed root on
//! x̄_cp(a) − x̄_p over [`PIVOT_RATIOS`] finds the one equilibrium. A pivot at or ahead of
//! mid-pad has none: an isoviscous flat pad pivoted there carries no load (real centrally
//! pivoted pads run on thermal and elastic crowning).
//!
//! A crowned pad ([`Profile::Crowned`], the crown fixed relative to h2 here) is found the same
//! way: its converging-diverging film puts the centre of pressure ahead of mid-pad as the edges
//! become parallel, so a central pivot has an equilibrium; [`super::pad`] nests this root in
//! the load balance, where the crown's ratio to h2 changes with the film. A crown above about
//! the trailing-edge film also pinches the film near the ratio at which it touches, which throws
//! the centre of pressure back: x̄_cp then falls and rises with a, and the equilibrium taken is
//! the main branch's, on the rising side of x̄_cp's minimum.

use std::cell::Cell;

use super::long_pad;
use super::performance::{evaluate, optimum_ratio, Evaluated, Method};
use super::profile::Profile;
use crate::calc::turbulence::Flow;
use crate::calc::{Budget, CalcError};
use crate::numerics::optimise::brent_minimise;
use crate::numerics::roots::{brent_bracketed, Stopping};

/// The film ratios a pivoted pad may settle at: those of a fixed pad.
pub const PIVOT_RATIOS: (f64, f64) = super::performance::RATIOS;

/// Where the pivot is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Pivot {
    /// x̄_p, a fraction of B from the leading edge.
    At(f64),
    /// Where the centre of pressure lies at the load-maximising film ratio.
    Optimum,
}

/// The pad in equilibrium.
#[derive(Debug, Clone)]
pub struct Equilibrium {
    pub ratio: f64,
    pub pivot: f64,
    pub evaluated: Evaluated,
    /// da/dx̄_p: how far the film ratio moves per unit of pivot position.
    pub ratio_per_pivot: f64,
    /// (dW̄/da)/W̄ at the equilibrium.
    pub load_slope: f64,
    /// Film solves (or closed-form evaluations) of the search.
    pub evaluations: u32,
}

/// The lowest film ratio a crowned pad of crown ratio k = δ/h2 is searched from: parallel
/// edges, or — for k > ¼, where the parallel film would touch — just above the ratio
/// (2√k − 1)² at which the film h̄ = a − (a − 1) x̄ − 4 k x̄(1 − x̄) first touches the runner
/// (its minimum over x̄ is zero there), so the film is positive over the whole bracket.
fn crowned_ratio_floor(k: f64) -> f64 {
    let touching = if k > 0.25 {
        (2.0 * k.sqrt() - 1.0).powi(2)
    } else {
        0.0
    };
    (touching * (1.0 + 1e-3)).max(1.0)
}

/// The equilibrium of a pad of shape `pad` (plane or crowned; its film ratio is the unknown)
/// and aspect `l_over_b` pivoted at `pivot`, in a `flow`.
pub fn equilibrium(
    pivot: Pivot,
    pad: Profile,
    flow: Flow,
    l_over_b: f64,
    method: Method,
    budget: &Budget,
) -> Result<Equilibrium, CalcError> {
    let plane = |a: f64| pad.with_ratio(a);
    let evaluations = Cell::new(0);
    let at = |a: f64| -> Result<Evaluated, CalcError> {
        evaluations.set(evaluations.get() + 1);
        Ok(evaluate(plane(a), flow, l_over_b, method, budget)?)
    };
    // The laminar closed form's root needs only x̄_cp(a), which the plane pad has in closed form.
    let center = |a: f64| -> Result<f64, CalcError> {
        match (method, pad, flow) {
            (Method::LongPad, Profile::PlaneInclined { .. }, Flow::Laminar) => {
                evaluations.set(evaluations.get() + 1);
                Ok(long_pad::plane_center_of_pressure(a))
            }
            _ => Ok(at(a)?.performance.center_of_pressure),
        }
    };
    let (ratio, pivot) = match pivot {
        Pivot::Optimum => {
            let (ratio, n) = optimum_ratio(plane(2.0), flow, l_over_b, method, budget)?;
            evaluations.set(evaluations.get() + n);
            (ratio, at(ratio)?.performance.center_of_pressure)
        }
        Pivot::At(x_p) => {
            // A crowned pad may settle with parallel edges (its crown still converges the
            // film), and a lightly crowned one near them.
            let (lo, hi) = match pad {
                Profile::Crowned { crown, .. } => (crowned_ratio_floor(crown), PIVOT_RATIOS.1),
                _ => PIVOT_RATIOS,
            };
            let (mut lo, x_hi) = (lo, center(hi)?);
            let mut x_lo = center(lo)?;
            if x_p <= x_lo && matches!(pad, Profile::PlaneInclined { .. }) {
                return Err(CalcError::impossible(
                    "/pivot_position_fraction",
                    format!("a flat pad pivoted at {x_p} of B carries no useful load in the isoviscous film: its centre of pressure lies behind {x_lo:.4} of B for every film ratio above {lo} (and at mid-pad as the film becomes parallel), so a central or leading-side pivot has no equilibrium; real centrally pivoted pads run on thermal and elastic crowning (Khonsari & Booser §7.5): move the pivot towards the trailing edge (0.58 maximises the load)"),
                ));
            }
            if x_p <= x_lo {
                // A crown higher than about the trailing-edge film pinches the film near the
                // touching ratio, which throws the centre of pressure back again: x̄_cp falls,
                // then rises with a. The main branch (the one that continues the lightly crowned
                // pad's) is the rising side, right of x̄_cp's minimum.
                let (a_min, x_min) = lowest_center_of_pressure(lo, hi, &at)?;
                if x_p <= x_min {
                    return Err(CalcError::impossible(
                        "/pivot_position_fraction",
                        format!("a pivot at {x_p} of B has no equilibrium on this crowned pad: its centre of pressure lies behind {x_min:.4} of B for every film ratio above {lo} (the crown, {:.4} of the trailing-edge film, is past the fold where the equilibrium branch ends)", pad_crown(pad)),
                    ));
                }
                (lo, x_lo) = (a_min, x_min);
            }
            if x_p >= x_hi {
                return Err(CalcError::impossible(
                    "/pivot_position_fraction",
                    format!("a pivot at {x_p} of B needs a film ratio above {hi}: the centre of pressure reaches only {x_hi:.4} of B there"),
                ));
            }
            let mut failure = None;
            let root = brent_bracketed(
                |a| match center(a) {
                    Ok(x) => x - x_p,
                    Err(e) => {
                        failure = Some(e);
                        0.0
                    }
                },
                (lo, x_lo - x_p),
                (hi, x_hi - x_p),
                Stopping {
                    x_tolerance: 1e-9,
                    max_iterations: 100,
                },
            );
            if let Some(e) = failure {
                return Err(e);
            }
            let root = root.map_err(|e| CalcError::from_root("pivot_equilibrium", e))?;
            (root.x, x_p)
        }
    };
    let mut settled = settled(pad.with_ratio(ratio), pivot, flow, l_over_b, method, budget)?;
    settled.evaluations += evaluations.get();
    Ok(settled)
}

/// The film ratio over [lo, hi] at which the centre of pressure lies furthest forward, and that
/// position: Brent's minimisation to 1e-6 in a, errors of the solves kept.
fn lowest_center_of_pressure(
    lo: f64,
    hi: f64,
    at: &impl Fn(f64) -> Result<Evaluated, CalcError>,
) -> Result<(f64, f64), CalcError> {
    let mut failure = None;
    let (a, x) = brent_minimise(
        |a| match at(a) {
            Ok(e) => e.performance.center_of_pressure,
            Err(e) => {
                failure.get_or_insert(e);
                1.0
            }
        },
        lo,
        hi,
        1e-6,
    );
    match failure {
        Some(e) => Err(e),
        None => Ok((a, x)),
    }
}

/// The crown ratio k = δ/h2 of a crowned pad (0 for another shape).
fn pad_crown(pad: Profile) -> f64 {
    match pad {
        Profile::Crowned { crown, .. } => crown,
        _ => 0.0,
    }
}

/// The pad `pad` at its equilibrium film ratio about `pivot`, with the sensitivities by central
/// differences of the same method (three evaluations, counted).
pub fn settled(
    pad: Profile,
    pivot: f64,
    flow: Flow,
    l_over_b: f64,
    method: Method,
    budget: &Budget,
) -> Result<Equilibrium, CalcError> {
    let ratio = pad.ratio();
    let at = |a: f64| evaluate(pad.with_ratio(a), flow, l_over_b, method, budget);
    let step = 1e-4 * ratio;
    let (below, above) = (at(ratio - step)?, at(ratio + step)?);
    let evaluated = at(ratio)?;
    let dx = (above.performance.center_of_pressure - below.performance.center_of_pressure)
        / (2.0 * step);
    let dw = (above.performance.load - below.performance.load) / (2.0 * step);
    Ok(Equilibrium {
        ratio,
        pivot,
        load_slope: dw / evaluated.performance.load,
        ratio_per_pivot: 1.0 / dx,
        evaluated,
        evaluations: 3,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::calc::thrust::long_pad;
    use crate::fidelity::Level;

    #[test]
    fn the_long_pad_pivot_reproduces_stachowiak_table_4_2() {
        // Table 4.2 read backwards: a pivot at X/B from the trailing edge settles at
        // K = h1/h0 − 1 (K = 1.0 at X/B = 0.431, K = 3.0 at 0.366; 3 decimals printed, so the
        // ratio is within the slope's share of half a unit).
        for (k, from_trailing) in [(1.0, 0.431), (2.0, 0.393), (3.0, 0.366)] {
            let got = equilibrium(
                Pivot::At(1.0 - from_trailing),
                Profile::PlaneInclined { ratio: 2.0 },
                Flow::Laminar,
                1.0,
                Method::LongPad,
                &Budget::unlimited(),
            )
            .unwrap();
            let slack = 0.0005 * got.ratio_per_pivot.abs() + 1e-9;
            assert!(
                (got.ratio - 1.0 - k).abs() <= slack,
                "K {k}: got {}",
                got.ratio - 1.0
            );
            // The equilibrium is a root of the moment about the pivot: x̄_cp on the pivot.
            assert!((got.evaluated.performance.center_of_pressure - got.pivot).abs() < 1e-9);
        }
    }

    #[test]
    fn the_optimum_pivot_of_the_long_pad_is_at_its_optimum_ratio() {
        let got = equilibrium(
            Pivot::Optimum,
            Profile::PlaneInclined { ratio: 2.0 },
            Flow::Laminar,
            1.0,
            Method::LongPad,
            &Budget::unlimited(),
        )
        .unwrap();
        assert!((got.ratio - 2.189).abs() < 5e-3);
        let x_cp =
            long_pad::performance(Profile::PlaneInclined { ratio: got.ratio }, Flow::Laminar)
                .center_of_pressure;
        assert!((got.pivot - x_cp).abs() < 1e-12);
        // At the maximum the load no longer changes with the ratio.
        assert!(got.load_slope.abs() < 1e-3, "{}", got.load_slope);
    }

    #[test]
    fn a_central_pivot_is_refused_with_the_reason() {
        for method in [Method::LongPad, Method::level(Level::Fast)] {
            let err = equilibrium(
                Pivot::At(0.5),
                Profile::PlaneInclined { ratio: 2.0 },
                Flow::Laminar,
                1.0,
                method,
                &Budget::unlimited(),
            )
            .unwrap_err();
            match err {
                CalcError::Impossible { pointer, message } => {
                    assert_eq!(pointer, "/pivot_position_fraction");
                    assert!(message.contains("carries no useful load"), "{message}");
                }
                other => panic!("{other:?}"),
            }
        }
    }

    #[test]
    fn square_pad_with_a_65_percent_pivot_is_near_table_7_4() {
        // Khonsari & Booser §7.5, Table 7.4: a 65 % offset pivot on a square pad is designed
        // with h1/h2 ≈ 5, K_h 0.23, K_f 0.51, K_q 1.66 — rounded rules that the isoviscous
        // equilibrium meets within 10 % in K_h and K_f (it settles at h1/h2 = 3.7: a stiffer
        // ratio than the rule, whose pads also run on thermal crowning).
        let got = equilibrium(
            Pivot::At(0.65),
            Profile::PlaneInclined { ratio: 2.0 },
            Flow::Laminar,
            1.0,
            Method::level(Level::Standard),
            &Budget::unlimited(),
        )
        .unwrap();
        let p = got.evaluated.performance;
        assert!((3.5..5.0).contains(&got.ratio), "ratio {}", got.ratio);
        assert!((p.k_h() / 0.23 - 1.0).abs() < 0.1, "K_h {}", p.k_h());
        assert!((p.friction / 0.51 - 1.0).abs() < 0.12, "K_f {}", p.friction);
        assert!((p.center_of_pressure - 0.65).abs() < 1e-8);
        assert!(got.ratio_per_pivot > 0.0);
    }

    #[test]
    fn the_equilibrium_converges_with_the_grid() {
        // Each level's film ratio within its neighbour's reach: the fast and standard answers
        // differ from high by less than a percent.
        let at = |level| {
            equilibrium(
                Pivot::At(0.6),
                Profile::PlaneInclined { ratio: 2.0 },
                Flow::Laminar,
                0.5,
                Method::level(level),
                &Budget::unlimited(),
            )
            .unwrap()
            .ratio
        };
        let high = at(Level::High);
        for level in [Level::Fast, Level::Standard] {
            assert!((at(level) / high - 1.0).abs() < 0.01, "{level:?}");
        }
    }
}
