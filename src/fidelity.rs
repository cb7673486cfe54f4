//! Fidelity levels and the solver report every result carries (DESIGN.md §3).

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

/// A fidelity level a calculation offers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum Level {
    /// An analytic or approximate closed form.
    ClosedForm,
    Fast,
    Standard,
    High,
}

/// What the solver did: the response's `solver` block.
#[derive(Debug, Clone, PartialEq, Serialize, ToSchema)]
pub struct SolverReport {
    /// The scheme, e.g. `closed_form` or `finite_volume_psor`.
    #[schema(example = "closed_form")]
    pub method: String,
    pub fidelity: Level,
    /// Grid size where the method has one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub grid: Option<Vec<u32>>,
    /// Iterations of the outer loop (0 for a closed form).
    pub iterations: u32,
    /// Final residual, where the method iterates.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub residual: Option<f64>,
    /// Estimated relative error of the headline result, where known.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error_estimate: Option<f64>,
    /// Wall time of the calculation in milliseconds (parsing and serialisation excluded).
    pub elapsed_ms: f64,
}

impl SolverReport {
    /// The report of a closed-form evaluation: no grid, no iterations.
    pub fn closed_form(method: &str) -> Self {
        SolverReport {
            method: method.to_owned(),
            fidelity: Level::ClosedForm,
            grid: None,
            iterations: 0,
            residual: None,
            error_estimate: None,
            elapsed_ms: 0.0,
        }
    }
}

/// What a request asks for: a level, or an explicit grid and/or tolerance (the level is then
/// `standard` with those settings).
#[derive(Debug, Clone, Copy, PartialEq, Deserialize, ToSchema)]
#[serde(untagged)]
pub enum FidelityRequest {
    /// `closed_form`, `fast`, `standard` (the default) or `high`.
    Level(Level),
    /// An explicit grid `[circumferential cells, axial cells over the half-length]` and/or
    /// relative tolerance of the iterative solve.
    Custom(CustomFidelity),
}

/// Explicit numerical settings.
#[derive(Debug, Clone, Copy, PartialEq, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct CustomFidelity {
    /// Cells [along the sliding direction, across]; see the calculation for the ranges.
    #[schema(example = json!([96, 12]))]
    pub grid: Option<[u32; 2]>,
    /// Relative change per sweep at which the iteration stops (1e-14 … 1e-3).
    #[schema(example = 1e-8)]
    pub tolerance: Option<f64>,
}

impl Default for FidelityRequest {
    fn default() -> Self {
        FidelityRequest::Level(Level::Standard)
    }
}
