"""Efficiency maps of the full model for the FMU's map level (`mesh_model = rigid`,
`friction_model = map`), format `hypoid-effmap 2` (docs/data-files.md): the points, the map
file with its provenance (the data files' content hashes), and which built-in data a map fits.
The command is `hypoid effmap` (hypoid/cli/effmap.py)."""

import math
import os
import pathlib
import time

from hypoid.errors import UsageError
from hypoid.fmu import parallel
from hypoid.fmu.instance import Instance, unzipped
from hypoid.fmu.values import RPM, TABLE
from hypoid.fmu.variables import MODEL_VERSION
from hypoid.maps import speedgrid
from hypoid.tca.gearset_file import read_gearset

MAGIC = "hypoid-effmap 2"
# The speeds: by default banded per gear set through its mesh resonances (hypoid/maps/speedgrid.py,
# on the base speeds speedgrid.BASE_SPEEDS_RPM); a grid given as numbers is taken as it is.
BANDED = None
# The torques: a mesh resonance's speed rises with the load (the contact stiffens), by about a
# tenth of itself from 50 to 100 N.m and again to 200 N.m (speedgrid.mode_speeds), so the nodes at
# 75 and 150 N.m keep a ridge's shift from one torque node to the next within about its width.
TORQUES = [10, 25, 50, 75, 100, 150, 200, 300, 400]
# from a cold start in winter (the EU's -7 degC test, -20 and -30 degC) to a hot axle's sump
TEMPERATURES_C = [-30, -15, 0, 20, 40, 70, 100, 130, 150]
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

    ref = parallel.FmuRef(fmu)  # before the workers: they are forked with its bytes
    with parallel.executor(workers=workers) as client:
        parallel.run([(i, efficiency_point, p) for i, p in enumerate(points)], ref, store,
                     client, desc="map points")
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


BUILTIN_MAPS = pathlib.Path(__file__).resolve().parents[2] / "resources" / "maps"


def map_temperatures(path):
    """The bath temperatures [K] of a map file (its 'temperatures' line)."""
    for line in pathlib.Path(path).read_text().splitlines():
        if line.startswith("temperatures "):
            return [float(x) for x in line.split("#")[0].split()[1:]]
    raise ValueError(f"{path}: no 'temperatures' line")


def builtin_map_range():
    """(lowest, highest) bath temperature [K] that every built-in map covers, read from the
    shipped maps (so the map level follows the maps as they were made, not this grid)."""
    spans = [map_temperatures(p) for p in sorted(BUILTIN_MAPS.glob("gearset*_*.txt"))]
    return max(t[0] for t in spans), min(t[-1] for t in spans)


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
            raise UsageError(f"{key}: data file {name} not found")
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


def map_speeds(fmu, params, grid):
    """The grid with its speeds [rpm] made: as given, or banded through the gear set's mesh
    resonances (speedgrid); and the line the map's header says about them."""
    speeds, torques, temperatures_c = grid
    if speeds is not BANDED:
        return grid, "Speeds: as given."
    with Instance(str(fmu)) as inst:
        speeds, bands, step = speedgrid.speed_grid(inst, params,
                                                   source_files(fmu, params)["gear_set"], torques)
    return (speeds, torques, temperatures_c), speedgrid.describe(bands, step)


def write_map(fmu, out, params, workers, grid, command):
    t0 = time.time()
    keys = provenance_keys(fmu, params)  # before the long run: a missing file fails at once
    grid, speeds_text = map_speeds(fmu, params, grid)
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
        speeds_text,
        f"{len(etas)} points in {time.time() - t0:.0f} s.",
    ]
    name = "full-model map: " + (", ".join(f"{k}={pathlib.Path(str(v)).name}"
                                           for k, v in params.items()) or "defaults")
    pathlib.Path(out).write_text(format_map(name, grid, etas, provenance, keys))
    return len(etas)
