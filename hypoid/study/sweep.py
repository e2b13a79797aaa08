"""Grids of steady-state operating points and continuation sweeps of the FMU, run in parallel
with resume, into tidy tables (CSV, Parquet) and quick-look plots. The command is `hypoid sweep`
(hypoid/cli/sweep.py)."""

import itertools
import os
import pathlib
import time

from hypoid.fmu import parallel
from hypoid.fmu.instance import SPEED_KEY, normalize, start_values
from hypoid.study import continuation, results, steady

# columns every table carries, so each row describes its point fully
ESSENTIAL = ("gear_set", "lubricant", "lubricant_file", "T_s", SPEED_KEY, "T_bath",
             "friction_model", "mesh_model")
POINT_ORDER = ("gear_set", "lubricant", "lubricant_file", "friction_model", "mesh_model", "k_f",
               "T_bath", "T_s", SPEED_KEY)


# ---------------------------------------------------------------------------- grids
def grid(base, vary):
    """Cartesian product of the varied values over the base parameters."""
    names = list(vary)
    return [{**base, **dict(zip(names, combo))}
            for combo in itertools.product(*(vary[n] for n in names))]


def complete(points, extra=()):
    """Normalised points that all carry the same columns (missing ones at their start value)."""
    names = list(dict.fromkeys(list(ESSENTIAL) + list(extra) + [k for p in points for k in p]))
    defaults = start_values(names)
    return [normalize({**defaults, **p}) for p in points]


def key_of(params, settings, fmu, **extra):
    """The result key: the point's parameters, the settings and the FMU's content hash (a
    rebuilt FMU re-runs everything; an interrupted run of the same FMU resumes)."""
    return results.point_key({**params, "__settings": settings.as_dict(), "__fmu": fmu.sha,
                              **extra})


# Steady points a task of a local pool runs in turn (sweep.execute): the points of a grid come in
# order of speed, neighbouring speeds share the friction model's node tables, and each worker
# process solves the tables it uses for itself; one point a task had both workers solve most of
# them (docs/decisions.md, "The study's steady points a few at a time")
POINTS_PER_TASK = 16

# ---------------------------------------------------------------------------- worker tasks
def point_task(inst, params, settings, trace):
    row, window = steady.run_point(inst, params, settings, trace)
    return {"status": "ok", **row, "worker_pid": os.getpid(), "_trace": window}


def sweep_task(inst, params, speeds, settings, ramp_time):
    rows = continuation.run_sweep(inst, params, speeds, settings, ramp_time)
    return {"status": "ok", "rows": rows}


# ---------------------------------------------------------------------------- runs
class PointsPlan:
    """Steady points not yet in out/log/<name>.csv; results are appended as they arrive."""

    def __init__(self, points, out, fmu, settings=steady.Settings(), traced=(), name="points"):
        self.out = pathlib.Path(out)
        self.log = results.Table(self.out / "log", name)
        self.stem = self.out / name
        traced = {results.canonical(p) for p in traced}
        self.fmu_sha = fmu.sha[:16]
        self.jobs = {key_of(p, settings, fmu): p for p in points}
        done = self.log.done_keys()
        self.tasks = [(k, point_task, (p, settings, results.canonical(p) in traced))
                      for k, p in self.jobs.items() if k not in done]

    def on_result(self, key, res):
        window = res.pop("_trace", None)
        row = {**self.jobs[key], results.KEY: key, **res, "fmu_sha256": self.fmu_sha}
        if window is not None:
            path = results.write_trace(self.out / "traces", key, self.jobs[key], window)
            row["trace"] = str(path.relative_to(self.out))
        self.log.append([row])

    def finish(self):
        """The tidy table of this plan's points (CSV and Parquet next to the log)."""
        df = self.log.read()
        if not df.empty:
            df = df[df[results.KEY].astype(str).isin(set(self.jobs))]
            df = df.drop_duplicates(results.KEY, keep="last")
        return results.write_tidy(df, self.stem, POINT_ORDER)


class SweepsPlan:
    """Continuation sweeps [(params without speed, speeds)], one task per sweep."""

    def __init__(self, sweeps, out, fmu, settings=steady.Settings(), ramp_time=0.1,
                 name="continuation"):
        self.out = pathlib.Path(out)
        self.log = results.Table(self.out / "log", name)
        self.stem = self.out / name
        self.ramp_time = ramp_time
        self.fmu_sha = fmu.sha[:16]
        self.jobs = {}
        for params, speeds in sweeps:
            speeds = [float(s) for s in speeds]
            key = key_of(params, settings, fmu, speeds=speeds, ramp_time=ramp_time)
            self.jobs[key] = (params, speeds)
        done = self.log.done_keys("sweep_key")
        self.tasks = [(k, sweep_task, (p, s, settings, ramp_time))
                      for k, (p, s) in self.jobs.items() if k not in done]

    def on_result(self, key, res):
        params, speeds = self.jobs[key]
        common = {**params, "sweep_key": key, "fmu_sha256": self.fmu_sha,
                  "ramp_time_s": self.ramp_time,
                  "sweep_speeds": f"{min(speeds):g}-{max(speeds):g} ({len(speeds)})"}
        if res.get("status") != "ok":
            self.log.append([{**common, results.KEY: key, **res}])
            return
        rows = []
        for r in res["rows"]:
            row = {**common, **r, "status": "ok"}
            row[results.KEY] = results.point_key({"sweep": key, "order": r["order"]})
            rows.append(row)
        self.log.append(rows)

    def finish(self):
        df = self.log.read()
        if not df.empty:
            df = df[df["sweep_key"].astype(str).isin(set(self.jobs))]
        return results.write_tidy(df, self.stem, ("gear_set", "T_s", "sweep_key", "order"))


def execute(plans, fmu, client=None, desc="tasks"):
    """Runs the plans' tasks together (in list order) and returns each plan's tidy table. On
    local forked workers the steady points go POINTS_PER_TASK at a time (parallel.each)."""
    tasks, owner = [], {}
    per_task = POINTS_PER_TASK if parallel.inherits(client, fmu) else 1
    for i, plan in enumerate(plans):
        n = per_task if isinstance(plan, PointsPlan) else 1
        for j in range(0, len(plan.tasks), n):
            group = plan.tasks[j:j + n]
            if len(group) == 1:
                key, fn, args = group[0]
                tasks.append(((i, key), fn, args))
                owner[(i, key)] = (plan, None)
            else:
                tasks.append(((i, ("points", j)), parallel.each,
                              (fmu.sha, [(fn, args) for _, fn, args in group])))
                owner[(i, ("points", j))] = (plan, [key for key, _, _ in group])

    def deliver(k, res):
        plan, keys = owner[k]
        if keys is None:
            plan.on_result(k[1], res)
            return
        results = res.get("results") or [dict(res) for _ in keys]  # the whole task failed
        for key, r in zip(keys, results):
            plan.on_result(key, r)

    parallel.run(tasks, fmu, deliver, client, desc=desc)
    return [plan.finish() for plan in plans]


def run_points(points, out, fmu, client=None, settings=steady.Settings(), traced=(),
               name="points"):
    return execute([PointsPlan(points, out, fmu, settings, traced, name)], fmu, client,
                   "points")[0]


def run_sweeps(sweeps, out, fmu, client=None, settings=steady.Settings(), ramp_time=0.1,
               name="continuation"):
    return execute([SweepsPlan(sweeps, out, fmu, settings, ramp_time, name)], fmu, client,
                   "sweeps")[0]
