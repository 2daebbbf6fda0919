#!/usr/bin/env python3
"""Independent reference for the elastic-plastic asperity laws.

What: load P (N) and contact radius a (m) of the Kogut-Etsion 2002,
Jackson-Green 2005, Chang-Etsion-Bogy 1987 and Zhao-Maietta-Chang 2000 laws on
loading; the elastic unloading from the flattened shape (span = 3 P_m/(4 E* a_m)
clamped to delta_max, P = P_m t^(3/2), a = a_m t^(1/2)); the JKR pull-off on
the unloading sphere R_u = a_m^2/span; and Greenwood-Williamson totals (load,
area, count per summit) over standard-normal heights, on approach and on
retraction, for the gold RF-MEMS asperity.

How: mpmath at 40 digits, written from the formulas in docs/physics.md (not from
the Rust code): constants as decimal strings, inputs as the exact binary values
the Rust test passes. GW integrals by mpmath.quad (tanh-sinh) split at every
point where the integrand jumps or kinks: the law breakpoints in delta, the
history breakpoints in delta_max, the contact edge on retraction (found by
mpmath.findroot), and the clamp point of the unloading span.

Digits: single-asperity values about 30 significant (mpmath, dps 40); GW
totals: mpmath's own error estimate is stored with each (quad_rel_error). The Rust tests compare at 1e-12 (laws) and 1e-8 (GW).

Run: python3 tests/data/plastic.py > tests/data/plastic.json
"""
import json
import mpmath as mp

mp.mp.dps = 40
PI = mp.pi

# Parameter sets: radius (m), contact modulus (Pa), yield strength (Pa),
# hardness (Pa or None -> 2.8 Y), Poisson ratio of the yielding body.
SETS = {
    "gold": dict(R=1e-6, E=4.796e10, Y=0.4e9, H=None, nu=0.42),
    "steel": dict(R=2e-5, E=1.15e11, Y=1.0e9, H=3.5e9, nu=0.3),
}


def params(s):
    R, E, Y, nu = (mp.mpf(s[k]) for k in ("R", "E", "Y", "nu"))
    H = mp.mpf("2.8") * Y if s["H"] is None else mp.mpf(s["H"])
    return R, E, Y, H, nu


def hertz(R, E, d):
    return mp.mpf(4) / 3 * E * mp.sqrt(R) * d**mp.mpf(1.5), mp.sqrt(R * d)


class Law:
    def __init__(self, name, s):
        self.name = name
        R, E, Y, H, nu = params(s)
        self.R, self.E, self.Y, self.H, self.nu = R, E, Y, H, nu
        K = mp.mpf("0.454") + mp.mpf("0.41") * nu
        self.K = K
        if name in ("kogut-etsion", "chang-etsion-bogy"):
            self.wc = (PI * K * H / (2 * E)) ** 2 * R
            self.elastic_w = 1
        elif name == "zhao-maietta-chang":
            self.wc = (3 * PI * mp.mpf("0.6") * H / (4 * E)) ** 2 * R
            self.elastic_w = 1
        else:
            self.C = mp.mpf("1.295") * mp.exp(mp.mpf("0.736") * nu)
            self.wc = (PI * self.C * Y / (2 * E)) ** 2 * R
            self.Pc = mp.mpf(4) / 3 * (R / E) ** 2 * (self.C * PI * Y / 2) ** 3
            self.B = mp.mpf("0.14") * mp.exp(23 * Y / E)
            self.elastic_w = mp.mpf("1.9")
        self.breaks = {
            "kogut-etsion": [1, 6, 110],
            "chang-etsion-bogy": [1],
            "zhao-maietta-chang": [1, 54],
            "jackson-green": [mp.mpf("1.9")],
        }[name]

    def load(self, d):
        """(P, a) on loading at interference d."""
        if d <= 0:
            return mp.mpf(0), mp.mpf(0)
        R, E, H, wc = self.R, self.E, self.H, self.wc
        w = d / wc
        if w <= self.elastic_w:
            return hertz(R, E, d)
        if self.name == "kogut-etsion":
            Pc = mp.mpf(2) / 3 * PI * self.K * H * R * wc
            Ac = PI * R * wc
            if w <= 6:
                p, a = mp.mpf("1.03") * w ** mp.mpf("1.425"), mp.mpf("0.93") * w ** mp.mpf("1.136")
            elif w <= 110:
                p, a = mp.mpf("1.40") * w ** mp.mpf("1.263"), mp.mpf("0.94") * w ** mp.mpf("1.146")
            else:
                p, a = 3 / self.K * w, 2 * w
            return p * Pc, mp.sqrt(a * Ac / PI)
        if self.name == "chang-etsion-bogy":
            A = PI * R * d * (2 - wc / d)
            return self.K * H * A, mp.sqrt(A / PI)
        if self.name == "zhao-maietta-chang":
            w2 = 54 * wc
            if d > w2:
                A = 2 * PI * R * d
                return H * A, mp.sqrt(A / PI)
            x = (d - wc) / (w2 - wc)
            pm = H * (1 - (1 - mp.mpf("0.6")) * mp.log(w2 / d) / mp.log(w2 / wc))
            A = PI * R * d * (1 - 2 * x**3 + 3 * x**2)
            return pm * A, mp.sqrt(A / PI)
        # Jackson-Green 2005
        g = (w / mp.mpf("1.9")) ** self.B
        A = PI * R * d * g
        aR = mp.sqrt(d / R) * (w / mp.mpf("1.9")) ** (self.B / 2)
        HG = self.Y * mp.mpf("2.84") * (1 - mp.exp(mp.mpf("-0.82") * aR ** mp.mpf("-0.7")))
        p = mp.exp(mp.mpf("-0.25") * w ** (mp.mpf(5) / 12)) * w ** mp.mpf(1.5) + 4 * HG / (
            self.C * self.Y
        ) * (1 - mp.exp(mp.mpf("-0.04") * w ** (mp.mpf(5) / 9))) * w
        return p * self.Pc, mp.sqrt(A / PI)

    def unloading(self, dm):
        """(residual, span, Pm, am) after loading to dm; None when elastic."""
        if dm <= self.elastic_w * self.wc:
            return None
        Pm, am = self.load(dm)
        span = min(3 * Pm / (4 * self.E * am), dm)
        return dm - span, span, Pm, am

    def after(self, d, dm):
        if d >= dm:
            return self.load(d)
        u = self.unloading(dm)
        if u is None:
            return self.load(d)
        res, span, Pm, am = u
        x = d - res
        if x <= 0:
            return mp.mpf(0), mp.mpf(0)
        t = x / span
        return Pm * t ** mp.mpf(1.5), am * mp.sqrt(t)

    def span_clamp_w(self):
        """w where 3P/(4E a) = delta (the unloading span clamp), if any above the elastic limit."""
        f = lambda w: (lambda pa: 3 * pa[0] / (4 * self.E * pa[1]) - w * self.wc)(self.load(w * self.wc))
        lo = self.elastic_w * (1 + mp.mpf("1e-30"))
        pts = [lo * (1 + mp.mpf(k) / 200) for k in range(0, 400)]
        out = []
        for a, b in zip(pts, pts[1:]):
            if any(abs(a - bp) < mp.mpf("1e-20") or (a < bp < b) for bp in self.breaks):
                # The sign may flip across a jump: that point is a breakpoint already.
                continue
            if f(a) * f(b) < 0:
                out.append(mp.findroot(f, (a, b), solver="anderson"))
        return out


def jkr_pull_off(law, dm):
    """Load-controlled JKR pull-off -(3/2) pi w R_u after loading to dm (w = 0.5)."""
    u = law.unloading(dm)
    Ru = law.R if u is None else u[3] ** 2 / u[1]
    return -mp.mpf(3) / 2 * PI * mp.mpf("0.5") * Ru


def gw(law, d, closest=None):
    """Per-summit (load, area, count) over standard-normal heights, sigma = 5 nm."""
    sigma = mp.mpf(5e-9)
    phi = lambda s: mp.exp(-s * s / 2) / mp.sqrt(2 * PI)
    cuts = [d / sigma]
    cuts += [(d + b * law.wc) / sigma for b in law.breaks]
    if closest is not None:
        cuts += [(closest + b * law.wc) / sigma for b in law.breaks]
        cuts += [(closest + w * law.wc) / sigma for w in law.span_clamp_w()]
        # contact edge: sigma s - d = residual(sigma s - closest)
        def edge(s):
            u = law.unloading(sigma * s - closest)
            return sigma * s - d - (0 if u is None else u[0])
        s0 = (closest + law.elastic_w * law.wc) / sigma
        hi = s0 + 1
        while edge(hi) <= 0:
            hi += 1
        if edge(s0) < 0:
            cuts.append(mp.findroot(edge, (s0, hi), solver="anderson"))
    lo = d / sigma
    cuts = sorted(set(c for c in cuts if c >= lo and c < 40))
    def st(s):
        delta = sigma * s - d
        return law.load(delta) if closest is None else law.after(delta, sigma * s - closest)
    pieces = cuts + [mp.inf]
    load, e1 = mp.quad(lambda s: st(s)[0] * phi(s), pieces, error=True)
    area, e2 = mp.quad(lambda s: PI * st(s)[1] ** 2 * phi(s), pieces, error=True)
    count, e3 = mp.quad(lambda s: (1 if st(s)[1] > 0 else 0) * phi(s), pieces, error=True)
    rel = max(e1 / abs(load), e2 / abs(area), e3 / abs(count))
    return load, area, count, rel


def main():
    out = {
        "source": "tests/data/plastic.py: mpmath (dps 40) evaluation of the elastic-plastic laws "
        "from docs/physics.md; GW totals by mpmath.quad split at every jump and kink",
        "command": "python3 tests/data/plastic.py > tests/data/plastic.json",
        "digits": "laws ~30 significant; GW totals ~15 significant",
        "sets": SETS,
        "laws": [],
        "unloading": [],
        "pull_off": [],
        "gw": [],
    }
    ws = [0.3, 0.999999, 1.000001, 1.5, 1.899999, 1.900001, 2.5, 5.999999, 6.000001, 30,
          53.99999, 54.00001, 80, 109.9999, 110.0001, 500, 5000]
    for set_name, s in SETS.items():
        for name in ("kogut-etsion", "jackson-green", "chang-etsion-bogy", "zhao-maietta-chang"):
            law = Law(name, s)
            for w in ws:
                d = float(w * law.wc)
                P, a = law.load(mp.mpf(d))
                out["laws"].append(dict(set=set_name, law=name, w=w, delta=d,
                                        load=float(P), radius=float(a)))
            for wm in (3.0, 20.0, 300.0):
                dm = float(wm * law.wc)
                for f in (0.2, 0.6, 0.9, 0.999):
                    d = float(f * dm)
                    P, a = law.after(mp.mpf(d), mp.mpf(dm))
                    out["unloading"].append(dict(set=set_name, law=name, delta=d, delta_max=dm,
                                                 load=float(P), radius=float(a)))
                out["pull_off"].append(dict(set=set_name, law=name, delta_max=dm, work=0.5,
                                            pull_off=float(jkr_pull_off(law, mp.mpf(dm)))))
    gold = SETS["gold"]
    for name in ("kogut-etsion", "jackson-green", "chang-etsion-bogy", "zhao-maietta-chang"):
        law = Law(name, gold)
        for h in (-1.5, 0.0, 1.0, 2.5):
            d = float(h * 5e-9)
            L, A, N, rel = gw(law, mp.mpf(d))
            out["gw"].append(dict(law=name, separation=d, closest=None,
                                  load=float(L), area=float(A), count=float(N),
                                  quad_rel_error=float(rel)))
        for h, hc in ((0.5, -0.5), (0.0, -1.5)):
            d, c = float(h * 5e-9), float(hc * 5e-9)
            L, A, N, rel = gw(law, mp.mpf(d), mp.mpf(c))
            out["gw"].append(dict(law=name, separation=d, closest=c,
                                  load=float(L), area=float(A), count=float(N),
                                  quad_rel_error=float(rel)))
    print(json.dumps(out, indent=1))


if __name__ == "__main__":
    main()
