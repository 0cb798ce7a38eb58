"""vri.Image and vri.render's array front door (SPEC §12; issue 51 items 1-2;
docs/PYTHON.md): an ndarray with the CLI's bytes that saves, composites and
shows itself as the CLI writes it; an array rendered as `vri render VOLUME
--colormap --range --opacity` renders its .npy file."""
import numpy as np
import pytest

import vri

SMALL = dict(width=40, height=32)
CLI_SMALL = ["--width", "40", "--height", "32"]


@pytest.fixture
def neghip(root):
    return np.fromfile(root / "data" / "neghip_64x64x64_uint8.raw", dtype=np.uint8).reshape(64, 64, 64)


def test_an_image_is_the_cli_array_and_saves_the_cli_files(root, run_cli, tmp_path):
    scene = root / "scenes" / "neghip.json"
    image = vri.render(scene, method="preint1", **SMALL)
    assert isinstance(image, vri.Image) and isinstance(image, np.ndarray)
    assert image.shape == (32, 40, 4) and image.dtype == np.float32
    for ext in ("npy", "png") + (("exr",) if vri._vri._exr_supported else ()):
        run_cli("render", scene, "-o", tmp_path / f"cli.{ext}", "--method", "preint1", *CLI_SMALL)
        image.save(tmp_path / f"py.{ext}")
        assert (tmp_path / f"py.{ext}").read_bytes() == (tmp_path / f"cli.{ext}").read_bytes(), ext
    assert image._repr_png_() == (tmp_path / "cli.png").read_bytes()
    assert image[..., 3]._repr_png_() is None  # a slice is shown as numbers
    with pytest.raises(ValueError, match="must end in .npy, .png or .exr"):
        image.save(tmp_path / "x.jpg")


def test_composite_is_over_the_scene_background(root):
    scene = vri.Scene({"volume": {"builtin": "sphere", "dims": [12, 12, 12]},
                       "transfer_function": {"points": [[-6, 1, 0.5, 0, 0.5], [0, 0, 0, 1, 0]]},
                       "camera": {"eye": [5.5, 5.5, 40], "target": [5.5, 5.5, 5.5], "width": 16, "height": 12},
                       "background": [0.2, 0.4, 0.6], "method": {"name": "exact"}})
    image = vri.render(scene)
    assert image.background == (0.2, 0.4, 0.6)
    rgb = image.composite()
    assert rgb.shape == (12, 16, 3) and rgb.dtype == np.float32
    a = np.asarray(image, dtype=np.float32)
    np.testing.assert_allclose(rgb, np.clip(a[..., :3] + (1 - a[..., 3:]) * np.float32([0.2, 0.4, 0.6]), 0, 1))
    assert np.all(rgb[0, 0] == np.float32([0.2, 0.4, 0.6]))  # a corner sees no sphere
    assert np.all(image.composite(background=(1, 1, 1))[0, 0] == 1)
    u8 = image.to_uint8()
    assert u8.dtype == np.uint8 and u8.shape == (12, 16, 3)
    assert np.abs(u8.astype(int) - np.rint(rgb * 255).astype(int)).max() <= 1
    assert np.any(u8 != image.to_uint8(background=(0, 0, 0)))


def test_an_array_renders_as_its_npy_file_does(root, neghip, run_cli, tmp_path):
    np.save(tmp_path / "neghip.npy", neghip)
    cases = [(dict(), []),
             (dict(cmap="viridis", clim=(30, 200), opacity="sigmoid"),
              ["--colormap", "viridis", "--range", "30.0,200.0", "--opacity", "sigmoid"]),
             (dict(cmap="magma", clim="p5,p99"), ["--colormap", "magma", "--range", "p5,p99"]),
             (dict(opacity="linear"), ["--opacity", "ramp"])]
    for kwargs, flags in cases:
        out = tmp_path / "cli.npy"
        run_cli("render", tmp_path / "neghip.npy", "-o", out, *CLI_SMALL, *flags)
        image = vri.render(neghip, **kwargs, **SMALL)
        assert image.tobytes() == np.load(out).tobytes(), kwargs
        assert image[..., 3].max() > 0.05, kwargs
    # a volume file and a vri.Volume are seen alike
    volume = vri.Volume.from_numpy(neghip)
    assert vri.render(volume, cmap="viridis", **SMALL).tobytes() == \
        vri.render(tmp_path / "neghip.npy", cmap="viridis", **SMALL).tobytes()


def test_spacing_is_x_y_z_and_scale_napari_s_z_y_x(neghip):
    by_spacing = vri.render(neghip, spacing=(1, 1, 2.5), **SMALL)
    assert vri.render(neghip, scale=(2.5, 1, 1), **SMALL).tobytes() == by_spacing.tobytes()
    assert vri.render(neghip, spacing=(1, 1, 2.5), scale=(2.5, 1, 1), **SMALL).tobytes() == by_spacing.tobytes()
    assert vri.render(neghip, **SMALL).tobytes() != by_spacing.tobytes()
    with pytest.raises(ValueError, match=r"spacing \(1, 1, 2\) \(x, y, z\) and scale \(1, 1, 2\) \(z, y, x\) disagree"):
        vri.render(neghip, spacing=(1, 1, 2), scale=(1, 1, 2), **SMALL)


def test_colour_maps_reversed_matplotlib_s_and_opacity_arrays(neghip):
    viridis = vri.render(neghip, cmap="viridis", **SMALL)
    reversed_ = vri.render(neghip, cmap="viridis_r", **SMALL)
    assert np.array_equal(viridis[..., 3], reversed_[..., 3])  # the same opacity, other colours
    assert not np.array_equal(viridis[..., :3], reversed_[..., :3])
    pytest.importorskip("matplotlib")
    blues = vri.render(neghip, cmap="Blues", **SMALL)
    assert np.array_equal(blues[..., 3], viridis[..., 3])
    covered = blues[..., 3] > 0.3
    assert (blues[..., 2][covered] >= blues[..., 0][covered]).all()  # blue over red where it shows
    with pytest.warns(RuntimeWarning, match="every pixel is transparent"):
        clear = vri.render(neghip, opacity=np.zeros(8), **SMALL)
    assert clear.max() == 0
    dense = vri.render(neghip, opacity=[0.0, 0.5], **SMALL)
    assert dense[..., 3].max() > viridis[..., 3].max()


def test_bad_front_door_arguments_are_one_clear_line(root, neghip):
    with pytest.raises(ValueError, match="cmap: unknown colour map 'no_such_map' \\(vri's: viridis, magma"):
        vri.render(neghip, cmap="no_such_map", **SMALL)
    with pytest.raises(ValueError, match="apply to an array or a volume; a scene sets its own"):
        vri.render(root / "scenes" / "neghip.json", cmap="viridis", **SMALL)
    with pytest.raises(ValueError, match="--opacity: expected ramp or sigmoid, found 'cubic'"):
        vri.render(neghip, opacity="cubic", **SMALL)
    with pytest.raises(ValueError, match="at least 2 opacities"):
        vri.render(neghip, opacity=[0.5], **SMALL)
    with pytest.raises(ValueError, match="--range: expected data, pLO,pHI"):
        vri.render(neghip, clim="lots", **SMALL)
    with pytest.raises(ValueError, match="3-D"):
        vri.render(np.zeros((4, 4)), **SMALL)
