//! General (unsymmetric) band matrices: Gaussian elimination with partial pivoting in band
//! storage (Golub & Van Loan §4.3.5–4.3.6; LAPACK's `gbtrf`/`gbtrs`). Row interchanges widen
//! the upper band from `ku` to `ku + kl`, so each row keeps room for that fill. A matrix of order
//! n with `kl` sub- and `ku` super-diagonals costs about n·kl·(kl + ku) multiply–adds to factor
//! and n·(2kl + ku) to solve. Used where the Jacobian of a Newton step is not symmetric (the
//! compressible Reynolds equation's Couette flux); symmetric positive definite systems use the
//! band Cholesky of [`super::banded`].

use super::driver::Budget;

/// A band matrix of order `n`, factored in place by [`Band::lu`].
#[derive(Debug, Clone)]
pub struct Band {
    n: usize,
    kl: usize,
    ku: usize,
    /// Row i holds columns i − kl ..= i + ku + kl (room for the fill of pivoting).
    data: Vec<f64>,
}

/// The matrix is singular to working precision: no usable pivot in column `column`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Singular {
    pub column: usize,
}

/// Why [`Band::lu_within`] gave no factor.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Unfactored {
    Singular(Singular),
    /// The budget ran out (deadline or cancellation) part-way.
    Stopped,
}

/// Columns eliminated between two polls of [`Band::lu_within`]'s budget: at a band of 256
/// (the finest gas films) about 8·10⁶ multiply–adds, a few milliseconds; the clock's read is
/// lost in it.
const COLUMNS_PER_POLL: usize = 64;

impl Band {
    /// The zero matrix of order `n` with `kl` sub-diagonals and `ku` super-diagonals.
    pub fn zeros(n: usize, kl: usize, ku: usize) -> Self {
        Band {
            n,
            kl,
            ku,
            data: vec![0.0; n * (2 * kl + ku + 1)],
        }
    }

    pub fn order(&self) -> usize {
        self.n
    }

    fn width(&self) -> usize {
        2 * self.kl + self.ku + 1
    }

    fn index(&self, i: usize, j: usize) -> usize {
        debug_assert!(
            j + self.kl >= i && j <= i + self.ku + self.kl,
            "({i}, {j}) outside the band"
        );
        i * self.width() + (j + self.kl - i)
    }

    /// A_ij += v (i, j within the band: |i − j| ≤ kl below, ≤ ku above).
    pub fn add(&mut self, i: usize, j: usize, v: f64) {
        debug_assert!(j + self.kl >= i && j <= i + self.ku);
        let k = self.index(i, j);
        self.data[k] += v;
    }

    /// A_ij.
    pub fn get(&self, i: usize, j: usize) -> f64 {
        self.data[self.index(i, j)]
    }

    /// P A = L U in place, with row interchanges chosen by the largest pivot in each column.
    pub fn lu(self) -> Result<BandLu, Singular> {
        self.factor(|| Ok(()), |s| s)
    }

    /// [`Band::lu`], stopped when `budget` runs out (polled every [`COLUMNS_PER_POLL`]
    /// columns): a factorisation of a fine film takes seconds, longer than a request's
    /// deadline may leave, and a budget checked only between factorisations is seen that late.
    pub fn lu_within(self, budget: &Budget) -> Result<BandLu, Unfactored> {
        self.factor(
            || {
                if budget.alive() {
                    Ok(())
                } else {
                    Err(Unfactored::Stopped)
                }
            },
            Unfactored::Singular,
        )
    }

    #[allow(clippy::needless_range_loop)] // band indices read clearer than iterator chains
    /// The elimination, asking `poll` every [`COLUMNS_PER_POLL`] columns whether to go on.
    fn factor<E>(
        mut self,
        poll: impl Fn() -> Result<(), E>,
        singular: impl Fn(Singular) -> E,
    ) -> Result<BandLu, E> {
        let (n, kl, ku) = (self.n, self.kl, self.ku);
        let mut pivots = vec![0usize; n];
        let mut scale = 0.0f64;
        for v in &self.data {
            scale = scale.max(v.abs());
        }
        let tiny = scale * f64::EPSILON * n as f64;
        for k in 0..n {
            if k % COLUMNS_PER_POLL == 0 {
                poll()?;
            }
            let last_row = (k + kl).min(n - 1);
            let last_col = (k + ku + kl).min(n - 1);
            let mut p = k;
            let mut best = self.get(k, k).abs();
            for i in k + 1..=last_row {
                let v = self.get(i, k).abs();
                if v > best {
                    best = v;
                    p = i;
                }
            }
            if best.is_nan() || best <= tiny {
                return Err(singular(Singular { column: k }));
            }
            pivots[k] = p;
            if p != k {
                for j in k..=last_col {
                    let (a, b) = (self.index(k, j), self.index(p, j));
                    self.data.swap(a, b);
                }
            }
            let pivot = self.get(k, k);
            let row_k = self.index(k, k);
            for i in k + 1..=last_row {
                let at = self.index(i, k);
                let m = self.data[at] / pivot;
                self.data[at] = m;
                if m == 0.0 {
                    continue;
                }
                // Row i −= m · row k over the columns after k (contiguous in both rows).
                let len = last_col - k;
                let (upper, lower) = self.data.split_at_mut(at);
                for (t, u) in lower[1..=len]
                    .iter_mut()
                    .zip(&upper[row_k + 1..=row_k + len])
                {
                    *t -= m * u;
                }
            }
        }
        Ok(BandLu {
            factor: self,
            pivots,
        })
    }
}

/// The factor of a [`Band`]: the Gauss transforms, the interchanges and U.
#[derive(Debug, Clone)]
pub struct BandLu {
    factor: Band,
    pivots: Vec<usize>,
}

impl BandLu {
    /// Solves A x = b in place.
    #[allow(clippy::needless_range_loop)]
    pub fn solve(&self, x: &mut [f64]) {
        let a = &self.factor;
        let (n, kl, ku) = (a.n, a.kl, a.ku);
        for k in 0..n {
            let p = self.pivots[k];
            if p != k {
                x.swap(k, p);
            }
            let xk = x[k];
            for i in k + 1..=(k + kl).min(n - 1) {
                x[i] -= a.get(i, k) * xk;
            }
        }
        for k in (0..n).rev() {
            let mut s = x[k];
            for j in k + 1..=(k + ku + kl).min(n - 1) {
                s -= a.get(k, j) * x[j];
            }
            x[k] = s / a.get(k, k);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn a_zero_leading_pivot_is_interchanged() {
        // [[0, 1], [2, 3]] x = [1, 8] → x = [2.5, 1].
        let mut a = Band::zeros(2, 1, 1);
        a.add(0, 1, 1.0);
        a.add(1, 0, 2.0);
        a.add(1, 1, 3.0);
        let lu = a.lu().unwrap();
        let mut x = [1.0, 8.0];
        lu.solve(&mut x);
        assert!((x[0] - 2.5).abs() < 1e-14 && (x[1] - 1.0).abs() < 1e-14);
        assert!(Band::zeros(3, 1, 1).lu().is_err());
    }

    /// A budget already spent stops the factorisation before its first column; a live one
    /// factors as [`Band::lu`] does.
    #[test]
    fn a_spent_budget_stops_the_factorisation() {
        use std::sync::atomic::AtomicBool;
        use std::sync::Arc;
        use std::time::{Duration, Instant};
        let matrix = || {
            let mut a = Band::zeros(3, 1, 1);
            for i in 0..3 {
                a.add(i, i, 2.0);
            }
            a
        };
        let spent = Budget::new(Instant::now(), Arc::new(AtomicBool::new(false)));
        assert_eq!(matrix().lu_within(&spent).err(), Some(Unfactored::Stopped));
        let cancelled = Budget::new(
            Instant::now() + Duration::from_secs(60),
            Arc::new(AtomicBool::new(true)),
        );
        assert_eq!(
            matrix().lu_within(&cancelled).err(),
            Some(Unfactored::Stopped)
        );
        let mut x = [2.0, 4.0, 6.0];
        matrix()
            .lu_within(&Budget::unlimited())
            .unwrap()
            .solve(&mut x);
        assert_eq!(x, [1.0, 2.0, 3.0]);
        assert_eq!(
            Band::zeros(3, 1, 1).lu_within(&Budget::unlimited()).err(),
            Some(Unfactored::Singular(Singular { column: 0 }))
        );
    }

    proptest! {
        #[test]
        fn solutions_satisfy_the_system(
            n in 1usize..40, kl in 0usize..5, ku in 0usize..5,
            seed in proptest::collection::vec(-1.0f64..1.0, 40 * 11),
            b in proptest::collection::vec(-1.0f64..1.0, 40),
        ) {
            let mut a = Band::zeros(n, kl, ku);
            let mut dense = vec![vec![0.0; n]; n];
            for i in 0..n {
                for j in i.saturating_sub(kl)..=(i + ku).min(n - 1) {
                    // Weak diagonal: pivoting matters.
                    let v = seed[(i * 11 + j + kl - i) % seed.len()] + if i == j { 0.1 } else { 0.0 };
                    a.add(i, j, v);
                    dense[i][j] = v;
                }
            }
            if let Ok(lu) = a.lu() {
                let mut x = b[..n].to_vec();
                lu.solve(&mut x);
                let norm = x.iter().fold(1.0f64, |m, v| m.max(v.abs()));
                for i in 0..n {
                    let r: f64 = (0..n).map(|j| dense[i][j] * x[j]).sum::<f64>() - b[i];
                    prop_assert!(r.abs() < 1e-9 * norm, "row {i}: {r}");
                }
            }
        }
    }
}
