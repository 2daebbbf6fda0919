#!/usr/bin/env python3
"""Independent reference values for src/electrical.

What: single-spot constriction resistances (Maxwell/Holm, Sharvin, Wexler with
the Mikrajuddin Gamma(K) fit; two metals; film), Greenwood-Williamson sums of
parallel spots over Gaussian summit heights (conductance and sum of squared
conductances, count), Greenwood's mean-field interaction term, explicit-spot
resistances (parallel, Greenwood 1966, exact equal-potential solve), c_sq and
Holm's phi-theta temperatures.

How (independent of the Rust code path):
- mpmath at 40 significant digits throughout.
- GW sums: direct tanh-sinh quadrature (mpmath.quad) of g(a(s)) phi(s) over
  s in [h, inf), with a = sqrt(R sigma (s - h)) and phi the standard normal
  density written out (no F_n closed forms, no substitution).
- c_sq = E[1/|X-Y|] in the unit square: the 1-D integral
  8 int_0^1 (1/2 - t/6)/sqrt(1 + t^2) dt (polar-like substitution v = u t of
  4 int int (1-u)(1-v)/sqrt(u^2+v^2)), checked against the closed form.
- Exact spots: mpmath.lu_solve of the full matrix at 40 digits.
- Formulas as in docs/physics.md ("Contact resistance"); two metals as
  in src/electrical/spot.rs's documented form.

Digits: every value is printed with 17 significant digits (repr of the
rounded double); the quadratures are converged far beyond 1e-15.

Run: python3 tests/data/electrical.py > tests/data/electrical.json
"""
import json
import random

import mpmath as mp

mp.mp.dps = 40

RHO = 2.44e-8   # gold, Ohm m
MFP = 3.46e-8   # gold, m
RHO2 = 1.68e-8  # copper, Ohm m
MFP2 = 3.9e-8   # copper, m
FILM = 1e-13    # Ohm m^2


def f(x):
    return float(mp.mpf(x))


def gamma_fit(k):
    return (1 + mp.mpf("0.83") * k) / (1 + mp.mpf("1.33") * k)


def wexler_side(rho, l, a):
    """One half-space of the two-metal form: 2 rho l/(3 pi a^2) + Gamma(l/a) rho/(4a)."""
    rho, l, a = mp.mpf(rho), mp.mpf(l), mp.mpf(a)
    return 2 * rho * l / (3 * mp.pi * a**2) + gamma_fit(l / a) * rho / (4 * a)


def spot_models():
    """Per-spot resistance functions R(a) (mp) by name."""
    rho, l, rho2, l2 = map(mp.mpf, (RHO, MFP, RHO2, MFP2))
    return {
        "maxwell": lambda a: rho / (2 * a),
        "sharvin": lambda a: 4 * rho * l / (3 * mp.pi * a**2),
        "wexler": lambda a: 4 * rho * l / (3 * mp.pi * a**2) + gamma_fit(l / a) * rho / (2 * a),
        "wexler_film": lambda a: 4 * rho * l / (3 * mp.pi * a**2)
        + gamma_fit(l / a) * rho / (2 * a)
        + mp.mpf(FILM) / (mp.pi * a**2),
        "maxwell_two_metals": lambda a: (rho + rho2) / (4 * a),
        "sharvin_two_metals": lambda a: 2 * (rho * l + rho2 * l2) / (3 * mp.pi * a**2),
        "wexler_two_metals": lambda a: wexler_side(RHO, MFP, a) + wexler_side(RHO2, MFP2, a),
    }


def mutual_rho(name):
    return (mp.mpf(RHO) + mp.mpf(RHO2)) / 2 if name.endswith("two_metals") else mp.mpf(RHO)


def c_sq():
    num = 8 * mp.quad(lambda t: (mp.mpf(1) / 2 - t / 6) / mp.sqrt(1 + t * t), [0, 1])
    closed = 4 * mp.log(1 + mp.sqrt(2)) - mp.mpf(4) / 3 * (mp.sqrt(2) - 1)
    assert abs(num - closed) < mp.mpf("1e-35")
    return num


def single_spots():
    models = spot_models()
    rows = []
    for a in [1e-9, 1e-8, 3.46e-8, 1e-7, 1e-6, 1e-4]:
        row = {"radius_m": a}
        for name, r in models.items():
            row[name] = f(r(mp.mpf(a)))
        rows.append(row)
    return rows


def phi(s):
    return mp.exp(-s * s / 2) / mp.sqrt(2 * mp.pi)


def gw_sums(csq):
    """N Hertz summits (radius R, Gaussian heights sigma) in a square A_n."""
    N, R, SIG, AN = 1e4, 1e-6, 5e-9, 1e-8
    n, rs, side = mp.mpf(N), mp.mpf(R) * mp.mpf(SIG), mp.sqrt(mp.mpf(AN))
    models = spot_models()
    rows = []
    for h in [-1.0, 0.0, 0.5, 1.0, 2.0, 3.0, 4.0]:
        hm = mp.mpf(h)
        pts = [hm, hm + mp.mpf("0.25"), hm + 1, hm + 3, hm + 8, mp.inf]
        count = n * mp.quad(phi, pts)
        row = {"h": h, "contacts": f(count)}
        for name, r in models.items():
            g = lambda s: 1 / r(mp.sqrt(rs * (s - hm))) if s > hm else mp.mpf(0)
            G = n * mp.quad(lambda s: g(s) * phi(s), pts)
            G2 = n * mp.quad(lambda s: g(s) ** 2 * phi(s), pts)
            rint = mutual_rho(name) * csq / (mp.pi * side) * (1 - G2 / G**2)
            row[name] = {
                "conductance_S": f(G),
                "conductance_sq_S2": f(G2),
                "parallel_ohm": f(1 / G),
                "greenwood_term_ohm": f(rint),
                "greenwood_total_ohm": f(1 / G + rint),
            }
        rows.append(row)
    return {"count": N, "summit_radius_m": R, "sigma_m": SIG, "nominal_area_m2": AN, "rows": rows}


def explicit(spots, name):
    """parallel, Greenwood 1966 (current weights G_i/sum G), exact solve."""
    r = spot_models()[name]
    k = mutual_rho(name) / mp.pi
    xs = [mp.mpf(s[0]) for s in spots]
    ys = [mp.mpf(s[1]) for s in spots]
    a = [mp.mpf(s[2]) for s in spots]
    n = len(spots)
    G = [1 / r(ai) for ai in a]
    tot = mp.fsum(G)
    dist = lambda i, j: mp.sqrt((xs[i] - xs[j]) ** 2 + (ys[i] - ys[j]) ** 2)
    mutual = mp.fsum(G[i] * G[j] * k / dist(i, j) for i in range(n) for j in range(n) if i != j)
    M = mp.matrix(n, n)
    for i in range(n):
        for j in range(n):
            M[i, j] = r(a[i]) if i == j else k / dist(i, j)
    I = mp.lu_solve(M, mp.matrix([1] * n))
    return {
        "parallel_ohm": f(1 / tot),
        "greenwood_ohm": f(1 / tot + mutual / tot**2),
        "exact_ohm": f(1 / mp.fsum(I)),
    }


def spot_sets():
    rng = random.Random(15)
    sets = []
    for n, side, amin, amax in [(8, 1e-4, 2e-7, 2e-6), (25, 2e-5, 1e-8, 2e-7)]:
        spots = [
            (rng.uniform(0, side), rng.uniform(0, side), rng.uniform(amin, amax))
            for _ in range(n)
        ]
        entry = {"spots": [list(s) for s in spots]}
        for name in ["maxwell", "wexler", "wexler_two_metals"]:
            entry[name] = explicit(spots, name)
        sets.append(entry)
    return sets


def heating():
    kb, e = mp.mpf("1.380649e-23"), mp.mpf("1.602176634e-19")
    L = mp.pi**2 * kb**2 / (3 * e**2)
    rows = []
    for t0 in [293.15, 77.0, 400.0]:
        for u in [0.0, 0.01, 0.08, 0.43, 1.0]:
            tmax = mp.sqrt(mp.mpf(t0) ** 2 + mp.mpf(u) ** 2 / (4 * L))
            rows.append({"bulk_K": t0, "voltage_V": u, "max_temperature_K": f(tmax)})
    return {"lorenz": f(L), "rows": rows}


def main():
    csq = c_sq()
    out = {
        "description": __doc__.strip().splitlines()[0],
        "source": "tests/data/electrical.py (mpmath, 40 digits)",
        "resistivity": RHO,
        "mean_free_path": MFP,
        "resistivity2": RHO2,
        "mean_free_path2": MFP2,
        "film_resistance": FILM,
        "c_sq": f(csq),
        "single_spot": single_spots(),
        "gw_gaussian_hertz": gw_sums(csq),
        "explicit_spots": spot_sets(),
        "heating": heating(),
    }
    print(json.dumps(out, indent=1))


if __name__ == "__main__":
    main()
