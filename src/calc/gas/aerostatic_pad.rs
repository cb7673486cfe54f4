//! `POST /v1/gas-bearings/aerostatic-pad`: the circular externally pressurised gas pad with a
//! central recess at a given absolute recess pressure and film — load, flows, the power to
//! compress the gas, and the land's friction (Stachowiak & Batchelor §6.5).
//!
//! This file is the wire (request, validation, response); the physics is [`super::recess_pad`].

use std::f64::consts::PI;

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::gas_spec::{Gas, GasSpec, FIRST_ORDER_SLIP_LIMIT};
use super::recess_pad::RecessPad;
use crate::calc::quantity::Positive;
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::effects::Mode;
use crate::fidelity::{Level, SolverReport};
use crate::numerics::quadrature::IntegralError;

pub struct AerostaticPad;

/// Radii, m: up to 2 m.
const MAX_RADIUS_M: f64 = 2.0;
/// Smallest recess radius as a share of the outer one (a point feed has ln(R/R₀) → ∞).
const MIN_RECESS_SHARE: f64 = 1e-3;
/// Film range, m: from 0.1 µm (first-order slip is then already stretched for air) to 1 mm.
const FILM_RANGE_M: (f64, f64) = (1e-7, 1e-3);
/// The film is at most this share of the land's width (R − R₀): a thin film.
const MAX_FILM_OVER_LAND: f64 = 0.01;
/// Largest recess pressure, Pa absolute (1000 bar; gas viscosity is pressure dependent well
/// before it, §11.1).
const MAX_RECESS_PRESSURE_PA: f64 = 1e8;
/// Largest speed, rpm.
const MAX_SPEED_RPM: f64 = 1e6;
/// Transition of a film's Reynolds number from laminar flow (Khonsari & Booser §7.11: 580–800
/// for a plane film; the lower end is taken).
const LAMINAR_REYNOLDS_LIMIT: f64 = 580.0;
/// Deepest recess, in films, before the gas it stores risks pneumatic hammer (S&B §6.5: a gas
/// recess only 10–20 times the film deep).
const MAX_RECESS_DEPTH_IN_FILMS: f64 = 20.0;

/// Effects the pad understands.
#[derive(Debug, Clone, Copy, Default, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct AerostaticPadEffects {
    /// First-order slip at the walls (Burgdorfer; Khonsari & Booser Eq. 11.10): the land's flow
    /// factor h³p becomes h³p(1 + 6λ/h) with the local mean free path λ ∝ 1/p. `auto` applies
    /// it when the Knudsen number λ_a/h at ambient pressure exceeds 0.01 (§11.2).
    #[serde(default)]
    pub slip_flow: Mode,
}

/// Request: the pad, the gas and the recess pressure and film it runs at.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct AerostaticPadInput {
    /// Outer radius R, m (0 … 2).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 2.0, example = 0.1)]
    pub outer_radius_m: Positive,
    /// Recess radius R₀, m (below `outer_radius_m`, at least 0.001 of it).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 2.0, example = 0.05)]
    pub recess_radius_m: Positive,
    /// Recess pressure p_r, Pa, **absolute** (above the gas's ambient pressure; at most 1e8).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 1e8, example = 600000.0)]
    pub recess_pressure_pa: Positive,
    /// Film over the land h, m (1e-7 … 1e-3, at most 1 % of the land's width R − R₀).
    #[schema(value_type = f64, minimum = 1e-7, maximum = 1e-3, example = 2e-5)]
    pub film_m: Positive,
    pub gas: GasSpec,
    /// Relative speed of the runner, rpm (0 … 1e6): the land's viscous friction.
    #[schema(value_type = Option<f64>, minimum = 0.0, maximum = 1e6, example = 3000.0)]
    pub speed_rpm: Option<f64>,
    /// Recess depth below the land, m: adds the recess's friction, and warns beyond 20 films
    /// (pneumatic hammer).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 0.1, example = 2e-4)]
    pub recess_depth_m: Option<Positive>,
    #[serde(default)]
    pub effects: AerostaticPadEffects,
}

/// The parsed request.
#[derive(Debug, Clone)]
pub struct AerostaticPadCase {
    pub outer_radius: f64,
    pub recess_radius: f64,
    pub recess_pressure: f64,
    pub film: f64,
    pub gas: Gas,
    pub speed_rpm: Option<f64>,
    pub recess_depth: Option<f64>,
    pub slip_flow: Mode,
}

impl Validate for AerostaticPadInput {
    type Valid = AerostaticPadCase;
    fn validate(self) -> Result<AerostaticPadCase, Vec<FieldError>> {
        let mut errors = Vec::new();
        let (r, r0) = (self.outer_radius_m.get(), self.recess_radius_m.get());
        let (pr, h) = (self.recess_pressure_pa.get(), self.film_m.get());
        for (pointer, value) in [("/outer_radius_m", r), ("/recess_radius_m", r0)] {
            if value > MAX_RADIUS_M {
                errors.push(FieldError::new(
                    pointer,
                    format!("must be at most {MAX_RADIUS_M} m"),
                ));
            }
        }
        if r0 >= r {
            errors.push(FieldError::new(
                "/recess_radius_m",
                "must be below outer_radius_m (the land lies between them)",
            ));
        } else if r0 < MIN_RECESS_SHARE * r {
            errors.push(FieldError::new(
                "/recess_radius_m",
                format!("must be at least {MIN_RECESS_SHARE} of outer_radius_m"),
            ));
        }
        if !(FILM_RANGE_M.0..=FILM_RANGE_M.1).contains(&h) {
            errors.push(FieldError::new(
                "/film_m",
                format!(
                    "must be within [{:e}, {:e}] m",
                    FILM_RANGE_M.0, FILM_RANGE_M.1
                ),
            ));
        } else if r0 < r && h > MAX_FILM_OVER_LAND * (r - r0) {
            errors.push(FieldError::new(
                "/film_m",
                format!(
                    "must be at most {MAX_FILM_OVER_LAND} of the land's width R − R₀ = {:.4e} m (a thin film)",
                    r - r0
                ),
            ));
        }
        if pr > MAX_RECESS_PRESSURE_PA {
            errors.push(FieldError::new(
                "/recess_pressure_pa",
                format!("must be at most {MAX_RECESS_PRESSURE_PA:e} Pa"),
            ));
        }
        if let Some(n) = self.speed_rpm {
            if !(0.0..=MAX_SPEED_RPM).contains(&n) {
                errors.push(FieldError::new(
                    "/speed_rpm",
                    format!("must be within [0, {MAX_SPEED_RPM:e}] rpm"),
                ));
            }
        }
        if self.recess_depth_m.is_some_and(|d| d.get() > 0.1) {
            errors.push(FieldError::new("/recess_depth_m", "must be at most 0.1 m"));
        }
        let gas = match self.gas.parse("/gas") {
            Ok(gas) => {
                if pr <= gas.ambient_pressure_pa {
                    errors.push(FieldError::new(
                        "/recess_pressure_pa",
                        format!(
                            "must exceed the ambient pressure {} Pa (pressures are absolute; a recess at or below ambient carries no load)",
                            gas.ambient_pressure_pa
                        ),
                    ));
                }
                Some(gas)
            }
            Err(mut e) => {
                errors.append(&mut e);
                None
            }
        };
        match (errors.is_empty(), gas) {
            (true, Some(gas)) => Ok(AerostaticPadCase {
                outer_radius: r,
                recess_radius: r0,
                recess_pressure: pr,
                film: h,
                gas,
                speed_rpm: self.speed_rpm,
                recess_depth: self.recess_depth_m.map(Positive::get),
                slip_flow: self.effects.slip_flow,
            }),
            _ => Err(errors),
        }
    }
}

/// Result: the pad's load and flow at the recess pressure, its power and friction.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct AerostaticPadOutput {
    /// Load W = ∫(p − p_a) dA over recess and land, N.
    pub load_n: f64,
    /// W/((p_r − p_a) π R²): the load over the recess's gauge pressure on the whole pad
    /// (S&B's K*, Fig 6.9, on the gauge pressure; the incompressible pad's
    /// (1 − (R₀/R)²)/(2 ln(R/R₀)) as p_r → p_a).
    pub load_coefficient: f64,
    /// Mass flow ṁ through the film, kg/s.
    pub mass_flow_kg_s: f64,
    /// Volume flow at the recess pressure ṁ/ρ(p_r), m³/s (S&B eq 6.28).
    pub volume_flow_recess_m3_s: f64,
    /// Volume flow at the ambient pressure ṁ/ρ(p_a) (free air delivered), m³/s.
    pub volume_flow_ambient_m3_s: f64,
    /// Isothermal power to compress the flow from ambient to the recess pressure,
    /// ṁ R T ln(p_r/p_a), W: the least pumping power (losses in lines and restrictors extra).
    pub compression_power_w: f64,
    /// Radial-flow Reynolds number at the recess edge, ṁ/(2π R₀ μ) (= ρ ū h/μ there).
    pub radial_reynolds_number: f64,
    /// Knudsen number λ_a/h at ambient pressure (the film's largest).
    pub knudsen_number: f64,
    /// Gas viscosity used, Pa·s.
    pub viscosity_pa_s: f64,
    /// Viscous friction torque on the runner (land, and recess where `recess_depth_m` is
    /// given), N·m (with `speed_rpm`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub friction_torque_n_m: Option<f64>,
    /// Friction power ω T, W (with `speed_rpm`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub friction_power_w: Option<f64>,
    /// Couette Reynolds number at the outer radius ρ(p_a) ω R h/μ (with `speed_rpm`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub couette_reynolds_number: Option<f64>,
}

impl Calculation for AerostaticPad {
    const PATH: &'static str = "/v1/gas-bearings/aerostatic-pad";
    const SUMMARY: &'static str = "Circular aerostatic (externally pressurised gas) pad with a central recess: load, mass and volume flows, compression power and friction at a recess pressure and film";
    const DESCRIPTION: &'static str = include_str!("aerostatic_pad.md");
    const FIDELITY: &'static [Level] = &[Level::ClosedForm];
    const EFFECTS: &'static [&'static str] = &["slip_flow"];
    const EXAMPLE: &'static str = r#"{"outer_radius_m": 0.1, "recess_radius_m": 0.05, "recess_pressure_pa": 600000, "film_m": 2e-5, "gas": {"name": "air", "temperature_k": 293.15}, "speed_rpm": 3000}"#;

    type Input = AerostaticPadInput;
    type Output = AerostaticPadOutput;

    fn run(case: AerostaticPadCase, ctx: &mut Context) -> Result<AerostaticPadOutput, CalcError> {
        let gas = &case.gas;
        for (code, message) in &gas.assumptions {
            ctx.warn(code, message.clone());
        }
        let slip = gas.slip_flow(case.slip_flow, case.film);
        let knudsen = gas.knudsen_number(case.film);
        if slip.applied && knudsen > FIRST_ORDER_SLIP_LIMIT {
            ctx.warn(
                "slip_beyond_first_order",
                format!("Knudsen number {knudsen:.3} exceeds {FIRST_ORDER_SLIP_LIMIT}: the first-order slip law assumes Kn ≪ 1 and the flow is uncertain here"),
            );
        }
        let pad = RecessPad {
            recess_radius: case.recess_radius,
            outer_radius: case.outer_radius,
            recess_pressure: case.recess_pressure,
            ambient_pressure: gas.ambient_pressure_pa,
            film: case.film,
            viscosity: gas.viscosity_pa_s,
            slip_mean_free_path: slip.applied.then_some(gas.mean_free_path_m),
        };
        ctx.decide("slip_flow", slip);
        let flow = pad.solve(&ctx.budget()).map_err(|e| match e {
            IntegralError::Stopped(stopped) => CalcError::from(stopped),
            IntegralError::Integrand(never) => match never {},
        })?;
        ctx.report(SolverReport::closed_form("isothermal_radial_flow"));
        let rt = gas.gas_constant_j_kg_k * gas.temperature_k;
        let mass_flow = flow.pressure_flow / rt;
        let mu = gas.viscosity_pa_s;
        let radial_reynolds = mass_flow / (2.0 * PI * case.recess_radius * mu);
        if radial_reynolds > LAMINAR_REYNOLDS_LIMIT {
            ctx.warn(
                "turbulent_film",
                format!("radial-flow Reynolds number {radial_reynolds:.0} at the recess edge exceeds {LAMINAR_REYNOLDS_LIMIT}: the laminar film model overstates the load and understates the flow's pressure loss"),
            );
        }
        let mut out = AerostaticPadOutput {
            load_n: flow.load,
            load_coefficient: flow.load_coefficient,
            mass_flow_kg_s: mass_flow,
            volume_flow_recess_m3_s: flow.pressure_flow / case.recess_pressure,
            volume_flow_ambient_m3_s: flow.pressure_flow / gas.ambient_pressure_pa,
            compression_power_w: flow.pressure_flow
                * (case.recess_pressure / gas.ambient_pressure_pa).ln(),
            radial_reynolds_number: radial_reynolds,
            knudsen_number: knudsen,
            viscosity_pa_s: mu,
            friction_torque_n_m: None,
            friction_power_w: None,
            couette_reynolds_number: None,
        };
        if let Some(depth) = case.recess_depth {
            if depth > MAX_RECESS_DEPTH_IN_FILMS * case.film {
                ctx.warn(
                    "pneumatic_hammer_risk",
                    format!("the recess is {:.0} films deep: a gas recess deeper than 10–20 films stores enough gas to risk pneumatic hammer (S&B §6.5)", depth / case.film),
                );
            }
        }
        if let Some(rpm) = case.speed_rpm {
            let omega = rpm * PI / 30.0;
            let torque = pad.friction_torque(omega, case.recess_depth);
            let couette =
                gas.density_kg_m3(gas.ambient_pressure_pa) * omega * case.outer_radius * case.film
                    / mu;
            if couette > LAMINAR_REYNOLDS_LIMIT {
                ctx.warn(
                    "turbulent_film",
                    format!("Couette Reynolds number {couette:.0} at the outer radius exceeds {LAMINAR_REYNOLDS_LIMIT}: the laminar friction understates the loss"),
                );
            }
            out.friction_torque_n_m = Some(torque);
            out.friction_power_w = Some(torque * omega);
            out.couette_reynolds_number = Some(couette);
        }
        Ok(out)
    }
}

#[cfg(test)]
#[path = "aerostatic_pad_tests.rs"]
mod tests;
