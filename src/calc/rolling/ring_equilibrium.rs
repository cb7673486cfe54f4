//! The quasi-static equilibrium of a bearing's rings, as numbers: the one-dimensional load
//! balance that the ball bearing's pure radial or pure axial case and the roller bearing's
//! radial case solve.

use crate::calc::{CalcError, Context};
use crate::numerics::roots::{brent, grow_bracket, Root, RootError, Stopping};

/// Brent iterations allowed in the one-dimensional cases.
pub(super) const MAX_BRENT_ITERATIONS: u32 = 200;

/// The one-dimensional load balance: `force` is negative (or zero) at 0 and turns positive as the
/// ring is pushed in; `hi` is doubled (at most 200 times) until it does, then Brent's method
/// finds the root. `method` names the solve in a not-converged answer.
pub(super) fn load_balance_root(
    mut force: impl FnMut(f64) -> f64,
    hi: f64,
    method: &'static str,
    ctx: &Context,
) -> Result<Root, CalcError> {
    let hi = grow_bracket(&mut force, hi)
        .map_err(|_| CalcError::Internal(format!("{method}: no bracket")))?;
    ctx.check_deadline()?;
    let stop = Stopping {
        x_tolerance: 0.0,
        max_iterations: MAX_BRENT_ITERATIONS,
    };
    brent(force, 0.0, hi, stop).map_err(|e| match e {
        RootError::NotConverged { iterations, width } => CalcError::NotConverged {
            method,
            iterations,
            residual: width,
        },
        other => CalcError::Internal(format!("{method} bracket: {other:?}")),
    })
}
