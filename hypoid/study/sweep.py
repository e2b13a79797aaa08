"""`hypoid sweep`: a grid of steady-state operating points, or continuation sweeps, of the FMU,
run in parallel with resume; tidy tables (CSV, Parquet) and quick-look plots in --out.

    hypoid sweep --out results/my-sweep --set gear_set=2 --vary T_s=50,100 \\
                 --vary speed_rpm=1000:5000:250 [--continuation] [--scheduler tcp://host:8786]

`speed_rpm` is the pinion speed: it sets w_set and w_p0. Any FMU parameter or input can be set
or varied by name (enumerations by item name or number). A re-run into the same --out skips the
points already done; change --out (or delete it) after changing the settings.
"""

import itertools
import os
import pathlib
import sys
import time

from hypoid.cli import args as cliargs
from hypoid.study import continuation, results, steady
from hypoid.fmu import parallel
from hypoid.fmu.instance import SPEED_KEY, normalize, start_values
from hypoid.paths import user_path

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
    """Runs the plans' tasks together (in list order) and returns each plan's tidy table."""
    tasks, owner = [], {}
    for i, plan in enumerate(plans):
        for key, fn, args in plan.tasks:
            tasks.append(((i, key), fn, args))
            owner[(i, key)] = plan
    parallel.run(tasks, fmu, lambda k, res: owner[k].on_result(k[1], res), client, desc=desc)
    return [plan.finish() for plan in plans]


def run_points(points, out, fmu, client=None, settings=steady.Settings(), traced=(),
               name="points"):
    return execute([PointsPlan(points, out, fmu, settings, traced, name)], fmu, client,
                   "points")[0]


def run_sweeps(sweeps, out, fmu, client=None, settings=steady.Settings(), ramp_time=0.1,
               name="continuation"):
    return execute([SweepsPlan(sweeps, out, fmu, settings, ramp_time, name)], fmu, client,
                   "sweeps")[0]


# ---------------------------------------------------------------------------- CLI
def _parser():
    ap = cliargs.Parser("hypoid sweep", __doc__)
    ap.add_fmu()
    ap.add_argument("--out", required=True, type=user_path,
                    help="results folder (resumes if it exists)")
    ap.add_set()
    ap.add_vary()
    ap.add_argument("--continuation", action="store_true",
                    help="speed_rpm is swept up then down in one run per other-parameter combo")
    ap.add_argument("--ramp-time", type=float, default=0.1, help="s per speed change (0.1)")
    ap.add_argument("--trace", action="store_true", help="keep every point's window signals")
    ap.add_argument("--scheduler", help="dask.distributed scheduler address (default: local)")
    ap.add_argument("--workers", type=int, default=2, help="local worker processes; 0 = serial")
    ap.add_argument("--samples-per-cycle", type=int, default=32)
    ap.add_argument("--window-cycles", type=int, default=50)
    ap.add_argument("--max-settle-time", type=float, default=1.0)
    return ap


def main(argv):
    args = _parser().parse_args(argv)
    base, vary = cliargs.parse_set(args.set), cliargs.parse_vary(args.vary)
    settings = steady.Settings(samples_per_cycle=args.samples_per_cycle,
                               window_cycles=args.window_cycles,
                               max_settle_time=args.max_settle_time)
    fmu = parallel.FmuRef(cliargs.fmu_path(args.fmu))
    speeds = vary.pop(SPEED_KEY, None) if args.continuation else None
    if args.continuation and not speeds:
        raise cliargs.UsageError("--continuation needs --vary speed_rpm=...")
    points = complete(grid(base, vary))
    t0 = time.time()
    with parallel.executor(args.scheduler, args.workers) as client:
        if args.continuation:
            sweeps = [({k: v for k, v in p.items() if k != SPEED_KEY}, speeds) for p in points]
            df = run_sweeps(sweeps, args.out, fmu, client, settings, args.ramp_time)
        else:
            df = run_points(points, args.out, fmu, client, settings,
                            traced=points if args.trace else ())
    from hypoid.study import plots

    made = plots.quick_look(df, pathlib.Path(args.out), continuation=args.continuation)
    print(f"hypoid sweep: {len(df)} rows in {time.time() - t0:.1f} s -> {args.out} "
          f"({', '.join(p.name for p in made)})")
    bad = df[df["status"] != "ok"] if "status" in df else df.iloc[0:0]
    if len(bad):
        print(f"hypoid sweep: {len(bad)} rows failed; see the 'message' column", file=sys.stderr)
    return 0 if not len(bad) else 1
