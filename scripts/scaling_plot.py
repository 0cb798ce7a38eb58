#!/usr/bin/python3
"""scaling_plot.py SCALING.txt OUT.png: the plot of docs/PERFORMANCE.md,
"Scaling" (issue 21, item 7), from scripts/scaling_study.sh's output: CPU
time against the image's pixels (bonsai) and against the volume's side N
(Marschner-Lobb N³), preint1 and riemann, log-log, with the slope-1 line
through the first point of each (time proportional to pixels, or to N)."""
import re
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def table(text, heading):
    """The rows of the markdown table under the heading that starts with `heading`."""
    part = text.split("### " + heading, 1)[1].split("###", 1)[0]
    return [[c.strip() for c in line.strip().strip("|").split("|")] for line in part.splitlines()
            if line.startswith("|") and not line.startswith("|---")][1:]


def cpu(cell):  # "wall / cpu" -> cpu ms
    return float(cell.split("/")[1])


text = open(sys.argv[1]).read()
image = table(text, "Image size")
volume = table(text, "Volume size")
fig, (a, b) = plt.subplots(1, 2, figsize=(9, 3.8))
px = [int(re.match(r"(\d+)", r[0]).group(1)) ** 2 for r in image]
ns = [int(re.match(r"(\d+)", r[0]).group(1)) for r in volume]
for ax, xs, rows, cols, xlabel, title in [
        (a, px, image, (1, 2), "pixels", "bonsai (256³), step 1, 2 threads"),
        (b, ns, volume, (2, 3), "N (volume N³, 512² image)", "Marschner–Lobb N³ uint8, step 1")]:
    for col, name in zip(cols, ["preint1", "riemann"]):
        ys = [cpu(r[col]) for r in rows]
        ax.plot(xs, ys, "o-", label=name)
        ax.plot(xs, [ys[0] * x / xs[0] for x in xs], ":", color="grey", lw=0.8)
    ax.set_xscale("log"), ax.set_yscale("log")
    ax.set_xlabel(xlabel), ax.set_ylabel("CPU ms per frame"), ax.set_title(title, fontsize=9)
    ax.legend(fontsize=8)
fig.suptitle("Frame time against image and volume size (dotted: proportional)", fontsize=10)
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=90)
