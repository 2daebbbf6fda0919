"""Reference values for full contact in the boundary elements
(src/bem/full_contact.rs, tests/it/bem_full.rs), computed independently.

Periodic elastic half-space, contact modulus E*, rigid surface h (mean
removed). In full contact the gap is 0 everywhere, so u = h + c and the
pressure is p = K^-1 h + P with (K^-1 h)_q = E* |q| h_q/2 (q = 0 dropped);
full contact holds exactly for P >= P_full = max(-(K^-1 h)). The elastic
energy per nominal area is
    U_full/A0 = (1/2) mean(h K^-1 h) = (E*/4) sum_q |q| |h_q|^2,
h_q = (1/N) sum_x h(x) e^{-i q.x}, Persson's full-contact energy
(Persson & Tosatti, J. Chem. Phys. 115, 5597, 2001; docs/physics.md).

Case "waves": a 64 x 64 map of two plane waves, written here to
bem_full_contact_waves.npy (float64, metres),
    h = a cos(2 pi 3 x/L) + b cos(2 pi (2 x + 5 y)/L + 0.3),
a = 2e-8 m, b = 1e-8 m, L = 64 dx, dx = 1e-7 m, E* = 1e9 Pa. Closed forms,
no FFT: (K^-1 h) = (E*/2)(q1 a cos(.) + q2 b cos(.)), q1 = 2 pi 3/L,
q2 = 2 pi sqrt(29)/L, so U_full/A0 = (E*/8)(q1 a^2 + q2 b^2) and P_full is
the largest of -(K^-1 h) over the 4096 pixels; mpmath at 40 digits.

Case "selfaffine-256": examples/data/selfaffine-256.npy, dx = 3.90625e-7 m,
E* = 1e9 Pa: U_full/A0 by the q-sum with numpy's FFT, its terms summed by
mpmath.fsum, and P_full = max(-(K^-1 h)) by numpy's inverse FFT.

Run (numpy 2.4.6, mpmath 1.4.1): python tests/data/bem_full_contact.py > tests/data/bem_full_contact.json
"""
import json
from pathlib import Path

import mpmath as mp
import numpy as np

ROOT = Path(__file__).resolve().parents[2]
mp.mp.dps = 40


def waves():
    n, dx, e, a, b = 64, 1e-7, 1e9, 2e-8, 1e-8
    L = n * dx
    q1 = 2 * mp.pi * 3 / L
    q2 = 2 * mp.pi * mp.sqrt(29) / L
    h = np.zeros((n, n))
    neg = []
    for i in range(n):  # row index: y
        for j in range(n):  # column index: x
            x, y = j * dx, i * dx
            p1 = 2 * mp.pi * 3 * x / L
            p2 = 2 * mp.pi * (2 * x + 5 * y) / L + mp.mpf("0.3")
            h[i, j] = float(a * mp.cos(p1) + b * mp.cos(p2))
            neg.append(-(e / 2) * (q1 * a * mp.cos(p1) + q2 * b * mp.cos(p2)))
    np.save(ROOT / "tests/data/bem_full_contact_waves.npy", h)
    # The map stores h rounded to float64; its own mean (about 1e-24 m) is
    # removed by the solver and does not change K^-1 h.
    return {
        "rows": n,
        "pixel_size_m": dx,
        "estar_Pa": e,
        "u_full_J_per_m2": float(e / 8 * (q1 * a**2 + q2 * b**2)),
        "p_full_Pa": float(max(neg)),
    }


def selfaffine():
    h = np.load(ROOT / "examples/data/selfaffine-256.npy")
    h = h - h.mean()
    n = h.shape[0]
    dx, e = 3.90625e-7, 1e9
    q1 = 2 * np.pi * np.fft.fftfreq(n, d=dx)
    q = np.hypot(q1[None, :], q1[:, None])
    hq = np.fft.fft2(h) / h.size
    terms = (e / 4) * q * np.abs(hq) ** 2
    u_full = mp.fsum(float(t) for t in terms.ravel())
    p = np.real(np.fft.ifft2(np.fft.fft2(h) * e * q / 2))
    return {
        "rows": n,
        "pixel_size_m": dx,
        "estar_Pa": e,
        "u_full_J_per_m2": float(u_full),
        "p_full_Pa": float(-p.min()),
    }


print(json.dumps({"waves": waves(), "selfaffine_256": selfaffine()}, indent=1))
