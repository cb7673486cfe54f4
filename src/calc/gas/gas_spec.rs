//! The `gas` object every gas-bearing request takes, as it arrives, and its parser into [`Gas`]:
//! viscosity, ambient (absolute) pressure, the specific gas constant and temperature, and the
//! molecular mean free path that the slip-flow effect is decided on.
//!
//! Sources: Khonsari & Booser §11.1 (Eqs. 11.1–11.2, Table 11.1: μ at 300 and 400 K and the
//! exponent n of μ ∝ Tⁿ), §11.2 (Knudsen number Kn = λ/h; continuum below 0.01, slip flow to
//! 15; air's λ = 0.064 µm at 1 atm); Stachowiak & Batchelor §4.8 and Table 6.1.

use serde::Deserialize;
use utoipa::ToSchema;

use crate::calc::quantity::Positive;
use crate::calc::FieldError;
use crate::effects::{Criterion, Decision, Mode};

/// Universal gas constant, J/(kmol·K) (Khonsari & Booser Eq. 11.1: 8.3143 kJ/(kmol·K)).
pub const UNIVERSAL_GAS_CONSTANT_J_KMOL_K: f64 = 8314.3;

/// One standard atmosphere, Pa: the ambient pressure when the request gives none.
pub const STANDARD_ATMOSPHERE_PA: f64 = 101_325.0;

/// The reference temperature of Table 11.1's power law, K (its first column).
pub const REFERENCE_TEMPERATURE_K: f64 = 300.0;

/// Knudsen number above which a first-order slip correction is due (Khonsari & Booser §11.2:
/// continuum flow below 0.01).
pub const SLIP_KNUDSEN_THRESHOLD: f64 = 0.01;

/// Knudsen number beyond which the first-order slip form H³P(1 + 6Kn/(PH)) is no longer a model
/// of the flow (it assumes Kn ≪ 1; the texts' molecular regime starts at 15, and Burgdorfer's
/// correction is already poor near 1: spec H-10).
pub const FIRST_ORDER_SLIP_LIMIT: f64 = 1.0;

/// Accepted temperatures, K: the power law is Table 11.1's fit between 300 and 400 K; Table 11.2
/// spans 100 … 600 K, and beyond that the law is an extrapolation this service does not make.
pub const TEMPERATURE_RANGE_K: (f64, f64) = (100.0, 1000.0);

/// Accepted ambient pressures, Pa (absolute): from a rough vacuum to 100 bar, above which gas
/// viscosity starts to depend on pressure (§11.1: N₂ constant to ~100 bar).
pub const AMBIENT_PRESSURE_RANGE_PA: (f64, f64) = (100.0, 1.0e7);

/// Accepted viscosities, Pa·s: gases lie near 1e-5 (hydrogen 8.96e-6, xenon 2.33e-5).
pub const VISCOSITY_RANGE_PA_S: (f64, f64) = (1.0e-7, 1.0e-3);

/// Accepted specific gas constants, J/(kg·K): from xenon (63) to hydrogen (4124), with room.
pub const GAS_CONSTANT_RANGE_J_KG_K: (f64, f64) = (10.0, 10_000.0);

/// A gas whose properties the texts tabulate.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum NamedGas {
    Air,
    Nitrogen,
    Helium,
}

impl NamedGas {
    /// (molar mass kg/kmol, μ at 300 K Pa·s, exponent n of μ ∝ Tⁿ): Khonsari & Booser Table 11.1.
    pub fn table_11_1(self) -> (f64, f64, f64) {
        match self {
            NamedGas::Air => (28.96, 18.5e-6, 0.757),
            NamedGas::Nitrogen => (28.02, 17.9e-6, 0.733),
            NamedGas::Helium => (4.003, 19.81e-6, 0.670),
        }
    }

    pub fn as_str(self) -> &'static str {
        match self {
            NamedGas::Air => "air",
            NamedGas::Nitrogen => "nitrogen",
            NamedGas::Helium => "helium",
        }
    }

    /// Specific gas constant R = R_u/M, J/(kg·K).
    pub fn gas_constant_j_kg_k(self) -> f64 {
        UNIVERSAL_GAS_CONSTANT_J_KMOL_K / self.table_11_1().0
    }

    /// μ = μ_r (T/T_r)ⁿ with T_r = 300 K (Khonsari & Booser Eq. 11.2, Table 11.1), Pa·s.
    pub fn viscosity_pa_s(self, temperature_k: f64) -> f64 {
        let (_, mu_r, n) = self.table_11_1();
        mu_r * (temperature_k / REFERENCE_TEMPERATURE_K).powf(n)
    }
}

/// The gas in the film. Give either `name` (air, nitrogen or helium: viscosity from Khonsari &
/// Booser Table 11.1's power law μ = μ_r (T/300 K)ⁿ at `temperature_k`, gas constant from the
/// molar mass) or `viscosity_pa_s` (with, optionally, `gas_constant_j_kg_k` and `temperature_k`
/// for the mean free path; air's values are assumed where they are missing). Pressures are
/// absolute.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
#[schema(example = json!({"name": "air", "temperature_k": 300.0, "ambient_pressure_pa": 101325.0}))]
pub struct GasSpec {
    /// A gas of Table 11.1: `air`, `nitrogen` or `helium`.
    pub name: Option<NamedGas>,
    /// Dynamic viscosity μ, Pa·s (1e-7 … 1e-3); instead of `name`.
    #[schema(value_type = Option<f64>, minimum = 1e-7, maximum = 1e-3, example = 1.85e-5)]
    pub viscosity_pa_s: Option<Positive>,
    /// Ambient pressure p_a, Pa, **absolute** (100 … 1e7); default 101 325 (1 atm). Film
    /// pressures are reported absolute and loads integrate p − p_a.
    #[schema(value_type = Option<f64>, minimum = 100.0, maximum = 1e7, example = 101325.0)]
    pub ambient_pressure_pa: Option<Positive>,
    /// Specific gas constant R = R_u/M, J/(kg·K) (10 … 10 000; air 287.1); with
    /// `viscosity_pa_s` only (a named gas fixes it). Default: air's.
    #[schema(value_type = Option<f64>, minimum = 10.0, maximum = 10000.0, example = 287.1)]
    pub gas_constant_j_kg_k: Option<Positive>,
    /// Gas temperature T, K (100 … 1000); default 300 K. Sets a named gas's viscosity and every
    /// gas's mean free path.
    #[schema(value_type = Option<f64>, minimum = 100.0, maximum = 1000.0, example = 300.0)]
    pub temperature_k: Option<Positive>,
    /// Molecular mean free path at the ambient pressure, m (1e-10 … 1e-3), overriding the
    /// kinetic-theory value λ = (μ/p_a)√(πRT/2).
    #[schema(value_type = Option<f64>, minimum = 1e-10, maximum = 1e-3, example = 6.4e-8)]
    pub mean_free_path_m: Option<Positive>,
}

/// A gas, parsed: everything a gas film needs, in SI.
#[derive(Debug, Clone, PartialEq)]
pub struct Gas {
    /// The named gas, if the request named one.
    pub name: Option<NamedGas>,
    /// μ, Pa·s (isothermal film; pressure-independent below ~100 bar).
    pub viscosity_pa_s: f64,
    /// p_a, Pa, absolute.
    pub ambient_pressure_pa: f64,
    /// R, J/(kg·K).
    pub gas_constant_j_kg_k: f64,
    /// T, K.
    pub temperature_k: f64,
    /// λ_a, the mean free path at p_a, m.
    pub mean_free_path_m: f64,
    /// What was assumed for missing fields: (code, sentence), for the response's warnings.
    pub assumptions: Vec<(&'static str, String)>,
}

/// Kinetic-theory mean free path λ = (μ/p)√(πRT/2), m (hard-sphere gas, the form behind the
/// texts' 0.064 µm for air at 1 atm: it gives 0.065 µm at 20 °C).
pub fn kinetic_mean_free_path_m(
    viscosity_pa_s: f64,
    pressure_pa: f64,
    gas_constant_j_kg_k: f64,
    temperature_k: f64,
) -> f64 {
    viscosity_pa_s / pressure_pa
        * (std::f64::consts::PI * gas_constant_j_kg_k * temperature_k / 2.0).sqrt()
}

impl Gas {
    /// Mass density ρ = p/(RT) at absolute pressure `pressure_pa`, kg/m³.
    pub fn density_kg_m3(&self, pressure_pa: f64) -> f64 {
        pressure_pa / (self.gas_constant_j_kg_k * self.temperature_k)
    }

    /// Mean free path at absolute pressure `pressure_pa` (λ ∝ 1/p at fixed T), m.
    pub fn mean_free_path_at_m(&self, pressure_pa: f64) -> f64 {
        self.mean_free_path_m * self.ambient_pressure_pa / pressure_pa
    }

    /// Knudsen number Kn = λ_a/h of a film `film_m` thick at ambient pressure.
    pub fn knudsen_number(&self, film_m: f64) -> f64 {
        self.mean_free_path_m / film_m
    }

    /// The slip-flow effect for a film whose thinnest part is `film_m`: `auto` applies the
    /// first-order slip correction (Burgdorfer; Khonsari & Booser Eq. 11.10) when Kn = λ_a/h_min
    /// exceeds 0.01 (§11.2's end of continuum flow). The decision says which Kn it used.
    pub fn slip_flow(&self, mode: Mode, film_m: f64) -> Decision {
        let mut d = Decision::decide(
            mode,
            Criterion {
                name: "knudsen_number",
                value: self.knudsen_number(film_m),
                threshold: SLIP_KNUDSEN_THRESHOLD,
            },
            "first-order slip flow (Kn = λ_a/h_min; H³P → H³P(1 + 6Kn/(PH)))",
        );
        if d.applied {
            d.model = Some("first_order_slip");
        }
        d
    }
}

fn check_range(
    errors: &mut Vec<FieldError>,
    pointer: String,
    value: Option<f64>,
    (lo, hi): (f64, f64),
    unit: &str,
) {
    if let Some(v) = value {
        if !(lo..=hi).contains(&v) {
            errors.push(FieldError::new(
                pointer,
                format!("must be within [{lo:e}, {hi:e}] {unit}, got {v}"),
            ));
        }
    }
}

impl GasSpec {
    /// [`GasSpec::parse`] for a request that gathers all its errors: the gas, or None with
    /// its errors added to `errors`.
    pub fn parse_into(self, at: &str, errors: &mut Vec<FieldError>) -> Option<Gas> {
        self.parse(at).map_err(|mut e| errors.append(&mut e)).ok()
    }

    /// Parse into a [`Gas`]; `at` is the JSON pointer of this object in the request.
    pub fn parse(self, at: &str) -> Result<Gas, Vec<FieldError>> {
        let mut errors = Vec::new();
        let p = |field: &str| format!("{at}/{field}");
        let get = |v: Option<Positive>| v.map(Positive::get);
        check_range(
            &mut errors,
            p("viscosity_pa_s"),
            get(self.viscosity_pa_s),
            VISCOSITY_RANGE_PA_S,
            "Pa·s",
        );
        check_range(
            &mut errors,
            p("ambient_pressure_pa"),
            get(self.ambient_pressure_pa),
            AMBIENT_PRESSURE_RANGE_PA,
            "Pa (absolute)",
        );
        check_range(
            &mut errors,
            p("gas_constant_j_kg_k"),
            get(self.gas_constant_j_kg_k),
            GAS_CONSTANT_RANGE_J_KG_K,
            "J/(kg·K)",
        );
        check_range(
            &mut errors,
            p("temperature_k"),
            get(self.temperature_k),
            TEMPERATURE_RANGE_K,
            "K",
        );
        check_range(
            &mut errors,
            p("mean_free_path_m"),
            get(self.mean_free_path_m),
            (1e-10, 1e-3),
            "m",
        );
        let mut assumptions = Vec::new();
        let ambient_pressure_pa = get(self.ambient_pressure_pa).unwrap_or(STANDARD_ATMOSPHERE_PA);
        let temperature_k = get(self.temperature_k).unwrap_or(REFERENCE_TEMPERATURE_K);
        let (viscosity_pa_s, gas_constant_j_kg_k) = match (self.name, self.viscosity_pa_s) {
            (Some(_), Some(_)) => {
                errors.push(FieldError::new(
                    p("viscosity_pa_s"),
                    "give either name or viscosity_pa_s, not both",
                ));
                (0.0, 0.0)
            }
            (None, None) => {
                errors.push(FieldError::new(
                    at.to_owned(),
                    "give the gas: name (air, nitrogen, helium) or viscosity_pa_s",
                ));
                (0.0, 0.0)
            }
            (Some(gas), None) => {
                if self.gas_constant_j_kg_k.is_some() {
                    errors.push(FieldError::new(
                        p("gas_constant_j_kg_k"),
                        format!("is fixed by name = {}: omit it", gas.as_str()),
                    ));
                }
                (gas.viscosity_pa_s(temperature_k), gas.gas_constant_j_kg_k())
            }
            (None, Some(mu)) => {
                let r = match get(self.gas_constant_j_kg_k) {
                    Some(r) => r,
                    None => {
                        let r = NamedGas::Air.gas_constant_j_kg_k();
                        if self.mean_free_path_m.is_none() {
                            assumptions.push((
                                "gas_constant_assumed",
                                format!("gas_constant_j_kg_k not given: air's {r:.1} J/(kg·K) assumed for the mean free path"),
                            ));
                        }
                        r
                    }
                };
                (mu.get(), r)
            }
        };
        if !errors.is_empty() {
            return Err(errors);
        }
        let mean_free_path_m = get(self.mean_free_path_m).unwrap_or_else(|| {
            kinetic_mean_free_path_m(
                viscosity_pa_s,
                ambient_pressure_pa,
                gas_constant_j_kg_k,
                temperature_k,
            )
        });
        Ok(Gas {
            name: self.name,
            viscosity_pa_s,
            ambient_pressure_pa,
            gas_constant_j_kg_k,
            temperature_k,
            mean_free_path_m,
            assumptions,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn spec(v: serde_json::Value) -> GasSpec {
        serde_json::from_value(v).unwrap()
    }

    fn rel(a: f64, b: f64) -> f64 {
        ((a - b) / b).abs()
    }

    #[test]
    fn table_11_1_power_law_reproduces_the_400_k_column() {
        // Khonsari & Booser Table 11.1: μ(400 K) for air 23.0, nitrogen 22.1, helium 24.02 µPa·s;
        // the spec's check T8 (air, n = 0.757).
        for (gas, want) in [
            (NamedGas::Air, 23.0e-6),
            (NamedGas::Nitrogen, 22.1e-6),
            (NamedGas::Helium, 24.02e-6),
        ] {
            let got = gas.viscosity_pa_s(400.0);
            assert!(rel(got, want) < 0.005, "{gas:?}: {got} vs {want}");
            assert_eq!(gas.viscosity_pa_s(300.0), gas.table_11_1().1);
        }
    }

    #[test]
    fn air_mean_free_path_is_the_texts_0_064_um_at_1_atm() {
        // §11.2 and S&B §4.8: 0.064 µm at 1 atm (room temperature); kinetic theory at 20 °C.
        let air = spec(serde_json::json!({"name": "air", "temperature_k": 293.15}))
            .parse("/gas")
            .unwrap();
        assert!(
            rel(air.mean_free_path_m, 0.064e-6) < 0.03,
            "{}",
            air.mean_free_path_m
        );
        // Spec check T7: h = 0.54 µm gives Kn ≈ 0.12 with λ = 0.064 µm.
        let given = spec(serde_json::json!({"name": "air", "mean_free_path_m": 0.064e-6}))
            .parse("/gas")
            .unwrap();
        assert!(rel(given.knudsen_number(0.54e-6), 0.1185) < 0.001);
        // λ ∝ 1/p.
        assert!(rel(given.mean_free_path_at_m(2.0 * 101_325.0), 0.032e-6) < 1e-12);
    }

    #[test]
    fn defaults_are_one_atmosphere_and_300_k_and_air_density_is_right() {
        let air = spec(serde_json::json!({"name": "air"}))
            .parse("/gas")
            .unwrap();
        assert_eq!(air.ambient_pressure_pa, STANDARD_ATMOSPHERE_PA);
        assert_eq!(air.temperature_k, 300.0);
        assert_eq!(air.viscosity_pa_s, 18.5e-6);
        // Table 11.1's specific volumes at 300 K (air 0.861, N₂ 0.890, He 6.23 m³/kg) are at 1 bar.
        assert!(rel(1.0 / air.density_kg_m3(1.0e5), 0.861) < 0.002);
        let n2 = spec(serde_json::json!({"name": "nitrogen"}))
            .parse("/gas")
            .unwrap();
        assert!(rel(1.0 / n2.density_kg_m3(1.0e5), 0.890) < 0.01);
        let he = spec(serde_json::json!({"name": "helium"}))
            .parse("/gas")
            .unwrap();
        assert!(rel(1.0 / he.density_kg_m3(1.0e5), 6.23) < 0.01);
    }

    #[test]
    fn a_viscosity_alone_assumes_air_for_the_mean_free_path_and_says_so() {
        let g = spec(serde_json::json!({"viscosity_pa_s": 1.85e-5, "ambient_pressure_pa": 2e5}))
            .parse("/gas")
            .unwrap();
        assert_eq!(g.viscosity_pa_s, 1.85e-5);
        assert_eq!(g.ambient_pressure_pa, 2e5);
        assert_eq!(g.assumptions[0].0, "gas_constant_assumed");
        let r = spec(serde_json::json!({"viscosity_pa_s": 2e-5, "gas_constant_j_kg_k": 2077.0}))
            .parse("/gas")
            .unwrap();
        assert!(r.assumptions.is_empty());
        assert_eq!(r.gas_constant_j_kg_k, 2077.0);
    }

    #[test]
    fn bad_gases_name_their_field() {
        let cases = [
            (serde_json::json!({}), "/gas"),
            (
                serde_json::json!({"name": "air", "viscosity_pa_s": 1e-5}),
                "/gas/viscosity_pa_s",
            ),
            (
                serde_json::json!({"name": "air", "gas_constant_j_kg_k": 287.0}),
                "/gas/gas_constant_j_kg_k",
            ),
            (
                serde_json::json!({"name": "air", "ambient_pressure_pa": 10.0}),
                "/gas/ambient_pressure_pa",
            ),
            (
                serde_json::json!({"name": "air", "temperature_k": 5000.0}),
                "/gas/temperature_k",
            ),
            (
                serde_json::json!({"viscosity_pa_s": 1.0}),
                "/gas/viscosity_pa_s",
            ),
        ];
        for (body, pointer) in cases {
            let errors = spec(body.clone()).parse("/gas").unwrap_err();
            assert!(
                errors.iter().any(|e| e.pointer == pointer),
                "{body}: {errors:?}"
            );
        }
        // Absolute pressures ≤ 0 never parse at all.
        assert!(serde_json::from_value::<GasSpec>(
            serde_json::json!({"name": "air", "ambient_pressure_pa": 0.0})
        )
        .is_err());
        assert!(serde_json::from_value::<GasSpec>(serde_json::json!({"name": "argon"})).is_err());
        assert!(serde_json::from_value::<GasSpec>(
            serde_json::json!({"name": "air", "viscosty_pa_s": 1e-5})
        )
        .is_err());
    }

    #[test]
    fn slip_flow_is_decided_on_the_knudsen_number() {
        let air = spec(serde_json::json!({"name": "air", "mean_free_path_m": 0.064e-6}))
            .parse("/gas")
            .unwrap();
        let thin = air.slip_flow(Mode::Auto, 0.5e-6);
        assert!(thin.applied && thin.model == Some("first_order_slip"));
        assert!(!air.slip_flow(Mode::Auto, 10e-6).applied);
        assert!(!air.slip_flow(Mode::Off, 0.5e-6).applied);
        assert!(air.slip_flow(Mode::On, 10e-6).applied);
    }
}
