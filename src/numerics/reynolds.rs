//! The Reynolds equation on a rectangle, finite volumes, with cavitation.
//!
//! Solves, in dimensionless variables,
//!
//! ```text
//! ∂x(h³ ∂x p) + a ∂y(h³ ∂y p) = Λ ∂x h + s(x, y)
//! ```
//!
//! on x ∈ [x0, x1] (a node list that may cluster), y ∈ [0, Ly] with p = 0 on every edge, or,
//! when the problem is symmetric about the mid-plane y = Ly, on the half y ∈ [0, Ly] with
//! ∂y p = 0 there. The stencil is flux-conservative: h³ is taken at cell faces, and the wedge
//! term is integrated exactly over each control volume as Λ (h_e − h_w) Δy, so mass is
//! conserved cell by cell. With `cavitation` the system is the linear complementarity problem
//! p ≥ 0, L p − b ≥ 0, p (L p − b) = 0 — the Reynolds (Swift–Stieber) condition — solved
//! exactly by an active-set method on banded Cholesky factors ([`solve`], in
//! `complementarity`), which also gives the film's linear response ([`Linearised`]).
//!
//! [`solve_mass_conserving`] solves the mass-conserving (JFO) alternative on the same stencil,
//! with the film content θ_f as a second field: the wedge term becomes Λ ∂x(θ_f h), upwinded,
//! and a film may be periodic in x with nodes held at a feed's pressure. Its Gauss–Seidel sweeps
//! run under the solver driver ([`Driver`]): one iteration is one sweep, the budget is polled
//! every 16 sweeps, the cap is [`Stopping::max_sweeps`]; it converges when the relative change
//! per sweep is at or below the tolerance and diverges when it is not finite. A periodic full
//! film (no cavitation, no feed line: a pure squeeze film that keeps its negative pressures) is
//! one banded solve of [`solve`], its columns numbered round the seam.

mod complementarity;

pub use complementarity::{solve, Linearised};

use super::driver::{Budget, Driver, Stopped, Verdict};
use crate::fidelity::{IterationUnit, SolverReport};

/// The grid: node positions along x (both ends are boundary nodes), and a uniform spacing across.
#[derive(Debug, Clone, PartialEq)]
pub struct Grid {
    /// Node coordinates along x, strictly increasing; `x[0]` and `x[last]` carry p = 0.
    pub x: Vec<f64>,
    /// Cells across the modelled width (half the width when `symmetric`).
    pub ny: usize,
    /// Modelled width: the whole width, or the half up to the mid-plane when `symmetric`.
    pub width: f64,
    /// p = 0 at y = 0 and ∂p/∂y = 0 at y = `width` (the mid-plane of a symmetric film).
    pub symmetric: bool,
    /// x[0] and x[nx] are the same line (x[nx] = x[0] + period): column 0 holds unknowns unless
    /// held, and column nx mirrors it. Mass-conserving solves and the active-set solve
    /// ([`complementarity::solve`]) only.
    pub periodic: bool,
}

impl Grid {
    pub fn nx(&self) -> usize {
        self.x.len() - 1
    }
    pub fn dy(&self) -> f64 {
        self.width / self.ny as f64
    }
    /// y of node row j.
    pub fn y(&self, j: usize) -> f64 {
        j as f64 * self.dy()
    }
    /// Width of node i's control volume along x.
    pub fn cv_x(&self, i: usize) -> f64 {
        let n = self.nx();
        match i {
            0 => 0.5 * (self.x[1] - self.x[0]),
            _ if i == n => 0.5 * (self.x[n] - self.x[n - 1]),
            _ => 0.5 * (self.x[i + 1] - self.x[i - 1]),
        }
    }
    /// Height of row j's control volume (the mid-plane row of a symmetric grid has half).
    pub fn cv_y(&self, j: usize) -> f64 {
        if j == 0 || j == self.ny {
            0.5 * self.dy()
        } else {
            self.dy()
        }
    }
}

/// The assembled five-point system for the interior unknowns (node rows 1..ny, columns 1..nx-1,
/// plus the mid-plane row when symmetric): a_P p_P = a_E p_E + a_W p_W + a_N p_N + a_S p_S − b.
#[derive(Debug, Clone)]
pub struct Stencil {
    nx: usize,
    rows: usize,
    ae: Vec<f64>,
    aw: Vec<f64>,
    an: Vec<f64>,
    a_s: Vec<f64>,
    ap: Vec<f64>,
    b: Vec<f64>,
    /// The wedge term's two faces, Λ h_e Δy and Λ h_w Δy (b = ce − cw + src): the Couette
    /// fluxes a mass-conserving solve weights by the film content upwind of each face.
    ce: Vec<f64>,
    cw: Vec<f64>,
    /// The source integrated over the control volume (squeeze: 12 ∂h/∂τ).
    src: Vec<f64>,
    /// Nodes held at their given value (feed ports), not solved.
    held: Vec<bool>,
    periodic: bool,
    /// The far y edge (row ny) is an ambient p = 0 edge (not a symmetry plane).
    far_edge: bool,
}

/// A direction of flow.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Axis {
    X,
    Y,
}

/// What the Reynolds problem is: film thickness h(x, y), anisotropy `a` of the y-term, wedge
/// coefficient Λ, an optional source s(x, y) (squeeze terms), and optionally the flow
/// conductance per direction in place of h³ (turbulence coefficients scale it), all
/// dimensionless.
pub struct Problem<'a> {
    pub film: &'a dyn Fn(f64, f64) -> f64,
    pub conductance: Option<&'a dyn Fn(f64, f64, Axis) -> f64>,
    pub anisotropy: f64,
    pub wedge: f64,
    pub source: Option<&'a dyn Fn(f64, f64) -> f64>,
    /// Nodes held at the value the field gives them (a feed port at supply pressure), if any.
    pub held: Option<&'a dyn Fn(f64, f64) -> bool>,
}

/// Index of node (i, j) in a full-grid field of (nx+1) × (ny+1) values, x fastest.
pub fn at(grid: &Grid, i: usize, j: usize) -> usize {
    j * (grid.nx() + 1) + i
}

impl Stencil {
    pub fn assemble(grid: &Grid, problem: &Problem) -> Stencil {
        let nx = grid.nx();
        let rows = grid.ny + 1;
        let n = (nx + 1) * rows;
        let dy = grid.dy();
        let mut s = Stencil {
            nx,
            rows,
            ae: vec![0.0; n],
            aw: vec![0.0; n],
            an: vec![0.0; n],
            a_s: vec![0.0; n],
            ap: vec![0.0; n],
            b: vec![0.0; n],
            ce: vec![0.0; n],
            cw: vec![0.0; n],
            src: vec![0.0; n],
            held: vec![false; n],
            periodic: grid.periodic,
            far_edge: !grid.symmetric,
        };
        let period = grid.x[nx] - grid.x[0];
        let first = if grid.periodic { 0 } else { 1 };
        let h = problem.film;
        let cond = |x: f64, y: f64, axis: Axis| match problem.conductance {
            Some(c) => c(x, y, axis),
            None => h(x, y).powi(3),
        };
        // Column by column, each coefficient function over a whole column at one x (a film
        // that depends on x through trigonometric functions may then keep them), each face once:
        // a column's east faces are the next column's west faces, and a node's north face is
        // the next node's south face.
        let last_row = if grid.symmetric { grid.ny } else { grid.ny - 1 };
        let ys: Vec<f64> = (0..=last_row).map(|j| grid.y(j)).collect();
        let x_faces = |x: f64, out: &mut Vec<(f64, f64)>| {
            out.clear();
            out.extend(ys.iter().map(|&y| {
                let hx = h(x, y);
                let c = match problem.conductance {
                    Some(c) => c(x, y, Axis::X),
                    None => hx.powi(3),
                };
                (hx, c)
            }));
        };
        let (mut west, mut east) = (Vec::new(), Vec::new());
        let mut y_faces = vec![0.0; last_row + 1];
        let mut sources = vec![0.0; last_row + 1];
        for i in first..nx {
            let (xw, xp, xe) = if i == 0 {
                (grid.x[nx - 1] - period, grid.x[0], grid.x[1])
            } else {
                (grid.x[i - 1], grid.x[i], grid.x[i + 1])
            };
            let (fw, fe) = (0.5 * (xw + xp), 0.5 * (xp + xe));
            let wx = fe - fw;
            if i == first {
                x_faces(fw, &mut west);
            }
            x_faces(fe, &mut east);
            // y_faces[j]: the face between rows j and j + 1 (the mid-plane row has none).
            for (j, face) in y_faces.iter_mut().enumerate() {
                let y_n = ((j as f64 + 0.5) * dy).min(grid.width);
                *face = if grid.symmetric && j == grid.ny {
                    0.0
                } else {
                    cond(xp, y_n, Axis::Y)
                };
            }
            if let Some(f) = problem.source {
                for (v, &y) in sources.iter_mut().zip(&ys) {
                    *v = f(xp, y);
                }
            }
            for j in 1..=last_row {
                let k = j * (nx + 1) + i;
                let y = ys[j];
                if problem.held.is_some_and(|held| held(xp, y)) {
                    s.held[k] = true;
                    if i == 0 {
                        s.held[k + nx] = true;
                    }
                    continue;
                }
                let hy = grid.cv_y(j);
                let ((hw, cw), (he, ce)) = (west[j], east[j]);
                s.ae[k] = ce / (xe - xp) * hy;
                s.aw[k] = cw / (xp - xw) * hy;
                s.a_s[k] = problem.anisotropy * y_faces[j - 1] / dy * wx;
                s.an[k] = problem.anisotropy * y_faces[j] / dy * wx;
                s.ap[k] = s.ae[k] + s.aw[k] + s.an[k] + s.a_s[k];
                let source = sources[j] * wx * hy;
                s.ce[k] = problem.wedge * he * hy;
                s.cw[k] = problem.wedge * hw * hy;
                s.src[k] = source;
                s.b[k] = problem.wedge * (he - hw) * hy + source;
            }
            std::mem::swap(&mut west, &mut east);
        }
        s
    }

    /// Node (j, i) holds an unknown: inside the boundary (a periodic film's column 0 too), and
    /// not held.
    fn interior(&self, j: usize, i: usize) -> bool {
        let first = usize::from(!self.periodic);
        i >= first && i < self.nx && j >= 1 && j < self.rows && self.ap[j * (self.nx + 1) + i] > 0.0
    }

    /// Largest |a_P p − Σ a_nb p_nb + b| over unknowns, for the free nodes (p > 0), and the
    /// largest violation of L p − b ≥ 0 on the contact nodes (p = 0), scaled by max a_P·max p.
    pub fn residual(&self, p: &[f64], cavitation: bool) -> f64 {
        let w = self.nx + 1;
        let (mut worst, mut scale_p, mut scale_a) = (0.0f64, 0.0f64, 0.0f64);
        for j in 1..self.rows {
            for i in 0..self.nx {
                if !self.interior(j, i) {
                    continue;
                }
                let k = j * w + i;
                let north = if j + 1 < self.rows { p[k + w] } else { 0.0 };
                let r = self.ap[k] * p[k]
                    - self.ae[k] * p[k + 1]
                    - self.aw[k] * p[self.west(k)]
                    - self.an[k] * north
                    - self.a_s[k] * p[k - w]
                    + self.b[k];
                let r = if cavitation && p[k] <= 0.0 {
                    (-r).max(0.0)
                } else {
                    r.abs()
                };
                worst = worst.max(r);
                scale_p = scale_p.max(p[k].abs());
                scale_a = scale_a.max(self.ap[k]);
            }
        }
        worst / (scale_a * scale_p).max(f64::MIN_POSITIVE)
    }

    /// A good SOR factor for this stencil: from the Jacobi spectral radius of the
    /// anisotropic Laplacian on the grid, ω = 2 / (1 + √(1 − ρ²)).
    pub fn sor_factor(&self, grid: &Grid) -> f64 {
        let n = self.nx as f64;
        let m = if grid.symmetric {
            2.0 * grid.ny as f64
        } else {
            grid.ny as f64
        };
        let (mut sx, mut sy) = (0.0, 0.0);
        for k in 0..self.ap.len() {
            sx += self.ae[k] + self.aw[k];
            sy += self.an[k] + self.a_s[k];
        }
        let rho = (sx * (std::f64::consts::PI / n).cos() + sy * (std::f64::consts::PI / m).cos())
            / (sx + sy);
        (2.0 / (1.0 + (1.0 - rho * rho).max(0.0).sqrt())).clamp(1.0, 1.97)
    }
}

/// How the iteration stops: relative change per sweep, with a cap that is never unbounded.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stopping {
    pub tolerance: f64,
    pub max_sweeps: u32,
}

/// A finished solve: the driver's report (method, iterations, the scaled equation residual of
/// [`Stencil::residual`], elapsed time).
#[derive(Debug, Clone, PartialEq)]
pub struct Solved {
    pub report: SolverReport,
}

impl Solved {
    /// This solve counted together with the `earlier` one that started it (a coarse solve whose
    /// field started this one): the iterations and time of both, this one's residual.
    #[must_use]
    pub fn after(mut self, earlier: &Solved) -> Solved {
        self.report.iterations += earlier.report.iterations;
        self.report.elapsed_ms += earlier.report.elapsed_ms;
        self
    }
}

/// Why a solve produced no field: the driver's stop (cap, deadline or divergence) and its report.
pub type SolveError = Stopped;

/// Mass-conserving cavitation (Jakobsson–Floberg–Olsson, in Elrod and Adams' universal-variable
/// form with the complementarity of Giacopini et al. 2010): besides the pressure p each node
/// carries the film content θ_f ∈ [0, 1] (the fraction of the gap filled with liquid), and the
/// control-volume balance is
///
/// ```text
/// Σ a_nb (p_nb − p_P) = ce θ_P − cw θ_W + src θ_P,   p ≥ 0,  0 ≤ θ ≤ 1,  p (1 − θ) = 0
/// ```
///
/// The Couette flux through a face carries the content of the node upwind of it (the surface
/// moves towards +x), so a cavitated zone transports its streamers downstream and the film
/// reforms where they fill the gap again. The squeeze source is weighted by the content of its
/// cell (quasi-steady: ∂(θ h)/∂t ≈ θ ∂h/∂t). Solved by Gauss–Seidel sweeps in +x (the
/// transport of θ through a cavitated zone is then exact in one sweep): each node first takes
/// the content that balances its cell at p = 0; if that content reaches 1 the node is full film
/// and its pressure is the over-relaxed Gauss–Seidel value, clipped at zero.
///
/// `content` holds θ on the same nodes as `p`; its values on the x = x0 boundary column are the
/// supply's content (1: flooded) and stay as given. The pressure boundary values stay as given.
/// Stops when both the relative pressure change and the largest content change per sweep fall
/// below the tolerance (under the driver, method `finite_volume_jfo_gauss_seidel`).
pub fn solve_mass_conserving(
    stencil: &Stencil,
    omega: f64,
    p: &mut [f64],
    content: &mut [f64],
    stop: Stopping,
    budget: &Budget,
) -> Result<Solved, SolveError> {
    let run = Driver::new(
        "finite_volume_jfo_gauss_seidel",
        IterationUnit::Sweeps,
        stop.max_sweeps,
        budget,
    )
    .check_every(16)
    .run(|_| {
        let (change, size, content_change) = jfo_sweep(stencil, omega, p, content);
        if !change.is_finite() || !size.is_finite() || !content_change.is_finite() {
            return Verdict::Diverged(f64::NAN);
        }
        let relative = (if size > 0.0 { change / size } else { change }).max(content_change);
        if relative <= stop.tolerance {
            Verdict::Converged((), stencil.mass_residual(p, content))
        } else {
            Verdict::Continue(relative)
        }
    })?;
    Ok(Solved { report: run.report })
}

/// One Gauss–Seidel sweep of the mass-conserving system: (largest pressure change, largest p,
/// largest content change). A plain function, not the driver's closure, so that the slices keep
/// their no-alias guarantee and the inner loop compiles as tightly as a hand loop.
fn jfo_sweep(stencil: &Stencil, omega: f64, p: &mut [f64], content: &mut [f64]) -> (f64, f64, f64) {
    let w = stencil.nx + 1;
    let nx = stencil.nx;
    let first = if stencil.periodic { 0 } else { 1 };
    // The coefficient rows as plain slices, so their bounds are checked once per sweep.
    let (ap, an, ae, aw, a_s) = (
        &stencil.ap[..],
        &stencil.an[..],
        &stencil.ae[..],
        &stencil.aw[..],
        &stencil.a_s[..],
    );
    let (cw, ce, src) = (&stencil.cw[..], &stencil.ce[..], &stencil.src[..]);
    let (mut change, mut size, mut content_change) = (0.0f64, 0.0f64, 0.0f64);
    for j in 1..stencil.rows {
        let has_north = j + 1 < stencil.rows;
        for i in first..nx {
            let k = j * w + i;
            let ap_k = ap[k];
            if ap_k <= 0.0 {
                continue;
            }
            // Across the seam of a periodic film the west neighbour is column nx − 1.
            let kw = if i == 0 { k + nx - 1 } else { k - 1 };
            let north = if has_north { an[k] * p[k + w] } else { 0.0 };
            let nb = ae[k] * p[k + 1] + aw[k] * p[kw] + north + a_s[k] * p[k - w];
            let inflow = cw[k] * content[kw];
            let out = ce[k] + src[k];
            let balanced = if out > 0.0 {
                (nb + inflow) / out
            } else {
                f64::INFINITY
            };
            let (next_p, next_theta) = if balanced < 1.0 {
                (0.0, balanced.max(0.0))
            } else {
                let gs = (nb + inflow - out) / ap_k;
                ((p[k] + omega * (gs - p[k])).max(0.0), 1.0)
            };
            change = change.max((next_p - p[k]).abs());
            size = size.max(next_p);
            content_change = content_change.max((next_theta - content[k]).abs());
            p[k] = next_p;
            content[k] = next_theta;
            if i == 0 {
                p[k + nx] = next_p;
                content[k + nx] = next_theta;
            }
        }
    }
    (change, size, content_change)
}

/// The flows across the modelled domain's boundaries, from a field and its content (θ = 1
/// everywhere for a film without mass-conserving cavitation), in the stencil's units (the
/// Couette flux of a full film through a face of thickness h and width Δy is Λ h Δy).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Fluxes {
    /// Into the domain through the x = x0 edge (Couette with the supply's content, minus the
    /// backward pressure flow).
    pub inflow: f64,
    /// Out through the x = x1 edge.
    pub outflow: f64,
    /// Out through the y edges held at p = 0 (one edge when symmetric).
    pub side: f64,
    /// Taken up by the squeeze source.
    pub squeeze: f64,
}

impl Fluxes {
    /// inflow − outflow − side − squeeze, relative to the inflow: zero for a conserving field.
    pub fn imbalance(&self) -> f64 {
        (self.inflow - self.outflow - self.side - self.squeeze) / self.inflow.abs().max(1e-300)
    }
}

impl Stencil {
    /// The discrete fluxes of field `p` with film content `content` through the domain's
    /// boundary faces — the same face fluxes the cell balances use, so for a converged
    /// mass-conserving field they close to the solver's tolerance.
    pub fn fluxes(&self, p: &[f64], content: &[f64]) -> Fluxes {
        let w = self.nx + 1;
        let nx = self.nx;
        let mut f = Fluxes {
            inflow: 0.0,
            outflow: 0.0,
            side: 0.0,
            squeeze: 0.0,
        };
        let first = if self.periodic { 0 } else { 1 };
        // Where a face's flux goes when its far node is not solved: an ambient y edge, the
        // outlet column, or a supply (the x0 column, a held port).
        enum Sink {
            Free,
            Side,
            Out,
            Supply,
        }
        let sink = |k: usize| {
            let (j, i) = (k / w, k % w);
            let edge_row = j == 0 || (self.far_edge && j + 1 == self.rows);
            if self.held[k] {
                Sink::Supply
            } else if edge_row {
                Sink::Side
            } else if self.periodic {
                Sink::Free
            } else if i == nx {
                Sink::Out
            } else if i == 0 {
                Sink::Supply
            } else {
                Sink::Free
            }
        };
        let add = |to: usize, out: f64, f: &mut Fluxes| match sink(to) {
            Sink::Free => {}
            Sink::Side => f.side += out,
            Sink::Out => f.outflow += out,
            Sink::Supply => f.inflow -= out,
        };
        for j in 1..self.rows {
            for i in first..nx {
                let k = j * w + i;
                if self.ap[k] <= 0.0 {
                    continue;
                }
                let kw = if i == 0 { k + nx - 1 } else { k - 1 };
                add(
                    k + 1,
                    self.ce[k] * content[k] - self.ae[k] * (p[k + 1] - p[k]),
                    &mut f,
                );
                add(
                    kw,
                    self.aw[k] * (p[k] - p[kw]) - self.cw[k] * content[kw],
                    &mut f,
                );
                add(k - w, self.a_s[k] * (p[k] - p[k - w]), &mut f);
                if j + 1 < self.rows {
                    add(k + w, self.an[k] * (p[k] - p[k + w]), &mut f);
                }
                f.squeeze += self.src[k] * content[k];
            }
        }
        f
    }

    /// Largest cell imbalance of the mass-conserving balance, relative to the largest Couette
    /// face flux.
    pub fn mass_residual(&self, p: &[f64], content: &[f64]) -> f64 {
        let w = self.nx + 1;
        let (mut worst, mut scale) = (0.0f64, 0.0f64);
        let first = if self.periodic { 0 } else { 1 };
        for j in 1..self.rows {
            for i in first..self.nx {
                let k = j * w + i;
                if self.ap[k] <= 0.0 {
                    continue;
                }
                let kw = if i == 0 { k + self.nx - 1 } else { k - 1 };
                let north = if j + 1 < self.rows { p[k + w] } else { 0.0 };
                let diffusion = self.ae[k] * (p[k + 1] - p[k])
                    + self.aw[k] * (p[kw] - p[k])
                    + self.an[k] * (north - p[k])
                    + self.a_s[k] * (p[k - w] - p[k]);
                let r = self.ce[k] * content[k] - self.cw[k] * content[kw]
                    + self.src[k] * content[k]
                    - diffusion;
                worst = worst.max(r.abs());
                scale = scale.max(self.ce[k]);
            }
        }
        worst / scale.max(f64::MIN_POSITIVE)
    }
}

/// Bilinear transfer of a field from `coarse` to `fine` (same x extent; used to start a fine
/// solve from a converged coarse one).
pub fn prolong(coarse: &Grid, pc: &[f64], fine: &Grid) -> Vec<f64> {
    let mut out = vec![0.0; (fine.nx() + 1) * (fine.ny + 1)];
    let (wc, wf) = (coarse.nx() + 1, fine.nx() + 1);
    for j in 0..=fine.ny {
        let yc = fine.y(j) / coarse.dy();
        let j0 = (yc.floor() as usize).min(coarse.ny.saturating_sub(1));
        let ty = (yc - j0 as f64).clamp(0.0, 1.0);
        for i in 0..=fine.nx() {
            let x = fine.x[i];
            let i0 = coarse.x.partition_point(|&c| c <= x).clamp(1, coarse.nx()) - 1;
            let tx = ((x - coarse.x[i0]) / (coarse.x[i0 + 1] - coarse.x[i0])).clamp(0.0, 1.0);
            let v = |ii: usize, jj: usize| pc[jj * wc + ii];
            let lo = v(i0, j0) * (1.0 - tx) + v(i0 + 1, j0) * tx;
            let hi = v(i0, j0 + 1) * (1.0 - tx) + v(i0 + 1, j0 + 1) * tx;
            out[j * wf + i] = lo * (1.0 - ty) + hi * ty;
        }
    }
    out[..=fine.nx()].fill(0.0);
    for j in 0..=fine.ny {
        out[j * wf] = 0.0;
        out[j * wf + fine.nx()] = 0.0;
        if j == fine.ny && !fine.symmetric {
            for i in 0..=fine.nx() {
                out[j * wf + i] = 0.0;
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fidelity::StopReason;
    use std::sync::atomic::AtomicBool;
    use std::sync::Arc;
    use std::time::Instant;

    fn uniform(nx: usize, ny: usize, width: f64, symmetric: bool) -> Grid {
        Grid {
            x: (0..=nx).map(|i| i as f64 / nx as f64).collect(),
            ny,
            width,
            symmetric,
            periodic: false,
        }
    }

    /// Uniform film, no wedge, constant unit source on the unit square: the Poisson problem
    /// ∇²p = 1 with p = 0 on the edges; the centre value is −0.07367 (series solution).
    #[test]
    fn poisson_square_matches_the_series_solution() {
        let film = |_: f64, _: f64| 1.0;
        let src = |_: f64, _: f64| 1.0;
        let problem = Problem {
            film: &film,
            conductance: None,
            anisotropy: 1.0,
            wedge: 0.0,
            source: Some(&src),
            held: None,
        };
        for (grid, centre) in [
            (uniform(32, 32, 1.0, false), (16, 16)),
            (uniform(32, 16, 0.5, true), (16, 16)),
        ] {
            let s = Stencil::assemble(&grid, &problem);
            let mut p = vec![0.0; (grid.nx() + 1) * (grid.ny + 1)];
            solve(&s, &mut p, false, &Budget::unlimited()).unwrap();
            let v = p[at(&grid, centre.0, centre.1)];
            assert!((v + 0.073671).abs() < 2e-4, "{v}");
        }
    }

    /// A one-dimensional slider (no y-variation of h, very wide): p stays ≥ 0 under cavitation
    /// and matches the free solution where the free one is positive (a converging wedge).
    #[test]
    fn cavitation_clips_only_negative_pressure() {
        let grid = uniform(64, 8, 0.5, true);
        let film = |x: f64, _: f64| 2.0 - x; // converging in +x: positive pressure
        let problem = Problem {
            film: &film,
            conductance: None,
            anisotropy: 1e-6,
            wedge: 6.0,
            source: None,
            held: None,
        };
        let s = Stencil::assemble(&grid, &problem);
        let mut free = vec![0.0; (grid.nx() + 1) * (grid.ny + 1)];
        let mut cav = free.clone();
        solve(&s, &mut free, false, &Budget::unlimited()).unwrap();
        solve(&s, &mut cav, true, &Budget::unlimited()).unwrap();
        assert!(free.iter().all(|&v| v >= -1e-12));
        for (a, b) in free.iter().zip(&cav) {
            assert!((a - b).abs() < 1e-8);
        }
        // Plane slider with h1/h2 = 2: the peak sits at 2/3 of the length from the inlet.
        let mid = grid.ny;
        let row: Vec<f64> = (0..=grid.nx()).map(|i| free[at(&grid, i, mid)]).collect();
        let imax = row
            .iter()
            .enumerate()
            .max_by(|a, b| a.1.total_cmp(b.1))
            .unwrap()
            .0;
        let xmax = grid.x[imax];
        assert!((xmax - 2.0 / 3.0).abs() < 0.03, "peak at {xmax}");
    }

    #[test]
    fn capped_and_late_solves_report_why() {
        let grid = uniform(32, 8, 0.5, true);
        let film = |x: f64, _: f64| 2.0 - x;
        let problem = Problem {
            film: &film,
            conductance: None,
            anisotropy: 1.0,
            wedge: 6.0,
            source: None,
            held: None,
        };
        let s = Stencil::assemble(&grid, &problem);
        let n = (grid.nx() + 1) * (grid.ny + 1);
        let (mut p, mut content) = (vec![0.0; n], vec![1.0; n]);
        let r = solve_mass_conserving(
            &s,
            1.5,
            &mut p,
            &mut content,
            Stopping {
                tolerance: 1e-14,
                max_sweeps: 5,
            },
            &Budget::unlimited(),
        );
        assert!(
            matches!(r, Err(ref s) if s.reason() == StopReason::IterationCap && s.report.iterations == 5)
        );
        let r = solve(
            &s,
            &mut p,
            true,
            &Budget::new(Instant::now(), Arc::new(AtomicBool::new(true))),
        );
        assert!(matches!(r, Err(ref s) if s.reason() == StopReason::Deadline));
    }

    /// A journal-like film h = 1 + 0.8 cos x over [0, 2π]: the active-set solution meets the
    /// complementarity conditions to rounding (p ≥ 0; the free equations hold; no cavitated
    /// node pulls upward), a warm start from a nearby film lands on the same field in fewer
    /// steps, and the linear response to a change of ε matches the difference of two solves.
    #[test]
    fn complementarity_holds_and_the_linear_response_matches_resolves() {
        let grid = Grid {
            x: (0..=96)
                .map(|i| 2.0 * std::f64::consts::PI * i as f64 / 96.0)
                .collect(),
            ny: 12,
            width: 0.5,
            symmetric: true,
            periodic: false,
        };
        let stencil_at = |eps: f64| {
            let film = move |x: f64, _: f64| 1.0 + eps * x.cos();
            Stencil::assemble(
                &grid,
                &Problem {
                    film: &film,
                    conductance: None,
                    anisotropy: 0.25,
                    wedge: 12.0 * std::f64::consts::PI,
                    source: None,
                    held: None,
                },
            )
        };
        let n = (grid.nx() + 1) * (grid.ny + 1);
        let s = stencil_at(0.8);
        let mut p = vec![0.0; n];
        let cold = solve(&s, &mut p, true, &Budget::unlimited()).unwrap();
        assert!(p.iter().all(|&v| v >= 0.0));
        assert!(s.residual(&p, true) < 1e-12, "{}", s.residual(&p, true));
        assert!(p.iter().filter(|&&v| v == 0.0).count() > n / 3, "cavitated");
        let mut warm = p.clone();
        let warmed = solve(&stencil_at(0.79), &mut warm, true, &Budget::unlimited()).unwrap();
        let mut fresh = vec![0.0; n];
        solve(&stencil_at(0.79), &mut fresh, true, &Budget::unlimited()).unwrap();
        assert!(warm.iter().zip(&fresh).all(|(a, b)| (a - b).abs() < 1e-12));
        assert!(
            warmed.report.iterations < cold.report.iterations,
            "{} vs {}",
            warmed.report.iterations,
            cold.report.iterations
        );

        let d = 1e-5;
        let (plus, minus) = (stencil_at(0.8 + d), stencil_at(0.8 - d));
        let change: Vec<f64> = plus
            .residuals(&p)
            .iter()
            .zip(minus.residuals(&p))
            .map(|(a, b)| (a - b) / (2.0 * d))
            .collect();
        let dp = Linearised::at(&s, &p).unwrap().response(&change, &p);
        let (mut pp, mut pm) = (p.clone(), p.clone());
        solve(&plus, &mut pp, true, &Budget::unlimited()).unwrap();
        solve(&minus, &mut pm, true, &Budget::unlimited()).unwrap();
        let peak = dp.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        for k in 0..n {
            let fd = (pp[k] - pm[k]) / (2.0 * d);
            assert!(
                (dp[k] - fd).abs() < 1e-4 * peak,
                "node {k}: {} vs {fd}",
                dp[k]
            );
        }
    }

    /// A one-dimensional film with two converging–diverging lobes, flooded at the inlet: the
    /// mass-conserving solve closes its flow balance, keeps p ≥ 0, 0 ≤ θ ≤ 1 and p (1 − θ) = 0,
    /// and agrees with the Reynolds condition on the first lobe (rupture obeys the same
    /// p = ∂p/∂n = 0 condition); the second lobe must reform from the streamers the first
    /// rupture left, so it starts later and carries less than the Reynolds condition says
    /// (Stachowiak & Batchelor §5.6.3: without reformation the film is overestimated).
    #[test]
    fn mass_conserving_film_reforms_later_than_the_reynolds_condition() {
        let grid = uniform(400, 4, 0.5, true);
        let film = |x: f64, _: f64| 1.5 + 0.5 * (4.0 * std::f64::consts::PI * x).cos();
        let problem = Problem {
            film: &film,
            conductance: None,
            anisotropy: 1e-6,
            wedge: 6.0,
            source: None,
            held: None,
        };
        let s = Stencil::assemble(&grid, &problem);
        let n = (grid.nx() + 1) * (grid.ny + 1);
        let stop = Stopping {
            tolerance: 1e-11,
            max_sweeps: 400_000,
        };
        let omega = s.sor_factor(&grid);
        let mut reynolds = vec![0.0; n];
        solve(&s, &mut reynolds, true, &Budget::unlimited()).unwrap();
        let (mut p, mut theta) = (vec![0.0; n], vec![1.0; n]);
        let done = solve_mass_conserving(&s, omega, &mut p, &mut theta, stop, &Budget::unlimited())
            .unwrap();
        assert!(done.report.residual.is_some_and(|r| r < 1e-8), "{done:?}");
        let flows = s.fluxes(&p, &theta);
        assert!(flows.imbalance().abs() < 1e-7, "{flows:?}");
        for k in 0..n {
            assert!(p[k] >= 0.0 && (0.0..=1.0).contains(&theta[k]));
            assert!(p[k] == 0.0 || theta[k] == 1.0);
        }
        // The Reynolds-condition field destroys and creates mass at its boundaries.
        let ones = vec![1.0; n];
        assert!(s.fluxes(&reynolds, &ones).imbalance().abs() > 1e-2);
        let mid = grid.ny;
        let lobe = |f: &[f64], a: f64, b: f64| -> f64 {
            (0..=grid.nx())
                .filter(|&i| grid.x[i] >= a && grid.x[i] < b)
                .map(|i| f[at(&grid, i, mid)] * grid.cv_x(i))
                .sum()
        };
        // Up to the first rupture (x ≈ 0.32, h ≈ 1.2) the two agree; beyond it the Reynolds
        // condition refills the gap at once and builds pressure from x ≈ 0.34, the streamers
        // (θ h = 1.2) fill it only at x = 0.5, where the second lobe starts with the same flow.
        let (r1, j1) = (lobe(&reynolds, 0.0, 0.3), lobe(&p, 0.0, 0.3));
        let (r2, j2) = (lobe(&reynolds, 0.3, 1.0), lobe(&p, 0.3, 1.0));
        assert!((j1 / r1 - 1.0).abs() < 1e-3, "first lobe {j1} vs {r1}");
        assert!(j2 < 0.75 * r2, "beyond the rupture {j2} vs {r2}");
        let first_pressure = (0..=grid.nx())
            .find(|&i| grid.x[i] > 0.33 && p[at(&grid, i, mid)] > 0.0)
            .map(|i| grid.x[i]);
        assert!(
            first_pressure.is_some_and(|x| (x - 0.5).abs() < 0.01),
            "reformed at {first_pressure:?}"
        );
        // Ahead of the reformation the streamers carry the rupture's flow: θ h constant.
        let row: Vec<(f64, f64, f64)> = (0..=grid.nx())
            .map(|i| {
                let k = at(&grid, i, mid);
                (grid.x[i], theta[k], film(grid.x[i], 0.0))
            })
            .collect();
        let cav: Vec<f64> = row
            .iter()
            .filter(|r| r.1 < 0.95)
            .map(|r| r.1 * r.2)
            .collect();
        assert!(cav.len() > 10);
        let (lo, hi) = cav
            .iter()
            .fold((f64::MAX, f64::MIN), |(a, b), &v| (a.min(v), b.max(v)));
        assert!(hi - lo < 0.02 * hi, "θh from {lo} to {hi}");
    }

    /// A periodic film whose seam column is held flooded at p = 0 is the same problem as the
    /// open film fed at x0 and discharging at x1: the same field, and the supply the held
    /// column gives is the open film's inflow less its outflow. A port held at a supply
    /// pressure over part of the width feeds exactly what leaves at the sides.
    /// A periodic full film (negative pressures kept) by the direct solve: a long bearing's
    /// mid-plane tends to Sommerfeld's infinitely long film (Khonsari & Booser Eq. 8.10,
    /// p = 6ε sin θ (2 + ε cos θ)/((2 + ε²)(1 + ε cos θ)²) for ∂θ(h³∂θp) = 6 ∂θh), which is odd
    /// about θ = π; the seam's column nx repeats column 0 and every node's equation holds.
    #[test]
    fn periodic_full_film_is_sommerfeld_s_long_film() {
        let (n, e) = (256, 0.6);
        let film = move |x: f64, _: f64| 1.0 + e * x.cos();
        let grid = Grid {
            x: (0..=n)
                .map(|i| 2.0 * std::f64::consts::PI * i as f64 / n as f64)
                .collect(),
            ny: 32,
            width: 12.0,
            symmetric: true,
            periodic: true,
        };
        let problem = Problem {
            film: &film,
            conductance: None,
            anisotropy: 1.0,
            wedge: 6.0,
            source: None,
            held: None,
        };
        let stencil = Stencil::assemble(&grid, &problem);
        let mut p = vec![0.0; (n + 1) * (grid.ny + 1)];
        let solved = solve(&stencil, &mut p, false, &Budget::unlimited()).unwrap();
        assert_eq!(solved.report.iterations, 1);
        let sommerfeld = |t: f64| {
            6.0 * e * t.sin() * (2.0 + e * t.cos()) / ((2.0 + e * e) * (1.0 + e * t.cos()).powi(2))
        };
        let peak = (0..n)
            .map(|i| sommerfeld(grid.x[i]).abs())
            .fold(0.0, f64::max);
        let mid = grid.ny;
        for i in 0..n {
            let k = at(&grid, i, mid);
            assert!(
                (p[k] - sommerfeld(grid.x[i])).abs() < 2e-3 * peak,
                "θ node {i}"
            );
            assert!(
                (p[k] + p[at(&grid, n - i, mid)]).abs() < 1e-9 * peak,
                "odd at {i}"
            );
        }
        for j in 0..=grid.ny {
            assert_eq!(p[at(&grid, 0, j)], p[at(&grid, n, j)]);
        }
        let scale = stencil.ap.iter().fold(0.0f64, |a, &b| a.max(b)) * peak;
        let r = stencil.residuals(&p);
        assert!(r.iter().all(|v| v.abs() < 1e-10 * scale));
        assert!(stencil.residual(&p, false) < 1e-10);
        // The seam column's equations are in both residuals: a change at a seam node shows.
        let k = at(&grid, 0, mid / 2);
        let mut q = p.clone();
        q[k] += 1e-3 * peak;
        q[at(&grid, n, mid / 2)] = q[k];
        assert!(stencil.residuals(&q)[k].abs() > 1e-4 * stencil.ap[k] * peak);
        assert!(stencil.residual(&q, false) > 1e-6);
    }

    #[test]
    fn periodic_film_with_held_ports() {
        let film = |x: f64, _: f64| 1.0 + 0.6 * x.cos();
        let mut grid = Grid {
            x: (0..=96)
                .map(|i| 2.0 * std::f64::consts::PI * i as f64 / 96.0)
                .collect(),
            ny: 8,
            width: 0.5,
            symmetric: true,
            periodic: false,
        };
        let open_problem = Problem {
            film: &film,
            conductance: None,
            anisotropy: 0.25,
            wedge: 6.0,
            source: None,
            held: None,
        };
        let stop = Stopping {
            tolerance: 1e-12,
            max_sweeps: 200_000,
        };
        let n = (grid.nx() + 1) * (grid.ny + 1);
        let open = Stencil::assemble(&grid, &open_problem);
        let omega = open.sor_factor(&grid);
        let (mut p0, mut t0) = (vec![0.0; n], vec![1.0; n]);
        solve_mass_conserving(&open, omega, &mut p0, &mut t0, stop, &Budget::unlimited()).unwrap();
        let f0 = open.fluxes(&p0, &t0);

        grid.periodic = true;
        let seam = |x: f64, _: f64| x < 1e-9;
        let problem = Problem {
            held: Some(&seam),
            ..open_problem
        };
        let periodic = Stencil::assemble(&grid, &problem);
        let (mut p1, mut t1) = (vec![0.0; n], vec![1.0; n]);
        solve_mass_conserving(
            &periodic,
            omega,
            &mut p1,
            &mut t1,
            stop,
            &Budget::unlimited(),
        )
        .unwrap();
        let f1 = periodic.fluxes(&p1, &t1);
        for k in 0..n {
            assert!((p0[k] - p1[k]).abs() < 1e-9 * (1.0 + p0[k].abs()), "{k}");
        }
        assert!((f1.inflow - (f0.inflow - f0.outflow)).abs() < 1e-9 * f0.inflow);
        assert!(f1.imbalance().abs() < 1e-8 && f0.imbalance().abs() < 1e-8);

        // A port over the middle third of the width at supply pressure, at x = π/2.
        let port = |x: f64, y: f64| (x - 0.5 * std::f64::consts::PI).abs() < 0.04 && y > 0.33;
        let fed = Problem {
            held: Some(&port),
            ..open_problem
        };
        let s = Stencil::assemble(&grid, &fed);
        let (mut p, mut t) = (vec![0.0; n], vec![1.0; n]);
        for j in 0..=grid.ny {
            for i in 0..=grid.nx() {
                if port(grid.x[i], grid.y(j)) {
                    p[at(&grid, i, j)] = 0.5;
                }
            }
        }
        let done =
            solve_mass_conserving(&s, omega, &mut p, &mut t, stop, &Budget::unlimited()).unwrap();
        assert!(done.report.residual.is_some_and(|r| r < 1e-8));
        let f = s.fluxes(&p, &t);
        assert!(f.inflow > 0.0 && f.outflow == 0.0, "{f:?}");
        assert!(f.imbalance().abs() < 1e-8, "{f:?}");
        assert!(t.iter().any(|&c| c < 0.9), "the film cavitates");
    }
}
