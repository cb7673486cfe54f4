//! The Reynolds (Swift–Stieber) film solved exactly: the linear complementarity problem
//! p ≥ 0, r = A p + b ≥ 0, p r = 0 of the five-point stencil (A is symmetric and an M-matrix)
//! by the primal–dual active-set method (Hintermüller, Ito & Kunisch 2003, a semismooth Newton
//! method; for an M-matrix it ends in finitely many steps from any start). Each step solves the
//! free nodes' equations with the cavitated nodes held at p = 0 by a banded Cholesky
//! factorisation (the nodes numbered across the short direction first; the columns of a periodic
//! film in the cyclic order 0, n−1, 1, n−2, …, so that the seam's neighbours are as near as
//! every other pair and the band only doubles), then frees every
//! cavitated node whose equation pulls its pressure above zero and cavitates every free node
//! whose pressure fell below it. The active set that no longer changes is the exact discrete
//! solution: there is no sweep tolerance.
//!
//! The factorisation of the converged active set also gives the film's linear response to a
//! change of its coefficients ([`Linearised`]): the dynamic coefficients without a re-solve.

use super::{Budget, SolveError, Solved, Stencil};
use crate::fidelity::IterationUnit;
use crate::numerics::banded::{BandCholesky, NotPositiveDefinite, SymmetricBand};
use crate::numerics::driver::{Driver, Verdict};

/// Active-set steps before a solve counts as stopped (a few suffice from a warm start, a few
/// tens from a cold one).
const MAX_STEPS: u32 = 200;

/// A cavitated node is freed when its equation's pull exceeds this share of the largest
/// a_P·p (round-off must not flip a node that sits on the rupture line).
const FREEING_THRESHOLD: f64 = 1e-12;

/// The unknowns (interior, not held, a_P > 0), numbered column by column across y; a periodic
/// film's columns 0 … nx − 1 in cyclic order (column nx repeats column 0 and shares its unknowns).
#[derive(Debug, Clone)]
struct Numbering {
    /// Grid node of each unknown.
    nodes: Vec<usize>,
    /// Unknown of each grid node (usize::MAX: a boundary or held node).
    index: Vec<usize>,
    /// Sub-diagonals of the band: the largest distance between neighbouring unknowns.
    band: usize,
}

impl Numbering {
    fn of(stencil: &Stencil) -> Numbering {
        let (nx, w) = (stencil.nx, stencil.nx + 1);
        // Fewer columns would make a node its own (or its east its west) neighbour.
        debug_assert!(
            !stencil.periodic || nx >= 3,
            "a periodic film of {nx} columns"
        );
        let columns: Vec<usize> = if stencil.periodic {
            (0..nx)
                .map(|t| if t % 2 == 0 { t / 2 } else { nx - 1 - t / 2 })
                .collect()
        } else {
            (1..nx).collect()
        };
        let mut index = vec![usize::MAX; w * stencil.rows];
        let mut nodes = Vec::new();
        for i in columns {
            for j in 1..stencil.rows {
                let k = j * w + i;
                if stencil.ap[k] > 0.0 && !stencil.held[k] {
                    index[k] = nodes.len();
                    nodes.push(k);
                }
            }
        }
        if stencil.periodic {
            for j in 1..stencil.rows {
                index[j * w + nx] = index[j * w];
            }
        }
        let mut numbering = Numbering {
            nodes,
            index,
            band: 1,
        };
        numbering.band = numbering
            .nodes
            .iter()
            .flat_map(|&k| {
                let r = numbering.index[k];
                [stencil.west(k), k - w]
                    .into_iter()
                    .filter_map(|nb| numbering.unknown(nb))
                    .map(move |c| r.abs_diff(c))
            })
            .max()
            .unwrap_or(1)
            .max(1);
        numbering
    }

    fn unknown(&self, k: usize) -> Option<usize> {
        let r = self.index[k];
        (r != usize::MAX).then_some(r)
    }
}

impl Stencil {
    /// Node k's west neighbour: across the seam of a periodic film, column nx − 1.
    pub(super) fn west(&self, k: usize) -> usize {
        if self.periodic && k.is_multiple_of(self.nx + 1) {
            k + self.nx - 1
        } else {
            k - 1
        }
    }

    /// Node k's neighbours with their coefficients: east, west, north (below the last row) and
    /// south.
    fn neighbours(&self, k: usize) -> impl Iterator<Item = (usize, f64)> {
        let w = self.nx + 1;
        let north = ((k / w) + 1 < self.rows).then(|| (k + w, self.an[k]));
        [(k + 1, self.ae[k]), (self.west(k), self.aw[k])]
            .into_iter()
            .chain(north)
            .chain([(k - w, self.a_s[k])])
    }
}

/// The free nodes' operator A_FF, the cavitated ones' rows replaced by the identity (so the
/// matrix stays symmetric and positive definite), factored.
/// `storage` is a zero matrix of the numbering's order and band.
fn factor(
    stencil: &Stencil,
    numbering: &Numbering,
    free: &[bool],
    storage: SymmetricBand,
) -> Result<BandCholesky, NotPositiveDefinite> {
    let mut a = storage;
    for (r, &k) in numbering.nodes.iter().enumerate() {
        if !free[r] {
            a.set(r, r, 1.0);
            continue;
        }
        a.set(r, r, stencil.ap[k]);
        // The lower triangle: each coupling from its later unknown (the stencil is symmetric).
        for (nb, coefficient) in stencil.neighbours(k) {
            if let Some(c) = numbering.unknown(nb).filter(|&c| c < r && free[c]) {
                a.set(r, c, -coefficient);
            }
        }
    }
    a.cholesky()
}

/// Σ a_nb p_nb − b at node k: the free equation's right side (a_P p_P equals it).
fn pull(stencil: &Stencil, p: &[f64], k: usize) -> f64 {
    stencil
        .neighbours(k)
        .map(|(nb, coefficient)| coefficient * p[nb])
        .sum::<f64>()
        - stencil.b[k]
}

/// The film from the start `p` (its positive nodes the first free set; when none is positive,
/// the nodes with b < 0; boundary values stay as given), with cavitation (`cavitation`) or
/// without (one linear solve), under the driver (method `finite_volume_active_set`, one iteration an
/// active-set step); `budget` stops a late solve.
pub fn solve(
    stencil: &Stencil,
    p: &mut [f64],
    cavitation: bool,
    budget: &Budget,
) -> Result<Solved, SolveError> {
    let numbering = Numbering::of(stencil);
    // A start with pressure gives the first free set; from rest, the nodes the wedge (or
    // source) pressurises: b < 0 pulls p above zero.
    let warm = numbering.nodes.iter().any(|&k| p[k] > 0.0);
    let mut free: Vec<bool> = numbering
        .nodes
        .iter()
        .map(|&k| !cavitation || if warm { p[k] > 0.0 } else { stencil.b[k] < 0.0 })
        .collect();
    let mut x = vec![0.0; numbering.nodes.len()];
    let mut storage = Some(SymmetricBand::zeros(numbering.nodes.len(), numbering.band));
    let run = Driver::new(
        "finite_volume_active_set",
        IterationUnit::NewtonSteps,
        MAX_STEPS,
        budget,
    )
    .run(|_| {
        let band = storage
            .take()
            .unwrap_or_else(|| SymmetricBand::zeros(numbering.nodes.len(), numbering.band));
        let Ok(cholesky) = factor(stencil, &numbering, &free, band) else {
            return Verdict::Diverged(f64::NAN);
        };
        // The right side: −b plus the fixed boundary values' pull; cavitated rows hold 0.
        for (r, &k) in numbering.nodes.iter().enumerate() {
            x[r] = if free[r] {
                stencil
                    .neighbours(k)
                    .filter(|&(nb, _)| numbering.unknown(nb).is_none())
                    .map(|(nb, coefficient)| coefficient * p[nb])
                    .sum::<f64>()
                    - stencil.b[k]
            } else {
                0.0
            };
        }
        cholesky.solve(&mut x);
        storage = Some(SymmetricBand::recycled(cholesky));
        if x.iter().any(|v| !v.is_finite()) {
            return Verdict::Diverged(f64::NAN);
        }
        for (r, &k) in numbering.nodes.iter().enumerate() {
            p[k] = x[r];
        }
        stencil.close_seam(p);
        if !cavitation {
            return Verdict::Converged((), stencil.residual(p, false));
        }
        let scale = numbering
            .nodes
            .iter()
            .map(|&k| stencil.ap[k] * p[k].abs())
            .fold(0.0, f64::max);
        let mut changed = 0usize;
        for (r, &k) in numbering.nodes.iter().enumerate() {
            let next = if free[r] {
                p[k] >= 0.0
            } else {
                pull(stencil, p, k) > FREEING_THRESHOLD * scale
            };
            if next != free[r] {
                changed += 1;
                free[r] = next;
            }
        }
        if changed == 0 {
            Verdict::Converged((), stencil.residual(p, true))
        } else {
            Verdict::Continue(changed as f64)
        }
    })?;
    Ok(Solved { report: run.report })
}

/// The converged film's free-node operator: the film's first-order response to a change of its
/// coefficients with the cavitated region held (at the Reynolds condition p = ∂p/∂n = 0 the
/// rupture line's own movement changes the pressure only to second order).
#[derive(Debug, Clone)]
pub struct Linearised {
    numbering: Numbering,
    cholesky: BandCholesky,
}

impl Linearised {
    /// The operator of `stencil` on the free nodes of the converged field `p` (p > 0).
    pub fn at(stencil: &Stencil, p: &[f64]) -> Result<Linearised, NotPositiveDefinite> {
        let numbering = Numbering::of(stencil);
        let free: Vec<bool> = numbering.nodes.iter().map(|&k| p[k] > 0.0).collect();
        let storage = SymmetricBand::zeros(numbering.nodes.len(), numbering.band);
        let cholesky = factor(stencil, &numbering, &free, storage)?;
        Ok(Linearised {
            numbering,
            cholesky,
        })
    }

    /// δp from δr, the change of the equations' residual a_P p − Σ a_nb p_nb + b at the
    /// converged field (per grid node): A_FF δp = −δr on the free nodes, 0 elsewhere.
    pub fn response(&self, residual_change: &[f64], p: &[f64]) -> Vec<f64> {
        let mut x: Vec<f64> = self
            .numbering
            .nodes
            .iter()
            .map(|&k| if p[k] > 0.0 { -residual_change[k] } else { 0.0 })
            .collect();
        self.cholesky.solve(&mut x);
        let mut dp = vec![0.0; residual_change.len()];
        for (r, &k) in self.numbering.nodes.iter().enumerate() {
            dp[k] = x[r];
        }
        dp
    }
}

impl Stencil {
    /// A periodic film's column nx repeats column 0.
    fn close_seam(&self, p: &mut [f64]) {
        if self.periodic {
            let w = self.nx + 1;
            for j in 0..self.rows {
                p[j * w + self.nx] = p[j * w];
            }
        }
    }

    /// a_P p − Σ a_nb p_nb + b at every interior node that is not held (0 at boundary and held
    /// nodes). Linear in the stencil's coefficients: a stencil assembled from the derivatives of
    /// a film's coefficient functions gives the residual's derivative.
    pub fn residuals(&self, p: &[f64]) -> Vec<f64> {
        let mut r = vec![0.0; p.len()];
        let w = self.nx + 1;
        let rows = self.rows - usize::from(self.far_edge);
        // A periodic film's column 0 holds unknowns too (column nx mirrors it).
        let first = usize::from(!self.periodic);
        for j in 1..rows {
            for i in first..self.nx {
                let k = j * w + i;
                if !self.held[k] {
                    r[k] = self.ap[k] * p[k] - pull(self, p, k);
                }
            }
        }
        r
    }
}
