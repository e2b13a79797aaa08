"""`hypoid effmap`: efficiency maps of the full model for the FMU's map level
(`mesh_model = rigid`, `friction_model = map`), format `hypoid-effmap 2` (docs/data-files.md).

    hypoid effmap --out my_map.txt --gear-set-file my_set.txt --lubricant-file my_oil.txt
    hypoid effmap --out my_map.txt --gear-set 2 --set k_f=0.15 --speeds-rpm 500:5000:500
    hypoid effmap --all --out-dir resources/maps            (the built-in maps, ~5 min)

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

import math
import os
import pathlib
import time

from hypoid.cli import args as cliargs
from hypoid.fmu import parallel
from hypoid.tca.gearset_file import read_gearset
from hypoid.fmu.instance import unzipped
from hypoid.paths import data_file, user_path
from hypoid.fmu.values import RPM, TABLE
from hypoid.fmu.variables import MODEL_VERSION

MAGIC = "hypoid-effmap 2"
SPEEDS_RPM = [100, 250, 500, 1000, 1500, 2000, 3000, 4000, 5000, 6000]
TORQUES = [10, 25, 50, 100, 200, 300, 400]
TEMPERATURES_C = [20, 40, 70, 100, 130]
QUICK_GRID = ([500, 2000, 4000], [50, 100, 200], [40, 100])
# The elastic transient decays with 1/(zeta_2 omega_2) = 30 ms (docs/physics.md): 0.15 s
# settles it; the steady state repeats every 3 mesh cycles (the load-share period), so a window
# of a whole number of those periods gives the exact mean.
SETTLE_CYCLES, WINDOW_CYCLES, SETTLE_MIN_S = 12, 24, 0.15
LUBRICANTS = {1: "OS265962", 2: "OS265963"}
ENERGIES = ["E_in", "E_out", "E_friction"]
SET_BY_THE_MAP = ("T_s", "T_w", "T_bath", "w_set", "w_p0", "load_mode", "speed_rpm")


# ---------------------------------------------------------------------------- the points
def efficiency_point(inst, params, speed, torque, T_bath, coast):
    """Steady conjunctional efficiency of one operating point (full model) on `inst`."""
    inst.start(dict(params, w_set=speed, w_p0=speed, T_s=-torque if coast else torque,
                    T_bath=T_bath, load_mode="speed"))
    mesh_period = 2 * math.pi / (inst.pinion_teeth() * speed)
    settle = max(SETTLE_MIN_S, SETTLE_CYCLES * mesh_period)
    inst.do_step(0.0, settle)
    before = inst.reals(ENERGIES)
    inst.do_step(settle, WINDOW_CYCLES * mesh_period)
    after = inst.reals(ENERGIES)
    d_in, d_out, d_fric = (a - b for a, b in zip(after, before))
    supplied = -d_out if coast else d_in
    return {"status": "ok", "eta": 1.0 - d_fric / supplied}


def compute_map(fmu, params, speeds_rpm, torques, temperatures_c, workers):
    """eta[direction][temperature][speed][torque] over the grid, in parallel (hypoid.fmu.parallel:
    one reused instance per worker, a progress bar)."""
    points = [(params, n * RPM, T, K + 273.15, d)
              for d in (False, True) for K in temperatures_c for n in speeds_rpm for T in torques]
    etas = [None] * len(points)

    def store(i, res):
        if res.get("status") != "ok":
            raise RuntimeError(f"map point {points[i][1:]}: {res.get('message')}")
        etas[i] = res["eta"]

    with parallel.executor(workers=workers) as client:
        parallel.run([(i, efficiency_point, p) for i, p in enumerate(points)],
                     parallel.FmuRef(fmu), store, client, desc="map points")
    return etas


# ---------------------------------------------------------------------------- provenance
def content_hash(path):
    """FNV-1a 64 of a data file's bytes with carriage returns left out (so a checkout with
    CRLF line ends hashes like one with LF), as 16 hex digits: the FMU computes the same."""
    h = 0xcbf29ce484222325
    for byte in pathlib.Path(path).read_bytes().replace(b"\r", b""):
        h = ((h ^ byte) * 0x100000001b3) & 0xFFFFFFFFFFFFFFFF
    return f"{h:016x}"


def paper_tooth_data(params):
    """True when the point runs the paper's calibrated one-series tooth data (tooth_data = paper
    or preset = paper), as the FMU decides it (fmu-src/model/setup.c)."""
    def chosen(name):
        return TABLE.canonical(name, params.get(name, TABLE.start(name))) == "paper"
    return chosen("preset") or chosen("tooth_data")


def builtin_gear_set(params):
    """The resources' gear-set file of the built-in gear_set for these parameters."""
    folder = "gearsets/" if paper_tooth_data(params) else "gearsets/loaded/"
    return f"{folder}gearset{params.get('gear_set', 1)}.txt"


def builtin_map_fits(params):
    """Whether the built-in maps (made at the defaults) are made for these parameters' data
    files: no gear-set or lubricant file of one's own, and the default tooth data."""
    own = {"gear_set_file", "lubricant_file"} & {k for k, v in params.items() if v}
    return not own and paper_tooth_data(params) == paper_tooth_data({})


def source_files(fmu, params):
    """{'gear_set': path, 'lubricant': path}: the data files the FMU reads for these
    parameters (its built-in resources, a user's file, or a name inside its resources)."""
    resources = unzipped(fmu) / "resources"
    gear = params.get("gear_set_file") or builtin_gear_set(params)
    lub = params.get("lubricant_file") or \
        f"lubricants/{LUBRICANTS[params.get('lubricant', 1)]}.txt"
    out = {}
    for key, name in (("gear_set", gear), ("lubricant", lub)):
        p = pathlib.Path(name)
        p = p if p.is_absolute() else resources / p
        if not p.is_file():
            raise cliargs.UsageError(f"{key}: data file {name} not found")
        out[key] = p
    return out


def provenance_keys(fmu, params):
    """The map's keys that say what it was made from (checked by the FMU: the two hashes)."""
    resources = unzipped(fmu) / "resources"
    lines = []
    for key, path in source_files(fmu, params).items():
        shown = path.relative_to(resources) if path.is_relative_to(resources) else path
        lines += [f"{key}_hash {content_hash(path)}", f"{key}_source {shown}"]
    lines.append(f"model_version {MODEL_VERSION}")
    return lines


def format_map(name, grid, etas, provenance, keys):
    speeds_rpm, torques, temperatures_c = grid
    per_K = len(speeds_rpm) * len(torques)
    lines = [f"# {line}" for line in provenance]
    lines += [MAGIC, f"name {name}", *keys,
              "speeds " + " ".join(f"{n * RPM:.10g}" for n in speeds_rpm) + "   # rad/s (pinion)",
              "torques " + " ".join(f"{T:g}" for T in torques) + "   # N.m (pinion side)",
              "temperatures " + " ".join(f"{K + 273.15:.2f}" for K in temperatures_c) + "   # K"]
    for d, direction in enumerate(("drive", "coast")):
        for k in range(len(temperatures_c)):
            start = (d * len(temperatures_c) + k) * per_K
            block = etas[start:start + per_K]
            lines.append(f"# {direction} at {temperatures_c[k]} °C: rows of speed, columns of "
                         "torque")
            lines.append(f"{direction}.{k + 1} " + " ".join(f"{e:.8f}" for e in block))
    return "\n".join(lines) + "\n"


def settings_text(params):
    made = ", ".join(f"{k}={v}" for k, v in params.items()) or "defaults"
    return (f"parameters {made} (others at their defaults: varying mesh, ehl_thermal); speed "
            f"held by the governor, settle max({SETTLE_MIN_S} s, {SETTLE_CYCLES} mesh cycles), "
            f"window {WINDOW_CYCLES} mesh cycles")


def coast_flank_text(gear_set_path):
    """What the coast rows run on: the file's coast flank, or the drive flank's data where the
    file has none (a one-series file: the FMU uses it for both flanks)."""
    if "coast" in read_gearset(gear_set_path).flanks:
        return "Coast runs on the gear-set file's coast-flank contact data."
    return "Coast uses the drive flank's contact data for the coast flank (no coast TCA data)."


def write_map(fmu, out, params, workers, grid, command):
    t0 = time.time()
    keys = provenance_keys(fmu, params)  # before the long run: a missing file fails at once
    etas = compute_map(str(fmu), params, *grid, workers)
    bad = [e for e in etas if not 0.0 < e <= 1.0]
    if bad:
        raise RuntimeError(f"efficiencies outside (0, 1]: {bad[:5]}")
    provenance = [
        "Efficiency map of the HypoidGearPair full model, written by `hypoid effmap`",
        f"({command}); regenerate it that way, do not edit.",
        f"Made with {settings_text(params)};",
        "eta = 1 - dE_friction/dE_in (coast: T_s < 0, the wheel drives, "
        "eta = 1 - dE_friction/(-dE_out)).",
        coast_flank_text(source_files(fmu, params)["gear_set"]),
        f"{len(etas)} points in {time.time() - t0:.0f} s.",
    ]
    name = "full-model map: " + (", ".join(f"{k}={pathlib.Path(str(v)).name}"
                                           for k, v in params.items()) or "defaults")
    pathlib.Path(out).write_text(format_map(name, grid, etas, provenance, keys))
    return len(etas)


# ---------------------------------------------------------------------------- CLI
def _parser():
    ap = cliargs.Parser("hypoid effmap", __doc__)
    ap.add_fmu()
    ap.add_argument("--out", type=user_path, help="the map file to write")
    ap.add_argument("--gear-set", type=int, help="built-in gear set 1-3 (default 1)")
    ap.add_argument("--gear-set-file", help="a gear-set data file of your own")
    ap.add_argument("--lubricant", type=int, help="built-in lubricant 1-2 (default 1)")
    ap.add_argument("--lubricant-file", help="a lubricant data file of your own")
    ap.add_set()
    ap.add_argument("--speeds-rpm", help=f"pinion speeds, a:b:step or v1,v2,... (default "
                                         f"{','.join(map(str, SPEEDS_RPM))})")
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
        axis("--speeds-rpm", args.speeds_rpm, SPEEDS_RPM, 0.0),
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
