//! The basement: numerical kernels every room shares. No physics and no HTTP here.

pub mod band_lu;
pub mod banded;
pub mod dense;
pub mod driver;
pub mod elliptic;
pub mod fft;
pub mod gmres;
pub mod half_space;
pub mod interpolate;
pub mod log_fmm;
pub mod multigrid;
pub mod newton;
pub mod ode;
pub mod optimise;
pub mod quadrature;
pub mod refine;
pub mod reynolds;
pub mod reynolds_gas;
pub mod richardson;
pub mod roots;
