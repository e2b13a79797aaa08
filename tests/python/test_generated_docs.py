"""Documented numbers that are written by a script from a recorded run, checked against that
record: docs/paper-findings.md (tools/paper_findings.py, docs/paper-findings.json) and
physics.md §10.8's tables of what the loaded tooth data do at 2000 rpm (tools/tooth_figures.py,
docs/figures/km_effect.json), of the force laws against the reference model
(tools/mesh_law_reference.py, docs/figures/mesh_law_reference.json) and of μ, P_loss and DTE
with the paper's and the loaded tooth data (tools/friction_figures.py --block tooth-data,
docs/figures/friction_tooth-data.json). A changed figure in the page makes each check fail."""

import json
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]


def _fails_on(script, text, old, new, tmp_path, name):
    stale = tmp_path / name
    stale.write_text(text.replace(old, new, 1))
    return subprocess.run(script + ["--file", str(stale)], capture_output=True).returncode == 1


def test_page_numbers_are_the_recorded_study(tmp_path):
    """docs/paper-findings.md's generated blocks are written by tools/paper_findings.py from the
    recorded study (docs/paper-findings.json); a changed figure makes the check fail."""
    script = [sys.executable, str(ROOT / "tools" / "paper_findings.py"), "--check"]
    subprocess.run(script, check=True)
    data = json.loads((ROOT / "docs" / "paper-findings.json").read_text())
    text = (ROOT / "docs" / "paper-findings.md").read_text()
    row = data["default"]["findings"][0]["this FMU"]
    assert row in text
    assert _fails_on(script, text, row, row + "1", tmp_path, "paper-findings.md")


def test_page_states_the_recorded_verdicts():
    """The recorded default study gives the verdicts this page discusses: the paper's 2000 rpm
    findings not reproduced with Table 3, the what-if's mode-3 dip reproduced."""
    rec = json.loads((ROOT / "docs" / "paper-findings.json").read_text())["default"]
    got = {f["id"]: f["verdict"] for f in rec["findings"]}
    assert got["F3-f2"] == "reproduced" and got["F3-f3"] == "not reproduced"
    assert got["F3-f3-I_p=0.001"] == "reproduced"
    ref, (wif,) = rec["details"]["reference"], rec["details"]["whatif"]
    assert wif["where"] == {"I_p": 0.001}
    assert all(abs(d["peak_rpm"] - ref["resonance_rpm"]["f2"]) < 60
               for d in ref["torques"].values())  # Table 3: the strongest peak is mode 2's
    assert all(abs(d["peak_rpm"] - wif["resonance_rpm"]["f3"]) < 60
               for d in wif["torques"].values())  # what-if: mode 3's


def test_physics_km_effect_table_is_the_recorded_run(tmp_path):
    script = [sys.executable, str(ROOT / "tools" / "tooth_figures.py"), "--check"]
    subprocess.run(script, check=True)
    text = (ROOT / "docs" / "physics.md").read_text()
    row = next(line for line in text.splitlines() if line.startswith("| 1 | 50 | "))
    assert _fails_on(script, text, row, row.replace(" | ", " | 9", 1), tmp_path, "physics.md")


def test_loaded_modal_speeds_are_the_fmus():
    """The page's claim for the loaded tooth data: hypoid.study.modes at the drive flank's k_m(T),
    R_p(T) interpolated between the file's levels gives the mode-3 speed the FMU itself computed
    in the recorded sweep (its calculated n(f_3)), to the rpm."""
    rec = json.loads((ROOT / "docs" / "paper-findings.json").read_text())["loaded"]
    for t, m in rec["modal"].items():
        assert abs(m["f3"] - rec["sweep"][t]["fmu_f3_rpm"]) < 1.0, t


def test_physics_mesh_law_comparison_is_the_recorded_run(tmp_path):
    """physics.md §10.8's comparison of the force laws against the reference model is written by
    tools/mesh_law_reference.py from docs/figures/mesh_law_reference.json; and the record says
    what the text claims: the FMU within 5 % of the reference over the sweep, the filtered secant
    not."""
    script = [sys.executable, str(ROOT / "tools" / "mesh_law_reference.py"), "check",
              "--doc-file"]
    subprocess.run(script[:-1], check=True)
    text = (ROOT / "docs" / "physics.md").read_text()
    row = next(line for line in text.splitlines() if line.startswith("| 2000 rpm | "))
    stale = tmp_path / "physics.md"
    stale.write_text(text.replace(row, row.replace(" µm", "1 µm", 1), 1))
    assert subprocess.run(script + [str(stale)], capture_output=True).returncode == 1
    rec = json.loads((ROOT / "docs" / "figures" / "mesh_law_reference.json").read_text())
    for d in rec["torques"].values():
        ref = [r["pp_um"] for r in d["runs"]["reference"]]
        dev = {k: max(abs(r["pp_um"] / q - 1.0) for r, q in zip(d["runs"][k], ref))
               for k in ("fmu", "secant")}
        assert dev["fmu"] < 0.05 and dev["secant"] > 0.5, dev


def test_physics_tooth_data_table_is_the_recorded_run(tmp_path):
    script = [sys.executable, str(ROOT / "tools" / "friction_figures.py"), "--block",
              "tooth-data", "--check"]
    subprocess.run(script, check=True)
    text = (ROOT / "docs" / "physics.md").read_text()
    row = next(line for line in text.splitlines() if line.startswith("| OS265962 | 2000 | 100 |"))
    assert _fails_on(script, text, row, row.replace(" | ", " | 9", 1), tmp_path, "physics.md")
