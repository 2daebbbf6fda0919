"""Reference values of the stickiness criteria (src/stickiness.rs,
src/bem/roughness.rs), computed independently with numpy.

Map case: examples/data/selfaffine-256.npy (periodic, pixel 3.90625e-7 m),
E* = 1e9 Pa, w = 0.05 J/m^2, rho = 2e-9 m. Definitions (those of Adhesion
0.93's example on the contact-mechanics challenge): the heights' mean
removed; RMS gradient from periodic forward differences; RMS curvature =
RMS(Laplacian)/2 from periodic central second differences; full-contact
energy per area = (1/2) sum_q (E* |q|/2) |h_q|^2 / N^2 (numpy's FFT,
q = 2 pi fftfreq); then
  PR   = h' E* rho/(2w) (h'^2/(h'' rho))^(2/3),  g0 = 16 h'^2/(3 h'')
  PT   = U_full/w
  Tabor = (1/h'')^(1/3) (w/E*)^(2/3)/rho
  mu_rho = sqrt(w dx/(E* rho^2)).
Spectrum case: Persson's self-affine spectrum (H = 0.8, q_l = 1e5,
q_r = 4e5, q_s = 4e8 rad/m, h_rms = 1e-8 m), moments in closed form
(int q^k (q/q_r)^-e dq = q_r^e (b^m - a^m)/m, m = k + 1 - e != 0 here):
  h'^2 = 2 pi int q^3 C dq, h''^2 = (pi/2) int q^5 C dq,
  U_full = (pi E*/2) int q^2 C dq, dx = pi/q_s.
Challenge case: mu_rho of Adhesion 0.93's example (dx = 0.1 mm/512,
rho = 30 x 2.071 nm, w = 0.05 J/m^2, E* = 25 MPa), which prints 0.31811.

Run: python tests/data/stickiness.py > tests/data/stickiness.json
"""
import json
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[2]


def criteria(g, k, u, dx, e, w, rho):
    g0 = 16.0 / 3.0 * g * g / k
    return {
        "slope_rms": g,
        "curvature_rms": k,
        "full_contact_energy": u,
        "pixel_size": dx,
        "pastewka_robbins": g * e * rho / (2 * w) * (g * g / (k * rho)) ** (2.0 / 3.0),
        "g0": g0,
        "range_over_g0": rho / g0,
        "persson_tosatti": u / w,
        "tabor": (1 / k) ** (1.0 / 3.0) * (w / e) ** (2.0 / 3.0) / rho,
        "mu_rho": float(np.sqrt(w * dx / (e * rho * rho))),
    }


def map_case():
    h = np.load(ROOT / "examples/data/selfaffine-256.npy").astype(float)
    h = h - h.mean()
    dx = 3.90625e-7
    e, w, rho = 1e9, 0.05, 2e-9
    gx = (np.roll(h, -1, axis=1) - h) / dx
    gy = (np.roll(h, -1, axis=0) - h) / dx
    g = float(np.sqrt(np.mean(gx**2 + gy**2)))
    lap = (np.roll(h, -1, 1) - 2 * h + np.roll(h, 1, 1)) / dx**2 + (
        np.roll(h, -1, 0) - 2 * h + np.roll(h, 1, 0)
    ) / dx**2
    k = float(np.sqrt(np.mean(lap**2)) / 2)
    ny, nx = h.shape
    qx = 2 * np.pi * np.fft.fftfreq(nx, dx)
    qy = 2 * np.pi * np.fft.fftfreq(ny, dx)
    q = np.hypot(qx[None, :], qy[:, None])
    hq = np.fft.fft2(h)
    u = float(0.5 * np.sum(e * q / 2 * np.abs(hq) ** 2) / (nx * ny) ** 2)
    return criteria(g, k, u, dx, e, w, rho) | {"E": e, "w": w, "rho": rho}


def spectrum_case():
    hurst, ql, qr, qs, hrms = 0.8, 1e5, 4e5, 4e8, 1e-8
    e, w, rho = 1e9, 0.05, 2e-9
    ex = 2 * (1 + hurst)

    def integral(k):
        flat = (qr ** (k + 1) - ql ** (k + 1)) / (k + 1)
        m = k + 1 - ex
        return flat + qr**ex * (qs**m - qr**m) / m

    c0 = hrms**2 / (2 * np.pi * integral(1))
    g = float(np.sqrt(2 * np.pi * c0 * integral(3)))
    k = float(np.sqrt(np.pi / 2 * c0 * integral(5)))
    u = float(np.pi * e / 2 * c0 * integral(2))
    dx = float(np.pi / qs)
    return criteria(g, k, u, dx, e, w, rho) | {"E": e, "w": w, "rho": rho}


def challenge_mu_rho():
    dx, rho, w, e = 1e-4 / 512, 30 * 2.071e-9, 0.05, 25e6
    return {"pixel_size": dx, "rho": rho, "w": w, "E": e,
            "mu_rho": float(np.sqrt(w * dx / (e * rho * rho))),
            "published": 0.31811}


if __name__ == "__main__":
    print(json.dumps({"map": map_case(), "spectrum": spectrum_case(),
                      "challenge": challenge_mu_rho()}, indent=1))
