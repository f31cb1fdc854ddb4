"""The `tress_cli` fixture; helpers are in tress_testing.py (shared with the Blender and
Maya tests)."""

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))

from tress_testing import cli_or_skip  # noqa: E402


@pytest.fixture(scope="session")
def tress_cli():
    """Path of the `tress` command."""
    return cli_or_skip()
