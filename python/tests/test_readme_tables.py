"""python/README.md's table of errors: each example is what the package
raises. The rows whose example holds the machine's numbers (the memory
available, a CPU time) or needs a forced panic are raised by
test_robust.py; here their type and fixed words are checked against it.
(The function table is checked against the stubs by the Rust test
tests/it/doc_reference_tables.rs.)"""

import numpy as np
import pytest

import asperity
from conftest import REPO

README = (REPO / "python" / "README.md").read_text()
ROBUST = (REPO / "python" / "tests" / "test_robust.py").read_text()


def error_rows():
    lines = README[README.index("| what | raises | for example |"):].splitlines()[2:]
    rows = []
    for line in lines:
        if not line.startswith("|"):
            break
        what, raises, example = (c.strip() for c in line.strip().strip("|").split("|"))
        rows.append((what, raises.strip("`"), example.strip("`")))
    return rows


def scene_with(**surface):
    d = asperity.default_scene()
    d["surface"] = {**d["surface"], **surface}
    return d


HEIGHTS = np.random.default_rng(0).normal(size=(8, 8)) * 1e-9

# The call that raises each row's example, by the row's first words.
CALLS = {
    "a value out of range": lambda: asperity.surface(np.zeros((4, 4)), -1),
    "an entry of an array": lambda: asperity.bem(HEIGHTS, 1e-8, 1e9, pressures=[1e3, 2e3, -1]),
    "a scene key": lambda: asperity.run(scene_with(sigmaa=5e-9)),
    "a scene value of the wrong type": lambda: asperity.run(scene_with(sigma="5e-9")),
    "an array of booleans": lambda: asperity.surface(np.zeros((4, 4), complex), 1e-9),
    "an array of the wrong shape": lambda: asperity.surface(np.zeros(10), 1e-9),
}

# Rows raised by test_robust.py: the words of the example it asserts.
ROBUST_WORDS = {
    "more memory than the process may use": "MemoryError",
    "a sweep beyond its CPU limit": "max_cpu_seconds: the first point took ",
    "a bug in asperity": "internal error in asperity.",
}


def test_every_error_row_is_what_the_package_raises():
    rows = error_rows()
    assert len(rows) == 10, rows
    checked = 0
    for what, raises, example in rows:
        call = next((c for k, c in CALLS.items() if what.startswith(k)), None)
        if call is None:
            words = next((w for k, w in ROBUST_WORDS.items() if what.startswith(k)), None)
            if words is not None:
                assert words in ROBUST, (what, words)
                assert example.startswith(words) or words == raises, (what, example)
                checked += 1
            else:
                assert raises == "RuntimeError" and not example, (what, raises, example)
            continue
        with pytest.raises({"ValueError": ValueError, "TypeError": TypeError}[raises]) as e:
            call()
        assert type(e.value).__name__ == raises, (what, type(e.value))
        message = str(e.value)
        shown = example.split("...")[0].rstrip(": ")
        assert message.startswith(shown), (what, message, example)
        if "..." not in example:
            assert message == example, (what, message)
        checked += 1
    assert checked == 9, checked
