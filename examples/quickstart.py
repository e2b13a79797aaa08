# %% [markdown]
# # HypoidGearPair: a quick start for engineers
#
# Five short experiments with the FMU through [fmpy](https://github.com/CATIA-Systems/FMPy):
# a launch, a tip-out into coast, a small speed sweep, a loss map and drive against coast.
# Each runs in a second or less. The notebook `examples/quickstart.ipynb` and the plain script
# `examples/quickstart.py` (`.venv/bin/python examples/quickstart.py`, figures in
# `quickstart-out/`) are the same code: `examples/make_notebook.py` makes the notebook from the
# script, and the tests execute both.
#
# Units are SI at the FMU's interface: torques in N·m, speeds in rad/s, temperatures in K,
# lengths in m. Enumerations (`load_mode`, `friction_model`, ...) are set by their integer codes,
# which `hypoid.variables.ENUMERATIONS` lists by item name.

# %%
import math
import os
import pathlib
import sys

import matplotlib
import numpy as np
from fmpy import simulate_fmu

if "ipykernel" not in sys.modules:
    matplotlib.use("Agg")  # a plain script: write the figures to files only
import matplotlib.pyplot as plt  # noqa: E402

from hypoid.variables import ENUMERATIONS, VARIABLES  # noqa: E402


def find_fmu():
    """$HYPOID_FMU, or build/HypoidGearPair.fmu of the repository this file (or the working
    directory, in a notebook) lies in."""
    if os.environ.get("HYPOID_FMU"):
        return pathlib.Path(os.environ["HYPOID_FMU"]).resolve()
    here = pathlib.Path(globals().get("__file__", "quickstart.ipynb")).resolve().parent
    for folder in (here, *here.parents):
        candidate = folder / "build" / "HypoidGearPair.fmu"
        if candidate.exists():
            return candidate
    raise FileNotFoundError("build/HypoidGearPair.fmu not found: build it with scripts/setup.sh")


FMU = find_fmu()
OUT = pathlib.Path(os.environ.get("QUICKSTART_OUT", "quickstart-out")).resolve()
OUT.mkdir(parents=True, exist_ok=True)
RPM = math.pi / 30  # rad/s per rpm
SPEED = ENUMERATIONS["load_mode"]["speed"]  # the wheel end follows a speed governor
print("FMU:", FMU)
print("load_mode codes:", ENUMERATIONS["load_mode"])


def run(stop_time, start_values, output, signals=None, output_interval=2e-4):
    """One simulation; `signals` = {input name: [(t, value), ...]} with rising times, linear in
    between. The other inputs keep their start values."""
    inputs = None
    if signals:
        names = [n for n, v in VARIABLES.items() if v.causality == "input"]
        times = sorted({t for points in signals.values() for t, _ in points})
        inputs = np.zeros(len(times), dtype=[("time", float)] + [(n, float) for n in names])
        inputs["time"] = times
        for name in names:
            default = start_values.get(name, VARIABLES[name].start)
            ts, vs = zip(*signals.get(name, [(0.0, default)]))
            inputs[name] = np.interp(times, ts, vs)
    return simulate_fmu(str(FMU), stop_time=stop_time, output_interval=output_interval,
                        start_values=start_values, input=inputs, output=output)


def save(fig, name):
    fig.tight_layout()
    fig.savefig(OUT / f"{name}.png", dpi=90)


# %% [markdown]
# ## 1. A launch
#
# The wheel end is held by the speed governor (`load_mode = speed`), whose set-point `w_set`
# ramps from 100 to 2000 rpm in 0.3 s while the input shaft carries 150 N·m. The governor
# (bandwidth `governor_bandwidth`, 2 Hz) follows with a lag and some overshoot. `T_w_out` is the
# torque the governor needs at the wheel end; `eta` the instantaneous mesh efficiency.

# %%
launch = run(1.0, {"load_mode": SPEED, "T_s": 150.0, "w_p0": 100 * RPM, "w_set": 100 * RPM},
             ["w_p", "w_set", "T_w_out", "P_loss", "eta"],
             signals={"w_set": [(0.0, 100 * RPM), (0.05, 100 * RPM), (0.35, 2000 * RPM),
                                (1.0, 2000 * RPM)]})
fig, ax = plt.subplots(3, 1, figsize=(7, 6), sharex=True)
ax[0].plot(launch["time"], launch["w_p"] / RPM, label="w_p")
ax[0].plot(launch["time"], launch["w_set"] / RPM, "--", label="w_set")
ax[0].legend()
ax[0].set_ylabel("pinion speed [rpm]")
ax[1].plot(launch["time"], launch["T_w_out"])
ax[1].set_ylabel("wheel-end torque [N·m]")
ax[2].plot(launch["time"], launch["P_loss"], alpha=0.3, label="instantaneous")
ax[2].plot(launch["time"], np.convolve(launch["P_loss"], np.ones(50) / 50, "same"),
           label="10 ms mean")
ax[2].set_ylabel("friction loss [W]")
ax[2].legend()
ax[2].set_xlabel("time [s]")
save(fig, "launch")
print(f"launch: {launch['w_p'][-1] / RPM:.0f} rpm at the end, "
      f"loss {launch['P_loss'][-100:].mean():.0f} W")

# %% [markdown]
# ## 2. A tip-out into coast
#
# At 2000 rpm the driver lifts off: the input torque falls from +150 N·m to −40 N·m (engine
# braking) within 2 ms at 0.15 s. The teeth cross the backlash: `contact` goes from the drive flank (1)
# through separation (0) to the coast flank (−1), and the DTE from about +b to about −b.

# %%
tipout = run(0.4, {"load_mode": SPEED, "T_s": 150.0, "w_set": 2000 * RPM, "w_p0": 2000 * RPM},
             ["DTE", "contact", "n_impacts", "W_t"],
             signals={"T_s": [(0.0, 150.0), (0.15, 150.0), (0.152, -40.0), (0.4, -40.0)]},
             output_interval=5e-5)
fig, ax = plt.subplots(2, 1, figsize=(7, 5), sharex=True)
ax[0].plot(tipout["time"], tipout["DTE"] * 1e6)
ax[0].set_ylabel("DTE [µm]")
ax[1].plot(tipout["time"], tipout["contact"], drawstyle="steps-post")
ax[1].set_ylabel("contact flank")
ax[1].set_xlabel("time [s]")
save(fig, "tipout")
print(f"tip-out: contact {tipout['contact'][0]} -> {tipout['contact'][-1]}, "
      f"{tipout['n_impacts'][-1]} contact changes")

# %% [markdown]
# ## 3. A small sweep: efficiency over speed
#
# Four steady points at 100 N·m. `eta_cycle` is the RMS of the instantaneous efficiency over the
# last completed window of `n_avg_cycles` mesh cycles (the paper's figure); 20 cycles keep the
# runs short.

# %%
speeds_rpm = [500, 1000, 2000, 3000]
sweep = []
for n in speeds_rpm:
    r = run(0.25, {"load_mode": SPEED, "T_s": 100.0, "w_set": n * RPM, "w_p0": n * RPM,
                   "n_avg_cycles": 20}, ["eta_cycle", "P_loss_cycle"], output_interval=0.01)
    sweep.append((n, r["eta_cycle"][-1], r["P_loss_cycle"][-1]))
    print(f"{n:5d} rpm: eta_cycle = {100 * r['eta_cycle'][-1]:.2f} %, "
          f"loss {r['P_loss_cycle'][-1]:.0f} W")
fig, ax = plt.subplots(figsize=(6, 3.5))
ax.plot([s[0] for s in sweep], [100 * s[1] for s in sweep], "o-")
ax.set_xlabel("pinion speed [rpm]")
ax.set_ylabel("eta_cycle [%]")
save(fig, "sweep")

# %% [markdown]
# ## 4. A loss map
#
# Mean friction loss over a 3 × 3 grid of speed and input torque (same short runs).

# %%
map_speeds, map_torques = [1000, 2000, 3000], [50.0, 100.0, 200.0]
loss = np.zeros((len(map_torques), len(map_speeds)))
for i, torque in enumerate(map_torques):
    for j, n in enumerate(map_speeds):
        r = run(0.25, {"load_mode": SPEED, "T_s": torque, "w_set": n * RPM, "w_p0": n * RPM,
                       "n_avg_cycles": 20}, ["P_loss_cycle"], output_interval=0.01)
        loss[i, j] = r["P_loss_cycle"][-1]
fig, ax = plt.subplots(figsize=(6, 4))
mesh = ax.pcolormesh(map_speeds, map_torques, loss, shading="nearest")
fig.colorbar(mesh, label="friction loss [W]")
ax.set_xlabel("pinion speed [rpm]")
ax.set_ylabel("input torque [N·m]")
save(fig, "lossmap")
print("loss map [W] (rows: torque, columns: speed):\n", np.round(loss))

# %% [markdown]
# ## 5. Drive against coast
#
# The same 100 N·m and 2000 rpm, once driving (power from the pinion) and once coasting (power
# from the wheel end, `T_s = −100 N·m`). The coast flank of a hypoid carries the load at other
# sliding conditions, so the friction differs; the DTE sits on the other side of the backlash.
# `DTE` includes the half backlash b (paper eq. 25); `DTE_elastic` is the tooth deflection alone.

# %%
sides = {}
for label, torque in (("drive", 100.0), ("coast", -100.0)):
    r = run(0.25, {"load_mode": SPEED, "T_s": torque, "w_set": 2000 * RPM, "w_p0": 2000 * RPM,
                   "n_avg_cycles": 20},
            ["eta_cycle", "P_loss_cycle", "DTE", "DTE_elastic", "contact"], output_interval=1e-3)
    sides[label] = r
    print(f"{label}: eta_cycle = {100 * r['eta_cycle'][-1]:.2f} %, "
          f"loss {r['P_loss_cycle'][-1]:.0f} W, mean DTE {1e6 * r['DTE'][-50:].mean():.1f} µm "
          f"of which elastic {1e6 * r['DTE_elastic'][-50:].mean():.1f} µm, "
          f"contact {r['contact'][-1]}")
fig, ax = plt.subplots(figsize=(6, 3.5))
ax.bar(list(sides), [100 * (1 - sides[k]["eta_cycle"][-1]) for k in sides])
ax.set_ylabel("loss: 1 − eta_cycle [%]")
save(fig, "drive_coast")
