"""Shared helpers: the command-line program of the same tree and a deep
comparison of Python results against its JSON.

The CLI is found at $ASPERITY_CLI or target/release/asperity (built by
`cargo build --release`, as .ci/run does); without it the tests fail with
that instruction rather than skip.
"""

import json
import math
import os
import signal
import subprocess
from pathlib import Path

import numpy as np
import pytest

# A job started in the background by a non-interactive shell has SIGINT
# ignored, and its children inherit that: a child Python then installs no
# KeyboardInterrupt handler and the Ctrl-C tests (and the README's Ctrl-C
# walk-through) could not be interrupted. Take SIGINT back for this process;
# a handled signal is reset to the default in a child at exec, so the
# children's Python installs its own handler again.
if signal.getsignal(signal.SIGINT) is signal.SIG_IGN:
    signal.signal(signal.SIGINT, signal.default_int_handler)

REPO = Path(__file__).resolve().parents[2]

# Every message an exception provoked under `pytest.raises` carries (and
# those passed to `record`): test_zz_messages.py checks that none speaks
# the command line's language (`--flags`).
MESSAGES = []
_raises = pytest.raises


class _Recording:
    def __init__(self, ctx):
        self.ctx = ctx

    def __enter__(self):
        return self.ctx.__enter__()

    def __exit__(self, kind, value, tb):
        if value is not None:
            MESSAGES.append(str(value))
        return self.ctx.__exit__(kind, value, tb)


def _recording_raises(*args, **kwargs):
    if len(args) > 1:  # the callable form: pytest.raises(E, f, *args)
        info = _raises(*args, **kwargs)
        MESSAGES.append(str(info.value))
        return info
    return _Recording(_raises(*args, **kwargs))


pytest.raises = _recording_raises


def record(e):
    """The message of `e` (an ExceptionInfo, an exception or a str),
    recorded for test_zz_messages.py."""
    msg = str(e.value) if hasattr(e, "value") else str(e)
    MESSAGES.append(msg)
    return msg
SCENES = sorted((REPO / "examples" / "scenes").glob("*.toml"))
# Values that are wall-clock times, not results.
TIMES = {"seconds", "solve_wall_s", "exact_seconds"}
RTOL = 1e-12


def cli_path() -> Path:
    p = Path(os.environ.get("ASPERITY_CLI", REPO / "target" / "release" / "asperity"))
    if not p.exists():
        pytest.fail(
            f"the asperity CLI is not at {p}: run `cargo build --release` "
            "(or set ASPERITY_CLI) before pytest python/tests"
        )
    return p


def cli(*args, cwd=None, check=True):
    """Runs the CLI; returns the CompletedProcess (text)."""
    r = subprocess.run(
        [str(cli_path()), *map(str, args)],
        capture_output=True,
        text=True,
        cwd=cwd,
    )
    if check and r.returncode != 0:
        raise AssertionError(f"asperity {' '.join(map(str, args))} exited {r.returncode}: {r.stderr}")
    return r


def cli_json(*args, cwd=None):
    """`asperity ARGS --json` parsed."""
    return json.loads(cli(*args, "--json", cwd=cwd).stdout)


def cli_error(*args, cwd=None):
    """The one-line message of a CLI run that must exit 2 (bad input)."""
    r = cli(*args, cwd=cwd, check=False)
    assert r.returncode == 2, (r.returncode, r.stdout, r.stderr)
    lines = [l for l in r.stderr.splitlines() if l.startswith("error: ")]
    assert lines, r.stderr
    return lines[-1][len("error: "):]


def close(a: float, b: float, rtol: float = RTOL) -> bool:
    if math.isnan(a) and math.isnan(b):
        return True
    return a == b or abs(a - b) <= rtol * max(abs(a), abs(b))


def assert_same(py, ref, path="", rtol=RTOL):
    """Python result `py` equals the CLI's JSON `ref` (numbers to `rtol`
    relative; NumPy arrays against lists; wall-clock times skipped)."""
    if isinstance(py, (np.ndarray, np.generic)):
        py = py.tolist()
    if isinstance(ref, (np.ndarray, np.generic)):
        ref = ref.tolist()
    if isinstance(ref, dict):
        assert isinstance(py, dict), f"{path}: {type(py)} is not a dict"
        assert set(py) == set(ref), f"{path}: keys {sorted(set(py) ^ set(ref))} differ"
        for k in ref:
            if k in TIMES:
                continue
            assert_same(py[k], ref[k], f"{path}.{k}", rtol)
    elif isinstance(ref, list):
        assert isinstance(py, list), f"{path}: {type(py)} is not a list"
        assert len(py) == len(ref), f"{path}: {len(py)} items, CLI {len(ref)}"
        for i, (a, b) in enumerate(zip(py, ref)):
            assert_same(a, b, f"{path}[{i}]", rtol)
    elif isinstance(ref, bool) or ref is None or isinstance(ref, str):
        assert py == ref, f"{path}: {py!r} != CLI {ref!r}"
    elif isinstance(ref, (int, float)):
        assert isinstance(py, (int, float)) and not isinstance(py, bool), f"{path}: {py!r}"
        assert close(float(py), float(ref), rtol), f"{path}: {py!r} != CLI {ref!r}"
    else:
        raise AssertionError(f"{path}: unexpected {type(ref)}")


def read_csv_columns(path: Path):
    """A CSV the CLI wrote, as columns of str."""
    lines = [l for l in path.read_text().splitlines() if l]
    names = lines[0].split(",")
    cols = {n: [] for n in names}
    for line in lines[1:]:
        for n, cell in zip(names, line.split(",")):
            cols[n].append(cell)
    # A sweep's rows end in their checksum, which the file alone carries.
    cols.pop("checksum", None)
    return cols


TEXT = {"leg", "note", "status"}


def assert_table(py: dict, csv_path: Path):
    """A table from Python equals the CSV the CLI wrote, column by column."""
    ref = read_csv_columns(csv_path)
    assert list(py) == list(ref), (list(py), list(ref))
    for name, cells in ref.items():
        col = py[name]
        assert isinstance(col, np.ndarray), name
        assert len(col) == len(cells), name
        if name in TEXT:
            assert col.tolist() == cells, name
        else:
            want = np.array([float(c) if c else np.nan for c in cells])
            got = col.astype(float)
            same = (got == want) | (np.isnan(got) & np.isnan(want))
            assert same.all(), (name, got[~same][:3], want[~same][:3])
