//! The film shape of a fixed pad along the sliding direction, h̄(x̄) = h/h2 on x̄ = x/B ∈ [0, 1]
//! from the leading edge (Khonsari & Booser Table 7.2 naming: h1 at the leading edge, h2 at the
//! trailing edge, B along the sliding direction). Every shape here is uniform across the pad.
//! A crowned pad's film need not be thinnest at the trailing edge: h2 there is still the scale.

/// A pad's film shape, with its film ratio a = h1/h2 > 1.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Profile {
    /// Plane inclined over the whole breadth: h̄ = a − (a − 1) x̄ (Khonsari & Booser Table 6.2;
    /// the pads of Table 7.2).
    PlaneInclined { ratio: f64 },
    /// Rayleigh step: h̄ = a up to the step at x̄_s, 1 after it (Khonsari & Booser §6.7).
    Step { ratio: f64, step_position: f64 },
    /// Tapered land: plane taper from a to 1 over the leading 1 − f of the breadth, then a flat
    /// land of fraction f at the trailing edge (Stachowiak & Batchelor §4.3; f = 0 is
    /// [`Profile::PlaneInclined`]).
    TaperedLand { ratio: f64, land_fraction: f64 },
    /// Parabolic: h̄ = 1 + (a − 1)(1 − x̄)², tangent to the runner at the trailing edge (the
    /// parabolic slider of Hamrock's *Fundamentals of Fluid Film Lubrication* §8.5).
    Parabolic { ratio: f64 },
    /// A tilted plane pad with a parabolic crown over its breadth (Khonsari & Booser §7.5):
    /// h̄ = a − (a − 1) x̄ − 4 c x̄ (1 − x̄), the pad's middle standing the crown height δ
    /// proud of the line through its edges, c = δ/h2. The film converges then diverges where
    /// the crown outweighs the tilt.
    Crowned { ratio: f64, crown: f64 },
    /// A flat land: parallel faces (h̄ = 1), which carry load in the isoviscous model only by
    /// the thermal wedge the texts leave unmodelled. Its performance is the texts' empirical
    /// rule (Khonsari & Booser §7.8, Eq. 7.14, Ex 7.4): K_h = `multiplier` × K_h of the plane
    /// pad of film ratio [`FLAT_LAND_EQUIVALENT_RATIO`] on the same L/B (0.4 for small, slow,
    /// lightly loaded lands to 0.8 for long, fast, hot ones), K_f = 1, K_q = 0.5.
    FlatLand { multiplier: f64 },
}

/// The film ratio of the plane pad whose K_h the flat-land rule scales (Eq. 7.14).
pub const FLAT_LAND_EQUIVALENT_RATIO: f64 = 1.2;

impl Profile {
    /// h1/h2.
    pub fn ratio(self) -> f64 {
        match self {
            Profile::PlaneInclined { ratio }
            | Profile::Step { ratio, .. }
            | Profile::TaperedLand { ratio, .. }
            | Profile::Parabolic { ratio }
            | Profile::Crowned { ratio, .. } => ratio,
            Profile::FlatLand { .. } => 1.0,
        }
    }

    /// The same shape with film ratio `ratio`.
    #[must_use]
    pub fn with_ratio(self, ratio: f64) -> Profile {
        match self {
            Profile::PlaneInclined { .. } => Profile::PlaneInclined { ratio },
            Profile::Step { step_position, .. } => Profile::Step {
                ratio,
                step_position,
            },
            Profile::TaperedLand { land_fraction, .. } => Profile::TaperedLand {
                ratio,
                land_fraction,
            },
            Profile::Parabolic { .. } => Profile::Parabolic { ratio },
            Profile::Crowned { crown, .. } => Profile::Crowned { ratio, crown },
            // Parallel: the empirical rule fixes the equivalent wedge.
            Profile::FlatLand { .. } => self,
        }
    }

    /// The name the wire uses for the shape.
    pub fn kind(self) -> &'static str {
        match self {
            Profile::PlaneInclined { .. } => "plane_inclined",
            Profile::Step { .. } => "step",
            Profile::TaperedLand { .. } => "tapered_land",
            Profile::Parabolic { .. } => "parabolic",
            Profile::Crowned { .. } => "crowned",
            Profile::FlatLand { .. } => "flat_land",
        }
    }

    /// h̄ at x̄ (at a step, the thickness just after it).
    pub fn thickness(self, x: f64) -> f64 {
        match self {
            Profile::PlaneInclined { ratio } => ratio - (ratio - 1.0) * x,
            Profile::Step {
                ratio,
                step_position,
            } => {
                if x < step_position {
                    ratio
                } else {
                    1.0
                }
            }
            Profile::TaperedLand {
                ratio,
                land_fraction,
            } => {
                let taper = 1.0 - land_fraction;
                if x < taper {
                    ratio - (ratio - 1.0) * x / taper
                } else {
                    1.0
                }
            }
            Profile::Parabolic { ratio } => 1.0 + (ratio - 1.0) * (1.0 - x).powi(2),
            Profile::Crowned { ratio, crown } => {
                ratio - (ratio - 1.0) * x - 4.0 * crown * x * (1.0 - x)
            }
            Profile::FlatLand { .. } => 1.0,
        }
    }

    /// dh̄/dx̄ where the shape is smooth (0 on flats and at a step, which
    /// [`Profile::breaks`] separates).
    pub fn slope(self, x: f64) -> f64 {
        match self {
            Profile::PlaneInclined { ratio } => 1.0 - ratio,
            Profile::Step { .. } => 0.0,
            Profile::TaperedLand {
                ratio,
                land_fraction,
            } => {
                let taper = 1.0 - land_fraction;
                if x < taper {
                    (1.0 - ratio) / taper
                } else {
                    0.0
                }
            }
            Profile::Parabolic { ratio } => -2.0 * (ratio - 1.0) * (1.0 - x),
            Profile::Crowned { ratio, crown } => 1.0 - ratio - 4.0 * crown * (1.0 - 2.0 * x),
            Profile::FlatLand { .. } => 0.0,
        }
    }

    /// Where the shape is not smooth inside the pad (a step, the start of a land): grids put a
    /// node there and integrals split there, so both stay exact across it.
    pub fn breaks(self) -> Option<f64> {
        match self {
            Profile::Step { step_position, .. } => Some(step_position),
            Profile::TaperedLand { land_fraction, .. } if land_fraction > 0.0 => {
                Some(1.0 - land_fraction)
            }
            _ => None,
        }
    }

    /// The thinnest film h̄_min over the pad: h2 (= 1) but for a crown that outweighs the tilt,
    /// whose parabola has its vertex inside.
    pub fn minimum(self) -> f64 {
        match self {
            Profile::Crowned { ratio, crown } if crown > 0.0 => {
                let vertex = ((4.0 * crown + ratio - 1.0) / (8.0 * crown)).clamp(0.0, 1.0);
                self.thickness(vertex).min(1.0)
            }
            _ => 1.0,
        }
    }

    /// The smooth pieces [x̄0, x̄1] of the pad, leading edge first.
    pub fn pieces(self) -> Vec<(f64, f64)> {
        match self.breaks() {
            Some(b) => vec![(0.0, b), (b, 1.0)],
            None => vec![(0.0, 1.0)],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_shape_runs_from_h1_to_h2() {
        let shapes = [
            Profile::PlaneInclined { ratio: 2.5 },
            Profile::Step {
                ratio: 2.5,
                step_position: 0.6,
            },
            Profile::TaperedLand {
                ratio: 2.5,
                land_fraction: 0.2,
            },
            Profile::Parabolic { ratio: 2.5 },
        ];
        for p in shapes {
            assert_eq!(p.thickness(0.0), 2.5, "{p:?}");
            assert!((p.thickness(1.0) - 1.0).abs() < 1e-15, "{p:?}");
        }
    }

    #[test]
    fn a_crowned_pad_without_crown_is_the_plane_pad_and_its_minimum_is_the_vertex() {
        let plane = Profile::PlaneInclined { ratio: 1.5 };
        let flat = Profile::Crowned {
            ratio: 1.5,
            crown: 0.0,
        };
        let crowned = Profile::Crowned {
            ratio: 1.5,
            crown: 0.5,
        };
        for i in 0..=10 {
            let x = i as f64 / 10.0;
            assert_eq!(plane.thickness(x), flat.thickness(x));
            assert_eq!(plane.slope(x), flat.slope(x));
            // The slope is the derivative of the thickness.
            let d = (crowned.thickness(x + 1e-6) - crowned.thickness(x - 1e-6)) / 2e-6;
            assert!((d - crowned.slope(x)).abs() < 1e-8);
        }
        assert_eq!(crowned.thickness(0.0), 1.5);
        assert!((crowned.thickness(1.0) - 1.0).abs() < 1e-15);
        // h̄ = 2x² − 2.5x + 1.5: vertex at 0.625, h̄ = 0.71875.
        assert!((crowned.minimum() - 0.71875).abs() < 1e-15);
        assert_eq!(flat.minimum(), 1.0);
    }

    #[test]
    fn a_tapered_land_without_land_is_the_plane_pad() {
        let plane = Profile::PlaneInclined { ratio: 3.0 };
        let land = Profile::TaperedLand {
            ratio: 3.0,
            land_fraction: 0.0,
        };
        for i in 0..10 {
            let x = i as f64 / 10.0;
            assert!((plane.thickness(x) - land.thickness(x)).abs() < 1e-15);
            assert_eq!(plane.slope(x), land.slope(x));
        }
        assert_eq!(land.breaks(), None);
    }
}
