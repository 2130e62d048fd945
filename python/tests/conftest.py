"""Shared set-up of the Python tests: the frame size (small, so the suite takes seconds) and
the CLI binary, which ctest passes in PENUMBRA_CLI (python/CMakeLists.txt)."""
import os
import shutil

import pytest

WIDTH, HEIGHT = 160, 107


@pytest.fixture
def cli():
    path = os.environ.get("PENUMBRA_CLI") or shutil.which("penumbra")
    if not path:
        pytest.skip("PENUMBRA_CLI is not set (ctest sets it to the built CLI)")
    return path


@pytest.fixture
def source_dir():
    here = os.path.dirname(os.path.abspath(__file__))
    return os.environ.get("PENUMBRA_SOURCE_DIR") or os.path.dirname(os.path.dirname(here))
