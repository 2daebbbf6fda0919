"""`asperity.fn` on 1e6 points from Python against the same call in Rust,
in-process (the issue's bound: within 2x).

    python python/benchmarks/bench_fn.py [points] [n]

Runs `cargo run --release --example fn_time` for the Rust time (best of 7,
process CPU time) and times `asperity.fn` on the same points here (best of
7, process CPU time of this process, which is also what the single-threaded
call costs). Prints both and their ratio as one JSON line. A benchmark, not
a test: it prints, it does not assert.
"""

import json
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

import asperity

REPO = Path(__file__).resolve().parents[2]


def python_seconds(points: int, n: float, repeats: int = 7) -> float:
    h = np.linspace(-3.0, 8.0, points)
    best = float("inf")
    for _ in range(repeats):
        c0, w0 = time.process_time(), time.perf_counter()
        asperity.fn("gaussian", n, h)
        cpu, wall = time.process_time() - c0, time.perf_counter() - w0
        best = min(best, cpu if cpu >= 0.2 else wall)
    return best


def rust_seconds(points: int, n: float) -> float:
    out = subprocess.run(
        ["cargo", "run", "--quiet", "--release", "--example", "fn_time", "--", str(points), "gaussian", str(n)],
        cwd=REPO,
        capture_output=True,
        text=True,
        check=True,
    ).stdout
    return json.loads(out.strip().splitlines()[-1])["seconds"]


def main() -> None:
    points = int(float(sys.argv[1])) if len(sys.argv) > 1 else 1_000_000
    n = float(sys.argv[2]) if len(sys.argv) > 2 else 1.5
    rust = rust_seconds(points, n)
    py = python_seconds(points, n)
    print(json.dumps({"points": points, "n": n, "rust_s": rust, "python_s": py, "ratio": py / rust}))


if __name__ == "__main__":
    main()
