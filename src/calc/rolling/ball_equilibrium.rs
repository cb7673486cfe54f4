//! The general quasi-static equilibrium of a ball bearing's inner ring: three degrees of freedom
//! (radial δ_r, axial δ_a, tilt θ) and, at speed, every ball's own position between its two
//! grooves (Jones's model: the inner and outer contacts no longer collinear). The load
//! distribution room uses it when a tilting moment is given or when the centrifugal or
//! gyroscopic ball loads apply; without them its classic two-unknown solver answers.
//!
//! Geometry (see [`super::geometry`] and [`super::load_distribution`]). Ball j sits at azimuth
//! ψ_j; in its plane (axial, radial) the outer groove curvature centre O is fixed and the inner
//! one is at I_j = (a₀ + δ_a + θℜ cos ψ_j, r₀ + δ_r cos ψ_j) from it, ℜ = d_m/2 + (f_i − ½)D cos α_f
//! the radius of the inner groove centres (Harris), the tilt taken to first order (small θ).
//! - Series balls (no speed effects): the contact deflection is the approach of the groove
//!   centres, δ_j = |I_j| − BD (`varying`) or its linearisation (`fixed`), Q = K_n δ^{3/2}.
//! - Free balls: the ball centre B_j = O + X_j. Outer contact δ_o = |X_j| − (f_o − ½)D, normal
//!   along X_j; inner contact δ_i = |I_j − X_j| − (f_i − ½)D, normal along I_j − X_j; Q = K δ^{3/2}
//!   with each contact's own K from the exact Hertz solution at α_f. The ball carries the
//!   centrifugal force F_c = ½ m d_m ω_m² radially outward (Khonsari & Booser RI-9; ω_m the cage
//!   speed of the texts' kinematics at α_f, Hamrock eq. 21.93) and, with the gyroscopic effect,
//!   the friction force f_j at its outer contact that supplies the gyroscopic moment (outer-race
//!   control, below). Ball balance: Q_i n_i − Q_o n_o + F_c r̂ + f_j = 0.
//!
//! Ring balance: Σ_j Q_ij (cos α_ij cos ψ_j, sin α_ij, ℜ sin α_ij cos ψ_j) = (F_r, F_a, M), the
//! moment only when the tilt is free.
//!
//! Solution. With the friction forces held fixed every force is the gradient of
//! Π = Σ (2/5)(Q_i δ_i + Q_o δ_o) − F_c X_r − f·X − F_r δ_r − F_a δ_a − M θ, convex in all unknowns
//! (each δ is a norm of an affine map, less a constant), so the equilibrium is its minimum:
//! Newton with the ball blocks eliminated (a 3 × 3 Schur complement), Armijo backtracking on Π,
//! a Levenberg shift where a block is singular. The gyroscopic friction forces depend on the
//! contact angles: a few under-relaxed updates between Newton solves bring the state near, and
//! a Newton on the whole (non-symmetric) balance with the friction's Jacobian by central
//! differences finishes, its steps judged by the residual. Convergence: every
//! force residual (ring and ball) ≤ 1e-9 of the load scale.
//!
//! Gyroscopic moment (outside the texts, which leave high-speed ball motion to "a separate
//! computer model", Hamrock §21.3.6): the ball, spinning at ω_R about an axis s at angle β to the
//! bearing axis and orbiting at ω_m, needs dL/dt = J ω_R ω_m sin β t̂ (J = m D²/10, t̂ the
//! orbit's tangent); under outer-race control (no spin at the outer contact, pure rolling at
//! both) tan(α_o + β) = sin α_o/(d_m/D + cos α_o) and ω_R = −(ω_m − ω_o)√[sin²α_o +
//! (d_m/D + cos α_o)²], the cage speed following from rolling at the inner contact:
//! ω_m − ω_o = (ω_i − ω_o)(1 − γ cos α_i)/[1 − γ cos α_i + γ κ cos(α_i + β)], γ = D/d_m, κ the
//! root above (Harris's outer-race control, derived here from the rolling and no-spin
//! conditions; at α = 0 it gives the texts' cage and spin speeds). The outer contact supplies
//! the moment by the friction force f = (2M_g/D) τ, τ ⟂ n_o in the ball's plane. Checked in
//! direction against a public Harris-form implementation (S. Sudhof's `BallBearing` MATLAB class,
//! its ball force balances with λ_o = 2, λ_i = 0): the same friction force on the ball; another
//! public port (a `Ball_balance.m` of a spindle study) writes the term with the opposite sign.
//! Not checked against a worked example: the texts have none.

use crate::calc::CalcError;
use crate::fidelity::{IterationUnit, SolverReport, StopReason};
use crate::numerics::driver::{Budget, Converged, Driver, Stopped, Verdict};
use crate::numerics::newton::{self, armijo, residual_falls, LineSearch, NewtonSystem};
use crate::numerics::optimise::brent_minimise;

const TOLERANCE: f64 = 1e-9;
const MAX_ITERATIONS: u32 = 300;
const MAX_HALVINGS: u32 = 60;
/// Relaxed friction updates before the coupled Newton, and the balance that ends them early.
const WARM_FRICTION_UPDATES: u32 = 30;
const WARM_TOLERANCE: f64 = 1e-6;

/// How the contact deflection follows the ring displacement for series balls.
#[derive(Debug, Clone, Copy)]
pub(super) enum SeriesLaw {
    /// δ = |I| − BD.
    Varying,
    /// δ = A₀ + e·(I − I₀) − BD, e = (sin α_f, cos α_f).
    Fixed { sin: f64, cos: f64 },
}

/// Speeds and inertia for the gyroscopic moment, rad/s and kg·m².
#[derive(Debug, Clone, Copy)]
pub(super) struct Gyro {
    pub inertia_kg_m2: f64,
    pub inner_rad_s: f64,
    pub outer_rad_s: f64,
}

#[derive(Debug, Clone, Copy)]
pub(super) enum Balls {
    Series {
        k_n: f64,
        law: SeriesLaw,
    },
    Free {
        k_i: f64,
        k_o: f64,
        centrifugal_n: f64,
        gyro: Option<Gyro>,
    },
}

/// The problem: geometry, ball model, loads.
#[derive(Debug, Clone)]
pub(super) struct Problem {
    pub ball_diameter_m: f64,
    pub pitch_diameter_m: f64,
    /// BD, r₀, a₀, m.
    pub bd: f64,
    pub r0: f64,
    pub a0: f64,
    /// ℜ, m.
    pub arm: f64,
    /// (f_i − ½)D and (f_o − ½)D, m.
    pub inner_offset: f64,
    pub outer_offset: f64,
    pub cosines: Vec<f64>,
    pub balls: Balls,
    pub tilt_free: bool,
    /// F_r, F_a (N), M (N·m).
    pub load: [f64; 3],
    /// Residual scale, N.
    pub scale: f64,
    /// Characteristic deflection, m.
    pub delta_scale: f64,
}

/// One ball at equilibrium.
#[derive(Debug, Clone, Copy)]
pub(super) struct BallState {
    pub inner_load: f64,
    /// rad.
    pub inner_angle: f64,
    pub outer_load: f64,
    pub outer_angle: f64,
    /// Gyroscopic friction force at the outer contact, N (signed along τ).
    pub friction_n: f64,
}

#[derive(Debug, Clone)]
pub(super) struct Solution {
    /// δ_r, δ_a (from a₀), θ (rad).
    pub displacement: [f64; 3],
    pub balls: Vec<BallState>,
    pub report: SolverReport,
}

/// Gradient and Hessian blocks of Π at a point.
struct Local {
    energy: f64,
    g_v: [f64; 3],
    h_vv: [[f64; 3]; 3],
    g_x: Vec<[f64; 2]>,
    h_vx: Vec<[[f64; 2]; 3]>,
    h_xx: Vec<[[f64; 2]; 2]>,
}

/// Contact of one ball: Q, dQ/dδ, and energy (2/5) Q δ, zero when unloaded.
fn contact(k: f64, delta: f64) -> (f64, f64, f64) {
    if delta <= 0.0 {
        return (0.0, 0.0, 0.0);
    }
    let root = delta.sqrt();
    let q = k * delta * root;
    (q, 1.5 * k * root, 0.4 * q * delta)
}

/// dq n nᵀ + (q/ℓ)(I − n nᵀ).
fn contact_hessian(q: f64, dq: f64, n: [f64; 2], length: f64) -> [[f64; 2]; 2] {
    let t = if length > 0.0 { q / length } else { 0.0 };
    let mut h = [[0.0; 2]; 2];
    for (a, row) in h.iter_mut().enumerate() {
        for (b, cell) in row.iter_mut().enumerate() {
            let nn = n[a] * n[b];
            *cell = dq * nn + t * (if a == b { 1.0 } else { 0.0 } - nn);
        }
    }
    h
}

fn unit(v: [f64; 2]) -> ([f64; 2], f64) {
    let l = v[0].hypot(v[1]);
    if l > 0.0 {
        ([v[0] / l, v[1] / l], l)
    } else {
        ([0.0, 1.0], 0.0)
    }
}

/// Solve a small system by Gaussian elimination with partial pivoting; None when singular.
///
/// Kept here rather than `numerics::dense::solve` (nalgebra's LU): on the gyroscopic README case
/// the LU's different round-off moves the converged state by 3e-14 and the reported
/// `solver.residual` (a round-off-level 1.9e-11) by 4e-5 relative, beyond the 1e-9 the issue
/// allows for this change.
fn solve<const N: usize>(mut a: [[f64; N]; N], mut b: [f64; N]) -> Option<[f64; N]> {
    for col in 0..N {
        let pivot = (col..N).max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs()))?;
        if a[pivot][col].abs().is_nan() || a[pivot][col] == 0.0 {
            return None;
        }
        a.swap(col, pivot);
        b.swap(col, pivot);
        for row in col + 1..N {
            let f = a[row][col] / a[col][col];
            let pivot_row = a[col];
            for (cell, p) in a[row].iter_mut().zip(pivot_row).skip(col) {
                *cell -= f * p;
            }
            b[row] -= f * b[col];
        }
    }
    let mut x = [0.0; N];
    for row in (0..N).rev() {
        let s: f64 = (row + 1..N).map(|k| a[row][k] * x[k]).sum();
        x[row] = (b[row] - s) / a[row][row];
    }
    x.iter().all(|v| v.is_finite()).then_some(x)
}

impl Problem {
    /// The inner groove centre of ball j relative to the outer one, (axial, radial), at the
    /// scaled unknowns v = (δ_r, δ_a, θℜ).
    fn inner_centre(&self, v: [f64; 3], c: f64) -> [f64; 2] {
        [self.a0 + v[1] + v[2] * c, self.r0 + v[0] * c]
    }

    /// ∂I/∂v (rows axial, radial).
    fn jacobian(c: f64) -> [[f64; 3]; 2] {
        [[0.0, 1.0, c], [c, 0.0, 0.0]]
    }

    fn load_scaled(&self) -> [f64; 3] {
        [self.load[0], self.load[1], self.load[2] / self.arm]
    }

    /// Signed approach |I| − BD (fixed law: its linearisation) at cos ψ = c.
    pub fn signed_deflection(&self, d: [f64; 3], c: f64) -> f64 {
        let v = [d[0], d[1], d[2] * self.arm];
        let i = self.inner_centre(v, c);
        match self.balls {
            Balls::Series {
                law: SeriesLaw::Fixed { sin, cos },
                ..
            } => self.a0.hypot(self.r0) + sin * (i[0] - self.a0) + cos * (i[1] - self.r0) - self.bd,
            _ => i[0].hypot(i[1]) - self.bd,
        }
    }

    /// Load-zone half angle on the continuous circle from ψ = 0, rad: the approach is convex in
    /// c = cos ψ, so the loaded arc from ψ = 0 ends at the first root below c = 1.
    pub fn load_zone_half_angle(&self, d: [f64; 3]) -> f64 {
        let f = |c: f64| self.signed_deflection(d, c);
        if f(1.0) <= 0.0 {
            return 0.0;
        }
        // The minimiser of the convex approach over [−1, 1].
        let (c_min, _) = brent_minimise(f, -1.0, 1.0, 1e-12);
        if f(c_min) > 0.0 && f(-1.0) > 0.0 {
            return std::f64::consts::PI;
        }
        let (mut a, mut b) = (if f(-1.0) <= 0.0 { -1.0 } else { c_min }, 1.0);
        for _ in 0..200 {
            let m = 0.5 * (a + b);
            if f(m) > 0.0 {
                b = m;
            } else {
                a = m;
            }
        }
        (0.5 * (a + b)).clamp(-1.0, 1.0).acos()
    }

    fn local(&self, v: [f64; 3], x: &[[f64; 2]], friction: &[[f64; 2]]) -> Local {
        let load = self.load_scaled();
        let mut l = Local {
            energy: -(load[0] * v[0] + load[1] * v[1] + load[2] * v[2]),
            g_v: [-load[0], -load[1], -load[2]],
            h_vv: [[0.0; 3]; 3],
            g_x: Vec::new(),
            h_vx: Vec::new(),
            h_xx: Vec::new(),
        };
        for (j, &c) in self.cosines.iter().enumerate() {
            let jac = Self::jacobian(c);
            let i = self.inner_centre(v, c);
            // The inner contact's force direction n, load, and Hessian in I.
            let (q, n, h_i, energy) = match self.balls {
                Balls::Series { k_n, law } => {
                    let (n, delta, length) = match law {
                        SeriesLaw::Varying => {
                            let (n, len) = unit(i);
                            (n, len - self.bd, len)
                        }
                        SeriesLaw::Fixed { sin, cos } => (
                            [sin, cos],
                            self.a0.hypot(self.r0)
                                + sin * (i[0] - self.a0)
                                + cos * (i[1] - self.r0)
                                - self.bd,
                            0.0,
                        ),
                    };
                    let (q, dq, e) = contact(k_n, delta);
                    (q, n, contact_hessian(q, dq, n, length), e)
                }
                Balls::Free {
                    k_i,
                    k_o,
                    centrifugal_n,
                    ..
                } => {
                    let xj = x[j];
                    let (n, len) = unit([i[0] - xj[0], i[1] - xj[1]]);
                    let (q, dq, e_i) = contact(k_i, len - self.inner_offset);
                    let h_i = contact_hessian(q, dq, n, len);
                    let (m, len_o) = unit(xj);
                    let (q_o, dq_o, e_o) = contact(k_o, len_o - self.outer_offset);
                    let h_o = contact_hessian(q_o, dq_o, m, len_o);
                    let f = friction[j];
                    l.energy += e_o - centrifugal_n * xj[1] - f[0] * xj[0] - f[1] * xj[1];
                    l.g_x.push([
                        -q * n[0] + q_o * m[0] - f[0],
                        -q * n[1] + q_o * m[1] - centrifugal_n - f[1],
                    ]);
                    let mut hxx = h_i;
                    for a in 0..2 {
                        for b in 0..2 {
                            hxx[a][b] += h_o[a][b];
                        }
                    }
                    l.h_xx.push(hxx);
                    // H_vX = −Jᵀ H_i.
                    let mut hvx = [[0.0; 2]; 3];
                    for (r, row) in hvx.iter_mut().enumerate() {
                        for (b, cell) in row.iter_mut().enumerate() {
                            *cell = -(jac[0][r] * h_i[0][b] + jac[1][r] * h_i[1][b]);
                        }
                    }
                    l.h_vx.push(hvx);
                    (q, n, h_i, e_i)
                }
            };
            l.energy += energy;
            for r in 0..3 {
                l.g_v[r] += q * (jac[0][r] * n[0] + jac[1][r] * n[1]);
                for s in 0..3 {
                    let mut acc = 0.0;
                    for a in 0..2 {
                        for b in 0..2 {
                            acc += jac[a][r] * h_i[a][b] * jac[b][s];
                        }
                    }
                    l.h_vv[r][s] += acc;
                }
            }
        }
        if !self.tilt_free {
            l.g_v[2] = 0.0;
            for r in 0..3 {
                l.h_vv[2][r] = 0.0;
                l.h_vv[r][2] = 0.0;
            }
            l.h_vv[2][2] = 1.0;
            for h in &mut l.h_vx {
                h[2] = [0.0; 2];
            }
        }
        l
    }

    fn residual(&self, l: &Local) -> f64 {
        let ring = l.g_v[0].hypot(l.g_v[1]).max(l.g_v[2].abs());
        let balls = l.g_x.iter().map(|g| g[0].hypot(g[1])).fold(0.0, f64::max);
        ring.max(balls) / self.scale
    }

    /// A Levenberg floor for singular blocks: a small stiffness on the problem's own scale.
    fn stiffness_floor(&self) -> f64 {
        1e-9 * self.scale / self.delta_scale.max(f64::MIN_POSITIVE)
    }

    /// The Newton step (dv, dX).
    fn step(&self, l: &Local) -> Option<([f64; 3], Vec<[f64; 2]>)> {
        let floor = self.stiffness_floor();
        let mut schur = l.h_vv;
        let mut rhs = [-l.g_v[0], -l.g_v[1], -l.g_v[2]];
        let mut inverses = Vec::with_capacity(l.h_xx.len());
        for (j, h) in l.h_xx.iter().enumerate() {
            let trace = h[0][0] + h[1][1];
            let det = h[0][0] * h[1][1] - h[0][1] * h[1][0];
            let shift = if trace > 0.0 && det > 1e-14 * trace * trace {
                1e-12 * trace
            } else {
                floor.max(1e-12 * trace.abs())
            };
            let (a, b, d) = (h[0][0] + shift, h[0][1], h[1][1] + shift);
            let det = a * d - b * b;
            let inv = [[d / det, -b / det], [-b / det, a / det]];
            let hvx = l.h_vx[j];
            let g = l.g_x[j];
            // Hvx A⁻¹ (3 × 2).
            let mut p = [[0.0; 2]; 3];
            for r in 0..3 {
                for c in 0..2 {
                    p[r][c] = hvx[r][0] * inv[0][c] + hvx[r][1] * inv[1][c];
                }
            }
            for r in 0..3 {
                for s in 0..3 {
                    schur[r][s] -= p[r][0] * hvx[s][0] + p[r][1] * hvx[s][1];
                }
                rhs[r] += p[r][0] * g[0] + p[r][1] * g[1];
            }
            inverses.push(inv);
        }
        let trace = schur[0][0] + schur[1][1] + schur[2][2];
        let shift = 1e-12 * trace.abs();
        for (r, row) in schur.iter_mut().enumerate() {
            row[r] += shift;
        }
        let dv = solve(schur, rhs).or_else(|| {
            let mut s = schur;
            for (r, row) in s.iter_mut().enumerate() {
                row[r] += floor;
            }
            solve(s, rhs)
        })?;
        let dx = inverses
            .iter()
            .enumerate()
            .map(|(j, inv)| {
                let hvx = l.h_vx[j];
                let g = l.g_x[j];
                let t = [
                    -g[0] - (hvx[0][0] * dv[0] + hvx[1][0] * dv[1] + hvx[2][0] * dv[2]),
                    -g[1] - (hvx[0][1] * dv[0] + hvx[1][1] * dv[1] + hvx[2][1] * dv[2]),
                ];
                [
                    inv[0][0] * t[0] + inv[0][1] * t[1],
                    inv[1][0] * t[0] + inv[1][1] * t[1],
                ]
            })
            .collect();
        Some((dv, dx))
    }

    /// Newton on Π with the friction forces held ([`HeldFriction`]), from `state`.
    fn newton(
        &self,
        state: State,
        friction: &[[f64; 2]],
        budget: &Budget,
        work: &mut Work,
    ) -> Result<Converged<(State, Local)>, Stopped> {
        let driver = Driver::new(
            "newton_schur_energy_line_search",
            IterationUnit::NewtonSteps,
            MAX_ITERATIONS,
            budget,
        )
        .check_every(8);
        let system = HeldFriction {
            problem: self,
            friction,
        };
        work.add(newton::solve(&system, state, TOLERANCE, LINE, &driver))
    }

    /// The gyroscopic friction forces at the outer contacts of the balls in state (v, X), in
    /// the balls' planes (axial, radial), and their signed magnitudes along τ.
    fn gyroscopic_friction(&self, v: [f64; 3], x: &[[f64; 2]]) -> Vec<[f64; 2]> {
        self.cosines
            .iter()
            .zip(x)
            .map(|(&c, xj)| self.ball_friction(self.inner_centre(v, c), *xj))
            .collect()
    }

    /// The gyroscopic friction force on one ball with its inner groove centre at `i` and its
    /// centre at `x` (both from the outer groove centre).
    fn ball_friction(&self, i: [f64; 2], x: [f64; 2]) -> [f64; 2] {
        let Balls::Free { gyro: Some(g), .. } = self.balls else {
            return [0.0; 2];
        };
        let (d, dm) = (self.ball_diameter_m, self.pitch_diameter_m);
        let gamma = d / dm;
        let (n, _) = unit([i[0] - x[0], i[1] - x[1]]);
        let (m, _) = unit(x);
        let (alpha_i, alpha_o) = (n[0].atan2(n[1]), m[0].atan2(m[1]));
        let kappa = alpha_o.sin().hypot(dm / d + alpha_o.cos());
        let beta = alpha_o.sin().atan2(dm / d + alpha_o.cos()) - alpha_o;
        let rolling = 1.0 - gamma * alpha_i.cos();
        let relative = (g.inner_rad_s - g.outer_rad_s) * rolling
            / (rolling + gamma * kappa * (alpha_i + beta).cos());
        let orbit = g.outer_rad_s + relative;
        let spin = -relative * kappa;
        let moment = g.inertia_kg_m2 * spin * orbit * beta.sin();
        let t = 2.0 * moment / d;
        // τ ⟂ m with m × τ = t̂: τ = (−m_r, m_z) in (axial, radial).
        [-t * m[1], t * m[0]]
    }

    /// ∂f/∂I and ∂f/∂X of one ball's friction (central differences), rows (axial, radial).
    fn friction_jacobians(&self, i: [f64; 2], x: [f64; 2]) -> ([[f64; 2]; 2], [[f64; 2]; 2]) {
        let h = 1e-6 * self.outer_offset.max(self.inner_offset);
        let mut d_i = [[0.0; 2]; 2];
        let mut d_x = [[0.0; 2]; 2];
        for k in 0..2 {
            let (mut ip, mut im, mut xp, mut xm) = (i, i, x, x);
            ip[k] += h;
            im[k] -= h;
            xp[k] += h;
            xm[k] -= h;
            let (a, b) = (self.ball_friction(ip, x), self.ball_friction(im, x));
            let (c, e) = (self.ball_friction(i, xp), self.ball_friction(i, xm));
            for r in 0..2 {
                d_i[r][k] = (a[r] - b[r]) / (2.0 * h);
                d_x[r][k] = (c[r] - e[r]) / (2.0 * h);
            }
        }
        (d_i, d_x)
    }

    /// Newton on the whole balance with the friction following the state
    /// ([`CoupledFriction`]), from `state`.
    fn coupled_newton(
        &self,
        state: State,
        budget: &Budget,
        work: &mut Work,
    ) -> Result<Converged<(State, Local)>, Stopped> {
        let driver = Driver::new(
            "newton_gyroscopic_friction",
            IterationUnit::NewtonSteps,
            MAX_ITERATIONS,
            budget,
        )
        .check_every(8);
        work.add(newton::solve(
            &CoupledFriction { problem: self },
            state,
            TOLERANCE,
            LINE,
            &driver,
        ))
    }

    /// Solve from the ring pushed along the load, the balls against their outer grooves.
    pub fn solve(&self, budget: &Budget) -> Result<Solution, CalcError> {
        let load = self.load_scaled();
        let norm = (load[0] * load[0] + load[1] * load[1] + load[2] * load[2]).sqrt();
        let push = 2.0 * self.delta_scale;
        let v = if norm > 0.0 {
            [
                push * load[0] / norm,
                push * load[1] / norm,
                if self.tilt_free {
                    push * load[2] / norm
                } else {
                    0.0
                },
            ]
        } else {
            [0.0; 3]
        };
        let x: Vec<[f64; 2]> = match self.balls {
            Balls::Free {
                k_o, centrifugal_n, ..
            } => self
                .cosines
                .iter()
                .map(|&c| {
                    let (e, _) = unit(self.inner_centre(v, c));
                    let r = self.outer_offset + (centrifugal_n / k_o).powf(2.0 / 3.0);
                    [e[0] * r, e[1] * r]
                })
                .collect(),
            Balls::Series { .. } => Vec::new(),
        };
        let mut friction = vec![[0.0; 2]; x.len()];
        let mut work = Work::default();
        let gyroscopic = matches!(self.balls, Balls::Free { gyro: Some(_), .. });
        let mut run = self.newton(State { v, x }, &friction, budget, &mut work)?;
        if gyroscopic {
            // A few under-relaxed updates of the friction forces bring the state near; the
            // coupled Newton finishes. The relaxation halves whenever an update moves the
            // forces more than the one before (an oscillation). Each update is one held-
            // friction Newton solve; running out of updates is not a failure (the coupled
            // Newton goes on from where they left the state).
            let mut relaxation = 1.0;
            let mut last_change = f64::INFINITY;
            let mut failure = None;
            let warm = Driver::new(
                "relaxed_gyroscopic_friction",
                IterationUnit::Evaluations,
                WARM_FRICTION_UPDATES,
                budget,
            )
            .run(|_| {
                let State { v, x } = &run.value.0;
                let target = self.gyroscopic_friction(*v, x);
                let residual = self.residual(&self.local(*v, x, &target));
                if residual <= WARM_TOLERANCE {
                    return Verdict::Converged((), residual);
                }
                let change = target
                    .iter()
                    .zip(&friction)
                    .map(|(a, b)| (a[0] - b[0]).hypot(a[1] - b[1]))
                    .fold(0.0, f64::max);
                if change > last_change {
                    relaxation *= 0.5;
                }
                last_change = change;
                for (f, t) in friction.iter_mut().zip(&target) {
                    f[0] += relaxation * (t[0] - f[0]);
                    f[1] += relaxation * (t[1] - f[1]);
                }
                match self.newton(run.value.0.clone(), &friction, budget, &mut work) {
                    Ok(next) => {
                        run = next;
                        Verdict::Continue(residual)
                    }
                    Err(stopped) => {
                        failure = Some(stopped);
                        Verdict::Stalled(residual)
                    }
                }
            });
            if let Some(stopped) = failure {
                return Err(stopped.into());
            }
            match warm {
                Err(stopped) if stopped.reason() != StopReason::IterationCap => {
                    return Err(stopped.into())
                }
                _ => {}
            }
            run = self.coupled_newton(run.value.0, budget, &mut work)?;
            friction = self.gyroscopic_friction(run.value.0.v, &run.value.0.x);
        }
        let (State { v, x }, _) = run.value;
        let balls = self.states(v, &x, &friction);
        Ok(Solution {
            displacement: [v[0], v[1], v[2] / self.arm],
            balls,
            report: run.report.named(match self.balls {
                Balls::Series { .. } => "newton_energy_line_search_3dof",
                Balls::Free { .. } => "newton_schur_energy_line_search_ball_dof",
            }),
        })
    }

    fn states(&self, v: [f64; 3], x: &[[f64; 2]], friction: &[[f64; 2]]) -> Vec<BallState> {
        self.cosines
            .iter()
            .enumerate()
            .map(|(j, &c)| {
                let i = self.inner_centre(v, c);
                match self.balls {
                    Balls::Series { k_n, law } => {
                        let (delta, angle) = match law {
                            SeriesLaw::Varying => (i[0].hypot(i[1]) - self.bd, i[0].atan2(i[1])),
                            SeriesLaw::Fixed { sin, cos } => (
                                self.a0.hypot(self.r0)
                                    + sin * (i[0] - self.a0)
                                    + cos * (i[1] - self.r0)
                                    - self.bd,
                                sin.atan2(cos),
                            ),
                        };
                        let q = contact(k_n, delta).0;
                        BallState {
                            inner_load: q,
                            inner_angle: angle,
                            outer_load: q,
                            outer_angle: angle,
                            friction_n: 0.0,
                        }
                    }
                    Balls::Free { k_i, k_o, .. } => {
                        let xj = x[j];
                        let (n, len) = unit([i[0] - xj[0], i[1] - xj[1]]);
                        let (m, len_o) = unit(xj);
                        let f = friction[j];
                        BallState {
                            inner_load: contact(k_i, len - self.inner_offset).0,
                            inner_angle: n[0].atan2(n[1]),
                            outer_load: contact(k_o, len_o - self.outer_offset).0,
                            outer_angle: m[0].atan2(m[1]),
                            friction_n: f[0] * (-m[1]) + f[1] * m[0],
                        }
                    }
                }
            })
            .collect()
    }
}

/// The unknowns: the ring's scaled displacement v = (δ_r, δ_a, θℜ) and, for free balls, every
/// ball centre X_j (from its outer groove centre).
#[derive(Debug, Clone)]
struct State {
    v: [f64; 3],
    x: Vec<[f64; 2]>,
}

/// A Newton direction (dv, dX).
type Step = ([f64; 3], Vec<[f64; 2]>);

/// The line search of every Newton run here: at most [`MAX_HALVINGS`] halvings, no step taken
/// that the system does not accept.
const LINE: LineSearch = LineSearch {
    max_halvings: MAX_HALVINGS,
    take_shortest: false,
};

/// The Newton steps and trial points of the runs of one solve so far: a solve reports their
/// sum, and each run's report (converged or stopped) carries the sum up to it.
#[derive(Debug, Default)]
struct Work {
    steps: u32,
    evaluations: u32,
}

impl Work {
    fn add<T>(&mut self, run: Result<Converged<T>, Stopped>) -> Result<Converged<T>, Stopped> {
        match run {
            Ok(mut done) => {
                self.count(&mut done.report);
                Ok(done)
            }
            Err(mut stopped) => {
                self.count(&mut stopped.report);
                Err(stopped)
            }
        }
    }

    fn count(&mut self, report: &mut SolverReport) {
        self.steps += report.iterations;
        self.evaluations += report.evaluations.unwrap_or(0);
        *report = report.clone().counting(self.steps, self.evaluations);
    }
}

impl State {
    /// x + t·step.
    fn advance(&self, (dv, dx): &Step, t: f64) -> State {
        let v = self.v;
        State {
            v: [v[0] + t * dv[0], v[1] + t * dv[1], v[2] + t * dv[2]],
            x: self
                .x
                .iter()
                .zip(dx)
                .map(|(a, d)| [a[0] + t * d[0], a[1] + t * d[1]])
                .collect(),
        }
    }
}

/// Π with the friction forces held: a convex energy, its steps judged by Armijo on Π or a fall
/// of the force residual.
struct HeldFriction<'a> {
    problem: &'a Problem,
    friction: &'a [[f64; 2]],
}

impl NewtonSystem for HeldFriction<'_> {
    type Point = State;
    type Eval = Local;
    type Step = Step;

    fn evaluate(&self, s: &State) -> Local {
        self.problem.local(s.v, &s.x, self.friction)
    }

    fn residual(&self, at: &Local) -> f64 {
        self.problem.residual(at)
    }

    /// The Schur-complement Newton step; a ring step far beyond the geometry (a singular
    /// system: no ball touching yet) is shortened to it, the direction staying the Newton
    /// direction.
    fn direction(&self, _s: &State, at: &Local) -> Option<Step> {
        let p = self.problem;
        let (mut dv, mut dx) = p.step(at)?;
        let longest = dv[0].abs().max(dv[1].abs()).max(dv[2].abs());
        let limit = p.bd + 4.0 * p.delta_scale;
        if longest > limit {
            let shrink = limit / longest;
            dv.iter_mut().for_each(|d| *d *= shrink);
            dx.iter_mut().for_each(|d| {
                d[0] *= shrink;
                d[1] *= shrink;
            });
        }
        Some((dv, dx))
    }

    fn slope(&self, at: &Local, (dv, dx): &Step) -> Option<f64> {
        let mut slope = (0..3).map(|r| at.g_v[r] * dv[r]).sum::<f64>();
        for (g, d) in at.g_x.iter().zip(dx) {
            slope += g[0] * d[0] + g[1] * d[1];
        }
        Some(slope)
    }

    fn advance(&self, s: &State, step: &Step, t: f64) -> State {
        s.advance(step, t)
    }

    fn accepts(&self, here: &Local, trial: &Local, t: f64, slope: Option<f64>) -> bool {
        armijo(here.energy, trial.energy, t, slope.unwrap_or(f64::NAN))
            || residual_falls(self.residual(here), self.residual(trial), t)
    }
}

/// The whole balance with the gyroscopic friction following the state: its Jacobian by central
/// differences makes the system non-symmetric (no energy), so a step is judged by the fall of
/// the force vector's 2-norm.
struct CoupledFriction<'a> {
    problem: &'a Problem,
}

impl CoupledFriction<'_> {
    /// |(∇_v Π, ∇_X Π)|₂.
    fn norm(l: &Local) -> f64 {
        let mut s = l.g_v.iter().map(|g| g * g).sum::<f64>();
        s += l.g_x.iter().map(|g| g[0] * g[0] + g[1] * g[1]).sum::<f64>();
        s.sqrt()
    }
}

impl NewtonSystem for CoupledFriction<'_> {
    type Point = State;
    type Eval = Local;
    type Step = Step;

    fn evaluate(&self, s: &State) -> Local {
        let f = self.problem.gyroscopic_friction(s.v, &s.x);
        self.problem.local(s.v, &s.x, &f)
    }

    fn residual(&self, at: &Local) -> f64 {
        self.problem.residual(at)
    }

    /// The Newton step with the ball blocks eliminated: A = H_xx − ∂f/∂X (shifted), C = H_xv −
    /// (∂f/∂I) J, B = H_vx; the ring step from the 3 × 3 Schur complement, then each ball's.
    fn direction(&self, s: &State, here: &Local) -> Option<Step> {
        let p = self.problem;
        let floor = p.stiffness_floor();
        let mut schur = here.h_vv;
        let mut rhs = [-here.g_v[0], -here.g_v[1], -here.g_v[2]];
        let mut blocks = Vec::with_capacity(s.x.len());
        for (j, &c) in p.cosines.iter().enumerate() {
            let (df_i, df_x) = p.friction_jacobians(p.inner_centre(s.v, c), s.x[j]);
            let jac = Problem::jacobian(c);
            // A = H_xx − ∂f/∂X; C = H_xv − (∂f/∂I) J; B = H_vx.
            let mut a = here.h_xx[j];
            for r in 0..2 {
                for k in 0..2 {
                    a[r][k] -= df_x[r][k];
                }
                a[r][r] += 1e-12 * (here.h_xx[j][0][0] + here.h_xx[j][1][1]).abs() + floor * 1e-3;
            }
            let mut cm = [[0.0; 3]; 2];
            for r in 0..2 {
                for col in 0..3 {
                    let dfv = df_i[r][0] * jac[0][col] + df_i[r][1] * jac[1][col];
                    cm[r][col] =
                        here.h_vx[j][col][r] - if p.tilt_free || col < 2 { dfv } else { 0.0 };
                }
            }
            let det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
            if det.is_nan() || det == 0.0 {
                return None;
            }
            let inv = [
                [a[1][1] / det, -a[0][1] / det],
                [-a[1][0] / det, a[0][0] / det],
            ];
            let b = here.h_vx[j];
            let g = here.g_x[j];
            // P = B A⁻¹ (3 × 2).
            let mut pm = [[0.0; 2]; 3];
            for r in 0..3 {
                for k in 0..2 {
                    pm[r][k] = b[r][0] * inv[0][k] + b[r][1] * inv[1][k];
                }
            }
            for r in 0..3 {
                for col in 0..3 {
                    schur[r][col] -= pm[r][0] * cm[0][col] + pm[r][1] * cm[1][col];
                }
                rhs[r] += pm[r][0] * g[0] + pm[r][1] * g[1];
            }
            blocks.push((inv, cm));
        }
        let dv = solve(schur, rhs)?;
        let dx: Vec<[f64; 2]> = blocks
            .iter()
            .zip(&here.g_x)
            .map(|((inv, cm), g)| {
                let t = [
                    -g[0] - (cm[0][0] * dv[0] + cm[0][1] * dv[1] + cm[0][2] * dv[2]),
                    -g[1] - (cm[1][0] * dv[0] + cm[1][1] * dv[1] + cm[1][2] * dv[2]),
                ];
                [
                    inv[0][0] * t[0] + inv[0][1] * t[1],
                    inv[1][0] * t[0] + inv[1][1] * t[1],
                ]
            })
            .collect();
        Some((dv, dx))
    }

    fn advance(&self, s: &State, step: &Step, t: f64) -> State {
        s.advance(step, t)
    }

    fn accepts(&self, here: &Local, trial: &Local, t: f64, _slope: Option<f64>) -> bool {
        residual_falls(Self::norm(here), Self::norm(trial), t)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn small_systems_solve() {
        let a = [[4.0, 1.0, 0.0], [1.0, 3.0, 1.0], [0.0, 1.0, 2.0]];
        let x = solve(a, [1.0, 2.0, 3.0]).unwrap();
        for r in 0..3 {
            let s: f64 = (0..3).map(|c| a[r][c] * x[c]).sum();
            assert!((s - [1.0, 2.0, 3.0][r]).abs() < 1e-12);
        }
        assert!(solve([[0.0, 0.0], [0.0, 0.0]], [1.0, 1.0]).is_none());
    }
}
