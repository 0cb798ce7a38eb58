"""Writes render_methods.ipynb from render_methods.py: each `# %%` block one
cell (`# %% [markdown]` blocks as markdown). The notebook is made, not edited:
re-run this after changing the script (a test checks they agree)."""
import json
import pathlib
import sys

HERE = pathlib.Path(__file__).resolve().parent


def cells_of(source):
    """The cells, each with a stable id (nbformat 4.5)."""
    cells = []
    for block in source.split("# %%")[1:]:
        header, _, body = block.partition("\n")
        body = body.strip("\n")
        if header.strip() == "[markdown]":
            text = "\n".join(line[2:] if line.startswith("# ") else line.lstrip("#") for line in body.splitlines())
            cells.append({"cell_type": "markdown", "id": f"cell-{len(cells)}", "metadata": {},
                          "source": text.splitlines(keepends=True)})
        else:
            cells.append({"cell_type": "code", "execution_count": None, "id": f"cell-{len(cells)}", "metadata": {},
                          "outputs": [], "source": body.splitlines(keepends=True)})
    return cells


def notebook(source):
    return {"cells": cells_of(source),
            "metadata": {"kernelspec": {"display_name": "Python 3", "language": "python", "name": "python3"},
                         "language_info": {"name": "python"}},
            "nbformat": 4, "nbformat_minor": 5}


def text(source):
    return json.dumps(notebook(source), indent=1) + "\n"


if __name__ == "__main__":
    out = HERE / "render_methods.ipynb"
    out.write_text(text((HERE / "render_methods.py").read_text()))
    print("wrote", out, file=sys.stderr)
