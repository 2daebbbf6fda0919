"""The package itself: version, exports, type stubs."""

import re
from pathlib import Path

import asperity
from conftest import REPO, cli


def test_version_is_the_crate_version():
    cargo = (REPO / "Cargo.toml").read_text()
    version = re.search(r'\[workspace\.package\]\s*version = "([^"]+)"', cargo).group(1)
    assert asperity.__version__ == version
    assert cli("--version").stdout.split() == ["asperity", version]


def test_stubs_and_marker_are_installed():
    pkg = Path(asperity.__file__).parent
    assert (pkg / "py.typed").exists()
    stub = (pkg / "__init__.pyi").read_text()
    for name in asperity.__all__:
        if name != "__version__":
            assert re.search(rf"^(def|class) {name}\b", stub, re.M), name


def test_every_json_subcommand_has_a_function():
    # Subcommands of `asperity --help` that print JSON (all but run's
    # companions sweep/merge, which write files, and map, which draws).
    text = cli("--help").stdout
    commands = re.findall(r"^  ([a-z][a-z-]*)\s", text, re.M)
    assert "punch-fit" in commands and "rough-sphere" in commands
    python_name = {"schema": "scene_schema"}
    for c in commands:
        if c in ("merge", "map", "help"):
            continue
        assert hasattr(asperity, python_name.get(c, c.replace("-", "_"))), c
