#!/usr/bin/env python3
"""Independent reference for adhesion with an elastic-perfectly-plastic cap.

What: on the periodic 32 x 32 map of bem_plastic_reference.py
(bem_plastic_map32.npy; E* = 1e9 Pa, pixels of 1 um, hardness H = 0.1 E*),
the equilibrium of a rigid rough surface against an elastic half-space with
the exponential interaction -w exp(-g/rho) where the gap is open and the
compressive contact pressure capped at H (plastic interpenetration g < 0).

Formulation (docs/physics.md, written from it, not from the Rust code): the
signed gap g = a - b with a, b >= 0 (a the open gap, b the plastic
interpenetration), u = g + h, and under load control (mean pressure P) the
potential per pixel area
    Pi(a, b) = (1/2) u.K^-1 u + sum [-w exp(-a/rho) + H b] + P sum g,
K^-1 the periodic stiffness (Westergaard kernel E*|q|/2, q = 0 term 0). Its
stationarity is K^-1 u + phi'(g) + P = 0 where g != 0 (phi' = (w/rho)
exp(-g/rho) for g > 0, -H for g < 0) and -w/rho <= p <= H where g = 0, with
the pressure p = K^-1 u + P: the conditions the Rust gap solver meets at
mean pressure P. With H > w/rho no minimiser has a > 0 and b > 0 at one
pixel (lowering both lowers Pi), so g = a - b is the signed gap.

The adhesion, w = 0.2 J/m^2 and rho = 50 nm, keeps the potential convex
(the largest curvature of the interaction, w/rho^2 = 8e13 Pa/m, is below the
smallest stiffness of the map's modes, E* pi/L = 9.8e13 Pa/m), so the
equilibrium at each load is unique: a shorter range (w/rho^2 above the
stiffness) has several equilibria at one load, which two solvers need not
pick alike.

How: L-BFGS-B (scipy) on Pi in units of h_rms and E* h_rms/dx from the
rigid start, then Newton's method on the stationarity with the sets
(open g > 0, contact g = 0, plastic g < 0) fixed, sets updated from the
violations until they repeat, and the Karush-Kuhn-Tucker conditions checked
(the stationarity on open and plastic pixels to 1e-10 of E* g_rms/2, g of the
sign of its set, -w/rho <= p <= H on contact pixels). Outputs per load: the
area fraction (g <= 0), the plastic fraction (g < 0), the mean clipped gap
(mean max(g, 0)), the mean signed gap and the displaced volume per area
(mean max(-g, 0)).

Run: python3 tests/data/bem_plastic_adhesion_reference.py > tests/data/bem_plastic_adhesion_reference.json
"""
import json
import os

import numpy as np
from scipy.optimize import minimize

HERE = os.path.dirname(os.path.abspath(__file__))
N = 32
DX = 1e-6
ESTAR = 1e9
HARD = 0.1 * ESTAR
W = 0.2
RHO = 5e-8


def stiffness():
    n = N * N
    q = 2 * np.pi * np.fft.fftfreq(N, d=DX)
    qx, qy = np.meshgrid(q, q)
    kern = 0.5 * ESTAR * np.hypot(qx, qy)
    k = np.empty((n, n))
    for j in range(n):
        e = np.zeros(n)
        e[j] = 1.0
        k[:, j] = np.real(np.fft.ifft2(np.fft.fft2(e.reshape(N, N)) * kern)).ravel()
    return k


def dphi(g, w, rho):
    return np.where(g > 0, w / rho * np.exp(-np.maximum(g, 0) / rho), np.where(g < 0, -HARD, 0.0))


def lbfgs(kinv, h, p_mean, w, rho):
    n = len(h)
    s = np.sqrt(np.mean(h ** 2))
    p0 = ESTAR * s / DX
    scale = p0 * s

    def f(x):
        a, b = x[:n] * s, x[n:] * s
        u = a - b + h
        ku = kinv @ u
        e = 0.5 * u @ ku + np.sum(-w * np.exp(-a / rho) + HARD * b) + p_mean * np.sum(a - b)
        ga = ku + w / rho * np.exp(-a / rho) + p_mean
        gb = -ku + HARD - p_mean
        return e / scale, np.concatenate([ga, gb]) * s / scale

    c = 0.0
    g0 = np.maximum(c - h, 0.0) + s
    x0 = np.concatenate([g0 / s, np.zeros(n)])
    r = minimize(f, x0, jac=True, method="L-BFGS-B", bounds=[(0, None)] * (2 * n),
                 options={"maxiter": 200000, "maxfun": 400000, "ftol": 1e-16, "gtol": 1e-12,
                          "maxcor": 50})
    return (r.x[:n] - r.x[n:]) * s


def newton(kinv, h, p_mean, w, rho, g):
    n = len(h)
    s = np.sqrt(np.mean(h ** 2))
    p_ref = 0.5 * np.sqrt(np.mean((kinv @ h) ** 2)) * 2  # rms(K^-1 h)
    tol_g = 1e-3 * s
    opn = g > tol_g
    pla = g < -tol_g
    seen = set()
    for it in range(200):
        key = (opn.tobytes(), pla.tobytes())
        if key in seen:
            break
        seen.add(key)
        con = ~(opn | pla)
        gg = np.where(con, 0.0, g)
        for _ in range(100):
            u = gg + h
            res = kinv @ u + dphi(gg, w, rho) + p_mean
            res = np.where(con, 0.0, res)
            if np.max(np.abs(res)) < 1e-13 * p_ref:
                break
            fr = np.flatnonzero(~con)
            jac = kinv[np.ix_(fr, fr)].copy()
            jac[np.diag_indices(len(fr))] += np.where(
                gg[fr] > 0, -w / rho ** 2 * np.exp(-np.maximum(gg[fr], 0) / rho), 0.0)
            gg[fr] -= np.linalg.solve(jac, res[fr])
        g = gg
        p = kinv @ (g + h) + p_mean
        new_opn = (opn & (g > 0)) | (con & (p < -w / rho))
        new_pla = (pla & (g < 0)) | (con & (p > HARD))
        opn, pla = new_opn, new_pla
    con = ~(opn | pla)
    p = kinv @ (g + h) + p_mean
    res = np.where(con, 0.0, kinv @ (g + h) + dphi(g, w, rho) + p_mean)
    ok = (np.max(np.abs(res)) < 1e-10 * p_ref and np.all(g[opn] > 0) and np.all(g[pla] < 0)
          and np.all(g[con] == 0)
          and np.all(p[con] >= -w / rho * (1 + 1e-12)) and np.all(p[con] <= HARD * (1 + 1e-12)))
    assert ok, "KKT conditions not met"
    return g, it, float(np.max(np.abs(res)) / p_ref)


def main():
    h = np.load(os.path.join(HERE, "bem_plastic_map32.npy")).ravel()
    h = h - h.mean()
    kinv = stiffness()
    out = {"n": N, "pixel_size_m": DX, "contact_modulus_Pa": ESTAR, "hardness_Pa": HARD,
           "adhesion_energy_J_m2": W, "adhesion_range_m": RHO,
           "map": "tests/data/bem_plastic_map32.npy", "periodic": True, "cases": []}
    for f in (0.01, 0.03, 0.06, 0.09):
        p_mean = f * ESTAR
        for w in (W, 0.0):
            g = lbfgs(kinv, h, p_mean, w, RHO)
            g, it, margin = newton(kinv, h, p_mean, w, RHO, g)
            out["cases"].append({
                "pressure_Pa": p_mean,
                "adhesion_energy_J_m2": w,
                "area_fraction": float(np.mean(g <= 0)),
                "plastic_fraction": float(np.mean(g < 0)),
                "mean_gap_m": float(np.mean(np.maximum(g, 0))),
                "mean_signed_gap_m": float(np.mean(g)),
                "plastic_volume_per_area_m": float(np.mean(np.maximum(-g, 0))),
                "active_set_iterations": it,
                "kkt_residual_over_p_ref": margin,
            })
    print(json.dumps(out, indent=1))


if __name__ == "__main__":
    main()
