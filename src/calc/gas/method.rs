//! How a gas film is solved: a fidelity level's mesh, or an explicit one, and the Richardson
//! pair (the mesh and every other node of it) that gives the error estimate.

use crate::calc::FieldError;
use crate::fidelity::{FidelityRequest, Level};

/// Cells along the sliding direction (x) and across the half-width (y; 0 for an infinitely
/// wide film).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Mesh {
    pub along: usize,
    pub across: usize,
}

/// The numerical method of a request.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Method {
    pub level: Level,
    pub mesh: Mesh,
    /// Also solved on the half mesh (every other node), extrapolated, and the difference's
    /// third reported as the error estimate.
    pub richardson: bool,
}

impl Method {
    /// An explicit mesh: extrapolated when it halves exactly (even counts, at least 8 along).
    pub fn mesh(mesh: Mesh) -> Method {
        Method {
            level: Level::Standard,
            mesh,
            richardson: mesh.along.is_multiple_of(2)
                && mesh.across.is_multiple_of(2)
                && mesh.along >= 8,
        }
    }

    /// The grid the report shows.
    pub fn grid(&self) -> Vec<u32> {
        vec![self.mesh.along as u32, self.mesh.across as u32]
    }
}

/// The method of a request's `fidelity`: `levels` gives each level's mesh; `{"grid": [along,
/// across]}` an explicit one within `along` and `across` (cells). The Newton solve converges to
/// round-off: a `tolerance` does not apply, and `closed_form` is not offered.
pub fn parse(
    fidelity: FidelityRequest,
    levels: impl Fn(Level) -> Mesh,
    along: (u32, u32),
    across: (u32, u32),
    errors: &mut Vec<FieldError>,
) -> Method {
    let standard = Method {
        level: Level::Standard,
        mesh: levels(Level::Standard),
        richardson: true,
    };
    match fidelity {
        FidelityRequest::Level(Level::ClosedForm) => {
            errors.push(FieldError::new(
                "/fidelity",
                "a gas film has no closed form at a general bearing number: give fast, standard, high or a grid",
            ));
            standard
        }
        FidelityRequest::Level(level) => Method {
            level,
            mesh: levels(level),
            richardson: true,
        },
        FidelityRequest::Custom(custom) => {
            if custom.tolerance.is_some() {
                errors.push(FieldError::new(
                    "/fidelity/tolerance",
                    "the gas film is solved by Newton to round-off: give a level or a grid",
                ));
            }
            match custom.grid {
                Some([a, c])
                    if (along.0..=along.1).contains(&a) && (across.0..=across.1).contains(&c) =>
                {
                    Method::mesh(Mesh {
                        along: a as usize,
                        across: c as usize,
                    })
                }
                Some(_) => {
                    errors.push(FieldError::new(
                        "/fidelity/grid",
                        format!(
                            "must be [cells along the sliding direction {}…{}, cells across the half-width {}…{}]",
                            along.0, along.1, across.0, across.1
                        ),
                    ));
                    standard
                }
                None => standard,
            }
        }
    }
}
