"""Drive a passenger car with the hypoid axle over a speed cycle and report what the axle costs:
the energy at the wheels, the axle's losses by part (mesh, churning, bearings, seals) and by
cycle phase, the mean axle efficiency and the oil temperature, from a cold start and from a warm
axle, with the difference.

The scene (docs/axle.md): the gear FMU (load_mode = torque, axle_losses = full, thermal_model =
sump) carries the vehicle's inertia at its wheel end (I_w += m r^2 + J_wheels) and the
half-shaft compliance (k_t2 = k_hs); the vehicle FMU (LongitudinalVehicle.fmu, coupling =
2) returns the road load and the brake torque at the wheel speed; a driver (a PI speed
controller with feed-forward of the cycle's acceleration) sets the propeller-shaft torque T_s
and the brakes. Both FMUs run in fmpy's co-simulation master (Jacobi, communication step
--step) or, with --master libcosim or ecos, in libcosim's or Ecos' fixed-step algorithm
(libcosimpy or ecospy, test extras; the build's integer-coded gear FMU). The car is the vehicle
FMU's by name: --set m=1800 CdA=0.68 (any of its parameters; the rest of --set goes to the gear
FMU, e.g. the driveline inertias I_s=0.08) or a
vehicle file (--vehicle my_car.toml: the vehicle's parameters, the driveline's inertias, the
engine's drag map for engine braking, the air pressure; hypoid/drivecycle/vehicle.py describes
it); the air density follows the air temperature (--t-amb) unless rho_air is given.

Cycles: wltc1, wltc2, wltc3a, wltc3 (= wltc3b) and nedc from the European Commission JRC's
`wltp` package (PyPI wltp 0.1.2a0, wltp/cycles/); udds, hwfet, us06 and ftp75 from the cycle
files of NREL's FASTSim package (PyPI fastsim 2.1.5, fastsim/resources/cycles/); or a CSV file
with the columns `time` (s, increasing) and `speed` (km/h), optionally `grade` (%, uphill
positive, within +-30 %) and `phase` (a name per row), separated by ',' or by ';' with decimal
commas. A progress bar runs on stderr when it is a terminal.

Examples:
  hypoid drive-cycle                              WLTC class 3, cold (20 degC) and warm (80 degC)
  hypoid drive-cycle --cycle nedc --no-warm
  hypoid drive-cycle --cycle my_route.csv --t-amb 5 --set gear_set=2
  hypoid drive-cycle --cycle ftp75 --vehicle my_car.toml --set m=1800 --t-amb -7
  hypoid drive-cycle --level full                 the paper's full model (slow: minutes)
  hypoid drive-cycle --set friction_preset=paper  friction data: runs the fast level (says so)

A --set parameter that the default level does not reach (friction data: not in the built-in
maps; the compliant mesh's: not in the rigid one) moves it to the cheapest level that it
reaches, and one line says so; with --level given, such a parameter is refused (exit 2).

Writes <out>/<name>/: summary.json, summary.md, cold.csv (and warm.csv), drive_cycle.png; the
folder appears only when the run is complete."""

import json
import os
import pathlib
import shutil
import tempfile

from hypoid import data
from hypoid.cli import args as cliargs
from hypoid.drivecycle import summary
from hypoid.drivecycle.cycles import load_cycle
from hypoid.drivecycle.levels import LEVELS, ZERO_C, choose_level
from hypoid.drivecycle.run import MASTERS, check_gear_set, simulate
from hypoid.drivecycle.vehicle import Vehicle, fmu_parameters, read_vehicle_file, split_set
from hypoid.paths import user_path


def _parser():
    ap = cliargs.Parser("hypoid drive-cycle", __doc__)
    ap.add_fmu()
    ap.add_argument("--vehicle-fmu", type=user_path, help=cliargs.FMU_HELP.format(
        what="vehicle FMU", env=data.FMUS["vehicle"][1], name=data.FMUS["vehicle"][0]))
    ap.add_argument("--cycle", default="wltc3",
                    help="wltc3 (default), wltc1, wltc2, wltc3a, nedc, udds, hwfet, us06, ftp75 "
                         "or a CSV file")
    ap.add_argument("--vehicle", type=user_path,
                    help="a vehicle file (TOML): the car, driveline inertias, engine drag map")
    ap.add_argument("--level", choices=sorted(LEVELS),
                    help="gear FMU fidelity: map (rigid mesh, the mesh friction from the "
                         "efficiency map; the default when the oil and the air are within the "
                         "built-in maps' range, from -30 degC), fast (the same with the friction "
                         "model itself, ~4x dearer; the default below it) or full (the paper's "
                         "model)")
    ap.add_argument("--step", type=float, default=0.05,
                    help="communication step of the co-simulation in s (0.05)")
    ap.add_argument("--t-amb", type=float, default=20.0, help="air temperature in degC (20)")
    ap.add_argument("--t-oil0", type=float, help="oil at the start in degC (default: --t-amb)")
    ap.add_argument("--warm", type=float, default=80.0,
                    help="oil at the start of the warm run in degC (80)")
    ap.add_argument("--no-warm", action="store_true", help="only the cold start")
    ap.add_argument("--master", choices=sorted(MASTERS), default="fmpy",
                    help="co-simulation master: fmpy (default), libcosim (libcosimpy) or ecos "
                         "(ecospy); the last two with the build's integer-coded gear FMU and "
                         "the inputs held over each step")
    ap.add_argument("--until", type=float,
                    help="stop after this many seconds of the cycle (default: the whole cycle)")
    ap.add_argument("--out", type=user_path, default=user_path("results"),
                    help="parent folder of the run's folder (default: ./results)")
    ap.add_argument("--name", help="the run's folder name (default: drive_cycle_<cycle>)")
    ap.add_set()
    return ap


def check_args(args):
    if not 1e-3 <= args.step <= 1.0:
        raise cliargs.UsageError(f"--step {args.step}: between 0.001 and 1 s")
    if args.until is not None and not args.until >= args.step:
        raise cliargs.UsageError(f"--until {args.until}: at least one step ({args.step} s)")
    for name in ("t_amb", "t_oil0", "warm"):
        value = getattr(args, name)
        if value is not None and not -70.0 <= value <= 170.0:
            raise cliargs.UsageError(f"--{name.replace('_', '-')} {value}: a temperature "
                                     "between -70 and 170 degC")


def main(argv):
    args = _parser().parse_args(argv)
    check_args(args)
    gear_fmu, vehicle_fmu, car, extra, cycle = _scene(args)
    _run_folder(args, cycle)  # refused before the runs, not after them
    T_amb = args.t_amb + ZERO_C
    starts = [("cold", (args.t_oil0 if args.t_oil0 is not None else args.t_amb) + ZERO_C)]
    if not args.no_warm:
        starts.append(("warm", args.warm + ZERO_C))
    level, note = choose_level(args.level, T_amb, [T0 for _, T0 in starts], extra)
    if note:
        print(f"hypoid drive-cycle: {note}", flush=True)
    runs = [simulate(cycle, gear_fmu, vehicle_fmu, level, T0, T_amb, args.step, extra,
                     label, vehicle=car, master=args.master, until=args.until)
            for label, T0 in starts]
    summaries = [summary.summarise(run, cycle, args.step) for run in runs]
    diff = summary.difference(summaries[0], summaries[1]) if len(summaries) == 2 else None
    meta = {"cycle": cycle.name, "source": cycle.source, "level": level, "level_note": note,
            "gear_fmu_settings": LEVELS[level], "step_s": args.step,
            "master": args.master, "until_s": args.until,
            "T_amb_degC": args.t_amb, "set": extra, "vehicle": runs[0].vehicle.record(),
            "driveline": runs[0].driveline, "vehicle_file": str(args.vehicle or "")}
    text = summary.markdown(meta, summaries, diff)
    final = _write(args, cycle, runs, text, {"meta": meta, "runs": summaries,
                                             "warm_minus_cold": diff})
    print(text, end="")
    print(f"hypoid drive-cycle: wrote {final}/ (summary.json, summary.md, "
          + ", ".join(f"{r.label}.csv" for r in runs) + ", drive_cycle.png)")
    return 0


def _scene(args):
    """(gear FMU, vehicle FMU, the car, the gear FMU's --set values, the cycle), checked."""
    gear_fmu = cliargs.fmu_path(args.fmu)
    vehicle_fmu = cliargs.fmu_path(args.vehicle_fmu, "vehicle")
    known = fmu_parameters(vehicle_fmu)
    car = read_vehicle_file(args.vehicle, known) if args.vehicle else Vehicle()
    car_set, gear_set = split_set(args.set, known)
    car.fmu.update(car_set)
    extra = cliargs.parse_set(gear_set)
    check_gear_set(extra)
    cycle = load_cycle(args.cycle)
    if args.master != "fmpy" and (cycle.grade is not None or car.fmu.get("grade", 0.0)):
        raise cliargs.UsageError(f"--master {args.master}: a grade needs the fmpy master (it adds "
                                 "the grade's load at the wheel); leave --master out")
    return gear_fmu, vehicle_fmu, car, extra, cycle


def _run_folder(args, cycle):
    """The run's folder <out>/<name>/, which must not exist yet."""
    final = pathlib.Path(args.out) / (args.name or f"drive_cycle_{cycle.name}")
    if final.exists():
        raise cliargs.UsageError(f"{final} exists: give another --name or remove it")
    return final


def _write(args, cycle, runs, text, data):
    """The run's folder, written whole in a temporary folder and then renamed."""
    final = _run_folder(args, cycle)
    final.parent.mkdir(parents=True, exist_ok=True)
    tmp = pathlib.Path(tempfile.mkdtemp(dir=final.parent, prefix=f".{final.name}."))
    try:
        (tmp / "summary.json").write_text(json.dumps(data, indent=2) + "\n")
        (tmp / "summary.md").write_text(text)
        for run in runs:
            summary.write_csv(run, tmp / f"{run.label}.csv")
        summary.plot(cycle, runs, tmp / "drive_cycle.png")
        os.replace(tmp, final)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return final
