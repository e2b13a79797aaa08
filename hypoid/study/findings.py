"""The paper's findings (Paouris et al. 2016, §3) as numbers computed from study tables, with a
verdict each. Used by the report and by tests/python/test_paper_findings.py (same functions, a
smaller grid). Efficiency is eta_rms, the RMS over 50 mesh cycles of steady state."""

import numpy as np
import pandas as pd

from hypoid.study.tables import (BUILTIN_LUBRICANTS, PAPER_EHL, REFERENCE, calibration_probes, curve,  # noqa: F401
                           prepare, resonances, select, whatifs)

DIP_MIN = 2e-4  # an efficiency dip counts when 0.02 percentage points below the trend
FADE = 0.35  # ... and has faded when below this fraction of the low-torque dips
EDGE_RPM = 200.0  # the trend is the chord between the grid speeds this far from the resonance
BAND_RPM = 120.0  # the dip is looked for within this distance of the resonance
BRANCH_MIN_UM = 3.0  # up and down DTE peak-to-peak differ by this much: two branches


# ---------------------------------------------------------------------------- selection
def reference_lubricants(df, torque=100.0):
    """eta_rms by speed for OS265962, OS265963 and the swapped-alpha* variant (gear set 1)."""
    base = dict(gear_set=1, T_s=torque)
    one = curve(df, gear_set=1, T_s=torque, lubricant=1, lubricant_file="")
    two = curve(df, gear_set=1, T_s=torque, lubricant=2, lubricant_file="")
    files = select(df, **base)
    files = files[files["lubricant_file"] != ""] if "lubricant_file" in files else files.iloc[:0]
    swap = files.groupby("speed_rpm")["eta_rms"].mean().sort_index()
    return one, two, swap


def speed_range(speeds):
    """'1150 rpm' for one speed, '1150-1200 rpm' for several."""
    lo, hi = min(speeds), max(speeds)
    return f"{lo:g} rpm" if lo == hi else f"{lo:g}-{hi:g} rpm"


# ---------------------------------------------------------------------------- measures
def dip(eta, n_res):
    """Depth of the efficiency dip at a resonance: the largest drop of eta below the chord
    between the grid speeds EDGE_RPM either side; nan when the grid does not bracket it."""
    s = eta.dropna()
    lo = s[s.index <= n_res - EDGE_RPM]
    hi = s[s.index >= n_res + EDGE_RPM]
    inner = s[(s.index - n_res).__abs__() <= BAND_RPM]
    if lo.empty or hi.empty or inner.empty:
        return float("nan")
    (n0, e0), (n1, e1) = (lo.index[-1], lo.iloc[-1]), (hi.index[0], hi.iloc[0])
    chord = e0 + (e1 - e0) * (inner.index.to_numpy() - n0) / (n1 - n0)
    return float(np.max(chord - inner.to_numpy()))


def branches(cont, gear_set, torque, **where):
    """Up and down branches of a continuation sweep merged by speed."""
    sel = select(cont, gear_set=gear_set, T_s=torque, **where)
    if sel.empty:
        return pd.DataFrame()
    cols = ["DTE_pp_um", "DTE_min_minus_b_um", "contact_loss_fraction", "eta_rms"]
    up = sel[sel["branch"] == "up"].groupby("speed_rpm")[cols].mean()
    down = sel[sel["branch"] == "down"].groupby("speed_rpm")[cols].mean()
    return up.merge(down, left_index=True, right_index=True, suffixes=("_up", "_down"))


def jump(cont, gear_set, torque, n_res, half_width=250.0, **where):
    """Two-branch (hysteresis) band and separation near a resonance."""
    b = branches(cont, gear_set, torque, **where)
    if b.empty:
        return None
    b = b[(b.index - n_res).__abs__() <= half_width]
    if b.empty:
        return None
    diff = (b["DTE_pp_um_up"] - b["DTE_pp_um_down"]).abs()
    two = b[diff > BRANCH_MIN_UM]
    return {"speeds_two_branches": [float(x) for x in two.index],
            "max_branch_gap_um": float(diff.max()),
            "max_DTE_pp_um": float(max(b["DTE_pp_um_up"].max(), b["DTE_pp_um_down"].max())),
            "min_DTE_min_minus_b_um": float(min(b["DTE_min_minus_b_um_up"].min(),
                                                b["DTE_min_minus_b_um_down"].min())),
            "max_contact_loss": float(max(b["contact_loss_fraction_up"].max(),
                                          b["contact_loss_fraction_down"].max()))}


# ---------------------------------------------------------------------------- findings
def _where(where):
    return "".join(f", {k} = {v:g}" for k, v in where.items())


def _finding(fid, figure, paper, measure, ok, at=""):
    verdict = "diagnostic" if ok is None else ("reproduced" if ok else "not reproduced")
    return {"id": fid, "figure": figure, "paper": paper, "at": at, "this FMU": measure,
            "verdict": verdict}


def lubricant_ranking(pts, torque=100.0):
    one, two, _ = reference_lubricants(pts, torque)
    gap = (one - two).dropna()
    if gap.empty:
        return _finding("F1", "6a", "OS265963 (higher alpha*) less efficient at every speed",
                        "no data", None)
    return _finding("F1", "6a", "OS265963 (higher alpha*) less efficient at every speed",
                    f"eta(OS265962) - eta(OS265963) = {100 * gap.min():.3f} to "
                    f"{100 * gap.max():.3f} %-points over {len(gap)} speeds "
                    f"({speed_range(gap.index)})", bool((gap > 0).all()),
                    f"{torque:g} N·m")


def swapped_alpha(pts, torque=100.0):
    one, two, swap = reference_lubricants(pts, torque)
    closure = ((swap - two) / (one - two)).dropna()
    text = "OS265963 with OS265962's alpha* data is almost as efficient as OS265962"
    if closure.empty:
        return _finding("F2", "7", text, "no data", None)
    return _finding("F2", "7", text,
                    f"share of the efficiency gap closed: {100 * closure.min():.0f} to "
                    f"{100 * closure.max():.0f} % (median {100 * closure.median():.0f} %) over "
                    f"{len(closure)} speeds", bool((closure >= 0.5).all()), f"{torque:g} N·m")


def resonance_dips(pts, mode, gear_set=1, low=(50.0, 100.0), high=(200.0, 300.0), suffix="",
                   **where):
    """Dip at the resonance of `mode` ('f2' or 'f3') for each torque, and the verdict."""
    n_res = resonances(pts, gear_set, **where).get(mode)
    if n_res is None:
        return None, {}
    dips = {t: dip(curve(pts, gear_set=gear_set, lubricant=1, lubricant_file="", T_s=t,
                         **where), n_res) for t in (*low, *high)}
    lo = [dips[t] for t in low]
    hi = [dips[t] for t in high]
    ok = None
    if all(np.isfinite(lo + hi)):
        ok = min(lo) > DIP_MIN and max(hi) < FADE * min(lo)
    measure = ", ".join(f"{t:g} N·m: {100 * d:.3f}" for t, d in dips.items())
    return _finding(f"F3-{mode}{suffix}", "6a, 8",
                    "efficiency dips near the mesh resonance at 50 and 100 N·m; the dip fades at "
                    "200 and 300 N·m", f"dip below the trend [%-points] {measure}", ok,
                    f"{n_res:.0f} rpm (mode {mode[1]})" + _where(where)), dips


def jump_finding(cont, torque, mode, pts, gear_set=1, suffix="", **where):
    n_res = resonances(pts, gear_set, **where).get(mode)
    j = jump(cont, gear_set, torque, n_res, **where) if n_res else None
    text = ("jump phenomenon: two DTE branches near resonance, DTE minimum below the half "
            "backlash (tooth separation)")
    if j is None:
        return _finding(f"F4-{mode}-{torque:g}{suffix}", "9", text, "no data", None), None
    two = j["speeds_two_branches"]
    band = speed_range(two) if two else "none"
    ok = bool(two) and j["min_DTE_min_minus_b_um"] < 0
    return _finding(f"F4-{mode}-{torque:g}{suffix}", "9", text,
                    f"two branches: {band} (largest up/down gap {j['max_branch_gap_um']:.1f} µm);"
                    f" min(DTE) - b = {j['min_DTE_min_minus_b_um']:.1f} µm; contact lost up to "
                    f"{100 * j['max_contact_loss']:.0f} % of the time", ok,
                    f"{torque:g} N·m near {n_res:.0f} rpm (mode {mode[1]})" + _where(where)), j


def away_from_resonance(speeds, res, margin=150.0):
    s = np.asarray(speeds, float)
    return np.all([np.abs(s - n) > margin for n in res.values()], axis=0)


def gear_sets(pts, torque=100.0):
    e2 = curve(pts, gear_set=2, lubricant=1, lubricant_file="", T_s=torque)
    e3 = curve(pts, gear_set=3, lubricant=1, lubricant_file="", T_s=torque)
    d = (e2 - e3).dropna()
    text = "gear set 2 more efficient than gear set 3 away from resonance"
    if d.empty:
        return _finding("F5", "11a", text, "no data", None)
    away = away_from_resonance(d.index, resonances(pts, 2)) & away_from_resonance(
        d.index, resonances(pts, 3))
    da = d[away]
    if da.empty:
        return _finding("F5", "11a", text, "no speeds away from resonance", None)
    return _finding("F5", "11a", text,
                    f"eta(set 2) - eta(set 3) = {100 * da.min():.3f} to {100 * da.max():.3f} "
                    f"%-points at {len(da)} speeds away from resonance (all speeds: "
                    f"{100 * d.min():.3f} to {100 * d.max():.3f})", bool((da > 0).all()),
                    f"{torque:g} N·m")


def gear_set_dte(pts, torque=100.0, band=(1000.0, 2000.0)):
    """Fig. 11b: between 1000 and 2000 rpm gear set 2 has the larger DTE amplitudes."""
    p2 = curve(pts, "DTE_pp_um", gear_set=2, lubricant=1, lubricant_file="", T_s=torque)
    p3 = curve(pts, "DTE_pp_um", gear_set=3, lubricant=1, lubricant_file="", T_s=torque)
    d = pd.DataFrame({"2": p2, "3": p3}).dropna()
    d = d[(d.index >= band[0]) & (d.index <= band[1])]
    text = "gear set 2 has large DTE amplitudes (resonance) at 1000-2000 rpm, set 3 smaller"
    if d.empty:
        return _finding("F8", "11b", text, "no data", None)
    share = float((d["2"] > d["3"]).mean())
    return _finding("F8", "11b", text,
                    f"largest DTE p-p in {speed_range(band)}: set 2 {d['2'].max():.1f} µm "
                    f"at {d['2'].idxmax():g} rpm, set 3 {d['3'].max():.1f} µm at "
                    f"{d['3'].idxmax():g} rpm; set 2 larger at {100 * share:.0f} % of "
                    f"{len(d)} speeds", bool(d["2"].max() > d["3"].max() and share > 0.5),
                    f"{torque:g} N·m")


def regime_finding(pts, trace_dir, speed=1000.0):
    """Fig. 5 (diagnostic): the highly loaded points of the cycle lie in hard EHL (PE)."""
    from hypoid.study import regime, results

    sel = select(pts, gear_set=1, lubricant=1, lubricant_file="", speed_rpm=speed)
    text = "most highly loaded points of the cycle are in the piezoviscous-elastic regime"
    if "trace" not in sel or trace_dir is None:
        return None
    parts = []
    share_pe = []
    for row in sel[sel["trace"].fillna("").astype(str) != ""].itertuples():
        tr = results.read_trace(trace_dir, row.point_key)
        if tr is None:
            continue
        s = regime.pair_samples(tr)
        cls = regime.classify(s["g_V"], s["g_E"], s["alpha_r"])
        high = s["W"] > 0.5 * s["W"].max()
        counts = {r: float(np.mean(cls[high] == i)) for i, r in enumerate(regime.REGIMES)}
        share_pe.append(counts["PE"])
        parts.append(f"{row.T_s:g} N·m: " + ", ".join(f"{r} {100 * v:.0f} %"
                                                      for r, v in counts.items() if v > 0))
    if not parts:
        return None
    return _finding("F7", "5", text, "pairs above half the peak load: " + "; ".join(parts)
                    + " (substitute Hamrock-Dowson map, docs/physics.md §7; diagnostic)",
                    None, f"{speed:g} rpm")


def contact_loss_at(pts, speed, torque=100.0, gear_set=1, **where):
    sel = select(pts, gear_set=gear_set, lubricant=1, lubricant_file="", T_s=torque,
                 speed_rpm=speed, **where)
    return None if sel.empty else sel.iloc[0]


def resonance_load(pts, near, away=5000.0, torque=100.0, fid="F6", **where):
    """Fig. 10: near resonance, contact is lost part of the cycle, the mean load while in
    contact and the mean friction coefficient are higher than away from resonance."""
    a, b = contact_loss_at(pts, near, torque, **where), contact_loss_at(pts, away, torque, **where)
    text = ("near resonance the teeth separate during the cycle (zero friction), and the mean "
            "contact load and friction coefficient are higher than away from resonance")
    if a is None or b is None:
        return _finding(fid, "10", text, "no data", None, f"{near:g} vs {away:g} rpm")
    ok = bool(a["contact_loss_fraction"] > 0 and a["W_t_mean_contact_N"] > b["W_t_mean_contact_N"]
              and a["mu_mean"] > b["mu_mean"])
    return _finding(fid, "10", text,
                    f"contact lost {100 * a['contact_loss_fraction']:.0f} % vs "
                    f"{100 * b['contact_loss_fraction']:.0f} % of the time; mean load in contact "
                    f"{a['W_t_mean_contact_N']:.0f} vs {b['W_t_mean_contact_N']:.0f} N; mean mu "
                    f"{a['mu_mean']:.4f} vs {b['mu_mean']:.4f}", ok,
                    f"{torque:g} N·m, {near:g} vs {away:g} rpm" + _where(where))


def all_findings(pts, cont, trace_dir=None):
    """Every finding the tables allow, as a DataFrame (one row each)."""
    pts, cont = prepare(pts), prepare(cont)
    rows = [lubricant_ranking(pts), swapped_alpha(pts)]
    rows += resonance_findings(pts, cont)
    for e0 in calibration_probes(pts):
        for mode in ("f2", "f3"):
            f, _ = resonance_dips(pts, mode, suffix=f"-e0x{e0:g}", e_0_scale=e0)
            if f:
                rows.append(f)
    rows.append(gear_sets(pts))
    rows.append(gear_set_dte(pts))
    for where in whatifs(pts):
        rows += resonance_findings(pts, cont, suffix=_suffix(where), **where)
    rows.append(regime_finding(pts, trace_dir))
    return pd.DataFrame([r for r in rows if r])


def _suffix(where):
    return "".join(f"-{k}={v:g}" for k, v in where.items())


def resonance_findings(pts, cont, suffix="", **where):
    """F3, F4 and F6 at both mesh resonances of gear set 1 (of a what-if when `where` sets
    its parameters)."""
    rows = []
    for mode in ("f2", "f3"):
        f, _ = resonance_dips(pts, mode, suffix=suffix, **where)
        if f:
            rows.append(f)
    if not cont.empty:
        for t in sorted(select(cont, gear_set=1, **where)["T_s"].unique()):
            for mode in ("f2", "f3"):
                f, j = jump_finding(cont, t, mode, pts, suffix=suffix, **where)
                if j is not None or not suffix:  # a what-if's sweeps cover its mode 3 only
                    rows.append(f)
    for mode, n in sorted(resonances(pts, 1, **where).items()):
        near = _nearest_speed(pts, n, **where)
        if near is not None:
            rows.append(resonance_load(pts, near, fid=f"F6-{mode}{suffix}", **where))
    return rows


def _nearest_speed(pts, n, torque=100.0, **where):
    s = curve(pts, gear_set=1, lubricant=1, lubricant_file="", T_s=torque, **where)
    if s.empty:
        return None
    return float(s.index[np.argmin(np.abs(s.index - n))])


# ---------------------------------------------------------------------------- detail numbers
def _pair_peak(trace_dir, row):
    """Tooth pair 1's peak contact load over the traced window [N], or None."""
    from hypoid.study import results

    key = getattr(row, "point_key", None)
    if trace_dir is None or not key:
        return None
    tr = results.read_trace(trace_dir, key)
    return None if tr is None or "pair[1].W" not in tr else float(tr["pair[1].W"].max())


def _row_numbers(row, trace_dir):
    out = {k: float(getattr(row, k)) for k in
           ("eta_rms", "DTE_pp_um", "DTE_min_minus_b_um", "contact_loss_fraction",
            "W_t_mean_contact_N", "mu_mean", "h_c_mean_um", "lambda_mean")}
    out["pair_peak_N"] = _pair_peak(trace_dir, row)
    return out


def variant_numbers(pts, cont, trace_dir=None, **where):
    """The numbers docs/records/paper-findings.md quotes for gear set 1 at the reference inertias or a
    what-if: resonance speeds; per torque the strongest DTE peak, the DTE, separation and dip at
    each resonance, and the continuation's branches; the traced points near and away from
    resonance (Fig. 10)."""
    res = resonances(pts, 1, **where)
    out = {"resonance_rpm": res, "torques": {}, "traced": {}}
    for t in sorted(select(pts, gear_set=1, lubricant=1, lubricant_file="", **where)["T_s"]
                    .unique()):
        sel = select(pts, gear_set=1, lubricant=1, lubricant_file="", T_s=t, **where)
        by = sel.groupby("speed_rpm").mean(numeric_only=True).sort_index()
        lost = by[by["contact_loss_fraction"] > 0]
        d = {"peak_rpm": float(by["DTE_pp_um"].idxmax()), "peak_DTE_pp_um":
             float(by["DTE_pp_um"].max()),
             "separation_rpm": [float(x) for x in lost.index],
             "max_contact_loss": float(by["contact_loss_fraction"].max())}
        for mode, n in res.items():
            near = float(by.index[np.argmin(np.abs(by.index - n))])
            r = by.loc[near]
            d[mode] = {"rpm": near, "DTE_pp_um": float(r["DTE_pp_um"]),
                       "DTE_min_minus_b_um": float(r["DTE_min_minus_b_um"]),
                       "contact_loss_fraction": float(r["contact_loss_fraction"]),
                       "dip": dip(by["eta_rms"], n)}
            j = jump(cont, 1, t, n, **where) if not cont.empty else None
            if j is not None:
                d[mode]["jump"] = j
        out["torques"][f"{t:g}"] = d
    if "trace" in pts:
        tr = select(pts, gear_set=1, lubricant=1, lubricant_file="", **where)
        tr = tr[tr["trace"].fillna("").astype(str) != ""]
        for row in tr.sort_values(["T_s", "speed_rpm"]).itertuples():
            out["traced"][f"{row.T_s:g}@{row.speed_rpm:g}"] = _row_numbers(row, trace_dir)
    return out


def gear_set_numbers(pts, torque=100.0):
    """Fig. 11's explanation: mean load in contact, friction and film of sets 2 and 3 over the
    speeds away from their resonances, and their lever arms."""
    out = {}
    for gs in (2, 3):
        sel = select(pts, gear_set=gs, lubricant=1, lubricant_file="", T_s=torque)
        if sel.empty:
            continue
        away = sel[away_from_resonance(sel["speed_rpm"], resonances(pts, gs))]
        out[str(gs)] = {"R_p0_mm": float(1e3 * sel["R_p0"].iloc[0]) if "R_p0" in sel else None,
                        "W_t_mean_contact_N": float(away["W_t_mean_contact_N"].mean()),
                        "mu_mean": float(away["mu_mean"].mean()),
                        "lambda_mean": float(away["lambda_mean"].mean())}
    return out


def probe_numbers(pts, e0):
    """The calibration probe (e_0_scale = e0): per torque the dip and the contact loss at the
    grid speed nearest each resonance of gear set 1."""
    out = {}
    for t in sorted(select(pts, gear_set=1, e_0_scale=e0)["T_s"].unique()):
        by = select(pts, gear_set=1, lubricant=1, lubricant_file="", T_s=t, e_0_scale=e0) \
            .groupby("speed_rpm").mean(numeric_only=True).sort_index()
        d = {}
        for mode, n in resonances(pts, 1).items():
            near = float(by.index[np.argmin(np.abs(by.index - n))])
            d[mode] = {"rpm": near, "dip": dip(by["eta_rms"], n),
                       "contact_loss_fraction": float(by.loc[near, "contact_loss_fraction"]),
                       "DTE_min_minus_b_um": float(by.loc[near, "DTE_min_minus_b_um"])}
        out[f"{t:g}"] = d
    return out


def lubricant_numbers(pts, torque=100.0):
    """Fig. 7's residual: eta(OS265962) - eta(OS265963 with OS265962's alpha*) by speed."""
    one, _, swap = reference_lubricants(pts, torque)
    res = (one - swap).dropna()
    return {f"{n:g}": float(v) for n, v in res.items()}


def sensitivity_numbers(pts, extra, torque=100.0):
    """eta_rms by speed of the reference and of each sensitivity variant (label, params) of a
    study, gear set 1 at `torque` (the full study's table)."""
    out = {"reference": {f"{n:g}": float(v) for n, v in
                         curve(pts, gear_set=1, lubricant=1, lubricant_file="", T_s=torque)
                         .items()}}
    for label, params in extra:
        if "e_0_scale" in params:
            continue  # the calibration probe has its own numbers
        sel = select(pts, gear_set=1, T_s=torque, **params)
        if "lubricant" not in params:
            sel = sel[(sel["lubricant"] == 1) & (sel["lubricant_file"] == "")]
        out[label] = {f"{n:g}": float(v) for n, v in
                      sel.groupby("speed_rpm")["eta_rms"].mean().items()}
    return out


def details(pts, cont, trace_dir=None, extra=()):
    """Every detail number of docs/records/paper-findings.md, as plain data (JSON-able); `extra`: the
    study's sensitivity variants (label, params)."""
    pts, cont = prepare(pts), prepare(cont)
    return {"reference": variant_numbers(pts, cont, trace_dir),
            "whatif": [{"where": w, **variant_numbers(pts, cont, trace_dir, **w)}
                       for w in whatifs(pts)],
            "gear_sets": gear_set_numbers(pts),
            "lubricants": lubricant_numbers(pts),
            "probes": {f"{e0:g}": probe_numbers(pts, e0) for e0 in calibration_probes(pts)},
            "sensitivity": sensitivity_numbers(pts, extra) if extra else {}}
