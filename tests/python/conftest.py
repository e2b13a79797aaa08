"""Shared fixtures for the FMU tests: the built FMU, its extracted copy, and a small harness
around fmpy's FMU2Slave that records log messages and drives steps."""

import pathlib
import shutil

import numpy as np
import pytest
from fmpy import extract, read_model_description
from fmpy import free, calloc
from fmpy.fmi2 import (FMU2Slave, fmi2CallbackAllocateMemoryTYPE, fmi2CallbackFreeMemoryTYPE,
                       fmi2CallbackFunctions, fmi2CallbackLoggerTYPE)

ROOT = pathlib.Path(__file__).resolve().parents[2]
FMU_PATH = ROOT / "build" / "HypoidGearPair.fmu"


@pytest.fixture(scope="session")
def fmu_path():
    if not FMU_PATH.exists():
        pytest.fail(f"{FMU_PATH} is missing: build it first (scripts/setup.sh)")
    return FMU_PATH


@pytest.fixture(scope="session")
def unzipped(fmu_path, tmp_path_factory):
    directory = tmp_path_factory.mktemp("fmu")
    extract(str(fmu_path), str(directory))
    return directory


@pytest.fixture(scope="session")
def model_description(fmu_path):
    return read_model_description(str(fmu_path))


class Harness:
    """One FMU instance driven step by step; `messages` collects (status, category, text)."""

    def __init__(self, unzipped, md, name="instance", logging=False):
        self.md = md
        self.vr = {v.name: v.valueReference for v in md.modelVariables}
        self.types = {v.name: v.type for v in md.modelVariables}
        self.messages = []
        self.fmu = FMU2Slave(guid=md.guid, unzipDirectory=str(unzipped),
                             modelIdentifier=md.coSimulation.modelIdentifier, instanceName=name)
        self.callbacks = fmi2CallbackFunctions()
        self.callbacks.logger = fmi2CallbackLoggerTYPE(self._log)
        self.callbacks.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
        self.callbacks.freeMemory = fmi2CallbackFreeMemoryTYPE(free)
        self.fmu.instantiate(loggingOn=logging, callbacks=self.callbacks)
        self.t = 0.0
        self.freed = False

    def _log(self, component, instance, status, category, message):
        self.messages.append((status, category.decode(), message.decode().replace("%%", "%")))

    def set(self, **values):
        for name, value in values.items():
            name = name.replace("__", ".")
            kind, ref = self.types[name], [self.vr[name]]
            if kind == "Real":
                self.fmu.setReal(ref, [float(value)])
            elif kind in ("Integer", "Enumeration"):
                self.fmu.setInteger(ref, [int(value)])
            elif kind == "String":
                self.fmu.setString(ref, [value])
            else:
                self.fmu.setBoolean(ref, [bool(value)])

    def get(self, *names):
        out = []
        for name in names:
            kind = self.types[name]
            getter = self.fmu.getReal if kind == "Real" else self.fmu.getInteger
            out.append(getter([self.vr[name]])[0])
        return out[0] if len(out) == 1 else out

    def init(self, start=0.0, **values):
        self.fmu.setupExperiment(startTime=start)
        self.set(**values)
        self.fmu.enterInitializationMode()
        self.fmu.exitInitializationMode()
        self.t = start
        return self

    def run(self, t_end, h, names):
        """Steps to t_end with step h; returns an array of the named outputs after each step."""
        rows = []
        n = int(round((t_end - self.t) / h))
        for _ in range(n):
            self.fmu.doStep(currentCommunicationPoint=self.t, communicationStepSize=h)
            self.t += h
            rows.append(self.fmu.getReal([self.vr[x] for x in names]))
        return np.array(rows)

    def errors(self):
        return [m for m in self.messages if m[0] >= 3]

    def free(self):
        if not self.freed:
            self.freed = True
            self.fmu.freeInstance()


@pytest.fixture
def harness(unzipped, model_description):
    made = []

    def make(**kwargs):
        h = Harness(unzipped, model_description, **kwargs)
        made.append(h)
        return h

    yield make
    for h in made:
        h.free()


@pytest.fixture
def fmu_in_dir_with_space(fmu_path, tmp_path):
    target = tmp_path / "dir with space" / "HypoidGearPair.fmu"
    target.parent.mkdir()
    shutil.copy(fmu_path, target)
    return target
