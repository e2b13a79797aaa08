#!/usr/bin/env python3
"""Model Exchange against co-simulation in the five work-precision scenes (bench/wp_driver.py):
the gear FMU integrated by fmpy's CVode (BDF, rtol 1e-6 and atol = rtol x the FMU's nominals:
the tolerances simulate_fmu sets) against the same FMU in co-simulation at its defaults
(solver = auto, rtol 1e-6), both against a co-simulation reference at CVODE BDF rtol 1e-10.

    python bench/me_vs_cs.py [--scenes design,resonance,...] [--json OUT]

Per scene: eta_cycle at the end, the mean pinion speed and the DTE peak to peak over the scene's
window (sampled at 64 per mesh cycle), and the largest difference of w_p at any sample; the
reversal scene's torque step reaches Model Exchange as an input event (fmpy's input signals).
About two minutes."""

import argparse
import json
import sys
import time

import numpy as np
from fmpy import simulate_fmu

from hypoid.fmu.values import TABLE
from wp_driver import FINE_PER_CYCLE, scenes

FMU = "build/HypoidGearPair.fmu"
NAMES = ["w_p", "DTE", "eta_cycle", "n_impacts"]
REFERENCE = dict(solver="cvode_bdf", rtol=1e-10, atol=1e-14)


def inputs(scene):
    """The scene's input events as fmpy input signals (None without events)."""
    if not scene.events:
        return None
    names = sorted({n for _, values in scene.events for n in values})
    rows = [(0.0, *[scene.start[n] for n in names])]
    for t, values in scene.events:
        last = rows[-1][1:]
        rows.append((t, *last))
        rows.append((t, *[values.get(n, x) for n, x in zip(names, last)]))
    return np.array(rows, dtype=[("time", float)] + [(n, float) for n in names])


def run(scene, fmi_type, extra=None):
    start = {k: v for k, v in scene.start.items()
             if not (scene.events and k in scene.events[0][1])}
    start = {var.name: value for var, value in TABLE.fmu_values({**start, **(extra or {})})}
    dt = 1.0 / (FINE_PER_CYCLE * scene.f_mesh)
    kw = dict(start_values=start, output=NAMES, stop_time=scene.t_end, output_interval=dt,
              input=inputs(scene), fmi_type=fmi_type)
    if fmi_type == "ModelExchange":
        kw.update(relative_tolerance=1e-6, record_events=False)
    wall = time.perf_counter()
    r = simulate_fmu(FMU, **kw)
    return r, time.perf_counter() - wall


def metrics(scene, r):
    a, b = scene.window
    sel = (r["time"] >= a - 1e-12) & (r["time"] <= b + 1e-12)
    return dict(eta_cycle=float(r["eta_cycle"][-1]), w_mean=float(np.mean(r["w_p"][sel])),
                dte_pp=float(np.ptp(r["DTE"][sel])), impacts=int(r["n_impacts"][-1]))


def compare(scene):
    ref, _ = run(scene, "CoSimulation", REFERENCE)
    out = {"title": scene.title, "reference": metrics(scene, ref)}
    for label, fmi_type in (("co-simulation", "CoSimulation"), ("model exchange",
                                                                 "ModelExchange")):
        r, wall = run(scene, fmi_type)
        n = min(len(r), len(ref))
        m = metrics(scene, r)
        out[label] = dict(m, wall=wall, w_p_max_err=float(np.max(np.abs(
            r["w_p"][:n] - ref["w_p"][:n]))),
            err={k: m[k] - out["reference"][k] for k in ("eta_cycle", "w_mean", "dte_pp")})
    cs, me = out["co-simulation"], out["model exchange"]
    out["me_minus_cs"] = {k: me[k] - cs[k] for k in ("eta_cycle", "w_mean", "dte_pp")}
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--scenes", default="design,off_resonance,resonance,reversal,cold")
    ap.add_argument("--json")
    args = ap.parse_args()
    all_scenes = scenes()
    results = {}
    print("| scene | eta_cycle ME - CS | w_mean ME - CS [rad/s] | DTE p-p ME - CS [um] | "
          "max abs w_p err vs ref CS / ME [rad/s] | eta_cycle err vs ref CS / ME | "
          "wall CS / ME [s] |")
    print("|---|---|---|---|---|---|---|")
    for key in args.scenes.split(","):
        res = results[key] = compare(all_scenes[key])
        cs, me, d = res["co-simulation"], res["model exchange"], res["me_minus_cs"]
        print(f"| {key} | {d['eta_cycle']:.1e} | {d['w_mean']:.1e} | {1e6 * d['dte_pp']:.1e} | "
              f"{cs['w_p_max_err']:.1e} / {me['w_p_max_err']:.1e} | "
              f"{cs['err']['eta_cycle']:.1e} / {me['err']['eta_cycle']:.1e} | "
              f"{cs['wall']:.1f} / {me['wall']:.1f} |", flush=True)
    if args.json:
        with open(args.json, "w") as f:
            json.dump(results, f, indent=1)
    return 0


if __name__ == "__main__":
    sys.exit(main())
