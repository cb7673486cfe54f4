//! `POST /v1/rolling-bearings/life`: basic rating life L10, the life at another reliability
//! (factor a1), and the modified life a1·a_ISO·L10 of ISO 281:2007 from the lubrication
//! (viscosity ratio κ) and contamination (e_C C_u/P).
//!
//! This file is the wire; the formulas below are computed by the model `iso281.rs`.
//!
//! - Basic rating life (Khonsari & Booser RB-3, eqs 13.5–13.7; Hamrock 21.3.6):
//!   L10 = (C/P)^p million revolutions, p = 3 for balls (point contact), 10/3 for rollers (line
//!   contact); L10h = 10⁶ L10/(60 n).
//! - Equivalent load (RB-4, eq 13.8): P = X F_r + Y F_a, raised to F_r when smaller (a radial
//!   bearing never sees less than its radial load; ISO 281's X = 1, Y = 0 branch).
//! - Duty cycle (RB-5, eqs 13.9–13.10; Ex 13.3): P_m = [Σ P_iᵖ u_i / Σ u_i]^{1/p} with u_i the
//!   revolutions of step i (n_i t_i when times are given); the mean speed for hours is
//!   Σ u_i / Σ t_i. Khonsari & Booser use the exponent 3 for rollers too; the life exponent p is
//!   used here, as ISO 281 does, which is identical for balls.
//! - Reliability factor a1: `weibull` (default) is the texts' Weibull relation
//!   L_S = L10 [ln(1/S)/ln(1/0.9)]^{1/e} (Hamrock 21.3.6) with slope e = 1.5 by default, which is
//!   Khonsari & Booser Table 13.9 (0.62, 0.53, 0.44, 0.33, 0.21 at 95…99 %); `iso_281_2007` is
//!   a1 = 0.95 [ln(100/R)/ln(100/90)]^{2/3} + 0.05 (0.64, 0.55, 0.47, 0.37, 0.25 at 95…99 %).
//! - a_ISO (ISO 281:2007, radial ball and radial roller bearings), with x = e_C C_u/P and κ
//!   clipped to [0.1, 4]: a_ISO = 0.1 [1 − (x₁ − x₂/κ^e)^m x^q]^{−r}, capped at 50, where
//!   ball: x₁ = 2.5671, m = 0.83, q = 1/3, r = 9.3; roller: x₁ = 1.5859, m = 1, q = 0.4,
//!   r = 9.185; and by κ band (x₂ ball / roller, e): 0.1 ≤ κ < 0.4: 2.2649 / 1.3993, 0.054381;
//!   0.4 ≤ κ < 1: 1.9987 / 1.2348, 0.19087; 1 ≤ κ ≤ 4: 1.9987 / 1.2348, 0.071739.
//! - Rated viscosity (ISO 281 / SKF): ν1 = 45000 n^{−0.83} d_m^{−0.5} for n < 1000 rpm,
//!   4500 n^{−0.5} d_m^{−0.5} for n ≥ 1000 rpm (mm²/s, n in rpm, d_m in mm); κ = ν/ν1.
//!
//! Outside the texts (spec khonsari-booser-ch9-17.md §5 marks them "verify"), checked as follows:
//! - a_ISO constants and ν1: a public Rust implementation of ISO 281:2007 eqs (27)–(36) found with
//!   the code search (`a_iso_ball`, `nu_1_mm2_s`: the same ball constants, the roller
//!   1.5859/1.3993/1.2348, 0.4, −9.185 and the same ν1 law), and a Python bearing model
//!   (`AIso`) with the same ball constants; the roller band coefficients are continuous across
//!   κ = 0.4 and 1 with the ball's band exponents (1.3993·0.4^−0.054381 = 1.2348·0.4^−0.19087 to
//!   5 digits), as the ball's are. They reproduce Khonsari & Booser's chart readings of Ex 13.4
//!   (a_SKF 20 and 5 → 18.6 and 4.84) and Fig 15.9 (ν1 8 → 7.61, 18 → 19.0).
//! - a1, texts' set: the SKF ConCentra catalogue table (easymanua.ls/skf/concentra, p. 9) and
//!   RBC Bearings' "Adjustment factors for rating life" page give 1, 0.62, 0.53, 0.44, 0.33,
//!   0.21 for 90…99 %, as Table 13.9 does.
//! - a1, ISO 281:2007 set: verify. No second public source was found by the search; the formula
//!   reproduces the values the spec quotes for ISO 281:2007 to the two decimals given.

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::iso281::{self, FactorSet, KappaSource, Kind, LifeCase, Lubrication};
use crate::calc::quantity::{NonNegative, Positive};
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::fidelity::Level;

pub struct Life;

/// Largest load or load rating accepted, N.
const MAX_LOAD_N: f64 = 1e12;
/// Largest C/P (and C_u/P) accepted: beyond it L10 exceeds 10¹⁸ million revolutions and means
/// nothing.
const MAX_LOAD_RATIO: f64 = 1e6;
/// Speed range accepted, rpm.
const SPEED_RANGE_RPM: (f64, f64) = (1e-6, 1e7);
/// Largest pitch diameter accepted, m.
const MAX_PITCH_DIAMETER_M: f64 = 100.0;
/// Largest number of duty-cycle steps.
const MAX_DUTY_STEPS: usize = 1000;
/// Default Weibull slope of the texts' a1 (Khonsari & Booser Table 13.9).
const TEXTS_WEIBULL_SLOPE: f64 = 1.5;

/// Ball or roller bearing: the life exponent and the a_ISO constants.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, Serialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum BearingKind {
    /// Radial ball bearing: point contact, p = 3.
    Ball,
    /// Radial roller bearing: line contact, p = 10/3.
    Roller,
}

impl BearingKind {
    /// The life exponent p of L10 = (C/P)^p.
    pub fn life_exponent(self) -> f64 {
        Kind::from(self).life_exponent()
    }
}

/// Which published reliability factors a1 to use.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, Serialize, ToSchema)]
pub enum ReliabilityFactorSet {
    /// The texts' Weibull relation a1 = [ln(100/R)/ln(100/90)]^{1/e}, slope e = 1.5 unless
    /// `weibull_slope` says otherwise (Khonsari & Booser Table 13.9; Hamrock 21.3.6).
    #[default]
    #[serde(rename = "weibull")]
    Weibull,
    /// ISO 281:2007: a1 = 0.95 [ln(100/R)/ln(100/90)]^{2/3} + 0.05, tabulated for 90…99.95 %.
    #[serde(rename = "iso_281_2007")]
    Iso281_2007,
}

/// Reliability in percent, strictly within (0, 100).
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(try_from = "f64")]
pub struct Reliability(f64);

impl TryFrom<f64> for Reliability {
    type Error = String;
    fn try_from(v: f64) -> Result<Self, String> {
        if (1.0..100.0).contains(&v) {
            Ok(Reliability(v))
        } else {
            Err(format!(
                "must be a reliability in percent within [1, 100), got {v}: below 1 % the Weibull law is extrapolated beyond any use, and 100 % is an infinitely short life"
            ))
        }
    }
}

/// A contamination factor e_C within [0, 1] (1 very clean, 0 severely contaminated).
#[derive(Debug, Clone, Copy, PartialEq, Deserialize)]
#[serde(try_from = "f64")]
pub struct ContaminationFactor(f64);

impl TryFrom<f64> for ContaminationFactor {
    type Error = String;
    fn try_from(v: f64) -> Result<Self, String> {
        if v.is_finite() && (0.0..=1.0).contains(&v) {
            Ok(ContaminationFactor(v))
        } else {
            Err(format!(
                "must be a contamination factor within [0, 1], got {v}"
            ))
        }
    }
}

/// One step of a duty cycle: a load held at a speed for a share of the time or of the
/// revolutions.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct DutyStep {
    /// Equivalent dynamic load P_i of the step, N, > 0.
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 1e12, example = 8000.0)]
    pub equivalent_load_n: Positive,
    /// Speed n_i of the step, rpm, 1e-6 … 1e7.
    #[schema(value_type = f64, minimum = 1e-6, maximum = 1e7, example = 500.0)]
    pub speed_rpm: Positive,
    /// Share of the time spent in this step, > 0; normalised by the sum over the steps (minutes
    /// per cycle, percent or fractions all work). Give this or `revolution_fraction`, the same
    /// kind in every step.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e9, example = 10.0)]
    pub time_fraction: Option<Positive>,
    /// Share of the revolutions made in this step, > 0; normalised by the sum over the steps.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e9, example = 0.25)]
    pub revolution_fraction: Option<Positive>,
}

/// Request: the bearing's rating and its load (one equivalent load, its components, or a duty
/// cycle), the speed, the reliability, and optionally the lubrication and contamination for the
/// modified life.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct LifeInput {
    /// `ball` (p = 3) or `roller` (p = 10/3); radial bearings.
    pub bearing_kind: BearingKind,
    /// Basic dynamic load rating C, N, > 0 (catalogue value: the load for 10⁶ revolutions at
    /// 90 % reliability).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 1e12, example = 35700.0)]
    pub dynamic_load_rating_n: Positive,
    /// Equivalent dynamic load P, N, > 0. Or give `radial_load_n` (with `axial_load_n`,
    /// `x_factor`, `y_factor`), or `duty_cycle` — exactly one of the three.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e12, example = 5000.0)]
    pub equivalent_load_n: Option<Positive>,
    /// Radial load F_r, N, ≥ 0: P = X F_r + Y F_a (at least F_r).
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 1e12, example = 3000.0)]
    pub radial_load_n: Option<NonNegative>,
    /// Axial load F_a, N, ≥ 0 (default 0); needs `x_factor` and `y_factor` when > 0.
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 1e12, example = 7000.0)]
    pub axial_load_n: Option<NonNegative>,
    /// Radial load factor X, dimensionless, ≥ 0 (catalogue or Khonsari & Booser Table 13.8);
    /// default 1 when there is no axial load.
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 100.0, example = 0.56)]
    pub x_factor: Option<NonNegative>,
    /// Axial load factor Y, dimensionless, ≥ 0; default 0 when there is no axial load.
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 100.0, example = 1.5)]
    pub y_factor: Option<NonNegative>,
    /// A duty cycle (1 … 1000 steps) instead of one load and speed: the mean load
    /// P_m = [Σ P_iᵖ u_i / Σ u_i]^{1/p} over the revolutions u_i, and the time-mean speed.
    #[schema(example = json!([{"equivalent_load_n": 4000.0, "speed_rpm": 1500.0, "time_fraction": 0.7}, {"equivalent_load_n": 8000.0, "speed_rpm": 900.0, "time_fraction": 0.3}]))]
    pub duty_cycle: Option<Vec<DutyStep>>,
    /// Speed n, rpm, 1e-6 … 1e7; required unless `duty_cycle` gives each step's speed.
    #[schema(value_type = Option<f64>, minimum = 1e-6, maximum = 1e7, example = 5000.0)]
    pub speed_rpm: Option<Positive>,
    /// Reliability R, percent, within [1, 100); default 90 (the rating's, a1 = 1).
    #[schema(value_type = Option<f64>, minimum = 1.0, exclusive_maximum = 100.0, example = 90.0)]
    pub reliability_percent: Option<Reliability>,
    /// Which a1 set: `weibull` (default; the texts' Table 13.9 with slope 1.5) or
    /// `iso_281_2007`.
    pub reliability_factor: Option<ReliabilityFactorSet>,
    /// Weibull slope e of the `weibull` set, dimensionless, 0.1 … 10; default 1.5.
    #[schema(value_type = Option<f64>, minimum = 0.1, maximum = 10.0, example = 1.5)]
    pub weibull_slope: Option<Positive>,
    /// Operating kinematic viscosity ν of the oil (or grease base oil) at the operating
    /// temperature, mm²/s, > 0; with `pitch_diameter_m` gives κ = ν/ν1. Or give `kappa`.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e6, example = 20.0)]
    pub operating_viscosity_mm2_s: Option<Positive>,
    /// Bearing mean (pitch) diameter d_m = (d + D)/2, m, > 0: gives the rated viscosity ν1.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 100.0, example = 0.07)]
    pub pitch_diameter_m: Option<Positive>,
    /// Viscosity ratio κ = ν/ν1, dimensionless, > 0 (clipped to [0.1, 4] with a warning).
    /// Instead of `operating_viscosity_mm2_s`.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e6, example = 2.5)]
    pub kappa: Option<Positive>,
    /// Contamination factor e_C, dimensionless, within [0, 1] (1 very clean … 0 severely
    /// contaminated; Khonsari & Booser Table 13.10's η_c); needed for a_ISO.
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 1.0, example = 1.0)]
    pub contamination_factor: Option<ContaminationFactor>,
    /// Fatigue load limit C_u (SKF's P_u), N, > 0 (catalogue); needed for a_ISO.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e12, example = 980.0)]
    pub fatigue_load_limit_n: Option<Positive>,
}

/// The load and speed the life uses.
struct Loading {
    load_n: f64,
    raised_from_n: Option<f64>,
    speed_rpm: f64,
    duty_steps: usize,
}

impl LifeInput {
    /// P and n from exactly one of: the equivalent load, its components, the duty cycle.
    fn loading(&self, errors: &mut Vec<FieldError>) -> Option<Loading> {
        let components = self.radial_load_n.is_some()
            || self.axial_load_n.is_some()
            || self.x_factor.is_some()
            || self.y_factor.is_some();
        let given = [
            self.equivalent_load_n.is_some(),
            components,
            self.duty_cycle.is_some(),
        ];
        match given.iter().filter(|g| **g).count() {
            0 => {
                errors.push(FieldError::new(
                    "/equivalent_load_n",
                    "give the load: equivalent_load_n, or radial_load_n (with axial_load_n, x_factor, y_factor), or duty_cycle",
                ));
                return None;
            }
            1 => {}
            _ => {
                let pointer = if self.duty_cycle.is_some() {
                    "/duty_cycle"
                } else if self.radial_load_n.is_some() {
                    "/radial_load_n"
                } else if self.axial_load_n.is_some() {
                    "/axial_load_n"
                } else if self.x_factor.is_some() {
                    "/x_factor"
                } else {
                    "/y_factor"
                };
                errors.push(FieldError::new(
                    pointer,
                    "give exactly one of: equivalent_load_n; radial_load_n with axial_load_n, x_factor, y_factor; duty_cycle",
                ));
                return None;
            }
        }
        if let Some(steps) = &self.duty_cycle {
            if self.speed_rpm.is_some() {
                errors.push(FieldError::new(
                    "/speed_rpm",
                    "a duty cycle gives each step's speed: omit speed_rpm",
                ));
            }
            return duty_cycle(steps, self.bearing_kind.life_exponent(), errors);
        }
        let speed_rpm = match self.speed_rpm {
            Some(n) => check_speed(n.get(), "/speed_rpm", errors),
            None => {
                errors.push(FieldError::new(
                    "/speed_rpm",
                    "the speed is needed for the life in hours and the rated viscosity",
                ));
                None
            }
        };
        let (load_n, raised_from_n) = match self.equivalent_load_n {
            Some(p) => (check_load(p.get(), "/equivalent_load_n", errors)?, None),
            None => self.combined_load(errors)?,
        };
        Some(Loading {
            load_n,
            raised_from_n,
            speed_rpm: speed_rpm?,
            duty_steps: 0,
        })
    }

    /// P = X F_r + Y F_a, at least F_r; returns (P, the raw value when raised).
    fn combined_load(&self, errors: &mut Vec<FieldError>) -> Option<(f64, Option<f64>)> {
        let Some(radial) = self.radial_load_n.map(NonNegative::get) else {
            errors.push(FieldError::new(
                "/radial_load_n",
                "the load components need radial_load_n (0 for a purely axial load)",
            ));
            return None;
        };
        let axial = self.axial_load_n.map_or(0.0, NonNegative::get);
        let (x, y) = match (self.x_factor, self.y_factor) {
            (Some(x), Some(y)) => (x.get(), y.get()),
            (None, None) if axial == 0.0 => (1.0, 0.0),
            (None, _) => {
                errors.push(FieldError::new(
                    "/x_factor",
                    "an axial load needs the bearing's X and Y factors (catalogue, or Khonsari & Booser Table 13.8)",
                ));
                return None;
            }
            (Some(_), None) => {
                errors.push(FieldError::new(
                    "/y_factor",
                    "give the Y factor with the X factor",
                ));
                return None;
            }
        };
        for (value, pointer) in [(x, "/x_factor"), (y, "/y_factor")] {
            if value > 100.0 {
                errors.push(FieldError::new(
                    pointer,
                    format!("must be at most 100, got {value}"),
                ));
            }
        }
        for (value, pointer) in [(radial, "/radial_load_n"), (axial, "/axial_load_n")] {
            if value > MAX_LOAD_N {
                errors.push(FieldError::new(
                    pointer,
                    format!("must be at most {MAX_LOAD_N:e} N, got {value}"),
                ));
            }
        }
        let combined = x * radial + y * axial;
        let load = combined.max(radial);
        if load <= 0.0 {
            errors.push(FieldError::new(
                "/radial_load_n",
                format!(
                    "the equivalent load X F_r + Y F_a = {x}·{radial} + {y}·{axial} is 0: a bearing without load has no fatigue life to rate"
                ),
            ));
            return None;
        }
        Some((load, (combined < radial).then_some(combined)))
    }

    /// κ's source, e_C and C_u, or None when the request asks for no modified life.
    fn lubrication(&self, errors: &mut Vec<FieldError>) -> Option<Lubrication> {
        let kappa = match (self.kappa, self.operating_viscosity_mm2_s) {
            (Some(_), Some(_)) => {
                errors.push(FieldError::new(
                    "/kappa",
                    "give kappa or operating_viscosity_mm2_s (with pitch_diameter_m), not both",
                ));
                return None;
            }
            (Some(k), None) => Some(KappaSource::Given(k.get())),
            (None, Some(nu)) => match self.pitch_diameter_m {
                Some(dm) => Some(KappaSource::Viscosity {
                    viscosity_mm2_s: nu.get(),
                    pitch_diameter_mm: dm.get() * 1e3,
                }),
                None => {
                    errors.push(FieldError::new(
                        "/pitch_diameter_m",
                        "the rated viscosity ν1 that κ = ν/ν1 needs comes from the pitch diameter",
                    ));
                    return None;
                }
            },
            (None, None) => None,
        };
        for (value, pointer, limit) in [
            (self.kappa.map(Positive::get), "/kappa", 1e6),
            (
                self.operating_viscosity_mm2_s.map(Positive::get),
                "/operating_viscosity_mm2_s",
                1e6,
            ),
            (
                self.fatigue_load_limit_n.map(Positive::get),
                "/fatigue_load_limit_n",
                MAX_LOAD_N,
            ),
        ] {
            if let Some(v) = value.filter(|v| *v > limit) {
                errors.push(FieldError::new(
                    pointer,
                    format!("must be at most {limit:e}, got {v}"),
                ));
            }
        }
        match (kappa, self.contamination_factor, self.fatigue_load_limit_n) {
            (None, None, None) => None,
            (Some(kappa), Some(e_c), Some(c_u)) => Some(Lubrication {
                kappa,
                contamination: e_c.0,
                fatigue_load_limit_n: c_u.get(),
            }),
            (None, _, _) => {
                errors.push(FieldError::new(
                    "/kappa",
                    "a_ISO needs the viscosity ratio: give kappa, or operating_viscosity_mm2_s with pitch_diameter_m",
                ));
                None
            }
            (Some(_), e_c, c_u) => {
                if e_c.is_none() {
                    errors.push(FieldError::new(
                        "/contamination_factor",
                        "a_ISO needs the contamination factor e_C (1 very clean … 0 severely contaminated)",
                    ));
                }
                if c_u.is_none() {
                    errors.push(FieldError::new(
                        "/fatigue_load_limit_n",
                        "a_ISO needs the bearing's fatigue load limit C_u (catalogue)",
                    ));
                }
                None
            }
        }
    }
}

fn check_speed(n: f64, pointer: &str, errors: &mut Vec<FieldError>) -> Option<f64> {
    if (SPEED_RANGE_RPM.0..=SPEED_RANGE_RPM.1).contains(&n) {
        Some(n)
    } else {
        errors.push(FieldError::new(
            pointer,
            format!(
                "must be within [{:e}, {:e}] rpm, got {n}",
                SPEED_RANGE_RPM.0, SPEED_RANGE_RPM.1
            ),
        ));
        None
    }
}

fn check_load(p: f64, pointer: &str, errors: &mut Vec<FieldError>) -> Option<f64> {
    if p <= MAX_LOAD_N {
        Some(p)
    } else {
        errors.push(FieldError::new(
            pointer,
            format!("must be at most {MAX_LOAD_N:e} N, got {p}"),
        ));
        None
    }
}

/// Mean load P_m = [Σ P_iᵖ u_i / Σ u_i]^{1/p} and time-mean speed Σ u_i / Σ t_i of a duty cycle.
fn duty_cycle(steps: &[DutyStep], p: f64, errors: &mut Vec<FieldError>) -> Option<Loading> {
    if steps.is_empty() || steps.len() > MAX_DUTY_STEPS {
        errors.push(FieldError::new(
            "/duty_cycle",
            format!("needs 1 … {MAX_DUTY_STEPS} steps, got {}", steps.len()),
        ));
        return None;
    }
    let by_time = steps[0].time_fraction.is_some();
    let before = errors.len();
    // (revolutions, time, load) per step, in consistent relative units.
    let mut shares = Vec::with_capacity(steps.len());
    for (i, step) in steps.iter().enumerate() {
        let at = |field: &str| format!("/duty_cycle/{i}/{field}");
        let load = check_load(
            step.equivalent_load_n.get(),
            &at("equivalent_load_n"),
            errors,
        );
        let speed = check_speed(step.speed_rpm.get(), &at("speed_rpm"), errors);
        let share = match (step.time_fraction, step.revolution_fraction) {
            (Some(t), None) if by_time => Some(t.get()),
            (None, Some(u)) if !by_time => Some(u.get()),
            (Some(_), Some(_)) => {
                errors.push(FieldError::new(
                    at("revolution_fraction"),
                    "give time_fraction or revolution_fraction, not both",
                ));
                None
            }
            (None, None) => {
                errors.push(FieldError::new(
                    at("time_fraction"),
                    "give the step's time_fraction or revolution_fraction",
                ));
                None
            }
            _ => {
                let (field, kind) = if by_time {
                    ("revolution_fraction", "time_fraction")
                } else {
                    ("time_fraction", "revolution_fraction")
                };
                errors.push(FieldError::new(
                    at(field),
                    format!("the first step gives {kind}: give {kind} in every step"),
                ));
                None
            }
        };
        if let (Some(load), Some(speed), Some(share)) = (load, speed, share) {
            let (revolutions, time) = if by_time {
                (share * speed, share)
            } else {
                (share, share / speed)
            };
            shares.push((revolutions, time, load));
        }
    }
    if errors.len() > before {
        return None;
    }
    // Normalise by the largest load first so that Pᵖ cannot overflow.
    let p_max = shares.iter().map(|s| s.2).fold(0.0, f64::max);
    let revolutions: f64 = shares.iter().map(|s| s.0).sum();
    let time: f64 = shares.iter().map(|s| s.1).sum();
    let weighted: f64 = shares.iter().map(|s| (s.2 / p_max).powf(p) * s.0).sum();
    let load_n = p_max * (weighted / revolutions).powf(1.0 / p);
    let speed_rpm = revolutions / time;
    if !(load_n.is_finite() && speed_rpm.is_finite() && load_n > 0.0 && speed_rpm > 0.0) {
        errors.push(FieldError::new(
            "/duty_cycle",
            "the step shares are too disparate for a finite mean load and speed",
        ));
        return None;
    }
    Some(Loading {
        load_n,
        raised_from_n: None,
        speed_rpm,
        duty_steps: steps.len(),
    })
}

impl Validate for LifeInput {
    type Valid = LifeCase;
    fn validate(self) -> Result<LifeCase, Vec<FieldError>> {
        let mut errors = Vec::new();
        let rating_n = self.dynamic_load_rating_n.get();
        if rating_n > MAX_LOAD_N {
            errors.push(FieldError::new(
                "/dynamic_load_rating_n",
                format!("must be at most {MAX_LOAD_N:e} N, got {rating_n}"),
            ));
        }
        let loading = self.loading(&mut errors);
        if let Some(l) = &loading {
            if rating_n / l.load_n > MAX_LOAD_RATIO {
                let pointer = if self.duty_cycle.is_some() {
                    "/duty_cycle"
                } else if self.equivalent_load_n.is_some() {
                    "/equivalent_load_n"
                } else {
                    "/radial_load_n"
                };
                errors.push(FieldError::new(
                    pointer,
                    format!(
                        "the load {} N is below C/{MAX_LOAD_RATIO:e}: far below any load a rating life means anything for",
                        l.load_n
                    ),
                ));
            }
        }
        let factor_set = self.reliability_factor.unwrap_or_default();
        let weibull_slope = match (self.weibull_slope.map(Positive::get), factor_set) {
            (None, _) => TEXTS_WEIBULL_SLOPE,
            (Some(e), ReliabilityFactorSet::Weibull) if (0.1..=10.0).contains(&e) => e,
            (Some(e), ReliabilityFactorSet::Weibull) => {
                errors.push(FieldError::new(
                    "/weibull_slope",
                    format!("must be within [0.1, 10], got {e}"),
                ));
                TEXTS_WEIBULL_SLOPE
            }
            (Some(_), ReliabilityFactorSet::Iso281_2007) => {
                errors.push(FieldError::new(
                    "/weibull_slope",
                    "belongs to reliability_factor weibull; ISO 281:2007's a1 has its own form",
                ));
                TEXTS_WEIBULL_SLOPE
            }
        };
        let pitch_diameter_mm = match self.pitch_diameter_m.map(Positive::get) {
            Some(d) if d > MAX_PITCH_DIAMETER_M => {
                errors.push(FieldError::new(
                    "/pitch_diameter_m",
                    format!("must be at most {MAX_PITCH_DIAMETER_M} m, got {d}"),
                ));
                None
            }
            d => d.map(|d| d * 1e3),
        };
        let lubrication = self.lubrication(&mut errors);
        // e_C C_u/P enters a_ISO; bounded like C/P so a tiny P cannot make it infinite.
        if let (Some(l), Some(lub)) = (&loading, &lubrication) {
            if lub.fatigue_load_limit_n / l.load_n > MAX_LOAD_RATIO {
                errors.push(FieldError::new(
                    "/fatigue_load_limit_n",
                    format!(
                        "C_u = {} N is above {MAX_LOAD_RATIO:e} times the load {} N: no a_ISO means anything there",
                        lub.fatigue_load_limit_n, l.load_n
                    ),
                ));
            }
        }
        match loading {
            Some(l) if errors.is_empty() => Ok(LifeCase {
                kind: self.bearing_kind.into(),
                rating_n,
                load_n: l.load_n,
                raised_from_n: l.raised_from_n,
                speed_rpm: l.speed_rpm,
                duty_steps: l.duty_steps,
                reliability_percent: self.reliability_percent.map_or(90.0, |r| r.0),
                factor_set: factor_set.into(),
                weibull_slope,
                pitch_diameter_mm,
                lubrication,
            }),
            _ => Err(errors),
        }
    }
}

/// Result.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct LifeOutput {
    /// `ball` or `roller`.
    pub bearing_kind: BearingKind,
    /// Life exponent p: 3 (ball) or 10/3 (roller), dimensionless.
    #[schema(example = 3.0)]
    pub life_exponent: f64,
    /// Equivalent dynamic load P used, N (the duty cycle's mean load P_m, or X F_r + Y F_a
    /// raised to F_r when smaller).
    #[schema(example = 5000.0)]
    pub equivalent_load_n: f64,
    /// C/P, dimensionless.
    #[schema(example = 7.14)]
    pub load_ratio: f64,
    /// Speed used for hours and ν1, rpm (the duty cycle's time-mean speed).
    #[schema(example = 5000.0)]
    pub speed_rpm: f64,
    /// Basic rating life L10 = (C/P)^p, million revolutions (90 % reliability).
    #[schema(example = 364.0)]
    pub l10_million_revolutions: f64,
    /// L10h = 10⁶ L10/(60 n), hours.
    #[schema(example = 1213.4)]
    pub l10_hours: f64,
    /// Reliability R used, percent.
    #[schema(example = 90.0)]
    pub reliability_percent: f64,
    /// Which a1 set was used: `weibull` or `iso_281_2007`.
    pub reliability_factor: ReliabilityFactorSet,
    /// Reliability factor a1, dimensionless (1 at 90 %).
    #[schema(example = 1.0)]
    pub a1: f64,
    /// a1 L10, million revolutions: the life reached by R % of the bearings.
    #[schema(example = 364.0)]
    pub life_at_reliability_million_revolutions: f64,
    /// a1 L10h, hours.
    #[schema(example = 1213.4)]
    pub life_at_reliability_hours: f64,
    /// Rated viscosity ν1 (ISO 281 / SKF) at the speed and pitch diameter, mm²/s; when
    /// `pitch_diameter_m` is given.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = 7.61)]
    pub rated_viscosity_mm2_s: Option<f64>,
    /// Viscosity ratio κ = ν/ν1 (or as given) before clipping, dimensionless; with a_ISO.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = 2.63)]
    pub kappa: Option<f64>,
    /// κ used in a_ISO, clipped to [0.1, 4], dimensionless.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = 2.63)]
    pub kappa_used: Option<f64>,
    /// e_C C_u / P, dimensionless; with a_ISO.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = 0.196)]
    pub contamination_load_ratio: Option<f64>,
    /// ISO 281:2007 life modification factor a_ISO, dimensionless, 0.1 (about) … 50.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = 18.6)]
    pub a_iso: Option<f64>,
    /// Modified rating life a1 a_ISO L10, million revolutions.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = 6760.0)]
    pub modified_life_million_revolutions: Option<f64>,
    /// Modified rating life a1 a_ISO L10h, hours.
    #[serde(skip_serializing_if = "Option::is_none")]
    #[schema(example = 22530.0)]
    pub modified_life_hours: Option<f64>,
}

impl Calculation for Life {
    const PATH: &'static str = "/v1/rolling-bearings/life";
    const SUMMARY: &'static str =
        "Rolling-bearing fatigue life: L10, reliability factor a1, ISO 281 a_ISO and modified life";
    const DESCRIPTION: &'static str = include_str!("life.md");
    const FIDELITY: &'static [Level] = &[Level::ClosedForm];
    const EFFECTS: &'static [&'static str] = &[];
    const EXAMPLE: &'static str = r#"{"bearing_kind": "ball", "dynamic_load_rating_n": 35700, "equivalent_load_n": 5000, "speed_rpm": 5000, "operating_viscosity_mm2_s": 20, "pitch_diameter_m": 0.07, "contamination_factor": 0.5, "fatigue_load_limit_n": 980}"#;

    type Input = LifeInput;
    type Output = LifeOutput;

    fn run(case: LifeCase, ctx: &mut Context) -> Result<LifeOutput, CalcError> {
        Ok(life(&case, ctx))
    }
}

/// The whole calculation, with its warnings: the model's lives as the response.
pub(super) fn life(case: &LifeCase, ctx: &mut Context) -> LifeOutput {
    let r = iso281::life(case);
    ctx.record(&r.notes);
    let m = r.modified;
    LifeOutput {
        bearing_kind: case.kind.into(),
        life_exponent: r.life_exponent,
        equivalent_load_n: case.load_n,
        load_ratio: r.load_ratio,
        speed_rpm: case.speed_rpm,
        l10_million_revolutions: r.l10_million_revolutions,
        l10_hours: r.l10_hours,
        reliability_percent: case.reliability_percent,
        reliability_factor: case.factor_set.into(),
        a1: r.a1,
        life_at_reliability_million_revolutions: r.life_at_reliability_million_revolutions,
        life_at_reliability_hours: r.life_at_reliability_hours,
        rated_viscosity_mm2_s: r.rated_viscosity_mm2_s,
        kappa: m.map(|m| m.kappa),
        kappa_used: m.map(|m| m.kappa_used),
        contamination_load_ratio: m.map(|m| m.contamination_load_ratio),
        a_iso: m.map(|m| m.a_iso),
        modified_life_million_revolutions: m.map(|m| m.modified_life_million_revolutions),
        modified_life_hours: m.map(|m| m.modified_life_hours),
    }
}

impl From<BearingKind> for Kind {
    fn from(k: BearingKind) -> Self {
        match k {
            BearingKind::Ball => Kind::Ball,
            BearingKind::Roller => Kind::Roller,
        }
    }
}

impl From<Kind> for BearingKind {
    fn from(k: Kind) -> Self {
        match k {
            Kind::Ball => BearingKind::Ball,
            Kind::Roller => BearingKind::Roller,
        }
    }
}

impl From<ReliabilityFactorSet> for FactorSet {
    fn from(s: ReliabilityFactorSet) -> Self {
        match s {
            ReliabilityFactorSet::Weibull => FactorSet::Weibull,
            ReliabilityFactorSet::Iso281_2007 => FactorSet::Iso281_2007,
        }
    }
}

impl From<FactorSet> for ReliabilityFactorSet {
    fn from(s: FactorSet) -> Self {
        match s {
            FactorSet::Weibull => ReliabilityFactorSet::Weibull,
            FactorSet::Iso281_2007 => ReliabilityFactorSet::Iso281_2007,
        }
    }
}

#[cfg(test)]
#[path = "life_tests.rs"]
mod tests;
