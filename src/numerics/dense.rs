//! Small dense linear systems, through nalgebra's LU with partial pivoting. Large or sparse
//! systems (the EHL line contact's Newton matrix) use faer instead.

use nalgebra::{DMatrix, DVector};

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

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    #[test]
    fn singular_systems_have_no_solution() {
        assert_eq!(solve([[1.0, 2.0], [2.0, 4.0]], [1.0, 2.0]), None);
    }

    proptest! {
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
