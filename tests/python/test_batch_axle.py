"""The batch tools see the whole axle (sweep, study, regress): with axle_losses = full the
points carry every part of the ledger, the axle efficiency and the oil temperature, the sweep
plots them, and a regression scenario compares them; coast points read as coast (the back flank
is their working flank), not as teeth apart and negative peak loads."""

import math

import pandas as pd
import pytest

from hypoid import regress
from hypoid.fmu import parallel
from hypoid.fmu.instance import Instance
from hypoid.study import metrics, plots, steady, sweep

QUICK = steady.Settings(window_cycles=10, min_settle_cycles=10, max_settle_time=0.05)


@pytest.fixture(scope="module")
def axle_points(fmu_path, tmp_path_factory):
    out = tmp_path_factory.mktemp("axle")
    pts = sweep.complete([
        {"T_s": 100.0, "speed_rpm": 2000.0, "axle_losses": "full"},
        {"T_s": -100.0, "speed_rpm": 2000.0, "axle_losses": "full"},
        {"T_s": 100.0, "speed_rpm": 3000.0, "axle_losses": "full"},
        {"T_s": 100.0, "speed_rpm": 2000.0}])
    df = sweep.run_points(pts, out, parallel.FmuRef(fmu_path), None, QUICK)
    return df.set_index(["T_s", "speed_rpm", "axle_losses"]), out, df


def test_axle_points_carry_the_ledger_and_mesh_points_do_not(axle_points):
    """Before, a sweep with axle_losses = full wrote no axle column."""
    df, _, _ = axle_points
    full, mesh = df.loc[(100.0, 2000.0, "full")], df.loc[(100.0, 2000.0, "mesh")]
    for col in metrics.AXLE_FIGURES:
        assert math.isfinite(full[col]), col
        assert col not in mesh or pd.isna(mesh[col]), col
    parts = sum(full[c] for c in ("P_mesh_mean_W", "P_churn_mean_W", "P_bearings_mean_W",
                                  "P_seals_mean_W"))
    assert parts == pytest.approx(full["P_axle_mean_W"], rel=1e-9)  # the ledger adds up
    assert full["P_bearings_mean_W"] > 0 and full["P_seals_mean_W"] > 0
    assert 0.8 < full["eta_axle_energy"] < full["eta_energy"] < 1.0
    assert full["T_oil_mean_C"] == pytest.approx(40.0, abs=0.5)  # T_bath's default, held


def test_a_coast_point_reads_as_coast(axle_points):
    """Before, a coast point read 'contact lost 100 %' and a negative peak load."""
    df, _, _ = axle_points
    coast, drive = df.loc[(-100.0, 2000.0, "full")], df.loc[(100.0, 2000.0, "full")]
    assert coast["flank"] == "coast" and drive["flank"] == "drive"
    assert coast["contact_loss_fraction"] == 0.0 and coast["apart_fraction"] == 0.0
    assert coast["back_contact_fraction"] == 1.0  # the FMU's code: on the back flank throughout
    assert coast["W_t_peak_N"] > coast["W_t_mean_N"] > 0
    # the same torque on the other flank carries a load of the same order
    assert 0.5 < coast["W_t_mean_N"] / drive["W_t_mean_N"] < 2.0


def test_the_sweep_plots_the_axle(axle_points, tmp_path):
    _, _, df = axle_points
    made = plots.quick_look(df, tmp_path)
    assert [p.name for p in made] == ["sweep.png", "sweep_axle.png"]
    assert all(p.stat().st_size > 10_000 for p in made)


def test_regression_compares_the_axle_ledger_in_an_axle_scenario(fmu_path):
    """Before, hypoid regress compared the 14 mesh quantities only, also in an axle scenario."""
    scenarios = {"axle_2000": {"T_s": 100.0, "speed_rpm": 2000.0, "axle_losses": "full"},
                 "mesh_2000": {"T_s": 100.0, "speed_rpm": 2000.0}}
    values = regress.run_all(fmu_path, scenarios)
    assert set(values["axle_2000"]) == set(regress.QUANTITIES) | set(regress.AXLE_QUANTITIES)
    assert set(values["mesh_2000"]) == set(regress.QUANTITIES)
    tol = regress.read_tolerances()
    params = {n: regress._params_text(p) for n, p in scenarios.items()}
    _, problems = regress.compare(values, values, params, tol, scenarios)
    assert problems == []
    moved = {n: dict(v) for n, v in values.items()}
    moved["axle_2000"]["P_bearings_mean_W"] *= 1.01  # a 1 % change of the bearings' loss
    _, problems = regress.compare(values, moved, params, tol, scenarios)
    assert len(problems) == 1 and "P_bearings_mean_W" in problems[0]


def test_whole_axle_reads_the_instance(fmu_path):
    with Instance(fmu_path) as inst:
        inst.start({"axle_losses": "full"})
        assert steady.whole_axle(inst)
        inst.start({})
        assert not steady.whole_axle(inst)


def test_eta_axle_under_the_default_says_it_is_the_mesh_alone(fmu_path):
    """Decision: axle_losses stays mesh by default (the paper's scene, which every study and the
    regression reference run), and whoever reads eta_axle or P_axle is told: their descriptions
    in the FMU's modelDescription say that under axle_losses = mesh they are the mesh's alone,
    and the batch tools write the axle columns only for points that run the whole axle."""
    from fmpy import read_model_description

    md = {v.name: v for v in read_model_description(str(fmu_path)).modelVariables}
    for name in ("eta_axle", "P_axle", "eta_axle_cycle"):
        text = md[name].description
        assert "axle_losses = mesh" in text and "default" in text, (name, text)
    assert md["axle_losses"].start in ("1", 1)  # mesh
    with Instance(fmu_path) as inst:
        inst.start({"T_s": 100.0, "w_set": 2000 * math.pi / 30, "w_p0": 2000 * math.pi / 30,
                    "load_mode": "speed"})
        inst.do_step(0.0, 0.05)
        P_axle, P_loss = inst.reals(["P_axle", "P_loss"])
    assert P_axle == P_loss  # the mesh alone, as the description says
