//! Isothermal line-contact EHL by a fully coupled Newton solve.
//!
//! Dimensionless form (Venner & Lubrecht 2000, ch. 8): X = x/b, P = p/p_h, H = hR_x/b², with b
//! the Hertz half-width and p_h the Hertz pressure. The unknowns are P at the grid nodes and the
//! film constant H₀:
//!
//! - Reynolds: d/dX(ε dP/dX) − d(ρ̄H)/dX = 0, ε = ρ̄H³/(η̄λ̄), λ̄ = 12ūη₀R_x²/(b³p_h), with
//!   P = 0 at both ends of the domain and P ≥ 0 everywhere: where the operator would pull P
//!   below zero the node is cavitated (P = 0). The complementarity is solved as a primal–dual
//!   active set inside the Newton loop.
//! - Film: H(X) = H₀ + X²/2 − (1/π)∫ ln|X − X′| P(X′) dX′ (the constant of the logarithm is
//!   part of H₀).
//! - Load: ∫ P dX = π/2.
//!
//! Discretisation: node-centred finite volumes on a grid clustered at the inlet edge (X = −1),
//! where the film is formed, and at the outlet constriction and pressure spike (X ≈ 1); ε at the
//! faces as the mean of the nodes; the Couette flux ρ̄H at a face by second-order upwind
//! extrapolation (first-order at the first face); the deformation integral exact for pressure
//! constant over each cell ([`line_log_cell`](crate::numerics::half_space::line_log_cell)), with the Hertz pressure's part taken
//! analytically; its product with a field by the fast multipole method of [`LineLogInfluence`]
//! (O(n) work and storage where the dense matrix is n²). The Newton direction solves the exact
//! Jacobian by GMRES, matrix-free ([`Jacobian`]); each step is damped until the residual falls
//! ([`newton::solve`] under the solver driver).

use std::f64::consts::{FRAC_PI_2, PI};

use nalgebra::DMatrix;

use super::fluid::Fluid;
use super::formulas::MoesAsymptotes;
use crate::fidelity::{IterationUnit, SolverReport};
use crate::numerics::band_lu::{Band, BandLu};
use crate::numerics::dense;
use crate::numerics::driver::{Budget, Driver, Stopped};
use crate::numerics::gmres;
use crate::numerics::interpolate::linear;
use crate::numerics::log_fmm::LineLogInfluence;
use crate::numerics::newton::{self, LineSearch, NewtonSystem};

/// Films below this (dimensionless) are treated as this in ε, so that a Newton iterate that
/// briefly interpenetrates the surfaces cannot make ε negative.
const FILM_FLOOR: f64 = 1e-12;
const MAX_NEWTON: u32 = 80;
/// Halve the step until the scaled residual falls strictly; at the seventh halving (1/128)
/// take it anyway, so that the iteration keeps moving (Venner's damped Newton).
const LINE_SEARCH: LineSearch = LineSearch {
    max_halvings: 7,
    take_shortest: true,
};
/// Converged when the scaled residual (a pressure change, in units of p_h) is below this.
const TOLERANCE: f64 = 1e-10;
/// The Newton direction's relative linear residual: the scaled residual of the iterate, kept
/// within these (inexact Newton with a forcing proportional to the residual: quadratic).
const FORCING_MAX: f64 = 1e-3;
const FORCING_MIN: f64 = 1e-12;
/// Half-width of the deformation band kept in the preconditioner ([`BandedPart`]).
/// Measured on the accuracy bench's cases (M = 20 … 1000, L = 10, 128 … 2048 cells): GMRES
/// took about 8–28 iterations per Newton step at 2048 cells with 8, 3–14 with 64; 32 was the
/// fastest overall (the band LU costs n·b² and each of its solves n·b).
const PRECONDITIONER_BAND: usize = 32;
/// Half-width of the influence entries kept exact beside the operator: the preconditioner's band
/// widened by the reach of a row's film coefficients (nodes i − 2 … i + 1).
const KERNEL_BAND: usize = PRECONDITIONER_BAND + 3;
/// GMRES: Krylov vectors per cycle, and iterations before the dense fallback.
const GMRES_RESTART: usize = 60;
const GMRES_MAX_ITERATIONS: usize = 240;

/// The problem in dimensionless form.
#[derive(Debug, Clone, Copy)]
pub struct LineProblem {
    pub fluid: Fluid,
    /// λ̄ = 12ūη₀R_x²/(b³p_h) = 3π²/(8M²).
    pub lambda: f64,
    /// Domain ends X_a < 0 < X_b.
    pub inlet: f64,
    pub outlet: f64,
    /// A first guess of the central film H_c, for the start from the Hertz pressure and for
    /// the width of the grid's clusters.
    pub film_guess: f64,
}

/// A converged field on one grid.
#[derive(Debug, Clone)]
pub struct LineSolution {
    pub x: Vec<f64>,
    pub pressure: Vec<f64>,
    pub film: Vec<f64>,
    pub h0: f64,
    /// The driver's report of the Newton solve (residual: the scaled residual at the last
    /// iterate).
    pub report: SolverReport,
}

/// Everything the residual and the Jacobian need at one iterate.
struct State {
    film: Vec<f64>,
    density: Vec<f64>,
    density_slope: Vec<f64>,
    /// ε at the nodes and its local slope d ε/dP (through η̄ and ρ̄).
    epsilon: Vec<f64>,
    epsilon_slope: Vec<f64>,
    /// Reynolds residuals at the nodes (0 at the two boundary nodes).
    residual: Vec<f64>,
    /// |∂Rᵢ/∂Pᵢ|: the scale of the active-set test and of the convergence measure.
    diagonal: Vec<f64>,
    load_error: f64,
}

struct Grid {
    x: Vec<f64>,
    /// Cell widths (the control volumes; half cells at the two ends).
    volume: Vec<f64>,
    /// Influence coefficients K_{ij}: the operator, and the entries |i − j| ≤ [`KERNEL_BAND`]
    /// row by row (the preconditioner's and the diagonal's).
    kernel: LineLogInfluence,
    near: Vec<f64>,
    /// The film at zero H₀ and zero pressure, corrected for the discretisation error of the
    /// Hertz part: X²/2 − D_H(X) + (1/π)Σⱼ K_{ij} P_H(Xⱼ). The Hertz pressure's deformation
    /// D_H is taken exactly and only the difference P − P_H goes through the discrete kernel.
    base: Vec<f64>,
    /// Couette flux at the face between nodes i and i + 1, as weights on ρ̄H at (i, i − 1).
    upwind: Vec<[f64; 2]>,
}

impl Grid {
    fn new(problem: &LineProblem, cells: usize) -> Self {
        let x = clustered_nodes(problem, cells);
        let n = x.len();
        let mut faces = Vec::with_capacity(n + 1);
        faces.push(x[0]);
        faces.extend(x.windows(2).map(|w| 0.5 * (w[0] + w[1])));
        faces.push(x[n - 1]);
        let volume: Vec<f64> = faces.windows(2).map(|f| f[1] - f[0]).collect();
        let kernel = LineLogInfluence::new(&x, &faces);
        // Row i holds cells i − KERNEL_BAND ..= i + KERNEL_BAND, zero beyond the ends: taken
        // from the operator's exact blocks where they hold them (on a small grid, all), the
        // rest computed.
        let width = 2 * KERNEL_BAND + 1;
        let mut kept = vec![None; n * width];
        for (rows, columns, block) in kernel.exact_blocks() {
            for (i, entries) in rows.zip(block.chunks_exact(columns.len())) {
                for (j, &k) in columns.clone().zip(entries) {
                    if i.abs_diff(j) <= KERNEL_BAND {
                        kept[i * width + j + KERNEL_BAND - i] = Some(k);
                    }
                }
            }
        }
        let near = kept
            .into_iter()
            .enumerate()
            .map(|(at, k)| {
                let (i, j) = (
                    at / width,
                    (at / width + at % width).checked_sub(KERNEL_BAND),
                );
                match (k, j) {
                    (Some(k), _) => k,
                    (None, Some(j)) if j < n => kernel.entry(i, j),
                    _ => 0.0,
                }
            })
            .collect();
        let hertz: Vec<f64> = x.iter().map(|&x| hertz_pressure(x)).collect();
        let base = kernel
            .apply(&hertz)
            .iter()
            .zip(&x)
            .map(|(discrete, &x)| 0.5 * x * x - hertz_deformation(x) + discrete / PI)
            .collect();
        let upwind = (0..n)
            .map(|i| {
                if i == 0 || i == n - 1 {
                    [1.0, 0.0]
                } else {
                    // Linear extrapolation of ρ̄H from nodes i − 1, i to the face.
                    let r = 0.5 * (x[i + 1] - x[i]) / (x[i] - x[i - 1]);
                    [1.0 + r, -r]
                }
            })
            .collect();
        Grid {
            x,
            volume,
            kernel,
            near,
            base,
            upwind,
        }
    }

    fn nodes(&self) -> usize {
        self.x.len()
    }

    /// K_{ij}: from the kept band, or computed.
    fn influence(&self, i: usize, j: usize) -> f64 {
        if i.abs_diff(j) <= KERNEL_BAND {
            self.near[i * (2 * KERNEL_BAND + 1) + j + KERNEL_BAND - i]
        } else {
            self.kernel.entry(i, j)
        }
    }

    /// H at every node.
    fn film(&self, pressure: &[f64], h0: f64) -> Vec<f64> {
        self.kernel
            .apply(pressure)
            .iter()
            .zip(&self.base)
            .map(|(deformation, base)| h0 + base - deformation / PI)
            .collect()
    }

    /// The net Couette outflow of node i's cell, c_e − c_w, as weights on ρ̄H at i, i − 1, i − 2.
    fn wedge(&self, i: usize) -> [(usize, f64); 3] {
        let [east_i, east_im1] = self.upwind[i];
        let [west_im1, west_im2] = self.upwind[i - 1];
        [
            (i, east_i),
            (i - 1, east_im1 - west_im1),
            (i.saturating_sub(2), -west_im2),
        ]
    }
}

/// Nodes from `inlet` to `outlet`, their density raised threefold over the Hertz zone and
/// sharply at its two edges, over a width that follows the expected film: the inlet meniscus
/// region where the film forms is about H_c^(2/3) wide (the Hertz gap outside the contact grows
/// as (|X| − 1)^(3/2)), and so is the outlet constriction with its pressure spike.
fn clustered_nodes(problem: &LineProblem, cells: usize) -> Vec<f64> {
    let width = (2.0 * problem.film_guess.powf(2.0 / 3.0)).clamp(0.01, 0.3);
    let span = problem.outlet - problem.inlet;
    let contact_boost = 2.0;
    let edge_amplitude = 0.3 * (span + 2.2 * contact_boost) / (width * PI.sqrt());
    let density = |x: f64| {
        let gauss = |c: f64| (-((x - c) / width).powi(2)).exp();
        1.0 + contact_boost * smooth_box(x, 1.1)
            + edge_amplitude * (gauss(-1.0) + gauss(1.0 - 0.5 * width))
    };
    // Cumulative density on a fine uniform sample, inverted at equal increments.
    let samples = 40 * cells + 2000;
    let step = span / samples as f64;
    let mut cumulative = Vec::with_capacity(samples + 1);
    cumulative.push(0.0);
    for k in 0..samples {
        let a = problem.inlet + k as f64 * step;
        let last = cumulative[k];
        cumulative.push(last + 0.5 * step * (density(a) + density(a + step)));
    }
    let total = cumulative[samples];
    let mut nodes = Vec::with_capacity(cells + 1);
    let mut k = 0;
    for i in 0..=cells {
        let target = total * i as f64 / cells as f64;
        while k + 1 < samples && cumulative[k + 1] < target {
            k += 1;
        }
        let t = ((target - cumulative[k]) / (cumulative[k + 1] - cumulative[k])).clamp(0.0, 1.0);
        nodes.push(problem.inlet + (k as f64 + t) * step);
    }
    nodes[0] = problem.inlet;
    nodes[cells] = problem.outlet;
    nodes
}

/// ≈ 1 for |x| < half_width, ≈ 0 outside, with smooth shoulders.
fn smooth_box(x: f64, half_width: f64) -> f64 {
    0.5 * (1.0 - ((x.abs() - half_width) / 0.05).tanh())
}

impl LineProblem {
    /// The problem at Moes' (M, L) for `fluid`: λ̄ = 3π²/(8M²), the first central-film guess
    /// H_c = πH_Moes/(8M) from Moes' asymptotes, and the domain it sets — the inlet at √(60H_c)
    /// but at least 4.5 half-widths upstream, the outlet at √(3H_c) but at least 1.5.
    #[must_use]
    pub fn at_moes(fluid: Fluid, m: f64, l: f64) -> Self {
        let film_guess = PI * MoesAsymptotes::new(m, l).central() / (8.0 * m);
        LineProblem {
            fluid,
            lambda: 3.0 * PI * PI / (8.0 * m * m),
            inlet: -(60.0 * film_guess).sqrt().max(4.5),
            outlet: (3.0 * film_guess).sqrt().max(1.5),
            film_guess,
        }
    }

    fn state(&self, grid: &Grid, pressure: &[f64], h0: f64) -> State {
        let n = grid.nodes();
        let film = grid.film(pressure, h0);
        let mut density = vec![1.0; n];
        let mut density_slope = vec![0.0; n];
        let mut epsilon = vec![0.0; n];
        let mut epsilon_slope = vec![0.0; n];
        for i in 0..n {
            let (rho, rho_slope) = self.fluid.density(pressure[i]);
            let (ln_eta, ln_eta_slope) = self.fluid.ln_viscosity(pressure[i]);
            let h = film[i].max(FILM_FLOOR);
            density[i] = rho;
            density_slope[i] = rho_slope;
            epsilon[i] = rho * h * h * h * (-ln_eta).exp() / self.lambda;
            epsilon_slope[i] = epsilon[i] * (rho_slope / rho - ln_eta_slope);
        }
        let mut residual = vec![0.0; n];
        let mut diagonal = vec![1.0; n];
        for i in 1..n - 1 {
            let east = 0.5 * (epsilon[i] + epsilon[i + 1]) / (grid.x[i + 1] - grid.x[i]);
            let west = 0.5 * (epsilon[i - 1] + epsilon[i]) / (grid.x[i] - grid.x[i - 1]);
            let poiseuille =
                east * (pressure[i + 1] - pressure[i]) - west * (pressure[i] - pressure[i - 1]);
            let wedge: f64 = grid
                .wedge(i)
                .iter()
                .map(|&(m, w)| w * density[m] * film[m])
                .sum();
            residual[i] = poiseuille - wedge;
            let (_, w_self) = grid.wedge(i)[0];
            diagonal[i] = east + west - w_self * density[i] * grid.influence(i, i) / PI;
        }
        let load_error = grid
            .volume
            .iter()
            .zip(pressure)
            .map(|(v, p)| v * p)
            .sum::<f64>()
            - FRAC_PI_2;
        State {
            film,
            density,
            density_slope,
            epsilon,
            epsilon_slope,
            residual,
            diagonal,
            load_error,
        }
    }

    /// Nodes whose Gauss–Seidel value would not be positive: the cavitated set.
    fn cavitated(state: &State, pressure: &[f64]) -> Vec<bool> {
        let n = pressure.len();
        (0..n)
            .map(|i| {
                i == 0 || i == n - 1 || pressure[i] + state.residual[i] / state.diagonal[i] <= 0.0
            })
            .collect()
    }

    /// The scaled residual: Reynolds residuals over |∂R/∂P| at pressurised nodes, the
    /// complementarity violation at cavitated ones, and the relative load error.
    fn merit(state: &State, pressure: &[f64]) -> f64 {
        let n = pressure.len();
        // min(P, −s) = 0 with s the Gauss–Seidel increment: P ≥ 0, s ≤ 0, P·s = 0.
        (1..n - 1)
            .map(|i| {
                pressure[i]
                    .min(-state.residual[i] / state.diagonal[i])
                    .abs()
            })
            .fold((state.load_error / FRAC_PI_2).abs(), f64::max)
    }

    /// The Newton system over the unknowns [P₁ … P_{n−2}, H₀] in its parts: the local
    /// coefficients of each row, its film coefficients (the dense part is their product with
    /// the influence matrix), the H₀ column, the load row (the cell widths) and the right-hand
    /// side.
    fn jacobian(
        &self,
        grid: &Grid,
        state: &State,
        pressure: &[f64],
        cavitated: &[bool],
    ) -> Jacobian {
        let n = grid.nodes();
        let unknowns = n - 1; // interior nodes n − 2, plus H₀
        let mut local = vec![[0.0; 4]; n - 2];
        let mut film = vec![[(0, 0.0); 6]; n];
        let mut h0 = vec![0.0; n - 2];
        let mut rhs = vec![0.0; unknowns];
        let mut scale = vec![1.0; unknowns];
        // ∂ε_m/∂H_m (zero where the film is at its floor).
        let epsilon_per_film: Vec<f64> = (0..n)
            .map(|m| {
                if state.film[m] > FILM_FLOOR {
                    3.0 * state.epsilon[m] / state.film[m]
                } else {
                    0.0
                }
            })
            .collect();
        for i in 1..n - 1 {
            let row = i - 1;
            if cavitated[i] {
                local[row][2] = 1.0;
                rhs[row] = -pressure[i];
                continue;
            }
            let dx_e = grid.x[i + 1] - grid.x[i];
            let dx_w = grid.x[i] - grid.x[i - 1];
            let east = 0.5 * (state.epsilon[i] + state.epsilon[i + 1]) / dx_e;
            let west = 0.5 * (state.epsilon[i - 1] + state.epsilon[i]) / dx_w;
            // Half the pressure gradients at the faces: dRᵢ/dε_m of the face means.
            let grad_e = 0.5 * (pressure[i + 1] - pressure[i]) / dx_e;
            let grad_w = 0.5 * (pressure[i] - pressure[i - 1]) / dx_w;
            // Slot m + 2 − i holds node m (m = i − 2 … i + 1); the boundary nodes are not
            // unknowns.
            let mut add = |m: usize, c: f64| {
                if (1..n - 1).contains(&m) {
                    local[row][m + 2 - i] += c;
                }
            };
            let coeffs = &mut film[i];
            // dQᵢ/dε_m for m = i − 1, i, i + 1, through the film and locally through P_m.
            for (slot, (m, c)) in [(i - 1, -grad_w), (i, grad_e - grad_w), (i + 1, grad_e)]
                .into_iter()
                .enumerate()
            {
                coeffs[slot] = (m, c * epsilon_per_film[m]);
                add(m, c * state.epsilon_slope[m]);
            }
            for (m, c) in [(i - 1, west), (i, -(east + west)), (i + 1, east)] {
                add(m, c);
            }
            for (slot, (m, w)) in grid.wedge(i).into_iter().enumerate() {
                coeffs[3 + slot] = (m, -w * state.density[m]);
                add(m, -w * state.density_slope[m] * state.film[m]);
            }
            h0[row] = coeffs.iter().map(|&(_, c)| c).sum();
            rhs[row] = -state.residual[i];
            scale[row] = state.diagonal[i];
        }
        rhs[unknowns - 1] = -state.load_error;
        scale[unknowns - 1] = FRAC_PI_2;
        Jacobian {
            local,
            film,
            h0,
            rhs,
            scale,
        }
    }

    /// Solve on `cells` cells, starting from `start` (interpolated onto this grid) or from the
    /// Hertz pressure with the guessed film: damped Newton under the solver driver (at most
    /// [`MAX_NEWTON`] steps, the deadline polled before each), the step halved until the scaled
    /// residual falls and taken anyway at 1/128 ([`LINE_SEARCH`]). The report counts the Newton
    /// steps and the trial points of the line searches.
    pub fn solve(
        &self,
        cells: usize,
        start: Option<&LineSolution>,
        budget: &Budget,
    ) -> Result<LineSolution, Stopped> {
        let grid = Grid::new(self, cells);
        let n = grid.nodes();
        let (mut pressure, h0) = match start {
            Some(s) => (
                grid.x
                    .iter()
                    .map(|&x| linear(&s.x, &s.pressure, x))
                    .collect::<Vec<_>>(),
                s.h0,
            ),
            None => self.hertz_start(&grid),
        };
        pressure[0] = 0.0;
        pressure[n - 1] = 0.0;
        let driver = Driver::new(
            "newton_finite_volume",
            IterationUnit::NewtonSteps,
            MAX_NEWTON,
            budget,
        );
        let system = LineNewton {
            problem: self,
            grid: &grid,
        };
        let run = newton::solve(&system, (pressure, h0), TOLERANCE, LINE_SEARCH, &driver)?;
        let ((pressure, h0), at) = run.value;
        Ok(LineSolution {
            x: grid.x,
            pressure,
            film: at.state.film,
            h0,
            report: run.report,
        })
    }

    /// The Hertz pressure √(1 − X²) and the H₀ that puts the guessed film at X = 0.
    fn hertz_start(&self, grid: &Grid) -> (Vec<f64>, f64) {
        let pressure: Vec<f64> = grid.x.iter().map(|&x| hertz_pressure(x)).collect();
        let centre = linear(&grid.x, &grid.film(&pressure, 0.0), 0.0);
        (pressure, self.film_guess - centre)
    }
}

/// The Newton matrix of one iterate, in parts ([`LineProblem::jacobian`]): row i − 1 of
/// interior node i is Σ_{m = i−2}^{i+1} local·P_m + Σ_m film_m·(H₀ − (1/π)Σ_k K_{mk}P_k), and
/// the last row the load Σ_k V_k P_k. Its product costs one influence product (O(n)),
/// its factorisation is never needed: the direction comes from GMRES ([`gmres`]) on the
/// product, preconditioned by the [`BandedPart`].
struct Jacobian {
    /// Per row: the coefficients on P at nodes i − 2 … i + 1 at fixed film; a cavitated row is
    /// 1 on its own node.
    local: Vec<[f64; 4]>,
    /// Per node i: ∂Rᵢ/∂H_m for the (up to six) nodes m whose film enters Rᵢ; none where i is
    /// cavitated.
    film: Vec<[(usize, f64); 6]>,
    /// ∂Rᵢ/∂H₀ per row: the sum of its film coefficients.
    h0: Vec<f64>,
    rhs: Vec<f64>,
    /// Each row's unit in the merit ([`LineProblem::merit`]): |∂Rᵢ/∂Pᵢ| at pressurised nodes,
    /// 1 at cavitated ones, π/2 for the load. GMRES solves the rows divided by it, so that its
    /// residual norm weighs the rows as the Newton iteration's convergence test does.
    scale: Vec<f64>,
}

impl Jacobian {
    /// The dense-part entry of row `i` (a node) in the column of node `k`: −(1/π)Σ_m film_m K_{mk}.
    fn deformation(&self, grid: &Grid, i: usize, k: usize) -> f64 {
        // A cavitated row's coefficients are all zero: no entry need be computed.
        -self.film[i]
            .iter()
            .filter(|&&(_, c)| c != 0.0)
            .map(|&(m, c)| c * grid.influence(m, k))
            .sum::<f64>()
            / PI
    }

    /// out = J v.
    fn apply(&self, grid: &Grid, v: &[f64], out: &mut [f64]) {
        let n = grid.nodes();
        let mut full = vec![0.0; n];
        full[1..n - 1].copy_from_slice(&v[..n - 2]);
        let h0 = v[n - 2];
        // The film change at every node: H₀ − (1/π)Σ_k K_{mk}P_k.
        let film: Vec<f64> = grid
            .kernel
            .apply(&full)
            .iter()
            .map(|d| h0 - d / PI)
            .collect();
        for i in 1..n - 1 {
            let local: f64 = (0..4)
                .filter(|&s| i + s >= 2)
                .map(|s| self.local[i - 1][s] * full[i + s - 2])
                .sum();
            let through_film: f64 = self.film[i].iter().map(|&(m, c)| c * film[m]).sum();
            out[i - 1] = local + through_film;
        }
        out[n - 2] = grid.volume[1..n - 1]
            .iter()
            .zip(&full[1..n - 1])
            .map(|(w, p)| w * p)
            .sum();
    }

    /// The whole matrix, for the direct solve GMRES falls back on.
    fn dense(&self, grid: &Grid) -> DMatrix<f64> {
        let n = grid.nodes();
        let unknowns = n - 1;
        DMatrix::from_fn(unknowns, unknowns, |row, col| {
            if row == unknowns - 1 {
                return if col < unknowns - 1 {
                    grid.volume[col + 1]
                } else {
                    0.0
                };
            }
            if col == unknowns - 1 {
                return self.h0[row];
            }
            let (i, k) = (row + 1, col + 1);
            let local = if k + 2 >= i && k <= i + 1 {
                self.local[row][k + 2 - i]
            } else {
                0.0
            };
            local + self.deformation(grid, i, k)
        })
    }

    /// The direction: [`Jacobian::krylov`] to the relative residual `forcing` (Dembo,
    /// Eisenstat & Steihaug's inexact Newton: a forcing that falls with the residual keeps the
    /// convergence quadratic); the dense LU of the whole matrix when GMRES does not get there
    /// (or the banded part is singular).
    fn solve(&self, grid: &Grid, forcing: f64) -> Option<Vec<f64>> {
        match self.krylov(grid, forcing) {
            Some((step, outcome)) if outcome.converged && step.iter().all(|v| v.is_finite()) => {
                Some(step)
            }
            _ => dense::solve_large(self.dense(grid), &self.rhs),
        }
    }

    /// GMRES on the rows over their [`Jacobian::scale`] until the linear residual is
    /// `tolerance` of the right-hand side's, right preconditioned by the [`BandedPart`];
    /// `None` when that is singular.
    fn krylov(&self, grid: &Grid, tolerance: f64) -> Option<(Vec<f64>, gmres::Outcome)> {
        let band = BandedPart::new(self, grid)?;
        let b: Vec<f64> = self
            .rhs
            .iter()
            .zip(&self.scale)
            .map(|(r, s)| r / s)
            .collect();
        let apply = |v: &[f64], out: &mut [f64]| {
            self.apply(grid, v, out);
            out.iter_mut().zip(&self.scale).for_each(|(o, s)| *o /= s);
        };
        let settings = gmres::Settings {
            tolerance,
            restart: GMRES_RESTART,
            max_iterations: GMRES_MAX_ITERATIONS,
        };
        Some(gmres::solve(&b, apply, |v| band.solve(v), settings))
    }
}

/// The preconditioner: the Jacobian's rows over their [`Jacobian::scale`] (the system GMRES
/// solves), with the dense part cut to the band |i − k| ≤ [`PRECONDITIONER_BAND`] (the local
/// stencil and the strongest deformation couplings, those of nearby nodes), bordered by the H₀
/// column and the load row; solved by a band LU (on the scaled rows, whose pivots are of one
/// order) and block elimination of the border: for M = [A c; dᵀ 0], H₀ = (dᵀA⁻¹r − s)/(dᵀA⁻¹c)
/// and P = A⁻¹(r − cH₀). O(n) to build and to apply.
struct BandedPart {
    band: BandLu,
    /// A⁻¹c, and the load row d.
    inverse_h0: Vec<f64>,
    load: Vec<f64>,
    /// dᵀA⁻¹c.
    schur: f64,
}

impl BandedPart {
    fn new(jacobian: &Jacobian, grid: &Grid) -> Option<Self> {
        let n = grid.nodes();
        let w = PRECONDITIONER_BAND;
        let scale = &jacobian.scale;
        let mut a = Band::zeros(n - 2, w, w);
        for i in 1..n - 1 {
            let row = i - 1;
            for s in 0..4 {
                // Node i + s − 2, when an unknown (1 … n − 2).
                if (3..=n).contains(&(i + s)) {
                    a.add(row, i + s - 3, jacobian.local[row][s] / scale[row]);
                }
            }
            for k in i.saturating_sub(w).max(1)..=(i + w).min(n - 2) {
                a.add(row, k - 1, jacobian.deformation(grid, i, k) / scale[row]);
            }
        }
        let band = a.lu().ok()?;
        let mut inverse_h0: Vec<f64> = jacobian.h0.iter().zip(scale).map(|(c, s)| c / s).collect();
        band.solve(&mut inverse_h0);
        let load: Vec<f64> = grid.volume[1..n - 1]
            .iter()
            .map(|v| v / scale[n - 2])
            .collect();
        let schur = dense::dot(&load, &inverse_h0);
        (schur.is_finite() && schur != 0.0).then_some(BandedPart {
            band,
            inverse_h0,
            load,
            schur,
        })
    }

    /// v ← M⁻¹v.
    fn solve(&self, v: &mut [f64]) {
        let m = v.len() - 1;
        let (pressure, h0) = v.split_at_mut(m);
        self.band.solve(pressure);
        let step = (dense::dot(&self.load, pressure) - h0[0]) / self.schur;
        pressure
            .iter_mut()
            .zip(&self.inverse_h0)
            .for_each(|(p, z)| *p -= z * step);
        h0[0] = step;
    }
}

/// One iterate's state and its scaled residual ([`LineProblem::merit`]).
struct Iterate {
    state: State,
    merit: f64,
}

/// The coupled Newton system on one grid: unknowns (P at the nodes, H₀); the direction by
/// preconditioned GMRES on the exact Jacobian ([`Jacobian::solve`]).
struct LineNewton<'a> {
    problem: &'a LineProblem,
    grid: &'a Grid,
}

impl NewtonSystem for LineNewton<'_> {
    type Point = (Vec<f64>, f64);
    type Eval = Iterate;
    type Step = Vec<f64>;

    fn evaluate(&self, (pressure, h0): &(Vec<f64>, f64)) -> Iterate {
        let state = self.problem.state(self.grid, pressure, *h0);
        let merit = LineProblem::merit(&state, pressure);
        Iterate { state, merit }
    }

    fn residual(&self, at: &Iterate) -> f64 {
        at.merit
    }

    fn direction(&self, (pressure, _): &(Vec<f64>, f64), at: &Iterate) -> Option<Vec<f64>> {
        let cavitated = LineProblem::cavitated(&at.state, pressure);
        let jacobian = self
            .problem
            .jacobian(self.grid, &at.state, pressure, &cavitated);
        jacobian.solve(self.grid, at.merit.clamp(FORCING_MIN, FORCING_MAX))
    }

    /// The damped step, projected: P ≥ 0, and P = 0 at the two ends.
    fn advance(
        &self,
        (pressure, h0): &(Vec<f64>, f64),
        step: &Vec<f64>,
        t: f64,
    ) -> (Vec<f64>, f64) {
        let n = pressure.len();
        let trial: Vec<f64> = (0..n)
            .map(|i| {
                if i == 0 || i == n - 1 {
                    0.0
                } else {
                    (pressure[i] + t * step[i - 1]).max(0.0)
                }
            })
            .collect();
        (trial, h0 + t * step[n - 2])
    }

    /// A trial point is taken when its scaled residual is strictly below the current one.
    fn accepts(&self, here: &Iterate, trial: &Iterate, _t: f64, _slope: Option<f64>) -> bool {
        trial.merit < here.merit
    }
}

/// The Hertz line-contact pressure P_H = √(1 − X²) inside the contact, 0 outside.
fn hertz_pressure(x: f64) -> f64 {
    (1.0 - x * x).max(0.0).sqrt()
}

/// D_H(X) = (1/π)∫₋₁¹ ln|X − S| √(1 − S²) dS, exactly (Johnson 1985, §2.8 — the deformation of a
/// half-space under the Hertz line pressure): ½(X² − ½ − ln 2) for |X| ≤ 1, and
/// ½[X² − ½ − ln 2 − |X|√(X² − 1) + ln(|X| + √(X² − 1))] outside.
fn hertz_deformation(x: f64) -> f64 {
    let inside = 0.5 * (x * x - 0.5 - std::f64::consts::LN_2);
    let a = x.abs();
    if a <= 1.0 {
        inside
    } else {
        let root = (a * a - 1.0).sqrt();
        inside + 0.5 * ((a + root).ln() - a * root)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::calc::lubricant::model::PressureLaw;

    /// Moes' M = 200 with αp_h = 24 (Barus, Dowson–Higginson density) on the numerical room's
    /// shortest domain.
    fn problem() -> LineProblem {
        let film_guess = 0.01;
        LineProblem {
            fluid: Fluid {
                law: PressureLaw::Barus { alpha_1_pa: 2e-8 },
                eta0_pa_s: 0.05,
                hertz_pressure_pa: 1.2e9,
                compressible: true,
            },
            lambda: 3.0 * PI * PI / (8.0 * 200.0 * 200.0),
            inlet: -4.5,
            outlet: 1.5,
            film_guess,
        }
    }

    /// The Newton system of the 256-cell grid at the 128-cell solution (the iterate the level
    /// ladder starts from: cavitated outlet, pressure spike).
    fn system() -> (LineProblem, Grid, Vec<f64>, f64, State, Vec<bool>) {
        let problem = problem();
        let coarse = problem.solve(128, None, &Budget::unlimited()).unwrap();
        let grid = Grid::new(&problem, 256);
        let pressure: Vec<f64> = grid
            .x
            .iter()
            .map(|&x| linear(&coarse.x, &coarse.pressure, x))
            .collect();
        let state = problem.state(&grid, &pressure, coarse.h0);
        let cavitated = LineProblem::cavitated(&state, &pressure);
        (problem, grid, pressure, coarse.h0, state, cavitated)
    }

    #[test]
    fn the_jacobian_product_matches_differences_of_the_residual() {
        let (problem, grid, pressure, h0, state, cavitated) = system();
        assert!(cavitated.iter().filter(|&&c| c).count() > 10);
        let jacobian = problem.jacobian(&grid, &state, &pressure, &cavitated);
        let n = grid.nodes();
        // A smooth direction over the pressurised zone and a change of H₀.
        let mut v: Vec<f64> = (1..n - 1)
            .map(|i| {
                let x = grid.x[i];
                if pressure[i] > 0.0 {
                    (1.0 - x * x).max(0.0) * (1.0 + 0.3 * (5.0 * x).sin())
                } else {
                    0.0
                }
            })
            .collect();
        v.push(0.02);
        let mut product = vec![0.0; n - 1];
        jacobian.apply(&grid, &v, &mut product);
        let delta = 1e-6;
        let shifted = |t: f64| {
            let mut p = pressure.clone();
            for i in 1..n - 1 {
                p[i] += t * v[i - 1];
            }
            problem.state(&grid, &p, h0 + t * v[n - 2])
        };
        let (up, down) = (shifted(delta), shifted(-delta));
        for i in (1..n - 1).filter(|&i| !cavitated[i]) {
            let difference = (up.residual[i] - down.residual[i]) / (2.0 * delta);
            let tolerance = 1e-5 * (difference.abs() + state.diagonal[i]);
            assert!(
                (product[i - 1] - difference).abs() < tolerance,
                "row {i}: {} vs {difference}",
                product[i - 1]
            );
        }
        let load = (up.load_error - down.load_error) / (2.0 * delta);
        assert!(
            (product[n - 2] - load).abs() < 1e-8,
            "{} vs {load}",
            product[n - 2]
        );
    }

    #[test]
    fn the_krylov_direction_matches_the_dense_lu() {
        let (problem, grid, pressure, _, state, cavitated) = system();
        let jacobian = problem.jacobian(&grid, &state, &pressure, &cavitated);
        let direct = dense::solve_large(jacobian.dense(&grid), &jacobian.rhs).unwrap();
        // GMRES gets there itself (no fall-back to the dense LU).
        let (krylov, outcome) = jacobian.krylov(&grid, 1e-12).unwrap();
        assert!(outcome.converged, "{outcome:?}");
        let scale = direct.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for (k, d) in krylov.iter().zip(&direct) {
            assert!((k - d).abs() < 1e-8 * scale, "{k} vs {d}");
        }
    }

    #[test]
    fn hertz_deformation_matches_quadrature() {
        for &x in &[-3.0, -1.5, -1.0, -0.4, 0.0, 0.7, 1.0, 1.2, 4.0] {
            // Substituting S = sin φ removes the square-root endpoints; 20 000 midpoints.
            let n = 20_000;
            let sum: f64 = (0..n)
                .map(|k| {
                    let phi = -FRAC_PI_2 + (k as f64 + 0.5) * PI / n as f64;
                    let s = phi.sin();
                    (x - s).abs().ln() * phi.cos() * phi.cos() * PI / n as f64
                })
                .sum::<f64>()
                / PI;
            assert!(
                (hertz_deformation(x) - sum).abs() < 2e-4,
                "X = {x}: {} vs {sum}",
                hertz_deformation(x)
            );
        }
    }
}
