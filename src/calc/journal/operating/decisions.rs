//! The effects the plain bearing decides at run time (turbulence, inertia, cavitation,
//! misalignment), the closed form's name and note, and the validity warnings.

use super::{Case, Effects, Geometry, Notes, TURBULENT_REYNOLDS};
use crate::calc::journal::feed::Feed;
use crate::calc::journal::film::{FeedLine, Misalignment};
use crate::calc::journal::performance::{Approximation, Method, Point};
use crate::effects::{Criterion, Decision};

/// Turbulence: `auto` applies the Ng–Pan film above a film Reynolds number of 1000 (at the
/// inlet temperature); the closed forms are laminar only.
pub(super) fn decide_turbulence(notes: &mut Notes, case: &Case, reynolds: f64) -> bool {
    let criterion = Criterion {
        name: "film_reynolds_number",
        value: reynolds,
        threshold: TURBULENT_REYNOLDS,
    };
    let decision = Decision::decide(case.effects.turbulence, criterion, "turbulence");
    if decision.applied && matches!(case.method, Method::ClosedForm(_)) {
        notes.warn(
            "turbulent_film",
            format!("film Reynolds number {reynolds:.0}: the film is turbulent, but the closed forms are laminar and underestimate friction and load capacity; use a numerical fidelity"),
        );
        notes.decide(
            "turbulence",
            Decision {
                applied: false,
                reason: format!("{}; closed forms are laminar", decision.reason),
                ..decision
            },
        );
        return false;
    }
    let applied = decision.applied;
    let reason = if applied {
        format!(
            "{}: linearised turbulent film (Ng–Pan coefficients, Khonsari & Booser Eq. 6.26–6.31)",
            decision.reason
        )
    } else {
        decision.reason.clone()
    };
    notes.decide("turbulence", Decision { reason, ..decision });
    applied
}

pub(super) fn decide_inertia(notes: &mut Notes, effects: Effects, reynolds: f64, g: Geometry) {
    let reduced = reynolds * g.radial_clearance_m / (0.5 * g.diameter_m);
    let inertia = Decision::decide(
        effects.inertia,
        Criterion {
            name: "reduced_reynolds_number",
            value: reduced,
            threshold: 1.0,
        },
        "inertia",
    );
    if inertia.applied {
        notes.warn("fluid_inertia", format!("reduced Reynolds number {reduced:.2} exceeds 1: fluid inertia matters and is not modelled"));
    }
    notes.decide(
        "inertia",
        Decision {
            applied: false,
            ..inertia
        },
    );
}

pub(super) fn approximation_name(case: &Case) -> Option<&'static str> {
    let cav = case.cavitation();
    match case.method {
        Method::ClosedForm(Approximation::Short) => Some(if cav {
            "short_half_sommerfeld"
        } else {
            "short_full_sommerfeld"
        }),
        Method::ClosedForm(Approximation::Long) => Some(if case.half_sommerfeld() {
            "long_half_sommerfeld"
        } else if cav {
            "long_reynolds"
        } else {
            "long_full_sommerfeld"
        }),
        Method::Numerical { .. } => None,
    }
}

pub(super) fn approximation_note(case: &Case) -> Option<String> {
    let ld = case.geometry.l_over_d();
    match case.method {
        Method::ClosedForm(Approximation::Short) => Some(if ld <= 0.5 {
            format!("infinitely short bearing (Ocvirk): axial pressure flow dominates; valid for L/D ≤ 0.5, and L/D = {ld:.3} fits")
        } else {
            format!("infinitely short bearing (Ocvirk): chosen for L/D ≤ 1 but valid only to L/D = 0.5; at L/D = {ld:.3} it gives trends, not numbers")
        }),
        Method::ClosedForm(Approximation::Long) => Some(if ld >= 2.0 {
            format!("infinitely long bearing: circumferential flow dominates; it suits L/D ≥ 2 or end-sealed bearings, and L/D = {ld:.3} fits")
        } else {
            format!("infinitely long bearing: it suits L/D ≥ 2; at L/D = {ld:.3} it overestimates the load capacity")
        }),
        Method::Numerical { .. } => None,
    }
}

pub(super) fn validity_warnings(notes: &mut Notes, case: &Case, point: &Point) {
    let ld = case.geometry.l_over_d();
    match case.method {
        Method::ClosedForm(Approximation::Short) if ld > 0.5 => notes.warn(
            "short_bearing_outside_validity",
            format!("the short-bearing approximation holds for L/D ≤ 0.5 (trends to 1); L/D = {ld:.3}: use a numerical fidelity"),
        ),
        Method::ClosedForm(Approximation::Long) if ld < 2.0 => notes.warn(
            "long_bearing_outside_validity",
            format!("the long-bearing approximation overestimates load capacity below L/D ≈ 2; L/D = {ld:.3}: use a numerical fidelity"),
        ),
        _ => {}
    }
    let eps = point.eccentricity_ratio.get();
    if eps > 0.95 {
        notes.warn(
            "very_high_eccentricity",
            format!("ε = {eps:.4}: the minimum film is {:.1} % of the clearance; surface roughness, elastic and thermal distortion matter here", 100.0 * (1.0 - eps)),
        );
    }
}

/// Cavitation: the Reynolds condition, mass-conserving JFO with its supply, or off.
pub(super) fn decide_cavitation(notes: &mut Notes, case: &Case, temperature_c: f64) {
    let cavitation = Decision {
        applied: case.cavitation(),
        mode: case.effects.cavitation.mode(),
        reason: match (case.cavitation(), case.supply(temperature_c)) {
            (false, _) => "requested off: full Sommerfeld film, negative pressures kept".into(),
            (true, None) if case.half_sommerfeld() => "Gümbel's half-Sommerfeld film: the full film solved, its negative pressures set to zero afterwards (the model of legacy codes and of the short bearing's closed form; it does not conserve mass at the rupture: `reynolds` is the physical condition)".into(),
            (true, None) => "Reynolds (Swift–Stieber) condition: p ≥ 0, the film ruptures where the pressure and its gradient vanish (auto keeps it; `jfo` conserves mass through rupture and reformation)".into(),
            (true, Some(supply)) => format!(
                "mass-conserving JFO cavitation (Elrod–Adams film content, finite volumes): rupture and reformation conserve mass; fed {}",
                match (supply.position, supply.port) {
                    (FeedLine::MaxFilm, None) => "flooded along a line at h_max".to_string(),
                    (FeedLine::OppositeLoad, None) => "flooded along a line opposite the load".to_string(),
                    (position, Some(port)) => format!(
                        "through the feed at {} at P̄_s = {:.4} (supply pressure), a periodic 360° film elsewhere",
                        match position {
                            FeedLine::MaxFilm => "h_max",
                            FeedLine::OppositeLoad => "the top, opposite the load",
                            FeedLine::TwoGrooves => "±90° to the load line",
                        },
                        port.pressure_nd
                    ),
                    (FeedLine::TwoGrooves, None) => "through two grooves".to_string(),
                }
            ),
        },
        criterion: None,
        model: case.cavitation().then_some(if case.mass_conserving() {
            "jfo"
        } else if case.half_sommerfeld() {
            "half_sommerfeld"
        } else {
            "reynolds"
        }),
    };
    if case.mass_conserving() && matches!(case.feed, Some(Feed::CircumferentialGroove { .. })) {
        notes.warn("jfo_circumferential_groove", "circumferential groove: each land's mass-conserving film is fed along a line at h_max at the edges' pressure, as the Reynolds model is; the groove's supply pressure is not applied at the land's edge");
    }
    notes.decide("cavitation", cavitation);
}

/// Misalignment: applied when the request tilts the journal and the effect is not off.
pub(super) fn decide_misalignment(notes: &mut Notes, case: &Case) {
    notes.decide(
        "misalignment",
        Misalignment::decision(case.misalignment, case.effects.misalignment),
    );
}
