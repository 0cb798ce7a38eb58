#!/usr/bin/env python3
"""npy_diff.py A.npy B.npy [--over E]: how far two images (.npy, float RGBA)
are apart, for the measuring scripts in scripts/: the largest |A - B| over
every pixel and channel (printed as 1.2e-03) or, with --over E, the share of
pixels where some channel differs by more than E (printed as 0.13%)."""
import argparse

import numpy as np


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("a")
    p.add_argument("b")
    p.add_argument("--over", type=float, help="print the share of pixels with a channel off by more than this")
    args = p.parse_args()
    d = np.abs(np.load(args.a).astype(float) - np.load(args.b).astype(float))
    if args.over is None:
        print("%.1e" % d.max())
    else:
        print("%.2f%%" % (100 * (d.max(-1) > args.over).mean()))


if __name__ == "__main__":
    main()
