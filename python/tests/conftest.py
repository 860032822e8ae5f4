"""Shared fixtures: the repository, the hotlap program to compare with, and a scratch folder.

Run by the test suite (ctest's PythonTests) as
``PYTHONPATH=build/python HOTLAP_BINARY=build/hotlap /usr/bin/python3 -m pytest python/tests``.
"""

import json
import os
import pathlib
import subprocess
import tempfile

import pytest

REPO = pathlib.Path(__file__).resolve().parents[2]
EXAMPLE_LOG = REPO / "data" / "telemetry" / "darlington_example.csv"
LEFT_TIR = REPO / "data" / "cars" / "gen7" / "tyres" / "left.tir"


@pytest.fixture(scope="session")
def cli():
    """Runs the hotlap program with arguments; returns the completed process (check=True)."""
    binary = os.environ.get("HOTLAP_BINARY", str(REPO / "build" / "hotlap"))
    if not pathlib.Path(binary).exists():
        pytest.fail("the hotlap program is not built (HOTLAP_BINARY=%s)" % binary)

    # `hotlap race` caches its fall-off: in a folder of the test session's, never the user's.
    cache = tempfile.mkdtemp(prefix="hotlap-test-cache-")
    env = dict(os.environ, HOTLAP_CACHE_DIR=cache)

    def run(*args, check=True):
        return subprocess.run([binary, *map(str, args)], capture_output=True, text=True,
                              check=check, env=env)

    return run


def read_csv(path):
    """A CSV in the shared format as {column: list of floats} (comment lines skipped)."""
    import numpy as np

    with open(path) as f:
        lines = [line for line in f if not line.startswith("#")]
    header = lines[0].strip().split(",")
    rows = [[float(c) if c.strip() else float("nan") for c in line.strip().split(",")] for line in lines[1:]]
    table = np.array(rows)
    return {name: table[:, i] for i, name in enumerate(header)}


def read_json(path):
    with open(path) as f:
        return json.load(f)
