//! Grid refinement with an error estimate: solve on a grid, then on a finer one started from
//! the coarser solution, judge the pair (Richardson's estimate of the finer grid's error for a
//! second-order scheme: see [`super::richardson`]), and refine again while the estimate exceeds
//! the tolerance and a finer grid is allowed. A refinement that fails falls back to the last
//! pair that resolved the result, saying so.
//!
//! The grids are the caller's (`L`: a cell count, a mesh); `finer` gives the next one, or `None`
//! beyond the finest the fidelity allows.

/// Two successive grids' solutions; `fine` was started from `coarse`.
#[derive(Debug, Clone, PartialEq)]
pub struct Pair<L, S> {
    pub coarse: S,
    pub fine: S,
    /// The fine solution's grid.
    pub grid: L,
}

/// What the caller's judgement says of a pair.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Judgement {
    /// The pair resolves the result, with this estimated relative error of the fine solution.
    Resolved(f64),
    /// The pair does not resolve it (a film that closes on the coarser grid, say): refine.
    Unresolved,
}

/// How refinement ended with a result.
#[derive(Debug, Clone, PartialEq)]
pub enum Refined<L, S, E> {
    /// The estimate is within the tolerance.
    Converged { pair: Pair<L, S>, error: f64 },
    /// The finest grid allowed is resolved but its estimate exceeds the tolerance.
    GridLimited { pair: Pair<L, S>, error: f64 },
    /// Solving on `failed_grid` failed with `failure`; the pair is the last one resolved.
    FellBack {
        pair: Pair<L, S>,
        error: f64,
        failed_grid: L,
        failure: E,
    },
}

/// Refinement that ends without a resolved pair.
#[derive(Debug, Clone, PartialEq)]
pub enum RefineError<L, S, E> {
    /// A solve failed before any pair resolved.
    Failed { grid: L, failure: E },
    /// The finest grid allowed still does not resolve the result.
    Unresolved(Pair<L, S>),
    /// The starting grid is already the finest: there is nothing to refine to.
    NoFinerGrid,
}

/// Refine from `coarse` (solved on `grid`) until [`Judgement::Resolved`] within `tolerance`.
/// `solve(grid, start)` solves on `grid` from the coarser solution `start`. `finer(grid)` must
/// give at least one grid ([`RefineError::NoFinerGrid`] otherwise).
pub fn refine<L: Copy, S: Clone, E>(
    grid: L,
    mut coarse: S,
    tolerance: f64,
    finer: impl Fn(L) -> Option<L>,
    mut solve: impl FnMut(L, &S) -> Result<S, E>,
    mut judge: impl FnMut(&S, &S) -> Judgement,
) -> Result<Refined<L, S, E>, RefineError<L, S, E>> {
    let Some(mut next) = finer(grid) else {
        return Err(RefineError::NoFinerGrid);
    };
    let mut last: Option<(Pair<L, S>, f64)> = None;
    loop {
        let fine = match solve(next, &coarse) {
            Ok(fine) => fine,
            Err(failure) => {
                return match last {
                    Some((pair, error)) => Ok(Refined::FellBack {
                        pair,
                        error,
                        failed_grid: next,
                        failure,
                    }),
                    None => Err(RefineError::Failed {
                        grid: next,
                        failure,
                    }),
                }
            }
        };
        let judgement = judge(&coarse, &fine);
        let pair = Pair {
            coarse,
            fine,
            grid: next,
        };
        let finest = finer(next);
        match (judgement, finest) {
            (Judgement::Resolved(error), _) if error <= tolerance => {
                return Ok(Refined::Converged { pair, error })
            }
            (Judgement::Resolved(error), None) => return Ok(Refined::GridLimited { pair, error }),
            (Judgement::Unresolved, None) => return Err(RefineError::Unresolved(pair)),
            (Judgement::Resolved(error), Some(_)) => last = Some((pair.clone(), error)),
            (Judgement::Unresolved, Some(_)) => {}
        }
        coarse = pair.fine;
        next = finest.expect("matched Some above");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A "solution" on n cells: the value 1 + 1/n² (second order), judged by Richardson.
    fn judge(c: &f64, f: &f64) -> Judgement {
        Judgement::Resolved((crate::numerics::richardson::fine_error(*c, *f) / f).abs())
    }
    fn doubling(max: usize) -> impl Fn(usize) -> Option<usize> {
        move |n| (2 * n <= max).then_some(2 * n)
    }
    fn value(n: usize) -> f64 {
        1.0 + 1.0 / (n * n) as f64
    }

    #[test]
    fn refines_until_the_estimate_is_within_tolerance() {
        let mut solves = Vec::new();
        let solve = |n: usize, _: &f64| -> Result<f64, ()> {
            solves.push(n);
            Ok(value(n))
        };
        // Error of the fine grid ≈ 1/n²: below 1e-3 from n = 32.
        let r = refine(4, value(4), 1e-3, doubling(1024), solve, judge).unwrap();
        let Refined::Converged { pair, error } = r else {
            panic!("{r:?}")
        };
        assert_eq!((pair.grid, solves), (32, vec![8, 16, 32]));
        assert!(error <= 1e-3 && (error - 1.0 / 1024.0).abs() < 1e-4);
    }

    #[test]
    fn stops_at_the_finest_grid_and_falls_back_when_a_solve_fails() {
        let ok = |n: usize, _: &f64| -> Result<f64, &str> { Ok(value(n)) };
        let r = refine(4, value(4), 1e-9, doubling(16), ok, judge).unwrap();
        assert!(matches!(
            r,
            Refined::GridLimited {
                pair: Pair { grid: 16, .. },
                ..
            }
        ));
        let fails_at_32 = |n: usize, _: &f64| -> Result<f64, &str> {
            if n == 32 {
                Err("stalled")
            } else {
                Ok(value(n))
            }
        };
        let r = refine(4, value(4), 1e-9, doubling(64), fails_at_32, judge).unwrap();
        assert!(matches!(
            r,
            Refined::FellBack {
                failed_grid: 32,
                pair: Pair { grid: 16, .. },
                ..
            }
        ));
        let never = |_: &f64, _: &f64| Judgement::Unresolved;
        let r = refine(4, value(4), 1e-9, doubling(16), ok, never);
        assert!(matches!(
            r,
            Err(RefineError::Unresolved(Pair { grid: 16, .. }))
        ));
        let r = refine(4, value(4), 1e-9, doubling(4), ok, judge);
        assert!(matches!(r, Err(RefineError::NoFinerGrid)));
    }
}
