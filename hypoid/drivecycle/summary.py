"""What a drive cycle cost: the summary of a run (energy at the wheels, the axle's losses by part
and by phase, mean efficiency, oil temperature, the energy audit), warm minus cold, the summary
page, the CSV of a run and the figure."""

import numpy as np

from hypoid.drivecycle.cycles import KMH
from hypoid.drivecycle.levels import ZERO_C
from hypoid.drivecycle.run import PARTS


def energy_at(rows, name, t):
    return float(np.interp(t, rows["time"], rows[name]))


def audit(run, E_through):
    """The gear FMU's two balances at the end of the run, in J and relative to the energy that
    went into the axle (docs/axle.md, "Energy audit"):
      heat:   C_sump (T_oil - T_oil0) - (E_friction + E_churn + E_bearings + E_seals - Q_housing)
      energy: E_in - E_out - losses - E_damping + E_excitation - (E_stored - E_stored(0))."""
    e = {name: float(col[-1]) for name, col in run.rows.items()}
    losses = sum(e[name] for name in PARTS.values())
    heat = run.C_sump * (e["T_oil"] - float(run.rows["T_oil"][0])) - (losses - e["Q_housing"])
    energy = e["E_in"] - e["E_out"] - losses - e["E_damping"] + e["E_excitation"] \
        - (e["E_stored"] - float(run.rows["E_stored"][0]))
    return {"heat_residual_J": heat, "energy_residual_J": energy,
            "heat_residual_relative": heat / E_through if E_through > 0 else None,
            "energy_residual_relative": energy / E_through if E_through > 0 else None}


def summarise(run, cycle, h):
    r = run.rows
    dE_out = np.diff(r["E_out"])
    P_in = r["P_in_axle"]
    E_through = float(np.sum(0.5 * (P_in[1:] + P_in[:-1])) * h)
    losses = {part: float(r[name][-1]) for part, name in PARTS.items()}
    E_axle = sum(losses.values())
    phases = []
    t_end = float(r["time"][-1])
    for name, a, b in [(n, a, min(b, t_end)) for n, a, b in cycle.phases if a < t_end]:
        d = {part: energy_at(r, n, b) - energy_at(r, n, a) for part, n in PARTS.items()}
        sel = (r["time"] >= a) & (r["time"] <= b)
        phases.append({"phase": name, "t_start_s": a, "t_end_s": b,
                       "distance_km": (energy_at(r, "x", b) - energy_at(r, "x", a)) / 1e3,
                       "losses_J": d, "loss_J": sum(d.values()),
                       "T_oil_end_degC": energy_at(r, "T_oil", b) - ZERO_C,
                       "v_tracking_rms_kmh": float(np.sqrt(np.mean(
                           (r["v"][sel] - r["v_target"][sel]) ** 2)) / KMH)})
    return {
        "label": run.label, "T_oil0_degC": run.T_oil0 - ZERO_C, "wall_s": run.wall,
        "distance_km": float(r["x"][-1]) / 1e3,
        "wheel_energy_J": {"traction": float(np.sum(dE_out[dE_out > 0])),
                           "coast_and_braking_back": float(-np.sum(dE_out[dE_out < 0]))},
        "road_J": float(r["E_road"][-1]), "brakes_J": float(r["E_brake"][-1]),
        "grade_J": float(r["E_grade"][-1]),
        "vehicle": run.vehicle.record() if run.vehicle else None,
        "driveline": run.driveline,
        "axle_losses_J": losses, "axle_loss_J": E_axle,
        "mesh_viscous_J": float(np.sum(0.5 * (r["P_loss_viscous"][1:]
                                              + r["P_loss_viscous"][:-1])) * h),
        "energy_into_axle_J": E_through,
        # none when nothing went through the axle (a car that never moves)
        "mean_axle_efficiency": 1.0 - E_axle / E_through if E_through > 0 else None,
        "T_oil_degC": {"start": float(r["T_oil"][0]) - ZERO_C, "end": float(r["T_oil"][-1])
                       - ZERO_C, "max": float(np.max(r["T_oil"])) - ZERO_C},
        "heat_to_air_J": float(r["Q_housing"][-1]),
        "speed_tracking_rms_kmh": float(np.sqrt(np.mean((r["v"] - r["v_target"]) ** 2)) / KMH),
        "phases": phases,
        "audit": audit(run, E_through),
    }


def _minus(a, b):
    return None if a is None or b is None else a - b


def difference(cold, warm):
    """warm - cold of the headline figures (None where a figure is undefined)."""
    d = {part: warm["axle_losses_J"][part] - cold["axle_losses_J"][part] for part in PARTS}
    eta = _minus(warm["mean_axle_efficiency"], cold["mean_axle_efficiency"])
    return {"axle_losses_J": d, "axle_loss_J": warm["axle_loss_J"] - cold["axle_loss_J"],
            "axle_loss_relative": (warm["axle_loss_J"] / cold["axle_loss_J"] - 1.0
                                   if cold["axle_loss_J"] > 0 else None),
            "mean_axle_efficiency_points": None if eta is None else 100 * eta,
            "T_oil_end_degC": warm["T_oil_degC"]["end"] - cold["T_oil_degC"]["end"]}


def car_line(car):
    """One line on the car the run drove (summary.json has all of it)."""
    if not car:
        return ""
    f, e = car["vehicle_fmu"], car["engine"]
    drag = ", ".join(f"{T:g} N m at {n:g} rpm" for n, T in zip(e["drag_speed_rpm"],
                                                              e["drag_torque_Nm"]))
    return (f"Car ({car['source']}): m {f['m']:g} kg, r_dyn {f['r_dyn']:g} m, J_wheels "
            f"{f['J_wheels']:g} kg m^2, c_rr {f['c_rr']:g}, CdA {f['CdA']:g} m^2, rho_air "
            f"{f['rho_air']:.3f} kg/m^3; engine braking at the propeller shaft {drag} (clutch "
            f"open below {e['clutch_open_below_kmh']:g} km/h), drive up to {e['T_max_Nm']:g} N m.")


def _f(x, fmt, scale=1.0):
    """x * scale in fmt, or 'n/a' for an undefined figure."""
    return "n/a" if x is None else format(x * scale, fmt)


def markdown(meta, runs, diff):
    kj = 1e-3
    lines = [f"# hypoid drive-cycle: {meta['cycle']}", "", f"Cycle: {meta['source']}; "
             f"level {meta['level']}; {meta['master']} master; step {meta['step_s']} s; "
             f"air {meta['T_amb_degC']:.0f} degC.", "", car_line(runs[0].get("vehicle")),
             "", "| | " + " | ".join(s["label"] for s in runs) + " |",
             "|---|" + "---|" * len(runs)]

    def row(name, fn):
        lines.append(f"| {name} | " + " | ".join(fn(s) for s in runs) + " |")

    row("oil at start / end / max (degC)", lambda s: "{start:.1f} / {end:.1f} / {max:.1f}".format(
        **s["T_oil_degC"]))
    row("distance (km)", lambda s: f"{s['distance_km']:.2f}")
    row("energy at the wheels, traction (kJ)",
        lambda s: f"{s['wheel_energy_J']['traction'] * kj:.0f}")
    if any(abs(s["grade_J"]) > 0 for s in runs):
        row("work against the grade, net (kJ)", lambda s: f"{s['grade_J'] * kj:.0f}")
    row("energy into the axle (kJ)", lambda s: f"{s['energy_into_axle_J'] * kj:.0f}")
    for part in PARTS:
        row(f"loss: {part} (kJ)", lambda s, p=part: f"{s['axle_losses_J'][p] * kj:.1f}")
    row("axle loss (kJ)", lambda s: f"{s['axle_loss_J'] * kj:.1f}")
    row("mean axle efficiency (%)", lambda s: _f(s["mean_axle_efficiency"], ".2f", 100))
    row("speed tracking RMS (km/h)", lambda s: f"{s['speed_tracking_rms_kmh']:.2f}")
    row("residual of the heat balance / energy audit (of the energy into the axle)",
        lambda s: f"{_f(s['audit']['heat_residual_relative'], '.1e')} / "
                  f"{_f(s['audit']['energy_residual_relative'], '.1e')}")
    row("wall time (s)", lambda s: f"{s['wall_s']:.1f}")
    lines += ["", "Losses by phase (kJ): mesh / churning / bearings / seals = total", ""]
    for s in runs:
        lines.append(f"- {s['label']}: " + "; ".join(
            f"{p['phase']}: " + " / ".join(f"{p['losses_J'][x] * kj:.1f}" for x in PARTS)
            + f" = {p['loss_J'] * kj:.1f}" for p in s["phases"]))
    if diff:
        lines += ["", f"Warm minus cold: axle loss {diff['axle_loss_J'] * kj:+.1f} kJ "
                  f"({_f(diff['axle_loss_relative'], '+.1f', 100)} %), mean efficiency "
                  f"{_f(diff['mean_axle_efficiency_points'], '+.2f')} %-points; "
                  + ", ".join(f"{p} {diff['axle_losses_J'][p] * kj:+.1f} kJ" for p in PARTS)]
    return "\n".join(lines) + "\n"


def write_csv(run, path):
    names = list(run.rows)
    np.savetxt(path, np.column_stack([run.rows[n] for n in names]), delimiter=",",
               header=",".join(names), comments="", fmt="%.9g")


def plot(cycle, runs, path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(4, 1, figsize=(10, 11), sharex=True)
    r0 = runs[0].rows
    ax[0].plot(r0["time"], r0["v_target"] / KMH, "k-", lw=0.8, label="cycle")
    ax[0].plot(r0["time"], r0["v"] / KMH, "C3--", lw=0.8, label=f"vehicle ({runs[0].label})")
    ax[0].set_ylabel("speed (km/h)")
    for name, a, _ in cycle.phases:
        for a_ in ax:
            a_.axvline(a, color="0.8", lw=0.6)
        ax[0].text(a, ax[0].get_ylim()[1] * 0.92, " " + name, fontsize=8)
    for k, run in enumerate(runs):
        ax[1].plot(run.rows["time"], run.rows["T_oil"] - ZERO_C, f"C{k}", label=run.label)
    ax[1].set_ylabel("oil temperature (°C)")
    r = runs[0].rows
    for part, name in zip(PARTS, ["P_loss", "P_churn", "P_bearings", "P_seals"]):
        ax[2].plot(r["time"], r[name], lw=0.6, label=part)
    ax[2].set_ylabel(f"loss power ({runs[0].label}, W)")
    for k, run in enumerate(runs):
        total = sum(run.rows[n] for n in PARTS.values())
        ax[3].plot(run.rows["time"], total * 1e-3, f"C{k}", label=f"{run.label}: all parts")
        ax[3].plot(run.rows["time"], run.rows["E_friction"] * 1e-3, f"C{k}:",
                   label=f"{run.label}: mesh")
    ax[3].set_ylabel("axle loss energy (kJ)")
    ax[3].set_xlabel("time (s)")
    for a_ in ax:
        a_.legend(fontsize=8, loc="upper left")
        a_.grid(alpha=0.3)
    fig.suptitle(f"{cycle.name}: the axle from a cold start and warm")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)

