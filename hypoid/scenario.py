"""`hypoid run`: simulate one scenario of the FMU and write its time series, a summary and plots.

    hypoid run --fmu build/HypoidGearPair.fmu --out results [--stop-time 0.5] [--set T_s=200 ...]
"""

import argparse
import json
import math
import pathlib
import sys
import time

import numpy as np

from hypoid.paths import user_path, with_absolute_files
from hypoid.sweep import parse_assignments, parse_scalar

OUTPUTS = ["w_s", "w_p", "w_g", "w_w", "DTE", "W_t", "T_fp", "T_fg", "P_loss", "P_in", "eta",
           "eta_cycle", "T_w_out", "k_m", "contact", "n_impacts", "E_in", "E_out", "E_friction",
           "E_damping", "E_excitation", "E_stored", "pair[1].W", "pair[2].W", "pair[3].W",
           "pair[1].mu", "pair[1].h_c", "pair[1].T_c"]


def simulate(fmu, stop_time, output_interval, start_values):
    """Runs the FMU; returns the structured result array and the CPU time it took."""
    from fmpy import simulate_fmu

    t0 = time.process_time()
    result = simulate_fmu(str(fmu), stop_time=stop_time, output_interval=output_interval,
                          start_values=start_values, output=OUTPUTS)
    return result, time.process_time() - t0


def summarise(r, cpu, stop_time, start_values):
    """Steady-state figures over the second half of the run."""
    late = r["time"] >= 0.5 * stop_time
    residual = (r["E_in"] - r["E_out"] - r["E_friction"] - r["E_damping"] + r["E_excitation"]
                - (r["E_stored"] - r["E_stored"][0]))
    return {
        "start_values": start_values,
        "stop_time_s": stop_time,
        "cpu_time_s": cpu,
        "real_time_factor": stop_time / cpu if cpu > 0 else math.inf,
        "pinion_speed_rpm": float(np.mean(r["w_p"][late]) * 30 / math.pi),
        "DTE_mean_um": float(np.mean(r["DTE"][late]) * 1e6),
        "DTE_peak_to_peak_um": float(np.ptp(r["DTE"][late]) * 1e6),
        "DTE_min_um": float(np.min(r["DTE"][late]) * 1e6),
        "contact_loss_fraction": float(np.mean(r["contact"][late] != 1)),
        "impacts": int(r["n_impacts"][-1]),
        "W_t_mean_N": float(np.mean(r["W_t"][late])),
        "P_loss_mean_W": float(np.mean(r["P_loss"][late])),
        "eta_mean": float(np.mean(r["eta"][late])),
        "eta_cycle_last": float(r["eta_cycle"][-1]),
        "energy_residual_relative": float(abs(residual[-1]) / max(abs(r["E_in"][-1]), 1e-300)),
    }


def plot(r, out_dir, title):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    t = r["time"]
    fig, ax = plt.subplots(4, 1, figsize=(9, 10), sharex=True)
    ax[0].plot(t, r["w_p"] * 30 / math.pi, label="pinion")
    ax[0].plot(t, r["w_g"] * 30 / math.pi * (r["w_p"][0] / r["w_g"][0]), label="gear x i")
    ax[0].set_ylabel("speed [rpm]")
    ax[0].legend()
    ax[1].plot(t, r["DTE"] * 1e6)
    ax[1].axhline(70.0, color="k", lw=0.8, ls="--", label="half backlash (default)")
    ax[1].set_ylabel("DTE [um]")
    ax[1].legend()
    ax[2].plot(t, r["W_t"], label="W_t")
    for k in (1, 2, 3):
        ax[2].plot(t, r[f"pair[{k}].W"], lw=0.8, label=f"pair {k}")
    ax[2].set_ylabel("mesh load [N]")
    ax[2].legend(ncol=4)
    ax[3].plot(t, r["eta"], lw=0.8, label="eta")
    ax[3].plot(t, r["eta_cycle"], label="eta_cycle")
    ax[3].set_ylabel("efficiency [-]")
    ax[3].set_xlabel("time [s]")
    ax[3].legend()
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(out_dir / "timeseries.png", dpi=110)
    plt.close(fig)


def main(argv):
    ap = argparse.ArgumentParser(prog="hypoid run", description=__doc__.splitlines()[0])
    ap.add_argument("--fmu", default="build/HypoidGearPair.fmu")
    ap.add_argument("--out", default="results")
    ap.add_argument("--stop-time", type=float, default=0.5)
    ap.add_argument("--output-interval", type=float, default=5e-5)
    ap.add_argument("--set", nargs="*", default=[], metavar="NAME=VALUE",
                    help="start values, e.g. T_s=200 gear_set=2")
    args = ap.parse_args(argv)
    try:
        start_values = with_absolute_files(
            {k: parse_scalar(v) for k, v in parse_assignments(args.set).items()})
    except ValueError as e:
        print(f"hypoid run: {e}", file=sys.stderr)
        return 2
    fmu = pathlib.Path(user_path(args.fmu))
    if not fmu.exists():
        print(f"hypoid run: {fmu} not found (build it with scripts/setup.sh)", file=sys.stderr)
        return 2
    out_dir = pathlib.Path(args.out) / "default-scenario"
    out_dir.mkdir(parents=True, exist_ok=True)
    r, cpu = simulate(fmu, args.stop_time, args.output_interval, start_values)
    summary = summarise(r, cpu, args.stop_time, start_values)
    names = r.dtype.names
    np.savetxt(out_dir / "timeseries.csv", np.column_stack([r[n] for n in names]),
               delimiter=",", header=",".join(names), comments="")
    (out_dir / "summary.json").write_text(json.dumps(summary, indent=2) + "\n")
    plot(r, out_dir, "HypoidGearPair default scenario " + json.dumps(start_values))
    print(json.dumps(summary, indent=2))
    print(f"hypoid run: wrote {out_dir}/timeseries.csv, summary.json, timeseries.png")
    return 0
