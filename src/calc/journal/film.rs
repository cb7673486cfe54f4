//! The pressure field of a plain 360° journal bearing, solved numerically, and the performance
//! numbers integrated from it, in Table 8.6 conventions (Khonsari & Booser §8.12, Eq. 8.36–8.44).
//!
//! Reynolds equation (Eq. 8.36), isoviscous, aligned journal:
//!
//! ```text
//! ∂θ(h̄³ ∂θ P̄) + (1/(4λ²)) ∂ȳ(h̄³ ∂ȳ P̄) = 12π ∂θ h̄,   h̄ = 1 + ε cos θ
//! ```
//!
//! with P̄ = (p − p_s)(C/R)²/(μ N_s), N_s in rev/s, λ = L/D, ȳ = y/L, θ from h_max in the
//! direction of rotation. The film starts at h_max (P̄ = 0 there: the feed line), P̄ = 0 at both
//! ends; cavitation by the Reynolds condition (P̄ ≥ 0). The mid-plane is a symmetry plane, so
//! half the length is solved. Nodes along θ cluster towards h_min, where the pressure spikes at
//! high eccentricity: θ(s) = s + κ sin s on a uniform s, κ = 0.75 ε.
//!
//! Mass-conserving (JFO) cavitation replaces the Reynolds condition on request
//! ([`FilmModel::mass_conserving`]): the film content θ_f is solved with the pressure
//! ([`reynolds::solve_mass_conserving`]), the right side becomes 12π ∂θ(θ_f h̄), and the film is
//! fed either along the same line (flooded, P̄ = 0), or, for a hole or axial-groove feed, through
//! ports held at the supply pressure in a periodic 360° film (P̄ is then above ambient).

use std::cell::Cell;
use std::f64::consts::PI;

use crate::calc::turbulence::{turbulent_flow_factors, turbulent_shear_factor};
use crate::calc::Budget;
use crate::effects::{Decision, Mode};
use crate::fidelity::IterationUnit;
use crate::numerics::banded::NotPositiveDefinite;
use crate::numerics::driver::{Driver, Verdict};
use crate::numerics::interpolate::Parabola;
use crate::numerics::reynolds::{
    self, at, Axis, Fluxes, Grid, Linearised, Problem, SolveError, Solved, Stencil, Stopping,
};

/// The wedge coefficient of Eq. 8.36, 12π (θ in radians, N_s in rev/s).
const WEDGE: f64 = 12.0 * PI;

/// Cells around the circumference and across the half-length.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Mesh {
    pub circumferential: usize,
    pub axial_half: usize,
}

impl Mesh {
    /// Cells in all: around the circumference times across the half-length.
    pub fn cells(self) -> usize {
        self.circumferential * self.axial_half
    }

    /// The mesh a nested solve starts from and the error estimate compares with: half the cells
    /// each way (circumferential counts are even, by validation), at least 2 across the
    /// half-length.
    pub fn coarse(self) -> Mesh {
        Mesh {
            circumferential: self.circumferential / 2,
            axial_half: (self.axial_half / 2).max(2),
        }
    }

    /// Whether [`Mesh::coarse`] halves the spacing exactly in both directions — the ratio 2 that
    /// Richardson's f + (f − c)/3 assumes for a second-order scheme.
    pub fn halves_exactly(self) -> bool {
        self.circumferential.is_multiple_of(2)
            && self.axial_half.is_multiple_of(2)
            && self.axial_half >= 4
    }

    /// The refinement ratio r from [`Mesh::coarse`] to this mesh for the error estimate
    /// |f − c|/(r² − 1): exactly 2 when halving; otherwise the smaller of the two directions'
    /// ratios (the larger, conservative estimate), or the circumferential ratio alone when the
    /// axial count cannot be reduced (2 cells: the estimate then lacks the axial part).
    pub fn refinement_ratio(self) -> f64 {
        let c = self.coarse();
        let rx = self.circumferential as f64 / c.circumferential as f64;
        let ry = self.axial_half as f64 / c.axial_half as f64;
        if ry > 1.0 {
            rx.min(ry)
        } else {
            rx
        }
    }
}

/// Everything the numbers of Table 8.6 are made from, for one solve.
#[derive(Debug, Clone, PartialEq)]
pub struct FilmSolution {
    /// Dimensionless load components (∫∫ P̄ dθ dȳ over the full length): along the line of
    /// centres towards h_max, and perpendicular to it, against the rotation.
    pub load_radial: f64,
    pub load_tangential: f64,
    /// P̄_max and its angle from h_max, rad (mid-plane).
    pub max_pressure_nd: f64,
    pub max_pressure_angle: f64,
    /// Film rupture angle from h_max on the mid-plane, rad (2π when the film never ruptures).
    pub cavitation_angle: f64,
    /// Q_L/((π/2) N_s D L C), both ends.
    pub side_leakage_nd: f64,
    /// Q_i/((π/2) N_s D L C) at the feed line θ = 0.
    pub inlet_flow_nd: f64,
    /// The film's extent (θ start, θ end).
    pub span: (f64, f64),
    /// The smallest film thickness h̄_min = h_min/C.
    pub min_thickness: f64,
    /// ∫∫ P̄ (−∂h̄/∂θ) dθ dȳ: the pressure-gradient part of the journal's shear, integrated by
    /// parts (P̄ = 0 on the edges).
    pub pressure_shear: f64,
    /// The pressure's moment on the journal about the bearing centre (the axis at mid-length),
    /// ∫∫ P̄ (ȳ − ½)(sin θ, −cos θ) dθ dȳ in the film frame (towards h_max, 90° ahead), with z
    /// along the spin and ȳ increasing along z; M = μ N_s (R/C)² R L² times it. Zero for an
    /// aligned (symmetric) film.
    pub moment: [f64; 2],
    /// ∫∫ G_f/h̄ dθ dȳ over the film: the Couette part (G_f = 1 laminar), shear over the whole
    /// span whatever the film does (the Table 8.6 convention).
    pub couette_shear: f64,
    /// (θ, P̄) at the grid nodes of the mid-plane.
    pub midplane: Vec<(f64, f64)>,
    /// Mass-conserving films only: the film content θ_f (liquid fraction of the gap) at the
    /// mid-plane nodes, the fraction of the film's area that is cavitated (θ_f < 1), and the
    /// discrete flow balance.
    pub midplane_content: Option<Vec<f64>>,
    pub cavitated_fraction: Option<f64>,
    pub flow_balance: Option<FlowBalance>,
    pub solved: Solved,
}

/// The flows through the film's boundaries as the finite volumes pass them (the stencil's face
/// fluxes; first-order at the p = 0 edges, so the reported leakage takes the edge gradient to
/// second order instead), Q/((π/2) N_s D L C). For a converged mass-conserving film
/// supply = outlet + side to the solver's tolerance.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlowBalance {
    /// In from the feed line or ports.
    pub supply: f64,
    /// Out through the film's end line (0 for a periodic film).
    pub outlet: f64,
    /// Out at both ends of the bearing.
    pub side: f64,
}

impl FlowBalance {
    /// (supply − outlet − side)/supply.
    pub fn imbalance(&self) -> f64 {
        (self.supply - self.outlet - self.side) / self.supply.abs().max(1e-300)
    }
}

impl FilmSolution {
    /// S = μ N_s L D (R/C)²/W = 2 / |∫∫ P̄|.
    pub fn sommerfeld_number(&self) -> f64 {
        2.0 / self.load_radial.hypot(self.load_tangential)
    }
    /// Attitude angle φ between the load line and the line of centres, rad.
    pub fn attitude_angle(&self) -> f64 {
        self.load_tangential.atan2(self.load_radial)
    }
}

/// The θ grid: nodes clustered towards h_min.
pub fn circumferential_nodes(cells: usize, eps: f64) -> Vec<f64> {
    let kappa = 0.75 * eps.clamp(0.0, 1.0);
    (0..=cells)
        .map(|i| {
            let s = 2.0 * PI * i as f64 / cells as f64;
            s + kappa * s.sin()
        })
        .collect()
}

/// The clustered θ grid of a full circle that starts at `start`: θ = s + κ sin s on a uniform s
/// from s₀ (s₀ + κ sin s₀ = start, by Newton: the map is monotone for κ < 1) over 2π.
pub fn circumferential_nodes_from(start: f64, cells: usize, eps: f64) -> Vec<f64> {
    let kappa = 0.75 * eps.clamp(0.0, 1.0);
    let mut s0 = start;
    // The map is monotone, so Newton settles in a few steps; at the cap of 50 (not reached in
    // practice) the last iterate is taken.
    let _settled = Driver::new(
        "newton_grid_start",
        IterationUnit::NewtonSteps,
        50,
        &Budget::unlimited(),
    )
    .run(|_| {
        let step = (s0 + kappa * s0.sin() - start) / (1.0 + kappa * s0.cos());
        s0 -= step;
        if step.abs() < 1e-15 {
            Verdict::Converged((), step.abs())
        } else {
            Verdict::Continue(step.abs())
        }
    });
    let mut x: Vec<f64> = (0..=cells)
        .map(|i| {
            let s = s0 + 2.0 * PI * i as f64 / cells as f64;
            s + kappa * s.sin()
        })
        .collect();
    x[0] = start;
    x[cells] = start + 2.0 * PI;
    x
}

/// The grid of `film` on `mesh`: the full circle clustered towards h_min, or a partial arc with
/// as many cells per radian as the full circle would have twice over.
pub fn grid(mesh: Mesh, film: &Film) -> Grid {
    let x = match film.span {
        None => circumferential_nodes(mesh.circumferential, film.eccentricity_ratio),
        // A full circle fed elsewhere than at h_max: the same clustering, shifted to start there.
        Some((start, end)) if (end - start - 2.0 * PI).abs() < 1e-12 => {
            circumferential_nodes_from(start, mesh.circumferential, film.eccentricity_ratio)
        }
        Some((start, end)) => {
            let cells = ((mesh.circumferential as f64) * (end - start) / PI)
                .round()
                .max(16.0) as usize;
            (0..=cells)
                .map(|i| start + (end - start) * i as f64 / cells as f64)
                .collect()
        }
    };
    let symmetric = film.tilt.is_none();
    Grid {
        x,
        ny: if symmetric {
            mesh.axial_half
        } else {
            2 * mesh.axial_half
        },
        width: if symmetric { 0.5 } else { 1.0 },
        symmetric,
        periodic: film.periodic(),
    }
}

/// The film's shape and motion: h̄ = 1 + A cos θ + B sin θ with ∂h̄/∂τ = Ȧ cos θ + Ḃ sin θ
/// (τ = N_s t). At equilibrium A = ε, B = 0 and the film is still; the dynamic coefficients
/// perturb A, B, Ȧ and Ḃ about it on the same grid and with the same feed line.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Film {
    pub eccentricity_ratio: f64,
    pub l_over_d: f64,
    pub cos_offset: f64,
    pub sin_offset: f64,
    pub cos_rate: f64,
    pub sin_rate: f64,
    pub physics: FilmModel,
    /// The film's extent in θ (from h_max): (start, end); the full circle from h_max when None.
    pub span: Option<(f64, f64)>,
    /// Misalignment in the film frame: (ε′, direction of the tilt θ_δ from h_max); the film is
    /// then h̄ = 1 + A cos θ + B sin θ − ε′ (ȳ − ½) cos(θ − θ_δ) over the whole length ȳ ∈ [0, 1].
    pub tilt: Option<(f64, f64)>,
    /// The journal turns: the wedge term 12π ∂θh̄ is in the equation (true for every
    /// [`Film::steady`] film). False: a pure squeeze film (Khonsari & Booser §9.5–9.6), driven
    /// by the rates alone; its pressure scale N_s is then the squeeze's own rate (with Ȧ = 1,
    /// P̄ = p (C/R)²/(μ ε̇)). A pure squeeze film without cavitation has no feed line: it is
    /// periodic round the circle (one banded solve, its columns numbered round the seam).
    pub rotating: bool,
}

/// What the film model includes beyond the isoviscous, laminar Reynolds equation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FilmModel {
    /// Reynolds cavitation (p ≥ 0); false keeps the full (Sommerfeld) film with its negative
    /// pressures.
    pub cavitation: bool,
    /// Gümbel's half-Sommerfeld film (with `cavitation` false): the full film is solved and its
    /// negative pressures are set to zero afterwards, so the film carries only its positive
    /// part (the model of ROSS's `FluidFlow` and of the short bearing's closed form). It does
    /// not conserve mass at the rupture; the Reynolds condition is the physical one.
    pub half_sommerfeld: bool,
    /// Turbulent film by the linearised Ng–Pan model (Khonsari & Booser Eq. 6.26–6.31), with the
    /// Reynolds number ρ U C/μ at the clearance; local Re = Re_C h̄. None: laminar.
    pub turbulence_reynolds: Option<f64>,
    /// A partial bearing: its arc, rad, centred on the load line (None: the full 360° bearing,
    /// fed at h_max).
    pub arc: Option<f64>,
    /// A misaligned journal (Khonsari & Booser Eq. 8.70); None: aligned.
    pub misalignment: Option<Misalignment>,
    /// Mass-conserving (JFO) cavitation in place of the Reynolds condition, with the supply
    /// that feeds it (requires `cavitation`).
    pub mass_conserving: Option<Supply>,
}

/// A tilted journal (Khonsari & Booser Eq. 8.70). Stachowiak & Batchelor's PARTIAL and
/// STABILITY programs tilt in the load plane: load line, direction 0.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Misalignment {
    /// ε′ = (difference of the journal-centre displacements at the two ends)/C, dimensionless.
    pub tilt: f64,
    /// Direction of the tilt in the direction of rotation, rad, from the load line (or from the
    /// line of centres when `from_line_of_centres`).
    pub direction: f64,
    /// The direction is measured from the line of centres (a tilt that follows the journal).
    pub from_line_of_centres: bool,
}

impl Misalignment {
    /// The tilt's direction θ_δ in the film frame (from h_max, positive with rotation) when the
    /// attitude angle is φ: the load line lies at θ = π − φ there, h_min at θ = π.
    pub fn film_direction(&self, attitude: f64) -> f64 {
        if self.from_line_of_centres {
            PI + self.direction
        } else {
            PI - attitude + self.direction
        }
    }

    /// The tilt's direction u in the load frame (x along the load, y 90° ahead in the rotation)
    /// when the attitude angle is φ.
    pub fn load_frame_direction(&self, attitude: f64) -> f64 {
        if self.from_line_of_centres {
            // h_min lies φ ahead of the load line.
            self.direction + attitude
        } else {
            self.direction
        }
    }

    /// The component of a moment (M_x, M_y) in the load frame against the tilt: −M·(z × u), the
    /// tilt being a rotation about z × u; positive when the film resists the misalignment.
    pub fn restoring(&self, attitude: f64, [mx, my]: [f64; 2]) -> f64 {
        let towards = self.load_frame_direction(attitude);
        -(mx * -towards.sin() + my * towards.cos())
    }

    /// The misalignment effect's decision: applied when the request tilts the journal and the
    /// effect is not off.
    pub fn decision(given: Option<Misalignment>, mode: Mode) -> Decision {
        match (given, mode) {
            (None, _) => Decision::not_applicable(mode, "the request gives no misalignment: journal aligned"),
            (Some(Misalignment { tilt: e, .. }), Mode::Off) => Decision::not_applicable(
                mode,
                format!("requested off: the misalignment given (ε′ = {e:.4} of the clearance) is not applied; journal aligned"),
            ),
            (Some(Misalignment {
                tilt: e,
                direction: dir,
                from_line_of_centres: from_centres,
            }), Mode::Auto | Mode::On) => Decision {
                applied: true,
                mode: Mode::On,
                reason: format!(
                    "journal tilted {:.1}° from the {}: the ends' centres differ by ε′ = {e:.4} of the clearance (Khonsari & Booser Eq. 8.70); whole-length film, h_min at an end",
                    dir.to_degrees(),
                    if from_centres { "line of centres" } else { "load line" }
                ),
                criterion: None,
                model: None,
            },
        }
    }
}

/// Where a mass-conserving film is fed.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FeedLine {
    /// At h_max (the Reynolds model's feed line, Table 8.6).
    MaxFilm,
    /// Opposite the load (a hole or groove at the top of a bottom-loaded bearing): φ ahead of
    /// h_max against the rotation, inside the Reynolds model's cavitated zone; the film must
    /// reform from what the supply fills.
    OppositeLoad,
    /// Two axial grooves at ±90° to the load line (at θ = π/2 − φ and 3π/2 − φ).
    TwoGrooves,
}

/// The supply of a mass-conserving film: where, and through what.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Supply {
    pub position: FeedLine,
    /// None: a line across the whole length, flooded (θ_f = 1) at the edges' pressure, where
    /// the film starts and ends (the Reynolds model's feed line). Some: a port of finite size
    /// at supply pressure in a periodic 360° film, which elsewhere carries round whatever
    /// leaves the cavitated zone.
    pub port: Option<Port>,
}

impl Supply {
    /// A flooded line feed at `position`.
    pub fn line(position: FeedLine) -> Supply {
        Supply {
            position,
            port: None,
        }
    }
}

/// A feed port (hole or axial groove), centred on the mid-plane.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Port {
    /// Axial extent over the bearing length (L_g/L, or D_H/L for a hole).
    pub length_ratio: f64,
    /// Angular width, rad (w_g/R, or D_H/R for a hole); at least one node column.
    pub width: f64,
    /// Supply pressure above ambient, P̄_s = p_s (C/R)²/(μ N_s).
    pub pressure_nd: f64,
}

impl FilmModel {
    /// Laminar with Reynolds cavitation: the base model (Table 8.6).
    pub const REYNOLDS: FilmModel = FilmModel {
        cavitation: true,
        half_sommerfeld: false,
        turbulence_reynolds: None,
        arc: None,
        misalignment: None,
        mass_conserving: None,
    };

    /// The film content is a field of its own (mass-conserving cavitation).
    pub fn has_content(&self) -> bool {
        self.cavitation && self.mass_conserving.is_some()
    }

    /// A mass-conserving 360° film fed through ports: periodic, with held port nodes.
    pub fn port(&self) -> Option<(FeedLine, Port)> {
        match self.mass_conserving {
            Some(Supply {
                position,
                port: Some(port),
            }) if self.cavitation && self.arc.is_none() => Some((position, port)),
            _ => None,
        }
    }
}

impl Film {
    /// The aligned, steady film at eccentricity ratio ε.
    pub fn steady(eccentricity_ratio: f64, l_over_d: f64) -> Film {
        Film {
            eccentricity_ratio,
            l_over_d,
            cos_offset: 0.0,
            sin_offset: 0.0,
            cos_rate: 0.0,
            sin_rate: 0.0,
            physics: FilmModel::REYNOLDS,
            span: None,
            tilt: None,
            rotating: true,
        }
    }

    /// The wedge coefficient of Eq. 8.36: 12π for a turning journal, 0 for pure squeeze.
    fn wedge(&self) -> f64 {
        if self.rotating {
            WEDGE
        } else {
            0.0
        }
    }

    /// Whether the film closes on itself round the circle: fed through ports (mass-conserving),
    /// or a pure squeeze film that keeps its negative pressures (no feed line).
    fn periodic(&self) -> bool {
        self.physics.port().is_some() || (!self.rotating && !self.physics.cavitation)
    }
    fn a(&self) -> f64 {
        self.eccentricity_ratio + self.cos_offset
    }
    /// The y-term's weight in Eq. 8.36 on ȳ = y/L: 1/(4λ²), λ = L/D.
    fn anisotropy(&self) -> f64 {
        1.0 / (4.0 * self.l_over_d * self.l_over_d)
    }

    /// h̄(θ, ȳ), ȳ = y/L from one end.
    pub fn thickness(&self, theta: f64, y: f64) -> f64 {
        self.thickness_at(theta.sin_cos(), y)
    }

    /// h̄ at (sin θ, cos θ) and ȳ.
    fn thickness_at(&self, (sin, cos): (f64, f64), y: f64) -> f64 {
        let tilt = self.tilt.map_or(0.0, |(e, dir)| {
            let (sd, cd) = dir.sin_cos();
            e * (y - 0.5) * (cos * cd + sin * sd)
        });
        1.0 + self.a() * cos + self.sin_offset * sin - tilt
    }

    /// ∂h̄/∂θ at (sin θ, cos θ) and ȳ.
    fn slope_at(&self, (sin, cos): (f64, f64), y: f64) -> f64 {
        let tilt = self.tilt.map_or(0.0, |(e, dir)| {
            let (sd, cd) = dir.sin_cos();
            e * (y - 0.5) * (sin * cd - cos * sd)
        });
        -self.a() * sin + self.sin_offset * cos + tilt
    }

    /// ∂h̄/∂θ at θ and ȳ.
    pub fn slope(&self, theta: f64, y: f64) -> f64 {
        self.slope_at(theta.sin_cos(), y)
    }

    /// |e|/C of the journal centre in the section at ȳ (a tilted journal's centre moves along
    /// its length): h̄ = 1 + |e| cos(θ − ψ) there, its smallest film 1 − |e|.
    pub fn centre_offset(&self, y: f64) -> f64 {
        let (e, dir) = self.tilt.unwrap_or((0.0, 0.0));
        let s = e * (y - 0.5);
        (self.a() - s * dir.cos()).hypot(self.sin_offset - s * dir.sin())
    }

    /// The smallest h̄ anywhere in the clearance: 1 − |e| of the journal centre at the mid-plane,
    /// or at the worse end when tilted.
    pub fn min_thickness(&self) -> f64 {
        1.0 - self.centre_offset(0.0).max(self.centre_offset(1.0))
    }
}

/// Solve `film` on `mesh` (nodes clustered for its nominal ε), starting from `start` (a field on
/// the same grid) when given, else (a Reynolds-condition film) from the field of the half mesh.
pub fn solve(
    film: Film,
    mesh: Mesh,
    stop: Stopping,
    start: Option<Vec<f64>>,
    budget: &Budget,
) -> Result<(FilmSolution, Vec<f64>), SolveError> {
    // From rest, a Reynolds-condition film starts from its half mesh's field (recursively: the
    // active set then moves a few nodes, not across the film).
    let start = match start {
        None if !film.physics.has_content() && mesh.circumferential >= 48 => {
            let coarse = mesh.coarse();
            let (_, field) = solve(film, coarse, stop, None, budget)?;
            Some(prolonged(&film, coarse, &field, mesh))
        }
        start => start,
    };
    budget.count_field_solve();
    let g = grid(mesh, &film);
    // Port nodes (a periodic film fed at supply pressure): the columns within the port's
    // angular width of each groove centre (the film's start, and π on for two grooves; always
    // the nearest column), the rows within its axial extent (always the mid-plane).
    let port = film.physics.port();
    let centres: Vec<f64> = match port {
        None => Vec::new(),
        Some((position, _)) => {
            let nearest = |c: f64| {
                g.x.iter()
                    .copied()
                    .min_by(|a, b| (a - c).abs().total_cmp(&(b - c).abs()))
                    .unwrap_or(c)
            };
            let start = g.x[0];
            match position {
                FeedLine::TwoGrooves => vec![start, nearest(start + PI)],
                _ => vec![start],
            }
        }
    };
    let held = |theta: f64, y: f64| -> bool {
        let Some((_, p)) = port else { return false };
        let axial = (y - 0.5).abs() <= 0.5 * p.length_ratio + 1e-12;
        axial
            && centres.iter().any(|&c| {
                let d = (theta - c + PI).rem_euclid(2.0 * PI) - PI;
                d.abs() <= 0.5 * p.width + 1e-12
            })
    };
    let stencil = assemble(
        &film,
        &g,
        port.is_some().then_some(&held as &dyn Fn(f64, f64) -> bool),
    );
    let n = (g.nx() + 1) * (g.ny + 1);
    if film.physics.has_content() {
        // The field is [P̄; θ_f]; a pressure-only start begins flooded.
        let start = start.unwrap_or_default();
        let mut p = if start.len() >= n {
            start[..n].to_vec()
        } else {
            vec![0.0; n]
        };
        let mut content = if start.len() == 2 * n {
            start[n..].to_vec()
        } else {
            vec![1.0; n]
        };
        match port {
            // The supply: flooded at the feed line.
            None => {
                for j in 0..=g.ny {
                    content[at(&g, 0, j)] = 1.0;
                }
            }
            // The ports: flooded at supply pressure.
            Some((_, port)) => {
                for j in 0..=g.ny {
                    for i in 0..=g.nx() {
                        if held(g.x[i], g.y(j)) {
                            p[at(&g, i, j)] = port.pressure_nd;
                            content[at(&g, i, j)] = 1.0;
                        }
                    }
                }
            }
        }
        let omega = stencil.sor_factor(&g);
        let solved =
            reynolds::solve_mass_conserving(&stencil, omega, &mut p, &mut content, stop, budget)?;
        let fluxes = stencil.fluxes(&p, &content);
        let solution = integrate(&g, &p, &film, solved, Some((&content, fluxes)));
        p.extend_from_slice(&content);
        return Ok((solution, p));
    }
    let mut p = start
        .filter(|s| s.len() == n)
        .unwrap_or_else(|| vec![0.0; n]);
    let solved = reynolds::solve(&stencil, &mut p, film.physics.cavitation, budget)?;
    let solution = if film.physics.half_sommerfeld {
        integrate(&g, &positive_part(&p), &film, solved, None)
    } else {
        integrate(&g, &p, &film, solved, None)
    };
    Ok((solution, p))
}

/// The half-Sommerfeld film's pressures: the full film's, negatives set to zero.
pub fn positive_part(p: &[f64]) -> Vec<f64> {
    p.iter().map(|v| v.max(0.0)).collect()
}

/// The film's five-point stencil on `g`: h̄, the squeeze source of a moving film, the Ng–Pan
/// conductances of a turbulent one, and the `held` nodes of ported supplies.
fn assemble(film: &Film, g: &Grid, held: Option<&dyn Fn(f64, f64) -> bool>) -> Stencil {
    let film = *film;
    // The stencil asks for a whole column at one θ: its sine and cosine are kept.
    let trig = Trig::default();
    let thickness = |theta: f64, y: f64| film.thickness_at(trig.at(theta), y);
    let squeeze = |theta: f64, _y: f64| {
        let (sin, cos) = trig.at(theta);
        12.0 * (film.cos_rate * cos + film.sin_rate * sin)
    };
    let moving = film.cos_rate != 0.0 || film.sin_rate != 0.0;
    let turbulent = |theta: f64, y: f64, axis: Axis| {
        let h = film.thickness_at(trig.at(theta), y);
        let (gx, gy) = turbulent_flow_factors(film.physics.turbulence_reynolds.unwrap_or(0.0) * h);
        h.powi(3) * if axis == Axis::X { gx } else { gy }
    };
    let problem = Problem {
        film: &thickness,
        conductance: if film.physics.turbulence_reynolds.is_some() {
            Some(&turbulent)
        } else {
            None
        },
        anisotropy: film.anisotropy(),
        wedge: film.wedge(),
        source: if moving { Some(&squeeze) } else { None },
        held,
    };
    Stencil::assemble(g, &problem)
}

/// sin θ and cos θ of the last θ asked for.
struct Trig(Cell<(f64, f64, f64)>);

impl Default for Trig {
    fn default() -> Self {
        Trig(Cell::new((f64::NAN, 0.0, 0.0)))
    }
}

impl Trig {
    fn at(&self, theta: f64) -> (f64, f64) {
        let (last, sin, cos) = self.0.get();
        if last == theta {
            return (sin, cos);
        }
        let (sin, cos) = theta.sin_cos();
        self.0.set((theta, sin, cos));
        (sin, cos)
    }
}

/// The field solved on `coarse` (a mesh of [`Mesh::coarse`]) carried over to `mesh`, to start
/// the fine solve of a pair. A mass-conserving field carries its content after the pressure:
/// only the pressure is carried over; the content starts flooded and settles in the first
/// sweeps.
pub fn prolonged(film: &Film, coarse: Mesh, field: &[f64], mesh: Mesh) -> Vec<f64> {
    let coarse_grid = grid(coarse, film);
    let pc = &field[..(coarse_grid.nx() + 1) * (coarse_grid.ny + 1)];
    reynolds::prolong(&coarse_grid, pc, &grid(mesh, film))
}

/// The load ∫∫ P̄ (−cos θ, sin θ) dθ dȳ over the whole length: along the line of centres
/// towards h_max, and perpendicular to it against the rotation (see [`FilmSolution`]).
fn load(g: &Grid, p: &[f64]) -> [f64; 2] {
    let halves = if g.symmetric { 2.0 } else { 1.0 };
    let (mut radial, mut tangential) = (0.0, 0.0);
    for i in 0..=g.nx() {
        let (sin, cos) = g.x[i].sin_cos();
        let column: f64 = (0..=g.ny).map(|j| p[at(g, i, j)] * g.cv_y(j)).sum();
        let w = g.cv_x(i) * halves;
        radial -= column * cos * w;
        tangential += column * sin * w;
    }
    [radial, tangential]
}

/// The step δ of a differenced perturbation of the film's shape at eccentricity ratio ε:
/// 10⁻³ (1 − ε), small against the minimum film, large against the solvers' tolerance.
pub fn perturbation_step(eccentricity_ratio: f64) -> f64 {
    1e-3 * (1.0 - eccentricity_ratio).max(1e-3)
}

/// The film's linear response about a converged Reynolds-condition field: the load's
/// derivative with respect to a parameter of the film (its shape or motion), from one
/// factorisation of the free nodes' operator ([`reynolds::Linearised`]) — Lund's perturbation
/// of the Reynolds equation, on the same grid, stencil and cavitated region as the field. A
/// half-Sommerfeld film perturbs its full film (every node free) and counts the change where
/// the full film's pressure is positive.
pub struct Response {
    film: Film,
    grid: Grid,
    field: Vec<f64>,
    operator: Linearised,
    /// The nodes the operator solves for: the field's positive ones, or every node (1) of a
    /// half-Sommerfeld film's full film.
    free: Vec<f64>,
}

impl Response {
    /// About `film`'s converged `field` on `mesh` (a Reynolds-condition film, not a
    /// mass-conserving one).
    pub fn at(film: &Film, mesh: Mesh, field: Vec<f64>) -> Result<Response, NotPositiveDefinite> {
        debug_assert!(!film.physics.has_content());
        debug_assert!(!(film.physics.cavitation && film.physics.half_sommerfeld));
        let grid = grid(mesh, film);
        let free = if film.physics.half_sommerfeld {
            vec![1.0; field.len()]
        } else {
            field.clone()
        };
        let operator = Linearised::at(&assemble(film, &grid, None), &free)?;
        Ok(Response {
            film: *film,
            grid,
            field,
            operator,
            free,
        })
    }

    /// The load's change from the equations' residual change: the field's response, counted
    /// where the film carries pressure.
    fn load_change(&self, residual_change: &[f64]) -> [f64; 2] {
        let dp = self.operator.response(residual_change, &self.free);
        if self.film.physics.half_sommerfeld {
            let counted: Vec<f64> = dp
                .iter()
                .zip(&self.field)
                .map(|(d, p)| if *p > 0.0 { *d } else { 0.0 })
                .collect();
            load(&self.grid, &counted)
        } else {
            load(&self.grid, &dp)
        }
    }

    /// ∂(load)/∂A (`cos`: h̄ gains A cos θ) or ∂(load)/∂B (sin θ). The stencil is linear in its
    /// coefficient functions, so a laminar film's derivative is the residual of the stencil
    /// assembled from ∂h̄ and ∂(h̄³) = 3h̄² ∂h̄ — exact, one assembly. A turbulent film's
    /// conductance carries the Ng–Pan factors of the local h̄: there the residual is
    /// differenced centrally over A ± δ ([`perturbation_step`]).
    pub fn shape_derivative(&self, cos: bool) -> [f64; 2] {
        let film = self.film;
        let change = if film.physics.turbulence_reynolds.is_none() {
            let trig = Trig::default();
            let dh = |theta: f64, _y: f64| {
                let (sin, cos_t) = trig.at(theta);
                if cos {
                    cos_t
                } else {
                    sin
                }
            };
            let dcond = |theta: f64, y: f64, _axis: Axis| {
                let h = film.thickness_at(trig.at(theta), y);
                3.0 * h * h * dh(theta, y)
            };
            let problem = Problem {
                film: &dh,
                conductance: Some(&dcond),
                anisotropy: film.anisotropy(),
                wedge: film.wedge(),
                source: None,
                held: None,
            };
            Stencil::assemble(&self.grid, &problem).residuals(&self.field)
        } else {
            let delta = perturbation_step(film.eccentricity_ratio);
            let shifted = |sign: f64| {
                let mut f = film;
                if cos {
                    f.cos_offset += sign * delta;
                } else {
                    f.sin_offset += sign * delta;
                }
                assemble(&f, &self.grid, None).residuals(&self.field)
            };
            let (plus, minus) = (shifted(1.0), shifted(-1.0));
            plus.iter()
                .zip(&minus)
                .map(|(a, b)| (a - b) / (2.0 * delta))
                .collect()
        };
        self.load_change(&change)
    }

    /// ∂(load)/∂Ȧ (`cos`) or ∂(load)/∂Ḃ: the rate enters only the squeeze source
    /// 12 (Ȧ cos θ + Ḃ sin θ) integrated over each control volume, linearly.
    pub fn squeeze_derivative(&self, cos: bool) -> [f64; 2] {
        let g = &self.grid;
        let mut change = vec![0.0; self.field.len()];
        for i in 0..=g.nx() {
            let (sin_t, cos_t) = g.x[i].sin_cos();
            let weight = 12.0 * if cos { cos_t } else { sin_t } * g.cv_x(i);
            for j in 0..=g.ny {
                change[at(g, i, j)] = weight * g.cv_y(j);
            }
        }
        self.load_change(&change)
    }
}

/// The film's numbers from its field; `content` (mass-conserving films) carries θ_f and the
/// stencil's boundary fluxes, from which the flows are then taken (they close exactly).
fn integrate(
    g: &Grid,
    p: &[f64],
    film: &Film,
    solved: Solved,
    content: Option<(&[f64], Fluxes)>,
) -> FilmSolution {
    let h = |theta: f64, y: f64| film.thickness(theta, y);
    let l_over_d = film.l_over_d;
    // A symmetric grid holds half the length: its integrals count twice.
    let halves = if g.symmetric { 2.0 } else { 1.0 };
    let mid_row = if g.symmetric { g.ny } else { g.ny / 2 };
    let [radial, tangential] = load(g, p);
    let mut pressure_shear = 0.0;
    // The moment about the mid-plane centre (zero on a symmetric grid, by symmetry).
    let mut moment = [0.0; 2];
    for i in 0..=g.nx() {
        let trig = g.x[i].sin_cos();
        for j in 0..=g.ny {
            let w = g.cv_x(i) * g.cv_y(j) * halves;
            let v = p[at(g, i, j)];
            if !g.symmetric {
                let arm = g.y(j) - 0.5;
                moment[0] += v * arm * trig.0 * w;
                moment[1] -= v * arm * trig.1 * w;
            }
            // −∂h̄/∂θ for the pressure part of the journal's shear (integrated by parts).
            pressure_shear -= v * film.slope_at(trig, g.y(j)) * w;
        }
    }

    // Peak and rupture on the mid-plane row.
    let mid: Vec<f64> = (0..=g.nx()).map(|i| p[at(g, i, mid_row)]).collect();
    let imax = mid
        .iter()
        .enumerate()
        .max_by(|a, b| a.1.total_cmp(b.1))
        .map_or(0, |m| m.0);
    let (mut max_pressure_nd, mut max_pressure_angle) = parabolic_peak(&g.x, &mid, imax);
    if !g.symmetric {
        // A tilted film peaks towards an end: take the row that holds the largest pressure.
        let (k, _) = p
            .iter()
            .enumerate()
            .max_by(|a, b| a.1.total_cmp(b.1))
            .unwrap_or((0, &0.0));
        let row_index = k / (g.nx() + 1);
        if row_index != mid_row {
            let row: Vec<f64> = (0..=g.nx()).map(|i| p[at(g, i, row_index)]).collect();
            (max_pressure_nd, max_pressure_angle) = parabolic_peak(&g.x, &row, k % (g.nx() + 1));
        }
    }
    let cavitation_angle = match (imax..=g.nx()).find(|&i| mid[i] <= 0.0) {
        Some(k) if k > imax && k < g.nx() && mid[k - 1] > 0.0 => {
            // Near rupture p ~ (θc − θ)²: √p is linear; extrapolate it to zero.
            let (a, b) = (
                mid[k - 1].sqrt(),
                if k >= 2 { mid[k - 2].sqrt() } else { 0.0 },
            );
            let (ta, tb) = (g.x[k - 1], if k >= 2 { g.x[k - 2] } else { g.x[k - 1] });
            if b > a {
                (ta + a * (ta - tb) / (b - a)).min(g.x[k])
            } else {
                g.x[k]
            }
        }
        Some(k) => g.x[k],
        None => g.x[g.nx()],
    };

    // Pressure-flow conductance h³, scaled by the Ng–Pan factor of its direction when turbulent.
    let conductance = |theta: f64, y: f64, axis: Axis| {
        let h = h(theta, y);
        let (gx, gy) = film
            .physics
            .turbulence_reynolds
            .map_or((1.0, 1.0), |re| turbulent_flow_factors(re * h));
        h.powi(3) * if axis == Axis::X { gx } else { gy }
    };
    // Side leakage: h³ |∂P/∂ȳ| at the ends (second-order one-sided), both ends.
    let dy = g.dy();
    let edge_flow = |row1: usize, row2: usize, y_edge: f64| {
        let mut flow = 0.0;
        for i in 1..g.nx() {
            let (p1, p2) = (p[at(g, i, row1)], p[at(g, i, row2)]);
            let dpdy = if g.ny >= 2 {
                (4.0 * p1 - p2) / (2.0 * dy)
            } else {
                p1 / dy
            };
            flow += conductance(g.x[i], y_edge, Axis::Y) * dpdy * g.cv_x(i);
        }
        flow
    };
    let edges = if g.symmetric {
        2.0 * edge_flow(1, 2.min(g.ny), 0.0)
    } else {
        edge_flow(1, 2, 0.0) + edge_flow(g.ny - 1, g.ny - 2, 1.0)
    };
    let side_leakage_nd = edges / (48.0 * PI * l_over_d * l_over_d);

    // Inlet flow at θ = 0: ∫ [h̄ − h̄³ ∂θP̄/(12π)] dȳ, second-order one-sided derivative.
    let (d1, d2) = (g.x[1] - g.x[0], g.x[2] - g.x[1]);
    let mut inlet = 0.0;
    for j in 0..=g.ny {
        let (p1, p2) = (p[at(g, 1, j)], p[at(g, 2, j)]);
        let dpdt = (d1 + d2) / (d1 * d2) * p1 - d1 / (d2 * (d1 + d2)) * p2;
        let h0 = h(g.x[0], g.y(j));
        inlet +=
            (h0 - conductance(g.x[0], g.y(j), Axis::X) * dpdt / (12.0 * PI)) * g.cv_y(j) * halves;
    }

    let mut solution = FilmSolution {
        load_radial: radial,
        load_tangential: tangential,
        max_pressure_nd,
        max_pressure_angle,
        cavitation_angle,
        side_leakage_nd,
        inlet_flow_nd: inlet,
        span: (g.x[0], g.x[g.nx()]),
        min_thickness: film.min_thickness(),
        pressure_shear,
        moment,
        couette_shear: 0.0,
        midplane: g.x.iter().cloned().zip(mid.iter().cloned()).collect(),
        midplane_content: None,
        cavitated_fraction: None,
        flow_balance: None,
        solved,
    };
    match content {
        None => solution.couette_shear = couette_shear(film, (g.x[0], g.x[g.nx()])),
        Some((theta, fluxes)) => {
            // The stencil's own face fluxes (Λ = 12π per unit h̄ and width) balance exactly. A
            // ported (periodic) film supplies what leaks: its supply is reported as the
            // leakage, whose edge gradient is taken to second order.
            let scale = halves / (12.0 * PI);
            solution.flow_balance = Some(FlowBalance {
                supply: fluxes.inflow * scale,
                outlet: fluxes.outflow * scale,
                side: fluxes.side * scale,
            });
            if g.periodic {
                solution.inlet_flow_nd = solution.side_leakage_nd;
            }
            // Couette shear carried by the liquid only: θ_f G_f/h̄ (streamers in the cavitated
            // zone, Stachowiak & Batchelor §5.3: τ* = h_cav/h² there), by the nodes' volumes.
            // The edge rows held at p = 0 and the outlet column of an arc are boundary values
            // the solve never visits: they take the content of their interior neighbour.
            let last_row = g.ny - usize::from(!g.symmetric);
            let content = |i: usize, j: usize| {
                let i = if !g.periodic && i == g.nx() { i - 1 } else { i };
                theta[at(g, i, j.clamp(1, last_row))]
            };
            let re = film.physics.turbulence_reynolds;
            let (mut shear, mut cavitated, mut area) = (0.0, 0.0, 0.0);
            for j in 0..=g.ny {
                for i in 0..=g.nx() {
                    let w = g.cv_x(i) * g.cv_y(j) * halves;
                    let hh = h(g.x[i], g.y(j));
                    let theta_k = content(i, j);
                    shear +=
                        w * theta_k * re.map_or(1.0, |re| turbulent_shear_factor(re * hh)) / hh;
                    area += w;
                    if theta_k < 1.0 {
                        cavitated += w;
                    }
                }
            }
            solution.couette_shear = shear;
            solution.cavitated_fraction = Some(cavitated / area);
            solution.midplane_content = Some((0..=g.nx()).map(|i| content(i, mid_row)).collect());
        }
    }
    solution
}

/// ∫∫ G_f/h̄ dθ dȳ over the span and the whole length: a laminar, aligned full circle in closed
/// form; otherwise the trapezoidal rule on 720 intervals (exact to rounding for the periodic
/// full circle); across the length 40 intervals when tilted (h̄ is then linear in ȳ), else one.
fn couette_shear(film: &Film, span: (f64, f64)) -> f64 {
    // A laminar, aligned film over a whole turn: h̄ = 1 + e cos(θ − α), e = |(A, B)|, and
    // ∫ dθ/h̄ over a period is 2π/√(1 − e²).
    if film.physics.turbulence_reynolds.is_none()
        && film.tilt.is_none()
        && (span.1 - span.0 - 2.0 * PI).abs() < 1e-12
    {
        let e = film.a().hypot(film.sin_offset);
        return 2.0 * PI / (1.0 - e * e).sqrt();
    }
    let n = 720;
    let w = (span.1 - span.0) / n as f64;
    let re = film.physics.turbulence_reynolds;
    // (ȳ, weight): the mid-plane stands for the whole length unless the film is tilted.
    let rows: Vec<(f64, f64)> = match film.tilt {
        None => vec![(0.5, 1.0)],
        Some(_) => (0..=40)
            .map(|j| {
                (
                    j as f64 / 40.0,
                    if j == 0 || j == 40 {
                        0.5 / 40.0
                    } else {
                        1.0 / 40.0
                    },
                )
            })
            .collect(),
    };
    let mut sum = 0.0;
    for (y, wy) in rows {
        for i in 0..=n {
            let h = film.thickness(span.0 + w * i as f64, y);
            let wx = if i == 0 || i == n { 0.5 * w } else { w };
            sum += wx * wy * re.map_or(1.0, |re| turbulent_shear_factor(re * h)) / h;
        }
    }
    sum
}

/// The peak of a sampled curve by a parabola through the largest sample and its neighbours.
fn parabolic_peak(x: &[f64], y: &[f64], i: usize) -> (f64, f64) {
    if i == 0 || i + 1 >= y.len() {
        return (y[i], x[i]);
    }
    let (x0, x1, x2) = (x[i - 1], x[i], x[i + 1]);
    let y1 = y[i];
    let parabola = Parabola::through([x0, x1, x2], [y[i - 1], y1, y[i + 1]]);
    if parabola.a >= 0.0 {
        return (y1, x1);
    }
    let xv = parabola.vertex().clamp(x0, x2);
    (parabola.at(xv).max(y1), xv)
}

#[cfg(test)]
mod tests;
