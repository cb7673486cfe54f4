//! `POST /v1/thrust-bearings/parasitic-losses`: the power a bearing loses outside its oil films
//! (Khonsari & Booser §7.10, after Booser and Missana 1990) — the turbulent drag of oil on the
//! wetted rotating surfaces (Eq. 7.17 with f = 0.016/Re^0.25, Eq. 7.18) and the through-flow
//! loss of the feed oil accelerated to a surface speed (Eq. 7.16); Ex 7.6 reproduced.
//!
//! SI throughout: ρ is the mass density, so the texts' ρV²/2g (ρ a weight density) is ρV²/2
//! here, and Re = ρVh/μ.

use std::f64::consts::PI;

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use crate::calc::lubricant::{validity, Lubricant, LubricantSpec};
use crate::calc::quantity::{Celsius, Positive};
use crate::calc::turbulence::surface_drag_friction_factor;
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::fidelity::Level;

pub struct ParasiticLosses;

/// Below this Reynolds number the flow in a gap is not the turbulent channel flow Eq. 7.18
/// describes (the 2000 of channel flow; the texts' laminar thrust films turn turbulent at
/// 580–1200 on a pad's own scale).
const TURBULENT_FROM_RE: f64 = 2000.0;
/// Ranges: speed (rpm), sizes and gaps (m), flow (m³/s), velocity heads (the texts' tests
/// gave 1.5–3.2).
const MAX_SPEED_RPM: f64 = 1e6;
const SIZE_RANGE: (f64, f64) = (1e-4, 10.0);
const GAP_RANGE: (f64, f64) = (1e-6, 1.0);
const MAX_FLOW_M3_S: f64 = 10.0;
const MAX_VELOCITY_HEADS: f64 = 10.0;
const MAX_SURFACES: usize = 16;

/// A wetted rotating surface and its gap to the stationary wall beside it.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum SurfaceSpec {
    /// The cylindrical rim of a runner in a casing: surface speed V = πDN over the area
    /// πD·width (Ex 7.6). Eq. 7.18's drag only: for annular spaces round a journal the texts
    /// raise f by 30–40 % (Vohr's Eq. 7.19), which is not applied.
    Rim {
        /// Rim (runner outer) diameter D, m (1e-4 … 10).
        #[schema(value_type = f64, minimum = 1e-4, maximum = 10.0, example = 0.381)]
        diameter_m: Positive,
        /// Axial width of the rim, m (1e-4 … 10).
        #[schema(value_type = f64, minimum = 1e-4, maximum = 10.0, example = 0.0762)]
        width_m: Positive,
        /// Radial gap h between the rim and the casing, m (1e-6 … 1).
        #[schema(value_type = f64, minimum = 1e-6, maximum = 1.0, example = 0.00635)]
        gap_m: Positive,
    },
    /// A flat annular face of a runner: Eq. 7.17 applied ring by ring over the radius, each
    /// ring at its own speed ωr and Reynolds number ρωrh/μ — an extension of §7.10, which
    /// treats the rim.
    Face {
        /// Inner diameter of the wetted annulus, m (0 … outer).
        #[schema(value_type = f64, minimum = 0.0, maximum = 10.0, example = 0.15)]
        inner_diameter_m: f64,
        /// Outer diameter, m (1e-4 … 10).
        #[schema(value_type = f64, minimum = 1e-4, maximum = 10.0, example = 0.381)]
        outer_diameter_m: Positive,
        /// Axial gap h between the face and the wall it faces, m (1e-6 … 1).
        #[schema(value_type = f64, minimum = 1e-6, maximum = 1.0, example = 0.01)]
        gap_m: Positive,
    },
}

/// Feed oil accelerated to a surface speed.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct ThroughFlowSpec {
    /// Feed flow Q, m³/s (0 … 10).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 10.0, example = 0.006309)]
    pub flow_m3_s: Positive,
    /// Diameter whose surface speed V the oil is brought to, m (1e-4 … 10).
    #[schema(value_type = f64, minimum = 1e-4, maximum = 10.0, example = 0.381)]
    pub diameter_m: Positive,
    /// Velocity heads k lost (0 … 10, default 1, one acceleration as in Ex 7.6): a whole
    /// bearing loses more — 1.6–1.9 measured over tapered-land and pivoted-pad thrust bearings,
    /// 1.5–3.2 over journal bearings (§7.10).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 1.0)]
    pub velocity_heads: Option<Positive>,
}

/// Request.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct ParasiticLossesInput {
    /// Shaft speed N, rev/min (> 0, at most 1e6).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 1e6, example = 10000.0)]
    pub speed_rpm: Positive,
    /// The oil (its viscosity and density at `temperature_c`).
    pub lubricant: LubricantSpec,
    /// Oil temperature, °C: required by a temperature-dependent viscosity; a constant one
    /// takes its density at 20 °C when it is absent.
    #[schema(value_type = Option<f64>, minimum = -273.0, maximum = 1000.0, example = 15.0)]
    pub temperature_c: Option<Celsius>,
    /// The wetted rotating surfaces (up to 16; default none).
    #[serde(default)]
    #[schema(example = json!([{"kind": "rim", "diameter_m": 0.381, "width_m": 0.0762, "gap_m": 0.00635}]))]
    pub surfaces: Vec<SurfaceSpec>,
    /// The feed oil's through-flow loss, if any.
    pub through_flow: Option<ThroughFlowSpec>,
}

/// A surface checked, in radii and gaps (m).
#[derive(Debug, Clone, Copy, PartialEq)]
enum Surface {
    Rim { radius: f64, width: f64, gap: f64 },
    Face { inner: f64, outer: f64, gap: f64 },
}

/// The parsed request.
#[derive(Debug, Clone)]
pub struct ParasiticCase {
    omega: f64,
    lubricant: Lubricant,
    temperature_c: f64,
    surfaces: Vec<Surface>,
    /// (Q, radius, k).
    through_flow: Option<(f64, f64, f64)>,
}

impl Validate for ParasiticLossesInput {
    type Valid = ParasiticCase;
    fn validate(self) -> Result<ParasiticCase, Vec<FieldError>> {
        let mut errors = Vec::new();
        let rpm = self.speed_rpm.get();
        FieldError::check_at_most(&mut errors, "/speed_rpm", rpm, MAX_SPEED_RPM);
        if self.surfaces.is_empty() && self.through_flow.is_none() {
            errors.push(FieldError::new(
                "/surfaces",
                "give at least one wetted surface or a through_flow",
            ));
        }
        if self.surfaces.len() > MAX_SURFACES {
            errors.push(FieldError::new(
                "/surfaces",
                format!("at most {MAX_SURFACES} surfaces"),
            ));
        }
        let mut surfaces = Vec::new();
        for (n, surface) in self.surfaces.iter().enumerate() {
            let at = |field: &str| format!("/surfaces/{n}/{field}");
            match *surface {
                SurfaceSpec::Rim {
                    diameter_m,
                    width_m,
                    gap_m,
                } => {
                    FieldError::check_within(
                        &mut errors,
                        at("diameter_m"),
                        diameter_m.get(),
                        SIZE_RANGE,
                    );
                    FieldError::check_within(&mut errors, at("width_m"), width_m.get(), SIZE_RANGE);
                    FieldError::check_within(&mut errors, at("gap_m"), gap_m.get(), GAP_RANGE);
                    surfaces.push(Surface::Rim {
                        radius: 0.5 * diameter_m.get(),
                        width: width_m.get(),
                        gap: gap_m.get(),
                    });
                }
                SurfaceSpec::Face {
                    inner_diameter_m,
                    outer_diameter_m,
                    gap_m,
                } => {
                    let outer = outer_diameter_m.get();
                    FieldError::check_within(
                        &mut errors,
                        at("outer_diameter_m"),
                        outer,
                        SIZE_RANGE,
                    );
                    if !(0.0..outer).contains(&inner_diameter_m) {
                        errors.push(FieldError::new(
                            at("inner_diameter_m"),
                            format!("must be within [0, outer_diameter_m = {outer}), got {inner_diameter_m}"),
                        ));
                    }
                    FieldError::check_within(&mut errors, at("gap_m"), gap_m.get(), GAP_RANGE);
                    surfaces.push(Surface::Face {
                        inner: 0.5 * inner_diameter_m,
                        outer: 0.5 * outer,
                        gap: gap_m.get(),
                    });
                }
            }
        }
        let through_flow = self.through_flow.map(|t| {
            FieldError::check_at_most(
                &mut errors,
                "/through_flow/flow_m3_s",
                t.flow_m3_s.get(),
                MAX_FLOW_M3_S,
            );
            FieldError::check_within(
                &mut errors,
                "/through_flow/diameter_m",
                t.diameter_m.get(),
                SIZE_RANGE,
            );
            let k = t.velocity_heads.map_or(1.0, Positive::get);
            FieldError::check_at_most(
                &mut errors,
                "/through_flow/velocity_heads",
                k,
                MAX_VELOCITY_HEADS,
            );
            (t.flow_m3_s.get(), 0.5 * t.diameter_m.get(), k)
        });
        let oil = match self.lubricant.parse("/lubricant") {
            Ok(lubricant) => {
                match validity::operating_temperature(&lubricant, self.temperature_c) {
                    Ok(t) => Some((lubricant, t)),
                    Err(e) => {
                        errors.push(e);
                        None
                    }
                }
            }
            Err(mut e) => {
                errors.append(&mut e);
                None
            }
        };
        match (errors.is_empty(), oil) {
            (true, Some((lubricant, temperature_c))) => Ok(ParasiticCase {
                omega: rpm * PI / 30.0,
                lubricant,
                temperature_c,
                surfaces,
                through_flow,
            }),
            _ => Err(errors),
        }
    }
}

/// One surface's drag loss.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct SurfaceDrag {
    /// `rim` or `face`.
    pub kind: &'static str,
    /// Surface speed V, m/s: the rim's, or the face's outer edge's.
    pub surface_speed_m_s: f64,
    /// Re = ρVh/μ at that speed.
    pub reynolds_number: f64,
    /// f = 0.016/Re^0.25 at that speed (Eq. 7.18).
    pub friction_factor: f64,
    /// Wetted area, m².
    pub area_m2: f64,
    /// Drag power E_p, W: f(ρV²/2)V A (Eq. 7.17), over the face integrated ring by ring.
    pub power_w: f64,
}

/// The feed oil's through-flow loss.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct ThroughFlowLoss {
    /// The surface speed V the oil is brought to, m/s.
    pub surface_speed_m_s: f64,
    /// E_p = k Q ρV²/2, W (Eq. 7.16).
    pub power_w: f64,
}

/// Result.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct ParasiticLossesOutput {
    /// Each surface's drag, in the order sent.
    pub surfaces: Vec<SurfaceDrag>,
    /// Σ of the surfaces' drag power, W.
    pub drag_power_w: f64,
    /// The through-flow loss, when `through_flow` is given.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub through_flow: Option<ThroughFlowLoss>,
    /// Drag plus through-flow, W.
    pub total_power_w: f64,
    /// The oil's viscosity at `temperature_c`, Pa·s.
    pub viscosity_pa_s: f64,
    /// The oil's density at `temperature_c`, kg/m³.
    pub density_kg_m3: f64,
}

/// The oil's viscosity and density at the request's temperature.
#[derive(Debug, Clone, Copy)]
struct Oil {
    viscosity: f64,
    density: f64,
}

impl Oil {
    /// Re = ρVh/μ.
    fn reynolds(self, speed: f64, gap: f64) -> f64 {
        self.density * speed * gap / self.viscosity
    }

    /// Drag power per unit area at surface speed V over gap h: f(ρV²/2)V with Eq. 7.18's f.
    fn drag_per_area(self, speed: f64, gap: f64) -> f64 {
        surface_drag_friction_factor(self.reynolds(speed, gap)) * 0.5 * self.density * speed.powi(3)
    }
}

impl Surface {
    /// The surface's drag at angular speed ω.
    fn drag(self, oil: Oil, omega: f64) -> SurfaceDrag {
        match self {
            Surface::Rim { radius, width, gap } => {
                let speed = omega * radius;
                let area = 2.0 * PI * radius * width;
                let re = oil.reynolds(speed, gap);
                SurfaceDrag {
                    kind: "rim",
                    surface_speed_m_s: speed,
                    reynolds_number: re,
                    friction_factor: surface_drag_friction_factor(re),
                    area_m2: area,
                    power_w: oil.drag_per_area(speed, gap) * area,
                }
            }
            Surface::Face { inner, outer, gap } => {
                // dE = f(ρ(ωr)²/2)ωr 2πr dr with f ∝ r^−¼: the power is the outer edge's
                // per-area value times 2π∫r^(15/4) dr / r_o^(11/4), exactly.
                let speed = omega * outer;
                let re = oil.reynolds(speed, gap);
                let integral = (outer.powf(4.75) - inner.powf(4.75)) / 4.75;
                SurfaceDrag {
                    kind: "face",
                    surface_speed_m_s: speed,
                    reynolds_number: re,
                    friction_factor: surface_drag_friction_factor(re),
                    area_m2: PI * (outer * outer - inner * inner),
                    power_w: oil.drag_per_area(speed, gap) * 2.0 * PI * integral / outer.powf(2.75),
                }
            }
        }
    }
}

impl Calculation for ParasiticLosses {
    const PATH: &'static str = "/v1/thrust-bearings/parasitic-losses";
    const SUMMARY: &'static str =
        "Parasitic power losses: turbulent drag on wetted rotating surfaces (rims, faces) and the feed oil's through-flow loss";
    const DESCRIPTION: &'static str = include_str!("parasitic.md");
    const FIDELITY: &'static [Level] = &[Level::ClosedForm];
    const EFFECTS: &'static [&'static str] = &[];
    const EXAMPLE: &'static str = r#"{"speed_rpm": 10000, "lubricant": {"viscosity_pa_s": 0.01379, "density_15c_kg_m3": 849.8}, "temperature_c": 15, "surfaces": [{"kind": "rim", "diameter_m": 0.381, "width_m": 0.0762, "gap_m": 0.00635}], "through_flow": {"flow_m3_s": 0.006309, "diameter_m": 0.381, "velocity_heads": 1.0}}"#;

    type Input = ParasiticLossesInput;
    type Output = ParasiticLossesOutput;

    fn run(case: ParasiticCase, ctx: &mut Context) -> Result<ParasiticLossesOutput, CalcError> {
        validity::check_temperatures(ctx, &case.lubricant, &[case.temperature_c])?;
        validity::warn_hot_oil(ctx, "the oil", case.temperature_c);
        let oil = Oil {
            viscosity: case.lubricant.viscosity_pa_s(case.temperature_c),
            density: case.lubricant.density_kg_m3(case.temperature_c),
        };
        if !(oil.viscosity.is_finite() && oil.viscosity > 0.0 && oil.density > 0.0) {
            return Err(CalcError::impossible(
                "/temperature_c",
                format!("the lubricant has no usable viscosity and density at {} °C (μ = {:e} Pa·s, ρ = {:e} kg/m³)", case.temperature_c, oil.viscosity, oil.density),
            ));
        }
        let surfaces: Vec<SurfaceDrag> = case
            .surfaces
            .iter()
            .map(|s| s.drag(oil, case.omega))
            .collect();
        for (n, s) in surfaces.iter().enumerate() {
            if s.reynolds_number < TURBULENT_FROM_RE {
                ctx.warn(
                    "drag_not_turbulent",
                    format!("surface {n}: Re = {:.0} is below {TURBULENT_FROM_RE:.0}, where the gap's flow is not the turbulent channel flow Eq. 7.18 describes (for a face, at its outer edge; inner rings are slower still): the drag is an estimate", s.reynolds_number),
                );
            }
        }
        let through_flow = case.through_flow.map(|(flow, radius, k)| {
            let speed = case.omega * radius;
            ThroughFlowLoss {
                surface_speed_m_s: speed,
                power_w: k * flow * 0.5 * oil.density * speed * speed,
            }
        });
        let drag_power_w: f64 = surfaces.iter().map(|s| s.power_w).sum();
        let total_power_w = drag_power_w + through_flow.as_ref().map_or(0.0, |t| t.power_w);
        CalcError::finite_or_out_of_range(
            ParasiticLossesOutput {
                surfaces,
                drag_power_w,
                through_flow,
                total_power_w,
                viscosity_pa_s: oil.viscosity,
                density_kg_m3: oil.density,
            },
            "speed_rpm, the diameters and gaps, and the lubricant",
        )
    }
}

#[cfg(test)]
#[path = "parasitic_tests.rs"]
mod tests;
