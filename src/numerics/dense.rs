//! Dense linear systems by LU with partial pivoting: small ones ([`solve`]) through nalgebra's
//! LU, large ones ([`solve_large`]: the EHL line contact's Newton matrix, up to 2048 unknowns,
//! where its GMRES does not converge) through a recursively blocked LU whose bulk is nalgebra's
//! matrix product; and the inner product of long rows ([`dot`]).

use std::ops::Range;

use nalgebra::{DMatrix, DMatrixView, DMatrixViewMut, DVector};

/// Solve A x = b for a small N × N system given by rows; `None` when A is singular or the
/// solution is not finite.
#[must_use]
pub fn solve<const N: usize>(a: [[f64; N]; N], b: [f64; N]) -> Option<[f64; N]> {
    let matrix = DMatrix::from_fn(N, N, |i, j| a[i][j]);
    let x = matrix.lu().solve(&DVector::from_column_slice(&b))?;
    let mut out = [0.0; N];
    out.copy_from_slice(x.as_slice());
    out.iter().all(|v| v.is_finite()).then_some(out)
}

/// Σ aᵢbᵢ over the shorter of the two, in eight interleaved partial sums: independent chains
/// the compiler can keep in vector registers (a single running sum is one long dependency chain,
/// which it may not reorder), about three times faster over the rows of a large dense matrix.
#[must_use]
pub fn dot(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len().min(b.len());
    let (a, b) = (&a[..n], &b[..n]);
    let mut lanes = [0.0; 8];
    let (a8, b8) = (a.chunks_exact(8), b.chunks_exact(8));
    let tail: f64 = a8
        .remainder()
        .iter()
        .zip(b8.remainder())
        .map(|(x, y)| x * y)
        .sum();
    for (x, y) in a8.zip(b8) {
        for k in 0..8 {
            lanes[k] += x[k] * y[k];
        }
    }
    lanes.iter().sum::<f64>() + tail
}

/// Blocks of at most this many columns are factorised, and triangular blocks of at most this
/// many rows solved, element by element; everything larger is split in two.
const BLOCK: usize = 16;

/// Solve A x = b for a large dense system (hundreds to thousands of unknowns) by LU with
/// partial pivoting, recursively blocked (Toledo 1997, "Locality of reference in LU
/// decomposition with partial pivoting", SIAM J. Matrix Anal. Appl. 18(4)): the columns are
/// split in halves, the left half factorised, the top of the right half solved with the left's
/// unit lower triangle, the rest of the right half updated by one matrix product and then
/// factorised. The products run in nalgebra's `gemm`, which hands dynamic sizes to
/// `matrixmultiply`'s cache-blocked kernels, so nearly all of the O(n³) work runs at
/// matrix-product speed. (nalgebra's own `lu` eliminates one column at a time: ten times slower
/// at 2049 unknowns, where the matrix no longer fits in cache.) `None` when the solution is not
/// finite (a zero pivot).
#[must_use]
pub fn solve_large(mut a: DMatrix<f64>, b: &[f64]) -> Option<Vec<f64>> {
    let n = a.nrows();
    assert_eq!(a.ncols(), n, "square");
    assert_eq!(b.len(), n, "one right-hand side per row");
    let mut pivots = vec![0; n];
    factorise(&mut a, 0..n, &mut pivots);
    // Every swap has reached every column, so L is in the final row order: P b first, then
    // forward substitution with the unit lower factor and back substitution with the upper.
    let mut x = b.to_vec();
    for (j, &p) in pivots.iter().enumerate() {
        x.swap(j, p);
    }
    let data = a.as_slice();
    for j in 0..n {
        let (factor, column) = (x[j], &data[j * n..(j + 1) * n]);
        for i in j + 1..n {
            x[i] -= factor * column[i];
        }
    }
    for j in (0..n).rev() {
        let column = &data[j * n..(j + 1) * n];
        x[j] /= column[j];
        let factor = x[j];
        for i in 0..j {
            x[i] -= factor * column[i];
        }
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

/// LU of the columns `columns` = c₀..c₁ of `a` on its rows c₀.. (the columns left of c₀ already
/// factorised, their updates applied), its row swaps applied to these columns only (the caller
/// applies them to the others, column by column: a whole-row swap would touch one page per
/// column).
fn factorise(a: &mut DMatrix<f64>, columns: Range<usize>, pivots: &mut [usize]) {
    let Range { start, end } = columns;
    if end - start <= BLOCK {
        return factorise_by_columns(a, columns, pivots);
    }
    let middle = start + (end - start) / 2;
    factorise(a, start..middle, pivots);
    swap_rows(a, &pivots[start..middle], start, middle..end);
    let (left, mut right) = a.columns_range_pair_mut(start..middle, middle..end);
    let (mut top, mut below) = right.rows_range_pair_mut(start..middle, middle..);
    solve_unit_lower(left.rows_range(start..middle), &mut top);
    below.gemm(-1.0, &left.rows_range(middle..), &top, 1.0);
    factorise(a, middle..end, pivots);
    swap_rows(a, &pivots[middle..end], middle, start..middle);
}

/// Row j ↔ row `swaps[j − first]`, for j = first, first + 1, … in turn, in the columns `columns`.
fn swap_rows(a: &mut DMatrix<f64>, swaps: &[usize], first: usize, columns: Range<usize>) {
    let n = a.nrows();
    for column in a.as_mut_slice()[columns.start * n..columns.end * n].chunks_exact_mut(n) {
        for (j, &p) in (first..).zip(swaps) {
            column.swap(j, p);
        }
    }
}

/// [`factorise`] one column at a time (right-looking, rank-1 updates within the block).
fn factorise_by_columns(a: &mut DMatrix<f64>, columns: Range<usize>, pivots: &mut [usize]) {
    let n = a.nrows();
    let Range { start, end } = columns;
    for j in start..end {
        let column = &a.as_slice()[j * n..(j + 1) * n];
        let mut p = j;
        for r in j + 1..n {
            if column[r].abs() > column[p].abs() {
                p = r;
            }
        }
        pivots[j] = p;
        swap_rows(a, &[p], j, start..end);
        let (done, rest) = a.as_mut_slice().split_at_mut((j + 1) * n);
        let column = &mut done[j * n..];
        let inverse = 1.0 / column[j];
        let multipliers = &mut column[j + 1..];
        multipliers.iter_mut().for_each(|m| *m *= inverse);
        for target in rest[..(end - j - 1) * n].chunks_exact_mut(n) {
            let factor = target[j];
            for (t, &m) in target[j + 1..].iter_mut().zip(&*multipliers) {
                *t -= factor * m;
            }
        }
    }
}

/// X ← L⁻¹X for L unit lower triangular (its strictly lower part read from `lower`), split in
/// halves like [`factorise`] so that the bulk is one matrix product.
fn solve_unit_lower(lower: DMatrixView<f64>, x: &mut DMatrixViewMut<f64>) {
    let k = lower.nrows();
    if k <= BLOCK {
        for mut column in x.column_iter_mut() {
            for j in 0..k {
                let factor = column[j];
                for i in j + 1..k {
                    column[i] -= factor * lower[(i, j)];
                }
            }
        }
        return;
    }
    let half = k / 2;
    let (mut top, mut bottom) = x.rows_range_pair_mut(0..half, half..);
    solve_unit_lower(lower.view_range(0..half, 0..half), &mut top);
    bottom.gemm(-1.0, &lower.view_range(half.., 0..half), &top, 1.0);
    solve_unit_lower(lower.view_range(half.., half..), &mut bottom);
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn dot_matches_the_running_sum() {
        for n in [0, 1, 7, 8, 9, 100, 2049] {
            let a: Vec<f64> = (0..n).map(|i| (0.3 * i as f64).sin()).collect();
            let b: Vec<f64> = (0..n).map(|i| 1.0 + (0.7 * i as f64).cos()).collect();
            let running: f64 = a.iter().zip(&b).map(|(x, y)| x * y).sum();
            assert!(
                (dot(&a, &b) - running).abs() < 1e-12 * (1.0 + n as f64),
                "n = {n}"
            );
        }
        // The shorter length rules.
        assert_eq!(dot(&[1.0, 2.0, 3.0], &[4.0, 5.0]), 14.0);
    }

    #[test]
    fn singular_systems_have_no_solution() {
        assert_eq!(solve([[1.0, 2.0], [2.0, 4.0]], [1.0, 2.0]), None);
    }

    /// A deterministic, well-spread matrix: the entries of an LCG in (−½, ½), the diagonal not
    /// favoured, so that partial pivoting has to swap rows.
    fn scrambled(n: usize, seed: u64) -> DMatrix<f64> {
        let mut state = seed;
        DMatrix::from_fn(n, n, |_, _| {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (state >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        })
    }

    #[test]
    fn large_systems_agree_with_nalgebras_lu() {
        // Sizes across the block edge and the recursion's uneven halves.
        for n in [1, 2, 15, 16, 17, 33, 100, 257] {
            let a = scrambled(n, n as u64);
            let b: Vec<f64> = (0..n).map(|i| 1.0 + (i as f64 * 0.7).sin()).collect();
            let x = solve_large(a.clone(), &b).unwrap();
            let expected = a.lu().solve(&DVector::from_column_slice(&b)).unwrap();
            let scale = expected.amax();
            for (got, want) in x.iter().zip(expected.iter()) {
                assert!(
                    (got - want).abs() < 1e-10 * scale,
                    "n = {n}: {got} vs {want}"
                );
            }
        }
    }

    #[test]
    fn large_singular_systems_have_no_solution() {
        assert_eq!(solve_large(DMatrix::zeros(3, 3), &[1.0; 3]), None);
        // A zero column: its pivot is exactly zero, in the recursion's second half.
        let mut a = scrambled(40, 3);
        a.column_mut(27).fill(0.0);
        assert_eq!(solve_large(a, &[1.0; 40]), None);
    }

    proptest! {
        #[test]
        fn large_solutions_satisfy_the_system(n in 1usize..80, seed in any::<u64>()) {
            let a = scrambled(n, seed);
            let b: Vec<f64> = (0..n).map(|i| 1.0 + i as f64).collect();
            // A random matrix may be badly conditioned: judge the backward error.
            if let Some(x) = solve_large(a.clone(), &b) {
                let r = &a * DVector::from_column_slice(&x) - DVector::from_column_slice(&b);
                let scale = a.amax() * x.iter().fold(0.0f64, |m, v| m.max(v.abs())) * n as f64;
                prop_assert!(r.amax() <= 1e-12 * scale, "residual {}", r.amax());
            }
        }

        #[test]
        fn solutions_satisfy_the_system(
            m in proptest::array::uniform3(proptest::array::uniform3(-10.0f64..10.0)),
            b in proptest::array::uniform3(-10.0f64..10.0),
        ) {
            // Diagonally dominant, so well conditioned.
            let mut a = m;
            for (i, row) in a.iter_mut().enumerate() {
                row[i] += 40.0;
            }
            let x = solve(a, b).unwrap();
            for i in 0..3 {
                let r: f64 = (0..3).map(|j| a[i][j] * x[j]).sum::<f64>() - b[i];
                prop_assert!(r.abs() < 1e-12);
            }
        }
    }
}
