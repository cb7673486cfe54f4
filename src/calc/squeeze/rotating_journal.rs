//! The squeezed journal that also turns (Khonsari & Booser §9.6, Ex 9.5; spec SQ-7): a constant
//! load W applied to a journal turning at ω, from ε₁ on the load line, until ε reaches ε₂.
//!
//! The rotation's wedge pushes the journal sideways, so the load is not along its path and the
//! pure squeeze's one-dimensional quadrature no longer holds. The path is the journal room's
//! orbit of a massless journal (Booker's mobility, [`crate::calc::journal::orbit`]) under a
//! constant load, where the book marches a chart of χ = ė/ω at constant W̄ = C²W/(μR²LU). The
//! film is the short bearing's (the full 360° film or the π film, closed forms) or the finite
//! Reynolds film with cavitation (the impedance table `/v1/journal-bearings/dynamic` uses).
//! Frame and signs are the orbit's: the load points along −y, the journal turns counter-
//! clockwise, and the start is r̄ = (0, −ε₁).
//!
//! A journal whose film carries the load before ε₂ settles there (its steady equilibrium lies
//! below ε₂): it never reaches ε₂, and the room answers with that verdict.

use std::f64::consts::PI;
use std::sync::Arc;

use crate::calc::journal::film::Mesh;
use crate::calc::journal::finite_moving_film::{FiniteSqueezeFilm, ImpedanceTable, TableDensity};
use crate::calc::journal::load_law::LoadLaw;
use crate::calc::journal::moving_film::{ShortArc, ShortFilm};
use crate::calc::journal::orbit::{self, OrbitError, OrbitFilm, Problem, Scales, Start, Until};
use crate::calc::{Budget, CalcError};
use crate::fidelity::SolverReport;
use crate::numerics::driver::Stopped;

/// Journal revolutions the run may take before it counts as never reaching ε₂ (the `/dynamic`
/// room's horizon).
const MAX_REVOLUTIONS: f64 = 20_000.0;

/// The film of the turning journal.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RotatingFilm {
    /// The short bearing (Booker's closed forms): `Full` keeps the whole circle's pressures,
    /// `PiFilm` the half-Sommerfeld arc centred on the squeeze vector.
    Short(ShortArc),
    /// The finite film with the Reynolds condition, tabulated on `mesh` at `density`.
    Finite { mesh: Mesh, density: TableDensity },
}

/// The bearing, the oil, the speed and the load, SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TurningJournal {
    pub radius_m: f64,
    pub length_m: f64,
    pub clearance_m: f64,
    pub viscosity_pa_s: f64,
    /// ω, rad/s.
    pub omega: f64,
    pub load_n: f64,
}

/// How the run ended.
#[derive(Debug, Clone, PartialEq)]
pub enum Approach {
    /// ε reached ε₂ after `time_s`; the radial speeds C dε/dt at ε₁ and ε₂, m/s.
    Reached {
        time_s: f64,
        speed_initial_m_s: f64,
        speed_final_m_s: f64,
        report: SolverReport,
    },
    /// The journal settled short of ε₂, at `eccentricity_ratio`.
    Settles { eccentricity_ratio: f64 },
}

/// The run from ε₁ to ε₂ at step tolerance `tolerance`.
pub fn approach(
    journal: TurningJournal,
    e1: f64,
    e2: f64,
    film: RotatingFilm,
    tolerance: f64,
    budget: &Budget,
) -> Result<Approach, CalcError> {
    let TurningJournal {
        radius_m: r,
        length_m: l,
        clearance_m: c,
        viscosity_pa_s: mu,
        omega,
        load_n,
    } = journal;
    let scales = Scales::of(mu, r, l, c, omega);
    let film = match film {
        RotatingFilm::Short(arc) => OrbitFilm::Short(ShortFilm {
            arc,
            speed_sum: 1.0,
        }),
        RotatingFilm::Finite { mesh, density } => {
            let l_over_d = l / (2.0 * r);
            let table =
                ImpedanceTable::build(FiniteSqueezeFilm { l_over_d, mesh }, density, budget)?;
            OrbitFilm::Finite {
                table: Arc::new(table),
                speed_sum: 1.0,
            }
        }
    };
    let reach = film.reach();
    let problem = Problem {
        film,
        mass: 0.0,
        load: LoadLaw::Constant {
            force: [0.0, -load_n],
        },
        force_scale: scales.force,
    };
    let start = [0.0, -e1];
    let until = Until::Eccentricity {
        target: e2,
        horizon: MAX_REVOLUTIONS * 2.0 * PI,
        settled_within: 100.0 * tolerance,
    };
    let run = orbit::run(
        &problem,
        Start {
            position: start,
            velocity: [0.0, 0.0],
        },
        until,
        tolerance,
        0,
        budget,
    )
    .map_err(|e| match e {
        OrbitError::Contact { time, eccentricity } => CalcError::impossible(
            "/load_n",
            format!(
                "the journal leaves the film's model at t = {:.6e} s (ε = {eccentricity:.6}; it reaches ε = {reach}) before ε₂",
                time / omega
            ),
        ),
        OrbitError::Stopped(report) => Stopped { report }.into(),
    })?;
    let Some(tau) = run.time_to_target else {
        if !run.steady {
            return Err(CalcError::impossible(
                "/final_eccentricity_ratio",
                format!("the turning journal did not reach ε₂ within {MAX_REVOLUTIONS} revolutions ({:.4e} s), nor settle short of it (largest ε {:.4})", run.end / omega, run.peak_eccentricity),
            ));
        }
        return Ok(Approach::Settles {
            eccentricity_ratio: run.peak_eccentricity,
        });
    };
    // C dε/dt = C ω (r̂ · dr̄/dτ); at the centre r̂ is the load's direction.
    let radial_speed = |position: [f64; 2]| -> Result<f64, CalcError> {
        let v = problem.mobility_velocity(0.0, position).ok_or_else(|| {
            CalcError::impossible("/load_n", "the film cannot carry the load at this position")
        })?;
        let e = position[0].hypot(position[1]);
        let (ux, uy) = if e > 0.0 {
            (position[0] / e, position[1] / e)
        } else {
            (0.0, -1.0)
        };
        Ok(c * omega * (ux * v[0] + uy * v[1]))
    };
    Ok(Approach::Reached {
        time_s: tau / omega,
        speed_initial_m_s: radial_speed(start)?,
        speed_final_m_s: radial_speed(run.position)?,
        report: run.report,
    })
}
