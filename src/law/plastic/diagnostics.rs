//! Plasticity diagnostics of a rough surface at one separation: the GW
//! plasticity index and the fraction of contacts in each regime.
//!
//! With summit heights `z = sigma s` (standardised tail `Q(s) = P(S > s)`)
//! and the flat at separation `d`, a summit is in contact when
//! `z - d > 0`; with regime limits `omega_e` (elastic up to) and `omega_p`
//! (fully plastic beyond), the expected fractions of the contacts are
//!
//! ```text
//! elastic         = [Q(h) - Q(h + omega_e/sigma)] / Q(h)
//! elastic-plastic = [Q(h + omega_e/sigma) - Q(h + omega_p/sigma)] / Q(h)
//! fully plastic   = Q(h + omega_p/sigma) / Q(h),           h = d/sigma
//! ```

use crate::heights::HeightDistribution;
use crate::material::plastic::RegimeLimits;

/// Fractions of the contacts in each regime (they sum to 1 when there is
/// any contact; all 0 otherwise).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RegimeFractions {
    /// Expected number of contacts per summit, `Q(h)`.
    pub contacts_per_summit: f64,
    /// Fraction elastic.
    pub elastic: f64,
    /// Fraction elastic-plastic.
    pub elastic_plastic: f64,
    /// Fraction fully plastic.
    pub fully_plastic: f64,
}

/// Regime fractions at separation `d` (m) over heights of scale `sigma`
/// (m) with distribution `dist` and the law's regime `limits` (m).
pub fn contact_fractions(
    limits: &RegimeLimits,
    sigma: f64,
    separation: f64,
    dist: &dyn HeightDistribution,
) -> RegimeFractions {
    let h = separation / sigma;
    let q0 = dist.tail(h);
    if !(q0 > 0.0) {
        return RegimeFractions::default();
    }
    let q = |omega: f64| {
        if omega.is_finite() {
            dist.tail(h + omega / sigma)
        } else {
            0.0
        }
    };
    let (qe, qp) = (q(limits.elastic), q(limits.fully_plastic));
    RegimeFractions {
        contacts_per_summit: q0,
        elastic: (q0 - qe) / q0,
        elastic_plastic: (qe - qp).max(0.0) / q0,
        fully_plastic: qp / q0,
    }
}

/// An elastic law chosen for a surface whose plasticity index exceeds 1
/// (Greenwood & Williamson 1966: `psi = (E*/H) sqrt(sigma/R)`; above 1 most
/// contacts yield): the warning `summary.json` carries, its sentence by
/// `Display`.
#[derive(Debug, Clone, PartialEq)]
pub struct ElasticLawYields {
    /// The elastic law's name.
    pub law: String,
    /// The plasticity index `psi` (> 1).
    pub psi: f64,
}

impl std::fmt::Display for ElasticLawYields {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let (law, psi) = (&self.law, self.psi);
        write!(
            f,
            "plasticity index psi = {psi:.3} > 1: most contacts yield, but the law {law} is \
             elastic (it over-predicts the load at a given area); consider kogut-etsion or \
             jackson-green"
        )
    }
}

/// The warning when the elastic law `law` is chosen for a surface whose
/// plasticity index `psi` exceeds 1; `None` otherwise.
pub fn elastic_law_warning(law: &str, psi: f64) -> Option<ElasticLawYields> {
    (psi > 1.0).then(|| ElasticLawYields {
        law: law.to_string(),
        psi,
    })
}
