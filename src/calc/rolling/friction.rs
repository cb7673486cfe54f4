//! `POST /v1/rolling-bearings/friction`: friction moment and power loss of a rolling bearing by
//! the components of Khonsari & Booser §15.2 (Eq. 15.1–15.5): M = M_P + M_L + M_S with
//! - load term M_P = ½ μ P d (Eq. 15.1/15.2; μ the bearing type's constant friction coefficient,
//!   Table 15.1; P the equivalent load; d the bore);
//! - lubricant term M_L = 10⁻⁷ f_L (ν n)^{2/3} d_m³ for ν n ≥ 2000, 160·10⁻⁷ f_L d_m³ below
//!   (Eq. 15.3/15.4; ν in mm²/s at the operating temperature — the base oil's for grease — n in
//!   rpm, d_m = (d + D)/2 in mm, M in N·mm; f_L from Table 15.2);
//! - seal term M_S = ((d + D)/f1)² + f2 for two rubbing seals (Eq. 15.5, Table 15.3).

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use crate::calc::quantity::{NonNegative, Positive};
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::fidelity::Level;

pub struct Friction;

/// The seal factors Table 15.3 lists: f1 from 10 (full-complement cylindrical 2LS) to 20
/// (deep-groove 2RS1 and most others), f2 from 10 to 50 N·mm.
const SEAL_F1: (f64, f64) = (10.0, 20.0);
const SEAL_F2: (f64, f64) = (10.0, 50.0);

/// Two rubbing seals' factors (Khonsari & Booser Table 15.3).
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct SealFactors {
    /// f1, dimensionless (0.1 … 1000; e.g. 20 for deep-groove 2RS1).
    #[schema(value_type = f64, minimum = 0.1, maximum = 1000.0, example = 20.0)]
    pub f1: Positive,
    /// f2, N·mm (e.g. 10 for deep-groove 2RS1).
    #[schema(value_type = f64, minimum = 0.0, maximum = 1e6, example = 10.0)]
    pub f2: NonNegative,
}

/// Request.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct FrictionInput {
    /// Bore d, m (> 0, at most 10).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 10.0, example = 0.1)]
    pub bore_diameter_m: Positive,
    /// Outside diameter D, m (> bore, at most 20).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 20.0, example = 0.18)]
    pub outside_diameter_m: Positive,
    /// Speed n, rev/min (> 0, at most 1e6).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 1e6, example = 10000.0)]
    pub speed_rpm: Positive,
    /// Equivalent load P, N (≥ 0).
    #[schema(value_type = f64, minimum = 0.0, maximum = 1e12, example = 26700.0)]
    pub equivalent_load_n: NonNegative,
    /// Constant friction coefficient μ of the bearing type, dimensionless (Table 15.1: about
    /// 0.0015 deep-groove ball, 0.002 angular contact, 0.0011 cylindrical roller; 0 … 0.1).
    #[schema(minimum = 0.0, maximum = 0.1, example = 0.002)]
    pub friction_coefficient: f64,
    /// Lubrication factor f_L, dimensionless (Table 15.2, by bearing type and grease / oil spot /
    /// oil bath / vertical bath or jet; 0 … 100).
    #[schema(minimum = 0.0, maximum = 100.0, example = 6.6)]
    pub lubrication_factor: f64,
    /// Kinematic viscosity ν at the operating temperature, mm²/s (base oil for grease; 0.1 … 1e5).
    #[schema(value_type = f64, minimum = 0.1, maximum = 1e5, example = 6.0)]
    pub operating_viscosity_mm2_s: Positive,
    /// Two rubbing seals; absent for open or shielded bearings.
    pub seals: Option<SealFactors>,
}

/// The validated case, in the formulas' units (mm, rpm, N).
#[derive(Debug, Clone, Copy)]
pub struct FrictionCase {
    d_mm: f64,
    outer_mm: f64,
    speed_rpm: f64,
    load_n: f64,
    mu: f64,
    f_l: f64,
    nu: f64,
    seals: Option<(f64, f64)>,
}

impl Validate for FrictionInput {
    type Valid = FrictionCase;
    fn validate(self) -> Result<FrictionCase, Vec<FieldError>> {
        let mut errors = Vec::new();
        let (d, outer) = (self.bore_diameter_m.get(), self.outside_diameter_m.get());
        if d > 10.0 {
            errors.push(FieldError::new("/bore_diameter_m", "must be at most 10 m"));
        } else if outer <= d || outer > 20.0 {
            errors.push(FieldError::new(
                "/outside_diameter_m",
                "must exceed the bore and be at most 20 m",
            ));
        }
        if !(0.0..=0.1).contains(&self.friction_coefficient) {
            errors.push(FieldError::new(
                "/friction_coefficient",
                "must be within [0, 0.1]",
            ));
        }
        if !(0.0..=100.0).contains(&self.lubrication_factor) {
            errors.push(FieldError::new(
                "/lubrication_factor",
                "must be within [0, 100]",
            ));
        }
        if self.speed_rpm.get() > 1e6 {
            errors.push(FieldError::new("/speed_rpm", "must be at most 1e6 rev/min"));
        }
        if self.equivalent_load_n.get() > 1e12 {
            errors.push(FieldError::new(
                "/equivalent_load_n",
                "must be at most 1e12 N",
            ));
        }
        let nu = self.operating_viscosity_mm2_s.get();
        if !(0.1..=1e5).contains(&nu) {
            errors.push(FieldError::new(
                "/operating_viscosity_mm2_s",
                "must be within [0.1, 1e5] mm²/s",
            ));
        }
        if let Some(s) = self.seals {
            if !(0.1..=1000.0).contains(&s.f1.get()) {
                errors.push(FieldError::new("/seals/f1", "must be within [0.1, 1000]"));
            }
            if s.f2.get() > 1e6 {
                errors.push(FieldError::new("/seals/f2", "must be at most 1e6 N·mm"));
            }
        }
        if !errors.is_empty() {
            return Err(errors);
        }
        Ok(FrictionCase {
            d_mm: d * 1e3,
            outer_mm: outer * 1e3,
            speed_rpm: self.speed_rpm.get(),
            load_n: self.equivalent_load_n.get(),
            mu: self.friction_coefficient,
            f_l: self.lubrication_factor,
            nu,
            seals: self.seals.map(|s| (s.f1.get(), s.f2.get())),
        })
    }
}

/// Result.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct FrictionOutput {
    /// Load term M_P = ½ μ P d, N·m.
    pub load_moment_n_m: f64,
    /// Lubricant (viscous) term M_L, N·m.
    pub lubricant_moment_n_m: f64,
    /// Seal term M_S, N·m (0 without rubbing seals).
    pub seal_moment_n_m: f64,
    /// Total friction moment M, N·m.
    pub friction_moment_n_m: f64,
    /// Power loss 2π (n/60) M, W.
    pub power_loss_w: f64,
    /// ν n, mm²/s · rev/min: which branch of M_L applied (≥ 2000 the (ν n)^{2/3} law).
    pub viscosity_speed_product: f64,
    /// Pitch diameter d_m = (d + D)/2, m.
    pub pitch_diameter_m: f64,
}

impl Calculation for Friction {
    const PATH: &'static str = "/v1/rolling-bearings/friction";
    const SUMMARY: &'static str =
        "Friction moment and power loss of a rolling bearing (load, lubricant and seal terms)";
    const DESCRIPTION: &'static str = include_str!("friction.md");
    const FIDELITY: &'static [Level] = &[Level::ClosedForm];
    const EFFECTS: &'static [&'static str] = &[];
    const EXAMPLE: &'static str = r#"{"bore_diameter_m": 0.1, "outside_diameter_m": 0.18, "speed_rpm": 10000, "equivalent_load_n": 26700, "friction_coefficient": 0.002, "lubrication_factor": 6.6, "operating_viscosity_mm2_s": 6.0}"#;

    type Input = FrictionInput;
    type Output = FrictionOutput;

    fn run(c: FrictionCase, ctx: &mut Context) -> Result<FrictionOutput, CalcError> {
        if let Some((f1, f2)) = c.seals {
            if !(SEAL_F1.0..=SEAL_F1.1).contains(&f1) || !(SEAL_F2.0..=SEAL_F2.1).contains(&f2) {
                ctx.warn(
                    "seal_factors_outside_catalogue",
                    format!("f1 = {f1}, f2 = {f2} N·mm lie outside Table 15.3's seal factors (f1 {}–{}, f2 {}–{} N·mm, Khonsari & Booser): the seal torque ((d + D)/f1)² + f2 is extrapolated", SEAL_F1.0, SEAL_F1.1, SEAL_F2.0, SEAL_F2.1),
                );
            }
        }
        let d_m = 0.5 * (c.d_mm + c.outer_mm);
        let nu_n = c.nu * c.speed_rpm;
        let m_p = 0.5 * c.mu * c.load_n * c.d_mm;
        let m_l = if nu_n >= 2000.0 {
            1e-7 * c.f_l * nu_n.powf(2.0 / 3.0) * d_m.powi(3)
        } else {
            160e-7 * c.f_l * d_m.powi(3)
        };
        let m_s = c
            .seals
            .map_or(0.0, |(f1, f2)| ((c.d_mm + c.outer_mm) / f1).powi(2) + f2);
        let total = (m_p + m_l + m_s) * 1e-3; // N·mm → N·m
        Ok(FrictionOutput {
            load_moment_n_m: m_p * 1e-3,
            lubricant_moment_n_m: m_l * 1e-3,
            seal_moment_n_m: m_s * 1e-3,
            friction_moment_n_m: total,
            power_loss_w: 2.0 * std::f64::consts::PI * c.speed_rpm / 60.0 * total,
            viscosity_speed_product: nu_n,
            pitch_diameter_m: d_m * 1e-3,
        })
    }
}

#[cfg(test)]
mod tests {
    use serde_json::json;

    use super::*;
    use crate::calc::testing::{
        assert_rel, invalid_pointers, ok, result_field as get, warning_codes,
    };

    /// Khonsari & Booser Ex 15.2 (spec FE-2, recomputed): 7220 jet-lubricated, d = 100,
    /// D = 180 mm, 10 000 rpm, F_a = 26 700 N, ν = 6 mm²/s, μ = 0.002, f_L = 6.6:
    /// M_P = 2670, M_L = 2775.6, M = 5445.6 N·mm (the text cites Eq. 15.4 but evaluates 15.3).
    #[test]
    fn example_15_2() {
        let v = ok::<Friction>(&serde_json::from_str(Friction::EXAMPLE).unwrap());
        assert_rel(get(&v, "load_moment_n_m"), 2.670, 1e-9, "M_P");
        assert_rel(get(&v, "lubricant_moment_n_m"), 2.7756, 5e-4, "M_L");
        assert_rel(get(&v, "friction_moment_n_m"), 5.4456, 5e-4, "M");
    }

    /// Khonsari & Booser Ex 15.1 (spec FE-1): 306 deep-groove bearing, d = 30 mm, 3600 rpm,
    /// P = 712 N, μ = 0.0015: M_P = 16.02 N·mm, power 6.04 W (the load term alone: f_L = 0).
    #[test]
    fn example_15_1_load_term() {
        let v = ok::<Friction>(
            &json!({"bore_diameter_m": 0.03, "outside_diameter_m": 0.072, "speed_rpm": 3600,
            "equivalent_load_n": 712, "friction_coefficient": 0.0015, "lubrication_factor": 0.0, "operating_viscosity_mm2_s": 20}),
        );
        assert_rel(get(&v, "friction_moment_n_m"), 0.01602, 1e-3, "M");
        assert_rel(get(&v, "power_loss_w"), 6.04, 2e-3, "power");
    }

    /// The two branches of M_L meet at ν n = 2000 to 0.8 % (2000^{2/3} = 158.7 against 160, spec H-17).
    #[test]
    fn lubricant_branches_meet() {
        let at = |nu: f64| {
            let v = ok::<Friction>(
                &json!({"bore_diameter_m": 0.05, "outside_diameter_m": 0.09, "speed_rpm": 1000,
                "equivalent_load_n": 0, "friction_coefficient": 0.0, "lubrication_factor": 2.0, "operating_viscosity_mm2_s": nu}),
            );
            get(&v, "lubricant_moment_n_m")
        };
        assert_rel(at(1.999_999), at(2.0), 0.009, "continuity at ν n = 2000");
    }

    #[test]
    fn seals_add_their_moment_and_bad_input_is_named() {
        let base = json!({"bore_diameter_m": 0.05, "outside_diameter_m": 0.09, "speed_rpm": 1500,
            "equivalent_load_n": 1000, "friction_coefficient": 0.0015, "lubrication_factor": 2.0, "operating_viscosity_mm2_s": 30});
        let mut sealed = base.clone();
        sealed["seals"] = json!({"f1": 20, "f2": 10});
        let m_s = get(&ok::<Friction>(&sealed), "seal_moment_n_m");
        assert_rel(
            m_s,
            (((50.0 + 90.0) / 20.0f64).powi(2) + 10.0) * 1e-3,
            1e-12,
            "M_S",
        );
        assert!(warning_codes(&ok::<Friction>(&sealed)).is_empty());
        let mut bad = base.clone();
        bad["outside_diameter_m"] = json!(0.04);
        assert_eq!(
            invalid_pointers::<Friction>(&bad),
            vec!["/outside_diameter_m"]
        );
    }

    /// Issue 12, item 4: f1 = 0.05 was accepted under a schema minimum of 0.1, and f1 = 0.1
    /// (7.8 kN·m here) came back without a word. Each factor is refused at its own pointer;
    /// factors outside Table 15.3's (f1 10–20, f2 10–50 N·mm) warn.
    #[test]
    fn seal_factors_follow_the_schema_and_the_catalogue() {
        let with = |f1: f64, f2: f64| {
            json!({"bore_diameter_m": 0.05, "outside_diameter_m": 0.09, "speed_rpm": 1500,
                "equivalent_load_n": 1000, "friction_coefficient": 0.0015, "lubrication_factor": 2.0,
                "operating_viscosity_mm2_s": 30, "seals": {"f1": f1, "f2": f2}})
        };
        assert_eq!(
            invalid_pointers::<Friction>(&with(0.05, 10.0)),
            vec!["/seals/f1"]
        );
        assert_eq!(
            invalid_pointers::<Friction>(&with(1001.0, 10.0)),
            vec!["/seals/f1"]
        );
        assert_eq!(
            invalid_pointers::<Friction>(&with(20.0, 2e6)),
            vec!["/seals/f2"]
        );
        for (f1, f2, warns) in [(0.1, 10.0, true), (10.0, 50.0, false), (20.0, 60.0, true)] {
            let codes = warning_codes(&ok::<Friction>(&with(f1, f2)));
            assert_eq!(
                codes.contains(&"seal_factors_outside_catalogue".to_owned()),
                warns,
                "f1 {f1}, f2 {f2}: {codes:?}"
            );
        }
    }
}
