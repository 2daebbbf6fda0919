"""Array-likes: lists, int arrays, 0-d and 2-D `h` for fn; sequences for
list flags; the shape of the result follows `h`."""

import numpy as np

import asperity
from conftest import assert_same, cli_json


def test_fn_shapes_and_types():
    ref = cli_json("fn", "--dist", "gaussian", "--n", 1.5, "--h", "-1,0,1,2")
    want = np.array([v["F"] for v in ref["values"]])
    for h in ([-1, 0, 1, 2], np.array([-1, 0, 1, 2]), (-1.0, 0.0, 1.0, 2.0), np.array([-1, 0, 1, 2], dtype=np.int32)):
        got = asperity.fn("gaussian", 1.5, h)
        assert isinstance(got, np.ndarray) and got.shape == (4,) and got.dtype == np.float64
        assert_same(got, want.tolist())
    two_d = asperity.fn("gaussian", 1.5, np.array([[-1, 0], [1, 2]]))
    assert two_d.shape == (2, 2)
    assert_same(two_d.ravel(), want.tolist())
    zero_d = asperity.fn("gaussian", 1.5, 0.0)
    assert zero_d.shape == ()
    assert_same(float(zero_d), want[1])
    assert asperity.fn("gaussian", 1.5, np.array(2)).shape == ()
    assert asperity.fn("gaussian", 1.5, []).shape == (0,)
    # Non-contiguous views are read correctly.
    big = np.arange(-2.0, 2.0, 0.5)
    assert_same(asperity.fn("exponential", 1.0, big[::2]), asperity.fn("exponential", 1.0, big)[::2])


def test_list_flags_take_sequences_and_arrays():
    a = asperity.rough_sphere(10, d=[1, 2])
    b = asperity.rough_sphere(10, d=np.array([1.0, 2.0]))
    c = asperity.rough_sphere(10, d=(1, 2))
    assert_same(a, b)
    assert_same(a, c)


def test_numbers_lists_come_back_as_arrays():
    p = asperity.persson(0.8, 1e5, 4e5, 4e8, 1e9, [1e4, 1e6], h_rms=1e-8)
    assert isinstance(p["states"], list) and isinstance(p["states"][0], dict)
    r = asperity.rough_sphere(10, d=[1.0], rho=[0.0, 0.5])
    assert isinstance(r["states"][0]["pressure"], list)


def test_sweep_takes_any_sequence():
    d = asperity.default_scene()
    d["program"]["points"] = 20
    t = asperity.sweep(d, {"surface.sigma": np.array([4e-9, 6e-9]), "adhesion.w": [0, 1]})
    assert t["index"].tolist() == [0, 1, 2, 3]
    assert t["surface.sigma"].tolist() == [4e-9, 4e-9, 6e-9, 6e-9]
    assert t["adhesion.w"].tolist() == [0.0, 1.0, 0.0, 1.0]
    assert t["status"].tolist() == ["ok"] * 4
