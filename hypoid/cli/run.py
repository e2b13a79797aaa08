"""`hypoid run`: simulate one scenario of the FMU and write its time series, per-mesh-cycle
figures, a summary and plots into a folder named after the run.

    hypoid run --set T_s=200 speed_rpm=3000 friction_model=ehl_isothermal [--stop-time 0.5]
    hypoid run --name my-case --out results --set lubricant_file=my_oil.txt

The folder is <out>/<name>, the name from --name or from the values set ("defaults" without
any); an existing folder is never overwritten: the run goes to <name>-2, <name>-3, ... (or give
--overwrite). Files: timeseries.csv (every output sample), cycles.csv (mean, minimum and maximum
of each mesh cycle), summary.json (steady-state figures over the second half), timeseries.png
(the whole run as mesh-cycle envelopes and means) and zoom.png (the last few mesh cycles
sample by sample). The output interval defaults to 1/16 of the mesh period at the start speed.
Paths (--out, --fmu, data files in --set) are relative to the folder you stand in.
"""

import json
import sys

from hypoid.cli import args as cliargs
from hypoid.fmu.instance import Instance
from hypoid.paths import user_path
from hypoid.study.scenario import (SAMPLES_PER_CYCLE, cycle_table, fresh_folder, half_backlash,
                                   mesh_cycles, plot_run, plot_zoom, run_name, simulate,
                                   summarise, write_tables)


def _parser():
    ap = cliargs.Parser("hypoid run", __doc__)
    ap.add_fmu()
    ap.add_argument("--out", type=user_path, default=user_path("results"),
                    help="parent folder of the run's folder (default: ./results)")
    ap.add_argument("--name", help="the run's folder name (default: from the values set)")
    ap.add_argument("--overwrite", action="store_true", help="reuse <out>/<name> if it exists")
    ap.add_argument("--stop-time", type=float, default=0.5, help="s simulated (0.5)")
    ap.add_argument("--output-interval", type=float,
                    help=f"s between samples (default: mesh period / {SAMPLES_PER_CYCLE})")
    ap.add_set()
    return ap


def main(argv):
    args = _parser().parse_args(argv)
    params = cliargs.parse_set(args.set)
    if args.stop_time <= 0 or (args.output_interval is not None and args.output_interval <= 0):
        raise cliargs.UsageError("--stop-time and --output-interval must be positive")
    with Instance(cliargs.fmu_path(args.fmu), name="run") as inst:
        r, h, cpu = simulate(inst, params, args.stop_time, args.output_interval)
        b, n_p = half_backlash(inst), inst.pinion_teeth()
        warnings = [text for _, category, text in inst.messages if category == "logStatusWarning"]
    for text in warnings:  # ignored or implausible values: the run went on, the user is told
        print(f"hypoid run: FMU warning: {text}", file=sys.stderr)
    name = run_name(params, args.name)
    folder = fresh_folder(args.out, name, args.overwrite)
    cycle = mesh_cycles(r, n_p)
    cycles = cycle_table(r, cycle)
    summary = summarise(r, cpu, args.stop_time, params, b)
    summary["fmu_warnings"] = warnings
    write_tables(r, cycles, folder)
    (folder / "summary.json").write_text(json.dumps(summary, indent=2) + "\n")
    title = f"hypoid run {name}" + (f" ({folder.name})" if folder.name != name else "")
    plot_run(r, cycles, b, folder, title)
    plot_zoom(r, cycle, b, folder, title)
    print(json.dumps(summary, indent=2))
    print(f"hypoid run: wrote {folder}/ (timeseries.csv, cycles.csv, summary.json, "
          "timeseries.png, zoom.png)")
    return 0
