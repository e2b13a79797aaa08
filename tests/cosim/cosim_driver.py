#!/usr/bin/env python3
"""The gear FMU coupled to the vehicle FMU in a real co-simulation host (libcosim, through
libcosimpy), in our own fmpy master with the same algorithm and in an fmu-manipulation-toolbox
container; the scene and the energy balance.
docs/cosimulation.md explains the coupling and the figures.

    python tests/cosim/cosim_driver.py [--steps 2e-3 1e-3 5e-4 2e-4 1e-4] [--json OUT] [--plot PNG]
                                       [--record]

prints, for each communication step, the energy residual of the coupled system and how far the
libcosim run is from the fmpy run, from the fmu-manipulation-toolbox container run by fmpy, from a
Gauss-Seidel master and from the finest step; then, at H = 0.5 ms, each gear tolerance setting of
TOLERANCES against a converged run and the hosts against each other under it. --record keeps
these tables in the record docs/records/cosimulation.

Coupling (Jacobi, as libcosim's fixed_step_algorithm): both FMUs step over [t_n, t_n + h] with
inputs held at the values of t_n, then outputs are transferred:
    profile  T_s(t_n)  -> gear.T_s          (libcosim: the override manipulator)
    vehicle  T_hs      -> gear.T_w          (half-shaft torque, positive resists)
    gear     w_w       -> vehicle.w_w       (wheel-side flange speed)
"""

import argparse
import json
import math
import pathlib
import shutil
import sys
import tempfile
import time
from dataclasses import dataclass, field

import numpy as np

from hypoid.cosim.libcosim import Execution, step_ns, why_unavailable as libcosim_available
from hypoid.cosim.libcosim import GearVehicle as LibcosimGearVehicle
from hypoid.cosim.master import GearVehicle

ROOT = pathlib.Path(__file__).resolve().parents[2]
GEAR_FMU = ROOT / "build" / "HypoidGearPair.fmu"
# The build's variant for hosts without Enumeration support (libcosim 0.11 ignores Enumeration
# variables, load_mode among them): enumerations as coded Integers, its own GUID, same binary.
GEAR_INTENUM_FMU = ROOT / "build" / "HypoidGearPair_intenum.fmu"
VEHICLE_FMU = ROOT / "build" / "LongitudinalVehicle.fmu"
# The scene's communication step. Not 1 ms: there the Jacobi coupling takes the damping of the
# gear's mode 2 (input shaft and pinion on the mesh, ~300 Hz) through the half-shaft damper's
# feedthrough, and with the loaded contact law's stiffness it grows (coupling_stability.py,
# docs/cosimulation.md "Stability").
H = 5e-4
RATIO = 36.0 / 13.0  # gear set 1 (checked against the FMU's `ratio` by the test)
RPM = math.pi / 30.0

# Recorded outputs.
GEAR_OUT = ["w_s", "w_p", "w_w", "W_t", "T_w_out", "eta", "P_loss", "E_in", "E_out",
            "E_friction", "E_damping", "E_excitation", "E_stored"]
VEHICLE_OUT = ["T_hs", "v", "w_wheel", "P_in", "E_in", "E_kin", "E_spring", "E_road", "E_grade",
               "E_damper"]


@dataclass
class Scene:
    """A launch, a tip-out into coast (engine braking) and a tip-in, torque-driven at the pinion.
    T_s is piecewise linear through `profile` (s, N.m) and sampled at each communication point."""

    stop_time: float = 2.5
    profile: tuple = ((0.0, 0.0), (0.3, 150.0), (1.2, 150.0), (1.3, -50.0), (1.8, -50.0),
                      (1.9, 150.0), (2.5, 150.0))
    w_p0: float = 100.0 * RPM
    gear: dict = field(default_factory=dict)     # extra gear parameters (fidelity etc.)
    vehicle: dict = field(default_factory=dict)  # extra vehicle parameters

    def torque(self, t):
        ts, vs = zip(*self.profile)
        return float(np.interp(t, ts, vs))

    def gear_start(self):
        """Parameters and initial inputs of the gear: torque-driven at both ends, starting at rest
        torque-wise (T_s = T_w = 0, consistent with the vehicle's untwisted half-shaft)."""
        values = {"load_mode": 1, "w_p0": self.w_p0, "T_s": self.torque(0.0), "T_w": 0.0}
        values.update(self.gear)
        return values

    def vehicle_start(self):
        r_dyn = self.vehicle.get("r_dyn", 0.3)
        # w_w: the input's start value, the gear's w_w at the start (a master that initializes
        # without iterating the loop then starts consistently too)
        values = {"v0": r_dyn * self.w_p0 / RATIO, "T_hs0": 0.0, "w_w": self.w_p0 / RATIO}
        values.update(self.vehicle)
        return values


def n_steps(scene, h):
    return int(round(scene.stop_time / h))


# ------------------------------------------------------------------ results and checks


@dataclass
class Result:
    host: str
    h: float
    t: np.ndarray         # communication points t_0 .. t_N
    T_s: np.ndarray       # torque applied over [t_k, t_k+1] (last entry repeats)
    gear: dict            # output name -> values at t_0 .. t_N
    vehicle: dict
    wall: float           # seconds
    log: list = field(default_factory=list)  # (status, message) logged by the FMUs, when kept


def energy_balance(r):
    """The coupled system's energy balance over the run (J).

    W_Ts = gear.E_in, the work done by T_s on the input shaft, must equal what the gear dissipated
    and stored plus what the vehicle received through the coupling and dissipated and stored:
      gear:    E_friction + E_damping - E_excitation + (E_stored - E_stored(0))
      vehicle: (E_kin - E_kin(0)) + (E_spring - E_spring(0)) + E_road + E_grade + E_damper
    The residual W_Ts - gear - vehicle is the sum of each FMU's own closure (integrator error,
    tiny) and of the coupling error E_out(gear) - E_in(vehicle): the gear integrates the held T_w
    against its continuous w_w, the vehicle the continuous T_hs against the held w_w."""
    g, v = r.gear, r.vehicle
    w_ts = g["E_in"][-1]
    gear = g["E_friction"][-1] + g["E_damping"][-1] - g["E_excitation"][-1] \
        + g["E_stored"][-1] - g["E_stored"][0]
    veh = v["E_kin"][-1] - v["E_kin"][0] + v["E_spring"][-1] - v["E_spring"][0] \
        + v["E_road"][-1] + v["E_grade"][-1] + v["E_damper"][-1]
    gear_closure = g["E_in"][-1] - g["E_out"][-1] - g["E_friction"][-1] - g["E_damping"][-1] \
        + g["E_excitation"][-1] - (g["E_stored"][-1] - g["E_stored"][0])
    veh_closure = v["E_in"][-1] - veh
    coupling = g["E_out"][-1] - v["E_in"][-1]
    # gross energy through the interface, the natural scale of the coupling error
    through = float(np.sum(np.abs(v["P_in"][1:])) * r.h)
    return {"W_Ts": w_ts, "gear": gear, "vehicle": veh, "residual": w_ts - gear - veh,
            "gear_closure": gear_closure, "vehicle_closure": veh_closure,
            "coupling": coupling, "interface_throughput": through,
            "relative_residual": (w_ts - gear - veh) / w_ts}


def resample(r, h):
    """Every k-th communication point, so a run with a finer step lines up with one at h."""
    k = int(round(h / r.h))
    idx = np.arange(0, len(r.t), k)
    return {"t": r.t[idx], **{f"gear.{n}": x[idx] for n, x in r.gear.items()},
            **{f"vehicle.{n}": x[idx] for n, x in r.vehicle.items()}}


def difference(a, b, names=("gear.w_p", "gear.T_w_out", "gear.eta"), h=None):
    """Largest absolute difference of each named output on the coarser of the two time grids
    (abs), that over the output's largest magnitude in a (rel), and the RMS difference over the
    output's RMS in a (rms_rel)."""
    h = h or max(a.h, b.h)
    ra, rb = resample(a, h), resample(b, h)
    n = min(len(ra["t"]), len(rb["t"]))
    assert np.allclose(ra["t"][:n], rb["t"][:n], atol=1e-12, rtol=0)
    out = {}
    for name in names:
        x, y = ra[name][:n], rb[name][:n]
        d = float(np.max(np.abs(x - y)))
        out[name] = {"abs": d, "rel": d / float(np.max(np.abs(x))),
                     "rms_rel": float(np.sqrt(np.mean((x - y) ** 2) / np.mean(x ** 2)))}
    return out


# ------------------------------------------------------------------ libcosim


def libcosim_variables(path):
    """{name: libcosim's variable type} of every variable libcosim loads from the FMU at path (it
    leaves out the types it does not support)."""
    ex = Execution(1e-3)
    try:
        ex.add("probe", path)
        return {name: typ for name, (_, typ) in ex.vars["probe"].items()}
    finally:
        ex.close()


def run_libcosim(scene, h, gear_fmu=GEAR_FMU, vehicle_fmu=VEHICLE_FMU):
    """The scene in libcosim's fixed-step (Jacobi) master (hypoid.cosim.libcosim.GearVehicle, with
    the build's integer-coded gear FMU next to gear_fmu: load_mode = torque is an Integer there).
    T_s goes in through the override manipulator before every step; a time-series observer
    records every step including the initial state (step 0)."""
    wall = time.perf_counter()
    n = n_steps(scene, h)
    m = LibcosimGearVehicle(gear_fmu, vehicle_fmu, scene.gear_start(), scene.vehicle_start(), h,
                            GEAR_OUT, VEHICLE_OUT, gear_inputs=("T_s",), record=n + 1)
    try:
        ns = step_ns(h)
        t_s = np.empty(n + 1)
        for k in range(n):
            t_s[k] = scene.torque(k * ns * 1e-9)
            m.step(gear_inputs=[t_s[k]])
        t_s[n] = t_s[n - 1]
        t, gear, vehicle = m.series()
    finally:
        m.close()
    return Result("libcosim", h, t, t_s, gear, vehicle, time.perf_counter() - wall)


# ------------------------------------------------------------------ our own master with fmpy


def comm_times(n, ns, times="fmpy"):
    """The communication points t_0 .. t_n and the step sizes h_0 .. h_n-1 [s] a master passes to
    fmi2DoStep for n steps of ns nanoseconds. fmpy: t_k = (k ns) 1e-9 and the constant h = ns 1e-9;
    libcosim: its whole nanoseconds converted, t_k = k ns / 1e9, and each step the difference
    t_k+1 - t_k, which differs from h in the last bits at almost every step."""
    if times == "fmpy":
        return np.arange(n + 1) * ns * 1e-9, np.full(n, ns * 1e-9)
    if times == "libcosim":
        t = np.array([k * ns / 1e9 for k in range(n + 1)])
        return t, np.diff(t)
    raise ValueError(times)


def run_fmpy(scene, h, algorithm="jacobi", gear_fmu=GEAR_FMU, vehicle_fmu=VEHICLE_FMU,
             times="fmpy"):
    """The scene in the package's fixed-step master (hypoid.cosim.master.GearVehicle, fmpy).

    jacobi: libcosim's fixed_step_algorithm call for call: start values, fmi2SetupExperiment
      (start 0, no stop time), initialization mode with as many set-inputs / get-outputs /
      transfer passes as there are FMUs, the transferred inputs set, exit, get outputs, transfer;
      then per step set the held inputs on both, step both, get outputs, transfer.
    gauss-seidel: the gear steps first; the vehicle then steps with the gear's new w_w.
    times: the communication points and step sizes passed to fmi2DoStep (comm_times)."""
    wall = time.perf_counter()
    n = n_steps(scene, h)
    t, steps = comm_times(n, step_ns(h), times)
    t_s = np.empty(n + 1)
    with GearVehicle(gear_fmu, vehicle_fmu, scene.gear_start(), scene.vehicle_start(), GEAR_OUT,
                     VEHICLE_OUT, gear_inputs=("T_s",), algorithm=algorithm,
                     init_passes=2) as m:
        g_rows, v_rows = [m.outputs[0]], [m.outputs[1]]
        for k in range(n):
            t_s[k] = scene.torque(float(t[k]))
            g_out, v_out = m.step(float(t[k]), float(steps[k]), [t_s[k]])
            g_rows.append(g_out)
            v_rows.append(v_out)
    t_s[n] = t_s[n - 1]
    g_arr, v_arr = np.array(g_rows), np.array(v_rows)
    return Result(f"fmpy-{algorithm}", h, t, t_s,
                  {name: g_arr[:, j] for j, name in enumerate(GEAR_OUT)},
                  {name: v_arr[:, j] for j, name in enumerate(VEHICLE_OUT)},
                  time.perf_counter() - wall)


# ------------------------------------------------------------------ fmu-manipulation-toolbox


def make_container(scene, h, directory):
    """A container FMU (fmu-manipulation-toolbox) of the gear and the vehicle, linked as above,
    with the scene's start values, internal step h, the gear's free inputs (T_s, T_bath, w_set) as
    its inputs (fmpy leaves the last two at their start values) and every recorded output as
    gear_NAME / vehicle_NAME (the linked ports are exposed as locals gear.w_w, vehicle.T_hs).
    Its default scheduling is parallel: Jacobi, like libcosim."""
    from fmu_manipulation_toolbox.assembly import AssemblyNode
    directory = pathlib.Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    shutil.copy(GEAR_FMU, directory / "gear.fmu")
    shutil.copy(VEHICLE_FMU, directory / "vehicle.fmu")
    node = AssemblyNode("GearVehicle.fmu", step_size=h, auto_link=False, auto_input=False,
                        auto_output=False)
    node.add_fmu("gear.fmu")
    node.add_fmu("vehicle.fmu")
    node.add_link("gear.fmu", "w_w", "vehicle.fmu", "w_w")
    node.add_link("vehicle.fmu", "T_hs", "gear.fmu", "T_w")
    for name in ("T_s", "T_bath", "w_set", "T_amb", "v_air"):  # w_set: unused (load_mode torque)
        node.add_input(name, "gear.fmu", name)
    node.add_input("T_brake", "vehicle.fmu", "T_brake")
    for name, value in scene.gear_start().items():
        if name != "T_s":
            node.add_start_value("gear.fmu", name, repr(value))
    for name, value in scene.vehicle_start().items():
        node.add_start_value("vehicle.fmu", name, repr(value))
    for name in GEAR_OUT:
        node.add_output("gear.fmu", name, "gear_" + name)
    for name in VEHICLE_OUT:
        node.add_output("vehicle.fmu", name, "vehicle_" + name)
    import logging
    quiet = logging.getLogger("fmu_manipulation_toolbox")
    level = quiet.level
    quiet.setLevel(logging.ERROR)  # one line per unconnected output otherwise
    try:
        node.make_fmu(directory)
    finally:
        quiet.setLevel(level)
    return directory / "GearVehicle.fmu"


def run_container(scene, h, container):
    """The container FMU run by fmpy.simulate_fmu with the communication step h; T_s is given as
    fmpy's input signal (the profile's breakpoints, interpolated at each communication point), the
    other inputs at their start values."""
    from fmpy import read_model_description, simulate_fmu
    wall = time.perf_counter()
    held = {v.name: float(v.start) for v in read_model_description(str(container)).modelVariables
            if v.causality == "input" and v.name != "T_s"}  # T_bath, w_set at their start values
    signal = np.array([(t, ts, *held.values()) for t, ts in scene.profile],
                      dtype=[("time", float), ("T_s", float)] + [(n, float) for n in held])
    log = []

    def logger(component, instance, status, category, message):
        log.append((status, message.decode(errors="replace")))

    r = simulate_fmu(str(container), stop_time=scene.stop_time, output_interval=h, input=signal,
                     output=["gear_" + n for n in GEAR_OUT] + ["vehicle_" + n for n in VEHICLE_OUT],
                     logger=logger)
    t_s = np.array([scene.torque(t) for t in r["time"]])
    return Result("container", h, r["time"], t_s, {n: r["gear_" + n] for n in GEAR_OUT},
                  {n: r["vehicle_" + n] for n in VEHICLE_OUT}, time.perf_counter() - wall, log)


def container_available():
    try:
        import fmu_manipulation_toolbox.assembly  # noqa: F401 - only: is it there?
    except ImportError as e:
        return f"{type(e).__name__}: {e}"
    return None


# ------------------------------------------------------------------ the figures


def study(steps, scene=None, gauss_seidel=True, container=True):
    """Runs the scene at each step with libcosim, fmpy (and the container); returns the runs and
    a JSON-able summary."""
    scene = scene or Scene()
    container = container and container_available() is None
    tmp = pathlib.Path(tempfile.mkdtemp(prefix="cosim-"))
    try:
        runs = {}
        for h in steps:
            runs[h] = {"libcosim": run_libcosim(scene, h),
                       "jacobi": run_fmpy(scene, h, "jacobi")}
            if gauss_seidel:
                runs[h]["gauss-seidel"] = run_fmpy(scene, h, "gauss-seidel")
            if container:
                box = make_container(scene, h, tmp / f"container-{h:g}")
                runs[h]["container"] = run_container(scene, h, box)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    finest = runs[min(steps)]["libcosim"]
    rows = []
    for h in steps:
        lc = runs[h]["libcosim"]
        row = {"h": h, "wall_libcosim": lc.wall, "wall_fmpy": runs[h]["jacobi"].wall,
               "energy": energy_balance(lc),
               "energy_fmpy": energy_balance(runs[h]["jacobi"]),
               "libcosim_vs_fmpy": difference(lc, runs[h]["jacobi"]),
               "final": {"v": float(lc.vehicle["v"][-1]), "w_p": float(lc.gear["w_p"][-1])}}
        if gauss_seidel:
            row["jacobi_vs_gauss_seidel"] = difference(lc, runs[h]["gauss-seidel"])
            row["energy_gauss_seidel"] = energy_balance(runs[h]["gauss-seidel"])
        if container:
            row["container_vs_fmpy"] = difference(runs[h]["container"], runs[h]["jacobi"])
            row["wall_container"] = runs[h]["container"].wall
        if h != min(steps):
            row["vs_finest"] = difference(lc, finest, h=h)
        rows.append(row)
    return runs, rows


def plot(runs, rows, path):
    """The scene at the coarsest and finest step (libcosim), and the energy residual and the
    libcosim-fmpy and Jacobi-Gauss-Seidel differences against the step."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    steps = sorted(runs)
    fig = plt.figure(figsize=(11, 8.5), layout="constrained")
    grid = fig.add_gridspec(4, 2, width_ratios=(1.6, 1))
    axes = [fig.add_subplot(grid[k, 0]) for k in range(4)]
    for h in (steps[-1], steps[0]):
        r = runs[h]["libcosim"]
        lab = f"h = {h * 1e3:g} ms"
        axes[0].plot(r.t, r.T_s, lw=1, label=lab)
        axes[1].plot(r.t, r.gear["w_p"] * 30 / math.pi, lw=0.8, label=lab)
        axes[2].plot(r.t, r.gear["T_w_out"], lw=0.8, label=lab)
        axes[3].plot(r.t, r.vehicle["v"] * 3.6, lw=1, label=lab)
    for ax, lab in zip(axes, ("T_s (N.m)", "pinion speed (rpm)", "T_w = T_hs (N.m)",
                              "vehicle speed (km/h)")):
        ax.set_ylabel(lab)
        ax.grid(alpha=0.3)
    axes[0].legend(loc="lower right", fontsize=8)
    axes[0].set_title("libcosim: gear FMU + vehicle FMU, launch / tip-out / tip-in")
    axes[3].set_xlabel("t (s)")
    hs = np.array([r["h"] for r in rows]) * 1e3
    ax = fig.add_subplot(grid[0:2, 1])
    ax.loglog(hs, [abs(r["energy"]["residual"]) for r in rows], "o-", label="|energy residual| (J)")
    ax.loglog(hs, [abs(r["energy"]["gear_closure"]) for r in rows], "s:",
              label="gear FMU's own closure (J)")
    ax.loglog(hs, abs(rows[0]["energy"]["residual"]) * hs / hs[0], "k--", lw=0.8, label="~ h")
    ax.set_xlabel("communication step (ms)")
    ax.set_title(f"energy balance, W_Ts = {rows[-1]['energy']['W_Ts']:.0f} J")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3, which="both")
    ax = fig.add_subplot(grid[2:4, 1])
    ax.loglog(hs, [r["jacobi_vs_gauss_seidel"]["gear.w_p"]["rel"] for r in rows
                   if "jacobi_vs_gauss_seidel" in r] or [np.nan] * len(hs), "o-",
              label="Jacobi - Gauss-Seidel (coupling error)")
    ax.loglog(hs, [max(r["libcosim_vs_fmpy"]["gear.w_p"]["rel"], 1e-16) for r in rows], "s-",
              label="libcosim - fmpy (same algorithm)")
    ax.set_xlabel("communication step (ms)")
    ax.set_title("max |difference| of w_p / max |w_p|")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3, which="both")
    fig.savefig(path, dpi=80)
    plt.close(fig)


def print_table(rows):
    nan = {"rel": float("nan"), "rms_rel": float("nan")}
    print("energy (libcosim runs; J):")
    print(f"{'h (ms)':>7} {'W_Ts':>9} {'residual':>11} {'rel':>9} {'coupling':>11} "
          f"{'gear own':>10} {'vehicle own':>11} {'wall lc/fmpy/box (s)':>21}")
    for r in rows:
        e = r["energy"]
        print(f"{r['h'] * 1e3:7.2f} {e['W_Ts']:9.2f} {e['residual']:11.3e} "
              f"{e['relative_residual']:9.2e} {e['coupling']:11.3e} {e['gear_closure']:10.2e} "
              f"{e['vehicle_closure']:11.2e} {r['wall_libcosim']:9.1f}/{r['wall_fmpy']:.1f}/"
              f"{r.get('wall_container', float('nan')):.1f}")
    print("differences of the gear outputs, max over the run / max |signal| (RMS / RMS for eta):")
    print(f"{'h (ms)':>7} {'output':>8} {'lc-fmpy':>9} {'box-fmpy':>9} {'Jac-GS':>9} "
          f"{'vs finest':>9}")
    for r in rows:
        for name in ("w_p", "T_w_out", "eta"):
            key = "rms_rel" if name == "eta" else "rel"
            cols = [r.get(k, {}).get("gear." + name, nan)[key] for k in
                    ("libcosim_vs_fmpy", "container_vs_fmpy", "jacobi_vs_gauss_seidel",
                     "vs_finest")]
            print(f"{r['h'] * 1e3:7.2f} {name:>8} " + " ".join(f"{c:9.2e}" for c in cols))


# ------------------------------------------------------------------ tolerances and hosts


# Gear settings for the comparison of tolerances and hosts. atol (m, on the DTE; the FMU scales the
# speeds' by omega_4 / R_p: 5.2e-5 rad/s at 1e-10 m) dominates the speeds' tolerance at the
# scene's 100-200 rpm unless it shrinks with rtol: atol = 1e-4 m x rtol, as the work-precision
# benchmark pairs them (bench/wp_driver.py), makes rtol the tolerance in force.
TIGHT = {"solver": 1, "rtol": 1e-10, "atol": 1e-14}  # CVODE BDF (code 1)
CONVERGED = {"solver": 1, "rtol": 1e-12, "atol": 1e-16}
# an independent check of CONVERGED: the explicit method (code 4) at steps of at most 5 us
CHECK = ("arkode_erk, rtol 1e-10, atol 1e-14 m, max_step 5 µs (a check of the converged run)",
         {"solver": 4, "rtol": 1e-10, "atol": 1e-14, "max_step": 5e-6})
TOLERANCES = [("defaults: arkode_erk, rtol 1e-6, atol 1e-10 m", {}),
              ("cvode_bdf, rtol 1e-8, atol 1e-10 m", {"solver": 1, "rtol": 1e-8}),
              ("cvode_bdf, rtol 1e-10, atol 1e-10 m", {"solver": 1, "rtol": 1e-10}),
              ("cvode_bdf, rtol 1e-8, atol 1e-12 m", {"solver": 1, "rtol": 1e-8, "atol": 1e-12}),
              ("cvode_bdf, rtol 1e-10, atol 1e-14 m", TIGHT)]


def tolerance_study(h=H, container=True):
    """Each setting of TOLERANCES at step h: w_p's largest difference from the CONVERGED run
    (relative to max |w_p|), and libcosim's and the container's from our master under it."""
    container = container and container_available() is None
    reference = run_fmpy(Scene(gear=CONVERGED), h)
    tmp = pathlib.Path(tempfile.mkdtemp(prefix="cosim-tol-"))
    rows = []
    try:
        for k, (label, gear) in enumerate(TOLERANCES):
            scene = Scene(gear=gear)
            own = run_fmpy(scene, h)
            row = {"setting": label, "gear": gear,
                   "vs_converged": difference(own, reference)["gear.w_p"]["rel"],
                   "libcosim_vs_fmpy": difference(run_libcosim(scene, h), own)["gear.w_p"]["rel"]}
            if container:
                box = run_container(scene, h, make_container(scene, h, tmp / str(k)))
                row["container_vs_fmpy"] = difference(box, own)["gear.w_p"]["rel"]
            rows.append(row)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    check = run_fmpy(Scene(gear=CHECK[1]), h)
    rows.append({"setting": CHECK[0], "gear": CHECK[1],
                 "vs_converged": difference(check, reference)["gear.w_p"]["rel"]})
    return rows


def _e(x):
    """2 significant digits: 1.4e-11, 3.2e-02 as 3.2e-2."""
    return "—" if x is None or not math.isfinite(x) else f"{x:.1e}".replace("e-0", "e-").replace(
        "e+00", "")


def energy_table(rows):
    lines = ["| h | W_Ts (J) | residual (J) | residual / W_Ts | coupling term (J) | "
             "gear's own closure (J) | vehicle's own (J) |", "|---|---|---|---|---|---|---|"]
    for r in rows:
        e, bold = r["energy"], "**" if r["h"] in (H, 1e-4) else ""
        lines.append(f"| {bold}{r['h'] * 1e3:g} ms{bold} | {e['W_Ts']:.2f} | "
                     f"{bold}{e['residual']:.3g}{bold} | {bold}{_e(e['relative_residual'])}{bold} "
                     f"| {e['coupling']:.3g} | {_e(e['gear_closure'])} | "
                     f"{_e(e['vehicle_closure'])} |")
    return lines


def hosts_table(rows):
    lines = ["| h | output | libcosim − fmpy (Jacobi) | container − fmpy | Jacobi − Gauss-Seidel "
             "| vs 0.1 ms |", "|---|---|---|---|---|---|"]
    for r in rows:
        if r["h"] not in (H, 1e-4):
            continue
        for name, label in (("w_p", "w_p"), ("T_w_out", "T_w seen (`T_w_out`)"), ("eta", "eta")):
            key = "rms_rel" if name == "eta" else "rel"
            cols = [r.get(k, {}).get("gear." + name, {}).get(key) for k in
                    ("libcosim_vs_fmpy", "container_vs_fmpy", "jacobi_vs_gauss_seidel",
                     "vs_finest")]
            lines.append(f"| {r['h'] * 1e3:g} ms | {label} | " + " | ".join(map(_e, cols)) + " |")
    return lines


def tolerance_table(rows):
    lines = ["| gear settings | our master − converged | libcosim − our master | "
             "container − our master |",
             "|---|---|---|---|"]
    for r in rows:
        lines.append(f"| {r['setting']} | {_e(r['vs_converged'])} | "
                     f"{_e(r.get('libcosim_vs_fmpy'))} | {_e(r.get('container_vs_fmpy'))} |")
    return lines


def record(rows, tol_rows):
    """The three tables into the record docs/records/cosimulation (its data and page)."""
    from hypoid.records import cosimulation
    from hypoid.records.docblocks import commit
    from hypoid.records.registry import FOLDER

    measured = (f"on {commit(ROOT)}, {time.strftime('%Y-%m-%d')}, by "
                "`tests/cosim/cosim_driver.py`")
    for name, lines in (("energy", energy_table(rows)), ("hosts", hosts_table(rows)),
                        ("tolerances", tolerance_table(tol_rows))):
        cosimulation.save(FOLDER, name, lines, measured)


def print_tolerances(rows):
    print(f"gear tolerance settings at {H * 1e3:g} ms: w_p vs converged, libcosim - fmpy, "
          "container - fmpy:")
    for r in rows:
        print(f"  {r['setting']:<48} {_e(r['vs_converged']):>8} "
              f"{_e(r.get('libcosim_vs_fmpy')):>8} {_e(r.get('container_vs_fmpy')):>8}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--steps", type=float, nargs="+", default=[2e-3, 1e-3, 5e-4, 2e-4, 1e-4])
    ap.add_argument("--no-gauss-seidel", action="store_true")
    ap.add_argument("--no-container", action="store_true")
    ap.add_argument("--json", help="write the summary here")
    ap.add_argument("--plot", help="write the figure here (PNG)")
    ap.add_argument("--record", action="store_true",
                    help="keep the tables as the record docs/records/cosimulation")
    args = ap.parse_args()
    why = libcosim_available()
    if why:
        sys.exit(f"libcosimpy is not usable here: {why}")
    runs, rows = study(sorted(args.steps, reverse=True), gauss_seidel=not args.no_gauss_seidel,
                       container=not args.no_container)
    print_table(rows)
    tol_rows = tolerance_study(container=not args.no_container)
    print_tolerances(tol_rows)
    if args.json:
        pathlib.Path(args.json).write_text(json.dumps({"steps": rows, "tolerances": tol_rows},
                                                      indent=1, default=float))
    if args.plot:
        plot(runs, rows, args.plot)
    if args.record:
        record(rows, tol_rows)
    return 0


if __name__ == "__main__":
    sys.exit(main())
