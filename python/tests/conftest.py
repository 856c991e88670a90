"""Shared fixtures: the source tree, the hsx program (for agreement with the CLI) and small scenes."""
import os
import pathlib
import shutil

import pytest

SOURCE = pathlib.Path(os.environ.get("HSX_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))


@pytest.fixture(scope="session")
def source_dir():
    return SOURCE


@pytest.fixture(scope="session")
def scenes_dir():
    return SOURCE / "data" / "scenes"


@pytest.fixture(scope="session")
def hsx_program():
    """The hsx program of the same build (ctest passes HSX_PROGRAM); tests needing it are skipped without it."""
    path = os.environ.get("HSX_PROGRAM") or shutil.which("hsx")
    if not path or not os.path.exists(path):
        pytest.skip("the hsx program is not available (set HSX_PROGRAM)")
    return path
