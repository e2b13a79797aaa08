"""libcosim (the Open Simulation Platform's co-simulation library, through libcosimpy, a test
extra) as a master: a fixed-step (Jacobi) execution of FMUs addressed by instance and variable
names, start values set by name, connections, inputs overridden before a step, outputs read
after it. libcosim 0.11 ignores Enumeration variables: give it the build's integer-coded gear
FMU (`<name>_intenum.fmu`, the enumerations as Integers with the same codes), see
docs/integration.md."""

from hypoid.cosim import host
from hypoid.errors import UsageError


def _load():
    from libcosimpy._internal import libcosimc

    libcosimc()


def why_unavailable():
    """None when libcosimpy loads here, else why not (one line)."""
    return host.why_not(_load)


def step_ns(h):
    """libcosim counts time in whole nanoseconds."""
    ns = int(round(h * 1e9))
    if ns <= 0 or abs(ns - h * 1e9) > 1e-6:
        raise UsageError(f"step {h} s is not a whole number of nanoseconds")
    return ns


class Execution:
    """One libcosim execution with a fixed step h (s), an override manipulator and a last-value
    observer. libcosim initialises the FMUs inside the first step (its C API has no separate
    call), so outputs are readable after a step only."""

    host, outputs_at_start, reads_after_transfer = "libcosim", False, False

    def __init__(self, h):
        host.require("libcosim", why_unavailable, "pip install libcosimpy==0.0.6 (Linux x86_64)")
        from libcosimpy.CosimExecution import CosimExecution
        from libcosimpy.CosimLogging import CosimLogLevel, log_output_level
        from libcosimpy.CosimManipulator import CosimManipulator
        from libcosimpy.CosimObserver import CosimObserver

        log_output_level(CosimLogLevel.ERROR)
        self.ex = CosimExecution.from_step_size(step_ns(h))
        self.override = CosimManipulator.create_override()
        self.ex.add_manipulator(self.override)
        self.last = CosimObserver.create_last_value()
        self.ex.add_observer(self.last)
        self.slaves, self.index, self.vars = {}, {}, {}

    def add(self, name, path):
        from libcosimpy.CosimSlave import CosimLocalSlave

        self.slaves[name] = CosimLocalSlave(fmu_path=str(path), instance_name=name)
        i = self.ex.add_local_slave(self.slaves[name])
        if i < 0:
            raise RuntimeError(f"libcosim could not load {path}")
        self.index[name] = i
        self.vars[name] = {v.name.decode(): (v.reference, v.type.value
                                             if hasattr(v.type, "value") else v.type)
                           for v in self.ex.slave_variables(i)}

    def ref(self, name, var):
        try:
            return self.vars[name][var][0]
        except KeyError:
            raise UsageError(f"libcosim: {name} has no variable {var!r} it can set or read "
                             "(Enumerations need the integer-coded FMU)") from None

    def initial(self, name, values):
        """Start values {variable: value}; the value's kind follows libcosim's variable type
        (0 Real, 1 Integer, 2 String, 3 Boolean); enumerations as their integer codes."""
        setters = {0: (self.ex.real_initial_value, float), 1: (self.ex.integer_initial_value, int),
                   2: (self.ex.string_initial_value, str), 3: (self.ex.boolean_initial_value, bool)}
        for var, value in values.items():
            setter, kind = setters[self.vars[name][var][1] if var in self.vars[name] else 0]
            if not setter(self.index[name], self.ref(name, var), kind(value)):
                raise UsageError(f"libcosim refused the start value {name}.{var} = {value!r}")

    def connect(self, src, out, dst, inp):
        if self.ex.connect_real_variables(self.index[src], self.ref(src, out), self.index[dst],
                                          self.ref(dst, inp)) != 0:
            raise RuntimeError(f"libcosim: connecting {src}.{out} -> {dst}.{inp} failed")

    def set_reals(self, name, names, values):
        """Real inputs for the next step (and after it, until overridden again)."""
        self.override.slave_real_values(self.index[name], [self.ref(name, n) for n in names],
                                        [float(v) for v in values])

    def step(self):
        if not self.ex.step():
            raise RuntimeError(f"libcosim step failed: {self.ex.status()}")

    def reals(self, name, refs):
        """The last values of the Real variables with these references."""
        return self.last.last_real_values(self.index[name], refs)

    def record(self, variables, n):
        """A time-series observer of {instance: [Real variable]} for n samples (steps 0 .. n-1;
        libcosim's default buffer keeps 10 000)."""
        from libcosimpy.CosimEnums import CosimVariableType
        from libcosimpy.CosimObserver import CosimObserver

        self.series_observer = CosimObserver.create_time_series(buffer_size=n)
        self.ex.add_observer(self.series_observer)
        for name, names in variables.items():
            for var in names:
                self.series_observer.start_time_series(self.index[name], self.ref(name, var),
                                                       CosimVariableType.REAL)

    def series(self, name, var, n):
        """(values, times in s) of a recorded variable over steps 0 .. n-1. libcosimpy's
        time_series_real_samples drops a sample when step 0 is among them: this calls the C
        function directly."""
        import ctypes

        import numpy as np
        from libcosimpy._internal import libcosimc, wrap_function

        get = wrap_function(lib=libcosimc(), funcname="cosim_observer_slave_get_real_samples",
                            argtypes=[ctypes.c_void_p, ctypes.c_int, ctypes.c_uint32,
                                      ctypes.c_int64, ctypes.c_size_t,
                                      ctypes.POINTER(ctypes.c_double),
                                      ctypes.POINTER(ctypes.c_int64),
                                      ctypes.POINTER(ctypes.c_int64)],
                            restype=ctypes.c_int64)
        values, steps = np.empty(n), np.empty(n, dtype=np.int64)
        times = np.empty(n, dtype=np.int64)
        got = get(ctypes.cast(self.series_observer.ptr(), ctypes.c_void_p), self.index[name],
                  self.ref(name, var), 0, n, values.ctypes.data_as(ctypes.POINTER(ctypes.c_double)),
                  steps.ctypes.data_as(ctypes.POINTER(ctypes.c_int64)),
                  times.ctypes.data_as(ctypes.POINTER(ctypes.c_int64)))
        if got != n or not np.array_equal(steps, np.arange(n)):
            raise RuntimeError(f"libcosim observer: {got} samples of {name}.{var}, not {n}")
        return values, times * 1e-9

    def close(self):
        """Frees the C side (observers and manipulator before the execution, slaves last)."""
        for attr in ("series_observer", "last", "override", "ex", "slaves"):
            self.__dict__.pop(attr, None)


class GearVehicle(host.GearVehicle):
    """hypoid.cosim.host.GearVehicle in libcosim. `record` = n keeps every output over steps
    0 .. n-1 (series()); libcosim initialises inside the first step, so the outputs of step()
    are those after it."""

    def __init__(self, gear_fmu, vehicle_fmu, gear_start, vehicle_start, h, gear_out,
                 vehicle_out, gear_inputs=("T_s",), vehicle_inputs=(), record=0):
        super().__init__(Execution, gear_fmu, vehicle_fmu, gear_start, vehicle_start, h,
                         gear_out, vehicle_out, gear_inputs, vehicle_inputs)
        self.n_record = record
        if record:
            self.ex.record({"gear": gear_out, "vehicle": vehicle_out}, record)

    def series(self):
        """(times in s, {gear output: values}, {vehicle output: values}) of the recorded steps."""
        gear = {x: self.ex.series("gear", x, self.n_record)[0] for x in self.gear_out}
        vehicle = {x: self.ex.series("vehicle", x, self.n_record)[0] for x in self.vehicle_out}
        return self.ex.series("gear", self.gear_out[0], self.n_record)[1], gear, vehicle
