"""Benchmark of `hypoid drive-cycle`: a cycle (default WLTC class 3b, cold start at 20 degC) at
the map level (the runner's default), the fast level and the full level (or --levels), their
wall and CPU times,
real-time factors and the axle's cycle energy loss and oil-temperature rise, and each level's
error against the full one.
Not a timed test: it writes the data of the record docs/records/drive-cycle
(drive-cycle-levels.json) and its page, and prints a table.

  .venv/bin/python bench/drive_cycle.py                    # WLTC 3b, three levels (full: slow)
  .venv/bin/python bench/drive_cycle.py --until 589 --json /tmp/x.json   # only its low phase
  .venv/bin/python bench/drive_cycle.py --summary DIR      # record `hypoid drive-cycle`'s DIR

--summary DIR records the output of `hypoid drive-cycle --level fast --out ... --name ...` (its
summary.json, cold and warm, and its figure) as the record's other part (drive-cycle.json,
docs/figures/drive_cycle_wltc3.png)."""

import argparse
import datetime
import json
import pathlib
import resource
import shutil
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from hypoid.drivecycle import cycles, levels, summary  # noqa: E402
from hypoid.drivecycle import run as runner  # noqa: E402
from hypoid.records.docblocks import commit  # noqa: E402
from hypoid.records.registry import FOLDER, RECORDS  # noqa: E402

LEVELS_DATA, RUNS_DATA = (FOLDER / name for name in RECORDS["drive-cycle"].data)


def record_summary(folder):
    """`hypoid drive-cycle`'s output folder as the record's runs (and its figure)."""
    data = json.loads((folder / "summary.json").read_text())
    meta = data["meta"]
    data.update(command=f"hypoid drive-cycle --cycle {meta['cycle']} --level {meta['level']}",
                commit=commit(ROOT), recorded=datetime.date.today().isoformat())
    RUNS_DATA.write_text(json.dumps(data, indent=2) + "\n")
    shutil.copyfile(folder / "drive_cycle.png", ROOT / "docs" / "figures" / "drive_cycle_wltc3.png")


def cpu_seconds():
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime


def run(cycle, level, args):
    wall, cpu = time.perf_counter(), cpu_seconds()
    r = runner.simulate(cycle, args.fmu, args.vehicle_fmu, level, args.t_oil0 + 273.15,
                            args.t_amb + 273.15, args.step, {}, level)
    wall, cpu = time.perf_counter() - wall, cpu_seconds() - cpu
    s = summary.summarise(r, cycle, args.step)
    span = cycle.t[-1] - cycle.t[0]
    return {"level": level, "settings": levels.LEVELS[level], "wall_s": wall, "cpu_s": cpu,
            "real_time_factor_wall": span / wall, "real_time_factor_cpu": span / cpu,
            "axle_loss_J": s["axle_loss_J"], "axle_losses_J": s["axle_losses_J"],
            "mean_axle_efficiency": s["mean_axle_efficiency"],
            "T_oil_rise_K": s["T_oil_degC"]["end"] - s["T_oil_degC"]["start"],
            "speed_tracking_rms_kmh": s["speed_tracking_rms_kmh"], "audit": s["audit"]}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--cycle", default="wltc3")
    ap.add_argument("--until", type=float, help="stop the cycle at this time [s]")
    ap.add_argument("--levels", nargs="+", default=["map", "fast", "full"])
    ap.add_argument("--step", type=float, default=0.05)
    ap.add_argument("--t-amb", type=float, default=20.0)
    ap.add_argument("--t-oil0", type=float, default=20.0)
    ap.add_argument("--fmu", default=str(ROOT / "build" / "HypoidGearPair.fmu"))
    ap.add_argument("--vehicle-fmu", default=str(ROOT / "build" / "LongitudinalVehicle.fmu"))
    ap.add_argument("--json", default=str(LEVELS_DATA), help="where the levels' results go")
    ap.add_argument("--summary", type=pathlib.Path, help="record this `hypoid drive-cycle` output")
    args = ap.parse_args()
    if args.summary:
        record_summary(args.summary)
        (FOLDER / "drive-cycle.md").write_text(RECORDS["drive-cycle"].write())
        return
    cycle = cycles.load_cycle(args.cycle)
    if args.until:
        keep = cycle.t <= args.until
        cycle = cycles.Cycle(f"{cycle.name}_to_{args.until:g}s", cycle.t[keep],
                                 cycle.v[keep], [p for p in cycle.phases if p[1] < args.until],
                                 cycle.source)
    results = [run(cycle, level, args) for level in args.levels]
    full = next((r for r in results if r["level"] == "full"), None)
    for r in results:
        if full and r is not full:
            r["loss_error_vs_full"] = r["axle_loss_J"] / full["axle_loss_J"] - 1.0
            r["T_oil_rise_error_K"] = r["T_oil_rise_K"] - full["T_oil_rise_K"]
    out = {"cycle": cycle.name, "duration_s": float(cycle.t[-1] - cycle.t[0]),
           "step_s": args.step, "T_amb_degC": args.t_amb, "T_oil0_degC": args.t_oil0,
           "machine": "2 cores shared with other jobs (wall time depends on the load; see cpu_s)",
           "results": results}
    pathlib.Path(args.json).write_text(json.dumps(out, indent=2) + "\n")
    if pathlib.Path(args.json) == LEVELS_DATA:
        (FOLDER / "drive-cycle.md").write_text(RECORDS["drive-cycle"].write())
    print(f"{cycle.name} ({out['duration_s']:.0f} s), cold start {args.t_oil0:g} degC")
    print(f"{'level':<6} {'wall s':>8} {'cpu s':>8} {'RTF(cpu)':>9} {'loss kJ':>9} "
          f"{'eta %':>7} {'dT_oil K':>9}")
    for r in results:
        print(f"{r['level']:<6} {r['wall_s']:8.1f} {r['cpu_s']:8.1f} "
              f"{r['real_time_factor_cpu']:9.1f} {r['axle_loss_J'] / 1e3:9.2f} "
              f"{100 * r['mean_axle_efficiency']:7.2f} {r['T_oil_rise_K']:9.2f}")
    for r in results:
        if "loss_error_vs_full" in r:
            print(f"{r['level']} vs full: loss {100 * r['loss_error_vs_full']:+.2f} %, "
                  f"oil rise {r['T_oil_rise_error_K']:+.2f} K")


if __name__ == "__main__":
    main()
