# %% [markdown]
# # vri from Python: two methods, their error, and the error against the step
#
# Renders the bundled *neghip* volume under a transfer function with a narrow
# opaque spike (`scenes/neghip_spike.json`) with `riemann` (one sample per
# step) and `preint1` (first-order pre-integration), compares both with the
# `exact` reference, and plots the images, their error maps and the RMS error
# as the step shrinks. Point sampling steps over the spike; pre-integration
# integrates the transfer function between samples and does not. Run it as a script (`python3 examples/render_methods.py`) or
# as the notebook `render_methods.ipynb` made from it (`make_notebook.py`).
# The figure goes to `render_methods.png` in the current directory, or in
# `$VRI_EXAMPLE_OUT`; `$VRI_EXAMPLE_SIZE` sets the image size (default 160).
# It needs the module on the path: `cmake --install build --component python`
# (docs/PYTHON.md) or `PYTHONPATH=build/python`.

# %%
import os
import pathlib
import sys

import matplotlib
if "ipykernel" not in sys.modules:  # a script writes the figure; a notebook shows it too
    matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

import vri

# The repository root: $VRI_EXAMPLE_ROOT, else the first folder at or above
# the current one that holds scenes/neghip.json.
ROOT = pathlib.Path(os.environ.get("VRI_EXAMPLE_ROOT") or next(
    p for p in [pathlib.Path.cwd(), *pathlib.Path.cwd().parents] if (p / "scenes" / "neghip.json").exists()))
SIZE = int(os.environ.get("VRI_EXAMPLE_SIZE", "160"))
OUT = pathlib.Path(os.environ.get("VRI_EXAMPLE_OUT", "."))
print("vri", vri.__version__, "on", ROOT / "scenes" / "neghip_spike.json")

# %%
scene = vri.load_scene(ROOT / "scenes" / "neghip_spike.json")
size = dict(width=SIZE, height=SIZE)
reference = vri.render(scene, method="exact", tolerance=1e-5, **size)
images = {m: vri.render(scene, method=m, step=1.0, **size) for m in ("riemann", "preint1")}


def rms(image):
    """RMS over pixels and channels of the difference with the exact image."""
    return float(np.sqrt(np.mean((image.astype(np.float64) - reference) ** 2)))


for method, image in images.items():
    print(f"{method:8s} step 1: RMS error {rms(image):.3e}, max {np.abs(image - reference).max():.3e}")

# %%
steps = [0.25, 0.5, 1.0, 2.0, 4.0]
errors = {m: [rms(vri.render(scene, method=m, step=h, **size)) for h in steps] for m in ("riemann", "preint1")}
for method, values in errors.items():
    print(method, " ".join(f"{h:g}:{e:.2e}" for h, e in zip(steps, values)))

# %%
def over_background(image, background=(0, 0, 0)):
    """Premultiplied RGBA over the scene's background, clipped for display."""
    return np.clip(image[..., :3] + (1 - image[..., 3:]) * np.asarray(background), 0, 1)


fig, axes = plt.subplots(2, 3, figsize=(12, 7.5))
for row, (method, image) in enumerate(images.items()):
    axes[row, 0].imshow(over_background(image))
    axes[row, 0].set_title(f"{method}, step 1")
    shown = axes[row, 1].imshow(np.abs(image - reference).max(axis=-1), cmap="magma")
    axes[row, 1].set_title(f"{method}: |error| vs exact")
    fig.colorbar(shown, ax=axes[row, 1])
axes[0, 2].imshow(over_background(reference))
axes[0, 2].set_title("exact (tolerance 1e-5)")
for method, values in errors.items():
    axes[1, 2].loglog(steps, values, "o-", label=method)
axes[1, 2].set_xlabel("step (voxel units)")
axes[1, 2].set_ylabel("RMS error against exact")
axes[1, 2].legend()
for ax in axes.flat[:5]:
    ax.set_xticks([])
    ax.set_yticks([])
fig.tight_layout()
fig.savefig(OUT / "render_methods.png", dpi=80)
print("wrote", OUT / "render_methods.png")
