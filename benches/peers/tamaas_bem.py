"""Tamaas on the same 256^2 map as `asperity bem` (examples/data/selfaffine-256.npy).

    python3 -m venv /work/venv-peers && /work/venv-peers/bin/pip install tamaas numpy
    /work/venv-peers/bin/python benches/peers/tamaas_bem.py > benches/peers/tamaas_bem.json

Non-adhesive: PolonskyKeerRey (pressure primal) at p = 0.01 E*, for several of
Tamaas' own tolerances; adhesive: PolonskyKeerRey in the gap with
ExponentialAdhesionFunctional (w, rho) under mean-gap control. CPU time is
time.process_time() around solve() alone (one thread: OMP_NUM_THREADS=1).
The pixel size is L/256 with L = 100 um; E* = 1e9 Pa (E = 1e9, nu = 0).
"""
import json
import os
import time

os.environ.setdefault("OMP_NUM_THREADS", "1")
import numpy as np  # noqa: E402
import tamaas as tm  # noqa: E402

tm.set_log_level(tm.LogLevel.error)
HERE = os.path.dirname(os.path.abspath(__file__))
surface = np.load(os.path.join(HERE, "..", "..", "examples", "data", "selfaffine-256.npy"))
n = surface.shape[0]
L = 1e-4
ESTAR = 1e9


def model():
    m = tm.ModelFactory.createModel(tm.model_type.basic_2d, [L, L], [n, n])
    m.E, m.nu = ESTAR, 0.0
    return m


def state(m, contact):
    gap = m.displacement - surface
    gap -= gap[contact].mean() if contact.any() else 0.0
    return float(np.clip(gap, 0, None).mean())


rows = []
for tol in [1e-4, 1e-6, 1e-8, 1e-10, 1e-12]:
    m = model()
    solver = tm.PolonskyKeerRey(m, surface, tol)
    solver.max_iter = 100000
    t = time.process_time()
    solver.solve(0.01 * ESTAR)
    cpu = time.process_time() - t
    p = m.traction
    contact = p > 0
    rows.append(
        {
            "tolerance": tol,
            "area_fraction": float(contact.mean()),
            "mean_gap_m": state(m, contact),
            "mean_pressure_Pa": float(p.mean()),
            "cpu_s": cpu,
        }
    )

h_rms = float(np.sqrt(((surface - surface.mean()) ** 2).mean()))
W, RHO = 0.02, 2 * L / n
adh = []
for f in [1.0, 0.5, 0.25]:
    m = model()
    solver = tm.PolonskyKeerRey(m, surface, 1e-10, tm.PolonskyKeerRey.gap, tm.PolonskyKeerRey.gap)
    solver.max_iter = 100000
    functional = tm.ExponentialAdhesionFunctional(surface)
    functional.parameters = {"rho": RHO, "surface_energy": W}
    solver.addFunctionalTerm(functional)
    t = time.process_time()
    solver.solve(f * h_rms)
    cpu = time.process_time() - t
    gap = m.displacement - surface
    gap -= gap.min()
    adh.append(
        {
            "mean_gap_m": f * h_rms,
            "pressure_Pa": float(m.traction.mean()),
            "area_fraction": float((gap <= 1e-12 * h_rms).mean()),
            "cpu_s": cpu,
        }
    )

print(
    json.dumps(
        {
            "tamaas": tm.__version__,
            "map": "examples/data/selfaffine-256.npy",
            "pressure_Pa": 0.01 * ESTAR,
            "by_tolerance": rows,
            "adhesion": {"adhesion_energy_J_per_m2": W, "adhesion_range_m": RHO, "states": adh},
        },
        indent=1,
    )
)
