"""Drive a passenger car with the hypoid axle over a speed cycle and report what the axle costs:
the energy at the wheels, the axle's losses by part (mesh, churning, bearings, seals) and by
cycle phase, the mean axle efficiency and the oil temperature, from a cold start and from a warm
axle, with the difference.

The scene (docs/axle.md): the gear FMU (load_mode = torque, axle_losses = full, thermal_model =
sump) carries the vehicle's inertia at its wheel end (I_w += m r^2 + J_wheels) and the
half-shaft compliance (k_t2 = k_hs); the vehicle FMU (build/LongitudinalVehicle.fmu, coupling =
2) returns the road load and the brake torque at the wheel speed; a driver (a PI speed
controller with feed-forward of the cycle's acceleration) sets the propeller-shaft torque T_s
and the brakes. Both FMUs run in fmpy's co-simulation master (Jacobi, communication step
--step) or, with --master libcosim, in libcosim's fixed-step algorithm (libcosimpy; the build's
integer-coded gear FMU). Cycles: WLTC class 3b and NEDC from the European Commission JRC's `wltp` package
(PyPI wltp 0.1.2a0, wltp/cycles/class3.py and nedc.py), or a CSV file with the columns
`time` (s, increasing) and `speed` (km/h), optionally `phase` (a name per row).

Examples:
  hypoid drive-cycle                              WLTC class 3, cold (20 degC) and warm (80 degC)
  hypoid drive-cycle --cycle nedc --no-warm
  hypoid drive-cycle --cycle my_route.csv --t-amb 5 --set gear_set=2
  hypoid drive-cycle --level full                 the paper's full model (slow: minutes)
  hypoid drive-cycle --set friction_preset=paper  friction data: runs the fast level (says so)

A --set parameter that the default level does not reach (friction data: not in the built-in
maps; the compliant mesh's: not in the rigid one) moves it to the cheapest level that it
reaches, and one line says so; with --level given, such a parameter is refused (exit 2).

Writes <out>/<name>/: summary.json, summary.md, cold.csv (and warm.csv), drive_cycle.png; the
folder appears only when the run is complete."""

import json
import math
import os
import pathlib
import shutil
import tempfile
import time
from dataclasses import asdict, dataclass, field

import numpy as np

from hypoid.cli import args as cliargs
from hypoid.maps.effmap import TEMPERATURES_C, builtin_map_fits
from hypoid.fmu.instance import TABLE, Instance
from hypoid.paths import user_path

KMH = 1 / 3.6
ZERO_C = 273.15
ROOT = pathlib.Path(__file__).resolve().parents[2]
DEFAULT_VEHICLE_FMU = ROOT / "build" / "LongitudinalVehicle.fmu"

# The fidelity levels of the gear FMU for vehicle energy (docs/work-precision.md, "Which level
# and settings for which use"): map, its pick for oil at 20 degC or warmer, the rigid mesh with
# the mesh friction from the full model's efficiency map (resources/maps, 20-130 degC; the
# default); fast, its pick for cold starts below 20 degC, the rigid mesh with the friction model
# itself; full: the paper's model.
LEVELS = {
    "fast": {"mesh_model": "rigid", "friction_model": "ehl_thermal", "rtol": 1e-4},
    "map": {"mesh_model": "rigid", "friction_model": "map", "rtol": 1e-5},
    "full": {"mesh_model": "varying", "friction_model": "ehl_thermal", "rtol": 1e-6},
}

# The map level's lowest oil temperature: the built-in maps' (hypoid effmap's grid). Below it the
# map holds its 20 degC edge, so a cycle that starts or can cool below it runs the fast level.
MAP_T_MIN = min(TEMPERATURES_C) + ZERO_C

# What a --set parameter reaches at each level (docs/axle.md, "Which level a --set reaches"):
# the map level takes the mesh friction from a map made with the default friction and gear data
# (only the gear set and lubricant have a built-in map each), and the rigid mesh of the map and
# fast levels has no stiffness, transmission error or backlash. Every parameter of the gear FMU
# is in one of the three groups or is named in reaching_levels (a test checks it), so that a new
# one is placed deliberately.
REACHES_EVERY_LEVEL = frozenset({
    "gear_set", "lubricant", "load_mode", "solver", "rtol", "atol",
    "max_step", "steps_per_mesh_cycle", "I_s", "I_p", "I_g", "I_w", "k_t1", "k_t2", "zeta_2",
    "zeta_3", "zeta_4", "w_p0", "governor_bandwidth", "n_avg_cycles", "axle_losses",
    "thermal_model", "ring_d", "ring_b", "r_m_p", "r_m_g", "delta_p", "delta_g", "beta_p",
    "beta_g", "alpha_n", "oil_level", "V_oil", "brg_ph_dm", "brg_ph_Y", "brg_ph_x", "brg_pt_dm",
    "brg_pt_Y", "brg_pt_x", "brg_gn_dm", "brg_gn_Y", "brg_gn_x", "brg_gf_dm", "brg_gf_Y",
    "brg_gf_x", "brg_f0", "brg_f1", "F_pre_p", "F_pre_g", "d_seal_p", "d_seal_w", "T_oil0",
    "C_sump", "A_housing", "L_housing", "eps_housing", "h_housing"})
MESH_FRICTION = frozenset({    # the friction model and its data: not in the built-in maps
    "gear_set_file", "lubricant_file", "mu_const", "E", "nu", "k_s", "rho_s", "c_s", "tau_0",
    "varsigma_a", "sigma_s", "eta_beta_sigma", "sigma_over_beta", "T_inlet_rise", "Lambda_cap",
    "k_f", "hertz_model", "roelands_z", "shear_pressure", "relaxation", "friction_preset",
    "friction_table", "tooth_data", "preset"})
MESH_DYNAMICS = frozenset({    # the compliant mesh only: the full level
    "b", "backlash_model", "backlash_smoothing", "k_m_scale", "e_0_scale"})


def reaching_levels(name, value, extra):
    """The levels at which `--set name=value` reaches the result. A parameter at its default
    reaches them all; with efficiency_map_file the map is the user's own, made (hypoid effmap
    --set ...) with the friction they set."""
    if name == "efficiency_map_file":
        return {"map"}
    if name == "friction_model":  # the levels' own settings, which --set overrides
        return {"map"} if value == "map" else {"fast", "full"}
    if name == "mesh_model":
        return {"map", "fast"} if value == "rigid" else {"full"}
    if value == TABLE.start(name):  # the default: the levels are made with it
        return set(LEVELS)
    if name in MESH_DYNAMICS:
        return {"full"}
    if name in MESH_FRICTION and "efficiency_map_file" not in extra:
        return {"fast", "full"}
    return set(LEVELS)


def unreached(level, extra):
    """The --set names that do not reach the result at `level`."""
    return [n for n, v in extra.items() if level not in reaching_levels(n, v, extra)]


def default_level(T_amb, starts, extra):
    """The drive cycle's level when none is asked for (docs/work-precision.md): map while the oil
    starts and the air stays in the map's range and a built-in map exists (none for a gear-set
    or lubricant file of one's own, nor for the tooth data the maps were not made with), or when a
    map of one's own is given; else fast; and the cheapest level that every --set parameter
    reaches (fast for friction data, full for the compliant mesh's)."""
    in_range = min(T_amb, *starts) >= MAP_T_MIN and builtin_map_fits(extra)
    first = "map" if in_range or "efficiency_map_file" in extra else "fast"
    order = ["map", "fast", "full"]
    return next(lv for lv in order[order.index(first):] if not unreached(lv, extra))


def _why(level, name, value):
    """Why `--set name=value` does not reach the result at `level`, in a few words."""
    if name in MESH_FRICTION:
        return (f"the {level} level takes the mesh friction from the built-in efficiency map, "
                "made with the default friction and gear data")
    if name in MESH_DYNAMICS:
        return f"the {level} level's rigid mesh has no stiffness, transmission error or backlash"
    if name == "efficiency_map_file":
        return "only the map level reads a map"
    return f"{name} = {value} is not the {level} level's {LEVELS[level][name]}"


def check_level(level, extra):
    """A UsageError when a --set parameter does not reach the result at the level asked for."""
    missed = unreached(level, extra)
    if not missed:
        return
    name, value = missed[0], extra[missed[0]]
    reach = sorted(reaching_levels(name, value, extra), key=list(LEVELS).index)
    own_map = " (or give efficiency_map_file=, a map made with hypoid effmap --set ...)" \
        if level == "map" and name in MESH_FRICTION else ""
    raise cliargs.UsageError(f"--set {', '.join(missed)} with --level {level}: "
                             f"{_why(level, name, value)}{own_map}; it reaches the result at "
                             f"--level {' or '.join(reach)}")


def choose_level(asked, T_amb, starts, extra):
    """(level, note): the level asked for (checked), or the default with a one-line note when a
    --set parameter moved it off the level the temperatures and data files give."""
    if asked:
        check_level(asked, extra)
        return asked, None
    files = {k: v for k, v in extra.items()
             if k in ("gear_set_file", "lubricant_file", "efficiency_map_file")}
    base, level = default_level(T_amb, starts, files), default_level(T_amb, starts, extra)
    if level == base:
        return level, None
    missed = unreached(base, extra)
    return level, (f"--set {', '.join(missed)} does not reach the result at the {base} level "
                   f"({_why(base, missed[0], extra[missed[0]])}): running the {level} level")


GEAR_OUT = ["w_w", "w_p", "T_oil", "P_loss", "P_loss_viscous", "P_churn", "P_bearings",
            "P_seals", "P_axle", "P_in_axle", "eta_axle", "E_in", "E_out", "E_friction",
            "E_churn", "E_bearings", "E_seals", "Q_housing", "Q_dot_housing", "E_damping",
            "E_excitation", "E_stored"]
VEHICLE_OUT = ["T_hs", "v", "x", "E_road", "E_brake", "E_grade"]
PARTS = {"mesh": "E_friction", "churning": "E_churn", "bearings": "E_bearings",
         "seals": "E_seals"}


# ---------------------------------------------------------------------------- cycles
@dataclass
class Cycle:
    name: str
    t: np.ndarray        # s
    v: np.ndarray        # m/s
    phases: list         # [(name, t_start, t_end)]
    source: str

    def speed(self, t):
        return float(np.interp(t, self.t, self.v))


WLTC3_PHASES = ("low", "medium", "high", "extra-high")


def builtin_cycle(name):
    """WLTC class 3b or NEDC from the `wltp` package (speeds in km/h at 1 Hz)."""
    try:
        from wltp.cycles import class3, nedc
    except ImportError as e:
        raise cliargs.UsageError(f"--cycle {name}: the wltp package is missing ({e}); "
                                 "install the project with scripts/setup.sh") from None
    if name == "wltc3":
        data, names = class3.class_data_b(), WLTC3_PHASES
        source = "WLTC class 3b, wltp 0.1.2a0 (European Commission JRC), wltp/cycles/class3.py"
    else:
        data, names = nedc.cycle_data(), ("ECE (urban)", "EUDC (extra-urban)")
        source = "NEDC, wltp 0.1.2a0 (European Commission JRC), wltp/cycles/nedc.py"
    v = np.asarray(data["cycle"], float) * KMH
    t = np.arange(len(v), dtype=float)
    phases = [(n, float(a), float(b)) for n, (a, b) in zip(names, data["parts"])]
    # the parts are [first, last] second: close the gaps between them
    phases = [(n, a, phases[k + 1][1] if k + 1 < len(phases) else t[-1])
              for k, (n, a, _) in enumerate(phases)]
    return Cycle(name, t, v, phases, source)


def read_csv_cycle(path):
    """A user's cycle: columns time [s] (strictly increasing, from >= 0) and speed [km/h]
    (finite, >= 0), optionally phase. Every problem is one UsageError naming file, line and
    value."""
    p = pathlib.Path(path)
    try:
        lines = p.read_text().splitlines()
    except (OSError, UnicodeDecodeError) as e:
        raise cliargs.UsageError(f"--cycle {p}: cannot read it ({e})") from None
    rows = [(n, line) for n, line in enumerate(lines, 1) if line.strip() and
            not line.lstrip().startswith("#")]
    if not rows:
        raise cliargs.UsageError(f"--cycle {p}: the file is empty")
    header = [h.strip().lower() for h in rows[0][1].split(",")]
    missing = [c for c in ("time", "speed") if c not in header]
    if missing:
        raise cliargs.UsageError(f"--cycle {p}: line {rows[0][0]}: missing column(s) "
                                 f"{', '.join(missing)}; the header must name time (s) and "
                                 f"speed (km/h), optionally phase (found: {', '.join(header)})")
    it, iv = header.index("time"), header.index("speed")
    ip = header.index("phase") if "phase" in header else None
    t, v, ph = [], [], []
    for n, line in rows[1:]:
        cells = [c.strip() for c in line.split(",")]
        if len(cells) != len(header):
            raise cliargs.UsageError(f"--cycle {p}: line {n}: {len(cells)} values for "
                                     f"{len(header)} columns")
        try:
            tt, vv = float(cells[it]), float(cells[iv])
        except ValueError:
            raise cliargs.UsageError(f"--cycle {p}: line {n}: time {cells[it]!r} or speed "
                                     f"{cells[iv]!r} is not a number") from None
        if not (math.isfinite(tt) and math.isfinite(vv)):
            raise cliargs.UsageError(f"--cycle {p}: line {n}: time {tt} s or speed {vv} km/h "
                                     "is not finite")
        if vv < 0 or tt < 0:
            raise cliargs.UsageError(f"--cycle {p}: line {n}: time {tt} s and speed {vv} km/h "
                                     "must not be negative")
        if t and tt <= t[-1]:
            raise cliargs.UsageError(f"--cycle {p}: line {n}: time {tt} s does not increase "
                                     f"(the row before has {t[-1]} s)")
        t.append(tt)
        v.append(vv * KMH)
        ph.append(cells[ip] if ip is not None else "all")
    if len(t) < 2:
        raise cliargs.UsageError(f"--cycle {p}: at least two rows of time and speed are needed")
    phases = []
    for k, name in enumerate(ph):
        if not phases or phases[-1][0] != name:
            phases.append([name, t[k], t[k]])
        phases[-1][2] = t[min(k + 1, len(t) - 1)]
    return Cycle(p.stem, np.array(t), np.array(v), [tuple(x) for x in phases], f"file {p}")


def load_cycle(text):
    if text in ("wltc3", "nedc"):
        return builtin_cycle(text)
    if not text.lower().endswith(".csv"):
        raise cliargs.UsageError(f"--cycle {text!r}: give wltc3, nedc or a .csv file")
    return read_csv_cycle(user_path(text))


# ---------------------------------------------------------------------------- vehicle, driver
@dataclass
class Vehicle:
    """A mid-size passenger car (the vehicle FMU's defaults, docs/cosimulation.md); v_eps is
    wider than the FMU's default so that the rolling resistance and brakes stay smooth over a
    long communication step at standstill (docs/axle.md)."""
    m: float = 1500.0        # kg
    r_dyn: float = 0.3       # m
    J_wheels: float = 3.0    # kg m^2
    c_rr: float = 0.012
    CdA: float = 0.7         # m^2
    rho_air: float = 1.2     # kg/m^3
    k_hs: float = 1.2e4      # N m/rad, both half-shafts and tyres
    v_eps: float = 0.5       # m/s
    v_rest: float = 1e-6     # m/s: below it the car stands (3.6 mm an hour; docs/axle.md)
    air_factor: float = 0.5  # air speed over the housing / vehicle speed (assumed)

    def fmu_values(self):
        return {"m": self.m, "r_dyn": self.r_dyn, "J_wheels": self.J_wheels, "c_rr": self.c_rr,
                "CdA": self.CdA, "rho_air": self.rho_air, "k_hs": self.k_hs,
                "v_eps": self.v_eps, "coupling": 2.0}

    def road_force(self, v):
        return (self.c_rr * self.m * 9.81 * math.tanh(v / self.v_eps)
                + 0.5 * self.rho_air * self.CdA * v * abs(v))


@dataclass
class Driver:
    """Speed tracking: feed-forward of the cycle's acceleration and road load, PI on the speed
    error; negative demand goes to engine braking (down to T_s_min) and then to the brakes."""
    vehicle: Vehicle
    ratio: float             # N_g / N_p
    J_wheel: float           # all inertia referred to the wheel [kg m^2]
    k_p: float = 1.0         # 1/s
    k_i: float = 0.1         # 1/s^2
    T_s_max: float = 600.0   # N m at the propeller shaft
    T_s_min: float = -20.0   # engine braking at the propeller shaft, in gear (v > 3 m/s)
    integral: float = field(default=0.0, init=False)

    def command(self, v_now, v_next, v, h):
        """(T_s, T_brake) for the step towards v_next (the cycle's speed at the step's end)."""
        veh, r = self.vehicle, self.vehicle.r_dyn
        if v_next <= 0.0 and v < 0.3:
            self.integral = 0.0
            return 0.0, 300.0  # standing: no drive, brakes held
        e = v_now - v
        self.integral = float(np.clip(self.integral + e * h, -2.0, 2.0))
        a = (v_next - v_now) / h + self.k_p * e + self.k_i * self.integral
        T_wheel = self.J_wheel / r * a + r * veh.road_force(v_now)
        T_s = T_wheel / self.ratio
        floor = self.T_s_min if v > 3.0 else 0.0
        if T_s >= floor:
            return min(T_s, self.T_s_max), 0.0
        return floor, floor * self.ratio - T_wheel


# ---------------------------------------------------------------------------- the run
@dataclass
class Run:
    label: str
    T_oil0: float            # K
    rows: dict               # name -> array over the steps (time first)
    wall: float              # s
    C_sump: float            # J/K, the gear FMU's (for the heat balance)


def gear_start(level, vehicle, I_w0, T_oil0, T_amb, extra):
    values = dict(LEVELS[level])
    values.update(load_mode="torque", axle_losses="full", thermal_model="sump", T_s=0.0,
                  T_w=0.0, w_p0=0.0, T_oil0=T_oil0, T_amb=T_amb, T_bath=T_oil0,
                  I_w=I_w0 + vehicle.m * vehicle.r_dyn ** 2 + vehicle.J_wheels,
                  k_t2=vehicle.k_hs)
    values.update(extra)
    return values


class FmpyMaster:
    """The gear and the vehicle in fmpy (hypoid.fmu.instance), Jacobi: both step over [t, t + h]
    with the inputs of t (T_w = the vehicle's T_hs, w_w = the gear's w_w, both of t). A wheel
    speed below w_rest reaches the vehicle as 0: the car stands, and its brakes and rolling
    resistance hold it with a constant torque instead of one the gear's integrator noise makes
    (each change of T_w restarts the gear FMU's integrator: docs/axle.md)."""

    def __init__(self, gear_fmu, vehicle_fmu, gear_values, vehicle_values, h, w_rest=0.0):
        self.gear, self.car = Instance(gear_fmu, name="gear"), Instance(vehicle_fmu,
                                                                         name="vehicle")
        self.gear.start(gear_values)
        self.car.start(vehicle_values)
        self.g_refs = [self.gear.ref(x) for x in GEAR_OUT]
        self.v_refs = [self.car.ref(x) for x in VEHICLE_OUT]
        self.g_in = [self.gear.ref(x) for x in ("T_s", "T_w", "v_air")]
        self.v_in = [self.car.ref(x) for x in ("w_w", "T_brake")]
        self.h, self.k, self.w_rest = h, 0, w_rest
        self.outputs = self._read()

    def _read(self):
        return (self.gear._call(self.gear.slave.getReal, self.g_refs),
                self.car._call(self.car.slave.getReal, self.v_refs))

    def step(self, T_s, T_brake, v_air):
        gv, vv = self.outputs
        self.gear._call(self.gear.slave.setReal, self.g_in, [T_s, vv[I_THS], v_air])
        w_w = gv[I_WW] if abs(gv[I_WW]) >= self.w_rest else 0.0
        self.car._call(self.car.slave.setReal, self.v_in, [w_w, T_brake])
        t = self.k * self.h
        self.gear.do_step(t, self.h)
        self.car.do_step(t, self.h)
        self.k += 1
        self.outputs = self._read()
        return self.outputs

    def close(self):
        self.gear.close()
        self.car.close()


class LibcosimMaster:
    """The same scene in libcosim's fixed-step (Jacobi) algorithm with the integer-coded gear
    FMU: T_hs -> T_w and w_w -> w_w are libcosim connections; T_s, v_air and T_brake go in
    through its override manipulator before each step."""

    def __init__(self, gear_fmu, vehicle_fmu, gear_values, vehicle_values, h):
        from hypoid.cosim import libcosim
        from hypoid.fmu.instance import TABLE

        self.ex = libcosim.Execution(h)
        self.ex.add("gear", libcosim.intenum_fmu(gear_fmu))
        self.ex.add("vehicle", vehicle_fmu)
        self.ex.initial("gear", {var.name: x for var, x in TABLE.fmu_values(gear_values)})
        self.ex.initial("vehicle", vehicle_values)
        self.ex.connect("vehicle", "T_hs", "gear", "T_w")
        self.ex.connect("gear", "w_w", "vehicle", "w_w")
        self.g_refs = [self.ex.ref("gear", x) for x in GEAR_OUT]
        self.v_refs = [self.ex.ref("vehicle", x) for x in VEHICLE_OUT]

    def step(self, T_s, T_brake, v_air):
        self.ex.set_reals("gear", ["T_s", "v_air"], [T_s, v_air])
        self.ex.set_reals("vehicle", ["T_brake"], [T_brake])
        self.ex.step()
        return self.ex.reals("gear", self.g_refs), self.ex.reals("vehicle", self.v_refs)

    def close(self):
        self.ex.close()


MASTERS = {"fmpy": FmpyMaster, "libcosim": LibcosimMaster}
I_WW, I_THS, I_V = GEAR_OUT.index("w_w"), VEHICLE_OUT.index("T_hs"), VEHICLE_OUT.index("v")


def _driver(gear, vehicle):
    """The driver for this gear (an Instance after initialisation: ratio and inertias)."""
    ratio = float(gear.get("ratio"))
    J = gear.reals(["I_w"])[0] + gear.get("I_g") + (gear.get("I_p") + gear.get("I_s")) \
        * ratio ** 2
    return Driver(vehicle, ratio, J)


def simulate(cycle, gear_fmu, vehicle_fmu, level, T_oil0, T_amb, h, extra, label,
             vehicle=None, master="fmpy", until=None):
    """One co-simulation over the cycle (up to `until` s if given) in the named master; the
    recorded outputs at every communication point. The state at t = 0 and the driver's data
    come from fmpy's initialisation in both masters: libcosim initialises inside its first
    step and cannot be read before it."""
    vehicle = vehicle or Vehicle()
    wall = time.perf_counter()
    I_w0 = float(TABLE.variable("I_w").start)
    g_values = gear_start(level, vehicle, I_w0, T_oil0, T_amb, extra)
    m = FmpyMaster(gear_fmu, vehicle_fmu, g_values, vehicle.fmu_values(), h,
                   vehicle.v_rest / vehicle.r_dyn)
    driver, (gv, vv) = _driver(m.gear, vehicle), m.outputs
    if master != "fmpy":
        m.close()
        m = MASTERS[master](gear_fmu, vehicle_fmu, g_values, vehicle.fmu_values(), h)
    t_end = cycle.t[-1] if until is None else min(cycle.t[-1], cycle.t[0] + until)
    n = int(round((t_end - cycle.t[0]) / h))
    names = ["time", "v_target", "T_s", "T_brake"] + GEAR_OUT + VEHICLE_OUT
    rec = np.empty((n + 1, len(names)))
    t, T_s, T_b = cycle.t[0], 0.0, 0.0
    try:
        for k in range(n + 1):
            v_now = cycle.speed(t)
            rec[k] = [t, v_now, T_s, T_b, *gv, *vv]
            if k == n:
                break
            T_s, T_b = driver.command(v_now, cycle.speed(t + h), vv[I_V], h)
            gv, vv = m.step(T_s, T_b, vehicle.air_factor * abs(vv[I_V]))
            t = cycle.t[0] + (k + 1) * h
    finally:
        m.close()
    rows = {name: rec[:, j] for j, name in enumerate(names)}
    C_sump = float(g_values.get("C_sump", TABLE.variable("C_sump").start))
    return Run(label, T_oil0, rows, time.perf_counter() - wall, C_sump)


# ---------------------------------------------------------------------------- results
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
            "heat_residual_relative": heat / E_through,
            "energy_residual_relative": energy / E_through}


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
        "axle_losses_J": losses, "axle_loss_J": E_axle,
        "mesh_viscous_J": float(np.sum(0.5 * (r["P_loss_viscous"][1:]
                                              + r["P_loss_viscous"][:-1])) * h),
        "energy_into_axle_J": E_through,
        "mean_axle_efficiency": 1.0 - E_axle / E_through if E_through > 0 else float("nan"),
        "T_oil_degC": {"start": float(r["T_oil"][0]) - ZERO_C, "end": float(r["T_oil"][-1])
                       - ZERO_C, "max": float(np.max(r["T_oil"])) - ZERO_C},
        "heat_to_air_J": float(r["Q_housing"][-1]),
        "speed_tracking_rms_kmh": float(np.sqrt(np.mean((r["v"] - r["v_target"]) ** 2)) / KMH),
        "phases": phases,
        "audit": audit(run, E_through),
    }


def difference(cold, warm):
    """warm - cold of the headline figures."""
    d = {part: warm["axle_losses_J"][part] - cold["axle_losses_J"][part] for part in PARTS}
    return {"axle_losses_J": d, "axle_loss_J": warm["axle_loss_J"] - cold["axle_loss_J"],
            "axle_loss_relative": warm["axle_loss_J"] / cold["axle_loss_J"] - 1.0,
            "mean_axle_efficiency_points": 100 * (warm["mean_axle_efficiency"]
                                                  - cold["mean_axle_efficiency"]),
            "T_oil_end_degC": warm["T_oil_degC"]["end"] - cold["T_oil_degC"]["end"]}


def markdown(meta, runs, diff):
    kj = 1e-3
    lines = [f"# hypoid drive-cycle: {meta['cycle']}", "", f"Cycle: {meta['source']}; "
             f"level {meta['level']}; {meta['master']} master; step {meta['step_s']} s; "
             f"air {meta['T_amb_degC']:.0f} degC.",
             "", "| | " + " | ".join(s["label"] for s in runs) + " |",
             "|---|" + "---|" * len(runs)]

    def row(name, fn):
        lines.append(f"| {name} | " + " | ".join(fn(s) for s in runs) + " |")

    row("oil at start / end / max (degC)", lambda s: "{start:.1f} / {end:.1f} / {max:.1f}".format(
        **s["T_oil_degC"]))
    row("distance (km)", lambda s: f"{s['distance_km']:.2f}")
    row("energy at the wheels, traction (kJ)",
        lambda s: f"{s['wheel_energy_J']['traction'] * kj:.0f}")
    row("energy into the axle (kJ)", lambda s: f"{s['energy_into_axle_J'] * kj:.0f}")
    for part in PARTS:
        row(f"loss: {part} (kJ)", lambda s, p=part: f"{s['axle_losses_J'][p] * kj:.1f}")
    row("axle loss (kJ)", lambda s: f"{s['axle_loss_J'] * kj:.1f}")
    row("mean axle efficiency (%)", lambda s: f"{100 * s['mean_axle_efficiency']:.2f}")
    row("speed tracking RMS (km/h)", lambda s: f"{s['speed_tracking_rms_kmh']:.2f}")
    row("residual of the heat balance / energy audit (of the energy into the axle)",
        lambda s: "{heat_residual_relative:.1e} / {energy_residual_relative:.1e}".format(
            **s["audit"]))
    row("wall time (s)", lambda s: f"{s['wall_s']:.1f}")
    lines += ["", "Losses by phase (kJ): mesh / churning / bearings / seals = total", ""]
    for s in runs:
        lines.append(f"- {s['label']}: " + "; ".join(
            f"{p['phase']}: " + " / ".join(f"{p['losses_J'][x] * kj:.1f}" for x in PARTS)
            + f" = {p['loss_J'] * kj:.1f}" for p in s["phases"]))
    if diff:
        lines += ["", f"Warm minus cold: axle loss {diff['axle_loss_J'] * kj:+.1f} kJ "
                  f"({100 * diff['axle_loss_relative']:+.1f} %), mean efficiency "
                  f"{diff['mean_axle_efficiency_points']:+.2f} %-points; "
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


# ---------------------------------------------------------------------------- command line
def _parser():
    ap = cliargs.Parser("hypoid drive-cycle", __doc__)
    ap.add_fmu()
    ap.add_argument("--vehicle-fmu", type=user_path, default=str(DEFAULT_VEHICLE_FMU),
                    help="the vehicle FMU (default: build/LongitudinalVehicle.fmu)")
    ap.add_argument("--cycle", default="wltc3", help="wltc3 (default), nedc or a CSV file")
    ap.add_argument("--level", choices=sorted(LEVELS),
                    help="gear FMU fidelity: map (rigid mesh, the mesh friction from the "
                         "efficiency map; the default when the oil and the air are at 20 degC or "
                         "warmer, the map's range), fast (the same with the friction model "
                         "itself, ~4x dearer; the default below 20 degC) or full (the paper's "
                         "model)")
    ap.add_argument("--step", type=float, default=0.05,
                    help="communication step of the co-simulation in s (0.05)")
    ap.add_argument("--t-amb", type=float, default=20.0, help="air temperature in degC (20)")
    ap.add_argument("--t-oil0", type=float, help="oil at the start in degC (default: --t-amb)")
    ap.add_argument("--warm", type=float, default=80.0,
                    help="oil at the start of the warm run in degC (80)")
    ap.add_argument("--no-warm", action="store_true", help="only the cold start")
    ap.add_argument("--master", choices=sorted(MASTERS), default="fmpy",
                    help="co-simulation master: fmpy (default) or libcosim (libcosimpy, with "
                         "the build's integer-coded gear FMU)")
    ap.add_argument("--until", type=float,
                    help="stop after this many seconds of the cycle (default: the whole cycle)")
    ap.add_argument("--out", type=user_path, default=user_path("results"),
                    help="parent folder of the run's folder (default: ./results)")
    ap.add_argument("--name", help="the run's folder name (default: drive_cycle_<cycle>)")
    ap.add_set()
    return ap


def check_args(args):
    if not 1e-3 <= args.step <= 1.0:
        raise cliargs.UsageError(f"--step {args.step}: between 0.001 and 1 s")
    if args.until is not None and not args.until >= args.step:
        raise cliargs.UsageError(f"--until {args.until}: at least one step ({args.step} s)")
    for name in ("t_amb", "t_oil0", "warm"):
        value = getattr(args, name)
        if value is not None and not -70.0 <= value <= 170.0:
            raise cliargs.UsageError(f"--{name.replace('_', '-')} {value}: a temperature "
                                     "between -70 and 170 degC")


def main(argv):
    args = _parser().parse_args(argv)
    check_args(args)
    extra = cliargs.parse_set(args.set)
    cycle = load_cycle(args.cycle)
    gear_fmu, vehicle_fmu = cliargs.fmu_path(args.fmu), cliargs.fmu_path(args.vehicle_fmu)
    T_amb = args.t_amb + ZERO_C
    starts = [("cold", (args.t_oil0 if args.t_oil0 is not None else args.t_amb) + ZERO_C)]
    if not args.no_warm:
        starts.append(("warm", args.warm + ZERO_C))
    level, note = choose_level(args.level, T_amb, [T0 for _, T0 in starts], extra)
    if note:
        print(f"hypoid drive-cycle: {note}", flush=True)
    runs = [simulate(cycle, gear_fmu, vehicle_fmu, level, T0, T_amb, args.step, extra,
                     label, master=args.master, until=args.until) for label, T0 in starts]
    summaries = [summarise(run, cycle, args.step) for run in runs]
    diff = difference(summaries[0], summaries[1]) if len(summaries) == 2 else None
    meta = {"cycle": cycle.name, "source": cycle.source, "level": level, "level_note": note,
            "gear_fmu_settings": LEVELS[level], "step_s": args.step,
            "master": args.master, "until_s": args.until,
            "T_amb_degC": args.t_amb, "set": extra, "vehicle": asdict(Vehicle())}
    text = markdown(meta, summaries, diff)
    name = args.name or f"drive_cycle_{cycle.name}"
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    final = out / name
    if final.exists():
        raise cliargs.UsageError(f"{final} exists: give another --name or remove it")
    tmp = pathlib.Path(tempfile.mkdtemp(dir=out, prefix=f".{name}."))
    try:
        (tmp / "summary.json").write_text(json.dumps(
            {"meta": meta, "runs": summaries, "warm_minus_cold": diff}, indent=2) + "\n")
        (tmp / "summary.md").write_text(text)
        for run in runs:
            write_csv(run, tmp / f"{run.label}.csv")
        plot(cycle, runs, tmp / "drive_cycle.png")
        os.replace(tmp, final)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    print(text, end="")
    print(f"hypoid drive-cycle: wrote {final}/ (summary.json, summary.md, "
          + ", ".join(f"{r.label}.csv" for r in runs) + ", drive_cycle.png)")
    return 0
