"""The module's surface: its version, its type stubs, its docstrings."""
import pathlib
import re

import pytest
import vri

STUB = pathlib.Path(__file__).resolve().parents[1] / "vri" / "__init__.pyi"
TYPING_ONLY = {"SceneLike", "TransferFunctionLike", "Trace", "RaySignal", "MethodInfo", "MethodParameter"}


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


def test_methods_are_the_registry_and_say_what_renders(root):
    methods = vri.methods()
    assert [m["name"] for m in methods] == ["riemann", "preint1", "preint2", "preint2-dual", "adaptive", "exact",
                                            "pt", "pt-cylindrical", "tet-raycast"]
    assert all(m["paper"] for m in methods)
    rules = {p["key"]: p for p in vri.method_parameters()}
    assert rules["table_size"] == {"key": "table_size", "flag": "--table-size", "expects": "an integer in [2, 4096]"}
    for m in methods:  # each listed key is a method key: numeric ones have a rule
        assert m["parameters"] and all(k in rules or k in ("builder", "strategy") for k in m["parameters"]), m
    grid = root / "scenes" / "neghip.json"
    for m in methods:  # each claim about grids holds for vri.render
        if m["grid"]:
            assert vri.render(grid, method=m["name"], width=4, height=3).shape == (3, 4, 4)
        else:
            with pytest.raises(ValueError, match=f"method '{m['name']}' needs a tetrahedral mesh"):
                vri.render(grid, method=m["name"], width=4, height=3)
