"""Where the Tamaas/asperity ratio on the 256^2 map comes from: iterations and cost per iteration.

    target/peers-venv/bin/python benches/peers/tamaas_iterations.py > benches/peers/tamaas_iterations.json

(venv as in tamaas_bem.py: tamaas==2.9.0 numpy; `cargo build --release --example bem_rough_time` first.)
The same problem as tamaas_bem.py's 256^2 rows (examples/data/selfaffine-256.npy, periodic, L = 100 um,
E* = 1 GPa, p = 0.01 E*), one thread each. Tamaas' iteration count is read from its own convergence log
(log level info, captured from file descriptor 2); its cost of one convolution is `Model.solveNeumann()`
(the pressure-to-displacement operator, FFT forward and inverse) timed over REPS calls. asperity's
iterations and CPU come from `bem_rough_time` (the mean CPU of five solves a call: its counter,
`/proc/self/stat`, ticks every 10 ms). CPU times are process CPU (time.process_time, /proc/self/stat),
medians over REPS calls, the two solvers in turns.
"""
import json
import os
import platform
import re
import subprocess
import sys
import tempfile
import time

os.environ.setdefault("OMP_NUM_THREADS", "1")
import numpy as np  # noqa: E402
import tamaas as tm  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
BIN = os.path.join(ROOT, "target", "release", "examples", "bem_rough_time")
MAP = os.path.join(ROOT, "examples", "data", "selfaffine-256.npy")
L, ESTAR = 1e-4, 1e9
REPS = int(os.environ.get("REPS", "5"))


def tamaas_solve(surface, tol):
    """(CPU s, iterations) of one PolonskyKeerRey solve, its log captured from fd 2."""
    n = surface.shape[0]
    m = tm.ModelFactory.createModel(tm.model_type.basic_2d, [L, L], [n, n])
    m.E, m.nu = ESTAR, 0.0
    solver = tm.PolonskyKeerRey(m, surface, tol)
    solver.max_iter = 100000
    tm.set_log_level(tm.LogLevel.info)
    sys.stderr.flush()
    saved = os.dup(2)
    with tempfile.TemporaryFile(mode="w+") as log:
        os.dup2(log.fileno(), 2)
        try:
            t = time.process_time()
            solver.solve(0.01 * ESTAR)
            cpu = time.process_time() - t
        finally:
            sys.stderr.flush()
            os.dup2(saved, 2)
            os.close(saved)
        log.seek(0)
        rows = re.findall(r"^\s*(\d+)\s+\S+\s+\S+\s*$", log.read(), re.M)
    tm.set_log_level(tm.LogLevel.error)
    return cpu, int(rows[-1])


def tamaas_convolution(n, reps=200):
    m = tm.ModelFactory.createModel(tm.model_type.basic_2d, [L, L], [n, n])
    m.E, m.nu = ESTAR, 0.0
    m.traction[:] = np.random.default_rng(0).random((n, n))
    t = time.process_time()
    for _ in range(reps):
        m.solveNeumann()
    return (time.process_time() - t) / reps


def asperity_solve(tol):
    env = dict(os.environ, RAYON_NUM_THREADS="1")
    # Five solves a call: their mean CPU (the counter ticks every 10 ms).
    out = subprocess.run([BIN, "5", repr(tol), MAP, repr(L)], cwd=ROOT, env=env,
                         capture_output=True, text=True, check=True).stdout
    return json.loads(out)


def main():
    surface = np.load(MAP)
    rows = []
    for tol in (1e-6, 1e-8, 1e-12):
        t_cpu, a_cpu, t_it, a_it = [], [], None, None
        for _ in range(REPS):
            cpu, t_it = tamaas_solve(surface, tol)
            t_cpu.append(cpu)
            a = asperity_solve(tol)
            a_cpu.append(a["cpu_s_mean"])
            a_it = a["iterations"]
        tm_med, as_med = float(np.median(t_cpu)), float(np.median(a_cpu))
        rows.append({
            "tolerance": tol,
            "tamaas": {"iterations": t_it, "cpu_s_median": tm_med, "ms_per_iteration": 1e3 * tm_med / t_it},
            "asperity": {"iterations": a_it, "cpu_s_median": as_med, "ms_per_iteration": 1e3 * as_med / a_it},
            "ratio_tamaas_over_asperity": tm_med / as_med,
        })
        print(f"tol {tol:g}: Tamaas {t_it} it {tm_med:.3f} s ({1e3 * tm_med / t_it:.2f} ms/it), asperity {a_it} it "
              f"{as_med:.3f} s ({1e3 * as_med / a_it:.2f} ms/it), {tm_med / as_med:.1f}x", file=sys.stderr)
    conv = tamaas_convolution(surface.shape[0])
    print(f"Tamaas solveNeumann 256^2: {1e3 * conv:.2f} ms CPU", file=sys.stderr)
    json.dump({
        "script": "benches/peers/tamaas_iterations.py",
        "date": time.strftime("%Y-%m-%d"),
        "cpu": platform.processor() or open("/proc/cpuinfo").read().split("model name")[1].split("\n")[0].strip(": \t"),
        "load_average": os.getloadavg(),
        "tamaas": tm.__version__,
        "map": os.path.relpath(MAP, ROOT),
        "reps": REPS,
        "rows": rows,
        "tamaas_convolution_ms": 1e3 * conv,
    }, sys.stdout, indent=1)
    print()


if __name__ == "__main__":
    main()
