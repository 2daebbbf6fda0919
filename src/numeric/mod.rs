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

/// `1 / k!` for `k = 0..14`: the Taylor coefficients of `exp` that the
/// fast exponentials ([`gauss`]'s estimate, the normal law's SIMD lanes)
/// sum by Horner's rule.
pub(crate) const INV_FACTORIAL: [f64; 14] = [
    1.0,
    1.0,
    0.5,
    1.0 / 6.0,
    1.0 / 24.0,
    1.0 / 120.0,
    1.0 / 720.0,
    1.0 / 5040.0,
    1.0 / 40320.0,
    1.0 / 362_880.0,
    1.0 / 3_628_800.0,
    1.0 / 39_916_800.0,
    1.0 / 479_001_600.0,
    1.0 / 6_227_020_800.0,
];
