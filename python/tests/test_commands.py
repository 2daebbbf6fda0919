"""Every JSON subcommand: the Python function equals `asperity X ... --json`
(1e-12 relative), with the flags as keyword arguments and lists of numbers
as NumPy arrays; commands that read a file take arrays."""

import numpy as np
import pytest

import asperity
from conftest import REPO, assert_same, cli_json, close

def num(x) -> str:
    """A number as the shortest text that reads back the same double."""
    return repr(float(x))


MAP = REPO / "examples" / "data" / "measured-topography.npy"
MAP_PIXEL = 50e-9


def test_law():
    for law, lam in [("jkr", None), ("maugis", 0.7), ("cos", 2.0), ("hertz", None)]:
        flags = ["--lambda", lam] if lam is not None else []
        ref = cli_json("law", "--law", law, *flags)
        assert_same(asperity.law(law, lambda_=lam), ref)


def test_fn_against_cli():
    h = [-1.5, 0.0, 0.5, 2.25, 6.0]
    for dist, n in [("gaussian", 1.5), ("exponential", 1.0), ("gaussian", 0.7)]:
        ref = cli_json("fn", "--dist", dist, "--n", n, "--h", ",".join(map(repr, h)))
        got = asperity.fn(dist, n, h)
        assert_same(got, [v["F"] for v in ref["values"]])


def test_heating():
    assert_same(asperity.heating(voltage=0.2), cli_json("heating", "--voltage", 0.2))
    assert_same(
        asperity.heating(max_temperature=500.0, bulk_temperature=300.0),
        cli_json("heating", "--max-temperature", 500, "--bulk-temperature", 300),
    )


def test_spots(tmp_path):
    # 40 spots on a jittered 8 x 5 grid of 1.25 um x 2 um cells: radii
    # below 0.2 um and jitter below 0.3 um keep them apart (overlapping
    # spots are refused, naming the pair).
    rng = np.random.default_rng(3)
    gx, gy = np.meshgrid(np.arange(8) * 1.25e-6, np.arange(5) * 2e-6)
    x = gx.ravel() + rng.uniform(-3e-7, 3e-7, 40)
    y = gy.ravel() + rng.uniform(-3e-7, 3e-7, 40)
    r = rng.uniform(5e-8, 2e-7, 40)
    f = tmp_path / "spots.csv"
    f.write_text("x_m,y_m,radius_m\n" + "".join(f"{num(a)},{num(b)},{num(c)}\n" for a, b, c in zip(x, y, r)))
    for mfp in [None, 3.8e-8]:
        flags = ["--mean-free-path", mfp] if mfp else []
        ref = cli_json("spots", f, "--resistivity", 2.2e-8, *flags)
        assert_same(asperity.spots(x, y, r, 2.2e-8, mean_free_path=mfp), ref)
    # Lists work as well as arrays.
    assert_same(asperity.spots(list(x), list(y), list(r), 2.2e-8), cli_json("spots", f, "--resistivity", 2.2e-8))


def test_surface():
    heights = np.load(MAP)
    # The CLI reads a file and says which ("source"); Python takes the array.
    ref = cli_json("surface", MAP, "--pixel-size", MAP_PIXEL, "--estar", 48e9, "--hardness", 1e9)
    assert ref.pop("source")["format"] == "npy"
    assert_same(asperity.surface(heights, MAP_PIXEL, estar=48e9, hardness=1e9), ref)
    ref = cli_json("surface", MAP, "--pixel-size", MAP_PIXEL, "--periodic")
    ref.pop("source")
    assert_same(asperity.surface(heights, MAP_PIXEL, periodic=True), ref)


def test_shape():
    ref = cli_json("shape", "--profile", "sphere", "--radius", 1e-6, "--estar", 48e9, "--w", 0.5,
                   "--radii", "1e-8,5e-8,1e-7")
    got = asperity.shape("sphere", 48e9, 0.5, radius=1e-6, radii=[1e-8, 5e-8, 1e-7])
    assert_same(got, ref)
    ref = cli_json("shape", "--profile", "cone", "--tan-angle", 0.2, "--estar", 48e9, "--w", 0.5,
                   "--stress", 1e9)
    assert_same(asperity.shape("cone", 48e9, 0.5, tan_angle=0.2, stress=1e9), ref)


FIG3 = dict(estar=1.0, w=0.007957747154594767, radius=1.0, amplitude=0.1, wavelength=0.03)


def fig3_flags():
    return [x for k, v in FIG3.items() for x in (f"--{k}", v)]


def test_punch():
    depths = np.linspace(-0.01, 0.04, 7)
    ref = cli_json("punch", *fig3_flags(), "--radii", "0.1,0.3,0.45",
                   "--depths", ",".join(map(num, depths)), "--cycle", "-0.01:0.04")
    got = asperity.punch(**FIG3, radii=np.array([0.1, 0.3, 0.45]), depths=depths, cycle=(-0.01, 0.04))
    assert_same(got, ref)
    assert_same(asperity.punch(**FIG3), cli_json("punch", *fig3_flags()))


def test_punch_fit(tmp_path):
    radii = np.linspace(0.05, 0.4, 12)
    p = asperity.punch(**FIG3, radii=radii)
    phase = ["loading"] * 12 + ["unloading"] * 12
    radius = [s["radius_m"] for s in p["envelope_loading"] + p["envelope_unloading"]]
    load = [s["load_N"] for s in p["envelope_loading"] + p["envelope_unloading"]]
    f = tmp_path / "fit.csv"
    f.write_text("phase,radius_m,load_N\n" + "".join(f"{a},{num(b)},{num(c)}\n" for a, b, c in zip(phase, radius, load)))
    ref = cli_json("punch-fit", f, "--radius", 1.0)
    got = asperity.punch_fit(phase, radius, load, punch_radius=1.0)
    assert_same(got, ref)


PERSSON = dict(hurst=0.8, q_long=1e5, q_roll=4e5, q_short=4e8, estar=1e9)


def test_persson():
    flags = [x for k, v in PERSSON.items() for x in (f"--{k.replace('_', '-')}", v)]
    ref = cli_json("persson", *flags, "--h-rms", 1e-8, "--pressures", "1e4,1e6",
                   "--gamma", 0.42, "--adhesion-energy", 0.05)
    got = asperity.persson(**PERSSON, pressures=[1e4, 1e6], h_rms=1e-8, gamma=0.42, adhesion_energy=0.05)
    assert_same(got, ref)
    ref = cli_json("persson", *flags, "--slope-rms", 0.1, "--pressures", "1e5")
    assert_same(asperity.persson(**PERSSON, pressures=np.array([1e5]), slope_rms=0.1), ref)


def test_persson_capillary_equals_cli():
    flags = [x for k, v in PERSSON.items() for x in (f"--{k.replace('_', '-')}", v)]
    ref = cli_json("persson", *flags, "--h-rms", 1e-8, "--pressures", "1e5,1e6",
                   "--relative-humidity", 0.9, "--contact-angle-2", 30)
    got = asperity.persson(**PERSSON, pressures=[1e5, 1e6], h_rms=1e-8, relative_humidity=0.9,
                           contact_angle_2=30.0)
    assert_same(got, ref)
    cap = got["capillary"]
    for s in cap["states"]:
        assert close(s["flooded_pressure_Pa"], cap["laplace_pressure_Pa"] * s["wetted_fraction"])
        assert s["contact_fraction"] < s["wetted_fraction"] < 1
    with pytest.raises(ValueError, match="relative_humidity"):
        asperity.persson(**PERSSON, pressures=[1e5], h_rms=1e-8, relative_humidity=1.5)


def test_sphere():
    ref = cli_json("sphere", "--mu", 0.5, "--resolution", 0.5)
    assert_same(asperity.sphere(0.5, resolution=0.5), ref)


def test_rough_sphere():
    ref = cli_json("rough-sphere", "--mu", 10, "--d", "1,2", "--rho", "0,0.5", "--tolerance", 1e-4, "--errors")
    got = asperity.rough_sphere(10, d=[1, 2], rho=np.array([0.0, 0.5]), tolerance=1e-4, errors=True)
    assert_same(got, ref)


def test_bem(tmp_path):
    rng = np.random.default_rng(7)
    # A small periodic random map (smoothed white noise), heights in m.
    z = rng.normal(size=(32, 32))
    k = np.fft.fftfreq(32)
    kk = np.hypot(*np.meshgrid(k, k))
    z = np.real(np.fft.ifft2(np.fft.fft2(z) * np.exp(-(kk / 0.1) ** 2))) * 1e-8
    f = tmp_path / "map.npy"
    np.save(f, z)
    ref = cli_json("bem", f, "--pixel-size", 1e-7, "--estar", 1e9, "--pressures", "1e6,1e7",
                   "--periodic", "--resistivity", 2.2e-8)
    got = asperity.bem(z, 1e-7, 1e9, pressures=[1e6, 1e7], periodic=True, resistivity=2.2e-8)
    assert_same(got, ref)
    assert isinstance(got["states"][0]["cluster_sizes_px"], list)


def test_bem_hardness_equals_cli_and_names_bad_values():
    f = REPO / "tests" / "data" / "bem_plastic_map32.npy"
    z = np.load(f)
    ref = cli_json("bem", f, "--pixel-size", 1e-6, "--estar", 1e9, "--periodic",
                   "--pressures", "5e6,5e7", "--hardness", 1e8)
    got = asperity.bem(z, 1e-6, 1e9, pressures=[5e6, 5e7], periodic=True, hardness=1e8)
    assert_same(got, ref)
    # The plastic area fraction is a result: positive at 0.05 E* on this map.
    assert got["states"][1]["plastic_area_fraction"] > 0
    for bad in (-1.0, float("inf"), float("nan")):
        with pytest.raises(ValueError, match="hardness"):
            asperity.bem(z, 1e-6, 1e9, pressures=[5e6], periodic=True, hardness=bad)
    # A mean pressure above the hardness cannot be carried: named.
    with pytest.raises(ValueError, match="pressures"):
        asperity.bem(z, 1e-6, 1e9, pressures=[2e8], periodic=True, hardness=1e8)


def test_bem_convergence_criteria_and_capillary_equal_cli():
    f = REPO / "examples" / "data" / "selfaffine-256.npy"
    z = np.load(f)
    # A capped solve: RuntimeError with its residual, or flagged when allowed.
    with pytest.raises(RuntimeError, match="residual"):
        asperity.bem(z, 3.90625e-7, 1e9, pressures=[1e6], periodic=True, max_iterations=5)
    got = asperity.bem(z, 3.90625e-7, 1e9, pressures=[1e6], periodic=True, max_iterations=5,
                       allow_unconverged=True)
    assert got["states"][0]["converged"] is False
    assert any("not converged" in w for w in got["warnings"])
    ref = cli_json("bem", f, "--pixel-size", 3.90625e-7, "--estar", 1e9, "--gaps", 2e-7,
                   "--periodic", "--adhesion-energy", 0.05, "--adhesion-range", 2e-9,
                   "--relative-humidity", 0.99)
    got = asperity.bem(z, 3.90625e-7, 1e9, gaps=[2e-7], periodic=True, adhesion_energy=0.05,
                       adhesion_range=2e-9, relative_humidity=0.99)
    for key in ("pastewka_robbins", "persson_tosatti", "tabor", "mu_rho"):
        assert close(got["adhesion_criteria"][key], ref["adhesion_criteria"][key]), key
    assert got["capillary"]["states"][0]["regime"] == ref["capillary"]["states"][0]["regime"]
    assert close(got["capillary"]["states"][0]["flooded_pressure_Pa"],
                 ref["capillary"]["states"][0]["flooded_pressure_Pa"])
    p = asperity.persson(0.8, 1e5, 4e5, 4e8, 1e9, [1e6], h_rms=1e-8, adhesion_energy=0.05,
                         adhesion_range=2e-9)
    assert p["adhesion_criteria"]["pastewka_robbins_valid"] is False


def test_sweep_equals_cli(tmp_path):
    scene = REPO / "examples" / "scenes" / "hertz-exponential.toml"
    from conftest import cli, read_csv_columns

    cli("sweep", scene, "--vary", "surface.sigma=2e-9:8e-9:3", "--vary", "program.points=20:40:2",
        "--out", tmp_path / "sw", "--threads", 2)
    ref = read_csv_columns(tmp_path / "sw" / "results.csv")
    sigma = sorted({float(v) for v in ref["surface.sigma"]})
    points = sorted({float(v) for v in ref["program.points"]})
    got = asperity.sweep(scene, {"surface.sigma": sigma, "program.points": np.array(points)}, threads=2)
    assert list(got) == list(ref)
    for name, cells in ref.items():
        col = got[name]
        assert isinstance(col, np.ndarray), name
        if name == "status":
            assert col.tolist() == cells
        elif name in ("index", "seed"):
            assert col.tolist() == [int(c) for c in cells], name
        else:
            assert_same(col, [float(c) if c else float("nan") for c in cells], name)


def test_sweep_where_every_point_fails_is_runtime_error_like_the_cli(tmp_path):
    scene = REPO / "examples" / "scenes" / "hertz-exponential.toml"
    from conftest import cli

    # A bad path is bad input, refused before any point runs (exit 2 and
    # ValueError, naming it); a sweep whose every point fails at run time
    # is exit 1 and RuntimeError.
    r = cli("sweep", scene, "--vary", "surface.nonsense=1:2:2", "--out", tmp_path / "sw", check=False)
    assert r.returncode == 2 and "surface.nonsense" in r.stderr
    with pytest.raises(ValueError, match=r"surface\.nonsense"):
        asperity.sweep(scene, {"surface.nonsense": [1.0, 2.0]})
    r = cli("sweep", scene, "--vary", "surface.sigma=1:2:2", "--out", tmp_path / "sw2", check=False)
    assert r.returncode == 1 and "every one of the 2 points failed" in r.stderr
    with pytest.raises(RuntimeError, match=r"every one of the 2 points failed"):
        asperity.sweep(scene, {"surface.sigma": [1.0, 2.0]})
