#!/usr/bin/env python3
"""Real-time factor of the FMU (simulated seconds per CPU second, median of N runs after a
warm-up) for a few scenes, plus the FMU size and the modal frequencies of the built-in sets.

    .venv/bin/python bench/realtime_factor.py [--fmu build/HypoidGearPair.fmu] [--runs 5]
"""

import argparse
import json
import math
import os
import statistics
import time

from fmpy import extract, read_model_description, simulate_fmu
from fmpy.fmi2 import FMU2Slave

RPM = math.pi / 30
SCENES = {
    "varying, 2000 rpm, 100 N.m (steady meshing)": {},
    "varying, 1200 rpm, 50 N.m, frictionless (contact loss)":
        {"T_s": 50.0, "w_set": 1200 * RPM, "w_p0": 1200 * RPM, "friction_model": 1},
    "mean mesh, 2000 rpm, 100 N.m": {"mesh_model": 1},
}


def cpu_of_run(fmu_dir, md, start_values, stop_time):
    t0 = time.process_time()
    simulate_fmu(fmu_dir, model_description=md, stop_time=stop_time, output_interval=1e-3,
                 start_values=start_values, output=["w_p"])
    return time.process_time() - t0


def modal_frequencies(fmu_dir, md):
    out = {}
    for k in (1, 2, 3):
        s = FMU2Slave(guid=md.guid, unzipDirectory=fmu_dir,
                      modelIdentifier=md.coSimulation.modelIdentifier, instanceName="modal")
        vr = {v.name: v.valueReference for v in md.modelVariables}
        s.instantiate()
        s.setupExperiment(startTime=0.0)
        s.setInteger([vr["gear_set"]], [k])
        s.enterInitializationMode()
        s.exitInitializationMode()
        names = ["f_2", "f_3", "f_4", "c_t1", "c_m", "c_t2", "k_m0", "R_p0"]
        out[f"gear set {k}"] = dict(zip(names, s.getReal([vr[n] for n in names])))
        s.terminate()
        s.freeInstance()
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--fmu", default="build/HypoidGearPair.fmu")
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--stop-time", type=float, default=0.5)
    args = ap.parse_args()
    fmu_dir = extract(args.fmu)
    md = read_model_description(args.fmu)
    report = {"fmu_bytes": os.path.getsize(args.fmu), "stop_time_s": args.stop_time,
              "runs": args.runs, "real_time_factor_median": {}}
    for name, values in SCENES.items():
        cpu_of_run(fmu_dir, md, values, 0.05)  # warm-up
        cpu = [cpu_of_run(fmu_dir, md, values, args.stop_time) for _ in range(args.runs)]
        report["real_time_factor_median"][name] = args.stop_time / statistics.median(cpu)
    report["modal"] = modal_frequencies(fmu_dir, md)
    print(json.dumps(report, indent=2))


if __name__ == "__main__":
    main()
