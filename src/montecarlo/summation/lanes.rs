//! The lane sums of a block: each summit's load, area `pi a^2` and count
//! `[a > 0]` and their squares added to lane `i mod LANES` of its chunk,
//! the lanes combined in a fixed tree at the end of the block (so the sums
//! do not depend on the SIMD width or the thread count), and Hertz's state
//! computed inside the same pass ([`Accumulator::add_root_monomials`]), a
//! tabulated law's by the law itself ([`Accumulator::add_law_states`]).

use super::{Partial, CHUNK, LANES};
use crate::law::{ContactState, LawKernels};
use crate::loading::{Observables, EXTRA_SLOTS};
use crate::numeric::lanes::StateSums;

/// Stack buffers of one chunk.
pub(super) struct Buffers {
    pub(super) delta: [f64; CHUNK],
    pub(super) delta_max: [f64; CHUNK],
    pub(super) load: [f64; CHUNK],
    pub(super) radius: [f64; CHUNK],
}

impl Buffers {
    pub(super) fn new() -> Self {
        Buffers {
            delta: [0.0; CHUNK],
            delta_max: [0.0; CHUNK],
            load: [0.0; CHUNK],
            radius: [0.0; CHUNK],
        }
    }
}

/// The lane sums of one block: `lanes[k][j]` for `k` = load, area, count
/// and their squares, lane `j`; further observables in `extras`, summed in
/// summit order.
#[derive(Default)]
pub(super) struct Accumulator {
    lanes: StateSums,
    extras: Partial,
}

impl Accumulator {
    /// Adds the first `n` summits of a chunk (load and radius, already
    /// scaled), padding the last lane group with free summits (exact
    /// zeros).
    #[inline]
    pub(super) fn add_chunk(&mut self, buf: &mut Buffers, n: usize, obs: &Observables) {
        if !obs.extras().is_empty() {
            for (&load, &radius) in buf.load[..n].iter().zip(&buf.radius[..n]) {
                let st = ContactState { load, radius };
                for (k, e) in obs.extras().iter().take(EXTRA_SLOTS).enumerate() {
                    let v = e.value(&st);
                    self.extras.sum[3 + k] += v;
                    self.extras.sq[3 + k] += v * v;
                }
            }
        }
        let padded = n.next_multiple_of(LANES);
        buf.load[n..padded].fill(0.0);
        buf.radius[n..padded].fill(0.0);
        lane_sums(&buf.load[..padded], &buf.radius[..padded], &mut self.lanes);
    }

    /// [`add_chunk`](Self::add_chunk) of the states `P = k d sqrt(d)`,
    /// `a = c sqrt(d)`, `d = max((z - sep) scale, 0)` of heights `z`
    /// ([`LawKernels::root_monomials`](crate::law::LawKernels::root_monomials)),
    /// computed in the same pass: the same lanes, the same operations, so
    /// the same bits (the padding the chunk path adds is `+0.0` to lanes
    /// that hold non-negative sums, which changes nothing).
    #[inline]
    pub(super) fn add_root_monomials(&mut self, z: &[f64], sep: f64, scale: f64, k: f64, c: f64) {
        crate::numeric::simd::arch().dispatch(RootMonomialSums {
            z,
            sep,
            scale,
            k,
            c,
            lanes: &mut self.lanes,
        });
    }

    /// [`add_chunk`](Self::add_chunk) of `law`'s states at interferences
    /// `(z - sep) scale` (after `(z - closest) scale`), summed by the law
    /// in the same lanes and order ([`LawKernels::add_state_sums`]), so
    /// the same bits; `false` (nothing added) when the law does not fuse.
    #[inline]
    pub(super) fn add_law_states(
        &mut self,
        law: &dyn LawKernels,
        z: &[f64],
        sep: f64,
        closest: Option<f64>,
        scale: f64,
    ) -> bool {
        law.add_state_sums(z, sep, closest, scale, &mut self.lanes)
    }

    /// Lanes combined in a fixed tree: `((l0 + l1) + (l2 + l3)) + ((l4 + l5) + (l6 + l7))`.
    pub(super) fn finish(&self) -> Partial {
        let mut p = self.extras;
        let tree =
            |l: &[f64; LANES]| ((l[0] + l[1]) + (l[2] + l[3])) + ((l[4] + l[5]) + (l[6] + l[7]));
        for k in 0..3 {
            p.sum[k] = tree(&self.lanes.lanes[k]);
            p.sq[k] = tree(&self.lanes.lanes[3 + k]);
        }
        p
    }
}

/// Adds `P`, `pi a^2`, `[a > 0]` and their squares of each summit to lane
/// `i mod LANES` (lengths multiples of [`LANES`]); branch-free, vectorised
/// at the widest SIMD the CPU has ([`pulp::Arch`]).
#[inline]
fn lane_sums(load: &[f64], radius: &[f64], lanes: &mut StateSums) {
    crate::numeric::simd::arch().dispatch(LaneSums {
        load,
        radius,
        lanes,
    });
}

/// [`lane_sums`] as a [`pulp::WithSimd`] operation: its body is compiled
/// inside the target-feature context (a closure passed to `dispatch` was
/// left out of line and ran as 128-bit SSE2 code with its accumulators on
/// the stack: 40 % of a Hertz sum's time).
struct LaneSums<'a> {
    load: &'a [f64],
    radius: &'a [f64],
    lanes: &'a mut StateSums,
}

impl pulp::WithSimd for LaneSums<'_> {
    type Output = ();

    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _simd: S) {
        let mut acc = *self.lanes;
        for (l, r) in self
            .load
            .chunks_exact(LANES)
            .zip(self.radius.chunks_exact(LANES))
        {
            for j in 0..LANES {
                acc.add(j, l[j], r[j]);
            }
        }
        *self.lanes = acc;
    }
}

/// [`Accumulator::add_root_monomials`] as a [`pulp::WithSimd`] operation.
struct RootMonomialSums<'a> {
    z: &'a [f64],
    sep: f64,
    scale: f64,
    k: f64,
    c: f64,
    lanes: &'a mut StateSums,
}

impl pulp::WithSimd for RootMonomialSums<'_> {
    type Output = ();

    #[inline(always)]
    fn with_simd<S: pulp::Simd>(self, _simd: S) {
        let mut acc = *self.lanes;
        let (sep, scale, k, c) = (self.sep, self.scale, self.k, self.c);
        // `root_monomial_state`, then as `LaneSums`, a lane group at a
        // time (the remainder padded with free summits: +0.0 everywhere).
        let mut groups = self.z.chunks_exact(LANES);
        for g in &mut groups {
            root_monomial_group(&mut acc, g.try_into().expect("LANES"), sep, scale, k, c);
        }
        let rest = groups.remainder();
        if !rest.is_empty() {
            let mut pad = [f64::NEG_INFINITY; LANES];
            pad[..rest.len()].copy_from_slice(rest);
            root_monomial_group(&mut acc, &pad, sep, scale, k, c);
        }
        *self.lanes = acc;
    }
}

/// One lane group of [`RootMonomialSums`].
#[inline(always)]
fn root_monomial_group(
    acc: &mut StateSums,
    z: &[f64; LANES],
    sep: f64,
    scale: f64,
    k: f64,
    c: f64,
) {
    let (mut p, mut a) = ([0.0; LANES], [0.0; LANES]);
    for j in 0..LANES {
        (p[j], a[j]) = crate::law::hertz::root_monomial_state((z[j] - sep) * scale, k, c);
    }
    for j in 0..LANES {
        acc.add(j, p[j], a[j]);
    }
}
