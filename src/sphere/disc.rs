//! One mesh with its compliance matrix: everything that depends only on the
//! nodes (Greenwood 2009, appendix 1).
//!
//! The half-space influence `D(r, s)` is homogeneous of degree one,
//! `D(lambda r, lambda s) = lambda D(r, s)`, so a mesh scaled by `lambda` has the
//! compliance `lambda C` and the load weights `lambda^2 W` of the original: a
//! [`Discretisation`] is a [`BaseMesh`] (nodes, `C`, `W`, assembled once) seen
//! at a scale. Following a moving contact edge by rescaling costs `O(n)`; the
//! `O(n^2)` elliptic-integral assembly happens only when the scale leaves
//! its allowed band (see `trace.rs`).
//!
//! Far field beyond the last node `r_m` (the sphere then continues rigidly:
//! `H = H_m + f(r) - f(r_m)`): load `2 int sigma_hat r dr` in closed form,
//! and its displacement at the centre `2 mu^2 int sigma_hat ds` (nearly uniform
//! over the mesh, so it only shifts `alpha`) by Gauss–Legendre.

use super::compliance::{compliance_matrix, load_weights};
use super::force_law::{tail_integral, tail_moment, traction, GAP_MAX_TENSION};
use super::mesh::MeshSpec;
use super::quadrature::{gauss_legendre, Rule};
use super::Shape;
use std::sync::Arc;

/// Nodes, compliance matrix and load weights of one mesh at scale 1.
#[derive(Debug)]
pub(crate) struct BaseMesh {
    pub spec: MeshSpec,
    pub r: Vec<f64>,
    /// `C` row-major `n x n`.
    pub c: Vec<f64>,
    /// `W_j = int phi_j r dr`.
    pub w: Vec<f64>,
}

impl BaseMesh {
    pub fn new(spec: MeshSpec) -> Self {
        let r = spec.nodes();
        let c = compliance_matrix(&r);
        let w = load_weights(&r);
        BaseMesh { spec, r, c, w }
    }
}

/// A base mesh at a scale, with the shape sampled at its nodes.
#[derive(Debug, Clone)]
pub(crate) struct Discretisation {
    pub base: Arc<BaseMesh>,
    /// `lambda`: node radii are `lambda r_base`.
    pub scale: f64,
    /// The effective spec (base spec scaled by `lambda`).
    pub spec: MeshSpec,
    pub r: Vec<f64>,
    /// `W_j` at this scale.
    pub w: Vec<f64>,
    /// Undeformed shape `f_i` in units of `z0`.
    pub f: Vec<f64>,
    pub mu: f64,
    pub shape: Shape,
    /// Whether the tracer moves this mesh with the contact edge (a view
    /// whose scale puts the base's plateau centre on the edge): tangents are
    /// then taken along the moving nodes (`newton.rs`).
    pub moving: bool,
    tail_rule: Rule,
}

/// Undeformed gap `f(r)/z0`: `mu r^2/2`, or `rho - sqrt(rho^2 - rho mu r^2)` for a
/// true sphere (written without cancellation).
pub(crate) fn shape_gap(shape: Shape, mu: f64, r: f64) -> f64 {
    match shape {
        Shape::Paraboloid => 0.5 * mu * r * r,
        Shape::Sphere { rho } => {
            let x = rho * mu * r * r;
            let root = (rho * rho - x).max(0.0).sqrt();
            x / (rho + root)
        }
    }
}

/// Solver-unit radius of the sphere's equator `r = R`: `sqrt(rho/mu)`.
pub(crate) fn sphere_edge(shape: Shape, mu: f64) -> f64 {
    match shape {
        Shape::Paraboloid => f64::INFINITY,
        Shape::Sphere { rho } => (rho / mu).sqrt(),
    }
}

impl Discretisation {
    /// `base` at scale `lambda` (no assembly).
    pub fn view(base: Arc<BaseMesh>, scale: f64, mu: f64, shape: Shape) -> Self {
        let s = base.spec;
        let spec = MeshSpec {
            edge: s.edge * scale,
            h0: s.h0 * scale,
            growth: s.growth,
            inner: s.inner * scale,
            outer: s.outer * scale,
            r_max: s.r_max * scale,
        };
        let r: Vec<f64> = base.r.iter().map(|x| x * scale).collect();
        let w = base.w.iter().map(|x| x * scale * scale).collect();
        let f = r.iter().map(|&x| shape_gap(shape, mu, x)).collect();
        Discretisation {
            base,
            scale,
            spec,
            r,
            w,
            f,
            mu,
            shape,
            moving: false,
            tail_rule: gauss_legendre(16),
        }
    }

    /// `base` at scale `lambda`, moving with the contact edge.
    pub fn moving_view(base: Arc<BaseMesh>, scale: f64, mu: f64, shape: Shape) -> Self {
        Discretisation {
            moving: true,
            ..Self::view(base, scale, mu, shape)
        }
    }

    /// `r f'(r)` in units of `z0` (the change of the shape at a node that
    /// moves with the mesh scale, per unit `ln lambda`): `2 f` for the
    /// paraboloid, `mu r^2/sqrt(1 - mu r^2/rho)` for the true sphere.
    pub fn shape_scale_rate(&self, i: usize) -> f64 {
        let r = self.r[i];
        match self.shape {
            Shape::Paraboloid => 2.0 * self.f[i],
            Shape::Sphere { rho } => {
                let x = self.mu * r * r;
                x / (1.0 - x / rho).max(f64::MIN_POSITIVE).sqrt()
            }
        }
    }

    pub fn len(&self) -> usize {
        self.r.len()
    }

    /// Row `i` of the base compliance matrix (multiply by `scale`).
    #[inline]
    pub fn c_row(&self, i: usize) -> &[f64] {
        let n = self.len();
        &self.base.c[i * n..(i + 1) * n]
    }

    /// Far-field load `2 int_{r_m}^{r_end} sigma_hat r dr` with the rigid
    /// continuation from the last gap `hm`.
    pub fn tail_load(&self, hm: f64) -> f64 {
        self.tail_load_at(hm, *self.r.last().unwrap())
    }

    /// [`tail_load`](Self::tail_load) for a last node at `rm`.
    pub fn tail_load_at(&self, hm: f64, rm: f64) -> f64 {
        match self.shape {
            Shape::Paraboloid => 2.0 * tail_integral(hm),
            Shape::Sphere { rho } => {
                let fm = shape_gap(self.shape, self.mu, rm);
                let c = hm - fm;
                let hr = c + rho;
                if hr <= hm {
                    return 0.0;
                }
                (2.0 / rho)
                    * ((rho + c) * (tail_integral(hm) - tail_integral(hr))
                        - (tail_moment(hm) - tail_moment(hr)))
            }
        }
    }

    /// Far-field displacement at the centre, `2 mu^2 int_{r_m}^{r_end} sigma_hat ds`,
    /// with `s = r_m / t`.
    pub fn tail_centre_displacement(&self, hm: f64) -> f64 {
        self.tail_centre_displacement_at(hm, *self.r.last().unwrap())
    }

    /// [`tail_centre_displacement`](Self::tail_centre_displacement) for a
    /// last node at `rm` (its derivative in `rm` enters the moving-mesh
    /// tangent).
    pub fn tail_centre_displacement_at(&self, hm: f64, rm: f64) -> f64 {
        let r_end = sphere_edge(self.shape, self.mu);
        if r_end <= rm * (1.0 + 1e-12) {
            return 0.0;
        }
        let t_lo = rm / r_end; // 0 for the paraboloid
        let fm = shape_gap(self.shape, self.mu, rm);
        let mut sum = 0.0;
        for (x, w) in self.tail_rule.x.iter().zip(&self.tail_rule.w) {
            let t = t_lo + (1.0 - t_lo) * x;
            let s = rm / t;
            let h = hm + shape_gap(self.shape, self.mu, s) - fm;
            sum += w * traction(h) * rm / (t * t);
        }
        2.0 * self.mu * self.mu * sum * (1.0 - t_lo)
    }

    /// Linear interpolation of a gap profile `(r, h)` from another mesh onto
    /// this one; beyond its last node the sphere continues rigidly.
    pub fn interpolate(&self, r_old: &[f64], h_old: &[f64]) -> Vec<f64> {
        let n_old = r_old.len();
        let r_last = r_old[n_old - 1];
        let f_last = shape_gap(self.shape, self.mu, r_last);
        let mut k = 0;
        self.r
            .iter()
            .map(|&x| {
                if x >= r_last {
                    return h_old[n_old - 1] + shape_gap(self.shape, self.mu, x) - f_last;
                }
                while k + 2 < n_old && r_old[k + 1] < x {
                    k += 1;
                }
                let t = (x - r_old[k]) / (r_old[k + 1] - r_old[k]);
                h_old[k] + t * (h_old[k + 1] - h_old[k])
            })
            .collect()
    }

    /// Contact radius: the outermost radius where the gap rises through
    /// `3^(1/6)` (maximum tension), located on the quadratic through the
    /// bracketing nodes and one neighbour (the gap is smooth there; linear
    /// interpolation would bias the radius by `O(h^2 H''/H')`); 0 when the
    /// central gap is above it.
    pub fn contact_radius(&self, h: &[f64]) -> f64 {
        contact_radius(&self.r, h)
    }

    /// Pressure `p/(w E*^2/R)^(1/3) = mu sigma_hat(H)` at the nodes.
    pub fn pressure(&self, h: &[f64]) -> Vec<f64> {
        h.iter().map(|&x| self.mu * traction(x)).collect()
    }
}

/// See [`Discretisation::contact_radius`].
pub(crate) fn contact_radius(r: &[f64], h: &[f64]) -> f64 {
    let g = GAP_MAX_TENSION;
    if h[0] >= g {
        return 0.0;
    }
    let n = h.len();
    for i in (1..n).rev() {
        if h[i - 1] < g && h[i] >= g {
            let t = (g - h[i - 1]) / (h[i] - h[i - 1]);
            let lin = r[i - 1] + t * (r[i] - r[i - 1]);
            // third node: the neighbour on the side of the longer interval
            let k = if i + 1 < n {
                i + 1
            } else if i >= 2 {
                i - 2
            } else {
                return lin;
            };
            return quadratic_crossing([r[i - 1], r[i], r[k]], [h[i - 1], h[i], h[k]], g)
                .filter(|x| *x >= r[i - 1] && *x <= r[i])
                .unwrap_or(lin);
        }
    }
    *r.last().unwrap()
}

/// Root in `[x0, x1]` of the quadratic through three points minus `g`.
fn quadratic_crossing(x: [f64; 3], y: [f64; 3], g: f64) -> Option<f64> {
    // Newton form: p(s) = y0 + d1 (s - x0) + d2 (s - x0)(s - x1)
    let d1 = (y[1] - y[0]) / (x[1] - x[0]);
    let d12 = (y[2] - y[1]) / (x[2] - x[1]);
    let d2 = (d12 - d1) / (x[2] - x[0]);
    // solve in u = s - x0: d2 u^2 + (d1 - d2 (x1 - x0)) u + (y0 - g) = 0
    let (a, b, c) = (d2, d1 - d2 * (x[1] - x[0]), y[0] - g);
    let mut u = (g - y[0]) / d1; // linear start
    for _ in 0..8 {
        let f = (a * u + b) * u + c;
        let df = 2.0 * a * u + b;
        if df == 0.0 || !df.is_finite() {
            return None;
        }
        let du = f / df;
        u -= du;
        if du.abs() <= 1e-15 * (1.0 + u.abs()) {
            break;
        }
    }
    let s = x[0] + u;
    s.is_finite().then_some(s)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The quadratic crossing is exact for a quadratic gap profile, where the
    /// linear one is off by `O(h^2)`.
    #[test]
    fn crossing_is_exact_for_quadratics() {
        let r: Vec<f64> = (0..20).map(|i| 0.3 * i as f64).collect();
        let h: Vec<f64> = r.iter().map(|x| 0.9 + 0.05 * x * x).collect();
        let exact = ((GAP_MAX_TENSION - 0.9) / 0.05f64).sqrt();
        let a = contact_radius(&r, &h);
        assert!((a - exact).abs() < 1e-12, "{a} {exact}");
        let i = r.iter().position(|x| *x > exact).unwrap();
        let t = (GAP_MAX_TENSION - h[i - 1]) / (h[i] - h[i - 1]);
        let lin = r[i - 1] + t * 0.3;
        assert!((lin - exact).abs() > 1e-4);
    }

    /// `lambda C` is the compliance of the mesh scaled by `lambda`.
    #[test]
    fn scaled_view_matches_assembly() {
        let spec = MeshSpec {
            edge: 1.0,
            h0: 0.05,
            growth: 0.2,
            inner: 0.2,
            outer: 0.3,
            r_max: 6.0,
        };
        let lam = 1.37;
        let view = Discretisation::view(Arc::new(BaseMesh::new(spec)), lam, 1.0, Shape::Paraboloid);
        let direct = BaseMesh::new(view.spec);
        assert_eq!(direct.r.len(), view.len());
        for (a, b) in direct.r.iter().zip(&view.r) {
            assert!((a - b).abs() < 1e-12 * (1.0 + a));
        }
        let n = view.len();
        for i in 0..n {
            for j in 0..n {
                let c = lam * view.c_row(i)[j];
                let d = direct.c[i * n + j];
                assert!((c - d).abs() < 1e-11 * (1.0 + d.abs()), "{i} {j}: {c} {d}");
            }
        }
        for (a, b) in direct.w.iter().zip(&view.w) {
            assert!((a - b).abs() < 1e-12 * (1.0 + a));
        }
    }
}
