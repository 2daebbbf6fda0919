"""Every example scene: Python's run equals `asperity run SCENE --json` and
the tables the CLI writes, to 1e-12 relative (the same library, so in
practice bit for bit)."""

import os

import numpy as np
import pytest

import asperity
from conftest import SCENES, assert_same, assert_table, cli_json


@pytest.mark.parametrize("scene", SCENES, ids=[s.stem for s in SCENES])
def test_scene_equals_cli(scene, tmp_path, monkeypatch):
    ref = cli_json("run", scene, "--out", tmp_path / "cli")
    # Nothing is written unless out= is given.
    work = tmp_path / "cwd"
    work.mkdir()
    monkeypatch.chdir(work)
    r = asperity.run(scene)
    assert os.listdir(work) == []
    assert_same(r.summary, ref)
    assert_table(r.curve, tmp_path / "cli" / "curve.csv")
    mc = tmp_path / "cli" / "montecarlo.csv"
    if mc.exists():
        assert_table(r.montecarlo, mc)
    else:
        assert r.montecarlo is None
    assert r.warnings == ref["warnings"]
    assert r.states == ref.get("states")
    assert isinstance(r.curve["leg"][0], str)
    assert r.curve["separation_m"].dtype == np.float64


def test_text_dict_and_file_run_alike(tmp_path):
    scene = next(s for s in SCENES if s.stem == "rf-mems-switch")
    ref = cli_json("run", scene, "--out", tmp_path / "cli")
    assert_same(asperity.run_toml(scene.read_text()).summary, ref)
    # The default study is rf-mems-switch.toml; as a dict it runs the same.
    assert_same(asperity.run(asperity.default_scene()).summary, ref)


def test_dict_edits_and_out_writes_the_cli_files(tmp_path):
    d = asperity.default_scene()
    d["program"]["points"] = 40
    d["outputs"]["hysteresis_energy"] = False
    r = asperity.run(d, out=tmp_path / "py")
    assert r.summary["points"] == 40
    assert len(r.curve["separation_m"]) == 80
    assert r.summary["hysteresis_energy"] is None
    for f in ("curve.csv", "summary.json"):
        assert (tmp_path / "py" / f).exists(), f
    assert_table(r.curve, tmp_path / "py" / "curve.csv")


def test_path_like_and_str_paths_agree():
    scene = next(s for s in SCENES if s.stem == "dmt-stiff")
    assert_same(asperity.run(str(scene)).summary, asperity.run(scene).summary)


def test_bad_scene_argument_type():
    with pytest.raises(TypeError):
        asperity.run(42)
