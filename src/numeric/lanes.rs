//! Helpers for loops over SIMD lanes (inside a [`pulp::WithSimd`]
//! operation, where the CPU's widest vectors are enabled).

/// `v[j] = sqrt(v[j])` in the CPU's SIMD registers: correctly rounded, so
/// bit for bit the scalar `f64::sqrt` (which the compiler does not always
/// vectorise by itself).
#[inline(always)]
pub fn sqrt_lanes<S: pulp::Simd>(simd: S, v: &mut [f64]) {
    let (head, tail) = S::as_mut_simd_f64s(v);
    for x in head {
        *x = simd.sqrt_f64s(*x);
    }
    for x in tail {
        *x = x.sqrt();
    }
}

/// Lanes of [`StateSums`] (fixed: part of the reduction order).
pub const STATE_LANES: usize = 8;

/// Lane sums of contact states: `lanes[k][j]` for `k` = load `P`, area
/// `pi a^2`, count `[a > 0]` and their squares (the count's square is the
/// count), lane `j`. A run of states adds state `i` to lane
/// `i mod STATE_LANES` ([`add`](Self::add)), so the order of the additions
/// in a lane, and the sums, do not depend on who computes the states (the
/// Monte Carlo lane sums, or a law adding its own states,
/// [`LawKernels::add_state_sums`](crate::law::LawKernels::add_state_sums)).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct StateSums {
    /// `[P, pi a^2, [a > 0], P^2, (pi a^2)^2, [a > 0]]`, each per lane.
    pub lanes: [[f64; STATE_LANES]; 6],
}

impl StateSums {
    /// Adds load `p` (N), area `pi a^2` and count `[a > 0]` of one state
    /// (radius `a`, m) and their squares to lane `j` (`j < STATE_LANES`).
    #[inline(always)]
    pub fn add(&mut self, j: usize, p: f64, a: f64) {
        let acc = &mut self.lanes;
        let area = std::f64::consts::PI * a * a;
        let c = if a > 0.0 { 1.0 } else { 0.0 };
        acc[0][j] += p;
        acc[1][j] += area;
        acc[2][j] += c;
        acc[3][j] += p * p;
        acc[4][j] += area * area;
        acc[5][j] += c;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    struct Roots<'a>(&'a mut [f64]);

    impl pulp::WithSimd for Roots<'_> {
        type Output = ();
        fn with_simd<S: pulp::Simd>(self, simd: S) {
            sqrt_lanes(simd, self.0);
        }
    }

    #[test]
    fn lane_roots_are_the_scalar_roots_bit_for_bit() {
        let x: Vec<f64> = (0..37)
            .map(|k| [0.0, -0.0, 1e-300, 2.0, 1e300, f64::INFINITY][k % 6] * (1.0 + k as f64))
            .chain([f64::NAN, -1.0])
            .collect();
        let mut y = x.clone();
        crate::numeric::simd::arch().dispatch(Roots(&mut y));
        for (a, b) in x.iter().zip(&y) {
            let s = a.sqrt();
            assert!(
                s.to_bits() == b.to_bits() || (s.is_nan() && b.is_nan()),
                "{a}"
            );
        }
    }
}
