# %% [markdown]
# # HypoidGearPair: a quick start for engineers
#
# Five short experiments with the FMU: a launch, a tip-out into coast, a small speed sweep, a
# loss map and drive against coast. Each takes a second or less. The notebook
# `examples/quickstart.ipynb` and the plain script `examples/quickstart.py`
# (`.venv/bin/python examples/quickstart.py`, figures in `quickstart-out/`) are the same code:
# `examples/make_notebook.py` makes the notebook from the script, and the tests execute both.
# To work in the notebook, open it in any Jupyter front end with the project's environment as
# the kernel (the test extras bring the kernel, `ipykernel`; a front end such as JupyterLab or
# VS Code is the user's choice and not pinned here).
#
# The FMU is reached through `hypoid.fmu.instance.Instance`, the `hypoid` package's access layer
# (over fmpy): values by name, enumerations by item name (`load_mode="speed"`), `speed_rpm` for
# the speed set-point and the initial speed together, one instance restarted for each
# experiment. Values are SI at the FMU's interface: N·m, rad/s, K, m.

# %%
import os
import pathlib
import sys

import matplotlib
import numpy as np

if "ipykernel" not in sys.modules:
    matplotlib.use("Agg")  # a plain script: figures go to files only
import matplotlib.pyplot as plt  # noqa: E402

from hypoid.fmu.instance import RPM, Instance  # noqa: E402


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


OUT = pathlib.Path(os.environ.get("QUICKSTART_OUT", "quickstart-out")).resolve()
OUT.mkdir(parents=True, exist_ok=True)
gear = Instance(find_fmu())
print("FMU:", gear.fmu_path)


def run(params, t_end, h, names, inputs=None):
    """Restarts the FMU with `params` and steps to t_end in steps of h; `inputs` maps an input
    to a function of time, set before each step (held over it). Returns {name: array} of the
    outputs after each step, and "time"."""
    gear.start(params)
    rows = []
    while gear.t < t_end - 0.5 * h:
        for name, signal in (inputs or {}).items():
            gear.set(name, signal(gear.t))
        gear.step(h)
        rows.append([gear.t] + [gear.get(n) for n in names])
    return dict(zip(["time"] + names, np.array(rows).T))


def save(fig, name):
    fig.tight_layout()
    fig.savefig(OUT / f"{name}.png", dpi=90)


# %% [markdown]
# ## 1. A launch
#
# The wheel end is held by the speed governor (`load_mode = speed`), whose set-point `w_set`
# ramps from 100 to 2000 rpm in 0.3 s while the input shaft carries 150 N·m. The governor
# (bandwidth `governor_bandwidth`, 2 Hz) follows with a lag and some overshoot. `T_w_out` is the
# torque it needs at the wheel end.

# %%
def w_set_ramp(t):
    return RPM * float(np.interp(t, [0.05, 0.35], [100.0, 2000.0]))


launch = run({"load_mode": "speed", "T_s": 150.0, "speed_rpm": 100.0}, 1.0, 2e-4,
             ["w_p", "w_set", "T_w_out", "P_loss"], inputs={"w_set": w_set_ramp})
fig, ax = plt.subplots(3, 1, figsize=(7, 6), sharex=True)
ax[0].plot(launch["time"], launch["w_p"] / RPM, label="w_p")
ax[0].plot(launch["time"], launch["w_set"] / RPM, "--", label="w_set")
ax[0].set_ylabel("pinion speed [rpm]")
ax[0].legend()
ax[1].plot(launch["time"], launch["T_w_out"])
ax[1].set_ylabel("wheel-end torque [N·m]")
ax[2].plot(launch["time"], launch["P_loss"], alpha=0.3, label="instantaneous")
ax[2].plot(launch["time"], np.convolve(launch["P_loss"], np.ones(50) / 50, "same"),
           label="10 ms mean")
ax[2].set_ylabel("friction loss [W]")
ax[2].set_xlabel("time [s]")
ax[2].legend()
save(fig, "launch")
print(f"launch: {launch['w_p'][-1] / RPM:.0f} rpm at the end, "
      f"loss {launch['P_loss'][-500:].mean():.0f} W")

# %% [markdown]
# ## 2. A tip-out into coast
#
# At 2000 rpm the driver lifts off: the input torque falls from +150 N·m to −40 N·m (engine
# braking) at 0.15 s. The teeth cross the backlash: `contact` goes from the drive flank (1)
# through separation (0) to the coast flank (−1), and the DTE from about +b to about −b.

# %%
tipout = run({"load_mode": "speed", "T_s": 150.0, "speed_rpm": 2000.0}, 0.4, 5e-5,
             ["DTE", "contact", "n_impacts"],
             inputs={"T_s": lambda t: 150.0 if t < 0.15 else -40.0})
fig, ax = plt.subplots(2, 1, figsize=(7, 5), sharex=True)
ax[0].plot(tipout["time"], tipout["DTE"] * 1e6)
ax[0].set_ylabel("DTE [µm]")
ax[1].plot(tipout["time"], tipout["contact"], drawstyle="steps-post")
ax[1].set_ylabel("contact flank")
ax[1].set_xlabel("time [s]")
save(fig, "tipout")
print(f"tip-out: contact {tipout['contact'][0]:.0f} -> {tipout['contact'][-1]:.0f}, "
      f"{tipout['n_impacts'][-1]:.0f} contact changes")

# %% [markdown]
# ## 3. A small sweep: efficiency over speed
#
# Four steady points at 100 N·m. `eta_cycle` is the RMS of the instantaneous efficiency over the
# last completed window of `n_avg_cycles` mesh cycles (the paper's figure); 20 cycles keep the
# runs short.

# %%
def steady(torque, speed_rpm, names=("eta_cycle", "P_loss_cycle")):
    """The named outputs after 0.25 s at a steady operating point."""
    r = run({"load_mode": "speed", "T_s": torque, "speed_rpm": speed_rpm, "n_avg_cycles": 20},
            0.25, 0.01, list(names))
    return {n: r[n][-1] for n in names}


speeds_rpm = [500, 1000, 2000, 3000]
sweep = [steady(100.0, n) for n in speeds_rpm]
for n, point in zip(speeds_rpm, sweep):
    print(f"{n:5d} rpm: eta_cycle = {100 * point['eta_cycle']:.2f} %, "
          f"loss {point['P_loss_cycle']:.0f} W")
fig, ax = plt.subplots(figsize=(6, 3.5))
ax.plot(speeds_rpm, [100 * p["eta_cycle"] for p in sweep], "o-")
ax.set_xlabel("pinion speed [rpm]")
ax.set_ylabel("eta_cycle [%]")
save(fig, "sweep")

# %% [markdown]
# ## 4. A loss map
#
# Mean friction loss over a 3 × 3 grid of speed and input torque (the same short runs).

# %%
map_speeds, map_torques = [1000, 2000, 3000], [50.0, 100.0, 200.0]
loss = np.array([[steady(torque, n)["P_loss_cycle"] for n in map_speeds]
                 for torque in map_torques])
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
sides = {label: steady(torque, 2000.0, ("eta_cycle", "P_loss_cycle", "DTE", "DTE_elastic",
                                        "contact"))
         for label, torque in (("drive", 100.0), ("coast", -100.0))}
for label, s in sides.items():
    print(f"{label}: eta_cycle = {100 * s['eta_cycle']:.2f} %, loss {s['P_loss_cycle']:.0f} W, "
          f"DTE {1e6 * s['DTE']:.1f} µm of which elastic {1e6 * s['DTE_elastic']:.1f} µm, "
          f"contact {s['contact']:.0f}")
fig, ax = plt.subplots(figsize=(6, 3.5))
ax.bar(list(sides), [100 * (1 - s["eta_cycle"]) for s in sides.values()])
ax.set_ylabel("loss: 1 − eta_cycle [%]")
save(fig, "drive_coast")
gear.close()
