"""`hypoid effmap`: efficiency maps of the full model for the FMU's map level
(`mesh_model = rigid`, `friction_model = map`), format `hypoid-effmap 1` (docs/data-files.md).

Each point runs the full model (varying mesh, ehl_thermal friction by default) at a held pinion
speed, a pinion torque and a bath temperature, in drive (T_s > 0) and coast (T_s < 0, the wheel
drives), lets the transient settle, and measures the conjunctional efficiency over a window of
mesh cycles from the FMU's energy audit: eta = 1 - dE_friction / dE_input.

    hypoid effmap --all --out-dir resources/maps            (the built-in maps)
    hypoid effmap --gear-set 2 --lubricant-file my.txt --out my_map.txt
"""

import math
import os
import pathlib
import time

from hypoid import cliargs, parallel
from hypoid.paths import user_path
from hypoid.values import RPM

SPEEDS_RPM = [100, 250, 500, 1000, 1500, 2000, 3000, 4000, 5000, 6000]
TORQUES = [10, 25, 50, 100, 200, 300, 400]
TEMPERATURES_C = [20, 40, 70, 100, 130]
# The elastic transient decays with 1/(zeta_2 omega_2) = 30 ms (docs/physics.md §8.6): 0.15 s settles it;
# the steady state repeats every 3 mesh cycles (the load-share period), so a window of a whole
# number of those periods gives the exact mean.
SETTLE_CYCLES, WINDOW_CYCLES, SETTLE_MIN_S = 12, 24, 0.15
LUBRICANTS = {1: "OS265962", 2: "OS265963"}
ENERGIES = ["E_in", "E_out", "E_friction"]


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
    """eta[direction][temperature][speed][torque] over the grid, in parallel (hypoid.parallel:
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


def format_map(name, speeds_rpm, torques, temperatures_c, etas, provenance):
    per_K = len(speeds_rpm) * len(torques)
    lines = [f"# {line}" for line in provenance]
    lines += ["hypoid-effmap 1", f"name {name}",
              "speeds " + " ".join(f"{n * RPM:.10g}" for n in speeds_rpm) + "   # rad/s (pinion)",
              "torques " + " ".join(f"{T:g}" for T in torques) + "   # N.m (pinion side)",
              "temperatures " + " ".join(f"{K + 273.15:.2f}" for K in temperatures_c) + "   # K"]
    for d, direction in enumerate(("drive", "coast")):
        for k in range(len(temperatures_c)):
            start = (d * len(temperatures_c) + k) * per_K
            block = etas[start:start + per_K]
            lines.append(f"# {direction} at {temperatures_c[k]} degC: rows of speed, columns of torque")
            lines.append(f"{direction}.{k + 1} " + " ".join(f"{e:.8f}" for e in block))
    return "\n".join(lines) + "\n"


def write_map(fmu, out, params, workers, grid):
    speeds, torques, temps = grid
    t0 = time.time()
    etas = compute_map(str(fmu), params, speeds, torques, temps, workers)
    bad = [e for e in etas if not 0.0 < e <= 1.0]
    if bad:
        raise RuntimeError(f"efficiencies outside (0, 1]: {bad[:5]}")
    name = ", ".join(f"{k}={v}" for k, v in params.items()) or "defaults"
    provenance = [
        "Efficiency map of the HypoidGearPair full model, written by `hypoid effmap`:",
        "regenerate with `hypoid effmap --all --out-dir resources/maps`, do not edit.",
        f"Full-model parameters: {name} (others at their defaults: varying mesh, ehl_thermal).",
        f"Each point: speed held by the governor, settle max({SETTLE_MIN_S} s, {SETTLE_CYCLES} "
        f"mesh cycles), then eta = 1 - dE_friction/dE_in over {WINDOW_CYCLES} mesh cycles",
        "(coast: T_s < 0, the wheel drives, eta = 1 - dE_friction/(-dE_out)).",
        "Coast uses the drive flank's contact data for the coast flank (no coast TCA data).",
        f"{len(etas)} points in {time.time() - t0:.0f} s.",
    ]
    text = format_map(f"full-model map: {name}", speeds, torques, temps, etas, provenance)
    pathlib.Path(out).write_text(text)
    return len(etas)


def main(argv):
    ap = cliargs.Parser("hypoid effmap", __doc__)
    ap.add_fmu()
    ap.add_argument("--all", action="store_true", help="built-in maps of gear sets 1-3 x lubricants")
    ap.add_argument("--out-dir", default="resources/maps")
    ap.add_argument("--out", help="one map file")
    ap.add_argument("--gear-set", type=int, default=1)
    ap.add_argument("--lubricant", type=int, default=1)
    ap.add_argument("--lubricant-file")
    ap.add_argument("--workers", type=int, default=os.cpu_count() or 1,
                    help="worker processes (0: in this process)")
    ap.add_argument("--quick", action="store_true", help="a 3 x 3 x 2 grid, for tests")
    args = ap.parse_args(argv)
    cliargs.fmu_path(args.fmu)
    grid = (SPEEDS_RPM, TORQUES, TEMPERATURES_C)
    if args.quick:
        grid = ([500, 2000, 4000], [50, 100, 200], [40, 100])
    jobs = []
    if args.all:
        out_dir = pathlib.Path(args.out_dir)
        out_dir.mkdir(parents=True, exist_ok=True)
        jobs = [(out_dir / f"gearset{g}_{LUBRICANTS[l]}.txt", {"gear_set": g, "lubricant": l})
                for g in (1, 2, 3) for l in (1, 2)]
    elif args.out:
        params = {"gear_set": args.gear_set, "lubricant": args.lubricant}
        if args.lubricant_file:
            params["lubricant_file"] = user_path(args.lubricant_file)
        jobs = [(pathlib.Path(args.out), params)]
    else:
        ap.error("give --all or --out FILE")
    for out, params in jobs:
        n = write_map(args.fmu, out, params, args.workers, grid)
        print(f"hypoid effmap: wrote {out} ({n} points)")
    return 0
