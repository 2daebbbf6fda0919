"""asperity: adhesive contact between rough surfaces, from Python.

A thin layer over the Rust library (pyo3 + NumPy; python/README.md): scenes
run as ``asperity run`` runs them (``run``, ``sweep``; every key in
``scene_schema()``), and every command of the ``asperity`` program that
prints JSON is a function taking the command's flags as keyword arguments.
SI units throughout. Every call releases the GIL while the library
computes, so threads run in parallel; long calls stop within a second of
Ctrl-C (``KeyboardInterrupt``), leaving nothing half-written.

Errors name the parameter or the scene key path: bad input raises
``ValueError`` (``surface.sigma = -1e-09 is out of range: ...``,
``pixel_size = -1 is out of range: ...``), an array of the wrong kind
``TypeError``, work beyond the memory available ``MemoryError`` (before
anything is allocated), every other failure ``RuntimeError``.
"""

from ._asperity import (  # noqa: F401
    RunResult,
    __version__,
    bem,
    default_scene,
    heating,
    law,
    persson,
    punch,
    punch_fit,
    read_topography,
    rough_sphere,
    run,
    run_toml,
    scene_schema,
    shape,
    sphere,
    spots,
    surface,
    sweep,
)
from ._asperity import fn  # noqa: F401  (the command's name, `asperity fn`)

__all__ = [
    "RunResult",
    "__version__",
    "bem",
    "default_scene",
    "fn",
    "heating",
    "law",
    "persson",
    "punch",
    "punch_fit",
    "read_topography",
    "rough_sphere",
    "run",
    "run_toml",
    "scene_schema",
    "shape",
    "sphere",
    "spots",
    "surface",
    "sweep",
]
