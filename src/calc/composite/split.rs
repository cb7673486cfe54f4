//! The steady speed split of a composite bearing at a given eccentricity or load, and the same
//! bearing with its sleeve held (Harnoy ch. 18, §18.4.1; spec PART B.1.1 and B.1.4).
//!
//! At a given ε the sleeve speed is the closed form of [`Restraint::steady_speed_ratio`], and
//! the load follows from the speed sum ω_j(1 + ξ). At a given load ε and ξ are coupled: ξ rises
//! with ε (the film's torque grows as 1/√(1 − ε²)) and so does the load (1 + ξ) w̄(ε), so one
//! bracketed root in ε — the closed-form ξ evaluated inside — finds the pair
//! ([`SleeveFilm::eccentricity_for`]). The held sleeve is compared at the same load.

use super::film::{LoadError, SleeveFilm, COMPARISON_MAX_ECCENTRICITY, MAX_ECCENTRICITY};
use super::sleeve::Restraint;

/// What fixes the film.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Operating {
    /// The eccentricity ratio ε; the load follows.
    Eccentricity(f64),
    /// The load W, N; ε follows.
    Load(f64),
}

/// A steady film state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FilmState {
    pub eccentricity: f64,
    /// ω_b/ω_j.
    pub speed_ratio: f64,
    /// W, N.
    pub load: f64,
    /// M_h, N·m.
    pub torque: f64,
}

/// The split and its comparison.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Split {
    pub composite: FilmState,
    /// The same bearing, sleeve held (ξ = 0), at the composite's load.
    pub fixed: FilmState,
    /// Closed-form load evaluations of the searches (the held sleeve's always, the
    /// composite's when the load is given).
    pub evaluations: u32,
}

/// The steady state at ε of a composite bearing at journal speed ω_j, rad/s.
pub fn state_at(
    film: &SleeveFilm,
    restraint: &Restraint,
    journal_speed: f64,
    eps: f64,
) -> FilmState {
    let xi = restraint.steady_speed_ratio(film.petroff_coefficient(eps), journal_speed);
    FilmState {
        eccentricity: eps,
        speed_ratio: xi,
        load: film.load(eps, journal_speed * (1.0 + xi)),
        torque: film.torque(eps, journal_speed, xi * journal_speed),
    }
}

/// The steady split at `operating` and the held sleeve at the same load.
pub fn split(
    film: &SleeveFilm,
    restraint: &Restraint,
    journal_speed: f64,
    operating: Operating,
) -> Result<Split, LoadError> {
    let mut evaluations = 0;
    let composite = match operating {
        Operating::Eccentricity(eps) => state_at(film, restraint, journal_speed, eps),
        Operating::Load(load) => {
            let found = film.eccentricity_for(load, MAX_ECCENTRICITY, |eps| {
                journal_speed
                    * (1.0
                        + restraint
                            .steady_speed_ratio(film.petroff_coefficient(eps), journal_speed))
            })?;
            evaluations += found.evaluations;
            state_at(film, restraint, journal_speed, found.eccentricity)
        }
    };
    if composite.load <= 0.0 {
        // A concentric journal carries nothing, held or not.
        return Ok(Split {
            composite,
            fixed: FilmState {
                speed_ratio: 0.0,
                torque: film.torque(0.0, journal_speed, 0.0),
                ..composite
            },
            evaluations,
        });
    }
    // The held sleeve needs at most twice the composite's (1 + ξ ≤ 2) load coefficient: it
    // may run beyond the composite's bound, never beyond the comparison's.
    let found = film.eccentricity_for(composite.load, COMPARISON_MAX_ECCENTRICITY, |_| {
        journal_speed
    })?;
    evaluations += found.evaluations;
    let fixed = FilmState {
        eccentricity: found.eccentricity,
        speed_ratio: 0.0,
        load: composite.load,
        torque: film.torque(found.eccentricity, journal_speed, 0.0),
    };
    Ok(Split {
        composite,
        fixed,
        evaluations,
    })
}

#[cfg(test)]
mod tests {
    use std::f64::consts::PI;

    use super::*;

    const FILM: SleeveFilm = SleeveFilm {
        radius: 0.05,
        length: 0.1,
        clearance: 6e-5,
        viscosity: 0.03,
    };
    const PINS: Restraint = Restraint {
        coefficient: 0.0357,
        rolling_torque: 0.0,
    };

    /// The load search returns the state the eccentricity gives: ε, ξ, torque, and the load
    /// balance closed at the found ε; the held sleeve runs more eccentric at the same load.
    #[test]
    fn load_and_eccentricity_agree() {
        let wj = 3500.0 * PI / 30.0;
        for eps in [0.05, 0.5, 0.9, 0.99] {
            for restraint in [
                PINS,
                Restraint {
                    rolling_torque: 5.0,
                    ..PINS
                },
            ] {
                let at = state_at(&FILM, &restraint, wj, eps);
                let s = split(&FILM, &restraint, wj, Operating::Load(at.load)).unwrap();
                let c = s.composite;
                assert!((c.eccentricity - eps).abs() < 1e-10, "{eps}: {c:?}");
                assert!((c.speed_ratio / at.speed_ratio - 1.0).abs() < 1e-9);
                assert!((c.load / at.load - 1.0).abs() < 1e-9);
                assert!(s.fixed.eccentricity > c.eccentricity);
                assert!((s.fixed.load - c.load).abs() == 0.0);
                let back = FILM.load(s.fixed.eccentricity, wj);
                assert!((back / c.load - 1.0).abs() < 1e-9);
            }
        }
    }

    /// A load beyond ε = 0.999 is refused with the most the film carries; at the bound the
    /// held sleeve still finds its ε (beyond 0.999).
    #[test]
    fn too_heavy_a_load_says_how_much_it_could_carry() {
        let wj = 100.0;
        let max = state_at(&FILM, &PINS, wj, MAX_ECCENTRICITY).load;
        match split(&FILM, &PINS, wj, Operating::Load(1.01 * max)) {
            Err(LoadError::TooHeavy { max_load }) => assert!((max_load / max - 1.0).abs() < 1e-12),
            other => panic!("{other:?}"),
        }
        let s = split(&FILM, &PINS, wj, Operating::Eccentricity(MAX_ECCENTRICITY)).unwrap();
        assert!(s.fixed.eccentricity > MAX_ECCENTRICITY && s.fixed.eccentricity < 0.9995);
    }
}
