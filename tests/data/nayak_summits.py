#!/usr/bin/env python3
"""Summit statistics of an isotropic Gaussian surface by direct quadrature of
Rice's formula (Nayak 1971), to check the closed forms in src/surface/nayak.rs.

What: for moments m0 = m2 = 1, m4 = alpha (so Nayak's alpha = m0 m4/m2^2),
the summit density, the mean of the summits' mean curvature
kappa = -(z_xx + z_yy)/2, and the mean and standard deviation of summit
heights, as dimensionless coefficients:
  density / (m4/m2), mean_curvature / sqrt(m4), mean_height / sqrt(m0),
  height_std / sqrt(m0).
How (independent of the closed forms): Rice's formula for the density of
points with zero gradient and negative-definite Hessian,
  n = p_grad(0) E[|det H| 1{H < 0}],   p_grad(0) = 1/(2 pi m2),
with the isotropic covariances var z_xx = var z_yy = m4, cov(z_xx, z_yy) =
m4/3, var z_xy = m4/3, cov(z, z_xx) = -m2, gradient independent of (z, H).
In s = (z_xx + z_yy)/2 (var 2 m4/3), d = (z_xx - z_yy)/2 and c = z_xy (iid,
var m4/3): det H = s^2 - rho^2 with rho^2 = d^2 + c^2 (Rayleigh), H < 0 iff
s < 0 and rho < |s|. The (s, rho) integral is done numerically by mpmath.quad
(Gauss-Legendre inside, tanh-sinh outside) at 20 digits; the height enters through the Gaussian conditional
z | s (mean -m2 s / var s, variance m0 - m2^2 / var s).
Digits: 20-digit working precision, written with 16 significant digits (the
Rust test asserts 1e-13).

Run: /path/to/venv/bin/python tests/data/nayak_summits.py > tests/data/nayak_summits.json
"""
import json
import sys

import mpmath as mp

mp.mp.dps = 20


def stats(alpha):
    m0, m2, m4 = mp.mpf(1), mp.mpf(1), mp.mpf(alpha)
    vs = 2 * m4 / 3
    sig2 = m4 / 3
    phi = lambda s: mp.exp(-s * s / (2 * vs)) / mp.sqrt(2 * mp.pi * vs)

    def weight(s):  # E[|det H| 1{H<0} | s], by quadrature over rho
        a = abs(s)
        return mp.quad(lambda r: (s * s - r * r) * r / sig2 * mp.exp(-r * r / (2 * sig2)), [0, a], method="gauss-legendre")

    def moment(f):
        return mp.quad(lambda s: f(s) * weight(s) * phi(s), [-mp.inf, -3 * mp.sqrt(vs), 0])

    w0 = moment(lambda s: 1)
    density = w0 / (2 * mp.pi * m2)
    kappa = moment(lambda s: -s) / w0
    mu = lambda s: -m2 * s / vs
    v = m0 - m2 * m2 / vs
    mean = moment(mu) / w0
    second = moment(lambda s: mu(s) ** 2 + v) / w0
    std = mp.sqrt(second - mean**2)
    return {
        "alpha": alpha,
        "density_over_m4_per_m2": mp.nstr(density / (m4 / m2), 16),
        "mean_curvature_over_sqrt_m4": mp.nstr(kappa / mp.sqrt(m4), 16),
        "mean_height_over_sqrt_m0": mp.nstr(mean / mp.sqrt(m0), 16),
        "height_std_over_sqrt_m0": mp.nstr(std / mp.sqrt(m0), 16),
    }


if __name__ == "__main__":
    rows = []
    for a in (1.5, 2, 3, 5, 10, 100):
        rows.append(stats(a))
        print("alpha", a, file=sys.stderr)
    print(json.dumps({
        "provenance": "tests/data/nayak_summits.py: mpmath " + mp.__version__
        + " quadrature of Rice's summit integrals, 20 digits, written to 16",
        "rows": rows,
    }, indent=1))
