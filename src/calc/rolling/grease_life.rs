//! `POST /v1/rolling-bearings/grease-life`: the 10 % grease life and relubrication interval of
//! Khonsari & Booser §15.12 (Eq. 15.34): log10 L = A + B/T − 9.6·10⁻⁷ k_f d n, L in hours,
//! T = 273 + θ (K), A = −2.60 and B = 2450 for premium greases, d the bore in mm, n in rpm, k_f
//! the bearing type's speed factor (Table 15.6). Relubricate at half the life. Fitted on tests at
//! 75–175 °C: life is about flat below 70 °C and falls below 30–40 °C (stiff grease).

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use crate::calc::quantity::{Celsius, Positive};
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::fidelity::Level;

pub struct GreaseLife;

/// Request.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct GreaseLifeInput {
    /// Bore d, m (> 0, at most 2).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 2.0, example = 0.07)]
    pub bore_diameter_m: Positive,
    /// Speed n, rev/min (> 0, at most 1e5).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 1e5, example = 3600.0)]
    pub speed_rpm: Positive,
    /// Bearing operating temperature, °C (−50 … 250).
    #[schema(value_type = f64, minimum = -50.0, maximum = 250.0, example = 85.0)]
    pub temperature_c: Celsius,
    /// Speed factor k_f (Table 15.6: 0.9–1.1 single-row deep-groove ball, 1.6 angular contact,
    /// 1.8–2.3 cylindrical roller, 4 tapered, 7–12 spherical roller; default 1; 0.1 … 100).
    #[schema(minimum = 0.1, maximum = 100.0, example = 1.0)]
    pub speed_factor: Option<f64>,
    /// Grease constant A of Eq. 15.34 (default −2.60, premium greases).
    #[schema(minimum = -20.0, maximum = 20.0, example = -2.6)]
    pub constant_a: Option<f64>,
    /// Grease constant B of Eq. 15.34, K (default 2450, premium greases).
    #[schema(minimum = 0.0, maximum = 20000.0, example = 2450.0)]
    pub constant_b: Option<f64>,
}

/// The validated case.
#[derive(Debug, Clone, Copy)]
pub struct GreaseLifeCase {
    d_mm: f64,
    speed_rpm: f64,
    temperature_c: f64,
    k_f: f64,
    a: f64,
    b: f64,
}

impl Validate for GreaseLifeInput {
    type Valid = GreaseLifeCase;
    fn validate(self) -> Result<GreaseLifeCase, Vec<FieldError>> {
        let mut errors = Vec::new();
        let t = self.temperature_c.get();
        let k_f = self.speed_factor.unwrap_or(1.0);
        let (a, b) = (
            self.constant_a.unwrap_or(-2.60),
            self.constant_b.unwrap_or(2450.0),
        );
        for (ok, pointer, message) in [
            (
                (-50.0..=250.0).contains(&t),
                "/temperature_c",
                "must be within [-50, 250] °C",
            ),
            (
                (0.1..=100.0).contains(&k_f),
                "/speed_factor",
                "must be within [0.1, 100]",
            ),
            (
                (-20.0..=20.0).contains(&a),
                "/constant_a",
                "must be within [-20, 20]",
            ),
            (
                (0.0..=20000.0).contains(&b),
                "/constant_b",
                "must be within [0, 20000] K",
            ),
            (
                self.bore_diameter_m.get() <= 2.0,
                "/bore_diameter_m",
                "must be at most 2 m",
            ),
            (
                self.speed_rpm.get() <= 1e5,
                "/speed_rpm",
                "must be at most 1e5 rev/min",
            ),
        ] {
            if !ok {
                errors.push(FieldError::new(pointer, message));
            }
        }
        if !errors.is_empty() {
            return Err(errors);
        }
        Ok(GreaseLifeCase {
            d_mm: self.bore_diameter_m.get() * 1e3,
            speed_rpm: self.speed_rpm.get(),
            temperature_c: t,
            k_f,
            a,
            b,
        })
    }
}

/// Result.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct GreaseLifeOutput {
    /// log10 of the 10 % grease life in hours.
    pub log10_life: f64,
    /// 10 % grease life L10, h.
    pub grease_life_hours: f64,
    /// Relubrication interval, h (half the life; halve again for vertical shafts).
    pub relubrication_interval_hours: f64,
    /// The speed term 9.6·10⁻⁷ k_f d n, in log10 h.
    pub speed_term: f64,
}

impl Calculation for GreaseLife {
    const PATH: &'static str = "/v1/rolling-bearings/grease-life";
    const SUMMARY: &'static str = "Grease life and relubrication interval of a rolling bearing";
    const DESCRIPTION: &'static str = include_str!("grease_life.md");
    const FIDELITY: &'static [Level] = &[Level::ClosedForm];
    const EFFECTS: &'static [&'static str] = &[];
    const EXAMPLE: &'static str =
        r#"{"bore_diameter_m": 0.07, "speed_rpm": 3600, "temperature_c": 85, "speed_factor": 1.0}"#;

    type Input = GreaseLifeInput;
    type Output = GreaseLifeOutput;

    fn run(c: GreaseLifeCase, ctx: &mut Context) -> Result<GreaseLifeOutput, CalcError> {
        let speed_term = 9.6e-7 * c.k_f * c.d_mm * c.speed_rpm;
        let log10_life = c.a + c.b / (273.0 + c.temperature_c) - speed_term;
        if !(75.0..=175.0).contains(&c.temperature_c) {
            ctx.warn(
                "grease_life_temperature_range",
                format!("Eq. 15.34 is fitted on tests at 75–175 °C; at {} °C: below about 70 °C life is roughly flat, below 30–40 °C it falls (stiff grease)", c.temperature_c),
            );
        }
        if log10_life < 0.0 {
            ctx.warn("grease_life_below_one_hour", "the speed term exceeds the temperature term: the fit is extrapolated far beyond its data");
        }
        let life = 10f64.powf(log10_life);
        Ok(GreaseLifeOutput {
            log10_life,
            grease_life_hours: life,
            relubrication_interval_hours: 0.5 * life,
            speed_term,
        })
    }
}

#[cfg(test)]
mod tests {
    use serde_json::json;

    use super::*;
    use crate::calc::testing::{assert_rel, invalid_pointers, ok, result_field as get};

    /// Khonsari & Booser Ex 15.6 (spec FE-13, recomputed): 214 deep-groove ball bearing,
    /// d = 70 mm, 85 °C, 3600 rpm, k_f = 1: log L = 4.0017 → 10 038 h; without the speed term
    /// 4.2436 → 17 522 h.
    #[test]
    fn example_15_6() {
        let v = ok::<GreaseLife>(&serde_json::from_str(GreaseLife::EXAMPLE).unwrap());
        assert_rel(get(&v, "grease_life_hours"), 10038.0, 5e-4, "L");
        assert_rel(
            get(&v, "log10_life") + get(&v, "speed_term"),
            4.2436,
            1e-4,
            "without speed",
        );
        assert_rel(
            get(&v, "relubrication_interval_hours"),
            5019.0,
            5e-4,
            "interval",
        );
    }

    #[test]
    fn hotter_and_faster_shorten_life() {
        let life = |t: f64, n: f64| {
            get(
                &ok::<GreaseLife>(
                    &json!({"bore_diameter_m": 0.05, "speed_rpm": n, "temperature_c": t}),
                ),
                "grease_life_hours",
            )
        };
        assert!(life(120.0, 3000.0) < life(90.0, 3000.0));
        assert!(life(90.0, 6000.0) < life(90.0, 3000.0));
        assert_eq!(
            invalid_pointers::<GreaseLife>(
                &json!({"bore_diameter_m": 0.05, "speed_rpm": 3000, "temperature_c": 400})
            ),
            vec!["/temperature_c"]
        );
    }
}
