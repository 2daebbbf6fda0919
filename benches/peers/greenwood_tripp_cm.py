"""ContactMechanics' GreenwoodTripp (1.8.3) side by side with `asperity rough-sphere`
on the same points: CPU time and the load's difference from the independent
reference of tests/data/rough_sphere.py (converged to < 5e-9).

ContactMechanics.ReferenceSolutions.GreenwoodTripp.GreenwoodTripp(d, mu, rhomax=5,
n=100, tol=1e-6, mix=0.1) iterates p <- mix mu F_3/2(d + rho^2 + w - w0) + (1 - mix) p
on 100 uniform points to rho = 5 (F_n by scipy quad, the displacement by Simpson's rule
in a mapped variable) until the pressure changes by < 1e-6; it returns w - w0, p, rho.
Its load here is 2 pi int p rho drho by Simpson's rule on its own points. It is run
with its defaults (a user's first call) and, where the contact reaches beyond rho = 5,
again with rhomax set to the reference's outer radius.

asperity is run through its command line, one process per point (cold start: the
process, the compliance assembly, the solve), CPU time of the child from
resource.getrusage; the warm per-state and per-curve times are in
`cargo bench --bench rough_sphere`.

Run (several minutes; ContactMechanics takes seconds to minutes per point):
  cargo build --release
  /work/venv-peers/bin/python benches/peers/greenwood_tripp_cm.py > benches/peers/greenwood_tripp_cm.json
"""
import json
import os
import resource
import subprocess
import sys
import time

import numpy as np
from scipy.integrate import simpson

from ContactMechanics.ReferenceSolutions.GreenwoodTripp import GreenwoodTripp

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
POINTS = [(0.1, 0.0), (1.0, 0.0), (1.0, -1.0), (1.0, 2.0), (10.0, 0.0), (10.0, -1.0), (100.0, 0.5)]


def reference():
    with open(os.path.join(ROOT, "tests", "data", "rough_sphere.json")) as f:
        data = json.load(f)
    return {(c["mu"], c["d"]): c for c in data["cases"]}


def cm(mu, d, rhomax):
    t0 = time.process_time()
    try:
        w, p, rho = GreenwoodTripp(d, mu, rhomax=rhomax)
        load = float(2 * np.pi * simpson(p * rho, x=rho))
    except RuntimeError as e:  # its iteration limit
        load = float("nan")
        print(f"ContactMechanics mu={mu} d={d} rhomax={rhomax}: {e}", file=sys.stderr)
    return load, time.process_time() - t0


def asperity(mu, d):
    exe = os.path.join(ROOT, "target", "release", "asperity")
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    out = subprocess.run([exe, "rough-sphere", "--mu", str(mu), "--d", str(d), "--json", "--errors"],
                         check=True, capture_output=True, text=True).stdout
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    s = json.loads(out)["states"][0]
    return s["load"], s["load_error"], cpu


def main():
    ref = reference()
    rows = []
    for mu, d in POINTS:
        c = ref[(mu, d)]
        exact = c["load"]
        a_load, a_err, a_cpu = asperity(mu, d)
        cm_load, cm_cpu = cm(mu, d, 5)
        row = {"mu": mu, "d": d, "reference_load": exact, "reference_rho_max": c["rho_max"],
               "asperity_load": a_load, "asperity_error_estimate": a_err,
               "asperity_rel_diff": abs(a_load - exact) / exact, "asperity_cpu_s": a_cpu,
               "cm_load": cm_load, "cm_rel_diff": abs(cm_load - exact) / exact, "cm_cpu_s": cm_cpu}
        if c["rho_max"] > 5:
            l2, t2 = cm(mu, d, c["rho_max"])
            row.update({"cm_wide_rhomax": c["rho_max"], "cm_wide_load": l2,
                        "cm_wide_rel_diff": abs(l2 - exact) / exact, "cm_wide_cpu_s": t2})
        print(json.dumps(row), file=sys.stderr)
        rows.append(row)
    json.dump({
        "source": "benches/peers/greenwood_tripp_cm.py: ContactMechanics 1.8.3 GreenwoodTripp "
                  "against asperity rough-sphere, loads against tests/data/rough_sphere.json",
        "cpu": open("/proc/cpuinfo").read().split("model name")[1].split("\n")[0].strip(": \t"),
        "rows": rows,
    }, sys.stdout, indent=1)


if __name__ == "__main__":
    main()
