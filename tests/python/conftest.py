"""Shared fixtures for the FMU tests: the built FMU, its extracted copy, and a small harness
on hypoid.fmu.instance.Instance that records log messages and drives steps."""

import pathlib
import shutil

import pytest
from fmpy import extract, read_model_description

from hypoid.fmu.instance import RAW, Instance

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


class Harness(Instance):
    """One FMU instance driven step by step (hypoid.fmu.instance.Instance); `fmu` is the raw fmpy
    slave, `set` passes values to the FMU unchecked (its own checks are under test) and
    `messages` collects (status, category, text)."""

    def __init__(self, unzipped, name="instance", logging=False):
        super().__init__(unzipped, name=name, logging=logging, keep_messages=10 ** 6)
        self.fmu = self.slave

    def set(self, **values):
        for name, value in values.items():
            var = self.table.variable(name.replace("__", "."))
            self.set_raw(var, RAW[var.type](value))

    def get(self, *names):
        out = [Instance.get(self, name) for name in names]
        return out[0] if len(out) == 1 else out

    def init(self, start=0.0, **values):
        self.used = True
        self._call(self.fmu.setupExperiment, startTime=start)
        self.set(**values)
        self._call(self.fmu.enterInitializationMode)
        self._call(self.fmu.exitInitializationMode)
        self.t = start
        return self

    def run(self, t_end, h, names):
        """Steps to t_end with step h; returns an array of the named outputs after each step."""
        return self.record(t_end, h, names)

    def free(self):
        self.close(terminate=False)


@pytest.fixture
def harness(unzipped):
    made = []

    def make(**kwargs):
        h = Harness(unzipped, **kwargs)
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
