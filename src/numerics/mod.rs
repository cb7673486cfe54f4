//! The basement: numerical kernels every room shares. No physics and no HTTP here.

pub mod elliptic;
pub mod fft;
pub mod half_space;
pub mod multigrid;
pub mod optimise;
pub mod quadrature;
pub mod reynolds;
pub mod richardson;
pub mod roots;
