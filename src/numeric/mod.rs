//! Small numerical building blocks shared by the laws, the integrators and
//! the solvers: bracketed root finding and minimisation, adaptive
//! quadrature, monotone interpolation, Chebyshev series, SIMD lane helpers,
//! and the one seed mixer of the crate's random streams.

pub mod chebyshev;
pub mod gauss;
pub mod lanes;
pub mod mix;
pub mod pchip;
pub mod quadrature;
pub mod roots;
pub mod simd;
