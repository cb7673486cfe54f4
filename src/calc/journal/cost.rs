//! What a journal film's grid costs before it is solved, so that a grid the request's deadline
//! cannot pay for is refused at once (a 422 naming the grid) instead of being solved until the
//! deadline stops it (a 504 after the whole wait).
//!
//! The Reynolds-condition and full films are solved by banded Cholesky factorisations
//! (`numerics::reynolds::complementarity`): one per active-set step, each n b²/2 multiply–adds
//! for n unknowns and b sub-diagonals (b the unknowns across the length, which the nodes are
//! numbered across first). Beyond `high`'s mesh these factorisations are the request's time.
//! Mass-conserving films are solved by sweeps and are not estimated here.

use std::f64::consts::PI;

use super::film::{FilmModel, Mesh};
use super::performance::{placed, third_mesh, Method, ThirdMesh};
use crate::calc::grid_cost::{self, Factorisations};
use crate::calc::{Budget, CalcError};
use crate::fidelity::Level;

/// Seconds per unit of band work (unknowns × band²) of one active-set step, assembly, solve
/// and integration included. Measured in release on the 2-core machine the service is built
/// on: the README's request (10 kN, ISO VG 32 from 40 °C, thermal and dynamics) on the grid
/// [512, 256] took 6.6 s; it factored its mesh (130 816 unknowns, band 256) 8 times and the
/// half mesh (32 640, band 128) 26 times (counted by instrumenting the factorisation), 9.6
/// factorisations' worth of 8.57e9 units: 8.0e-11 s each. The same constant gives 13 s for
/// [1024, 256], which took 12.2 s (a 504 at the 10 s deadline).
pub const SECONDS_PER_BAND_WORK: f64 = 8.0e-11;

/// Factorisations of the request's own mesh that the simplest request of its kind takes,
/// with those of the half mesh its error estimate and search also solve (each a sixteenth of
/// the work: a quarter of the unknowns, half the band), counted on [256, 64] as for
/// [`SECONDS_PER_BAND_WORK`]. A film that ruptures (the Reynolds condition) takes several
/// active-set steps per solve, a film without rupture one; a given eccentricity needs one
/// point's solves, a given load an equilibrium search's. Thermal iterations at a given
/// eccentricity, dynamics and placed films add to these, so the estimate stays below the
/// request's time.
fn factorisations(physics: &FilmModel, load_given: bool) -> f64 {
    let (own, half) = match (physics.cavitation, load_given) {
        (true, false) => (3.0, 3.0),
        (true, true) => (7.0, 13.0),
        (false, false) => (1.0, 1.0),
        (false, true) => (4.0, 7.0),
    };
    own + half / 16.0
}

/// Unknowns and band of one factorisation of `physics`'s film on `mesh`: the columns round the
/// film (a partial arc has as many per radian as the full circle twice over, at least 16) times
/// the rows across the length (half of it for an aligned journal, the whole of a tilted one).
pub fn factorisation_size(mesh: Mesh, physics: &FilmModel) -> (usize, usize) {
    let columns = match physics.arc {
        Some(arc) => ((mesh.circumferential as f64) * arc / PI).round().max(16.0) as usize,
        None => mesh.circumferential,
    };
    let rows = if physics.misalignment.is_some() {
        2 * mesh.axial_half
    } else {
        mesh.axial_half
    };
    (columns * rows, rows)
}

/// A 422 naming the grid (or the fidelity, for a level's own mesh) when the film solves would
/// take longer than the request's deadline leaves.
pub fn check_affordable(
    method: Method,
    physics: &FilmModel,
    load_given: bool,
    budget: &Budget,
) -> Result<(), CalcError> {
    let (Method::Numerical { level, mesh, .. }, None) = (method, physics.mass_conserving) else {
        return Ok(());
    };
    let explicit = Method::numerical(level, None, None).mesh() != Some(mesh);
    let size = factorisation_size(mesh, physics);
    // The error estimate's solve on the doubled mesh: sixteen times the band work, one point's
    // factorisations (a placed film's search takes five solves at least).
    let third = match third_mesh(mesh) {
        ThirdMesh::Double(_) => {
            let steps = if physics.cavitation { 3.0 } else { 1.0 };
            16.0 * steps * if placed(physics) { 5.0 } else { 1.0 }
        }
        ThirdMesh::Quarter(_) => 0.0,
    };
    within_deadline(
        mesh,
        explicit,
        size,
        factorisations(physics, load_given) + third,
        budget,
    )
}

/// As [`check_affordable`], for a room that solves the aligned film on `mesh` `solves` times,
/// each one factorisation at least (the `/dynamic` room's impedance table, the squeezed
/// journal's quadrature); a `periodic` film (a still film without rupture) numbers its
/// columns round the seam, with twice the band.
pub fn check_solves(
    mesh: Mesh,
    periodic: bool,
    explicit: bool,
    solves: usize,
    budget: &Budget,
) -> Result<(), CalcError> {
    let (unknowns, rows) = factorisation_size(mesh, &FilmModel::REYNOLDS);
    let band = if periodic { 2 * rows } else { rows };
    within_deadline(mesh, explicit, (unknowns, band), solves as f64, budget)
}

/// The refusal of `factorisations` of (unknowns, band) on `mesh` when they outlast the
/// deadline.
fn within_deadline(
    mesh: Mesh,
    explicit: bool,
    (unknowns, band): (usize, usize),
    factorisations: f64,
    budget: &Budget,
) -> Result<(), CalcError> {
    let high = Method::numerical(Level::High, None, None)
        .mesh()
        .expect("a level has a mesh");
    grid_cost::within_deadline(
        &Factorisations {
            grid: [mesh.circumferential, mesh.axial_half],
            unknowns,
            band,
            count: factorisations,
            seconds_per_band_work: SECONDS_PER_BAND_WORK,
        },
        explicit,
        [high.circumferential, high.axial_half],
        budget,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::calc::journal::film::Misalignment;
    use crate::fidelity::Level;

    fn grid(circumferential: usize, axial_half: usize) -> Method {
        Method::numerical(
            Level::Standard,
            Some(Mesh {
                circumferential,
                axial_half,
            }),
            None,
        )
    }

    /// The README's request (load given, Reynolds film) against the measured times: [512, 256]
    /// (6.6 s) fits the 10 s deadline, [1024, 256] (12.2 s) does not; the estimate stays below
    /// both; the levels' meshes cost milliseconds.
    #[test]
    fn the_estimate_stays_below_the_measured_time_and_parts_the_deadline() {
        let film = FilmModel::REYNOLDS;
        let at = |m: Method| {
            let (unknowns, band) = factorisation_size(m.mesh().unwrap(), &film);
            factorisations(&film, true) * SECONDS_PER_BAND_WORK * (unknowns * band * band) as f64
        };
        let (fits, late) = (at(grid(512, 256)), at(grid(1024, 256)));
        assert!(fits < 6.6, "{fits}");
        assert!(late < 12.2 && late > 10.0, "{late}");
        for level in [Level::Fast, Level::Standard, Level::High] {
            assert!(at(Method::numerical(level, None, None)) < 0.005);
        }
        // A tilted journal has the whole length: twice the rows, eight times the work; a 90°
        // arc half the circle's columns.
        let mesh = Mesh {
            circumferential: 64,
            axial_half: 8,
        };
        let tilted = FilmModel {
            misalignment: Some(Misalignment::default()),
            ..film
        };
        let arc = FilmModel {
            arc: Some(0.5 * PI),
            ..film
        };
        assert_eq!(factorisation_size(mesh, &tilted), (1024, 16));
        assert_eq!(factorisation_size(mesh, &arc), (256, 8));
    }

    #[test]
    fn a_grid_beyond_the_deadline_is_refused_naming_the_grid() {
        use std::sync::atomic::AtomicBool;
        use std::sync::Arc;
        use std::time::{Duration, Instant};
        let budget = Budget::new(
            Instant::now() + Duration::from_secs(10),
            Arc::new(AtomicBool::new(false)),
        );
        let film = FilmModel::REYNOLDS;
        match check_affordable(grid(1024, 256), &film, true, &budget) {
            Err(CalcError::Impossible { pointer, message }) => {
                assert_eq!(pointer, "/fidelity/grid");
                assert!(message.contains("about 10.7 s at least"), "{message}");
            }
            other => panic!("{other:?}"),
        }
        assert_eq!(
            check_affordable(grid(512, 256), &film, true, &budget),
            Ok(())
        );
        // Without a deadline (the CLI's own budget is the server's) nothing is refused.
        assert_eq!(
            check_affordable(grid(1024, 256), &film, true, &Budget::unlimited()),
            Ok(())
        );
    }
}
