"""The car around the axle and its driver: the vehicle FMU's parameters by name (--set m=1800 or
a vehicle file), the air density from the air temperature, the engine's drag torque (engine
braking) against the propeller shaft's speed, and the speed-tracking driver.

A vehicle file (TOML; every key optional, SI units unless the key says otherwise):

    [vehicle]              # the vehicle FMU's parameters by name (its modelDescription)
    m = 1800.0             # kg
    r_dyn = 0.32           # m
    CdA = 0.68             # m^2
    c_rr = 0.010
    J_wheels = 3.6         # kg m^2, wheels, tyres, discs and half-shafts at the wheel
    # rho_air: kg/m^3; left out, it follows the air temperature (ideal gas at pressure_Pa)
    [driveline]            # the gear FMU's inertias (kg m^2), each at its own shaft
    I_s = 0.08             # propeller shaft, gearbox output and what turns with it
    [engine]               # at the propeller shaft (the gearbox's ratio included)
    T_max_Nm = 600.0       # most drive torque
    drag_speed_rpm = [0, 1000, 2000, 4000]    # propeller-shaft speeds of the drag map
    drag_torque_Nm = [-10, -15, -22, -40]     # engine braking there (<= 0; linear between,
                                              # held beyond the ends)
    clutch_open_below_kmh = 10.8              # no engine braking below this speed
    [air]
    pressure_Pa = 101325.0

Unknown sections or keys, a non-positive mass, radius or CdA, a grade beyond +-30 % and the like
are refused with one line naming the file, the key and the value."""

import math
from dataclasses import dataclass, field

from hypoid import csvtext
from hypoid.drivecycle.interp import interp
from hypoid.errors import UsageError

R_AIR = 287.05           # J/(kg K), dry air (ISO 2533)
P_AIR = 101325.0         # Pa, ISO 2533 sea level
ZERO_C = 273.15
GRADE_MAX = 0.30         # rise over run
# The drive cycle's car (a mid-size passenger car, docs/cosimulation.md); v_eps wider than the
# FMU's default so that the rolling resistance and brakes stay smooth over a long communication
# step at standstill (docs/axle.md). The vehicle FMU's other parameters keep its start values.
CAR = {"m": 1500.0, "r_dyn": 0.3, "J_wheels": 3.0, "c_rr": 0.012, "CdA": 0.7, "k_hs": 1.2e4,
       "v_eps": 0.5}
# Set by the drive cycle itself: the road-load coupling, a start at rest.
MASTER_SET = {"coupling": 2.0, "v0": 0.0, "T_hs0": 0.0}
POSITIVE = ("m", "r_dyn", "CdA", "k_hs", "v_eps", "g", "rho_air", "h_max")
NON_NEGATIVE = ("J_wheels", "c_rr", "c_hs")
DRIVELINE = ("I_s", "I_p", "I_g", "I_w")
ENGINE_KEYS = ("T_max_Nm", "drag_speed_rpm", "drag_torque_Nm", "clutch_open_below_kmh")
AIR_KEYS = ("pressure_Pa",)


def fmu_parameters(vehicle_fmu):
    """{name: start value} of the vehicle FMU's parameters, from its modelDescription."""
    from fmpy import read_model_description

    md = read_model_description(str(vehicle_fmu))
    return {v.name: float(v.start) for v in md.modelVariables
            if v.causality == "parameter" and v.start is not None}


def air_density(T_amb, p=P_AIR):
    """rho = p / (R T), dry air as an ideal gas (kg/m^3; T in K)."""
    return p / (R_AIR * T_amb)


@dataclass
class Engine:
    """Drive limit and drag (engine braking) at the propeller shaft."""
    T_max: float = 600.0                                   # N m
    drag_rpm: list = field(default_factory=lambda: [0.0])  # propeller-shaft speed, rpm
    drag_Nm: list = field(default_factory=lambda: [-20.0])  # N m (<= 0) at those speeds
    v_clutch: float = 3.0                                  # m/s: below it, no engine braking

    def drag(self, w_p):
        """The engine's drag torque (<= 0) at the propeller-shaft speed w_p (rad/s)."""
        return interp(abs(w_p) * 30.0 / math.pi, self.drag_rpm, self.drag_Nm)


@dataclass
class Vehicle:
    fmu: dict = field(default_factory=lambda: dict(CAR))   # vehicle FMU parameters given
    engine: Engine = field(default_factory=Engine)
    driveline: dict = field(default_factory=dict)          # gear FMU inertias given
    p_air: float = P_AIR     # Pa
    v_rest: float = 1e-6     # m/s: below it the car stands (3.6 mm an hour; docs/axle.md)
    air_factor: float = 0.5  # air speed over the housing / vehicle speed (assumed)
    source: str = "the drive cycle's car"

    def __getattr__(self, name):  # m, r_dyn, ... read as attributes
        fmu = self.__dict__.get("fmu", {})
        if name in fmu:
            return fmu[name]
        raise AttributeError(name)

    def for_air(self, T_amb, defaults):
        """The vehicle FMU's values for air at T_amb (K): its start values, the car's, the
        user's; rho_air from the temperature unless given."""
        values = {**defaults, **self.fmu, **MASTER_SET}
        if "rho_air" not in self.fmu:
            values["rho_air"] = air_density(T_amb, self.p_air)
        return Vehicle(values, self.engine, self.driveline, self.p_air, self.v_rest,
                       self.air_factor, self.source)

    def fmu_values(self):
        """What the vehicle FMU is given: a road at grade 0, the grade is the master's (below)."""
        return {**self.fmu, "grade": 0.0}

    def angle(self, slope):
        """The road's angle (rad): the vehicle's own grade and the route's rise over run."""
        return self.fmu.get("grade", 0.0) + math.atan(slope)

    def road_force(self, v, slope=0.0):
        """Rolling resistance, drag and grade (N) at speed v on a road of rise/run `slope`."""
        f = self.fmu
        return (0.5 * f["rho_air"] * f["CdA"] * v * abs(v) + self.grade_force(v, slope)
                + f["c_rr"] * f["m"] * f.get("g", 9.81) * math.tanh(v / f["v_eps"]))

    def grade_force(self, v, slope):
        """What the grade adds to the level road's load (N), which the vehicle FMU (at grade 0)
        does not: m g sin(angle) and the rolling resistance's cos(angle) - 1. The master adds it
        at the wheel (a standing car's held brakes take it instead)."""
        a, f = self.angle(slope), self.fmu
        if a == 0.0:
            return 0.0
        g = f.get("g", 9.81)
        return f["m"] * g * math.sin(a) + f["c_rr"] * f["m"] * g * (math.cos(a) - 1.0) \
            * math.tanh(v / f["v_eps"])

    def record(self):
        """What summary.json says about the car."""
        return {"vehicle_fmu": dict(self.fmu), "driveline_given": dict(self.driveline),
                "engine": {"T_max_Nm": self.engine.T_max, "drag_speed_rpm": self.engine.drag_rpm,
                           "drag_torque_Nm": self.engine.drag_Nm,
                           "clutch_open_below_kmh": self.engine.v_clutch * 3.6},
                "air_pressure_Pa": self.p_air, "housing_air_factor": self.air_factor,
                "source": self.source}


# ---------------------------------------------------------------------------- checks and files
def _bad(where, key, value, text):
    raise UsageError(f"{where}: {key} = {value!r}: {text}")


def check_fmu_value(where, name, value, known):
    """One vehicle FMU parameter: known, settable, a finite number in its range."""
    if name in MASTER_SET:
        _bad(where, name, value, "set by the drive cycle itself (road-load coupling, start at rest)")
    if name not in known:
        _bad(where, name, value, f"not a vehicle parameter (the vehicle FMU's are "
             f"{', '.join(n for n in known if n not in MASTER_SET)})")
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        _bad(where, name, value, "a finite number is needed")
    value = float(value)
    if name in POSITIVE and not value > 0:
        _bad(where, name, value, "must be positive")
    if name in NON_NEGATIVE and value < 0:
        _bad(where, name, value, "must not be negative")
    if name == "grade" and abs(math.tan(value)) > GRADE_MAX:
        _bad(where, name, value, f"the road angle in rad; beyond +-{100 * GRADE_MAX:g} % "
             f"(+-{math.atan(GRADE_MAX):.3f} rad)")
    return value


def _engine(where, table, engine):
    for key, value in table.items():
        if key not in ENGINE_KEYS:
            _bad(where, f"engine.{key}", value, f"unknown key (known: {', '.join(ENGINE_KEYS)})")
    if "T_max_Nm" in table:
        T = table["T_max_Nm"]
        if isinstance(T, bool) or not isinstance(T, (int, float)) or not T > 0:
            _bad(where, "engine.T_max_Nm", T, "a positive torque in N m")
        engine.T_max = float(T)
    if "clutch_open_below_kmh" in table:
        v = table["clutch_open_below_kmh"]
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not 0 <= v < 200:
            _bad(where, "engine.clutch_open_below_kmh", v, "a speed in km/h, 0 ... 200")
        engine.v_clutch = float(v) / 3.6
    if ("drag_speed_rpm" in table) != ("drag_torque_Nm" in table):
        _bad(where, "engine.drag_speed_rpm / drag_torque_Nm", "", "give both, of equal length")
    if "drag_speed_rpm" in table:
        n, T = table["drag_speed_rpm"], table["drag_torque_Nm"]
        ok = (isinstance(n, list) and isinstance(T, list) and len(n) == len(T) >= 1
              and all(isinstance(x, (int, float)) and not isinstance(x, bool)
                      and math.isfinite(x) for x in n + T))
        if not ok:
            _bad(where, "engine.drag_torque_Nm", T, "two lists of numbers of equal length")
        if any(b <= a for a, b in zip(n, n[1:])) or n[0] < 0:
            _bad(where, "engine.drag_speed_rpm", n, "speeds from >= 0, strictly increasing")
        if any(x > 0 for x in T):
            _bad(where, "engine.drag_torque_Nm", T, "engine braking torques are <= 0")
        engine.drag_rpm, engine.drag_Nm = [float(x) for x in n], [float(x) for x in T]


def read_vehicle_file(path, known):
    """A Vehicle from a TOML vehicle file (the module's docstring)."""
    where = f"--vehicle {path}"
    data = csvtext.read_toml(path, where, UsageError)
    sections = ("vehicle", "driveline", "engine", "air")
    for key, value in data.items():
        if key not in sections or not isinstance(value, dict):
            _bad(where, key, value, f"unknown section or key (the sections are "
                 f"{', '.join(f'[{s}]' for s in sections)})")
    car = Vehicle(source=f"file {path}")
    for name, value in data.get("vehicle", {}).items():
        car.fmu[name] = check_fmu_value(where, name, value, known)
    for name, value in data.get("driveline", {}).items():
        if name not in DRIVELINE:
            _bad(where, f"driveline.{name}", value, f"unknown key (known: {', '.join(DRIVELINE)})")
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not value > 0:
            _bad(where, f"driveline.{name}", value, "a positive inertia in kg m^2")
        car.driveline[name] = float(value)
    _engine(where, data.get("engine", {}), car.engine)
    for key, value in data.get("air", {}).items():
        if key not in AIR_KEYS:
            _bad(where, f"air.{key}", value, f"unknown key (known: {', '.join(AIR_KEYS)})")
        if isinstance(value, bool) or not isinstance(value, (int, float)) \
                or not 3e4 <= value <= 1.2e5:
            _bad(where, f"air.{key}", value, "an air pressure in Pa, 30000 ... 120000")
        car.p_air = float(value)
    return car


def split_set(extra_texts, known):
    """--set NAME=VALUE texts split into (vehicle FMU values, the rest for the gear FMU)."""
    vehicle, rest = {}, []
    for item in extra_texts:
        name, sep, text = item.partition("=")
        if sep and name.strip() in known or name.strip() in MASTER_SET:
            try:
                value = float(text)
            except ValueError:
                _bad("--set", name.strip(), text, "a number is needed")
            vehicle[name.strip()] = check_fmu_value("--set", name.strip(), value, known)
        else:
            rest.append(item)
    return vehicle, rest


@dataclass
class Driver:
    """Speed tracking: feed-forward of the cycle's acceleration and road load (with the route's
    grade), PI on the speed error; negative demand goes to engine braking (down to the engine's
    drag at the propeller shaft's speed, with the clutch closed) and then to the brakes."""
    vehicle: Vehicle
    ratio: float             # N_g / N_p
    J_wheel: float           # all inertia referred to the wheel [kg m^2]
    k_p: float = 1.0         # 1/s
    k_i: float = 0.1         # 1/s^2
    integral: float = field(default=0.0, init=False)
    standing: bool = field(default=True, init=False)

    def command(self, v_now, v_next, v, h, w_p=0.0, slope=0.0):
        """(T_s, T_brake) for the step towards v_next (the cycle's speed at the step's end); w_p
        the propeller shaft's speed (rad/s), slope the road's rise over run."""
        veh, r, engine = self.vehicle, self.vehicle.r_dyn, self.vehicle.engine
        self.standing = v_next <= 0.0 and v < 0.3
        if self.standing:
            self.integral = 0.0
            return 0.0, 300.0  # standing: no drive, brakes held (also against a grade)
        e = v_now - v
        self.integral = min(max(self.integral + e * h, -2.0), 2.0)
        a = (v_next - v_now) / h + self.k_p * e + self.k_i * self.integral
        T_wheel = self.J_wheel / r * a + r * veh.road_force(v_now, slope)
        T_s = T_wheel / self.ratio
        floor = engine.drag(w_p) if v > engine.v_clutch else 0.0
        if T_s >= floor:
            return min(T_s, engine.T_max), 0.0
        return floor, floor * self.ratio - T_wheel
