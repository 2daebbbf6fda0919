#!/usr/bin/env python3
"""The numpy peer of `benches/montecarlo.rs` (`mc_state/*/fixed/approach`).

Same work as one `MonteCarlo::state` call: N = 1e6 summits with sorted
exponential heights (sigma = 5 nm, R = 1 um), the flat at d = -sigma (every
summit in contact), the law evaluated on every summit, and the six sums
(load, area, count and their squares) that give the totals and standard
errors. Written the way a numpy user would (whole-array operations,
float64); single-threaded unless the BLAS/numpy build threads elementwise
ops (it does not).

Laws:
- hertz: P = (4/3) E* R^(1/2) x^(3/2), a = sqrt(R x).
- jkr: Newton on x^4 - sqrt(8/3) x - Dbar = 0 for all summits at once
  (the Rust law's start and stopping rule, iterated until every lane
  converged), then Pbar = A^3 - sqrt(6 A^3), A = x^2.
- tabulated-md: piecewise degree-6 Chebyshev panels (the layout of
  `InterpolatedLaw`): np.searchsorted for the panel, Clenshaw for the
  load and a^2, sqrt for a. PANELS panels over the population's range
  (pass the count the Rust table has: printed by the Rust bench).
- interp: np.interp of the load and of a^2 on a linear table with as many
  nodes as the Chebyshev table holds coefficients (PANELS x (DEG + 1)),
  sqrt for a: the cheapest tabulated law a numpy user would write (far
  less accurate than the Chebyshev panels at the same node count: linear
  interpolation errs by h^2 f''/8 per node spacing h).
- interp, matched: the same with the node count doubled until the linear
  table of the JKR load (a smooth stand-in of the same scales over the
  population's interferences, all in contact) is within TABLE_TOL of its
  largest value at 200,000 random points, TABLE_TOL = 1e-9 being the
  tolerance of asperity's tabulated Maugis-Dugdale law at the default
  accuracy (0.1 x 1e-8, `montecarlo::TABLE_TOLERANCE_FRACTION`).

Run: python3 benches/peers/montecarlo_numpy.py [PANELS]
(needs numpy; e.g. python3 -m venv /tmp/venv && /tmp/venv/bin/pip install numpy).
Prints ns per summit (best of REPEATS runs) per law.
"""
import sys
import time

import numpy as np

N = 1_000_000
SIGMA = 5e-9
R = 1e-6
E_STAR = 4.8e10
W = 0.5
REPEATS = 15
DEG = 6


def heights(n, seed=1):
    rng = np.random.default_rng(seed)
    e = rng.standard_exponential(n + 1)
    s = np.cumsum(e)
    return SIGMA * -np.log1p(-s[:-1] / s[-1])  # exponential quantile, sorted


def sums(load, radius):
    area = np.pi * radius * radius
    c = (radius > 0.0).astype(np.float64)
    return (load.sum(), area.sum(), c.sum(), (load * load).sum(), (area * area).sum(), c.sum())


def hertz(x):
    k = 4.0 / 3.0 * E_STAR * np.sqrt(R)
    xp = np.maximum(x, 0.0)
    return k * xp * np.sqrt(xp), np.sqrt(R * xp)


# Maugis scales (K = 4E*/3).
K = 4.0 / 3.0 * E_STAR
D_SCALE = (np.pi**2 * W**2 * R / K**2) ** (1.0 / 3.0)
P_SCALE = np.pi * W * R
A_SCALE = (np.pi * W * R**2 / K) ** (1.0 / 3.0)
B = np.sqrt(8.0 / 3.0)
XC = 6.0 ** (-1.0 / 6.0)
DC = -0.75 * (4.0 / 3.0) ** (2.0 / 3.0)


def jkr(x):
    d = x / D_SCALE
    ok = d >= DC
    dd = np.where(ok, d, 0.0)
    bound = np.sqrt(np.sqrt(np.maximum(dd, 0.0))) + B ** (1.0 / 3.0)
    fold = XC + np.sqrt((dd - DC) / (6.0 * XC * XC))
    s = np.minimum(bound, fold)
    active = np.ones_like(s, dtype=bool)
    for _ in range(60):
        s2 = s * s
        f = s2 * s2 - B * s - dd
        fp = 4.0 * s2 * s - B
        step = np.where(active & (fp > 0.0), f / np.where(fp > 0.0, fp, 1.0), 0.0)
        s = s - step
        active &= np.abs(step) > 4.0 * np.finfo(float).eps * s
        if not active.any():
            break
    a = np.maximum(s, XC) ** 2
    a3 = a * a * a
    load = np.where(ok, (a3 - np.sqrt(6.0 * a3)) * P_SCALE, 0.0)
    radius = np.where(ok, a * A_SCALE, 0.0)
    return load, radius


def make_table(lo, hi, panels):
    edges = np.linspace(lo, hi, panels + 1)
    # Coefficients of a smooth stand-in (the timing does not depend on them).
    rng = np.random.default_rng(0)
    cl = rng.standard_normal((panels, DEG + 1)) * 1e-7
    cr = np.abs(rng.standard_normal((panels, DEG + 1))) * 1e-16
    return edges, cl, cr


def clenshaw(c, t):
    b1 = np.zeros_like(t)
    b2 = np.zeros_like(t)
    for j in range(DEG, 0, -1):
        b1, b2 = 2.0 * t * b1 - b2 + c[:, j], b1
    return t * b1 - b2 + c[:, 0]


def tabulated(x, table):
    edges, cl, cr = table
    n = len(cl)
    i = np.clip(np.searchsorted(edges, x, side="right"), 1, n) - 1
    l, r = edges[i], edges[i + 1]
    t = np.clip((2.0 * x - l - r) / (r - l), -1.0, 1.0)
    load = clenshaw(cl[i], t)
    radius = np.sqrt(np.maximum(clenshaw(cr[i], t), 0.0))
    return load, radius


def make_linear(lo, hi, nodes):
    xs = np.linspace(lo, hi, nodes)
    # A smooth stand-in (the timing does not depend on the values).
    return xs, 1e-7 * np.sin(xs / hi * 3.0), 1e-16 * (1.0 + xs / hi)


def interp(x, linear):
    xs, load, a2 = linear
    return np.interp(x, xs, load), np.sqrt(np.maximum(np.interp(x, xs, a2), 0.0))


TABLE_TOL = 1e-9


def matched_linear(lo, hi, start):
    """A linear table of the JKR load and a^2 on [lo, hi] whose
    interpolation error is at most TABLE_TOL of the largest |load|."""
    rng = np.random.default_rng(2)
    xt = rng.uniform(lo, hi, 200_000)
    lt, at = jkr(xt)
    scale = np.abs(lt).max()
    n = start
    while True:
        xs = np.linspace(lo, hi, n)
        lx, ax = jkr(xs)
        err = np.abs(np.interp(xt, xs, lx) - lt).max() / scale
        if err <= TABLE_TOL or n > 1 << 26:
            return (xs, lx, ax * ax), n, err
        n *= 2


def best_ns(f, z, d):
    best = float("inf")
    for _ in range(REPEATS):
        t0 = time.perf_counter()
        x = z - d
        sums(*f(x))
        best = min(best, time.perf_counter() - t0)
    return best / len(z) * 1e9


def main():
    panels = int(sys.argv[1]) if len(sys.argv) > 1 else 300
    z = heights(N)
    d = -SIGMA
    table = make_table(0.0, float(z[-1] - d), panels)
    linear = make_linear(0.0, float(z[-1] - d), panels * (DEG + 1))
    matched, n_matched, err = matched_linear(0.0, float(z[-1] - d), panels * (DEG + 1))
    print(f"numpy {np.__version__}, N = {N}, best of {REPEATS}, one thread")
    for name, f in [
        ("hertz", hertz),
        ("jkr", jkr),
        (f"tabulated-md ({panels} panels)", lambda x: tabulated(x, table)),
        (f"interp ({panels * (DEG + 1)} nodes)", lambda x: interp(x, linear)),
        (f"interp ({n_matched} nodes, err {err:.1e})", lambda x: interp(x, matched)),
    ]:
        print(f"{name:32s} {best_ns(f, z, d):8.2f} ns/summit")


if __name__ == "__main__":
    main()
