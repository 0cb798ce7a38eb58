"""vri.render: the same bytes as `vri render -o X.npy`, from files, dicts and numpy."""
import json
import threading
import time

import numpy as np
import pytest

import vri

SMALL = dict(width=40, height=32)
CLI_SMALL = ["--width", "40", "--height", "32"]


@pytest.mark.parametrize("scene,flags", [
    ("scenes/neghip.json", dict(method="preint1", step=1.0)),
    ("scenes/neghip.json", dict(method="riemann", step=0.5)),
    ("scenes/neghip.json", dict(method="exact", tolerance=1e-3)),
    ("scenes/neghip.json", dict(method="preint2-dual")),
    ("scenes/neghip_lit.json", dict(method="preint2", step=2.0)),
    ("scenes/bonsai.json", dict(method="adaptive", strategy="guaranteed", tolerance=1e-3)),
    ("scenes/blunt_fin.json", dict(method="pt-cylindrical", table_size=64)),
    ("scenes/blunt_fin.json", dict(method="tet-raycast", table_size=64)),
])
def test_render_equals_cli_bytes(root, cli_render, scene, flags):
    cli_flags = CLI_SMALL + [x for k, v in flags.items() for x in ("--" + k.replace("_", "-"), v)]
    expected = cli_render(root / scene, *cli_flags)
    image = vri.render(vri.load_scene(root / scene), **SMALL, **flags)
    assert image.dtype == np.float32 and image.shape == (32, 40, 4)
    assert image.tobytes() == expected.tobytes()
    assert image[..., 3].max() > 0.05  # the scene is not empty


def test_render_accepts_paths_dicts_and_scenes_alike(root):
    path = root / "scenes" / "neghip.json"
    as_dict = json.loads(path.read_text())
    images = [vri.render(x, method="preint1", **SMALL)
              for x in (str(path), path, vri.load_scene(path), vri.Scene(as_dict, base_dir=path.parent))]
    for other in images[1:]:
        assert other.tobytes() == images[0].tobytes()


def test_clip_keyword_is_the_scene_key(root, cli_render):
    # SPEC §12 "clip" (docs/CLIPPING.md): clip= replaces the scene's; {} removes it.
    clipped = root / "scenes" / "engine_clipped.json"
    expected = cli_render(clipped, *CLI_SMALL, "--method", "preint1")
    image = vri.render(clipped, method="preint1", **SMALL)
    assert image.tobytes() == expected.tobytes()
    clip = json.loads(clipped.read_text())["clip"]
    whole = root / "scenes" / "engine.json"
    assert vri.render(whole, method="preint1", clip=clip, **SMALL).tobytes() == expected.tobytes()
    unclipped = vri.render(clipped, method="preint1", clip={}, **SMALL)
    assert unclipped.tobytes() == vri.render(whole, method="preint1", **SMALL).tobytes()
    assert unclipped.tobytes() != expected.tobytes()
    with pytest.raises(ValueError, match=r"render\(\): clip.planes\[0\]: expected a plane \[nx, ny, nz, d\] whose normal is not 0"):
        vri.render(whole, clip={"planes": [[0, 0, 0, 1]]}, **SMALL)
    with pytest.raises(ValueError, match=r"render\(\): clip.box2: unknown key \(did you mean .box.\?\)"):
        vri.render(whole, clip={"box": [[0, 0, 0], [1, 1, 1]], "box2": 1}, **SMALL)


def test_a_volume_file_renders_as_the_cli_renders_it(root, cli_render):
    # SPEC §12: a volume file where a scene stands; vri.load_volume reads any format.
    engine = root / "data" / "engine.nrrd"
    expected = cli_render(engine, *CLI_SMALL)
    assert vri.render(engine, **SMALL).tobytes() == expected.tobytes()
    assert vri.render(str(engine), **SMALL).tobytes() == expected.tobytes()
    volume = vri.load_volume(engine)
    assert isinstance(volume, vri.Volume) and volume.to_numpy().shape == (128, 256, 256)
    assert isinstance(vri.load_volume(root / "data" / "tetra_mesh_small_ascii.vtk"), vri.Mesh)
    with pytest.raises(OSError, match="cannot open"):
        vri.load_volume(root / "data" / "no_such_volume.nrrd")


def test_threads_do_not_change_a_byte(root):
    scene = vri.load_scene(root / "scenes" / "engine.json")
    one = vri.render(scene, method="preint1", threads=1, **SMALL)
    two = vri.render(scene, method="preint1", threads=2, **SMALL)
    assert one.tobytes() == two.tobytes()


def neghip_volume_dict(root, volume):
    scene = json.loads((root / "scenes" / "neghip.json").read_text())
    scene["volume"] = volume
    return scene


def neghip_array(root):
    return np.fromfile(root / "data" / "neghip_64x64x64_uint8.raw", dtype=np.uint8).reshape(64, 64, 64)


def test_volume_from_numpy_renders_as_the_raw_file(root, cli_render):
    a = neghip_array(root)
    volume = vri.Volume.from_numpy(a)
    assert volume.dims == (64, 64, 64) and volume.dtype == "uint8"
    assert np.shares_memory(volume.to_numpy(), a)  # viewed, not copied
    scene = vri.Scene(neghip_volume_dict(root, volume), base_dir=root / "scenes")
    expected = cli_render(root / "scenes" / "neghip.json", "--method", "preint1", *CLI_SMALL)
    assert vri.render(scene, method="preint1", **SMALL).tobytes() == expected.tobytes()


def test_a_dict_holding_a_volume_is_left_as_it_was(root):
    # Issue 47, defect 17: the first call deleted the dict's "volume" key.
    scene = neghip_volume_dict(root, vri.Volume.from_numpy(neghip_array(root)))
    scene["transfer_function"]["file"] = str(root / "presets" / "neghip.json")
    before = dict(scene)
    first = vri.render(scene, method="preint1", **SMALL)
    assert scene == before and "volume" in scene
    assert vri.render(scene, method="preint1", **SMALL).tobytes() == first.tobytes()
    vri.Scene(scene)
    assert "volume" in scene


@pytest.mark.parametrize("convert", [
    lambda a: np.asfortranarray(a),             # Fortran order: copied into C order
    lambda a: a.astype(np.float64),             # converted to float32, exactly
    lambda a: a.astype(np.int32),
    lambda a: a.astype(">u2"),                  # big-endian: byte-swapped
    lambda a: a[:, :, ::-1][:, :, ::-1],        # a non-contiguous view
])
def test_any_numeric_array_gives_the_same_image(root, convert):
    a = neghip_array(root)
    reference = vri.render(vri.Scene(neghip_volume_dict(root, vri.Volume.from_numpy(a)), base_dir=root / "scenes"),
                           method="preint1", **SMALL)
    other = vri.Volume.from_numpy(convert(a))
    assert other.range == (float(a.min()), float(a.max()))
    image = vri.render(vri.Scene(neghip_volume_dict(root, other), base_dir=root / "scenes"), method="preint1", **SMALL)
    assert image.tobytes() == reference.tobytes()


def test_spacing_and_origin_are_x_y_z(root):
    a = np.zeros((4, 3, 2), dtype=np.float32)  # [z, y, x]
    v = vri.Volume.from_numpy(a, spacing=(1, 2, 3), origin=(-1, 0, 1))
    assert v.dims == (2, 3, 4) and v.shape == (4, 3, 2)
    assert v.spacing == (1.0, 2.0, 3.0) and v.origin == (-1.0, 0.0, 1.0)


def kuhn_mesh(n=3):
    """An n^3 point grid, each cube cut into 6 tetrahedra; integer coordinates, scalars x + 2y + 3z."""
    idx = np.arange(n ** 3).reshape(n, n, n)  # [z, y, x]
    z, y, x = np.meshgrid(np.arange(n), np.arange(n), np.arange(n), indexing="ij")
    points = np.stack([x.ravel(), y.ravel(), z.ravel()], axis=1).astype(np.float64)
    scalars = (x + 2 * y + 3 * z).ravel().astype(np.float32)
    cells = []
    for k in range(n - 1):
        for j in range(n - 1):
            for i in range(n - 1):
                c = lambda dx, dy, dz: idx[k + dz, j + dy, i + dx]
                v0, v7 = c(0, 0, 0), c(1, 1, 1)
                for a, b in [((1, 0, 0), (1, 1, 0)), ((1, 0, 0), (1, 0, 1)), ((0, 1, 0), (1, 1, 0)),
                             ((0, 1, 0), (0, 1, 1)), ((0, 0, 1), (1, 0, 1)), ((0, 0, 1), (0, 1, 1))]:
                    cells.append([v0, c(*a), c(*b), v7])
    return points, np.array(cells, dtype=np.int64), scalars


def write_legacy_vtk(path, points, cells, scalars):
    lines = ["# vtk DataFile Version 2.0", "kuhn", "ASCII", "DATASET UNSTRUCTURED_GRID",
             f"POINTS {len(points)} double"]
    lines += [" ".join(repr(float(v)) for v in p) for p in points]
    lines.append(f"CELLS {len(cells)} {5 * len(cells)}")
    lines += ["4 " + " ".join(str(int(v)) for v in c) for c in cells]
    lines.append(f"CELL_TYPES {len(cells)}")
    lines += ["10"] * len(cells)
    lines += [f"POINT_DATA {len(points)}", "SCALARS s float 1", "LOOKUP_TABLE default"]
    lines += [repr(float(v)) for v in scalars]
    path.write_text("\n".join(lines) + "\n")


@pytest.mark.parametrize("method", ["exact", "tet-raycast", "pt"])
def test_mesh_from_numpy_renders_as_the_vtk_file(tmp_path, cli_render, method):
    points, cells, scalars = kuhn_mesh()
    write_legacy_vtk(tmp_path / "kuhn.vtk", points, cells, scalars)
    scene = {"transfer_function": {"points": [[0, 1, 0.5, 0.2, 0.0], [6, 0.2, 0.6, 1.0, 0.8], [12, 1, 1, 1, 2.0]]},
             "camera": {"eye": [6, -5, 7], "target": [1, 1, 1], "up": [0, 0, 1], "fov_y": 35,
                        "width": 24, "height": 20},
             "method": {"name": method, "table_size": 32, "tolerance": 1e-4}}
    (tmp_path / "kuhn.json").write_text(json.dumps({**scene, "volume": {"file": "kuhn.vtk"}}))
    expected = cli_render(tmp_path / "kuhn.json")
    mesh = vri.Mesh.from_numpy(points, cells, scalars)
    assert mesh.n_points == 27 and mesh.n_cells == 48 and mesh.range == (0.0, 12.0)
    image = vri.render({**scene, "volume": mesh})
    assert image.tobytes() == expected.tobytes()
    assert image[..., 3].max() > 0.1


def test_the_gil_is_released_while_rendering(root):
    """The main thread keeps running Python while another thread renders."""
    scene = vri.load_scene(root / "scenes" / "bonsai.json")
    window = {}

    def work():
        window["start"] = time.monotonic()
        vri.render(scene, method="exact", tolerance=1e-6, width=320, height=320, threads=1)  # ~0.8 s: over 0.3 on a quiet machine too
        window["end"] = time.monotonic()

    worker = threading.Thread(target=work)
    ticks = []
    worker.start()
    while worker.is_alive():
        ticks.append(time.monotonic())
        time.sleep(0.002)
    worker.join()
    inside = [t for t in ticks if window["start"] + 0.05 < t < window["end"] - 0.05]
    assert window["end"] - window["start"] > 0.3, "the render should take long enough to measure"
    assert len(inside) >= 10


def test_two_python_threads_render_at_once(root):
    scene = vri.load_scene(root / "scenes" / "neghip.json")
    expected = {m: vri.render(scene, method=m, **SMALL) for m in ("preint1", "riemann")}
    results = {}
    threads = [threading.Thread(target=lambda m=m: results.__setitem__(m, vri.render(scene, method=m, **SMALL)))
               for m in expected]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for m in expected:
        assert results[m].tobytes() == expected[m].tobytes()


def test_error_estimate_and_trace_equal_the_cli(root, run_cli, tmp_path):
    scene = root / "scenes" / "neghip.json"
    flags = ["--method", "adaptive", "--tolerance", "1e-3", *CLI_SMALL]
    run_cli("render", scene, "-o", tmp_path / "i.npy", "--error-estimate", tmp_path / "e.npy",
            "--trace-pixel", "20", "16", "--trace", tmp_path / "t.csv", *flags)
    kw = dict(method="adaptive", tolerance=1e-3, **SMALL)
    estimate = vri.error_estimate(scene, **kw)
    assert estimate.tobytes() == np.load(tmp_path / "e.npy").tobytes()
    assert estimate[..., 3].max() > 0
    steps = vri.trace(scene, (20, 16), **kw)
    rows = (tmp_path / "t.csv").read_text().splitlines()[1:]
    assert len(rows) == len(steps["t"]) > 0
    for row, outer, t, h in zip(rows, steps["outer"], steps["t"], steps["h"]):
        kind, ct, ch, _ = row.split(",")
        assert (kind == "outer") == outer
        assert float(ct) == pytest.approx(t, rel=1e-9, abs=1e-12)
        assert float(ch) == pytest.approx(h, rel=1e-9, abs=1e-12)
