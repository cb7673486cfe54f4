//! Grid transfers between a fine 2-D node grid and the coarse grid of every second node
//! (Brandt's standard coarsening; Venner & Lubrecht 2000 ch. 2–3): injection, full weighting
//! and bilinear interpolation. Grids are row-major with x fastest; node counts are odd (an
//! even number of cells), the coarse grid has (n + 1)/2 nodes per direction.

/// The coarse node counts of a fine grid of `nx` × `ny` nodes.
#[must_use]
pub fn coarse_size(nx: usize, ny: usize) -> (usize, usize) {
    debug_assert!(nx % 2 == 1 && ny % 2 == 1);
    (nx.div_ceil(2), ny.div_ceil(2))
}

/// Injection: the coarse value is the coincident fine value (for the solution in FAS).
#[must_use]
pub fn inject(fine: &[f64], nx: usize, ny: usize) -> Vec<f64> {
    let (cx, cy) = coarse_size(nx, ny);
    let mut coarse = Vec::with_capacity(cx * cy);
    for j in 0..cy {
        for i in 0..cx {
            coarse.push(fine[2 * j * nx + 2 * i]);
        }
    }
    coarse
}

/// Full weighting (stencil ¼ ⊗ [1 2 1]ᵀ[1 2 1]/4) at the coarse interior nodes; the coarse
/// boundary is zero (for residuals, which vanish where the solution is prescribed).
#[must_use]
pub fn full_weighting(fine: &[f64], nx: usize, ny: usize) -> Vec<f64> {
    let (cx, cy) = coarse_size(nx, ny);
    let mut coarse = vec![0.0; cx * cy];
    let at = |i: usize, j: usize| fine[j * nx + i];
    for jc in 1..cy - 1 {
        for ic in 1..cx - 1 {
            let (i, j) = (2 * ic, 2 * jc);
            let edges = at(i - 1, j) + at(i + 1, j) + at(i, j - 1) + at(i, j + 1);
            let corners = at(i - 1, j - 1) + at(i + 1, j - 1) + at(i - 1, j + 1) + at(i + 1, j + 1);
            coarse[jc * cx + ic] = (4.0 * at(i, j) + 2.0 * edges + corners) / 16.0;
        }
    }
    coarse
}

/// Bilinear interpolation of a coarse grid of `cx` × `cy` nodes onto the fine grid of
/// (2cx − 1) × (2cy − 1) nodes.
#[must_use]
pub fn bilinear(coarse: &[f64], cx: usize, cy: usize) -> Vec<f64> {
    let (nx, ny) = (2 * cx - 1, 2 * cy - 1);
    let mut fine = vec![0.0; nx * ny];
    let at = |i: usize, j: usize| coarse[j * cx + i];
    for j in 0..ny {
        let (jc, odd_j) = (j / 2, j % 2 == 1);
        for i in 0..nx {
            let (ic, odd_i) = (i / 2, i % 2 == 1);
            fine[j * nx + i] = match (odd_i, odd_j) {
                (false, false) => at(ic, jc),
                (true, false) => 0.5 * (at(ic, jc) + at(ic + 1, jc)),
                (false, true) => 0.5 * (at(ic, jc) + at(ic, jc + 1)),
                (true, true) => {
                    0.25 * (at(ic, jc) + at(ic + 1, jc) + at(ic, jc + 1) + at(ic + 1, jc + 1))
                }
            };
        }
    }
    fine
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A bilinear field x + 2y + 3xy on nodes (i, j) of a grid with spacing `h`.
    fn field(nx: usize, ny: usize, h: f64) -> Vec<f64> {
        (0..nx * ny)
            .map(|k| {
                let (x, y) = ((k % nx) as f64 * h, (k / nx) as f64 * h);
                x + 2.0 * y + 3.0 * x * y
            })
            .collect()
    }

    #[test]
    fn transfers_reproduce_bilinear_fields() {
        let (nx, ny) = (9, 7);
        let fine = field(nx, ny, 0.5);
        let (cx, cy) = coarse_size(nx, ny);
        let coarse = field(cx, cy, 1.0);
        assert_eq!(inject(&fine, nx, ny), coarse);
        assert_eq!(bilinear(&coarse, cx, cy), fine);
        // Full weighting is exact for bilinear fields at interior nodes.
        let weighted = full_weighting(&fine, nx, ny);
        for jc in 1..cy - 1 {
            for ic in 1..cx - 1 {
                let k = jc * cx + ic;
                assert!((weighted[k] - coarse[k]).abs() < 1e-12);
            }
        }
    }
}
