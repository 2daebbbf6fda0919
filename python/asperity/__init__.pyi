"""Type stubs of asperity (the compiled module asperity._asperity).

SI units throughout. Every function releases the GIL while it computes;
long calls stop within a second of Ctrl-C (KeyboardInterrupt). Bad input
raises ValueError (TypeError for an array of the wrong kind) naming the
parameter or the scene key path; memory beyond what is available raises
MemoryError before anything is allocated; every other failure raises
RuntimeError. The full documentation is in each function's docstring.
"""

import os
from typing import Any, Callable, Dict, List, Mapping, Optional, Sequence, Tuple, Union

import numpy as np
import numpy.typing as npt

__version__: str

ArrayLike = npt.ArrayLike
Scene = Union[Mapping[str, Any], str, "os.PathLike[str]"]
Path = Union[str, "os.PathLike[str]"]

class RunResult:
    """The result of a run (`asperity run SCENE`)."""

    @property
    def summary(self) -> Dict[str, Any]:
        """The dict `asperity run SCENE --json` prints."""
    @property
    def curve(self) -> Dict[str, npt.NDArray[Any]]:
        """`curve.csv`: column name to array (SI units as in the name, e.g.
        `separation_m`, `load_N`; `leg` as str; NaN where not computed)."""
    @property
    def montecarlo(self) -> Optional[Dict[str, npt.NDArray[Any]]]:
        """`montecarlo.csv` likewise (`leg`, `note` as str), or None."""
    @property
    def states(self) -> Optional[List[Dict[str, Any]]]:
        """The states listed by the scene's `[program] states`, or None."""
    @property
    def warnings(self) -> List[str]:
        """The run's warnings (results outside a model's validity)."""

def run(scene: Scene, *, out: Optional[Path] = None) -> RunResult:
    """Run a scene: a dict with the TOML structure or a path to a TOML file
    (a map's path relative to the file's directory). Writes `curve.csv`,
    `summary.json` and the charts into `out` only when given."""

def run_toml(text: str, *, out: Optional[Path] = None) -> RunResult:
    """Run a scene given as TOML text."""

def default_scene() -> Dict[str, Any]:
    """The default study (examples/scenes/rf-mems-switch.toml, what a bare `asperity` runs) as a dict."""

def scene_schema() -> Dict[str, Any]:
    """The JSON Schema (draft 2020-12) of scene files and dicts: every key's
    type, unit (`x-unit`), default, range and description (the same as
    `asperity schema --json`)."""

def sweep(
    scene: Scene,
    vary: Mapping[str, ArrayLike],
    threads: Optional[int] = None,
    *,
    seed: int = 0,
    max_cpu_seconds: float = 86400.0,
    progress: bool = False,
    callback: Optional[Callable[[Dict[str, Any]], Any]] = None,
) -> Dict[str, npt.NDArray[Any]]:
    """Grid over every combination of the values of each dotted scene path
    (the first slowest); returns `results.csv`'s columns (`index`, the
    paths, `seed`, `status` as str, the result columns; NaN where a point
    failed). Point seeds are SplitMix64(seed + index), as `asperity sweep`.
    The first point runs alone; its time times the others' count is the
    estimate refused beyond `max_cpu_seconds` (ValueError). `progress`
    shows points done, rate and ETA on sys.stderr; `callback` gets each
    finished row as a dict."""

def fn(dist: str, n: float, h: ArrayLike) -> npt.NDArray[np.float64]:
    """F_n(h) = int_h^inf (s - h)^n phi(s) ds of the standardised `gaussian`
    or `exponential` height distribution, in the shape of `h`."""

def law(law: str, lambda_: Optional[float] = None) -> Dict[str, Any]:
    """`asperity law --json`: pull-off facts of one law in Maugis units."""

def heating(
    voltage: Optional[float] = None,
    max_temperature: Optional[float] = None,
    bulk_temperature: float = ...,
    softening_temperature: float = ...,
    melting_temperature: float = ...,
) -> Dict[str, Any]:
    """`asperity heating --json`: peak temperature (K) at a contact voltage
    (V), or the voltage reaching a temperature (Holm, Wiedemann-Franz); no
    temperature (None, condition "molten") once the spot melts (gold's
    softening 373.15 K and melting 1337.33 K by default)."""

def spots(
    x: ArrayLike,
    y: ArrayLike,
    radius: ArrayLike,
    resistivity: float,
    mean_free_path: Optional[float] = None,
) -> Dict[str, Any]:
    """`asperity spots --json` on spots at (x, y) (m) of radii (m): parallel,
    Greenwood (1966) and exact resistances (Ohm)."""

def surface(
    heights: ArrayLike,
    pixel_size: float,
    periodic: bool = False,
    estar: Optional[float] = None,
    hardness: Optional[float] = None,
    pixel_size_y: Optional[float] = None,
) -> Dict[str, Any]:
    """`asperity surface --json` on a 2-D height map (m) with pixels of
    `pixel_size` (m) along x and `pixel_size_y` along y (default: square):
    moments, summits, GW parameters, plasticity index."""

def read_topography(
    path: Union[str, "os.PathLike[str]"],
    channel: Union[str, int, None] = None,
    height_unit: Optional[str] = None,
    fill_missing: bool = False,
) -> Tuple[np.ndarray, Dict[str, Any]]:
    """Read a measured map (AFM, profilometer, interferometer, exchange
    formats, `.npy`, text): 2-D heights in m (NaN where missing unless
    `fill_missing`) and a dict of `format`, `channel`, `unit`,
    `pixel_size_m` ((dx, dy) m or None), `rows`, `cols`, `missing`,
    `periodic`."""

def shape(
    profile: str,
    estar: float,
    w: float,
    radius: Optional[float] = None,
    tan_angle: Optional[float] = None,
    exponent: Optional[float] = None,
    coefficient: Optional[float] = None,
    radii: Optional[ArrayLike] = None,
    stress: Optional[float] = None,
) -> Dict[str, Any]:
    """`asperity shape --json`: JKR (or Maugis-Dugdale with `stress`) of an
    axisymmetric profile."""

def punch(
    estar: float,
    w: float,
    radius: float,
    amplitude: float,
    wavelength: float,
    radii: Optional[ArrayLike] = None,
    depths: Optional[ArrayLike] = None,
    cycle: Optional[ArrayLike] = None,
) -> Dict[str, Any]:
    """`asperity punch --json`: the wavy punch of Kesari & Lew (2011);
    `cycle` is (hmin, hmax) in m."""

def punch_fit(
    phase: Sequence[str],
    radius: ArrayLike,
    load: ArrayLike,
    punch_radius: float,
) -> Dict[str, Any]:
    """`asperity punch-fit --json` on measured (phase, radius m, load N)."""

def persson(
    hurst: float,
    q_long: float,
    q_roll: float,
    q_short: float,
    estar: float,
    pressures: ArrayLike,
    h_rms: Optional[float] = None,
    slope_rms: Optional[float] = None,
    gamma: float = 1.0,
    adhesion_energy: Optional[float] = None,
    adhesion_range: Optional[float] = None,
    relative_humidity: Optional[float] = None,
    surface_tension: float = 0.0728,
    contact_angle_1: float = 0.0,
    contact_angle_2: float = 0.0,
    temperature: float = 293.15,
    molar_volume: float = 1.8e-5,
) -> Dict[str, Any]:
    """`asperity persson --json`: Persson's theory and GW on a self-affine
    spectrum."""

def sphere(
    mu: float,
    rho: Optional[float] = None,
    resolution: Optional[float] = None,
    curve: Optional[Path] = None,
) -> Dict[str, Any]:
    """`asperity sphere --json`: the full Lennard-Jones sphere solver."""

def rough_sphere(
    mu: float,
    d: ArrayLike,
    rho: Optional[ArrayLike] = None,
    tolerance: Optional[float] = None,
    errors: bool = False,
    out: Optional[Path] = None,
) -> Dict[str, Any]:
    """`asperity rough-sphere --json`: Greenwood-Tripp rough sphere."""

def bem(
    heights: ArrayLike,
    pixel_size: float,
    estar: float,
    pressures: Optional[ArrayLike] = None,
    gaps: Optional[ArrayLike] = None,
    periodic: bool = False,
    adhesion_energy: Optional[float] = None,
    adhesion_range: Optional[float] = None,
    gamma: float = 1.0,
    resistivity: Optional[float] = None,
    tolerance: float = 1e-10,
    max_iterations: int = 10000,
    memory_limit_mib: float = 1024.0,
    out: Optional[Path] = None,
    allow_unconverged: bool = False,
    relative_humidity: Optional[float] = None,
    surface_tension: float = 0.0728,
    contact_angle_1: float = 0.0,
    contact_angle_2: float = 0.0,
    temperature: float = 293.15,
    molar_volume: float = 1.8e-5,
    hardness: Optional[float] = None,
) -> Dict[str, Any]:
    """`asperity bem --json` on a 2-D height map (m): FFT boundary elements
    beside GW and Persson."""
