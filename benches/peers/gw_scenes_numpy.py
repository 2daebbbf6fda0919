#!/usr/bin/env python3
"""The GW curves end to end: `asperity run` on a scene against numpy's curve.

The two curves of gw_curves_numpy.py (resistance: Hertz summits with gold
Wexler spots and Greenwood's mean-field term; kogut-etsion: the gold
surface with Kogut & Etsion summits) as scenes (benches/peers/scenes/), each
with its 1000 approach separations listed in `[program] separations` (the
numpy peer's own), run by the CLI with every output written (curve.csv,
summary.json with the listed states, the charts) into a fresh folder. What the user waits for is
the whole process; what the curve costs is the extra CPU time of the
1000-point scene over the same scene with 2 of those separations (start-up,
parsing, planning, the scene's 200-point curve and its outputs cancel; what
is left is 998 more GW states, their listing in summary.json and the text
report).

Timing: children's CPU time (user + sys, `resource.getrusage`) of RUNS runs
of each, interleaved (2, 1000, 2, 1000, ...), one rayon thread; the median
of the differences of consecutive pairs. numpy: time.process_time() of its
curve at the smallest node count whose worst error is at most the scene's
(the scene's listed states against the 256-node reference of gw_curves_numpy.py,
itself checked against mpmath there).

Run from the repository root (needs numpy and mpmath):
    cargo build --release
    python3 benches/peers/gw_scenes_numpy.py [RUNS]
"""
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import gw_curves_numpy as peer  # noqa: E402

EXE = os.environ.get("ASPERITY_CLI", os.path.join("target", "release", "asperity"))
SCENES = Path(__file__).resolve().parent / "scenes"
KEYS = {"load": "load_N", "count": "contacts", "area": "real_area_m2", "resistance": "resistance_ohm"}


def scene_text(name, separations):
    text = (SCENES / f"curve-{name}.toml").read_text()
    listed = ", ".join(repr(float(s)) for s in separations)
    return text.replace("[program]\n", f"[program]\nseparations = [{listed}]\n", 1)


def children_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run(scene, out):
    t0 = children_cpu()
    subprocess.run([EXE, "run", str(scene), "--out", str(out)], check=True, capture_output=True,
                   env={**os.environ, "RAYON_NUM_THREADS": "1"})
    return children_cpu() - t0


def read_states(out):
    """The listed states of the run's summary.json, by the peer's names."""
    states = json.loads((out / "summary.json").read_text())["states"]
    return {k: np.array([s[c] for s in states]) for k, c in KEYS.items() if c in states[0]}


def main():
    runs = int(sys.argv[1]) if len(sys.argv) > 1 else 15
    print(f"| curve | scene error | asperity 1000 - 2 points (CPU) | numpy nodes | numpy curve (CPU) | error | numpy/asperity |")
    print("|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        for name, c in peer.CASES.items():
            h = c["h"]()
            seps = h * peer.SIGMA
            # Listed separations are reported in the order given: the numpy
            # curve's, ascending; approach from the top means descending.
            big, small = tmp / f"{name}-1000.toml", tmp / f"{name}-2.toml"
            big.write_text(scene_text(name, seps[::-1]))
            small.write_text(scene_text(name, seps[::-1][[0, -1]]))
            run(big, tmp / "check")
            got = read_states(tmp / "check")
            ref = c["reference"]()
            keys = [k for k in c["keys"] if k in got]
            ref_desc = {k: np.asarray(ref[k])[::-1] for k in keys}
            err = peer.worst(got, ref_desc, keys)
            diffs = []
            for i in range(runs):
                a = run(small, tmp / f"s{i}")
                b = run(big, tmp / f"b{i}")
                diffs.append(b - a)
            extra = statistics.median(diffs)
            for n in peer.NODE_CHOICES:
                np_err = peer.worst(c["curve"](n), ref, keys)
                if np_err <= err:
                    break
            np_cpu = peer.cpu(lambda: c["curve"](n), peer.REPEATS)
            print(f"| {name} ({', '.join(keys)}) | {err:.1e} | {extra * 1e3:.2f} ms | {n} | "
                  f"{np_cpu * 1e3:.2f} ms | {np_err:.1e} | {np_cpu / extra:.2f}x |")


if __name__ == "__main__":
    main()
