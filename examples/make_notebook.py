"""Writes examples/quickstart.ipynb from examples/quickstart.py, the one source of both.

The script is split at its `# %%` lines (the "percent" cell format that editors such as VS Code,
Spyder and jupytext understand); `# %% [markdown]` cells become markdown with the leading `# `
of each line removed. The notebook is stored without outputs. Run it after editing the script:

    .venv/bin/python examples/make_notebook.py

(a test fails while the notebook is stale)."""

import pathlib
import sys

import nbformat

HERE = pathlib.Path(__file__).resolve().parent
SCRIPT = HERE / "quickstart.py"
NOTEBOOK = HERE / "quickstart.ipynb"


def cells(text):
    """[(kind, source)] of a percent-format script, kind 'code' or 'markdown'."""
    out = []
    for chunk in text.split("# %%")[1:]:
        header, _, body = chunk.partition("\n")
        body = body.strip("\n")
        if header.strip() == "[markdown]":
            lines = [ln[2:] if ln.startswith("# ") else ln.lstrip("#") for ln in body.splitlines()]
            out.append(("markdown", "\n".join(lines)))
        else:
            out.append(("code", body))
    return out


def notebook(text):
    nb = nbformat.v4.new_notebook()
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3",
                                 "language": "python"}
    nb.metadata["language_info"] = {"name": "python"}
    make = {"code": nbformat.v4.new_code_cell, "markdown": nbformat.v4.new_markdown_cell}
    nb.cells = [make[kind](source) for kind, source in cells(text)]
    for i, cell in enumerate(nb.cells):
        cell["id"] = f"cell-{i}"  # stable ids: regenerating changes nothing
    return nb


def main():
    nbformat.write(notebook(SCRIPT.read_text()), NOTEBOOK)
    print(f"wrote {NOTEBOOK}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
