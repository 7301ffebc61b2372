"""Shared fixtures of the Python binding tests (run by ctest as `python_bindings`, see python/CMakeLists.txt).

ctest sets PYTHONPATH to build/python, FAIRSURF_CLI to the fairsurf executable and FAIRSURF_DATA_DIR
to data/; run by hand, the defaults below assume the build tree is build/.
"""

import os
import pathlib

import pytest

# One OpenMP thread (set before the extension loads libgomp): ctest runs the suites side by side on
# CI's two cores, and OpenMP threads waiting for busy cores made these tests 6x slower (38 s vs 6 s).
# Subprocesses (the CLI, the examples) inherit it, so comparisons run alike.
os.environ.setdefault("OMP_NUM_THREADS", "1")

ROOT = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def data_dir():
    return pathlib.Path(os.environ.get("FAIRSURF_DATA_DIR", ROOT / "data"))


@pytest.fixture(scope="session")
def cli():
    return pathlib.Path(os.environ.get("FAIRSURF_CLI", ROOT / "build" / "bin" / "fairsurf"))


@pytest.fixture(scope="session")
def hand(data_dir):
    """810 vertices, one 16-edge hole at the wrist: a fill takes a fraction of a second."""
    import fairsurf

    return fairsurf.read_mesh(data_dir / "hand_lowres.obj")
