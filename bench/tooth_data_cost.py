#!/usr/bin/env python3
"""What the loaded tooth data cost the full model against the paper's one series: the C host
(build/bench_fmu, no Python in the loop) at five operating points, both tooth data in one run
(their batches interleaved, so that the machine's load affects them alike), 1 ms communication
steps, six outputs read per step, medians of --runs batches. Writes the record
docs/records/tooth-data-cost (its data and page).

    .venv/bin/python bench/tooth_data_cost.py          # about 2 min
"""

import datetime
import json
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

POINTS = {"2000 rpm, 100 N·m (defaults)": [],
          "1200 rpm, 50 N·m": ["T_s=50", "w_set=125.66", "w_p0=125.66"],
          "2000 rpm, 300 N·m": ["T_s=300"], "2000 rpm, −100 N·m (coast)": ["T_s=-100"],
          "2200 rpm, 100 N·m": ["w_set=230.38", "w_p0=230.38"]}
VARIANTS = ("one-series:tooth_data=paper", "loaded:tooth_data=loaded")


def bench(args, sets):
    """{variant: (real-time factor, steps, rhs, µs CPU per mesh cycle)} of one bench_fmu run."""
    cmd = [args.bench, str(unzipped(args.fmu)), "levels", "--levels", "full", "--runs",
           str(args.runs), "--cpu", str(args.cpu)]
    for v in VARIANTS:
        cmd += ["--variant", v]
    for s in sets:
        cmd += ["--set", s]
    out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
    fig = {}
    for line in out.splitlines():
        cells = [x.strip() for x in line.strip().strip("|").split("|")]
        if len(cells) == 8 and cells[0] == "full":
            fig[cells[1]] = (float(cells[2]), float(cells[5]), float(cells[6]), float(cells[7]))
    return shlex.join(["build/bench_fmu", "FMU_DIR"] + cmd[2:]), fig


def record(args):
    rows, commands = [], []
    for point, sets in POINTS.items():
        cmd, fig = bench(args, sets)
        commands.append(cmd)
        a, b = (fig[v.split(":")[0]] for v in VARIANTS)
        rows.append([point, f"{a[0]:.1f} / {b[0]:.1f}", f"{a[1]:.1f} / {b[1]:.1f}",
                     f"{a[2]:.0f} / {b[2]:.0f}", f"{a[3]:.1f} / {b[3]:.1f}"])
    text = ("The full model at its defaults with the one-series (`tooth_data = paper`) and the "
            "loaded tooth data (`tooth_data = loaded`), both in one run of the C host per point "
            f"(`{commands[0]}`, with `--set` for the other points), medians of {args.runs} "
            "interleaved batches, 1 ms steps, six outputs read.")
    return {"provenance": f"Measured on {commit(ROOT)}, {datetime.date.today().isoformat()}.",
            "sections": [{"text": text}, {"table": {
                "columns": ["point", "real-time factor one-series / loaded",
                            "solver steps per mesh cycle", "right-hand sides per mesh cycle",
                            "µs CPU per mesh cycle"], "rows": rows}}]}


def main():
    args = bench_parser(__doc__).parse_args()
    (FOLDER / "tooth-data-cost.json").write_text(
        json.dumps(record(args), indent=1, ensure_ascii=False) + "\n")
    (FOLDER / "tooth-data-cost.md").write_text(RECORDS["tooth-data-cost"].write())
    return 0


if __name__ == "__main__":
    sys.exit(main())
