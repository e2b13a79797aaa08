"""The one way the tools, benchmarks and tests reach an FMU: `Instance(fmu_path)` unzips the FMU
once per content (a cache in the temporary folder), instantiates a co-simulation slave, sets
values by name (enumerations by item name or code, `speed_rpm` for w_set and w_p0; see
hypoid.fmu.values), steps, reads, restarts with fmi2Reset and frees. Every failed FMI call raises
`FmuError` with the FMU's last log messages."""

import ctypes
import functools
import hashlib
import os
import pathlib
import shutil
import tempfile
import zipfile

from fmpy import calloc, free, read_model_description
from fmpy.fmi1 import FMICallException
from fmpy.fmi2 import (FMU2Slave, fmi2CallbackAllocateMemoryTYPE, fmi2CallbackFreeMemoryTYPE,
                       fmi2CallbackFunctions, fmi2CallbackLoggerTYPE)

from hypoid.fmu import sample_loop
from hypoid.fmu.values import RPM, SPEED_KEY, TABLE, BadValue, Table  # noqa: F401 (re-exported)

ERROR = 3  # fmi2Status of errors (fmi2Error) and worse
RAW = {"Real": float, "Integer": int, "Enumeration": int, "Boolean": bool, "String": str}


class FmuError(RuntimeError):
    """An FMI call failed; the message carries the FMU's last log messages, `function` and
    `status` the failed call and its fmi2Status."""

    def __init__(self, message, function="", status=ERROR):
        super().__init__(message)
        self.function, self.status = function, status


# ---------------------------------------------------------------------------- the unzipped FMU
def unzip_bytes(sha, data):
    """The FMU given as bytes, unpacked once per machine in <tmp>/hypoid-fmu/<sha> (atomic
    rename, so parallel workers can race)."""
    root = pathlib.Path(tempfile.gettempdir()) / "hypoid-fmu"
    target = root / sha[:24]
    if (target / "modelDescription.xml").exists():
        return target
    root.mkdir(parents=True, exist_ok=True)
    tmp = pathlib.Path(tempfile.mkdtemp(dir=root, prefix=".unzip-"))
    try:
        fmu = tmp / "model.fmu"
        fmu.write_bytes(data)
        with zipfile.ZipFile(fmu) as z:
            z.extractall(tmp / "x")
        try:
            os.rename(tmp / "x", target)
        except OSError:  # another process won the race
            pass
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return target


def unzipped(fmu_path):
    """The unpacked folder of an FMU file (or the folder itself if it is one already)."""
    p = pathlib.Path(fmu_path)
    if p.is_dir():
        return p
    if not p.is_file():
        raise FileNotFoundError(f"{p}: no such FMU (build it with scripts/setup.sh)")
    data = p.read_bytes()
    return unzip_bytes(hashlib.sha256(data).hexdigest(), data)


@functools.lru_cache(maxsize=16)
def _description(directory):
    md = read_model_description(str(pathlib.Path(directory) / "modelDescription.xml"))
    return md, Table.from_model_description(md)


# ---------------------------------------------------------------------------- one instance
class Instance:
    """An instantiated co-simulation slave. `messages` holds (status, category, text) of the
    FMU's log (the last `keep_messages`); `logging` switches on the FMU's debug logging.
    hypoid.fmu.exchange.ExchangeInstance is the same for Model Exchange."""

    fmpy_class = FMU2Slave  # the fmpy class of the interface

    def _interface(self):
        """The model description's element of the interface (its modelIdentifier)."""
        return self.md.coSimulation

    def __init__(self, fmu_path, unzip_dir=None, name="hypoid", logging=False,
                 keep_messages=1000, model_identifier=None, guid=None):
        self.fmu_path = str(fmu_path)
        self.unzip_dir = str(unzip_dir or unzipped(fmu_path))
        self.md, self.table = _description(self.unzip_dir)
        self.vars = self.table.variables
        self.messages = []
        self._n_logged = 0  # messages logged so far (the list keeps only the last ones)
        self.keep_messages = keep_messages
        self._callbacks = self._make_callbacks()
        self.slave = self.fmpy_class(guid=guid or self.md.guid, unzipDirectory=self.unzip_dir,
                                     modelIdentifier=model_identifier
                                     or self._interface().modelIdentifier,
                                     instanceName=name)
        self._call(self.slave.instantiate, callbacks=self._callbacks, loggingOn=logging)
        self.t = 0.0
        self.used = False
        self.freed = False

    def _make_callbacks(self):
        cb = fmi2CallbackFunctions()
        cb.logger = fmi2CallbackLoggerTYPE(self._log)
        cb.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
        cb.freeMemory = fmi2CallbackFreeMemoryTYPE(free)
        return cb

    def _log(self, component, instance, status, category, message):
        self._n_logged += 1
        self.messages.append((status, category.decode(errors="replace"),
                              message.decode(errors="replace").replace("%%", "%")))
        if len(self.messages) > self.keep_messages:
            del self.messages[:-self.keep_messages]

    def errors(self):
        return [m for m in self.messages if m[0] >= ERROR]

    def _call(self, fn, *args, **kwargs):
        """An FMI call; a failure raises FmuError with the messages the FMU logged during it (or
        fmpy's text when it logged none)."""
        before = self._n_logged
        try:
            return fn(*args, **kwargs)
        except FMICallException as e:
            raise self._failure(before, e.function, e.status, str(e)) from None

    def _failure(self, before, function, status, fallback):
        """FmuError for a failed call, with the messages logged since `before` of _n_logged."""
        new = self.messages[len(self.messages) - min(self._n_logged - before,
                                                     len(self.messages)):]
        said = [m[2] for m in new if m[0] >= ERROR] or [m[2] for m in new]
        return FmuError(" | ".join(said[-3:]) or fallback, function, status)

    # ------------------------------------------------------------------ values
    def ref(self, name):
        return self.table.variable(name).vr

    def enum_value(self, name, value):
        """An enumeration's code from its item name ('ehl_thermal') or code (4)."""
        return self.table.code(self.table.variable(name), value)

    def set_raw(self, var, value):
        """One value straight to the setter of the variable's type (no conversion)."""
        ref = [var.vr]
        if var.type == "Real":
            self._call(self.slave.setReal, ref, [value])
        elif var.type in ("Integer", "Enumeration"):
            self._call(self.slave.setInteger, ref, [value])
        elif var.type == "String":
            self._call(self.slave.setString, ref, [value])
        else:
            self._call(self.slave.setBoolean, ref, [value])

    def set(self, name, value):
        self.set_many({name: value})

    def set_many(self, params):
        """Sets variables by name (and `speed_rpm`); values in any form hypoid.fmu.values takes."""
        for var, value in self.table.fmu_values(params):
            self.set_raw(var, value)

    def set_unchecked(self, values):
        """{name: value} straight to the setters, converted only to the variable's type and not
        checked against the table: the FMU's own checks are what a test of the FMU reaches."""
        for name, value in values.items():
            var = self.table.variable(name)
            self.set_raw(var, RAW[var.type](value))

    def get(self, name):
        var = self.table.variable(name)
        if var.type == "Real":
            return self._call(self.slave.getReal, [var.vr])[0]
        if var.type == "String":
            return self._call(self.slave.getString, [var.vr])[0].decode()
        if var.type == "Boolean":
            return self._call(self.slave.getBoolean, [var.vr])[0]
        return self._call(self.slave.getInteger, [var.vr])[0]

    def reals(self, names):
        return self._call(self.slave.getReal, [self.ref(n) for n in names])

    def refs(self, names):
        """The value references of the named variables, for get_reals and set_reals."""
        return [self.ref(n) for n in names]

    def get_reals(self, refs):
        """The Real variables with these value references (a master's hot loop)."""
        return self._call(self.slave.getReal, refs)

    def set_reals(self, refs, values):
        """Real inputs by value reference, unconverted (a master's hot loop)."""
        self._call(self.slave.setReal, refs, values)

    def ints(self, names):
        return self._call(self.slave.getInteger, [self.ref(n) for n in names])

    # ------------------------------------------------------------------ life cycle
    def start(self, params=None, start_time=0.0, stop_time=None, checked=True):
        """fmi2Reset (if used before), set the start values (unchecked: set_unchecked),
        initialise at start_time."""
        self.setup(start_time, stop_time)
        (self.set_many if checked else self.set_unchecked)(params or {})
        self.enter_initialization()
        self.exit_initialization()
        return self

    def setup(self, start_time=0.0, stop_time=None):
        """fmi2Reset (if used before) and fmi2SetupExperiment: start() up to the start values,
        for a master that initialises several FMUs together."""
        if self.used:  # what the last run logged goes with it
            self._call(self.slave.reset)
            self.messages.clear()
        self.used = True
        self._call(self.slave.setupExperiment, startTime=start_time, stopTime=stop_time)
        self.t = start_time

    def enter_initialization(self):
        self._call(self.slave.enterInitializationMode)

    def exit_initialization(self):
        self._call(self.slave.exitInitializationMode)

    def do_step(self, t, h):
        self._call(self.slave.doStep, currentCommunicationPoint=t, communicationStepSize=h)
        self.t = t + h

    def step(self, h):
        """One communication step of size h from the current time."""
        self.do_step(self.t, h)

    def record(self, t_end, h, names):
        """Steps of size h up to t_end; returns the named Real outputs after each step as an
        array (one row a step)."""
        import numpy as np

        refs = [self.ref(n) for n in names]
        rows = []
        for _ in range(int(round((t_end - self.t) / h))):
            self.do_step(self.t, h)
            rows.append(self._call(self.slave.getReal, refs))
        return np.array(rows)

    def series(self, stop_time, h, names):
        """The named outputs (Real, Integer, Boolean) now and after each step of size h up to
        stop_time, as a structured array with a 'time' field, like fmpy's simulate_fmu."""
        import numpy as np

        names = list(dict.fromkeys(names))  # each output once
        reals = [n for n in names if self.table.variable(n).type == "Real"]
        ints = [n for n in names if self.vars[n].type != "Real"]
        rr = [self.reals(reals)]
        ri = [self.ints(ints)]
        times = [self.t]
        for _ in range(int(round((stop_time - self.t) / h))):
            self.do_step(self.t, h)
            rr.append(self.reals(reals))
            ri.append(self.ints(ints))
            times.append(self.t)
        out = np.zeros(len(times), dtype=[("time", float)] + [(n, float) for n in reals]
                       + [(n, np.int64) for n in ints])
        out["time"] = times
        for j, n in enumerate(reals):
            out[n] = [row[j] for row in rr]
        for j, n in enumerate(ints):
            out[n] = [row[j] for row in ri]
        return out

    def fast_io(self, reals, ints=(), inputs=(), native=True):
        """A FastIo for the hot loops of the studies (fixed names, fewer Python layers; its
        run() in C where the build has the loop, unless native=False)."""
        return FastIo(self, reals, ints, inputs, native)

    def pinion_teeth(self):
        """N_p of the gear set in use (after initialisation)."""
        return int(self.get("N_p"))

    def terminate(self):
        self._call(self.slave.terminate)

    def close(self, terminate=True):
        """fmi2Terminate (when initialised and `terminate`) and fmi2FreeInstance; safe to call
        twice."""
        if self.freed:
            return
        self.freed = True
        if terminate and self.used:
            try:
                self.slave.terminate()
            except FMICallException:  # the instance may be in an error state
                pass
        self.slave.freeInstance()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()


# ---------------------------------------------------------------------------- the hot loop
_STEP = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p, ctypes.c_double, ctypes.c_double,
                         ctypes.c_int)
_ARRAY = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_size_t,
                          ctypes.c_void_p)  # fmi2Get/SetReal/Integer with raw buffer addresses
_DERIVATIVES = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p, ctypes.c_void_p, ctypes.c_size_t,
                                ctypes.c_void_p, ctypes.c_void_p)  # fmi2SetRealInputDerivatives
WARNING = 1  # fmi2Warning: the worst status that is not a failure


class FastIo:
    """fmi2DoStep, fmi2GetReal/GetInteger of fixed outputs into rows of numpy arrays and
    fmi2SetReal of fixed inputs, called straight through ctypes: the studies step an instance
    ~10^6 times, and fmpy's wrappers (argument arrays built per call, several Python layers)
    cost about as much as the FMU's own step there. Same calls, same values; a failed call
    raises FmuError like Instance's other calls."""

    def __init__(self, inst, reals, ints=(), inputs=(), native=True):
        self.inst = inst
        dll, self.component = inst.slave.dll, inst.slave.component
        self._fns = [ctypes.cast(getattr(dll, f), ctypes.c_void_p).value
                     for f in ("fmi2DoStep", "fmi2GetReal", "fmi2GetInteger", "fmi2SetReal")]
        self._do_step = _STEP(self._fns[0])
        self._get_real, self._get_int, self._set_real = (_ARRAY(a) for a in self._fns[1:])
        self._loop = sample_loop.library() if native else None
        self._set_derivatives = _DERIVATIVES(
            ctypes.cast(dll.fmi2SetRealInputDerivatives, ctypes.c_void_p).value)
        self.n_real, self.n_int = len(reals), len(ints)
        self._vr_real = self._refs(reals)
        self._vr_int = self._refs(ints)
        self._vr_in = self._refs(inputs)
        self._in = (ctypes.c_double * max(1, len(inputs)))()
        self._der = (ctypes.c_double * max(1, len(inputs)))()
        self._order = (ctypes.c_int * max(1, len(inputs)))(*[1] * max(1, len(inputs)))
        self._out = (ctypes.c_double * max(1, self.n_real))()

    def _refs(self, names):
        refs = [self.inst.ref(n) for n in names]
        return (ctypes.c_uint * max(1, len(refs)))(*refs)

    def _check(self, status, function, before):
        if status > WARNING:
            raise self.inst._failure(before, function, status, f"{function} failed")

    def set_inputs(self, values):
        """fmi2SetReal of the inputs given at construction, in that order."""
        before = self.inst._n_logged
        self._in[:len(values)] = values
        self._check(self._set_real(self.component, self._vr_in, len(values), self._in),
                    "fmi2SetReal", before)

    def set_derivatives(self, values):
        """fmi2SetRealInputDerivatives (first order) of the inputs, in the order given at
        construction."""
        before = self.inst._n_logged
        self._der[:len(values)] = values
        self._check(self._set_derivatives(self.component, self._vr_in, len(values),
                                          self._order, self._der),
                    "fmi2SetRealInputDerivatives", before)

    def step(self, t, h):
        before = self.inst._n_logged
        self._check(self._do_step(self.component, t, h, 1), "fmi2DoStep", before)
        self.inst.t = t + h

    def reals(self):
        """The Real outputs given at construction, as a list."""
        before = self.inst._n_logged
        self._check(self._get_real(self.component, self._vr_real, self.n_real, self._out),
                    "fmi2GetReal", before)
        return self._out[:self.n_real]

    def run(self, t, h, reals, ints, times, inputs=None):
        """len(times) steps of size h from t, each followed by a read of the outputs into the
        next row of `reals` (C-ordered float64, n_real columns) and `ints` (C-ordered int32,
        n_int columns, unused without integer outputs), its end time into `times` (float64);
        `inputs[i]` (values of the inputs, in their order) set before step i. The same calls as
        set_inputs(), step() and read() in a loop, made by the C loop of hypoid.fmu.sample_loop
        where the checkout's build has it (native=False at construction: never): per sample,
        the Python and ctypes around the FMU's calls cost about as much as the FMU's step.
        Returns the end time."""
        if self._loop is not None:
            before = self.inst._n_logged
            status, _, function, t_end = sample_loop.run(self._loop, self._fns, self, t, h,
                                                         reals, ints, times, inputs)
            if t_end != t:  # as step(): the end of the last step made
                self.inst.t = t = t_end
            self._check(status, function, before)
            return t
        return self._run_here(t, h, reals, ints, times, inputs)

    def _run_here(self, t, h, reals, ints, times, inputs):
        """run()'s loop in Python, with the calls bound once."""
        inst, comp = self.inst, self.component
        do_step, get_real, get_int = self._do_step, self._get_real, self._get_int
        vr_real, n_real, vr_int, n_int = self._vr_real, self.n_real, self._vr_int, self.n_int
        r_at, r_stride = reals.ctypes.data, reals.strides[0]
        i_at, i_stride = ints.ctypes.data, ints.strides[0]
        for i in range(len(times)):
            if inputs is not None:
                if i:
                    inst.t = t  # as step(): the end of the last step made
                self.set_inputs(inputs[i])
            before = inst._n_logged
            s = do_step(comp, t, h, 1)
            if s > WARNING:
                if i:
                    inst.t = t
                self._check(s, "fmi2DoStep", before)
            t += h
            times[i] = t
            before = inst._n_logged
            s = get_real(comp, vr_real, n_real, r_at + i * r_stride)
            if s <= WARNING and n_int:
                s = get_int(comp, vr_int, n_int, i_at + i * i_stride)
                function = "fmi2GetInteger"
            else:
                function = "fmi2GetReal"
            if s > WARNING:
                inst.t = t
                self._check(s, function, before)
        inst.t = t
        return t

    def read(self, real_address, int_address):
        """The outputs to memory: n_real float64 at real_address, n_int int32 at int_address
        (rows of numpy arrays: array.ctypes.data + i * array.strides[0])."""
        before = self.inst._n_logged
        s = self._get_real(self.component, self._vr_real, self.n_real, real_address)
        self._check(s, "fmi2GetReal", before)
        if self.n_int:
            s = self._get_int(self.component, self._vr_int, self.n_int, int_address)
            self._check(s, "fmi2GetInteger", before)


def simulate(fmu_path, stop_time, output_interval, start_values=None, output=()):
    """One run from t = 0 (fmpy's simulate_fmu in its everyday use, on Instance): the outputs at
    t = 0 and every output_interval as a structured array with a 'time' field."""
    with Instance(fmu_path, name="simulate") as inst:
        inst.start(start_values or {})
        return inst.series(stop_time, output_interval, list(output))


def normalize(params, table=TABLE):
    """Point parameters in canonical form (hypoid.fmu.values.Table.canonical)."""
    return table.normalize(params)


def start_values(names, table=TABLE):
    """The start values of the named variables (and `speed_rpm`), normalised."""
    return {n: table.start(n) for n in names}
