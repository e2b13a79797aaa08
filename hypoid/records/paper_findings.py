"""The paper-findings record: the page docs/records/paper-findings.md is written text around
generated blocks, each made from paper-findings.json (recorded from `hypoid study` and a `hypoid
sweep` of the loaded tooth data by tools/paper_findings.py). The modal block is computed here
(hypoid.study.modes, no FMU); every other number comes from the data."""

from hypoid.errors import UsageError
from hypoid.records import docblocks
from hypoid.records.pages import load
from hypoid.study import findings as fd
from hypoid.study import modes, report

NEAR_RPM = 150.0  # a DTE peak belongs to a mode within this distance of its modal speed


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
            return f"(`{name}` not recorded: see `tools/paper_findings.py --help`)"
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


def page(record, folder, text):
    """The page with every generated block rewritten from the data."""
    data = load(folder, record.data[0])
    source = f"hypoid records {record.name} from {record.data[0]}"
    for name, fn in BLOCKS.items():
        new = docblocks.replace(text, name, source, fn(data))
        if new is None:
            if name not in data and name in OPTIONAL:
                continue
            raise UsageError(f"{record.page} has no block {name!r} "
                             f"({docblocks.begin(name, source)} ... {docblocks.end(name)})")
        text = new
    return text
