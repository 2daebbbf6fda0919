#!/usr/bin/env python3
"""The numpy peer of `Topography::characterise` (`benches/surface.rs`).

Same work on the same map: the bench's 4096 x 4096 synthetic Gaussian
surface (correlation length 4 px, rms 1 nm, pixel 0.1 um, seed 1), which
the Rust timing example writes as `.npy`; then, non-periodic rules:

- mean plane z = c0 + c1 x + c2 y by least squares (decoupled normal
  equations about the centre, as `src/surface/plane.rs`), residual r;
- m0 = mean r^2; m2 = (mean (dr/dx)^2 + mean (dr/dy)^2) / 2 with forward
  differences inside the array; m4 likewise with 3-point second differences
  (`src/surface/moments.rs`);
- summits: interior pixels strictly above their 8 neighbours, curvature
  -(5-point Laplacian) / (2 dx^2); count, mean curvature, mean height and
  height standard deviation (divisor N) (`src/surface/summits.rs`).

Written the way a numpy user would (whole-array operations, float64, one
temporary per step); one thread (BLAS pinned to 1, numpy's elementwise
kernels do not thread). Timing: process CPU time (`time.process_time`),
median of REPEATS calls, the map already in memory. The asperity figure is
the CPU time per call of `tools/reports/surface_ns_per_pixel.rs` on a
1-thread rayon pool, run before and after the numpy runs (interleaved) and
the median of both runs' medians taken. Both answers are checked against
each other: summit count and the sum of their flat indices equal, moments, plane and summit
statistics to 1e-12 relative (roundoff of sums in another order).

End to end (the map read from its file, as a user runs it): the same
`.npy` through `asperity surface MAP.npy --pixel-size 1e-7 --json` against
a Python process doing `np.load` and `characterise` above, each a whole
process on one thread (`RAYON_NUM_THREADS=1`), run in turn (A B A B ...),
E2E_REPEATS each; CPU time (user + system) and peak resident memory of each
process from `/usr/bin/time`, medians quoted, and the numpy process's own
`np.load` + `characterise` CPU time (without the interpreter's start). The
answers are checked against each other (moments to 1e-12, summit count
equal).

Run from the repository root:
  cargo build --release --example surface_ns_per_pixel --bin asperity
  python3 benches/peers/surface_numpy.py        # needs numpy
Writes benches/peers/surface_numpy.json.
"""
import json
import os
import platform
import subprocess
import sys
import time

for var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ[var] = "1"

import numpy as np  # noqa: E402

SIDE = 4096
DX = 1e-7
REPEATS = 5
RUST_REPEATS = 9
EXAMPLE = "target/release/examples/surface_ns_per_pixel"
ASPERITY = "target/release/asperity"
E2E_REPEATS = 5
NUMPY_CHILD = """
import sys, time
t0 = time.process_time()
import numpy as np
sys.path.insert(0, {here!r})
from surface_numpy import characterise
t1 = time.process_time()
r = characterise(np.load({npy!r}), {dx!r})
t2 = time.process_time()
import json
print(json.dumps({{"m0": r["m0"], "m2": r["m2"], "m4": r["m4"], "summits": r["summits"],
                  "import_s": t1 - t0, "load_characterise_s": t2 - t1}}))
"""
NPY = "/tmp/asperity_surface_numpy_map.npy"
OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "surface_numpy.json")


def characterise(z, dx):
    rows, cols = z.shape
    jc, ic = (cols - 1) / 2.0, (rows - 1) / 2.0
    x = np.arange(cols) - jc
    y = np.arange(rows) - ic
    mean = z.mean()
    sxx = rows * cols * (cols * cols - 1) / 12.0
    syy = cols * rows * (rows * rows - 1) / 12.0
    cx = (z @ x).sum() / sxx
    cy = (y @ z).sum() / syy
    r = z - (mean + cx * x[None, :] + cy * y[:, None])
    m0 = np.mean(r * r)
    m2 = (np.mean(np.diff(r, axis=1) ** 2) + np.mean(np.diff(r, axis=0) ** 2)) / 2.0 / dx**2
    d2x = r[:, 2:] - 2.0 * r[:, 1:-1] + r[:, :-2]
    d2y = r[2:, :] - 2.0 * r[1:-1, :] + r[:-2, :]
    m4 = (np.mean(d2x * d2x) + np.mean(d2y * d2y)) / 2.0 / dx**4
    c = r[1:-1, 1:-1]
    top = np.ones(c.shape, dtype=bool)
    for di in (0, 1, 2):
        for dj in (0, 1, 2):
            if (di, dj) != (1, 1):
                top &= c > r[di : di + rows - 2, dj : dj + cols - 2]
    i, j = np.nonzero(top)
    i, j = i + 1, j + 1
    h = r[i, j]
    lap = r[i - 1, j] + r[i + 1, j] + r[i, j - 1] + r[i, j + 1] - 4.0 * h
    kappa = -lap / (2.0 * dx * dx)
    return {
        "c0": mean - cx * jc - cy * ic,
        "slope_x": cx / dx,
        "slope_y": cy / dx,
        "m0": m0,
        "m2": m2,
        "m4": m4,
        "summits": int(len(h)),
        "mean_curvature": kappa.mean(),
        "mean_height": h.mean(),
        "height_std": h.std(),
        "positions": (i, j),
    }


def rust_run(write_npy):
    args = [EXAMPLE, str(RUST_REPEATS), str(SIDE)] + ([NPY] if write_npy else [])
    env = dict(os.environ, RAYON_NUM_THREADS="1")
    return json.loads(subprocess.run(args, env=env, check=True, capture_output=True, text=True).stdout)


def whole_process(args, env):
    """Runs args under /usr/bin/time; its stdout, CPU seconds (user + system)
    and peak RSS (MiB). (A child forked from this process would start its
    peak RSS at this process's, which holds the map: /usr/bin/time's own
    child does not.)"""
    stats = "/tmp/asperity_surface_numpy_time.txt"
    timed = ["/usr/bin/time", "-f", "%U %S %M", "-o", stats] + args
    out = subprocess.run(timed, env=env, check=True, capture_output=True, text=True).stdout
    with open(stats) as f:
        user, system, kib = f.read().split()[-3:]
    os.remove(stats)
    return out, float(user) + float(system), float(kib) / 1024.0


def end_to_end(ours):
    """asperity surface MAP.npy against np.load + characterise, whole processes in turn."""
    env = dict(os.environ, RAYON_NUM_THREADS="1")
    here = os.path.dirname(os.path.abspath(__file__))
    child = NUMPY_CHILD.format(here=here, npy=NPY, dx=DX)
    a_cmd = [ASPERITY, "surface", NPY, "--pixel-size", repr(DX), "--json"]
    b_cmd = [sys.executable, "-c", child]
    a, b = [], []
    for k in range(E2E_REPEATS + 1):
        ra = whole_process(a_cmd, env)
        rb = whole_process(b_cmd, env)
        if k > 0:  # the first pair warms the page cache
            a.append(ra)
            b.append(rb)
    got = json.loads(a[-1][0])
    theirs = json.loads(b[-1][0])
    assert got["summits"]["count"] == ours["summits"] == theirs["summits"]
    worst = max(abs(got[k] - ours[k]) / abs(ours[k]) for k in ("m0", "m2", "m4"))
    worst = max([worst] + [abs(theirs[k] - ours[k]) / abs(ours[k]) for k in ("m0", "m2", "m4")])
    assert worst <= 1e-12, worst
    med = lambda v: float(np.median(v))  # noqa: E731
    a_cpu, b_cpu = med([r[1] for r in a]), med([r[1] for r in b])
    in_process = med([json.loads(r[0])["load_characterise_s"] for r in b])
    return {
        "command": " ".join(a_cmd),
        "file_mib": round(os.path.getsize(NPY) / 2**20, 1),
        "repeats": E2E_REPEATS,
        "asperity_cpu_s_median": round(a_cpu, 3),
        "asperity_peak_mib_median": round(med([r[2] for r in a]), 1),
        "numpy_process_cpu_s_median": round(b_cpu, 3),
        "numpy_process_peak_mib_median": round(med([r[2] for r in b]), 1),
        "numpy_load_characterise_cpu_s_median": round(in_process, 3),
        "ratio_numpy_process_over_asperity": round(b_cpu / a_cpu, 2),
        "ratio_numpy_in_process_over_asperity": round(in_process / a_cpu, 2),
        "largest_relative_difference": worst,
    }


def cpu_model():
    try:
        out = subprocess.run(["lscpu"], capture_output=True, text=True).stdout
        return next(l.split(":", 1)[1].strip() for l in out.splitlines() if l.startswith("Model name"))
    except (OSError, StopIteration):
        return platform.processor()


def main():
    for exe in (EXAMPLE, ASPERITY):
        if not os.path.exists(exe):
            sys.exit(f"{exe} missing: cargo build --release --example surface_ns_per_pixel --bin asperity")
    first = rust_run(write_npy=True)
    z = np.load(NPY)
    assert z.shape == (SIDE, SIDE) and z.dtype == np.float64
    times = []
    for _ in range(REPEATS):
        t0 = time.process_time()
        ours = characterise(z, DX)
        times.append(time.process_time() - t0)
    second = rust_run(write_npy=False)
    e2e = end_to_end(ours)
    os.remove(NPY)
    numpy_ms = float(np.median(times)) * 1e3
    rust_ms = float(np.median([first["cpu_ms_median"], second["cpu_ms_median"]]))
    pixels = SIDE * SIDE

    worst = {}
    for key in ("c0", "slope_x", "slope_y", "m0", "m2", "m4", "mean_curvature", "mean_height", "height_std"):
        worst[key] = abs(ours[key] - first[key]) / abs(ours[key])
    assert ours["summits"] == first["summits"], (ours["summits"], first["summits"])
    i, j = ours["positions"]
    index_sum = int((i.astype(np.int64) * SIDE + j).sum())
    assert index_sum == first["summit_index_sum"], (index_sum, first["summit_index_sum"])
    assert all(v <= 1e-12 for v in worst.values()), worst

    result = {
        "cpu": cpu_model(),
        "numpy": np.__version__,
        "python": platform.python_version(),
        "map": f"{SIDE} x {SIDE}, synthetic Gaussian, l = 4 px, seed 1, non-periodic",
        "numpy_cpu_ms_median": round(numpy_ms, 1),
        "numpy_ns_per_pixel": round(numpy_ms * 1e6 / pixels, 2),
        "numpy_repeats": REPEATS,
        "asperity_cpu_ms_median": round(rust_ms, 1),
        "asperity_ns_per_pixel": round(rust_ms * 1e6 / pixels, 2),
        "asperity_runs_cpu_ms": [first["cpu_ms_median"], second["cpu_ms_median"]],
        "asperity_threads": first["threads"],
        "ratio_numpy_over_asperity": round(numpy_ms / rust_ms, 2),
        "summits": ours["summits"],
        "summit_index_sum": index_sum,
        "largest_relative_difference": max(worst.values()),
        "relative_differences": worst,
        "end_to_end": e2e,
        "load_average": os.getloadavg(),
    }
    with open(OUT, "w") as f:
        json.dump(result, f, indent=2)
        f.write("\n")
    print(json.dumps(result, indent=2))


if __name__ == "__main__":
    main()
