#!/usr/bin/env python3
"""Numpy peers of the two GW curves of the curve benchmark, side by side with asperity.

Same work as `cargo run --release --example gw_peer_curves -- CASE RTOL`
(which this script runs, once per tolerance), both answers checked against
one reference:

- resistance: 10^4 Hertz summits (R = 1 um, E* = 48 GPa), Gaussian heights
  (sigma = 5 nm), (100 um)^2, gold Wexler spots (rho = 2.44e-8 Ohm m,
  l = 3.46e-8 m) with Greenwood's mean-field term; 1000 approach
  separations from -sigma to 4 sigma; load, count, sum G, sum G^2 and R.
- kogut-etsion: the gold surface (E* = 47.96 GPa, Y = 0.4 GPa, H = 2.8 Y,
  nu = 0.42, psi = 3.03) with Kogut & Etsion (2002) summits; the 1000
  approach separations of LoadingProgram(6 sigma, -3 sigma, 1000);
  load, area, count.

The numpy rule is what a numpy user would write: t = sqrt(s - d/sigma)
(the contact onset's square root gone), Gauss-Legendre with n nodes on
each piece (Kogut-Etsion: split at w = 1, 6, 110, so no piece holds a
jump), vectorised over all states at once. For each tolerance the
smallest n (of 4, 6, 8, ..., 64) whose worst error is at most asperity's
is used: numpy is given at least asperity's accuracy.

Reference: the same rule with 256 nodes per piece (resistance: 4 equal
pieces), itself checked against mpmath (tanh-sinh, 30 digits) at 5
states of each curve; the script stops if they differ by more than 1e-13.

Errors: the largest relative error over the 1000 states and over the
outputs. CPU time: time.process_time() around REPEATS curves (numpy), the
example's /proc/self/stat utime + stime around rust_repeats(rtol) curves
(asperity, 1 rayon thread).

Run from the repository root:
    cargo build --release --example gw_peer_curves
    python3 benches/peers/gw_curves_numpy.py [RTOL ...]   (default 1e-6 1e-3)
(needs numpy and mpmath).
"""
import json
import math
import os
import subprocess
import sys
import time

import numpy as np

REPEATS = 20
# Enough curves for ~30 clock ticks (10 ms each) of asperity's CPU time:
# the interpolated curves take well under 0.1 ms at loose tolerances.
RUST_REPEATS = {True: 5000, False: 200}


def rust_repeats(rtol):
    return RUST_REPEATS[rtol >= 1e-7]
EXE = os.environ.get("GW_PEER_EXE", os.path.join("target", "release", "examples", "gw_peer_curves"))
NODE_CHOICES = [4, 6, 8, 10, 12, 16, 20, 24, 32, 40, 48, 64]

# Shared geometry: Gaussian heights, standard normal density.
SIGMA = 5e-9
R = 1e-6
N_SUMMITS = 1e12 * 1e-8
INV_SQRT_2PI = 1.0 / math.sqrt(2.0 * math.pi)


def span(h):
    """Length in s beyond the onset h where phi has fallen by e^-40.5."""
    hp = np.maximum(h, 0.0)
    return np.sqrt(hp * hp + 81.0) - hp + np.maximum(-h, 0.0)


def gl(n):
    x, w = np.polynomial.legendre.leggauss(n)
    return 0.5 * (x + 1.0), 0.5 * w  # on [0, 1]


# ---------------------------------------------------------------- resistance
E_HERTZ = 48e9
RHO = 2.44e-8
MFP = 3.46e-8
SIDE = 1e-4
C_SQ = 4.0 * math.log(1.0 + math.sqrt(2.0)) - 4.0 / 3.0 * (math.sqrt(2.0) - 1.0)


def res_separations():
    return (-1.0 + 5.0 * np.arange(1000) / 999.0) * SIGMA


def res_sums(h, n, pieces=1):
    """count, load, sum G, sum G^2 at onsets h (array), n nodes per piece."""
    x, w = gl(n)
    t_top = np.sqrt(span(h))[:, None]
    out = np.zeros((4, h.size))
    for p in range(pieces):
        t = t_top * ((p + x[None, :]) / pieces)
        wt = (t_top / pieces) * w[None, :]
        s = h[:, None] + t * t
        pdf = INV_SQRT_2PI * np.exp(-0.5 * s * s)
        weight = 2.0 * t * pdf * wt
        delta = SIGMA * t * t
        a = math.sqrt(R * SIGMA) * t
        knudsen = MFP / a
        gamma = (1.0 + 0.83 * knudsen) / (1.0 + 1.33 * knudsen)
        res = 4.0 * RHO * MFP / (3.0 * math.pi * a * a) + gamma * RHO / (2.0 * a)
        g = 1.0 / res
        load = 4.0 / 3.0 * E_HERTZ * math.sqrt(R) * delta * np.sqrt(delta)
        out[0] += weight.sum(axis=1)
        out[1] += (weight * load).sum(axis=1)
        out[2] += (weight * g).sum(axis=1)
        out[3] += (weight * g * g).sum(axis=1)
    return N_SUMMITS * out


def res_outputs(sums):
    count, load, g, g2 = sums
    parallel = 1.0 / g
    inter = RHO * C_SQ / (math.pi * SIDE) * np.maximum(1.0 - g2 / (g * g), 0.0)
    resistance = parallel + np.where(count >= 2.0, inter, 0.0)
    return {"count": count, "load": load, "g": g, "g2": g2, "resistance": resistance}


def res_curve(n):
    return res_outputs(res_sums(res_separations() / SIGMA, n))


def res_mp(h):
    import mpmath as mp

    mp.mp.dps = 30
    T = mp.sqrt(mp.mpf(float(span(np.array([h]))[0])))
    h = mp.mpf(h)
    sig, r = mp.mpf(SIGMA), mp.mpf(R)

    def f(t, k):
        s = h + t * t
        wgt = 2 * t * mp.exp(-s * s / 2) / mp.sqrt(2 * mp.pi)
        if k == 0:
            return wgt
        delta = sig * t * t
        if k == 1:
            return wgt * mp.mpf(4) / 3 * mp.mpf(E_HERTZ) * mp.sqrt(r) * delta**1.5
        if t == 0:
            return mp.mpf(0)
        a = mp.sqrt(r * sig) * t
        kn = mp.mpf(MFP) / a
        gam = (1 + mp.mpf("0.83") * kn) / (1 + mp.mpf("1.33") * kn)
        res = 4 * mp.mpf(RHO) * mp.mpf(MFP) / (3 * mp.pi * a * a) + gam * mp.mpf(RHO) / (2 * a)
        return wgt / res if k == 2 else wgt / (res * res)

    return [float(N_SUMMITS * mp.quad(lambda t: f(t, k), [0, T / 4, T / 2, T])) for k in range(4)]


# -------------------------------------------------------------- kogut-etsion
E_KE = 4.796e10
Y = 0.4e9
H_KE = 2.8 * Y
NU = 0.42
K_KE = 0.454 + 0.41 * NU
OMEGA_C = (math.pi * K_KE * H_KE / (2.0 * E_KE)) ** 2 * R
P_C = 2.0 / 3.0 * math.pi * K_KE * H_KE * R * OMEGA_C
A_C = math.pi * R * OMEGA_C
# (multiple of omega_c at the piece's top, load coefficient/exponent, area coefficient/exponent)
KE_PIECES = [
    (1.0, 1.0, 1.5, 1.0, 1.0),
    (6.0, 1.03, 1.425, 0.93, 1.136),
    (110.0, 1.40, 1.263, 0.94, 1.146),
    (math.inf, None, None, None, None),  # fully plastic: P = (3/K) w P_c, A = 2 w A_c
]


def ke_separations():
    # LoadingProgram::new(6 sigma, -3 sigma, 1000).separations(), ascending
    start, closest = 6.0 * SIGMA, -3.0 * SIGMA
    return np.array([closest + (start - closest) * i / 999.0 for i in range(1000)])


def ke_sums(h, n):
    """load, area, count at onsets h, n nodes on each of the 4 pieces (in t)."""
    x, w = gl(n)
    t_top = np.sqrt(span(h))
    out = np.zeros((3, h.size))
    lo = np.zeros_like(h)
    for top, cp, ep, ca, ea in KE_PIECES:
        hi = np.minimum(math.sqrt(top * OMEGA_C / SIGMA), t_top)
        width = np.maximum(hi - lo, 0.0)[:, None]
        t = lo[:, None] + width * x[None, :]
        s = h[:, None] + t * t
        weight = 2.0 * t * INV_SQRT_2PI * np.exp(-0.5 * s * s) * width * w[None, :]
        wr = SIGMA * t * t / OMEGA_C
        if cp is None:
            load = (3.0 / K_KE) * wr * P_C
            area = 2.0 * wr * A_C
        elif ep == 1.5:
            load = P_C * wr * np.sqrt(wr)
            area = A_C * wr
        else:
            lw = np.log(wr)
            load = cp * P_C * np.exp(ep * lw)
            area = ca * A_C * np.exp(ea * lw)
        out[0] += (weight * load).sum(axis=1)
        out[1] += (weight * area).sum(axis=1)
        out[2] += weight.sum(axis=1)
        lo = hi
    return N_SUMMITS * out


def ke_curve(n):
    load, area, count = ke_sums(ke_separations() / SIGMA, n)
    return {"load": load, "area": area, "count": count}


def ke_mp(h):
    import mpmath as mp

    mp.mp.dps = 30
    T = mp.sqrt(mp.mpf(float(span(np.array([h]))[0])))
    h = mp.mpf(h)
    oc = mp.mpf(OMEGA_C)
    cuts = [mp.mpf(0)] + [
        mp.sqrt(m * oc / mp.mpf(SIGMA)) for m in (1, 6, 110) if mp.sqrt(m * oc / mp.mpf(SIGMA)) < T
    ] + [T]

    def f(t, k):
        s = h + t * t
        wgt = 2 * t * mp.exp(-s * s / 2) / mp.sqrt(2 * mp.pi)
        if k == 2:
            return wgt
        w = mp.mpf(SIGMA) * t * t / oc
        if w <= 1:
            p, a = w**1.5, w
        elif w <= 6:
            p, a = mp.mpf("1.03") * w ** mp.mpf("1.425"), mp.mpf("0.93") * w ** mp.mpf("1.136")
        elif w <= 110:
            p, a = mp.mpf("1.40") * w ** mp.mpf("1.263"), mp.mpf("0.94") * w ** mp.mpf("1.146")
        else:
            p, a = 3 / mp.mpf(K_KE) * w, 2 * w
        return wgt * (p * mp.mpf(P_C) if k == 0 else a * mp.mpf(A_C))

    return [float(N_SUMMITS * mp.quad(lambda t: f(t, k), cuts)) for k in range(3)]


# ------------------------------------------------------------------- driver
def worst(values, ref, keys):
    e = 0.0
    for k in keys:
        v, r = np.asarray(values[k]), np.asarray(ref[k])
        ok = r != 0.0
        e = max(e, float(np.max(np.abs(v[ok] / r[ok] - 1.0))))
    return e


def cpu(f, repeats):
    f()
    t0 = time.process_time()
    for _ in range(repeats):
        f()
    return (time.process_time() - t0) / repeats


CASES = {
    "resistance": {
        "curve": res_curve,
        "reference": lambda: res_outputs(res_sums(res_separations() / SIGMA, 256, pieces=4)),
        "mp": res_mp,
        "mp_keys": ["count", "load", "g", "g2"],
        "keys": ["count", "load", "g", "g2", "resistance"],
        "h": lambda: res_separations() / SIGMA,
    },
    "kogut-etsion": {
        "curve": ke_curve,
        "reference": lambda: dict(zip(["load", "area", "count"], ke_sums(ke_separations() / SIGMA, 256))),
        "mp": ke_mp,
        "mp_keys": ["load", "area", "count"],
        "keys": ["load", "area", "count"],
        "h": lambda: ke_separations() / SIGMA,
    },
}


def main():
    rtols = [float(a) for a in sys.argv[1:]] or [1e-6, 1e-3]
    rows = []
    for name, c in CASES.items():
        ref = c["reference"]()
        h = c["h"]()
        for i in (0, 250, 500, 750, 999):
            mp = c["mp"](float(h[i]))
            for k, m in zip(c["mp_keys"], mp):
                dev = abs(ref[k][i] / m - 1.0)
                if dev > 1e-13:
                    sys.exit(f"{name}: reference {k} at state {i} is off mpmath by {dev:.1e}")
        for rtol in rtols:
            out = subprocess.run(
                [EXE, name, repr(rtol), str(rust_repeats(rtol))], check=True, capture_output=True, text=True
            ).stdout
            rust = json.loads(out)
            if not np.allclose(rust["d"], h * SIGMA, rtol=0, atol=1e-22):
                sys.exit(f"{name}: separations differ")
            rust_err = worst(rust, ref, c["keys"])
            for n in NODE_CHOICES:
                np_err = worst(c["curve"](n), ref, c["keys"])
                if np_err <= rust_err:
                    break
            np_cpu = cpu(lambda: c["curve"](n), REPEATS)
            rows.append((name, rtol, rust["cpu_s"], rust_err, rust["evaluations"] / 1000, n, np_cpu, np_err))
    cpu_model = "?"
    with open("/proc/cpuinfo") as f:
        for line in f:
            if line.startswith("model name"):
                cpu_model = line.split(":", 1)[1].strip()
                break
    print(f"CPU: {cpu_model}; numpy {np.__version__}; CPU time per 1000-point curve, one thread")
    print("| curve | rtol | asperity | error | evaluations/state | numpy nodes/piece | numpy | error | numpy/asperity |")
    print("|---|---|---|---|---|---|---|---|---|")
    for name, rtol, rc, re, ev, n, nc, ne in rows:
        print(
            f"| {name} | {rtol:.0e} | {rc * 1e3:.3f} ms | {re:.1e} | {ev:.0f} | {n} | {nc * 1e3:.3f} ms | {ne:.1e} | {nc / rc:.2f}x |"
        )


if __name__ == "__main__":
    main()
