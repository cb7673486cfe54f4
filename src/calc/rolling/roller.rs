//! Cylindrical roller bearings in the load distribution room (model): the validated roller
//! bearing (the `bearing` object's roller variant and its validation are the wire file
//! `bearing_spec.rs`) and the radial equilibrium of the inner ring on line contacts.
//!
//! Model (Khonsari & Booser §14.2 RI-4 and §14.4 RI-6; Hamrock §21.3.6):
//! - Straight (uncrowned) rollers of effective length L (the length less the corner radii or
//!   undercuts, Hamrock A.1.8), each between two line contacts. Palmgren's load–deflection law
//!   per contact, δ = 3.84·10⁻⁵ Q^0.9/L^0.8 (mm, N, mm; steel on steel, E′ = 219 000 N/mm²,
//!   other materials by scaling Q with E′_steel/E′_pair, Khonsari RI-4), is independent of the
//!   raceway curvature, so both contacts in series give Q = K_n δ^{10/9} with δ the total
//!   approach and K_n = (2c)^{−10/9}, c the law's constant (Khonsari's n = 1/0.9 for rollers;
//!   Hamrock's linear K₁ law is the cruder j = 1).
//! - Rigid rings, radial load only: roller j at ψ_j = 2πj/Z (ψ = 0 on the load line) is
//!   compressed by δ_j = δ_r cos ψ_j − P_d/2 (Hamrock eq. 21.105), loaded where positive;
//!   Σ Q_j cos ψ_j = F_r, solved for δ_r by Brent's method (monotone). Zero clearance gives
//!   Stribeck's roller constant Z F_r/Q_max → 4.08 (Khonsari T16: 4.077 for 8, 4.088 for 10
//!   rollers).
//! - Crowned rollers (`profile: {"crown_radius_m": R}`; Hamrock A.1.8: r_ay/D ≈ 10² for
//!   cylindrical rollers) are sliced into 40 laminae of width w = L/40 across the length; at
//!   lamina k, y_k from the roller's middle, the crown drop g_k = y_k²/(2R) lowers the approach
//!   at each of the two contacts, and the lamina carries its share of Palmgren's law:
//!   Q_k = (w/L) K_n (δ − 2g_k)₊^{10/9}, which sums back to the straight roller's Q = K_n δ^{10/9}
//!   when R → ∞. Light loads touch only the middle laminae (the point-contact end of the range).
//! - A cylindrical roller bearing of the N/NU kind carries no axial load and this model no
//!   tilting moment (no edge loading, no misalignment along the rollers).
//! - The raceway contacts of the most loaded roller are the Hertz room's line contacts (roller
//!   radius D/2 against (d_m − D)/2 convex inside and −(d_m + D)/2 concave outside): maximum
//!   pressure, half-width b (reported as the semi-minor axis; the semi-major axis is L/2) and
//!   Hamrock's approach with its logarithms (eq. 21.51).

use super::geometry::Material;
use super::ring_equilibrium::{balanced, load_balance_root, MAX_BRENT_ITERATIONS};
use crate::calc::contact::hertz::{Body, Contact, Invalid, Method, Shape, Solution};
use crate::calc::CalcError;
use crate::fidelity::{IterationUnit, SolverReport};
use crate::numerics::driver::{Budget, Driver};

/// Palmgren's constant, mm per N^0.9 mm^−0.8, and the steel E′ it holds for, Pa (Khonsari RI-4).
const PALMGREN_MM: f64 = 3.84e-5;
const PALMGREN_STEEL_E_PA: f64 = 2.19e11;
const TOLERANCE: f64 = 1e-9;
/// ISO 76's contact pressure at C0 for roller bearings, Pa.
pub const ROLLER_STATIC_LIMIT_PA: f64 = 4.0e9;

/// Laminae of a crowned roller.
const LAMINAE: usize = 40;

/// A validated roller bearing.
#[derive(Debug, Clone, Copy)]
pub struct RollerBearing {
    pub roller_diameter_m: f64,
    pub length_m: f64,
    pub pitch_diameter_m: f64,
    pub roller_count: usize,
    pub clearance_m: f64,
    /// Crown radius, m (None: straight).
    pub crown_radius_m: Option<f64>,
    pub(super) rollers: Material,
    pub(super) rings: Material,
}

/// The validated roller case.
#[derive(Debug, Clone, Copy)]
pub struct RollerCase {
    pub bearing: RollerBearing,
    pub radial_load_n: f64,
}

/// The roller equilibrium.
pub struct RollerEquilibrium {
    pub loads: Vec<f64>,
    /// The most loaded roller's total approach δ, m.
    pub max_approach_m: f64,
    pub radial_displacement_m: f64,
    pub stiffness: f64,
    pub report: SolverReport,
}

impl RollerBearing {
    /// E′ of the pair, Pa (Hamrock: 2/E′ = Σ (1 − ν²)/E).
    fn effective_modulus(&self) -> f64 {
        let c = |m: Material| {
            let nu = m.poisson_ratio.get();
            (1.0 - nu * nu) / m.elastic_modulus_pa.get()
        };
        2.0 / (c(self.rollers) + c(self.rings))
    }

    /// Palmgren's per-contact constant c in SI: δ = c Q^0.9 (m, N).
    fn palmgren(&self) -> f64 {
        let l_mm = self.length_m * 1e3;
        1e-3 * PALMGREN_MM * (PALMGREN_STEEL_E_PA / self.effective_modulus()).powf(0.9)
            / l_mm.powf(0.8)
    }

    /// K_n of a roller between both raceways, N/m^(10/9): Q = K_n δ^{10/9}.
    pub fn contact_stiffness(&self) -> f64 {
        (2.0 * self.palmgren()).powf(-10.0 / 9.0)
    }

    /// The laminae: (offset from the middle y_k, crown drop g_k), m; one lamina of drop 0 for a
    /// straight roller.
    pub fn laminae(&self) -> Vec<(f64, f64)> {
        match self.crown_radius_m {
            None => vec![(0.0, 0.0)],
            Some(r) => (0..LAMINAE)
                .map(|k| {
                    let y = ((k as f64 + 0.5) / LAMINAE as f64 - 0.5) * self.length_m;
                    (y, y * y / (2.0 * r))
                })
                .collect(),
        }
    }

    /// A roller's load at the total approach δ (both contacts), N, and its laminae's loads.
    pub fn roller_load(&self, delta: f64, laminae: &[(f64, f64)]) -> (f64, Vec<f64>) {
        let k = self.contact_stiffness() / laminae.len() as f64;
        let loads: Vec<f64> = laminae
            .iter()
            .map(|&(_, g)| {
                let d = delta - 2.0 * g;
                if d > 0.0 {
                    k * d.powf(10.0 / 9.0)
                } else {
                    0.0
                }
            })
            .collect();
        (loads.iter().sum(), loads)
    }

    /// The Hertz line contact of a roller on the inner or outer raceway under `load_n`, from the
    /// Hertz model, with the model's warnings in the solution.
    pub fn raceway_solution(
        &self,
        inner: bool,
        load_n: f64,
        length_m: f64,
    ) -> Result<Solution, CalcError> {
        let d = self.roller_diameter_m;
        let race = if inner {
            0.5 * (self.pitch_diameter_m - d)
        } else {
            -0.5 * (self.pitch_diameter_m + d)
        };
        let body = |r: f64, m: Material| Body {
            radius_x_m: Some(r),
            radius_y_m: None,
            modulus_pa: m.elastic_modulus_pa.get(),
            poisson_ratio: m.poisson_ratio.get(),
        };
        let contact = Contact::new(
            [body(0.5 * d, self.rollers), body(race, self.rings)],
            load_n,
            Shape::Line { length_m },
            Method::Exact,
        )
        .map_err(|errors| {
            Invalid::refusal(
                errors,
                "/bearing",
                "a roller's raceway contact is not a Hertz line contact",
            )
        })?;
        contact.solve()
    }
}

/// The radial equilibrium: Brent on δ_r (monotone force), or the preloaded bearing at rest.
pub fn equilibrium(case: &RollerCase, budget: &Budget) -> Result<RollerEquilibrium, CalcError> {
    const METHOD: &str = "brent_roller_load_balance";
    let b = &case.bearing;
    let z = b.roller_count;
    let k = b.contact_stiffness();
    let half = 0.5 * b.clearance_m;
    // The crown drop at the roller's ends: the approach a crowned roller needs to touch all along.
    let crown = b.laminae().iter().map(|l| 2.0 * l.1).fold(0.0, f64::max);
    let cosines: Vec<f64> = (0..z)
        .map(|j| (std::f64::consts::TAU * j as f64 / z as f64).cos())
        .collect();
    let laminae = b.laminae();
    let loads = |d_r: f64| -> Vec<f64> {
        cosines
            .iter()
            .map(|&c| b.roller_load(d_r * c - half, &laminae).0)
            .collect()
    };
    let force = |d_r: f64| -> f64 {
        loads(d_r)
            .iter()
            .zip(&cosines)
            .map(|(q, c)| q * c)
            .sum::<f64>()
            - case.radial_load_n
    };
    let preload = z as f64 * b.roller_load(-half, &laminae).0;
    let scale = case.radial_load_n.max(preload);
    if case.radial_load_n == 0.0 {
        return Ok(RollerEquilibrium {
            loads: loads(0.0),
            max_approach_m: -half,
            radial_displacement_m: 0.0,
            stiffness: k,
            report: Driver::new(
                METHOD,
                IterationUnit::RootSearchSteps,
                MAX_BRENT_ITERATIONS,
                budget,
            )
            .converged_at_start((), 0.0)
            .report,
        });
    }
    // From the concentric position, past the clearance, doubled until the rollers carry F_r.
    let delta_scale = (case.radial_load_n / (z as f64 * k)).powf(0.9);
    // (At least a millionth of the roller diameter: a denormal load's δ scale underflows.)
    let hi = (half.abs() + delta_scale + crown).max(1e-6 * b.roller_diameter_m);
    let root = load_balance_root(&force, hi, METHOD, budget)?;
    let report = balanced(&root, force(root.x).abs() / scale, TOLERANCE)?;
    Ok(RollerEquilibrium {
        loads: loads(root.x),
        max_approach_m: root.x - half,
        radial_displacement_m: root.x,
        stiffness: k,
        report,
    })
}
