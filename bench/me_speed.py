#!/usr/bin/env python3
"""The gear and the vehicle FMU as one Model Exchange system through tests/cosim's launch,
tip-out and tip-in (2.5 s): in the C host on the project's solver layer (build/bench_me, no
Python in the loop) at the full and the map level, CVODE BDF at rtol 1e-6 and 1e-5 and ARKODE's
explicit pair at 1e-6, also with the process's table store already holding the friction tables
(--keep-store 1: the runs after the first); and
through fmpy's CVode from Python (hypoid.cosim.exchange.GearVehicleExchange, output every 10 ms),
what a Python user gets. Medians of --runs runs. Writes the record docs/records/me-speed (its
data and page).

    .venv/bin/python bench/me_speed.py          # about 2 min
"""

import argparse
import datetime
import json
import pathlib
import re
import statistics
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "tests" / "cosim"))

import cosim_driver as cd  # noqa: E402

from hypoid.cosim.exchange import GearVehicleExchange  # noqa: E402
from hypoid.fmu.instance import unzipped  # noqa: E402
from hypoid.records.docblocks import commit  # noqa: E402
from hypoid.records.registry import FOLDER, RECORDS  # noqa: E402

MAP = {"mesh_model": "rigid", "friction_model": "map"}
METHODS = {"bdf": "CVODE BDF", "erk": "ARKODE ERK"}
LINE = re.compile(r": ([\d.]+)x real time; (\d+) steps, (\d+) right-hand sides .*?, (\d+) events; "
                  r"w_p = ([\d.]+)")


def c_host(args, level, method, rtol, keep):
    """(command, real-time factor, steps, right-hand sides, events, w_p at the end): the median
    run of bench_me;
    with keep, of the runs after the first (which solves the tables the others find)."""
    cmd = [args.bench, str(unzipped(args.gear)), str(unzipped(args.vehicle)), "--level", level,
           "--method", method, "--rtol", f"{rtol:g}", "--runs", str(args.runs + keep),
           "--keep-store", str(keep)]
    out = subprocess.run(["nice"] + cmd, capture_output=True, text=True, check=True).stdout
    runs = [tuple(float(x) for x in LINE.search(line).groups()) for line in out.splitlines()
            if LINE.search(line)][keep:]
    shown = ["build/bench_me", "GEAR_DIR", "VEHICLE_DIR"] + cmd[3:]
    return " ".join(shown), statistics.median(r[0] for r in runs), *runs[0][1:]


def python_host(args, level):
    """(CPU seconds, events, w_p at the end) of fmpy's CVode through hypoid.cosim.exchange,
    median run."""
    scene = cd.Scene(gear=MAP if level == "map" else {})
    cpu, events = [], 0
    for _ in range(args.runs):
        start = time.process_time()
        with GearVehicleExchange(args.gear, args.vehicle, scene.gear_start(),
                                 scene.vehicle_start(), scene.torque) as m:
            g, _ = m.run(scene.stop_time, 0.01, ["w_p"], ["v"])
            events, w_p = m.events, g["w_p"][-1]
        cpu.append(time.process_time() - start)
    return statistics.median(cpu), events, w_p


def record(args):
    rows, commands = [], []
    runs = {"full": (("bdf", 1e-6, 0), ("bdf", 1e-6, 1), ("bdf", 1e-5, 0), ("erk", 1e-6, 0),
                     ("erk", 1e-6, 1)),
            "map": (("bdf", 1e-6, 0), ("bdf", 1e-5, 0), ("erk", 1e-6, 0))}
    for level, settings in runs.items():
        tables = level == "full"  # the map level has none
        for method, rtol, keep in settings:
            cmd, rtf, steps, rhs, events, w_p = c_host(args, level, method, rtol, keep)
            commands.append(cmd)
            store = ("already holds them" if keep else "empty (the run solves them)") \
                if tables else "(none used)"
            rows.append([f"C host, {level}", METHODS[method], f"{rtol:g}", store, f"{rtf:.1f}",
                         f"{2.5 / rtf:.4f}", f"{steps:.0f}", f"{rhs:.0f}", f"{events:.0f}",
                         f"{w_p:.6f}"])
        cpu, events, w_p = python_host(args, level)
        rows.append([f"fmpy from Python, {level}", "CVODE BDF", "1e-06",
                     "empty (the run solves them)" if tables else "(none used)",
                     f"{2.5 / cpu:.1f}", f"{cpu:.4f}", "", "", f"{events}", f"{w_p:.6f}"])
    text = ("tests/cosim's scene (from 100 rpm, T_s ramped to 150 N·m in 0.3 s, a tip-out to "
            "−50 N·m at 1.2–1.3 s, a tip-in at 1.8–1.9 s, 2.5 s) with the gear (`load_mode = "
            "torque`) and the vehicle FMU (half-shaft coupling), both in Model Exchange and "
            "integrated as one ODE of 31 states, atol = rtol × nominals, root finding on the gear's "
            "event indicators and an event iteration at every root and step event: by CVODE BDF "
            "with a dense Newton iteration and difference-quotient Jacobians, or ARKODE's "
            "explicit embedded Runge-Kutta pair ARK4(3)6L[2]SA (`--method erk`). The C host: "
            f"`{commands[0]}` and its variants; it stops at the torque profile's breakpoints "
            "and interpolates the other outputs (every 10 ms). The full level's friction tables "
            "come from node tables that the first instance of a process solves and the "
            "process's table store keeps while an instance lives: `--keep-store 1` keeps one "
            "more gear instance through the runs, and the row gives the runs after the first. "
            "fmpy's CVode: `hypoid.cosim.exchange.GearVehicleExchange` (its right-hand side in "
            "Python around the FMUs' calls, output every 10 ms). Real-time factor = 2.5 s over "
            f"the CPU seconds of the integration (start-up excluded), medians of {args.runs} "
            "runs; the machine shared.")
    return {"provenance": f"Measured on {commit(ROOT)}, {datetime.date.today().isoformat()}.",
            "sections": [{"text": text}, {"table": {
                "columns": ["host, level", "integrator", "rtol", "friction tables in the store",
                            "real-time factor", "CPU [s]", "steps", "right-hand sides",
                            "events", "w_p at 2.5 s [rad/s]"], "rows": rows}}]}


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--bench", default=str(ROOT / "build" / "bench_me"))
    p.add_argument("--gear", default=str(cd.GEAR_FMU))
    p.add_argument("--vehicle", default=str(cd.VEHICLE_FMU))
    p.add_argument("--runs", type=int, default=5)
    args = p.parse_args()
    (FOLDER / "me-speed.json").write_text(
        json.dumps(record(args), indent=1, ensure_ascii=False) + "\n")
    (FOLDER / "me-speed.md").write_text(RECORDS["me-speed"].write())
    return 0


if __name__ == "__main__":
    sys.exit(main())
