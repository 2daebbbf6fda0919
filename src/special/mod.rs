//! Special functions whose accuracy the crate promises, each tested against
//! high-precision (mpmath) values in `tests/`.
//!
//! - [`normal`]: the standard normal density, tail `Q(h)`, `erfc`, the scaled
//!   Mills ratio `Q(h)/phi(h)` and the inverse tail, all with relative
//!   accuracy far into the tail;
//! - [`gaussian_fn`]: the Greenwood–Williamson integrals
//!   `F_n(h) = int_h^inf (s-h)^n phi(s) ds` of the standard normal for
//!   `n = 0, 1/2, 1, 3/2, 2, 5/2`;
//! - [`gamma`]: `Gamma(x)` and `ln Gamma(x)` for real `x`;
//! - [`elliptic`]: complete elliptic integrals `K(m)`, `E(m)`;
//! - [`struve`]: Struve functions `H0`, `H1` of real argument.

pub(crate) mod cbrt;
pub mod elliptic;
pub mod gamma;
pub mod gaussian_fn;
#[allow(missing_docs)]
mod gaussian_tables;
pub mod normal;
mod scaled;
pub mod struve;
#[allow(missing_docs)]
mod struve_tables;
