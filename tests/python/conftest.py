"""What the tests of the Python package share: the vigen command line of the
same build (VIGEN_CLI, set by ctest), run as a subprocess to compare the
package with it, and the source tree."""
import os
import shutil
import subprocess

import pytest

SOURCE_DIR = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def _cli_path():
    path = os.environ.get("VIGEN_CLI") or os.path.join(SOURCE_DIR, "build", "vigen")
    if not os.path.exists(path):
        path = shutil.which("vigen")
    return path


@pytest.fixture(scope="session")
def source_dir():
    """The source tree (tableaux/, docs/, ...)."""
    return SOURCE_DIR


@pytest.fixture(scope="session")
def cli():
    """run(*args) -> CompletedProcess of the vigen command line (text)."""
    path = _cli_path()
    if path is None:
        pytest.skip("the vigen command line is not built")

    def run(*args, check=False):
        return subprocess.run([path, *args], capture_output=True, text=True, check=check, cwd=SOURCE_DIR)

    return run
