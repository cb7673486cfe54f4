//! A thrust bearing of sector pads as the texts design it (Khonsari & Booser §7.2–7.4): each
//! sector is the rectangular pad B × L at its mean radius — B the arc at R_m, L = R2 − R1, U the
//! runner speed at R_m — carrying its share of the load (sector pads perform within about 10 %
//! of that pad; Stachowiak & Batchelor §4.3). Then the design checks of the texts' procedure.

use std::f64::consts::PI;

use super::operating::Pad;

/// k_g: the share of the annulus under pads, the rest feed grooves (Khonsari & Booser Eq. 7.1:
/// 0.80–0.85).
pub const PAD_AREA_SHARE: f64 = 0.85;

/// The bearing's sectors.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sectors {
    pub inner_radius_m: f64,
    pub outer_radius_m: f64,
    pub count: u32,
    /// Each pad's angle, rad.
    pub angle_rad: f64,
}

impl Sectors {
    /// R_m = (R1 + R2)/2.
    pub fn mean_radius_m(&self) -> f64 {
        0.5 * (self.inner_radius_m + self.outer_radius_m)
    }

    /// The equivalent rectangular pad: B = R_m β along the runner, L = R2 − R1 across it.
    pub fn pad(&self) -> Pad {
        Pad {
            breadth_m: self.mean_radius_m() * self.angle_rad,
            length_m: self.outer_radius_m - self.inner_radius_m,
        }
    }

    /// The runner's speed at the mean radius, m/s, at `speed_rpm`.
    pub fn sliding_speed_m_s(&self, speed_rpm: f64) -> f64 {
        speed_rpm * 2.0 * PI / 60.0 * self.mean_radius_m()
    }

    /// The pads' total area N β (R2² − R1²)/2, m².
    pub fn area_m2(&self) -> f64 {
        self.count as f64
            * 0.5
            * self.angle_rad
            * (self.outer_radius_m.powi(2) - self.inner_radius_m.powi(2))
    }

    /// The default pad angle: the annulus shared by `count` pads with k_g of it under pads.
    pub fn default_angle_rad(count: u32) -> f64 {
        PAD_AREA_SHARE * 2.0 * PI / count as f64
    }
}

/// The kind of pad, for the unit-load ranges of Khonsari & Booser Table 7.1.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PadType {
    Taper,
    Step,
    TiltPad,
    /// Flat land: parallel faces (20–35 psi ungrooved, to about 100 with radial grooves, §7.7).
    Flat,
}

impl PadType {
    /// Table 7.1's unit-load range, Pa (psi: taper 150–400, step 100–300, tilt pad 250–700,
    /// flat 20–100).
    pub fn unit_load_range_pa(self) -> (f64, f64) {
        const PSI: f64 = 6894.757;
        let (lo, hi) = match self {
            PadType::Taper => (150.0, 400.0),
            PadType::Step => (100.0, 300.0),
            PadType::TiltPad => (250.0, 700.0),
            PadType::Flat => (20.0, 100.0),
        };
        (lo * PSI, hi * PSI)
    }

    pub fn name(self) -> &'static str {
        match self {
            PadType::Taper => "taper",
            PadType::Step => "step",
            PadType::TiltPad => "tilt pad",
            PadType::Flat => "flat land",
        }
    }
}

/// The allowable minimum film from the surfaces' roughness: h_min ≥ 10 (Ra₁² + Ra₂²)^½
/// (Khonsari & Booser §8.12 with Table 8.7: film parameter Λ > 10 keeps the film hydrodynamic).
pub fn allowable_film_m(roughness_ra_m: [f64; 2]) -> f64 {
    10.0 * roughness_ra_m[0].hypot(roughness_ra_m[1])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn example_7_1_sizing() {
        // Khonsari & Booser Ex 7.1: R1 = 2.875 in, R2 = 6.3 in, 7 pads of B = 3.5 in at
        // R_m = 4.59 in, 3600 rpm: L = 3.425 in, U = 1730 in/s, unit load about 300 psi.
        let inch = 0.0254;
        let (r1, r2) = (2.875 * inch, 6.3 * inch);
        let rm = 0.5 * (r1 + r2);
        let s = Sectors {
            inner_radius_m: r1,
            outer_radius_m: r2,
            count: 7,
            angle_rad: 3.5 * inch / rm,
        };
        let pad = s.pad();
        assert!((pad.breadth_m / inch - 3.5).abs() < 1e-12);
        assert!((pad.length_m / inch - 3.425).abs() < 1e-12);
        assert!((s.sliding_speed_m_s(3600.0) / inch / 1730.0 - 1.0).abs() < 0.005);
        let unit = 25_000.0 * 4.448_222 / (7.0 * pad.area_m2());
        assert!((unit / 6894.757 / 300.0 - 1.0).abs() < 0.01, "{unit}");
        // The sectors' true area is the rectangles' (B at R_m times L).
        assert!((s.area_m2() / (7.0 * pad.area_m2()) - 1.0).abs() < 1e-12);
    }

    #[test]
    fn allowable_film_is_ten_composite_roughnesses() {
        // 0.8 µm on each surface (a 32 µin finish): 11.3 µm.
        assert!((allowable_film_m([0.8e-6, 0.8e-6]) - 11.3137e-6).abs() < 1e-9);
    }
}
