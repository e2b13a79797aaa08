"""The study machinery (hypoid.study.steady, .continuation, .sweep, .parallel, .results): instance
reuse through fmi2Reset, steady-state detection, window sampling, resume after an interruption,
the dask path, error rows, and the swapped-alpha* lubricant file."""

import copy
import functools
import math
import os
import pathlib
import signal
import subprocess
import sys
import time

import numpy as np
import pandas as pd
import pytest

from hypoid.cli import args as cliargs
from hypoid.study import continuation, results, steady, paper as study, sweep
from hypoid import lubricant
from hypoid.fmu import parallel
from hypoid.fmu.instance import FmuError, Instance, normalize

QUICK = steady.Settings(window_cycles=10, min_settle_cycles=10, max_settle_time=0.05)
OUTS = ("eta_rms", "eta_mean", "DTE_pp_um", "DTE_min_um", "W_t_mean_N", "mu_mean", "h_c_mean_um")


@pytest.fixture(scope="module")
def inst(fmu_path):
    i = Instance(fmu_path)
    yield i
    i.close()


# ---------------------------------------------------------------------------- grids
def test_parse_values_and_grid():
    vary = cliargs.parse_vary(["speed_rpm=1000:2000:250", "T_s=50,100",
                               "friction_model=ehl_thermal,2"])
    assert vary == {"speed_rpm": [1000, 1250, 1500, 1750, 2000], "T_s": [50, 100],
                    "friction_model": ["ehl_thermal", "coulomb"]}
    pts = sweep.grid({"gear_set": 2}, {"T_s": [50, 100], "speed_rpm": [1000, 2000, 3000]})
    assert len(pts) == 6 and all(p["gear_set"] == 2 for p in pts)


def test_points_are_normalised_so_equal_points_get_equal_keys():
    a = sweep.complete([{"friction_model": 4, "T_s": 100, "speed_rpm": 2000}])[0]
    b = sweep.complete([{"friction_model": "ehl_thermal", "T_s": 100.0}])[0]
    assert a == b and results.point_key(a) == results.point_key(b)
    assert a["lubricant_file"] == "" and a["T_bath"] == pytest.approx(313.15)
    with pytest.raises(ValueError, match="friction_model"):
        normalize({"friction_model": "magic"})


# ---------------------------------------------------------------------------- one instance
def test_reset_between_points_reproduces_a_fresh_instance(inst, fmu_path):
    other = sweep.complete([{"gear_set": 2, "lubricant": 2, "T_s": 300, "speed_rpm": 3000,
                                 "friction_model": "coulomb", "T_bath": 353.15}])[0]
    point = sweep.complete([{"T_s": 100, "speed_rpm": 2000}])[0]
    steady.run_point(inst, other, QUICK)
    reused, _ = steady.run_point(inst, point, QUICK)
    fresh_inst = Instance(fmu_path)
    try:
        fresh, _ = steady.run_point(fresh_inst, point, QUICK)
    finally:
        fresh_inst.close()
    for k in OUTS:
        assert reused[k] == fresh[k], k


RESET_TWICE = """
import sys
import numpy as np
from hypoid.fmu.instance import Instance
from hypoid.study import sweep
from hypoid.study.tables import PAPER_CHOICES
point = sweep.complete([{**PAPER_CHOICES, "T_s": 100, "speed_rpm": 2000}])[0]
with Instance(sys.argv[1], logging=True) as i:
    for _ in range(2):
        i.start(point)
        before = len(i.messages)
        i.fast_io(["w_p"]).run(0.0, 1e-4, np.empty((3, 1)), np.empty((3, 1), np.int32),
                               np.empty(3))
        built = [m[2] for m in i.messages[before:] if "friction table built" in m[2]]
        print(built[0].split("(")[1].split()[0])
"""


def test_reset_keeps_the_process_tables(fmu_path):
    """fmi2Reset keeps the process's shared tables (model/table_store.h) also when the instance
    is the process's only one, as a study's worker is (a process of its own here): the same
    point again after a reset solves no friction node table column (the FMU's log says how many
    it solved)."""
    out = subprocess.run([sys.executable, "-c", RESET_TWICE, str(fmu_path)], check=True,
                         capture_output=True, text=True).stdout.split()
    assert int(out[0]) > 0 and int(out[1]) == 0, out


def test_fast_io_reads_what_fmpy_reads_and_raises_the_fmus_errors(inst):
    """The studies' hot loop (Instance.fast_io) against fmpy's own calls on the same instance."""
    inst.start({"T_s": 100.0, "speed_rpm": 2000.0})
    io = inst.fast_io(["w_p", "DTE", "pair[2].mu"], ["contact", "n_impacts"], ["w_set"])
    reals, ints = np.zeros((2, 3)), np.zeros((2, 2), dtype=np.int32)
    io.set_inputs([200.0])
    io.step(0.0, 1e-4)
    io.read(reals[1:].ctypes.data, ints[1:].ctypes.data)
    assert inst.t == 1e-4 and inst.get("w_set") == 200.0
    assert list(reals[1]) == inst.reals(["w_p", "DTE", "pair[2].mu"])
    assert list(ints[1]) == inst.ints(["contact", "n_impacts"]) and not reals[0].any()
    with pytest.raises(FmuError, match="does not continue the FMU time") as e:
        io.step(0.5, 1e-4)
    assert e.value.function == "fmi2DoStep"
    with pytest.raises(FmuError, match=r"w_set = 1000000 rad/s .* outside its range"):
        io.set_inputs([1e6])


def test_fast_io_run_in_c_makes_the_python_loops_calls(inst):
    """FastIo.run in C (hypoid/fmu/sample_loop.c, built by scripts/setup.sh) and in Python: the
    same values bit for bit, a ramped input, and the FMU's error with the failed call's name."""
    from hypoid.fmu import sample_loop

    assert sample_loop.library() is not None, "build/libhg_sample_loop.so: run cmake --build"
    out = {}
    for native in (True, False):
        inst.start({"T_s": 100.0, "speed_rpm": 2000.0})
        io = inst.fast_io(["w_p", "DTE", "pair[2].mu"], ["contact", "n_impacts"], ["w_set"],
                          native=native)
        reals, ints = np.empty((40, 3)), np.empty((40, 2), dtype=np.int32)
        times = np.empty(40)
        ramp = [[209.0 + 0.05 * i] for i in range(40)]
        t = io.run(0.0, 1e-4, reals, ints, times, ramp)
        assert t == times[-1] == inst.t and inst.get("w_set") == ramp[-1][0]
        with pytest.raises(FmuError, match="does not continue the FMU time") as e:
            io.run(0.5, 1e-4, reals[:1], ints[:1], times[:1])
        assert e.value.function == "fmi2DoStep" and inst.t == t
        with pytest.raises(FmuError, match=r"w_set = 1000000 rad/s .* outside its range") as e:
            io.run(t, 1e-4, reals[:1], ints[:1], times[:1], [[1e6]])
        assert e.value.function == "fmi2SetReal"
        out[native] = reals, ints, times
    for a, b in zip(out[True], out[False]):
        assert np.array_equal(a, b)
    assert len(set(out[True][0][:, 0])) == 40  # the speed moved at every step


def test_window_is_sampled_32_times_per_mesh_cycle(inst):
    row, win = steady.run_point(inst, {"T_s": 100.0, "speed_rpm": 3000.0}, QUICK, trace=True)
    n = QUICK.window_cycles * QUICK.samples_per_cycle
    assert len(win["eta"]) == n
    period = 60.0 / (3000.0 * row["N_p"])
    assert win["time"][-1] - win["time"][0] == pytest.approx((n - 1) * period / 32, rel=1e-9)
    assert (win["theta"][-1] - win["theta"][0]) / (2 * math.pi) == pytest.approx(
        (n - 1) / 32, rel=2e-3)  # the mesh angle advances one cycle per 32 samples
    assert row["eta_rms"] == pytest.approx(np.sqrt(np.mean(win["eta"] ** 2)))
    assert 0.98 < row["eta_rms"] < 1.0 and row["contact_loss_fraction"] == 0.0


def test_steady_state_detection_converges_or_reports_the_time_limit(inst):
    row, _ = steady.run_point(inst, {"T_s": 100.0, "speed_rpm": 2500.0},
                              steady.Settings(window_cycles=10))
    assert row["converged"] and row["settle_d_eta"] <= 1e-5
    strict = steady.Settings(window_cycles=10, tol_eta=0.0, tol_dte_rel=0.0, tol_dte_abs=0.0,
                             max_settle_time=0.03)
    row, _ = steady.run_point(inst, {"T_s": 100.0, "speed_rpm": 2500.0}, strict)
    assert not row["converged"]
    assert 0.03 <= row["settle_time_s"] < 0.03 + 10 * 60 / (2500 * 13) + 1e-9


def test_continuation_visits_speeds_up_then_down(inst):
    rows = continuation.run_sweep(inst, {"T_s": 100.0}, [3000, 2000, 2500],
                                  steady.Settings(window_cycles=10), ramp_time=0.05)
    assert [(r["speed_rpm"], r["branch"]) for r in rows] == [
        (2000, "up"), (2500, "up"), (3000, "up"), (3000, "down"), (2500, "down"),
        (2000, "down")]
    for r in rows:  # the governor has followed the ramps
        assert r["speed_mean_rpm"] == pytest.approx(r["speed_rpm"], rel=2e-3)


# ---------------------------------------------------------------------------- runs, resume
def test_interrupted_run_keeps_its_results_and_resumes(tmp_path, fmu_path, monkeypatch):
    pts = sweep.complete(sweep.grid({"T_s": 100}, {"speed_rpm": [2000, 3000, 4000]}))
    fmu = parallel.FmuRef(fmu_path)
    calls = []
    real = sweep.point_task

    def flaky(inst, params, settings, trace):
        calls.append(params["speed_rpm"])
        if len(calls) == 2:
            raise KeyboardInterrupt  # the user stops the run during the second point
        return real(inst, params, settings, trace)

    monkeypatch.setattr(sweep, "point_task", flaky)
    with pytest.raises(KeyboardInterrupt):
        sweep.run_points(pts, tmp_path, fmu, None, QUICK)
    log = results.Table(tmp_path / "log", "points")
    assert len(log.done_keys()) == 1  # the first result was written before the interruption
    monkeypatch.setattr(sweep, "point_task", real)
    plan = sweep.PointsPlan(pts, tmp_path, fmu, QUICK)
    assert len(plan.tasks) == 2  # a re-run does only the missing points
    df = sweep.execute([plan], fmu)[0]
    assert len(df) == 3 and (df["status"] == "ok").all()
    assert len(sweep.PointsPlan(pts, tmp_path, fmu, QUICK).tasks) == 0
    assert pd.read_parquet(tmp_path / "points.parquet").shape[0] == 3
    rebuilt = copy.copy(fmu)
    rebuilt.sha = "0" * 64  # another FMU build: nothing is reused
    assert len(sweep.PointsPlan(pts, tmp_path, rebuilt, QUICK).tasks) == 3


def test_failed_point_is_a_row_and_the_next_point_still_runs(tmp_path, fmu_path):
    pts = sweep.complete([{"T_s": 100, "speed_rpm": 2000,
                               "lubricant_file": str(tmp_path / "missing.txt")},
                              {"T_s": 100, "speed_rpm": 2500}])
    fmu = parallel.FmuRef(fmu_path)
    df = sweep.run_points(pts, tmp_path, fmu, None, QUICK)
    bad = df[df["lubricant_file"] != ""].iloc[0]
    assert bad["status"] == "error" and "missing.txt" in bad["message"]
    assert df[df["lubricant_file"] == ""].iloc[0]["status"] == "ok"
    assert len(sweep.PointsPlan(pts, tmp_path, fmu, QUICK).tasks) == 1  # failures are retried


def test_local_pool_and_a_dask_scheduler_match_the_serial_run(tmp_path, fmu_path):
    from dask.distributed import LocalCluster

    pts = sweep.complete(sweep.grid({"T_s": 50}, {"speed_rpm": [1500, 2500, 3500, 4500]}))
    fmu = parallel.FmuRef(fmu_path)
    serial = sweep.run_points(pts, tmp_path / "serial", fmu, None, QUICK)  # instance here too
    with parallel.executor(workers=2) as pool:
        assert isinstance(pool, parallel.LocalPool)
        local = sweep.run_points(pts, tmp_path / "local", fmu, pool, QUICK)
    with LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=None) as cluster:
        with parallel.executor(cluster.scheduler_address) as client:
            dist = sweep.run_points(pts, tmp_path / "dask", fmu, client, QUICK)
    for df in (local, dist):
        assert (df["status"] == "ok").all()
        assert df["worker_pid"].nunique() <= 2  # one reused instance per worker process
        assert os.getpid() not in set(df["worker_pid"])
        for k in OUTS:
            np.testing.assert_array_equal(df[k].to_numpy(), serial[k].to_numpy(), err_msg=k)


def test_local_pool_runs_points_a_few_at_a_time_each_on_its_own(tmp_path, fmu_path, monkeypatch):
    """sweep.execute hands a local pool's workers POINTS_PER_TASK points at a time: a failure ends
    its own point only (the next one gets a new instance), and the rows are the serial run's."""
    monkeypatch.setattr(sweep, "POINTS_PER_TASK", 3)
    pts = sweep.complete([{"T_s": 50, "speed_rpm": 1500},
                          {"T_s": 50, "speed_rpm": 2000,
                           "lubricant_file": str(tmp_path / "missing.txt")},
                          {"T_s": 50, "speed_rpm": 2500}, {"T_s": 50, "speed_rpm": 3500}])
    fmu = parallel.FmuRef(fmu_path)
    serial = sweep.run_points(pts, tmp_path / "serial", fmu, None, QUICK)
    with parallel.executor(workers=2) as pool:
        plan = sweep.PointsPlan(pts, tmp_path / "local", fmu, QUICK)
        submitted = []
        run = parallel.run
        monkeypatch.setattr(parallel, "run", lambda tasks, *a, **k: (submitted.extend(tasks),
                                                                     run(tasks, *a, **k)))
        local = sweep.execute([plan], fmu, pool)[0]
    assert [fn for _, fn, _ in submitted] == [parallel.each, sweep.point_task]
    for df in (serial, local):
        bad = df["lubricant_file"] != ""
        assert (df.loc[bad, "status"] == "error").all() and (df.loc[~bad, "status"] == "ok").all()
        assert "missing.txt" in df.loc[bad, "message"].iloc[0]
    ok = local["status"] == "ok"
    assert local.loc[ok, "worker_pid"].iloc[:2].nunique() == 1  # the first task's two points
    for k in OUTS:
        np.testing.assert_array_equal(local.loc[ok, k].to_numpy(),
                                      serial.loc[serial["status"] == "ok", k].to_numpy(),
                                      err_msg=k)


def test_call_all_runs_the_calls_in_order_on_other_processes_or_here():
    calls = [functools.partial(divmod, n, 7) for n in range(5)] + [os.getpid]
    here = parallel.call_all(calls, workers=0)
    there = parallel.call_all(calls, workers=2)
    assert here[:-1] == there[:-1] == [divmod(n, 7) for n in range(5)]
    assert here[-1] == os.getpid() != there[-1]


def test_table_widens_its_header_for_new_columns(tmp_path):
    t = results.Table(tmp_path, "x")
    t.append([{"point_key": "a", "status": "ok", "v": 1.0}])
    t.append([{"point_key": "b", "status": "error", "message": "boom"}])
    df = t.read()
    assert list(df.columns) == ["point_key", "status", "v", "message"]
    assert df["message"].iloc[1] == "boom" and math.isnan(df["v"].iloc[1])
    assert t.done_keys() == {"a"}


# ---------------------------------------------------------------------------- lubricant file
def test_swapped_alpha_lubricant_file(tmp_path):
    path = study.swapped_lubricant(tmp_path)
    values = {}
    for line in open(path):
        words = line.split("#")[0].split()
        if len(words) == 2:
            values[words[0]] = words[1]
    for i, a in enumerate(lubricant.BUILTIN["OS265962"]["alpha_star"], 1):
        assert float(values[f"alpha_star_{i}"]) == pytest.approx(a * 1e-9)
    assert float(values["hn_alpha"]) == lubricant.BUILTIN["OS265963"]["hn_alpha"]
    assert float(values["hn_lambda"]) == lubricant.BUILTIN["OS265963"]["hn_lambda"]
    builtin = lubricant.render(lubricant.build(name="OS265963", **lubricant.BUILTIN["OS265963"]),
                               lubricant.BUILTIN_NOTES["OS265963"])
    assert builtin == (sweep.pathlib.Path(lubricant.builtin_dir()) / "OS265963.txt").read_text()


# ---------------------------------------------------------------------------- ending a sweep
def _children(pid):
    """The ids of the live processes whose parent is `pid` (from /proc)."""
    out = []
    for stat in pathlib.Path("/proc").glob("[0-9]*/stat"):
        try:
            fields = stat.read_text().rsplit(")", 1)[1].split()
        except OSError:
            continue
        if int(fields[1]) == pid and fields[0] != "Z":
            out.append(int(stat.parent.name))
    return out


@pytest.mark.skipif(not pathlib.Path("/proc/self/stat").exists(), reason="reads /proc")
@pytest.mark.parametrize("signum", [signal.SIGTERM, signal.SIGINT])
def test_a_signal_ends_the_sweep_and_its_workers(tmp_path, fmu_path, signum):
    """Before, SIGTERM killed the parent alone and left both workers running their points."""
    cmd = [sys.executable, "-c", "import sys; from hypoid import cli; sys.exit(cli.main())", "sweep", "--fmu", str(fmu_path),
           "--out", str(tmp_path / "s"), "--workers", "2", "--window-cycles", "100000",
           "--max-settle-time", "1e4", "--set", "T_s=100", "--vary", "speed_rpm=2000,3000,4000"]
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 30
    while len(_children(proc.pid)) < 2 and time.monotonic() < deadline and proc.poll() is None:
        time.sleep(0.2)
    workers = _children(proc.pid)
    assert len(workers) >= 2, "the sweep did not start its workers"
    time.sleep(1.0)  # the workers are inside their first point
    proc.send_signal(signum)
    _, err = proc.communicate(timeout=30)
    assert proc.returncode == 2
    assert "interrupted" in err and "Traceback" not in err, err
    time.sleep(0.2)
    alive = [w for w in workers if pathlib.Path(f"/proc/{w}").exists()
             and "Z" not in pathlib.Path(f"/proc/{w}/stat").read_text().rsplit(")", 1)[1][:3]]
    assert not alive, f"workers {alive} outlived the sweep"


def test_negative_numbers_in_list_options_are_values():
    """Before, `--temperatures-c -10,20` was read as an unknown option."""
    from hypoid.cli import effmap

    args = effmap._parser().parse_args(["--out", "m.txt", "--temperatures-c", "-10,20",
                                        "--torques", "-50:50:50"])
    assert cliargs.numbers("--temperatures-c", args.temperatures_c) == [-10, 20]
    assert cliargs.numbers("--torques", args.torques) == [-50, 0, 50]
    with pytest.raises(cliargs.UsageError, match="unrecognized arguments: -x"):
        effmap._parser().parse_args(["--out", "m.txt", "-x"])
