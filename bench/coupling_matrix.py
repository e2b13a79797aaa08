#!/usr/bin/env python3
"""The coupling matrix: the gear FMU and the vehicle FMU in each coupling, master and
communication step, in each scene, against a fine reference (docs/integration.md).

    python bench/coupling_matrix.py [--couplings half_shaft torque] [--masters jacobi ...]
        [--steps 1e-4 5e-4 1e-3 2e-3 5e-3 1e-2] [--scenes cruise tip launch downhill]
        [--hosts fmpy ecos libcosim] [--gear build/HypoidGearPair.fmu]
        [--vehicle build/LongitudinalVehicle.fmu] [--json OUT] [--label " (before)"]
        [--gear-values friction_table=false]
    python bench/coupling_matrix.py --record OUT1.json [OUT2.json ...]   # the record's data

Hosts: fmpy (tests/cosim/coupling_master.py's masters, every master) and, for the Jacobi master,
Ecos and libcosim (their fixed-step algorithms: coupling_master.run_ecos, run_libcosim, with the
integer-coded gear FMU the build writes next to --gear), where their libraries load.

Per cell: stable (mesh-force spread within 1.5x the reference's in the scene's flat windows),
that spread over the reference's, w_p's largest error over max |w_p| of the reference, the energy
residual over the input work, CPU seconds. The reference: the half-shaft coupling under a
Gauss-Seidel master at 0.05 ms (the same physics in both couplings: gear, half-shaft, vehicle),
with the driver's torque T_s held over each step h as the cells at h hold it (the error is the
coupling's, not the sampling of the driver's input).
Targets (Jacobi, every step, cruise and tip): spread <= 1.5x, |energy| <= 1e-3, w_p <= 1e-3, the
1 ms run no dearer than the 0.5 ms one. --record merges --json files into the record's data,
docs/records/coupling-matrix.json (`hypoid records coupling-matrix` writes its page). The full
matrix costs about 15 min of CPU per coupling."""

import argparse
import dataclasses
import json
import math
import pathlib
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "cosim"))
sys.path.insert(0, str(ROOT))

import coupling_master as cm  # noqa: E402
from hypoid.cosim import ecos, libcosim  # noqa: E402
from hypoid.cosim.host import intenum_fmu  # noqa: E402

# host: (its run, why it does not load here); the outside hosts run the Jacobi master only
HOSTS = {"fmpy": None,
         "ecos": (cm.run_ecos, ecos.why_unavailable),
         "libcosim": (cm.run_libcosim, libcosim.why_unavailable)}

STEPS = [1e-4, 5e-4, 1e-3, 2e-3, 5e-3, 1e-2]
H_REF = 5e-5


def reference(scene, gear, vehicle, h):
    """The reference of the cells at step h: the half-shaft coupling, Gauss-Seidel at H_REF, the
    driver's torque held over each h as in those cells."""
    return cm.run(scene, "half_shaft", "gauss-seidel", H_REF, gear, vehicle, hold=h)


def cell_text(m):
    if m["failed"]:
        return "failed"
    mark = "" if m["stable"] else " **limit cycle**"
    return (f"{m['std_ratio']:.2f}{mark} / {m['w_p_err']:.1e} ({m['w_p_rms']:.0e}) / "
            f"{m['energy']:+.1e} / {m['cpu']:.2f} s")


def record(rows, steps, scenes, provenance):
    """The record's data ({"provenance", "sections"}, hypoid.records.pages.tables_page): per
    scene a table of coupling x master x host rows, one column per step."""
    blocks = [{"text": "Each cell: the mesh-force spread over the reference's in the scene's flat "
               "windows (above 1.5: a limit cycle, in bold) / the largest w_p error over max "
               "|w_p| (in brackets its RMS over w_p's) / the energy residual over the input work "
               "/ the run's CPU. \"failed\": the gear stopped with fmi2Error (in Ecos: an FMU "
               "refused a connected input, which Ecos itself passes over). Reference: the "
               "half-shaft "
               f"coupling under Gauss-Seidel at {H_REF * 1e3:g} ms with the driver's torque held "
               "over each step of the column. Every input held over the step (no input "
               "derivatives). Hosts: fmpy's FMU2Slave under the masters of "
               "tests/cosim/coupling_master.py; Ecos (ecospy) and libcosim (libcosimpy), their "
               "fixed-step algorithms (Jacobi), with the integer-coded gear FMU; libcosim "
               "initialises inside its first step, so its cells are measured from t = h. "
               "`torque`: the connection before the half-shaft coupling (the gear's torque load "
               "mode against the vehicle's half-shaft coupling 1). `half_shaft (friction_table "
               "off)`: the half-shaft coupling with the gear's friction solved at every "
               "evaluation (friction_table = false) in the reference and the cells alike: the "
               "coupling's own error, without the friction tables' keys, which move at the "
               "steps' starts, and so at other instants at each step."}]
    for scene in scenes:
        keys = sorted({(r["coupling"], r["master"], r["host"]) for r in rows
                       if r["scene"] == scene},
                      key=lambda k: (not k[0].startswith("half_shaft"), k[0],
                                     cm.MASTERS.index(k[1]), list(HOSTS).index(k[2])))
        table = []
        for key in keys:
            cells = []
            for h in steps:
                m = [r for r in rows if r["scene"] == scene and abs(r["h"] - h) < 1e-12
                     and (r["coupling"], r["master"], r["host"]) == key]
                cells.append(cell_text(m[0]).replace("**limit cycle**", "**(limit cycle)**")
                             if m else "—")
            table.append(list(key) + cells)
        blocks += [{"heading": cm.SCENES[scene].title, "level": 2},
                   {"table": {"columns": ["coupling", "master", "host"]
                              + [f"{h * 1e3:g} ms" for h in steps], "rows": table}}]
    return {"provenance": provenance, "sections": blocks}


def _value(arg):
    """NAME=VALUE as (name, value): true / false as booleans, numbers as floats."""
    name, text = arg.split("=", 1)
    low = text.strip().lower()
    if low in ("true", "false"):
        return name, low == "true"
    try:
        return name, float(text)
    except ValueError:
        return name, text


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--couplings", nargs="+", default=["half_shaft", "torque"])
    ap.add_argument("--masters", nargs="+", default=list(cm.MASTERS))
    ap.add_argument("--steps", type=float, nargs="+", default=STEPS)
    ap.add_argument("--scenes", nargs="+", default=list(cm.SCENES))
    ap.add_argument("--hosts", nargs="+", default=list(HOSTS), choices=list(HOSTS),
                    help="the outside hosts run the Jacobi master, where they load")
    ap.add_argument("--gear", default=str(ROOT / "build" / "HypoidGearPair.fmu"))
    ap.add_argument("--vehicle", default=str(ROOT / "build" / "LongitudinalVehicle.fmu"))
    ap.add_argument("--reference-gear", help="the FMUs of the reference (default: --gear)")
    ap.add_argument("--reference-vehicle")
    ap.add_argument("--json", help="write the cells' measures")
    ap.add_argument("--label", default="", help="appended to the coupling's name in the cells")
    ap.add_argument("--gear-values", nargs="+", default=[], metavar="NAME=VALUE",
                    help="the gear's start values in the references and the cells alike "
                         "(true / false, numbers, else text)")
    ap.add_argument("--record", nargs="+", metavar="JSON",
                    help="write docs/records/coupling-matrix.json from these --json files "
                    "(no runs); then `hypoid records coupling-matrix` writes the page")
    args = ap.parse_args()
    for s in args.scenes:
        if s not in cm.SCENES:
            print(f"coupling_matrix: unknown scene {s} (have {', '.join(cm.SCENES)})",
                  file=sys.stderr)
            return 2
    if args.record:
        rows = [r for f in args.record for r in json.loads(pathlib.Path(f).read_text())]
        steps = sorted({r["h"] for r in rows})
        scenes = [s for s in cm.SCENES if any(r["scene"] == s for r in rows)]
        commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT,
                                capture_output=True, text=True).stdout.strip() or "?"
        data = record(rows, steps, scenes, f"*Measured on {commit}, "
                      f"{time.strftime('%Y-%m-%d')}, with `python bench/coupling_matrix.py`.*")
        out = ROOT / "docs" / "records" / "coupling-matrix.json"
        out.write_text(json.dumps(data, indent=1, ensure_ascii=False) + "\n")
        return 0
    try:
        gear_values = dict(_value(a) for a in args.gear_values)
    except ValueError:
        print(f"coupling_matrix: --gear-values takes NAME=VALUE, not {args.gear_values}",
              file=sys.stderr)
        return 2
    hosts = []
    for host in args.hosts:
        why = HOSTS[host] and HOSTS[host][1]()
        if why:
            print(f"coupling_matrix: {host} is not usable here ({why}): left out", file=sys.stderr)
        else:
            hosts.append(host)
    gear_intenum = intenum_fmu(args.gear, "libcosim and Ecos") if set(hosts) - {"fmpy"} else None
    rows = []
    for name in args.scenes:
        scene = cm.SCENES[name]
        scene = dataclasses.replace(scene, gear={**scene.gear, **gear_values})
        refs = {}
        for h in args.steps:
            refs[h] = reference(scene, args.reference_gear or args.gear,
                                args.reference_vehicle or args.vehicle, h)
            assert not refs[h].failed, refs[h].failed
        for coupling in args.couplings:
            for master in args.masters:
                for h in args.steps:
                    ref = refs[h]
                    for host in hosts:
                        if host != "fmpy" and master != "jacobi":
                            continue
                        try:
                            r = (cm.run(scene, coupling, master, h, args.gear, args.vehicle)
                                 if host == "fmpy" else
                                 HOSTS[host][0](scene, coupling, h, gear_intenum, args.vehicle))
                        except Exception as e:  # a master the FMUs cannot run (no FMU states)
                            rows.append({"scene": name, "coupling": coupling + args.label,
                                         "master": master,
                                         "host": host, "h": h, "failed": str(e)[:120],
                                         "stable": False})
                            print(name, coupling, master, host, h, "cannot run:", str(e)[:80],
                                  flush=True)
                            continue
                        m = cm.measures(r, ref, scene)
                        m["host"] = host
                        m["coupling"] += args.label
                        rows.append(m)
                        print(name, coupling, master, host, f"{h * 1e3:g} ms", cell_text(m),
                              flush=True)
    if args.json:
        pathlib.Path(args.json).write_text(json.dumps(rows, indent=1, default=str))
    return 0


if __name__ == "__main__":
    sys.exit(main())
