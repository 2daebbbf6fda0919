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
