#!/usr/bin/env python3
"""Independent reference for the hysteresis energy of a rough surface:
JKR asperities (Fuller & Tabor 1975) on standard-normal summit heights,
approached from h_start = d/sigma down to h_min, then retracted to h_start.

Maugis units per asperity: loads pi w R, interferences (pi^2 w^2 R/K^2)^(1/3),
K = 4E*/3; k = sigma in interference units. JKR, parametric in A = a/a_unit:
delta = A^2 - B sqrt(A), P = A^3 - sqrt(6 A^3), B = sqrt(8/3); the stable branch
runs from the jump-out fold A_c = 6^(-1/3) (delta_c = A_c^2 - B sqrt(A_c)).
On approach an asperity is free until delta = 0, then on the stable branch; on
retraction it stays on the stable branch down to delta_c. So the two legs differ
only for delta in [delta_c, 0) on summits that touched (s >= h_min), and the
energy lost per cycle, swapping the order of integration, is

  W / (N pi w R delta_unit) = int_{h_min}^{h_start} phi(s) G(max(delta_c, k (s - h_start))) ds
  G(x) = int_x^0 -P(delta) d delta = int_{A(x)}^{A(0)} -P(A) (2A - B/(2 sqrt A)) dA,

A(0) = B^(2/3). mpmath at 30 digits: A(x) by bracketed findroot (anderson) on the largest root of
y^4 - B y - x = 0 (A = y^2), quad with the kink at s = h_start + delta_c/k.
This is not the Rust code path (which integrates totals over separation).

Run: /tmp/venv-*/bin/python tests/data/hysteresis_energy.py > tests/data/hysteresis_energy.json
"""
import json
import mpmath as mp

mp.mp.dps = 30
B = mp.sqrt(mp.mpf(8) / 3)
AC = mp.mpf(6) ** (-mp.mpf(1) / 3)
DC = AC**2 - B * mp.sqrt(AC)
A0 = B ** (mp.mpf(2) / 3)


def a_of(x):
    """Stable-branch A at interference x >= DC (largest root)."""
    if x == 0:
        return A0
    # y^4 - B y is increasing on [sqrt(A_c), sqrt(A0)]: a bracketed root.
    y = mp.findroot(lambda y: y**4 - B * y - x, (mp.sqrt(AC), mp.sqrt(A0)), solver="anderson", tol=mp.mpf(10) ** -50, verify=False)
    return y * y


def g(x):
    if x >= 0:
        return mp.mpf(0)
    lo = a_of(x)
    return mp.quad(lambda a: -(a**3 - mp.sqrt(6 * a**3)) * (2 * a - B / (2 * mp.sqrt(a))), [lo, AC, A0] if lo < AC else [lo, A0])


def energy(k, h_min, h_start):
    phi = lambda s: mp.exp(-s * s / 2) / mp.sqrt(2 * mp.pi)
    kink = h_start + DC / k
    pts = [h_min] + ([kink] if h_min < kink < h_start else []) + [h_start]
    return mp.quad(lambda s: phi(s) * g(max(DC, k * (s - h_start))), pts)


if __name__ == "__main__":
    rows = []
    for k, h_min, h_start in [(1.0, 0.0, 3.0), (0.5, -1.0, 4.0)]:
        w = energy(mp.mpf(k), mp.mpf(h_min), mp.mpf(h_start))
        rows.append({"k_sigma_over_maugis_delta": k, "h_min": h_min, "h_start": h_start,
                     "energy_over_N_pi_w_R_delta": float(w)})
    print(json.dumps({
        "source": "tests/data/hysteresis_energy.py: mpmath (30 digits) quad of the per-asperity "
                  "JKR loop energy over standard-normal heights",
        "command": "python3 tests/data/hysteresis_energy.py > tests/data/hysteresis_energy.json",
        "cases": rows}, indent=1))
