//! The pressure field of a finite fixed pad, solved numerically, and its performance numbers
//! (Khonsari & Booser §6.9 and §7.3, Eq. 6.41–6.49).
//!
//! Reynolds equation (Eq. 6.41), isoviscous, steady:
//!
//! ```text
//! ∂x̄(h̄³ ∂x̄ P̄) + (B/L)² ∂ȳ(h̄³ ∂ȳ P̄) = 6 ∂x̄ h̄,   P̄ = p h2²/(μ U B),  x̄ = x/B,  ȳ = y/L
//! ```
//!
//! with the runner sliding towards +x̄ (leading edge x̄ = 0), P̄ = 0 on all four edges and the
//! Reynolds condition P̄ ≥ 0 wherever the film diverges. The mid-plane ȳ = ½ is a symmetry
//! plane, so half the pad is solved (`numerics::reynolds`, exact active-set solve). A step or
//! the start of a land sits on a node: the finite volumes on either side then carry their own
//! h̄ and the 1-D part of the solution is exact.
//!
//! A turbulent film ([`Flow::Turbulent`], Ng–Pan; Khonsari & Booser Eq. 6.26–6.31) takes the
//! conductances h̄³ 12 G_x and h̄³ 12 G_y at the local Re = Re₂ h̄ (Re₂ = ρ U h2/μ) through the
//! basement's `conductance` hook, and the runner's Couette shear G_f/h̄. A laminar film passes
//! no conductance: its stencil is h̄³ as before, bit for bit.

use super::coefficients::Performance;
use super::profile::Profile;
use crate::calc::turbulence::Flow;
use crate::calc::Budget;
use crate::numerics::interpolate::Parabola;
use crate::numerics::reynolds::{self, at, Axis, Grid, Problem, SolveError, Solved, Stencil};

/// The wedge coefficient of Eq. 6.41.
const WEDGE: f64 = 6.0;

/// Cells along the sliding direction and across half the pad.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Mesh {
    pub along: usize,
    pub across_half: usize,
}

impl Mesh {
    /// Half the cells each way: the mesh Richardson's extrapolation compares with.
    pub fn coarse(self) -> Mesh {
        Mesh {
            along: self.along / 2,
            across_half: self.across_half / 2,
        }
    }
}

/// The grid: uniform along each smooth piece of the profile (a break on a node, the pieces'
/// cells in proportion to their lengths, at least one each), uniform across. With `halves` the
/// grid is the fine one of a Richardson pair: its pieces have exactly twice the cells of
/// [`Mesh::coarse`]'s, so both meshes put the break on a node and the spacing halves exactly.
pub fn grid(mesh: Mesh, profile: Profile, halves: bool) -> Grid {
    // Cells of the first piece on a mesh of n cells along.
    let split = |n: usize, b: f64| ((n as f64 * b).round() as usize).clamp(1, n - 1);
    let x = match profile.breaks() {
        None => uniform(0.0, 1.0, mesh.along),
        Some(b) => {
            let first = if halves {
                2 * split(mesh.along / 2, b)
            } else {
                split(mesh.along, b)
            };
            let mut x = uniform(0.0, b, first);
            x.pop();
            x.extend(uniform(b, 1.0, mesh.along - first));
            x
        }
    };
    Grid {
        x,
        ny: mesh.across_half,
        width: 0.5,
        symmetric: true,
        periodic: false,
    }
}

fn uniform(a: f64, b: f64, cells: usize) -> Vec<f64> {
    (0..=cells)
        .map(|i| a + (b - a) * i as f64 / cells as f64)
        .collect()
}

/// The film solved: its performance and the mid-plane profile of P̄ along x̄.
#[derive(Debug, Clone)]
pub struct Field {
    pub performance: Performance,
    pub solved: Solved,
    /// (x̄, P̄) along the mid-plane.
    pub mid_plane: Vec<(f64, f64)>,
}

/// Solve the pad `profile` of aspect L/B = `l_over_b` in a `flow` on `mesh` (`halves`: as the
/// fine mesh of a Richardson pair, see [`grid`]).
pub fn solve(
    profile: Profile,
    flow: Flow,
    l_over_b: f64,
    mesh: Mesh,
    halves: bool,
    budget: &Budget,
) -> Result<Field, SolveError> {
    let g = grid(mesh, profile, halves);
    let stencil = assemble(profile, flow, l_over_b, &g, 0.0);
    // Start with every node free: a converging pad has no cavitated node, so one active-set
    // step solves it; a diverging part cavitates in the next steps.
    let n = (g.nx() + 1) * (g.ny + 1);
    let mut p = vec![1.0; n];
    for j in 0..=g.ny {
        p[at(&g, 0, j)] = 0.0;
        p[at(&g, g.nx(), j)] = 0.0;
    }
    for i in 0..=g.nx() {
        p[at(&g, i, 0)] = 0.0;
    }
    budget.count_field_solve();
    let solved = reynolds::solve(&stencil, &mut p, true, budget)?;
    let all_full = vec![1.0; n];
    let fluxes = stencil.fluxes(&p, &all_full);
    let performance = integrate(profile, flow, &g, &p, fluxes);
    let mid_plane = (0..=g.nx()).map(|i| (g.x[i], p[at(&g, i, g.ny)])).collect();
    Ok(Field {
        performance,
        solved,
        mid_plane,
    })
}

/// A sector pad's load and centre of pressure from its film in polar coordinates (θ, r),
/// solved rather than mapped to the rectangle at the mean radius as the texts do (Khonsari &
/// Booser §7.2): with x̄ = θ/β along the runner, ȳ = (r − R1)/L across, ρ̄ = r/R_m =
/// 1 + (ȳ − ½) L/R_m, B = R_m β and U = ω R_m, the polar Reynolds equation
/// ∂r(r h³ ∂r p) + ∂θ(h³/r ∂θ p) = 6 μ ω r ∂θ h scales as Table 7.2's pads to
///
/// ```text
/// ∂x̄(h̄³/ρ̄ ∂x̄ P̄) + (B/L)² ∂ȳ(ρ̄ h̄³ ∂ȳ P̄) = 6 ρ̄ ∂x̄ h̄,   W̄ = ∫∫ P̄ ρ̄ dx̄ dȳ,
/// ```
///
/// the rectangle's equation as L/R_m → 0. The basement takes ρ̄ h̄ as the film (the Couette
/// flux) and h̄³/ρ̄, ρ̄ h̄³ as the conductances; the sector is not symmetric about its mean
/// radius, so its whole width is solved (2 × `mesh.across_half` cells). Laminar, isoviscous:
/// (W̄, x̄_cp) and the solve's report.
pub fn solve_sector(
    profile: Profile,
    l_over_b: f64,
    curvature: f64,
    mesh: Mesh,
    budget: &Budget,
) -> Result<(f64, f64, Solved), SolveError> {
    let g = Grid {
        ny: 2 * mesh.across_half,
        width: 1.0,
        symmetric: false,
        ..grid(mesh, profile, false)
    };
    let stencil = assemble(profile, Flow::Laminar, l_over_b, &g, curvature);
    let mut p = vec![0.0; (g.nx() + 1) * (g.ny + 1)];
    for j in 1..g.ny {
        for i in 1..g.nx() {
            p[at(&g, i, j)] = 1.0;
        }
    }
    budget.count_field_solve();
    let solved = reynolds::solve(&stencil, &mut p, true, budget)?;
    let (mut load, mut moment) = (0.0, 0.0);
    for j in 0..=g.ny {
        let w = g.cv_y(j) * (1.0 + (g.y(j) - 0.5) * curvature);
        for i in 0..=g.nx() {
            let v = p[at(&g, i, j)] * g.cv_x(i) * w;
            load += v;
            moment += v * g.x[i];
        }
    }
    Ok((load, moment / load, solved))
}

/// The five-point stencil of the pad on `g`. A node on a step takes the mean of the
/// conductance over its control volume for the flow across (h̄ differs on its two halves).
/// `curvature` is L/R_m of a sector pad solved in polar coordinates ([`solve_sector`]), 0 for
/// the rectangle: then ρ̄ = 1 exactly and the stencil is the rectangle's bit for bit.
fn assemble(profile: Profile, flow: Flow, l_over_b: f64, g: &Grid, curvature: f64) -> Stencil {
    let radius = |y: f64| 1.0 + (y - 0.5) * curvature;
    // The Couette flux per unit ȳ: ρ̄ h̄ (ω r h/2 on a sector).
    let thickness = |x: f64, y: f64| radius(y) * profile.thickness(x);
    // h̄³ scaled by the flow's factor of the direction (1 when laminar).
    let along = |h: f64, axis: Axis| {
        let (gx, gy) = flow.pressure_factors(h);
        h.powi(3) * if axis == Axis::X { gx } else { gy }
    };
    let step = match profile {
        Profile::Step {
            ratio,
            step_position,
        } => {
            let i = g.x.partition_point(|&x| x < step_position);
            let (west, east) = (g.x[i] - g.x[i - 1], g.x[i + 1] - g.x[i]);
            let mean = (west * along(ratio, Axis::Y) + east * along(1.0, Axis::Y)) / (west + east);
            Some((step_position, mean))
        }
        _ => None,
    };
    let conductance = |x: f64, y: f64, axis: Axis| {
        let c = match step {
            Some((at, mean)) if axis == Axis::Y && x == at => mean,
            _ => along(profile.thickness(x), axis),
        };
        // h̄³/ρ̄ around the sector, ρ̄ h̄³ across it.
        if axis == Axis::X {
            c / radius(y)
        } else {
            c * radius(y)
        }
    };
    let scaled = step.is_some() || flow != Flow::Laminar || curvature != 0.0;
    let problem = Problem {
        film: &thickness,
        conductance: scaled.then_some(&conductance as &dyn Fn(f64, f64, Axis) -> f64),
        anisotropy: (1.0 / l_over_b).powi(2),
        wedge: WEDGE,
        source: None,
        held: None,
    };
    Stencil::assemble(g, &problem)
}

/// The performance numbers of the field `p` on the half pad `g` (doubled for the whole pad).
fn integrate(
    profile: Profile,
    flow: Flow,
    g: &Grid,
    p: &[f64],
    fluxes: reynolds::Fluxes,
) -> Performance {
    let nx = g.nx();
    let (mut load, mut moment, mut wedge_shear) = (0.0, 0.0, 0.0);
    for j in 0..=g.ny {
        let wy = g.cv_y(j);
        for i in 0..=nx {
            let v = p[at(g, i, j)] * g.cv_x(i) * wy;
            load += v;
            moment += v * g.x[i];
        }
        // ∫ (h̄/2) ∂P̄/∂x̄ dx̄ face by face, h̄ at each face (exact across a step).
        for i in 0..nx {
            let face = 0.5 * (g.x[i] + g.x[i + 1]);
            wedge_shear +=
                0.5 * profile.thickness(face) * (p[at(g, i + 1, j)] - p[at(g, i, j)]) * wy;
        }
    }
    let couette: f64 = super::long_pad::couette_shear(profile, flow);
    let (peak, peak_x) = peak(profile, g, p);
    // Flows in the stencil's units are 12 Q̄ per unit of ȳ; the half pad is doubled. The
    // stencil's fluxes cross the faces half a cell inside the side edge: the Couette flow
    // h̄/2 along the strip between that face and the edge (where P̄ = 0) enters at the leading
    // edge, leaves partly at the trailing edge and the rest through the side.
    let strip = 0.5 * g.dy();
    let (strip_in, strip_out) = (
        0.5 * profile.thickness(0.0) * strip,
        0.5 * profile.thickness(1.0) * strip,
    );
    Performance {
        load: 2.0 * load,
        friction: couette + 2.0 * wedge_shear,
        center_of_pressure: moment / load,
        max_pressure: peak,
        max_pressure_position: peak_x,
        inlet_flow: 2.0 * (fluxes.inflow / 12.0 + strip_in),
        side_flow: 2.0 * (fluxes.side / 12.0 + strip_in - strip_out),
        outlet_flow: 2.0 * (fluxes.outflow / 12.0 + strip_out),
    }
}

/// The largest pressure (on the mid-plane) and where it is: the node maximum, refined by the
/// parabola through it and its neighbours where the profile is smooth there.
fn peak(profile: Profile, g: &Grid, p: &[f64]) -> (f64, f64) {
    let row = |i: usize| p[at(g, i, g.ny)];
    let top = (1..g.nx())
        .max_by(|&a, &b| row(a).total_cmp(&row(b)))
        .unwrap_or(1);
    let on_break = profile.breaks().is_some_and(|b| g.x[top] == b);
    if on_break || top == 0 || top == g.nx() {
        return (row(top), g.x[top]);
    }
    let parabola = Parabola::through(
        [g.x[top - 1], g.x[top], g.x[top + 1]],
        [row(top - 1), row(top), row(top + 1)],
    );
    if parabola.a >= 0.0 {
        return (row(top), g.x[top]);
    }
    let x = parabola.vertex().clamp(g.x[top - 1], g.x[top + 1]);
    (parabola.at(x).max(row(top)), x)
}

#[cfg(test)]
mod tests;
