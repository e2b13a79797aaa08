"""results/report.md: the study's findings against the paper, the resonance speeds, every figure
with the table behind it, and the run's health (convergence, slow points, failures)."""

import pathlib

import numpy as np
import pandas as pd

from hypoid import findings as fd
from hypoid import plots


def md_table(df, digits=None, index=True):
    """A Markdown table; `digits` maps column name -> decimals (default: 4 significant)."""
    digits = digits or {}
    if index:
        df = df.reset_index()
    cols = [str(c) for c in df.columns]

    def fmt(col, v):
        if isinstance(v, (float, np.floating)):
            if not np.isfinite(v):
                return ""
            d = digits.get(col)
            return f"{v:.{d}f}" if d is not None else f"{v:.4g}"
        return str(v).replace("|", "/")

    lines = ["| " + " | ".join(cols) + " |", "|" + "---|" * len(cols)]
    for row in df.itertuples(index=False):
        lines.append("| " + " | ".join(fmt(c, v) for c, v in zip(cols, row)) + " |")
    return "\n".join(lines)


def _pivot(sel, column, value="eta_rms", scale=100.0):
    if sel.empty:
        return None
    t = sel.pivot_table(index="speed_rpm", columns=column, values=value, aggfunc="mean") * scale
    t.index = [f"{x:g}" for x in t.index]
    t.index.name = "speed [rpm]"
    t.columns = [f"{c:g}" if isinstance(c, (float, np.floating)) else str(c) for c in t.columns]
    return t


def _image(lines, figs, key, caption):
    if key in figs:
        lines += [f"![{caption}](figures/{figs[key].name})", "", f"*{caption}*", ""]


def modal_table(pts):
    rows = []
    for gs, g in pts.groupby("gear_set"):
        r = g.iloc[0]
        rows.append({"gear set": int(gs), "N_p": int(r["N_p"]), "ratio": r["ratio"],
                     "k_m0 [N/m]": r["k_m0"], "f_2 [Hz]": r["f_2"], "f_3 [Hz]": r["f_3"],
                     "f_4 [Hz]": r["f_4"], "n(f_2) [rpm]": r["n_f2_rpm"],
                     "n(f_3) [rpm]": r["n_f3_rpm"], "n(f_4) [rpm]": 60 * r["f_4"] / r["N_p"]})
    return pd.DataFrame(rows)


def health(raw_pts, raw_cont, pts):
    """Convergence, failures (from the raw tables) and the slowest ok points."""
    both = pd.concat([raw_pts.assign(kind="point"), raw_cont.assign(kind="continuation")],
                     ignore_index=True) if len(raw_cont) else raw_pts.assign(kind="point")
    ok = both[both["status"] == "ok"]
    lines = [f"- rows: {len(both)} ({len(ok)} ok, {len(both) - len(ok)} failed)",
             f"- steady state detected: {int(ok['converged'].sum())} of {len(ok)} rows "
             f"(the others stopped at the settling time limit and are flagged `converged = False`)",
             f"- settling time: median {ok['settle_time_s'].median():.3f} s, "
             f"max {ok['settle_time_s'].max():.3f} s (simulated)",
             f"- CPU per steady point: median {pts['cpu_s'].median():.2f} s, "
             f"max {pts['cpu_s'].max():.2f} s"]
    bad = both[both["status"] != "ok"]
    out = "\n".join(lines) + "\n"
    if len(bad):
        cols = [c for c in ("kind", "gear_set", "lubricant", "lubricant_file", "T_s", "speed_rpm",
                            "status", "message") if c in bad]
        out += "\nFailed rows:\n\n" + md_table(bad[cols], index=False) + "\n"
    slow = pts.nlargest(5, "cpu_s")
    varied = [c for c in fd.REFERENCE if c in pts and pts[c].astype(str).nunique() > 1]
    cols = ["gear_set", "lubricant_name", *varied, "T_s", "speed_rpm", "cpu_s", "settle_time_s",
            "solver_steps", "impacts", "converged"]
    out += "\nSlowest steady points:\n\n" + md_table(slow[cols], {"T_bath": 2}, index=False) + "\n"
    return out


def write(out, pts, cont, info):
    """Writes figures, findings.csv, modal.csv and report.md into `out`; returns the path."""
    out = pathlib.Path(out)
    pts_all, cont_all = pts, cont
    pts, cont = fd.prepare(pts), fd.prepare(cont)
    figs = plots.all_figures(pts, cont, out / "figures")
    find = fd.all_findings(pts_all, cont_all, out / "traces")
    find.to_csv(out / "findings.csv", index=False)
    modal = modal_table(pts)
    modal.to_csv(out / "modal.csv", index=False)
    n_rows = len(pts_all) + len(cont_all)
    rate = n_rows / info["wall_s"] if info.get("wall_s") else float("nan")
    L = [f"# HypoidGearPair study `{info['study']}`", "",
         f"Finished {info['finished']}; FMU `{info['fmu']}` (sha256 {info['fmu_sha256'][:12]}); "
         f"{info['scheduler']}.", "",
         f"{len(pts_all)} steady-state points and {len(cont_all)} continuation windows in "
         f"{info['wall_s']:.0f} s wall time ({rate:.1f} rows/s), {info.get('cpu_s_total', 0):.0f} "
         "s CPU in the FMU runs. Every row: settled until the block-to-block change of mean "
         "efficiency, DTE peak-to-peak and speed fell below tolerance, then "
         f"{info['settings']['window_cycles']} mesh cycles recorded at "
         f"{info['settings']['samples_per_cycle']} samples per mesh cycle. Efficiency is "
         "`eta_rms`, the RMS of the instantaneous efficiency over that window (the paper's "
         "measure, docs/physics.md §9.2).", "",
         "Tables: `points.csv` / `points.parquet` (steady points), `continuation.csv` / "
         "`continuation.parquet` (up/down sweeps), `findings.csv`, `modal.csv`; signals of the "
         "traced points in `traces/`. Interpretation and caveats: `docs/paper-findings.md`.", "",
         "## Paper findings in this FMU", "",
         md_table(find[["id", "figure", "at", "paper", "this FMU", "verdict"]], index=False), "",
         "F3/F4/F6 are evaluated at both mesh resonances of gear set 1: mode 2 (`f2`, the "
         "contact-loss resonance of this FMU) and mode 3 (`f3`, placed at the paper's 2000 rpm by "
         "the k_m calibration, docs/physics.md §8.4).", "",
         "## Resonance speeds", "",
         "Natural frequencies of the linearised system at the mean mesh stiffness (calculated "
         "parameters f_2..f_4); resonance speed n = 60 f / N_p.", "",
         md_table(modal, {"ratio": 3, "f_2 [Hz]": 1, "f_3 [Hz]": 1, "f_4 [Hz]": 1,
                          "n(f_2) [rpm]": 0, "n(f_3) [rpm]": 0, "n(f_4) [rpm]": 0},
                  index=False), ""]
    L += ["## Efficiency vs speed and torque (Fig. 8)", ""]
    _image(L, figs, "fig8", "Efficiency (top) and DTE peak-to-peak (bottom) vs pinion speed per "
           "input torque; open circles: contact lost during the cycle; dotted: resonance speeds.")
    t = _pivot(fd.select(pts, gear_set=1, lubricant=1, lubricant_file=""), "T_s")
    if t is not None:
        t.columns = [f"eta {c} N.m [%]" for c in t.columns]
        L += [md_table(t, {c: 3 for c in t.columns}), ""]
    for key in [k for k in figs if k.startswith("fig8-e0x")]:
        _image(L, figs, key, "Calibration probe: the same with the unloaded transmission error "
               f"scaled by {key[8:]} (e_0_scale), to see what the paper's 2000 rpm findings need.")
    L += ["## Lubricants (Figs. 6a and 7)", ""]
    _image(L, figs, "fig6a", "Efficiency of the two oils at 100 N.m.")
    _image(L, figs, "fig7", "OS265963 with the pressure-viscosity (alpha*) data of OS265962: "
           "efficiency (top) and difference to OS265962 (bottom).")
    t = _pivot(fd.select(pts, gear_set=1, T_s=100.0), "lubricant_name")
    if t is not None:
        L += [md_table(t, {c: 3 for c in t.columns}), ""]
    L += ["## Jump phenomenon (Fig. 9)", ""]
    _image(L, figs, "fig9", "Maximum and minimum DTE over the window, speed swept up (solid) and "
           "down (dashed), against the half backlash.")
    if not cont.empty:
        rows = []
        for t_s in sorted(cont["T_s"].unique()):
            b = fd.branches(cont, 1, t_s)
            b = b[(b["DTE_pp_um_up"] - b["DTE_pp_um_down"]).abs() > fd.BRANCH_MIN_UM]
            for n, r in b.iterrows():
                rows.append({"T_s [N.m]": t_s, "speed [rpm]": n,
                             "DTE p-p up/down [um]": f"{r['DTE_pp_um_up']:.1f} / "
                                                     f"{r['DTE_pp_um_down']:.1f}",
                             "min DTE - b up/down [um]": f"{r['DTE_min_minus_b_um_up']:.1f} / "
                                                         f"{r['DTE_min_minus_b_um_down']:.1f}",
                             "contact lost up/down [%]":
                                 f"{100 * r['contact_loss_fraction_up']:.0f} / "
                                 f"{100 * r['contact_loss_fraction_down']:.0f}",
                             "eta up/down [%]": f"{100 * r['eta_rms_up']:.3f} / "
                                                f"{100 * r['eta_rms_down']:.3f}"})
        if rows:
            L += ["Speeds with two branches (up/down DTE peak-to-peak differ by more than "
                  f"{fd.BRANCH_MIN_UM:g} um):", "", md_table(pd.DataFrame(rows), index=False), ""]
        else:
            L += ["No speed with two branches in these sweeps.", ""]
    L += ["## One engagement near and away from resonance (Fig. 10)", ""]
    _image(L, figs, "fig10", "Contact load and friction coefficient of tooth pair 1 over its "
           "engagement (3 mesh cycles), 100 N.m.")
    if "trace" in pts:
        tr = pts[pts["trace"].fillna("").astype(str) != ""]
        cols = ["T_s", "speed_rpm", "eta_rms", "DTE_pp_um", "DTE_min_minus_b_um",
                "contact_loss_fraction", "W_t_mean_N", "W_t_mean_contact_N", "W_t_peak_N",
                "mu_mean", "h_c_mean_um", "lambda_mean"]
        L += [md_table(tr[cols].sort_values(["T_s", "speed_rpm"]), index=False), ""]
    L += ["## Gear sets 2 and 3 (Fig. 11)", ""]
    _image(L, figs, "fig11", "Efficiency and DTE peak-to-peak of gear sets 2 and 3 at 100 N.m; "
           "dotted lines: each set's resonance speeds.")
    t = _pivot(fd.select(pts, lubricant=1, lubricant_file="", T_s=100.0)
               .query("gear_set in [2, 3]"), "gear_set")
    if t is not None:
        t.columns = [f"eta set {c} [%]" for c in t.columns]
        L += [md_table(t, {c: 3 for c in t.columns}), ""]
    L += ["## Lubrication regime (Fig. 5)", ""]
    _image(L, figs, "fig5", "Viscosity and elasticity parameters of every loaded pair over two "
           "mesh cycles at 1000 rpm; the regions are the Hamrock-Dowson substitute of physics.md "
           "§7 (Zhang & Gou's map could not be reproduced).")
    if info.get("extra"):
        L += ["## Sensitivity runs (100 N.m, gear set 1)", ""]
        L += [_extra_table(pts, info["extra"]), ""]
    L += ["## Run health", "", health(pts_all, cont_all, pts), ""]
    path = out / "report.md"
    path.write_text("\n".join(L) + "\n")
    return path


def _extra_table(pts, extra):
    base = fd.curve(pts, gear_set=1, lubricant=1, lubricant_file="", T_s=100.0)
    cols = {"reference (OS265962, 40 degC, ehl_thermal, varying)": base}
    for label, params in extra:
        ref = {**fd.REFERENCE, **params}
        sel = pts
        for k, v in ref.items():
            if k in sel:
                sel = sel[sel[k].astype(str) == str(v)] if isinstance(v, str) else \
                    sel[np.isclose(sel[k].astype(float), float(v))]
        sel = sel[(sel["gear_set"] == 1) & np.isclose(sel["T_s"], 100.0)]
        if "lubricant" not in params:
            sel = sel[(sel["lubricant"] == 1) & (sel["lubricant_file"] == "")]
        cols[label] = sel.groupby("speed_rpm")["eta_rms"].mean()
    t = pd.DataFrame(cols).dropna() * 100
    t.index = [f"{x:g}" for x in t.index]
    t.index.name = "speed [rpm]"
    return md_table(t, {c: 3 for c in t.columns})
