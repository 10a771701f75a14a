"""Shared set-up for the Python package's tests: paths from CTest's environment."""
import os
import subprocess

import pytest

SOURCE_DIR = os.environ.get("PROXSIM_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
BINARY = os.environ.get("PROXSIM_BINARY", os.path.join(SOURCE_DIR, "build", "release", "proxsim"))
SCENARIOS = os.path.join(SOURCE_DIR, "data", "scenarios")


def scenario(name):
    return os.path.join(SCENARIOS, name)


def run_cli(*args):
    """`proxsim ARGS...`; returns the completed process (never raises on exit codes)."""
    return subprocess.run([BINARY, *args], capture_output=True, text=True, timeout=300)


def read_tree(root, skip=("timings.json", "manifest.json")):
    """{relative path: bytes} of every file under root, but the skipped names and the report (the
    manifest lists the timings and the report's files, whose sizes vary from run to run)."""
    files = {}
    for folder, _, names in os.walk(root):
        for name in names:
            path = os.path.join(folder, name)
            relative = os.path.relpath(path, root)
            if name in skip or relative.startswith("report"):
                continue
            with open(path, "rb") as f:
                files[relative] = f.read()
    return files


@pytest.fixture
def paper_sim():
    import proxsim

    with proxsim.Simulation.builtin("paper") as sim:
        yield sim
