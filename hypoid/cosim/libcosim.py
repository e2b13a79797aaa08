"""libcosim (the Open Simulation Platform's co-simulation library, through libcosimpy, a test
extra) as a master: a fixed-step (Jacobi) execution of FMUs addressed by instance and variable
names, start values set by name, connections, inputs overridden before a step, outputs read
after it. libcosim 0.11 ignores Enumeration variables: give it the build's integer-coded gear
FMU (`<name>_intenum.fmu`, the enumerations as Integers with the same codes), see
docs/integration.md."""

import pathlib

from hypoid.errors import UsageError


def why_unavailable():
    """None when libcosimpy loads here, else why not (one line)."""
    try:
        from libcosimpy._internal import libcosimc

        libcosimc()
    except Exception as e:  # noqa: BLE001 - any failure means: not usable here
        return f"{type(e).__name__}: {e}"
    return None


def intenum_fmu(fmu):
    """The integer-coded variant that the build writes next to the FMU."""
    fmu = pathlib.Path(fmu)
    path = fmu.with_name(f"{fmu.stem}_intenum.fmu")
    if not path.exists():
        raise UsageError(f"{path} is missing: libcosim needs the integer-coded FMU the build "
                         "writes next to the FMU")
    return path


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

    def __init__(self, h):
        why = why_unavailable()
        if why:
            raise UsageError(f"libcosim is not usable here ({why}): pip install "
                             "libcosimpy==0.0.6 (Linux x86_64)")
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

    def close(self):
        """Frees the C side (observer and manipulator before the execution, slaves last)."""
        for attr in ("last", "override", "ex", "slaves"):
            self.__dict__.pop(attr, None)
