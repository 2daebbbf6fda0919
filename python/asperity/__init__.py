"""asperity: adhesive contact between rough surfaces, from Python.

A thin layer over the Rust library (pyo3 + NumPy; python/README.md): scenes
run as ``asperity run`` runs them, and every command of the ``asperity``
program that prints JSON is a function taking the command's flags as
keyword arguments. SI units throughout. Every call releases the
GIL while the library computes, so threads run in parallel.

Errors: bad input raises ``ValueError`` whose message names the field or
flag exactly as the command line does (``surface.sigma = -1e-9 is out of
range: ...``, ``--h: ...``); every other failure raises ``RuntimeError``.
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
    rough_sphere,
    run,
    run_toml,
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
    "rough_sphere",
    "run",
    "run_toml",
    "shape",
    "sphere",
    "spots",
    "surface",
    "sweep",
]
