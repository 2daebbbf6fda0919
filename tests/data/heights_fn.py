"""Reference F_n(h) = int_h^inf (s-h)^n phi(s) ds for the non-Gaussian height distributions
of src/heights, with mpmath at 40 digits (independent of the Rust code paths).

- weibull: phi(s) = (k/lam)(s/lam)^(k-1) exp(-(s/lam)^k), s >= 0, lam = 1/sqrt(G(1+2/k) - G(1+1/k)^2)
  (unit standard deviation); F_n by mp.quad in y = (s/lam)^k: int_{y_h}^inf (lam y^(1/k) - h)^n e^-y dy.
- truncated-gaussian: phi(s)/Z on [-k, k], Z = erf(k/sqrt 2); F_n = mp.quad over [max(h,-k), k].
- exponential: F_n(h) = e^-h Gamma(n+1, max(-h, 0)) ... = e^(-h) * gammainc(n+1, -h) for h < 0
  (mp.gammainc upper incomplete), Gamma(n+1) e^-h for h >= 0.
Writes heights_fn.json next to this script. Run: python3 tests/data/heights_fn.py
"""
import json, os
import mpmath as mp

mp.mp.dps = 40
NS = [0, 0.5, 1, 1.5, 2, 2.5, 0.3, 3]


def weibull(k, n, h):
    k = mp.mpf(k); n = mp.mpf(n); h = mp.mpf(h)
    lam = 1 / mp.sqrt(mp.gamma(1 + 2 / k) - mp.gamma(1 + 1 / k) ** 2)
    y0 = (h / lam) ** k if h > 0 else mp.mpf(0)
    f = lambda y: max(lam * y ** (1 / k) - h, 0) ** n * mp.exp(-y)
    return lam, mp.quad(f, [y0, y0 + 0.01, y0 + 0.1, y0 + 1, y0 + 4, y0 + 16, mp.inf])


def truncated(k, n, h):
    k = mp.mpf(k); n = mp.mpf(n); h = mp.mpf(h)
    if h >= k:
        return mp.mpf(0)
    z = mp.erf(k / mp.sqrt(2))
    lo = max(h, -k)
    f = lambda s: (s - h) ** n * mp.exp(-s * s / 2) / mp.sqrt(2 * mp.pi)
    return mp.quad(f, mp.linspace(lo, k, 6)) / z


def exponential(n, h):
    n = mp.mpf(n); h = mp.mpf(h)
    if h >= 0:
        return mp.gamma(n + 1) * mp.exp(-h)
    return mp.exp(-h) * mp.gammainc(n + 1, -h)


def main():
    out = {"description": __doc__, "source": "tests/data/heights_fn.py, mpmath " + mp.__version__ + ", 40 digits",
           "weibull": [], "truncated": [], "exponential": []}
    for k in [0.5, 1, 2, 3.5]:
        for n in NS:
            for h in [-2, -0.5, 0, 0.3, 1, 2.5, 5]:
                lam, v = weibull(k, n, h)
                out["weibull"].append({"k": k, "n": n, "h": h, "F": mp.nstr(v, 25), "lambda": mp.nstr(lam, 25)})
    for k in [1, 2.5, 4]:
        for n in NS:
            for h in [-5, -k, -1, 0, 0.5, k - 0.3, k - 0.01]:
                out["truncated"].append({"k": k, "n": n, "h": h, "F": mp.nstr(truncated(k, n, h), 25)})
    for n in NS + [4, 3.5, 7.5]:
        for h in [-30, -10, -3, -1, -0.25, 0, 0.5, 3, 40]:
            out["exponential"].append({"n": n, "h": h, "F": mp.nstr(exponential(n, h), 25)})
    with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "heights_fn.json"), "w") as f:
        json.dump(out, f, indent=1)


if __name__ == "__main__":
    main()
