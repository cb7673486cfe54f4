//! `POST /v1/composite-bearings/start-up`: the composite bearing's start-up under a linear
//! speed ramp — the rolling phase, break-away and the sleeve's run-down to its steady split
//! (Harnoy ch. 18; the start-up law is this service's documented choice, see [`super::start`]).
//!
//! This file is the wire (request, validation, response); the physics is [`super::start`].

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::speed_split::{load_error, parse_bearing, rpm, Bearing, BearingFields};
use super::start::{simulate, Breakaway, StartError, StartUp};
use crate::calc::lubricant::LubricantSpec;
use crate::calc::quantity::{Celsius, NonNegative, Positive};
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::fidelity::Level;

pub struct StartUpRoom;

/// Largest load, N; inertia, kg·m²; ramp, s; traction coefficient.
const MAX_LOAD_N: f64 = 1e9;
const MAX_INERTIA_KG_M2: f64 = 1e6;
const MIN_RAMP_S: f64 = 1e-6;
const MAX_RAMP_S: f64 = 1e6;
const MAX_TRACTION: f64 = 2.0;
/// Samples of the sleeve speed history: default and range.
const DEFAULT_SAMPLES: u32 = 101;
const MAX_SAMPLES: u32 = 2001;

/// Request.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct CompositeStartUpInput {
    /// Journal radius R, m (0 … 10).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 10.0, example = 0.05)]
    pub journal_radius_m: Positive,
    /// Length L of the sleeve's bore (the film), m (0 … 10; L/D at most 2, the short-bearing
    /// film is meant for L/D ≤ 1/2).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 10.0, example = 0.1)]
    pub sleeve_length_m: Positive,
    /// Radial clearance C between journal and sleeve, m (1e-7 … a tenth of the radius).
    #[schema(value_type = f64, minimum = 1e-7, maximum = 0.1, example = 6e-5)]
    pub radial_clearance_m: Positive,
    pub lubricant: LubricantSpec,
    /// Film temperature, °C (−273 … 1000): where the viscosity is taken; required unless the
    /// lubricant has a constant `viscosity_pa_s`.
    #[schema(value_type = Option<f64>, minimum = -273.0, maximum = 1000.0, example = 40.0)]
    pub temperature_c: Option<Celsius>,
    /// The journal's speed at the end of the ramp ω_J, rpm (0 … 1e6).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 1e6, example = 3500.0)]
    pub journal_speed_rpm: Positive,
    /// Radial load on the journal W, N (0 … 1e9), constant through the start-up: it presses
    /// journal on sleeve while they roll, and the film carries it once they slide.
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 1e9, example = 20000.0)]
    pub load_n: Positive,
    /// Boundary friction coefficient f_c between the centrifugal pins and the housing,
    /// dimensionless (0 … 2); with `pin_mass_kg`, `pin_radius_m` and `housing_radius_m`, or
    /// give their product `restraint_coefficient_kg_m2`.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 2.0, example = 0.3)]
    pub pin_friction_coefficient: Option<Positive>,
    /// Total mass of the centrifugal pins m_c, kg (0 … 1e4).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e4, example = 1.5)]
    pub pin_mass_kg: Option<Positive>,
    /// Radius R_m of the circle of the pins' centres when they touch the housing, m (0 … 10,
    /// at most `housing_radius_m`).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 0.085)]
    pub pin_radius_m: Option<Positive>,
    /// Radius R_h of the housing bore the pins rub on, m (0 … 10).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 0.0933)]
    pub housing_radius_m: Option<Positive>,
    /// The restraint's coefficient k = f_c m_c R_m R_h, kg·m² (0 … 1e6): M_f = k ω_b²; instead
    /// of its four factors.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e6, example = 0.0357)]
    pub restraint_coefficient_kg_m2: Option<Positive>,
    /// Friction torque M_r of the rolling bearing, N·m (0 … 1e6; default 0), constant,
    /// opposing the sleeve's rotation.
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 1e6, example = 0.0)]
    pub rolling_friction_torque_n_m: Option<NonNegative>,
    /// Equivalent moment of inertia I_eq of the sleeve unit (sleeve, disc, pins, the rolling
    /// bearing's inner ring and a share of its elements), kg·m² (0 … 1e6).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 1e6, example = 0.01)]
    pub sleeve_inertia_kg_m2: Positive,
    /// Duration t_r of the journal's linear speed ramp from rest to `journal_speed_rpm`, s
    /// (1e-6 … 1e6).
    #[schema(value_type = f64, minimum = 1e-6, maximum = 1e6, example = 2.0)]
    pub ramp_time_s: Positive,
    /// Journal–sleeve traction coefficient f_t while they roll together, dimensionless
    /// (0 … 2): the contact passes at most f_t W R to the sleeve before it slides (the
    /// boundary/mixed friction of Harnoy's Fig 18-4, which gives no number).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 2.0, example = 0.005)]
    pub rolling_traction_coefficient: Positive,
    /// Points of the sleeve speed history, evenly spaced in time from 0 to the end of the run
    /// (2 … 2001; default 101).
    #[schema(minimum = 2, maximum = 2001, example = 101)]
    pub history_points: Option<u32>,
}

/// The parsed request.
#[derive(Debug, Clone, PartialEq)]
pub struct CompositeStartUpCase {
    pub start: StartUp,
    pub bearing: Bearing,
    pub samples: usize,
}

impl Validate for CompositeStartUpInput {
    type Valid = CompositeStartUpCase;
    fn validate(self) -> Result<CompositeStartUpCase, Vec<FieldError>> {
        let mut errors = Vec::new();
        let checks = [
            ("load_n", self.load_n.get(), 0.0, MAX_LOAD_N, " N"),
            (
                "sleeve_inertia_kg_m2",
                self.sleeve_inertia_kg_m2.get(),
                0.0,
                MAX_INERTIA_KG_M2,
                " kg·m²",
            ),
            (
                "ramp_time_s",
                self.ramp_time_s.get(),
                MIN_RAMP_S,
                MAX_RAMP_S,
                " s",
            ),
            (
                "rolling_traction_coefficient",
                self.rolling_traction_coefficient.get(),
                0.0,
                MAX_TRACTION,
                "",
            ),
        ];
        for (name, value, lo, hi, unit) in checks {
            if value < lo || value > hi {
                // Every field here is positive by type: a lower bound of 0 is exclusive.
                let range = if lo == 0.0 {
                    format!("(0, {hi:e}]")
                } else {
                    format!("[{lo:e}, {hi:e}]")
                };
                errors.push(FieldError::new(
                    format!("/{name}"),
                    format!("must lie within {range}{unit}"),
                ));
            }
        }
        let samples = self.history_points.unwrap_or(DEFAULT_SAMPLES);
        if !(2..=MAX_SAMPLES).contains(&samples) {
            errors.push(FieldError::new(
                "/history_points",
                format!("must lie within [2, {MAX_SAMPLES}]"),
            ));
        }
        let bearing = parse_bearing(
            BearingFields {
                journal_radius_m: self.journal_radius_m,
                sleeve_length_m: self.sleeve_length_m,
                radial_clearance_m: self.radial_clearance_m,
                lubricant: self.lubricant,
                temperature_c: self.temperature_c,
                journal_speed_rpm: self.journal_speed_rpm,
                pin_friction_coefficient: self.pin_friction_coefficient,
                pin_mass_kg: self.pin_mass_kg,
                pin_radius_m: self.pin_radius_m,
                housing_radius_m: self.housing_radius_m,
                restraint_coefficient_kg_m2: self.restraint_coefficient_kg_m2,
                rolling_friction_torque_n_m: self.rolling_friction_torque_n_m,
            },
            &mut errors,
        );
        match (errors.is_empty(), bearing) {
            (true, Some(bearing)) => Ok(CompositeStartUpCase {
                start: StartUp {
                    film: bearing.film,
                    restraint: bearing.restraint,
                    load: self.load_n.get(),
                    journal_speed: bearing.journal_speed,
                    ramp_time: self.ramp_time_s.get(),
                    inertia: self.sleeve_inertia_kg_m2.get(),
                    traction_coefficient: self.rolling_traction_coefficient.get(),
                },
                bearing,
                samples: samples as usize,
            }),
            _ => Err(errors),
        }
    }
}

/// One sample of the start-up.
#[derive(Debug, Clone, Copy, Serialize, ToSchema)]
pub struct CompositeStartUpSample {
    /// Time from the start of the ramp, s.
    pub time_s: f64,
    /// Journal speed ω_j, rpm.
    pub journal_speed_rpm: f64,
    /// Sleeve speed ω_b, rpm.
    pub sleeve_speed_rpm: f64,
}

/// Result.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct CompositeStartUpOutput {
    /// Journal speed at break-away, rpm (0: the sleeve slides from the start); omitted when
    /// the sleeve never breaks away.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub breakaway_journal_speed_rpm: Option<f64>,
    /// Time of break-away from the start of the ramp, s; omitted when the sleeve never breaks
    /// away.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub breakaway_time_s: Option<f64>,
    /// Eccentricity ratio of the rolling film at break-away (the load on the speed sum
    /// 2ω_j), dimensionless; 0.999 where the full film cannot carry the load yet.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub eccentricity_at_breakaway: Option<f64>,
    /// Minimum film C(1 − ε) of the rolling film at break-away, m.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub min_film_at_breakaway_m: Option<f64>,
    /// The sleeve's steady speed at the final journal speed, rpm: the speed split's, or the
    /// journal's when the sleeve never breaks away.
    pub steady_sleeve_speed_rpm: f64,
    /// The steady speed ratio ω_b/ω_J, dimensionless.
    pub steady_speed_ratio: f64,
    /// The steady film's eccentricity ratio, dimensionless.
    pub steady_eccentricity_ratio: f64,
    /// The sleeve's speed when the ramp ends, rpm.
    pub sleeve_speed_at_ramp_end_rpm: f64,
    /// The time after which the sleeve speed stays within ±1 % of its steady speed — its last
    /// crossing of the band's edge — s (1 % of
    /// the journal speed where the steady sleeve stands); omitted when the sleeve never breaks
    /// away.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub settling_time_s: Option<f64>,
    /// The time the run ends, s: the ramp and the settling, with margin.
    pub end_time_s: f64,
    /// The sleeve speed history, evenly spaced in time.
    pub history: Vec<CompositeStartUpSample>,
}

impl Calculation for StartUpRoom {
    const PATH: &'static str = "/v1/composite-bearings/start-up";
    const SUMMARY: &'static str = "Composite bearing start-up under a linear journal speed ramp: rolling phase, break-away speed and time, the sleeve's run-down to its steady split, settling time and speed history (a documented modelling choice: the text gives no start-up law)";
    const DESCRIPTION: &'static str = include_str!("start_up.md");
    const FIDELITY: &'static [Level] = &[Level::Standard];
    const EFFECTS: &'static [&'static str] = &[];
    const EXAMPLE: &'static str = r#"{"journal_radius_m": 0.05, "sleeve_length_m": 0.1, "radial_clearance_m": 6e-5, "lubricant": {"viscosity_pa_s": 0.03}, "journal_speed_rpm": 3500, "load_n": 20000, "restraint_coefficient_kg_m2": 0.0357, "sleeve_inertia_kg_m2": 0.01, "ramp_time_s": 2.0, "rolling_traction_coefficient": 0.005, "history_points": 11}"#;

    type Input = CompositeStartUpInput;
    type Output = CompositeStartUpOutput;

    fn run(
        case: CompositeStartUpCase,
        ctx: &mut Context,
    ) -> Result<CompositeStartUpOutput, CalcError> {
        for (code, message) in &case.bearing.viscosity.assumptions {
            ctx.warn(code, message.clone());
        }
        let s = case.start;
        let sim = simulate(&s, &ctx.budget(), case.samples).map_err(|e| match e {
            StartError::Load(e) => load_error("/load_n", s.load, e),
            StartError::Calc(e) => e,
        })?;
        ctx.report(sim.report.clone());
        for (code, message) in &sim.warnings {
            ctx.warn(code, message.clone());
        }
        let breakaway_time = sim.breakaway.time();
        let rolling_film = sim.film_at_breakaway;
        let output = CompositeStartUpOutput {
            breakaway_journal_speed_rpm: breakaway_time.map(|t| rpm(s.journal_speed_at(t))),
            breakaway_time_s: breakaway_time,
            eccentricity_at_breakaway: rolling_film.map(|f| f.eccentricity),
            min_film_at_breakaway_m: rolling_film
                .map(|f| s.film.clearance * (1.0 - f.eccentricity)),
            steady_sleeve_speed_rpm: rpm(sim.steady_sleeve_speed),
            steady_speed_ratio: sim.steady_sleeve_speed / s.journal_speed,
            steady_eccentricity_ratio: sim.steady_eccentricity,
            sleeve_speed_at_ramp_end_rpm: rpm(sim.sleeve_speed_at_ramp_end),
            settling_time_s: match sim.breakaway {
                Breakaway::Never => None,
                _ => sim.settling_time,
            },
            end_time_s: sim.end_time,
            history: sim
                .history
                .iter()
                .map(|p| CompositeStartUpSample {
                    time_s: p.time,
                    journal_speed_rpm: rpm(p.journal_speed),
                    sleeve_speed_rpm: rpm(p.sleeve_speed),
                })
                .collect(),
        };
        CalcError::finite_or_out_of_range(output, "the speed, load, inertia, ramp time and sizes")
    }
}

#[cfg(test)]
#[path = "start_up_tests.rs"]
mod tests;
