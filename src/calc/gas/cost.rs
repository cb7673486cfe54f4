//! What a gas film's explicit grid costs before it is solved, so that a grid the request's
//! deadline cannot pay for is refused at once (a 422 naming `/fidelity/grid`, through
//! [`grid_cost::within_deadline`]) instead of being solved until the deadline stops it (a 504
//! after the whole wait). A level's mesh is never refused.
//!
//! Every gas film is solved by Newton (`numerics::reynolds_gas`), each step one band LU of its
//! Jacobian: 2 n b² multiply–adds for n unknowns and b sub-diagonals (b the unknowns across,
//! twice that round a journal's seam). Beyond `high`'s meshes these factorisations are the
//! request's time: in the release runs below they were 60–75 % of it, the rest the Jacobians'
//! assembly and the line searches, which the estimate leaves out. The whirl coefficients'
//! harmonic system has twice the order and twice the band: each is eight Newton steps' worth.
//!
//! Each room's count is the factorisations of its own mesh and of its half mesh (each a
//! sixteenth of the work: a quarter of the unknowns, half the band) that the simplest request
//! of a kind took on the room's example, counted by instrumenting the factorisation, halved
//! where a search sets the count (an easier case may need fewer trials), so that the estimate
//! stays below the request's time.

use super::method::{Mesh, Method};
use crate::calc::grid_cost::{self, Factorisations};
use crate::calc::{Budget, CalcError};
use crate::fidelity::Level;
use crate::numerics::reynolds_gas::{factorisation_size, FarEdge, GasGrid};

/// Seconds per unit of band-LU work (unknowns × band²) of one Newton step. Measured in release
/// on the 2-core machine the service is built on (LU alone, timed around each factorisation):
/// 4.47e-10 on the slider's [1024, 256] (261 888 unknowns, band 256, 7.7 s each), 4.77e-10 to
/// 5.2e-10 on the journal's [512, 128] (65 536, band 256, 2.0–2.2 s each), 5.3e-10 to 6.3e-10
/// on smaller ones; this is a little under the fastest.
pub const SECONDS_PER_BAND_WORK: f64 = 4.0e-10;

/// Newton steps' worth of one harmonic (whirl coefficient) factorisation: twice the order,
/// twice the band (`numerics::reynolds_gas::harmonic_response`).
pub const HARMONIC_FACTORISATION: f64 = 8.0;

/// Factorisations a request takes at least: of its own mesh, and of the half mesh (solved
/// when the grid halves exactly).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Least {
    pub own: f64,
    pub half: f64,
}

impl Least {
    const fn new(own: f64, half: f64) -> Least {
        Least { own, half }
    }

    /// One film from its half mesh: the half mesh by continuation in Λ from ambient, then
    /// the mesh from the half mesh's field, by Newton in 1 step where the film is nearly linear
    /// (Λ below the continuation's start, 2), else 2 or more: the slider's [256, 64] took 1
    /// at Λ = 0.085 and 0.85, 2 at 1.7, 2.1 and 8.5, 3 at 85 and 850; every grid measured at
    /// the example's Λ = 8.5 took 2 (the slider's [512, 128] to [1024, 256]: 13.0 s and 25.9 s
    /// on [512, 256] and [1024, 256], 6.1 s on [512, 256] at Λ = 0.085), the journal's at
    /// Λ = 5.2 too ([256, 64] to [512, 128]: 7.95 s on [512, 128]). The half mesh took 2 at
    /// least.
    pub fn one_film(bearing_number: f64) -> Least {
        Least::new(if bearing_number < 2.0 { 1.0 } else { 2.0 }, 2.0)
    }

    /// The gas journal's by-load search (a secant on ln(ε/(1 − ε)), each trial a film from
    /// the last): the example's film by load took 81 and 90 on [512, 128] (20 N, Λ = 5.2:
    /// 443 s), 21 and 24 on [256, 64] at Λ = 0.52 (1 N, 4.9 s), 13 and 16 at Λ = 0.052
    /// (0.01 N, 3.6 s).
    pub const JOURNAL_BY_LOAD: Least = Least::new(10.0, 12.0);

    /// The tilting-pad journal at a given eccentricity (each of two pads' tilt searches, a walk
    /// and a secant, every trial a film): Ex 11.6's bearing at ε′ = 0.5 on [192, 48] took 54
    /// and 55 (1.1 s of LU).
    pub const TILTING_PAD_JOURNAL_AT_ECCENTRICITY: Least = Least::new(27.0, 27.0);

    /// The tilting-pad journal by load (a secant in ε′ over those): Ex 11.6 (11.12 N) took
    /// 249 and 249 on [192, 48] (4.5 s), 258 on [256, 64].
    pub const TILTING_PAD_JOURNAL_BY_LOAD: Least = Least::new(120.0, 120.0);

    /// The tilting-pad thrust pad at a given clearance (the pitch from rest, then Broyden on
    /// pitch and roll, each trial a film from the last; the half mesh searches from rest, the
    /// mesh from the half mesh's balance): the example's pad at 20 µm on [192, 48] took 6
    /// and 41 (1.6 s).
    pub const THRUST_PAD_AT_CLEARANCE: Least = Least::new(3.0, 20.0);

    /// The tilting-pad thrust pad by load (a secant in ln C over those): the example
    /// (2001.7 N) took 61 and 163 on [128, 24], 66 and 163 on [192, 48] (12.2 s).
    pub const THRUST_PAD_BY_LOAD: Least = Least::new(30.0, 80.0);

    /// These and `ratios` whirl ratios' harmonic factorisations on both meshes.
    pub fn with_whirl_ratios(self, ratios: usize) -> Least {
        let harmonic = ratios as f64 * HARMONIC_FACTORISATION;
        Least {
            own: self.own + harmonic,
            half: self.half + harmonic,
        }
    }
}

/// The refusal of an explicit grid (`method`'s mesh, not `levels`' mesh of its level) whose
/// film on `grid` (with `far_edge`) needs `least` factorisations that outlast the deadline.
pub fn check(
    method: Method,
    levels: impl Fn(Level) -> Mesh,
    (grid, far_edge): (&GasGrid, FarEdge),
    least: Least,
    budget: &Budget,
) -> Result<(), CalcError> {
    let mesh = method.mesh;
    if mesh == levels(method.level) {
        return Ok(());
    }
    let (unknowns, band) = factorisation_size(grid, far_edge);
    let half = if method.richardson { least.half } else { 0.0 };
    let high = levels(Level::High);
    grid_cost::within_deadline(
        &Factorisations {
            grid: [mesh.along, mesh.across],
            unknowns,
            band,
            count: least.own + half / 16.0,
            seconds_per_band_work: SECONDS_PER_BAND_WORK,
        },
        true,
        [high.along, high.across],
        budget,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::calc::gas::slider_film::{self, SliderFilm};
    use std::sync::atomic::AtomicBool;
    use std::sync::Arc;
    use std::time::{Duration, Instant};

    fn slider(along: usize, across: usize) -> (Method, GasGrid) {
        let film = SliderFilm {
            film_ratio: 2.0,
            bearing_number: 10.0,
            knudsen_number: 0.0,
            width_ratio: Some(1.0),
        };
        let mesh = Mesh { along, across };
        (Method::mesh(mesh), slider_film::grid(&film, mesh))
    }

    /// The slider's measured grids: [1024, 256] (25.9 s) is refused at the 10 s deadline,
    /// [512, 256] (13.0 s) and [1024, 128] (4.4 s) are not, and each estimate stays below
    /// the measured time; a level's mesh is never refused, even with no time left.
    #[test]
    fn the_estimate_stays_below_the_measured_time() {
        let budget =
            |left: Duration| Budget::new(Instant::now() + left, Arc::new(AtomicBool::new(false)));
        let ten = budget(Duration::from_secs(10));
        let at = |(m, g): &(Method, GasGrid)| {
            check(
                *m,
                slider_film::level_mesh,
                (g, FarEdge::Symmetry),
                Least::one_film(10.0),
                &ten,
            )
        };
        match at(&slider(1024, 256)) {
            Err(CalcError::Impossible { pointer, message }) => {
                assert_eq!(pointer, "/fidelity/grid");
                // 2⅛ factorisations of 261 888 unknowns, band 256, 6.87 s each.
                assert!(
                    message.contains("would take about 14.6 s at least")
                        && message.contains("261888 unknowns with a band of 256")
                        && message.contains("(`high` is [128, 24])"),
                    "{message}"
                );
            }
            other => panic!("{other:?}"),
        }
        assert_eq!(at(&slider(512, 256)), Ok(()));
        assert_eq!(at(&slider(1024, 128)), Ok(()));
        let seconds = |(_, g): &(Method, GasGrid)| {
            let (n, b) = factorisation_size(g, FarEdge::Symmetry);
            (2.0 + 2.0 / 16.0) * SECONDS_PER_BAND_WORK * (n * b * b) as f64
        };
        for (grid, measured) in [((1024, 256), 25.9), ((512, 256), 13.0), ((1024, 128), 4.4)] {
            let estimate = seconds(&slider(grid.0, grid.1));
            assert!(estimate < 0.7 * measured, "{grid:?}: {estimate}");
        }
        // A nearly linear film (Λ = 0.085: [512, 256] in 6.1 s) counts one step on its mesh.
        let low = Least::one_film(0.085);
        assert_eq!(low, Least::new(1.0, 2.0));
        let (n, b) = factorisation_size(&slider(512, 256).1, FarEdge::Symmetry);
        let estimate = (low.own + low.half / 16.0) * SECONDS_PER_BAND_WORK * (n * b * b) as f64;
        assert!(estimate < 0.7 * 6.1, "{estimate}");
        let spent = budget(Duration::ZERO);
        for level in [Level::Fast, Level::Standard, Level::High] {
            let mesh = slider_film::level_mesh(level);
            let method = Method {
                level,
                mesh,
                richardson: true,
            };
            let (_, grid) = slider(mesh.along, mesh.across);
            assert_eq!(
                check(
                    method,
                    slider_film::level_mesh,
                    (&grid, FarEdge::Symmetry),
                    Least::one_film(10.0),
                    &spent
                ),
                Ok(())
            );
        }
    }

    /// Whirl ratios add eight Newton steps' worth each on both meshes; an odd grid (no half
    /// mesh) counts its own mesh only.
    #[test]
    fn whirl_ratios_and_an_odd_grid_count_as_they_solve() {
        let l = Least::one_film(10.0).with_whirl_ratios(14);
        assert_eq!(
            l,
            Least {
                own: 114.0,
                half: 114.0
            }
        );
        // 2 factorisations of 1023 × 255 unknowns, band 255, 6.8 s each: more than 6 s.
        let (_, grid) = slider(1024, 255);
        let odd = Method::mesh(Mesh {
            along: 1024,
            across: 255,
        });
        assert!(!odd.richardson);
        let budget = Budget::new(
            Instant::now() + Duration::from_secs(6),
            Arc::new(AtomicBool::new(false)),
        );
        match check(
            odd,
            slider_film::level_mesh,
            (&grid, FarEdge::Symmetry),
            Least::one_film(10.0),
            &budget,
        ) {
            Err(CalcError::Impossible { message, .. }) => {
                assert!(
                    message.contains(
                        "(2.0 banded factorisations' worth of 260865 unknowns with a band of 255"
                    ),
                    "{message}"
                );
            }
            other => panic!("{other:?}"),
        }
    }
}
