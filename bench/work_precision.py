#!/usr/bin/env python3
"""Work-precision benchmark of the HypoidGearPair FMU: every fidelity level x solver x tolerance
against a tight reference of the full model, in five scenes: the record docs/records/work-precision
(every run in a CSV table, the references and diagnoses in JSON, log-log work-precision plots;
hypoid.records.work_precision writes the page: recommendations, where the performance targets
stand).

    .venv/bin/python bench/work_precision.py            # everything (about 15-25 min on 1 core)
    .venv/bin/python bench/work_precision.py --quick    # fewer settings, 1 timed run (~3 min)
    .venv/bin/python bench/work_precision.py --replot   # plots and page from the record's data only

Timing: CPU time (time.process_time) of the fmi2DoStep calls only, with 0.05 s communication
steps, median of >= 3 runs after a warm-up (the finely sampled run of the same setting).
"""

import argparse
import csv
import json
import os
import pathlib
import platform
import sys
import time

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import wp_driver as W  # noqa: E402

from hypoid import data  # noqa: E402
from hypoid.records import machine  # noqa: E402
from hypoid.records.registry import FOLDER, RECORDS  # noqa: E402
from hypoid.records.work_precision import LEVEL_TITLES, read_csv  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]

FULL_SETTINGS = ([W.DEFAULT]
                 + [W.Setting(s, 10.0 ** -k) for s in ("bdf", "adams", "erk") for k in range(3, 9)]
                 + [W.Setting("newmark", n) for n in (10, 20, 50, 100, 200)])
# the mean mesh has no mesh-frequency dynamics of its own: also try it without the automatic
# max_step of 1/30 mesh period (the rigid levels have no automatic max_step)
FREE_SETTINGS = {"mean": [W.Setting(s, 10.0 ** -k) for s in ("bdf_free", "adams_free")
                          for k in range(3, 7)]}
QUICK_FREE = {"mean": [W.Setting("bdf_free", 1e-3), W.Setting("adams_free", 1e-5)]}
QUICK_SETTINGS = ([W.DEFAULT] + [W.Setting("bdf", r) for r in (1e-3, 1e-5, 1e-7)]
                  + [W.Setting("adams", r) for r in (1e-4, 1e-6)]
                  + [W.Setting("erk", r) for r in (1e-4, 1e-6)]
                  + [W.Setting("newmark", n) for n in (20, 100)])

METRICS = {  # key: (column of the error, title, unit factor, unit, floor for the log plots)
    "eta_E": ("err_eta_E", "energy efficiency over the window |d eta| [%-points]", 100.0,
              "%-points", 1e-8),
    "dte_pp": ("err_dte_pp", "DTE peak to peak |d| [µm]", 1e6, "µm", 1e-5),
    "loss": ("err_loss", "contact-loss fraction |d| [-]", 1.0, "", 1e-5),
    "w_mean": ("err_w_rel", "mean input speed, relative |d| [-]", 1.0, "", 1e-12),
}
COLORS = {"full": "black", "smoothed": "tab:blue", "isothermal": "tab:orange", "mean": "tab:green",
          "rigid": "tab:red", "map": "tab:purple"}
STYLES = {"default": ("none", "*"), "bdf": ("-", "o"), "adams": ("--", "s"),
          "erk": ("-", "P"), "newmark": (":", "^"),
          "bdf_free": ("-.", "D"), "adams_free": ("-.", "v")}

CSV_COLUMNS = ["scene", "level", "solver", "value", "label", "status", "cpu_per_s", "rtf",
               "err_eta_E", "err_eta_cycle", "err_dte_pp", "err_loss", "err_w_rel",
               "eta_E", "eta_cycle", "dte_pp", "loss", "w_mean", "energy_residual",
               "solver_steps", "rhs_evals", "n_impacts", "runs", "cpu_spread", "message"]


def log(*a):
    print(*a, flush=True)


# ------------------------------------------------------------------ measurement


def map_source(fmu):
    """The efficiency map: built into the FMU, else the repository's resources/maps file."""
    name = "maps/gearset1_OS265962.txt"
    if os.path.exists(os.path.join(fmu.dir, "resources", name)):
        return "built into the FMU"
    local = data.resource(name)  # the package's built-in data (the checkout's resources/)
    if local.is_file():
        fmu.map_file = str(local)
        return f"resources/{name} (efficiency_map_file; not yet in the FMU)"
    return None


def errors(row, ref):
    if row["status"] != "ok":
        return row
    row["err_eta_E"] = abs(row["eta_E"] - ref["eta_E"])
    row["err_eta_cycle"] = abs(row["eta_cycle"] - ref["eta_cycle"])
    row["err_dte_pp"] = abs(row["dte_pp"] - ref["dte_pp"])
    row["err_loss"] = abs(row["loss"] - ref["loss"])
    row["err_w_rel"] = abs(row["w_mean"] - ref["w_mean"]) / abs(ref["w_mean"])
    row["rtf"] = 1.0 / row["cpu_per_s"]
    return row


def pick_resonance(fmu):
    """The resonance scene's speed (wp_driver.RESONANCE_RPM) if its reference shows contact loss,
    else the nearby speed with the most (the mode-3 resonance of the default tooth data)."""
    rpm0 = W.RESONANCE_RPM
    sc = W.scenes()["resonance"]
    ref = W.measure(fmu, sc, "full", W.REFERENCE, repeats=1, min_total_cpu=0)
    note = f"{rpm0:.0f} rpm reference: contact lost {100 * ref.get('loss', 0):.1f} % of the window"
    if ref["status"] == "ok" and ref["loss"] > 0.01:
        return rpm0, note + " (kept)"
    best = (ref.get("loss", 0.0), rpm0)
    for rpm in (rpm0 + d for d in (-100, -50, -25, 25, 50, 100)):
        r = W.measure(fmu, W.scenes(rpm)["resonance"], "full", W.Setting("bdf", 1e-8), repeats=1,
                      min_total_cpu=0)
        if r["status"] == "ok":
            best = max(best, (r["loss"], float(rpm)))
    return best[1], note + f"; the most contact loss nearby is at {best[1]:.0f} rpm (used)"


SWEEP_COMMS = (1e-3, 1e-2, 0.1, 1.0)
SWEEP_SETTINGS = [("full", W.DEFAULT), ("full", W.Setting("bdf", 1e-6)),
                  ("full", W.Setting("newmark", 10)), ("mean", W.DEFAULT), ("rigid", W.DEFAULT),
                  ("map", W.DEFAULT), ("map", W.Setting("bdf", 1e-3))]

DIAG_CASES = [
    ("varying, frictionless", dict(mesh_model="varying", friction_model="none")),
    ("varying, frictionless, e_0 = 0", dict(mesh_model="varying", friction_model="none",
                                            e_0_scale=0.0)),
    ("varying, coulomb", dict(mesh_model="varying", friction_model="coulomb",
                              backlash_model="exact")),
    ("varying, ehl_isothermal", dict(mesh_model="varying", friction_model="ehl_isothermal",
                                     backlash_model="exact")),
    ("varying, ehl_thermal (full)", dict(mesh_model="varying", friction_model="ehl_thermal",
                                         backlash_model="exact")),
    ("mean, frictionless", dict(mesh_model="mean", friction_model="none")),
    ("mean, ehl_thermal", dict(mesh_model="mean", friction_model="ehl_thermal")),
    ("rigid, ehl_thermal", dict(mesh_model="rigid", friction_model="ehl_thermal")),
    ("rigid, map", dict(mesh_model="rigid", friction_model="map")),
]


def step_diagnosis(fmu, scene):
    """What sets the step count: CVODE BDF steps per mesh cycle with max_step free (1 s) at a
    loose and a default tolerance, for the model's ingredients one by one (design scene)."""
    out = []
    for name, lv in DIAG_CASES:
        W.LEVELS["_diag"] = lv
        row = dict(case=name)
        for rtol in (1e-3, 1e-6):
            values = W.start_values(fmu, scene, "_diag", W.Setting("bdf", rtol))
            values["max_step"] = 1.0
            inst = W.instance(fmu)
            try:
                inst.start(values)
                c0 = time.process_time()
                for k in range(int(round(scene.t_end / W.COMM))):
                    inst.slave.doStep(k * W.COMM, W.COMM)
                cpu = time.process_time() - c0
                steps, evals = inst.ints(["solver_steps", "rhs_evals"])
                cycles = scene.f_mesh * scene.t_end
                row[f"{rtol:.0e}"] = dict(steps_per_cycle=steps / cycles,
                                          rhs_per_cycle=evals / cycles, rtf=scene.t_end / cpu,
                                          us_per_rhs=1e6 * cpu / max(evals, 1))
            except W.FMICallException:
                row[f"{rtol:.0e}"] = dict(failed=W.error_text(inst)[:200])
            finally:
                inst.close()
        out.append(row)
    W.LEVELS.pop("_diag", None)
    return out


def agreement(ref, conf, scene):
    """Reference (BDF) against its confirmation (Adams) at the same tolerance."""
    out = {k: abs(ref[k] - conf[k]) for k in ("eta_E", "eta_cycle", "dte_pp", "loss")}
    out["w_rel"] = abs(ref["w_mean"] - conf["w_mean"]) / abs(ref["w_mean"])
    ts, x1, _ = ref["trace"]
    _, x2, _ = conf["trace"]
    a, b = scene.window
    sel = (ts > a) & (ts <= b)
    out["dte_max_abs_diff"] = float(np.max(np.abs(x1[sel] - x2[sel])))
    return out


def run_all(args):
    t_start = time.time()
    fmu = W.Fmu(args.fmu)
    meta = dict(fmu=str(args.fmu), fmu_mtime=time.ctime(os.path.getmtime(args.fmu)),
                host=platform.node(), python=platform.python_version(),
                cpu=machine.processor(), quick=args.quick,
                started=time.ctime())
    settings = QUICK_SETTINGS if args.quick else FULL_SETTINGS
    repeats = 1 if args.quick else 3
    min_cpu = 0.05 if args.quick else 0.3
    levels = [lv for lv in W.LEVELS if not args.levels or lv in args.levels]
    meta["map"] = map_source(fmu)
    if meta["map"] is None:
        log("no efficiency map (resources/maps/gearset1_OS265962.txt): the map level is skipped")
        levels = [lv for lv in levels if lv != "map"]
    meta["resonance_rpm"], meta["resonance_note"] = pick_resonance(fmu)
    log(meta["resonance_note"])
    all_scenes = W.scenes(meta["resonance_rpm"])
    keys = [k for k in all_scenes if not args.scenes or k in args.scenes]
    rows, refs, model_err, agree = [], {}, {}, {}
    for key in keys:
        sc = all_scenes[key]
        t0 = time.time()
        ref = W.measure(fmu, sc, "full", W.REFERENCE, repeats=repeats, min_total_cpu=min_cpu,
                        keep_trace=True)
        conf = W.measure(fmu, sc, "full", W.CONFIRM, repeats=1, min_total_cpu=0, keep_trace=True)
        if ref["status"] != "ok" or conf["status"] != "ok":
            raise SystemExit(f"{key}: the reference failed: {ref['message']} {conf['message']}")
        agree[key] = agreement(ref, conf, sc)
        ref.pop("trace"), conf.pop("trace")
        refs[key] = ref
        shown = ("eta_E", "eta_cycle", "dte_pp", "loss", "w_mean", "n_impacts")
        log(f"[{key}] reference {json.dumps({k: ref[k] for k in shown})}")
        log(f"[{key}] BDF vs Adams at rtol 1e-10: {json.dumps(agree[key])}")
        for lv in levels:
            own = ref if lv == "full" else W.measure(fmu, sc, lv, W.REFERENCE, repeats=1,
                                                     min_total_cpu=0)
            if own["status"] == "ok":
                model_err[(key, lv)] = errors(dict(own), ref)
            extra_settings = (QUICK_FREE if args.quick else FREE_SETTINGS).get(lv, [])
            for st in settings + extra_settings:
                r = errors(W.measure(fmu, sc, lv, st, repeats=repeats, min_total_cpu=min_cpu), ref)
                rows.append(r)
                if r["status"] != "ok":
                    log(f"[{key}] {lv:10s} {st.label:22s} FAILED: {r['message'][:200]}")
                else:
                    log(f"[{key}] {lv:10s} {st.label:22s} RTF {r['rtf']:8.1f}  "
                        f"d_eta {100 * r['err_eta_E']:.2e} %  d_dte {1e6 * r['err_dte_pp']:.2e} µm  "
                        f"d_loss {r['err_loss']:.3f}  d_w {r['err_w_rel']:.1e}")
        log(f"[{key}] done in {time.time() - t0:.0f} s")
    for key, ref in refs.items():
        rows.append(errors(dict(ref, label="reference bdf rtol 1e-10"), ref))
    if "design" in keys:
        log("step-count diagnosis ...")
        extra_diag = step_diagnosis(fmu, all_scenes["design"])
    else:
        extra_diag = []
    log("communication-step sweep ...")
    sweep = []
    if "design" in keys:
        for lv, st in SWEEP_SETTINGS:
            if lv not in levels:
                continue
            for comm in SWEEP_COMMS:
                try:
                    sweep.append(W.steady_rtf(fmu, all_scenes["design"], lv, st, comm,
                                              repeats=1 if args.quick else 3))
                except W.RunError as e:
                    log(f"sweep {lv} {st.label} {comm}: {e}")
    log("memory ...")
    meta["memory"] = W.memory_per_instance(fmu, 200)
    meta["step_overhead_s"] = W.step_overhead(fmu)
    meta["finished"] = time.ctime()
    meta["runtime_min"] = (time.time() - t_start) / 60.0
    extra = dict(meta=meta, agreement=agree, diagnosis=extra_diag, sweep=sweep,
                 model_error={f"{k}|{lv}": v for (k, lv), v in model_err.items()},
                 references=refs, scenes={k: dict(title=all_scenes[k].title,
                                                  window=all_scenes[k].window,
                                                  t_end=all_scenes[k].t_end) for k in keys})
    fmu.close()
    return rows, extra


# ------------------------------------------------------------------ outputs


def write_csv(rows, path):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=CSV_COLUMNS, extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow({k: r.get(k, "") for k in CSV_COLUMNS})


def jsonable(o):
    if isinstance(o, dict):
        return {str(k): jsonable(v) for k, v in o.items()}
    if isinstance(o, (list, tuple)):
        return [jsonable(v) for v in o]
    if isinstance(o, (np.floating, np.integer)):
        return o.item()
    return o


def plot(rows, extra, key, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, 2, figsize=(13, 10.5))
    for ax, (metric, (col, title, factor, unit, floor)) in zip(axes.flat, METRICS.items()):
        for lv in W.LEVELS:
            for solver, (ls, mk) in STYLES.items():
                sel = [r for r in rows if r["scene"] == key and r["level"] == lv
                       and r["solver"] == solver and r["status"] == "ok"
                       and not r["label"].startswith("reference")]
                # along the setting: loosest first (rtol falling, steps per cycle rising)
                sel.sort(key=lambda r: r["value"] if solver == "newmark" else -r["value"])
                if sel:
                    x = [r["cpu_per_s"] for r in sel]
                    y = [max(r[col] * factor, floor) for r in sel]
                    ax.loglog(x, y, ls=ls, marker=mk, color=COLORS[lv], ms=4, lw=1,
                              label=f"{lv} / {solver}")
        ax.set_title(title, fontsize=10)
        ax.set_xlabel("CPU time per simulated second [s]   (real-time factor = 1 / x)")
        ax.grid(True, which="both", alpha=0.3)
        if metric == "eta_E":
            ax.axhline(1e-2, color="grey", lw=0.8)
            ax.text(ax.get_xlim()[0], 1.1e-2, " 0.01 %", fontsize=8, color="grey")
        if metric == "dte_pp":
            ax.axhline(0.1, color="grey", lw=0.8)
        ax.axvline(1.0, color="grey", lw=0.8)
    handles, labels = axes.flat[0].get_legend_handles_labels()
    fig.legend(handles, labels, fontsize=8, ncol=6, loc="lower center")
    fig.suptitle(extra["scenes"][key]["title"] + "\nerror against the full model at BDF rtol "
                 "1e-10 (points below the floor are drawn on it; lines follow the setting from "
                 "the loosest)", fontsize=11)
    fig.tight_layout(rect=(0, 0.07, 1, 1))
    fig.savefig(path, dpi=90)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--fmu", default=str(ROOT / "build" / "HypoidGearPair.fmu"))
    ap.add_argument("--quick", action="store_true", help="fewer settings, one timed run each")
    ap.add_argument("--replot", action="store_true",
                    help="the plots and the page again from the record's csv and json")
    ap.add_argument("--scenes", nargs="*", help="subset of scenes")
    ap.add_argument("--levels", nargs="*", help="subset of levels")
    ap.add_argument("--out", default=str(FOLDER), help="output directory (docs/records/)")
    args = ap.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    csv_path, json_path = out / "work-precision.csv", out / "work-precision.json"
    t0 = time.time()
    if args.replot:
        rows = read_csv(csv_path)
        extra = json.loads(json_path.read_text())
    else:
        rows, extra = run_all(args)
        extra["csv"] = str(csv_path)
        write_csv(rows, csv_path)
        json_path.write_text(json.dumps(jsonable(extra), indent=1))
        rows = read_csv(csv_path)
    plots = {}
    for k in extra["references"]:
        p = out / f"work-precision-{k}.png"
        plot(rows, extra, k, p)
        plots[k] = p
    (out / "work-precision.md").write_text(RECORDS["work-precision"].write(out))
    log(f"wrote {out / 'work-precision.md'}, {csv_path.name}, {json_path.name} and "
        f"{len(plots)} plots in {time.time() - t0:.0f} s")


if __name__ == "__main__":
    main()
