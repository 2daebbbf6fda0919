#!/usr/bin/env python3
"""Independent references for capillary (meniscus) adhesion (mpmath, 30 digits).

Not the solver: every quantity is computed here from its defining formula.

1. Kelvin radius r_K = gamma V_m / (R_g T ln(1/RH)), Laplace pressure gamma/r_K.
2. Rigid sphere with the equilibrium meniscus: the wetted radius from the
   sphere's gap R - sqrt(R^2 - r_c^2) = h_m - D (solved with findroot, not
   the closed form), load -(pi dp r_c^2 + 2 pi r_c gamma sin(phi + theta_1)),
   sin(phi) = r_c/R.
3. The elastic sphere held by the meniscus: Maugis-Dugdale with
   (sigma0, delta_t) = (dp, h_m), Maugis's equations (1)-(3) in Maugis units
   solved for m at each A, the pull-off the minimum of Pbar (findroot on
   mp.diff), converted to SI.
4. The two-zone contact at given contact radius a (or central gap g0):
   the gap h(r) = (2/pi) int_a^r [t^2/R - delta + (2/E*) g(t)]/sqrt(r^2-t^2) dt
   with g(t) = -sum sigma_i sqrt(c_i^2 - t^2)_+, integrated by mp.quad
   (t = r sin psi), Dugdale's conditions h(c_i) = range_i solved by findroot.
   The one-zone case is also checked here against Maugis's eq. (1).
Writes capillary.json next to this script.
"""
import json
import os
from mpmath import mp, mpf, sqrt, log, pi, asin, acos, sin, cos, quad, findroot, diff, atan, cbrt

mp.dps = 30
RG = mpf("8.314462618")


def kelvin(gamma, vm, temp, rh):
    return gamma * vm / (RG * temp * log(1 / mpf(rh)))


def rigid_load(R, gamma, th1, th2, rk, D):
    hm = rk * (cos(th1) + cos(th2))
    dp = gamma / rk
    if D >= hm:
        return mpf(0)
    hi = min(R, 2 * sqrt(2 * R * (hm - D)))
    rc = findroot(lambda x: (hm - D) - x * x / (R + sqrt(R * R - x * x)), (mpf(0), hi), solver="anderson")
    phi = asin(rc / R)
    return -(pi * dp * rc ** 2 + 2 * pi * rc * gamma * sin(phi + th1))


def md_pull_off(lam):
    def m_of_a(a):
        def f(m):
            s = sqrt(m * m - 1)
            t = atan(s)
            return (lam * a * a / 2 * (s + (m * m - 2) * t)
                    + 4 * lam * lam * a / 3 * (s * t - m + 1) - 1)
        lo = 1 + mpf(10) ** -25
        hi = mpf(2)
        while f(hi) < 0:
            hi *= 2
        return findroot(f, (lo, hi), solver="illinois", maxsteps=500)

    def pbar(a):
        m = m_of_a(a)
        s = sqrt(m * m - 1)
        return a ** 3 - lam * a * a * (s + m * m * atan(s))

    # coarse scan, then the root of dPbar/dA
    grid = [mpf(10) ** (k / mpf(20)) for k in range(-60, 41)]
    vals = [pbar(a) for a in grid]
    k = min(range(len(vals)), key=lambda i: vals[i])
    a0 = findroot(lambda a: diff(pbar, a), grid[k])
    return pbar(a0)


def gap(r, a, g0, R, E, zones, cs, delta):
    # (2/pi) int_a^r [t^2/R - delta + (2/E) g(t)] / sqrt(r^2 - t^2) dt,
    # with t = r sin(psi); for a = 0 the non-contact form (delta given).
    def integrand(psi):
        t = r * sin(psi)
        g = mpf(0)
        for (sig, rng), c in zip(zones, cs):
            if c > t:
                g -= sig * sqrt(c * c - t * t)
        return t * t / R - delta + 2 / E * g
    lo = asin(a / r) if a > 0 else mpf(0)
    pts = [lo]
    for c in cs:
        if lo < asin(min(c / r, 1)) < pi / 2:
            pts.append(asin(c / r))
    pts.append(pi / 2)
    return 2 / pi * quad(integrand, sorted(pts))


def two_zone(R, E, zones, s):
    a = s if s > 0 else mpf(0)
    g0 = -s if s < 0 else mpf(0)
    act = [z for z in zones if g0 < z[1]]

    def delta_of(cs):
        d = a * a / R - g0
        for (sig, rng), c in zip(act, cs):
            d -= 2 * sig / E * sqrt(c * c - a * a)
        return d

    def eqs(*cs):
        d = delta_of(cs)
        return [gap(c, a, g0, R, E, act, cs, d) - rng for (sig, rng), c in zip(act, cs)]

    # start: Hertz-like guesses
    guess = [a + sqrt(2 * R * rng) * mpf("0.7") for (sig, rng) in act]
    cs = findroot(eqs, guess) if len(act) > 1 else [findroot(lambda c: eqs(c)[0], guess[0])]
    cs = [mpf(c) for c in (cs if len(act) > 1 else cs)]
    d = delta_of(cs)
    P = 4 * E * a ** 3 / (3 * R)
    for (sig, rng), c in zip(act, cs):
        P -= 2 * sig * (c * c * acos(a / c) + a * sqrt(c * c - a * a))
    return {"s": float(s), "delta": float(d), "load": float(P), "c": [float(c) for c in cs]}


def maugis_eq1_residual(R, E, sig, rng, a, c):
    # one zone: Maugis's (1) in SI: gap at c equals the range
    K = 4 * E / 3
    w = sig * rng
    lam = 2 * sig * cbrt(R / (pi * w * K * K))
    A = a * cbrt(K / (pi * w * R * R))
    m = c / a
    s_ = sqrt(m * m - 1)
    t = atan(s_)
    return lam * A * A / 2 * (s_ + (m * m - 2) * t) + 4 * lam * lam * A / 3 * (s_ * t - m + 1) - 1


def main():
    out = {}
    gamma, vm, temp = mpf("0.0728"), mpf("1.8e-5"), mpf("293.15")
    out["kelvin"] = [{"rh": rh, "r_k": float(kelvin(gamma, vm, temp, rh))} for rh in (0.1, 0.5, 0.9)]
    # rigid pull-off as r_K/R -> 0, theta_1 = theta_2 = 0 and 30/60 degrees
    R = mpf("1e-6")
    rig = []
    for th1d, th2d in ((0, 0), (30, 60)):
        th1, th2 = th1d * pi / 180, th2d * pi / 180
        for ratio in ("1e-3", "1e-9", "1e-14", "1e-19"):
            rk = R * mpf(ratio)
            for frac in (0, "0.25", "0.5", "0.9"):
                hm = rk * (cos(th1) + cos(th2))
                D = hm * mpf(frac)
                rig.append({"theta_1_deg": th1d, "theta_2_deg": th2d, "r_k": float(rk),
                            "gap": float(D), "load": float(rigid_load(R, gamma, th1, th2, rk, D)),
                            "derjaguin": float(2 * pi * R * gamma * (cos(th1) + cos(th2)))})
    out["rigid"] = rig
    # elastic sphere with the meniscus: MD with (dp, h_m)
    el = []
    for R_, E_, rh in (("1e-6", "48e9", 0.5), ("1e-6", "48e9", 0.9), ("1e-5", "1e9", 0.3)):
        R_, E_ = mpf(R_), mpf(E_)
        rk = kelvin(gamma, vm, temp, rh)
        dp, hm = gamma / rk, 2 * rk
        w = dp * hm
        K = 4 * E_ / 3
        lam = 2 * dp * cbrt(R_ / (pi * w * K * K))
        pb = md_pull_off(lam)
        el.append({"radius": float(R_), "modulus": float(E_), "rh": rh, "lambda": float(lam),
                   "pull_off": float(pb * pi * w * R_)})
    out["elastic"] = el
    # two-zone points
    R_, E_ = mpf("1e-6"), mpf("48e9")
    rk = kelvin(gamma, vm, temp, 0.5)
    men = (gamma / rk, 2 * rk)
    w_s, z0 = mpf("0.5"), mpf("0.3e-9")
    sig_s = 16 * w_s / (9 * sqrt(3) * z0)
    sol = (sig_s, w_s / sig_s)
    tz = []
    for s in ("-1.2e-9", "-0.5e-9", "-0.1e-9", "1e-9", "5e-9", "2e-8", "1e-7"):
        p = two_zone(R_, E_, [men, sol], mpf(s))
        tz.append(p)
    one = []
    for s in ("-0.5e-9", "2e-9", "2e-8", "1e-7"):
        p = two_zone(R_, E_, [men], mpf(s))
        if mpf(s) > 0:
            p["maugis_eq1_residual"] = float(maugis_eq1_residual(R_, E_, men[0], men[1], mpf(s), mpf(p["c"][0])))
        one.append(p)
    out["two_zone"] = {"radius": float(R_), "modulus": float(E_),
                       "zones": [[float(men[0]), float(men[1])], [float(sol[0]), float(sol[1])]],
                       "both": tz, "meniscus_only": one}
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "capillary.json")
    with open(path, "w") as f:
        json.dump(out, f, indent=1)
    print(json.dumps(out, indent=1)[:3000])


main()
