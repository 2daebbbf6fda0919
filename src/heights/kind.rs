//! The distributions by kind: names, parameters, capabilities, building.

use super::{Empirical, Exponential, Gaussian, HeightDistribution, TruncatedGaussian, Weibull};
use crate::error::{Error, Result};
use std::sync::Arc;

/// The height distributions a study can name.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum DistributionKind {
    /// [`Gaussian`]: standard normal heights.
    Gaussian,
    /// [`Exponential`]: GW's `phi(s) = e^-s`, `s >= 0`.
    Exponential,
    /// [`Weibull`] of shape `k` (parameter `weibull_shape`).
    Weibull,
    /// [`TruncatedGaussian`] at `k` standard deviations (parameter `truncation`).
    TruncatedGaussian,
    /// [`Empirical`]: measured heights (parameter `heights`, m).
    Empirical,
}

/// Parameters of the distributions; each is used by one kind only
/// ([`DistributionKind::parameter`]).
#[derive(Debug, Clone, Default, PartialEq)]
#[non_exhaustive]
pub struct DistributionParams {
    /// Weibull shape `k` in `[0.1, 100]` (`weibull`).
    pub weibull_shape: Option<f64>,
    /// Truncation `k > 0` in standard deviations (`truncated-gaussian`).
    pub truncation: Option<f64>,
    /// Measured summit heights (m), at least 2 (`empirical`).
    pub heights: Option<Vec<f64>>,
}

crate::named_enum!(DistributionKind, "distribution");

impl DistributionKind {
    /// Every kind, in the order tables list them.
    pub const ALL: [DistributionKind; 5] = [
        DistributionKind::Gaussian,
        DistributionKind::Exponential,
        DistributionKind::Weibull,
        DistributionKind::TruncatedGaussian,
        DistributionKind::Empirical,
    ];

    /// Lower-case name as used in scenes and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            DistributionKind::Gaussian => "gaussian",
            DistributionKind::Exponential => "exponential",
            DistributionKind::Weibull => "weibull",
            DistributionKind::TruncatedGaussian => "truncated-gaussian",
            DistributionKind::Empirical => "empirical",
        }
    }

    /// The one parameter this kind needs, by its name in
    /// [`DistributionParams`].
    pub fn parameter(self) -> Option<&'static str> {
        match self {
            DistributionKind::Gaussian | DistributionKind::Exponential => None,
            DistributionKind::Weibull => Some("weibull_shape"),
            DistributionKind::TruncatedGaussian => Some("truncation"),
            DistributionKind::Empirical => Some("heights"),
        }
    }

    /// Whether `F_n` is exact without quadrature for this kind (as
    /// [`HeightDistribution::closed_form_moment`] of the built object):
    /// Gaussian for `n` in {0, 1/2, 1, 3/2, 2, 5/2}, exponential for every
    /// integer and half-integer `n`, measured heights for every `n >= 0`
    /// (exact sample averages); Weibull and truncated Gaussian never.
    pub fn closed_form_moment(self, n: f64) -> bool {
        match self {
            DistributionKind::Gaussian => crate::special::gaussian_fn::has_closed_form(n),
            DistributionKind::Exponential => n >= 0.0 && (2.0 * n).fract() == 0.0,
            DistributionKind::Empirical => n >= 0.0 && n.is_finite(),
            DistributionKind::Weibull | DistributionKind::TruncatedGaussian => false,
        }
    }

    /// Whether the kind is a finite sample that integrators sum exactly.
    pub fn is_sample(self) -> bool {
        self == DistributionKind::Empirical
    }

    /// Builds the distribution.
    ///
    /// # Errors
    /// [`Error::Invalid`] naming the parameter when it is missing, or when a
    /// parameter of another kind is given (it would be silently ignored);
    /// the constructor's error for a bad value (`heights[i]` for a bad
    /// measured height).
    pub fn build(self, params: &DistributionParams) -> Result<Arc<dyn HeightDistribution>> {
        let given = [
            ("weibull_shape", params.weibull_shape.is_some()),
            ("truncation", params.truncation.is_some()),
            ("heights", params.heights.is_some()),
        ];
        for (name, present) in given {
            if present && self.parameter() != Some(name) {
                return Err(Error::invalid(
                    name,
                    format!("does not apply to distribution {:?}", self.name()),
                ));
            }
        }
        let missing =
            |f: &str| Error::invalid(f, format!("required for distribution = {:?}", self.name()));
        Ok(match self {
            DistributionKind::Gaussian => Arc::new(Gaussian::new()),
            DistributionKind::Exponential => Arc::new(Exponential::new()),
            DistributionKind::Weibull => {
                let k = params
                    .weibull_shape
                    .ok_or_else(|| missing("weibull_shape"))?;
                Arc::new(Weibull::new(k).map_err(|e| e.renamed("weibull_shape"))?)
            }
            DistributionKind::TruncatedGaussian => {
                let k = params.truncation.ok_or_else(|| missing("truncation"))?;
                Arc::new(TruncatedGaussian::new(k).map_err(|e| e.renamed("truncation"))?)
            }
            DistributionKind::Empirical => {
                let h = params.heights.as_ref().ok_or_else(|| missing("heights"))?;
                Arc::new(Empirical::new(h)?)
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_kind_round_trips_and_builds_with_its_parameter() {
        for k in DistributionKind::ALL {
            let params = DistributionParams {
                weibull_shape: (k.parameter() == Some("weibull_shape")).then_some(1.5),
                truncation: (k.parameter() == Some("truncation")).then_some(3.0),
                heights: (k.parameter() == Some("heights")).then(|| vec![1e-9, 2e-9, 4e-9]),
            };
            let d = k.build(&params).unwrap();
            assert_eq!(d.name(), k.name());
            // The capability agrees with the object.
            for n in [0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 0.3] {
                assert_eq!(
                    d.closed_form_moment(n),
                    k.closed_form_moment(n),
                    "{k:?} n = {n}"
                );
            }
            if let Some(p) = k.parameter() {
                let e = k.build(&DistributionParams::default()).unwrap_err();
                assert_eq!(e.field(), Some(p));
            }
        }
    }

    #[test]
    fn parameters_of_other_kinds_are_refused() {
        let params = DistributionParams {
            weibull_shape: Some(2.0),
            ..Default::default()
        };
        let e = DistributionKind::Gaussian.build(&params).unwrap_err();
        assert_eq!(e.field(), Some("weibull_shape"));
        assert!(e.to_string().contains("does not apply"), "{e}");
    }
}
