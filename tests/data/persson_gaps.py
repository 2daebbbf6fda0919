"""Reference values for Persson's distribution of interfacial separations
(src/persson/gaps.rs) on an analytic self-affine spectrum.

Independent of the Rust code: mpmath at 20 digits, tanh-sinh quadrature
(mpmath.quad) over the wavevector with the spectrum and its cumulative
integrals written out here (antiderivatives per piece), mpmath.e1 and
mpmath.erf / mpmath.ncdf; the inner mean gap u_bar(q) by its own
mpmath.quad for every outer node (gamma = 1, so only the E1 term). Run:

    python3 tests/data/persson_gaps.py  (mpmath) > tests/data/persson_gaps.json

Definitions (Almqvist, Campana, Prodanov & Persson 2011, J. Mech. Phys.
Solids 59, 2355; Yang & Persson 2008; docs/physics.md):
  w(q; q') = (pi int_{q'}^{q} k^3 C dk)^(-1/2),  A(q)/A0 = erf(p w(q; q0)/E*),
  u_bar(q) = sqrt(pi) int_q^{q1} k^2 C w(k; q) E1(s^2)/2 dk,  s = w(k; q) p(q)/E*,
  p(q) = p A0/A(q),  h^2(q) = 2 pi int_q^{q1} k C dk,
  P(u < H) = A1/A0 + int_{q0}^{q1} (-dA/dq)/A0 [Phi((H-u_bar)/h) - Phi((-H-u_bar)/h)] dq,
  <u>   = int (-dA/dq)/A0 E|N(u_bar, h)| dq,  <u^2> = int (-dA/dq)/A0 (u_bar^2 + h^2) dq.
-dA/dq is differentiated here by mpmath.diff of erf(p w(q)/E*), not from
the closed form the crate uses.
"""
import json
import mpmath as mp

mp.mp.dps = 20

H = mp.mpf("0.8")
QL, QR, QS = mp.mpf("1e6"), mp.mpf("4e6"), mp.mpf("1e8")
H_RMS = mp.mpf("1e-8")
ESTAR = mp.mpf("1e9")
E = 2 * (1 + H)

# C = c0 on [QL, QR), c0 (q/QR)^-E on [QR, QS).
def _unit_int(k, a, b):
    """int_a^b q^k C_unit dq for QL <= a <= b <= QS."""
    s = mp.mpf(0)
    lo, hi = a, min(b, QR)
    if hi > lo:
        s += (hi ** (k + 1) - lo ** (k + 1)) / (k + 1)
    lo, hi = max(a, QR), b
    if hi > lo:
        m = k + 1 - E
        s += QR ** E * (hi ** m - lo ** m) / m
    return s

C0 = H_RMS ** 2 / (2 * mp.pi * _unit_int(1, QL, QS))


def C(q):
    if q < QL or q >= QS:
        return mp.mpf(0)
    return C0 if q < QR else C0 * (q / QR) ** (-E)


def cum(k, a, b):
    return C0 * _unit_int(k, a, b)


def w(q, qz):
    c = cum(3, qz, q)
    return mp.inf if c <= 0 else 1 / mp.sqrt(mp.pi * c)


def area(p, q):
    return mp.erf(p * w(q, QL) / ESTAR)


def ubar(p, qz):
    pz = p / area(p, qz)
    pts = [qz] + [x for x in (QR, QS) if x > qz]

    def f(k):
        s = w(k, qz) * pz / ESTAR
        if s > 40:  # E1(s^2) < exp(-1600): nothing left at 20 digits
            return mp.mpf(0)
        return k ** 2 * C(k) * w(k, qz) * mp.e1(s * s) / 2

    return mp.sqrt(mp.pi) * mp.quad(f, pts)


def stats(p, height):
    a1 = area(p, QS)

    def parts(q):
        if p * w(q, QL) / ESTAR > 12:  # exp(-144): still in contact
            return mp.mpf(0), mp.mpf(0), mp.mpf(0), mp.mpf(0)
        dens = -mp.diff(lambda x: area(p, x), q)
        ub = ubar(p, q)
        h = mp.sqrt(2 * mp.pi * cum(1, q, QS))
        below = mp.ncdf((height - ub) / h) - mp.ncdf((-height - ub) / h)
        z = ub / h
        mean = 2 * h * mp.npdf(z) + ub * (1 - 2 * mp.ncdf(-z))
        return dens, below, mean, ub * ub + h * h

    cache = {}

    def comp(i):
        def g(q):
            if q not in cache:
                cache[q] = parts(q)
            d = cache[q]
            return d[0] * (1 if i == 0 else d[i])
        return g

    pts = [QL, QR, QS]
    norm = a1 + mp.quad(comp(0), pts)
    below = a1 + mp.quad(comp(1), pts)
    mean = mp.quad(comp(2), pts)
    rms = mp.sqrt(mp.quad(comp(3), pts))
    return a1, norm, below, mean, rms


cases = []
for p_rel in ["1e-3", "1e-2"]:
    p = ESTAR * mp.mpf(p_rel) * mp.sqrt(2 * mp.pi * C0 * _unit_int(3, QL, QS))
    for h_rel in ["0.5", "2"]:
        height = mp.mpf(h_rel) * H_RMS
        a1, norm, below, mean, rms = stats(p, height)
        cases.append({
            "pressure": mp.nstr(p, 17), "height": mp.nstr(height, 17),
            "contact_fraction": mp.nstr(a1, 17), "normalisation": mp.nstr(norm, 17),
            "fraction_below": mp.nstr(below, 17), "mean_gap": mp.nstr(mean, 17),
            "rms_gap": mp.nstr(rms, 17),
        })
print(json.dumps({
    "hurst": "0.8", "q_long": "1e6", "q_roll": "4e6", "q_short": "1e8",
    "h_rms": "1e-8", "estar": "1e9", "gamma": "1", "cases": cases,
}, indent=1))
