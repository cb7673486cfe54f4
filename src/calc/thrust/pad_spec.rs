//! The wire parts every pad request and response shares: the pad's size, the effects, the
//! fidelity and the result block (Khonsari & Booser Table 7.2 naming).

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::film::Mesh;
use super::operating::{Conditions, Effects, Given, Operating, Pad, TurbulenceLaw};
use super::performance::Method;
use crate::calc::lubricant::LubricantSpec;
use crate::calc::quantity::{ratio_within, Celsius, Positive};
use crate::calc::{CalcError, FieldError};
use crate::effects::Mode;
use crate::fidelity::{FidelityRequest, Level};

/// The pad: B along the sliding direction, L across it (radially on a thrust bearing).
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct PadSpec {
    /// Breadth B along the sliding direction, m (> 0, at most 10).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 10.0, example = 0.089)]
    pub breadth_m: Positive,
    /// Length L across the sliding direction, m (> 0, at most 10; L/B from 0.1 to 10).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 10.0, example = 0.087)]
    pub length_m: Positive,
}

impl PadSpec {
    pub fn parse(self, errors: &mut Vec<FieldError>) -> Pad {
        let pad = Pad {
            breadth_m: self.breadth_m.get(),
            length_m: self.length_m.get(),
        };
        for (field, v) in [("breadth_m", pad.breadth_m), ("length_m", pad.length_m)] {
            if v > 10.0 {
                errors.push(FieldError::new(
                    format!("/pad/{field}"),
                    format!("must be at most 10 m, got {v}"),
                ));
            }
        }
        let ratio = pad.l_over_b();
        if !ratio_within(ratio, 0.1, 10.0) {
            errors.push(FieldError::new(
                "/pad/length_m",
                format!("L/B must be within [0.1, 10], got {ratio:.4}"),
            ));
        }
        pad
    }
}

/// Effects a pad understands.
#[derive(Debug, Clone, Copy, Default, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct PadEffects {
    /// The viscosity at the effective temperature, solved as a root in T: for a plane pad of
    /// B/L from 0.8 to 1.25 and h1/h2 from 1.25 to 3.25 on an oil whose viscosity falls with
    /// temperature, Jang & Khonsari's THD mean temperature (Khonsari & Booser §7.9, Table 7.5;
    /// model `jang_khonsari`, which also gives the maximum temperature); otherwise T_in + ΔT with
    /// ΔT = E_p/(ρ c_p Q₁) (Eq. 7.8 and §7.4's procedure; model `adiabatic_rise`, maximum
    /// T_in + 2ΔT). `auto` applies it when the isothermal rise lowers the viscosity by more than
    /// 5 %.
    #[serde(default)]
    pub thermal: Mode,
    /// Turbulent film (Ng–Pan; Khonsari & Booser Eq. 6.26–6.31): the flow factors G_x, G_y
    /// scale the pad's Poiseuille flow and G_f its Couette shear at the local Re = ρ U h/μ,
    /// solved at the trailing-edge Re₂ = ρ U h2/μ the operating point itself sets (model
    /// `ng_pan`). `auto` applies it when the laminar pad-average Reynolds number ρ U h_mean/μ
    /// exceeds 580, the start of the transition at 580–800 (§7.11); inside that range a warning
    /// gives both power losses.
    #[serde(default)]
    pub turbulence: Mode,
}

/// The turbulent film's law where the turbulence effect applies: `ng_pan` (default; the
/// linearised turbulent Reynolds equation of the `turbulence` effect), or `missana`: Khonsari &
/// Booser §7.11's empirical rule — the power loss E_p = f (ρ U²/2) U B L (Eq. 7.17) with the
/// turbulent friction factor f = 0.026/Re^0.25 (Eq. 7.20, Missana et al.'s test, parasitic
/// losses included) at the laminar pad-average Re = ρ U h_mean/μ, and the film, flows and
/// temperatures of the laminar pad at the viscosity multiplied by that loss over the laminar
/// one (the texts' "effective" viscosity; a rough approximation, they say).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum PadTurbulenceModel {
    /// Ng–Pan's linearised turbulent Reynolds equation (Eq. 6.26–6.31).
    #[default]
    NgPan,
    /// The empirical f = 0.026/Re^0.25 (Eq. 7.20) and the effective-viscosity rule (§7.11).
    Missana,
}

impl PadEffects {
    /// The effects, with the turbulent film's law `model`.
    pub fn with_law(self, model: PadTurbulenceModel) -> Effects {
        Effects {
            thermal: self.thermal,
            turbulence: self.turbulence,
            turbulence_law: match model {
                PadTurbulenceModel::NgPan => TurbulenceLaw::NgPan,
                PadTurbulenceModel::Missana => TurbulenceLaw::Missana,
            },
        }
    }
}

/// The method of a request's `fidelity`: `closed_form` is the infinitely long pad, a level its
/// mesh, `{"grid": [along B 8…512, across half of L 2…256]}` an explicit one (extrapolated
/// when it halves exactly). The film is solved exactly: a `tolerance` does not apply.
pub fn method(fidelity: FidelityRequest, errors: &mut Vec<FieldError>) -> Method {
    match fidelity {
        FidelityRequest::Level(level) => Method::level(level),
        FidelityRequest::Custom(custom) => {
            if custom.tolerance.is_some() {
                errors.push(FieldError::new(
                    "/fidelity/tolerance",
                    "the pad's film is solved exactly (active sets): give a level or a grid",
                ));
            }
            match custom.grid {
                Some([along, across])
                    if (8..=512).contains(&along) && (2..=256).contains(&across) =>
                {
                    Method::mesh(Mesh {
                        along: along as usize,
                        across_half: across as usize,
                    })
                }
                Some(_) => {
                    errors.push(FieldError::new(
                        "/fidelity/grid",
                        "must be [cells along B 8…512, cells across half of L 2…256]",
                    ));
                    Method::level(Level::Standard)
                }
                None => Method::level(Level::Standard),
            }
        }
    }
}

/// A pad's crown δ (`crown_m` at `pointer`), checked: at most 1e-3 m, and a numerical fidelity
/// (a crowned film diverges behind its crown and cavitates).
pub fn crown(
    crown: Option<Positive>,
    pointer: &str,
    method: Method,
    errors: &mut Vec<FieldError>,
) -> Option<f64> {
    let crown = crown.map(Positive::get)?;
    if crown > 1e-3 {
        errors.push(FieldError::new(
            pointer,
            format!("must be at most 1e-3 m, got {crown}"),
        ));
    }
    if method == Method::LongPad {
        errors.push(FieldError::new(
            "/fidelity",
            "a crowned pad's film diverges behind its crown and cavitates, which the infinitely long pad's closed form does not model: give a numerical fidelity",
        ));
    }
    Some(crown)
}

/// Table 7.2's coefficients of this pad.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct PadCoefficients {
    /// W̄ = W h2²/(μ U B² L) (= K_h²).
    pub load: f64,
    /// K_h: h2 = K_h (μ U B/P_avg)^½ (Eq. 7.5).
    pub k_h: f64,
    /// K_f: E_p = K_f μ U² B L/h2 (Eq. 7.6).
    pub k_f: f64,
    /// K_q: Q₁ = K_q U L h2 (Eq. 7.7).
    pub k_q: f64,
    /// K_s: Q_s = K_s U L h2 (Eq. 7.7), both sides.
    pub k_s: f64,
}

/// A point of the mid-plane pressure profile.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct PadPressurePoint {
    /// x/B from the leading edge.
    pub position_fraction: f64,
    /// Gauge pressure, Pa.
    pub pressure_pa: f64,
}

/// A pad's performance at its operating point: totals for the pad sent.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct PadResult {
    /// Load carried W, N.
    pub load_n: f64,
    /// Trailing-edge (minimum) film h2, m.
    pub outlet_film_m: f64,
    /// Leading-edge film h1, m.
    pub inlet_film_m: f64,
    /// h1/h2.
    pub film_ratio: f64,
    /// Friction force on the runner F, N.
    pub friction_force_n: f64,
    /// F/W.
    pub friction_coefficient: f64,
    /// Power loss E_p = F U, W.
    pub power_loss_w: f64,
    /// Centre of pressure, x/B from the leading edge.
    pub center_of_pressure_fraction: f64,
    /// Peak film pressure (gauge), Pa.
    pub max_pressure_pa: f64,
    /// Where the peak is, x/B from the leading edge.
    pub max_pressure_position_fraction: f64,
    /// Unit load P_avg = W/(B L), Pa.
    pub mean_pressure_pa: f64,
    /// Flow in at the leading edge Q₁, m³/s.
    pub inlet_flow_m3_s: f64,
    /// Flow out of both sides Q_s, m³/s.
    pub side_flow_m3_s: f64,
    /// Flow out at the trailing edge, m³/s.
    pub outlet_flow_m3_s: f64,
    /// ΔT = E_p/(ρ c_p Q₁), K (Eq. 7.8).
    pub temperature_rise_k: f64,
    /// Where the viscosity is taken, °C: with the thermal effect the THD mean temperature
    /// (model `jang_khonsari`) or T_in + ΔT (`adiabatic_rise`); else T_in.
    pub effective_temperature_c: f64,
    /// Estimated maximum film temperature, °C: Jang & Khonsari's fit where it applies, else
    /// T_in + 2ΔT (Khonsari & Booser §7.3).
    pub max_temperature_c: f64,
    /// μ at the effective temperature, Pa·s.
    pub effective_viscosity_pa_s: f64,
    /// Pad-average Reynolds number ρ U h_mean/μ (the turbulence effect's criterion).
    pub reynolds_number: f64,
    /// Trailing-edge Reynolds number Re₂ = ρ U h2/μ: a turbulent film's local Reynolds number
    /// is Re₂ h/h2.
    pub outlet_reynolds_number: f64,
    pub coefficients: PadCoefficients,
    /// The mid-plane pressure profile (with `include_field` and a numerical fidelity).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pressure_profile: Option<Vec<PadPressurePoint>>,
}

impl PadResult {
    /// The result block of `op`, with the film ratio `ratio`, and the profile (x̄, P̄) scaled
    /// to pascals when given.
    pub fn new(op: &Operating, ratio: f64, mid_plane: Option<&[(f64, f64)]>) -> PadResult {
        let p = op.performance;
        PadResult {
            load_n: op.load_n,
            outlet_film_m: op.outlet_film_m,
            inlet_film_m: op.inlet_film_m,
            film_ratio: ratio,
            friction_force_n: op.friction_force_n,
            friction_coefficient: op.friction_force_n / op.load_n,
            power_loss_w: op.power_loss_w,
            center_of_pressure_fraction: p.center_of_pressure,
            max_pressure_pa: op.max_pressure_pa,
            max_pressure_position_fraction: p.max_pressure_position,
            mean_pressure_pa: op.mean_pressure_pa,
            inlet_flow_m3_s: op.inlet_flow_m3_s,
            side_flow_m3_s: op.side_flow_m3_s,
            outlet_flow_m3_s: op.outlet_flow_m3_s,
            temperature_rise_k: op.temperature_rise_k,
            effective_temperature_c: op.effective_temperature_c,
            max_temperature_c: op.max_temperature_c,
            effective_viscosity_pa_s: op.effective_viscosity_pa_s,
            reynolds_number: op.reynolds_number,
            outlet_reynolds_number: op.outlet_reynolds_number,
            coefficients: PadCoefficients {
                load: p.load,
                k_h: p.k_h(),
                k_f: p.friction,
                k_q: p.inlet_flow,
                k_s: p.side_flow,
            },
            pressure_profile: mid_plane.map(|points| {
                points
                    .iter()
                    .map(|&(x, pressure)| PadPressurePoint {
                        position_fraction: x,
                        pressure_pa: pressure * op.pressure_scale_pa,
                    })
                    .collect()
            }),
        }
    }
}

/// The given film or load, checked.
pub fn given(
    outlet_film: Option<Positive>,
    load: Option<Positive>,
    film_allowed: bool,
    errors: &mut Vec<FieldError>,
) -> Given {
    match (outlet_film, load) {
        (Some(h), None) if film_allowed && (1e-8..=1e-2).contains(&h.get()) => {
            Given::OutletFilm(h.get())
        }
        (Some(h), None) if film_allowed => {
            errors.push(FieldError::new(
                "/outlet_film_m",
                format!("must be within [1e-8, 1e-2] m, got {}", h.get()),
            ));
            Given::OutletFilm(1e-5)
        }
        (None, Some(w)) if (1e-6..=1e9).contains(&w.get()) => Given::Load(w.get()),
        (None, Some(w)) => {
            errors.push(FieldError::new(
                "/load_n",
                format!("must be within [1e-6, 1e9] N, got {}", w.get()),
            ));
            Given::Load(1.0)
        }
        _ if film_allowed => {
            errors.push(FieldError::new(
                "/load_n",
                "give exactly one of load_n and outlet_film_m",
            ));
            Given::Load(1.0)
        }
        _ => {
            errors.push(FieldError::new("/load_n", "give load_n"));
            Given::Load(1.0)
        }
    }
}

/// The sliding speed, inlet temperature and lubricant, checked.
pub fn conditions(
    pad: Pad,
    speed: Positive,
    lubricant: LubricantSpec,
    inlet_temperature_c: Option<Celsius>,
    given: Given,
    effects: Effects,
    errors: &mut Vec<FieldError>,
) -> Option<Conditions> {
    if speed.get() > 500.0 {
        errors.push(FieldError::new(
            "/sliding_speed_m_s",
            format!("must be at most 500 m/s, got {}", speed.get()),
        ));
    }
    match lubricant.parse("/lubricant") {
        Ok(lubricant) => Some(Conditions {
            pad,
            sliding_speed_m_s: speed.get(),
            lubricant,
            inlet_temperature_c: inlet_temperature_c.map_or(40.0, Celsius::get),
            given,
            effects,
            viscosity_factor: 1.0,
        }),
        Err(mut e) => {
            errors.append(&mut e);
            None
        }
    }
}

/// Refuse a result with a number outside the floating-point range (an extreme request).
pub fn check_finite(result: &PadResult) -> Result<(), CalcError> {
    let c = &result.coefficients;
    let numbers = [
        result.load_n,
        result.outlet_film_m,
        result.inlet_film_m,
        result.friction_force_n,
        result.friction_coefficient,
        result.power_loss_w,
        result.center_of_pressure_fraction,
        result.max_pressure_pa,
        result.max_pressure_position_fraction,
        result.mean_pressure_pa,
        result.inlet_flow_m3_s,
        result.side_flow_m3_s,
        result.outlet_flow_m3_s,
        result.temperature_rise_k,
        result.effective_temperature_c,
        result.max_temperature_c,
        result.effective_viscosity_pa_s,
        result.reynolds_number,
        result.outlet_reynolds_number,
        c.load,
        c.k_h,
        c.k_f,
        c.k_q,
        c.k_s,
    ];
    CalcError::unless_finite(&numbers)
}
