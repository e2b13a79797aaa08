"""Benchmark of the default study (the main job of ./run.sh, `hypoid study default`): wall and CPU
time of whole runs into fresh folders (medians over --runs), and where the time goes: the local
cluster's start, the tasks (steady points, continuation sweeps, the axle's loss map; their CPU from
the result tables), the report, and the costliest points and windows. Not a timed test; it prints
a table and writes the record docs/records/study-time (its data study-time.json, or --json).

  .venv/bin/python bench/study_time.py                     # 3 runs of the default study
  .venv/bin/python bench/study_time.py --runs 1 --study ci
  .venv/bin/python bench/study_time.py --keep /tmp/st       # keep each run's results folder
"""

import argparse
import json
import os
import pathlib
import resource
import statistics
import subprocess
import sys
import tempfile
import time

import pandas as pd

from hypoid.records.registry import FOLDER, RECORDS

ROOT = pathlib.Path(__file__).resolve().parents[1]


def children_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def one_run(args, out):
    cmd = [str(ROOT / ".venv/bin/hypoid"), "study", args.study, "--fmu", args.fmu, "--out",
           str(out), "--workers", str(args.workers)]
    wall, cpu, load = time.perf_counter(), children_cpu(), os.getloadavg()[0]
    done = subprocess.run(cmd, capture_output=True, text=True)
    wall, cpu = time.perf_counter() - wall, children_cpu() - cpu
    if done.returncode != 0:
        sys.exit(f"study_time: {' '.join(cmd)} failed ({done.returncode}): "
                 f"{done.stderr.strip().splitlines()[-1:]}")
    # the load average (1 min) before and after: wall times mean little on shared cores
    return {"wall_s": wall, "cpu_s": cpu, "load_before": load, "load_after": os.getloadavg()[0],
            **parts(out)}


def parts(out):
    """The run's own timing (study.json) and the CPU of each kind of task (the tables)."""
    info = json.loads((out / "study.json").read_text())
    pts = pd.read_csv(out / "points.csv")
    cont = pd.read_csv(out / "continuation.csv")
    lm = pd.read_csv(out / "lossmap.csv")
    slow = pts.nlargest(5, "cpu_s")
    return {"cluster_start_s": info["cluster_start_s"], "tasks_wall_s": info["wall_s"],
            "report_s": info.get("report_s", float("nan")),
            "points": len(pts), "continuation_rows": len(cont),
            "points_cpu_s": float(pts["cpu_s"].sum()),
            "sweeps_cpu_s": sweeps_cpu(cont),
            "lossmap_cpu_s": float(lm["cpu_s"].sum()),
            "slowest_points": [f"set {r.gear_set}, {r.T_s:g} N.m, {r.speed_rpm:g} rpm: "
                               f"{r.cpu_s:.2f} s" for r in slow.itertuples()],
            "settle_s_simulated": float(pts["settle_time_s"].sum() + cont["settle_time_s"].sum()),
            "converged": int(pts["converged"].sum() + cont["converged"].sum())}


def sweeps_cpu(cont):
    """CPU of each continuation sweep, by torque (and inertia, where a what-if sweeps too)."""
    keys = ["T_s"] + (["I_p"] if "I_p" in cont else [])
    return {f"{k[0]:g} N.m" + (f", I_p {k[1]:g}" if len(k) > 1 else ""): float(c)
            for k, c in cont.groupby(keys)["cpu_s"].sum().items()}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--fmu", default=str(ROOT / "build/HypoidGearPair.fmu"))
    ap.add_argument("--study", default="default")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--keep", type=pathlib.Path, help="folder for the runs' results (kept)")
    ap.add_argument("--json", type=pathlib.Path, default=FOLDER / "study-time.json")
    args = ap.parse_args()
    root = args.keep or pathlib.Path(tempfile.mkdtemp(prefix="study-time-"))
    runs = []
    for k in range(args.runs):
        runs.append(one_run(args, root / f"run{k}"))
        print(f"run {k}: {runs[-1]['wall_s']:.1f} s wall, {runs[-1]['cpu_s']:.1f} s CPU (load "
              f"{runs[-1]['load_before']:.1f} -> {runs[-1]['load_after']:.1f})", flush=True)
    med = {key: statistics.median(r[key] for r in runs)
           for key in ("wall_s", "cpu_s", "cluster_start_s", "tasks_wall_s", "report_s",
                       "points_cpu_s", "lossmap_cpu_s")}
    report = {"study": args.study, "fmu": args.fmu, "runs": args.runs, "workers": args.workers,
              "finished": time.strftime("%Y-%m-%d %H:%M:%S"), "median": med, "each": runs}
    args.json.write_text(json.dumps(report, indent=2) + "\n")
    if args.json == FOLDER / "study-time.json":
        (FOLDER / "study-time.md").write_text(RECORDS["study-time"].write())
    print(f"\n{args.study} study, median of {args.runs}: {med['wall_s']:.1f} s wall, "
          f"{med['cpu_s']:.1f} s CPU (all processes)")
    for key in ("cluster_start_s", "tasks_wall_s", "report_s", "points_cpu_s", "lossmap_cpu_s"):
        print(f"  {key:16s} {med[key]:8.2f}")
    print(f"  sweeps CPU        {runs[-1]['sweeps_cpu_s']}")
    print("  slowest points   " + "; ".join(runs[-1]["slowest_points"]))
    print(f"-> {args.json}")


if __name__ == "__main__":
    main()
