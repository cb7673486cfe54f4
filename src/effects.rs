//! Optional physical effects: each is `auto`, `on` or `off` in the request, and every response
//! reports, for each effect its calculation knows, whether it was applied and why (DESIGN.md §4).

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

/// How the request wants an effect treated.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum Mode {
    /// Decide from the texts' criterion (the default).
    #[default]
    Auto,
    /// Always apply (a 422 if the request lacks what the effect needs).
    On,
    /// Never apply; costs no computation.
    Off,
}

/// The number an `auto` decision was made on.
#[derive(Debug, Clone, PartialEq, Serialize, ToSchema)]
pub struct Criterion {
    /// What the number is, with its unit in the name.
    #[schema(example = "viscosity_rise_ratio")]
    pub name: &'static str,
    /// Its value for this request.
    pub value: f64,
    /// The value above which `auto` applies the effect.
    pub threshold: f64,
}

/// Whether an effect was applied to this request, and why.
#[derive(Debug, Clone, PartialEq, Serialize, ToSchema)]
pub struct Decision {
    /// Whether the effect is part of this result.
    pub applied: bool,
    pub mode: Mode,
    /// One sentence: why it was or was not applied.
    pub reason: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub criterion: Option<Criterion>,
    /// Which model was applied, where the effect offers several (cavitation: `reynolds` or
    /// `jfo`).
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = "reynolds")]
    pub model: Option<&'static str>,
}

impl Decision {
    /// Decide an effect from its mode and, for `auto`, a criterion (applied when value > threshold).
    /// `on` and `off` still report the criterion so the user sees what `auto` would have done.
    pub fn decide(mode: Mode, criterion: Criterion, what: &str) -> Self {
        let exceeds = criterion.value > criterion.threshold;
        let (applied, reason) = match mode {
            Mode::On => (true, format!("{what}: requested on")),
            Mode::Off => (false, format!("{what}: requested off")),
            Mode::Auto if exceeds => (
                true,
                format!(
                    "{what}: {} = {:.4e} exceeds {:.4e}",
                    criterion.name, criterion.value, criterion.threshold
                ),
            ),
            Mode::Auto => (
                false,
                format!(
                    "{what}: {} = {:.4e} does not exceed {:.4e}; negligible",
                    criterion.name, criterion.value, criterion.threshold
                ),
            ),
        };
        Decision {
            applied,
            mode,
            reason,
            criterion: Some(criterion),
            model: None,
        }
    }

    /// The effect cannot apply to this request (for example a law the lubricant lacks).
    pub fn not_applicable(mode: Mode, reason: impl Into<String>) -> Self {
        Decision {
            applied: false,
            mode,
            reason: reason.into(),
            criterion: None,
            model: None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn crit(value: f64) -> Criterion {
        Criterion {
            name: "x",
            value,
            threshold: 1.0,
        }
    }

    #[test]
    fn auto_applies_only_above_threshold() {
        assert!(Decision::decide(Mode::Auto, crit(1.5), "e").applied);
        assert!(!Decision::decide(Mode::Auto, crit(0.5), "e").applied);
        assert!(!Decision::decide(Mode::Auto, crit(1.0), "e").applied);
    }

    #[test]
    fn on_and_off_override_the_criterion() {
        assert!(Decision::decide(Mode::On, crit(0.0), "e").applied);
        assert!(!Decision::decide(Mode::Off, crit(9.0), "e").applied);
    }
}
