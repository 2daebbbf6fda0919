"""Reference values of the Struve functions H0(x), H1(x) from mpmath struveh at 50 digits,
for src/special/struve.rs (tests/it/struve.rs).

Run: python3 tests/data/struve.py > tests/data/struve.json

x: 400 log-spaced points on [1e-6, 1e6], a dense uniform grid on [0, 60] (step 0.0625 plus an
irrational offset, so it never hits a table node), points just below and above the regime edges
2 and 50, and large arguments up to 1e6 as used by the wavy punch (2 pi a / l). The x are f64s
written with repr and evaluated exactly as those binary numbers; values are strings rounded to 20
significant digits (str::parse rounds them correctly).
"""
import json
import mpmath as mp

mp.mp.dps = 50
xs = set()
for i in range(400):
    xs.add(float(mp.mpf(10) ** (-6 + 12 * mp.mpf(i) / 399)))
for i in range(961):
    xs.add(0.0625 * i + 0.0123456789)
for e in [2.0, 50.0]:
    for d in [-1e-9, -1e-6, -1e-3, 0.0, 1e-6, 1e-3]:
        xs.add(e + d)
for x in [123.456, 1000.0, 2718.28, 31415.9, 1e5 + 0.5, 654321.0, 1e6]:
    xs.add(x)
rows = []
for x in sorted(xs):
    m = mp.mpf(x)
    rows.append({"x": repr(x), "h0": mp.nstr(mp.struveh(0, m), 20), "h1": mp.nstr(mp.struveh(1, m), 20)})
print(json.dumps({"source": "mpmath %s struveh, mp.dps = 50" % mp.__version__,
                  "script": "tests/data/struve.py", "rows": rows}, indent=0))
