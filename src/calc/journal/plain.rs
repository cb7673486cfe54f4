//! `POST /v1/journal-bearings/plain`: a plain 360° hydrodynamic journal bearing — equilibrium
//! from the load (or the field at a given eccentricity), film, pressure, friction, flow,
//! temperature, stiffness and damping, and the rigid-rotor stability threshold
//! (Khonsari & Booser ch. 8; Stachowiak & Batchelor ch. 4–5).

use serde::{Deserialize, Serialize};
use utoipa::ToSchema;

use super::eccentricity::EccentricityRatio;
use super::feed_spec::{FeedKind, FeedSpec};
use super::film::{Mesh, Misalignment};
use super::operating::{self, Case, Cavitation, CoefficientsMethod, Effects, Geometry, Solution};
use super::performance::{Approximation, Method, MAX_ECCENTRICITY};
use crate::calc::lubricant::LubricantSpec;
use crate::calc::quantity::{ratio_within, Celsius, Positive};
use crate::calc::{CalcError, Calculation, Context, FieldError, Validate};
use crate::effects::Mode;
use crate::fidelity::{FidelityRequest, Level};

pub struct PlainJournal;

/// Bearing geometry.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct GeometrySpec {
    /// Journal diameter D, m (> 0, at most 10).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 10.0, example = 0.1)]
    pub diameter_m: Positive,
    /// Bearing length L, m (> 0; L/D from 0.05 to 5).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 50.0, example = 0.1)]
    pub length_m: Positive,
    /// Radial clearance C, m (> 0; R/C from 50 to 10000, typically 500–1000).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 1.0, example = 0.0001)]
    pub radial_clearance_m: Positive,
}

impl GeometrySpec {
    /// D, L and C, with a 422 for each outside the journal room's ranges: D ≤ 10 m,
    /// L/D within [0.05, 5], R/C within [50, 10000]. Every journal-shaped room takes these.
    pub fn check(&self, errors: &mut Vec<FieldError>) -> (f64, f64, f64) {
        let (d, l, c) = (
            self.diameter_m.get(),
            self.length_m.get(),
            self.radial_clearance_m.get(),
        );
        if d > 10.0 {
            errors.push(FieldError::new(
                "/geometry/diameter_m",
                "must be at most 10 m",
            ));
        }
        let l_over_d = l / d;
        if !ratio_within(l_over_d, 0.05, 5.0) {
            errors.push(FieldError::new(
                "/geometry/length_m",
                format!("L/D must be within [0.05, 5], got {l_over_d:.4}"),
            ));
        }
        let r_over_c = 0.5 * d / c;
        if !(50.0..=1e4).contains(&r_over_c) {
            errors.push(FieldError::new(
                "/geometry/radial_clearance_m",
                format!("R/C must be within [50, 10000] (typical 500–1000), got {r_over_c:.1}"),
            ));
        }
        (d, l, c)
    }
}

/// A request's explicit journal grid `[circumferential cells 16…1024 (even), half-length
/// axial cells 2…256]` as the film's mesh (the journal and the squeezed journal take the same).
pub fn grid_mesh(grid: Option<[u32; 2]>, errors: &mut Vec<FieldError>) -> Option<Mesh> {
    let [n, m] = grid?;
    if !(16..=1024).contains(&n) || n % 2 != 0 || !(2..=256).contains(&m) {
        errors.push(FieldError::new(
            "/fidelity/grid",
            "must be [circumferential cells 16…1024 (even), half-length axial cells 2…256]",
        ));
    }
    Some(Mesh {
        circumferential: n as usize,
        axial_half: m as usize,
    })
}

/// Which closed form `fidelity: closed_form` uses.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum ClosedFormChoice {
    /// Short (Ocvirk) for L/D ≤ 1, long for L/D > 1, with a warning outside each one's range.
    #[default]
    Auto,
    /// Infinitely short bearing (Ocvirk; valid for L/D ≤ 1/2, trends to 1).
    Short,
    /// Infinitely long bearing (valid for L/D ≥ 2 or end-sealed bearings).
    Long,
}

/// How the film cavitates (see `JournalEffects::cavitation`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum CavitationMode {
    /// The Reynolds condition.
    #[default]
    Auto,
    /// The Reynolds condition.
    On,
    /// No cavitation: the full Sommerfeld film.
    Off,
    /// The Reynolds (Swift–Stieber) condition, p ≥ 0, solved exactly (active sets).
    Reynolds,
    /// Mass-conserving Jakobsson–Floberg–Olsson cavitation (Elrod–Adams film content).
    Jfo,
    /// Gümbel's half-Sommerfeld film: the full film, its negative pressures set to zero.
    HalfSommerfeld,
}

impl From<CavitationMode> for Cavitation {
    fn from(mode: CavitationMode) -> Cavitation {
        match mode {
            CavitationMode::Auto => Cavitation::Auto,
            CavitationMode::On => Cavitation::On,
            CavitationMode::Off => Cavitation::Off,
            CavitationMode::Reynolds => Cavitation::Reynolds,
            CavitationMode::Jfo => Cavitation::Jfo,
            CavitationMode::HalfSommerfeld => Cavitation::HalfSommerfeld,
        }
    }
}

/// Effects this calculation understands.
#[derive(Debug, Clone, Copy, Default, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct JournalEffects {
    /// Effective temperature T_e = T_in + k ΔT (Khonsari & Booser Eq. 8.63/8.64; k = 1, or ½
    /// for D < 50.8 mm) solved with μ(T_e) by a bracketed root find. `auto` applies it when the
    /// isothermal rise lowers the viscosity by more than 5 %.
    #[serde(default)]
    pub thermal: Mode,
    /// The cavitation model: `auto`, `on` and `reynolds` apply the Reynolds (Swift–Stieber)
    /// condition p ≥ 0 (the film ruptures where the pressure and its gradient vanish and refills
    /// wherever the pressure would rise: mass is not conserved across the cavitated zone; the
    /// Table 8.6 model). `half_sommerfeld` is Gümbel's film: the full film solved and its
    /// negative pressures set to zero afterwards (the legacy model of ROSS's `FluidFlow`; the
    /// short bearing's closed form; not mass-conserving), with stiffness and damping from the full
    /// film's response counted where it is positive. `jfo` applies mass-conserving Jakobsson–Floberg–Olsson cavitation (Elrod
    /// and Adams' film content θ_f ∈ [0, 1], complementarity p (1 − θ_f) = 0, upwind Couette
    /// fluxes): the film ruptures as with the Reynolds condition and reforms only where the
    /// streamers fill the gap again; it is fed flooded (θ_f = 1, at the edges' pressure) along a
    /// line across the whole length at h_max when no feed is given or with a circumferential
    /// groove (a partial arc: along its leading edge); a `hole`, `axial_groove` or `two_axial_grooves` feed becomes ports of
    /// its size at its supply pressure in a periodic 360° film (flooded, θ_f = 1, and held at
    /// P̄_s; elsewhere the film carries round what leaves the cavitated zone), where it sits:
    /// `opposite_load` (the default position, inside the Reynolds model's cavitated zone),
    /// `at_max_film`, or ±90° to the load line. The flow the ports supply is then the film's own
    /// (`inlet_flow_m3_s`). The friction then counts the Couette shear of the liquid only
    /// (θ_f/h in the cavitated zone). Costs about the same as the Reynolds condition per film;
    /// a feed away from h_max adds an attitude search. `off` keeps the full Sommerfeld film
    /// with its negative pressures (a film that cannot rupture: submerged at high ambient
    /// pressure).
    #[serde(default)]
    pub cavitation: CavitationMode,
    /// Turbulent film (Ng–Pan linearised coefficients for the pressure flows and the Couette
    /// shear, Khonsari & Booser Eq. 6.26–6.31, local Re = ρ U h/μ). `auto` applies it when the
    /// film Reynolds number ρ U C/μ at the inlet temperature exceeds 1000.
    #[serde(default)]
    pub turbulence: Mode,
    /// Fluid inertia: reported from the reduced Reynolds number Re·C/R against 1; not modelled.
    #[serde(default)]
    pub inertia: Mode,
    /// Journal misalignment (Khonsari & Booser Eq. 8.70: the whole-length film of a tilted
    /// journal). `auto` and `on` apply the request's `misalignment` when it gives one (the
    /// journal is aligned otherwise); `off` solves the aligned journal whatever `misalignment`
    /// gives.
    #[serde(default)]
    pub misalignment: Mode,
}

impl From<JournalEffects> for Effects {
    fn from(e: JournalEffects) -> Effects {
        Effects {
            thermal: e.thermal,
            cavitation: e.cavitation.into(),
            turbulence: e.turbulence,
            inertia: e.inertia,
            misalignment: e.misalignment,
        }
    }
}

/// Request. Give exactly one of `load_n` (the equilibrium is solved) and `eccentricity_ratio`.
#[derive(Debug, Clone, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct PlainInput {
    pub geometry: GeometrySpec,
    /// Journal speed, rev/min (> 0, at most 1e6); the bearing is stationary.
    #[schema(value_type = f64, minimum = 1e-6, maximum = 1e6, example = 3000.0)]
    pub speed_rpm: Positive,
    pub lubricant: LubricantSpec,
    /// Steady radial load W, N (1e-6 … 1e12).
    #[schema(value_type = Option<f64>, minimum = 1e-6, maximum = 1e12, example = 10000.0)]
    pub load_n: Option<Positive>,
    /// Eccentricity ratio ε = e/C, dimensionless, 0.0001 … 0.999 (instead of `load_n`).
    #[schema(minimum = 0.0001, maximum = 0.999, example = 0.6)]
    pub eccentricity_ratio: Option<f64>,
    /// Oil inlet temperature, °C (default 40): the viscosity is taken here, or at the effective
    /// temperature when the thermal effect applies.
    #[schema(value_type = Option<f64>, minimum = -273.0, maximum = 1000.0, example = 40.0)]
    pub inlet_temperature_c: Option<Celsius>,
    /// Bearing arc, degrees, centred on the load line (30 … 360; default 360, the full bearing fed
    /// at h_max). A partial bearing's edges are at ambient pressure; its line of centres is placed
    /// where the film force lies on the load line.
    #[schema(minimum = 30.0, maximum = 360.0, example = 360.0)]
    pub arc_deg: Option<f64>,
    /// Journal misalignment: the shaft's slope in the bearing and the plane it tilts in.
    pub misalignment: Option<MisalignmentSpec>,
    /// Oil feed: a hole or axial grooves with their supply pressure. Gives the pressure-fed and
    /// total flows (Martin's model) and puts the total flow in the heat balance; absent, the
    /// side leakage carries the heat (Table 8.6's ΔT).
    pub feed: Option<FeedSpec>,
    /// Rotor mass carried by this bearing, kg, 1e-6 … 1e8, for the stability threshold
    /// (default W/g).
    #[schema(value_type = Option<f64>, minimum = 1e-6, maximum = 1e8, example = 1000.0)]
    pub rotor_mass_kg: Option<Positive>,
    /// Stiffness of the shaft between the rotor mass and this bearing, N/m (a Jeffcott rotor:
    /// the shaft in series with the film; default rigid). Its flexibility γ = W/(k_s C) lowers
    /// the critical mass by 1 + γ k_eq (Hori's Routh–Hurwitz threshold as Stachowiak &
    /// Batchelor §5.6.4 give it; γ is their "dimensionless exciter mass").
    #[schema(value_type = Option<f64>, minimum = 1.0, maximum = 1e13, example = 1e8)]
    pub shaft_stiffness_n_m: Option<Positive>,
    /// `closed_form`, `fast`, `standard` (default), `high`, or `{"grid": [circumferential 16…1024,
    /// half-length axial 2…256], "tolerance": 1e-14…1e-3}` (the tolerance stops the
    /// mass-conserving film's sweeps; the Reynolds-condition film is solved exactly). An explicit
    /// grid of at least 96 × 12 that halves exactly is Richardson-extrapolated like `high`; a
    /// grid whose banded solves would outlast the request's deadline is refused at once (422
    /// at `/fidelity/grid`, with the estimate).
    #[serde(default)]
    pub fidelity: FidelityRequest,
    /// Which closed form `fidelity: closed_form` uses (default `auto`).
    #[serde(default)]
    pub closed_form: ClosedFormChoice,
    #[serde(default)]
    pub effects: JournalEffects,
    /// Compute stiffness, damping and the stability threshold (default true; false skips their
    /// cost: about ten further film solves, and the threshold search).
    #[serde(default = "yes")]
    #[schema(example = true)]
    pub dynamics: bool,
    /// Include the mid-plane pressure profile in the result (numerical fidelities; default false).
    #[serde(default)]
    #[schema(example = false)]
    pub include_field: bool,
}

fn yes() -> bool {
    true
}

impl Validate for PlainInput {
    type Valid = Case;
    fn validate(self) -> Result<Case, Vec<FieldError>> {
        let mut errors = Vec::new();
        let (d, l, c) = self.geometry.check(&mut errors);
        let l_over_d = l / d;
        // Below 1e-6 rev/min the Sommerfeld number leaves the range its searches work in (a
        // subnormal speed made S 0 and the equilibrium search a 500).
        if !(1e-6..=1e6).contains(&self.speed_rpm.get()) {
            errors.push(FieldError::new(
                "/speed_rpm",
                "must be within [1e-6, 1e6] rev/min",
            ));
        }
        if let Some(m) = self.rotor_mass_kg.map(Positive::get) {
            if !(1e-6..=1e8).contains(&m) {
                errors.push(FieldError::new(
                    "/rotor_mass_kg",
                    format!("must be within [1e-6, 1e8] kg (a micro-turbine's rotor to the largest turbine-generator's), got {m}"),
                ));
            }
        }
        let operating = match (self.load_n, self.eccentricity_ratio) {
            (Some(w), None) if (1e-6..=1e12).contains(&w.get()) => {
                Some(operating::Given::Load(w.get()))
            }
            (Some(w), None) => {
                errors.push(FieldError::new(
                    "/load_n",
                    format!("must be within [1e-6, 1e12] N, got {}", w.get()),
                ));
                None
            }
            (None, Some(eps)) if (1e-4..=MAX_ECCENTRICITY).contains(&eps) => {
                EccentricityRatio::new(eps).map(operating::Given::Eccentricity)
            }
            (None, Some(eps)) => {
                errors.push(FieldError::new(
                    "/eccentricity_ratio",
                    format!("must be within [0.0001, {MAX_ECCENTRICITY}], got {eps}: ε ≥ 1 means the journal touches the bearing"),
                ));
                None
            }
            _ => {
                errors.push(FieldError::new(
                    "/load_n",
                    "give exactly one of load_n and eccentricity_ratio",
                ));
                None
            }
        };
        let method = match self.fidelity {
            FidelityRequest::Level(Level::ClosedForm) => {
                Some(Method::ClosedForm(match self.closed_form {
                    ClosedFormChoice::Short => Approximation::Short,
                    ClosedFormChoice::Long => Approximation::Long,
                    ClosedFormChoice::Auto if l_over_d <= 1.0 => Approximation::Short,
                    ClosedFormChoice::Auto => Approximation::Long,
                }))
            }
            FidelityRequest::Level(level) => Some(Method::numerical(level, None, None)),
            FidelityRequest::Custom(custom) => {
                let mesh = grid_mesh(custom.grid, &mut errors);
                if let Some(t) = custom.tolerance {
                    if !(1e-14..=1e-3).contains(&t) {
                        errors.push(FieldError::new(
                            "/fidelity/tolerance",
                            "must be within [1e-14, 1e-3]",
                        ));
                    }
                }
                Some(Method::numerical(Level::Standard, mesh, custom.tolerance))
            }
        };
        if self.effects.cavitation == CavitationMode::Jfo
            && matches!(self.fidelity, FidelityRequest::Level(Level::ClosedForm))
        {
            errors.push(FieldError::new("/effects/cavitation", "the closed forms use the half-Sommerfeld or Reynolds condition; mass-conserving (jfo) cavitation needs a numerical fidelity"));
        }
        if self.effects.inertia == Mode::On {
            errors.push(FieldError::new("/effects/inertia", "fluid inertia is not modelled; use auto (the reduced Reynolds number is reported) or off"));
        }
        let arc = match self.arc_deg {
            None => None,
            Some(a) if a.is_finite() && (359.999..=360.0).contains(&a) => None,
            Some(a) if a.is_finite() && (30.0..360.0).contains(&a) => Some(a.to_radians()),
            Some(a) => {
                errors.push(FieldError::new(
                    "/arc_deg",
                    format!("must be within [30, 360] degrees, got {a}"),
                ));
                None
            }
        };
        if arc.is_some() && matches!(self.fidelity, FidelityRequest::Level(Level::ClosedForm)) {
            errors.push(FieldError::new("/arc_deg", "the closed forms are for the full 360° bearing; use a numerical fidelity for a partial arc"));
        }
        if arc.is_some() && self.feed.is_some() {
            errors.push(FieldError::new("/feed", "Martin's feed-flow model is for the full 360° bearing; a partial arc is fed at its edges"));
        }
        let misalignment = self.misalignment.and_then(|m| m.parse(l, c, &mut errors));
        if self.misalignment.is_some()
            && matches!(self.fidelity, FidelityRequest::Level(Level::ClosedForm))
            && self.effects.misalignment != Mode::Off
        {
            errors.push(FieldError::new(
                "/misalignment",
                "the closed forms are for an aligned journal; use a numerical fidelity",
            ));
        }
        if misalignment.is_some()
            && self.effects.misalignment != Mode::Off
            && self
                .feed
                .is_some_and(|f| f.kind == FeedKind::CircumferentialGroove)
        {
            errors.push(FieldError::new("/misalignment", "a misaligned bearing with a circumferential groove is not modelled (the two lands tilt differently)"));
        }
        let feed = match self.feed.map(|f| f.parse(l, d)) {
            Some(Ok(f)) => Some(f),
            Some(Err(mut e)) => {
                errors.append(&mut e);
                None
            }
            None => None,
        };
        let lubricant = self.lubricant.parse("/lubricant");
        let lubricant = match lubricant {
            Ok(l) => Some(l),
            Err(mut e) => {
                errors.append(&mut e);
                None
            }
        };
        // A circumferential groove: each land is a bearing of length (L − w_g)/2 carrying half
        // the load (Khonsari & Booser Eq. 8.61); the solve is of one land.
        let (length, operating) = match feed {
            Some(super::feed::Feed::CircumferentialGroove { width_m, .. }) => {
                let land = 0.5 * (l - width_m);
                if land / d < 0.05 {
                    errors.push(FieldError::new(
                        "/feed/groove_width_m",
                        "each land must keep L/D ≥ 0.05",
                    ));
                }
                let half = operating.map(|g| match g {
                    operating::Given::Load(w) => operating::Given::Load(0.5 * w),
                    e => e,
                });
                (land, half)
            }
            _ => (l, operating),
        };
        match (errors.is_empty(), operating, method, lubricant) {
            (true, Some(given), Some(method), Some(lubricant)) => Ok(Case {
                geometry: Geometry {
                    diameter_m: d,
                    length_m: length,
                    radial_clearance_m: c,
                },
                speed_rpm: self.speed_rpm.get(),
                lubricant,
                given,
                inlet_temperature_c: self.inlet_temperature_c.map(Celsius::get),
                feed,
                arc,
                misalignment,
                rotor_mass_kg: self.rotor_mass_kg.map(Positive::get),
                shaft_stiffness_n_m: self.shaft_stiffness_n_m.map(Positive::get),
                method,
                effects: self.effects.into(),
                dynamics: self.dynamics,
                include_field: self.include_field,
                turbulent: false,
            }),
            _ => Err(errors),
        }
    }
}

/// One node of the mid-plane pressure profile.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct ProfilePoint {
    /// θ from h_max in the direction of rotation, degrees.
    pub angle_deg: f64,
    /// Film pressure above the feed pressure, Pa (above ambient with `jfo` and a hole or
    /// axial-groove feed).
    pub pressure_pa: f64,
    /// Film content θ_f: the liquid fraction of the gap (1 in the full film, below 1 in the
    /// cavitated zone), dimensionless; with `effects.cavitation: jfo` only.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub film_content: Option<f64>,
}

/// The line a misalignment's direction is measured from.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum MisalignmentReference {
    #[default]
    LoadLine,
    LineOfCentres,
}

/// A tilted journal (Khonsari & Booser Eq. 8.70).
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct MisalignmentSpec {
    /// Slope of the journal axis relative to the bearing axis, rad (0 … 0.01; the text's rule of
    /// thumb for shaft deflection is 0.002 over half the bearing length).
    #[schema(value_type = f64, minimum = 0.0, maximum = 0.01, example = 0.0005)]
    pub slope_rad: crate::calc::quantity::NonNegative,
    /// Direction of the tilt: the plane it lies in, from the load line in the direction of
    /// rotation, degrees (−180 … 180; default 0, tilt in the load plane as a shaft bends under it).
    /// The journal's end at +z (z along its spin vector) is the one displaced this way; the
    /// other end moves the opposite way.
    #[serde(default)]
    #[schema(minimum = -180.0, maximum = 180.0, example = 0.0)]
    pub direction_deg: f64,
    /// What `direction_deg` is measured from: `load_line` (default; a tilt fixed in the bearing,
    /// as a shaft bending under its load — the convention of Stachowiak & Batchelor's PARTIAL
    /// and STABILITY programs, whose film h* = 1 + ε cos(x* − β) + y* t cos x* tilts in the load
    /// plane: `direction_deg` 0, ε′ = t) or `line_of_centres` (a tilt that follows the journal,
    /// where 0 tilts towards h_min: h_min = C(1 − ε) − ε′C/2 at one end).
    #[serde(default)]
    pub measured_from: MisalignmentReference,
}

impl MisalignmentSpec {
    /// The tilt of a journal of length `length_m` in the clearance `clearance_m`: ε′ = slope L/C
    /// (None for a zero slope); the ranges' and a tilt's that touches even when centred
    /// (ε′ ≥ 1.9) errors are pushed at their pointers.
    pub fn parse(
        &self,
        length_m: f64,
        clearance_m: f64,
        errors: &mut Vec<FieldError>,
    ) -> Option<Misalignment> {
        let tilt = self.slope_rad.get() * length_m / clearance_m;
        if self.slope_rad.get() > 0.01 {
            errors.push(FieldError::new(
                "/misalignment/slope_rad",
                "must be within [0, 0.01] rad",
            ));
        }
        if !(-180.0..=180.0).contains(&self.direction_deg) {
            errors.push(FieldError::new(
                "/misalignment/direction_deg",
                "must be within [-180, 180] degrees",
            ));
        }
        if tilt >= 1.9 {
            errors.push(FieldError::new(
                "/misalignment/slope_rad",
                format!("the ends of the journal move {tilt:.3} C apart: it would touch the bearing even when centred"),
            ));
        }
        (tilt > 0.0).then_some(Misalignment {
            tilt,
            direction: self.direction_deg.to_radians(),
            from_line_of_centres: self.measured_from == MisalignmentReference::LineOfCentres,
        })
    }
}

/// The film's moment on a misaligned journal.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct FilmMoment {
    /// The frame: x along the static load, y 90° ahead of it in the direction of rotation, z
    /// along the journal's spin vector (x, y, z right-handed); the tilted journal's end at +z is
    /// the one displaced towards `misalignment.direction_deg`. The moment is taken about the
    /// bearing centre (on the axis at mid-length).
    pub frame: String,
    /// Moment about x, N·m.
    pub mx_n_m: f64,
    /// Moment about y, N·m.
    pub my_n_m: f64,
    /// |M|, N·m.
    pub magnitude_n_m: f64,
    /// (M_x, M_y)/(μ N_s (R/C)² R L²), dimensionless (N_s in rev/s).
    pub dimensionless: [f64; 2],
    /// The moment's component against the tilt, N·m: −M·(z × u) for the tilt direction u (a
    /// tilt by the slope about z × u); positive when the film resists the misalignment.
    pub restoring_n_m: f64,
}

/// Stiffness and damping of the film.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct DynamicCoefficients {
    /// The frame: x along the static load, y perpendicular, 90° ahead in the direction of
    /// rotation; a film force f_i = −K_ij δ_j − C_ij δ̇_j on the journal.
    pub frame: String,
    /// K_xx, N/m.
    pub kxx: f64,
    /// K_xy, N/m.
    pub kxy: f64,
    /// K_yx, N/m.
    pub kyx: f64,
    /// K_yy, N/m.
    pub kyy: f64,
    /// C_xx, N·s/m.
    pub cxx: f64,
    /// C_xy, N·s/m.
    pub cxy: f64,
    /// C_yx, N·s/m.
    pub cyx: f64,
    /// C_yy, N·s/m.
    pub cyy: f64,
    /// K_ij C/W, dimensionless, [xx, xy, yx, yy].
    pub stiffness_dimensionless: [f64; 4],
    /// C_ij C ω/W, dimensionless, [xx, xy, yx, yy].
    pub damping_dimensionless: [f64; 4],
    /// How they were obtained.
    #[schema(
        example = "perturbation of the converged film: ±δ displacement and ±δ̇ velocity, central differences, feed line fixed at the equilibrium h_max, cavitation re-solved"
    )]
    pub method: String,
}

/// Rigid-rotor stability (Lund's linearised threshold).
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct Stability {
    /// Whether a rigid rotor of `rotor_mass_kg` runs stably at the operating speed.
    pub stable_at_operating_speed: bool,
    /// Speed at which oil whirl sets in, rev/min, holding load and viscosity (searched along the
    /// equilibrium locus on the `fast` mesh: a few per cent; a turbulent film's Reynolds number
    /// follows the speed along it); absent when none exists in the solved range (see
    /// `statement`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub threshold_speed_rpm: Option<f64>,
    /// Whirl frequency ratio at the operating point, dimensionless (about 0.5 for plain bearings);
    /// absent when the film cannot whirl.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub whirl_frequency_ratio: Option<f64>,
    /// Critical mass parameter m C ω²/W at the operating point (with the shaft's flexibility
    /// when `shaft_stiffness_n_m` is given); absent when stable for any mass.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub critical_mass_parameter: Option<f64>,
    /// Critical speed at the operating eccentricity, rad/s: ω_c = (m̄_c W/(m C))^½, the speed at
    /// which a rotor of `rotor_mass_kg` would whirl if the film kept this eccentricity and its
    /// dimensionless coefficients (Stachowiak & Batchelor's ω_c, §5.6.4); absent when stable
    /// for any mass.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub critical_speed_rad_s: Option<f64>,
    /// ω_c (C/g)^½, dimensionless: Stachowiak & Batchelor's ω*_c (with m = W/g it is
    /// (m̄_c)^½); absent when stable for any mass.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub critical_speed_dimensionless: Option<f64>,
    /// The rotor's m C ω²/W at the operating speed.
    pub mass_parameter: f64,
    /// Rotor mass used, kg.
    pub rotor_mass_kg: f64,
    /// The verdict in words.
    pub statement: String,
}

/// Result. Angles are measured from h_max in the direction of rotation. S and P̄ use N_s in rev/s.
#[derive(Debug, Clone, Serialize, ToSchema)]
pub struct PlainOutput {
    /// Steady load W, N (given, or carried at the given ε).
    pub load_n: f64,
    /// S = μ N_s L D (R/C)²/W, dimensionless, N_s in rev/s.
    pub sommerfeld_number: f64,
    /// ε = e/C, dimensionless.
    pub eccentricity_ratio: f64,
    /// φ, between the load line and the line of centres, degrees.
    pub attitude_angle_deg: f64,
    /// h_min = C (1 − ε), m.
    pub min_film_thickness_m: f64,
    /// Peak film pressure, Pa gauge: the film's P̄_max μ N_s (R/C)², plus the supply pressure
    /// when a feed is given (as Khonsari & Booser Ex 8.3 add it) — except with `jfo` and a hole
    /// or axial-groove feed, whose film holds the supply pressure at the ports itself.
    pub max_pressure_pa: f64,
    /// P̄_max = p_max (C/R)²/(μ N_s), dimensionless (Table 8.6 convention).
    pub max_pressure_dimensionless: f64,
    /// Angle of the peak from h_max (of the mid-plane when misaligned), degrees.
    pub max_pressure_angle_deg: f64,
    /// Film rupture angle from h_max (mid-plane), degrees; absent for a full film.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cavitation_start_angle_deg: Option<f64>,
    /// Share of the film's area that is cavitated (film content θ_f < 1), dimensionless 0 … 1;
    /// with `effects.cavitation: jfo` only.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cavitated_area_fraction: Option<f64>,
    /// Petroff's friction coefficient 2π² S (C/R), the concentric-journal estimate, dimensionless.
    pub petroff_friction_coefficient: f64,
    /// f = F/W, dimensionless; F is the journal-surface shear integrated over the full
    /// circumference (the convention of Table 8.6).
    pub friction_coefficient: f64,
    /// (R/C) f, dimensionless.
    pub friction_parameter: f64,
    /// Friction torque on the journal F R, N·m.
    pub friction_torque_n_m: f64,
    /// Power loss F U, W.
    pub power_loss_w: f64,
    /// Side leakage from both ends Q_L, m³/s (with a circumferential groove: one land's, as
    /// Khonsari & Booser Ex 8.5 count the hydrodynamic flow of the whole bearing).
    pub side_leakage_m3_s: f64,
    /// Q_L/((π/2) N_s D L C), dimensionless.
    pub side_leakage_dimensionless: f64,
    /// Flow entering at the feed line (θ = 0, h_max), m³/s; with `jfo` and a hole or axial-groove
    /// feed, the flow the ports supply, from the film (the side leakage: the film conserves
    /// mass); absent for closed forms.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub inlet_flow_m3_s: Option<f64>,
    /// Adiabatic oil temperature rise ΔT = E_p/(ρ c_p Q_L) (Khonsari & Booser Eq. 8.44), K;
    /// absent for the long-bearing closed form, which has no side leakage.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub temperature_rise_k: Option<f64>,
    /// Maximum bush temperature by Jang & Khonsari's THD fits (Khonsari & Booser Eq. 8.65,
    /// Table 8.11), °C; for temperature-dependent lubricants.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_temperature_c: Option<f64>,
    /// Shaft temperature by the same fits (about the mean film temperature), °C.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub shaft_temperature_c: Option<f64>,
    /// Pressure-fed flow through the feed Q_p, m³/s (Martin, Eq. 8.53–8.57); with a feed, except
    /// a JFO film fed through ports, whose supply is `inlet_flow_m3_s`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub supply_flow_m3_s: Option<f64>,
    /// Total flow drawn from the supply, m³/s (Martin, Eq. 8.58–8.60); with a feed, except a
    /// JFO film fed through ports (its supply is `inlet_flow_m3_s`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub total_flow_m3_s: Option<f64>,
    /// Temperature at which the viscosity was taken, °C (the inlet temperature, or the effective
    /// temperature when the thermal effect applied).
    pub effective_temperature_c: f64,
    /// Viscosity used, Pa·s.
    pub effective_viscosity_pa_s: f64,
    /// Film Reynolds number ρ U C/μ, dimensionless.
    pub reynolds_number: f64,
    /// The closed form used at `fidelity: closed_form`: `short_half_sommerfeld`,
    /// `short_full_sommerfeld`, `long_reynolds` or `long_full_sommerfeld`; absent for the
    /// numerical solution.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub approximation: Option<String>,
    /// Why that approximation, and how well it fits the L/D asked.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub approximation_note: Option<String>,
    /// Mid-plane pressure profile, with `include_field` and a numerical fidelity.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pressure_profile: Option<Vec<ProfilePoint>>,
    /// The film's moment on the journal when `misalignment` is given (absent when aligned: it
    /// is then zero by symmetry).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub misalignment_moment: Option<FilmMoment>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub dynamic_coefficients: Option<DynamicCoefficients>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub stability: Option<Stability>,
}

impl Calculation for PlainJournal {
    const PATH: &'static str = "/v1/journal-bearings/plain";
    const SUMMARY: &'static str = "Plain 360° journal bearing: equilibrium, film, friction, flow, temperature, K and C, stability";
    const DESCRIPTION: &'static str = include_str!("plain.md");
    const FIDELITY: &'static [Level] =
        &[Level::ClosedForm, Level::Fast, Level::Standard, Level::High];
    const EFFECTS: &'static [&'static str] = &[
        "thermal",
        "cavitation",
        "turbulence",
        "inertia",
        "misalignment",
    ];
    const EXAMPLE: &'static str = r#"{"geometry": {"diameter_m": 0.1, "length_m": 0.1, "radial_clearance_m": 0.0001}, "speed_rpm": 3000, "lubricant": {"iso_vg": 32}, "load_n": 10000, "inlet_temperature_c": 40}"#;

    type Input = PlainInput;
    type Output = PlainOutput;

    fn run(case: Case, ctx: &mut Context) -> Result<PlainOutput, CalcError> {
        let solution = operating::solve(&case, &ctx.budget())?;
        ctx.record(&solution.notes);
        ctx.report(solution.report.clone());
        Ok(PlainOutput::from(solution))
    }
}

impl From<Solution> for PlainOutput {
    fn from(s: Solution) -> PlainOutput {
        PlainOutput {
            load_n: s.load_n,
            sommerfeld_number: s.sommerfeld_number,
            eccentricity_ratio: s.eccentricity_ratio.get(),
            attitude_angle_deg: s.attitude_angle.to_degrees(),
            min_film_thickness_m: s.min_film_thickness_m,
            max_pressure_pa: s.max_pressure_pa,
            max_pressure_dimensionless: s.max_pressure_nd,
            max_pressure_angle_deg: s.max_pressure_angle.to_degrees(),
            cavitation_start_angle_deg: s.cavitation_start_angle.map(f64::to_degrees),
            cavitated_area_fraction: s.cavitated_area_fraction,
            petroff_friction_coefficient: s.petroff_friction_coefficient,
            friction_coefficient: s.friction_coefficient,
            friction_parameter: s.friction_parameter,
            friction_torque_n_m: s.friction_torque_n_m,
            power_loss_w: s.power_loss_w,
            side_leakage_m3_s: s.side_leakage_m3_s,
            side_leakage_dimensionless: s.side_leakage_nd,
            inlet_flow_m3_s: s.inlet_flow_m3_s,
            temperature_rise_k: s.temperature_rise_k,
            max_temperature_c: s.bush_temperatures.map(|t| t.max_c),
            shaft_temperature_c: s.bush_temperatures.map(|t| t.shaft_c),
            supply_flow_m3_s: s.flows.map(|f| f.pressure_fed),
            total_flow_m3_s: s.flows.map(|f| f.total),
            effective_temperature_c: s.effective_temperature_c,
            effective_viscosity_pa_s: s.effective_viscosity_pa_s,
            reynolds_number: s.reynolds_number,
            approximation: s.approximation.map(String::from),
            approximation_note: s.approximation_note,
            pressure_profile: s.pressure_profile.map(|nodes| {
                nodes
                    .into_iter()
                    .map(|n| ProfilePoint {
                        angle_deg: n.angle.to_degrees(),
                        pressure_pa: n.pressure_pa,
                        film_content: n.film_content,
                    })
                    .collect()
            }),
            misalignment_moment: s.moment.map(|m| FilmMoment {
                frame: "x along the static load, y 90° ahead in the direction of rotation, z along the spin; the +z end of the journal is displaced towards the tilt direction; about the bearing centre".into(),
                mx_n_m: m.mx_n_m,
                my_n_m: m.my_n_m,
                magnitude_n_m: m.magnitude_n_m,
                dimensionless: m.nd,
                restoring_n_m: m.restoring_n_m,
            }),
            dynamic_coefficients: s.dynamics.as_ref().map(|d| {
                let [kxx, kxy, kyx, kyy] = d.stiffness_n_m;
                let [cxx, cxy, cyx, cyy] = d.damping_n_s_m;
                DynamicCoefficients {
                    frame: "x along the static load, y perpendicular to it, 90° ahead in the direction of rotation".into(),
                    kxx, kxy, kyx, kyy, cxx, cxy, cyx, cyy,
                    stiffness_dimensionless: d.stiffness_nd,
                    damping_dimensionless: d.damping_nd,
                    method: match d.method {
                        CoefficientsMethod::ShortBearing => "closed form of the short (Ocvirk) bearing with the half-Sommerfeld film",
                        CoefficientsMethod::PerturbationMassConserving => "perturbation of the converged film: ±δ displacement and ±δ̇ velocity along each axis, central differences, feed line fixed where the equilibrium film is fed, pressure and film content re-solved (JFO) in each perturbed film, the squeeze term weighted by the film content (∂(θ_f h)/∂t ≈ θ_f ∂h/∂t)",
                        CoefficientsMethod::Perturbation => "perturbation of the converged film: ±δ displacement and ±δ̇ velocity along each axis, central differences, feed line fixed at the equilibrium h_max, cavitation re-solved in each perturbed film",
                    }
                    .into(),
                }
            }),
            stability: s.dynamics.map(|d| {
                let t = d.stability;
                Stability {
                    stable_at_operating_speed: t.stable_at_operating_speed,
                    threshold_speed_rpm: t.threshold_speed_rpm,
                    whirl_frequency_ratio: t.whirl_frequency_ratio,
                    critical_mass_parameter: t.critical_mass_parameter,
                    critical_speed_rad_s: t.critical_speed_rad_s,
                    critical_speed_dimensionless: t.critical_speed_nd,
                    mass_parameter: t.mass_parameter,
                    rotor_mass_kg: t.rotor_mass_kg,
                    statement: t.statement,
                }
            }),
        }
    }
}

#[cfg(test)]
mod tests;
