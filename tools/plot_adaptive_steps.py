#!/usr/bin/env python3
"""Plots the steps along one ray written by `vri render ... --trace STEPS.csv`
(like Campagnolo et al. 2015, Fig. 6) as a standalone SVG: the accumulated
alpha at the end of each outer step (top) and the inner and outer step
sizes against t (bottom), both in voxel units.

    python3 tools/plot_adaptive_steps.py STEPS.csv -o STEPS.svg
"""
import argparse
import csv

W, H, PAD, GAP = 720, 460, 50, 40
PANEL = (H - 2 * PAD - GAP) / 2


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("csv")
    ap.add_argument("-o", "--output", required=True)
    ap.add_argument("--title", default="adaptive steps along one ray")
    args = ap.parse_args()
    rows = list(csv.DictReader(open(args.csv)))
    steps = [(r["integral"], float(r["t"]), float(r["h"]), float(r["alpha"])) for r in rows]
    t0 = min(s[1] for s in steps)
    t1 = max(s[1] + s[2] for s in steps)
    hmax = max(s[2] for s in steps)
    x = lambda t: PAD + (t - t0) / (t1 - t0) * (W - 2 * PAD)
    y_alpha = lambda a: PAD + PANEL * (1 - a)
    y_h = lambda h: PAD + PANEL + GAP + PANEL * (1 - h / hmax)

    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" font-family="sans-serif" font-size="11">',
           f'<rect width="{W}" height="{H}" fill="white"/>',
           f'<text x="{W / 2}" y="20" text-anchor="middle" font-size="13">{args.title}</text>']
    for top, label, vmax in [(PAD, "alpha", "1"), (PAD + PANEL + GAP, "step h (voxels)", f"{hmax:g}")]:
        out.append(f'<rect x="{PAD}" y="{top}" width="{W - 2 * PAD}" height="{PANEL}" fill="none" stroke="#888"/>')
        out.append(f'<text x="{PAD - 6}" y="{top + 4}" text-anchor="end">{vmax}</text>')
        out.append(f'<text x="{PAD - 6}" y="{top + PANEL}" text-anchor="end">0</text>')
        out.append(f'<text x="{PAD + 4}" y="{top + 12}">{label}</text>')
    out.append(f'<text x="{PAD}" y="{H - 15}">t = {t0:.1f}</text>')
    out.append(f'<text x="{W - PAD}" y="{H - 15}" text-anchor="end">t = {t1:.1f} (voxel units along the ray)</text>')

    outer = [s for s in steps if s[0] == "outer"]
    if outer:
        pts = [(x(outer[0][1]), y_alpha(0))] + [(x(s[1] + s[2]), y_alpha(s[3])) for s in outer]
        out.append('<polyline fill="none" stroke="#1f77b4" stroke-width="1.5" points="' +
                   " ".join(f"{px:.1f},{py:.1f}" for px, py in pts) + '"/>')
        out += [f'<circle cx="{px:.1f}" cy="{py:.1f}" r="2" fill="#1f77b4"/>' for px, py in pts[1:]]
    for kind, colour, dy in [("inner", "#d62728", 0), ("outer", "#1f77b4", 2)]:
        for s in (s for s in steps if s[0] == kind):
            out.append(f'<line x1="{x(s[1]):.1f}" x2="{x(s[1] + s[2]):.1f}" y1="{y_h(s[2]) + dy:.1f}" '
                       f'y2="{y_h(s[2]) + dy:.1f}" stroke="{colour}" stroke-width="2"/>')
    legend_y = PAD + PANEL + GAP + 12
    out.append(f'<text x="{W - PAD - 4}" y="{legend_y}" text-anchor="end" fill="#d62728">inner steps</text>')
    out.append(f'<text x="{W - PAD - 4}" y="{legend_y + 14}" text-anchor="end" fill="#1f77b4">outer steps</text>')
    out.append("</svg>")
    open(args.output, "w").write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
