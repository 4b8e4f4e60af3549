"""Shared fixtures of the Python tests (run by ctest: tests/CMakeLists.txt sets the paths)."""
import os
import subprocess

import pytest


@pytest.fixture(scope="session")
def reference():
    """The C++ runtime's values on fixed inputs (tests/python/reference_values.cpp), exactly."""
    out = subprocess.run([os.environ["WAVECONTACT_REFERENCE"]], check=True, capture_output=True, text=True).stdout
    values = {}
    for line in out.splitlines():
        key, value = line.split()
        values[key] = float.fromhex(value)
    return values


@pytest.fixture(scope="session")
def source_dir():
    return os.environ["WAVECONTACT_SOURCE_DIR"]
