//! Discrete convolution of a 2-D grid with a translation-invariant kernel by the fast Fourier
//! transform: the elastic deformation of a point-contact film, Σ K(i − k, j − l) P(k, l), in
//! O(N log N) instead of the O(N²) direct sum (Venner & Lubrecht 2000 ch. 8 use multi-level
//! multi-integration for the same sum; the FFT is exact to round-off and simpler).
//!
//! The transforms are realfft's (over rustfft): a real-to-complex transform along each row,
//! then complex transforms along the columns of the half spectrum. This module is the one place
//! transforms are planned. Planning a size costs far more than one transform (twiddles, the
//! choice of algorithm), so plans come from per-thread planners that keep every size they have
//! built: a solve's grids, and every later solve on the same blocking-pool thread, reuse them.

use std::cell::RefCell;
use std::fmt;
use std::sync::Arc;

use realfft::num_complex::Complex;
use realfft::num_traits::Zero;
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};
use rustfft::{Fft, FftPlanner};

thread_local! {
    /// Each planner caches its plans by length (`plan_fft_*` hands back the same `Arc` for a
    /// length it has seen), so this is the per-thread plan cache.
    static PLANNERS: RefCell<(RealFftPlanner<f64>, FftPlanner<f64>)> =
        RefCell::new((RealFftPlanner::new(), FftPlanner::new()));
}

/// The four transforms of a `px` × `py` real grid, from this thread's cache.
#[derive(Clone)]
struct Plans {
    row_forward: Arc<dyn RealToComplex<f64>>,
    row_inverse: Arc<dyn ComplexToReal<f64>>,
    column_forward: Arc<dyn Fft<f64>>,
    column_inverse: Arc<dyn Fft<f64>>,
}

impl Plans {
    fn new(px: usize, py: usize) -> Plans {
        PLANNERS.with(|planners| {
            let (real, complex) = &mut *planners.borrow_mut();
            Plans {
                row_forward: real.plan_fft_forward(px),
                row_inverse: real.plan_fft_inverse(px),
                column_forward: complex.plan_fft_forward(py),
                column_inverse: complex.plan_fft_inverse(py),
            }
        })
    }

    fn scratch_len(&self) -> usize {
        self.row_forward
            .get_scratch_len()
            .max(self.row_inverse.get_scratch_len())
            .max(self.column_forward.get_inplace_scratch_len())
            .max(self.column_inverse.get_inplace_scratch_len())
    }
}

/// The convolution u(i, j) = Σ_{k,l} K(i − k, j − l) f(k, l) on a grid of `nx` × `ny` nodes
/// (row-major, x fastest), with sources f on the interior nodes 1 … n − 2 (the boundary nodes
/// carry none) and results on every node. The kernel's spectrum is computed once; the padded
/// periodic grid holds every offset −(n − 2) … n − 1 without wrapping onto another.
///
/// Spectra are stored column by column (the `px/2 + 1` frequencies along x, each a contiguous
/// column of `py`), so the column transforms run as one batch over one buffer.
#[derive(Clone)]
pub struct Convolution2d {
    nx: usize,
    ny: usize,
    /// Padded sizes (powers of two ≥ 2n − 2).
    px: usize,
    py: usize,
    plans: Plans,
    /// The kernel's spectrum, scaled by 1/(px py) for the unnormalised inverse.
    spectrum: Vec<Complex<f64>>,
    /// Work space reused by every `apply`: one real row, one row's half spectrum, the
    /// column-major half spectrum of the grid, and the transforms' scratch.
    row: Vec<f64>,
    row_spectrum: Vec<Complex<f64>>,
    columns: Vec<Complex<f64>>,
    scratch: Vec<Complex<f64>>,
}

impl fmt::Debug for Convolution2d {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Convolution2d")
            .field("nx", &self.nx)
            .field("ny", &self.ny)
            .field("px", &self.px)
            .field("py", &self.py)
            .finish_non_exhaustive()
    }
}

impl Convolution2d {
    /// `kernel(di, dj)` is K at the node offset (di, dj).
    pub fn new(nx: usize, ny: usize, kernel: impl Fn(i64, i64) -> f64) -> Self {
        assert!(nx >= 3 && ny >= 3, "a grid with interior nodes");
        let (px, py) = (
            (2 * nx - 2).next_power_of_two(),
            (2 * ny - 2).next_power_of_two(),
        );
        let plans = Plans::new(px, py);
        let half = px / 2 + 1;
        let mut c = Convolution2d {
            nx,
            ny,
            px,
            py,
            scratch: vec![Complex::zero(); plans.scratch_len()],
            plans,
            spectrum: Vec::new(),
            row: vec![0.0; px],
            row_spectrum: vec![Complex::zero(); half],
            columns: vec![Complex::zero(); half * py],
        };
        let mut wrapped = vec![0.0; px * py];
        for dj in -(ny as i64 - 2)..ny as i64 {
            for di in -(nx as i64 - 2)..nx as i64 {
                let (i, j) = (di.rem_euclid(px as i64), dj.rem_euclid(py as i64));
                wrapped[j as usize * px + i as usize] = kernel(di, dj);
            }
        }
        c.forward(
            |j, row| row.copy_from_slice(&wrapped[j * px..(j + 1) * px]),
            0..py,
        );
        let scale = 1.0 / (px * py) as f64;
        c.spectrum = c.columns.iter().map(|v| v * scale).collect();
        c
    }

    /// The 2-D forward transform into `columns` of the real grid whose rows `rows` are written
    /// by `fill(j, row)` (every other row is zero).
    fn forward(&mut self, fill: impl Fn(usize, &mut [f64]), rows: std::ops::Range<usize>) {
        let (py, half) = (self.py, self.px / 2 + 1);
        self.columns.fill(Complex::zero());
        for j in rows {
            fill(j, &mut self.row);
            self.plans
                .row_forward
                .process_with_scratch(&mut self.row, &mut self.row_spectrum, &mut self.scratch)
                .expect("buffer lengths match the plan");
            for (k, &v) in self.row_spectrum.iter().enumerate() {
                self.columns[k * py + j] = v;
            }
        }
        debug_assert_eq!(self.columns.len(), half * py);
        self.plans
            .column_forward
            .process_with_scratch(&mut self.columns, &mut self.scratch);
    }

    /// u = K ∗ f, written into `out` (length nx·ny); f's boundary nodes are ignored.
    pub fn apply(&mut self, f: &[f64], out: &mut [f64]) {
        let (nx, ny, px, py) = (self.nx, self.ny, self.px, self.py);
        assert!(f.len() == nx * ny && out.len() == nx * ny);
        self.forward(
            |j, row| {
                row.fill(0.0);
                row[1..nx - 1].copy_from_slice(&f[j * nx + 1..j * nx + nx - 1]);
            },
            1..ny - 1,
        );
        for (v, k) in self.columns.iter_mut().zip(&self.spectrum) {
            *v *= k;
        }
        self.plans
            .column_inverse
            .process_with_scratch(&mut self.columns, &mut self.scratch);
        // Back along x only for the rows that are wanted.
        let last = self.row_spectrum.len() - 1;
        for j in 0..ny {
            for (k, v) in self.row_spectrum.iter_mut().enumerate() {
                *v = self.columns[k * py + j];
            }
            // The spectrum of a real row has real end points; round-off leaves a trace of an
            // imaginary part, which the complex-to-real transform refuses.
            self.row_spectrum[0].im = 0.0;
            self.row_spectrum[last].im = 0.0;
            self.plans
                .row_inverse
                .process_with_scratch(&mut self.row_spectrum, &mut self.row, &mut self.scratch)
                .expect("buffer lengths match the plan");
            out[j * nx..(j + 1) * nx].copy_from_slice(&self.row[..nx]);
        }
        debug_assert_eq!(self.row.len(), px);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Σ over the interior sources, the O(N²) way.
    fn direct(nx: usize, ny: usize, kernel: impl Fn(i64, i64) -> f64, f: &[f64]) -> Vec<f64> {
        let mut u = vec![0.0; nx * ny];
        for j in 0..ny {
            for i in 0..nx {
                for l in 1..ny - 1 {
                    for k in 1..nx - 1 {
                        u[j * nx + i] +=
                            kernel(i as i64 - k as i64, j as i64 - l as i64) * f[l * nx + k];
                    }
                }
            }
        }
        u
    }

    #[test]
    fn fft_convolution_equals_the_direct_sum() {
        let (nx, ny) = (9, 6);
        let kernel = |di: i64, dj: i64| {
            1.0 / (1.0 + (di * di) as f64 + 0.5 * (dj * dj) as f64) + 0.1 * di as f64
        };
        let mut c = Convolution2d::new(nx, ny, kernel);
        let f: Vec<f64> = (0..nx * ny).map(|k| ((k * 37) % 11) as f64 - 4.0).collect();
        let mut out = vec![0.0; nx * ny];
        c.apply(&f, &mut out);
        let want = direct(nx, ny, kernel, &f);
        for j in 0..ny {
            for i in 0..nx {
                let direct = want[j * nx + i];
                assert!(
                    (out[j * nx + i] - direct).abs() < 1e-12,
                    "({i}, {j}): {} vs {direct}",
                    out[j * nx + i]
                );
            }
        }
    }

    /// A point contact's own kernel (1/r, singular-looking at the origin, asymmetric grid
    /// spacing) on a grid that is not a power of two either way, applied twice to different
    /// sources so the reused work space cannot leak one into the other.
    #[test]
    fn realfft_convolution_of_an_inverse_distance_kernel_equals_the_direct_sum() {
        let (nx, ny) = (33, 20);
        let (hx, hy) = (0.07, 0.05);
        let kernel = |di: i64, dj: i64| {
            let (x, y) = (di as f64 * hx, dj as f64 * hy);
            1.0 / (x * x + y * y + 0.25 * hx * hy).sqrt()
        };
        let mut c = Convolution2d::new(nx, ny, kernel);
        let mut out = vec![0.0; nx * ny];
        for seed in [3_usize, 7] {
            let f: Vec<f64> = (0..nx * ny)
                .map(|k| (((k * seed * 31) % 17) as f64 - 8.0) / 8.0)
                .collect();
            c.apply(&f, &mut out);
            let want = direct(nx, ny, kernel, &f);
            let scale = want.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            for (k, (got, want)) in out.iter().zip(&want).enumerate() {
                assert!(
                    (got - want).abs() <= 1e-12 * scale,
                    "node {k}: {got} vs {want}"
                );
            }
        }
    }

    #[test]
    fn plans_are_built_once_per_size_on_a_thread() {
        let kernel = |di: i64, dj: i64| (di + 2 * dj) as f64;
        let a = Convolution2d::new(17, 17, kernel);
        let b = Convolution2d::new(17, 17, kernel);
        assert!(Arc::ptr_eq(&a.plans.row_forward, &b.plans.row_forward));
        assert!(Arc::ptr_eq(
            &a.plans.column_inverse,
            &b.plans.column_inverse
        ));
    }
}
