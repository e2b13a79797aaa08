"""Silent surprises made visible: warnings at initialisation for values that
are ignored or implausible, units in the range messages, and the elastic mesh deflection as an
output beside the DTE (which keeps the paper's definition, half backlash included)."""

import json
import math
import pathlib

import numpy as np
import pytest

from hypoid.fmu.instance import FmuError
from hypoid.fmu.variables import ENUMERATIONS

RPM = math.pi / 30
B = 70e-6  # the default half backlash [m]
WARNING = 1  # fmi2Warning


def warnings(h):
    return [text for status, category, text in h.messages
            if status == WARNING and category == "logStatusWarning"]


@pytest.mark.parametrize("values, expected", [
    ({}, []),
    ({"T_w": 500.0}, ["T_w = 500 N.m is ignored: with load_mode = speed"]),
    ({"T_w": 500.0, "load_mode": 1}, []),  # torque-driven: T_w is used
    ({"w_set": 1500.0, "w_p0": 150.0}, ["w_set = 1500 rad/s (14324 rpm) is faster than",
                                         "if 1500 was meant in rpm, set 157.1 rad/s"]),
    ({"w_set": 800.0, "w_p0": 800.0}, []),  # 7639 rpm: fast, but a real axle speed
    ({"w_p0": -1200.0, "w_set": -100.0}, ["w_p0 = -1200 rad/s (-11459 rpm)"]),
    ({"w_set": 1500.0, "load_mode": 1}, []),  # torque-driven: w_set is not used
])
def test_warnings_at_initialisation(harness, values, expected):
    h = harness()
    h.start(values, checked=False)
    got = warnings(h)
    assert len(got) == (1 if expected else 0), got
    for part in expected:
        assert part in got[0], got
    h.record(0.002, 1e-3, ["w_p"])  # a warning is not an error: the run goes on
    assert not h.errors()


def test_range_messages_carry_units(harness):
    h = harness()
    h.slave.setupExperiment(startTime=0.0)
    with pytest.raises(FmuError):
        h.set_unchecked(dict(T_bath=40.0))
    with pytest.raises(FmuError):
        h.set_unchecked(dict(w_set=5000.0))
    with pytest.raises(FmuError):
        h.set_unchecked(dict(rtol=1.0))
    texts = [m[2] for m in h.errors()]
    assert "T_bath = 40 K (-233.15 degC) is outside its range [200, 500] K" in texts[0]
    assert "w_set = 5000 rad/s (47746.5 rpm) is outside its range [-2000, 2000] rad/s" in texts[1]
    assert "rtol = 1 is outside its range [1e-12, 0.1]" in texts[2]  # dimensionless


def run(harness, t_end, h_step, **values):
    """The deflection outputs after each step: {name: array}."""
    h = harness()
    h.start(values, checked=False)
    reals = ["DTE", "DTE_elastic", "W_t", "k_m"]
    rows, contact = [], []
    for _ in range(int(round(t_end / h_step))):
        h.step(h_step)
        rows.append(h.reals(reals))
        contact.append(h.ints(["contact"])[0])
    out = dict(zip(reals, np.array(rows).T))
    out["contact"] = np.array(contact)
    return out


def test_elastic_deflection_in_drive_and_coast(harness):
    """On the drive flank the deflection is DTE - b, on the back flank DTE + b; the mesh spring
    k_m f carries the mean mesh load (the damper c x' averages out over the window)."""
    for torque, side in ((200.0, 1), (-200.0, -1)):
        r = run(harness, 0.15, 1e-4, T_s=torque, w_set=2000 * RPM, w_p0=2000 * RPM)
        late = slice(len(r["DTE"]) // 2, None)
        assert np.all(r["contact"][late] == side)
        np.testing.assert_allclose(r["DTE_elastic"][late], r["DTE"][late] - side * B,
                                   rtol=0, atol=1e-12)
        spring = np.mean(r["k_m"][late] * r["DTE_elastic"][late])
        assert spring == pytest.approx(np.mean(r["W_t"][late]), rel=2e-2)
        assert side * np.mean(r["DTE_elastic"][late]) > 1e-6  # microns of tooth deflection


def test_elastic_deflection_is_zero_while_apart(harness):
    """The mode-2 resonance at 1200 rpm, 50 N.m (the paper's calibrated tooth data) separates the
    teeth part of the time: there the deflection is exactly 0 while the DTE moves inside the
    backlash."""
    r = run(harness, 0.3, 5e-5, T_s=50.0, w_set=1200 * RPM, w_p0=1200 * RPM,
            tooth_data=ENUMERATIONS["tooth_data"]["paper"])
    apart = r["contact"] == 0
    assert apart.sum() > 20
    assert np.all(r["DTE_elastic"][apart] == 0.0)
    assert np.all(np.abs(r["DTE"][apart]) <= B * (1 + 1e-9))


@pytest.mark.parametrize("mesh_model, check", [
    (1, lambda r: np.testing.assert_array_equal(r["DTE_elastic"], r["DTE"])),  # mean: no backlash
    (3, lambda r: np.testing.assert_array_equal(r["DTE_elastic"], 0.0)),      # rigid
])
def test_elastic_deflection_of_the_simpler_meshes(harness, mesh_model, check):
    check(run(harness, 0.01, 1e-3, mesh_model=mesh_model))


def test_hypoid_run_shows_the_warnings(tmp_path, fmu_path, capsys):
    """`hypoid run` passes the FMU's set-up warnings on to the user and into summary.json."""
    from hypoid.cli import run as run_cli

    argv = ["--fmu", str(fmu_path), "--out", str(tmp_path), "--stop-time", "0.005",
            "--set", "w_set=1500", "w_p0=150"]
    assert run_cli.main(argv) == 0
    err = capsys.readouterr().err
    assert "hypoid run: FMU warning: w_set = 1500 rad/s (14324 rpm)" in err
    (summary,) = tmp_path.glob("*/summary.json")
    assert "w_set = 1500 rad/s" in " ".join(json.loads(summary.read_text())["fmu_warnings"])


def test_data_file_range_messages_carry_units(harness, tmp_path):
    """A lubricant file's value out of range: the message gives the file's unit with the value
    and the range (the files are SI, docs/data-files.md)."""
    oil = pathlib.Path(__file__).resolve().parents[2] / "resources" / "lubricants" / "OS265962.txt"
    bad = tmp_path / "bad.txt"
    bad.write_text(oil.read_text().replace("\nk_f 0.18", "\nk_f 50"))
    h = harness()
    with pytest.raises(FmuError):
        h.start(dict(lubricant_file=str(bad)), checked=False)
    assert any("key 'k_f' = 50 W/(m K) is outside [0.01, 10] W/(m K)" in m[2]
               for m in h.errors()), h.errors()
