#!/usr/bin/env python3
"""The rigid level's speed sweep: its real-time factor and solver steps per mesh cycle from 500
to 6000 rpm against the full level's, both in one run of the C host (build/bench_fmu, no Python
in the loop) per speed, 100 N·m, 40 °C, 1 ms communication steps, six outputs read per step,
medians of --runs batches. Prints the table and writes the record docs/records/rigid-speed (its
data and page); --vs DIR adds the rows of another unzipped FMU (e.g. the build before a change)
to the printed table, measured in the same runs, and writes no record.

    .venv/bin/python bench/rigid_speed.py             # about 1 min
"""

import datetime
import json
import math
import pathlib
import shlex
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "bench"))

from level_table import bench_parser  # noqa: E402

from hypoid.fmu.instance import unzipped  # noqa: E402
from hypoid.records.docblocks import commit  # noqa: E402
from hypoid.records.registry import FOLDER, RECORDS  # noqa: E402

SPEEDS_RPM = (500, 1000, 2000, 4000, 6000)
LEVELS = ("rigid", "full")
COLUMNS = ["speed [rpm]", "rigid: × real time", "full: × real time", "rigid / full",
           "solver steps per mesh cycle rigid / full", "µs CPU per mesh cycle rigid / full"]


def bench(args, rpm):
    """{(level, variant): (real-time factor, steps, µs CPU per mesh cycle)} of one bench_fmu run
    at rpm, and its command line."""
    w = repr(rpm * math.pi / 30.0)
    cmd = [args.bench, str(unzipped(args.fmu)), "levels", "--levels", ",".join(LEVELS),
           "--runs", str(args.runs), "--cpu", str(args.cpu), "--set", f"w_set={w}",
           "--set", f"w_p0={w}"] + (["--vs", args.vs] if args.vs else [])
    out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
    fig = {}
    for line in out.splitlines():
        cells = [x.strip() for x in line.strip().strip("|").split("|")]
        if len(cells) == 8 and cells[0] in LEVELS:
            fig[(cells[0], cells[1])] = (float(cells[2]), float(cells[5]), float(cells[7]))
    return shlex.join(["build/bench_fmu", "FMU_DIR"] + cmd[2:]), fig


def rows_of(rpm, fig, variant):
    r, f = fig[("rigid", variant)], fig[("full", variant)]
    return [str(rpm), f"{r[0]:.0f}", f"{f[0]:.1f}", f"{r[0] / f[0]:.1f}",
            f"{r[1]:.2f} / {f[1]:.1f}", f"{r[2]:.1f} / {f[2]:.1f}"]


def sweep(args):
    """The rows per variant ("this FMU", and "this FMU, --vs FMU" with --vs) and the commands."""
    rows, commands = {}, []
    for rpm in SPEEDS_RPM:
        cmd, fig = bench(args, rpm)
        commands.append(cmd)
        for variant in sorted({v for _, v in fig}):
            rows.setdefault(variant, []).append(rows_of(rpm, fig, variant))
    return rows, commands


def record(rows, commands, args):
    text = ("The rigid level (`mesh_model = rigid`, `solver = auto`: CVODE BDF, rtol 1e-6) and "
            "the full level at their defaults, 100 N·m, 40 °C, the speed governor holding each "
            "speed, both levels in one run of the C host per speed "
            f"(`{commands[0]}`, `w_set` and `w_p0` the speed in rad/s), medians of {args.runs} "
            "batches, 1 ms steps, six outputs read.")
    return {"provenance": f"Measured on {commit(ROOT)}, {datetime.date.today().isoformat()}.",
            "sections": [{"text": text}, {"table": {"columns": COLUMNS, "rows": rows}}]}


def main():
    ap = bench_parser(__doc__)
    ap.add_argument("--vs", help="another unzipped FMU measured alongside (printed only)")
    args = ap.parse_args()
    rows, commands = sweep(args)
    for variant, table in rows.items():
        print(f"{variant}:\n| " + " | ".join(COLUMNS) + " |")
        for r in table:
            print("| " + " | ".join(r) + " |")
    print("commands:\n" + "\n".join(commands))
    if not args.vs:
        (FOLDER / "rigid-speed.json").write_text(
            json.dumps(record(rows["this FMU"], commands, args), indent=1, ensure_ascii=False)
            + "\n")
        (FOLDER / "rigid-speed.md").write_text(RECORDS["rigid-speed"].write())
    return 0


if __name__ == "__main__":
    sys.exit(main())
