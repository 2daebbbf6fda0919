#!/usr/bin/env python3
"""Independent Maugis-Dugdale reference values (mpmath, 40 digits).

Parametrised by the contact radius A (the Rust code uses the angle
t = atan(sqrt(m^2-1))): for each A, eq (1) of physics.md is solved for
m = c/a by a bracketing root finder, then Pbar(A), Dbar(A) follow from
(2)-(3). Extrema use mpmath numerical derivatives (mp.diff) and
mp.findroot. Writes maugis_pull_off.json next to this script.

  (lambda A^2/2)[s + (m^2-2) t] + (4 lambda^2 A/3)[s t - m + 1] = 1
  Pbar = A^3 - lambda A^2 [s + m^2 t],  Dbar = A^2 - (4/3) A lambda s

Non-contact branch (a = 0, Dugdale disc of radius C, see src/law/maugis.rs):
  Dbar = C^2/2 - (8 lambda/(3 pi)) C - 2/(pi lambda),  Pbar = -(pi lambda/2) C^2.
Its fold (displacement-controlled snap for lambda < 0.938) is found here by
findroot on mp.diff of Dbar(C), not from the closed form.
"""
import json
import os
from mpmath import mp, mpf, sqrt, atan, pi, findroot, diff

mp.dps = 40


def m_of_a(lam, a):
    def f(m):
        s = sqrt(m * m - 1)
        t = atan(s)
        return (lam * a * a / 2 * (s + (m * m - 2) * t)
                + 4 * lam * lam * a / 3 * (s * t - m + 1) - 1)
    lo = 1 + mpf(10) ** -30
    hi = mpf(2)
    while f(hi) < 0:
        hi *= 2
    return findroot(f, (lo, hi), solver="illinois", maxsteps=500)


def pbar(lam, a):
    m = m_of_a(lam, a)
    s = sqrt(m * m - 1)
    return a ** 3 - lam * a * a * (s + m * m * atan(s))


def dbar(lam, a):
    m = m_of_a(lam, a)
    return a * a - mpf(4) / 3 * a * lam * sqrt(m * m - 1)


def argmin_grid(g, lo, hi, n=120):
    xs = [lo * (hi / lo) ** (mpf(k) / n) for k in range(n + 1)]
    vals = [g(x) for x in xs]
    k = min(range(len(vals)), key=lambda i: vals[i])
    return xs[k], vals[k], k, len(xs)


def extremum(g, lo, hi):
    x0, _, k, n = argmin_grid(g, lo, hi)
    if k == 0 or k == n - 1:
        return None
    x = findroot(lambda x: diff(g, x), x0, tol=mpf(10) ** -30)
    return x


def reference(lam):
    lam = mpf(lam)
    out = {"lambda": float(lam)}
    # Load-controlled pull-off.
    a = extremum(lambda x: pbar(lam, x), mpf(10) ** -4, mpf(10))
    out["pull_off"] = {"load": float(pbar(lam, a)), "radius": float(a),
                       "interference": float(dbar(lam, a))}
    # Zero-load radius (stable side: above the pull-off radius).
    a0 = findroot(lambda x: pbar(lam, x), a * 1.5, tol=mpf(10) ** -30)
    out["zero_load_radius"] = float(a0)
    # Displacement-controlled snap: fold of the contact branch, if any.
    af = extremum(lambda x: dbar(lam, x), mpf(10) ** -5, mpf(10))
    if af is not None:
        out["jump_out"] = {"branch": "contact", "load": float(pbar(lam, af)),
                           "interference": float(dbar(lam, af)), "radius": float(af)}
    else:
        nc = lambda c: c * c / 2 - 8 * lam / (3 * pi) * c - 2 / (pi * lam)
        c = findroot(lambda x: diff(nc, x), mpf(1) * lam, tol=mpf(10) ** -30)
        out["jump_out"] = {"branch": "non_contact", "load": float(-pi * lam / 2 * c * c),
                           "interference": float(nc(c)), "radius": 0.0}
    return out


def main():
    lams = [0.01, 0.1, 0.3, 0.5, 1, 2, 3, 5, 10, 100]
    import mpmath
    data = {
        "provenance": "tests/data/maugis_pull_off.py, mpmath " + mpmath.__version__
                      + ", mp.dps = 40: the MD equations of docs/physics.md solved "
                      "for m at given A (illinois bracketing root), extrema by findroot on "
                      "mp.diff; the non-contact fold by findroot on mp.diff of Dbar(C). "
                      "Units: Pbar = P/(pi w R), Dbar = delta (K^2/(pi^2 w^2 R))^(1/3), "
                      "A = a (K/(pi w R^2))^(1/3).",
        "values": [reference(l) for l in lams],
    }
    here = os.path.dirname(os.path.abspath(__file__))
    with open(os.path.join(here, "maugis_pull_off.json"), "w") as f:
        json.dump(data, f, indent=1)
        f.write("\n")
    for v in data["values"]:
        print(v)


if __name__ == "__main__":
    main()
