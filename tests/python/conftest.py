"""Shared fixtures of the Python-module tests (run by ctest: tests/python/CMakeLists.txt).

The module is imported from SINSIM_BINARY_DIR/python; the CLI used as the outside reference is
SINSIM_BINARY_DIR/sinsim. Both come from the same build.
"""
import os
import sys

import pytest

BINARY_DIR = os.environ.get("SINSIM_BINARY_DIR", os.path.join(os.path.dirname(__file__), "../../build"))
SOURCE_DIR = os.environ.get("SINSIM_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "../.."))
sys.path.insert(0, os.path.join(BINARY_DIR, "python"))


def static_scenario(minutes=10, errors="none"):
    """A vehicle at rest at 45 deg N (as scenarios/static.yaml), as a dict."""
    return {
        "name": "static-py",
        "start": {"latitude": "45 deg", "longitude": "7 deg", "height": "250 m",
                  "heading": "0 deg"},
        "imu_rate": "100 Hz",
        "output_rate": "1 Hz",
        "vertical": {"channel": "damped", "time_constant": "100 s"},
        "errors": errors,
        "seed": 1,
        "segments": [{"type": "static", "duration": f"{minutes} min"}],
    }


@pytest.fixture
def source_dir():
    return SOURCE_DIR


@pytest.fixture
def binary_dir():
    return BINARY_DIR
