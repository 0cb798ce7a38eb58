"""Named colour maps and "range" from Python dicts (issue 20; docs/SCENES.md,
"Transfer functions"): a scene's volume gives "data" its range, a transfer
function on its own needs [lo, hi]."""
import numpy as np
import pytest

import vri


def test_colormap_scene_from_numpy_spans_the_data():
    a = np.arange(8 * 8 * 8, dtype=np.float32).reshape(8, 8, 8)
    scene = vri.Scene({"volume": vri.Volume.from_numpy(a),
                       "transfer_function": {"colormap": "viridis", "opacity": [[0, 0], [1, 0.2]]},
                       "camera": {"width": 16, "height": 16}, "method": {"name": "riemann", "step": 0.5}})
    points = scene.transfer_function
    assert points[0][0] == 0 and points[-1][0] == 511
    assert points[-1][4] == pytest.approx(0.2)
    image = vri.render(scene)
    assert image.shape == (16, 16, 4) and image[..., 3].max() > 0


def test_percentiles_and_rescaled_points():
    a = np.arange(10 * 10 * 10, dtype=np.float32).reshape(10, 10, 10)
    scene = vri.Scene({"volume": vri.Volume.from_numpy(a),
                       "transfer_function": {"points": [[0, 0, 0, 0, 0], [1, 1, 1, 1, 1]],
                                             "range": {"percentiles": [1, 99]}},
                       "camera": {"width": 8, "height": 8}})
    points = scene.transfer_function
    assert points[0][0] == pytest.approx(np.percentile(a, 1))
    assert points[-1][0] == pytest.approx(np.percentile(a, 99))


def test_a_transfer_function_alone_needs_a_range():
    with pytest.raises(ValueError, match=r'range: "data" needs a volume; give \[lo, hi\]'):
        vri.table({"colormap": "viridis", "range": "data"})
    with pytest.raises(ValueError, match=r"unknown colour map 'jet' \(known: viridis, magma"):
        vri.table({"colormap": "jet", "range": [0, 1]})
    assert vri.table({"colormap": "cool_to_warm", "range": [0, 1]}, size=16).shape == (16, 16, 4)
