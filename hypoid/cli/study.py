"""`hypoid study`: the paper's studies (Paouris et al. 2016, Figs. 5-11) on the FMU: steady-state
grids, continuation sweeps through the resonances, tables, plots and a report in --out.

    hypoid study default --out results     # a few minutes on 2 cores (./run.sh runs this)
    hypoid study full --out results-full   # the paper-size grid plus sensitivity runs
    hypoid study ci --out /tmp/ci          # a seconds-long smoke version

Options: --scheduler ADDRESS (a dask.distributed scheduler; default a pool of --workers local
processes, 2), --fmu PATH. A re-run into the same --out resumes.
"""

import json
import pathlib
import time

from hypoid.cli import args as cliargs
from hypoid.paths import user_path
from hypoid.study.paper import SPECS, run, write_report


def main(argv):
    ap = cliargs.Parser("hypoid study", __doc__)
    ap.add_argument("name", choices=sorted(SPECS), nargs="?", default="default")
    ap.add_argument("--out", type=user_path, default=user_path("results"))
    ap.add_fmu()
    ap.add_argument("--scheduler", help="dask.distributed scheduler address")
    ap.add_argument("--workers", type=int, default=2, help="local worker processes; 0 = serial")
    ap.add_argument("--no-report", action="store_true", help="tables only, no plots or report")
    args = ap.parse_args(argv)
    fmu = cliargs.fmu_path(args.fmu)
    pts, cont, info = run(args.name, args.out, fmu, args.scheduler, args.workers)
    out = pathlib.Path(args.out)
    cpu = float(pts["cpu_s"].sum()) + (float(cont["cpu_s"].sum()) if len(cont) else 0.0)
    info["cpu_s_total"] = cpu
    (out / "study.json").write_text(json.dumps(info, indent=2) + "\n")
    if not args.no_report:
        t0 = time.time()
        path = write_report(out, pts, cont, info, args.workers)
        info["report_s"] = time.time() - t0
        (out / "study.json").write_text(json.dumps(info, indent=2) + "\n")
        print(f"hypoid study: report {path}")
    bad = int((pts["status"] != "ok").sum()) + (int((cont["status"] != "ok").sum())
                                                if len(cont) else 0)
    print(f"hypoid study {args.name}: {len(pts)} points, {len(cont)} continuation rows, "
          f"{info['wall_s']:.0f} s wall, {cpu:.0f} s CPU, {bad} failed -> {out}")
    return 1 if bad else 0
