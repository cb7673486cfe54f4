//! The closed-form EHL film formulas both EHL rooms read: the Hamrock–Dowson groups and the
//! hard and soft point-contact fits, the four regime films in the reduced groups and the regime
//! rule, and the line-contact fits (Pan–Hamrock, Dowson–Higginson, Moes' asymptotes), with
//! the fitted ranges. Dimensionless throughout: U = η₀ū/(E′R_x), G = αE′, W = F/(E′R_x²),
//! H = h/R_x (Hamrock eqs 21.52–21.67).

use serde::Serialize;
use utoipa::ToSchema;

use crate::calc::Warning;

/// Ellipticities the hard-EHL fit was made over (34 cases, k = 1 … 8: Hamrock §21.3.3).
pub const HARD_FIT_ELLIPTICITY: (f64, f64) = (1.0, 8.0);
/// Ellipticities of the soft-EHL fit (17 cases, k = 1 … 12: Hamrock §21.3.4).
pub const SOFT_FIT_ELLIPTICITY: (f64, f64) = (1.0, 12.0);
/// U and W of the hard-EHL fit: the texts say "U over about 2 decades, W over 1 decade" from
/// the base case U = 0.168 × 10⁻¹¹, W = 0.111 × 10⁻⁶ (Hamrock Figs 21.70–21.71, Stachowiak
/// Figs 7.17–7.19, G = 4522); the upper ends are that statement, not a table (verify against
/// Hamrock & Dowson 1977, J. Lubr. Technol. 99:264).
pub const HARD_FIT_SPEED: (f64, f64) = (1.683e-12, 1.683e-10);
pub const HARD_FIT_LOAD: (f64, f64) = (1.106e-7, 1.106e-6);

// `Regime` is a value the responses carry by name; it derives its wire form here rather than
// through a mirror enum of the same four variants.
/// Fluid-film lubrication regime of the Hamrock–Dowson map.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, ToSchema)]
#[serde(rename_all = "kebab-case")]
pub enum Regime {
    IsoviscousRigid,
    PiezoviscousRigid,
    IsoviscousElastic,
    PiezoviscousElastic,
}

impl Regime {
    /// The regime from whether elastic deformation and piezoviscosity each count. See
    /// [`point_regime`].
    pub fn of(elastic: bool, piezoviscous: bool) -> Self {
        match (piezoviscous, elastic) {
            (false, false) => Regime::IsoviscousRigid,
            (true, false) => Regime::PiezoviscousRigid,
            (false, true) => Regime::IsoviscousElastic,
            (true, true) => Regime::PiezoviscousElastic,
        }
    }

    /// `isoviscous-rigid`, … as on the wire.
    pub fn name(self) -> &'static str {
        match self {
            Regime::IsoviscousRigid => "isoviscous-rigid",
            Regime::PiezoviscousRigid => "piezoviscous-rigid",
            Regime::IsoviscousElastic => "isoviscous-elastic",
            Regime::PiezoviscousElastic => "piezoviscous-elastic",
        }
    }
}

/// The Hamrock–Dowson dimensionless groups U, G, W (all positive and finite for valid input).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Groups {
    pub u: f64,
    pub g: f64,
    pub w: f64,
}

impl Groups {
    /// Reduced viscosity parameter g_v = GW³/U² (Hamrock eq. 21.60).
    pub fn viscosity_parameter(&self) -> f64 {
        self.g * self.w.powi(3) / (self.u * self.u)
    }

    /// Reduced elasticity parameter g_e = W^(8/3)/U² (Hamrock eq. 21.61).
    pub fn elasticity_parameter(&self) -> f64 {
        self.w.powf(8.0 / 3.0) / (self.u * self.u)
    }

    /// H from a reduced film Ĥ = H(W/U)² (Hamrock eq. 21.59).
    pub fn film_from_reduced(&self, reduced: f64) -> f64 {
        reduced * (self.u / self.w).powi(2)
    }
}

/// Hamrock–Dowson hard-EHL minimum film H_min = h_min/R_x (Hamrock eq. 21.57).
pub fn hard_min_film(g: &Groups, k: f64) -> f64 {
    3.63 * g.u.powf(0.68) * g.g.powf(0.49) * g.w.powf(-0.073) * (1.0 - (-0.68 * k).exp())
}

/// Hamrock–Dowson hard-EHL central film H_c = h_c/R_x (Stachowiak eq. 7.26).
pub fn hard_central_film(g: &Groups, k: f64) -> f64 {
    2.69 * g.u.powf(0.67) * g.g.powf(0.53) * g.w.powf(-0.067) * (1.0 - 0.61 * (-0.73 * k).exp())
}

/// Hamrock–Dowson soft-EHL minimum film (Hamrock eq. 21.58; no G: negligible piezoviscosity).
pub fn soft_min_film(g: &Groups, k: f64) -> f64 {
    7.43 * g.u.powf(0.65) * g.w.powf(-0.21) * (1.0 - 0.85 * (-0.31 * k).exp())
}

/// The reduced films Ĥ of the four regimes of an elliptical contact (Hamrock eqs 21.62–21.67;
/// the central films of the elastic regimes from Stachowiak §7.4).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RegimeFilms {
    /// Isoviscous–rigid Ĥ (minimum = central).
    pub isoviscous_rigid: f64,
    /// Piezoviscous–rigid Ĥ (minimum = central).
    pub piezoviscous_rigid: f64,
    /// Isoviscous–elastic Ĥ_min and Ĥ_c.
    pub isoviscous_elastic: (f64, f64),
    /// Piezoviscous–elastic Ĥ_min and Ĥ_c.
    pub piezoviscous_elastic: (f64, f64),
}

/// Ĥ of the four regimes for reduced groups g_v, g_e, ellipticity k and radius ratio
/// α_r = R_y/R_x: Ĥ_ir = 128 α_r λ_b² [0.131 atan(α_r/2) + 1.683]², λ_b = (1 + 2/(3α_r))⁻¹
/// (eqs 21.62–21.64, with the exact α_r as Stachowiak advises rather than α_r ≈ k^(π/2));
/// Ĥ_pvr = 1.66 g_v^⅔ (1 − e^−0.68k); Ĥ_ie = 8.70 g_e^0.67 (1 − 0.85e^−0.31k),
/// Ĥ_ie,c = 11.15 g_e^0.67 (1 − 0.72e^−0.28k); Ĥ_pve = 3.42 g_v^0.49 g_e^0.17 (1 − e^−0.68k),
/// Ĥ_pve,c = 3.61 g_v^0.53 g_e^0.13 (1 − 0.61e^−0.73k).
pub fn regime_films(gv: f64, ge: f64, k: f64, radius_ratio: f64) -> RegimeFilms {
    let lambda_b = 1.0 / (1.0 + 2.0 / (3.0 * radius_ratio));
    let bracket = 0.131 * (radius_ratio / 2.0).atan() + 1.683;
    RegimeFilms {
        isoviscous_rigid: 128.0 * radius_ratio * lambda_b * lambda_b * bracket * bracket,
        piezoviscous_rigid: 1.66 * gv.powf(2.0 / 3.0) * (1.0 - (-0.68 * k).exp()),
        isoviscous_elastic: (
            8.70 * ge.powf(0.67) * (1.0 - 0.85 * (-0.31 * k).exp()),
            11.15 * ge.powf(0.67) * (1.0 - 0.72 * (-0.28 * k).exp()),
        ),
        piezoviscous_elastic: (
            3.42 * gv.powf(0.49) * ge.powf(0.17) * (1.0 - (-0.68 * k).exp()),
            3.61 * gv.powf(0.53) * ge.powf(0.13) * (1.0 - 0.61 * (-0.73 * k).exp()),
        ),
    }
}

/// The regime of an elliptical contact. The texts draw the map (Hamrock Figs 21.72–21.74,
/// Stachowiak Fig. 7.20) but give no numeric rule (spec A.1.6, a gap), so this is a design
/// decision (verify against Hamrock & Dowson 1979): an effect counts when including it raises
/// the film, judged between adjacent regimes. Elastic when Ĥ_ie > Ĥ_ir (the IR–IE boundary where
/// those formulas are equal); then piezoviscous when Ĥ_pve > Ĥ_ie (IE–PE boundary), or, for a
/// rigid contact, when Ĥ_pvr > Ĥ_ir (IR–PR boundary). Comparing Ĥ_pvr with Ĥ_pve directly
/// would call a heavily loaded ball bearing (Hamrock's own example, g_v ≈ 5 × 10¹³)
/// piezoviscous–rigid, because Ĥ_pvr grows as W² without bound; this rule gives
/// piezoviscous–elastic for it and for the Hamrock–Dowson base case (spec A-R5).
pub fn point_regime(films: &RegimeFilms) -> Regime {
    let elastic = films.isoviscous_elastic.0 > films.isoviscous_rigid;
    let piezoviscous = if elastic {
        films.piezoviscous_elastic.0 > films.isoviscous_elastic.0
    } else {
        films.piezoviscous_rigid > films.isoviscous_rigid
    };
    Regime::of(elastic, piezoviscous)
}

/// Pan & Hamrock (1989), line contact, H_min = 1.714 W′^−0.128 U^0.694 G^0.568 and
/// H_c = 2.922 W′^−0.166 U^0.692 G^0.470 (J. Tribol. 111:246; not in the texts: verify).
pub fn pan_hamrock(g: &Groups, line_load: f64) -> (f64, f64) {
    (
        2.922 * line_load.powf(-0.166) * g.u.powf(0.692) * g.g.powf(0.470),
        1.714 * line_load.powf(-0.128) * g.u.powf(0.694) * g.g.powf(0.568),
    )
}

/// Dowson–Higginson line-contact minimum film H_min = 2.65 G^0.54 U^0.7 W′^−0.13
/// (Khonsari & Booser eq. 15.10).
pub fn dowson_higginson(g: &Groups, line_load: f64) -> f64 {
    2.65 * g.g.powf(0.54) * g.u.powf(0.7) * line_load.powf(-0.13)
}

/// Moes' line-contact asymptotes in M = W′(2U)^(−1/2), L = G(2U)^(1/4) (the factor 2: Moes
/// uses the sum speed), film H_M = H (2U)^(−1/2): rigid–isoviscous 3M⁻¹, elastic–isoviscous
/// 2.621 M^(−1/5), rigid–piezoviscous 1.287 L^(2/3), elastic–piezoviscous 1.311 M^(−1/8) L^(3/4)
/// (Moes 1992; Venner & Lubrecht 2000 §8; not in the texts: verify).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MoesAsymptotes {
    pub rigid_isoviscous: f64,
    pub elastic_isoviscous: f64,
    pub rigid_piezoviscous: f64,
    pub elastic_piezoviscous: f64,
}

impl MoesAsymptotes {
    pub fn new(m: f64, l: f64) -> Self {
        MoesAsymptotes {
            rigid_isoviscous: 3.0 / m,
            elastic_isoviscous: 2.621 * m.powf(-0.2),
            rigid_piezoviscous: 1.287 * l.powf(2.0 / 3.0),
            elastic_piezoviscous: 1.311 * m.powf(-0.125) * l.powf(0.75),
        }
    }

    /// Moes' central film H_M = {[H_RI^(7/3) + H_EI^(7/3)]^(3s/7) +
    /// [H_RP^(−7/2) + H_EP^(−7/2)]^(−2s/7)}^(1/s), s = 1.5 [1 + exp(−1.2 H_EI/H_RI)].
    pub fn central(&self) -> f64 {
        let s = 1.5 * (1.0 + (-1.2 * self.elastic_isoviscous / self.rigid_isoviscous).exp());
        let iso = (self.rigid_isoviscous.powf(7.0 / 3.0) + self.elastic_isoviscous.powf(7.0 / 3.0))
            .powf(3.0 * s / 7.0);
        let piezo = (self.rigid_piezoviscous.powf(-3.5) + self.elastic_piezoviscous.powf(-3.5))
            .powf(-2.0 * s / 7.0);
        (iso + piezo).powf(1.0 / s)
    }

    /// The same rule as [`point_regime`], on the asymptotes.
    pub fn regime(&self) -> Regime {
        let elastic = self.elastic_isoviscous > self.rigid_isoviscous;
        let piezoviscous = if elastic {
            self.elastic_piezoviscous > self.elastic_isoviscous
        } else {
            self.rigid_piezoviscous > self.rigid_isoviscous
        };
        Regime::of(elastic, piezoviscous)
    }
}

/// The range warning for the point-contact fit in use, if it is used outside its fitted range.
pub fn outside_fit(g: &Groups, k: f64, regime: Regime) -> Option<Warning> {
    let mut out = Vec::new();
    let within = |(lo, hi): (f64, f64), x: f64| (lo..=hi).contains(&x);
    match regime {
        Regime::PiezoviscousElastic => {
            if !within(HARD_FIT_ELLIPTICITY, k) {
                out.push(format!("k = {k:.3} outside 1–8"));
            }
            if !within(HARD_FIT_SPEED, g.u) {
                out.push(format!(
                    "U = {:.3e} outside {:.3e}–{:.3e}",
                    g.u, HARD_FIT_SPEED.0, HARD_FIT_SPEED.1
                ));
            }
            if !within(HARD_FIT_LOAD, g.w) {
                out.push(format!(
                    "W = {:.3e} outside {:.3e}–{:.3e}",
                    g.w, HARD_FIT_LOAD.0, HARD_FIT_LOAD.1
                ));
            }
        }
        Regime::IsoviscousElastic if !within(SOFT_FIT_ELLIPTICITY, k) => {
            out.push(format!("k = {k:.3} outside 1–12"));
        }
        _ => {}
    }
    (!out.is_empty()).then(|| Warning {
        code: "outside_fitted_range",
        message: format!(
            "the {} film formula is used outside the range it was fitted over ({}): the result is an extrapolation (Hamrock §21.3.3–21.3.4)",
            regime.name(),
            out.join("; ")
        ),
    })
}
