"""The records (docs/records/): every page is what `hypoid records` writes from its data, a changed
figure in a page makes the check fail, every record is in the docs index, and the records say
what the text claims of them (the recorded verdicts, the loaded tooth data's modal speeds, the
force laws against the reference model)."""

import json
import pathlib
import shutil

import pytest

from hypoid.records import docblocks
from hypoid.records import writer as cli
from hypoid.records.registry import FOLDER, RECORDS

ROOT = pathlib.Path(__file__).resolve().parents[2]


def data(name, k=0):
    return json.loads((FOLDER / RECORDS[name].data[k]).read_text())


def test_every_page_is_its_data():
    assert cli.write_all(list(RECORDS), check=True) == 0


@pytest.fixture
def copy(tmp_path):
    """The records and the index in a scratch folder."""
    folder = tmp_path / "records"
    shutil.copytree(FOLDER, folder)
    index = tmp_path / "README.md"
    shutil.copyfile(cli.INDEX, index)
    return folder, index


@pytest.mark.parametrize("name", list(RECORDS))
def test_a_changed_figure_fails_the_check(copy, name):
    """A digit of the first table row, changed, makes the page stale; writing restores it."""
    folder, index = copy
    page = folder / RECORDS[name].page
    text = page.read_text()
    lines = text.splitlines()
    row = next(line for prev, line in zip(lines, lines[1:]) if prev.startswith("|---")
               and any(c.isdigit() for c in line))
    digit = next(c for c in row if c.isdigit())
    page.write_text(text.replace(row, row.replace(digit, "1" if digit == "9" else "9", 1), 1))
    assert cli.write_all([name], check=True, folder=folder, index=index) == 1
    assert cli.write_all([name], check=False, folder=folder, index=index) == 0
    assert page.read_text() == text


def test_the_index_lists_every_record(copy):
    folder, index = copy
    text = cli.INDEX.read_text()
    for r in RECORDS.values():
        assert f"(records/{r.page})" in text
    index.write_text(text.replace(f"(records/{RECORDS['level-table'].page})", "(x.md)"))
    assert cli.write_all([], check=True, folder=folder, index=index) == 1


def test_markers_of_the_mixed_page():
    found, problems = docblocks.markers((FOLDER / "paper-findings.md").read_text())
    assert not problems and len(found) > 10


def test_records_state_the_recorded_verdicts():
    """The recorded default study gives the verdicts the findings page discusses: the paper's
    2000 rpm findings not reproduced with Table 3, the what-if's mode-3 dip reproduced."""
    rec = data("paper-findings")["default"]
    got = {f["id"]: f["verdict"] for f in rec["findings"]}
    assert got["F3-f2"] == "reproduced" and got["F3-f3"] == "not reproduced"
    assert got["F3-f3-I_p=0.001"] == "reproduced"
    ref, (wif,) = rec["details"]["reference"], rec["details"]["whatif"]
    assert wif["where"] == {"I_p": 0.001}
    assert all(abs(d["peak_rpm"] - ref["resonance_rpm"]["f2"]) < 60
               for d in ref["torques"].values())  # Table 3: the strongest peak is mode 2's
    assert all(abs(d["peak_rpm"] - wif["resonance_rpm"]["f3"]) < 60
               for d in wif["torques"].values())  # what-if: mode 3's


def test_loaded_modal_speeds_are_the_fmus():
    """The findings page's claim for the loaded tooth data: hypoid.study.modes at the drive
    flank's k_m(T), R_p(T) gives the mode-3 speed the FMU itself computed in the recorded sweep
    (its calculated n(f_3)), to the rpm."""
    rec = data("paper-findings")["loaded"]
    for t, m in rec["modal"].items():
        assert abs(m["f3"] - rec["sweep"][t]["fmu_f3_rpm"]) < 1.0, t


def test_mesh_law_record_says_what_physics_claims():
    """docs/physics.md §10.8: the FMU within 5 % of the reference model over the sweep, the
    filtered secant not."""
    for d in data("mesh-law")["torques"].values():
        ref = [r["pp_um"] for r in d["runs"]["reference"]]
        dev = {k: max(abs(r["pp_um"] / q - 1.0) for r, q in zip(d["runs"][k], ref))
               for k in ("fmu", "secant")}
        assert dev["fmu"] < 0.05 and dev["secant"] > 0.5, dev


def test_records_name_the_processor(tmp_path):
    """Real-time factors differ between processors by tens of per cent: a record names the
    model, not the architecture platform.processor() gives on Linux ('x86_64' or '')."""
    from hypoid.records import machine
    info = tmp_path / "cpuinfo"
    info.write_text("processor\t: 0\nvendor_id\t: GenuineIntel\n"
                    "model name\t: Intel(R) Xeon(R) Processor\n\nprocessor\t: 1\n")
    assert machine.processor(info) == "Intel(R) Xeon(R) Processor"
    assert machine.processor(tmp_path / "absent")  # platform's answer, never empty
    info.write_text("processor\t: 0\n")
    assert machine.processor(info) == machine.processor(tmp_path / "absent")
