//! `POST /v1/thrust-bearings/bearing`: a whole thrust bearing of fixed or tilting sector pads
//! under its total load — each pad solved at the mean radius as the texts' design procedure does
//! (Khonsari & Booser §7.2–7.5, Ex 7.1–7.3), the bearing's totals, and the design checks.

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::film;
use super::fixed_pad::{flat_land_warning, PadProfileSpec};
use super::operating::Given;
use super::pad::{self, RatioChoice, SolvedPad};
use super::pad_spec::{self, check_finite, conditions, PadEffects, PadResult, PadTurbulenceModel};
use super::performance::Method;
use super::pivot::Pivot;
use super::profile::Profile;
use super::sector::{allowable_film_m, PadType, Sectors};
use super::tilting_pad::PivotPosition;
use crate::calc::lubricant::LubricantSpec;
use crate::calc::quantity::{ratio_within, Celsius, Positive};
use crate::calc::range_schemas;
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::fidelity::{FidelityRequest, Level};

pub struct Bearing;

/// Fixed or tilting pads.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum PadsKind {
    /// Fixed pads of a `profile` (tapered land, step, …).
    Fixed,
    /// Plane pads tilting about a `pivot_position_fraction`.
    Tilting,
}

/// The pads.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct PadsSpec {
    pub kind: PadsKind,
    /// `fixed`: the film shape (as `/v1/thrust-bearings/fixed-pad`'s `profile`).
    pub profile: Option<PadProfileSpec>,
    /// `tilting`: the pivot, x/B from the leading edge, or `"optimum"`.
    #[schema(example = 0.6)]
    pub pivot_position_fraction: Option<PivotPosition>,
    /// Optional parabolic crown of each pad over its breadth, m (> 0, at most 1e-3): as the
    /// tilting pad's `crown_m` (a central pivot carries load) or, on fixed `plane_inclined`
    /// pads of a given `film_ratio` (from 1), the fixed pad's. Numerical fidelities only.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e-3, example = 2e-5)]
    pub crown_m: Option<Positive>,
}

/// Request.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct BearingInput {
    /// Bore of the pads R1, m (> 0, below `outer_radius_m`).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 5.0, example = 0.073)]
    pub inner_radius_m: Positive,
    /// Outside radius of the pads R2, m (at most 5).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 5.0, example = 0.16)]
    pub outer_radius_m: Positive,
    /// Number of pads (1 … 64).
    #[schema(minimum = 1, maximum = 64, example = 7)]
    pub pad_count: u32,
    /// Each pad's angle, degrees (default: 85 % of the annulus under pads, the rest feed
    /// grooves — k_g = 0.85 of Khonsari & Booser Eq. 7.1); the pads must fit in 360°.
    #[schema(exclusive_minimum = 0.0, maximum = 360.0, example = 43.7)]
    pub pad_angle_deg: Option<f64>,
    pub pads: PadsSpec,
    /// Shaft speed, rev/min (> 0, at most 1e6).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 1e6, example = 3600.0)]
    pub speed_rpm: Positive,
    /// Total thrust load W, N (1e-6 … 1e10), shared equally by the pads.
    #[schema(value_type = f64, minimum = 1e-6, maximum = 1e10, example = 111200.0)]
    pub load_n: Positive,
    pub lubricant: LubricantSpec,
    /// Oil inlet temperature, °C (default 40).
    #[schema(value_type = Option<f64>, minimum = -273.0, maximum = 1000.0, example = 49.0)]
    pub inlet_temperature_c: Option<Celsius>,
    /// Surface roughness Ra of the runner and of the pads, m: see
    /// [`range_schemas::roughness_pair`].
    #[schema(schema_with = range_schemas::roughness_pair)]
    pub surface_roughness_ra_m: Option<[f64; 2]>,
    /// The allowable minimum film, m, instead of the roughness rule.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e-3, example = 1.2e-5)]
    pub allowable_min_film_m: Option<Positive>,
    /// The highest film temperature allowed, °C (default 150: babbitt flows at about 150 °C,
    /// Khonsari & Booser §7.9).
    #[schema(value_type = Option<f64>, minimum = -273.0, maximum = 1000.0, example = 150.0)]
    pub max_temperature_limit_c: Option<Celsius>,
    /// `closed_form` (the infinitely long pad), `fast`, `standard` (default), `high`, or
    /// `{"grid": [cells along B 8…512, cells across half of L 2…256]}` for each pad's film.
    #[serde(default)]
    pub fidelity: FidelityRequest,
    #[serde(default)]
    pub effects: PadEffects,
    /// The turbulent film's law where the turbulence effect applies: `ng_pan` (default) or
    /// `missana` (Khonsari & Booser §7.11's f = 0.026/Re^0.25 and effective viscosity).
    #[serde(default)]
    pub turbulence_model: PadTurbulenceModel,
}

/// What the pads are.
#[derive(Debug, Clone, Copy)]
pub enum Pads {
    Fixed {
        profile: Profile,
        ratio: RatioChoice,
    },
    Tilting(Pivot),
}

/// The pads and their crown δ, m.
#[derive(Debug, Clone, Copy)]
pub struct CrownedPads {
    pub pads: Pads,
    pub crown_m: Option<f64>,
}

/// The parsed request.
#[derive(Debug, Clone)]
pub struct Case {
    pub sectors: Sectors,
    pub pads: CrownedPads,
    pub conditions: super::operating::Conditions,
    pub method: Method,
    pub allowable_film_m: f64,
    pub max_temperature_limit_c: f64,
}

impl Validate for BearingInput {
    type Valid = Case;
    fn validate(self) -> Result<Case, Vec<FieldError>> {
        let mut errors = Vec::new();
        let (r1, r2) = (self.inner_radius_m.get(), self.outer_radius_m.get());
        if r2 > 5.0 {
            errors.push(FieldError::new("/outer_radius_m", "must be at most 5 m"));
        }
        if r1 >= r2 {
            errors.push(FieldError::new(
                "/inner_radius_m",
                format!("must be below outer_radius_m ({r2} m), got {r1}"),
            ));
        }
        if !(1..=64).contains(&self.pad_count) {
            errors.push(FieldError::new("/pad_count", "must be within [1, 64]"));
        }
        let count = self.pad_count.clamp(1, 64);
        let angle = match self.pad_angle_deg {
            None => Sectors::default_angle_rad(count),
            Some(a) if a.is_finite() && a > 0.0 && a * count as f64 <= 360.0 => a.to_radians(),
            Some(a) => {
                errors.push(FieldError::new(
                    "/pad_angle_deg",
                    format!(
                        "must be above 0 with pad_count × angle at most 360°, got {a}° × {count}"
                    ),
                ));
                Sectors::default_angle_rad(count)
            }
        };
        let sectors = Sectors {
            inner_radius_m: r1,
            outer_radius_m: r2.max(r1 * 1.001),
            count,
            angle_rad: angle,
        };
        let pad = sectors.pad();
        let l_over_b = pad.l_over_b();
        if !ratio_within(l_over_b, 0.1, 10.0) {
            errors.push(FieldError::new(
                "/pad_angle_deg",
                format!("each pad's L/B = (R2 − R1)/(R_m β) must be within [0.1, 10], got {l_over_b:.4}"),
            ));
        }
        let method = pad_spec::method(self.fidelity, &mut errors);
        let crown_m = pad_spec::crown(self.pads.crown_m, "/pads/crown_m", method, &mut errors);
        let pads =
            match self.pads.kind {
                PadsKind::Fixed => {
                    if self.pads.pivot_position_fraction.is_some() {
                        errors.push(FieldError::new(
                            "/pads/pivot_position_fraction",
                            "applies only to tilting pads",
                        ));
                    }
                    match self.pads.profile {
                        Some(p) => {
                            let mut inner = Vec::new();
                            let (profile, ratio) = p.parse(crown_m.is_some(), &mut inner);
                            errors.extend(inner.into_iter().map(|e| {
                                FieldError::new(format!("/pads{}", e.pointer), e.message)
                            }));
                            Pads::Fixed { profile, ratio }
                        }
                        None => {
                            errors.push(FieldError::new(
                                "/pads/profile",
                                "fixed pads need their profile",
                            ));
                            Pads::Fixed {
                                profile: Profile::PlaneInclined { ratio: 2.0 },
                                ratio: RatioChoice::Given,
                            }
                        }
                    }
                }
                PadsKind::Tilting => {
                    if self.pads.profile.is_some() {
                        errors.push(FieldError::new(
                            "/pads/profile",
                            "tilting pads are plane: give pivot_position_fraction",
                        ));
                    }
                    Pads::Tilting(match self.pads.pivot_position_fraction {
                        Some(PivotPosition::Value(x)) if x.is_finite() && x > 0.0 && x <= 0.95 => {
                            Pivot::At(x)
                        }
                        Some(PivotPosition::Optimum(_)) => Pivot::Optimum,
                        Some(PivotPosition::Value(x)) => {
                            errors.push(FieldError::new(
                                "/pads/pivot_position_fraction",
                                format!("must be within (0, 0.95], got {x}"),
                            ));
                            Pivot::Optimum
                        }
                        None => {
                            errors.push(FieldError::new(
                                "/pads/pivot_position_fraction",
                                "tilting pads need their pivot",
                            ));
                            Pivot::Optimum
                        }
                    })
                }
            };
        if self.speed_rpm.get() > 1e6 {
            errors.push(FieldError::new("/speed_rpm", "must be at most 1e6 rev/min"));
        }
        let load = self.load_n.get();
        if !(1e-6..=1e10).contains(&load) {
            errors.push(FieldError::new(
                "/load_n",
                format!("must be within [1e-6, 1e10] N, got {load}"),
            ));
        }
        let roughness = self.surface_roughness_ra_m.unwrap_or([0.8e-6, 0.8e-6]);
        if roughness.iter().any(|r| !(0.0..=1e-4).contains(r)) {
            errors.push(FieldError::new(
                "/surface_roughness_ra_m",
                "each Ra must be within [0, 1e-4] m",
            ));
        }
        let allowable = match self.allowable_min_film_m {
            Some(h) if h.get() <= 1e-3 => h.get(),
            Some(h) => {
                errors.push(FieldError::new(
                    "/allowable_min_film_m",
                    format!("must be at most 1e-3 m, got {}", h.get()),
                ));
                1e-5
            }
            None => allowable_film_m(roughness),
        };
        let speed = sectors.sliding_speed_m_s(self.speed_rpm.get());
        let conditions = match Positive::try_from(speed) {
            Ok(u) => conditions(
                pad,
                u,
                self.lubricant,
                self.inlet_temperature_c,
                Given::Load(load / count as f64),
                self.effects.with_law(self.turbulence_model),
                &mut errors,
            ),
            Err(_) => {
                errors.push(FieldError::new(
                    "/speed_rpm",
                    format!("the runner speed at the mean radius underflows to {speed} m/s: the shaft must turn"),
                ));
                None
            }
        };
        // The runner speed is the bearing's speed at the mean radius: its limit is the speed's.
        for e in errors
            .iter_mut()
            .filter(|e| e.pointer == "/sliding_speed_m_s")
        {
            e.pointer = "/speed_rpm".to_owned();
            e.message = format!("the runner speed at the mean radius {}", e.message);
        }
        match conditions {
            Some(conditions) if errors.is_empty() => Ok(Case {
                sectors,
                pads: CrownedPads { pads, crown_m },
                conditions,
                method,
                allowable_film_m: allowable,
                max_temperature_limit_c: self.max_temperature_limit_c.map_or(150.0, Celsius::get),
            }),
            _ => Err(errors),
        }
    }
}

/// One design check of the texts' procedure.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct Check {
    /// `min_film`, `max_temperature`, `unit_load` or `temperature_rise`.
    pub name: &'static str,
    /// The bearing's value (SI units: m, °C, Pa, K).
    pub value: f64,
    /// The limit it is held to.
    pub limit: f64,
    /// Whether the value meets the limit.
    pub passed: bool,
    /// The rule and its source.
    pub rule: String,
}

/// Response.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct BearingOutput {
    /// R_m, m.
    pub mean_radius_m: f64,
    /// The equivalent pad's breadth B = R_m β along the runner, m.
    pub pad_breadth_m: f64,
    /// The equivalent pad's length L = R2 − R1, m.
    pub pad_length_m: f64,
    /// Each pad's angle, degrees.
    pub pad_angle_deg: f64,
    /// Runner speed at the mean radius U, m/s.
    pub sliding_speed_m_s: f64,
    /// W/N, N.
    pub load_per_pad_n: f64,
    /// Unit load W/(N B L), Pa.
    pub unit_load_pa: f64,
    /// The thinnest film, m: the trailing-edge film h2 but on crowned pads whose crown
    /// outweighs their tilt (then inside the pad).
    pub min_film_m: f64,
    /// h1/h2.
    pub film_ratio: f64,
    /// The tilting pads' pivot, x/B from the leading edge.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pivot_position_fraction: Option<f64>,
    /// The whole bearing's power loss, W.
    pub power_loss_w: f64,
    /// Friction torque on the runner, N·m.
    pub friction_torque_n_m: f64,
    /// Oil fed to all pads (their inlet flows), m³/s.
    pub inlet_flow_m3_s: f64,
    /// Side leakage of all pads, m³/s.
    pub side_flow_m3_s: f64,
    /// ΔT = E_p/(ρ c_p Q₁), K.
    pub temperature_rise_k: f64,
    /// Where the viscosity is taken, °C.
    pub effective_temperature_c: f64,
    /// Estimated maximum film temperature, °C.
    pub max_temperature_c: f64,
    /// How far the texts' mapping of a sector pad to the rectangle at the mean radius is from
    /// the sector solved in polar coordinates (r, θ): W̄ of the sector over the rectangle's at
    /// this film ratio, minus 1 (laminar and isoviscous, on the fidelity's mesh; second order in
    /// (R2 − R1)/R_m). Numerical fidelities only.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sector_load_deviation: Option<f64>,
    /// The design checks (Khonsari & Booser §7.2–7.9).
    pub checks: Vec<Check>,
    /// Whether every check passed.
    pub checks_passed: bool,
    /// One pad's full result.
    pub pad: PadResult,
}

impl Calculation for Bearing {
    const PATH: &'static str = "/v1/thrust-bearings/bearing";
    const SUMMARY: &'static str =
        "Thrust bearing of fixed or tilting sector pads: film, power, flows, temperatures, design checks";
    const DESCRIPTION: &'static str = include_str!("bearing.md");
    const FIDELITY: &'static [Level] =
        &[Level::ClosedForm, Level::Fast, Level::Standard, Level::High];
    const EFFECTS: &'static [&'static str] = &["thermal", "turbulence"];
    const EXAMPLE: &'static str = r#"{"inner_radius_m": 0.073, "outer_radius_m": 0.16, "pad_count": 7, "pad_angle_deg": 43.7, "pads": {"kind": "tilting", "pivot_position_fraction": 0.6}, "speed_rpm": 3600, "load_n": 111200, "lubricant": {"iso_vg": 32}, "inlet_temperature_c": 49}"#;

    type Input = BearingInput;
    type Output = BearingOutput;

    fn run(case: Case, ctx: &mut Context) -> Result<BearingOutput, CalcError> {
        let budget = ctx.budget();
        let c = &case.conditions;
        let crown = case.pads.crown_m;
        let solved = match case.pads.pads {
            Pads::Fixed { profile, ratio } => {
                pad::fixed(profile, ratio, crown, case.method, c, &budget)
            }
            Pads::Tilting(pivot) => pad::tilting(pivot, crown, case.method, c, &budget),
        }
        .map_err(per_pad_pointers)?;
        ctx.record(&solved.operating.notes);
        if let Pads::Fixed { profile, .. } = case.pads.pads {
            if let Some(message) = flat_land_warning(profile) {
                ctx.warn("flat_land_empirical", message);
            }
        }
        ctx.report(solved.report(case.method, &budget));
        let result = PadResult::new(&solved.operating, solved.ratio, None);
        check_finite(&result)?;
        let deviation = sector_deviation(&case, &solved, &budget)?;
        let pad_type = match case.pads.pads {
            Pads::Fixed {
                profile: Profile::Step { .. },
                ..
            } => PadType::Step,
            Pads::Fixed {
                profile: Profile::FlatLand { .. },
                ..
            } => PadType::Flat,
            Pads::Fixed { .. } => PadType::Taper,
            Pads::Tilting(_) => PadType::TiltPad,
        };
        let mut out = output(&case, &solved, pad_type, result);
        out.sector_load_deviation = deviation;
        Ok(out)
    }
}

/// The sector's W̄ solved in polar coordinates over the rectangle's, minus 1, both on the
/// fidelity's mesh across the whole width ([`film::solve_sector`]); none for `closed_form` and
/// for flat lands.
fn sector_deviation(
    case: &Case,
    solved: &SolvedPad,
    budget: &crate::calc::Budget,
) -> Result<Option<f64>, CalcError> {
    let Method::Numerical { mesh, .. } = case.method else {
        return Ok(None);
    };
    let h2 = solved.operating.outlet_film_m;
    let profile = match (case.pads.pads, case.pads.crown_m) {
        (_, Some(crown)) => Profile::Crowned {
            ratio: solved.ratio,
            crown: crown / h2,
        },
        // The texts' empirical rule, with no film to solve.
        (
            Pads::Fixed {
                profile: Profile::FlatLand { .. },
                ..
            },
            None,
        ) => return Ok(None),
        (Pads::Fixed { profile, .. }, None) => profile.with_ratio(solved.ratio),
        (Pads::Tilting(_), None) => Profile::PlaneInclined {
            ratio: solved.ratio,
        },
    };
    let s = &case.sectors;
    let curvature = (s.outer_radius_m - s.inner_radius_m) / s.mean_radius_m();
    let l_over_b = s.pad().l_over_b();
    let (sector, _, _) = film::solve_sector(profile, l_over_b, curvature, mesh, budget)?;
    let (rectangle, _, _) = film::solve_sector(profile, l_over_b, 0.0, mesh, budget)?;
    Ok(Some(sector / rectangle - 1.0))
}

/// A pad's refusal points at the bearing's fields: the load is the bearing's.
fn per_pad_pointers(e: CalcError) -> CalcError {
    match e {
        CalcError::Impossible { pointer, message } if pointer == "/pivot_position_fraction" => {
            CalcError::Impossible {
                pointer: "/pads/pivot_position_fraction".to_owned(),
                message,
            }
        }
        CalcError::Impossible { pointer, message }
            if pointer.starts_with("/profile") || pointer == "/crown_m" =>
        {
            CalcError::Impossible {
                pointer: format!("/pads{pointer}"),
                message,
            }
        }
        other => other,
    }
}

fn output(case: &Case, solved: &SolvedPad, pad_type: PadType, result: PadResult) -> BearingOutput {
    let s = &case.sectors;
    let op = &solved.operating;
    let n = s.count as f64;
    let pad = s.pad();
    let unit_load = op.load_n / pad.area_m2();
    let speed_rad_s = case.conditions.sliding_speed_m_s / s.mean_radius_m();
    let (low, high) = pad_type.unit_load_range_pa();
    let h2 = op.outlet_film_m;
    let min_film = case.pads.crown_m.map_or(h2, |crown| {
        let crowned = Profile::Crowned {
            ratio: solved.ratio,
            crown: crown / h2,
        };
        h2 * crowned.minimum()
    });
    // Khonsari & Booser §7.3: the target oil rise is 30–40 °F.
    let rise_limit = 40.0 / 1.8;
    let checks = vec![
        Check {
            name: "min_film",
            value: min_film,
            limit: case.allowable_film_m,
            passed: min_film >= case.allowable_film_m,
            rule: "minimum film at least the allowable (10 × the composite roughness, Khonsari & Booser §8.12 and Table 8.7, unless given)".to_owned(),
        },
        Check {
            name: "max_temperature",
            value: op.max_temperature_c,
            limit: case.max_temperature_limit_c,
            passed: op.max_temperature_c <= case.max_temperature_limit_c,
            rule: "maximum film temperature at most the limit (babbitt flows at about 150 °C, Khonsari & Booser §7.9)".to_owned(),
        },
        Check {
            name: "unit_load",
            value: unit_load,
            limit: high,
            passed: unit_load <= high,
            rule: format!(
                "unit load within Khonsari & Booser Table 7.1's range for {} bearings, {:.2}–{:.2} MPa{}",
                pad_type.name(),
                low * 1e-6,
                high * 1e-6,
                if unit_load < low { " (below it: lightly loaded)" } else { "" }
            ),
        },
        Check {
            name: "temperature_rise",
            value: op.temperature_rise_k,
            limit: rise_limit,
            passed: op.temperature_rise_k <= rise_limit,
            rule: "oil temperature rise at most 40 °F, 22 K (Khonsari & Booser §7.3's target of 30–40 °F)".to_owned(),
        },
    ];
    BearingOutput {
        mean_radius_m: s.mean_radius_m(),
        pad_breadth_m: pad.breadth_m,
        pad_length_m: pad.length_m,
        pad_angle_deg: s.angle_rad.to_degrees(),
        sliding_speed_m_s: case.conditions.sliding_speed_m_s,
        load_per_pad_n: op.load_n,
        unit_load_pa: unit_load,
        min_film_m: min_film,
        film_ratio: solved.ratio,
        pivot_position_fraction: solved.equilibrium.as_ref().map(|e| e.pivot),
        power_loss_w: n * op.power_loss_w,
        friction_torque_n_m: n * op.power_loss_w / speed_rad_s,
        inlet_flow_m3_s: n * op.inlet_flow_m3_s,
        side_flow_m3_s: n * op.side_flow_m3_s,
        temperature_rise_k: op.temperature_rise_k,
        effective_temperature_c: op.effective_temperature_c,
        max_temperature_c: op.max_temperature_c,
        sector_load_deviation: None,
        checks_passed: checks.iter().all(|c| c.passed),
        checks,
        pad: result,
    }
}
