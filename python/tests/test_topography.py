"""`asperity.read_topography`: every instrument sample against
SurfaceTopography 1.27.1 (tests/data/topography/reference.json), the
metadata against `asperity surface FILE --json`'s "source", an exported X3P
read back bit for bit, and errors in Python's words."""

import json

import numpy as np
import pytest

import asperity
from conftest import REPO, cli, cli_json, record

DIR = REPO / "tests" / "data" / "topography"
REFERENCE = json.loads((DIR / "reference.json").read_text())["samples"]


@pytest.mark.parametrize("r", REFERENCE, ids=[r["file"] for r in REFERENCE])
def test_reads_as_surface_topography(r):
    h, meta = asperity.read_topography(DIR / r["file"])
    assert h.dtype == np.float64 and h.shape == (r["rows"], r["cols"])
    assert (meta["rows"], meta["cols"]) == (r["rows"], r["cols"])
    assert meta["format"] == r["format"]
    assert meta["periodic"] == r["periodic"]
    assert meta["missing"] == r["missing"] == int(np.isnan(h).sum())
    if r["unit"] is None:
        assert meta["pixel_size_m"] is None
    else:
        dx, dy = meta["pixel_size_m"]
        want = r["pixel_size_m"]
        assert abs(dx / want[0] - 1) <= 1e-12
        if want[1] is not None:
            assert abs(dy / want[1] - 1) <= 1e-12
    flat = h.ravel()
    for k, want in zip(r["sample_index"], r["sample_m"]):
        if want is None:
            assert np.isnan(flat[k])
        else:
            assert abs(flat[k] - want) <= 1e-12 * r["std_m"], (k, flat[k], want)
    if r["missing"]:
        assert int(np.flatnonzero(np.isnan(flat))[0]) == r["missing_first"]


@pytest.mark.parametrize("name", ["x3p-2.x3p", "di-1.di", "generated-2.gwy", "opd-1.opd"])
def test_metadata_is_the_cli_source(name):
    h, meta = asperity.read_topography(DIR / name)
    source = cli_json("surface", DIR / name, "--fill-missing")["source"]
    for k in ["format", "channel", "unit", "rows", "cols", "missing"]:
        assert meta[k] == source[k], k
    assert list(meta["pixel_size_m"]) == source["pixel_size_m"]


def test_fill_missing_fills_and_keeps_the_known_pixels():
    raw, meta = asperity.read_topography(DIR / "generated-2.gwy")
    filled, again = asperity.read_topography(DIR / "generated-2.gwy", fill_missing=True)
    assert meta["missing"] == again["missing"] == 8
    known = ~np.isnan(raw)
    assert np.array_equal(raw[known], filled[known])
    assert not np.isnan(filled).any()


def test_an_exported_x3p_reads_back_bit_for_bit(tmp_path):
    out = tmp_path / "copy.x3p"
    cli("surface", DIR / "di-2.di", "--export", out)
    a, ma = asperity.read_topography(DIR / "di-2.di")
    b, mb = asperity.read_topography(out)
    assert np.array_equal(a.view(np.uint64), b.view(np.uint64))
    assert ma["pixel_size_m"] == mb["pixel_size_m"]
    assert mb["format"] == "x3p" and mb["unit"] == "m"


def test_npy_heights_in_a_unit(tmp_path):
    p = tmp_path / "map.npy"
    np.save(p, np.arange(12.0).reshape(3, 4))
    h, meta = asperity.read_topography(p, height_unit="nm")
    assert h[2, 3] == 11.0 * 1e-9 and meta["unit"] == "nm" and meta["pixel_size_m"] is None


def test_errors_name_the_parameter_and_the_file():
    with pytest.raises(ValueError) as e:
        asperity.read_topography(DIR / "x3p-2.x3p", channel=5)
    assert "channel" in record(e) and "Default" in str(e.value)
    with pytest.raises(ValueError) as e:
        asperity.read_topography(DIR / "x3p-2.x3p", height_unit="nm")
    assert "height_unit" in record(e)
    with pytest.raises(ValueError) as e:
        asperity.read_topography(DIR / "x3p-2.x3p", height_unit="furlong")
    assert "height_unit" in record(e) and "nm, um, m" in str(e.value)
    with pytest.raises(ValueError) as e:
        asperity.read_topography(DIR / "no-such-file.sdf")
    assert "no-such-file.sdf" in record(e)
    with pytest.raises(ValueError) as e:
        asperity.read_topography(DIR / "reference.json")
    assert "unknown extension 'json'" in record(e)
    with pytest.raises(TypeError):
        asperity.read_topography(DIR / "x3p-2.x3p", channel=1.5)
