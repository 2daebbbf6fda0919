//! Small numerical building blocks shared by the laws, the integrators and
//! the solvers: bracketed root finding and minimisation.

pub mod pchip;
pub mod quadrature;
pub mod roots;
