"""Reference compliance matrix for src/sphere/compliance.rs, computed
independently with mpmath (30 digits): each entry
C_ij = mean_{[s_j, s_j+1]} D(r_i, .) - mean_{[s_j-1, s_j]} D(r_i, .)
(last column: D(r_i, s_last) - left mean), with
D(r, s) = (4/pi) s E(r^2/s^2) for r <= s and
D(r, s) = (4/pi) r [E(s^2/r^2) - (1 - s^2/r^2) K(s^2/r^2)] for r > s
(uniform disc, Johnson Contact Mechanics eq. 3.25), integrated by mpmath.quad
(tanh-sinh, which handles the logarithmic endpoint singularity at s = r).
Also the displacement of a uniform disc by direct quadrature of the ring
Green's function (4/pi) s/(r+s) K(4rs/(r+s)^2) (physics.md) as an independent
check of D itself.

Run: python3 tests/data/compliance.py > tests/data/compliance.json
"""
import json
import mpmath as mp

mp.mp.dps = 30
mesh = [0.0, 0.15, 0.4, 0.5, 0.55, 0.9, 1.6, 3.0]


def D(r, s):
    r = mp.mpf(r); s = mp.mpf(s)
    if s == 0:
        return mp.mpf(0)
    if r <= s:
        return 4 / mp.pi * s * mp.ellipe((r / s) ** 2)
    m = (s / r) ** 2
    return 4 / mp.pi * r * (mp.ellipe(m) - (1 - m) * mp.ellipk(m))


def mean(r, a, b):
    return mp.quad(lambda s: D(r, s), [a, b]) / (b - a)


n = len(mesh)
C = []
for i in range(n):
    row = []
    for j in range(n):
        right = mean(mesh[i], mesh[j], mesh[j + 1]) if j + 1 < n else D(mesh[i], mesh[j])
        left = mean(mesh[i], mesh[j - 1], mesh[j]) if j > 0 else 0
        row.append(repr(float(right - left)))
    C.append(row)

# D from the ring Green's function, for r and s not equal.
ring = []
for (r, s) in [(0.3, 1.0), (1.0, 0.3), (0.999, 1.0), (2.0, 1.0), (0.0, 1.0)]:
    g = lambda t: 4 / mp.pi * t / (r + t) * mp.re(mp.ellipk(min(4 * r * t / (r + t) ** 2, mp.mpf(1) - mp.mpf(10) ** -28)))
    pts = [0, r, s] if 0 < r < s else [0, s]
    val = mp.quad(g, pts)
    ring.append({"r": r, "s": s, "d": repr(float(val)), "d_closed": repr(float(D(r, s)))})

print(json.dumps({
    "source": "mpmath %s, dps 30, tanh-sinh quadrature" % mp.__version__,
    "script": "tests/data/compliance.py",
    "mesh": mesh,
    "c": C,
    "ring": ring,
}, indent=1))
