"""The `tress_cli` fixture of the Python package's tests, and this folder's modules on
the path."""

import sys
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parents[1] / "python" / "tests"))
sys.path.insert(0, str(HERE.parent))

from tress_testing import cli_or_skip  # noqa: E402


@pytest.fixture(scope="session")
def tress_cli():
    """Path of the `tress` command."""
    return cli_or_skip()
