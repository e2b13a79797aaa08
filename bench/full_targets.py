#!/usr/bin/env python3
"""The full model's speed targets, measured with their accuracy: the full model
(varying mesh, thermal EHL, exact backlash) at the FMU's defaults, ARKODE's explicit pair at rtol
1e-4 and the paper's fixed-step Newmark at 50 steps per mesh cycle.

    .venv/bin/python bench/full_targets.py       # the record docs/records/full-targets (~3 min)
    .venv/bin/python bench/full_targets.py --out /tmp --runs 5

Accuracy (checked, exit status 1 when a candidate that must meet it does not): in each of the five
work-precision scenes (bench/wp_driver.py) every candidate's eta_cycle and DTE peak to peak
against the tight reference, CVODE BDF at rtol 1e-10 (atol 1e-14 m), measured as
bench/work_precision.py measures them. The defaults and arkode_erk must stay within 0.01 %-point
of eta_cycle and 0.1 um of DTE p-p; Newmark's errors are stated, not required.

Cost (one run of the C host, bench_fmu levels with one variant per candidate, batches interleaved
so that a load on the machine affects all alike): real-time factor at 2000 rpm, 100 N.m, 1 ms
communication steps, and the ratio of each candidate's to Newmark's. Targets: the defaults at
>= 50x real time and >= 5x Newmark at 50 steps per mesh cycle.
"""

import argparse
import json
import os
import pathlib
import platform
import shlex
import subprocess
import sys
import time
from dataclasses import dataclass

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import wp_driver as W  # noqa: E402

from hypoid.records.registry import RECORDS  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]
ETA_TOL = 0.01    # [%-point] of eta_cycle
DTE_TOL = 0.1e-6  # [m] of DTE peak to peak
RTF_TARGET = 50.0
NEWMARK_RATIO_TARGET = 5.0


@dataclass(frozen=True)
class Candidate:
    """A setting of the full model: parameters before initialisation (on top of the scene's).
    `solver` and `value` as wp_driver.Setting has them (the fine run samples Newmark at its own
    steps); `sets` is the same setting for bench_fmu; `checked`: must meet the accuracy."""
    label: str
    start: dict
    solver: str
    value: float
    checked: bool

    @property
    def sets(self):
        return ",".join(f"{k}={v}" for k, v in self.start.items())


CANDIDATES = [
    Candidate("defaults", {}, "defaults", 0.0, True),
    Candidate("arkode_erk rtol 1e-4", dict(solver="arkode_erk", rtol=1e-4, atol=1e-8),
              "arkode_erk", 1e-4, True),
    Candidate("newmark 50/cycle", dict(solver="newmark", steps_per_mesh_cycle=50), "newmark",
              50.0, False),
]


def log(msg):
    print(msg, file=sys.stderr, flush=True)


def metrics(fmu, scene, setting):
    """eta_cycle (timed run, 0.05 s steps) and DTE p-p (fine run) of the full model."""
    ts, xs, cs = W.fine_run(fmu, scene, "full", setting)
    fine = W.fine_metrics(scene, ts, xs, cs)
    _, recs, counters = W.timed_run(fmu, scene, "full", setting)
    coarse = W.coarse_metrics(scene, recs, counters)
    return dict(eta_cycle=coarse["eta_cycle"], dte_pp=fine["dte_pp"])


def accuracy(fmu, scenes):
    """rows: scene, candidate, errors against the reference, whether within the targets."""
    rows = []
    for key, scene in scenes.items():
        t0 = time.time()
        ref = metrics(fmu, scene, W.REFERENCE)
        for c in CANDIDATES:
            try:
                m = metrics(fmu, scene, c)
            except W.RunError as e:
                rows.append(dict(scene=key, candidate=c, error=str(e)[:200], ok=False))
                continue
            d_eta = abs(m["eta_cycle"] - ref["eta_cycle"]) * 100.0
            d_dte = abs(m["dte_pp"] - ref["dte_pp"])
            rows.append(dict(scene=key, candidate=c, ref=ref, d_eta=d_eta, d_dte=d_dte,
                             ok=d_eta <= ETA_TOL and d_dte <= DTE_TOL, error=""))
        log(f"full_targets: {key} done in {time.time() - t0:.0f} s")
    return rows


def bench_fmu_table(bench, fmu_dir, runs, cpu):
    """Real-time factors and us per mesh cycle of every candidate, one bench_fmu run."""
    cmd = [str(bench), str(fmu_dir), "levels", "--levels", "full", "--runs", str(runs),
           "--cpu", str(cpu)]
    for c in CANDIDATES:
        cmd += ["--variant", f"{c.label}:{c.sets}"]
    out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
    fig = {}
    for line in out.splitlines():
        cells = [x.strip() for x in line.strip().strip("|").split("|")]
        if len(cells) == 8 and cells[0] == "full":
            fig[cells[1]] = dict(rtf=float(cells[2]), us_step=float(cells[4]),
                                 steps=float(cells[5]), rhs=float(cells[6]),
                                 us_cycle=float(cells[7]))
    return shlex.join(["build/bench_fmu", "FMU_DIR"] + cmd[2:]), fig


def by_scene(rows):
    out = {}
    for r in rows:
        out.setdefault(r["scene"], []).append(r)
    return out


def defaults_text(fmu):
    """The FMU's default solver settings, from its model description."""
    out = []
    for v in fmu.md.modelVariables:
        if v.name in ("solver", "rtol", "atol"):
            items = {i.value: i.name for i in (v.declaredType.items if v.declaredType else [])}
            out.append(f"{v.name} = {items.get(v.start, v.start)}")
    return ", ".join(out)


def record(args, rows, cmd, fig, fmu, t_run):
    """The record's data (docs/records/full-targets.json; hypoid.records.full_targets writes the
    page from it)."""
    nm = fig["newmark 50/cycle"]
    scenes = []
    for key, rs in by_scene(rows).items():
        ref = next((r["ref"] for r in rs if "ref" in r), None)
        scenes.append(dict(scene=key, ref=ref and dict(eta_cycle=ref["eta_cycle"],
                                                       dte_pp_um=ref["dte_pp"] * 1e6),
                           results=[dict(label=r["candidate"].label, d_eta=r.get("d_eta"),
                                         d_dte_um=r["d_dte"] * 1e6 if "d_dte" in r else None,
                                         ok=r["ok"], error=r["error"]) for r in rs]))
    return dict(
        meta=dict(fmu=os.path.relpath(fmu.path, ROOT), run_at=time.strftime("%a %b %d %H:%M %Y"),
                  host=f"{platform.node()} ({platform.machine()}, 2 cores shared with other "
                       "jobs)", seconds=t_run, defaults=defaults_text(fmu), command=cmd,
                  runs=args.runs, cpu=args.cpu),
        targets=dict(rtf=RTF_TARGET, newmark_ratio=NEWMARK_RATIO_TARGET, eta_pt=ETA_TOL,
                     dte_um=DTE_TOL * 1e6),
        candidates=[dict(label=c.label, checked=c.checked, rtf=fig[c.label]["rtf"],
                         ratio=fig[c.label]["rtf"] / nm["rtf"], us_cycle=fig[c.label]["us_cycle"],
                         steps=fig[c.label]["steps"], rhs=fig[c.label]["rhs"])
                    for c in CANDIDATES],
        newmark_rhs_per_step=nm["rhs"] / nm["steps"], scenes=scenes)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--fmu", default=str(ROOT / "build" / "HypoidGearPair.fmu"))
    ap.add_argument("--bench", default=str(ROOT / "build" / "bench_fmu"),
                    help="the C host (cmake --build build --target bench_fmu)")
    ap.add_argument("--runs", type=int, default=3, help="timed batches per candidate")
    ap.add_argument("--cpu", type=float, default=0.2, help="CPU seconds per batch")
    ap.add_argument("--scenes", nargs="*", help="subset of the scenes")
    ap.add_argument("--out", default=str(ROOT / "docs" / "records"),
                    help="the records' folder (full-targets.json and .md)")
    args = ap.parse_args()
    if not pathlib.Path(args.bench).is_file():
        print(f"full_targets: {args.bench} is missing: cmake --build build --target bench_fmu",
              file=sys.stderr)
        sys.exit(2)
    t0 = time.time()
    fmu = W.Fmu(args.fmu)
    scenes = {k: s for k, s in W.scenes().items() if not args.scenes or k in args.scenes}
    if not scenes:
        print(f"full_targets: no such scene: {args.scenes}", file=sys.stderr)
        sys.exit(2)
    cmd, fig = bench_fmu_table(args.bench, fmu.dir, args.runs, args.cpu)
    rows = accuracy(fmu, scenes)
    out = pathlib.Path(args.out)
    data = record(args, rows, cmd, fig, fmu, time.time() - t0)
    (out / "full-targets.json").write_text(json.dumps(data, indent=1) + "\n")
    (out / "full-targets.md").write_text(RECORDS["full-targets"].write(out))
    failed = [r for r in rows if r["candidate"].checked and not r["ok"]]
    for r in failed:
        log(f"full_targets: FAILED: {r['candidate'].label} in {r['scene']}: "
            + (r["error"] or f"d eta_cycle {r['d_eta']:.2e} %-point, d DTE p-p "
                             f"{r['d_dte'] * 1e6:.3f} um"))
    log(f"full_targets: wrote {out}/full-targets.json and .md")
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
