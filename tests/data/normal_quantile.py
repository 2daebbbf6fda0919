"""Dense mpmath reference of the standard normal quantile Phi^-1(p).

p: 200 values log-spaced in [1e-300, 0.4] and their complements 1 - p (as
doubles), and 101 values uniform in [0.05, 0.95]; the quantile solves
log Phi(s) = log p (relative, so the far tails converge) at 50 digits.
Checks `asperity::special::normal::quantile` (Wichura's AS 241) in
tests/it/gaussian_fn.rs. Run: python tests/data/normal_quantile.py
"""
import json
import os

import mpmath as mp

mp.mp.dps = 50


def quantile(p):
    p = mp.mpf(p)
    guess = -mp.sqrt(-2 * mp.log(p)) if p < 0.5 else mp.sqrt(-2 * mp.log(1 - p)) if p > 0.5 else mp.mpf(0)
    if p > 0.5:
        # upper tail: solve log Q(s) = log(1 - p) instead
        s = mp.findroot(lambda x: mp.log(mp.erfc(x / mp.sqrt(2)) / 2) - mp.log(1 - p), guess)
    else:
        s = mp.findroot(lambda x: mp.log(mp.erfc(-x / mp.sqrt(2)) / 2) - mp.log(p), guess)
    return s


def main():
    ps = []
    for k in range(200):
        e = -300 + k * (300 + mp.log10(0.4)) / 199
        p = float(mp.mpf(10) ** e)
        ps += [p, 1.0 - p]
    ps += [0.05 + 0.009 * k for k in range(101)]
    rows = [{"p": p, "quantile": mp.nstr(quantile(p), 25)} for p in ps if 0.0 < p < 1.0]
    out = {
        "description": __doc__,
        "source": "tests/data/normal_quantile.py, mpmath " + mp.__version__ + ", 50 digits",
        "rows": rows,
    }
    with open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "normal_quantile.json"), "w") as f:
        json.dump(out, f, indent=1)


if __name__ == "__main__":
    main()
