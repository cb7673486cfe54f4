//! A fixed pad's dimensionless performance, by the infinitely long pad's closed form or by the
//! numerical film with Richardson's extrapolation, in Khonsari & Booser Table 7.2's scaling
//! (every number per unit h2, the trailing-edge film).

pub use super::coefficients::Performance;
use super::film::{self, Mesh};
use super::long_pad;
use super::profile::{Profile, FLAT_LAND_EQUIVALENT_RATIO};
use crate::calc::turbulence::Flow;
use crate::calc::Budget;
use crate::fidelity::{Level, SolverReport};
use crate::numerics::optimise::brent_minimise;
use crate::numerics::reynolds::SolveError;
use crate::numerics::richardson::fine_error;

/// How the performance is computed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Method {
    /// The infinitely long pad (no side leakage), whatever L.
    LongPad,
    /// The finite pad's film on `mesh`; with `richardson` also on its half mesh, extrapolated.
    Numerical {
        level: Level,
        mesh: Mesh,
        richardson: bool,
    },
}

impl Method {
    /// The mesh of a level: cells along B and across half of L (each extrapolated from half
    /// as many; docs/accuracy.md has the errors and times).
    pub fn level(level: Level) -> Method {
        let (along, across_half) = match level {
            Level::ClosedForm => return Method::LongPad,
            Level::Fast => (32, 8),
            Level::Standard => (64, 16),
            Level::High => (128, 32),
        };
        Method::Numerical {
            level,
            mesh: Mesh { along, across_half },
            richardson: true,
        }
    }

    /// An explicit mesh: extrapolated when it halves exactly (even counts, at least 8 × 4).
    pub fn mesh(mesh: Mesh) -> Method {
        Method::Numerical {
            level: Level::Standard,
            mesh,
            richardson: mesh.along.is_multiple_of(2)
                && mesh.across_half.is_multiple_of(2)
                && mesh.along >= 8
                && mesh.across_half >= 4,
        }
    }
}

/// A performance and what it cost.
#[derive(Debug, Clone)]
pub struct Evaluated {
    pub performance: Performance,
    /// Estimated relative error of W̄ (Richardson: a third of the two meshes' difference).
    pub error_estimate: Option<f64>,
    /// The fine solve's report (closed form: none).
    pub report: SolverReport,
    /// (x̄, P̄) along the mid-plane of the fine solve; the closed form gives none.
    pub mid_plane: Option<Vec<(f64, f64)>>,
}

/// The performance of `profile` in a `flow` on a pad of aspect L/B = `l_over_b` by `method`.
/// A flat land's is the texts' empirical rule on the equivalent plane pad's (Eq. 7.14; see
/// [`Profile::FlatLand`]): W̄ and the pressures scale with the multiplier squared (h2 ∝ K_h
/// at a given load), K_f = 1 (Couette shear over parallel faces), K_q = 0.5 in and out (the
/// Couette flow; no side leakage).
pub fn evaluate(
    profile: Profile,
    flow: Flow,
    l_over_b: f64,
    method: Method,
    budget: &Budget,
) -> Result<Evaluated, SolveError> {
    if let Profile::FlatLand { multiplier } = profile {
        let plane = Profile::PlaneInclined {
            ratio: FLAT_LAND_EQUIVALENT_RATIO,
        };
        let mut e = evaluate(plane, flow, l_over_b, method, budget)?;
        let scale = multiplier * multiplier;
        let p = &mut e.performance;
        p.load *= scale;
        p.max_pressure *= scale;
        p.friction = 1.0;
        p.inlet_flow = 0.5;
        p.side_flow = 0.0;
        p.outlet_flow = 0.5;
        if let Some(mid) = e.mid_plane.as_mut() {
            for (_, pressure) in mid.iter_mut() {
                *pressure *= scale;
            }
        }
        e.report = e.report.named("flat_land_empirical_on_plane_pad");
        return Ok(e);
    }
    match method {
        Method::LongPad => Ok(Evaluated {
            performance: long_pad::performance(profile, flow),
            error_estimate: None,
            report: SolverReport::closed_form("infinitely_long_pad"),
            mid_plane: None,
        }),
        Method::Numerical {
            level,
            mesh,
            richardson,
        } => {
            let fine = film::solve(profile, flow, l_over_b, mesh, richardson, budget)?;
            let grid = vec![mesh.along as u32, mesh.across_half as u32];
            let mut report = fine.solved.report.clone().at(level).on_grid(grid);
            let (performance, error_estimate) = if richardson {
                let coarse = film::solve(profile, flow, l_over_b, mesh.coarse(), false, budget)?;
                report.iterations += coarse.solved.report.iterations;
                let best = fine.performance.extrapolated(&coarse.performance);
                let error = fine_error(coarse.performance.load, fine.performance.load).abs()
                    / best.load.abs().max(f64::MIN_POSITIVE);
                (best, Some(error))
            } else {
                (fine.performance, None)
            };
            Ok(Evaluated {
                performance,
                error_estimate,
                report: report.with_error_estimate(error_estimate),
                mid_plane: Some(fine.mid_plane),
            })
        }
    }
}

/// Film ratios a pad may have (the range Table 7.2 spans, from nearly parallel to 10).
pub const RATIOS: (f64, f64) = (1.01, 10.0);

/// The film ratio h1/h2 that maximises W̄ for this shape (its other proportions kept) in a
/// `flow`, found by
/// Brent's minimisation on −W̄ over [`RATIOS`] to 1e-6: the ratio and the number of
/// evaluations. A solve that fails stops the search with its error.
pub fn optimum_ratio(
    profile: Profile,
    flow: Flow,
    l_over_b: f64,
    method: Method,
    budget: &Budget,
) -> Result<(f64, u32), SolveError> {
    let mut failure = None;
    let mut evaluations = 0;
    let (ratio, _) = brent_minimise(
        |a| {
            evaluations += 1;
            if failure.is_some() {
                return 0.0;
            }
            match evaluate(profile.with_ratio(a), flow, l_over_b, method, budget) {
                Ok(e) => -e.performance.load,
                Err(e) => {
                    failure = Some(e);
                    0.0
                }
            }
        },
        RATIOS.0,
        RATIOS.1,
        1e-6,
    );
    match failure {
        Some(e) => Err(e),
        None => Ok((ratio, evaluations)),
    }
}
