"""Reference values of the per-summit menisci on GW summits
(src/capillary/summits.rs), by Gauss-Legendre quadrature over the summit
heights (independent of the closed form there).

Water at 293.15 K (gamma = 0.0728 N/m, V_m = 1.8e-5 m^3/mol), contact
angles 0, RH = 0.99: r_K = gamma V_m/(R T ln(1/RH)), Delta p = gamma/r_K,
h_m = 2 r_K, w_m = 2 gamma. A summit at gap D pulls with
2 pi R w_m (1 - D/h_m) for 0 <= D < h_m and 2 pi R w_m for D <= 0 (Derjaguin);
summit heights z ~ N(0, sigma), D = d - z; the mean pressure is
eta int F(d - z) phi(z/sigma)/sigma dz, integrated piecewise between the
kinks z = d - h_m and z = d, 200 Gauss-Legendre nodes each, to +-14 sigma.

Run: python tests/data/capillary_maps.py > tests/data/capillary_maps.json
"""
import json

import numpy as np

R_GAS = 8.314462618
GAMMA, VM, T, RH = 0.0728, 1.8e-5, 293.15, 0.99


def meniscus():
    rk = GAMMA * VM / (R_GAS * T * np.log(1 / RH))
    return {"kelvin_radius": rk, "laplace_pressure": GAMMA / rk,
            "height": 2 * rk, "work": 2 * GAMMA}


def per_summit(eta, radius, sigma, d, m):
    hm, wm = m["height"], m["work"]
    x, w = np.polynomial.legendre.leggauss(200)

    def piece(a, b, f):
        if b <= a:
            return 0.0
        z = 0.5 * (b - a) * x + 0.5 * (b + a)
        phi = np.exp(-0.5 * (z / sigma) ** 2) / (np.sqrt(2 * np.pi) * sigma)
        return 0.5 * (b - a) * np.sum(w * f(z) * phi)

    lo, hi = -14 * sigma, 14 * sigma
    a = min(max(d - hm, lo), hi)
    b = min(max(d, lo), hi)
    mean = piece(a, b, lambda z: 1 - (d - z) / hm) + piece(b, hi, lambda z: np.ones_like(z))
    return float(2 * np.pi * eta * radius * wm * mean)


if __name__ == "__main__":
    m = meniscus()
    eta, radius, sigma = 1e12, 1e-6, 5e-8
    cases = [{"density": eta, "radius": radius, "sigma": sigma, "separation": d,
              "pressure": per_summit(eta, radius, sigma, d, m)}
             for d in (-5e-8, 0.0, 3e-8, 1e-7, 2e-7)]
    print(json.dumps({"relative_humidity": RH, "meniscus": m, "cases": cases}, indent=1))
