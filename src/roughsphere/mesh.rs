//! Radial meshes in Greenwood–Tripp units with the half-space compliance of
//! the sphere module ([`crate::sphere::compliance`]: piecewise-linear
//! pressure, "overlapping triangles", elliptic integrals with the log
//! singularity treated exactly).
//!
//! Two families, both images of `n` equally spaced points `xi` in `[0, 1]`
//! under a smooth map, so that meshes of `n`, `2n - 1`, `4n - 3` nodes are
//! nested and the discretisation error has the smooth expansion in powers
//! of the spacing that Richardson extrapolation needs (`solve.rs`):
//! - uniform, `rho = xi rho_max`. The compliance is homogeneous of degree
//!   one in the radii and the load weights of degree two, so `C = h C1`,
//!   `W = h^2 W1` with `C1`, `W1` of the unit-spacing mesh `0, 1, ..., n-1`,
//!   assembled once per process ([`Matrices::unit`]): moving the outer
//!   radius costs nothing;
//! - graded towards the contact edge `rho_e` (heavy loads, where the edge
//!   zone is narrow against the contact): spacing proportional to
//!   `sqrt(l^2 + (rho - rho_e)^2)`, i.e.
//!   `rho(xi) = rho_e + l sinh(xi Phi - asinh(rho_e/l))`,
//!   `Phi = asinh((rho_max - rho_e)/l) + asinh(rho_e/l)`; the matrices are
//!   assembled for each such mesh.

use crate::sphere::compliance::{compliance_matrix, load_weights};
use std::collections::HashMap;
use std::sync::{Arc, Mutex, OnceLock};

/// Compliance and load weights of one set of nodes.
#[derive(Debug)]
pub(crate) struct Matrices {
    /// `C_ij - C_0j` for `i >= 1` (row-major, `(n-1) x n`): the
    /// displacement relative to the centre.
    pub relative: Vec<f64>,
    /// `C_0j`.
    pub centre: Vec<f64>,
    /// Full `C` (row-major `n x n`).
    pub full: Vec<f64>,
    /// `W_j = int phi_j r dr`.
    pub weights: Vec<f64>,
}

/// Largest mesh (one matrix is `8 n^2` bytes, 32 MiB here).
pub(crate) const MAX_NODES: usize = 2049;

impl Matrices {
    fn assemble(r: &[f64]) -> Self {
        let n = r.len();
        let full = compliance_matrix(r);
        let centre = full[..n].to_vec();
        let mut relative = Vec::with_capacity((n - 1) * n);
        for i in 1..n {
            relative.extend((0..n).map(|j| full[i * n + j] - centre[j]));
        }
        Matrices {
            relative,
            centre,
            full,
            weights: load_weights(r),
        }
    }

    /// The unit-spacing mesh of `n` nodes, assembled on first use and kept
    /// for the life of the process.
    pub fn unit(n: usize) -> Arc<Matrices> {
        static CACHE: OnceLock<Mutex<HashMap<usize, Arc<Matrices>>>> = OnceLock::new();
        let cache = CACHE.get_or_init(|| Mutex::new(HashMap::new()));
        if let Some(m) = cache.lock().ok().and_then(|c| c.get(&n).cloned()) {
            return m;
        }
        // Assembled outside the lock; a race builds the same matrix twice
        // and keeps one.
        let r: Vec<f64> = (0..n).map(|k| k as f64).collect();
        let m = Arc::new(Matrices::assemble(&r));
        match cache.lock() {
            Ok(mut c) => c.entry(n).or_insert(m).clone(),
            Err(_) => m,
        }
    }
}

/// How the nodes are placed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Grading {
    /// Equal spacing.
    Uniform,
    /// Refined around `edge` with core width `width` (see the module doc).
    Edge {
        /// `rho_e`.
        edge: f64,
        /// `l`.
        width: f64,
    },
}

/// A mesh from 0 to `rho_max` (Greenwood–Tripp units).
#[derive(Debug, Clone)]
pub(crate) struct Mesh {
    mats: Arc<Matrices>,
    /// `C = scale * mats` (the spacing for uniform meshes, 1 otherwise).
    scale: f64,
    pub grading: Grading,
    /// Nodes, ascending, `rho[0] = 0`.
    pub rho: Vec<f64>,
}

impl Mesh {
    /// `n` nodes (`4 <= n <= MAX_NODES`) from 0 to `rho_max`.
    pub fn new(n: usize, rho_max: f64, grading: Grading) -> Self {
        match grading {
            Grading::Uniform => {
                let h = rho_max / (n - 1) as f64;
                Mesh {
                    mats: Matrices::unit(n),
                    scale: h,
                    grading,
                    rho: (0..n).map(|k| k as f64 * h).collect(),
                }
            }
            Grading::Edge { edge, width } => {
                let a = (edge / width).asinh();
                let phi = ((rho_max - edge) / width).asinh() + a;
                let mut rho: Vec<f64> = (0..n)
                    .map(|k| {
                        let xi = k as f64 / (n - 1) as f64;
                        edge + width * (xi * phi - a).sinh()
                    })
                    .collect();
                rho[0] = 0.0;
                rho[n - 1] = rho_max;
                Mesh {
                    mats: Arc::new(Matrices::assemble(&rho)),
                    scale: 1.0,
                    grading,
                    rho,
                }
            }
        }
    }

    /// The same family with `2n - 1` nodes (every node of `self` kept).
    pub fn refined(&self) -> Self {
        Mesh::new(2 * self.len() - 1, self.rho_max(), self.grading)
    }

    pub fn len(&self) -> usize {
        self.rho.len()
    }

    pub fn rho_max(&self) -> f64 {
        self.rho[self.len() - 1]
    }

    /// Multiplier of the stored compliance.
    #[inline]
    pub fn scale(&self) -> f64 {
        self.scale
    }

    /// Row `i >= 1` of the stored relative compliance (times
    /// [`scale`](Self::scale)).
    #[inline]
    pub fn relative_row(&self, i: usize) -> &[f64] {
        let n = self.len();
        &self.mats.relative[(i - 1) * n..i * n]
    }

    /// The stored relative compliance, row-major `(n-1) x n`.
    #[inline]
    pub fn relative(&self) -> &[f64] {
        &self.mats.relative
    }

    /// `E* u = C p` at every node for pressures `q` (row `i`, `sum_j C_ij q_j`).
    pub fn apply(&self, q: &[f64]) -> Vec<f64> {
        let n = self.len();
        (0..n)
            .map(|i| {
                let row = &self.mats.full[i * n..(i + 1) * n];
                self.scale * row.iter().zip(q).map(|(c, x)| c * x).sum::<f64>()
            })
            .collect()
    }

    /// `int p rho drho` of the piecewise-linear pressure through `p` (the
    /// load is `2 pi` times this).
    pub fn moment(&self, p: &[f64]) -> f64 {
        let s: f64 = self.mats.weights.iter().zip(p).map(|(w, x)| w * x).sum();
        self.scale * self.scale * s
    }

    /// `W_j` of [`moment`](Self::moment).
    #[cfg(test)]
    pub fn weight(&self, j: usize) -> f64 {
        self.scale * self.scale * self.mats.weights[j]
    }

    /// The central deflection `u(0) = (1/2) sum_j C_0j p_j` in
    /// Greenwood–Tripp units (`= int_0^inf p drho`: exact for the
    /// piecewise-linear pressure).
    pub fn central_deflection(&self, p: &[f64]) -> f64 {
        let s: f64 = self.mats.centre.iter().zip(p).map(|(c, x)| c * x).sum();
        0.5 * self.scale * s
    }

    /// Gap `H(rho)` at any radius by 4-point Lagrange interpolation of the
    /// nodal gaps (`H` is even in `rho`: mirrored nodes at the axis; error
    /// `O(h^4)`). Beyond the last node the shape `f` continues rigidly.
    pub fn gap_at(&self, gaps: &[f64], rho: f64, shape: impl Fn(f64) -> f64) -> f64 {
        let n = self.len();
        let last = self.rho_max();
        if rho >= last {
            return gaps[n - 1] + shape(rho) - shape(last);
        }
        let rho = rho.abs();
        let k = self.rho.partition_point(|x| *x <= rho).clamp(1, n - 1) as isize - 1;
        let base = (k - 1).min(n as isize - 4);
        let node = |m: isize| {
            let i = m.unsigned_abs();
            let x = if m < 0 { -self.rho[i] } else { self.rho[i] };
            (x, gaps[i])
        };
        let pts: [(f64, f64); 4] = std::array::from_fn(|a| node(base + a as isize));
        let mut sum = 0.0;
        for a in 0..4 {
            let mut w = 1.0;
            for b in 0..4 {
                if a != b {
                    w *= (rho - pts[b].0) / (pts[a].0 - pts[b].0);
                }
            }
            sum += w * pts[a].1;
        }
        sum
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The cached unit matrices scale to the direct assembly on a mesh of
    /// spacing `h`; the graded mesh is assembled on its own nodes.
    #[test]
    fn meshes_match_direct_assembly() {
        for grading in [
            Grading::Uniform,
            Grading::Edge {
                edge: 1.7,
                width: 0.2,
            },
        ] {
            let m = Mesh::new(9, 3.0, grading);
            let direct = compliance_matrix(&m.rho);
            for i in 1..9 {
                for j in 0..9 {
                    let d = direct[i * 9 + j] - direct[j];
                    let c = m.scale() * m.relative_row(i)[j];
                    assert!((c - d).abs() < 1e-12 * (1.0 + d.abs()), "{i} {j} {c} {d}");
                }
            }
            let w = load_weights(&m.rho);
            for (j, wj) in w.iter().enumerate() {
                assert!((m.weight(j) - wj).abs() < 1e-13);
            }
            assert!(m.rho.windows(2).all(|w| w[1] > w[0]));
            assert_eq!(m.rho[8], 3.0);
        }
    }

    /// Refinement keeps every node (nested meshes) in both families.
    #[test]
    fn refinement_is_nested() {
        for grading in [
            Grading::Uniform,
            Grading::Edge {
                edge: 5.0,
                width: 0.1,
            },
        ] {
            let m = Mesh::new(17, 7.0, grading);
            let f = m.refined();
            assert_eq!(f.len(), 33);
            for k in 0..17 {
                assert!((f.rho[2 * k] - m.rho[k]).abs() < 1e-12, "{grading:?} {k}");
            }
        }
        // the graded mesh is finest at the edge
        let g = Mesh::new(
            65,
            7.0,
            Grading::Edge {
                edge: 5.0,
                width: 0.05,
            },
        );
        let gaps: Vec<f64> = g.rho.windows(2).map(|w| w[1] - w[0]).collect();
        let (imin, _) = gaps
            .iter()
            .enumerate()
            .min_by(|a, b| a.1.total_cmp(b.1))
            .unwrap();
        assert!((g.rho[imin] - 5.0).abs() < 0.1, "{}", g.rho[imin]);
    }

    /// The interpolation reproduces even quadratics and cubics exactly.
    #[test]
    fn gap_interpolation_is_exact_for_low_degree() {
        let m = Mesh::new(21, 4.0, Grading::Uniform);
        let f = |r: f64| 1.5 + 0.3 * r * r;
        let g: Vec<f64> = m.rho.iter().map(|&r| f(r)).collect();
        for r in [0.0, 0.05, 0.13, 1.01, 3.3, 3.95] {
            assert!((m.gap_at(&g, r, |x| 0.3 * x * x) - f(r)).abs() < 1e-13);
        }
        assert!((m.gap_at(&g, 5.0, |x| 0.3 * x * x) - f(5.0)).abs() < 1e-13);
    }
}
