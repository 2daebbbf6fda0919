"""Tamaas 2.9.0 beside `asperity` on the same maps, one thread each, interleaved.

    python3 -m venv target/peers-venv && target/peers-venv/bin/pip install tamaas==2.9.0 numpy
    cargo build --release --example bem_rough_time
    target/peers-venv/bin/python benches/peers/tamaas_bem.py > benches/peers/tamaas_bem.json

Maps (periodic, side L = 100 um, E* = 1e9 Pa, E = 1e9, nu = 0):
- 256^2: examples/data/selfaffine-256.npy (H = 0.8, wavevectors 4 to 64 x 2 pi/L,
  RMS gradient 0.1);
- 1024^2: the same spectrum to 256 x 2 pi/L, random phases from numpy's
  default_rng(1), written to target/peers/selfaffine-1024.npy (RMS gradient 0.1).

Non-adhesive, p = 0.01 E*: Tamaas' PolonskyKeerRey (pressure primal) at its own
tolerance; asperity's `Problem::solve_pressure` at the same nominal tolerance
(its residual: the gap on the contact set and the penetration outside it over
h_rms), through `target/release/examples/bem_rough_time` (RAYON_NUM_THREADS=1).
Both CPU times are of the solve alone (Tamaas: time.process_time() around
solve(); asperity: its threads' schedstat counters around solve_pressure), in
turns (Tamaas, asperity, Tamaas, ...), medians of REPS. The answers are checked:
the same contact pixels and mean gaps within 1e-6 relative (both converged to
better than that).

Adhesive (Tamaas only, kept from the earlier run): PolonskyKeerRey in the gap
with ExponentialAdhesionFunctional (w, rho) under mean-gap control, 256^2.
"""
import json
import os
import subprocess
import sys
import time

os.environ.setdefault("OMP_NUM_THREADS", "1")
import numpy as np  # noqa: E402
import tamaas as tm  # noqa: E402

tm.set_log_level(tm.LogLevel.error)
ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
BIN = os.path.join(ROOT, "target", "release", "examples", "bem_rough_time")
L = 1e-4
ESTAR = 1e9
P = 0.01 * ESTAR
REPS = int(os.environ.get("REPS", "3"))


def map_1024():
    path = os.path.join(ROOT, "target", "peers", "selfaffine-1024.npy")
    if os.path.exists(path):
        return path
    n = 1024
    k = np.fft.fftfreq(n, 1.0 / n)
    kx, ky = np.meshgrid(k, k)
    q = np.hypot(kx, ky)
    amp = np.where((q >= 4) & (q <= 256), np.maximum(q, 1) ** (-(1 + 0.8)), 0.0)
    rng = np.random.default_rng(1)
    h = np.fft.ifft2(amp * np.exp(2j * np.pi * rng.random((n, n)))).real
    gx = (np.roll(h, -1, 1) - h) / (L / n)
    gy = (np.roll(h, -1, 0) - h) / (L / n)
    h *= 0.1 / np.sqrt((gx**2 + gy**2).mean())
    os.makedirs(os.path.dirname(path), exist_ok=True)
    np.save(path, h)
    return path


def tamaas_solve(surface, tol):
    n = surface.shape[0]
    m = tm.ModelFactory.createModel(tm.model_type.basic_2d, [L, L], [n, n])
    m.E, m.nu = ESTAR, 0.0
    solver = tm.PolonskyKeerRey(m, surface, tol)
    solver.max_iter = 100000
    t = time.process_time()
    solver.solve(P)
    cpu = time.process_time() - t
    p = m.traction
    contact = p > 0
    gap = m.displacement - surface
    gap -= gap[contact].mean() if contact.any() else 0.0
    return cpu, float(contact.mean()), float(np.clip(gap, 0, None).mean())


def asperity_solve(path, tol):
    env = dict(os.environ, RAYON_NUM_THREADS="1")
    out = subprocess.run(
        [BIN, "1", repr(tol), path, repr(L)], cwd=ROOT, env=env, capture_output=True, text=True, check=True
    ).stdout
    return json.loads(out)


def side_by_side(path, tols):
    surface = np.load(path)
    rows = []
    for tol in tols:
        t_cpu, a_cpu = [], []
        for _ in range(REPS):
            cpu, area, gap = tamaas_solve(surface, tol)
            t_cpu.append(cpu)
            a = asperity_solve(path, tol)
            a_cpu.append(a["cpu_s_median"])
        tm_med, as_med = float(np.median(t_cpu)), float(np.median(a_cpu))
        same_area = abs(a["area_fraction"] - area) * surface.size < 0.5
        rel_gap = abs(a["mean_gap_m"] - gap) / gap
        rows.append(
            {
                "map": os.path.relpath(path, ROOT),
                "pixels": surface.shape[0],
                "tolerance": tol,
                "tamaas": {"area_fraction": area, "mean_gap_m": gap, "cpu_s": t_cpu, "cpu_s_median": tm_med},
                "asperity": {
                    "area_fraction": a["area_fraction"],
                    "mean_gap_m": a["mean_gap_m"],
                    "iterations": a["iterations"],
                    "cpu_s": a_cpu,
                    "cpu_s_median": as_med,
                },
                "same_contact_pixels": same_area,
                "mean_gap_relative_difference": rel_gap,
                "ratio_tamaas_over_asperity": tm_med / as_med,
            }
        )
        print(f"{surface.shape[0]}^2 tol {tol:g}: Tamaas {tm_med:.3f} s, asperity {as_med:.3f} s, "
              f"{tm_med / as_med:.1f}x, gap diff {rel_gap:.1e}, same area {same_area}", file=sys.stderr)
        assert same_area and rel_gap < 1e-6, rows[-1]
    return rows


def adhesion(path):
    surface = np.load(path)
    n = surface.shape[0]
    h_rms = float(np.sqrt(((surface - surface.mean()) ** 2).mean()))
    w, rho = 0.02, 2 * L / n
    states = []
    for f in [1.0, 0.5, 0.25]:
        m = tm.ModelFactory.createModel(tm.model_type.basic_2d, [L, L], [n, n])
        m.E, m.nu = ESTAR, 0.0
        solver = tm.PolonskyKeerRey(m, surface, 1e-10, tm.PolonskyKeerRey.gap, tm.PolonskyKeerRey.gap)
        solver.max_iter = 100000
        functional = tm.ExponentialAdhesionFunctional(surface)
        functional.parameters = {"rho": rho, "surface_energy": w}
        solver.addFunctionalTerm(functional)
        t = time.process_time()
        solver.solve(f * h_rms)
        cpu = time.process_time() - t
        gap = m.displacement - surface
        gap -= gap.min()
        states.append(
            {
                "mean_gap_m": f * h_rms,
                "pressure_Pa": float(m.traction.mean()),
                "area_fraction": float((gap <= 1e-12 * h_rms).mean()),
                "cpu_s": cpu,
            }
        )
    return {"adhesion_energy_J_per_m2": w, "adhesion_range_m": rho, "states": states}


m256 = os.path.join(ROOT, "examples", "data", "selfaffine-256.npy")
result = {
    "tamaas": tm.__version__,
    "cpu": next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "?"),
    "pressure_Pa": P,
    "threads": 1,
    "reps": REPS,
    "side_by_side": side_by_side(m256, [1e-6, 1e-8, 1e-12]) + side_by_side(map_1024(), [1e-8]),
    "adhesion": adhesion(m256),
}
print(json.dumps(result, indent=1))
