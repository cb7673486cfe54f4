//! How a gas film is solved: a fidelity level's mesh, or an explicit one, and the Richardson
//! pair (the mesh and every other node of it) that gives the error estimate.

use crate::calc::quantity::Positive;
use crate::calc::FieldError;
use crate::fidelity::{FidelityRequest, Level};

/// Largest bearing number accepted: the solver is validated to Λ = 1000 (docs/accuracy.md) and
/// stays stable beyond; past 10⁴ the film is at its Λ → ∞ limit (P H = const) to 0.1 % anyway.
pub const MAX_BEARING_NUMBER: f64 = 1.0e4;
/// Smallest bearing number accepted: below it the film's pressure rises less than a millionth
/// of ambient (W̄ ∝ Λ as Λ → 0), a film that carries nothing worth computing.
pub const MIN_BEARING_NUMBER: f64 = 1.0e-6;

/// The 422 of a bearing number Λ outside [`MIN_BEARING_NUMBER`, `MAX_BEARING_NUMBER`], on the
/// speed field at `pointer`; `definition` is the film's Λ formula and `limit` names its
/// Λ → ∞ limit.
pub fn check_bearing_number(
    lambda: f64,
    pointer: &str,
    definition: &str,
    limit: &str,
) -> Result<(), FieldError> {
    if lambda.is_nan() || lambda > MAX_BEARING_NUMBER {
        return Err(FieldError::new(
            pointer,
            format!("the bearing number Λ = {definition} = {lambda:.4e} exceeds {MAX_BEARING_NUMBER:e}: {limit}"),
        ));
    }
    if lambda < MIN_BEARING_NUMBER {
        return Err(FieldError::new(
            pointer,
            format!("the bearing number Λ = {definition} = {lambda:.4e} is below {MIN_BEARING_NUMBER:e}: the film's pressure rise is below a millionth of ambient and it carries next to nothing (raise the speed or thin the film)"),
        ));
    }
    Ok(())
}

/// What a gas journal request fixes: the eccentricity ratio, or the load, N.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Given {
    Eccentricity(f64),
    Load(f64),
}

/// A journal request's one of `eccentricity_ratio` and `load_n`: ε within [0, 1) (`touching`
/// says what ε ≥ 1 means) and within `solved` (`why` says what bounds it), or the load.
pub fn given(
    eccentricity: Option<f64>,
    load: Option<Positive>,
    solved: (f64, f64),
    touching: &str,
    why: &str,
    errors: &mut Vec<FieldError>,
) -> Given {
    let (lo, hi) = solved;
    let refuse = |errors: &mut Vec<FieldError>, pointer: &str, message: String| {
        errors.push(FieldError::new(pointer, message));
        Given::Eccentricity(0.5)
    };
    match (eccentricity, load) {
        (Some(e), None) if !e.is_finite() || !(0.0..1.0).contains(&e) => refuse(
            errors,
            "/eccentricity_ratio",
            format!("must be within [0, 1): {touching}, got {e}"),
        ),
        (Some(e), None) if !(lo..=hi).contains(&e) => refuse(
            errors,
            "/eccentricity_ratio",
            format!("must be within [{lo}, {hi}] ({why}), got {e}"),
        ),
        (Some(e), None) => Given::Eccentricity(e),
        (None, Some(w)) => Given::Load(w.get()),
        _ => refuse(
            errors,
            "/load_n",
            "give exactly one of eccentricity_ratio and load_n".into(),
        ),
    }
}

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
