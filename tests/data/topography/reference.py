"""Reference values of the instrument files in this directory, from
SurfaceTopography 1.27.1 (MIT; https://github.com/ContactEngineering/SurfaceTopography).

Run in a virtual environment (the tests themselves need no Python):

    python3 -m venv /tmp/st-venv
    /tmp/st-venv/bin/pip install SurfaceTopography==1.27.1
    /tmp/st-venv/bin/python tests/data/topography/reference.py [--generate]

For every sample it opens the file with `open_topography(path)`, takes the
default channel's `topography()` converted with `to_unit("m")` and writes to
`reference.json` a compact record: the shape in asperity's order (rows along
y, columns along x: SurfaceTopography's `heights()` is indexed [x, y], so
asperity's map is its transpose), the pixel sizes (physical size / points),
the file's unit, the missing pixels (count, first, the sums of their flat indices
and of their squares), statistics of the known heights, 64 sampled heights, 4 weighted sums
with fixed pseudo-random weights, and the RMS height after removing the
least-squares mean plane of the heights (with the missing pixels filled by
asperity's rule when there are any: `fill_missing` below). No map is stored.

`--generate` first writes the `generated-*` samples with SurfaceTopography's
own writers (`to_gwy`, `to_x3p`, `to_netcdf`; `generate_plux` writes the
`.plux`, for which no writer exists, in the layout its reader reads) from seeded synthetic maps
(non-square pixels, missing pixels, integer X3P): the snapshot of the
repository lacks every `.gwy` example, and the writers cover the layouts the
remaining examples do not (X3P integers and validity bits, NetCDF masks and
periodicity).
"""

import json
import os
import sys

import numpy as np

import SurfaceTopography
from SurfaceTopography import Topography, open_topography

HERE = os.path.dirname(os.path.abspath(__file__))

# Every sample of a supported format, with the format asperity gives it.
SAMPLES = [
    ("x3p-2.x3p", "x3p"),
    ("sdf-1.sdf", "sdf"),
    ("sur-2.sur", "sur"),
    ("sur-3.sur", "sur"),
    ("di-1.di", "di"),
    ("di-2.di", "di"),
    ("di-3.di", "di"),
    ("di-4.di", "di"),
    ("di-5.di", "di"),
    ("di-6.di", "di"),
    ("10x10-one_channel_without_name.ibw", "ibw"),
    ("spot_1-1000nm.ibw", "ibw"),
    ("opd-1.opd", "opd"),
    ("opdx-3.opdx", "opdx"),
    ("nc-1.nc", "nc"),
    ("frt-1.frt", "frt"),
    ("frt-2.frt", "frt"),
    ("generated-1.gwy", "gwy"),
    ("generated-2.gwy", "gwy"),
    ("generated-float.x3p", "x3p"),
    ("generated-int16.x3p", "x3p"),
    ("generated-int32.x3p", "x3p"),
    ("generated-masked.nc", "nc"),
    ("generated-1.plux", "plux"),
]


def synthetic(nx, ny, seed, missing=0):
    rng = np.random.default_rng(seed)
    x = np.arange(nx)[:, None]
    y = np.arange(ny)[None, :]
    h = (np.sin(0.3 * x) * np.cos(0.17 * y) + 0.3 * rng.standard_normal((nx, ny))) * 1e-2
    if missing:
        mask = np.zeros((nx, ny), dtype=bool)
        mask[rng.integers(0, nx, missing), rng.integers(0, ny, missing)] = True
        h = np.ma.masked_array(h, mask=mask)
    return h


def generate():
    t = Topography(synthetic(40, 30, 1), (4.0, 6.0), unit="um")
    t.to_gwy(os.path.join(HERE, "generated-1.gwy"))
    t = Topography(synthetic(33, 17, 2, missing=9), (3.3, 1.0), unit="nm")
    t.to_gwy(os.path.join(HERE, "generated-2.gwy"))
    t = Topography(synthetic(25, 20, 3, missing=5), (2.5, 3.0), unit="um")
    t.to_x3p(os.path.join(HERE, "generated-float.x3p"), dtype="D")
    t = Topography(synthetic(24, 21, 4, missing=4), (2.4, 4.2), unit="mm")
    t.to_x3p(os.path.join(HERE, "generated-int16.x3p"), dtype="I")
    t = Topography(synthetic(19, 23, 5), (1.9, 2.3), unit="um")
    t.to_x3p(os.path.join(HERE, "generated-int32.x3p"), dtype="L")
    t = Topography(synthetic(16, 12, 6, missing=6), (1.6, 1.2), unit="um", periodic=True)
    t.to_netcdf(os.path.join(HERE, "generated-masked.nc"))
    generate_plux()


def generate_plux():
    """A Sensofar .plux as SurfaceTopography's PLUXReader reads it (no
    writer exists and the repository's plux-1.plux is absent from its
    snapshot): a zip of index.xml (GENERAL: IMAGE_SIZE_X/Y, FOV_X/Y, the
    pixel sizes in um; LAYER_k/FILENAME_Z), recipe.txt and per layer the
    float32 heights in um, IMAGE_SIZE_Y rows of IMAGE_SIZE_X, x fastest,
    NaN where missing. Two layers, non-square pixels, 5 missing pixels."""
    import zipfile

    nx, ny = 27, 14
    layers = [synthetic(nx, ny, 7, missing=5), synthetic(nx, ny, 8) * 3.0]
    index = (
        '<?xml version="1.0" encoding="UTF-8"?>\n<xml><GENERAL><VERSION>1</VERSION>'
        "<DATE>2026-11-29T12:00:00</DATE>"
        f"<IMAGE_SIZE_X>{nx}</IMAGE_SIZE_X><IMAGE_SIZE_Y>{ny}</IMAGE_SIZE_Y>"
        "<FOV_X>0.6459</FOV_X><FOV_Y>0.8125</FOV_Y></GENERAL>"
        "<INFO><ITEM_0><NAME>Device</NAME><VALUE>S neox</VALUE></ITEM_0></INFO>"
        + "".join(f"<LAYER_{k}><FILENAME_Z>LAYER_{k}.raw</FILENAME_Z></LAYER_{k}>" for k in range(len(layers)))
        + "</xml>\n"
    )
    fixed = (2026, 11, 29, 12, 0, 0)  # the same bytes on every run
    with zipfile.ZipFile(os.path.join(HERE, "generated-1.plux"), "w") as z:
        for name, data in [("index.xml", index.encode()), ("recipe.txt", b"<xml><RECIPE/></xml>\n")] + [
            (f"LAYER_{k}.raw", np.ma.filled(h, np.nan).T.astype("<f4").tobytes()) for k, h in enumerate(layers)
        ]:
            z.writestr(zipfile.ZipInfo(name, fixed), data, compress_type=zipfile.ZIP_DEFLATED)


def fill_missing(z):
    """asperity's rule: layer by layer from the edges of each hole, a pixel
    takes the mean of its 4 neighbours known before the layer, added in the
    order above, below, left, right (adding the 0 of an unknown neighbour is
    exact, so the sums are asperity's bit for bit)."""
    z = z.copy()
    while np.isnan(z).any():
        known = ~np.isnan(z)
        v = np.where(known, z, 0.0)
        s = np.zeros_like(z)
        n = np.zeros_like(z)
        for sl_to, sl_from in (
            ((slice(1, None), slice(None)), (slice(None, -1), slice(None))),  # above
            ((slice(None, -1), slice(None)), (slice(1, None), slice(None))),  # below
            ((slice(None), slice(1, None)), (slice(None), slice(None, -1))),  # left
            ((slice(None), slice(None, -1)), (slice(None), slice(1, None))),  # right
        ):
            s[sl_to] = s[sl_to] + v[sl_from]
            n[sl_to] = n[sl_to] + known[sl_from]
        layer = ~known & (n > 0)
        if not layer.any():
            break
        z[layer] = s[layer] / n[layer]
    return z


def plane_rms(z):
    rows, cols = z.shape
    i, j = np.meshgrid(np.arange(rows), np.arange(cols), indexing="ij")
    a = np.stack([np.ones(z.size), j.ravel().astype(float), i.ravel().astype(float)], axis=1)
    coef, *_ = np.linalg.lstsq(a, z.ravel(), rcond=None)
    r = z.ravel() - a @ coef
    return float(np.sqrt(np.mean(r * r)))


def weights(n, k):
    # Fixed pseudo-random weights in [-0.5, 0.5): a Weyl sequence.
    idx = np.arange(n, dtype=np.float64)
    return np.mod(idx * (0.6180339887498949 + 0.1 * k) + 0.5 * k, 1.0) - 0.5


def record(name, fmt):
    reader = open_topography(os.path.join(HERE, name))
    channel = reader.default_channel
    t = reader.topography()
    unit = t.unit
    if unit is not None:  # a file without a unit keeps its numbers
        t = t.to_unit("m")
    h = t.heights()
    if h.ndim == 1:  # a line scan: one row
        h = h[:, None]
        sx, sy = t.physical_sizes[0], None
    else:
        sx, sy = t.physical_sizes
    nx, ny = h.shape
    mask = np.ma.getmaskarray(h).T.copy()
    z = np.ma.filled(h.astype(float), np.nan).T.copy()
    z[mask] = np.nan
    flat = z.ravel()
    missing = np.flatnonzero(np.isnan(flat))
    known = flat[~np.isnan(flat)]
    idx = np.linspace(0, flat.size - 1, 64).round().astype(int)
    w = [weights(flat.size, k) for k in range(4)]
    zero = np.where(np.isnan(flat), 0.0, flat)
    filled = fill_missing(z) if missing.size else z
    return {
        "file": name,
        "format": fmt,
        "channel": channel.name,
        "channels": [c.name for c in reader.channels],
        "unit": unit,
        "rows": int(ny),
        "cols": int(nx),
        "pixel_size_m": [sx / nx, None if sy is None else sy / ny],
        "periodic": bool(t.is_periodic),
        "missing": int(missing.size),
        "missing_first": int(missing[0]) if missing.size else None,
        "missing_index_sum": int(sum(int(k) for k in missing)),
        "missing_index_square_sum": int(sum(int(k) * int(k) for k in missing)),
        "mean_m": float(known.mean()),
        "std_m": float(known.std()),
        "min_m": float(known.min()),
        "max_m": float(known.max()),
        "sample_index": [int(k) for k in idx],
        "sample_m": [None if np.isnan(flat[k]) else float(flat[k]) for k in idx],
        "weighted_sums_m": [float(np.dot(zero, wk)) for wk in w],
        "plane_rms_m": plane_rms(filled) if min(nx, ny) > 1 else None,
    }


def main():
    if "--generate" in sys.argv:
        generate()
    out = {
        "generator": "tests/data/topography/reference.py",
        "surface_topography": SurfaceTopography.__version__,
        "numpy": np.__version__,
        "samples": [record(name, fmt) for name, fmt in SAMPLES],
    }
    with open(os.path.join(HERE, "reference.json"), "w") as f:
        json.dump(out, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
