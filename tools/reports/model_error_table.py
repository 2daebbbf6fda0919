#!/usr/bin/env python3
"""The table of docs/physics.md "Model error on a rough surface".

Runs the gold microswitch surface (examples/scenes/mems-gold.toml: mu = 1.59,
z0 = 0.3 nm, 10,000 summits) at several summit-height deviations sigma with
the analytic adhesive laws and with the full-solver (calibrated) law, and
prints, per sigma/z0, each law's rough pull-off (GW integral) beside the
calibrated law's, and the calibrated law's pull-off of one switch (mean and
5 % quantile over populations) with the expected number of carriers.

    cargo build --release && python3 tools/reports/model_error_table.py

Uses target/release/asperity; about a minute of CPU.
"""
import json
import pathlib
import subprocess
import tempfile

ROOT = pathlib.Path(__file__).resolve().parents[2]
BIN = ROOT / "target" / "release" / "asperity"
BASE = (ROOT / "examples" / "scenes" / "mems-gold.toml").read_text()
Z0 = 0.3e-9


def run(sigma, law, seeds):
    text = BASE.replace('kind = "auto"', f'kind = "{law}"', 1)
    text = text.replace("sigma = 5e-9", f"sigma = {sigma:e}", 1)
    # Approach to one sigma above the mean summit height, as the base scene.
    text = text.replace("closest_separation = 5e-9", f"closest_separation = {sigma:e}", 1)
    text += f"\n[montecarlo]\nseeds = {seeds}\n"
    with tempfile.TemporaryDirectory() as d:
        p = pathlib.Path(d) / "s.toml"
        p.write_text(text)
        out = subprocess.run([str(BIN), "run", str(p), "--json"], capture_output=True, check=True)
    return json.loads(out.stdout)


def main():
    print("| sigma/z0 | calibrated (LJ) P_c [uN] | Maugis-Dugdale | JKR | DMT | one switch, LJ: mean [uN] | p05 [uN] | carriers |")
    print("|---|---|---|---|---|---|---|---|")
    for sigma in [0.3e-9, 1e-9, 3e-9, 5e-9, 10e-9]:
        cal = run(sigma, "calibrated", 100)
        row = [f"{sigma / Z0:.3g}", f"{cal['pull_off_load'] * 1e6:.4g}"]
        for law in ["maugis", "jkr", "dmt"]:
            v = run(sigma, law, 2)
            e = v["model_error"]["pull_off"]
            po = v["pull_off_load"]
            shown = "none" if po is None else f"{po * 1e6:.4g}"
            row.append(shown if e is None else f"{shown} ({100 * e:+.0f} %)")
        pop = cal.get("pull_off_population") or {}
        row += [
            f"{pop.get('mean_N', float('nan')) * 1e6:.4g} +- {pop.get('mean_se_N', float('nan')) * 1e6:.2g}",
            f"{pop.get('p05_N', float('nan')) * 1e6:.4g}",
            f"{pop.get('carriers', float('nan')):.3g}",
        ]
        print("| " + " | ".join(row) + " |")


if __name__ == "__main__":
    main()
