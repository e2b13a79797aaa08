#!/usr/bin/env python3
"""The record docs/records/paper-findings from a study's output: recorded into its data,
paper-findings.json (hypoid.records.paper_findings writes the page's generated blocks from it).

    .venv/bin/hypoid study default --out results               # the paper-findings study
    .venv/bin/python tools/paper_findings.py --study results   # record it, write the page
    .venv/bin/python tools/paper_findings.py --study results-full   # the full study's part
    .venv/bin/python tools/paper_findings.py --loaded DIR      # a sweep of the loaded tooth data

--study also copies the study's figures that the page shows into docs/figures/.
"""

import argparse
import datetime
import json
import math
import pathlib
import re
import shutil
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from hypoid.study import findings as fd  # noqa: E402
from hypoid.records import docblocks  # noqa: E402
from hypoid.records.paper_findings import NEAR_RPM  # noqa: E402
from hypoid.records.registry import FOLDER, RECORDS  # noqa: E402
from hypoid.study import modes  # noqa: E402

DATA = FOLDER / "paper-findings.json"
PAGE = FOLDER / "paper-findings.md"
FIGURES = ROOT / "docs" / "figures"

# ------------------------------------------------------------------ recording
def _finite(x):
    """NaN and infinities as None, for strict JSON."""
    if isinstance(x, dict):
        return {k: _finite(v) for k, v in x.items()}
    if isinstance(x, list):
        return [_finite(v) for v in x]
    if isinstance(x, float) and not math.isfinite(x):
        return None
    return x



def record(study):
    """The data file from a study directory (study.json, findings.csv, modal.csv,
    details.json of hypoid study)."""
    import pandas as pd

    info = json.loads((study / "study.json").read_text())
    find = pd.read_csv(study / "findings.csv").fillna("")
    modal = pd.read_csv(study / "modal.csv")
    det = json.loads((study / "details.json").read_text())
    return _finite({
        "study": {k: info.get(k) for k in ("study", "fmu_sha256", "finished", "wall_s",
                                           "cpu_s_total", "n_points", "n_sweep_rows")},
        "commit": docblocks.commit(ROOT), "recorded": datetime.date.today().isoformat(),
        "findings": find[["id", "figure", "at", "paper", "this FMU", "verdict"]]
        .to_dict("records"),
        "modal": modal.to_dict("records"),
        "details": det})


def copy_figures(study, page, done):
    """The study's figures that the page shows (figures/NAME.png links) and no study before it
    in `done` gave, into docs/figures/."""
    for name in re.findall(r"\(\.\./figures/([\w.\-]+\.png)\)", page.read_text()):
        src = study / "figures" / name
        if src.exists() and name not in done:
            shutil.copyfile(src, FIGURES / name)
            done.add(name)


# ------------------------------------------------------------------ the blocks
LOADED_FILE = ROOT / "resources" / "gearsets" / "loaded" / "gearset1.txt"
LOADED_SET = ("--set tooth_data=loaded roelands_z=simple shear_pressure=mean Lambda_cap=0 "
              "relaxation=constant inlet_heating=none")  # the study's paper choices with the loaded tooth data
LOADED_SWEEP = (f"hypoid sweep --out DIR {LOADED_SET} --vary T_s=50,100,300 "
                "--vary speed_rpm=1000:3600:100")
LOADED_CONTINUATION = (f"hypoid sweep --out DIR {LOADED_SET} --vary T_s=50,100 "
                       "--vary speed_rpm=2200:2900:50 --continuation")  # through mode 3


def loaded_modes(stiffness, path=LOADED_FILE):
    """Gear set 1's mode 2 and 3 speeds with the loaded tooth data at each torque: hypoid.study.modes
    at the mesh stiffness and lever arm the FMU linearises about, stiffness {torque: (k_m0,
    R_p0)} (its calculated parameters in the sweep), beside the file's secant k_m and its ripple
    interpolated linearly in the pinion torque between the levels (physics.md §10.8)."""
    import numpy as np

    from hypoid.tca.gearset_file import read_gearset

    gs = read_gearset(path)
    levels = np.array(gs.torque_levels)
    k_m = np.array([gs.layers[("drive", i + 1)]["k_m"].mean for i in range(len(levels))])
    psi = np.linspace(0.0, 2.0 * np.pi, 2001)
    ripple = np.array([np.ptp(gs.layers[("drive", i + 1)]["k_m"](psi)) / k_m[i]
                       for i in range(len(levels))])
    out = {}
    for t, (k_m0, R_p0) in stiffness.items():
        s = modes.system(k_m=k_m0, R_p=R_p0)
        w, phi = modes.modes(s)
        share = modes.mesh_strain_share(s, w, phi)
        out[f"{t:g}"] = {"k_m0": s.k_m, "R_p": s.R_p, "k_m_secant": float(np.interp(t, levels, k_m)),
                         "f2": modes.rpm(s, w[1]), "f3": modes.rpm(s, w[2]),
                         "mesh_share": [share[0], share[1]],
                         "ripple": float(np.interp(t, levels, ripple))}
    return out


def record_loaded(sweep):
    """The loaded tooth data's resonances: the modal prediction per torque and, from a `hypoid
    sweep` with tooth_data = loaded (its points.csv), the speeds of the DTE peaks, the efficiency
    dips there and where the teeth separate."""
    import pandas as pd

    from hypoid.study import tables

    pts = tables.prepare(pd.read_csv(sweep / "points.csv"))
    cont = tables.prepare(pd.read_csv(sweep / "continuation.csv")) \
        if (sweep / "continuation.csv").exists() else pd.DataFrame()
    first = pts.groupby("T_s").first()
    pred = loaded_modes({float(t): (float(r["k_m0"]), float(r["R_p0"]))
                         for t, r in first.iterrows()})
    out = {"modal": pred, "sweep": {}, "command": LOADED_SWEEP,
           "continuation": LOADED_CONTINUATION if len(cont) else "", "rows": len(pts) + len(cont),
           "fmu_sha256": str(pts["fmu_sha256"].iloc[0]) if "fmu_sha256" in pts else "",
           "commit": docblocks.commit(ROOT), "recorded": datetime.date.today().isoformat()}
    for t, g in pts.groupby("T_s"):
        by = g.groupby("speed_rpm").mean(numeric_only=True).sort_index()
        m = pred.get(f"{t:g}")
        near = {}
        for mode in ("f2", "f3"):
            band = by[(by.index - m[mode]).__abs__() <= NEAR_RPM]["DTE_pp_um"] if m else []
            if len(band):
                near[mode] = {"rpm": float(band.idxmax()), "DTE_pp_um": float(band.max()),
                              "dip": fd.dip(by["eta_rms"], m[mode])}
        j = fd.jump(cont, 1, t, m["f3"], NEAR_RPM, tooth_data="loaded") \
            if len(cont) and m else None
        out["sweep"][f"{t:g}"] = {
            "near": near, "jump_f3": j, "fmu_f3_rpm": float(by["n_f3_rpm"].iloc[0]),
            "separation_rpm": [float(n) for n in by.index[by["contact_loss_fraction"] > 0]],
            "max_DTE_pp_um": float(by["DTE_pp_um"].max()),
            "speeds": f"{by.index.min():g}-{by.index.max():g}"}
    return _finite(out)


def _default_first(study):
    """The default study's figures win over the full study's of the same name."""
    return json.loads((study / "study.json").read_text()).get("study") != "default"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--study", type=pathlib.Path, action="append", default=[],
                    help="record this study's output first (default and/or full; repeatable)")
    ap.add_argument("--loaded", type=pathlib.Path,
                    help="record a `hypoid sweep` of gear set 1 with tooth_data = loaded")
    args = ap.parse_args()
    if args.loaded:
        data = json.loads(DATA.read_text()) if DATA.exists() else {}
        data["loaded"] = record_loaded(args.loaded)
        DATA.write_text(json.dumps(data, indent=1, ensure_ascii=False) + "\n")
    copied = set()
    for study in sorted(args.study, key=_default_first):
        if not (study / "details.json").exists():
            print(f"paper_findings: {study} has no details.json (run hypoid study)")
            return 2
        data = json.loads(DATA.read_text()) if DATA.exists() else {}
        rec = record(study)
        data[rec["study"]["study"]] = rec
        DATA.write_text(json.dumps(data, indent=1, ensure_ascii=False) + "\n")
        copy_figures(study, PAGE, copied)
    PAGE.write_text(RECORDS["paper-findings"].write())
    return 0


if __name__ == "__main__":
    sys.exit(main())
