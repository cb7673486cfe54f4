//! The load on a dynamically loaded journal as a function of time: the force on the journal in
//! the bearing frame (x horizontal, y up, N) at the journal's rotation angle τ = ω_j t (rad).
//!
//! - constant: magnitude and direction;
//! - rotating: magnitude turning at `speed_ratio` × ω_j from its start direction (unbalance:
//!   ratio 1);
//! - sinusoidal: F_s + F_o sin(α τ) along a fixed direction (Harnoy Eq. 18-35);
//! - table: one period of (angle, F_x, F_y), the periodic cubic through the points;
//! - engine: a single-cylinder slider-crank on a main bearing, the cylinder above the crank
//!   (+y), crank angle = τ from top dead centre, turning counter-clockwise. The piston sits at
//!   y_p = r cos θ + s, s = √(l² − r² sin² θ); gas and reciprocating inertia load it:
//!   C = (p A + m ÿ_p)/d_y is the rod's compression, d = (x_p − x_c, y_p − y_c)/l its direction
//!   from crank pin to piston, and the force on the journal is −C d (rotating masses and
//!   counterweights left out: a stated simplification).

use std::f64::consts::PI;

use crate::numerics::interpolate::periodic_cubic;

/// A load law with its period.
#[derive(Debug, Clone, PartialEq)]
pub enum LoadLaw {
    Constant {
        force: [f64; 2],
    },
    Rotating {
        magnitude: f64,
        speed_ratio: f64,
        start: f64,
    },
    Sinusoidal {
        steady: f64,
        amplitude: f64,
        frequency_ratio: f64,
        direction: f64,
    },
    Table {
        /// Angles of the journal's rotation, rad, ascending within one period.
        angles: Vec<f64>,
        fx: Vec<f64>,
        fy: Vec<f64>,
        period: f64,
    },
    Engine(Engine),
}

/// The slider-crank's data (SI, angles in rad).
#[derive(Debug, Clone, PartialEq)]
pub struct Engine {
    pub bore: f64,
    pub crank_radius: f64,
    pub rod_length: f64,
    pub reciprocating_mass: f64,
    /// ω_j, rad/s (the inertia force scales with its square).
    pub angular_speed: f64,
    /// Cylinder pressure above ambient (gauge, Pa) over one cycle: crank angles, pressures.
    pub crank_angles: Vec<f64>,
    pub pressures: Vec<f64>,
    /// The cycle's length in crank angle: 4π for a four-stroke engine, 2π for a two-stroke.
    pub cycle: f64,
}

impl Engine {
    fn force(&self, theta: f64) -> [f64; 2] {
        let (r, l) = (self.crank_radius, self.rod_length);
        let (sn, cs) = theta.sin_cos();
        let s = (l * l - r * r * sn * sn).sqrt();
        // ÿ_p = ω² d²y_p/dθ².
        let y2 =
            -r * cs - r * r * (2.0 * theta).cos() / s - r.powi(4) * sn * sn * cs * cs / s.powi(3);
        let accel = self.angular_speed.powi(2) * y2;
        let p = periodic_cubic(&self.crank_angles, &self.pressures, self.cycle, theta);
        let area = 0.25 * PI * self.bore * self.bore;
        // Rod direction from the crank pin (−r sin θ, r cos θ) to the piston (0, y_p).
        let d = [r * sn / l, s / l];
        let compression = (p * area + self.reciprocating_mass * accel) / d[1];
        [-compression * d[0], -compression * d[1]]
    }
}

impl LoadLaw {
    /// The force on the journal at rotation angle τ (rad), N.
    #[must_use]
    pub fn force(&self, tau: f64) -> [f64; 2] {
        match self {
            LoadLaw::Constant { force } => *force,
            LoadLaw::Rotating {
                magnitude,
                speed_ratio,
                start,
            } => {
                let a = start + speed_ratio * tau;
                [magnitude * a.cos(), magnitude * a.sin()]
            }
            LoadLaw::Sinusoidal {
                steady,
                amplitude,
                frequency_ratio,
                direction,
            } => {
                let f = steady + amplitude * (frequency_ratio * tau).sin();
                [f * direction.cos(), f * direction.sin()]
            }
            LoadLaw::Table {
                angles,
                fx,
                fy,
                period,
            } => [
                periodic_cubic(angles, fx, *period, tau),
                periodic_cubic(angles, fy, *period, tau),
            ],
            LoadLaw::Engine(engine) => engine.force(tau),
        }
    }

    /// The load's period in τ (rad); a constant load's "period" is one revolution, the interval
    /// at which a settling orbit is compared with itself.
    #[must_use]
    pub fn period(&self) -> f64 {
        match self {
            LoadLaw::Constant { .. } => 2.0 * PI,
            LoadLaw::Rotating { speed_ratio, .. } if *speed_ratio != 0.0 => {
                2.0 * PI / speed_ratio.abs()
            }
            LoadLaw::Rotating { .. } => 2.0 * PI,
            LoadLaw::Sinusoidal {
                frequency_ratio, ..
            } if *frequency_ratio != 0.0 => 2.0 * PI / frequency_ratio.abs(),
            LoadLaw::Sinusoidal { .. } => 2.0 * PI,
            LoadLaw::Table { period, .. } => *period,
            LoadLaw::Engine(e) => e.cycle,
        }
    }

    /// The largest load magnitude over one period (sampled at 720 points per period; a
    /// table's or engine's peak between samples is within the cubic's smoothness of it).
    #[must_use]
    pub fn peak(&self) -> f64 {
        let period = self.period();
        (0..720)
            .map(|i| {
                let f = self.force(period * f64::from(i) / 720.0);
                f[0].hypot(f[1])
            })
            .fold(0.0, f64::max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn laws_give_their_forces_and_periods() {
        let rot = LoadLaw::Rotating {
            magnitude: 10.0,
            speed_ratio: 0.5,
            start: -0.5 * PI,
        };
        let f = rot.force(PI);
        // Half a revolution turns the load a quarter: from −90° to 0°.
        assert!((f[0] - 10.0).abs() < 1e-12 && f[1].abs() < 1e-12, "{f:?}");
        assert!((rot.period() - 4.0 * PI).abs() < 1e-15);
        let sine = LoadLaw::Sinusoidal {
            steady: 100.0,
            amplitude: 100.0,
            frequency_ratio: 2.0,
            direction: -0.5 * PI,
        };
        assert!((sine.peak() - 200.0).abs() < 1e-9 && (sine.period() - PI).abs() < 1e-15);
    }

    #[test]
    fn the_engine_at_top_dead_centre_pushes_the_journal_down_with_gas_and_inertia() {
        // At TDC (θ = 0): d = (0, 1), ÿ_p = −ω² r (1 + r/l); force on journal
        // = −(p A − m ω² r (1 + r/l)) downward.
        let engine = Engine {
            bore: 0.1,
            crank_radius: 0.05,
            rod_length: 0.2,
            reciprocating_mass: 1.0,
            angular_speed: 300.0,
            crank_angles: vec![0.0, PI, 2.0 * PI, 3.0 * PI],
            pressures: vec![5e6, 5e6, 5e6, 5e6],
            cycle: 4.0 * PI,
        };
        let f = LoadLaw::Engine(engine).force(0.0);
        let area = 0.25 * PI * 0.01;
        let want = 5e6 * area - 300.0f64.powi(2) * 0.05 * 1.25;
        assert!(
            f[0].abs() < 1e-9 && (f[1] + want).abs() < 1e-6 * want,
            "{f:?}"
        );
    }
}
