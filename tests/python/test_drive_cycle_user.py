"""The engineer's own car and route in `hypoid drive-cycle`: every vehicle FMU parameter by name
(--set, a vehicle file), the air density from the air temperature, the engine's drag map, the
driveline inertias in summary.json, a route's grade, ';' files with decimal commas, the standard
cycles shipped as package data, a car that never moves, and bad input as one line."""

import json
import math
import pathlib

import numpy as np
import pytest

from hypoid import cli
from hypoid.drivecycle import cycles, run as runner
from hypoid.drivecycle.vehicle import R_AIR, Engine, Vehicle, air_density

KMH = 1 / 3.6
MILE = 1.609344


def drive(tmp_path, capsys, rows, *argv, name="run", header="time,speed,grade", sep=","):
    """Runs hypoid drive-cycle (cold only) on a cycle written from rows; (code, summary, rows,
    stderr)."""
    f = tmp_path / f"{name}.csv"
    f.write_text("\n".join([header.replace(",", sep)]
                           + [sep.join(str(x) for x in r) for r in rows]) + "\n")
    code = cli.main(["drive-cycle", "--cycle", str(f), "--out", str(tmp_path / "out"),
                     "--name", name, "--no-warm", *argv])
    err = capsys.readouterr().err
    if code != 0:
        return code, None, None, err
    folder = tmp_path / "out" / name
    s = json.loads((folder / "summary.json").read_text())
    return code, s, np.genfromtxt(folder / "cold.csv", delimiter=",", names=True), err


def road_energy(r, m, c_rr, CdA, rho, v_eps=0.5, g=9.81):
    """The road load's work from the recorded speeds, by hand: (c_rr m g tanh(v/v_eps)
    + rho/2 CdA v^2) v integrated with the trapezoidal rule."""
    v = r["v"]
    P = (c_rr * m * g * np.tanh(v / v_eps) + 0.5 * rho * CdA * v * v) * v
    return float(np.trapezoid(P, r["time"]))


CRUISE = [(0, 0, 0), (2, 0, 0), (12, 60, 0), (40, 60, 0)]


def test_vehicle_parameters_by_name_and_the_air_density_from_its_temperature(tmp_path, capsys):
    """Before, --set m=1800 was refused and rho_air was 1.2 at any air temperature."""
    code, s, r, _ = drive(tmp_path, capsys, CRUISE, "--set", "m=1800", "CdA=0.6", "c_rr=0.009",
                          "--t-amb", "-7")
    assert code == 0
    car = s["meta"]["vehicle"]["vehicle_fmu"]
    rho = 101325.0 / (287.05 * (273.15 - 7.0))  # ideal gas, by hand: 1.3284 kg/m^3
    assert car["m"] == 1800 and car["CdA"] == 0.6 and car["rho_air"] == pytest.approx(rho)
    assert road_energy(r, 1800, 0.009, 0.6, rho) == pytest.approx(r["E_road"][-1], rel=2e-3)
    # the driveline's inertias as the gear FMU ran them: its own I_w plus the car's m r^2 + J
    d = s["meta"]["driveline"]
    assert d["I_w"] == pytest.approx(0.0 + 1800 * 0.3 ** 2 + 3.0, abs=2.0)
    assert set(d) >= {"I_s", "I_p", "I_g", "I_w", "ratio"}
    assert air_density(293.15) == pytest.approx(1.204, abs=1e-3)  # ISO 2533 air at 20 degC


def test_a_vehicle_file_sets_the_car_the_driveline_and_the_engine(tmp_path, capsys):
    car = tmp_path / "car.toml"
    car.write_text("[vehicle]\nm = 1800.0\nr_dyn = 0.32\nCdA = 0.65\n[driveline]\nI_s = 0.09\n"
                   "[engine]\ndrag_speed_rpm = [0, 1000, 3000]\n"
                   "drag_torque_Nm = [-10.0, -30.0, -50.0]\n[air]\npressure_Pa = 90000.0\n")
    down = [(0, 0, 0), (2, 0, 0), (14, 80, 0), (16, 80, 0), (40, 20, 0), (48, 0, 0), (50, 0, 0)]
    code, s, r, _ = drive(tmp_path, capsys, down, "--vehicle", str(car))
    assert code == 0
    v = s["meta"]["vehicle"]
    assert v["vehicle_fmu"]["r_dyn"] == 0.32 and s["meta"]["driveline"]["I_s"] == 0.09
    assert v["vehicle_fmu"]["rho_air"] == pytest.approx(90000.0 / (R_AIR * 293.15))
    # while braking from 80 km/h the engine drags at its map's torque for the shaft's speed
    # (the brakes take the rest); before, at -20 N m whatever the speed
    engine = Engine(drag_rpm=[0, 1000, 3000], drag_Nm=[-10.0, -30.0, -50.0])
    coast = (r["time"] > 20) & (r["time"] < 38) & (r["T_brake"] > 0)
    assert coast.sum() > 100
    w_p = r["w_p"][np.flatnonzero(coast) - 1]  # the command of a step uses the speed before it
    expect = np.array([engine.drag(w) for w in w_p])
    assert np.allclose(r["T_s"][coast], expect, rtol=1e-7)  # the CSV keeps 9 digits
    assert expect.min() < -30.0 < expect.max()


def test_a_routes_grade_costs_m_g_sin_theta_per_metre(tmp_path, capsys):
    """Uphill at a steady 36 km/h: the wheels' extra work over the level road is m g sin(theta)
    times the distance (theta = atan 5 %), by hand; the file in ';' with decimal commas."""
    def route(grade):
        return [(0, 0, 0), (2, 0, 0), (10, "36,0", 0), (15, "36,0", grade),
                (45, "36,0", grade), (50, "36,0", 0)]
    _, lvl, rl, _ = drive(tmp_path, capsys, route("0"), "--set", "m=1800", name="level", sep=";")
    _, up, ru, _ = drive(tmp_path, capsys, route("5,0"), "--set", "m=1800", name="up", sep=";")
    hill = (ru["time"] >= 15) & (ru["time"] <= 45)
    d = float(np.trapezoid(ru["v"][hill], ru["time"][hill]))
    expect = 1800 * 9.81 * math.sin(math.atan(0.05)) * d
    gained = (ru["E_out"][hill][-1] - ru["E_out"][hill][0]) \
        - (rl["E_out"][hill][-1] - rl["E_out"][hill][0])
    assert gained == pytest.approx(expect, rel=0.02)
    assert up["runs"][0]["grade_J"] == pytest.approx(
        1800 * 9.81 * math.sin(math.atan(0.05)) * float(np.trapezoid(
            ru["v"] * (ru["grade"] != 0) * ru["grade"] / 5.0, ru["time"])), rel=0.05)
    assert lvl["runs"][0]["grade_J"] == 0.0


def test_a_car_that_never_moves_ends_with_what_it_measured(tmp_path, capsys):
    """Before: 'unexpected ZeroDivisionError'."""
    code, s, r, err = drive(tmp_path, capsys, [(0, 0, 0), (20, 0, 0)])
    assert code == 0, err
    c = s["runs"][0]
    assert c["distance_km"] == 0.0 and c["energy_into_axle_J"] == 0.0
    assert c["mean_axle_efficiency"] is None and c["audit"]["energy_residual_relative"] is None
    assert (tmp_path / "out" / "run" / "summary.md").read_text().count("n/a") >= 1


@pytest.mark.parametrize("name, miles, seconds", [
    ("udds", 7.45, 1369), ("hwfet", 10.26, 765), ("us06", 8.01, 600), ("ftp75", 11.04, 2474)])
def test_the_epa_cycles_come_from_fastsims_files(name, miles, seconds):
    """Distances and durations against EPA's published figures (the FTP-75: 1874 s driven and
    the 600 s soak)."""
    c = cycles.builtin_cycle(name)
    assert c.t[-1] == seconds and "fastsim 2.1.5" in c.source
    assert float(np.trapezoid(c.v, c.t)) / 1e3 / MILE == pytest.approx(miles, abs=0.01)


def test_wltc_classes_come_from_the_wltp_package():
    assert cycles.builtin_cycle("wltc2").t[-1] == 1800
    assert float(np.trapezoid(cycles.builtin_cycle("wltc2").v, np.arange(1801))) \
        == pytest.approx(22649, abs=5)  # GTR 15's class 2 distance, m
    assert cycles.builtin_cycle("wltc3b").source == cycles.builtin_cycle("wltc3").source


@pytest.mark.parametrize("toml, words", [
    ("[vehicle]\nmass = 1800\n", ["car.toml", "mass", "1800", "not a vehicle parameter"]),
    ("[vehicle]\nm = 0\n", ["car.toml", "m = 0", "positive"]),
    ("[vehicle]\nr_dyn = -0.3\n", ["car.toml", "r_dyn = -0.3", "positive"]),
    ("[vehicle]\nCdA = 0.0\n", ["car.toml", "CdA = 0.0", "positive"]),
    ("[vehicle]\ngrade = 0.4\n", ["car.toml", "grade = 0.4", "30 %"]),
    ("[motor]\nT = 1\n", ["car.toml", "motor", "unknown section"]),
    ("[engine]\ndrag_speed_rpm = [0, 1000]\ndrag_torque_Nm = [-10, 5]\n",
     ["car.toml", "engine.drag_torque_Nm", "<= 0"]),
    ("[vehicle\n", ["car.toml", "not TOML"]),
])
def test_bad_vehicle_files_are_one_line_and_write_nothing(tmp_path, capsys, toml, words):
    (tmp_path / "car.toml").write_text(toml)
    code, _, _, err = drive(tmp_path, capsys, CRUISE, "--vehicle", str(tmp_path / "car.toml"))
    assert code == 2 and len(err.strip().splitlines()) == 1 and "Traceback" not in err
    for w in words:
        assert w in err, (w, err)
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())


@pytest.mark.parametrize("argv, rows, words", [
    (["--set", "m=-5"], CRUISE, ["--set", "m = -5.0", "positive"]),
    (["--set", "coupling=1"], CRUISE, ["coupling", "set by the drive cycle"]),
    (["--set", "T_s=-500"], CRUISE, ["--set T_s = -500.0", "set by the drive cycle", "driver"]),
    (["--set", "T_amb=300"], CRUISE, ["T_amb", "set by the drive cycle", "--t-amb"]),
    (["--set", "speed_rpm=1000"], CRUISE, ["speed_rpm", "set by the drive cycle"]),
    ([], [(0, 0, 0), (10, 20, 31)], ["line 3", "grade 31.0 %", "30 %"]),
    (["--master", "libcosim"], [(0, 0, 0), (10, 20, 3)], ["libcosim", "grade"]),
])
def test_bad_vehicle_values_and_grades_are_one_line(tmp_path, capsys, argv, rows, words):
    code, _, _, err = drive(tmp_path, capsys, rows, *argv)
    assert code == 2 and len(err.strip().splitlines()) == 1 and "Traceback" not in err
    for w in words:
        assert w in err, (w, err)


def test_the_progress_bar_is_for_a_terminal_only(monkeypatch):
    monkeypatch.delenv("CI", raising=False)
    monkeypatch.setattr(runner.sys.stderr, "isatty", lambda: True, raising=False)
    assert not runner.progress(10.0, "cold").disable
    monkeypatch.setenv("CI", "true")
    assert runner.progress(10.0, "cold").disable
    monkeypatch.setattr(runner.sys.stderr, "isatty", lambda: False, raising=False)
    monkeypatch.delenv("CI", raising=False)
    assert runner.progress(10.0, "cold").disable


# What a user may still choose among the values gear_start sets for the scene: the axle's loss and
# heat models, the half-shaft's stiffness (the vehicle's k_hs by default) and I_w (added to the
# car's inertia at the wheel end).
USER_CHOICES = {"axle_losses", "thermal_model", "k_t2", "I_w"}


def test_scene_values_are_refused_and_documented():
    """Every value gear_start sets for the scene itself is in SCENE_SET (refused by --set) or a
    user's choice, and docs/axle.md names every refused one."""
    for level in runner.LEVELS:
        scene = set(runner.gear_start(level, Vehicle(), 0.0, 293.15, 293.15, {}))
        scene -= set(runner.LEVELS[level])
        assert scene - USER_CHOICES <= set(runner.SCENE_SET), (level, scene - USER_CHOICES)
    docs = (pathlib.Path(__file__).resolve().parents[2] / "docs" / "axle.md").read_text()
    refused = docs.split("except what the scene sets itself")[1].split("those are refused")[0]
    assert not [n for n in runner.SCENE_SET if f"`{n}`" not in refused]


def test_an_existing_run_folder_is_refused_before_the_runs(tmp_path, capsys, monkeypatch):
    """Before, the check came after the cycle had run: a full-level cycle took minutes and then
    exited with nothing written."""
    (tmp_path / "out" / "run").mkdir(parents=True)

    def no_run(*args, **kwargs):
        raise AssertionError("simulated although the run folder exists")

    monkeypatch.setattr("hypoid.cli.drive_cycle.simulate", no_run)
    code, _, _, err = drive(tmp_path, capsys, CRUISE)
    assert code == 2 and len(err.strip().splitlines()) == 1 and "Traceback" not in err
    assert str(tmp_path / "out" / "run") in err and "exists" in err and "--name" in err
