#!/usr/bin/env python3
"""Independent numpy implementation of the `asperity surface` rules, and the
small stored maps it is run on.

What: for each stored map and both modes (interior / --periodic), the
quantities of the `asperity surface --json` contract and the summit positions,
written to surface_ref.json. How: the definitions coded directly in
numpy, independently of the Rust code path: the mean plane by
numpy.linalg.lstsq on the design matrix [1, x, y] (the Rust code uses the
closed-form centred normal equations), differences by numpy.diff / numpy.roll,
summits by 8 shifted boolean comparisons of whole arrays (the Rust code loops
over rows). Digits: float64 throughout; the two implementations agree to
rounding (the Rust test asserts counts and positions exactly and every mean to
1e-12 relative).

Maps (written here, deterministic seeds, numpy.save / text):
- surface_a.npy (64 x 80 float64): Gaussian-smoothed noise (FFT, 2-pixel
  kernel) of 5 nm RMS plus a 20 nm offset and a tilt; surface_a.txt is the same
  map as whitespace-separated text (17 significant digits, so bit-identical).
- surface_b.npy (33 x 47 float32): white noise in nm (use --scale 1e-9);
  surface_b.csv is the same map, comma separated, with a '#' header line.
- surface_bad/: files the readers must reject (1-D, ragged, NaN, inf, empty,
  int64 dtype, Fortran order).

Run: /path/to/venv/bin/python tests/data/surface_ref.py  (from the repository
root; writes tests/data/surface_*.{npy,txt,csv}, surface_bad/, surface_ref.json)
"""
import json
import os

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))


def make_maps():
    rng = np.random.default_rng(20261123)
    rows, cols = 64, 80
    noise = rng.standard_normal((rows, cols))
    ky = np.fft.fftfreq(rows)[:, None]
    kx = np.fft.fftfreq(cols)[None, :]
    smooth = np.real(np.fft.ifft2(np.fft.fft2(noise) * np.exp(-2 * np.pi**2 * 4 * (kx**2 + ky**2))))
    smooth *= 5e-9 / smooth.std()
    y, x = np.mgrid[0:rows, 0:cols]
    a = smooth + 2e-8 + 1e-10 * x - 4e-11 * y
    b = (rng.standard_normal((33, 47)) * 3.0).astype(np.float32)
    return a, b


def characterise(z, dx, periodic):
    z = np.asarray(z, dtype=np.float64)
    rows, cols = z.shape
    if periodic:
        r = z - z.mean()
    else:
        y, x = np.mgrid[0:rows, 0:cols]
        # Coordinates in pixels (the fitted plane does not depend on their
        # unit; in metres the design matrix is ill-conditioned, cond ~ 1/dx).
        a = np.column_stack([np.ones(z.size), x.ravel(), y.ravel()])
        coef, *_ = np.linalg.lstsq(a, z.ravel(), rcond=None)
        r = z - (a @ coef).reshape(rows, cols)
    m0 = np.mean(r**2)
    if periodic:
        dxf = np.roll(r, -1, axis=1) - r
        dyf = np.roll(r, -1, axis=0) - r
        d2x = np.roll(r, -1, axis=1) - 2 * r + np.roll(r, 1, axis=1)
        d2y = np.roll(r, -1, axis=0) - 2 * r + np.roll(r, 1, axis=0)
    else:
        dxf = np.diff(r, axis=1)
        dyf = np.diff(r, axis=0)
        d2x = np.diff(r, n=2, axis=1)
        d2y = np.diff(r, n=2, axis=0)
    m2 = (np.mean(dxf**2) + np.mean(dyf**2)) / 2 / dx**2
    m4 = (np.mean(d2x**2) + np.mean(d2y**2)) / 2 / dx**4
    alpha = m0 * m4 / m2**2
    # Summits: strictly above the 8 neighbours.
    p = np.pad(r, 1, mode="wrap") if periodic else r
    c = p[1:-1, 1:-1]
    is_top = np.ones(c.shape, dtype=bool)
    for di in (-1, 0, 1):
        for dj in (-1, 0, 1):
            if di or dj:
                is_top &= c > p[1 + di : p.shape[0] - 1 + di, 1 + dj : p.shape[1] - 1 + dj]
    lap = p[2:, 1:-1] + p[:-2, 1:-1] + p[1:-1, 2:] + p[1:-1, :-2] - 4 * c
    kappa = -lap / (2 * dx**2)
    ii, jj = np.nonzero(is_top)
    off = 0 if periodic else 1
    heights = c[ii, jj]
    curv = kappa[ii, jj]
    n = len(heights)
    summits = {
        "count": int(n),
        "density_per_m2": n / (c.size * dx**2),
        "mean_curvature_per_m": float(curv.mean()) if n else None,
        "radius_m": float(1 / curv.mean()) if n else None,
        "height_std_m": float(heights.std()) if n else None,
        "mean_height_m": float(heights.mean()) if n else None,
    }
    gw = {
        "density_per_m2": m4 / (6 * np.pi * np.sqrt(3) * m2),
        "radius_m": 0.375 * np.sqrt(np.pi / m4),
        "sigma_m": float(np.sqrt(m0 * (1 - 0.8968 / alpha))),
    }
    return {
        "rows": rows,
        "cols": cols,
        "rms_height_m": float(np.sqrt(m0)),
        "m0": float(m0),
        "m2": float(m2),
        "m4": float(m4),
        "bandwidth_alpha": float(alpha),
        "summits": summits,
        "gw_from_moments": {k: float(v) for k, v in gw.items()},
        "positions": [[int(i + off), int(j + off)] for i, j in zip(ii, jj)],
    }


def write_bad(dirname):
    os.makedirs(dirname, exist_ok=True)
    good = np.arange(12.0).reshape(3, 4)
    np.save(os.path.join(dirname, "one_d.npy"), np.arange(5.0))
    np.save(os.path.join(dirname, "int64.npy"), np.arange(12, dtype=np.int64).reshape(3, 4))
    np.save(os.path.join(dirname, "fortran.npy"), np.asfortranarray(good))
    nan = good.copy()
    nan[1, 2] = np.nan
    np.save(os.path.join(dirname, "nan.npy"), nan)
    inf = good.copy()
    inf[2, 0] = np.inf
    np.save(os.path.join(dirname, "inf.npy"), inf)
    open(os.path.join(dirname, "empty.npy"), "wb").close()
    files = {
        "empty.txt": "",
        "one_d.txt": "1 2 3 4 5\n",
        "ragged.txt": "1 2 3\n4 5\n6 7 8\n",
        "nan.csv": "1,2,3\n4,nan,6\n7,8,9\n",
        "inf.txt": "1 2 3\n4 5 6\n7 8 inf\n",
    }
    for name, text in files.items():
        with open(os.path.join(dirname, name), "w") as f:
            f.write(text)


def main():
    a, b = make_maps()
    np.save(os.path.join(HERE, "surface_a.npy"), a)
    np.savetxt(os.path.join(HERE, "surface_a.txt"), a, fmt="%.17g")
    np.save(os.path.join(HERE, "surface_b.npy"), b)
    with open(os.path.join(HERE, "surface_b.csv"), "w") as f:
        f.write("# white noise, heights in nm\n")
        for row in b.astype(np.float64):
            f.write(",".join(repr(float(v)) for v in row) + "\n")
    write_bad(os.path.join(HERE, "surface_bad"))
    out = {
        "provenance": "tests/data/surface_ref.py: numpy " + np.__version__
        + "; the issue-13 rules coded independently (lstsq plane, diff/roll, shifted comparisons); float64",
        "maps": {
            "surface_a": {"pixel_size": 1e-7, "scale": 1.0,
                          "interior": characterise(a, 1e-7, False),
                          "periodic": characterise(a, 1e-7, True)},
            "surface_b": {"pixel_size": 5e-8, "scale": 1e-9,
                          "interior": characterise(b.astype(np.float64) * 1e-9, 5e-8, False),
                          "periodic": characterise(b.astype(np.float64) * 1e-9, 5e-8, True)},
        },
    }
    with open(os.path.join(HERE, "surface_ref.json"), "w") as f:
        json.dump(out, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
