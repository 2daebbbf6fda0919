#!/usr/bin/env python3
"""Independent JKR reference values for axisymmetric profiles (mpmath, 30 digits).

What: for each profile, the Sneddon/Barthel integrals (Barthel 2008;
calK = E*/2)
    delta_0(a) = a int_0^a f'(r) dr / sqrt(a^2 - r^2)
    F_0(a)     = 2 E* int_0^a r^2 f'(r) dr / sqrt(a^2 - r^2)
    delta(a)   = delta_0(a) - sqrt(2 pi w a / E*)
    F(a)       = F_0(a) - sqrt(8 pi E* w a^3)
How: mp.quad (tanh-sinh) in the angle u, r = a sin u (no end-point singularity:
    delta_0(a) = a int_0^(pi/2) f'(a sin u) du,  F_0/(2E*) = a^2 int_0^(pi/2) sin^2 u f'(a sin u) du),
split at u_i = asin(r_i/a) between the table's nodes for the tabulated profile, where
the PCHIP derivative is a quadratic on each piece; no closed form is used. (An earlier
version integrated in r with the 1/sqrt(a^2 - r^2) weight and crashed in mpmath with a
ZeroDivisionError at the end point r = a on the tabulated case.) The
load-controlled pull-off is the largest a where dF/da = 0 (F' by mp.diff),
the displacement-controlled jump-out the largest a where d delta/da = 0, both
located by a log scan and refined by mp.findroot (anderson, bracketed). The
flat punch (no integral) is Kendall's closed form at 30 digits.
The tabulated profile (a rounded cone sqrt(r^2 + rho^2) - rho sampled at 41
uniform nodes; the analytic rounded cone is the case rounded_cone_analytic, which
the Rust tests compare with the table at the interpolation error, not at 1e-10) is interpolated by scipy's PchipInterpolator; its piecewise
cubic coefficients are evaluated in mpmath.
Digits: values are written as float64 (17 significant digits); the quadrature
agrees with itself at a higher tolerance to ~25 digits.
Writes axisym.json next to this script.
"""
import json
import os

import numpy as np
from mpmath import mp, mpf, sqrt, pi, quad, diff, findroot, asin, sin

from scipy.interpolate import PchipInterpolator

mp.dps = 30


def pchip_derivative(r_nodes, f_nodes):
    p = PchipInterpolator(np.array(r_nodes), np.array(f_nodes))
    c = p.c  # c[m, i]: coefficient of (x - x_i)^(3-m)
    xs = [mpf(x) for x in p.x]
    coef = [[mpf(float(c[m, i])) for m in range(4)] for i in range(len(xs) - 1)]

    def fp(r):
        r = mpf(r)
        i = 0
        while i < len(xs) - 2 and r >= xs[i + 1]:
            i += 1
        t = r - xs[i]
        c3, c2, c1, _ = coef[i]
        return 3 * c3 * t * t + 2 * c2 * t + c1

    return fp, xs


def make(case):
    kind = case["profile"]
    p = case["params"]
    breaks = []
    if kind == "paraboloid":
        R = mpf(p["radius"])
        fp = lambda r: r / R
    elif kind == "sphere":
        R = mpf(p["radius"])
        fp = lambda r: r / sqrt(R * R - r * r)
    elif kind == "cone":
        t = mpf(p["tan_angle"])
        fp = lambda r: t
    elif kind == "power":
        A, n = mpf(p["coefficient"]), mpf(p["exponent"])
        fp = lambda r: A * n * r ** (n - 1)
    elif kind == "rounded_cone":
        rho = mpf(p["rho"])
        fp = lambda r: r / sqrt(r * r + rho * rho)
    elif kind == "tabulated":
        fp, xs = pchip_derivative(p["r"], p["f"])
        breaks = xs
    else:
        raise ValueError(kind)
    return fp, breaks


def integrals(fp, breaks, a):
    a = mpf(a)
    pts = [mpf(0)] + [asin(b / a) for b in breaks if 0 < b < a] + [pi / 2]
    d0 = a * quad(lambda u: fp(a * sin(u)), pts)
    i0 = a * a * quad(lambda u: sin(u) ** 2 * fp(a * sin(u)), pts)
    return d0, i0


def jkr_case(case):
    E, w = mpf(case["estar"]), mpf(case["w"])
    fp, breaks = make(case)

    def delta(a):
        return integrals(fp, breaks, a)[0] - sqrt(2 * pi * w * a / E)

    def load(a):
        return 2 * E * integrals(fp, breaks, a)[1] - sqrt(8 * pi * E * w * a ** 3)

    lo, hi = mpf(case["scan"][0]), mpf(case["scan"][1])

    def critical(g):
        n = 60
        grid = [lo * (hi / lo) ** (mpf(i) / n) for i in range(n + 1)]
        vals = [diff(g, x) for x in grid]
        for i in range(n, 0, -1):
            if vals[i - 1] < 0 <= vals[i]:
                a = findroot(lambda x: diff(g, x), (grid[i - 1], grid[i]), solver="anderson")
                return a
        raise RuntimeError("no instability in scan range " + case["name"])

    out = {}
    for key, g in [("pull_off_load_control", load), ("jump_out_displacement_control", delta)]:
        a = critical(g)
        out[key] = {"radius_m": float(a), "load_N": float(load(a)), "interference_m": float(delta(a))}
    a_po = mpf(out["pull_off_load_control"]["radius_m"])
    curve = []
    for frac in case["fractions"]:
        a = a_po * mpf(frac)
        d0, i0 = integrals(fp, breaks, a)
        curve.append({
            "radius_m": float(a),
            "interference_m": float(d0 - sqrt(2 * pi * w * a / E)),
            "load_N": float(2 * E * i0 - sqrt(8 * pi * E * w * a ** 3)),
            "delta0_m": float(d0),
            "load0_N": float(2 * E * i0),
        })
    out["curve"] = curve
    return out


def flat_case(case):
    E, w, a0 = mpf(case["estar"]), mpf(case["w"]), mpf(case["params"]["radius"])
    p = {"radius_m": float(a0), "load_N": float(-sqrt(8 * pi * E * w * a0 ** 3)),
         "interference_m": float(-sqrt(2 * pi * w * a0 / E))}
    return {"pull_off_load_control": p, "jump_out_displacement_control": p, "curve": []}


def main():
    rho = 5e-8
    r_tab = [i * 10 * rho / 40 for i in range(41)]
    f_tab = [float(sqrt(mpf(r) ** 2 + mpf(rho) ** 2) - mpf(rho)) for r in r_tab]
    fr = [0.3, 0.7, 1.0, 1.5, 3.0]
    cases = [
        {"name": "paraboloid", "profile": "paraboloid", "params": {"radius": 1e-6},
         "estar": 1e9, "w": 0.05, "scan": [1e-10, 1e-6], "fractions": fr},
        {"name": "sphere_small", "profile": "sphere", "params": {"radius": 1e-6},
         "estar": 1e9, "w": 0.05, "scan": [1e-10, 0.999e-6], "fractions": fr},
        {"name": "sphere_large", "profile": "sphere", "params": {"radius": 1e-8},
         "estar": 1e8, "w": 0.5, "scan": [1e-12, 0.99999e-8], "fractions": [0.3, 0.7, 1.0, 1.1]},
        {"name": "cone", "profile": "cone", "params": {"tan_angle": 0.2},
         "estar": 1e9, "w": 0.05, "scan": [1e-12, 1e-5], "fractions": fr},
        {"name": "power_1_5", "profile": "power", "params": {"coefficient": 316.0, "exponent": 1.5},
         "estar": 1e9, "w": 0.05, "scan": [1e-12, 1e-5], "fractions": fr},
        {"name": "power_3", "profile": "power", "params": {"coefficient": 1e13, "exponent": 3.0},
         "estar": 1e9, "w": 0.05, "scan": [1e-12, 1e-5], "fractions": fr},
        {"name": "tabulated", "profile": "tabulated", "params": {"r": r_tab, "f": f_tab},
         "estar": 1e8, "w": 1.0, "scan": [1e-10, 5e-7], "fractions": fr},
        {"name": "rounded_cone_analytic", "profile": "rounded_cone", "params": {"rho": rho},
         "estar": 1e8, "w": 1.0, "scan": [1e-10, 5e-7], "fractions": fr},
        {"name": "flat", "profile": "flat", "params": {"radius": 1e-6},
         "estar": 1e9, "w": 0.05},
    ]
    for c in cases:
        c.update(flat_case(c) if c["profile"] == "flat" else jkr_case(c))
        print(c["name"], c["pull_off_load_control"], c["jump_out_displacement_control"])
    doc = {
        "what": "JKR for axisymmetric profiles: delta(a), F(a), pull-off, jump-out",
        "how": "mpmath 30-digit tanh-sinh quadrature of Sneddon's integrals in the angle u (r = a sin u, split at the table's nodes); "
               "extrema by mp.diff + findroot; scipy PchipInterpolator for the table",
        "digits": "float64 (17 significant); independent of the Rust closed forms",
        "cases": cases,
    }
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "axisym.json")
    with open(path, "w") as fh:
        json.dump(doc, fh, indent=1)


if __name__ == "__main__":
    main()
