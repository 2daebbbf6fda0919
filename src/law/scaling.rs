//! How a law's dimensionless form maps to other summit radii.
//!
//! With `rho = R/R_ref`, a law whose dimensionless curve does not depend on
//! `R` obeys `delta -> delta rho^alpha`, `P -> P rho^beta`, `a -> a rho^gamma`:
//! Maugis units (`Dbar = delta/(pi^2 w^2 R/K^2)^(1/3)`, `Pbar = P/(pi w R)`,
//! `A = a/(pi w R^2/K)^(1/3)`, Maugis 1992) give `(1/3, 1, 2/3)` for Hertz,
//! DMT and JKR; Bradley's rigid sphere `F = 2 pi w R f(delta/z0)` gives
//! `(0, 1, 0)`. Maugis–Dugdale does not scale (`lambda ~ R^(1/3)`).

/// Exponents of `rho = R/R_ref` by which a law's interference, load and
/// contact radius scale (see the module notes).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RadiusScaling {
    /// `alpha`: interferences scale as `rho^alpha`.
    pub interference: f64,
    /// `beta`: loads scale as `rho^beta`.
    pub load: f64,
    /// `gamma`: contact radii scale as `rho^gamma`.
    pub contact_radius: f64,
}

impl RadiusScaling {
    /// Maugis units: `(1/3, 1, 2/3)` (JKR, DMT, Hertz at fixed `E*`, `w`).
    pub const MAUGIS: RadiusScaling = RadiusScaling {
        interference: 1.0 / 3.0,
        load: 1.0,
        contact_radius: 2.0 / 3.0,
    };
    /// Rigid sphere with a Derjaguin surface force: `(0, 1, 0)` (Bradley).
    pub const RIGID: RadiusScaling = RadiusScaling {
        interference: 0.0,
        load: 1.0,
        contact_radius: 0.0,
    };

    /// Elastic-plastic sphere on a flat without adhesion: `(1, 2, 1)` at
    /// fixed `E*`, `Y`, `H` (the fits are in `delta/omega_c` with
    /// `omega_c ~ R` and `P_c ~ R^2`; see `law::plastic`).
    pub const PLASTIC: RadiusScaling = RadiusScaling {
        interference: 1.0,
        load: 2.0,
        contact_radius: 1.0,
    };

    /// Factors `[rho^-alpha, rho^beta, rho^gamma]` for radius ratio `rho`.
    pub fn factors(&self, rho: f64) -> [f64; 3] {
        if rho == 1.0 {
            return [1.0; 3];
        }
        [
            rho.powf(-self.interference),
            rho.powf(self.load),
            rho.powf(self.contact_radius),
        ]
    }
}
