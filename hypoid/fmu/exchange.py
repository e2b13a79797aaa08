"""An FMU in Model Exchange, reached like a co-simulation one (hypoid.fmu.instance.Instance: values
by name, the FMU's log in every error): `ExchangeInstance(fmu_path)` instantiates it for Model
Exchange; after `start()` it is in continuous-time mode, the initial event iteration done. The
host's side of the interface: the time, the continuous states, their derivatives and nominals,
the event indicators (numpy arrays), `completed_step()` and `event()` (event mode, the iteration
of fmi2NewDiscreteStates, back to continuous-time mode).

`integrate()` is a small host integrator over [t, t_end]: fmpy's CVODE (BDF, the tolerances as
fmpy's simulate_fmu sets them: rtol and rtol x nominals) with root finding on the event
indicators, an event iteration at every root and whenever a completed step asks for one."""

import ctypes

import numpy as np
from fmpy.fmi2 import FMU2Model

from hypoid.fmu.instance import Instance


def _pointer(array):
    return array.ctypes.data_as(ctypes.POINTER(ctypes.c_double))


class ExchangeInstance(Instance):
    """An instantiated Model Exchange FMU; nx continuous states, nz event indicators."""

    fmpy_class = FMU2Model

    def _interface(self):
        return self.md.modelExchange

    @property
    def nx(self):
        return self.md.numberOfContinuousStates

    @property
    def nz(self):
        return self.md.numberOfEventIndicators

    def exit_initialization(self):
        """fmi2ExitInitializationMode, then the initial event iteration and continuous-time
        mode."""
        super().exit_initialization()
        self._iterate()
        self._call(self.slave.enterContinuousTimeMode)

    def _iterate(self):
        """fmi2NewDiscreteStates until no new discrete states are needed. True when the
        continuous states changed."""
        changed = False
        while True:
            needed, terminate, _, values_changed, _, _ = self._call(self.slave.newDiscreteStates)
            changed |= bool(values_changed)
            if not needed or terminate:
                return changed

    # ------------------------------------------------------------------ the host's side
    def set_time(self, t):
        self._call(self.slave.setTime, t)
        self.t = t

    def state_index(self, name):
        """The place of the continuous state `name` in the state vector."""
        return [d.variable.derivative.name for d in self.md.derivatives].index(name)

    def states(self):
        x = np.zeros(self.nx)
        self._call(self.slave.getContinuousStates, _pointer(x), self.nx)
        return x

    def set_states(self, x):
        x = np.ascontiguousarray(x, dtype=float)
        self._call(self.slave.setContinuousStates, _pointer(x), self.nx)

    def derivatives(self):
        dx = np.zeros(self.nx)
        self._call(self.slave.getDerivatives, _pointer(dx), self.nx)
        return dx

    def nominals(self):
        n = np.zeros(self.nx)
        self._call(self.slave.getNominalsOfContinuousStates, _pointer(n), self.nx)
        return n

    def indicators(self):
        z = np.zeros(self.nz)
        self._call(self.slave.getEventIndicators, _pointer(z), self.nz)
        return z

    def real_setter(self, refs):
        """set_reals for these value references as one prepared call, set(values): for a
        master's connections at every right-hand side (the bare FMI call; a failure is made
        again through set_reals, which raises FmuError)."""
        n, fn, c = len(refs), self.slave._functions["fmi2SetReal"], self.slave.component
        vr, buf = (ctypes.c_uint * n)(*refs), (ctypes.c_double * n)()

        def put(values):
            buf[:] = values
            if fn(c, vr, n, buf) > 1:
                self.set_reals(refs, values)

        return put

    def real_getter(self, refs):
        """get_reals for these value references as one prepared call, get() -> list."""
        n, fn, c = len(refs), self.slave._functions["fmi2GetReal"], self.slave.component
        vr, buf = (ctypes.c_uint * n)(*refs), (ctypes.c_double * n)()

        def get():
            if fn(c, vr, n, buf) > 1:
                return self.get_reals(refs)
            return buf[:]

        return get

    def completed_step(self):
        """fmi2CompletedIntegratorStep: True when the FMU asks for an event."""
        event, _ = self._call(self.slave.completedIntegratorStep)
        return bool(event)

    def event(self):
        """An event at the current time and state: event mode, the discrete states' iteration,
        continuous-time mode. True when the continuous states changed."""
        self._call(self.slave.enterEventMode)
        changed = self._iterate()
        self._call(self.slave.enterContinuousTimeMode)
        return changed

    # ------------------------------------------------------------------ a host integrator
    def integrate(self, t_end, output_interval, names, rtol=1e-6, max_step=None):
        """From the current time to t_end with CVODE (Exchange below); the named outputs at every
        output_interval as a structured array like Instance.series, and the number of events."""
        return Exchange([self], rtol=rtol, max_step=max_step).run(
            t_end, output_interval, names)


class _Raw:
    """An instance's FMI functions of the right-hand side as the bare ctypes calls (fmpy's
    wrappers and Instance._call cost more than the FMU's own evaluation there); a status above
    fmi2Warning is for the caller to raise through the checked call."""

    def __init__(self, inst):
        f = inst.slave._functions
        self.inst, self.c, self.nx, self.nz = inst, inst.slave.component, inst.nx, inst.nz
        self.set_time = f["fmi2SetTime"]
        self.set_states = f["fmi2SetContinuousStates"]
        self.derivatives = f["fmi2GetDerivatives"]
        self.indicators = f["fmi2GetEventIndicators"]


class _Places:
    """For a vector of CVODE (a pointer and its length), a numpy view of it and a pointer to
    each instance's part (cuts: the parts' bounds), kept per vector: CVODE passes the same few."""

    def __init__(self, cuts):
        self.cuts, self.known = [int(c) for c in cuts], {}

    def __call__(self, p, k):
        address = ctypes.addressof(p.contents)
        got = self.known.get((address, k))
        if got is None:
            size = ctypes.sizeof(ctypes.c_double)
            ptrs = [ctypes.cast(address + size * a, ctypes.POINTER(ctypes.c_double))
                    for a in self.cuts[:-1]]
            got = self.known[(address, k)] = (np.ctypeslib.as_array(p, (k,)), ptrs)
        return got


class Exchange:
    """Instances in Model Exchange integrated as one ODE by CVODE (fmpy's SUNDIALS: BDF, dense
    Newton), the states of each instance one after the other. `couple(t, states)`, when given,
    sets the inputs from the outputs (or from the states: a list of each instance's state
    vector) before every evaluation (a master's connections)."""

    def __init__(self, instances, rtol=1e-6, max_step=None, couple=None):
        self.instances, self.rtol, self.couple = list(instances), rtol, couple
        self.max_step = max_step
        self.cuts = np.cumsum([0] + [inst.nx for inst in self.instances])
        self.zcuts = np.cumsum([0] + [inst.nz for inst in self.instances])
        self.events = 0

    def _load(self, t, x):
        parts = [x[a:b] for a, b in zip(self.cuts[:-1], self.cuts[1:])]
        for inst, part in zip(self.instances, parts):
            inst.set_time(t)
            inst.set_states(part)
        if self.couple:
            self.couple(t, parts)

    def _solver(self, t):
        from fmpy.sundials import CVodeSolver

        n, nz = int(self.cuts[-1]), int(self.zcuts[-1])
        raw = [_Raw(inst) for inst in self.instances]
        x_at, z_at = _Places(self.cuts), _Places(self.zcuts)

        def view(p, k):
            return np.ctypeslib.as_array(p, (k,))

        def get_x(p, k):
            view(p, k)[:] = np.concatenate([inst.states() for inst in self.instances])

        def set_x(p, k):
            # _load's calls, straight into the FMUs from CVODE's vector (the right-hand side's
            # hot loop); a failed call is made again the checked way, which raises FmuError
            whole, ptrs = x_at(p, k)
            x = whole.copy()
            parts = [x[a:b] for a, b in zip(self.cuts[:-1], self.cuts[1:])]
            for r, ptr, part in zip(raw, ptrs, parts):
                if r.set_time(r.c, self._t) > 1:
                    r.inst.set_time(self._t)
                r.inst.t = self._t
                if r.set_states(r.c, ptr, r.nx) > 1:
                    r.inst.set_states(part)
            if self.couple:
                self.couple(self._t, parts)

        def get_dx(p, k):
            for r, ptr in zip(raw, x_at(p, k)[1]):
                if r.derivatives(r.c, ptr, r.nx) > 1:
                    r.inst.derivatives()

        def get_z(p, k):
            for r, ptr in zip(raw, z_at(p, k)[1]):
                if r.nz and r.indicators(r.c, ptr, r.nz) > 1:
                    r.inst.indicators()

        def get_nominals(p, k):
            view(p, k)[:] = np.concatenate([inst.nominals() for inst in self.instances])

        def set_time(time):
            self._t = time

        class NoInput:
            def apply(self, time, **kw):
                pass

        self._t = t
        return CVodeSolver(nx=n, nz=nz, get_x=get_x, set_x=set_x, get_dx=get_dx, get_z=get_z,
                           get_nominals=get_nominals, set_time=set_time, input=NoInput(),
                           startTime=t, maxStep=self.max_step or float("inf"),
                           relativeTolerance=self.rtol, maxNumSteps=100000)

    def state(self):
        return np.concatenate([inst.states() for inst in self.instances])

    def run(self, t_end, output_interval, names, on_output=None):
        """Outputs `names` (of the first instance, or per instance a list) at every
        output_interval up to t_end; on_output(t) is called before each sample: it may set
        inputs that jump there, and then returns True (an event iteration and a restart)."""
        first = self.instances[0]
        lists = names if names and isinstance(names[0], (list, tuple)) else [names]
        t = first.t
        self._load(t, self.state())
        solver = self._solver(t)
        n_out = int(round((t_end - t) / output_interval))
        rows, times = [self._sample(lists)], [t]
        for k in range(1, n_out + 1):
            t_next = times[0] + k * output_interval
            while t < t_next - 1e-12 * max(1.0, abs(t_next)):
                root, _, t = solver.step(t, t_next)
                self._load(t, self.state())
                step_event = any([inst.completed_step() for inst in self.instances])
                if root or step_event:
                    self.events += 1
                    for inst in self.instances:
                        inst.event()
                    solver.reset(t)
            if on_output and on_output(t):  # inputs changed: an event, a restart
                self.events += 1
                for inst in self.instances:
                    inst.event()
                solver.reset(t)
            rows.append(self._sample(lists))
            times.append(t)
        return _table(times, rows, lists)

    def _sample(self, lists):
        return [inst.reals(n) if n else [] for inst, n in zip(self.instances, lists)]


def _table(times, rows, lists):
    """One structured array per instance with a 'time' field."""
    out = []
    for j, names in enumerate(lists):
        a = np.zeros(len(times), dtype=[("time", float)] + [(n, float) for n in names])
        a["time"] = times
        for i, n in enumerate(names):
            a[n] = [row[j][i] for row in rows]
        out.append(a)
    return out[0] if len(out) == 1 else out
