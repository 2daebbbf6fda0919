"""Reference for the order-statistic intervals of a quantile
(src/montecarlo/pull_off.rs, `quantile_ranks`, `widest_coverage`).

For a sample of n values from a continuous distribution, the order
statistics X_(r) <= X_(s) (1-based ranks, r < s) enclose the true
q-quantile with probability P(r <= B <= s - 1), B ~ Bin(n, q): a direct
binomial sum, here in mpmath at 50 digits. Every pair of ranks is tried
(no search shortcut): the shortest (s - r least) whose coverage is >= 0.95,
of equal lengths the largest coverage, then the lowest r. Where no pair
reaches 0.95 the widest pair's coverage 1 - (1-q)^n - q^n is stored.

Also stored: the exact coverage of the interval the code gave before
(ranks floor(nq - 1.96 sqrt(nq(1-q))) and ceil(nq + 1.96 sqrt(...)) + 1,
clamped to [1, n]), for the record.

Run: python tests/data/quantile_intervals.py > tests/data/quantile_intervals.json
"""
import json
import math
from mpmath import mp, mpf, binomial

mp.dps = 50
LEVEL = mpf("0.95")


def pmf(n, q):
    q = mpf(q)
    return [binomial(n, k) * q**k * (1 - q) ** (n - k) for k in range(n + 1)]


def coverage(p, r, s):
    # P(r <= B <= s - 1), summed term by term
    return mp.fsum(p[r:s])


def shortest(n, q):
    p = pmf(n, q)
    cum = [mpf(0)]
    for v in p:
        cum.append(cum[-1] + v)
    for width in range(1, n):
        best = None
        for r in range(1, n - width + 1):
            c = cum[r + width] - cum[r]
            if best is None or c > best[2]:
                best = (r, r + width, c)
        if best[2] >= LEVEL:
            r, s, _ = best
            return r, s, coverage(p, r, s)
    return None


def old_interval(n, q):
    half = 1.959963984540054 * math.sqrt(n * q * (1 - q))
    clamp = lambda r: int(max(1.0, min(float(n), r)))
    r = clamp(math.floor(n * q - half))
    s = clamp(math.ceil(n * q + half) + 1.0)
    return r, s, coverage(pmf(n, q), r, s) if s > r else mpf(0)


cases = []
for n in (5, 20, 100, 1000):
    for q in (0.05, 0.5, 0.95):
        got = shortest(n, q)
        o = old_interval(n, q)
        case = {
            "n": n,
            "q": q,
            "widest_coverage": float(1 - (1 - mpf(q)) ** n - mpf(q) ** n),
            "old_normal_ranks": [o[0], o[1]],
            "old_normal_coverage": float(o[2]),
        }
        if got is None:
            case.update(lower=None, upper=None, coverage=None)
        else:
            case.update(lower=got[0], upper=got[1], coverage=float(got[2]))
        cases.append(case)
print(json.dumps({"level": 0.95, "cases": cases}, indent=1))
