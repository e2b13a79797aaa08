"""The level-table record: what each fidelity level costs and how accurate it is at the FMU's
defaults (measured by bench/level_table.py into level-table.json)."""

from hypoid.records.pages import head, load, sci

TITLES = {"full": "full", "smoothed": "event-free", "isothermal": "isothermal friction",
          "mean": "mean mesh", "rigid": "rigid", "map": "map"}
HEADER = ["| level | solver in force | × real time, 1 ms steps | the same with `cvode_bdf` | "
          "× real time, 0.1 s steps | worst error against its own BDF rtol 1e-10 solution in the "
          "five work-precision scenes: efficiency η_E / η_cycle [%-point], DTE p-p [µm] | worst "
          "energy-audit residual (relative) |", "|---|---|---|---|---|---|---|"]
ETA_BOUND_PT, DTE_BOUND_UM = 0.01, 0.1  # the accuracy every level's defaults are held to


def rtf(x):
    """3 significant digits, thousands with a space: 2 560, 68 000, 49.7."""
    v = float(f"{x:.3g}")
    return f"{v:,.0f}".replace(",", " ") if v >= 100 else f"{v:.3g}"


def dte(x):
    return "–" if x is None else f"{x:.2g}"


def bounds_sentence(data):
    """Whether every level meets the bounds, from the data (never a claim written by hand)."""
    eta = [TITLES[lv] for lv, d in data["levels"].items()
           if max(d["eta_E_pt"], d["eta_cycle_pt"]) > ETA_BOUND_PT]
    dte_ = [TITLES[lv] for lv, d in data["levels"].items()
            if d["dte_pp_um"] is not None and d["dte_pp_um"] > DTE_BOUND_UM]
    said = (f"Every level is within {ETA_BOUND_PT} %-point of efficiency of its own tight "
            f"solution" if not eta else
            f"Beyond {ETA_BOUND_PT} %-point of efficiency of its own tight solution: "
            f"{', '.join(eta)}")
    said += (f", and the compliant ones within {DTE_BOUND_UM} µm of DTE p-p" if not dte_ else
             f"; beyond {DTE_BOUND_UM} µm of DTE p-p: {', '.join(dte_)}")
    return (said + ", in all five scenes (design 2000 rpm, off resonance, mode-3 resonance with "
            "tooth separation, torque reversal, −20 °C cold start).")


def page(record, folder, _old=None):
    data = load(folder, record.data[0])
    m = data["meta"]
    provenance = (f"Measured on {m['commit']}"
                  f"{' (with uncommitted changes to its sources)' if m['dirty'] else ''}, "
                  f"{m['date']}, load average {m['load_average']} on 2 cores, at 2000 rpm, "
                  f"100 N·m, 40 °C with the six usual outputs read after every step; costs: "
                  f"`{m['cost_commands'][0]}` and `{m['cost_commands'][1]}`; errors and "
                  "residuals: each level at its defaults (`solver = auto`, rtol 1e-6, atol "
                  "1e-10 m) and at CVODE BDF rtol 1e-10 in the scenes of `bench/wp_driver.py`.")
    rows = list(HEADER)
    for lv, title in TITLES.items():
        d = data["levels"][lv]
        rows.append(f"| {title} | `{d['solver']}` | {rtf(d['rtf_1ms'])} | {rtf(d['rtf_1ms_bdf'])} "
                    f"| {rtf(d['rtf_100ms'])} | {sci(d['eta_E_pt'])} / {sci(d['eta_cycle_pt'])}, "
                    f"{dte(d['dte_pp_um'])} | {sci(d['energy_residual'])} |")
    return (head(record, provenance) + "\n" + "\n".join(rows) + "\n\n" + bounds_sentence(data)
            + "\n")
