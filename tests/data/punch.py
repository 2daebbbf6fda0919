"""Reference values for the wavy punch (src/punch/), computed independently of the Rust code with
mpmath (30 digits) from the formulas re-derived in docs/physics.md ("Wavy punch"):

  h(a) = a^2/R - sqrt(2 pi w a/E*) + pi^2 A a H0(k a),                       k = 2 pi/l
  P(a) = 4E* a^3/(3R) - sqrt(8 pi w E* a^3) + 2E* [pi^2 A a^2 H0(k a) - (pi A a l/2) H1(k a)]

(mpmath struveh). Here P(a) is NOT evaluated from that closed form but by Sneddon's integral
P = pi E* int_0^a psi(t) dt, psi(t) = (2/pi)(h(a) - t^2/R - pi^2 A t H0(k t)), with mp.quad, so the
H1 term is checked too.

Evolution (paper eqs. 3.6-3.8): folds of h(a) = roots of dh/da found by sampling at l/64 and
refining with mpmath's bisection-safeguarded solver; loading keeps the smallest root of h(a) = h,
unloading the largest not beyond a_max. Energy loss per cycle = int P dh along loading minus along
unloading over [h_min, h_max], each integral taken in a on the continuous stretches with mp.quad
(tanh-sinh) — a different quadrature and root finder from the Rust code.

Loss coefficients of eq. 4.12 in closed form (units E* = R = w = 1): a2 = (2 pi)^(1/3), a4 = (pi/8)^(1/3),
c0 = F(a4) - F(a2), F = (8/15)a^5 - (4/3)sqrt(2 pi) a^(7/2) + pi a^2;
c1 = (4 pi^2/3) sqrt(a2) + G(a4) - G(a2), G = -(4 pi/3) a^(7/2) + pi sqrt(2 pi) a^2;
and, independently, c1 by a central difference of the loss of the envelope path 2-2'-4 (mp.quad).

Run: python3 tests/data/punch.py > tests/data/punch.json   (about a minute)
Numbers are strings with 20 significant digits.
"""
import json
import mpmath as mp

mp.mp.dps = 30
pi = mp.pi
S = lambda x: mp.nstr(x, 20)


class Punch:
    def __init__(s, E, w, R, A, l):
        s.E, s.w, s.R, s.A, s.l = map(mp.mpf, (E, w, R, A, l))
        s.k = 2 * pi / s.l

    def h(s, a):
        return a**2 / s.R - mp.sqrt(2 * pi * s.w * a / s.E) + pi**2 * s.A * a * mp.struveh(0, s.k * a)

    def dh(s, a):
        x = s.k * a
        return 2 * a / s.R - mp.sqrt(pi * s.w / (2 * s.E * a)) + pi**2 * s.A * (
            mp.struveh(0, x) + x * (2 / pi - mp.struveh(1, x)))

    def P_closed(s, a):
        x = s.k * a
        return 4 * s.E * a**3 / (3 * s.R) - mp.sqrt(8 * pi * s.w * s.E * a**3) + 2 * s.E * (
            pi**2 * s.A * a**2 * mp.struveh(0, x) - pi * s.A * a * s.l / 2 * mp.struveh(1, x))

    def P_sneddon(s, a):
        h = s.h(a)
        psi = lambda t: 2 / pi * (h - t**2 / s.R - pi**2 * s.A * t * mp.struveh(0, s.k * t))
        n = int(mp.ceil(a / (s.l / 4))) + 1
        pts = [a * i / n for i in range(n + 1)]
        return pi * s.E * mp.quad(psi, pts)

    def folds(s, h_stop):
        """Knots (a, h): origin, alternating minima/maxima, until h first reaches h_stop."""
        step = min(s.l / 64, mp.cbrt(pi * s.w * s.R**2 / (8 * s.E)) / 16)
        knots = [(mp.mpf(0), mp.mpf(0))]
        a0 = step * mp.mpf('1e-6')
        d0 = s.dh(a0)
        i = 1
        while True:
            a1 = step * i
            d1 = s.dh(a1)
            if mp.sign(d0) != mp.sign(d1):
                r = mp.findroot(s.dh, (a0, a1), solver='anderson')
                knots.append((r, s.h(r)))
                if d1 < 0 and knots[-1][1] >= h_stop:
                    return knots
            if d1 > 0 and s.h(a1) >= h_stop:
                knots.append((a1, s.h(a1)))
                return knots
            a0, d0, i = a1, d1, i + 1

    def root(s, p, q, h):
        if h == p[1]:
            return p[0]
        if h == q[1]:
            return q[0]
        return mp.findroot(lambda a: s.h(a) - h, (p[0], q[0]), solver='anderson')

    def evolution(s, h_max):
        k = s.folds(h_max)
        j = next(i for i, kn in enumerate(k) if kn[1] >= h_max)
        amax = s.root(k[j - 1], k[j], h_max)
        s.knots = k[:j] + [(amax, mp.mpf(h_max))]
        s.h_max = mp.mpf(h_max)

    def loading(s, h):
        k = s.knots
        if h <= 0:
            return mp.mpf(0)
        m = mp.mpf(0)
        for j in range(1, len(k)):
            if k[j][1] >= h and m < h:
                return s.root(k[j - 1], k[j], h)
            m = max(m, k[j][1])

    def unloading(s, h):
        k = s.knots
        for i in range(len(k) - 1, 0, -1):
            if k[i][1] <= h:
                return k[i][0] if i == len(k) - 1 else s.root(k[i], k[i + 1], h)
        return mp.mpf(0)

    def work(s, a0, a1):
        f = lambda a: s.P_closed(a) * s.dh(a)
        n = int(mp.ceil(abs(a1 - a0) / (s.l / 8))) + 1
        return mp.quad(f, [a0 + (a1 - a0) * i / n for i in range(n + 1)])

    def loss(s, h_min):
        k, L, U = s.knots, mp.mpf(0), mp.mpf(0)
        m = mp.mpf(0)
        for j in range(1, len(k)):
            lo, hi = max(m, h_min), min(k[j][1], s.h_max)
            if k[j][1] > m and hi > lo:
                L += s.work(s.root(k[j - 1], k[j], lo), s.root(k[j - 1], k[j], hi))
            m = max(m, k[j][1])
        sm = k[-1][1]
        for i in range(len(k) - 2, 0, -1):
            lo, hi = max(k[i][1], h_min), min(sm, s.h_max)
            if k[i][1] < sm and hi > lo:
                U += s.work(s.root(k[i], k[i + 1], lo), s.root(k[i], k[i + 1], hi))
            sm = min(sm, k[i][1])
        return L - U


def loss_coefficients():
    a2, a4 = mp.cbrt(2 * pi), mp.cbrt(pi / 8)
    F = lambda a: mp.mpf(8) / 15 * a**5 - mp.mpf(4) / 3 * mp.sqrt(2 * pi) * a**3.5 + pi * a**2
    G = lambda a: -4 * pi / 3 * a**3.5 + pi * mp.sqrt(2 * pi) * a**2
    c0 = F(a4) - F(a2)
    c1 = 4 * pi**2 / 3 * mp.sqrt(a2) + G(a4) - G(a2)

    def path(eps):  # loss of the envelope path 2-2'-4 (units E* = R = w = 1)
        hp = lambda a: a**2 - mp.sqrt(2 * pi * a) + pi * eps * mp.sqrt(a)
        hm = lambda a: a**2 - mp.sqrt(2 * pi * a) - pi * eps * mp.sqrt(a)
        Pp = lambda a: 4 * a**3 / 3 - mp.sqrt(8 * pi * a**3) + 2 * pi * eps * a**1.5
        Pm = lambda a: 4 * a**3 / 3 - mp.sqrt(8 * pi * a**3) - 2 * pi * eps * a**1.5
        dhm = lambda a: 2 * a - mp.sqrt(pi / (2 * a)) - pi * eps / (2 * mp.sqrt(a))
        b2 = mp.findroot(hp, a2)
        b4 = mp.findroot(dhm, a4)
        d = hm(b2)  # h from h_+(b2) = 0 down to h_-(b2) at fixed radius, stiffness 2E* a
        return Pp(b2) * d + b2 * d**2 + mp.quad(lambda a: Pm(a) * dhm(a), [b2, b4])

    e = mp.mpf('1e-12')
    return c0, c1, path(0), (path(e) - path(-e)) / (2 * e)


def curve_rows(p, radii):
    rows = []
    for a in radii:
        a = mp.mpf(a)
        pc, ps = p.P_closed(a), p.P_sneddon(a)
        assert abs(pc - ps) <= mp.mpf('1e-20') * (1 + abs(pc)) * p.E * p.R**2, (a, pc, ps)
        rows.append({"a": repr(float(a)), "h": S(p.h(a)), "P": S(ps)})
    return rows


if __name__ == "__main__":
    out = {"source": "mpmath %s, mp.dps = 30; tests/data/punch.py" % mp.__version__}
    c0, c1, c0q, c1q = loss_coefficients()
    out["loss_coefficients"] = {"c0": S(c0), "c1": S(c1), "c0_quad": S(c0q), "c1_central_difference": S(c1q)}
    cases = {
        # the paper's Fig. 8 parameters: E* = R = 1, 2 pi w/(R E*) = 0.05, A = 0.14
        "fig8_l0.1": (1, 0.05 / (2 * pi), 1, 0.14, 0.1),
        "fig8_l0.5": (1, 0.05 / (2 * pi), 1, 0.14, 0.5),
        # gelatin-like, SI: E* 17.08 kPa, w 80.4 mJ/m^2, R 0.25 m, l 1 mm, A sqrt(l) = 1.1e-4
        "gelatin_l1mm": (17.08e3, 80.4e-3, 0.25, 1.1e-4 / mp.sqrt(1e-3), 1e-3),
    }
    radii = {"fig8_l0.1": [0.001, 0.01, 0.05, 0.1, 0.2, 0.3, 0.45, 0.6, 0.8, 1.0],
             "fig8_l0.5": [0.001, 0.05, 0.2, 0.45, 0.8],
             "gelatin_l1mm": [1e-5, 1e-4, 1e-3, 4e-3, 8e-3, 0.012, 0.0175, 0.026]}
    out["curves"] = {}
    for name, pars in cases.items():
        p = Punch(*pars)
        out["curves"][name] = {"estar": repr(float(pars[0])), "w": repr(float(pars[1])), "radius": repr(float(pars[2])),
                               "amplitude": repr(float(pars[3])), "wavelength": repr(float(pars[4])),
                               "rows": curve_rows(p, radii[name])}
    # Evolution and loss: the paper's Fig. 3/7 example (A = 0.1, l/R = 0.03) and the gelatin-like case.
    evo = {"fig3": ((1, 0.05 / (2 * pi), 1, 0.1, 0.03), -0.06, 0.12, [-0.04, -0.01, 0.0, 0.01, 0.05, 0.1, 0.12]),
           "gelatin_l1mm": (cases["gelatin_l1mm"], -1e-3, 1.5e-3, [-6e-4, -1e-4, 2e-4, 8e-4, 1.4e-3])}
    out["evolution"] = {}
    for name, (pars, hmin, hmax, depths) in evo.items():
        p = Punch(*pars)
        p.evolution(hmax)
        rows = [{"h": repr(float(h)), "a_loading": S(p.loading(mp.mpf(h))), "a_unloading": S(p.unloading(mp.mpf(h)))}
                for h in depths]
        out["evolution"][name] = {"estar": repr(float(pars[0])), "w": repr(float(pars[1])), "radius": repr(float(pars[2])),
                                  "amplitude": repr(float(pars[3])), "wavelength": repr(float(pars[4])),
                                  "h_min": repr(hmin), "h_max": repr(hmax), "loss": S(p.loss(mp.mpf(hmin))), "rows": rows}
    print(json.dumps(out, indent=1))
