"""Shared fixtures for the FMU tests: the built FMU, its extracted copy, and instances of it
(hypoid.fmu.instance.Instance, the one FMU access class) that keep every log message."""

import pathlib
import shutil

import pytest
from fmpy import extract, read_model_description

from hypoid.fmu.instance import Instance

ROOT = pathlib.Path(__file__).resolve().parents[2]
FMU_PATH = ROOT / "build" / "HypoidGearPair.fmu"

# `./test.sh --quick` (`pytest -m quick`): the inner loop's subset. Every test is in it but the
# suites long by design (whole files: the bad-input matrix, the paper's studies, the extremes
# matrix, the notebook, the installed wheel, the co-simulation scenes, the loaded TCA, the
# layered tooth data) and the single tests that take seconds each (by function name, every
# parameter); of the long files a cheap test each stays, so that every layer is touched (the FMI
# layer and its bad input, each level, tribology, the axle, the master and the drive cycle, the
# studies' tools, the records, the package). About two minutes on two idle cores, with the C
# tests; CI runs everything. tests/python/test_quick_mode.py checks that every name here exists.
SLOW_FILES = {
    "test_robustness_inputs.py", "test_paper_findings.py", "test_extremes.py",
    "test_examples.py", "test_installed_package.py", "test_cosim.py", "test_tca_loaded.py",
    "test_gearset_layers.py",
}
SLOW_TESTS = {
    "test_drive_cycle.py::test_the_default_level_gives_the_full_levels_axle_loss",
    "test_drive_cycle.py::test_full_level_launches_from_a_standstill",
    "test_drive_cycle.py::test_libcosim_and_fmpy_masters_agree_on_the_axle_loss",
    "test_drive_cycle.py::test_wltc_launch_energy_audit_closes_to_1e_6",
    "test_gearset_blank.py::test_design_writes_the_builtin_loaded_file_from_table_1",
    "test_modes.py::test_dte_gain_against_a_time_domain_run",
    "test_sweeps.py::test_local_pool_and_a_dask_scheduler_match_the_serial_run",
    "test_sweeps.py::test_a_signal_ends_the_sweep_and_its_workers",
    "test_model_exchange.py::test_gear_and_vehicle_as_one_ode_against_co_simulation",
    "test_generated_docs.py::test_a_changed_figure_fails_the_check",
    "test_mesh_law.py::test_dte_against_the_reference_model",
    "test_coupling.py::test_ecos_stops_where_an_fmu_refuses_its_input",
    "test_map_speedgrid.py::test_the_full_models_ridge_lies_in_its_band_and_the_map_follows_it",
}
QUICK_FROM_SLOW = {
    "test_robustness_inputs.py::test_impossible_axle_and_oil_data_fail_naming_the_variable",
    "test_robustness_inputs.py::test_instantiate_arguments",
    "test_cosim.py::test_vehicle_initial_state_and_energy_closure",
    "test_tca_loaded.py::test_two_equal_pairs_share_the_load_equally",
    "test_gearset_layers.py::test_tooth_data_picks_the_built_in_file",
    "test_examples.py::test_notebook_is_made_from_the_script",
}


def pytest_configure(config):
    config.addinivalue_line("markers", "quick: the inner loop's subset (./test.sh --quick)")


def pytest_collection_modifyitems(config, items):
    for item in items:
        name, test = item.path.name, f"{item.path.name}::{item.originalname}"
        if test in QUICK_FROM_SLOW or (name not in SLOW_FILES and test not in SLOW_TESTS):
            item.add_marker(pytest.mark.quick)


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
