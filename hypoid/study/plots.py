"""Figures of a study, after the paper's Figs. 5-11, from the tidy tables and traces. Each
function writes one PNG and returns its path (or None when the tables lack the data)."""

import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from hypoid.study import regime, results  # noqa: E402
from hypoid.study import tables as tb  # noqa: E402

DPI = 120
# zlib's level for the PNGs: the same pixels as the default 6 in slightly larger files, for less
# of the encoding's CPU (docs/decisions.md, "The study's figures")
PNG_COMPRESS_LEVEL = 4
TORQUE_COLORS = {50.0: "tab:red", 100.0: "tab:blue", 200.0: "tab:green", 300.0: "tab:purple"}
LUB_COLORS = ["tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple"]
SET_COLORS = {1: "tab:blue", 2: "tab:orange", 3: "tab:green"}


def _save(fig, out, name):
    """out/name.png at DPI, cropped to what the figure draws plus savefig.pad_inches: the picture
    of bbox_inches="tight", byte for byte, without the extra draw that savefig makes to measure
    the figure (get_tightbbox lays it out to measure it, without drawing it)."""
    out = pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    path = out / f"{name}.png"
    fig.set_dpi(DPI)  # measured at the resolution it is drawn at
    bbox = fig.get_tightbbox(fig.canvas.get_renderer())
    fig.savefig(path, dpi=DPI, bbox_inches=bbox.padded(matplotlib.rcParams["savefig.pad_inches"]),
                pil_kwargs={"compress_level": PNG_COMPRESS_LEVEL})
    plt.close(fig)
    return path


def _resonance_lines(ax, pts, gear_set=1, color="0.45", label=True, y=0.99, **where):
    for mode, n in tb.resonances(pts, gear_set, **where).items():
        ax.axvline(n, color=color, ls=":", lw=1.2, zorder=0)
        if label:
            ax.text(n, y, f" mode {mode[1]}\n {n:.0f} rpm", transform=ax.get_xaxis_transform(),
                    va="top", ha="left", fontsize=7.5, color=color)


def _inertias(where):
    """The what-if part of a selection (its resonances differ from the reference's)."""
    return {k: v for k, v in where.items() if k in tb.WHATIF_COLUMNS}


def _eta_axis(ax):
    ax.set_ylabel("efficiency $\\eta_{RMS}$ [%]")
    ax.grid(True, alpha=0.3)


def fig8_torque(pts, out, name="fig8_efficiency_torque", note="", **where):
    """Efficiency and DTE peak-to-peak vs pinion speed per input torque (paper Fig. 8)."""
    base = tb.select(pts, gear_set=1, lubricant=1, lubricant_file="", **where)
    if base.empty:
        return None
    fig, ax = plt.subplots(2, 1, figsize=(9, 8.5), sharex=True,
                           gridspec_kw={"height_ratios": [3, 2]})
    for t, sel in base.groupby("T_s"):
        sel = sel.sort_values("speed_rpm")
        c = TORQUE_COLORS.get(t)
        ax[0].plot(sel["speed_rpm"], 100 * sel["eta_rms"], "-o", ms=3.5, color=c,
                   label=f"{t:g} N·m")
        ax[1].plot(sel["speed_rpm"], sel["DTE_pp_um"], "-o", ms=3.5, color=c, label=f"{t:g} N·m")
    lost = base[base["contact_loss_fraction"] > 0]
    if len(lost):
        ax[0].plot(lost["speed_rpm"], 100 * lost["eta_rms"], "o", mfc="none", mec="k", ms=9,
                   label="contact lost")
        ax[1].plot(lost["speed_rpm"], lost["DTE_pp_um"], "o", mfc="none", mec="k", ms=9)
    for a in ax:
        _resonance_lines(a, pts, **_inertias(where))
        a.grid(True, alpha=0.3)
    _eta_axis(ax[0])
    ax[0].legend(title="input torque T_s", ncol=5, fontsize=8, loc="lower right")
    ax[0].set_title("Efficiency vs pinion speed, OS265962, 40 °C, gear set 1 (paper Fig. 8)"
                    + (f"\n{note}" if note else ""))
    ax[1].set_ylabel("DTE peak-to-peak [µm]")
    ax[1].set_xlabel("pinion speed [rpm]")
    return _save(fig, out, name)


def _lub_curves(pts, torque=100.0):
    sel = tb.select(pts, gear_set=1, T_s=torque)
    return {name: g.sort_values("speed_rpm") for name, g in sel.groupby("lubricant_name")}


def fig6_lubricants(pts, out, torque=100.0):
    """Efficiency vs speed per lubricant (paper Fig. 6a), built-in oils only."""
    curves = {k: v for k, v in _lub_curves(pts, torque).items()
              if (v["lubricant_file"] == "").all()}
    if len(curves) < 2:
        return None
    fig, ax = plt.subplots(figsize=(9, 5))
    for (name, g), c in zip(curves.items(), LUB_COLORS):
        ax.plot(g["speed_rpm"], 100 * g["eta_rms"], "-o", ms=3.5, color=c, label=name)
    _resonance_lines(ax, pts)
    _eta_axis(ax)
    ax.set_xlabel("pinion speed [rpm]")
    ax.legend(loc="lower right")
    ax.set_title(f"Efficiency per lubricant, T_s = {torque:g} N·m, 40 °C, gear set 1 "
                 "(paper Fig. 6a)")
    return _save(fig, out, "fig6a_efficiency_lubricants")


def fig7_swapped(pts, out, torque=100.0):
    """OS265962, OS265963 and OS265963 with OS265962's alpha* (paper Fig. 7)."""
    curves = _lub_curves(pts, torque)
    one = [k for k in curves if k == "OS265962"]
    swap = [k for k, v in curves.items() if (v["lubricant_file"] != "").all()]
    if not one or not swap or "OS265963" not in curves:
        return None
    names = ["OS265962", "OS265963"] + swap
    ref = curves["OS265962"].set_index("speed_rpm")["eta_rms"]
    fig, ax = plt.subplots(2, 1, figsize=(9, 8), sharex=True)
    for name, c, st in zip(names, LUB_COLORS, ["-o", "-s", "--^"]):
        g = curves[name]
        ax[0].plot(g["speed_rpm"], 100 * g["eta_rms"], st, ms=4, color=c, label=name)
        d = g.set_index("speed_rpm")["eta_rms"] - ref
        ax[1].plot(d.index, 100 * d.to_numpy(), st, ms=4, color=c, label=name)
    for a in ax:
        _resonance_lines(a, pts)
        a.grid(True, alpha=0.3)
    _eta_axis(ax[0])
    ax[0].legend(loc="lower right")
    ax[0].set_title(f"Common pressure-viscosity response, T_s = {torque:g} N·m, 40 °C "
                    "(paper Fig. 7)")
    ax[1].set_ylabel("$\\eta - \\eta_{OS265962}$ [%-points]")
    ax[1].set_xlabel("pinion speed [rpm]")
    return _save(fig, out, "fig7_swapped_alpha")


def fig9_jump(cont, pts, out, name="fig9_dte_jump", note="", **where):
    """DTE peak response (max and min) on the up and down branches with the half backlash
    (paper Fig. 9), one panel per torque."""
    sel = tb.select(cont, gear_set=1, **where)
    if sel.empty:
        return None
    torques = sorted(sel["T_s"].unique())
    fig, axes = plt.subplots(len(torques), 1, figsize=(9, 4.2 * len(torques)), sharex=True,
                             squeeze=False)
    for ax, t in zip(axes[:, 0], torques):
        g = sel[sel["T_s"] == t]
        for branch, style, mk in (("up", "-", "^"), ("down", "--", "v")):
            b = g[g["branch"] == branch].sort_values("speed_rpm")
            ax.plot(b["speed_rpm"], b["DTE_max_um"], style, marker=mk, ms=4, color="tab:blue",
                    label=f"max DTE, speed {branch}")
            ax.plot(b["speed_rpm"], b["DTE_min_um"], style, marker=mk, ms=4, color="tab:red",
                    label=f"min DTE, speed {branch}")
        b_um = float(g["b_um"].iloc[0])
        ax.axhline(b_um, color="k", lw=1.2, label=f"half backlash b = {b_um:g} µm")
        lost = g[g["contact_loss_fraction"] > 0]
        ax.plot(lost["speed_rpm"], lost["DTE_min_um"], "o", mfc="none", mec="k", ms=9,
                label="contact lost")
        _resonance_lines(ax, pts, **where)
        ax.set_ylabel("DTE [µm]")
        ax.grid(True, alpha=0.3)
        ax.set_title(f"T_s = {t:g} N·m: speed swept up then down (continuation)", fontsize=10)
    axes[-1, 0].set_xlabel("pinion speed [rpm]")
    fig.suptitle("DTE peak response, OS265962, 40 °C, gear set 1 (paper Fig. 9)"
                 + (f"\n{note}" if note else ""))
    # below the panels, where it hides neither data nor the resonance labels
    handles, labels = axes[0, 0].get_legend_handles_labels()
    fig.legend(handles, labels, fontsize=8, ncol=3, loc="lower center")
    fig.tight_layout(rect=(0, 0.07 / len(torques) + 0.02, 1, 0.98))
    return _save(fig, out, name)


def engagement(trace, pair=1):
    """The last complete engagement period of a pair (3 mesh cycles) of a trace: x in mesh
    cycles (0-3) from the pair's phase, and the trace rows."""
    theta = trace["theta"].to_numpy()
    period = 6 * np.pi
    k = np.floor(theta[-1] / period)
    rows = (theta >= (k - 1) * period) & (theta < k * period)
    x = theta[rows] / (2 * np.pi) - 3 * (k - 1) - (pair - 1)
    x = np.mod(x, 3.0)
    order = np.argsort(x)
    return x[order], trace[rows].iloc[order]


def fig10_mesh_cycle(pts, out, torque=100.0, name="fig10_mesh_cycle", note="", **where):
    """Contact load and friction coefficient of one tooth pair over its engagement near and
    away from resonance (paper Fig. 10)."""
    sel = tb.select(pts, gear_set=1, lubricant=1, lubricant_file="", T_s=torque, **where)
    if "trace" not in sel:
        return None
    sel = sel[sel["trace"].fillna("").astype(str) != ""].sort_values("speed_rpm")
    if sel.empty:
        return None
    fig, ax = plt.subplots(2, 1, figsize=(9, 8), sharex=True)
    root = pathlib.Path(out).parent
    for row, c in zip(sel.itertuples(), LUB_COLORS):
        tr = results.read_trace(root / "traces", row.point_key)
        if tr is None:
            continue
        x, r = engagement(tr)
        w, mu = r["pair[1].W"].to_numpy(), r["pair[1].mu"].to_numpy()
        lab = (f"{row.speed_rpm:g} rpm (contact lost {100 * row.contact_loss_fraction:.0f} %)")
        ax[0].plot(x, w / 1e3, color=c, label=lab)
        on = w > 1.0
        ax[1].plot(x, np.where(on, mu, 0.0), color=c,
                   label=f"{row.speed_rpm:g} rpm, mu_mean {row.mu_mean:.4f}")
    ax[0].set_ylabel("tooth pair 1 contact load [kN]")
    ax[1].set_ylabel("tooth pair 1 friction coefficient [-]")
    ax[1].set_xlabel("engagement cycle of pair 1 [mesh cycles]")
    for a in ax:
        a.grid(True, alpha=0.3)
        a.legend(fontsize=8, loc="upper right")
    ax[1].legend(fontsize=8, loc="upper right", title_fontsize=8,
                 title="mu_mean: load-weighted over all pairs and the window (as in the table)")
    ax[0].set_title(f"One tooth pair over its engagement, T_s = {torque:g} N·m, OS265962, "
                    "gear set 1 (paper Fig. 10)" + (f"\n{note}" if note else ""))
    return _save(fig, out, name)


def fig11_gear_sets(pts, out, torque=100.0):
    """Efficiency and DTE peak-to-peak of gear sets 2 and 3 (paper Fig. 11)."""
    sel = tb.select(pts, lubricant=1, lubricant_file="", T_s=torque)
    sel = sel[sel["gear_set"].isin([2, 3])]
    if sel["gear_set"].nunique() < 2:
        return None
    fig, ax = plt.subplots(2, 1, figsize=(9, 8), sharex=True)
    for gs, g in sel.groupby("gear_set"):
        g = g.sort_values("speed_rpm")
        c = SET_COLORS[gs]
        lab = f"gear set {gs} (ratio {g['ratio'].iloc[0]:.2f})"
        ax[0].plot(g["speed_rpm"], 100 * g["eta_rms"], "-o", ms=3.5, color=c, label=lab)
        ax[1].plot(g["speed_rpm"], g["DTE_pp_um"], "-o", ms=3.5, color=c, label=lab)
        for a in ax:
            _resonance_lines(a, pts, gs, color=c, y=0.99 if gs == 2 else 0.87)
    _eta_axis(ax[0])
    ax[0].legend(loc="lower right")
    ax[1].legend(loc="upper right")
    ax[1].grid(True, alpha=0.3)
    ax[1].set_ylabel("DTE peak-to-peak [µm]")
    ax[1].set_xlabel("pinion speed [rpm]")
    ax[0].set_title(f"Gear sets 2 and 3, T_s = {torque:g} N·m, OS265962, 40 °C "
                    "(paper Fig. 11)")
    return _save(fig, out, "fig11_gear_sets")


def fig5_regime(pts, out, speed=1000.0, cycles=2):
    """Lubrication regime map: g_V against g_E of every pair in contact over two mesh cycles,
    one cloud per torque, on the Hamrock-Dowson regions (paper Fig. 5; docs/physics.md §7)."""
    sel = tb.select(pts, gear_set=1, lubricant=1, lubricant_file="", speed_rpm=speed)
    if "trace" not in sel:
        return None
    sel = sel[sel["trace"].fillna("").astype(str) != ""].sort_values("T_s")
    root = pathlib.Path(out).parent
    clouds = []
    for row in sel.itertuples():
        tr = results.read_trace(root / "traces", row.point_key)
        if tr is not None:
            n = int(len(tr) * cycles / 50)  # the window holds 50 mesh cycles
            clouds.append((row.T_s, regime.pair_samples(tr.iloc[-n:])))
    if not clouds:
        return None
    allv = np.concatenate([c["g_V"] for _, c in clouds])
    alle = np.concatenate([c["g_E"] for _, c in clouds])
    ar = np.nanmedian(np.concatenate([c["alpha_r"] for _, c in clouds]))
    ev = np.logspace(np.log10(alle.min()) - 1.5, np.log10(alle.max()) + 1.0, 200)
    vv = np.logspace(np.log10(allv.min()) - 1.5, np.log10(allv.max()) + 1.0, 200)
    E, V = np.meshgrid(ev, vv)
    reg = regime.classify(V, E, ar)
    fig, ax = plt.subplots(figsize=(8.5, 6.5))
    cmap = matplotlib.colors.ListedColormap(["#f2f2f2", "#dbe9f6", "#fde9d9", "#e2f0d9"])
    ax.pcolormesh(E, V, np.ma.masked_less(reg, 0), cmap=cmap, vmin=-0.5, vmax=3.5,
                  shading="auto")
    for i, name in enumerate(regime.REGIMES):
        m = reg == i
        if m.any():
            ax.text(np.exp(np.mean(np.log(E[m]))), np.exp(np.mean(np.log(V[m]))), name,
                    fontsize=13, color="0.3", ha="center", va="center",
                    bbox={"fc": "white", "ec": "0.7", "alpha": 0.8})
    for t, c in clouds:
        ax.scatter(c["g_E"], c["g_V"], s=8, color=TORQUE_COLORS.get(t), alpha=0.7,
                   label=f"{t:g} N·m")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("elasticity parameter $g_E = W^{8/3}/U^2$")
    ax.set_ylabel("viscosity parameter $g_V = G W^3/U^2$")
    ax.legend(title=f"{speed:g} rpm, {cycles} mesh cycles", loc="upper left")
    ax.set_title("Lubrication regime map (paper Fig. 5; Hamrock-Dowson regions, docs/physics.md §7,"
                 f"\nalpha_r = R_s/R_e = {ar:.1f}; diagnostic)", fontsize=10)
    return _save(fig, out, "fig5_regime_map")


LEGEND_UNITS = {"T_s": ("N·m", 1.0, 0.0), "T_bath": ("°C", 1.0, -273.15),
                "k_f": ("W/(m·K)", 1.0, 0.0)}


def _with_unit(name, value):
    """'T_s = 100 N·m', 'T_bath = 40 °C' for legends; names without a unit as they are."""
    if name in LEGEND_UNITS and isinstance(value, (int, float, np.number)):
        unit, factor, offset = LEGEND_UNITS[name]
        return f"{name} = {factor * value + offset:g} {unit}"
    return f"{name} = {value}"


def quick_look(df, out, continuation=False):
    """Efficiency and DTE p-p vs speed, one line per combination of the other varied columns
    (the `hypoid sweep` plot)."""
    df = tb.prepare(df)
    if df.empty or "speed_rpm" not in df:
        return []
    params = [c for c in ("gear_set", "lubricant_name", "friction_model", "mesh_model", "T_bath",
                          "T_s", "k_f") if c in df and df[c].nunique() > 1]
    groups = groups_of(df, params)
    fig, ax = plt.subplots(2, 1, figsize=(9, 8), sharex=True)
    for (key, g), c in zip(groups, plt.cm.tab10.colors * 10):
        key = key if isinstance(key, tuple) else (key,)
        label = ", ".join(_with_unit(p, v) for p, v in zip(params, key)) or "all"
        branches = g.groupby("branch") if continuation else [("", g)]
        for br, b in branches:
            b = b.sort_values("speed_rpm")
            st = "--" if br == "down" else "-"
            lab = f"{label} {br}".strip()
            ax[0].plot(b["speed_rpm"], 100 * b["eta_rms"], st, marker="o", ms=3, color=c,
                       label=lab)
            ax[1].plot(b["speed_rpm"], b["DTE_pp_um"], st, marker="o", ms=3, color=c)
    _eta_axis(ax[0])
    ax[0].legend(fontsize=7, loc="lower right")
    ax[1].set_ylabel("DTE peak-to-peak [µm]")
    ax[1].set_xlabel("pinion speed [rpm]")
    ax[1].grid(True, alpha=0.3)
    made = [_save(fig, out, "sweep")]
    if "P_axle_mean_W" in df and df["P_axle_mean_W"].notna().any():
        made.append(axle_quick_look(df, groups_of(df, params), out, continuation))
    return made


def groups_of(df, params):
    return df.groupby(params) if params else [((), df)]


AXLE_PARTS = {"P_mesh_mean_W": ("mesh", "-"), "P_churn_mean_W": ("churning", ":"),
              "P_bearings_mean_W": ("bearings", "--"), "P_seals_mean_W": ("seals", "-.")}


def axle_quick_look(df, groups, out, continuation=False):
    """The axle's ledger vs speed (points with axle_losses = full): each part's mean loss, the
    axle efficiency and the oil temperature, one colour per combination of the varied columns
    (the `hypoid sweep` plot sweep_axle.png)."""
    fig, ax = plt.subplots(3, 1, figsize=(9, 11), sharex=True)
    for (key, g), c in zip(groups, plt.cm.tab10.colors * 10):
        g = g[g["P_axle_mean_W"].notna()].sort_values("speed_rpm")
        key = key if isinstance(key, tuple) else (key,)
        label = ", ".join(str(v) for v in key) or "all"
        ax[0].plot(g["speed_rpm"], g["P_axle_mean_W"], "-", lw=2, color=c,
                   label=f"{label}: axle")
        for col, (part, st) in AXLE_PARTS.items():
            ax[0].plot(g["speed_rpm"], g[col], st, lw=1, color=c, label=f"{label}: {part}")
        ax[1].plot(g["speed_rpm"], 100 * g["eta_axle_energy"], "-o", ms=3, color=c, label=label)
        ax[2].plot(g["speed_rpm"], g["T_oil_mean_C"], "-o", ms=3, color=c, label=label)
    ax[0].set_ylabel("mean loss [W]")
    ax[1].set_ylabel("axle efficiency [%]")
    ax[2].set_ylabel("oil temperature [°C]")
    ax[2].set_xlabel("pinion speed [rpm]")
    for a in ax:
        a.grid(True, alpha=0.3)
        a.legend(fontsize=7)
    return _save(fig, out, "sweep_axle")


def axle_loss_map(lm, out, name="axle_loss_map"):
    """Stacked bars of the axle's losses by part over speed, one panel per oil temperature and
    input torque (the hypoid.maps.lossmap table); None when the table is empty."""
    from hypoid.maps.lossmap import PARTS

    if lm is None or lm.empty:
        return None
    temps, torques = sorted(lm["T_oil_C"].unique()), sorted(lm["T_s"].unique())
    speeds = sorted(lm["speed_rpm"].unique())
    fig, axes = plt.subplots(len(temps), len(torques), figsize=(3 * len(torques),
                             3.2 * len(temps)), sharex=True, squeeze=False)
    for i, T in enumerate(temps):
        for j, tq in enumerate(torques):
            ax = axes[i][j]
            sel = lm[(lm["T_oil_C"] == T) & (lm["T_s"] == tq)].set_index("speed_rpm")
            bottom = np.zeros(len(speeds))
            for k, (label, col) in enumerate(PARTS):
                y = sel[col].reindex(speeds).to_numpy()
                ax.bar(range(len(speeds)), y, bottom=bottom, color=f"C{k}", label=label)
                bottom += y
            ax.set_title(f"{T:.0f} °C, T_s = {tq:.0f} N·m", fontsize=9)
            ax.set_xticks(range(len(speeds)), [f"{n:.0f}" for n in speeds], fontsize=8)
            if j == 0:
                ax.set_ylabel("loss power [W]")
            if i == len(temps) - 1:
                ax.set_xlabel("pinion speed [rpm]")
    axes[0][0].legend(fontsize=8)
    fig.suptitle("Axle losses by part (gear set 1, OS265962, rigid mesh, oil at fixed T)")
    fig.tight_layout()
    return _save(fig, out, name)


def all_figures(pts, cont, out, lossmap=None, workers=0):
    """Every study figure the tables allow, drawn on `workers` local processes (0: here);
    returns {name: path}."""
    from functools import partial

    from hypoid.fmu import parallel

    out = pathlib.Path(out)
    jobs = {"fig5": partial(fig5_regime, pts, out), "fig6a": partial(fig6_lubricants, pts, out),
            "fig7": partial(fig7_swapped, pts, out), "fig8": partial(fig8_torque, pts, out),
            "fig9": partial(fig9_jump, cont, pts, out) if not cont.empty else None,
            "fig10": partial(fig10_mesh_cycle, pts, out),
            "fig11": partial(fig11_gear_sets, pts, out),
            "lossmap": partial(axle_loss_map, lossmap, out)}
    jobs = {name: job for name, job in jobs.items() if job is not None}
    for e0 in tb.calibration_probes(pts):
        jobs[f"fig8-e0x{e0:g}"] = partial(
            fig8_torque, pts, out, f"fig8_efficiency_torque_e0x{e0:g}",
            f"calibration probe: transmission error e_0 x {e0:g} (e_0_scale)", e_0_scale=e0)
    for where in tb.whatifs(pts):
        tag = "".join(f"_{k}{v:g}" for k, v in where.items())
        note = "what-if: " + ", ".join(f"{k} = {v:g}" for k, v in where.items())
        jobs[f"fig8{tag}"] = partial(fig8_torque, pts, out, f"fig8_efficiency_torque{tag}", note,
                                     **where)
        if not cont.empty:
            jobs[f"fig9{tag}"] = partial(fig9_jump, cont, pts, out, f"fig9_dte_jump{tag}", note,
                                         **where)
        # at 50 N.m, where the what-if's teeth separate (its 100 N.m traces are in the report)
        jobs[f"fig10{tag}_50"] = partial(fig10_mesh_cycle, pts, out, 50.0,
                                         f"fig10_mesh_cycle{tag}_50Nm", note, **where)
    made = dict(zip(jobs, parallel.call_all(list(jobs.values()), workers)))
    return {k: v for k, v in made.items() if v is not None}
