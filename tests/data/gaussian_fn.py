"""Reference values for src/special (Gaussian F_n, Q, erfc, Gamma) with mpmath at 50 digits.

F_n(h) = int_h^inf (s-h)^n phi(s) ds, phi the standard normal density, for n in
{0, 1/2, 1, 3/2, 2, 5/2}; two independent mpmath evaluations that must agree to 1e-30:
  (a) closed form Gamma(n+1)/sqrt(2 pi) exp(-h^2/4) D_(-n-1)(h)   (mp.pcfd)
  (b) direct quadrature mp.quad of (s-h)^n phi(s) on split intervals (in t = s - h).
Grid: h = -5 .. 10 step 0.25, 10.5 .. 37 step 0.5, plus extra points outside [-5, 37]
(-50, -30, -25, -21, -20, -12, -9.5, -9, -8.5, -7, -6, 37.25, 37.5, 38) and off-grid points
next to the method switches at +-20 and 12.
Also: erfc(x) (mp.erfc), Gamma(x), ln Gamma(x), normal quantiles.
Writes gaussian_fn.json next to this script. Run: python3 tests/data/gaussian_fn.py
"""
import json, os
import mpmath as mp

mp.mp.dps = 50
SQ2PI = mp.sqrt(2 * mp.pi)
NS = ["0", "0.5", "1", "1.5", "2", "2.5"]


def f_pcf(n, h):
    return mp.gamma(n + 1) / SQ2PI * mp.exp(-h * h / 4) * mp.pcfd(-n - 1, h)


def f_quad(n, h):
    # phi(h) int_0^inf t^n exp(-h t - t^2/2) dt, panels scaled to the decay length 1/max(h, 1)
    g = lambda t: t ** n * mp.exp(-h * t - t * t / 2)
    w = 1 / max(h, mp.mpf(1))
    pts = [0] + [w * 2 ** k for k in range(-3, 8)] + [mp.inf]
    if h < 0:
        pts = sorted(set(pts + [-h]))
    return mp.exp(-h * h / 2) / SQ2PI * mp.quad(g, pts)


def main():
    hs = [mp.mpf(-5) + mp.mpf(k) / 4 for k in range(61)]
    hs += [mp.mpf(10) + mp.mpf(k) / 2 for k in range(1, 55)]
    extra = ["-50", "-30", "-25", "-21", "-20.001", "-19.999", "-20", "-12", "19.999", "20.001", "-9.5", "-9", "-8.5", "-7", "-6", "-0.3333", "0.1", "1.7",
             "3.14159", "11.999", "12.001", "37.25", "37.5", "38"]
    hs += [mp.mpf(float(mp.mpf(x))) for x in extra]  # exactly the double the test uses
    table = {}
    worst = mp.mpf(0)
    for ns in NS:
        n = mp.mpf(ns)
        rows = []
        for h in hs:
            a = f_pcf(n, h)
            if h <= 37:
                b = f_quad(n, h)
                worst = max(worst, abs(a / b - 1))
            rows.append({"h": float(h), "F": mp.nstr(a, 25)})
        table[ns] = rows
    assert worst < 1e-30, worst
    erfc = [{"x": float(x), "erfc": mp.nstr(mp.erfc(x), 25)}
            for x in [mp.mpf(k) / 4 for k in range(-16, 109)]]
    gam = [{"x": x, "gamma": mp.nstr(mp.gamma(x), 25), "ln_gamma": mp.nstr(mp.log(abs(mp.gamma(x))), 25)}
           for x in [0.001, 0.1, 0.3, 0.7, 1.3, 1.9, 2.2, 3.7, 7.25, 11.9, 12.0, 15.5, 33.3, 100.7,
                     170.5, -0.5, -1.3, -2.7, -11.5, -13.5, 1e-8]]
    quant = []
    for p in ["1e-300", "1e-100", "1e-20", "1e-5", "0.01", "0.02425", "0.2", "0.5", "0.7", "0.97575", "0.999"]:
        p = mp.mpf(float(mp.mpf(p)))
        # solve log Phi(x) = log p (relative, so the far tail converges properly)
        guess = -mp.sqrt(-2 * mp.log(p)) if p < 0.5 else mp.mpf(0)
        s = mp.findroot(lambda x: mp.log(mp.erfc(-x / mp.sqrt(2)) / 2) - mp.log(p), guess)
        assert abs(mp.erfc(-s / mp.sqrt(2)) / 2 / p - 1) < mp.mpf(10) ** -40
        quant.append({"p": float(p), "quantile": mp.nstr(s, 25)})
    out = {
        "description": __doc__,
        "source": "tests/data/gaussian_fn.py, mpmath " + mp.__version__ + ", 50 digits",
        "max_rel_diff_pcfd_vs_quad": float(worst),
        "F": table,
        "erfc": erfc,
        "gamma": gam,
        "normal_quantile": quant,
    }
    with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "gaussian_fn.json"), "w") as f:
        json.dump(out, f, indent=1)


if __name__ == "__main__":
    main()
