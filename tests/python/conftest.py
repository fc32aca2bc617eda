"""The cosmems package under test is the build's (PYTHONPATH=<build>/python, set by CTest)."""
import os

import pytest


@pytest.fixture
def cli():
    """The `cosmems` command line of the same build."""
    path = os.environ.get("COSMEMS_CLI")
    if not path:
        pytest.skip("COSMEMS_CLI is not set (CTest sets it)")
    return path
