"""The command line as a new user meets it: one parser and one
error path for every `hypoid` tool (hypoid.cli.args, hypoid.cli), enumeration items by name,
`speed_rpm`, and `hypoid run`'s output folder, plots and half backlash."""

import json
import math

import pytest

from hypoid import cli, regress
from hypoid.cli import args as cliargs
from hypoid.study import scenario
from hypoid.fmu.instance import Instance
from hypoid.fmu.values import TABLE, BadValue


def one_line_error(capsys, argv, *words):
    """Runs `hypoid argv`; it must fail with status 2 and one line naming all `words`."""
    assert cli.main(argv) == 2
    captured = capsys.readouterr()
    lines = captured.err.strip().splitlines()
    assert len(lines) == 1, captured.err
    assert "Traceback" not in captured.err and lines[0].startswith("hypoid")
    for w in words:
        assert w in lines[0], (w, lines[0])
    return lines[0]


# ---------------------------------------------------------------------------- values by name
def test_enumeration_items_by_name_or_code():
    """Item 2: an item by name or code gives the FMU's code; a wrong one lists the codes."""
    var = TABLE.variable("friction_model")
    assert TABLE.code(var, "ehl_thermal") == 4 == TABLE.code(var, "4") == TABLE.code(var, 4)
    with pytest.raises(BadValue, match=r"none \(= 1\).*map \(= 5\)"):
        TABLE.code(var, "magic")
    assert TABLE.fmu_values({"load_mode": "torque"}) == [(TABLE.variable("load_mode"), 1)]


def test_instance_takes_items_by_name(fmu_path):
    with Instance(fmu_path) as inst:
        inst.start({"load_mode": "torque", "mesh_model": "mean", "speed_rpm": 1500})
        assert inst.get("load_mode") == 1 and inst.get("mesh_model") == 1
        assert inst.get("w_p0") == pytest.approx(1500 * math.pi / 30)


# ---------------------------------------------------------------------------- one error path
def test_unknown_tool_is_named(capsys):
    one_line_error(capsys, ["simulate"], "'simulate'", "run", "sweep")


@pytest.mark.parametrize("tool", ["run", "sweep --out x"])
def test_unknown_variable_is_named_with_a_suggestion(capsys, tool):
    """Item 9: `--set T_sx=40` printed only 'T_sx'."""
    one_line_error(capsys, tool.split() + ["--set", "T_sx=40"], "T_sx", "did you mean T_s")


def test_incomplete_range_says_what_a_range_is(capsys):
    """Item 9: `--vary speed_rpm=1000:2000` said 'could not convert string to float'."""
    one_line_error(capsys, ["sweep", "--out", "x", "--vary", "speed_rpm=1000:2000"],
                   "speed_rpm=1000:2000", "start:stop:step")


@pytest.mark.parametrize("assignment,words", [
    ("load_mode=fast", ["load_mode", "fast", "torque (= 1)", "speed (= 2)"]),
    ("T_s=abc", ["T_s", "abc", "number", "N.m"]),
    ("gear_set=1.5", ["gear_set", "integer"]),
    ("DTE=1", ["DTE", "output"]),
    ("T_s", ["T_s", "NAME=VALUE"]),
])
def test_bad_values_are_one_line(capsys, assignment, words):
    one_line_error(capsys, ["run", "--set", assignment], *words)


def test_fmu_errors_are_one_line_without_traceback(capsys, fmu_path, tmp_path):
    """Item 3: `T_bath=40` printed the FMU's message and then a 20-line traceback."""
    base = ["run", "--fmu", str(fmu_path), "--out", str(tmp_path), "--stop-time", "0.01"]
    one_line_error(capsys, base + ["--set", "T_bath=40"], "T_bath", "40", "range")
    one_line_error(capsys, base + ["--set", "friction_model=map"], "map", "rigid")
    assert not any(tmp_path.iterdir())  # nothing written for a failed run


def test_usage_errors_are_one_line(capsys):
    one_line_error(capsys, ["run", "--stop-tme", "1"], "--stop-tme", "--help")
    one_line_error(capsys, ["sweep"], "--out")
    one_line_error(capsys, ["run", "--fmu", "/nowhere/x.fmu"], "/nowhere/x.fmu", "no such FMU")


# ---------------------------------------------------------------------------- hypoid run
def run(tmp_path, *args, capsys=None):
    assert cli.main(["run", "--out", str(tmp_path), *args]) == 0
    if capsys:
        capsys.readouterr()
    summaries = sorted(tmp_path.glob("*/summary.json"), key=lambda p: p.stat().st_mtime_ns)
    return summaries[-1].parent, json.loads(summaries[-1].read_text())


def test_run_takes_items_by_name_and_speed_rpm(tmp_path, fmu_path, capsys):
    """Item 3: `--set load_mode=speed friction_model=map` (with the rigid mesh it needs) and
    `--set speed_rpm=3000` work."""
    common = ["--fmu", str(fmu_path), "--stop-time", "0.2"]
    folder, s = run(tmp_path, *common, "--set", "speed_rpm=3000", capsys=capsys)
    assert s["pinion_speed_rpm"] == pytest.approx(3000, rel=2e-3)
    assert folder.name == "speed_rpm=3000"
    _, s = run(tmp_path, *common, "--set", "load_mode=speed", "friction_model=map",
               "mesh_model=rigid", capsys=capsys)
    assert 90 < s["eta_mean_percent"] < 100


def test_run_folder_is_named_after_the_run_and_never_overwritten(tmp_path, fmu_path, capsys):
    """Item 4: every run wrote <out>/default-scenario/, each overwriting the last."""
    common = ["--fmu", str(fmu_path), "--stop-time", "0.02"]
    first, _ = run(tmp_path, *common, "--set", "T_s=150", capsys=capsys)
    second, _ = run(tmp_path, *common, "--set", "T_s=150", capsys=capsys)
    named, _ = run(tmp_path, *common, "--name", "my case", capsys=capsys)
    assert first.name == "T_s=150" and second.name == "T_s=150-2"
    assert named.name == "my-case"
    for f in (first, second):
        assert {p.name for p in f.iterdir()} >= {"timeseries.csv", "cycles.csv", "summary.json",
                                                  "timeseries.png", "zoom.png"}


def test_run_uses_the_fmus_half_backlash_and_a_mesh_based_interval(tmp_path, fmu_path, capsys):
    """Item 4: the half-backlash line was fixed at 70 µm; the default interval of 5e-5 s made a
    7 MB CSV for 0.5 s whatever the speed."""
    folder, s = run(tmp_path, "--fmu", str(fmu_path), "--stop-time", "0.05", "--set",
                    "b=50e-6", "speed_rpm=1000", capsys=capsys)
    assert s["half_backlash_um"] == pytest.approx(50.0)
    mesh_period = 60.0 / (1000 * 13)  # gear set 1: N_p = 13
    assert s["output_interval_s"] == pytest.approx(mesh_period / scenario.SAMPLES_PER_CYCLE)
    rows = len((folder / "timeseries.csv").read_text().splitlines()) - 1
    assert rows == round(0.05 / s["output_interval_s"]) + 1
    cycles = (folder / "cycles.csv").read_text().splitlines()
    assert abs(len(cycles) - 1 - 0.05 / mesh_period) <= 3


def test_mesh_cycles_and_cycle_table_against_a_hand_built_signal():
    """Per-cycle means, minima and maxima of a signal built with a known value per cycle."""
    import numpy as np

    n_p, w = 10, 2 * math.pi * 5.0  # 50 mesh cycles per second
    t = (np.arange(200) + 0.5) * 1e-3  # 20 samples per cycle, 10 cycles, off the boundaries
    r = {"time": t, "w_p": np.full_like(t, w), "w_g": np.full_like(t, w / 3)}
    k = np.floor(50.0 * t)  # the mesh cycle of each sample
    for name in scenario.CYCLE_SIGNALS[2:]:
        r[name] = k + 0.1 * np.sin(2 * math.pi * 50 * t)
    cycle = scenario.mesh_cycles(r, n_p)
    assert np.array_equal(cycle, k.astype(int))
    table = scenario.cycle_table(r, cycle)
    assert list(table["cycle"]) == list(range(1, int(k.max())))
    assert np.allclose(table["DTE_mean"], table["cycle"], atol=0.02)
    assert np.all(table["DTE_max"] - table["DTE_min"] <= 0.2 + 1e-12)


# ---------------------------------------------------------------------------- hypoid regress
def test_regress_help_reads_whole(capsys):
    """Item 9: the help stopped mid-sentence (only the docstring's first line)."""
    assert cli.main(["regress", "--help"]) == 0
    text = capsys.readouterr().out
    assert "Exit status 1 when anything moved beyond its tolerance." in text
    assert "--scenarios" in text and "[hot_oil_3000rpm]" in text


def test_regress_with_scenarios_of_ones_own(tmp_path, fmu_path, capsys):
    """Item 9: users can add regression scenarios of their own and compare with them later."""
    mine = tmp_path / "mine.toml"
    mine.write_text('[coulomb_1500]\nspeed_rpm = 1500\nT_s = 80\nfriction_model = "coulomb"\n'
                    'mesh_model = "mean"\n')
    argv = ["regress", "--fmu", str(fmu_path), "--scenarios", str(mine)]
    one_line_error(capsys, argv, "mine.reference.csv", "--update")
    assert cli.main(argv + ["--update"]) == 0
    ref = tmp_path / "mine.reference.csv"
    assert ref.exists()
    assert cli.main(argv) == 0
    values, params = regress.read_reference(ref)
    values["coulomb_1500"]["eta_rms"] += 1e-3  # far beyond the tolerance of 2e-5
    regress.write_reference(values, ref, regress.read_scenarios(mine))
    capsys.readouterr()
    assert cli.main(argv) == 1
    assert "MOVED coulomb_1500: eta_rms" in capsys.readouterr().out
    mine.write_text('[bad]\nspeed_rpm = 1500\nT_sx = 80\n')
    one_line_error(capsys, argv, "mine.toml", "[bad]", "T_sx")


def test_parse_set_and_vary_give_canonical_values():
    assert cliargs.parse_set(["T_s=200", "gear_set=2", "friction_model=4"]) == \
        {"T_s": 200.0, "gear_set": 2, "friction_model": "ehl_thermal"}
    assert cliargs.parse_vary(["T_bath=300:310:5"]) == {"T_bath": [300, 305, 310]}
