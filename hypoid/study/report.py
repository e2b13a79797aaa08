"""results/report.md: the study's findings against the paper, the resonance speeds, every figure
with the table behind it, and the run's health (convergence, slow points, failures)."""

import pathlib

import numpy as np
import pandas as pd

from hypoid.study import findings as fd
from hypoid.maps import lossmap as lmap
from hypoid.study import modes
from hypoid.study import tables as tb
from hypoid.fmu.values import TABLE


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
    varied = [c for c in tb.REFERENCE if c in pts and pts[c].astype(str).nunique() > 1]
    cols = ["gear_set", "lubricant_name", *varied, "T_s", "speed_rpm", "cpu_s", "settle_time_s",
            "solver_steps", "impacts", "converged"]
    out += "\nSlowest steady points:\n\n" + md_table(slow[cols], {"T_bath": 2}, index=False) + "\n"
    return out


def _header(pts_all, cont_all, info, find, modal):
    n_rows = len(pts_all) + len(cont_all)
    rate = n_rows / info["wall_s"] if info.get("wall_s") else float("nan")
    return [f"# HypoidGearPair study `{info['study']}`", "",
            f"Finished {info['finished']}; FMU `{info['fmu']}` (sha256 "
            f"{info['fmu_sha256'][:12]}); {info['scheduler']}.", "",
            f"{len(pts_all)} steady-state points and {len(cont_all)} continuation windows in "
            f"{info['wall_s']:.0f} s wall time ({rate:.1f} rows/s), "
            f"{info.get('cpu_s_total', 0):.0f} s CPU in the FMU runs. Every row: settled until "
            "the block-to-block change of mean efficiency, DTE peak-to-peak and speed fell below "
            f"tolerance, then {info['settings']['window_cycles']} mesh cycles recorded at "
            f"{info['settings']['samples_per_cycle']} samples per mesh cycle. Efficiency is "
            "`eta_rms`, the RMS of the instantaneous efficiency over that window (the paper's "
            "measure, docs/physics.md §9.2), in % in every table.", "",
            "Tables: `points.csv` / `points.parquet` (steady points), `continuation.csv` / "
            "`continuation.parquet` (up/down sweeps), `findings.csv`, `modal.csv`; signals of "
            "the traced points in `traces/`. Interpretation and caveats: "
            "`docs/records/paper-findings.md`.", "",
            "## Paper findings in this FMU", "",
            md_table(find[["id", "figure", "at", "paper", "this FMU", "verdict"]], index=False),
            "", "F3/F4/F6 are evaluated at both mesh resonances of gear set 1: mode 2 (`f2`, the "
            "contact-loss resonance of this FMU) and mode 3 (`f3`, placed at the paper's 2000 rpm "
            "by the k_m calibration, docs/physics.md §8.4).", "",
            "## Resonance speeds", "",
            "Natural frequencies of the linearised system at the mean mesh stiffness (calculated "
            "parameters f_2..f_4); resonance speed n = 60 f / N_p.", "",
            md_table(modal, {"ratio": 3, "f_2 [Hz]": 1, "f_3 [Hz]": 1, "f_4 [Hz]": 1,
                             "n(f_2) [rpm]": 0, "n(f_3) [rpm]": 0, "n(f_4) [rpm]": 0},
                     index=False), "", _modal_section(modal), ""]


def _modal_section(modal):
    """hypoid.study.modes at gear set 1's mean mesh stiffness and lever arm as the study ran them."""
    ref = modal[modal["gear set"].astype(str) == "1"]
    if ref.empty:
        return modes.findings_section()
    return modes.findings_section(float(ref["k_m0 [N/m]"].iloc[0]),
                                  float(ref["R_p0 [m]"].iloc[0]), fmu_dampers(modal))


def fmu_dampers(modal):
    """{I_p: (c_t1, c_m, c_t2)} of gear set 1 at the reference and each what-if inertia, as the
    FMU derived them (the modal table's damper columns)."""
    out = {}
    for r in modal.to_dict("records"):
        label = str(r["gear set"])
        if not label.startswith("1") or "c_m (damper)" not in r:
            continue
        ip = float(label.split("I_p = ")[1]) if "I_p = " in label else tb.REFERENCE["I_p"]
        out[ip] = tuple(float(r[f"{n} (damper)"]) for n in ("c_t1", "c_m", "c_t2"))
    return out


# ---------------------------------------------------------------------------- which settings
def _value_text(name, value):
    if name == "T_bath":
        return f"{float(value) - 273.15:g} °C"
    return f"{value:g}" if isinstance(value, float) else str(value)


def differing_defaults():
    """[(name, the tables' value, the FMU's default)] of the reference settings that are not the
    shipped FMU's defaults (the paper's EHL choices and tooth data)."""
    out = []
    for name, value in tb.REFERENCE.items():
        default = TABLE.start(name)
        same = (np.isclose(float(value), float(default), rtol=0, atol=1e-12)
                if not isinstance(value, str) and not isinstance(default, str)
                else str(value) == str(default))
        if not same:
            out.append((name, value, default))
    return out


def _at_defaults(pts):
    """Rows that ran every reference setting at the FMU's default instead of the paper's (none
    from a table without the columns that say so)."""
    needed = [n for n, _, _ in differing_defaults()] + ["gear_set", "lubricant", "T_s",
                                                        "speed_rpm", "T_bath", "eta_rms",
                                                        "P_loss_mean_W"]
    if pts.empty or any(c not in pts for c in needed):
        return pts.iloc[0:0]
    mask = np.ones(len(pts), bool)
    for name, _, default in differing_defaults():
        mask &= pts[name].astype(str).to_numpy() == str(default)
    return pts[mask]


def settings_section(pts):
    """Which settings made every table, and the FMU defaults' figure beside the paper's at the
    points that ran both."""
    diff = differing_defaults()
    ref = ", ".join(f"{n} = {_value_text(n, v)}" for n, v in tb.REFERENCE.items())
    L = ["## Settings behind the tables", "",
         f"Every table and figure below runs gear set 1 and OS265962 at the study's reference "
         f"settings unless its own line says otherwise: {ref}. These are the paper's choices, "
         "which the study reproduces."]
    if diff:
        L[-1] += (" The shipped FMU's defaults differ in " + ", ".join(
            f"{n} ({_value_text(n, d)} by default, {_value_text(n, v)} here)" for n, v, d in diff)
            + " (docs/friction-evidence.md says why).")
    L.append("")
    own = _at_defaults(pts)
    rows = []
    for r in own.to_dict("records"):
        paper = tb.select(pts, gear_set=r["gear_set"], lubricant=r["lubricant"],
                          lubricant_file="", T_s=r["T_s"], speed_rpm=r["speed_rpm"])
        if paper.empty:
            continue
        rows.append({"point": f"set {r['gear_set']:g}, {r['speed_rpm']:g} rpm, "
                              f"{r['T_s']:g} N·m, {_value_text('T_bath', r['T_bath'])}",
                     "eta_rms, paper's choices [%]": 100 * float(paper["eta_rms"].iloc[0]),
                     "eta_rms, FMU defaults [%]": 100 * float(r["eta_rms"]),
                     "P_loss, paper's choices [W]": float(paper["P_loss_mean_W"].iloc[0]),
                     "P_loss, FMU defaults [W]": float(r["P_loss_mean_W"])})
    if rows:
        t = pd.DataFrame(rows)
        L += ["The same point with the paper's choices (the tables) and with the shipped FMU's "
              "defaults (what `hypoid run` gives without --set):", "",
              md_table(t, {c: (3 if "%" in c else 1) for c in t.columns if c != "point"},
                       index=False), ""]
    return L


def made_with(**eq):
    """The line under a table: what it selects beyond the reference settings."""
    parts = [f"{n} = {_value_text(n, v)}" for n, v in eq.items()]
    return [f"*Settings: {', '.join(parts) if parts else 'the reference'}; the rest as in "
            "'Settings behind the tables'.*", ""]


def _pivot_lines(t, columns=None):
    if t is None:
        return []
    if columns:
        t.columns = [columns.format(c) for c in t.columns]
    return [md_table(t, {c: 3 for c in t.columns}), ""]


def _torque_section(pts, figs):
    L = ["## Efficiency vs speed and torque (Fig. 8)", ""]
    _image(L, figs, "fig8", "Efficiency (top) and DTE peak-to-peak (bottom) vs pinion speed per "
           "input torque; open circles: contact lost during the cycle; dotted: resonance speeds.")
    L += _pivot_lines(_pivot(tb.select(pts, gear_set=1, lubricant=1, lubricant_file=""), "T_s"),
                      "eta {} N·m [%]")
    L += made_with(gear_set=1, lubricant="OS265962")
    for key in [k for k in figs if k.startswith("fig8-e0x")]:
        _image(L, figs, key, "Calibration probe: the same with the unloaded transmission error "
               f"scaled by {key[8:]} (e_0_scale), to see what the paper's 2000 rpm findings need.")
    L += ["## Lubricants (Figs. 6a and 7)", ""]
    _image(L, figs, "fig6a", "Efficiency of the two oils at 100 N·m.")
    _image(L, figs, "fig7", "OS265963 with the pressure-viscosity (alpha*) data of OS265962: "
           "efficiency (top) and difference to OS265962 (bottom).")
    L += _pivot_lines(_pivot(tb.select(pts, gear_set=1, T_s=100.0), "lubricant_name"),
                      "eta {} [%]")
    L += made_with(gear_set=1, T_s=100.0)
    return L


def _branch_rows(cont):
    rows = []
    for t_s in sorted(cont["T_s"].unique()):
        b = fd.branches(cont, 1, t_s)
        b = b[(b["DTE_pp_um_up"] - b["DTE_pp_um_down"]).abs() > fd.BRANCH_MIN_UM]
        for n, r in b.iterrows():
            rows.append({"T_s [N·m]": t_s, "speed [rpm]": n,
                         "DTE p-p up/down [µm]": f"{r['DTE_pp_um_up']:.1f} / "
                                                 f"{r['DTE_pp_um_down']:.1f}",
                         "min DTE - b up/down [µm]": f"{r['DTE_min_minus_b_um_up']:.1f} / "
                                                     f"{r['DTE_min_minus_b_um_down']:.1f}",
                         "contact lost up/down [%]":
                             f"{100 * r['contact_loss_fraction_up']:.0f} / "
                             f"{100 * r['contact_loss_fraction_down']:.0f}",
                         "eta up/down [%]": f"{100 * r['eta_rms_up']:.3f} / "
                                            f"{100 * r['eta_rms_down']:.3f}"})
    return rows


def _jump_section(cont, figs):
    L = ["## Jump phenomenon (Fig. 9)", ""]
    _image(L, figs, "fig9", "Maximum and minimum DTE over the window, speed swept up (solid) and "
           "down (dashed), against the half backlash.")
    if cont.empty:
        return L
    rows = _branch_rows(cont)
    if rows:
        return L + ["Speeds with two branches (up/down DTE peak-to-peak differ by more than "
                    f"{fd.BRANCH_MIN_UM:g} µm):", "", md_table(pd.DataFrame(rows), index=False),
                    ""]
    return L + ["No speed with two branches in these sweeps.", ""]


TRACE_COLUMNS = {"T_s": "T_s [N·m]", "speed_rpm": "speed [rpm]", "eta_rms": "eta_rms [%]",
                 "DTE_pp_um": "DTE p-p [µm]", "DTE_min_minus_b_um": "min DTE - b [µm]",
                 "contact_loss_fraction": "contact lost [%]", "W_t_mean_N": "W_t mean [N]",
                 "W_t_mean_contact_N": "W_t mean in contact [N]", "W_t_peak_N": "W_t peak [N]",
                 "mu_mean": "mu_mean (load-weighted)", "h_c_mean_um": "h_c mean [µm]",
                 "lambda_mean": "lambda mean"}


def _engagement_section(pts, figs):
    L = ["## One engagement near and away from resonance (Fig. 10)", ""]
    _image(L, figs, "fig10", "Contact load and friction coefficient of tooth pair 1 over its "
           "engagement (3 mesh cycles), 100 N·m; the legend's mu_mean is the table's.")
    if "trace" in pts:
        tr = pts[pts["trace"].fillna("").astype(str) != ""].sort_values(["T_s", "speed_rpm"])
        t = tr[list(TRACE_COLUMNS)].copy()
        t[["eta_rms", "contact_loss_fraction"]] *= 100.0
        L += [md_table(t.rename(columns=TRACE_COLUMNS), {"eta_rms [%]": 3}, index=False), ""]
    L += ["## Gear sets 2 and 3 (Fig. 11)", ""]
    _image(L, figs, "fig11", "Efficiency and DTE peak-to-peak of gear sets 2 and 3 at 100 N·m; "
           "dotted lines: each set's resonance speeds.")
    L += _pivot_lines(_pivot(tb.select(pts, lubricant=1, lubricant_file="", T_s=100.0)
                             .query("gear_set in [2, 3]"), "gear_set"), "eta set {} [%]")
    L += made_with(lubricant="OS265962", T_s=100.0)
    L += ["## Lubrication regime (Fig. 5)", ""]
    _image(L, figs, "fig5", "Viscosity and elasticity parameters of every loaded pair over two "
           "mesh cycles at 1000 rpm; the regions are the Hamrock-Dowson substitute of physics.md "
           "§7 (Zhang & Gou's map could not be reproduced).")
    return L


def _lossmap_comparison(lm):
    loaded = lm[lm["T_s"] > 0]
    lo_pub, hi_pub = lmap.PUBLISHED_ETA_RANGE
    L = []
    for T, g in loaded.groupby("T_oil_C"):
        L.append(f"- {T:.0f} °C oil, loaded points: eta_axle {100 * g['eta_axle'].min():.2f}–"
                 f"{100 * g['eta_axle'].max():.2f} %.")
    spins = [(T, n, lmap.spin_torque_Nm(lm, T, n)) for T in sorted(lm["T_oil_C"].unique())
             for n in sorted(lm["speed_rpm"].unique())]
    spins = [f"{q:.2f} N·m at {n:.0f} rpm, {T:.0f} °C" for T, n, q in spins if np.isfinite(q)]
    if spins:
        L.append("- Spin loss (T_s = 0) as a drag torque at the pinion: " + "; ".join(spins)
                 + ".")
    L += [f"- Published: whole passenger-car and light-commercial axles at typically "
          f"{100 * lo_pub:.0f}–{100 * hi_pub:.0f} % torque efficiency, lower cold and at part "
          "load; the UK Transport Research Laboratory's dynamometer tests of Ford Transit axles "
          f"(TRL report RR10) lost at least {100 * lmap.PUBLISHED_MIN_LOSS_WARM:.0f} % even "
          "warm and at high power, up to 40 % cold at low power; Xu, Singh, Maddock, Kahraman "
          "and Hurley (SAE) measured rear-axle mechanical and spin losses varying strongly with "
          "oil temperature and bearing preload.",
          f"- Reading: {_reading(loaded, hi_pub)} JTEKT (FISITA 2006, F2006P299) attribute "
          "about half of a rear axle's loss to the pinion bearings; the pinion and carrier "
          "preloads here are calibrated to workshop turning-torque specifications, f_0 and f_1 "
          "are Schaeffler's catalogue values, the churning coefficients are not verified "
          "(docs/axle.md, 'How the figures compare' and 'Constants against published sources')."]
    return L


def _reading(loaded, hi_pub):
    """Where the loaded points fall against the published upper bound."""
    above = loaded[loaded["eta_axle"] > hi_pub]
    if above.empty:
        return f"every loaded point is at or below the published {100 * hi_pub:.0f} %."
    return (f"{len(above)} of {len(loaded)} loaded points lie above the published "
            f"{100 * hi_pub:.0f} % (from T_s = {above['T_s'].min():g} N·m): there the model "
            "loses less than the measured axles.")


def _lossmap_section(lm, figs):
    """The axle's loss map (hypoid.maps.lossmap) against published axle efficiencies."""
    if lm is None or lm.empty:
        return []
    L = ["## The axle's loss map (axle_losses = full)", "",
         "Steady runs (speed governor, rigid mesh, ehl_thermal, gear set 1, OS265962) with the "
         "oil held at each temperature: the parts of P_axle = P_loss (mesh) + P_churn + "
         "P_bearings + P_seals and eta_axle = 1 − P_axle / P_in_axle, means over the last "
         f"{lmap.MEAN_STEPS} steps of {lmap.T_END_S:g} s. At T_s = 0 no power enters and "
         "eta_axle is ~0 by definition. Models and sources: docs/axle.md.", ""]
    _image(L, figs, "lossmap", "The axle's losses by part over pinion speed, per oil temperature "
           "and input torque.")
    return L + [lmap.markdown(lm), "", "Compared with published axle figures:", "",
                *_lossmap_comparison(lm), ""]


def write(out, pts, cont, info, figs, find, modal, lossmap=None, det=None):
    """Writes report.md into `out` from the raw tables, the figures {key: path}, the findings,
    the modal table, the axle's loss map and the detail numbers (findings.details; hypoid.study.paper
    makes them); returns the path."""
    ok_pts, ok_cont = tb.prepare(pts), tb.prepare(cont)
    L = _header(pts, cont, info, find, modal)
    L += settings_section(ok_pts)
    L += _torque_section(ok_pts, figs)
    L += _jump_section(ok_cont, figs)
    L += _engagement_section(ok_pts, figs)
    L += _whatif_section(det, figs) if det else []
    L += _lossmap_section(lossmap, figs)
    if info.get("extra"):
        L += ["## Sensitivity runs (efficiency [%], 100 N·m, gear set 1)", "",
              _extra_table(ok_pts, info["extra"]),
              ""]
    L += ["## Run health", "", health(pts, cont, ok_pts), ""]
    path = pathlib.Path(out) / "report.md"
    path.write_text("\n".join(L) + "\n")
    return path


def _extra_table(pts, extra):
    return sensitivity_table(fd.sensitivity_numbers(pts, extra))


def sensitivity_table(sens):
    """eta [%] by speed: the reference and each sensitivity variant (findings'
    sensitivity_numbers), at the speeds all of them ran."""
    cols = {("reference (OS265962, 40 °C, ehl_thermal, varying)" if k == "reference" else k):
            pd.Series({float(n): v for n, v in s.items()}) for k, s in sens.items()}
    t = pd.DataFrame(cols).dropna().sort_index() * 100
    t.index = [f"{x:g}" for x in t.index]
    t.index.name = "speed [rpm]"
    return md_table(t, {c: 3 for c in t.columns})


# ---------------------------------------------------------------------------- the what-if
PAPER_COLUMN = {  # what Paouris et al. report near 2000 rpm (Figs. 8-10), in our words
    "strongest": "near 2000 rpm",
    "dip_f3": "a dip at 50 and 100 N·m, none at 200 and 300 N·m",
    "dip_f2": "not reported",
    "separation": "at 100 N·m near 2000 rpm (Figs. 9, 10)",
    "jump": "at 100 N·m near 2000 rpm",
    "load": "higher near resonance than at 5000 rpm, with zero-friction gaps",
}


def _per_torque(v, fmt, torques):
    """One value per torque of the reference's grid, '–' where the variant has none."""
    return " / ".join(fmt(v["torques"][t]) if t in v["torques"] else "–" for t in torques)


def _band(speeds):
    return fd.speed_range(speeds) if speeds else "none"


def _jump_text(d, mode):
    j = d.get(mode, {}).get("jump")
    if j is None:
        return "not swept"
    two = j["speeds_two_branches"]
    return (f"{_band(two)} (gap {j['max_branch_gap_um']:.1f} µm)" if two else
            f"none (gap ≤ {j['max_branch_gap_um']:.1f} µm)")


def _load_text(v, mode, torque="100", within=150.0):
    res = v["resonance_rpm"].get(mode)
    near = [k for k in v["traced"] if k.startswith(torque + "@")
            and res is not None and abs(float(k.split("@")[1]) - res) <= within]
    if res is None or not near:
        return "not traced"
    k = min(near, key=lambda s: abs(float(s.split("@")[1]) - res))
    away = v["traced"].get(f"{torque}@5000")
    a = v["traced"][k]
    text = (f"{k.split('@')[1]} rpm: contact lost {100 * a['contact_loss_fraction']:.0f} %, "
            f"{a['W_t_mean_contact_N']:.0f} N in contact, mu {a['mu_mean']:.4f}")
    if away and k != f"{torque}@5000":
        text += (f" (5000 rpm: {away['W_t_mean_contact_N']:.0f} N, mu "
                 f"{away['mu_mean']:.4f})")
    return text


def whatif_rows(det):
    """The side-by-side table of the what-if: the paper's Figs. 8-10, the reference (Table 3)
    and each what-if, from findings.details."""
    variants = [("Table 3 (I_p = 0.014 kg·m²)", det["reference"])] + [
        (", ".join(f"{k} = {v:g}" for k, v in w["where"].items()), w) for w in det["whatif"]]
    if not det["whatif"]:
        return []
    ts = list(det["reference"]["torques"])
    torques = "/".join(ts)

    def each(fmt):
        return lambda v: _per_torque(v, fmt, ts)

    def dips(mode):
        return each(lambda d: f"{100 * d[mode]['dip']:.3f}"
                    if mode in d and np.isfinite(d[mode]["dip"]) else "–")

    rows = [
        ("resonance speeds, mode 2 / mode 3 [rpm]", "–",
         lambda v: " / ".join(f"{v['resonance_rpm'][m]:.0f}" for m in ("f2", "f3"))),
        (f"strongest DTE peak at {torques} N·m [rpm: µm p-p]", PAPER_COLUMN["strongest"],
         each(lambda d: f"{d['peak_rpm']:g}: {d['peak_DTE_pp_um']:.0f}")),
        (f"efficiency dip at mode 3, {torques} N·m [%-points]", PAPER_COLUMN["dip_f3"],
         dips("f3")),
        (f"efficiency dip at mode 2, {torques} N·m [%-points]", PAPER_COLUMN["dip_f2"],
         dips("f2")),
        (f"min DTE − b near mode 3, {torques} N·m [µm]", "below 0 at 100 N·m",
         each(lambda d: f"{d['f3']['DTE_min_minus_b_um']:.1f}")),
        (f"tooth separation (grid speeds), {torques} N·m", PAPER_COLUMN["separation"],
         each(lambda d: _band(d["separation_rpm"]))),
        ("jump (two branches) near mode 3, swept torques", PAPER_COLUMN["jump"],
         lambda v: "; ".join(f"{t} N·m: {_jump_text(d, 'f3')}" for t, d in v["torques"].items()
                             if "jump" in d.get("f3", {}))),
        ("jump near mode 2, swept torques", "not reported",
         lambda v: "; ".join(f"{t} N·m: {_jump_text(d, 'f2')}" for t, d in v["torques"].items()
                             if "jump" in d.get("f2", {})) or "not swept"),
        ("one engagement near mode 3, 100 N·m (Fig. 10)", PAPER_COLUMN["load"],
         lambda v: _load_text(v, "f3")),
        ("the same at 50 N·m", "–", lambda v: _load_text(v, "f3", "50")),
    ]
    head = "| | paper (Figs. 8–10) | " + " | ".join(n for n, _ in variants) + " |"
    lines = [head, "|" + "---|" * (2 + len(variants))]
    for label, paper, fn in rows:
        lines.append(f"| {label} | {paper} | " + " | ".join(fn(v) or "–" for _, v in variants)
                     + " |")
    return lines


def _whatif_section(det, figs):
    lines = whatif_rows(det)
    if not lines:
        return []
    L = ["## What-if: the pinion inertia from the pinion's geometry", "",
         "Gear set 1 with only the pinion inertia changed (everything else Table 3's and the "
         "study's), beside the reference and the paper. Dips are below the chord between the "
         f"grid speeds {fd.EDGE_RPM:g} rpm either side of each resonance; 'contact lost' is the "
         "share of the window with the teeth apart; b is the half backlash.", "", *lines, ""]
    for key in [k for k in figs if k.startswith(("fig8_", "fig9_", "fig10_"))]:
        number, rest = key[3:].split("_", 1)
        torque = f", {rest.rsplit('_', 1)[1]} N·m" if number == "10" else ""
        _image(L, figs, key, f"What-if: paper Fig. {number}{torque} with the pinion inertia "
               "from its geometry.")
    return L
