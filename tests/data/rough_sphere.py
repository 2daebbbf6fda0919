"""Reference solutions of the Greenwood-Tripp rough sphere, computed
independently of src/roughsphere/ (different discretisation, different kernel,
different special functions).

Problem (Greenwood & Tripp 1967, J. Appl. Mech. 34, 153; Johnson, Contact
Mechanics, sec. 13.4), in their units: rho = r/sqrt(2 R sigma), gaps in sigma,
pressure in E* sqrt(sigma/(8R)), mu = (8/3) eta sigma sqrt(2 R beta):

    p(rho) = mu F_3/2(H(rho)),   H(rho) = d + rho^2 + u(rho) - u(0),
    u(rho) = (2/pi) int_0^inf p(t) t/(rho + t) K(4 rho t/(rho + t)^2) dt,
    P* = 2 pi int_0^inf p rho drho,

K the complete elliptic integral of the first kind in the parameter
convention (scipy.special.ellipkm1 of 1 - m). u is the ring-load (Boussinesq) kernel of
physics.md, E* w(r) = (4/pi) int p(s) s/(r+s) K(.) ds, rewritten in these
units (w/sigma = u); at rho = 0 it gives u(0) = int p dt.

Method (not the engine's): the pressure is represented by its values at
Gauss-Legendre nodes of equal panels on [0, rho_max] (degree q-1 polynomials
per panel, spectral accuracy), the displacement at every node by product
integration of the panel polynomials against the kernel (far panels: a
48-point Gauss rule through the panel interpolant; the panel holding the node,
split there, and its neighbours: 80-point Gauss-Legendre after the substitution
t = rho +- L x^6, which turns the logarithmic singularity at t = rho into
x^5 ln x; checked against scipy.integrate.quad in `check_rows`). The kernel is homogeneous of degree 0, so the weights are built once on
[0, 1] and scaled by rho_max. F_n(h) = Gamma(n+1) exp(-h^2/4) D_(-n-1)(h) /
sqrt(2 pi) (parabolic cylinder D, scipy.special.pbdv; checked against mpmath
pcfd to 3e-13 relative on [-8, 10]). Newton on the nodal gaps, continuation in
d from d = 8. rho_max is where the gap reaches 9 (p < 1e-18 mu) plus 10 %.

Convergence: every case is solved with two layouts (24 panels x 16 nodes and
32 panels x 20 nodes; for contacts wider than rho = 12 the panel edges are
graded towards the contact edge found on a first solve); the file keeps the finer one and the largest relative
difference between the two (load, central deflection, pressures) as
`layout_difference`.

The mu -> 0 limit: P*/mu -> pi F_5/2(d)/(5/2) exactly (rigid sphere), with
F_5/2 from mpmath at 30 digits (`rigid_limit`).

Run (a few minutes): /work/venv-peers/bin/python tests/data/rough_sphere.py > tests/data/rough_sphere.json
"""
import json
import sys

import mpmath as mp
import numpy as np
from scipy.special import ellipkm1, gamma, pbdv

MUS = [1e-3, 0.1, 1.0, 10.0, 100.0]
DS = [-1.0, 0.0, 0.5, 2.0]
RHOS = [0.0, 0.25, 0.5, 0.75, 1.0]
GAP_END = 9.0


def F(n, h):
    """F_n(h); 0 beyond h = 38.5 where phi(h) underflows (pbdv would give 0 * inf)."""
    h = np.asarray(h, dtype=float)
    far = h > 38.5
    hc = np.where(far, 0.0, h)
    v = np.array([pbdv(-n - 1, x)[0] for x in hc.ravel()]).reshape(h.shape)
    return np.where(far, 0.0, gamma(n + 1) * np.exp(-hc * hc / 4) * v / np.sqrt(2 * np.pi))


def kernel(rho, t, offset=None):
    """(2/pi) t/(rho+t) K(4 rho t/(rho+t)^2), with K(m) = ellipkm1(1 - m) and
    1 - m = ((t - rho)/(t + rho))^2 from the offset t - rho (given exactly by
    the clustered rules, so nodes next to the singularity keep their digits)."""
    t = np.asarray(t, dtype=float)
    off = t - rho if offset is None else offset
    s = rho + t
    safe = np.where(s > 0, s, 1.0)
    m1 = (off / safe) ** 2
    return np.where(s > 0, 2 / np.pi * t / safe * ellipkm1(m1), 0.0)


def lagrange(nodes, k, t):
    v = np.ones_like(np.asarray(t, dtype=float))
    for j, x in enumerate(nodes):
        if j != k:
            v = v * (t - x) / (nodes[k] - x)
    return v


def clustered(a, b, at, rule):
    """Nodes and weights on [a, b] clustered at the end `at` (a or b) by
    t = at +- L x^6: the log singularity at that end becomes x^5 ln x."""
    x, w = rule
    L = b - a
    m = 6
    t = L * x ** m
    wt = w * L * m * x ** (m - 1)
    return (a + t, wt, t) if at == a else (b - t, wt, -t)


class Layout:
    """Panels on [0, 1]: nodes, Gauss weights, product-integration weights."""

    def __init__(self, panels, q, edge=None, width=None):
        """`panels` equal panels, or (heavy loads) panel edges graded towards
        the contact edge at fraction `edge` of [0, 1] with core width `width`:
        the images of equal steps under x = e + w sinh(xi Phi - asinh(e/w))."""
        self.panels, self.q = panels, q
        g, w = np.polynomial.legendre.leggauss(q)
        G, W = np.polynomial.legendre.leggauss(48)
        X, Wx = np.polynomial.legendre.leggauss(80)
        self.unit_rule = ((X + 1) / 2, Wx / 2)
        if edge is None:
            edges = np.linspace(0, 1, panels + 1)
        else:
            a = np.arcsinh(edge / width)
            phi = np.arcsinh((1 - edge) / width) + a
            edges = edge + width * np.sinh(np.linspace(0, 1, panels + 1) * phi - a)
            edges[0], edges[-1] = 0.0, 1.0
        self.edges = edges
        self.x = np.concatenate([(a + b) / 2 + (b - a) / 2 * g for a, b in zip(edges[:-1], edges[1:])])
        self.w = np.concatenate([(b - a) / 2 * w for a, b in zip(edges[:-1], edges[1:])])
        self.local = g
        self.G, self.W = G, W
        self.A = np.array([self.row(r) for r in self.x])

    def basis(self, nodes, t):
        """All Lagrange basis polynomials of the panel at points t: (q, len(t))."""
        return np.array([lagrange(nodes, k, t) for k in range(self.q)])

    def row(self, rho):
        """Weights a_k with u(rho) = sum_k a_k p_k on the unit layout."""
        q = self.q
        out = np.zeros(self.panels * q)
        for P in range(self.panels):
            a, b = self.edges[P], self.edges[P + 1]
            nodes = (a + b) / 2 + (b - a) / 2 * self.local
            if a < rho < b:
                pieces = [clustered(a, rho, rho, self.unit_rule), clustered(rho, b, rho, self.unit_rule)]
            elif a - (b - a) <= rho <= a:
                pieces = [clustered(a, b, a, self.unit_rule)]
            elif b <= rho <= b + (b - a):
                pieces = [clustered(a, b, b, self.unit_rule)]
            else:
                t = (a + b) / 2 + (b - a) / 2 * self.G
                pieces = [(t, (b - a) / 2 * self.W, None)]
            v = np.zeros(q)
            split = a < rho < b
            for t, wt, off in pieces:
                # offsets from rho: exact when the rule is clustered at rho
                off = off if split else t - rho
                v += self.basis(nodes, t) @ (wt * kernel(rho, t, off))
            out[P * q:(P + 1) * q] = v
        return out


def newton(A, wq, x, mu, d, H):
    """Damped Newton on the nodal gaps at separation d from H."""
    def residual(H):
        p = mu * F(1.5, H)
        return H - d - x * x - (A @ p - wq @ p), p
    R, p = residual(H)
    for it in range(60):
        dp = -1.5 * mu * F(0.5, H)
        J = np.eye(len(x)) - (A - wq[None, :]) * dp[None, :]
        step = np.linalg.solve(J, R)
        lam = 1.0
        while True:
            Hn = H - lam * step
            Rn, pn = residual(Hn)
            if np.max(np.abs(Rn)) < np.max(np.abs(R)) or lam < 1e-3:
                break
            lam /= 2
        H, R = Hn, Rn
        scale = 1 + np.max(np.abs(H)) + wq @ pn
        if np.max(np.abs(lam * step)) < 1e-13 * scale and np.max(np.abs(R)) < 1e-12 * scale:
            return H
    raise RuntimeError(f"no convergence mu={mu} d={d}")


def solve(layout, mu, d, rho_max, rhos):
    x = layout.x * rho_max
    wq = layout.w * rho_max
    A = layout.A * rho_max  # kernel homogeneous of degree 0: weights scale with rho_max
    d0 = 8.0
    H = d0 + x * x
    step = (d - d0) / 10
    cur = d0
    while cur != d:
        nxt = d if abs(d - cur) <= abs(step) else cur + step
        try:
            H = newton(A, wq, x, mu, nxt, H + (nxt - cur))
            cur = nxt
        except (RuntimeError, np.linalg.LinAlgError):
            step /= 2
            if abs(step) < 1e-6:
                raise
    p = mu * F(1.5, H)
    u0 = wq @ p
    load = 2 * np.pi * np.sum(wq * x * p)
    press = []
    for r in rhos:
        if r == 0:
            h = d
        else:
            a = layout.row(r / rho_max) * rho_max
            h = d + r * r + a @ p - u0
        press.append(float(mu * F(1.5, np.array([h]))[0]))
    return float(load), float(u0), press, H, x


def rho_end(layout, mu, d):
    """rho where the gap reaches GAP_END on a first solve, plus 10 %."""
    rm = np.sqrt(GAP_END - d) * 1.5 + 1.0
    for _ in range(20):
        _, u0, _, H, x = solve(layout, mu, d, rm, [])
        if H[-1] < GAP_END:
            rm *= 1.3
            continue
        i = np.argmax(H > GAP_END)
        return 1.1 * x[i]
    raise RuntimeError("no outer radius")


def check_rows():
    """Product-integration weights against adaptive quadrature (scipy quad,
    split at the singularity) for a few radii; returns the largest
    difference relative to the row's sum."""
    from scipy.integrate import quad
    lay = Layout(4, 8)
    worst = 0.0
    for rho in [0.013, 0.3, 0.37, 0.5, 0.8123]:
        row = lay.row(rho)
        for P in range(lay.panels):
            a, b = lay.edges[P], lay.edges[P + 1]
            nodes = (a + b) / 2 + (b - a) / 2 * lay.local
            for k in range(lay.q):
                f = lambda t: lagrange(nodes, k, t) * kernel(rho, t)
                pts = [rho] if a < rho < b else None
                v, _ = quad(f, a, b, points=pts, limit=400, epsabs=1e-14, epsrel=1e-12)
                worst = max(worst, abs(v - row[P * lay.q + k]) / np.sum(np.abs(row)))
    return worst


def main():
    check = check_rows()
    print(f"product weights vs quad: {check:.1e}", file=sys.stderr)
    uniform = (Layout(24, 16), Layout(32, 20))
    cases = []
    for mu in MUS:
        for d in DS:
            rm = rho_end(uniform[0], mu, d)
            coarse, fine = uniform
            if rm > 12:
                # heavy load: panels graded towards the edge (steepest
                # pressure fall), core width max|p|/max|p'|
                _, _, _, H, x = solve(coarse, mu, d, rm, [])
                p = mu * F(1.5, H)
                slope = np.abs(np.diff(p) / np.diff(x))
                k = np.argmax(slope)
                edge, width = (x[k] + x[k + 1]) / 2 / rm, np.max(p) / slope[k] / rm
                coarse = Layout(24, 16, edge, 2 * width)
                fine = Layout(32, 20, edge, 2 * width)
            lc, uc, pc, _, _ = solve(coarse, mu, d, rm, RHOS)
            lf, uf, pf, _, _ = solve(fine, mu, d, rm, RHOS)
            diff = max(abs(lf - lc) / abs(lf), abs(uf - uc) / abs(uf),
                       max(abs(a - b) / abs(a) for a, b in zip(pf, pc)))
            print(f"mu={mu} d={d} rho_max={rm:.3f} load={lf:.12e} diff={diff:.1e}", file=sys.stderr)
            cases.append({
                "mu": mu, "d": d, "rho_max": rm, "load": lf, "central_deflection": uf,
                "pressure": [{"rho": r, "p": v} for r, v in zip(RHOS, pf)],
                "layout_difference": diff,
            })
    mp.mp.dps = 30

    def F52(h):
        return mp.gamma(mp.mpf(7) / 2) * mp.exp(-mp.mpf(h) ** 2 / 4) * mp.pcfd(-mp.mpf(7) / 2, h) / mp.sqrt(2 * mp.pi)

    rigid = [{"d": d, "load_over_mu": float(mp.pi * F52(d) / mp.mpf(2.5))} for d in [-1.0, -0.5, 0.0, 0.5, 1.0, 2.0]]
    json.dump({
        "source": "tests/data/rough_sphere.py: independent Greenwood-Tripp solver (Gauss-Legendre panels, "
                  "ring kernel with scipy ellipkm1, product integration by scipy quad, Newton); rigid limit by "
                  "mpmath pcfd at 30 digits",
        "units": "Greenwood-Tripp: rho = r/sqrt(2 R sigma), p in E* sqrt(sigma/(8R)), load in E* sqrt(sigma/(8R)) 2 R sigma, gaps in sigma",
        "product_weights_vs_quad": check,
        "cases": cases,
        "rigid_limit": rigid,
    }, sys.stdout, indent=1)


if __name__ == "__main__":
    main()
