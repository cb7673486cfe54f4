//! What a calculation carries while it runs: its deadline, the effect decisions, the solver
//! report and the warnings; and the ways it can fail.

use std::collections::BTreeMap;
use std::sync::atomic::AtomicBool;
use std::sync::Arc;
use std::time::Instant;

use serde::Serialize;
use utoipa::ToSchema;

use crate::effects::Decision;
use crate::fidelity::{SolverReport, StopReason};
use crate::numerics::driver::{Budget, Stopped};
use crate::numerics::roots::RootError;

/// A note on a result that is valid but deserves the user's attention (a model used outside
/// the range its source gives, an assumed property).
#[derive(Debug, Clone, PartialEq, Serialize, ToSchema)]
pub struct Warning {
    /// Stable machine-readable code, e.g. `barus_above_70_mpa`.
    #[schema(example = "barus_above_70_mpa")]
    pub code: &'static str,
    /// What to look at, with the numbers.
    pub message: String,
}

/// What a model says beside its numbers, in the order it said it: the decision on each effect
/// and the warnings. Models hold no [`Context`]; they return their notes as data and the wire
/// records them ([`Context::record`]), so a composed room can pass them on, map them or keep
/// them apart.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Notes {
    pub decisions: Vec<(&'static str, Decision)>,
    pub warnings: Vec<Warning>,
}

impl Notes {
    pub fn decide(&mut self, effect: &'static str, decision: Decision) {
        self.decisions.push((effect, decision));
    }

    pub fn warn(&mut self, code: &'static str, message: impl Into<String>) {
        self.warnings.push(Warning {
            code,
            message: message.into(),
        });
    }
}

/// Why a calculation did not produce a result. Each variant is, by construction, either the
/// user's fault (4xx) or ours (5xx).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CalcError {
    /// The input is valid field by field but describes an impossible or out-of-model case (422).
    #[error("{message}")]
    Impossible { pointer: String, message: String },
    /// An iteration hit its cap without converging (422, with its residual).
    #[error("{method} did not converge in {iterations} iterations (residual {residual:e})")]
    NotConverged {
        method: &'static str,
        iterations: u32,
        residual: f64,
    },
    /// An iterative solve stopped without converging (422, with its report: stop reason,
    /// iterations, residual). A deadline stop is [`CalcError::DeadlineExceeded`] instead.
    #[error("{} did not converge in {} iterations (residual {:e})", .0.method, .0.iterations, .0.residual.unwrap_or(f64::NAN))]
    Stopped(Box<SolverReport>),
    /// The deadline passed or the request was cancelled (504).
    #[error("deadline exceeded")]
    DeadlineExceeded,
    /// A bug: something that must not happen did (500; the detail is logged, not sent).
    #[error("internal error: {0}")]
    Internal(String),
}

impl CalcError {
    pub fn impossible(pointer: &str, message: impl Into<String>) -> Self {
        CalcError::Impossible {
            pointer: pointer.to_owned(),
            message: message.into(),
        }
    }

    /// Ok when every one of `numbers` (a room's list of its result's numbers) is finite;
    /// otherwise a 422 saying that the request's magnitudes take the result out of the
    /// floating-point range. For results with optional numbers, which
    /// [`CalcError::finite_or_out_of_range`] would read as not finite.
    pub fn unless_finite(numbers: &[f64]) -> Result<(), CalcError> {
        if numbers.iter().all(|v| v.is_finite()) {
            Ok(())
        } else {
            Err(CalcError::impossible(
                "",
                "this combination of inputs takes the result outside the floating-point range",
            ))
        }
    }

    /// `output` unchanged when every number in it is finite; otherwise a 422 saying that the
    /// request's magnitudes take the result out of the floating-point range (`what` names the
    /// inputs to look at). For closed forms whose valid inputs span more decades than an f64
    /// result can: the limit is the arithmetic's, not the model's.
    pub fn finite_or_out_of_range<T: serde::Serialize>(
        output: T,
        what: &str,
    ) -> Result<T, CalcError> {
        // serde_json writes a non-finite number as null, and outputs hold no other null.
        fn has_null(v: &serde_json::Value) -> bool {
            match v {
                serde_json::Value::Null => true,
                serde_json::Value::Array(a) => a.iter().any(has_null),
                serde_json::Value::Object(o) => o.values().any(has_null),
                _ => false,
            }
        }
        match serde_json::to_value(&output) {
            Ok(v) if !has_null(&v) => Ok(output),
            _ => Err(CalcError::impossible(
                "",
                format!("these inputs take the result outside the floating-point range (a value overflows or underflows): check the magnitudes of {what}"),
            )),
        }
    }

    /// A bracketed root search that found no root, as the answer to the request: a capped
    /// search is a 422 with its last bracket width as the residual; a bracket without a sign
    /// change or a non-finite function value is a bug of the caller (500), since rooms bracket
    /// their roots by construction. A room for which a missing sign change means something
    /// physical (a load the film cannot carry) matches that case itself before calling this.
    pub fn from_root(method: &'static str, error: RootError) -> Self {
        match error {
            RootError::NotConverged { iterations, width } => CalcError::NotConverged {
                method,
                iterations,
                residual: width,
            },
            other => CalcError::Internal(format!("{method}: {other:?}")),
        }
    }
}

impl From<Stopped> for CalcError {
    /// The one mapping of a driver stop: the deadline is a 504, every other stop a 422 that
    /// carries the report.
    fn from(stopped: Stopped) -> Self {
        match stopped.reason() {
            StopReason::Deadline => CalcError::DeadlineExceeded,
            _ => CalcError::Stopped(Box::new(stopped.report)),
        }
    }
}

/// The running calculation's surroundings.
#[derive(Debug)]
pub struct Context {
    budget: Budget,
    pub(crate) effects: BTreeMap<&'static str, Decision>,
    pub(crate) warnings: Vec<Warning>,
    pub(crate) report: Option<SolverReport>,
}

impl Context {
    /// A context that stops at `deadline` or when `cancelled` is set by the caller.
    pub fn new(deadline: Instant, cancelled: Arc<AtomicBool>) -> Self {
        Context {
            budget: Budget::new(deadline, cancelled),
            effects: BTreeMap::new(),
            warnings: Vec::new(),
            report: None,
        }
    }

    /// Long loops call this every few iterations so a late or cancelled request stops computing.
    pub fn check_deadline(&self) -> Result<(), CalcError> {
        if self.budget.alive() {
            Ok(())
        } else {
            Err(CalcError::DeadlineExceeded)
        }
    }

    /// The request's deadline carrier, for numerics and models: the one handle every loop
    /// polls (through the solver driver).
    pub fn budget(&self) -> Budget {
        self.budget.clone()
    }

    /// A context for one step of a composed calculation: the same deadline, its own decisions,
    /// warnings and report.
    pub fn child(&self) -> Context {
        Context {
            budget: self.budget.clone(),
            effects: BTreeMap::new(),
            warnings: Vec::new(),
            report: None,
        }
    }

    /// Record the decision on one effect.
    pub fn decide(&mut self, effect: &'static str, decision: Decision) {
        self.effects.insert(effect, decision);
    }

    /// Record a model's notes: its warnings, then its decisions, in their order.
    pub fn record(&mut self, notes: &Notes) {
        for w in &notes.warnings {
            self.warn(w.code, w.message.clone());
        }
        for (effect, decision) in &notes.decisions {
            self.decide(effect, decision.clone());
        }
    }

    pub fn warn(&mut self, code: &'static str, message: impl Into<String>) {
        if !self.warnings.iter().any(|w| w.code == code) {
            self.warnings.push(Warning {
                code,
                message: message.into(),
            });
        }
    }

    /// Set the solver report (its `elapsed_ms` is filled in by the caller).
    pub fn report(&mut self, report: SolverReport) {
        self.report = Some(report);
    }
}
