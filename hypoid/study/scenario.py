"""One scenario of the FMU: the run, its per-mesh-cycle figures, a summary, the output folder and
the plots. The command is `hypoid run` (hypoid/cli/run.py)."""

import math
import pathlib
import re
import time

import numpy as np

from hypoid.fmu.values import RPM

OUTPUTS = ["w_s", "w_p", "w_g", "w_w", "DTE", "W_t", "T_fp", "T_fg", "P_loss", "P_in", "eta",
           "eta_cycle", "T_w_out", "k_m", "contact", "n_impacts", "E_in", "E_out", "E_friction",
           "E_damping", "E_excitation", "E_stored", "pair[1].W", "pair[2].W", "pair[3].W",
           "pair[1].mu", "pair[1].h_c", "pair[1].T_c"]
CYCLE_SIGNALS = ["w_p", "w_g", "DTE", "W_t", "P_loss", "eta"]  # per-cycle mean / min / max
SAMPLES_PER_CYCLE = 16  # default output interval: this many samples per mesh cycle
ZOOM_CYCLES = 4
FALLBACK_INTERVAL = 1e-4  # s, when the start speed is (near) zero


# ---------------------------------------------------------------------------- simulation
def mesh_period(inst):
    """The mesh period [s] at the start speed, or None when the gear starts (nearly) at rest."""
    w = abs(inst.get("w_p0"))
    return 2.0 * math.pi / (inst.pinion_teeth() * w) if w > 1.0 else None


def simulate(inst, params, stop_time, output_interval=None):
    """Runs the scenario on `inst`; returns ({name: array} with 'time', the interval used, the
    CPU time of the stepping)."""
    inst.start(params)
    period = mesh_period(inst)
    h = output_interval or (period / SAMPLES_PER_CYCLE if period else FALLBACK_INTERVAL)
    t0 = time.process_time()
    r = inst.series(max(h, round(stop_time / h) * h), h, OUTPUTS)
    cpu = time.process_time() - t0
    return {name: r[name] for name in r.dtype.names}, h, cpu


def mesh_cycles(r, n_p):
    """Index of the mesh cycle of each sample, from the pinion angle N_p * integral of w_p."""
    dt = np.diff(r["time"], prepend=0.0)
    theta = np.cumsum(r["w_p"] * dt) * n_p
    return np.floor(theta / (2.0 * math.pi)).astype(np.int64)


def cycle_table(r, cycle):
    """Per complete mesh cycle: its mid time and the mean, minimum and maximum of CYCLE_SIGNALS."""
    ids = np.unique(cycle)[1:-1]  # the first and last cycles are incomplete
    rows = {"cycle": ids, "time": np.array([np.mean(r["time"][cycle == c]) for c in ids])}
    for name in CYCLE_SIGNALS:
        groups = [r[name][cycle == c] for c in ids]
        rows[f"{name}_mean"] = np.array([g.mean() for g in groups])
        rows[f"{name}_min"] = np.array([g.min() for g in groups])
        rows[f"{name}_max"] = np.array([g.max() for g in groups])
    return rows


def half_backlash(inst):
    """The half backlash b the dynamics uses [m]: the FMU's parameter b, 0 for the mean and
    rigid meshes (no backlash there)."""
    return inst.get("b") if inst.get("mesh_model") == inst.enum_value("mesh_model", "varying") \
        else 0.0


def summarise(r, cpu, stop_time, params, b):
    """Steady-state figures over the second half of the run."""
    late = r["time"] >= 0.5 * stop_time
    residual = (r["E_in"] - r["E_out"] - r["E_friction"] - r["E_damping"] + r["E_excitation"]
                - (r["E_stored"] - r["E_stored"][0]))
    return {
        "start_values": params,
        "stop_time_s": stop_time,
        "output_interval_s": float(r["time"][1] - r["time"][0]),
        "cpu_time_s": cpu,
        "real_time_factor": stop_time / cpu if cpu > 0 else math.inf,
        "half_backlash_um": b * 1e6,
        "pinion_speed_rpm": float(np.mean(r["w_p"][late]) / RPM),
        "DTE_mean_um": float(np.mean(r["DTE"][late]) * 1e6),
        "DTE_peak_to_peak_um": float(np.ptp(r["DTE"][late]) * 1e6),
        "DTE_min_um": float(np.min(r["DTE"][late]) * 1e6),
        "contact_loss_fraction": float(np.mean(r["contact"][late] != 1)),
        "impacts": int(r["n_impacts"][-1]),
        "W_t_mean_N": float(np.mean(r["W_t"][late])),
        "P_loss_mean_W": float(np.mean(r["P_loss"][late])),
        "eta_mean_percent": float(np.mean(r["eta"][late]) * 100),
        "eta_cycle_last_percent": float(r["eta_cycle"][-1] * 100),
        "energy_residual_relative": float(abs(residual[-1]) / max(abs(r["E_in"][-1]), 1e-300)),
    }


# ---------------------------------------------------------------------------- output folder
def run_name(params, name=None):
    """The run's folder name: --name, or the values set ('T_s=200_speed_rpm=3000')."""
    text = name or "_".join(f"{k}={_short(k, v)}" for k, v in params.items()) or "defaults"
    return re.sub(r"[^A-Za-z0-9_.=+-]", "-", text)[:120]


def _short(name, value):
    if name.endswith("_file"):
        return pathlib.Path(str(value)).name
    return f"{value:g}" if isinstance(value, float) else value


def fresh_folder(out, name, overwrite=False):
    """<out>/<name>, or <name>-2, -3, ... when it exists (unless overwrite)."""
    base = pathlib.Path(out) / name
    target, k = base, 1
    while target.exists() and not overwrite:
        k += 1
        target = base.with_name(f"{name}-{k}")
    target.mkdir(parents=True, exist_ok=True)
    return target


def write_tables(r, cycles, folder):
    names = list(r)
    np.savetxt(folder / "timeseries.csv", np.column_stack([r[n] for n in names]),
               delimiter=",", header=",".join(names), comments="", fmt="%.9g")
    cnames = list(cycles)
    np.savetxt(folder / "cycles.csv", np.column_stack([cycles[n] for n in cnames]),
               delimiter=",", header=",".join(cnames), comments="", fmt="%.9g")


# ---------------------------------------------------------------------------- plots
def _pyplot():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _band(ax, cycles, name, scale, label, color):
    t = cycles["time"]
    ax.fill_between(t, cycles[f"{name}_min"] * scale, cycles[f"{name}_max"] * scale,
                    color=color, alpha=0.3, lw=0, label=f"{label}: range in each mesh cycle")
    ax.plot(t, cycles[f"{name}_mean"] * scale, color=color, lw=1.2, label=f"{label}: cycle mean")


def _backlash_lines(ax, b):
    if b > 0:
        for sign in (1, -1):
            ax.axhline(sign * b * 1e6, color="k", lw=0.8, ls="--",
                       label=f"±b = ±{b * 1e6:.1f} µm (half backlash)" if sign > 0 else None)


def plot_run(r, cycles, b, folder, title):
    """timeseries.png: the whole run as mesh-cycle envelopes and means."""
    plt = _pyplot()
    fig, ax = plt.subplots(4, 1, figsize=(9, 10), sharex=True)
    ratio = np.nanmedian(r["w_p"] / np.where(r["w_g"] == 0, np.nan, r["w_g"]))
    _band(ax[0], cycles, "w_p", 1 / RPM, "pinion", "C0")
    ax[0].plot(cycles["time"], cycles["w_g_mean"] / RPM * ratio, color="C1", lw=1, ls="--",
               label=f"gear × {ratio:.3f}: cycle mean")
    ax[0].set_ylabel("speed [rpm]")
    _band(ax[1], cycles, "DTE", 1e6, "DTE", "C0")
    _backlash_lines(ax[1], b)
    ax[1].set_ylabel("DTE [µm]")
    _band(ax[2], cycles, "W_t", 1.0, "W_t", "C2")
    ax[2].set_ylabel("mesh load W_t [N]")
    _band(ax[3], cycles, "eta", 100.0, "η", "C3")
    ax[3].plot(r["time"], r["eta_cycle"] * 100, color="k", lw=1,
               label="η_cycle (FMU's window RMS)")
    ax[3].set_ylabel("efficiency [%]")
    ax[3].set_xlabel("time [s]")
    for a in ax:
        a.legend(fontsize=8, loc="best")
        a.grid(alpha=0.3)
    fig.suptitle(title, fontsize=10)
    fig.tight_layout()
    fig.savefig(folder / "timeseries.png", dpi=110)
    plt.close(fig)


def plot_zoom(r, cycle, b, folder, title):
    """zoom.png: the last ZOOM_CYCLES complete mesh cycles, sample by sample."""
    plt = _pyplot()
    last = np.unique(cycle)[-2] if len(np.unique(cycle)) > 1 else cycle[-1]
    sel = (cycle > last - ZOOM_CYCLES) & (cycle <= last)
    t = r["time"][sel] * 1e3
    fig, ax = plt.subplots(3, 1, figsize=(9, 8), sharex=True)
    ax[0].plot(t, r["DTE"][sel] * 1e6, ".-", lw=1, ms=3, label="DTE")
    _backlash_lines(ax[0], b)
    ax[0].set_ylabel("DTE [µm]")
    ax[1].plot(t, r["W_t"][sel], lw=1.2, label="W_t (total)")
    for k in (1, 2, 3):
        ax[1].plot(t, r[f"pair[{k}].W"][sel], lw=0.8, label=f"pair {k}")
    ax[1].set_ylabel("load [N]")
    ax[2].plot(t, r["eta"][sel] * 100, lw=1, label="η")
    ax[2].set_ylabel("efficiency [%]")
    ax[2].set_xlabel("time [ms]")
    for a in ax:
        a.legend(fontsize=8, loc="best")
        a.grid(alpha=0.3)
    fig.suptitle(f"{title}: last {ZOOM_CYCLES} mesh cycles", fontsize=10)
    fig.tight_layout()
    fig.savefig(folder / "zoom.png", dpi=110)
    plt.close(fig)
