#!/usr/bin/env python3
"""Real-time factor of the FMU (simulated seconds per CPU second, median of N runs after a
warm-up) for a few scenes, plus the FMU size and the modal frequencies of the built-in sets.

    .venv/bin/python bench/realtime_factor.py [--fmu build/HypoidGearPair.fmu] [--runs 5]
"""

import argparse
import json
import os
import statistics
import time

from hypoid.fmu.instance import Instance, unzipped

SCENES = {
    "varying, 2000 rpm, 100 N.m (steady meshing)": {},
    # the default (loaded) tooth data's mode 3: the teeth apart 25 % of the time (in contact at
    # 1200 rpm, the paper's one series' mode 2)
    "varying, 2300 rpm, 50 N.m, frictionless (contact loss)":
        {"T_s": 50.0, "speed_rpm": 2300, "friction_model": "none"},
    "mean mesh, 2000 rpm, 100 N.m": {"mesh_model": "mean"},
}
OUTPUT_INTERVAL = 1e-3  # s between the samples read (of w_p), as a host would


def cpu_of_run(inst, start_values, stop_time):
    t0 = time.process_time()
    inst.start(start_values)
    for k in range(int(round(stop_time / OUTPUT_INTERVAL))):
        inst.do_step(k * OUTPUT_INTERVAL, OUTPUT_INTERVAL)
        inst.reals(["w_p"])
    return time.process_time() - t0


def modal_frequencies(inst):
    names = ["f_2", "f_3", "f_4", "c_t1", "c_m", "c_t2", "k_m0", "R_p0"]
    return {f"gear set {k}": dict(zip(names, inst.start({"gear_set": k}).reals(names)))
            for k in (1, 2, 3)}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--fmu", default="build/HypoidGearPair.fmu")
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--stop-time", type=float, default=0.5)
    args = ap.parse_args()
    inst = Instance(unzipped(args.fmu), name="rtf")
    report = {"fmu_bytes": os.path.getsize(args.fmu), "stop_time_s": args.stop_time,
              "runs": args.runs, "real_time_factor_median": {}}
    for name, values in SCENES.items():
        cpu_of_run(inst, values, 0.05)  # warm-up
        cpu = [cpu_of_run(inst, values, args.stop_time) for _ in range(args.runs)]
        report["real_time_factor_median"][name] = args.stop_time / statistics.median(cpu)
    report["modal"] = modal_frequencies(inst)
    inst.close()
    print(json.dumps(report, indent=2))


if __name__ == "__main__":
    main()
