"""examples/: the script runs, the notebook is made from it and executes."""
import importlib.util
import os
import pathlib
import re
import shutil
import subprocess
import sys

import pytest

import vri


def example_env(tmp_path):
    env = dict(os.environ, VRI_EXAMPLE_SIZE="48", VRI_EXAMPLE_OUT=str(tmp_path), MPLBACKEND="Agg")
    env["PATH"] = "/usr/bin:" + env.get("PATH", "")  # Debian's python3 and jupyter, which have numpy
    # The kernel runs in the notebook's folder: the module's path must be absolute.
    env["PYTHONPATH"] = str(pathlib.Path(vri.__file__).resolve().parent.parent)  # the folder holding the package
    return env


def test_script_plots_both_methods_and_preint1_wins_at_every_step(root, tmp_path):
    done = subprocess.run([sys.executable, root / "examples" / "render_methods.py"], cwd=root,
                          env=example_env(tmp_path), capture_output=True, text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    assert (tmp_path / "render_methods.png").stat().st_size > 10_000
    rows = dict(re.findall(r"^(riemann|preint1) (.*)$", done.stdout, re.M))
    error = {m: {float(h): float(e) for h, e in (x.split(":") for x in rows[m].split())} for m in rows}
    # Pre-integration integrates the narrow spike between samples, point
    # sampling steps over it: preint1 is closer to exact at every step (2-4x
    # at 48x48), and its error shrinks with the step.
    for h in error["riemann"]:
        assert error["preint1"][h] < error["riemann"][h]
    assert error["preint1"][0.25] < 0.7 * error["preint1"][4.0]


def test_notebook_is_made_from_the_script(root):
    spec = importlib.util.spec_from_file_location("make_notebook", root / "examples" / "make_notebook.py")
    maker = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(maker)
    script = (root / "examples" / "render_methods.py").read_text()
    assert (root / "examples" / "render_methods.ipynb").read_text() == maker.text(script)


def test_notebook_executes(root, tmp_path):
    if not shutil.which("jupyter-nbconvert", path="/usr/bin"):
        pytest.skip("jupyter-nbconvert is not installed (scripts/install-deps.sh installs it)")
    shutil.copy(root / "examples" / "render_methods.ipynb", tmp_path)
    env = example_env(tmp_path)
    env.pop("MPLBACKEND")  # the kernel's inline backend shows the figure
    env["VRI_EXAMPLE_ROOT"] = str(root)
    done = subprocess.run(["/usr/bin/jupyter-nbconvert", "--to", "notebook", "--execute", "--output", "executed.ipynb",
                           tmp_path / "render_methods.ipynb"], cwd=root, env=env, capture_output=True, text=True,
                          timeout=600)
    assert done.returncode == 0, done.stderr
    executed = (tmp_path / "executed.ipynb").read_text()
    assert re.search(r"preint1 +step 1: RMS error", executed) and "image/png" in executed
