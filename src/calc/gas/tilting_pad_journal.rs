//! `POST /v1/gas-bearings/tilting-pad-journal`: a three-pad tilting-pad gas journal bearing,
//! load on a pad, rigid pivots (Khonsari & Booser §11.6, Ex 11.6, after Shapiro & Colsher
//! 1970), on the compressible Reynolds equation per pad; the model is
//! [`super::tilting_pad_film`].

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::cost::{self, Least};
use super::gas_spec::GasSpec;
use super::method::{self, Given, Method};
use super::tilting_pad_film::{
    self, BearingEquilibrium, BearingFilm, PadEquilibrium, PadFilm, PadGeometry, MAX_ECCENTRICITY,
    PIVOT_ANGLES,
};
use crate::calc::journal::plain::GeometrySpec;
use crate::calc::quantity::Positive;
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::fidelity::{FidelityRequest, Level};

pub struct TiltingPadGasJournal;

/// Default pad arc α, degrees: three pads of 90° leave 30° between pads. The texts' figure
/// that gives α (Fig. 11.18) is not printed; of arcs 90–120° and pivots at 0.5–0.65 of the arc,
/// 90° pads pivoted at 0.65 reproduce Ex 11.6's chart readings best
/// (`tests/data/gas/kb_ex11_6_tilting_pad_journal.json`).
pub const DEFAULT_ARC_DEG: f64 = 90.0;

/// Default pivot position from the leading edge, a fraction of the arc: offset toward the
/// trailing edge, as gas-bearing pads usually are (see [`DEFAULT_ARC_DEG`]).
pub const DEFAULT_PIVOT_OFFSET: f64 = 0.65;

/// The pads' shape; both fields optional.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct GasTiltingPadsSpec {
    /// Each pad's arc α, degrees, in [20, 120] (three pads of more than 120° overlap);
    /// default 90.
    #[schema(minimum = 20.0, maximum = 120.0, example = 90.0)]
    pub arc_deg: Option<f64>,
    /// The pivot's position from the pad's leading edge, a fraction of the arc, in [0.1, 0.9]
    /// (0.5: central; nearer an edge a pad finds no moment-free tilt); default 0.65.
    #[schema(minimum = 0.1, maximum = 0.9, example = 0.65)]
    pub pivot_offset: Option<f64>,
}

/// Request. Give exactly one of `eccentricity_ratio` and `load_n`.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct TiltingPadGasJournalInput {
    /// D, L and the **machined** clearance C (the pads' radius is R + C).
    pub geometry: GeometrySpec,
    /// C′/C, the preload factor: the pivot clearance C′ (the film at a pivot of the centred
    /// journal) over the machined clearance; dimensionless, in [0.05, 0.95] (0 < C′/C < 1:
    /// C′ = C is no preload); the texts advise 0.3–0.8.
    #[schema(minimum = 0.05, maximum = 0.95, example = 0.3)]
    pub preload_factor: f64,
    #[serde(default)]
    pub pads: Option<GasTiltingPadsSpec>,
    /// Journal speed N, rev/min (> 0, at most 1e6).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 1e6, example = 200000.0)]
    pub speed_rpm: Positive,
    pub gas: GasSpec,
    /// ε′ = e′/C′, the journal's displacement toward the loaded pad over the pivot clearance,
    /// dimensionless, in [0, 0.95] (1: pad 3's pivot film closes); instead of `load_n`.
    #[schema(minimum = 0.0, maximum = 0.95, example = 0.5)]
    pub eccentricity_ratio: Option<f64>,
    /// Load W, N (> 0), directed at pad 3's pivot; instead of `eccentricity_ratio`.
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 1e9, example = 11.0)]
    pub load_n: Option<Positive>,
    /// `fast`, `standard` (default), `high`, or `{"grid": [cells along a pad 8…512 (even),
    /// half-length cells 2…128]}`; each is also solved on its half mesh and
    /// Richardson-extrapolated; a grid whose Newton solves would outlast the request's deadline
    /// is refused at once (422 at `/fidelity/grid`, with the estimate).
    #[serde(default)]
    pub fidelity: FidelityRequest,
}

/// The parsed request.
#[derive(Debug, Clone)]
pub struct Case {
    pub diameter_m: f64,
    pub length_m: f64,
    pub clearance_m: f64,
    pub preload_factor: f64,
    pub geometry: PadGeometry,
    pub speed_rpm: f64,
    pub gas: super::Gas,
    pub given: Given,
    pub method: Method,
}

impl Case {
    pub fn radius_m(&self) -> f64 {
        0.5 * self.diameter_m
    }
    /// Ω, rad/s.
    pub fn angular_speed(&self) -> f64 {
        self.speed_rpm * std::f64::consts::PI / 30.0
    }
    /// Λ = 6μΩ(R/C)²/p_a on the machined clearance.
    pub fn bearing_number(&self) -> f64 {
        6.0 * self.gas.viscosity_pa_s
            * self.angular_speed()
            * (self.radius_m() / self.clearance_m).powi(2)
            / self.gas.ambient_pressure_pa
    }
    pub fn bearing(&self) -> BearingFilm {
        BearingFilm {
            geometry: self.geometry,
            preload_factor: self.preload_factor,
            bearing_number: self.bearing_number(),
            l_over_d: self.length_m / self.diameter_m,
        }
    }
}

impl Validate for TiltingPadGasJournalInput {
    type Valid = Case;
    fn validate(self) -> Result<Case, Vec<FieldError>> {
        let mut errors = Vec::new();
        let (d, l, c) = self.geometry.check(&mut errors);
        let k = self.preload_factor;
        if !(k > 0.0 && k < 1.0) {
            errors.push(FieldError::new(
                "/preload_factor",
                format!("the preload factor C′/C must be within (0, 1): C′ ≥ C leaves no preload, C′ ≤ 0 puts the pads on the journal; got {k}"),
            ));
        } else if !(0.05..=0.95).contains(&k) {
            errors.push(FieldError::new(
                "/preload_factor",
                format!("the preload factor C′/C must be within [0.05, 0.95] (the films the grids resolve), got {k}"),
            ));
        }
        let pads = self.pads.unwrap_or(GasTiltingPadsSpec {
            arc_deg: None,
            pivot_offset: None,
        });
        let arc = pads.arc_deg.unwrap_or(DEFAULT_ARC_DEG);
        if !arc.is_finite() || arc > 120.0 {
            errors.push(FieldError::new(
                "/pads/arc_deg",
                format!("three pads of {arc}° overlap: a pad's arc must be at most 120°"),
            ));
        } else if arc < 20.0 {
            errors.push(FieldError::new(
                "/pads/arc_deg",
                format!("a pad's arc must be at least 20°, got {arc}"),
            ));
        }
        let offset = pads.pivot_offset.unwrap_or(DEFAULT_PIVOT_OFFSET);
        if !(offset > 0.0 && offset < 1.0) {
            errors.push(FieldError::new(
                "/pads/pivot_offset",
                format!("the pivot must lie on the pad, strictly between its leading (0) and trailing (1) edges; got {offset}"),
            ));
        } else if !(0.1..=0.9).contains(&offset) {
            errors.push(FieldError::new(
                "/pads/pivot_offset",
                format!("must be within [0.1, 0.9] of the arc from the leading edge: nearer an edge the pad has no moment-free tilt; got {offset}"),
            ));
        }
        let speed = self.speed_rpm.get();
        if speed > 1e6 {
            errors.push(FieldError::new(
                "/speed_rpm",
                format!("must be at most 1e6 rpm, got {speed}"),
            ));
        }
        let given = method::given(
            self.eccentricity_ratio,
            self.load_n,
            (0.0, MAX_ECCENTRICITY),
            "at ε′ ≥ 1 the loaded pad touches the journal at its pivot",
            "beyond, the loaded pad's pivot film (C′/C)(1 − ε′) is below a twentieth of the pivot clearance, the pad all but touching",
            &mut errors,
        );
        let method = method::parse(
            self.fidelity,
            tilting_pad_film::level_mesh,
            (8, 512),
            (2, 128),
            &mut errors,
        );
        let gas = self.gas.parse_into("/gas", &mut errors);
        let Some(gas) = gas.filter(|_| errors.is_empty()) else {
            return Err(errors);
        };
        let case = Case {
            diameter_m: d,
            length_m: l,
            clearance_m: c,
            preload_factor: k,
            geometry: PadGeometry {
                arc: arc.to_radians(),
                pivot_offset: offset,
            },
            speed_rpm: speed,
            gas,
            given,
            method,
        };
        method::check_bearing_number(
            case.bearing_number(),
            "/speed_rpm",
            "6μΩ(R/C)²/p_a",
            "each pad's film is at its Λ → ∞ limit",
        )
        .map_err(|e| vec![e])?;
        Ok(case)
    }
}

/// One pad at its moment-free tilt.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct GasTiltingPadResult {
    /// 1, 2 or 3 (pad 3 takes the load; 1 and 2 mirror each other).
    pub pad: u32,
    /// θ_p from the load line, in the direction of rotation, degrees.
    pub pivot_angle_deg: f64,
    /// H_p = h_p/C at the pivot, dimensionless (C the machined clearance).
    pub pivot_film_dimensionless: f64,
    /// h_p, m.
    pub pivot_film_m: f64,
    /// H_M, the pad's thinnest film over C, dimensionless.
    pub min_film_dimensionless: f64,
    /// h_M, m.
    pub min_film_m: f64,
    /// Where the thinnest film is, from the pad's leading edge, a fraction of the arc.
    pub min_film_position_fraction: f64,
    /// The pad's tilt δ about its pivot, rad (positive closes the trailing edge).
    pub tilt_rad: f64,
    /// F/(p_a R L): the pad's force, along its pivot line, pushing the journal away from it;
    /// dimensionless.
    pub load_coefficient: f64,
    /// The pad's force, N.
    pub load_n: f64,
    /// Its share of the load: its force's component against the load over W, dimensionless
    /// (pads 1 and 2, preloading the journal, push with the load: negative; the three add to 1);
    /// absent at ε′ = 0 (no load).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub load_share: Option<f64>,
    /// F_i = F_f/(p_a C L), the pad's friction on the journal, dimensionless (the text's pad
    /// friction coefficient, Fig. 11.22).
    pub friction_dimensionless: f64,
    /// F_f, the pad's friction force on the journal, N.
    pub friction_force_n: f64,
    /// Peak film pressure, Pa, **absolute**.
    pub max_pressure_pa: f64,
}

/// Response.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct TiltingPadGasJournalOutput {
    /// Λ = 6μΩ(R/C)²/p_a on the machined clearance, dimensionless.
    pub bearing_number: f64,
    /// C_LT = W/(p_a R L), dimensionless.
    pub load_coefficient: f64,
    /// W, N.
    pub load_n: f64,
    /// ε′ = e′/C′ (given, or found for the load).
    pub eccentricity_ratio: f64,
    /// C′/C.
    pub preload_factor: f64,
    /// C′, m.
    pub pivot_clearance_m: f64,
    /// The pad arc α used, degrees.
    pub pad_arc_deg: f64,
    /// The pivot position used, from the leading edge, a fraction of the arc.
    pub pivot_offset: f64,
    /// Pads 1, 2, 3.
    pub pads: Vec<GasTiltingPadResult>,
    /// The bearing's thinnest film (the least pad's h_M), m.
    pub min_film_m: f64,
    /// Σ F_fi, the friction force on the journal, N.
    pub friction_force_n: f64,
    /// Σ F_i = Σ F_fi/(p_a C L), dimensionless.
    pub friction_dimensionless: f64,
    /// R Σ F_fi, N·m.
    pub friction_torque_n_m: f64,
    /// Ω R Σ F_fi, W.
    pub power_loss_w: f64,
}

impl Calculation for TiltingPadGasJournal {
    const PATH: &'static str = "/v1/gas-bearings/tilting-pad-journal";
    const SUMMARY: &'static str =
        "Three-pad tilting-pad gas journal bearing, load on a pad: compressible Reynolds per pad, moment-free tilts, eccentricity or load, pivot and minimum films, pad friction, power";
    const DESCRIPTION: &'static str = include_str!("tilting_pad_journal.md");
    const FIDELITY: &'static [Level] = &[Level::Fast, Level::Standard, Level::High];
    const EFFECTS: &'static [&'static str] = &[];
    const EXAMPLE: &'static str = r#"{"geometry": {"diameter_m": 0.0127, "length_m": 0.0127, "radial_clearance_m": 1.508e-5}, "preload_factor": 0.3, "speed_rpm": 200000, "gas": {"viscosity_pa_s": 6.96e-6, "ambient_pressure_pa": 103421, "gas_constant_j_kg_k": 296.8}, "load_n": 11.12}"#;

    type Input = TiltingPadGasJournalInput;
    type Output = TiltingPadGasJournalOutput;

    fn run(case: Case, ctx: &mut Context) -> Result<TiltingPadGasJournalOutput, CalcError> {
        for (code, message) in &case.gas.assumptions {
            ctx.warn(code, message.clone());
        }
        let pa = case.gas.ambient_pressure_pa;
        let (r, l) = (case.radius_m(), case.length_m);
        let bearing = case.bearing();
        let budget = ctx.budget();
        // A pad of the centred journal: every pad's grid has its shape.
        let pad = PadFilm {
            geometry: bearing.geometry,
            pivot_film: bearing.preload_factor,
            tilt: 0.0,
            bearing_number: bearing.bearing_number,
            l_over_d: Some(bearing.l_over_d),
        };
        let grid = tilting_pad_film::grid(&pad, case.method.mesh);
        cost::check(
            case.method,
            tilting_pad_film::level_mesh,
            (&grid, tilting_pad_film::problem(&pad, &grid).far_edge),
            match case.given {
                Given::Eccentricity(_) => Least::TILTING_PAD_JOURNAL_AT_ECCENTRICITY,
                Given::Load(_) => Least::TILTING_PAD_JOURNAL_BY_LOAD,
            },
            &budget,
        )?;
        let (done, search) = match case.given {
            Given::Eccentricity(e) => (
                tilting_pad_film::at_eccentricity(
                    &bearing,
                    e,
                    case.method,
                    None,
                    &budget,
                    "/pads/pivot_offset",
                )?,
                None,
            ),
            Given::Load(w) => {
                let (done, report) =
                    tilting_pad_film::at_load(&bearing, w / (pa * r * l), case.method, &budget)?;
                (done, Some(report))
            }
        };
        let fine = &done.loaded.evaluated.fine.report;
        let (iterations, evaluations) = [&done.upper, &done.loaded]
            .iter()
            .fold((0, 0), |(i, e), p| {
                (i + p.evaluated.iterations, e + p.evaluated.evaluations)
            });
        let mut report = fine
            .clone()
            .named(if search.is_some() {
                "finite_volume_newton_fitted_flux_secant_tilt_secant_load"
            } else {
                "finite_volume_newton_fitted_flux_secant_tilt"
            })
            .counting(iterations, evaluations)
            .at(case.method.level)
            .on_grid(case.method.grid())
            .with_error_estimate(done.error_estimate())
            .with_film_solves(budget.field_solves());
        if let Some(s) = search {
            report.iterations = s.iterations;
            report.iterations_unit = s.iterations_unit;
        }
        ctx.report(report);
        CalcError::finite_or_out_of_range(
            output(&case, &done),
            "the bearing's size, speed and load",
        )
    }
}

/// Σ F_fi = p_a C L Σ F_i (N), the torque R Σ F_fi (N·m) and the power Ω R Σ F_fi (W) of the
/// pads' dimensionless frictions F_i = F_fi/(p_a C L) (Khonsari & Booser Ex 11.6, steps 6–7).
pub fn friction_totals(
    frictions: &[f64],
    ambient_pressure_pa: f64,
    clearance_m: f64,
    length_m: f64,
    radius_m: f64,
    angular_speed: f64,
) -> (f64, f64, f64) {
    let force = frictions.iter().sum::<f64>() * ambient_pressure_pa * clearance_m * length_m;
    (force, force * radius_m, force * radius_m * angular_speed)
}

/// The response from the bearing in equilibrium.
fn output(case: &Case, done: &BearingEquilibrium) -> TiltingPadGasJournalOutput {
    let pa = case.gas.ambient_pressure_pa;
    let (r, l, c) = (case.radius_m(), case.length_m, case.clearance_m);
    let load_coefficient = done.load();
    let load_n = load_coefficient * pa * r * l;
    let g = case.geometry;
    let pad = |n: usize, p: &PadEquilibrium| {
        let e = &p.evaluated;
        let (h_m, at) = e.film.min_film();
        let angle = PIVOT_ANGLES[n];
        // The free tilt τ = Rδ/C − (C′/C)ε′ sin θ_p (the journal's sideways share).
        let tilt = (e.film.tilt + case.preload_factor * done.eccentricity * angle.sin()) * c / r;
        let force = e.performance.load * pa * r * l;
        let friction = e.performance.friction_journal * pa * c * l;
        GasTiltingPadResult {
            pad: n as u32 + 1,
            pivot_angle_deg: angle.to_degrees(),
            pivot_film_dimensionless: e.film.pivot_film,
            pivot_film_m: e.film.pivot_film * c,
            min_film_dimensionless: h_m,
            min_film_m: h_m * c,
            min_film_position_fraction: (at - g.leading()) / g.arc,
            tilt_rad: tilt,
            load_coefficient: e.performance.load,
            load_n: force,
            load_share: (load_n.abs() > 0.0).then(|| force * angle.cos() / load_n),
            friction_dimensionless: e.performance.friction_journal,
            friction_force_n: friction,
            max_pressure_pa: e.performance.max_pressure * pa,
        }
    };
    let pads: Vec<GasTiltingPadResult> = done
        .pads()
        .iter()
        .enumerate()
        .map(|(n, p)| pad(n, p))
        .collect();
    let frictions: Vec<f64> = pads.iter().map(|p| p.friction_dimensionless).collect();
    let (friction_force_n, friction_torque_n_m, power_loss_w) =
        friction_totals(&frictions, pa, c, l, r, case.angular_speed());
    TiltingPadGasJournalOutput {
        bearing_number: case.bearing_number(),
        load_coefficient,
        load_n,
        eccentricity_ratio: done.eccentricity,
        preload_factor: case.preload_factor,
        pivot_clearance_m: case.preload_factor * c,
        pad_arc_deg: g.arc.to_degrees(),
        pivot_offset: g.pivot_offset,
        min_film_m: pads
            .iter()
            .map(|p| p.min_film_m)
            .fold(f64::INFINITY, f64::min),
        friction_force_n,
        friction_dimensionless: frictions.iter().sum(),
        friction_torque_n_m,
        power_loss_w,
        pads,
    }
}

#[cfg(test)]
#[path = "tilting_pad_journal_tests.rs"]
mod tests;
