"""Shared fixtures for the FMU tests: the built FMU, its extracted copy, and instances of it
(hypoid.fmu.instance.Instance, the one FMU access class) that keep every log message."""

import pathlib
import shutil

import pytest
from fmpy import extract, read_model_description

from hypoid.fmu.instance import Instance

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


@pytest.fixture
def harness(unzipped):
    """make(name=..., logging=...): FMU instances (hypoid.fmu.instance.Instance, every log message
    kept) that the test drives call by call; freed at the end without fmi2Terminate."""
    made = []

    def make(name="instance", logging=False):
        h = Instance(unzipped, name=name, logging=logging, keep_messages=10 ** 6)
        made.append(h)
        return h

    yield make
    for h in made:
        h.close(terminate=False)


@pytest.fixture
def fmu_in_dir_with_space(fmu_path, tmp_path):
    target = tmp_path / "dir with space" / "HypoidGearPair.fmu"
    target.parent.mkdir()
    shutil.copy(fmu_path, target)
    return target
