#!/usr/bin/env python3
"""The numbers of docs/paper-findings.md, from a study's output: recorded into
docs/paper-findings.json and written from it between the page's generated-block markers.

    .venv/bin/hypoid study default --out results          # the paper-findings study
    .venv/bin/python tools/paper_findings.py --study results   # record it, write the page
    .venv/bin/python tools/paper_findings.py --study results-full   # the full study's part
    .venv/bin/python tools/paper_findings.py                # the page from the data file only
    .venv/bin/python tools/paper_findings.py --check        # exit 1 when the page is stale
                                                            # (tests/python/test_generated_docs)

--study also copies the study's figures that the page shows into docs/figures/. The modal
block is computed here (hypoid.study.modes, no FMU); every other number comes from the data file.
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
from hypoid.study import modes, report

DATA = ROOT / "docs" / "paper-findings.json"
PAGE = ROOT / "docs" / "paper-findings.md"
FIGURES = ROOT / "docs" / "figures"
BEGIN = "<!-- generated:{} (tools/paper_findings.py from docs/paper-findings.json) -->"
END = "<!-- /generated:{} -->"

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
    for name in re.findall(r"\(figures/([\w.\-]+\.png)\)", page.read_text()):
        src = study / "figures" / name
        if src.exists() and name not in done:
            shutil.copyfile(src, FIGURES / name)
            done.add(name)


# ------------------------------------------------------------------ the blocks
def _um(values):
    return "/".join(f"{v:.0f}" for v in values)


def provenance(data):
    lines = []
    for name, d in data.items():
        if name == "loaded":
            lines.append(f"- the loaded tooth data's sweep recorded {d['recorded']} on code "
                         f"{d['commit']} (FMU sha256 {d['fmu_sha256'][:12]}): {d['rows']} "
                         "points.")
            continue
        s = d["study"]
        lines.append(f"- `hypoid study {s['study']}` finished {s['finished']} on code "
                     f"{d['commit']} (FMU sha256 {s['fmu_sha256'][:12]}): {s['n_points']} steady "
                     f"points and {s['n_sweep_rows']} continuation windows in {s['wall_s']:.0f} s "
                     f"wall, {s['cpu_s_total']:.0f} s CPU.")
    return "\n".join(lines)


def resonance_block(d):
    import pandas as pd

    modal = pd.DataFrame(d["modal"])
    lines = [report.md_table(modal, {"ratio": 3, "f_2 [Hz]": 1, "f_3 [Hz]": 1, "f_4 [Hz]": 1,
                                     "n(f_2) [rpm]": 0, "n(f_3) [rpm]": 0, "n(f_4) [rpm]": 0},
                             index=False), ""]
    ref = d["details"]["reference"]
    ts = list(ref["torques"])
    at = {m: ref["torques"][ts[0]][m]["rpm"] for m in ("f2", "f3")}
    lines.append(
        f"Time-domain response of gear set 1 (study grid, {'/'.join(ts)} N·m): DTE peak-to-peak "
        f"{_um(ref['torques'][t]['f2']['DTE_pp_um'] for t in ts)} µm at {at['f2']:g} rpm "
        f"(mode 2), {_um(ref['torques'][t]['f3']['DTE_pp_um'] for t in ts)} µm at "
        f"{at['f3']:g} rpm (mode 3); minimum DTE minus the half backlash b at {at['f2']:g} rpm "
        + " / ".join(f"{ref['torques'][t]['f2']['DTE_min_minus_b_um']:+.1f}" for t in ts)
        + f" µm, at {at['f3']:g} rpm "
        + " / ".join(f"{ref['torques'][t]['f3']['DTE_min_minus_b_um']:+.1f}" for t in ts)
        + " µm (negative: the teeth separate).")
    return "\n".join(lines)


def findings_block(d):
    import pandas as pd

    return report.md_table(pd.DataFrame(d["findings"])[["id", "figure", "at", "paper",
                                                         "this FMU", "verdict"]], index=False)


def _traced(v, key):
    return v["traced"].get(key)


def engagement_block(d):
    """F6 (Fig. 10) at the reference: the traced points at 100 N.m."""
    ref = d["details"]["reference"]
    rows = []
    for key, r in ref["traced"].items():
        t, n = key.split("@")
        peak = f"{r['pair_peak_N'] / 1e3:.2f}" if r.get("pair_peak_N") else "–"
        rows.append(f"| {t} | {n} | {100 * r['contact_loss_fraction']:.0f} | {peak} | "
                    f"{r['W_t_mean_contact_N']:.0f} | {r['mu_mean']:.4f} | "
                    f"{r['h_c_mean_um']:.3f} | {100 * r['eta_rms']:.3f} |")
    return "\n".join(["| T_s [N·m] | speed [rpm] | contact lost [%] | pair 1 peak load [kN] | "
                      "mean load in contact [N] | mean μ (load-weighted) | mean h_c [µm] | "
                      "η_rms [%] |", "|---|---|---|---|---|---|---|---|", *rows])


def gear_set_block(d):
    g = d["details"]["gear_sets"]
    if not g:
        return "(no gear-set rows)"
    rows = [f"| {gs} | {v['R_p0_mm']:.2f} | {v['W_t_mean_contact_N']:.0f} | "
            f"{v['mu_mean']:.4f} | {v['lambda_mean']:.2f} |" for gs, v in g.items()]
    return "\n".join(["| gear set | R_p0 [mm] | mean load in contact [N] | mean μ | mean λ |",
                      "|---|---|---|---|---|", *rows])


def whatif_block(d):
    return "\n".join(report.whatif_rows(d["details"])) or "(no what-if in this study)"


def modal_block(d):
    """hypoid.study.modes at gear set 1's k_m0 and R_p0 as the study ran them, for Table 3 and the
    geometric pinion inertia, with the dampers the FMU chose for each (the study's rows)."""
    import pandas as pd

    modal = pd.DataFrame(d["modal"])
    ref = modal[modal["gear set"].astype(str) == "1"].iloc[0]
    return modes.inertia_reports(float(ref["k_m0 [N/m]"]), float(ref["R_p0 [m]"]),
                                 report.fmu_dampers(modal), level="####")


def lubricant_block(d):
    res = d["details"]["lubricants"]
    if not res:
        return "(no swapped-oil rows)"
    speeds = sorted(res, key=float)
    big = max(speeds, key=lambda n: res[n])
    return (f"With OS265962's α* data OS265963 still trails OS265962 by {100 * res[big]:.3f} "
            f"%-points at {big} rpm (the largest), falling to {100 * res[speeds[-1]]:.3f} at "
            f"{speeds[-1]} rpm.")


def probe_block(d):
    probes = d["details"]["probes"]
    if not probes:
        return "(the full study's calibration probe is not recorded)"
    lines = []
    for e0, p in probes.items():
        ts = list(p)
        m = {k: p[ts[0]][k]["rpm"] for k in ("f2", "f3")}
        lines += [f"| e_0_scale = {e0} | " + " | ".join(f"{t} N·m" for t in ts) + " |",
                  "|---|" + "---|" * len(ts)]
        for mode in ("f3", "f2"):
            lines.append(f"| dip at {m[mode]:g} rpm [%-points] | " + " | ".join(
                "–" if p[t][mode]["dip"] is None else f"{100 * p[t][mode]['dip']:.3f}"
                for t in ts) + " |")
            lines.append(f"| contact lost at {m[mode]:g} rpm | " + " | ".join(
                f"{100 * p[t][mode]['contact_loss_fraction']:.0f} %" for t in ts) + " |")
    return "\n".join(lines)


def sensitivity_block(d):
    sens = d["details"]["sensitivity"]
    return report.sensitivity_table(sens) if sens else "(no sensitivity runs recorded)"


LOADED_FILE = ROOT / "resources" / "gearsets" / "loaded" / "gearset1.txt"
NEAR_RPM = 150.0  # a DTE peak belongs to a mode within this distance of its modal speed
LOADED_SET = ("--set tooth_data=loaded roelands_z=simple shear_pressure=mean Lambda_cap=0 "
              "relaxation=constant")  # the study's paper choices with the loaded tooth data
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


def loaded_block(d):
    """Where gear set 1's resonances sit with the loaded tooth data."""
    rows = ["| T_s [N·m] | k_m: the file's secant mean / the FMU's k_m0 [10⁸ N/m] | k_m ripple "
            "(peak-to-peak / mean) | mode 2 / mode 3, modal at k_m0 [rpm] | their mesh share of "
            "strain energy | largest DTE p-p "
            f"within {NEAR_RPM:g} rpm of mode 2 / mode 3 [rpm: µm] | efficiency dip there "
            "[%-points] | teeth apart at (grid speeds) | two branches through mode 3 "
            "(continuation) |", "|---|---|---|---|---|---|---|---|---|"]
    for t, m in d["modal"].items():
        s = d["sweep"].get(t, {})
        near = s.get("near", {})
        peaks = " / ".join(f"{near[k]['rpm']:g}: {near[k]['DTE_pp_um']:.0f}" if k in near
                           else "–" for k in ("f2", "f3"))
        dips = " / ".join("–" if near.get(k, {}).get("dip") is None else
                          f"{100 * near[k]['dip']:.3f}" for k in ("f2", "f3"))
        sep = _runs(s.get("separation_rpm", []), 100.0)
        j = s.get("jump_f3")
        jump = "not swept" if j is None else (
            f"{_runs(j['speeds_two_branches'], 50.0)} (gap ≤ {j['max_branch_gap_um']:.1f} µm); "
            f"min DTE − b {j['min_DTE_min_minus_b_um']:+.1f} µm, contact lost up to "
            f"{100 * j['max_contact_loss']:.0f} %")
        rows.append(f"| {t} | {m['k_m_secant'] / 1e8:.2f} / {m['k_m0'] / 1e8:.2f} | "
                    f"{100 * m['ripple']:.0f} % | "
                    f"{m['f2']:.0f} / {m['f3']:.0f} | "
                    f"{m['mesh_share'][0]:.2f} / {m['mesh_share'][1]:.2f} | {peaks} | {dips} | "
                    f"{sep} | {jump} |")
    ts = list(d["modal"])
    sep = [t for t in ts if d["sweep"].get(t, {}).get("separation_rpm")]
    dips = [100 * v["dip"] for s in d["sweep"].values() for v in s.get("near", {}).values()
            if v.get("dip") is not None]
    summary = (f"Mode 3 moves from {d['modal'][ts[0]]['f3']:.0f} rpm at {ts[0]} N·m to "
               f"{d['modal'][ts[-1]]['f3']:.0f} rpm at {ts[-1]} N·m, mode 2 from "
               f"{d['modal'][ts[0]]['f2']:.0f} to {d['modal'][ts[-1]]['f2']:.0f} rpm; the "
               "largest DTE peak-to-peak of the sweep is "
               f"{max(s['max_DTE_pp_um'] for s in d['sweep'].values()):.0f} µm; the teeth "
               + (f"separate at {', '.join(sep)} N·m" if sep else "separate at no point")
               + f"; the deepest dip at a resonance is {max(dips):.3f} %-points"
               + (" (below the findings' 0.02 threshold)." if max(dips) < 100 * fd.DIP_MIN
                  else "."))
    runs = f"Sweeps: `{d['command']}`" + (f"; `{d['continuation']}`" if d.get("continuation")
                                         else "") + "."
    return "\n".join(rows + ["", summary, "", runs])


def _runs(speeds, step):
    """'1200-1300, 2500 rpm' for the speeds in runs of `step`, 'none' for none."""
    if not speeds:
        return "none"
    groups, start = [], speeds[0]
    for a, b in zip(speeds, speeds[1:] + [None]):
        if b is None or b - a > step + 1e-9:
            groups.append(f"{start:g}" if start == a else f"{start:g}–{a:g}")
            start = b
    return ", ".join(groups) + " rpm"


def _study(name, fn):
    """A block from the record of study `name`."""
    def block(data):
        if name not in data:
            return f"(`{name}` not recorded: see tools/paper_findings.py --help)"
        return fn(data[name])
    return block


BLOCKS = {"provenance": provenance, "resonances": _study("default", resonance_block),
          "findings": _study("default", findings_block), "modal": _study("default", modal_block),
          "whatif": _study("default", whatif_block),
          "engagement": _study("default", engagement_block),
          "gear-sets": _study("default", gear_set_block),
          "lubricants": _study("default", lubricant_block),
          "probe": _study("full", probe_block), "sensitivity": _study("full", sensitivity_block),
          "loaded": _study("loaded", loaded_block)}


OPTIONAL = {"loaded"}  # blocks the page may lack while their data are not recorded


def page_with(text, data):
    """The page with every generated block rewritten from the data."""
    for name, fn in BLOCKS.items():
        new = docblocks.replace(text, BEGIN.format(name), END.format(name), fn(data))
        if new is None:
            if name not in data and name in OPTIONAL:
                continue
            sys.exit(f"paper_findings: {PAGE.name} has no block '{name}' "
                     f"({BEGIN.format(name)} ... {END.format(name)})")
        text = new
    return text


def _default_first(study):
    """The default study's figures win over the full study's of the same name."""
    return json.loads((study / "study.json").read_text()).get("study") != "default"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--study", type=pathlib.Path, action="append", default=[],
                    help="record this study's output first (default and/or full; repeatable)")
    ap.add_argument("--loaded", type=pathlib.Path,
                    help="record a `hypoid sweep` of gear set 1 with tooth_data = loaded")
    ap.add_argument("--check", action="store_true", help="exit 1 when the page is stale")
    ap.add_argument("--file", type=pathlib.Path, default=PAGE, help="the page to write or check")
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
        copy_figures(study, args.file, copied)
    data = json.loads(DATA.read_text())
    return docblocks.write_or_check(args.file, page_with(args.file.read_text(), data), args.check,
                                    f"a generated block against {DATA.relative_to(ROOT)}",
                                    "tools/paper_findings.py")

if __name__ == "__main__":
    sys.exit(main())
