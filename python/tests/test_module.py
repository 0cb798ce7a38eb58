"""The module's surface: its version, its type stubs, its docstrings."""
import pathlib
import re

import vri

STUB = pathlib.Path(__file__).resolve().parents[1] / "vri.pyi"
TYPING_ONLY = {"SceneLike", "TransferFunctionLike", "Trace", "RaySignal"}


def test_version_is_cmake_project_version(root, run_cli):
    cmake = (root / "CMakeLists.txt").read_text()
    version = re.search(r"project\(vri VERSION (\d+\.\d+\.\d+)", cmake).group(1)
    assert vri.__version__ == version


def test_stubs_name_every_public_name_and_no_other():
    stub = STUB.read_text()
    stubbed = set(re.findall(r"^(?:def|class) (\w+)", stub, re.M)) - TYPING_ONLY
    stubbed |= set(re.findall(r"^([a-z]\w*): ", stub, re.M))  # module attributes (has_vulkan)
    public = {n for n in dir(vri) if not n.startswith("_")}
    assert stubbed == public


def test_every_public_function_has_a_docstring():
    for name in dir(vri):
        if not name.startswith("_"):
            assert (getattr(vri, name).__doc__ or "").strip(), name
