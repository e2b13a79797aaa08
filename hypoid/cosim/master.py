"""The gear FMU and a vehicle FMU in one fixed-step co-simulation master (fmpy, through
hypoid.fmu.instance.Instance): the master of the drive-cycle runner and of the co-simulation
tests (docs/cosimulation.md, docs/axle.md).

The coupling is the rear axle's: the vehicle's half-shaft torque T_hs goes to the gear's wheel-end
load T_w, the gear's wheel-flange speed w_w to the vehicle's w_w. Other inputs (the propeller-shaft
torque T_s, the brakes, the air speed) come from the caller at each step. Per step, Jacobi (as
libcosim's fixed_step_algorithm): both FMUs step over [t, t + h] with the inputs of t; Gauss-Seidel:
the gear steps first and the vehicle steps with the gear's new w_w.

Initialisation: both FMUs set up and given their start values; with `init_passes` > 0 the
coupled inputs go around the loop that many times in initialisation mode (libcosim's way: one
pass per FMU), else each FMU initialises on its start values alone.

With `ramp`, the gear's inputs reach it as ramps (fmi2SetRealInputDerivatives): over [t, t + h]
each goes linearly from where the last step's ramp ended to its value of t, a first-order hold
one step late, so that they never jump and the gear FMU's integrator never restarts for them
(docs/model.md, "Steps without restarts"; held values jump at every step, and each jump restarts
it). The ramp's end is value + slope h, the sum the FMU forms, to the bit."""

import math

from hypoid.fmu.instance import Instance

ALGORITHMS = ("jacobi", "gauss-seidel")


def _start(inst, values, name):
    """An input's value at the start: given, or the variable's start value."""
    return float(values.get(name, inst.table.variable(name).start))


def ramp_slope(a, b, h, lo=-math.inf, hi=math.inf):
    """The slope from a to b over h whose end a + slope h (in floating point, as the FMU forms it)
    stays within [lo, hi]: (b - a) / h, moved by an ulp where rounding would leave a bound. A target
    b outside [lo, hi] keeps its slope, so that the FMU refuses it by name."""
    slope = (b - a) / h
    if not lo <= b <= hi:
        return slope
    while a + slope * h < lo:
        slope = math.nextafter(slope, math.inf)
    while a + slope * h > hi:
        slope = math.nextafter(slope, -math.inf)
    return slope


class Pair:
    """Two FMU instances, `gear` and `vehicle`, closed together (also as a context manager)."""

    def close(self):
        self.gear.close()
        self.vehicle.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


class GearVehicle(Pair):
    """Two instances, `gear` and `vehicle`; step() returns the outputs (gear_out, vehicle_out) as
    lists of floats in the order given. A wheel speed below `w_rest` (rad/s) reaches the vehicle as
    0, so that a standing car's brakes and rolling resistance hold it with a constant torque
    instead of one the gear integrator's noise makes (docs/axle.md)."""

    def __init__(self, gear_fmu, vehicle_fmu, gear_start, vehicle_start, gear_out, vehicle_out,
                 gear_inputs=("T_s",), vehicle_inputs=(), algorithm="jacobi", init_passes=0,
                 w_rest=0.0, ramp=False):
        if algorithm not in ALGORITHMS:
            raise ValueError(f"algorithm {algorithm!r}: one of {', '.join(ALGORITHMS)}")
        self.algorithm, self.w_rest, self.ramp = algorithm, w_rest, ramp
        self.gear = Instance(gear_fmu, name="gear")
        self.vehicle = Instance(vehicle_fmu, name="vehicle")
        self.g_out, self.v_out = self.gear.refs(gear_out), self.vehicle.refs(vehicle_out)
        self.gear_inputs, self.vehicle_inputs = list(gear_inputs), list(vehicle_inputs)
        g_in_names = [*gear_inputs, "T_w"]
        self.g_in = self.gear.refs(g_in_names)
        self.v_in = self.vehicle.refs(["w_w", *vehicle_inputs])
        self.i_ww, self.i_ths = list(gear_out).index("w_w"), list(vehicle_out).index("T_hs")
        self._initialize(gear_start, vehicle_start, init_passes)
        # the hot loop: straight through ctypes (hypoid.fmu.instance.FastIo)
        self._g_io = self.gear.fast_io(gear_out, inputs=g_in_names)
        self._v_io = self.vehicle.fast_io(vehicle_out, inputs=["w_w", *vehicle_inputs])
        bounds = [self.gear.table.variable(n) for n in g_in_names]
        self._g_bounds = [(-math.inf if v.min is None else float(v.min),
                           math.inf if v.max is None else float(v.max)) for v in bounds]
        self._g_end = list(self.gear.get_reals(self.g_in))  # where the inputs stand

    def _initialize(self, gear_start, vehicle_start, passes):
        for inst, values in ((self.gear, gear_start), (self.vehicle, vehicle_start)):
            inst.setup()
            inst.set_many(values)
        for inst in (self.gear, self.vehicle):
            inst.enter_initialization()
        if passes:
            g_ext = [_start(self.gear, gear_start, n) for n in self.gear_inputs]
            v_ext = [_start(self.vehicle, vehicle_start, n) for n in self.vehicle_inputs]
            T_w, w_w = _start(self.gear, gear_start, "T_w"), _start(self.vehicle, vehicle_start,
                                                                    "w_w")
            for _ in range(passes):
                self._set_inputs(g_ext, T_w, v_ext, w_w)
                g, v = self._read()
                T_w, w_w = v[self.i_ths], g[self.i_ww]
            self._set_inputs(g_ext, T_w, v_ext, w_w)
        for inst in (self.gear, self.vehicle):
            inst.exit_initialization()
        self.outputs = self._read()

    def _set_inputs(self, gear_inputs, T_w, vehicle_inputs, w_w):
        self.gear.set_reals(self.g_in, [*gear_inputs, T_w])
        self.vehicle.set_reals(self.v_in, [self._to_vehicle(w_w), *vehicle_inputs])

    def _to_vehicle(self, w_w):
        return w_w if abs(w_w) >= self.w_rest else 0.0

    def _read(self):
        return self.gear.get_reals(self.g_out), self.vehicle.get_reals(self.v_out)

    def _gear_inputs(self, values, h):
        """The gear's inputs for a step of h: held, or as ramps from where they stand to values."""
        if not self.ramp:
            self._g_io.set_inputs(values)
            return
        start = self._g_end
        slopes = [ramp_slope(a, b, h, lo, hi)
                  for a, b, (lo, hi) in zip(start, values, self._g_bounds)]
        self._g_io.set_inputs(start)
        self._g_io.set_derivatives(slopes)
        self._g_end = [a + s * h for a, s in zip(start, slopes)]

    def step(self, t, h, gear_inputs=(), vehicle_inputs=(), T_w_add=0.0):
        """One communication step over [t, t + h] with the callers' inputs (in the order of
        gear_inputs and vehicle_inputs); the outputs at t + h. T_w_add (N m) is added to the
        vehicle's T_hs on its way to the gear's T_w: a load the caller models (a route's grade)."""
        g, v = self.outputs
        self._gear_inputs([*gear_inputs, v[self.i_ths] + T_w_add], h)
        if self.algorithm == "jacobi":
            self._v_io.set_inputs([self._to_vehicle(g[self.i_ww]), *vehicle_inputs])
            self._g_io.step(t, h)
            self._v_io.step(t, h)
            self.outputs = self._g_io.reals(), self._v_io.reals()
            return self.outputs
        self._g_io.step(t, h)
        g = self._g_io.reals()
        self._v_io.set_inputs([self._to_vehicle(g[self.i_ww]), *vehicle_inputs])
        self._v_io.step(t, h)
        self.outputs = g, self._v_io.reals()
        return self.outputs

