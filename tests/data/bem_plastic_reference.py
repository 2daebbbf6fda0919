#!/usr/bin/env python3
"""Independent reference for the elastic-perfectly-plastic boundary elements.

What: on a 32 x 32 map (written here, seeded, to bem_plastic_map32.npy), the
pressure field p that minimises the complementary energy (1/2) p.K p - p.h
over 0 <= p <= H at the imposed mean P, periodic and padded (non-periodic),
and its area fraction (p > 0), plastic fraction (p = H), mean gap and
plastically displaced volume per nominal area (mean over the map of the
interpenetration -g on the plastic pixels), g = K p - h - c.

How: written from docs/physics.md, not from the Rust code. K is the dense
compliance matrix: periodic, the Westergaard kernel 2/(E* |q|) (q = 0 term 0)
applied to every unit pressure by numpy's FFT; padded, Love's (1929)
coefficient of a uniformly loaded rectangle between every pair of pixels.
Heights: mean removed (periodic) or least-squares plane removed (padded). The
solution by a primal-dual active-set method (Hintermueller, Ito & Kunisch
2003): with the sets A0 (p = 0), AH (p = H) and F (free), one dense solve of
K_FF p_F - c = h_F - H K_F,AH 1, sum p = N P; then A0 = {p - k g <= 0},
AH = {p - k g >= H} with k = 1/K_00; until the sets repeat. The Karush-Kuhn-
Tucker conditions are then checked (g = 0 on F to 1e-10 h_rms (the dense solve rounds to ~1e-12), g >= 0 on A0,
g <= 0 on AH, 0 < p < H on F): exact for the discrete problem, so the sets
(the area and plastic fractions) are exact and the gap and volume carry only
the rounding of the dense solve (~1e-13 relative).

Run: python3 tests/data/bem_plastic_reference.py > tests/data/bem_plastic_reference.json
"""
import json
import numpy as np

N = 32
DX = 1e-6
ESTAR = 1e9
HARD = 0.1 * ESTAR
SEED = 20261129


def make_map():
    """A self-affine periodic map (Hurst 0.8, flat below q = 4 q0), random
    phases, RMS gradient 0.08 (by central differences... scaled to the
    forward-difference RMS gradient 0.08)."""
    rng = np.random.default_rng(SEED)
    q = 2 * np.pi * np.fft.fftfreq(N, d=DX)
    qx, qy = np.meshgrid(q, q)
    qq = np.hypot(qx, qy)
    q0 = 2 * np.pi / (N * DX)
    c = (np.maximum(qq, 4 * q0)) ** -3.6
    c[0, 0] = 0.0
    amp = np.sqrt(c) * np.exp(2j * np.pi * rng.random((N, N)))
    h = np.real(np.fft.ifft2(amp))
    h -= h.mean()
    gx = np.roll(h, -1, axis=1) - h
    gy = np.roll(h, -1, axis=0) - h
    g = np.sqrt(np.mean(gx ** 2 + gy ** 2)) / DX
    return h * 0.08 / g


def love_f(x, y):
    r = np.hypot(x, y)

    def lg(s, t):
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(s >= 0, np.log(s + r), 2 * np.log(np.abs(t)) - np.log(r - s))

    with np.errstate(invalid="ignore"):
        tx = np.where(x == 0, 0.0, x * lg(y, x))
        ty = np.where(y == 0, 0.0, y * lg(x, y))
    return tx + ty


def love_rect(x, y, dx, dy):
    a, b = dx / 2, dy / 2
    return love_f(x + a, y + b) - love_f(x - a, y + b) - love_f(x + a, y - b) + love_f(x - a, y - b)


def compliance(periodic):
    n = N * N
    if periodic:
        q = 2 * np.pi * np.fft.fftfreq(N, d=DX)
        qx, qy = np.meshgrid(q, q)
        qq = np.hypot(qx, qy)
        kern = np.where(qq > 0, 2.0 / (ESTAR * np.where(qq > 0, qq, 1.0)), 0.0)
        k = np.empty((n, n))
        for j in range(n):
            e = np.zeros(n)
            e[j] = 1.0
            k[:, j] = np.real(np.fft.ifft2(np.fft.fft2(e.reshape(N, N)) * kern)).ravel()
        return k
    ii, jj = np.divmod(np.arange(n), N)
    x = (jj[:, None] - jj[None, :]) * DX
    y = (ii[:, None] - ii[None, :]) * DX
    return love_rect(x, y, DX, DX) / (np.pi * ESTAR)


def heights(h, periodic):
    z = h.ravel().copy()
    if periodic:
        return z - z.mean()
    ii, jj = np.divmod(np.arange(N * N), N)
    a = np.column_stack([np.ones(N * N), jj * DX, ii * DX])
    coef, *_ = np.linalg.lstsq(a, z, rcond=None)
    return z - a @ coef


def project(x, p_mean, hard):
    """The Euclidean projection onto {0 <= p <= H, mean p = P}:
    clip(x - lam, 0, H) with lam by bisection."""
    lo, hi = x.min() - hard, x.max()
    for _ in range(200):
        lam = 0.5 * (lo + hi)
        if np.clip(x - lam, 0, hard).mean() > p_mean:
            lo = lam
        else:
            hi = lam
    return np.clip(x - 0.5 * (lo + hi), 0, hard)


def fista(k, h, p_mean, hard, steps):
    """Accelerated projected gradient (Beck & Teboulle 2009) on the
    complementary energy: a start for the active-set method."""
    lip = np.linalg.eigvalsh(k)[-1]
    p = project(np.full(len(h), p_mean), p_mean, hard)
    y, t = p.copy(), 1.0
    for _ in range(steps):
        pn = project(y - (k @ y - h) / lip, p_mean, hard)
        tn = 0.5 * (1 + np.sqrt(1 + 4 * t * t))
        y = pn + (t - 1) / tn * (pn - p)
        p, t = pn, tn
    free = (p > 0) & (p < hard)
    u = k @ p - h
    c = u[free].mean() if free.any() else 0.0
    return p, u - c


def solve(k, h, p_mean, hard):
    try:
        return active_set(k, h, p_mean, hard, np.full(len(h), p_mean), np.zeros(len(h)))
    except AssertionError:
        p, g = fista(k, h, p_mean, hard, 3000)
        return active_set(k, h, p_mean, hard, p, g)


def active_set(k, h, p_mean, hard, p, g):
    n = len(h)
    kappa = 1.0 / k[0, 0]
    seen = set()
    for it in range(500):
        y = p - kappa * g
        a0 = y <= 0
        ah = y >= hard
        f = ~(a0 | ah)
        if not f.any():
            # No free pixel: keep the nearest one to the middle free.
            j = np.argmin(np.abs(y - hard / 2))
            f[j] = True
            a0[j] = ah[j] = False
        key = (a0.tobytes(), ah.tobytes())
        if key in seen and it > 0:
            break
        seen.add(key)
        idx = np.flatnonzero(f)
        nf = len(idx)
        mat = np.zeros((nf + 1, nf + 1))
        mat[:nf, :nf] = k[np.ix_(idx, idx)]
        mat[:nf, nf] = -1.0
        mat[nf, :nf] = 1.0
        rhs = np.empty(nf + 1)
        rhs[:nf] = h[idx] - hard * k[np.ix_(idx, np.flatnonzero(ah))].sum(axis=1)
        rhs[nf] = n * p_mean - hard * ah.sum()
        sol = np.linalg.solve(mat, rhs)
        p = np.zeros(n)
        p[ah] = hard
        p[idx] = sol[:nf]
        c = sol[nf]
        g = k @ p - h - c
    hr = np.sqrt(np.mean(h ** 2))
    ok = (
        np.all(np.abs(g[f]) < 1e-10 * hr)
        and np.all(g[a0] >= -1e-10 * hr)
        and np.all(g[ah] <= 1e-10 * hr)
        and np.all((p[f] > 0) & (p[f] < hard))
    )
    assert ok, "KKT conditions not met"
    gap = np.where(p > 0, 0.0, np.maximum(g, 0.0))
    return {
        "pressure_Pa": p_mean,
        "area_fraction": float(np.mean(p > 0)),
        "plastic_fraction": float(np.mean(ah)),
        "mean_gap_m": float(gap.mean()),
        "plastic_volume_per_area_m": float(np.sum(-g[ah]) / n),
        "active_set_iterations": it,
        "kkt_margin_free_over_hrms": float(np.max(np.abs(g[f])) / hr) if f.any() else 0.0,
    }


def main():
    h = make_map()
    np.save("tests/data/bem_plastic_map32.npy", h)
    out = {"n": N, "pixel_size_m": DX, "contact_modulus_Pa": ESTAR,
           "hardness_Pa": HARD, "map": "tests/data/bem_plastic_map32.npy",
           "cases": []}
    for periodic in (True, False):
        k = compliance(periodic)
        z = heights(h, periodic)
        for f in (0.005, 0.02, 0.05, 0.08, 0.095):
            r = solve(k, z, f * ESTAR, HARD)
            r["periodic"] = periodic
            out["cases"].append(r)
    print(json.dumps(out, indent=1))


if __name__ == "__main__":
    main()
