"""Scene dicts are checked key by key against the scene schema: errors name
the key path (never a TOML line), unknown keys get a near match, cycles and
deep nesting end at the first key that does not fit; the schema describes
every key and validates every example scene."""

import json
import tomllib

import numpy as np
import pytest

import asperity
from conftest import REPO, SCENES, cli, record


def test_a_cyclic_dict_is_a_value_error_naming_the_key():
    d = asperity.default_scene()
    d["surface"]["self"] = d
    with pytest.raises(ValueError) as e:
        asperity.run(d)
    assert record(e).startswith("surface.self: unknown key"), str(e.value)


def test_unknown_keys_suggest_the_nearest():
    d = asperity.default_scene()
    d["surface"]["sigmaa"] = d["surface"].pop("sigma")
    with pytest.raises(ValueError) as e:
        asperity.run(d)
    msg = record(e)
    assert msg == "surface.sigmaa: unknown key (did you mean surface.sigma?)", msg
    assert "line" not in msg
    d = asperity.default_scene()
    d["surfaces"] = d.pop("surface")
    with pytest.raises(ValueError) as e:
        asperity.run(d)
    assert record(e) == "surfaces: unknown key (did you mean surface?)"


@pytest.mark.parametrize(
    "edit,start",
    [
        (lambda d: d["surface"].update({1: 2.0}), "surface: keys must be str"),
        (lambda d: d["surface"].update(sigma={"x": 1.0}), "surface.sigma: expected a number (m), got dict"),
        (lambda d: d["surface"].update(sigma="5e-9"), "surface.sigma: expected a number (m), got str"),
        (lambda d: d["surface"].update(sigma=[5e-9]), "surface.sigma: expected a number (m), got list"),
        (lambda d: d["surface"].update(sigma=float("nan")), "surface.sigma = NaN is out of range"),
        (lambda d: d["surface"].update(sigma=float("inf")), "surface.sigma = inf is out of range"),
        (lambda d: d["program"].update(points=2**70), "program.points: the integer"),
        (lambda d: d["program"].update(points=2.5), "program.points: expected an integer, got float"),
        (lambda d: d.update(surface=[1, 2]), "surface: expected a dict, got list"),
        (lambda d: d["law"].update(kind=object()), "law.kind: cannot put object"),
        (lambda d: d["surface"].update(sigma=-1e-9), "surface.sigma = -1e-9 is out of range"),
        (lambda d: d["law"].update(kind="maugis-dugdale"), 'law.kind: unknown law "maugis-dugdale"; known: auto, hertz'),
    ],
)
def test_bad_values_name_their_key_path(edit, start):
    d = asperity.default_scene()
    edit(d)
    with pytest.raises((ValueError, TypeError)) as e:
        asperity.run(d)
    msg = record(e)
    assert msg.startswith(start), msg
    assert "line " not in msg, msg


def test_numbers_of_every_python_and_numpy_kind_are_accepted():
    def max_load(sigma, points):
        d = asperity.default_scene()
        d["surface"]["sigma"] = sigma
        d["program"]["points"] = points
        return asperity.run(d).summary["max_load"]

    for sigma, points in [
        (np.float64(5e-9), np.int64(40)),
        (np.float32(5e-9), 40),
        (5e-9, np.uint16(40)),
        (np.array(5e-9), np.array(40)),
        (4e-9, True and 40),
    ]:
        assert max_load(sigma, points) == max_load(float(sigma), int(points))


def test_none_means_not_given():
    d = asperity.default_scene()
    d["program"]["points"] = 40
    d["montecarlo"] = None
    assert asperity.run(d).montecarlo is None


def test_the_schema_is_the_command_lines_and_describes_every_key():
    s = asperity.scene_schema()
    assert s["$schema"] == "https://json-schema.org/draft/2020-12/schema"
    assert json.loads(cli("schema", "--json").stdout) == s
    sigma = s["$defs"]["SurfaceSpec"]["properties"]["sigma"]
    assert sigma["x-unit"] == "m" and "description" in sigma


def test_every_example_scene_validates_against_the_schema():
    import jsonschema  # installed by .ci/run: the test must not skip
    s = asperity.scene_schema()
    jsonschema.Draft202012Validator.check_schema(s)
    validator = jsonschema.Draft202012Validator(s)
    for path in SCENES:
        scene = tomllib.loads(path.read_text())
        errors = list(validator.iter_errors(scene))
        assert not errors, (path.name, [e.message for e in errors][:3])
    assert not list(validator.iter_errors(asperity.default_scene()))
    # And it can fail: a misspelled key, a string for a number.
    bad = asperity.default_scene()
    bad["surface"]["sigmaa"] = 1.0
    assert list(validator.iter_errors(bad))
    bad = asperity.default_scene()
    bad["surface"]["sigma"] = "5e-9"
    assert list(validator.iter_errors(bad))


def test_help_lists_the_sections_and_points_to_the_schema():
    doc = asperity.run.__doc__
    for section in ("materials", "surface", "adhesion", "law", "program", "outputs", "accuracy",
                    "montecarlo", "electrical", "switch", "sphere"):
        assert f"``{section}``" in doc, section
    assert "scene_schema()" in doc


FUNCTIONS = ["run", "run_toml", "sweep", "default_scene", "scene_schema", "fn", "law", "heating",
             "spots", "surface", "shape", "punch", "punch_fit", "persson", "sphere", "rough_sphere", "bem"]


@pytest.mark.parametrize("name", FUNCTIONS)
def test_every_function_documents_its_parameters_and_returns(name):
    doc = getattr(asperity, name).__doc__ or ""
    assert len(doc) > 150, name
    import inspect
    params = [p for p in inspect.signature(getattr(asperity, name)).parameters]
    if params:
        assert "Parameters" in doc, name
        for p in params:
            assert p in doc, (name, p)
    assert "Returns" in doc or name in ("default_scene", "scene_schema", "run_toml"), name
    assert "Example" in doc or name in ("punch_fit", "sphere", "default_scene"), name
