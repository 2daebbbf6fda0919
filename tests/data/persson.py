"""Reference values for Persson's contact theory and GW on the same spectrum.

Independent of the Rust code: mpmath at 30 digits, tanh-sinh quadrature
(mpmath.quad) over the wavevector with the piecewise spectrum written out
here, mpmath.e1 / mpmath.erf, the inner integral F(s) by its own
mpmath.quad, and GW's F_n(h) = int_h^inf (s - h)^n phi(s) ds by quadrature
(not the closed forms the crate uses). Run:

    /work/venv-peers/bin/python tests/data/persson.py > tests/data/persson.json

Definitions (docs/physics.md, "Persson's theory"):
  <h^2> = 2 pi int q C dq, g^2 = 2 pi int q^3 C dq,
  m0 = 2 pi int q C, m2 = pi int q^3 C, m4 = (3 pi/4) int q^5 C,
  w(q) = (pi int_{q0}^q q'^3 C dq')^(-1/2),
  A/A0 = erf(sqrt(2) p/(E* g)),
  u(p) = sqrt(pi) int q^2 C w [gamma E1(s^2)/2 + 3 (1-gamma) F(s)] dq, s = w p/E*,
  F(s) = int_s^inf erf(x)^2 exp(-x^2)/x dx,
  u0 = gamma sqrt(pi) int q^2 C w dq, U_full/A0 = (pi E*/2) int q^2 C dq,
  GW (McCool): eta = m4/(6 pi sqrt3 m2), R = 0.375 sqrt(pi/m4),
  sigma = sqrt(m0 (1 - 0.8968/alpha)), y_s = 4 sqrt(m0/(pi alpha)),
  p = (4/3) eta E* sqrt(R) sigma^1.5 F_3/2(h), A/A0 = pi eta R sigma F_1(h),
  u = sigma h + y_s + pi eta R sigma^2 F_2(h).
"""
import json
import mpmath as mp

mp.mp.dps = 30


def spectrum(H, ql, qr, qs, h_rms=None, slope_rms=None):
    e = 2 * (1 + H)

    def c_unit(q):
        if q < ql or q > qs:
            return mp.mpf(0)
        if q < qr:
            return mp.mpf(1)
        return (q / qr) ** (-e)

    pts = [ql, qr, qs] if qr > ql else [ql, qs]

    def integral_unit(k):
        return mp.quad(lambda q: q**k * c_unit(q), pts)

    if h_rms is not None:
        c0 = mp.mpf(h_rms) ** 2 / (2 * mp.pi * integral_unit(1))
    else:
        c0 = mp.mpf(slope_rms) ** 2 / (2 * mp.pi * integral_unit(3))

    def C(q):
        return c0 * c_unit(q)

    def cum3(q):
        # int_{ql}^{q} q'^3 C dq', antiderivatives written out piecewise.
        q = mp.mpf(q)
        s = mp.mpf(0)
        if qr > ql:
            b = min(q, qr)
            s += c0 * (b**4 - ql**4) / 4
        if q > qr:
            m = 4 - e
            s += c0 * qr**e * (q**m - qr**m) / m
        return s

    return C, cum3, pts


def case(H, ql, qr, qs, estar, gamma, pressures_over_eg, h_rms=None, slope_rms=None):
    ql, qr, qs, estar, gamma = map(mp.mpf, (ql, qr, qs, estar, gamma))
    C, cum3, pts = spectrum(H, ql, qr, qs, h_rms, slope_rms)
    I = lambda k: mp.quad(lambda q: q**k * C(q), pts)
    m0, m2, m4 = 2 * mp.pi * I(1), mp.pi * I(3), 3 * mp.pi / 4 * I(5)
    g = mp.sqrt(2 * m2)
    # Check the written-out cumulative against quadrature once.
    assert abs(cum3(qs) / I(3) - 1) < mp.mpf(10) ** -25
    w = lambda q: 1 / mp.sqrt(mp.pi * cum3(q))
    F = lambda s: mp.quad(lambda x: mp.erf(x) ** 2 * mp.exp(-x * x) / x, [s, s + 2, mp.inf])

    def u(p):
        def f(q):
            s = w(q) * p / estar
            v = gamma * mp.e1(s * s) / 2
            if gamma != 1:
                v += 3 * (1 - gamma) * F(s)
            return q * q * C(q) * w(q) * v

        return mp.sqrt(mp.pi) * mp.quad(f, pts)

    u0 = gamma * mp.sqrt(mp.pi) * mp.quad(lambda q: q * q * C(q) * w(q), pts)
    ufull = mp.pi * estar / 2 * I(2)
    # GW (McCool relations; F_n by quadrature).
    alpha = m0 * m4 / m2**2
    eta = m4 / (6 * mp.pi * mp.sqrt(3) * m2)
    R = mp.mpf("0.375") * mp.sqrt(mp.pi / m4)
    sig = mp.sqrt(m0 * (1 - mp.mpf("0.8968") / alpha))
    ys = 4 * mp.sqrt(m0 / (mp.pi * alpha))
    phi = lambda s: mp.exp(-s * s / 2) / mp.sqrt(2 * mp.pi)
    Fn = lambda n, h: mp.quad(lambda s: (s - h) ** n * phi(s), [h, h + 10, mp.inf])
    scale = mp.mpf(4) / 3 * eta * estar * mp.sqrt(R) * sig**1.5
    states = []
    for r in pressures_over_eg:
        p = mp.mpf(r) * estar * g
        h = mp.findroot(lambda h: mp.log(Fn(1.5, h)) - mp.log(p / scale), 2)
        states.append(
            {
                "pressure": float(p),
                "area_fraction": mp.nstr(mp.erf(mp.sqrt(2) * p / (estar * g)), 20),
                "mean_gap": mp.nstr(u(p), 20),
                "gw_h": mp.nstr(h, 20),
                "gw_area_fraction": mp.nstr(mp.pi * eta * R * sig * Fn(1, h), 20),
                "gw_mean_gap": mp.nstr(sig * h + ys + mp.pi * eta * R * sig**2 * Fn(2, h), 20),
            }
        )
    return {
        "hurst": H,
        "q_long": float(ql),
        "q_roll": float(qr),
        "q_short": float(qs),
        "h_rms": h_rms,
        "slope_rms": slope_rms,
        "estar": float(estar),
        "gamma": float(gamma),
        "m0": mp.nstr(m0, 20),
        "m2": mp.nstr(m2, 20),
        "m4": mp.nstr(m4, 20),
        "mean_gap_slope": mp.nstr(u0, 20),
        "full_contact_energy": mp.nstr(ufull, 20),
        "states": states,
    }


cases = [
    case(0.8, 1e5, 4e5, 4e8, 1e9, 1.0, [1e-4, 1e-3, 1e-2, 0.1], h_rms=1e-8),
    case(0.8, 1e5, 4e5, 4e8, 1e9, 0.42, [1e-3, 1e-2, 0.1], h_rms=1e-8),
    case(0.5, 2e4, 2e4, 2e7, 1e11, 1.0, [1e-3, 3e-2], slope_rms=0.5),
]
print(
    json.dumps(
        {
            "provenance": "tests/data/persson.py: mpmath 30 digits, tanh-sinh quadrature, "
            "independent of the crate's closed-form segments and Gauss-Kronrod",
            "cases": cases,
        },
        indent=1,
    )
)
