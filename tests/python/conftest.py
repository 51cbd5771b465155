# The Python module's tests run against the module on PYTHONPATH (the build tree's under CTest, or an
# installed one) and compare it with the `uvtk` program: UVTK_BIN, or the build tree's next to the
# module, or `uvtk` on PATH. UVTK_MESHES_DIR overrides the repository's meshes/ folder.
import os
import pathlib
import shutil
import subprocess

import pytest

import uvtk


def _find_binary():
    if os.environ.get("UVTK_BIN"):
        return pathlib.Path(os.environ["UVTK_BIN"])
    # The build tree's: build/python/uvtk/__init__.py -> build/apps/uvtk/uvtk.
    beside = pathlib.Path(uvtk.__file__).resolve().parents[2] / "apps" / "uvtk" / "uvtk"
    if beside.exists():
        return beside
    found = shutil.which("uvtk")
    return pathlib.Path(found) if found else None


@pytest.fixture(scope="session")
def uvtk_bin():
    binary = _find_binary()
    if binary is None or not binary.exists():
        pytest.skip("no uvtk program: set UVTK_BIN")
    return binary


@pytest.fixture(scope="session")
def meshes_dir():
    return pathlib.Path(os.environ.get("UVTK_MESHES_DIR", pathlib.Path(__file__).resolve().parents[2] / "meshes"))


@pytest.fixture
def cli(uvtk_bin):
    """Runs `uvtk ARGS...`; returns the CompletedProcess (check=False: tests read the exit code)."""

    def run(*args):
        return subprocess.run([str(uvtk_bin), *map(str, args)], capture_output=True, text=True)

    return run
