//! What a film's grid costs before it is solved, for the rooms whose films are solved by banded
//! factorisations (the journal's `journal::cost`, the gas rooms' `gas::cost`): a grid whose
//! factorisations the request's deadline cannot pay for is refused at once (a 422 naming the
//! grid) instead of being solved until the deadline stops it (a 504 after the whole wait).
//!
//! A banded factorisation of n unknowns with b sub-diagonals costs about n b² units of work
//! (n b²/2 multiply–adds for Cholesky, 2 n b² for LU with pivoting); each room calibrates the
//! seconds per unit of its own solver on a measured release run and counts the factorisations
//! its simplest request of a kind takes at least, so that the estimate stays below the time.

use std::time::Duration;

use super::{Budget, CalcError};

/// The factorisations a request takes at least, in one size's worth.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Factorisations {
    /// The grid as the request gives it (or the level's mesh).
    pub grid: [usize; 2],
    /// Unknowns of one factorisation.
    pub unknowns: usize,
    /// Its band (sub-diagonals).
    pub band: usize,
    /// How many of this size the request takes at least (coarser ones counted by their work).
    pub count: f64,
    /// Seconds per unit of band work (unknowns × band²) of one, the room's calibration.
    pub seconds_per_band_work: f64,
}

impl Factorisations {
    /// Seconds of one factorisation.
    pub fn each(&self) -> f64 {
        self.seconds_per_band_work * self.unknowns as f64 * (self.band * self.band) as f64
    }

    /// Seconds of them all: the estimate.
    pub fn seconds(&self) -> f64 {
        self.count * self.each()
    }
}

/// The refusal of `work` when it outlasts what the deadline leaves: naming `/fidelity/grid`
/// for an `explicit` grid, `/fidelity` for a level's mesh; `high` is the room's finest level
/// mesh, the coarser grid the reason suggests.
pub fn within_deadline(
    work: &Factorisations,
    explicit: bool,
    high: [usize; 2],
    budget: &Budget,
) -> Result<(), CalcError> {
    let least = Duration::from_secs_f64(work.seconds());
    if budget.allows(least) {
        return Ok(());
    }
    let left = budget.remaining().unwrap_or_default().as_secs_f64();
    let [along, across] = work.grid;
    Err(CalcError::impossible(
        if explicit { "/fidelity/grid" } else { "/fidelity" },
        format!(
            "the grid [{along}, {across}] would take about {:.1} s at least ({:.1} banded factorisations' worth of {} unknowns with a band of {}, {:.2} s each), more than the {left:.1} s the request's deadline leaves: use a coarser grid (`high` is [{}, {}])",
            least.as_secs_f64(),
            work.count,
            work.unknowns,
            work.band,
            work.each(),
            high[0],
            high[1],
        ),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::AtomicBool;
    use std::sync::Arc;
    use std::time::Instant;

    /// 3 factorisations of 1000 unknowns, band 100, at 1e-8 s per unit: 0.1 s each, 0.3 s in
    /// all; refused when 0.2 s remain, accepted with 1 s or without a deadline, and the reason
    /// gives the estimate, the work and what remains.
    #[test]
    fn work_beyond_what_remains_is_refused_with_its_estimate() {
        let work = Factorisations {
            grid: [40, 25],
            unknowns: 1000,
            band: 100,
            count: 3.0,
            seconds_per_band_work: 1e-8,
        };
        assert!((work.each() - 0.1).abs() < 1e-12 && (work.seconds() - 0.3).abs() < 1e-12);
        let left = |ms: u64| {
            Budget::new(
                Instant::now() + Duration::from_millis(ms),
                Arc::new(AtomicBool::new(false)),
            )
        };
        match within_deadline(&work, true, [128, 24], &left(200)) {
            Err(CalcError::Impossible { pointer, message }) => {
                assert_eq!(pointer, "/fidelity/grid");
                assert!(
                    message.starts_with("the grid [40, 25] would take about 0.3 s at least (3.0 banded factorisations' worth of 1000 unknowns with a band of 100, 0.10 s each), more than the 0.")
                        && message.ends_with("use a coarser grid (`high` is [128, 24])"),
                    "{message}"
                );
            }
            other => panic!("{other:?}"),
        }
        match within_deadline(&work, false, [128, 24], &left(200)) {
            Err(CalcError::Impossible { pointer, .. }) => assert_eq!(pointer, "/fidelity"),
            other => panic!("{other:?}"),
        }
        assert_eq!(within_deadline(&work, true, [128, 24], &left(1000)), Ok(()));
        assert_eq!(
            within_deadline(&work, true, [128, 24], &Budget::unlimited()),
            Ok(())
        );
    }
}
