//! A hydrostatic pad's operating point: film, load, supply and recess pressures, flow.

/// The operating point: SI throughout.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Point {
    pub film: f64,
    pub load: f64,
    pub supply: f64,
    pub recess: f64,
    pub flow: f64,
}

impl Point {
    /// m = p_r/p_s.
    pub fn ratio(&self) -> f64 {
        self.recess / self.supply
    }
}
