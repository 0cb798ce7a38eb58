"""Shared fixtures: the repository root, the CLI next to the module, and a
helper that runs it. PYTHONPATH and VRI_CLI come from ctest (python/CMakeLists.txt)."""
import os
import pathlib
import subprocess

import numpy as np
import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def root():
    return ROOT


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("VRI_CLI")
    if not path:
        pytest.skip("VRI_CLI is not set (run through ctest)")
    return path


@pytest.fixture
def run_cli(cli):
    """Runs `vri ARGS...`; returns the CompletedProcess (text)."""
    def run(*args, check=True):
        done = subprocess.run([cli, *map(str, args)], capture_output=True, text=True)
        if check and done.returncode != 0:
            raise AssertionError(f"vri {' '.join(map(str, args))} failed: {done.stderr}")
        return done
    return run


@pytest.fixture
def cli_render(run_cli, tmp_path):
    """The CLI's .npy of a scene file with flags, loaded."""
    def render(scene, *flags):
        out = tmp_path / f"cli_{len(list(tmp_path.iterdir()))}.npy"
        run_cli("render", scene, "-o", out, *flags)
        return np.load(out)
    return render
