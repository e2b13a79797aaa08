"""examples/: the quick-start notebook and its plain-script twin run to the end, so that
they never rot. Both execute the same five experiments; the checks read the
physics they print (the tip-out ends on the coast flank, efficiencies are percentages of a
lossy gear)."""

import os
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"
sys.path.insert(0, str(EXAMPLES))

import make_notebook  # noqa: E402

FIGURES = ("launch", "tipout", "sweep", "lossmap", "drive_coast")


def check_output(text, out_dir):
    assert "tip-out: contact 1 -> -1" in text
    for side in ("drive", "coast"):  # a lossy gear: 97-99.9 % (docs/friction-evidence.md)
        eta = float(re.search(side + r": eta_cycle = ([0-9.]+) %", text).group(1))
        assert 97.0 < eta < 99.9, (side, eta)
    for name in FIGURES:
        assert (out_dir / f"{name}.png").stat().st_size > 1000, name


def test_notebook_is_made_from_the_script():
    """quickstart.ipynb holds exactly the cells of quickstart.py (run make_notebook.py)."""
    import nbformat

    stored = nbformat.read(EXAMPLES / "quickstart.ipynb", as_version=4)
    fresh = make_notebook.notebook((EXAMPLES / "quickstart.py").read_text())
    assert [(c.cell_type, c.source) for c in stored.cells] == \
        [(c.cell_type, c.source) for c in fresh.cells], "stale: run examples/make_notebook.py"
    assert all(not c.get("outputs") for c in stored.cells), "store the notebook without outputs"


def test_script_runs(tmp_path, fmu_path):
    env = dict(os.environ, QUICKSTART_OUT=str(tmp_path / "out"), MPLBACKEND="Agg")
    run = subprocess.run([sys.executable, str(EXAMPLES / "quickstart.py")], cwd=tmp_path,
                         env=env, capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr[-3000:]
    assert "Warning" not in run.stdout + run.stderr
    check_output(run.stdout, tmp_path / "out")


def test_notebook_executes(tmp_path, fmu_path, monkeypatch):
    import nbclient
    import nbformat

    monkeypatch.setenv("HYPOID_FMU", str(fmu_path))
    monkeypatch.setenv("QUICKSTART_OUT", str(tmp_path / "out"))
    nb = nbformat.read(EXAMPLES / "quickstart.ipynb", as_version=4)
    nbclient.NotebookClient(nb, timeout=300, kernel_name="python3",
                            resources={"metadata": {"path": str(tmp_path)}}).execute()
    text = "".join(o.get("text", "") for c in nb.cells if c.cell_type == "code"
                   for o in c.get("outputs", []))
    check_output(text, tmp_path / "out")
    images = [o for c in nb.cells for o in c.get("outputs", []) if "image/png" in o.get("data", {})]
    assert len(images) == len(FIGURES)
