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
//! constant over each cell ([`line_log_influence`]), with the Hertz pressure's part taken
//! analytically. The Jacobian is exact (the deformation makes it dense) and is factorised by LU
//! with partial pivoting; each step is damped until the residual falls ([`newton::solve`] under
//! the solver driver).

use std::f64::consts::{FRAC_PI_2, PI};

use nalgebra::DMatrix;

use super::fluid::Fluid;
use crate::fidelity::{IterationUnit, SolverReport};
use crate::numerics::dense;
use crate::numerics::driver::{Budget, Driver, Stopped};
use crate::numerics::half_space::line_log_influence;
use crate::numerics::interpolate::linear;
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
    /// Influence coefficients K_{ij}, row-major.
    kernel: Vec<f64>,
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
        let kernel = line_log_influence(&x, &faces);
        let hertz: Vec<f64> = x.iter().map(|&x| hertz_pressure(x)).collect();
        let base = (0..n)
            .map(|i| {
                let row = &kernel[i * n..(i + 1) * n];
                let discrete: f64 = row.iter().zip(&hertz).map(|(k, p)| k * p).sum();
                0.5 * x[i] * x[i] - hertz_deformation(x[i]) + discrete / PI
            })
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
            base,
            upwind,
        }
    }

    fn nodes(&self) -> usize {
        self.x.len()
    }

    fn influence(&self, i: usize, j: usize) -> f64 {
        self.kernel[i * self.nodes() + j]
    }

    /// H at every node.
    fn film(&self, pressure: &[f64], h0: f64) -> Vec<f64> {
        let n = self.nodes();
        (0..n)
            .map(|i| {
                let row = &self.kernel[i * n..(i + 1) * n];
                let deformation: f64 = row.iter().zip(pressure).map(|(k, p)| k * p).sum();
                h0 + self.base[i] - deformation / PI
            })
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

    /// The Newton matrix and right-hand side over the unknowns [P₁ … P_{n−2}, H₀].
    fn newton_system(
        &self,
        grid: &Grid,
        state: &State,
        pressure: &[f64],
        cavitated: &[bool],
    ) -> (DMatrix<f64>, Vec<f64>) {
        let n = grid.nodes();
        let unknowns = n - 1; // interior nodes n − 2, plus H₀
        let h0_col = unknowns - 1;
        let mut jacobian = DMatrix::<f64>::zeros(unknowns, unknowns);
        let mut rhs = vec![0.0; unknowns];
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
        // Per row: ∂Rᵢ/∂H_m for the (up to six) nodes whose film enters Rᵢ; the dense part of
        // the Jacobian is Σ_m ∂Rᵢ/∂H_m · ∂H_m/∂P_k, filled column by column below.
        let mut film_coeffs: Vec<[(usize, f64); 6]> = vec![[(0, 0.0); 6]; n];
        for i in 1..n - 1 {
            let row = i - 1;
            if cavitated[i] {
                jacobian[(row, row)] = 1.0;
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
            let mut local = |m: usize, c: f64| {
                if (1..n - 1).contains(&m) {
                    jacobian[(row, m - 1)] += c;
                }
            };
            let coeffs = &mut film_coeffs[i];
            // dQᵢ/dε_m for m = i − 1, i, i + 1, through the film and locally through P_m.
            for (slot, (m, c)) in [(i - 1, -grad_w), (i, grad_e - grad_w), (i + 1, grad_e)]
                .into_iter()
                .enumerate()
            {
                coeffs[slot] = (m, c * epsilon_per_film[m]);
                local(m, c * state.epsilon_slope[m]);
            }
            for (m, c) in [(i - 1, west), (i, -(east + west)), (i + 1, east)] {
                local(m, c);
            }
            for (slot, (m, w)) in grid.wedge(i).into_iter().enumerate() {
                coeffs[3 + slot] = (m, -w * state.density[m]);
                local(m, -w * state.density_slope[m] * state.film[m]);
            }
            jacobian[(row, h0_col)] = coeffs.iter().map(|&(_, c)| c).sum();
            rhs[row] = -state.residual[i];
        }
        for k in 1..n - 1 {
            // Column-major storage: column k − 1 is contiguous.
            let column = &mut jacobian.as_mut_slice()[(k - 1) * unknowns..k * unknowns];
            for i in 1..n - 1 {
                if cavitated[i] {
                    continue;
                }
                let dense: f64 = film_coeffs[i]
                    .iter()
                    .map(|&(m, c)| c * grid.influence(m, k))
                    .sum();
                column[i - 1] -= dense / PI;
            }
        }
        for k in 1..n - 1 {
            jacobian[(h0_col, k - 1)] = grid.volume[k];
        }
        rhs[h0_col] = -state.load_error;
        (jacobian, rhs)
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

/// One iterate's state and its scaled residual ([`LineProblem::merit`]).
struct Iterate {
    state: State,
    merit: f64,
}

/// The coupled Newton system on one grid: unknowns (P at the nodes, H₀); the direction by LU
/// with partial pivoting of the dense Jacobian ([`dense::solve_large`]: the deformation makes it
/// dense, and it has up to 2048 unknowns).
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
        let (jacobian, rhs) = self
            .problem
            .newton_system(self.grid, &at.state, pressure, &cavitated);
        dense::solve_large(jacobian, &rhs)
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
