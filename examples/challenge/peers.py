"""The contact-mechanics challenge's two problems solved by the peers on the
same generated surface as asperity's `examples/challenge` (the .npy it
writes), for tests/it/challenge.rs and docs/performance.md.

- Non-adhesive: ContactMechanics 1.8.3, `NonSmoothContactSystem` (hard wall,
  `PeriodicFFTElasticHalfSpace`), load control at the reference pressure,
  Polonsky & Keer's constrained conjugate gradients
  (`ContactMechanics.Optimization.constrained_conjugate_gradients`) with
  `pentol`, `forcetol`, `thermotol` below.
- Adhesive: Adhesion 0.93, `BoundedSmoothContactSystem` (hard wall plus
  `Adhesion.Interactions.Exponential(gamma0 = w, rho)`, V(g) = -w exp(-g/rho)
  for g >= 0), its `primal_objective` (energy and gradient in the gap) and
  `primal_hessian_product`, minimised at the non-adhesive state's mean gap
  by Bugnicourt et al.'s (2018) constrained conjugate gradients with the mean
  constraint (`NuMPI.Optimization.CCGWithoutRestart`, `mean_val`), the gap
  solver Adhesion's primal problems use. The substrate has
  `stiffness_q0 = 0` (the mean displacement is a rigid shift: the energy is
  that of the periodic half-space, as in asperity; at imposed mean gap the
  q = 0 stiffness only adds a uniform gradient the mean constraint removes).

Definitions, the same as asperity's (`src/bem/mod.rs`, `Solution`):
- A/A0: pixels in contact / all pixels; in contact where the pressure is
  > 0 (Polonsky & Keer: ContactMechanics' own `contact_zone = jac > 0`),
  where the gap is exactly 0 (adhesive: Adhesion's `contact_zone`,
  `gap == 0`).
- mean gap: the mean over all pixels of the gap, 0 in contact and
  max(u - h - offset, 0) elsewhere (non-adhesive; the raw mean of
  u - h - offset is recorded too), the solver's gap (adhesive, >= 0).
- mean pressure: the imposed load / area (non-adhesive); adhesive, the
  multiplier of the mean-gap constraint: minus the mean over the free
  pixels (gap > 0) of the energy gradient per pixel area, K u + V'(g)
  (asperity's `p_mean = -mean_F q`, `src/bem/gap_control.rs`).

CPU time: time.process_time() of each solve, one thread (run with
OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 MKL_NUM_THREADS=1).

Run (the peers' venv: pip install numpy scipy contactmechanics==1.8.3
Adhesion==0.93):
  OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 MKL_NUM_THREADS=1 \\
    python examples/challenge/peers.py tests/data/challenge_512.npy \\
    > tests/data/challenge_peers.json
"""
import datetime
import importlib.metadata as md
import json
import platform
import subprocess
import sys
import time

import numpy as np

import Adhesion  # noqa: F401  (registers make_system's adhesive systems)
from Adhesion.Interactions import Exponential
from Adhesion.System import BoundedSmoothContactSystem
from ContactMechanics import PeriodicFFTElasticHalfSpace
from ContactMechanics.Systems import NonSmoothContactSystem
from NuMPI.Optimization import CCGWithoutRestart
from SurfaceTopography import Topography

# The challenge (asperity's src/bem/challenge.rs).
SIDE = 1e-4                    # m
E_STAR = 25e6                  # Pa
W = 0.05                       # J/m^2
RHO = 30 * 2.071e-9            # m (Adhesion 0.93's example at 512^2)
P_REF = 0.01 * E_STAR * 1.0    # Pa, 0.01 E* g with g = 1

# Tolerances: relative to the pixel force of the reference pressure and to
# the RMS height.
PENTOL_REL = 1e-12             # Polonsky & Keer: penetration / h_rms
FORCETOL_REL = 1e-12           # tension outside contact / (P_REF dx^2)
THERMOTOL = 1e-12              # relative change of offset between iterations
GTOL_REL = 1e-10               # Bugnicourt: max |projected gradient| / (E* g dx^2 / 2)


def cpu_model():
    try:
        out = subprocess.run(["lscpu"], capture_output=True, text=True).stdout
        for line in out.splitlines():
            if line.startswith("Model name:"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor()


def non_adhesive(h, dx):
    n = h.shape[0]
    area = SIDE * SIDE
    a = dx * dx
    top = Topography(h, physical_sizes=(SIDE, SIDE), periodic=True)
    sub = PeriodicFFTElasticHalfSpace((n, n), E_STAR, physical_sizes=(SIDE, SIDE))
    system = NonSmoothContactSystem(sub, top)
    h_rms = float(np.sqrt(np.mean((h - h.mean()) ** 2)))
    t0 = time.process_time()
    res = system.minimize_proxy(external_force=P_REF * area,
                                pentol=PENTOL_REL * h_rms,
                                forcetol=FORCETOL_REL * P_REF * a,
                                thermotol=THERMOTOL, maxiter=100000)
    cpu = time.process_time() - t0
    u = res.x
    pressure = res.jac / a
    contact = pressure > 0
    raw_gap = u - h - res.offset
    gap = np.where(contact, 0.0, np.maximum(raw_gap, 0.0))
    return {
        "solver": "ContactMechanics 1.8.3 NonSmoothContactSystem.minimize_proxy "
                  "(Polonsky & Keer constrained conjugate gradients), load control",
        "converged": bool(res.success),
        "message": str(res.message),
        "iterations": int(res.nit),
        "pentol_m": PENTOL_REL * h_rms,
        "forcetol_n": FORCETOL_REL * P_REF * a,
        "thermotol": THERMOTOL,
        "max_penetration_m": float(res.maxcv["max_pen"]),
        "max_tension_outside_n": float(res.maxcv["max_pres"]),
        "contact_pixels": int(contact.sum()),
        "area_fraction": float(contact.mean()),
        "mean_gap_m": float(gap.mean()),
        "mean_gap_raw_m": float(raw_gap.mean()),
        "mean_pressure_pa": float(pressure.mean()),
        "cpu_s": cpu,
    }


def rigid_gap(h, g_mean):
    """max(c - h, 0) with mean g_mean (asperity's rigid-body start)."""
    lo, hi = h.min() + g_mean, h.mean() + g_mean
    for _ in range(200):
        c = 0.5 * (lo + hi)
        if np.maximum(c - h, 0).mean() < g_mean:
            lo = c
        else:
            hi = c
    return np.maximum(0.5 * (lo + hi) - h, 0.0)


def adhesive(h, dx, g_mean):
    n = h.shape[0]
    a = dx * dx
    top = Topography(h, physical_sizes=(SIDE, SIDE), periodic=True)
    sub = PeriodicFFTElasticHalfSpace((n, n), E_STAR, physical_sizes=(SIDE, SIDE),
                                      stiffness_q0=0.0)
    inter = Exponential(gamma0=W, rho=RHO)
    system = BoundedSmoothContactSystem(sub, inter, top)
    gtol = GTOL_REL * 0.5 * E_STAR * 1.0 * a
    fun = system.primal_objective(0.0, gradient=True)
    x0 = rigid_gap(h, g_mean)
    t0 = time.process_time()
    res = CCGWithoutRestart.constrained_conjugate_gradients(
        fun, system.primal_hessian_product, x0=x0.ravel(), mean_val=g_mean,
        gtol=gtol, maxiter=100000)
    cpu = time.process_time() - t0
    gap = res.x.reshape(h.shape)
    _, grad = fun(res.x)
    grad = grad.reshape(h.shape)
    free = gap > 0
    p_mean = -float(grad[free].mean()) / a
    return {
        "solver": "Adhesion 0.93 BoundedSmoothContactSystem primal_objective + "
                  "NuMPI CCGWithoutRestart (Bugnicourt et al. 2018) with mean_val, "
                  "mean-gap control",
        "converged": bool(res.success),
        "message": str(res.message),
        "iterations": int(res.nit),
        "gtol_n": gtol,
        "max_projected_gradient_n": float(np.max(np.abs(res.jac))),
        "contact_pixels": int((gap == 0).sum()),
        "area_fraction": float((gap == 0).mean()),
        "mean_gap_m": float(gap.mean()),
        "mean_pressure_pa": p_mean,
        "cpu_s": cpu,
    }


def main():
    path = sys.argv[1]
    # `--non-adhesive-only`: ContactMechanics alone (at 2048^2 Adhesion
    # would need about an hour).
    dry_only = "--non-adhesive-only" in sys.argv[2:]
    h = np.load(path)
    n = h.shape[0]
    dx = SIDE / n
    dry = non_adhesive(h, dx)
    wet = None if dry_only else adhesive(h, dx, dry["mean_gap_m"])
    print(json.dumps(record(path, n, dx, dry, wet, dry_only), indent=1))


def record(path, n, dx, dry, wet, dry_only=False):
    """The JSON written: provenance, the problem, the peers' states."""
    out = {
        "provenance": {
            "command": "OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 MKL_NUM_THREADS=1 "
                       "python examples/challenge/peers.py " + path
                       + (" --non-adhesive-only" if dry_only else ""),
            "date_utc": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M"),
            "python": platform.python_version(),
            "packages": {p: md.version(p) for p in
                         ["contactmechanics", "Adhesion", "SurfaceTopography",
                          "NuMPI", "muGrid", "numpy", "scipy"]},
            "cpu": cpu_model(),
            "map": path,
        },
        "n": n,
        "pixel_size_m": dx,
        "contact_modulus_pa": E_STAR,
        "reference_pressure_pa": P_REF,
        "adhesion_energy_j_m2": W,
        "adhesion_range_m": RHO,
        "non_adhesive": dry,
    }
    if wet is not None:
        out["adhesive"] = wet
    return out


if __name__ == "__main__":
    main()
