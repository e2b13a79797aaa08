"""Paths given to the tools are relative to the user's working directory:
a data file named relative to where the user stands reaches the FMU as an absolute path, so it
is not looked up inside the host's temporary unzip folder; names of the FMU's own resources still
pass through unchanged."""

import json
import os
import pathlib
import shutil
import sys

import pytest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))

from hypoid import paths  # noqa: E402
from hypoid.cli import run as run_cli  # noqa: E402
from hypoid.fmu.instance import normalize  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[2]
OIL = ROOT / "resources" / "lubricants" / "OS265963.txt"


@pytest.fixture
def user_dir(tmp_path, monkeypatch):
    """A working directory holding the user's own lubricant file my.txt."""
    monkeypatch.chdir(tmp_path)
    shutil.copy(OIL, tmp_path / "my.txt")
    return tmp_path


def test_data_file_rules(user_dir):
    assert paths.data_file("my.txt") == str(user_dir / "my.txt")
    assert paths.data_file("./my.txt") == str(user_dir / "my.txt")
    assert paths.data_file("") == ""
    assert paths.data_file(str(OIL)) == str(OIL)
    # not a file here: a name inside the FMU's resources folder, passed through
    assert paths.data_file("lubricants/OS265962.txt") == "lubricants/OS265962.txt"
    assert paths.user_path("out") == str(user_dir / "out")


def test_sweep_points_carry_absolute_files(user_dir, model_description):
    point = normalize({"lubricant_file": "my.txt", "gear_set_file": ""})
    assert point == {"lubricant_file": str(user_dir / "my.txt"), "gear_set_file": ""}


def test_run_with_a_relative_lubricant_file(user_dir, fmu_path):
    """`hypoid run --set lubricant_file=my.txt` from the user's folder reads that file: the run
    succeeds and matches the built-in lubricant 2 that my.txt is a copy of."""
    common = ["--fmu", str(fmu_path), "--stop-time", "0.01", "--output-interval", "1e-3"]

    def loss(out, *values):
        assert run_cli.main(common + ["--out", out, "--set", *values]) == 0
        found = list((user_dir / out).glob("*/summary.json"))
        assert len(found) == 1, found
        return json.loads(found[0].read_text())["P_loss_mean_W"]

    mine = loss("mine", "lubricant_file=my.txt")
    builtin = loss("builtin", "lubricant=2")
    assert mine > 0.0
    assert mine == pytest.approx(builtin, rel=1e-12)
