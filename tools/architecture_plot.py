#!/usr/bin/env python3
"""The layers of vri from its own #include lines (docs/ARCHITECTURE.md).

architecture_plot.py OUT_DIR: writes OUT_DIR/layers.png (one box per folder,
the method folders as one wing, an arrow A -> B where a file of A includes a
file of B) and OUT_DIR/layers.md (the counts, and any arrow that closes a
loop between folders, which a layered house has none of).

A folder is a room: src/<concept>/ with its public header include/vri/<concept>.hpp
(PUBLIC below: methods.hpp, the methods' public face, is the room
`integrators`; error, geometry, memory and image belong to core); src/methods/<method>/ are rooms
of the methods wing; the front doors
are src/cli, python/src, viewer/server, distributed and vulkan/host (with the
shared GLSL). Tests, benchmarks and tools are left out.
"""
import os
import re
import sys
from collections import defaultdict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.patches import FancyArrowPatch, Rectangle  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SOURCES = (".cpp", ".hpp", ".comp", ".glsl")
FRONTS = {"src/cli": "cli", "python/src": "python", "viewer/server": "viewer", "distributed": "distributed",
          "vulkan/host": "vulkan", "vulkan/shaders": "vulkan"}
PUBLIC = {"error.hpp": "core", "geometry.hpp": "core", "memory.hpp": "core", "image.hpp": "core",
          "camera.hpp": "camera", "transfer_function.hpp": "transfer", "volume.hpp": "volume",
          "lighting.hpp": "shading", "methods.hpp": "integrators", "scene.hpp": "scene", "render.hpp": "render",
          "io.hpp": "io", "analysis.hpp": "analysis"}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)


def room_of(path):
    """The room of a file path relative to ROOT, or None (not drawn)."""
    for prefix, name in FRONTS.items():
        if path.startswith(prefix + "/"):
            return name
    parts = path.split("/")
    if parts[0] == "include":
        return PUBLIC[parts[-1]]
    if parts[0] == "src" and len(parts) > 2:
        if parts[1] == "methods":
            return "methods/" + parts[2] if len(parts) > 3 else "methods"
        return parts[1]
    return None


def files():
    for top in ("src", "include", "python/src", "viewer/server", "distributed", "vulkan"):
        for d, _, names in os.walk(os.path.join(ROOT, top)):
            for n in names:
                if n.endswith(SOURCES):
                    yield os.path.relpath(os.path.join(d, n), ROOT)


def resolve(includer, name, known):
    """The file an include names: beside the includer, then the include folders."""
    here = os.path.dirname(includer)
    for base in (here, "include", "src", "vulkan/host", "vulkan/shaders", "viewer/server", "distributed", "python/src"):
        p = os.path.normpath(os.path.join(base, name))
        if p in known:
            return p
    return None


def graph():
    known = set(files())
    lines = defaultdict(int)
    edges = defaultdict(int)
    for f in known:
        text = open(os.path.join(ROOT, f), encoding="utf-8", errors="replace").read()
        a = room_of(f)
        lines[a] += text.count("\n")
        for name in INCLUDE.findall(text):
            target = resolve(f, name, known)
            b = room_of(target) if target else None
            if b and b != a:
                edges[(a, b)] += 1
    return lines, edges, known


def strongly_connected(nodes, edges):
    """Tarjan's components: a folder in a loop of includes shares one with the others."""
    succ = defaultdict(list)
    for a, b in edges:
        succ[a].append(b)
    index, low, stack, on, comps = {}, {}, [], set(), []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in succ[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            comps.append(comp)

    sys.setrecursionlimit(10000)
    for v in sorted(nodes):
        if v not in index:
            visit(v)
    return {v: i for i, c in enumerate(comps) for v in c}, comps


def floors(nodes, edges, comp_of):
    """Floor 1 imports nothing; each room stands one above the highest it imports (loops share a floor)."""
    succ = defaultdict(set)
    for a, b in edges:
        if comp_of[a] != comp_of[b]:
            succ[comp_of[a]].add(comp_of[b])
    memo = {}

    def floor(c):
        if c not in memo:
            memo[c] = 1 + max((floor(d) for d in succ[c]), default=0)
        return memo[c]

    return {v: floor(comp_of[v]) for v in nodes}


def main(out_dir):
    os.makedirs(out_dir, exist_ok=True)
    lines, edges, known = graph()
    # The wing: its rooms drawn inside one box, as one room to the rest.
    wing = sorted(r for r in lines if r.startswith("methods/"))
    flat = defaultdict(int)
    for (a, b), n in edges.items():
        a2 = "methods" if a.startswith("methods") else a
        b2 = "methods" if b.startswith("methods") else b
        if a2 != b2:
            flat[(a2, b2)] += n
    nodes = sorted({"methods" if r.startswith("methods") else r for r in lines})
    comp_of, comps = strongly_connected(nodes, flat)
    floor_of = floors(nodes, flat, comp_of)
    loops = sorted((a, b, n) for (a, b), n in flat.items() if comp_of[a] == comp_of[b])
    public = sorted(f for f in known if f.startswith("include/"))

    top = max(floor_of.values())
    rows = defaultdict(list)
    for v in nodes:
        rows[floor_of[v]].append(v)
    fig, ax = plt.subplots(figsize=(12, 0.8 * top + 1.0))
    pos = {}
    for f, row in rows.items():
        row.sort(key=lambda v: (v != "methods", v))
        widths = [5.2 if v == "methods" else 1.45 for v in row]
        x = (12 - sum(widths) - 0.25 * (len(row) - 1)) / 2
        for v, w in zip(row, widths):
            y = 1.15 * (f - 1)
            pos[v] = (x, y, w)
            colour = "#c6dbef" if v == "methods" else ("#fdd0a2" if v in FRONTS.values() else "#e5e5e5")
            ax.add_patch(Rectangle((x, y), w, 0.7, facecolor=colour, edgecolor="#444444", lw=0.8))
            total = lines[v] + (sum(lines[r] for r in wing) if v == "methods" else 0)
            ax.text(x + 0.06, y + 0.56, f"{v}/", fontsize=8.5, weight="bold", va="center")
            ax.text(x + w - 0.06, y + 0.56, f"{total:,}", fontsize=7, ha="right", va="center", color="#555555")
            if v == "methods":
                share = (w - 0.12) / len(wing)
                for i, r in enumerate(wing):
                    rx = x + 0.06 + i * share
                    ax.add_patch(Rectangle((rx, y + 0.06), share - 0.03, 0.36, facecolor="#9ecae1",
                                           edgecolor="#3182bd", lw=0.6))
                    ax.text(rx + (share - 0.03) / 2, y + 0.24, r.split("/")[1].replace("_", "_\n", 1)
                            if len(r) > 20 else r.split("/")[1], fontsize=5.6, ha="center", va="center")
            x += w + 0.25
    for (a, b), n in flat.items():
        xa, ya, wa = pos[a]
        xb, yb, wb = pos[b]
        loop = comp_of[a] == comp_of[b]
        ax.add_patch(FancyArrowPatch((xa + wa / 2, ya), (xb + wb / 2, yb + 0.7), arrowstyle="-|>", mutation_scale=7,
                                     color="#cb181d" if loop else "#969696", lw=0.5 + 0.25 * min(n, 12) ** 0.5,
                                     alpha=0.85 if loop else 0.45, connectionstyle="arc3,rad=0.05"))
    ax.set_xlim(-0.1, 12.1)
    ax.set_ylim(-0.3, 1.15 * top)
    ax.axis("off")
    ax.set_title(f"vri by folder: {len(nodes)} rooms on {top} floors, {len(flat)} arrows (a file includes another), "
                 f"{len(loops)} in loops (red); {len(public)} public headers", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(out_dir, "layers.png"), dpi=110)

    with open(os.path.join(out_dir, "layers.md"), "w") as md:
        md.write("# The layers, counted\n\n")
        md.write("Generated by `/usr/bin/python3 tools/architecture_plot.py docs/architecture` from the `#include`\n"
                 "lines of src/, include/, vulkan/, distributed/, python/src and viewer/server (tests, benchmarks\n"
                 "and tools left out). ![layers](layers.png)\n\n")
        md.write(f"- {len(nodes)} rooms on {top} floors, {len(flat)} arrows between them; "
                 f"the methods wing holds {len(wing)} folders ({', '.join(r.split('/')[1] for r in wing)}).\n")
        md.write(f"- {len(public)} installed headers (include/vri/).\n")
        md.write(f"- {len(loops)} arrows close a loop between rooms")
        md.write(":\n" + "".join(f"  - {a} -> {b} ({n} includes)\n" for a, b, n in loops) if loops else ".\n")
        md.write("\n| floor | rooms |\n|---|---|\n")
        for f in sorted(rows, reverse=True):
            md.write(f"| {f} | {', '.join(rows[f])} |\n")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: architecture_plot.py OUT_DIR")
    main(sys.argv[1])
