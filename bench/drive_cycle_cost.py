"""Benchmark: the drive-cycle cost table, level x cycle x start temperature. Each cell runs the
gear+vehicle co-simulation of `hypoid drive-cycle` (hypoid.drivecycle.run.simulate, the fmpy
master, 50 ms steps) and records the process CPU of the run (the median over --repeats; both FMUs
and the Python master run in this process), the real-time factor (cycle duration / CPU) and the
axle's cycle loss, and, where the full level ran at the same cycle and start, the map and fast
levels' loss relative to the full level's. Not a timed test: it writes the data of the record
docs/records/drive-cycle-cost (drive-cycle-cost.json, or --json) and its page, and prints a
table.

  nice .venv/bin/python bench/drive_cycle_cost.py                      # the record (~20 min)
  .venv/bin/python bench/drive_cycle_cost.py --until 20 --json /tmp/c.json   # a quick look
  .venv/bin/python bench/drive_cycle_cost.py --against OTHER.fmu --levels full --cycles wltc3 \
      --starts "cold 20" --json /tmp/ab.json       # this build against another, in one run

--against compares two builds of the gear FMU (--fmu and OTHER) in one run: each cell runs them
in turn (a b, b a, a b, ...), so that both meet the same machine, and reports their median CPU,
the ratio of the medians and the change of the axle's cycle loss. On a shared machine whose speed
drifts by tens of per cent between hours, that ratio is the evidence a change needs; it writes
no record.

Starts: "cold" at the air's temperature (-7 and 20 degC), "warm" with the oil at 80 degC in air
at 20 degC (as `hypoid drive-cycle`'s warm run). --heavy-input adds the first cycle's cold 20 degC
start of the map and fast levels with an engine and gearbox behind the pinion (I_s = 0.214
kg m^2 against the default's bare input shaft): the levels' cost must not depend on it."""

import argparse
import datetime
import json
import os
import pathlib
import resource
import statistics
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from hypoid.drivecycle import cycles, levels, summary  # noqa: E402
from hypoid.drivecycle import run as runner  # noqa: E402
from hypoid.records import machine  # noqa: E402
from hypoid.records.docblocks import commit  # noqa: E402
from hypoid.records.registry import FOLDER, RECORDS  # noqa: E402

DATA = FOLDER / RECORDS["drive-cycle-cost"].data[0]
STARTS = {"cold -7": (-7.0, -7.0), "cold 20": (20.0, 20.0), "warm 80": (80.0, 20.0)}  # oil, air
REPEATS = {"map": 3, "fast": 3, "full": 3}  # the full level's single runs spread by 10 %
HEAVY_INPUT = {"I_s": 0.214}  # kg m^2: an engine's and gearbox's inertia reflected to the pinion


def cpu_seconds():
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime


def once(cycle, level, start, sets, args, fmu=None):
    """One run (of the gear FMU `fmu`, else --fmu): CPU, wall and what it gave."""
    T_oil0, T_amb = STARTS[start]
    load, wall, cpu = os.getloadavg()[0], time.perf_counter(), cpu_seconds()
    r = runner.simulate(cycle, fmu or args.fmu, args.vehicle_fmu, level, T_oil0 + levels.ZERO_C,
                        T_amb + levels.ZERO_C, args.step, dict(sets), f"{level} {start}")
    wall, cpu = time.perf_counter() - wall, cpu_seconds() - cpu
    s = summary.summarise(r, cycle, args.step)
    return {"cpu_s": cpu, "wall_s": wall, "load_before": load, "load_after": os.getloadavg()[0],
            "axle_loss_J": s["axle_loss_J"], "T_oil_end_degC": s["T_oil_degC"]["end"],
            "energy_audit_relative": s["audit"]["energy_residual_relative"]}


def cell(cycle, level, start, repeats, args, sets=None):
    """A level at a cycle and start (and the gear's start values `sets`): each repeat's figures,
    the median CPU and its real-time factor."""
    sets = sets or {}
    each = [once(cycle, level, start, sets, args) for _ in range(repeats)]
    losses = {e["axle_loss_J"] for e in each}
    cpu = statistics.median(e["cpu_s"] for e in each)
    span = float(cycle.t[-1] - cycle.t[0])
    out = {"cycle": cycle.name, "start": start, "T_oil0_degC": STARTS[start][0],
           "T_amb_degC": STARTS[start][1], "level": level, "sets": sets, "repeats": repeats,
           "cpu_s": cpu,
           "real_time_factor_cpu": span / cpu, "axle_loss_J": each[0]["axle_loss_J"],
           "T_oil_end_degC": each[0]["T_oil_end_degC"],
           "energy_audit_relative": each[0]["energy_audit_relative"],
           "repeats_identical": len(losses) == 1, "each": each}
    print(f"{cycle.name:<8} {start:<8} {level:<5} {sets or ''} {cpu:8.2f} s CPU {span / cpu:8.1f}x "
          f"{out['axle_loss_J'] / 1e3:9.2f} kJ (load {each[0]['load_before']:.2f})", flush=True)
    return out


def ab_cell(cycle, level, start, repeats, args):
    """A level at a cycle and start with --fmu ("this") and --against, their runs in turn and
    the order swapped at every repeat: the median CPU of each, this over against, and the
    change of the axle's cycle loss."""
    builds = [("this", args.fmu), ("against", args.against)]
    each = {name: [] for name, _ in builds}
    for k in range(repeats):
        for name, fmu in builds[::-1] if k % 2 else builds:
            each[name].append(once(cycle, level, start, {}, args, fmu))
    cpu = {name: statistics.median(e["cpu_s"] for e in runs) for name, runs in each.items()}
    loss = {name: runs[0]["axle_loss_J"] for name, runs in each.items()}
    out = {"cycle": cycle.name, "start": start, "level": level, "repeats": repeats,
           "cpu_s": cpu, "cpu_ratio": cpu["this"] / cpu["against"], "axle_loss_J": loss,
           "loss_change": loss["this"] / loss["against"] - 1.0, "each": each}
    print(f"{cycle.name:<8} {start:<8} {level:<5} {cpu['this']:8.2f} s CPU against "
          f"{cpu['against']:8.2f} s: {out['cpu_ratio']:.3f}, axle loss "
          f"{100 * out['loss_change']:+.3f} %", flush=True)
    return out


def against(args, repeats):
    """--against: the two builds cell by cell; the data to --json if given."""
    cells = []
    for name in args.cycles:
        cycle = cycles.load_cycle(name)
        cycle = shortened(cycle, args.until) if args.until else cycle
        cells += [ab_cell(cycle, level, start, repeats[level], args)
                  for start in args.starts for level in args.levels]
    if args.json:
        out = {"command": "python " + " ".join(["bench/drive_cycle_cost.py", *sys.argv[1:]]),
               "this": args.fmu, "against": args.against, "commit": commit(ROOT),
               "processor": machine.processor(), "cells": cells}
        args.json.write_text(json.dumps(out, indent=2) + "\n")
        print(f"drive_cycle_cost: wrote {args.json}")


def errors(cells):
    """Each map and fast cell's axle loss against the full level's at its cycle and start."""
    full = {(c["cycle"], c["start"]): c["axle_loss_J"] for c in cells
            if c["level"] == "full" and not c["sets"]}
    for c in cells:
        ref = full.get((c["cycle"], c["start"]))
        if c["level"] != "full" and ref and not c["sets"]:
            c["loss_error_vs_full"] = c["axle_loss_J"] / ref - 1.0


def shortened(cycle, until):
    keep = cycle.t <= until
    return cycles.Cycle(f"{cycle.name}_to_{until:g}s", cycle.t[keep], cycle.v[keep],
                        [p for p in cycle.phases if p[1] < until], cycle.source)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--cycles", nargs="+", default=["wltc3", "us06"])
    ap.add_argument("--starts", nargs="+", default=list(STARTS), choices=list(STARTS))
    ap.add_argument("--levels", nargs="+", default=list(REPEATS), choices=list(REPEATS))
    ap.add_argument("--repeats", nargs=3, type=int, metavar=("MAP", "FAST", "FULL"),
                    default=list(REPEATS.values()), help="runs per cell of each level (3 3 3)")
    ap.add_argument("--until", type=float, help="stop each cycle at this time [s]")
    ap.add_argument("--step", type=float, default=0.05)
    ap.add_argument("--fmu", default=str(ROOT / "build" / "HypoidGearPair.fmu"))
    ap.add_argument("--vehicle-fmu", default=str(ROOT / "build" / "LongitudinalVehicle.fmu"))
    ap.add_argument("--json", type=pathlib.Path,
                    help="where the data go (default: the record's, or none with --against)")
    ap.add_argument("--against", metavar="FMU",
                    help="another build of the gear FMU to compare --fmu with in this run")
    ap.add_argument("--heavy-input", action=argparse.BooleanOptionalAction, default=True,
                    help=f"the first cycle's cold 20 start with {HEAVY_INPUT} (map, fast)")
    args = ap.parse_args()
    repeats = dict(zip(REPEATS, args.repeats))
    if args.against:
        if not pathlib.Path(args.against).is_file():
            ap.error(f"--against {args.against}: no such FMU")
        return against(args, repeats)
    args.json = args.json or DATA
    began, load0, t0 = datetime.datetime.now(datetime.timezone.utc), os.getloadavg(), time.time()
    cells = []
    for k, name in enumerate(args.cycles):
        cycle = cycles.load_cycle(name)
        cycle = shortened(cycle, args.until) if args.until else cycle
        cells += [cell(cycle, level, start, repeats[level], args)
                  for start in args.starts for level in args.levels]
        if k == 0 and args.heavy_input:
            cells += [cell(cycle, level, "cold 20", repeats[level], args, HEAVY_INPUT)
                      for level in ("map", "fast") if level in args.levels]
    errors(cells)
    out = {"command": "python " + " ".join(["bench/drive_cycle_cost.py", *sys.argv[1:]]),
           "commit": commit(ROOT), "recorded": began.date().isoformat(),
           "cycles": {c: float(cycles.load_cycle(c).t[-1] - cycles.load_cycle(c).t[0])
                      for c in args.cycles} if not args.until else {},
           "until_s": args.until, "step_s": args.step, "repeats": repeats,
           "machine": {"cpus": os.cpu_count(), "processor": machine.processor(),
                       "niceness": os.nice(0),
                       "load_average_before": list(load0),
                       "load_average_after": list(os.getloadavg()),
                       "shared": "2 cores shared with other jobs"},
           "wall_total_s": time.time() - t0, "cells": cells}
    args.json.write_text(json.dumps(out, indent=2) + "\n")
    if args.json == DATA:
        (FOLDER / RECORDS["drive-cycle-cost"].page).write_text(RECORDS["drive-cycle-cost"].write())
    print(f"drive_cycle_cost: wrote {args.json} ({out['wall_total_s'] / 60:.1f} min)")


if __name__ == "__main__":
    main()
