#!/usr/bin/env python3
"""distributed_model.py FIGURES.txt: docs/DISTRIBUTED.md's model of sort-last
frame time and memory for 2048^3 and 4096^3 volumes on 64-1024 ranks,
calibrated on the measurements scripts/distributed_figures.sh printed into
FIGURES.txt and on radix-k's published cost.

Per rank (one core a rank, as measured):
  render    t1 * (P / P1) * (n / n1) / N   the one-thread frame t1 of an n1^3
            volume at P1 pixels, scaled by pixels and ray length (samples
            ~ n per ray at step 1), shared by N balanced bricks;
  memory    B(n) * g / N + M0             B the volume's bytes, g = (1 + 2 G / s)^3
            the ghost layer's share on a brick of side s = n / N^(1/3) with
            G = 5 points a side (preint1 at step 1; an upper bound: faces on
            the volume's boundary have none; the share measured at 512^3 is
            printed beside it), M0 the rest of a rank (image, tables,
            program) measured as peak RSS minus brick;
  composite P * c_px + a * log2(N)        c_px from Kendall et al. 2010
            (radix-k with bounding boxes and run-length encoding: 64
            megapixels in 0.08 s on 32K processes of a Blue Gene/P), a an
            assumed 20 us per round; beside it, this machine's own IceT time
            per pixel (shared memory, oversubscribed) as a pessimistic bound.
"""
import math
import re
import sys

text = open(sys.argv[1]).read()
m = re.search(r"one process: peak RSS (\d+) bytes, render ([\d.e+-]+) s", text)
rss1, t1 = int(m.group(1)), float(m.group(2))
rows = re.findall(r"^\| (\d+) \| (\d+) \| (\d+) \| [\d.e+-]+ \| [\d.e+-]+ \|$", text, re.M)
n_max, brick_max, rss_max = max((int(a), int(b), int(c)) for a, b, c in rows)
V1 = 512**3 * 4  # the measured volume: float
ghost_measured = brick_max / (V1 / n_max)
G = 5
M0 = rss_max - brick_max
composite_1024 = re.search(r"^\| 1024 \| ([\d.e+-]+) \|", text, re.M)
local_px = float(composite_1024.group(1)) / 1024**2 if composite_1024 else float("nan")
P1, n1 = 256 * 256, 512
c_px, alpha = 0.08 / 64e6, 20e-6

print(f"calibration: t1 = {t1:.3f} s (512^3, 256^2, one thread); ghost share measured {ghost_measured:.3f} at "
      f"{n_max} ranks against {(1 + 2 * G / (n1 / n_max ** (1 / 3))) ** 3:.3f} modelled; "
      f"M0 = {M0 / 2**20:.0f} MiB; radix-k {c_px * 1e9:.2f} ns/pixel + {alpha * 1e6:.0f} us/round; "
      f"this machine's IceT {local_px * 1e9:.0f} ns/pixel")
print()
print("| volume | image | ranks | memory a rank (GiB) | render s | composite s (radix-k) | frame s | composite s (this machine's IceT) |")
print("|---|---|---|---|---|---|---|---|")
for n, bytes_per_sample in ((2048, 2), (4096, 2)):
    for side in (1024, 2048):
        P = side * side
        for N in (64, 128, 256, 512, 1024):
            B = n**3 * bytes_per_sample
            ghost = (1 + 2 * G / (n / N ** (1 / 3))) ** 3
            memory = B * ghost / N + M0
            render = t1 * (P / P1) * (n / n1) / N
            composite = P * c_px + alpha * math.log2(N)
            print(f"| {n}^3 uint16 | {side}^2 | {N} | {memory / 2**30:.2f} | {render:.2f} | {composite:.3f} | "
                  f"{render + composite:.2f} | {P * local_px:.2f} |")
