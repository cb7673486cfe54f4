//! Fidelity levels and the solver report every result carries (DESIGN.md §3).

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use crate::calc::range_schemas;

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

/// Why an iterative solve stopped. Only `converged` (or `direct`, where nothing iterates) comes
/// with a result; the others answer 422 (504 for `deadline`) with this report's numbers.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum StopReason {
    /// A closed form or a direct evaluation: nothing iterated.
    Direct,
    /// The convergence criterion of the method was met.
    Converged,
    /// The iteration cap was reached first.
    IterationCap,
    /// The request's deadline passed, or the client went away.
    Deadline,
    /// The iterate blew up (non-finite or growing residual).
    Diverged,
    /// The iteration could make no further progress (no descent, a step out of the domain).
    Stalled,
}

/// What one of the report's `iterations` is, so that rooms can be compared.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum IterationUnit {
    /// Nothing iterated (a closed form).
    None,
    /// Relaxation sweeps over a grid (Gauss–Seidel, SOR).
    Sweeps,
    /// Newton steps (each a linear solve, with its line search).
    NewtonSteps,
    /// Multigrid cycles on the finest grid.
    MultigridCycles,
    /// Steps of a bracketed root search (Brent: one evaluation each).
    RootSearchSteps,
    /// Evaluations of the inner model (for example whole film solves of an outer search).
    Evaluations,
    /// Attempted steps of a time integrator (accepted and rejected).
    TimeSteps,
}

// Filled by the solver driver (`numerics::driver`); a room adds only the fidelity, the grid and
// the error estimate.
/// What the solver did: the response's `solver` block.
#[derive(Debug, Clone, PartialEq, Serialize, ToSchema)]
pub struct SolverReport {
    /// The scheme, e.g. `closed_form` or `finite_volume_active_set`.
    #[schema(example = "closed_form")]
    pub method: String,
    pub fidelity: Level,
    /// Grid size where the method has one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub grid: Option<Vec<u32>>,
    /// Iterations of the outer loop (0 for a closed form), in `iterations_unit`.
    pub iterations: u32,
    /// What one iteration is.
    pub iterations_unit: IterationUnit,
    /// Evaluations of the inner model, where they differ from the iterations (trial points of
    /// a line search, film solves of an outer search).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub evaluations: Option<u32>,
    /// Why the solve stopped.
    pub stop_reason: StopReason,
    /// The method's convergence measure at the end, where the method iterates; what it
    /// measures depends on `method` (docs/solver-report.md has the table). Mostly dimensionless
    /// and relative — a scaled equation residual, a load or force imbalance over the load, a
    /// relative change or a relative error estimate — and within the method's tolerance when
    /// `stop_reason` is `converged`. It says how well the iterate solves the discrete
    /// equations, not how accurate the result is: that is `error_estimate`. The point-contact
    /// EHL multigrid reports its Reynolds defect over the central film, which is not its
    /// convergence test and may be of order 1 on a converged fine grid.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub residual: Option<f64>,
    /// Estimated relative error of the headline result, where known.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error_estimate: Option<f64>,
    /// Numerical film solves the whole request took (every search, the thermal balance and the
    /// stability threshold included; a linear response about a solved film counts as one).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub film_solves: Option<u32>,
    /// A time integrator's step control, where the method is one.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub time_integration: Option<Box<TimeIntegration>>,
    /// Wall time of the calculation in milliseconds (parsing and serialisation excluded).
    pub elapsed_ms: f64,
}

/// How a time integrator controlled its steps (its `iterations` are the attempted steps).
#[derive(Debug, Clone, PartialEq, Serialize, ToSchema)]
pub struct TimeIntegration {
    /// Steps rejected (the local error estimate above the tolerance, a stage outside the
    /// model's domain, or Newton not converging); they are among the `iterations`.
    pub rejected_steps: u32,
    /// The relative tolerance every accepted step's local error estimate met.
    pub relative_tolerance: f64,
}

impl SolverReport {
    /// The report of a closed-form evaluation: no grid, no iterations.
    pub fn closed_form(method: &str) -> Self {
        SolverReport {
            method: method.to_owned(),
            fidelity: Level::ClosedForm,
            grid: None,
            iterations: 0,
            iterations_unit: IterationUnit::None,
            evaluations: None,
            stop_reason: StopReason::Direct,
            residual: None,
            error_estimate: None,
            film_solves: None,
            time_integration: None,
            elapsed_ms: 0.0,
        }
    }

    /// A closed form inverted by a search (an equilibrium from the closed form's load): the
    /// closed form evaluated `evaluations` times until the search converged.
    pub fn closed_form_search(method: &str, evaluations: u32) -> Self {
        SolverReport {
            iterations: evaluations,
            iterations_unit: IterationUnit::Evaluations,
            stop_reason: StopReason::Converged,
            ..SolverReport::closed_form(method)
        }
    }

    /// The same report with the request's count of film solves.
    #[must_use]
    pub fn with_film_solves(mut self, solves: u32) -> Self {
        self.film_solves = Some(solves);
        self
    }

    /// The same report under the room's name for its method.
    #[must_use]
    pub fn named(mut self, method: impl Into<String>) -> Self {
        self.method = method.into();
        self
    }

    /// The same report with the room's convergence measure as the residual (where the
    /// driver's residual is an inner one, say a root bracket's width).
    #[must_use]
    pub fn with_residual(mut self, residual: f64) -> Self {
        self.residual = residual.is_finite().then_some(residual);
        self
    }

    /// The same report counting the work of every run of a nested solve (each grid of a
    /// refinement, each Newton run of an outer iteration), not only the last run's.
    #[must_use]
    pub fn counting(mut self, iterations: u32, evaluations: u32) -> Self {
        self.iterations = iterations;
        self.evaluations = (evaluations > 0).then_some(evaluations);
        self
    }

    /// The same report at fidelity `level`.
    #[must_use]
    pub fn at(mut self, level: Level) -> Self {
        self.fidelity = level;
        self
    }

    /// The same report on `grid`.
    #[must_use]
    pub fn on_grid(mut self, grid: Vec<u32>) -> Self {
        self.grid = Some(grid);
        self
    }

    /// The same report with an estimated relative error.
    #[must_use]
    pub fn with_error_estimate(mut self, error: Option<f64>) -> Self {
        self.error_estimate = error;
        self
    }
}

/// What a request asks for: a level, or an explicit grid and/or tolerance (the level is then
/// `standard` with those settings).
#[derive(Debug, Clone, Copy, PartialEq, Deserialize, ToSchema)]
#[serde(
    untagged,
    expecting = "must be a level — \"closed_form\", \"fast\", \"standard\" or \"high\" (those the calculation offers) — or an object {\"grid\": [cells, cells], \"tolerance\": number}"
)]
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
    /// Cells [along the sliding direction, across]: see [`range_schemas::grid`].
    #[schema(schema_with = range_schemas::grid)]
    pub grid: Option<[u32; 2]>,
    /// Relative change per sweep at which the iteration stops (1e-14 … 1e-3).
    #[schema(minimum = 1e-14, maximum = 1e-3, example = 1e-8)]
    pub tolerance: Option<f64>,
}

impl Default for FidelityRequest {
    fn default() -> Self {
        FidelityRequest::Level(Level::Standard)
    }
}

#[cfg(test)]
mod tests {
    use std::path::{Path, PathBuf};

    /// The method name of every `Driver::new(` in the non-test code of `text`: a string literal,
    /// or a constant of the same file holding one.
    fn driver_methods(text: &str, file: &Path) -> Vec<String> {
        let code = text.split("#[cfg(test)]").next().unwrap_or(text);
        let mut names = Vec::new();
        for (at, _) in code.match_indices("Driver::new(") {
            let rest = code[at + "Driver::new(".len()..].trim_start();
            let name = if let Some(literal) = rest.strip_prefix('"') {
                literal[..literal.find('"').unwrap()].to_owned()
            } else {
                let ident: String = rest
                    .chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect();
                let constant = format!("const {ident}: &str = \"");
                let Some(start) = code.find(&constant) else {
                    panic!(
                        "{}: Driver::new({ident}, …) is neither a literal nor a &str constant of the file",
                        file.display()
                    );
                };
                let value = &code[start + constant.len()..];
                value[..value.find('"').unwrap()].to_owned()
            };
            names.push(name);
        }
        names
    }

    fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
        for entry in std::fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                rust_files(&path, out);
            } else if path.extension().is_some_and(|e| e == "rs") {
                out.push(path);
            }
        }
    }

    /// docs/solver-report.md names every method the solver driver runs, so that its table of
    /// what `residual` means cannot fall behind the code.
    #[test]
    fn the_solver_report_doc_names_every_driver_method() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        let doc = std::fs::read_to_string(root.join("docs/solver-report.md")).unwrap();
        let mut files = Vec::new();
        rust_files(&root.join("src"), &mut files);
        let mut methods = Vec::new();
        for file in &files {
            let text = std::fs::read_to_string(file).unwrap();
            methods.extend(driver_methods(&text, file));
        }
        methods.sort();
        methods.dedup();
        assert!(methods.len() >= 20, "found only {methods:?}");
        let missing: Vec<&String> = methods
            .iter()
            .filter(|m| !doc.contains(&format!("`{m}`")))
            .collect();
        assert!(
            missing.is_empty(),
            "docs/solver-report.md does not name {missing:?}"
        );
    }
}
