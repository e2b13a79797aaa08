"""`hypoid sweep`: a grid of steady-state operating points, or continuation sweeps, of the FMU,
run in parallel with resume; tidy tables (CSV, Parquet) and quick-look plots in --out.

    hypoid sweep --out results/my-sweep --set gear_set=2 --vary T_s=50,100 \\
                 --vary speed_rpm=1000:5000:250 [--continuation] [--scheduler tcp://host:8786]

`speed_rpm` is the pinion speed: it sets w_set and w_p0. Any FMU parameter or input can be set
or varied by name (enumerations by item name or number). A re-run into the same --out skips the
points already done; change --out (or delete it) after changing the settings.
"""

import pathlib
import sys
import time

from hypoid.cli import args as cliargs
from hypoid.fmu import parallel
from hypoid.fmu.instance import SPEED_KEY
from hypoid.paths import user_path
from hypoid.study import steady
from hypoid.study.sweep import complete, grid, run_points, run_sweeps


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
