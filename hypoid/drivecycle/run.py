"""One drive-cycle run: the gear FMU (load_mode = torque, axle_losses = full, thermal_model =
sump) carries the vehicle's inertia at its wheel end (I_w += m r^2 + J_wheels) and the half-shaft
compliance (k_t2 = k_hs); the vehicle FMU (coupling = 2) returns the road load and the brake
torque at the wheel speed; the driver sets the propeller-shaft torque T_s and the brakes. Both
FMUs run in the package's co-simulation master (hypoid.cosim.master, fmpy, Jacobi) or in an
outside host's fixed-step algorithm, libcosim's or Ecos' (hypoid.cosim.host.GearVehicle, with the
build's integer-coded gear FMU)."""

import os
import sys
import time
from dataclasses import dataclass

import numpy as np

from hypoid.cosim import ecos, host, libcosim, master
from hypoid.drivecycle.levels import LEVELS
from hypoid.drivecycle.vehicle import Driver, Vehicle, fmu_parameters
from hypoid.errors import UsageError
from hypoid.fmu.values import SPEED_KEY, TABLE

GEAR_OUT = ["w_w", "w_p", "T_oil", "P_loss", "P_loss_viscous", "P_churn", "P_bearings",
            "P_seals", "P_axle", "P_in_axle", "eta_axle", "E_in", "E_out", "E_friction",
            "E_churn", "E_bearings", "E_seals", "Q_housing", "Q_dot_housing", "E_damping",
            "E_excitation", "E_stored"]
VEHICLE_OUT = ["T_hs", "v", "x", "E_road", "E_brake", "E_grade"]
PARTS = {"mesh": "E_friction", "churning": "E_churn", "bearings": "E_bearings",
         "seals": "E_seals"}


@dataclass
class Run:
    label: str
    T_oil0: float            # K
    rows: dict               # name -> array over the steps (time first)
    wall: float              # s
    C_sump: float            # J/K, the gear FMU's (for the heat balance)
    vehicle: Vehicle = None  # the car as run (air density at this run's air)
    driveline: dict = None   # the gear FMU's inertias, ratio and stiffnesses as initialised


# The gear FMU's values that the drive cycle sets itself, with what to give instead; --set of one
# of them is refused (it would be overwritten, or would break the scene).
SCENE_SET = {"T_s": "the driver sets it at each step",
             "v_air": "the car's speed sets it at each step",
             "T_w": "the vehicle's road load sets it at each step",
             "load_mode": "the driver's torque drives the axle",
             "w_set": "the car's speed follows the cycle", "w_p0": "the car starts at rest",
             SPEED_KEY: "the car's speed follows the cycle",
             "T_amb": "give --t-amb", "T_oil0": "give --t-oil0 and --warm",
             "T_bath": "give --t-oil0 and --warm"}


def check_gear_set(extra):
    """Refuses --set values of the gear FMU that the scene sets itself (SCENE_SET)."""
    for name, value in extra.items():
        if name in SCENE_SET:
            raise UsageError(f"--set {name} = {value!r}: set by the drive cycle itself "
                             f"({SCENE_SET[name]})")


def gear_start(level, vehicle, I_w0, T_oil0, T_amb, extra):
    """The gear FMU's values: the level's, the scene's, the vehicle's inertia at the wheel end
    (on top of the gear's own I_w, the vehicle file's or --set's if given) and the user's."""
    values = dict(LEVELS[level])
    values.update(vehicle.driveline)
    I_w_own = float(extra.get("I_w", vehicle.driveline.get("I_w", I_w0)))
    values.update(load_mode="torque", axle_losses="full", thermal_model="sump", T_s=0.0,
                  T_w=0.0, w_p0=0.0, T_oil0=T_oil0, T_amb=T_amb, T_bath=T_oil0,
                  k_t2=vehicle.k_hs)
    values.update({k: v for k, v in extra.items() if k != "I_w"})
    values["I_w"] = I_w_own + vehicle.m * vehicle.r_dyn ** 2 + vehicle.J_wheels
    return values


def progress(total, label):
    """A progress bar on stderr over the cycle's seconds; none when stderr is not a terminal or
    under CI."""
    from tqdm import tqdm

    quiet = not sys.stderr.isatty() or bool(os.environ.get("CI"))
    return tqdm(total=total, desc=label, unit="s", disable=quiet, dynamic_ncols=True,
                bar_format="{desc}: {percentage:3.0f}%|{bar}| {n:.0f}/{total:.0f} s of the "
                           "cycle [{elapsed}<{remaining}]")


GEAR_INPUTS, VEHICLE_INPUTS = ("T_s", "v_air"), ("T_brake",)


def fmpy_master(gear_fmu, vehicle_fmu, gear_values, vehicle_values, h, w_rest=0.0, ramp=True):
    return master.GearVehicle(gear_fmu, vehicle_fmu, gear_values, vehicle_values, GEAR_OUT,
                              VEHICLE_OUT, GEAR_INPUTS, VEHICLE_INPUTS, w_rest=w_rest,
                              ramp=ramp)


def hosted(Execution):
    """The master of an outside host (Execution: its driver's class)."""
    def make(gear_fmu, vehicle_fmu, gear_values, vehicle_values, h):
        return host.GearVehicle(Execution, gear_fmu, vehicle_fmu, gear_values, vehicle_values, h,
                                GEAR_OUT, VEHICLE_OUT, GEAR_INPUTS, VEHICLE_INPUTS)
    return make


MASTERS = {"fmpy": fmpy_master, "libcosim": hosted(libcosim.Execution),
           "ecos": hosted(ecos.Execution)}
I_V, I_WP = VEHICLE_OUT.index("v"), GEAR_OUT.index("w_p")
DRIVELINE_RECORD = ("I_s", "I_p", "I_g", "I_w", "ratio", "k_t1", "k_t2")


def _driver(gear, vehicle):
    """The driver for this gear (an Instance after initialisation: ratio and inertias)."""
    ratio = float(gear.get("ratio"))
    J = gear.reals(["I_w"])[0] + gear.get("I_g") + (gear.get("I_p") + gear.get("I_s")) \
        * ratio ** 2
    return Driver(vehicle, ratio, J)


def simulate(cycle, gear_fmu, vehicle_fmu, level, T_oil0, T_amb, h, extra, label,
             vehicle=None, master="fmpy", until=None, ramp=True):
    """One co-simulation over the cycle (up to `until` s if given) in the named master; the
    recorded outputs at every communication point. The state at t = 0 and the driver's data
    come from fmpy's initialisation in every master: libcosim initialises inside its first
    step and cannot be read before it. fmpy's master gives the gear its inputs as ramps
    (hypoid.cosim.master.GearVehicle's `ramp`, unless ramp is False); libcosim and Ecos hold
    them."""
    vehicle = (vehicle or Vehicle()).for_air(T_amb, fmu_parameters(vehicle_fmu))
    wall = time.perf_counter()
    I_w0 = float(TABLE.variable("I_w").start)
    g_values = gear_start(level, vehicle, I_w0, T_oil0, T_amb, extra)
    m = fmpy_master(gear_fmu, vehicle_fmu, g_values, vehicle.fmu_values(), h,
                    vehicle.v_rest / vehicle.r_dyn, ramp)
    driver, (gv, vv) = _driver(m.gear, vehicle), m.outputs
    driveline = {n: float(m.gear.get(n)) for n in DRIVELINE_RECORD}
    if master != "fmpy":
        m.close()
        m = MASTERS[master](gear_fmu, vehicle_fmu, g_values, vehicle.fmu_values(), h)
    t_end = cycle.t[-1] if until is None else min(cycle.t[-1], cycle.t[0] + until)
    n = int(round((t_end - cycle.t[0]) / h))
    names = ["time", "v_target", "grade", "T_s", "T_brake", "F_grade"] + GEAR_OUT + VEHICLE_OUT
    rec = np.empty((n + 1, len(names)))
    t, T_s, T_b, F_grade = cycle.t[0], 0.0, 0.0, 0.0
    bar = progress(float(t_end - cycle.t[0]), label)
    try:
        for k in range(n + 1):
            v_now, slope = cycle.speed(t), cycle.slope(t)
            rec[k] = [t, v_now, 100 * slope, T_s, T_b, F_grade, *gv, *vv]
            if k == n:
                break
            T_s, T_b = driver.command(v_now, cycle.speed(t + h), vv[I_V], h, gv[I_WP], slope)
            # the grade's load at the wheel, unless the held brakes of a standing car take it
            F_grade = 0.0 if driver.standing else vehicle.grade_force(vv[I_V], slope)
            extra_in = {"T_w_add": vehicle.r_dyn * F_grade} if F_grade else {}
            gv, vv = m.step(k * h, h, [T_s, vehicle.air_factor * abs(vv[I_V])], [T_b],
                            **extra_in)
            t = cycle.t[0] + (k + 1) * h
            bar.update(h)
    finally:
        bar.close()
        m.close()
    rows = {name: rec[:, j] for j, name in enumerate(names)}
    # the grade's work: the vehicle FMU runs at grade 0, the master applies the grade force
    work = 0.5 * (rows["F_grade"][1:] * rows["v"][1:] + rows["F_grade"][1:] * rows["v"][:-1]) * h
    rows["E_grade"] = np.concatenate([[0.0], np.cumsum(work)])
    C_sump = float(g_values.get("C_sump", TABLE.variable("C_sump").start))
    return Run(label, T_oil0, rows, time.perf_counter() - wall, C_sump, vehicle, driveline)


