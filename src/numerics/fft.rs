//! Discrete convolution of a 2-D grid with a translation-invariant kernel by the fast Fourier
//! transform: the elastic deformation of a point-contact film, Σ K(i − k, j − l) P(k, l), in
//! O(N log N) instead of the O(N²) direct sum (Venner & Lubrecht 2000 ch. 8 use multi-level
//! multi-integration for the same sum; the FFT is exact to round-off and simpler). Radix-2 only:
//! the grids that use it have power-of-two cell counts.

use std::f64::consts::PI;

/// In-place radix-2 decimation-in-time FFT of (re, im), length a power of two; `inverse`
/// transforms back without the 1/n factor.
fn fft(re: &mut [f64], im: &mut [f64], twiddles: &[(f64, f64)], inverse: bool) {
    let n = re.len();
    debug_assert!(n.is_power_of_two() && im.len() == n);
    let mut j = 0;
    for i in 1..n {
        let mut bit = n >> 1;
        while j & bit != 0 {
            j ^= bit;
            bit >>= 1;
        }
        j |= bit;
        if i < j {
            re.swap(i, j);
            im.swap(i, j);
        }
    }
    let mut len = 2;
    while len <= n {
        let stride = n / len;
        let half = len / 2;
        for start in (0..n).step_by(len) {
            for k in 0..half {
                let (c, s) = twiddles[k * stride];
                let s = if inverse { -s } else { s };
                let (a, b) = (start + k, start + k + half);
                let (br, bi) = (re[b] * c - im[b] * s, re[b] * s + im[b] * c);
                re[b] = re[a] - br;
                im[b] = im[a] - bi;
                re[a] += br;
                im[a] += bi;
            }
        }
        len <<= 1;
    }
}

/// exp(−2πik/n) for k < n/2.
fn twiddles(n: usize) -> Vec<(f64, f64)> {
    (0..n / 2)
        .map(|k| {
            let t = -2.0 * PI * k as f64 / n as f64;
            (t.cos(), t.sin())
        })
        .collect()
}

/// The convolution u(i, j) = Σ_{k,l} K(i − k, j − l) f(k, l) on a grid of `nx` × `ny` nodes
/// (row-major, x fastest), with sources f on the interior nodes 1 … n − 2 (the boundary nodes
/// carry none) and results on every node. The kernel's spectrum is computed once; the padded
/// periodic grid holds every offset −(n − 2) … n − 1 without wrapping onto another.
#[derive(Debug, Clone)]
pub struct Convolution2d {
    nx: usize,
    ny: usize,
    /// Padded sizes (powers of two ≥ 2n − 2).
    px: usize,
    py: usize,
    twiddles_x: Vec<(f64, f64)>,
    twiddles_y: Vec<(f64, f64)>,
    /// The kernel's spectrum, scaled by 1/(px py) for the inverse transform.
    spectrum_re: Vec<f64>,
    spectrum_im: Vec<f64>,
}

impl Convolution2d {
    /// `kernel(di, dj)` is K at the node offset (di, dj).
    pub fn new(nx: usize, ny: usize, kernel: impl Fn(i64, i64) -> f64) -> Self {
        assert!(nx >= 3 && ny >= 3, "a grid with interior nodes");
        let (px, py) = (
            (2 * nx - 2).next_power_of_two(),
            (2 * ny - 2).next_power_of_two(),
        );
        let (mut re, mut im) = (vec![0.0; px * py], vec![0.0; px * py]);
        for dj in -(ny as i64 - 2)..ny as i64 {
            for di in -(nx as i64 - 2)..nx as i64 {
                let (i, j) = (di.rem_euclid(px as i64), dj.rem_euclid(py as i64));
                re[j as usize * px + i as usize] = kernel(di, dj);
            }
        }
        let mut c = Convolution2d {
            nx,
            ny,
            px,
            py,
            twiddles_x: twiddles(px),
            twiddles_y: twiddles(py),
            spectrum_re: Vec::new(),
            spectrum_im: Vec::new(),
        };
        c.transform(&mut re, &mut im, false, py);
        let scale = 1.0 / (px * py) as f64;
        c.spectrum_re = re.iter().map(|v| v * scale).collect();
        c.spectrum_im = im.iter().map(|v| v * scale).collect();
        c
    }

    /// 2-D transform: rows first (only the first `rows` rows can be non-zero going forward),
    /// then columns.
    fn transform(&self, re: &mut [f64], im: &mut [f64], inverse: bool, rows: usize) {
        self.rows(re, im, inverse, rows);
        self.columns(re, im, inverse, self.py);
    }

    /// 1-D transforms of the first `rows` rows.
    fn rows(&self, re: &mut [f64], im: &mut [f64], inverse: bool, rows: usize) {
        let px = self.px;
        for j in 0..rows {
            let r = j * px..(j + 1) * px;
            fft(&mut re[r.clone()], &mut im[r], &self.twiddles_x, inverse);
        }
    }

    /// 1-D transforms of every column, writing back only its first `keep` entries.
    fn columns(&self, re: &mut [f64], im: &mut [f64], inverse: bool, keep: usize) {
        let (px, py) = (self.px, self.py);
        let (mut cr, mut ci) = (vec![0.0; py], vec![0.0; py]);
        for i in 0..px {
            for j in 0..py {
                cr[j] = re[j * px + i];
                ci[j] = im[j * px + i];
            }
            fft(&mut cr, &mut ci, &self.twiddles_y, inverse);
            for j in 0..keep {
                re[j * px + i] = cr[j];
                im[j * px + i] = ci[j];
            }
        }
    }

    /// u = K ∗ f, written into `out` (length nx·ny); f's boundary nodes are ignored.
    pub fn apply(&self, f: &[f64], out: &mut [f64]) {
        let (nx, ny, px, py) = (self.nx, self.ny, self.px, self.py);
        assert!(f.len() == nx * ny && out.len() == nx * ny);
        let (mut re, mut im) = (vec![0.0; px * py], vec![0.0; px * py]);
        for j in 1..ny - 1 {
            re[j * px + 1..j * px + nx - 1].copy_from_slice(&f[j * nx + 1..j * nx + nx - 1]);
        }
        // Forward: rows, then columns (only rows < ny are non-zero).
        self.transform(&mut re, &mut im, false, ny);
        for k in 0..px * py {
            let (a, b) = (re[k], im[k]);
            let (c, d) = (self.spectrum_re[k], self.spectrum_im[k]);
            re[k] = a * c - b * d;
            im[k] = a * d + b * c;
        }
        // Inverse: columns first, then only the rows that are wanted.
        self.columns(&mut re, &mut im, true, ny);
        self.rows(&mut re, &mut im, true, ny);
        for j in 0..ny {
            out[j * nx..(j + 1) * nx].copy_from_slice(&re[j * px..j * px + nx]);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fft_convolution_equals_the_direct_sum() {
        let (nx, ny) = (9, 6);
        let kernel = |di: i64, dj: i64| {
            1.0 / (1.0 + (di * di) as f64 + 0.5 * (dj * dj) as f64) + 0.1 * di as f64
        };
        let c = Convolution2d::new(nx, ny, kernel);
        let f: Vec<f64> = (0..nx * ny).map(|k| ((k * 37) % 11) as f64 - 4.0).collect();
        let mut out = vec![0.0; nx * ny];
        c.apply(&f, &mut out);
        for j in 0..ny {
            for i in 0..nx {
                let mut direct = 0.0;
                for l in 1..ny - 1 {
                    for k in 1..nx - 1 {
                        direct += kernel(i as i64 - k as i64, j as i64 - l as i64) * f[l * nx + k];
                    }
                }
                assert!(
                    (out[j * nx + i] - direct).abs() < 1e-12,
                    "({i}, {j}): {} vs {direct}",
                    out[j * nx + i]
                );
            }
        }
    }
}
