//! `POST /v1/lubricants/viscosity-index`: ASTM D2270 viscosity index from the kinematic
//! viscosities at 40 and 100 °C (Khonsari & Booser Eq. 2.6, 2.7; Stachowiak & Batchelor §2.4).

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::astm_d2270;
use super::spec::LubricantSpec;
use crate::calc::quantity::Positive;
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::fidelity::Level;

pub struct ViscosityIndex;

/// Request: the two kinematic viscosities, or a lubricant whose law gives them.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct ViscosityIndexInput {
    /// Kinematic viscosity at 40 °C, mm²/s (cSt), > 0 and above the 100 °C value.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e6, example = 73.3)]
    pub kinematic_viscosity_40c_mm2_s: Option<Positive>,
    /// Kinematic viscosity at 100 °C, mm²/s (cSt), at least 2 (ASTM D2270's range).
    #[schema(value_type = Option<f64>, minimum = 2.0, maximum = 1e5, example = 8.86)]
    pub kinematic_viscosity_100c_mm2_s: Option<Positive>,
    /// Instead of the two viscosities: a lubricant, evaluated at 40 and 100 °C.
    pub lubricant: Option<LubricantSpec>,
}

/// The validated case: ν40 and ν100 in mm²/s.
#[derive(Debug, Clone, Copy)]
pub struct ViscosityIndexCase {
    pub nu40: f64,
    pub nu100: f64,
}

impl Validate for ViscosityIndexInput {
    type Valid = ViscosityIndexCase;
    fn validate(self) -> Result<ViscosityIndexCase, Vec<FieldError>> {
        let (nu40, nu100, at) = match (self.kinematic_viscosity_40c_mm2_s, self.kinematic_viscosity_100c_mm2_s, self.lubricant) {
            (Some(a), Some(b), None) => (a.get(), b.get(), "/kinematic_viscosity_100c_mm2_s"),
            (None, None, Some(l)) => {
                let lub = l.parse("/lubricant")?;
                (lub.kinematic_mm2_s(40.0), lub.kinematic_mm2_s(100.0), "/lubricant")
            }
            _ => {
                return Err(vec![FieldError::new(
                    "",
                    "give kinematic_viscosity_40c_mm2_s with kinematic_viscosity_100c_mm2_s, or lubricant",
                )])
            }
        };
        if nu100.is_nan() || nu100 < astm_d2270::LOWEST_NU100_MM2_S || !nu100.is_finite() {
            return Err(vec![FieldError::new(
                at,
                format!(
                    "ASTM D2270 needs ν100 ≥ {} mm²/s, got {nu100}",
                    astm_d2270::LOWEST_NU100_MM2_S
                ),
            )]);
        }
        if self.kinematic_viscosity_40c_mm2_s.is_some() && nu40 > 1e6 {
            return Err(vec![FieldError::new(
                "/kinematic_viscosity_40c_mm2_s",
                format!("must be at most 1e6 mm²/s, got {nu40}"),
            )]);
        }
        if nu40.is_nan() || nu40 <= nu100 || !nu40.is_finite() || nu40 > 1e6 || nu100 > 1e5 {
            return Err(vec![FieldError::new(
                at,
                format!("need ν100 < ν40 (ν40 ≤ 1e6, ν100 ≤ 1e5 mm²/s), got ν40 = {nu40}, ν100 = {nu100}"),
            )]);
        }
        Ok(ViscosityIndexCase { nu40, nu100 })
    }
}

/// Result.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct ViscosityIndexOutput {
    /// Viscosity index, dimensionless, unrounded.
    #[schema(example = 92.4)]
    pub viscosity_index: f64,
    /// Viscosity index rounded as ASTM D2270 reports it: nearest whole number, halves to even.
    #[schema(example = 92)]
    pub viscosity_index_rounded: i64,
    /// L: ν40 of the VI = 0 reference oil with this oil's ν100, mm²/s.
    pub l_mm2_s: f64,
    /// H: ν40 of the VI = 100 reference oil with this oil's ν100, mm²/s.
    pub h_mm2_s: f64,
    /// `a` (ν40 ≥ H, VI ≤ 100: VI = 100 (L − U)/(L − H)) or `b` (ν40 < H, VI > 100: N = log(H/U)/log Y, VI = (10^N − 1)/0.00715 + 100).
    #[schema(example = "a")]
    pub procedure: String,
    /// ν40 used, mm²/s.
    pub kinematic_viscosity_40c_mm2_s: f64,
    /// ν100 used, mm²/s.
    pub kinematic_viscosity_100c_mm2_s: f64,
    /// VTC = 1 − ν100/ν40, dimensionless (Khonsari & Booser Eq. 2.8).
    pub viscosity_temperature_coefficient: f64,
}

impl Calculation for ViscosityIndex {
    const PATH: &'static str = "/v1/lubricants/viscosity-index";
    const SUMMARY: &'static str = "Viscosity index by ASTM D2270 (procedures A and B)";
    const DESCRIPTION: &'static str = include_str!("viscosity_index.md");
    const FIDELITY: &'static [Level] = &[Level::ClosedForm];
    const EFFECTS: &'static [&'static str] = &[];
    const EXAMPLE: &'static str =
        r#"{"kinematic_viscosity_40c_mm2_s": 73.3, "kinematic_viscosity_100c_mm2_s": 8.86}"#;

    type Input = ViscosityIndexInput;
    type Output = ViscosityIndexOutput;

    fn run(case: ViscosityIndexCase, ctx: &mut Context) -> Result<ViscosityIndexOutput, CalcError> {
        let vi = astm_d2270::viscosity_index(case.nu40, case.nu100);
        if !vi.value.is_finite() {
            return Err(CalcError::impossible(
                "",
                "the viscosity index is not finite for these viscosities",
            ));
        }
        if vi.value < 0.0 {
            ctx.warn(
                "negative_viscosity_index",
                "the oil thins faster with temperature than the VI = 0 reference oil",
            );
        }
        Ok(ViscosityIndexOutput {
            viscosity_index: vi.value,
            viscosity_index_rounded: astm_d2270::rounded(vi.value),
            l_mm2_s: vi.l,
            h_mm2_s: vi.h,
            procedure: if vi.procedure_b { "b" } else { "a" }.to_owned(),
            kinematic_viscosity_40c_mm2_s: case.nu40,
            kinematic_viscosity_100c_mm2_s: case.nu100,
            viscosity_temperature_coefficient: 1.0 - case.nu100 / case.nu40,
        })
    }
}
