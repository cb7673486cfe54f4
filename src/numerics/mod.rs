//! The basement: numerical kernels every room shares. No physics and no HTTP here.

pub mod roots;
pub mod reynolds;
