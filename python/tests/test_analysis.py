"""vri.table, vri.compare and vri.ray against `vri table`, `vri compare` and `vri ray`."""
import numpy as np
import pytest

import vri


@pytest.mark.parametrize("kw,flags", [
    (dict(size=64), ["--size", "64"]),
    (dict(size=32, builder="exact"), ["--size", "32", "--builder", "exact"]),
    (dict(size=16, lengths=4, max_length=3.0), ["--size", "16", "--lengths", "4", "--max-length", "3"]),
    (dict(size=16, order=2, iterations=8), ["--size", "16", "--order", "2", "--iterations", "8"]),
])
def test_table_equals_cli_bytes(root, run_cli, tmp_path, kw, flags):
    tf = root / "presets" / "neghip.json"
    run_cli("table", "--tf", tf, "-o", tmp_path / "t.npy", *flags)
    expected = np.load(tmp_path / "t.npy")
    table = vri.table(tf, **kw)
    assert table.shape == expected.shape and table.tobytes() == expected.tobytes()


def test_table_from_a_dict_is_the_closed_form():
    # Constant extinction tau and colour c over a slab of length l: alpha = 1 - exp(-tau l), C = c alpha.
    tau, length = 0.7, 2.0
    table = vri.table({"points": [[0, 0.5, 0.25, 1.0, tau], [1, 0.5, 0.25, 1.0, tau]]}, size=8, length=length)
    alpha = 1 - np.exp(-tau * length)
    assert np.allclose(table[..., 3], alpha, rtol=1e-6)
    assert np.allclose(table[..., 0], 0.5 * alpha, rtol=1e-6)
    with pytest.raises(ValueError, match="--order must be 1 or 2"):
        vri.table({"points": [[0, 1, 1, 1, 1], [1, 1, 1, 1, 1]]}, order=3)


def test_compare_matches_numpy():
    rng = np.random.default_rng(7)
    a = rng.random((6, 5, 4), dtype=np.float32)
    b = a + rng.normal(0, 0.01, a.shape).astype(np.float32)
    diff = vri.compare(a, b, tolerance=0.01)
    assert len(diff) == 4
    for c, d in enumerate(diff):
        delta = np.abs(a[..., c].astype(np.float64) - b[..., c])
        assert d.share_over == pytest.approx(np.mean(delta > 0.01))
        assert d.rms == pytest.approx(np.sqrt(np.mean(delta ** 2)), rel=1e-6)
        assert d.max == pytest.approx(delta.max(), rel=1e-6)
    with pytest.raises(ValueError, match="different shapes"):
        vri.compare(a, b[:3])


@pytest.mark.parametrize("step", [None, 0.5])
def test_ray_equals_cli(root, run_cli, tmp_path, step):
    scene = root / "scenes" / "neghip.json"
    flags = [] if step is None else ["--step", str(step)]
    done = run_cli("ray", scene, "--pixel", "256", "250", "-o", tmp_path / "r.csv", *flags)
    signal = vri.ray(scene, (256, 250), step=step)
    samples, xi = done.stdout.split()[1], [float(x) for x in done.stdout.split()[3::2]]
    assert signal["samples"] == int(samples)
    assert signal["xi"] == pytest.approx(xi, rel=1e-5)
    assert signal["xi"][2] < signal["xi"][0]  # the parabola follows the signal better than the hold
    rows = np.loadtxt(tmp_path / "r.csv", delimiter=",", skiprows=3)
    assert rows.shape[0] == len(signal["t"])
    for column, key in enumerate(["t", "signal", "order0", "order1", "order2"]):
        assert np.allclose(rows[:, column], signal[key], rtol=1e-8, atol=1e-8)
    assert (rows[:, 5] == signal["is_sample"]).all()
