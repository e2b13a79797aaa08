"""The records of what the tools cost and give over whole runs: the axle over a drive cycle
(drive-cycle: `hypoid drive-cycle --level fast`'s summary, cold and warm, and bench/drive_cycle.py's
three levels) and the default study's time (study-time: bench/study_time.py)."""

from hypoid.records.pages import head, load, table

TARGET_RTF, TARGET_LOSS = 90.0, 0.01  # the map level's speed target: >= 90x real time in CPU,
#                                       the cycle's axle loss within 1 % of the full level's


def levels(d):
    """Each level over the whole cycle: cost, axle loss, its difference from the full level."""
    meet = [r["level"] for r in d["results"] if r["real_time_factor_cpu"] >= TARGET_RTF
            and abs(r.get("loss_error_vs_full", float("inf"))) <= TARGET_LOSS]
    rows, parts = [], []
    for r in d["results"]:
        settings = ", ".join(f"{k} {v:.0e}" if k == "rtol" else f"{k} = {v}"
                             for k, v in r["settings"].items())
        err = f"{100 * r['loss_error_vs_full']:+.2f} %" if "loss_error_vs_full" in r else "–"
        rows.append([r["level"], settings, f"{r['cpu_s']:.1f}",
                     f"{r['real_time_factor_cpu']:.0f}x", f"{r['wall_s']:.0f}",
                     f"{r['axle_loss_J'] / 1e3:.2f}", err, f"{r['T_oil_rise_K']:.2f}"])
        a = r["audit"]
        parts.append([r["level"], *(f"{v / 1e3:.2f}" for v in r["axle_losses_J"].values()),
                      f"{r['axle_loss_J'] / 1e3:.2f}", f"{100 * r['mean_axle_efficiency']:.3f} %",
                      f"{a['energy_residual_relative']:.1e}", f"{a['heat_residual_relative']:.1e}"])
    text = (f"{d['cycle']}, {d['duration_s']:.0f} s, cold start at {d['T_oil0_degC']:g} °C, air "
            f"{d['T_amb_degC']:g} °C, {d['step_s']:g} s steps, by `bench/drive_cycle.py`; CPU time "
            "of the whole co-simulation (both FMUs and the Python master), wall time on "
            f"{d['machine']}. At least {TARGET_RTF:.0f}x real time with the axle's cycle loss "
            f"within {100 * TARGET_LOSS:g} % of the full level's: "
            f"{', '.join(f'**{m}**' for m in meet) or 'no level'}.")
    names = list(d["results"][0]["axle_losses_J"])
    return ["## The three levels over the cycle", "", text, "",
            table(["level", "gear FMU settings", "CPU [s]", "real-time factor (CPU)", "wall [s]",
                   "axle loss [kJ]", "against full", "oil rise [K]"], rows), "",
            "By part (kJ), with the energy audit's and the heat balance's residual relative to the "
            "energy into the axle:", "",
            table(["level", *names, "axle loss", "mean eta_axle", "energy audit", "heat balance"],
                  parts)]


def runs_table(runs, diff):
    """`hypoid drive-cycle`'s summary of the runs (cold, warm): the energies, losses by part and
    phase, oil temperature, audit residuals and warm minus cold."""
    kj, parts = 1e-3, list(runs[0]["axle_losses_J"])
    rows = [["oil at start / end / max (°C)", *("{start:.1f} / {end:.1f} / {max:.1f}".format(
        **s["T_oil_degC"]) for s in runs)],
            ["distance (km)", *(f"{s['distance_km']:.2f}" for s in runs)],
            ["energy at the wheels, traction (kJ)",
             *(f"{s['wheel_energy_J']['traction'] * kj:.0f}" for s in runs)],
            ["energy into the axle (kJ)", *(f"{s['energy_into_axle_J'] * kj:.0f}" for s in runs)]]
    rows += [[f"loss: {p} (kJ)", *(f"{s['axle_losses_J'][p] * kj:.1f}" for s in runs)]
             for p in parts]
    rows += [["axle loss (kJ)", *(f"{s['axle_loss_J'] * kj:.1f}" for s in runs)],
             ["mean axle efficiency (%)", *(f"{100 * s['mean_axle_efficiency']:.2f}" for s in runs)],
             ["speed tracking RMS (km/h)", *(f"{s['speed_tracking_rms_kmh']:.2f}" for s in runs)],
             ["heat balance / energy audit residual (of the energy into the axle)",
              *("{heat_residual_relative:.1e} / {energy_residual_relative:.1e}".format(**s["audit"])
                for s in runs)],
             ["wall time (s)", *(f"{s['wall_s']:.1f}" for s in runs)]]
    out = [table(["", *(s["label"] for s in runs)], rows), "",
           f"Losses by phase (kJ): {' / '.join(parts)} = total", ""]
    out += [f"- {s['label']}: " + "; ".join(
        f"{p['phase']}: " + " / ".join(f"{p['losses_J'][x] * kj:.1f}" for x in parts)
        + f" = {p['loss_J'] * kj:.1f}" for p in s["phases"]) for s in runs]
    if diff:
        out += ["", f"Warm minus cold: axle loss {diff['axle_loss_J'] * kj:+.1f} kJ "
                f"({100 * diff['axle_loss_relative']:+.1f} %), mean efficiency "
                f"{diff['mean_axle_efficiency_points']:+.2f} %-points; "
                + ", ".join(f"{p} {diff['axle_losses_J'][p] * kj:+.1f} kJ" for p in parts) + "."]
    return out


def page(record, folder, _old=None):
    runs = load(folder, record.data[1])
    m = runs["meta"]
    out = [head(record), f"## {m['cycle']} at the {m['level']} level, cold and warm", "",
           f"`{runs['command']}`, recorded on {runs['commit']}, {runs['recorded']}: {m['source']}; "
           f"{m['master']} master; {m['step_s']} s steps; air {m['T_amb_degC']:.0f} °C.", ""]
    out += runs_table(runs["runs"], runs["warm_minus_cold"])
    out += ["", "![WLTC class 3b, cold and warm](../figures/drive_cycle_wltc3.png)", ""]
    out += levels(load(folder, record.data[0]))
    return "\n".join(out) + "\n"


def study_time(record, folder, _old=None):
    d = load(folder, record.data[0])
    m, each = d["median"], d["each"]
    rows = [[k, f"{m[k]:.2f}", " / ".join(f"{r[k]:.2f}" for r in each)]
            for k in ("wall_s", "cpu_s", "cluster_start_s", "tasks_wall_s", "report_s",
                      "points_cpu_s", "lossmap_cpu_s")]
    loads = ", ".join(f"{r['load_before']:.1f} → {r['load_after']:.1f}" for r in each)
    last = each[-1]
    text = (f"`hypoid study {d['study']}` run {d['runs']} times with {d['workers']} workers, "
            f"finished {d['finished']}; load average (1 min) before → after each run: {loads}. "
            f"Each run: {last['points']} steady points and {last['continuation_rows']} "
            f"continuation windows, {last['converged']} of them converged, "
            f"{last['settle_s_simulated']:.1f} s simulated to settle.")
    sweeps = table(["continuation sweep", "CPU [s]"],
                   [[k, f"{v:.2f}"] for k, v in last["sweeps_cpu_s"].items()])
    return "\n".join([head(record), text, "",
                      table(["quantity [s]", "median", "each run"], rows), "",
                      "The last run's sweeps and slowest points:", "", sweeps, "",
                      "; ".join(last["slowest_points"]) + "."]) + "\n"


def cost(record, folder, _old=None):
    """The drive-cycle cost table: level x cycle x start, CPU, real-time factor, the axle's cycle
    loss and its error against the full level at the same cycle and start."""
    d = load(folder, record.data[0])
    m = d["machine"]
    rows = []
    for c in d["cells"]:
        err = f"{100 * c['loss_error_vs_full']:+.2f} %" if "loss_error_vs_full" in c else "–"
        rows.append([c["cycle"], f"{c['start']} (oil {c['T_oil0_degC']:g} °C, air "
                     f"{c['T_amb_degC']:g} °C)", c["level"], driveline(c.get("sets")),
                     f"{c['cpu_s']:.2f}",
                     str(c["repeats"]) + ("" if c["repeats_identical"] else " (losses differ)"),
                     f"{c['real_time_factor_cpu']:.1f}x", f"{c['axle_loss_J'] / 1e3:.2f}", err])
    spans = ", ".join(f"{k} {v:.0f} s" for k, v in d["cycles"].items()) or \
        f"each cycle's first {d['until_s']:g} s"
    reps = ", ".join(f"{k} {v}" for k, v in d["repeats"].items())
    single = [k for k, v in d["repeats"].items() if v == 1]
    if single:
        reps += f"; the {' and '.join(single)} level's figure is one run"
    loads = " → ".join("/".join(f"{x:.2f}" for x in m[k])
                       for k in ("load_average_before", "load_average_after"))
    text = (f"`{d['command']}`, recorded on {d['commit']}, {d['recorded']}: the gear and vehicle "
            f"FMUs in `hypoid drive-cycle`'s co-simulation (fmpy master, {d['step_s']:g} s "
            f"steps) over {spans}. CPU is the process's (both FMUs and the Python master), the "
            f"median of the runs of a cell (runs per cell: {reps}); the real-time factor is the "
            "cycle's duration over that CPU; the error is "
            "the axle's cycle loss against the full level's at the same cycle and start. "
            f"Machine: {m['cpus']} CPUs ({m['processor']}), {m['shared']}, niceness "
            f"{m['niceness']}; load average (1/5/15 min) at the start → the end: {loads}; "
            f"{d['wall_total_s'] / 60:.0f} min in all. Each run's CPU, wall time and load "
            "average are in the data.")
    return "\n".join([head(record), text, "", *heavy_input(d["cells"]),
                      table(["cycle", "start", "level", "driveline", "CPU [s]", "runs",
                             "real-time factor (CPU)", "axle loss [kJ]", "against full"],
                            rows)]) + "\n"


def driveline(sets):
    """The gear's start values a cell changed: an engine and gearbox behind the pinion."""
    return ", ".join(f"{k} = {v:g} kg·m²" for k, v in sets.items()) if sets else "the defaults"


def heavy_input(cells):
    """The cost with an engine and gearbox behind the pinion against the bare input shaft's, at
    the same cycle, start and level in the same run."""
    bare = {(c["cycle"], c["start"], c["level"]): c["cpu_s"] for c in cells if not c.get("sets")}
    lines = [f"{c['level']} {c['cpu_s'] / bare[(c['cycle'], c['start'], c['level'])]:.2f}×"
             for c in cells if c.get("sets") and (c["cycle"], c["start"], c["level"]) in bare]
    if not lines:
        return []
    return ["The input side's inertia (an engine and gearbox behind the pinion, I_s = 0.214 kg·m², "
            "against the bare input shaft's default) changes the levels' CPU by: "
            + ", ".join(lines) + " (the same cycle and start, in the same run).", ""]
