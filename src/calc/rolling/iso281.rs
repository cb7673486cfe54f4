//! ISO 281 and the texts' fatigue-life formulas (the model of `/v1/rolling-bearings/life`,
//! whose wire is `life.rs`; the analysis reaches it through that file's `life`): L10 = (C/P)^p,
//! the reliability factor a1, the rated viscosity ν1, a_ISO and the modified life. The sources
//! and checks are in `life.rs`'s module documentation.

use crate::calc::Notes;

/// κ range of the a_ISO formulas (ISO 281:2007 §9.3.3.4); outside, κ is clipped with a warning.
const KAPPA_RANGE: (f64, f64) = (0.1, 4.0);
/// a_ISO is capped here (ISO 281:2007; Khonsari & Booser RB-7: "do not use > 50").
pub(super) const A_ISO_CAP: f64 = 50.0;
/// Reliability range of ISO 281:2007's a1 table, percent.
const ISO_RELIABILITY_RANGE: (f64, f64) = (90.0, 99.95);
/// ν1's speed break, rpm.
const NU1_BREAK_RPM: f64 = 1000.0;

/// Ball or roller bearing: the life exponent and the a_ISO constants.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// Radial ball bearing: point contact, p = 3.
    Ball,
    /// Radial roller bearing: line contact, p = 10/3.
    Roller,
}

impl Kind {
    /// The life exponent p of L10 = (C/P)^p.
    pub fn life_exponent(self) -> f64 {
        match self {
            Kind::Ball => 3.0,
            Kind::Roller => 10.0 / 3.0,
        }
    }
}

/// Which published reliability factors a1 to use.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FactorSet {
    /// The texts' Weibull relation a1 = [ln(100/R)/ln(100/90)]^{1/e}.
    Weibull,
    /// ISO 281:2007: a1 = 0.95 [ln(100/R)/ln(100/90)]^{2/3} + 0.05.
    Iso281_2007,
}

/// Where κ comes from.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum KappaSource {
    Given(f64),
    /// κ = ν/ν1 with ν1 from the speed and the pitch diameter.
    Viscosity {
        viscosity_mm2_s: f64,
        pitch_diameter_mm: f64,
    },
}

/// What the modified life needs: κ's source, e_C and C_u.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Lubrication {
    pub(super) kappa: KappaSource,
    pub(super) contamination: f64,
    pub(super) fatigue_load_limit_n: f64,
}

/// The validated case, in N, rpm, percent and mm.
#[derive(Debug, Clone, PartialEq)]
pub struct LifeCase {
    pub(super) kind: Kind,
    pub(super) rating_n: f64,
    pub(super) load_n: f64,
    /// Set when P = X F_r + Y F_a fell below F_r and was raised to it: (X F_r + Y F_a, F_r).
    pub(super) raised_from_n: Option<f64>,
    pub(super) speed_rpm: f64,
    pub(super) duty_steps: usize,
    pub(super) reliability_percent: f64,
    pub(super) factor_set: FactorSet,
    pub(super) weibull_slope: f64,
    pub(super) pitch_diameter_mm: Option<f64>,
    pub(super) lubrication: Option<Lubrication>,
}

/// The lives of a case and what the model says beside them.
#[derive(Debug, Clone, PartialEq)]
pub struct LifeRating {
    /// p.
    pub life_exponent: f64,
    /// C/P.
    pub load_ratio: f64,
    /// L10, million revolutions.
    pub l10_million_revolutions: f64,
    /// L10h, hours.
    pub l10_hours: f64,
    /// a1.
    pub a1: f64,
    /// a1 L10, million revolutions.
    pub life_at_reliability_million_revolutions: f64,
    /// a1 L10h, hours.
    pub life_at_reliability_hours: f64,
    /// ν1, mm²/s, when the pitch diameter is known.
    pub rated_viscosity_mm2_s: Option<f64>,
    /// The modified life, when the lubrication is known.
    pub modified: Option<Modified>,
    /// The warnings, in the order they were found.
    pub notes: Notes,
}

/// ISO 281's modified life.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Modified {
    /// κ before clipping.
    pub kappa: f64,
    /// κ clipped to [0.1, 4].
    pub kappa_used: f64,
    /// e_C C_u / P.
    pub contamination_load_ratio: f64,
    pub a_iso: f64,
    pub modified_life_million_revolutions: f64,
    pub modified_life_hours: f64,
}

/// Reliability factor a1 at `reliability_percent` (see the module documentation).
pub(super) fn reliability_factor(set: FactorSet, reliability_percent: f64, slope: f64) -> f64 {
    let w = (100.0 / reliability_percent).ln() / (100.0_f64 / 90.0).ln();
    match set {
        FactorSet::Weibull => w.powf(1.0 / slope),
        FactorSet::Iso281_2007 => 0.95 * w.powf(2.0 / 3.0) + 0.05,
    }
}

/// Rated viscosity ν1, mm²/s, at `speed_rpm` for a pitch diameter in mm.
pub(super) fn rated_viscosity(speed_rpm: f64, pitch_diameter_mm: f64) -> f64 {
    if speed_rpm < NU1_BREAK_RPM {
        45_000.0 * speed_rpm.powf(-0.83) / pitch_diameter_mm.sqrt()
    } else {
        4_500.0 / speed_rpm.sqrt() / pitch_diameter_mm.sqrt()
    }
}

/// ISO 281:2007's a_ISO for κ already within [0.1, 4] and x = e_C C_u/P ≥ 0, capped at 50.
pub(super) fn a_iso(kind: Kind, kappa: f64, x: f64) -> f64 {
    let (x1, m, q, r) = match kind {
        Kind::Ball => (2.5671, 0.83, 1.0 / 3.0, 9.3),
        Kind::Roller => (1.5859, 1.0, 0.4, 9.185),
    };
    let (x2, e) = match (kind, kappa) {
        (Kind::Ball, k) if k < 0.4 => (2.2649, 0.054381),
        (Kind::Roller, k) if k < 0.4 => (1.3993, 0.054381),
        (Kind::Ball, k) if k < 1.0 => (1.9987, 0.19087),
        (Kind::Roller, k) if k < 1.0 => (1.2348, 0.19087),
        (Kind::Ball, _) => (1.9987, 0.071739),
        (Kind::Roller, _) => (1.2348, 0.071739),
    };
    // At κ = 0.1 the lubrication term x₁ − x₂/κ^e is 0 to the constants' rounding (8·10⁻⁵ for
    // balls, −1·10⁻⁴ for rollers): it is taken as ≥ 0, so a_ISO = 0.1 there for any x.
    let lubrication = (x1 - x2 / kappa.powf(e)).max(0.0);
    let bracket = 1.0 - lubrication.powf(m) * x.powf(q);
    if bracket <= 0.0 {
        return A_ISO_CAP;
    }
    (0.1 * bracket.powf(-r)).min(A_ISO_CAP)
}

/// The whole calculation; its warnings are in the rating's notes.
pub fn life(case: &LifeCase) -> LifeRating {
    let mut notes = Notes::default();
    let p = case.kind.life_exponent();
    let ratio = case.rating_n / case.load_n;
    let l10 = ratio.powf(p);
    let hours_per_million = 1e6 / (60.0 * case.speed_rpm);
    let l10_hours = l10 * hours_per_million;
    if ratio < 1.0 {
        notes.warn(
            "load_above_rating",
            format!(
                "P = {:.6} N exceeds the dynamic load rating C = {} N: L10 < 10⁶ revolutions, beyond the range the rating life is meant for (and likely beyond the static capacity)",
                case.load_n, case.rating_n
            ),
        );
    }
    if let Some(raw) = case.raised_from_n {
        notes.warn(
            "equivalent_load_raised_to_radial",
            format!(
                "X F_r + Y F_a = {raw:.6} N is below the radial load; P = F_r = {:.6} N is used (Khonsari & Booser RB-4)",
                case.load_n
            ),
        );
    }
    if case.duty_steps > 0 && case.lubrication.is_some() {
        notes.warn(
            "duty_cycle_mean_speed",
            format!(
                "the rated viscosity and a_ISO use the duty cycle's time-mean speed {:.6} rpm and mean load {:.6} N",
                case.speed_rpm, case.load_n
            ),
        );
    }
    let r = case.reliability_percent;
    if r < ISO_RELIABILITY_RANGE.0 {
        notes.warn(
            "reliability_below_90",
            format!(
                "R = {r} % is below the rating's 90 %: a1 > 1 extrapolates the Weibull relation"
            ),
        );
    } else if case.factor_set == FactorSet::Iso281_2007 && r > ISO_RELIABILITY_RANGE.1 {
        notes.warn(
            "reliability_beyond_iso_281",
            format!(
                "R = {r} % exceeds ISO 281:2007's a1 table (up to {} %): the formula is extrapolated",
                ISO_RELIABILITY_RANGE.1
            ),
        );
    }
    let a1 = reliability_factor(case.factor_set, r, case.weibull_slope);
    let rated = case
        .pitch_diameter_mm
        .map(|dm| rated_viscosity(case.speed_rpm, dm));
    let mut out = LifeRating {
        life_exponent: p,
        load_ratio: ratio,
        l10_million_revolutions: l10,
        l10_hours,
        a1,
        life_at_reliability_million_revolutions: a1 * l10,
        life_at_reliability_hours: a1 * l10_hours,
        rated_viscosity_mm2_s: rated,
        modified: None,
        notes: Notes::default(),
    };
    let Some(lub) = case.lubrication else {
        out.notes = notes;
        return out;
    };
    let kappa = match lub.kappa {
        KappaSource::Given(k) => k,
        KappaSource::Viscosity {
            viscosity_mm2_s,
            pitch_diameter_mm,
        } => viscosity_mm2_s / rated_viscosity(case.speed_rpm, pitch_diameter_mm),
    };
    let kappa_used = kappa.clamp(KAPPA_RANGE.0, KAPPA_RANGE.1);
    if kappa_used != kappa {
        notes.warn(
            "kappa_clipped",
            format!(
                "κ = {kappa:.6} is outside ISO 281's range [{}, {}]: a_ISO uses κ = {kappa_used}{}",
                KAPPA_RANGE.0,
                KAPPA_RANGE.1,
                if kappa < KAPPA_RANGE.0 {
                    " (below 0.1 the film cannot separate the surfaces; the modified life is not reliable)"
                } else {
                    " (a thicker film does not lengthen the life further)"
                }
            ),
        );
    }
    let x = lub.contamination * lub.fatigue_load_limit_n / case.load_n;
    let a = a_iso(case.kind, kappa_used, x);
    if a >= A_ISO_CAP {
        notes.warn(
            "a_iso_capped",
            format!("a_ISO reaches its cap {A_ISO_CAP} (e_C C_u/P = {x:.6}, κ = {kappa_used:.4}): the load is near or below the fatigue load limit"),
        );
    }
    out.modified = Some(Modified {
        kappa,
        kappa_used,
        contamination_load_ratio: x,
        a_iso: a,
        modified_life_million_revolutions: a1 * a * l10,
        modified_life_hours: a1 * a * l10_hours,
    });
    out.notes = notes;
    out
}
