#!/usr/bin/env python3
"""ContactMechanics 1.8.3's plastic system on the hard case of the plastic
boundary elements: provenance for tests/it/bem_plastic_cm.rs.

The case: a periodic self-affine map (Hurst 0.8, flat below q = 4 q0, random
phases, seed below) of 128 x 128 pixels of 1 um scaled to a forward-difference
RMS gradient of 0.08 (written to bem_plastic_cm_map128.npy), E* = 1e9 Pa,
hardness H = 0.1 E*, mean pressures P/E* in LOADS. A fresh
PlasticNonSmoothContactSystem per load (its minimize_proxy adds the plastic
displacement to the topography after a converged solve: a fresh system keeps
every load the same static problem as asperity's), solved by its
constrained_conjugate_gradients (Polonsky & Keer with the pressure truncated
at the hardness and a relaxation ("mixing") step when few pixels are
elastic) under the external force P A0, with pentol = 1e-8 h_rms (the gap
tolerance of asperity's 1e-8 residual), forcetol = 1e-8 H dx^2 and at most
MAXITER iterations.

Definitions recorded per load (ContactMechanics' own): converged
(result.success), contact pixels = result.jac > 0 (compressive force), plastic
pixels = result.plastic (gap < 0 after the offset), and, as asperity counts
them, pixels whose force equals the hardness (the solver truncates them to
exactly -H dx^2). Mean gap: mean of max(u - h - offset, 0) (plastic pixels
closed). CPU seconds by time.process_time(). Then, as a user runs it, one
system through the loads in turn with ContactMechanics' default pentol and
forcetol ("sequential_default_tolerances": each converged solve flattens the
topography by its plastic displacement, so these are loading-history states,
recorded for convergence only).

Run (a venv with numpy scipy contactmechanics==1.8.3):
  python tests/data/bem_plastic_cm.py > tests/data/bem_plastic_cm.json
The benchmark of docs/performance.md at 512^2 (the map written elsewhere):
  python tests/data/bem_plastic_cm.py 512 /tmp/bem_plastic_cm_map512.npy > /tmp/cm512.json
"""
import json
import os
import platform
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
N = 128
DX = 1e-6
ESTAR = 1e9
HARD = 0.1 * ESTAR
SEED = 20261130
SLOPE = 0.08
LOADS = (0.01, 0.03, 0.05, 0.07, 0.08, 0.09, 0.095, 0.099, 0.1)
MAXITER = 5000
MAP_PATH = os.path.join(HERE, "bem_plastic_cm_map128.npy")
if len(sys.argv) == 3:
    N, MAP_PATH = int(sys.argv[1]), sys.argv[2]


def make_map():
    rng = np.random.default_rng(SEED)
    q = 2 * np.pi * np.fft.fftfreq(N, d=DX)
    qx, qy = np.meshgrid(q, q)
    qq = np.hypot(qx, qy)
    q0 = 2 * np.pi / (N * DX)
    c = (np.maximum(qq, 4 * q0)) ** -3.6
    c[0, 0] = 0.0
    amp = np.sqrt(c) * np.exp(2j * np.pi * rng.random((N, N)))
    h = np.real(np.fft.ifft2(amp))
    h -= h.mean()
    gx = np.roll(h, -1, axis=1) - h
    gy = np.roll(h, -1, axis=0) - h
    g = np.sqrt(np.mean(gx ** 2 + gy ** 2)) / DX
    return h * SLOPE / g


def main():
    import ContactMechanics
    import scipy
    import SurfaceTopography
    from ContactMechanics import PeriodicFFTElasticHalfSpace, make_plastic_system
    from SurfaceTopography import PlasticTopography, Topography

    h = make_map()
    np.save(MAP_PATH, h)
    size = (N * DX, N * DX)
    h_rms = float(np.sqrt(np.mean(h ** 2)))
    area_px = DX * DX
    out = {
        "n": N, "pixel_size_m": DX, "contact_modulus_Pa": ESTAR, "hardness_Pa": HARD,
        "rms_gradient": SLOPE, "seed": SEED, "map": os.path.relpath(MAP_PATH, os.path.join(HERE, "..", "..")),
        "h_rms_m": h_rms, "pentol_m": 1e-8 * h_rms, "forcetol_N": 1e-8 * HARD * area_px,
        "maxiter": MAXITER,
        "versions": {"ContactMechanics": "1.8.3 (" + ContactMechanics.__file__.split("site-packages")[0]
                     .rstrip("/").split("/")[-1] + ")",
                     "SurfaceTopography": getattr(SurfaceTopography, "__version__", "?"),
                     "numpy": np.__version__, "scipy": scipy.__version__,
                     "python": sys.version.split()[0]},
        "machine": platform.processor() or platform.machine(),
        "loads": [],
    }
    out["versions"]["ContactMechanics"] = "1.8.3"
    for f in LOADS:
        substrate = PeriodicFFTElasticHalfSpace((N, N), ESTAR, physical_sizes=size)
        topo = PlasticTopography(Topography(h, physical_sizes=size, periodic=True), HARD)
        system = make_plastic_system(surface=topo, substrate=substrate)
        t0 = time.process_time()
        try:
            r = system.minimize_proxy(external_force=f * ESTAR * N * N * area_px,
                                      pentol=1e-8 * h_rms, forcetol=1e-8 * HARD * area_px,
                                      maxiter=MAXITER)
        except Exception as e:  # noqa: BLE001 (recorded: the solver raised)
            cpu = time.process_time() - t0
            rec = {"pressure_over_estar": f, "converged": False, "cpu_s": cpu,
                   "message": f"raised {type(e).__name__}: {e}"}
            out["loads"].append(rec)
            print(f, rec["message"], file=sys.stderr)
            continue
        cpu = time.process_time() - t0
        rec = {"pressure_over_estar": f, "converged": bool(r.success), "iterations": int(r.nit),
               "cpu_s": cpu, "message": str(r.message)}
        if r.success:
            force = np.asarray(r.jac)
            gap = np.asarray(r.x)[:N, :N] - h - r.offset
            rec.update({
                "area_fraction": float(np.mean(force > 0)),
                "plastic_fraction_cm": float(np.mean(r.plastic)),
                "plastic_fraction_at_hardness": float(np.mean(force >= HARD * area_px * (1 - 1e-12))),
                "mean_pressure_Pa": float(force.sum() / (N * N * area_px)),
                "mean_gap_m": float(np.mean(np.where(force > 0, 0.0, np.maximum(gap, 0.0)))),
            })
        out["loads"].append(rec)
        print(f, rec["converged"], rec["iterations"], f"{cpu:.2f}s", rec.get("area_fraction"),
              rec.get("plastic_fraction_at_hardness"), file=sys.stderr)
    # As a user would run it: one system through the loads in turn (each
    # converged solve flattens the topography by its plastic displacement),
    # ContactMechanics' default pentol and forcetol.
    substrate = PeriodicFFTElasticHalfSpace((N, N), ESTAR, physical_sizes=size)
    topo = PlasticTopography(Topography(h, physical_sizes=size, periodic=True), HARD)
    system = make_plastic_system(surface=topo, substrate=substrate)
    out["sequential_default_tolerances"] = []
    for f in LOADS:
        t0 = time.process_time()
        try:
            r = system.minimize_proxy(external_force=f * ESTAR * N * N * area_px, maxiter=MAXITER)
            rec = {"pressure_over_estar": f, "converged": bool(r.success), "iterations": int(r.nit),
                   "message": str(r.message)}
            if r.success:
                force = np.asarray(r.jac)
                rec["area_fraction"] = float(np.mean(force > 0))
                rec["plastic_fraction_at_hardness"] = float(
                    np.mean(force >= HARD * area_px * (1 - 1e-12)))
        except Exception as e:  # noqa: BLE001 (recorded: the solver raised)
            rec = {"pressure_over_estar": f, "converged": False,
                   "message": f"raised {type(e).__name__}: {e}"}
        rec["cpu_s"] = time.process_time() - t0
        out["sequential_default_tolerances"].append(rec)
        print("sequential", f, rec["converged"], rec.get("iterations"), rec.get("area_fraction"),
              file=sys.stderr)
    print(json.dumps(out, indent=1))


if __name__ == "__main__":
    main()
