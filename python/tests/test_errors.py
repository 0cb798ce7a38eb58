"""Bad input raises ValueError / OSError / TypeError with the CLI's one-line message."""
import json

import numpy as np
import pytest

import vri


def cli_error(run_cli, *args):
    done = run_cli(*args, check=False)
    assert done.returncode != 0
    line = done.stderr.strip().splitlines()[-1]
    assert line.startswith("vri: error: ")
    return line[len("vri: error: "):]


def test_missing_file_is_an_os_error(tmp_path):
    with pytest.raises(OSError, match="cannot open"):
        vri.load_scene(tmp_path / "nowhere.json")


def test_bad_scene_value_has_the_cli_message(root, run_cli, tmp_path):
    scene = json.loads((root / "scenes" / "neghip.json").read_text())
    scene["method"]["name"] = "preint3"
    path = tmp_path / "bad.json"
    scene["volume"]["file"] = str(root / "data" / "neghip_64x64x64_uint8.raw")
    scene["transfer_function"]["file"] = str(root / "presets" / "neghip.json")
    path.write_text(json.dumps(scene))
    message = cli_error(run_cli, "render", path, "-o", tmp_path / "x.npy")
    with pytest.raises(ValueError) as raised:
        vri.render(vri.load_scene(path))
    assert str(raised.value) == message
    assert "preint3" in message
    assert not (tmp_path / "x.npy").exists()


def test_bad_override_has_the_cli_message(root, run_cli, tmp_path):
    scene = root / "scenes" / "neghip.json"
    message = cli_error(run_cli, "render", scene, "-o", tmp_path / "x.npy", "--step", "-1", "--method", "riemann")
    with pytest.raises(ValueError) as raised:
        vri.render(scene, method="riemann", step=-1)
    assert str(raised.value) == message


def test_jitter_is_checked_as_the_cli_checks_it(root, run_cli, tmp_path):
    scene = root / "scenes" / "neghip.json"
    message = cli_error(run_cli, "render", scene, "-o", tmp_path / "x.npy", "--method", "riemann", "--jitter", "-1")
    assert "--jitter: expected an integer seed in [0, 2^53], found '-1'" in message
    with pytest.raises(ValueError, match=r"render\(\): jitter: expected an integer seed in \[0, 2\^53\], found -1"):
        vri.render(scene, method="riemann", jitter=-1)
    with pytest.raises(ValueError, match=r"found 9007199254740993"):
        vri.render(scene, method="riemann", jitter=2**53 + 1)


def test_method_parameters_are_checked_as_the_cli_and_the_scene_check_them(root, run_cli, tmp_path):
    scene = root / "scenes" / "neghip.json"
    for key, value, rule in [("table_size", 1, "an integer in [2, 4096]"), ("step", -1, "a finite number > 0"),
                             ("iterations", 5000, "an integer in [1, 4096]")]:
        flag = "--" + key.replace("_", "-")
        expected = f"method.{key} ({flag}): expected {rule}, found {value}"
        assert expected in cli_error(run_cli, "render", scene, "-o", tmp_path / "x.npy", flag, str(value))
        with pytest.raises(ValueError) as raised:
            vri.render(scene, **{key: value})
        assert expected in str(raised.value)


def test_work_cap_and_threads(root):
    with pytest.raises(ValueError, match="samples per ray"):
        vri.render(root / "scenes" / "neghip.json", method="riemann", step=1e-6)
    with pytest.raises(ValueError, match="--threads"):
        vri.render(root / "scenes" / "neghip.json", threads=10**6)


def test_unknown_or_mistyped_keyword_is_a_type_error(root):
    with pytest.raises(TypeError, match="unexpected keyword argument 'stpe'"):
        vri.render(root / "scenes" / "neghip.json", stpe=1.0)
    with pytest.raises(TypeError, match="'width' expected an int"):
        vri.render(root / "scenes" / "neghip.json", width="wide")
    with pytest.raises(TypeError, match="expected a vri.Scene"):
        vri.render(42)


def test_unknown_scene_key_is_refused():
    with pytest.raises(ValueError, match="trasnfer_function"):
        vri.Scene({"volume": {"builtin": "sphere"}, "trasnfer_function": {}, "camera": {}})


def test_bad_arrays_are_refused():
    with pytest.raises(ValueError, match="3-D array"):
        vri.Volume.from_numpy(np.zeros((4, 4)))
    with pytest.raises(ValueError, match="numeric"):
        vri.Volume.from_numpy(np.zeros((2, 2, 2), dtype=np.complex64))
    with pytest.raises(ValueError, match="at least 2"):
        vri.Volume.from_numpy(np.zeros((1, 4, 4)))
    a = np.zeros((3, 3, 3), dtype=np.float32)
    a[1, 2, 0] = np.nan
    with pytest.raises(ValueError, match="not finite"):
        vri.Volume.from_numpy(a)
    with pytest.raises(ValueError, match="spacing"):
        vri.Volume.from_numpy(np.zeros((2, 2, 2)), spacing=(1, 0, 1))
    with pytest.raises(ValueError, match="outside"):
        vri.Mesh.from_numpy(np.zeros((4, 3)), np.array([[0, 1, 2, 4]]), np.zeros(4))


def test_transparent_image_warns(root):
    scene = json.loads((root / "scenes" / "neghip.json").read_text())
    scene["transfer_function"] = {"points": [[0, 1, 1, 1, 0], [255, 1, 1, 1, 0]]}
    with pytest.warns(RuntimeWarning, match="every pixel is transparent"):
        image = vri.render(vri.Scene(scene, base_dir=root / "scenes"), method="preint1", width=8, height=8)
    assert not image.any()


def test_memory_budget_refuses_before_allocating(root):
    try:
        vri.set_max_memory("64K")
        with pytest.raises(ValueError, match="memory"):
            vri.load_scene(root / "scenes" / "neghip.json")
    finally:
        vri.set_max_memory(0)
    assert vri.max_memory() > 64 * 1024
