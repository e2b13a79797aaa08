"""`hypoid effmap`: efficiency maps of the full model for the FMU's map level
(`mesh_model = rigid`, `friction_model = map`), format `hypoid-effmap 2` (docs/data-files.md).

    hypoid effmap --out my_map.txt --gear-set-file my_set.txt --lubricant-file my_oil.txt
    hypoid effmap --out my_map.txt --gear-set 2 --set k_f=0.15 --speeds-rpm 500:5000:500
    hypoid effmap --all --out-dir resources/maps            (the built-in maps, ~50 min)

Each point runs the full model (varying mesh, ehl_thermal friction unless --set says otherwise)
at a held pinion speed, a pinion torque and a bath temperature, in drive (T_s > 0) and coast
(T_s < 0, the wheel drives), lets the transient settle, and measures the conjunctional
efficiency over a window of mesh cycles from the FMU's energy audit:
eta = 1 - dE_friction / dE_input.

A map records what it was made from: content hashes of the gear-set and lubricant files, the
model version and the settings. The FMU refuses a map whose gear set or lubricant differs from
the ones it runs with, and names both. Use the map with
    efficiency_map_file=my_map.txt mesh_model=rigid friction_model=map
and the same gear_set / gear_set_file and lubricant / lubricant_file it was made for.
"""

import os
import pathlib

from hypoid.cli import args as cliargs
from hypoid.fmu.values import TABLE
from hypoid.maps.effmap import (BANDED, LUBRICANTS, QUICK_GRID, SET_BY_THE_MAP, TEMPERATURES_C,
                                TORQUES, write_map)
from hypoid.paths import data_file, user_path


def _parser():
    ap = cliargs.Parser("hypoid effmap", __doc__)
    ap.add_fmu()
    ap.add_argument("--out", type=user_path, help="the map file to write")
    ap.add_argument("--gear-set", type=int, help="built-in gear set 1-3 (default 1)")
    ap.add_argument("--gear-set-file", help="a gear-set data file of your own")
    ap.add_argument("--lubricant", type=int, help="built-in lubricant 1-2 (default 1)")
    ap.add_argument("--lubricant-file", help="a lubricant data file of your own")
    ap.add_set()
    ap.add_argument("--speeds-rpm", help="pinion speeds, a:b:step or v1,v2,... (default: "
                                         "banded through the gear set's mesh resonances, "
                                         "hypoid/maps/speedgrid.py)")
    ap.add_argument("--torques", help=f"pinion torques [N.m] (default "
                                      f"{','.join(map(str, TORQUES))})")
    ap.add_argument("--temperatures-c", help=f"bath temperatures [°C] (default "
                                             f"{','.join(map(str, TEMPERATURES_C))})")
    ap.add_argument("--quick", action="store_true", help="a 3 x 3 x 2 grid, for tests")
    ap.add_argument("--all", action="store_true", help="the built-in maps of gear sets 1-3 x "
                                                       "lubricants 1-2 into --out-dir")
    ap.add_argument("--out-dir", type=user_path, default=user_path("resources/maps"),
                    help="with --all (default: ./resources/maps)")
    ap.add_argument("--workers", type=int, default=os.cpu_count() or 1,
                    help="worker processes (0: in this process)")
    return ap


def axis(option, text, default, minimum):
    """A grid axis from its option's text (a:b:step or v1,v2,...), or the default."""
    if text is None:
        return list(default)
    values = cliargs.numbers(option, text)
    if len(values) < 2 or values != sorted(set(values)) or values[0] < minimum:
        raise cliargs.UsageError(f"{option}={text}: give at least two ascending values >= "
                                 f"{minimum:g}")
    return values


def map_params(args):
    """The full-model parameters of one map from --gear-set*, --lubricant* and --set."""
    params = cliargs.parse_set(args.set)
    for option, name, value in (("--gear-set", "gear_set", args.gear_set),
                                ("--gear-set-file", "gear_set_file", args.gear_set_file),
                                ("--lubricant", "lubricant", args.lubricant),
                                ("--lubricant-file", "lubricant_file", args.lubricant_file)):
        if value is not None:
            params[name] = TABLE.parse(name, value)
    fixed = [k for k in params if k in SET_BY_THE_MAP]
    if fixed:
        raise cliargs.UsageError(f"--set {', '.join(fixed)}: the map sets speed, torque, bath "
                                 "temperature and load mode itself (use the grid options)")
    if params.get("friction_model") == "map" or params.get("mesh_model") == "rigid":
        raise cliargs.UsageError("a map is made from the full model: friction_model = map and "
                                 "mesh_model = rigid are what it is for, not what it is made of")
    for name in ("gear_set_file", "lubricant_file"):
        if params.get(name):
            params[name] = data_file(params[name])
    return params


def main(argv):
    args = _parser().parse_args(argv)
    fmu = cliargs.fmu_path(args.fmu)
    grid = QUICK_GRID if args.quick else (
        BANDED if args.speeds_rpm is None else axis("--speeds-rpm", args.speeds_rpm, None, 0.0),
        axis("--torques", args.torques, TORQUES, 0.0),
        axis("--temperatures-c", args.temperatures_c, TEMPERATURES_C, -273.15))
    if args.all:
        out_dir = pathlib.Path(args.out_dir)
        out_dir.mkdir(parents=True, exist_ok=True)
        jobs = [(out_dir / f"gearset{g}_{LUBRICANTS[lub]}.txt", {"gear_set": g, "lubricant": lub})
                for g in (1, 2, 3) for lub in (1, 2)]
        command = "hypoid effmap --all --out-dir resources/maps"
    elif args.out:
        jobs = [(pathlib.Path(args.out), map_params(args))]
        command = "hypoid effmap " + " ".join(argv)
    else:
        raise cliargs.UsageError("give --out FILE (one map) or --all (the built-in maps)")
    for out, params in jobs:
        n = write_map(fmu, out, params, args.workers, grid, command)
        print(f"hypoid effmap: wrote {out} ({n} points)")
    return 0
