"""One reusable FMU instance for studies: loads the FMU once, sets start values by variable name
(enumerations by item name or number), restarts with fmi2Reset between operating points and
reads the gear set's pinion tooth count (the mesh period needs it)."""

import math
import pathlib

from fmpy import calloc, extract, free, read_model_description
from fmpy.fmi1 import FMICallException
from fmpy.fmi2 import (FMU2Slave, fmi2CallbackAllocateMemoryTYPE, fmi2CallbackFreeMemoryTYPE,
                       fmi2CallbackFunctions, fmi2CallbackLoggerTYPE)

from hypoid.paths import data_file

RPM = math.pi / 30.0  # rad/s per rpm
SPEED_KEY = "speed_rpm"  # a point's pinion speed; sets both w_set and w_p0 (quick start)


class FmuError(RuntimeError):
    """An FMI call failed; the message carries the FMU's last log messages."""


class Instance:
    """An instantiated co-simulation slave of the HypoidGearPair FMU."""

    def __init__(self, fmu_path, unzip_dir=None, name="study"):
        self.fmu_path = str(fmu_path)
        self.md = read_model_description(self.fmu_path)
        self.unzip_dir = unzip_dir or extract(self.fmu_path)
        self.vars = {v.name: v for v in self.md.modelVariables}
        self.messages = []
        self._callbacks = self._make_callbacks()
        self.slave = FMU2Slave(guid=self.md.guid, unzipDirectory=self.unzip_dir,
                               modelIdentifier=self.md.coSimulation.modelIdentifier,
                               instanceName=name)
        self.slave.instantiate(callbacks=self._callbacks, loggingOn=False)
        self.used = False
        self._np_cache = {}

    def _make_callbacks(self):
        cb = fmi2CallbackFunctions()
        cb.logger = fmi2CallbackLoggerTYPE(self._log)
        cb.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
        cb.freeMemory = fmi2CallbackFreeMemoryTYPE(free)
        return cb

    def _log(self, component, instance, status, category, message):
        self.messages.append(message.decode(errors="replace").replace("%%", "%"))
        del self.messages[:-20]

    # ------------------------------------------------------------------ values
    def ref(self, name):
        if name not in self.vars:
            raise KeyError(f"the FMU has no variable {name!r}")
        return self.vars[name].valueReference

    def enum_value(self, name, value):
        """An enumeration value from its item name ('ehl_thermal') or number (4)."""
        items = self.vars[name].declaredType.items
        if isinstance(value, str) and not value.lstrip("-").isdigit():
            for item in items:
                if item.name == value:
                    return int(item.value)
            raise ValueError(f"{name} has no item {value!r} (items: "
                             + ", ".join(i.name for i in items) + ")")
        return int(value)

    def set(self, name, value):
        var = self.vars.get(name)
        if var is None:
            raise KeyError(f"the FMU has no variable {name!r}")
        ref = [var.valueReference]
        if var.type == "Real":
            self.slave.setReal(ref, [float(value)])
        elif var.type == "Enumeration":
            self.slave.setInteger(ref, [self.enum_value(name, value)])
        elif var.type == "Integer":
            self.slave.setInteger(ref, [int(value)])
        elif var.type == "String":
            self.slave.setString(ref, [str(value)])
        else:
            self.slave.setBoolean(ref, [bool(value)])

    def get(self, name):
        var = self.vars[name]
        if var.type == "Real":
            return self.slave.getReal([var.valueReference])[0]
        if var.type == "String":
            return self.slave.getString([var.valueReference])[0].decode()
        return self.slave.getInteger([var.valueReference])[0]

    # ------------------------------------------------------------------ life cycle
    def start(self, params):
        """fmi2Reset (if used before), set the point's start values, initialise at t = 0.

        `params` maps FMU variable names to values; `speed_rpm` sets w_set and w_p0."""
        try:
            if self.used:
                self.slave.reset()
            self.used = True
            self.messages.clear()
            self.slave.setupExperiment(startTime=0.0)
            for name, value in params.items():
                if name == SPEED_KEY:
                    self.set("w_set", value * RPM)
                    self.set("w_p0", value * RPM)
                else:
                    self.set(name, value)
            self.slave.enterInitializationMode()
            self.slave.exitInitializationMode()
        except FMICallException as e:
            raise FmuError(self._explain(e)) from None

    def do_step(self, t, h):
        try:
            self.slave.doStep(currentCommunicationPoint=t, communicationStepSize=h)
        except FMICallException as e:
            raise FmuError(self._explain(e)) from None

    def _explain(self, e):
        tail = " | ".join(self.messages[-3:])
        return f"{e}" + (f": {tail}" if tail else "")

    def pinion_teeth(self):
        """N_p of the gear set in use (after initialisation): the calculated parameter N_p, or
        the gear set's data file with FMUs that lack it."""
        if "N_p" in self.vars:
            return int(self.get("N_p"))
        path = self.get("gear_set_file")
        if not path:
            path = f"gearsets/gearset{self.get('gear_set')}.txt"
        p = pathlib.Path(path)
        if not p.is_absolute():
            p = pathlib.Path(self.unzip_dir) / "resources" / p
        if p not in self._np_cache:
            self._np_cache[p] = _read_np(p)
        return self._np_cache[p]

    def close(self):
        try:
            self.slave.terminate()
        except Exception:  # noqa: BLE001 - the instance may be in an error state
            pass
        self.slave.freeInstance()


def _read_np(path):
    for line in pathlib.Path(path).read_text().splitlines():
        words = line.split("#", 1)[0].split()
        if len(words) == 2 and words[0] == "N_p":
            return int(words[1])
    raise ValueError(f"{path}: no N_p line")


def normalize(md, params):
    """Point parameters in canonical form: enumerations by item name, integers as int, reals
    as float, strings as str (so equal points get equal keys), data files relative to the working
    directory made absolute (hypoid/paths.py). `speed_rpm` is a float."""
    by_name = {v.name: v for v in md.modelVariables}
    out = {}
    for name, value in params.items():
        var = by_name.get(name)
        if name == SPEED_KEY:
            out[name] = float(value)
        elif var is None:
            raise KeyError(f"the FMU has no variable {name!r}")
        elif var.type == "Enumeration":
            items = var.declaredType.items
            text = str(value)
            match = [i.name for i in items if i.name == text or str(i.value) == text]
            if not match:
                raise ValueError(f"{name} has no item {value!r} (items: "
                                 + ", ".join(f"{i.value}={i.name}" for i in items) + ")")
            out[name] = match[0]
        elif var.type == "Integer":
            out[name] = int(value)
        elif var.type == "Real":
            out[name] = float(value)
        elif var.type == "String":
            out[name] = data_file(str(value))
        else:
            out[name] = bool(value)
    return out


def start_values(md, names):
    """The model description's start values of the named variables, normalised."""
    by_name = {v.name: v for v in md.modelVariables}
    values = {}
    for n in names:
        if n == SPEED_KEY:
            values[n] = round(float(by_name["w_set"].start) / RPM, 9)
        else:
            values[n] = by_name[n].start if by_name[n].start is not None else ""
    return normalize(md, values)
