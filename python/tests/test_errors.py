"""Bad input raises ValueError with the command line's message in Python's
words (the parameter where the command line names its flag; scene key
paths as they are); other failures RuntimeError. A sample of the scene
fuzz's mutations (tests/it/scene_fuzz.rs: zero, negative, nan, inf, wrong
type, missing, duplicated) on the default scene."""

import re

import numpy as np
import pytest

import asperity
from conftest import REPO, SCENES, cli_error

GOLD = (REPO / "examples" / "scenes" / "mems-gold.toml").read_text()


def mutate(text, table, key, value):
    """`text` with `key = value` in `[table]` (value None: the key removed)."""
    out, inside, done = [], table == "", False
    for line in text.splitlines():
        if line.startswith("["):
            inside = line.strip() == f"[{table}]"
        if inside and not done and re.match(rf"{re.escape(key)}\s*=", line):
            done = True
            if value is not None:
                out.append(f"{key} = {value}")
            continue
        out.append(line)
    assert done, (table, key)
    return "\n".join(out) + "\n"


CASES = [
    ("surface", "sigma", "-5e-9", "surface.sigma"),
    ("surface", "sigma", "nan", "surface.sigma"),
    ("surface", "density", "0.0", "surface.density"),
    ("surface", "radius", "inf", "surface.radius"),
    ("materials", "nu1", "0.7", "materials.nu1"),
    ("materials", "e1", '"oops"', "e1"),
    ("adhesion", "w", "-0.5", "adhesion.w"),
    ("surface", "distribution", '"oops"', "distribution"),
    ("law", "kind", '"oops"', "kind"),
    ("program", "points", "0", "program.points"),
    ("accuracy", "rtol", "1.0", "accuracy.rtol"),
    ("surface", "sigma", None, "sigma"),
]


@pytest.mark.parametrize("table,key,value,field", CASES, ids=[f"{t}.{k}={v}" for t, k, v, _ in CASES])
def test_bad_scene_is_value_error_with_the_cli_message(table, key, value, field, tmp_path):
    text = mutate(GOLD, table, key, value)
    f = tmp_path / "bad.toml"
    f.write_text(text)
    want = cli_error("run", f, "--out", tmp_path / "out")
    assert field in want, want
    # The command line names the scene file; text has no file to name.
    named = f" (scene {f})"
    assert want.endswith(named), want
    with pytest.raises(ValueError) as e:
        asperity.run_toml(text)
    assert str(e.value) == want[: -len(named)]
    with pytest.raises(ValueError) as e:
        asperity.run(f)
    assert str(e.value) == want


def test_duplicated_key_is_refused(tmp_path):
    text = GOLD.replace("sigma = 5e-9", "sigma = 5e-9\nsigma = 6e-9", 1)
    f = tmp_path / "dup.toml"
    f.write_text(text)
    want = cli_error("run", f, "--out", tmp_path / "out")
    named = f" (scene {f})"
    assert want.endswith(named), want
    with pytest.raises(ValueError) as e:
        asperity.run_toml(text)
    assert str(e.value) == want[: -len(named)] and "sigma" in want
    with pytest.raises(ValueError) as e:
        asperity.run(f)
    assert str(e.value) == want


def test_bad_dict_value_names_the_field():
    d = asperity.default_scene()
    d["surface"]["sigma"] = -1e-9
    with pytest.raises(ValueError, match=r"surface\.sigma"):
        asperity.run(d)
    d = asperity.default_scene()
    d["surface"]["unknown_key"] = 1.0
    with pytest.raises(ValueError, match="unknown_key"):
        asperity.run(d)


def test_missing_file_is_value_error_like_the_cli(tmp_path):
    missing = tmp_path / "none.toml"
    want = cli_error("run", missing)
    with pytest.raises(ValueError) as e:
        asperity.run(missing)
    assert str(e.value) == want


def in_python_words(cli_message, words=()):
    """The command line's message with each flag as the Python parameter
    (`--q-long` -> `q_long`, `--lambda` -> `lambda_`), `words` first."""
    for flag, word in words:
        cli_message = cli_message.replace(flag, word)
    python = re.sub(r"--([a-z][a-z-]*)", lambda m: m.group(1).replace("-", "_"), cli_message)
    return python.replace("lambda =", "lambda_ =")


@pytest.mark.parametrize(
    "call,cli_args,words",
    [
        (lambda: asperity.fn("weird", 1.0, [0.0]), ["fn", "--dist", "weird", "--n", "1", "--h", "0"], ()),
        (lambda: asperity.fn("gaussian", -1.0, [0.0]), ["fn", "--dist", "gaussian", "--n", "-1", "--h", "0"], ()),
        (
            lambda: asperity.fn("gaussian", 1.0, [np.nan]),
            ["fn", "--dist", "gaussian", "--n", "1", "--h", "NaN"],
            [("--h", "h[0]")],
        ),
        (lambda: asperity.law("maugis", lambda_=-1.0), ["law", "--law", "maugis", "--lambda", "-1"], ()),
        (lambda: asperity.heating(), ["heating"], ()),
        (lambda: asperity.heating(voltage=-1.0), ["heating", "--voltage", "-1"], ()),
        (lambda: asperity.sphere(0.0), ["sphere", "--mu", "0"], ()),
        (lambda: asperity.rough_sphere(-1.0, d=[1.0]), ["rough-sphere", "--mu", "-1", "--d", "1"], ()),
        (
            lambda: asperity.shape("cone", 1e9, 0.5),
            ["shape", "--profile", "cone", "--estar", "1e9", "--w", "0.5"],
            (),
        ),
        (
            lambda: asperity.persson(0.8, 1e5, 4e5, 4e8, 1e9, [-1.0], h_rms=1e-8),
            ["persson", "--hurst", "0.8", "--q-long", "1e5", "--q-roll", "4e5", "--q-short", "4e8",
             "--estar", "1e9", "--pressures=-1", "--h-rms", "1e-8"],
            [("--pressures", "pressures[0]")],
        ),
        (
            lambda: asperity.persson(0.8, 4e5, 1e5, 4e8, 1e9, [1.0], h_rms=1e-8),
            ["persson", "--hurst", "0.8", "--q-long", "4e5", "--q-roll", "1e5", "--q-short", "4e8",
             "--estar", "1e9", "--pressures=1", "--h-rms", "1e-8"],
            (),
        ),
        (
            lambda: asperity.punch(1.0, 0.008, 1.0, 0.1, 0.03, cycle=(0.04, -0.01)),
            ["punch", "--estar", "1", "--w", "0.008", "--radius", "1", "--amplitude", "0.1",
             "--wavelength", "0.03", "--cycle=0.04:-0.01"],
            (),
        ),
    ],
)
def test_command_errors_are_the_clis_in_python_words(call, cli_args, words):
    want = in_python_words(cli_error(*cli_args), words)
    with pytest.raises(ValueError) as e:
        call()
    assert str(e.value) == want
    assert "--" not in str(e.value)


def test_an_unknown_law_names_the_parameter():
    with pytest.raises(ValueError) as e:
        asperity.law("maugis-dugdale")
    assert str(e.value).startswith('law: unknown law "maugis-dugdale"; known: hertz'), str(e.value)


def test_array_arguments_name_themselves():
    with pytest.raises(ValueError, match=r"radius\[1\]"):
        asperity.spots([0.0, 1e-6], [0.0, 0.0], [1e-7, -1.0], 2.2e-8)
    with pytest.raises(ValueError, match="^pixel_size = -1 is out of range"):
        asperity.surface(np.zeros((8, 8)), -1.0)
    with pytest.raises(ValueError, match=r"phase\[0\]"):
        asperity.punch_fit(["sideways"], [0.1], [0.0], punch_radius=1.0)
    with pytest.raises(ValueError, match=r"^heights: NaN height at row 1, column 2"):
        h = np.zeros((4, 4))
        h[1, 2] = np.nan
        asperity.surface(h, 1e-7)


def test_failure_that_is_not_bad_input_is_runtime_error(tmp_path):
    # Writing into a path that is a file: an I/O failure (CLI exit 1).
    blocker = tmp_path / "file"
    blocker.write_text("x")
    scene = next(s for s in SCENES if s.stem == "dmt-stiff")
    with pytest.raises(RuntimeError):
        asperity.run(scene, out=blocker / "sub")
