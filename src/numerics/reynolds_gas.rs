//! The compressible (isothermal, ideal-gas) Reynolds equation, solved by Newton.
//!
//! In dimensionless variables (P = p/p_a absolute, H = h/h_ref, x and y scaled by one length):
//!
//! ```text
//! ∂x(k ∂x P) + ∂y(k ∂y P) = Λ ∂x(P H),   k = H³P (1 + 6Kn/(P H)) = H³P + 6 Kn H²
//! ```
//!
//! (Khonsari & Booser Eqs. 11.3–11.10: the bearing number Λ and the first-order slip factor with
//! Kn = λ_a/h_ref; Kn = 0 is continuum flow). Steady films, and their first-order response to
//! a harmonic film motion ([`harmonic_response`]).
//!
//! **Scheme.** Vertex-centred finite volumes: the unknowns are nodal P, each node's control
//! volume balances the mass fluxes through its faces, so mass is conserved cell by cell. Along x
//! the flux f = Λ P H − k ∂x P is written for u = P H as f = a u − d ∂x u with d = k/H and
//! a = Λ + k H′/H² (the film part taken over a cell as d ln(H_e/H_w)/Δ, so that a uniform P
//! at Λ = 0 carries no flux), and discretised by the exponentially fitted (Scharfetter–Gummel,
//! Il'in–Allen–Southwell) flux f = (d/Δ)[B(−Pe) u_w − B(Pe) u_e], B(z) = z/(eᶻ − 1), Pe = a Δ/d: central
//! (second order) where the cell Péclet number is small, upwind where it is large. It is exact
//! for P H = const, the Λ → ∞ interior, so it stays stable and accurate at Λ = 1000 on grids
//! that are fine only in the boundary layers (the callers grade their grids; [`graded`]).
//! Across (y) there is no sliding and the flux is −k ∂y P, central. The first row is an edge
//! held at the boundary pressure; the last is a symmetry plane (half of a symmetric film) or a
//! second held edge (the whole width), as the problem's [`FarEdge`] says.
//!
//! **Newton.** The residual is the net outflow of every control volume; its Jacobian is
//! assembled analytically (the derivatives of the fitted flux through u, k and Pe) in band
//! storage and solved by band LU with partial pivoting ([`super::band_lu`]). Nodes are numbered
//! across first; a periodic x (a full journal) is numbered in cyclic order 0, n−1, 1, n−2, … so
//! that the wrap-around neighbour is as near as every other one (band 2× the column height),
//! instead of a bordered or Woodbury correction. Each Newton step is damped by halving until the
//! scaled residual falls ([`super::newton`]), and P is kept positive. At large Λ Newton starts
//! by continuation in Λ: Λ = 2, 8, 32, … up to the target, each solve starting from the last.
//! Every Newton run goes under the solver driver with the request's budget, and every
//! converged run counts one field solve.
//!
//! **Convergence.** The residual measure is the Jacobi-scaled residual max |Rᵢ/Jᵢᵢ| (a change of
//! P), against the tolerance (1e-10 by default). A start that already meets it still takes one
//! Newton step (the linear film) before the run converges: the scaled residual under-measures a
//! smooth error by the square of the spacing, so a weakly driven film's ambient field, or a
//! start interpolated from the half mesh, can meet the tolerance while carrying nothing or the
//! half mesh's answer.

use super::band_lu::{Band, BandLu, Unfactored};
use super::driver::{Budget, Driver, Stopped};
use super::newton::{self, LineSearch, NewtonSystem};
use crate::fidelity::{IterationUnit, SolverReport, StopReason};

/// The grid: nodes along x and across y.
#[derive(Debug, Clone, PartialEq)]
pub struct GasGrid {
    /// Node coordinates along x (the sliding direction), strictly increasing. Not periodic:
    /// the first and last nodes are held at the boundary pressure. Periodic: the last node is
    /// the first again (x[n] = x[0] + period) and mirrors it.
    pub x: Vec<f64>,
    /// Node coordinates across, strictly increasing from y[0] = 0, the edge held at the
    /// boundary pressure, to the far boundary at the last node: the symmetry plane (∂P/∂y = 0)
    /// or a second held edge, as the problem's [`FarEdge`] says. One node only: an infinitely
    /// wide film (no y flux).
    pub y: Vec<f64>,
    pub periodic: bool,
}

impl GasGrid {
    pub fn nx(&self) -> usize {
        self.x.len() - 1
    }
    pub fn ny(&self) -> usize {
        self.y.len() - 1
    }
    /// Index of node (i, j) in a field.
    pub fn at(&self, i: usize, j: usize) -> usize {
        i * self.y.len() + j
    }
    /// Width of node i's control volume along x.
    pub fn cv_x(&self, i: usize) -> f64 {
        let n = self.nx();
        let x = &self.x;
        if self.periodic {
            let period = x[n] - x[0];
            let (w, e) = match i {
                0 => (x[n - 1] - period, x[1]),
                _ if i == n => (x[n - 1], x[1] + period),
                _ => (x[i - 1], x[i + 1]),
            };
            let c = if i == n { x[0] + period } else { x[i] };
            0.5 * ((c - w) + (e - c))
        } else {
            match i {
                0 => 0.5 * (x[1] - x[0]),
                _ if i == n => 0.5 * (x[n] - x[n - 1]),
                _ => 0.5 * (x[i + 1] - x[i - 1]),
            }
        }
    }
    /// Height of row j's control volume (1 for an infinitely wide film).
    pub fn cv_y(&self, j: usize) -> f64 {
        let (n, y) = (self.ny(), &self.y);
        match j {
            _ if n == 0 => 1.0,
            0 => 0.5 * (y[1] - y[0]),
            _ if j == n => 0.5 * (y[n] - y[n - 1]),
            _ => 0.5 * (y[j + 1] - y[j - 1]),
        }
    }
    /// Quadrature weight of node (i, j) over the modelled area (trapezoid on the nodes; a
    /// periodic grid weighs its mirrored last column 0).
    pub fn weight(&self, i: usize, j: usize) -> f64 {
        if self.periodic && i == self.nx() {
            return 0.0;
        }
        self.cv_x(i) * self.cv_y(j)
    }
}

/// `2n` cells on [0, 1] clustered toward both ends: [`graded`]'s `n` cells toward 0 on [0, ½],
/// `finest` the end cell's length, and their mirror image on [½, 1] (a whole width whose two
/// edges both form boundary layers).
pub fn graded_both_ends(n: usize, finest: f64) -> Vec<f64> {
    let half = graded(n, 2.0 * finest, true);
    half.iter()
        .map(|v| 0.5 * v)
        .chain(half.iter().rev().skip(1).map(|v| 1.0 - 0.5 * v))
        .collect()
}

/// `n` cells on [0, 1] clustered toward 1 (toward 0 with `at_start`) so that the cell at that end
/// is about `finest` long: x(s) = tanh(δ s)/tanh δ, with δ solved from the end cell's length
/// (uniform when `finest` ≥ 1/n).
pub fn graded(n: usize, finest: f64, at_start: bool) -> Vec<f64> {
    let ds = 1.0 / n as f64;
    let ratio = finest / ds;
    let map = |delta: f64, s: f64| {
        if delta < 1e-9 {
            s
        } else {
            (delta * s).tanh() / delta.tanh()
        }
    };
    let delta = if ratio >= 1.0 {
        0.0
    } else {
        // End-cell length over ds, 1 − x(1 − ds) over ds, falls with δ: bisect on it.
        let end = |d: f64| (1.0 - map(d, 1.0 - ds)) / ds;
        let (mut lo, mut hi) = (0.0f64, 40.0f64);
        for _ in 0..100 {
            let mid = 0.5 * (lo + hi);
            if end(mid) > ratio {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    };
    let x: Vec<f64> = (0..=n).map(|k| map(delta, k as f64 * ds)).collect();
    if at_start {
        x.iter().rev().map(|v| 1.0 - v).collect()
    } else {
        x
    }
}

/// The boundary at the grid's last row (y at its largest).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum FarEdge {
    /// A symmetry plane, ∂P/∂y = 0: the grid holds half of a film symmetric about it (an
    /// aligned journal's mid-plane, a slider's centre line).
    #[default]
    Symmetry,
    /// A second edge held at the boundary pressure: the grid holds the whole width (a
    /// misaligned journal's film, antisymmetric in its tilt, has no symmetry plane). An
    /// infinitely wide film (one row) has no far edge: it is solved as without one.
    Held,
}

/// The coordinates the grid's x and y are.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Metric {
    /// Cartesian: x along the sliding, y across it.
    #[default]
    Cartesian,
    /// Polar, for a sector of a thrust runner turning toward +x: x is the angle θ (rad) and y the
    /// radius R (> 0), in the radius's scale, so that the balance is
    /// ∂θ(k/R ∂θP) + ∂R(R k ∂R P) = Λ R ∂θ(P H). Through a θ-face of row R the mass flux
    /// R(Λ P H − k/R² ∂θP) is 1/R times the Cartesian fitted flux at the bearing number Λ R²
    /// (the flux and its derivatives exactly, Péclet number included); a R-face's flux is the
    /// Cartesian one on a face R wide. Steady solves only ([`harmonic_response`] is
    /// Cartesian).
    Polar,
}

/// The film and the physics on a grid.
#[derive(Debug, Clone)]
pub struct GasProblem {
    /// Λ, the bearing number in this scaling (the coefficient of ∂x(PH)).
    pub bearing_number: f64,
    /// Kn = λ_a/h_ref of the slip factor (0: continuum).
    pub knudsen_number: f64,
    /// P held on the boundaries (1: ambient).
    pub boundary_pressure: f64,
    /// The last row: a symmetry plane ([`GasProblem::new`]'s default) or a held edge.
    pub far_edge: FarEdge,
    /// Cartesian ([`GasProblem::new`]'s default) or polar coordinates.
    pub metric: Metric,
    /// H at every node, indexed as [`GasGrid::at`].
    pub h_nodes: Vec<f64>,
    /// H at the x-faces: (i, j) is the face between nodes i and i+1 of row j.
    pub h_x_faces: Vec<f64>,
    /// H at the y-faces: (i, j) is the face between rows j and j+1 at column i.
    pub h_y_faces: Vec<f64>,
}

impl GasProblem {
    /// The film `h(x, y)` sampled on `grid`.
    pub fn new(
        grid: &GasGrid,
        bearing_number: f64,
        knudsen_number: f64,
        h: impl Fn(f64, f64) -> f64,
    ) -> Self {
        let (nx, ny1) = (grid.nx(), grid.y.len());
        let mut h_nodes = vec![0.0; (nx + 1) * ny1];
        let mut h_x_faces = vec![0.0; nx * ny1];
        let mut h_y_faces = vec![0.0; (nx + 1) * ny1.saturating_sub(1)];
        for i in 0..=nx {
            for j in 0..ny1 {
                h_nodes[grid.at(i, j)] = h(grid.x[i], grid.y[j]);
                if i < nx {
                    h_x_faces[i * ny1 + j] = h(0.5 * (grid.x[i] + grid.x[i + 1]), grid.y[j]);
                }
                if j + 1 < ny1 {
                    h_y_faces[i * (ny1 - 1) + j] = h(grid.x[i], 0.5 * (grid.y[j] + grid.y[j + 1]));
                }
            }
        }
        GasProblem {
            bearing_number,
            knudsen_number,
            boundary_pressure: 1.0,
            far_edge: FarEdge::Symmetry,
            metric: Metric::Cartesian,
            h_nodes,
            h_x_faces,
            h_y_faces,
        }
    }
}

/// B(z) = z/(eᶻ − 1), the Bernoulli function of the fitted flux (B(0) = 1).
fn bernoulli(z: f64) -> f64 {
    if z.abs() < 1e-6 {
        1.0 - 0.5 * z
    } else {
        z / z.exp_m1()
    }
}

/// B′(z).
fn bernoulli_slope(z: f64) -> f64 {
    if z.abs() < 1e-6 {
        -0.5 + z / 6.0
    } else {
        let b = bernoulli(z);
        let r = if z > 30.0 { 1.0 } else { z.exp() / z.exp_m1() };
        b * (1.0 / z - r)
    }
}

/// A face's flux f out of node a into node b, with its derivatives (∂f/∂p_a, ∂f/∂p_b), times
/// the face's `width`: added to a's residual and taken from b's, where each is an unknown.
fn scatter(
    r: &mut [f64],
    jac: &mut Band,
    (ia, ib): (Option<usize>, Option<usize>),
    (f, dfa, dfb): (f64, f64, f64),
    width: f64,
) {
    if let Some(ia) = ia {
        r[ia] += f * width;
        jac.add(ia, ia, dfa * width);
        if let Some(ib) = ib {
            jac.add(ia, ib, dfb * width);
        }
    }
    if let Some(ib) = ib {
        r[ib] -= f * width;
        jac.add(ib, ib, -dfb * width);
        if let Some(ia) = ia {
            jac.add(ib, ia, -dfa * width);
        }
    }
}

/// Mass flux through an x-face (per unit height), and its derivatives by P_w and P_e.
/// `dx` the node spacing, `hw`, `he` the node films, `hf` the face film.
#[allow(clippy::too_many_arguments)]
pub fn x_flux(
    lambda: f64,
    kn: f64,
    dx: f64,
    (pw, pe): (f64, f64),
    (hw, he): (f64, f64),
    hf: f64,
) -> (f64, f64, f64) {
    let pm = 0.5 * (pw + pe);
    let k = hf * hf * hf * pm + 6.0 * kn * hf * hf;
    let d = k / hf;
    // a = Λ + d (ln H)′ exactly (f = a u − d ∂x u is then −k ∂x P + Λ P H for any P), its
    // film part integrated over the cell: ln(H_e/H_w). With the old (H_e − H_w)/H_f, equal to
    // O(Δ³), a uniform P at Λ = 0 carried a spurious O(Δ²) flux, which as Λ → 0 (films of
    // O(Λ)) was an O(Δ²/Λ) error in the film's stiffness.
    let pe_number = lambda * dx * hf / k + (he / hw).ln();
    let (uw, ue) = (pw * hw, pe * he);
    let (bm, bp) = (bernoulli(-pe_number), bernoulli(pe_number));
    let s = bm * uw - bp * ue;
    let f = d / dx * s;
    let ds_dpe = -bernoulli_slope(-pe_number) * uw - bernoulli_slope(pe_number) * ue;
    let dpe_dk = -lambda * dx * hf / (k * k);
    let df_dk = s / (hf * dx) + d / dx * ds_dpe * dpe_dk;
    let dk_dp = 0.5 * hf * hf * hf;
    (
        f,
        d / dx * bm * hw + df_dk * dk_dp,
        -d / dx * bp * he + df_dk * dk_dp,
    )
}

/// Mass flux through a y-face (per unit width) from row s to row n, and its derivatives.
fn y_flux(kn: f64, dy: f64, (ps, pn): (f64, f64), hf: f64) -> (f64, f64, f64) {
    let pm = 0.5 * (ps + pn);
    let k = hf * hf * hf * pm + 6.0 * kn * hf * hf;
    let grad = (pn - ps) / dy;
    let dk = 0.5 * hf * hf * hf;
    (-k * grad, k / dy - grad * dk, -k / dy - grad * dk)
}

/// The unknowns' numbering: columns in band order, rows from the first unknown row.
struct Numbering {
    /// Band position of each node column (None: a held boundary column).
    column: Vec<Option<usize>>,
    /// First unknown row (0 for an infinitely wide film, 1 otherwise: row 0 is the edge).
    row0: usize,
    /// Unknown rows (the last row is one unless it is a held edge).
    rows: usize,
    unknowns: usize,
    band: usize,
}

impl Numbering {
    fn new(grid: &GasGrid, far_edge: FarEdge) -> Self {
        let nx = grid.nx();
        let row0 = usize::from(grid.ny() > 0);
        let held = usize::from(grid.ny() > 1 && far_edge == FarEdge::Held);
        let rows = grid.y.len() - row0 - held;
        let mut column = vec![None; nx + 1];
        let count;
        if grid.periodic {
            // 0, n−1, 1, n−2, …: neighbours (wrap-around included) are at most 2 apart.
            let (mut lo, mut hi, mut pos) = (0usize, nx - 1, 0usize);
            while lo <= hi {
                column[lo] = Some(pos);
                pos += 1;
                if hi != lo {
                    column[hi] = Some(pos);
                    pos += 1;
                }
                lo += 1;
                if hi == 0 {
                    break;
                }
                hi -= 1;
            }
            column[nx] = column[0];
            count = nx;
        } else {
            for (i, c) in column.iter_mut().enumerate().take(nx).skip(1) {
                *c = Some(i - 1);
            }
            count = nx - 1;
        }
        Numbering {
            column,
            row0,
            rows,
            unknowns: count * rows,
            band: if grid.periodic { 2 * rows } else { rows },
        }
    }

    fn index(&self, i: usize, j: usize) -> Option<usize> {
        if j < self.row0 || j >= self.row0 + self.rows {
            return None;
        }
        self.column[i].map(|c| c * self.rows + (j - self.row0))
    }
}

/// Unknowns and band of the Newton Jacobian of a film on `grid` with `far_edge`: what one
/// factorisation costs (about 2 n b² multiply–adds, [`super::band_lu`]), for estimating a
/// solve before it runs.
pub fn factorisation_size(grid: &GasGrid, far_edge: FarEdge) -> (usize, usize) {
    let numbering = Numbering::new(grid, far_edge);
    (numbering.unknowns, numbering.band)
}

/// One evaluation: the residual at the unknowns, its scaled norm and the Jacobian.
pub struct Evaluation {
    residual: Vec<f64>,
    norm: f64,
    jacobian: Band,
}

struct System<'a> {
    grid: &'a GasGrid,
    problem: &'a GasProblem,
    numbering: &'a Numbering,
    lambda: f64,
    /// Polled inside each factorisation (the finest films' take seconds).
    budget: &'a Budget,
}

impl System<'_> {
    fn assemble(&self, p: &[f64]) -> Evaluation {
        let (g, pr, nb) = (self.grid, self.problem, self.numbering);
        let (nx, ny1) = (g.nx(), g.y.len());
        let mut r = vec![0.0; nb.unknowns];
        let mut jac = Band::zeros(nb.unknowns, nb.band, nb.band);
        let kn = pr.knudsen_number;
        // x faces.
        for i in 0..nx {
            let dx = g.x[i + 1] - g.x[i];
            for j in 0..ny1 {
                let (a, b) = (g.at(i, j), g.at(i + 1, j));
                // Polar: 1/R times the flux at Λ R² (see [`Metric::Polar`]).
                let (lambda, hy) = match pr.metric {
                    Metric::Cartesian => (self.lambda, g.cv_y(j)),
                    Metric::Polar => (self.lambda * g.y[j] * g.y[j], g.cv_y(j) / g.y[j]),
                };
                let (f, dfa, dfb) = x_flux(
                    lambda,
                    kn,
                    dx,
                    (p[a], p[b]),
                    (pr.h_nodes[a], pr.h_nodes[b]),
                    pr.h_x_faces[i * ny1 + j],
                );
                let (ia, ib) = (nb.index(i, j), nb.index(i + 1, j));
                scatter(&mut r, &mut jac, (ia, ib), (f, dfa, dfb), hy);
            }
        }
        // y faces.
        for i in 0..=nx {
            if g.periodic && i == nx {
                continue;
            }
            let hx = g.cv_x(i);
            for j in 0..ny1.saturating_sub(1) {
                let (a, b) = (g.at(i, j), g.at(i, j + 1));
                let dy = g.y[j + 1] - g.y[j];
                let (f, dfa, dfb) = y_flux(kn, dy, (p[a], p[b]), pr.h_y_faces[i * (ny1 - 1) + j]);
                let (ia, ib) = (nb.index(i, j), nb.index(i, j + 1));
                let width = match pr.metric {
                    Metric::Cartesian => hx,
                    Metric::Polar => hx * 0.5 * (g.y[j] + g.y[j + 1]),
                };
                scatter(&mut r, &mut jac, (ia, ib), (f, dfa, dfb), width);
            }
        }
        let norm = r
            .iter()
            .enumerate()
            .map(|(k, v)| (v / jac.get(k, k)).abs())
            .fold(0.0, f64::max);
        Evaluation {
            residual: r,
            norm,
            jacobian: jac,
        }
    }
}

impl NewtonSystem for System<'_> {
    type Point = Vec<f64>;
    type Eval = Evaluation;
    type Step = Vec<f64>;

    fn evaluate(&self, p: &Vec<f64>) -> Evaluation {
        self.assemble(p)
    }
    fn residual(&self, at: &Evaluation) -> f64 {
        if at.norm.is_nan() {
            f64::INFINITY
        } else {
            at.norm
        }
    }
    /// None when the Jacobian is singular or the budget ran out part-way through its
    /// factorisation (the driver then reports the deadline).
    fn direction(&self, _p: &Vec<f64>, at: &Evaluation) -> Option<Vec<f64>> {
        let lu: BandLu = at.jacobian.clone().lu_within(self.budget).ok()?;
        let mut d: Vec<f64> = at.residual.iter().map(|v| -v).collect();
        lu.solve(&mut d);
        d.iter().all(|v| v.is_finite()).then_some(d)
    }
    fn advance(&self, p: &Vec<f64>, step: &Vec<f64>, t: f64) -> Vec<f64> {
        let (g, nb) = (self.grid, self.numbering);
        let mut q = p.clone();
        for i in 0..=g.nx() {
            for j in 0..g.y.len() {
                if let Some(k) = nb.index(i, j) {
                    let old = p[g.at(i, j)];
                    // Keep P positive: a step may at most halve it.
                    q[g.at(i, j)] = (old + t * step[k]).max(0.5 * old);
                }
            }
        }
        q
    }
    fn accepts(&self, here: &Evaluation, trial: &Evaluation, t: f64, _: Option<f64>) -> bool {
        newton::residual_falls(here.norm, trial.norm, t)
    }
}

/// How hard to try.
#[derive(Debug, Clone, Copy)]
pub struct GasStopping {
    /// On max |Rᵢ/Jᵢᵢ|.
    pub tolerance: f64,
    /// Newton steps per run (per continuation stage).
    pub max_newton_steps: u32,
}

impl Default for GasStopping {
    fn default() -> Self {
        GasStopping {
            tolerance: 1e-10,
            max_newton_steps: 60,
        }
    }
}

/// A solved film.
#[derive(Debug, Clone)]
pub struct GasSolution {
    /// P at every node ([`GasGrid::at`]); a periodic grid's last column repeats its first.
    pub p: Vec<f64>,
    /// The last Newton run's report, counting every stage's steps and line-search trials.
    pub report: SolverReport,
    /// Continuation stages run (1: Newton straight from the start).
    pub stages: u32,
}

/// Continuation's first bearing number and growth factor per stage.
const CONTINUATION_START: f64 = 2.0;
const CONTINUATION_FACTOR: f64 = 4.0;

/// Solve the film by Newton from `start` (a field at this Λ or near it; P = boundary pressure
/// everywhere when `None`). Without a start, or if Newton from it does not converge, the solve
/// continues in Λ from [`CONTINUATION_START`].
pub fn solve(
    grid: &GasGrid,
    problem: &GasProblem,
    start: Option<&[f64]>,
    stop: GasStopping,
    budget: &Budget,
) -> Result<GasSolution, Stopped> {
    let numbering = Numbering::new(grid, problem.far_edge);
    let mut field = vec![problem.boundary_pressure; (grid.nx() + 1) * grid.y.len()];
    let target = problem.bearing_number;
    let line = LineSearch {
        max_halvings: 12,
        take_shortest: true,
    };
    let mut tally = Tally::default();
    // One Newton run at Λ from `field`. A start that already meets the tolerance still takes
    // one full Newton step (the linear film), and Newton runs again from it: the scaled
    // residual under-measures a smooth error by the square of the mesh's spacing, so a weak
    // film's ambient field, or a start interpolated from the half mesh, can meet 1e-10 while
    // carrying nothing or the half mesh's answer.
    let run = |tally: &mut Tally, field: &mut Vec<f64>, lambda: f64| {
        let system = System {
            grid,
            problem,
            numbering: &numbering,
            lambda,
            budget,
        };
        let mut stepped = false;
        tally.stages += 1;
        loop {
            let driver = Driver::new(
                "newton_fitted_flux_band_lu",
                IterationUnit::NewtonSteps,
                stop.max_newton_steps,
                budget,
            );
            let outcome = newton::solve(&system, field.clone(), stop.tolerance, line, &driver);
            let report = match &outcome {
                Ok(done) => &done.report,
                Err(e) => &e.report,
            };
            tally.iterations += report.iterations;
            tally.evaluations += report.evaluations.unwrap_or(0);
            match outcome {
                Ok(done)
                    if done.report.iterations == 0
                        && !std::mem::replace(&mut stepped, true)
                        && linear_step(&system, field, &done.value.1, tally) =>
                {
                    continue
                }
                Ok(done) => {
                    budget.count_field_solve();
                    *field = done.value.0;
                    return Ok(done.report);
                }
                Err(e) => return Err(e),
            }
        }
    };
    if let Some(s) = start {
        field.copy_from_slice(s);
        match run(&mut tally, &mut field, target) {
            Ok(report) => return Ok(tally.solution(field, report)),
            // The deadline ends the solve (continuation would only assemble its start, a
            // fine film's half second, to find the budget spent); any other stop falls back.
            Err(e) if e.reason() == StopReason::Deadline => return Err(e),
            Err(_) => field.fill(problem.boundary_pressure),
        }
    }
    let mut lambda = target.min(CONTINUATION_START);
    loop {
        let report = match run(&mut tally, &mut field, lambda) {
            Ok(r) => r,
            Err(mut e) => {
                e.report = e
                    .report
                    .clone()
                    .counting(tally.iterations, tally.evaluations);
                return Err(e);
            }
        };
        if lambda >= target {
            return Ok(tally.solution(field, report));
        }
        lambda = (lambda * CONTINUATION_FACTOR).min(target);
    }
}

/// Newton's full step from `field`, evaluated as `at` by the run that converged there, where the
/// film is linear in its rise (the next residual is of the rise squared), counted in `tally` as
/// one step and one evaluation (that run's, which a run converged at its start does not count);
/// false when the Jacobian is singular or the budget is spent.
fn linear_step(system: &System, field: &mut Vec<f64>, at: &Evaluation, tally: &mut Tally) -> bool {
    tally.evaluations += 1;
    let Some(step) = system.direction(field, at) else {
        return false;
    };
    *field = system.advance(field, &step, 1.0);
    tally.iterations += 1;
    true
}

/// The work of every Newton run of one solve.
#[derive(Default)]
struct Tally {
    iterations: u32,
    evaluations: u32,
    stages: u32,
}

impl Tally {
    fn solution(&self, p: Vec<f64>, report: SolverReport) -> GasSolution {
        GasSolution {
            p,
            report: report.counting(self.iterations, self.evaluations),
            stages: self.stages,
        }
    }
}

/// A field on `coarse` interpolated onto `fine` (bilinear in the node coordinates), as a
/// Newton start: the fine film of a Richardson pair then needs neither continuation nor more
/// than a few steps.
pub fn prolong(coarse: &GasGrid, pc: &[f64], fine: &GasGrid) -> Vec<f64> {
    // The coarse interval holding v, and the weight of its right end.
    let locate = |nodes: &[f64], v: f64| -> (usize, f64) {
        if nodes.len() == 1 {
            return (0, 0.0);
        }
        let k = nodes.partition_point(|&x| x <= v).clamp(1, nodes.len() - 1) - 1;
        let t = ((v - nodes[k]) / (nodes[k + 1] - nodes[k])).clamp(0.0, 1.0);
        (k, t)
    };
    let mut pf = vec![0.0; fine.x.len() * fine.y.len()];
    for (i, &x) in fine.x.iter().enumerate() {
        let (ci, tx) = locate(&coarse.x, x);
        let ci1 = (ci + 1).min(coarse.nx());
        for (j, &y) in fine.y.iter().enumerate() {
            let (cj, ty) = locate(&coarse.y, y);
            let cj1 = (cj + 1).min(coarse.y.len() - 1);
            let v = |a: usize, b: usize| pc[coarse.at(a, b)];
            pf[fine.at(i, j)] = (1.0 - tx) * ((1.0 - ty) * v(ci, cj) + ty * v(ci, cj1))
                + tx * ((1.0 - ty) * v(ci1, cj) + ty * v(ci1, cj1));
        }
    }
    pf
}

/// The x-flux through the face between nodes i and i+1 of row j of a solved field (the mass
/// flow in units of the scaling, Λ P H − k ∂x P, per unit height).
pub fn flux_x(grid: &GasGrid, problem: &GasProblem, p: &[f64], i: usize, j: usize) -> f64 {
    let ny1 = grid.y.len();
    let (a, b) = (grid.at(i, j), grid.at(i + 1, j));
    x_flux(
        problem.bearing_number,
        problem.knudsen_number,
        grid.x[i + 1] - grid.x[i],
        (p[a], p[b]),
        (problem.h_nodes[a], problem.h_nodes[b]),
        problem.h_x_faces[i * ny1 + j],
    )
    .0
}

impl GasProblem {
    /// This film with `t·dh(x, y)` added at every node and face (a perturbed film on the same
    /// grid).
    pub fn shifted(&self, grid: &GasGrid, t: f64, dh: &dyn Fn(f64, f64) -> f64) -> GasProblem {
        let mut out = self.clone();
        let ny1 = grid.y.len();
        for i in 0..=grid.nx() {
            for j in 0..ny1 {
                out.h_nodes[grid.at(i, j)] += t * dh(grid.x[i], grid.y[j]);
                if i < grid.nx() {
                    out.h_x_faces[i * ny1 + j] +=
                        t * dh(0.5 * (grid.x[i] + grid.x[i + 1]), grid.y[j]);
                }
                if j + 1 < ny1 {
                    out.h_y_faces[i * (ny1 - 1) + j] +=
                        t * dh(grid.x[i], 0.5 * (grid.y[j] + grid.y[j + 1]));
                }
            }
        }
        out
    }
}

/// The first-order response P₁ = re + i·im of a film to a harmonic film perturbation
/// H = H₀(x, y) + dh(x, y) e^{iτ ν/ω}, at every node ([`GasGrid::at`]; 0 on held boundaries).
#[derive(Debug, Clone, PartialEq)]
pub struct HarmonicResponse {
    pub re: Vec<f64>,
    pub im: Vec<f64>,
}

/// Step of the central difference of the residual in the film, ∂R/∂H·dh (the fitted flux is
/// smooth in H: truncation O(t²) ≈ 1e-10, round-off ≈ 1e-16/t of the fluxes).
const FILM_STEP: f64 = 1e-5;

/// The linearised (perturbation) compressible Reynolds equation at the converged field `p` of
/// `problem`, for small harmonic film perturbations `shapes`, each dh(x, y) e^{iτν/ω}.
///
/// With the squeeze term the unsteady equation is ∇·(k∇P) = Λ ∂x(PH) + σ₀ ∂τ(PH) (Khonsari &
/// Booser Eq. 11.3; τ = ωt), and a journal's scaling has σ₀ = 2Λ: for motion at frequency ν the
/// squeeze number is σ = 2Λ ν/ω, the `squeeze` argument. In the finite-volume form,
/// R(P, H) + σ₀ ∂τ(P H)·A = 0 (R the net outflow of a control volume of area A), so to first
/// order
///
/// ```text
/// (J + iσ A H₀) P₁ = −(∂R/∂H) dh − iσ A P₀ dh
/// ```
///
/// with J the steady Newton Jacobian at P₀ (the same assembly). The complex system is solved as
/// a real one of twice the order, real and imaginary parts of each unknown interleaved (band
/// 2b + 1), by one band LU for all shapes (eight times a Newton step's factorisation, polling
/// `budget` as it goes). ∂R/∂H dh is a central difference of the residual ([`FILM_STEP`]).
/// Errs if the system is singular or the budget runs out.
pub fn harmonic_response(
    grid: &GasGrid,
    problem: &GasProblem,
    p: &[f64],
    squeeze: f64,
    shapes: &[&dyn Fn(f64, f64) -> f64],
    budget: &Budget,
) -> Result<Vec<HarmonicResponse>, Unfactored> {
    debug_assert_eq!(
        problem.metric,
        Metric::Cartesian,
        "the harmonic response is Cartesian"
    );
    let numbering = Numbering::new(grid, problem.far_edge);
    let system = |problem: &GasProblem| {
        System {
            grid,
            problem,
            numbering: &numbering,
            lambda: problem.bearing_number,
            budget,
        }
        .assemble(p)
    };
    let steady = system(problem).jacobian;
    let (n, b) = (numbering.unknowns, numbering.band);
    let mut big = Band::zeros(2 * n, 2 * b + 1, 2 * b + 1);
    for r in 0..n {
        for c in r.saturating_sub(b)..=(r + b).min(n - 1) {
            let v = steady.get(r, c);
            if v != 0.0 {
                big.add(2 * r, 2 * c, v);
                big.add(2 * r + 1, 2 * c + 1, v);
            }
        }
    }
    // The unknowns' nodes with their control-volume areas (a periodic grid's mirrored last
    // column is the first: weight 0 there, so it is skipped).
    let mut nodes = Vec::with_capacity(n);
    for i in 0..=grid.nx() {
        for j in 0..grid.y.len() {
            if let (Some(k), w) = (numbering.index(i, j), grid.weight(i, j)) {
                if w > 0.0 {
                    nodes.push((k, i, j, w));
                }
            }
        }
    }
    for &(k, i, j, area) in &nodes {
        let m = squeeze * area * problem.h_nodes[grid.at(i, j)];
        big.add(2 * k, 2 * k + 1, -m);
        big.add(2 * k + 1, 2 * k, m);
    }
    let lu = big.lu_within(budget)?;
    let mut out = Vec::with_capacity(shapes.len());
    for dh in shapes {
        let plus = system(&problem.shifted(grid, FILM_STEP, dh)).residual;
        let minus = system(&problem.shifted(grid, -FILM_STEP, dh)).residual;
        let mut rhs = vec![0.0; 2 * n];
        for k in 0..n {
            rhs[2 * k] = -(plus[k] - minus[k]) / (2.0 * FILM_STEP);
        }
        for &(k, i, j, area) in &nodes {
            let at = grid.at(i, j);
            rhs[2 * k + 1] = -squeeze * area * p[at] * dh(grid.x[i], grid.y[j]);
        }
        lu.solve(&mut rhs);
        let mut response = HarmonicResponse {
            re: vec![0.0; p.len()],
            im: vec![0.0; p.len()],
        };
        for i in 0..=grid.nx() {
            for j in 0..grid.y.len() {
                if let Some(k) = numbering.index(i, j) {
                    response.re[grid.at(i, j)] = rhs[2 * k];
                    response.im[grid.at(i, j)] = rhs[2 * k + 1];
                }
            }
        }
        out.push(response);
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn slider_1d(n: usize, lambda: f64, h1: f64) -> (GasGrid, GasProblem) {
        let grid = GasGrid {
            x: graded(n, 0.3 / lambda.max(1.0), false),
            y: vec![0.0],
            periodic: false,
        };
        let problem = GasProblem::new(&grid, lambda, 0.0, |x, _| h1 - (h1 - 1.0) * x);
        (grid, problem)
    }

    #[test]
    fn the_fitted_flux_jacobian_is_the_derivative_of_the_flux() {
        for (lambda, kn, dx) in [(0.01, 0.0, 0.1), (5.0, 0.1, 0.05), (1000.0, 0.0, 0.02)] {
            let (p, h, hf) = ((1.3, 1.7), (1.9, 1.6), 1.74);
            let (_, da, db) = x_flux(lambda, kn, dx, p, h, hf);
            let e = 1e-6;
            let fa = |v: f64| x_flux(lambda, kn, dx, (v, p.1), h, hf).0;
            let fb = |v: f64| x_flux(lambda, kn, dx, (p.0, v), h, hf).0;
            let na = (fa(p.0 + e) - fa(p.0 - e)) / (2.0 * e);
            let nb = (fb(p.1 + e) - fb(p.1 - e)) / (2.0 * e);
            assert!((da - na).abs() < 1e-6 * na.abs().max(1.0), "{da} {na}");
            assert!((db - nb).abs() < 1e-6 * nb.abs().max(1.0), "{db} {nb}");
        }
    }

    #[test]
    fn small_bearing_numbers_give_the_incompressible_slider() {
        // Λ → 0: P − 1 → Λ (H1 − H)(H − 1)/(H² (H1² − 1)) (Khonsari & Booser Table 11.3).
        let (h1, lambda) = (2.0, 1e-3);
        let (grid, problem) = slider_1d(200, lambda, h1);
        let s = solve(
            &grid,
            &problem,
            None,
            GasStopping::default(),
            &Budget::unlimited(),
        )
        .unwrap();
        for (i, &x) in grid.x.iter().enumerate() {
            let h = h1 - (h1 - 1.0) * x;
            let want = lambda * (h1 - h) * (h - 1.0) / (h * h * (h1 * h1 - 1.0));
            assert!(
                (s.p[i] - 1.0 - want).abs() < 2e-3 * lambda,
                "x {x}: {} vs {want}",
                s.p[i] - 1.0
            );
        }
    }

    #[test]
    fn large_bearing_numbers_converge_by_continuation_and_conserve_mass() {
        let (grid, problem) = slider_1d(120, 1000.0, 2.0);
        let s = solve(
            &grid,
            &problem,
            None,
            GasStopping::default(),
            &Budget::unlimited(),
        )
        .unwrap();
        assert!(s.stages > 1);
        let flows: Vec<f64> = (0..grid.nx())
            .map(|i| flux_x(&grid, &problem, &s.p, i, 0))
            .collect();
        for f in &flows {
            assert!((f - flows[0]).abs() < 1e-8 * flows[0].abs());
        }
        // Interior P H → H1 (Table 11.3, Λ → ∞).
        let mid = grid.x.iter().position(|&x| x >= 0.5).unwrap();
        let h = 2.0 - grid.x[mid];
        assert!((s.p[mid] * h - 2.0).abs() < 5e-3, "{}", s.p[mid] * h);
        assert!(s.p.iter().all(|p| p.is_finite() && *p > 0.0));
    }

    /// A held far edge solves the whole width: the film of a slider symmetric about its centre
    /// line, solved over the whole width with both edges held, is the half-width film with the
    /// symmetry plane, mirrored, node by node; an unsymmetric film on the whole width is not.
    #[test]
    fn a_held_far_edge_solves_the_whole_width() {
        let half_y = graded(6, 0.05, true);
        let mirrored = half_y.iter().rev().skip(1).map(|v| 2.0 - v);
        let whole_y: Vec<f64> = half_y.iter().copied().chain(mirrored).collect();
        let x = graded(24, 0.02, false);
        let (half, whole) = (
            GasGrid {
                x: x.clone(),
                y: half_y,
                periodic: false,
            },
            GasGrid {
                x,
                y: whole_y,
                periodic: false,
            },
        );
        let film = |x: f64, _: f64| 2.0 - x;
        let solve_on = |grid: &GasGrid, far_edge: FarEdge, h: &dyn Fn(f64, f64) -> f64| {
            let problem = GasProblem {
                far_edge,
                ..GasProblem::new(grid, 5.0, 0.0, h)
            };
            solve(
                grid,
                &problem,
                None,
                GasStopping::default(),
                &Budget::unlimited(),
            )
            .unwrap()
            .p
        };
        let (ph, pw) = (
            solve_on(&half, FarEdge::Symmetry, &film),
            solve_on(&whole, FarEdge::Held, &film),
        );
        let ny = half.ny();
        for i in 0..=half.nx() {
            for j in 0..=ny {
                let p = ph[half.at(i, j)];
                assert!((pw[whole.at(i, j)] - p).abs() < 1e-10, "({i}, {j})");
                assert!(
                    (pw[whole.at(i, 2 * ny - j)] - p).abs() < 1e-10,
                    "({i}, {j})"
                );
            }
        }
        // Both edges of the whole width stay at ambient; a film tilted across it is not mirrored.
        assert!((0..=whole.nx()).all(|i| pw[whole.at(i, 2 * ny)] == 1.0));
        let tilted = |x: f64, y: f64| 2.0 - x + 0.2 * (y - 1.0);
        let pt = solve_on(&whole, FarEdge::Held, &tilted);
        let mid = whole.nx() / 2;
        assert!((pt[whole.at(mid, 2)] - pt[whole.at(mid, 2 * ny - 2)]).abs() > 1e-3);
    }

    #[test]
    fn a_periodic_concentric_film_stays_at_ambient_and_a_grid_grades() {
        let grid = GasGrid {
            x: (0..=16)
                .map(|k| k as f64 * std::f64::consts::TAU / 16.0)
                .collect(),
            y: graded(6, 0.05, true),
            periodic: true,
        };
        let problem = GasProblem::new(&grid, 50.0, 0.0, |_, _| 1.0);
        let s = solve(
            &grid,
            &problem,
            None,
            GasStopping::default(),
            &Budget::unlimited(),
        )
        .unwrap();
        assert!(s.p.iter().all(|p| (p - 1.0).abs() < 1e-12));
        let y = &grid.y;
        assert!((y[1] - y[0] - 0.05).abs() < 1e-3 && y[6] == 1.0);
    }
}
