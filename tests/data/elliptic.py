"""Reference values of the complete elliptic integrals K(m), E(m) (parameter
convention) from mpmath at 330 digits, for src/special/elliptic.rs.

Run: python3 tests/data/elliptic.py > tests/data/elliptic.json

Numbers are strings (Python repr, shortest round trip) so that the Rust test
parses them with the correctly rounded str::parse rather than a JSON float
reader. Each row gives the complementary parameter m1 = 1 - m exactly as the f64 the
Rust test passes to `ellip_ke_comp`, and also m (an f64 that is 1 - m1 rounded)
with K, E evaluated at that rounded m for `ellip_ke`.
"""
import json
import mpmath as mp

mp.mp.dps = 330  # m = 1 - m1 must keep m1 down to 1e-300

rows = []
m1s = []
for e in range(-300, 1, 7):
    m1s.append(10.0 ** e)
for x in [1e-17, 3e-16, 1e-12, 2.5e-9, 1e-6, 1e-4, 3e-3, 0.01, 0.05, 0.0999, 0.1, 0.1001,
          0.2, 0.3, 0.5, 0.7, 0.9, 0.99, 0.999999, 1.0, 1.5, 2.0, 5.0, 10.0]:
    m1s.append(x)
for m1 in sorted(set(m1s)):
    m1m = mp.mpf(m1)
    m_exact = 1 - m1m
    m = float(1.0 - m1)  # what f64 code gets when it computes 1 - m1
    mm = mp.mpf(m)
    row = {
        "m1": repr(m1),
        "k_comp": repr(float(mp.ellipk(m_exact))),
        "e_comp": repr(float(mp.ellipe(m_exact))),
        "m": repr(m),
        "k": repr(float(mp.ellipk(mm))) if mm < 1 else None,  # K(1) = inf
        "e": repr(float(mp.ellipe(mm))),
    }
    rows.append(row)

print(json.dumps({
    "source": "mpmath %s, mp.dps = 330: ellipk(m), ellipe(m), m = 1 - m1" % mp.__version__,
    "script": "tests/data/elliptic.py",
    "rows": rows,
}, indent=1))
