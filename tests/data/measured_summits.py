#!/usr/bin/env python3
"""The example measured map and an independent direct sum over its summits.

What: (1) writes examples/data/measured-topography.npy, a 160 x 160 float64
height map (m): Gaussian-smoothed white noise (FFT filter exp(-(k l)^2/4),
correlation length l = 2 pixels), scaled to 5 nm RMS, plus a 3 nm tilt,
seed 20261123; pixel size 50 nm (the example scene's `pixel_size`).
(2) writes tests/data/measured_summits.json: the totals of the scene
`examples/scenes/measured-topography.toml` with `summits = "measured"`
computed by a direct numpy sum over the summits, for Hertz (w = 0) and DMT
(w = 0.5 J/m^2) at several separations.

How (independent of the Rust code path): mean plane by numpy.linalg.lstsq on
[1, x, y]; summits = interior pixels strictly higher than their 8 neighbours
(8 shifted whole-array comparisons); curvature kappa = -(5-point Laplacian)/2,
radius R_i = 1/kappa_i; heights from the mean summit height; contact modulus
E* = 1/((1-nu1^2)/E1 + (1-nu2^2)/E2); per summit delta_i = z_i - d,
Hertz P = (4/3) E* sqrt(R_i) delta^1.5, area pi R_i delta, count 1 for
delta > 0; DMT P = (4/3) E* sqrt(R_i) delta^1.5 - 2 pi w R_i for delta >= 0
(free otherwise); totals times f = A_n / ((rows-2)(cols-2) dx^2) with the
default A_n = rows cols dx^2. Sums with math.fsum (exactly rounded), so the
Rust block sums must agree to rounding (the test asserts 1e-12 relative,
against sum |terms| for the DMT load whose terms cancel).

Run: python tests/data/measured_summits.py (from the repository root;
numpy only).
"""
import json
import math
import os

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
MAP = os.path.join(ROOT, "examples", "data", "measured-topography.npy")
OUT = os.path.join(ROOT, "tests", "data", "measured_summits.json")
DX = 50e-9
E1 = E2 = 79e9
NU1 = NU2 = 0.42
W_DMT = 0.5


def make_map():
    rng = np.random.default_rng(20261123)
    n = 160
    noise = rng.standard_normal((n, n))
    k = 2 * np.pi * np.sqrt(np.fft.fftfreq(n)[:, None] ** 2 + np.fft.fftfreq(n)[None, :] ** 2)
    z = np.real(np.fft.ifft2(np.fft.fft2(noise) * np.exp(-(k * 2.0) ** 2 / 4)))
    z *= 5e-9 / z.std()
    y, x = np.mgrid[0:n, 0:n]
    z += 3e-9 * (x / n) - 1e-9 * (y / n)
    np.save(MAP, z.astype(np.float64))


def summits(z):
    rows, cols = z.shape
    y, x = np.mgrid[0:rows, 0:cols]
    a = np.column_stack([np.ones(z.size), (x * DX).ravel(), (y * DX).ravel()])
    coef, *_ = np.linalg.lstsq(a, z.ravel(), rcond=None)
    r = z - (a @ coef).reshape(z.shape)
    c = r[1:-1, 1:-1]
    peak = np.ones_like(c, dtype=bool)
    for di in (-1, 0, 1):
        for dj in (-1, 0, 1):
            if di or dj:
                peak &= c > r[1 + di:rows - 1 + di, 1 + dj:cols - 1 + dj]
    lap = r[:-2, 1:-1] + r[2:, 1:-1] + r[1:-1, :-2] + r[1:-1, 2:] - 4 * c
    h = c[peak]
    kappa = -lap[peak] / (2 * DX * DX)
    return h, kappa, rows, cols


def main():
    make_map()
    z = np.load(MAP)
    h, kappa, rows, cols = summits(z)
    radius = 1.0 / kappa
    heights = h - math.fsum(h) / len(h)
    estar = 1.0 / ((1 - NU1 ** 2) / E1 + (1 - NU2 ** 2) / E2)
    f = (rows * cols) / ((rows - 2) * (cols - 2))
    seps = [3e-9, 1e-9, 0.0, -2e-9]
    cases = []
    for d in seps:
        delta = heights - d
        on = delta > 0
        hertz = 4 / 3 * estar * np.sqrt(radius[on]) * delta[on] ** 1.5
        touch = delta >= 0
        dmt = 4 / 3 * estar * np.sqrt(radius[touch]) * delta[touch] ** 1.5 - 2 * np.pi * W_DMT * radius[touch]
        cases.append({
            "separation_m": d,
            "hertz_load_N": f * math.fsum(hertz),
            "area_m2": f * math.fsum(np.pi * radius[on] * delta[on]),
            "count": f * int(on.sum()),
            "dmt_load_N": f * math.fsum(dmt),
            "dmt_abs_sum_N": f * math.fsum(np.abs(dmt)),
        })
    json.dump({
        "provenance": "tests/data/measured_summits.py (numpy direct sums, math.fsum)",
        "map": "examples/data/measured-topography.npy",
        "pixel_size_m": DX,
        "summit_count": int(len(h)),
        "mean_summit_height_m": math.fsum(h) / len(h),
        "contact_modulus_Pa": estar,
        "factor": f,
        "cases": cases,
    }, open(OUT, "w"), indent=1)
    print(len(h), "summits", cases)


if __name__ == "__main__":
    main()
