"""Ecos (Easy co-simulation, from NTNU's Open Simulation Platform family, through ecospy, a test
extra) as a master: its fixed-step algorithm (Jacobi: every FMU steps over [t, t + h] with the
inputs of t, in parallel threads), FMUs and variables addressed as "instance::variable", start
values as a parameter set applied in initialisation mode, connections, inputs set before a step,
outputs read after it. The calls are hypoid.cosim.libcosim.Execution's, so one loop drives either
host (tests/cosim/coupling_master.py, run_host).

What Ecos 0.7 leaves to its caller, and this driver does:
- it ignores Enumeration variables, as libcosim does: give it the integer-coded gear FMU the
  build writes (hypoid.cosim.host.intenum_fmu); a start value or a read of a variable it
  cannot reach is refused here by name (Ecos logs a warning and goes on);
- it ignores the status of fmi2SetReal and fmi2DoStep: an input that an FMU refuses (out of its
  range) leaves the FMU with its old value, and the run goes on. Each connection here records
  what it passes (an Ecos modifier that returns its argument), set_reals what it sets, and
  step() reads every such input back and raises hypoid.fmu.instance.FmuError naming the input
  when an FMU did not take the value it was sent.

Ecos reads outputs after the connections' transfer: an output with direct feedthrough (the
vehicle's T_hs in its half-shaft coupling 1) reads as its value with the new inputs, not the one
passed on (the half-shaft coupling's T_wheel and w_wheel have none).

ecospy loads its bundled libecosc.so when imported; on Linux that needs Debian's libtbb12
(scripts/setup.sh installs it)."""

import pathlib

from hypoid.cosim import host
from hypoid.errors import UsageError
from hypoid.fmu.instance import FmuError

_CASTS = {"Real": float, "Integer": int, "Boolean": bool, "String": str}


def _load():
    from ecospy import EcosLib

    EcosLib.version()


def why_unavailable():
    """None when ecospy loads here, else why not (one line)."""
    return host.why_not(_load)


class Execution:
    """One Ecos simulation with a fixed step h (s). Models, start values and connections first;
    the simulation is made and initialised (start values, then the connections' values passed
    around once per model, as Ecos does) at the first set_reals, step or reals: the outputs
    of the start are readable before the first step."""

    host, outputs_at_start, reads_after_transfer = "Ecos", True, True

    def __init__(self, h):
        host.require("Ecos", why_unavailable, "pip install ecospy==0.7.2; on Linux it needs "
                     "Debian's libtbb12 (scripts/setup.sh)")
        from ecospy import EcosLib, EcosSimulationStructure

        EcosLib.set_log_level("err")
        self.h = float(h)
        if not self.h > 0.0:
            raise UsageError(f"Ecos step {h} s: must be positive")
        self.structure = EcosSimulationStructure()
        self.sim = None
        self.types, self.start, self.sent = {}, {}, {}

    def add(self, name, path):
        from fmpy import read_model_description

        self.types[name] = {v.name: v.type for v in read_model_description(str(path))
                            .modelVariables}
        self.structure.add_model(name, pathlib.Path(path))

    def ref(self, name, var):
        """The variable's Ecos identifier, "name::var"."""
        kind = self.types[name].get(var)
        if kind not in _CASTS:
            raise UsageError(f"Ecos: {name} has no variable {var!r} it can set or read"
                             + (" (Enumerations need the integer-coded FMU)"
                                if kind == "Enumeration" else ""))
        return f"{name}::{var}"

    def initial(self, name, values):
        """Start values {variable: value}, of the variable's type (enumerations as codes)."""
        for var, value in values.items():
            self.start[self.ref(name, var)] = _CASTS[self.types[name][var]](value)

    def connect(self, src, out, dst, inp):
        source, sink = self.ref(src, out), self.ref(dst, inp)

        def passed(value, sink=sink):
            self.sent[sink] = value
            return value

        self.structure.make_real_connection(source, sink, passed)

    def _simulation(self):
        if self.sim is None:
            from ecospy import EcosLib, EcosSimulation

            if self.start:
                self.structure.add_parameter_set("start", self.start)
            self.sim = EcosSimulation(step_size=self.h, structure=self.structure)
            if not self.sim.init(0.0, "start" if self.start else None):
                raise RuntimeError(f"Ecos could not initialise: {EcosLib.get_last_error()}")
            self._check_inputs("initialisation")
        return self.sim

    def set_reals(self, name, names, values):
        """Real inputs for the next step (and after it, until set again); checked after it."""
        sim = self._simulation()
        for var, value in zip(names, values):
            ref = self.ref(name, var)
            self.sent[ref] = float(value)
            sim.set_real(ref, self.sent[ref])

    def step(self):
        sim = self._simulation()
        t = sim.get_time()
        sim.step()
        self._check_inputs(f"the step from t = {t:.6g} s")

    def _check_inputs(self, when):
        """Every input passed by a connection or set: the value sent, else FmuError."""
        for sink, sent in self.sent.items():
            held = self.sim.get_real(sink)
            if held != sent:
                raise FmuError(f"Ecos: after {when} {sink} = {held!r}, not the {sent!r} it was "
                               "sent: the FMU refused it (Ecos goes on regardless)",
                               "fmi2SetReal")

    def reals(self, name, refs):
        """The values of the Real variables with these identifiers (ref()) after the last step."""
        sim = self._simulation()
        return [sim.get_real(r) for r in refs]

    def close(self):
        """Terminates the simulation and frees it, then the structure (which keeps the
        connections' modifiers alive)."""
        if self.sim is not None:
            self.sim.terminate()
            self.sim.free()
            self.sim = None
        self.structure.free()
