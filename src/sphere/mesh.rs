//! Non-uniform radial mesh that concentrates nodes at the contact edge.
//!
//! Node spacing `h(r) = h0 + g * dist(r, [lo, hi])`: uniform `h0` on a
//! plateau `[lo, hi]` around the edge `a` (covering the cohesive zone), then
//! growing linearly with the distance from it (geometric grading) towards the
//! centre and out to `r_max`. Nodes are equally spaced in
//! `Phi(r) = int_0^r dr/h(r)`, which is analytic.

/// Where and how fine the mesh is (lengths in the solver's radius unit).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshSpec {
    /// Centre of refinement (the contact edge; 0 when not in contact).
    pub edge: f64,
    /// Spacing on the plateau.
    pub h0: f64,
    /// Growth of the spacing per unit distance from the plateau.
    pub growth: f64,
    /// Plateau extent inside the edge.
    pub inner: f64,
    /// Plateau extent outside the edge.
    pub outer: f64,
    /// Outer radius (last node).
    pub r_max: f64,
}

impl MeshSpec {
    fn bounds(&self) -> (f64, f64) {
        let lo = (self.edge - self.inner).clamp(0.0, self.r_max);
        let hi = (self.edge + self.outer).clamp(lo, self.r_max);
        (lo, hi)
    }

    /// `Phi(r) = int_0^r dr / h(r)`.
    fn phi(&self, r: f64) -> f64 {
        let (lo, hi) = self.bounds();
        let (h0, g) = (self.h0, self.growth);
        let inner = |x: f64| (1.0 / g) * ((h0 + g * lo).ln() - (h0 + g * (lo - x)).ln());
        if r <= lo {
            inner(r)
        } else if r <= hi {
            inner(lo) + (r - lo) / h0
        } else {
            inner(lo) + (hi - lo) / h0 + (1.0 / g) * (1.0 + g * (r - hi) / h0).ln()
        }
    }

    /// Inverse of [`phi`](Self::phi).
    fn phi_inv(&self, p: f64) -> f64 {
        let (lo, hi) = self.bounds();
        let (h0, g) = (self.h0, self.growth);
        let p_lo = self.phi(lo);
        let p_hi = self.phi(hi);
        if p <= p_lo {
            // ln(h0 + g(lo - x)) = ln(h0 + g lo) - g p
            let v = ((h0 + g * lo).ln() - g * p).exp();
            lo - (v - h0) / g
        } else if p <= p_hi {
            lo + (p - p_lo) * h0
        } else {
            hi + h0 * ((g * (p - p_hi)).exp() - 1.0) / g
        }
    }

    /// Number of nodes [`nodes`](Self::nodes) returns, computed without
    /// allocating (saturates at `usize::MAX`).
    pub fn node_count(&self) -> usize {
        let total = self.phi(self.r_max).ceil();
        if total.is_finite() && total < 1e15 {
            (total as usize).max(4) + 1
        } else {
            usize::MAX
        }
    }

    /// The nodes, ascending, `r[0] = 0`, `r[n-1] = r_max`.
    pub fn nodes(&self) -> Vec<f64> {
        let total = self.phi(self.r_max);
        let n = (total.ceil() as usize).max(4);
        let mut r: Vec<f64> = (0..=n)
            .map(|k| self.phi_inv(total * k as f64 / n as f64))
            .collect();
        r[0] = 0.0;
        r[n] = self.r_max;
        r
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nodes_are_graded_around_the_edge() {
        let spec = MeshSpec {
            edge: 1.5,
            h0: 0.01,
            growth: 0.1,
            inner: 0.05,
            outer: 0.1,
            r_max: 20.0,
        };
        let r = spec.nodes();
        assert_eq!(r[0], 0.0);
        assert_eq!(*r.last().unwrap(), 20.0);
        assert!(r.windows(2).all(|w| w[1] > w[0]));
        // finest spacing at the edge, ~h0
        let near: Vec<f64> = r
            .windows(2)
            .filter(|w| (w[0] - 1.5).abs() < 0.05)
            .map(|w| w[1] - w[0])
            .collect();
        assert!(
            !near.is_empty() && near.iter().all(|&d| d < 0.011),
            "{near:?}"
        );
        // neighbouring spacings never jump by more than the growth allows
        for w in r.windows(3) {
            let ratio = (w[2] - w[1]) / (w[1] - w[0]);
            assert!(ratio < 1.3 && ratio > 1.0 / 1.3, "{ratio}");
        }
        // phi_inv inverts phi
        for x in [0.0, 0.7, 1.46, 1.5, 1.6, 5.0, 20.0] {
            assert!((spec.phi_inv(spec.phi(x)) - x).abs() < 1e-12 * (1.0 + x));
        }
    }

    proptest::proptest! {
        /// Any spec: strictly increasing nodes from 0 to r_max, finest spacing
        /// at most one Phi-step next to the edge, `h0 (e^g - 1)/g`, neighbouring
        /// spacings within the grading factor exp(growth).
        #[test]
        fn nodes_are_valid_for_any_spec(
            edge in 0.0f64..10.0,
            h0 in 1e-4f64..0.5,
            growth in 0.02f64..0.5,
            inner in 0.0f64..1.0,
            outer in 0.0f64..1.0,
            extra in 1.0f64..200.0,
        ) {
            let spec = MeshSpec { edge, h0, growth, inner, outer, r_max: edge + extra };
            let r = spec.nodes();
            proptest::prop_assert_eq!(r[0], 0.0);
            proptest::prop_assert_eq!(*r.last().unwrap(), edge + extra);
            proptest::prop_assert!(r.windows(2).all(|w| w[1] > w[0]));
            let min_gap = r.windows(2).map(|w| w[1] - w[0]).fold(f64::INFINITY, f64::min);
            proptest::prop_assert!(min_gap <= h0 * growth.exp_m1() / growth * (1.0 + 1e-9));
            for w in r.windows(3) {
                let ratio = (w[2] - w[1]) / (w[1] - w[0]);
                let bound = growth.exp() * (1.0 + 1e-9);
                proptest::prop_assert!(ratio <= bound && ratio >= 1.0 / bound, "{}", ratio);
            }
        }
    }

    #[test]
    fn edge_at_centre() {
        let spec = MeshSpec {
            edge: 0.0,
            h0: 0.1,
            growth: 0.1,
            inner: 0.3,
            outer: 0.3,
            r_max: 140.0,
        };
        let r = spec.nodes();
        assert!((r[1] - 0.1).abs() < 0.01);
        assert!(r.len() < 80, "{}", r.len());
    }
}
