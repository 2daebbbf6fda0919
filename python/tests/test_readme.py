"""The Python blocks of python/README.md run as written from the
repository root (the Slurm block needs a Slurm cluster and is only
compiled). Needs matplotlib and dask[distributed], which .ci/run installs."""

import re
import subprocess
import sys

from conftest import REPO

README = (REPO / "python" / "README.md").read_text()
BLOCKS = re.findall(r"```python\n(.*?)```", README, re.S)
OUTPUTS = ["load_area.png", "resistance_force.png"]


def test_readme_blocks_run_from_the_repository_root():
    assert len(BLOCKS) == 8
    try:
        for code in BLOCKS:
            if "SLURMCluster" in code:
                compile(code, "README.md", "exec")
                continue
            r = subprocess.run([sys.executable, "-c", code], cwd=REPO, capture_output=True, text=True, timeout=600)
            assert r.returncode == 0, f"{code}\n{r.stderr}"
        for f in OUTPUTS:
            assert (REPO / f).stat().st_size > 0, f
    finally:
        for f in OUTPUTS:
            (REPO / f).unlink(missing_ok=True)
