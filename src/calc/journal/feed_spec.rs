//! The oil feed on the wire: the request's `feed` object (kind, position, supply pressure,
//! hole or groove size), checked against the bearing and parsed into the model's
//! [`Feed`](super::feed::Feed).

use serde::Deserialize;
use utoipa::ToSchema;

use super::feed::{Feed, Position};
use crate::calc::quantity::Positive;
use crate::calc::FieldError;

/// Where the oil enters.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum FeedKind {
    /// A single feed hole (`hole_diameter_m`).
    Hole,
    /// A single axial groove (`groove_length_m`, `groove_width_m`).
    AxialGroove,
    /// Two axial grooves at ±90° to the load line (`groove_length_m`, `groove_width_m`).
    TwoAxialGrooves,
    /// A central circumferential groove (`groove_width_m`): each side is a bearing of length
    /// (L − w_g)/2 carrying half the load (Khonsari & Booser §8.13, Eq. 8.61, 8.62).
    CircumferentialGroove,
}

/// Where a single hole or groove sits.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Deserialize, ToSchema)]
#[serde(rename_all = "snake_case")]
pub enum FeedPosition {
    /// Opposite the load (the usual place; Table 8.6's leakage applies unchanged).
    #[default]
    OppositeLoad,
    /// At the maximum film thickness.
    AtMaxFilm,
}

/// The oil feed.
#[derive(Debug, Clone, Copy, Deserialize, ToSchema)]
#[serde(deny_unknown_fields)]
pub struct FeedSpec {
    pub kind: FeedKind,
    /// For a single hole or groove (default `opposite_load`).
    #[serde(default)]
    pub position: FeedPosition,
    /// Supply pressure above ambient P_s, Pa (> 0, at most 1e8).
    #[schema(value_type = f64, exclusive_minimum = 0.0, maximum = 1e8, example = 276000.0)]
    pub supply_pressure_pa: Positive,
    /// Feed-hole diameter D_H, m (hole; D_H/L from 0.05 to 0.5).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 0.01)]
    pub hole_diameter_m: Option<Positive>,
    /// Axial groove length L_g, m (grooves; L_g/L from 0.3 to 0.95).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 0.067)]
    pub groove_length_m: Option<Positive>,
    /// Groove width w_g, m (grooves; typically ≥ D/10).
    #[schema(value_type = Option<f64>, exclusive_minimum = 0.0, maximum = 10.0, example = 0.00476)]
    pub groove_width_m: Option<Positive>,
}

impl From<FeedPosition> for Position {
    fn from(position: FeedPosition) -> Position {
        match position {
            FeedPosition::OppositeLoad => Position::OppositeLoad,
            FeedPosition::AtMaxFilm => Position::AtMaxFilm,
        }
    }
}

impl FeedSpec {
    /// Check the feed against the bearing's length L and diameter D.
    pub fn parse(self, length_m: f64, diameter_m: f64) -> Result<Feed, Vec<FieldError>> {
        let p_s = self.supply_pressure_pa.get();
        if p_s > 1e8 {
            return Err(vec![FieldError::new(
                "/feed/supply_pressure_pa",
                "must be at most 1e8 Pa",
            )]);
        }
        let grooves = || -> Result<(f64, f64), Vec<FieldError>> {
            let (Some(lg), Some(wg)) = (self.groove_length_m, self.groove_width_m) else {
                return Err(vec![FieldError::new(
                    "/feed/groove_length_m",
                    "grooves need groove_length_m and groove_width_m",
                )]);
            };
            let ratio = lg.get() / length_m;
            if !(0.3..=0.95).contains(&ratio) {
                return Err(vec![FieldError::new(
                    "/feed/groove_length_m",
                    format!("L_g/L must be within [0.3, 0.95] (Martin's data), got {ratio:.3}"),
                )]);
            }
            let w = wg.get() / diameter_m;
            if !(0.01..=0.5).contains(&w) {
                return Err(vec![FieldError::new(
                    "/feed/groove_width_m",
                    format!("w_g/D must be within [0.01, 0.5], got {w:.3}"),
                )]);
            }
            Ok((ratio, w))
        };
        match self.kind {
            FeedKind::Hole => {
                let Some(dh) = self.hole_diameter_m else {
                    return Err(vec![FieldError::new(
                        "/feed/hole_diameter_m",
                        "a hole feed needs hole_diameter_m",
                    )]);
                };
                let ratio = dh.get() / length_m;
                if !(0.05..=0.5).contains(&ratio) {
                    return Err(vec![FieldError::new(
                        "/feed/hole_diameter_m",
                        format!("D_H/L must be within [0.05, 0.5], got {ratio:.3}"),
                    )]);
                }
                Ok(Feed::Hole {
                    position: self.position.into(),
                    supply_pressure_pa: p_s,
                    hole_over_length: ratio,
                })
            }
            FeedKind::AxialGroove => {
                let (length_ratio, width_over_diameter) = grooves()?;
                Ok(Feed::AxialGroove {
                    position: self.position.into(),
                    supply_pressure_pa: p_s,
                    length_ratio,
                    width_over_diameter,
                })
            }
            FeedKind::CircumferentialGroove => {
                let Some(wg) = self.groove_width_m else {
                    return Err(vec![FieldError::new(
                        "/feed/groove_width_m",
                        "a circumferential groove needs groove_width_m",
                    )]);
                };
                if wg.get() >= 0.5 * length_m {
                    return Err(vec![FieldError::new(
                        "/feed/groove_width_m",
                        "must be less than half the bearing length (each side keeps a land)",
                    )]);
                }
                Ok(Feed::CircumferentialGroove {
                    supply_pressure_pa: p_s,
                    width_m: wg.get(),
                })
            }
            FeedKind::TwoAxialGrooves => {
                let (length_ratio, width_over_diameter) = grooves()?;
                Ok(Feed::TwoAxialGrooves {
                    supply_pressure_pa: p_s,
                    length_ratio,
                    width_over_diameter,
                })
            }
        }
    }
}
