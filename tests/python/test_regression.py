"""Regression of FMU outputs: a few fixed scenarios (hypoid/regress.py) against the reference
values in tests/regression/reference.csv, within tests/regression/tolerances.csv. Regenerate the
reference deliberately with `hypoid regress --update` (see tests/regression/README.md)."""

import math

import pytest

from hypoid import regress


@pytest.fixture(scope="module")
def values(fmu_path):
    return regress.run_all(fmu_path)


def test_outputs_match_the_reference(values):
    ref, params = regress.read_reference()
    _, problems = regress.compare(values, ref, params, regress.read_tolerances())
    assert not problems, "outputs moved (intended? `hypoid regress --update`):\n" + "\n".join(
        problems)


def test_reference_covers_every_scenario_and_quantity():
    ref, params = regress.read_reference()
    tol = regress.read_tolerances()
    assert set(ref) == set(regress.SCENARIOS)
    axle = {n for n, p in regress.SCENARIOS.items() if p.get("axle_losses") == "full"}
    assert axle, "no scenario covers the axle's ledger"
    for name, qs in ref.items():
        extra = regress.AXLE_QUANTITIES if name in axle else ()
        assert set(qs) == set(regress.QUANTITIES + extra), name
    assert set(tol) == set(regress.QUANTITIES) | set(regress.AXLE_QUANTITIES)


def test_compare_flags_a_value_beyond_tolerance_only():
    ref, params = regress.read_reference()
    tol = regress.read_tolerances()
    name = next(iter(regress.SCENARIOS))
    for q in ("eta_rms", "DTE_pp_um", "mu_mean"):
        rel, ab = tol[q]
        allowed = ab + rel * abs(ref[name][q])
        for factor, should_fail in ((0.5, False), (3.0, True)):
            moved = {n: dict(v) for n, v in ref.items()}
            moved[name][q] = ref[name][q] + factor * allowed
            _, problems = regress.compare(moved, ref, params, tol)
            assert bool(problems) == should_fail, (q, factor, problems)
    assert not math.isnan(ref[name]["eta_rms"])


def test_reference_made_for_other_parameters_is_reported():
    ref, params = regress.read_reference()
    params = {**params, next(iter(regress.SCENARIOS)): '{"T_s": 1.0}'}
    _, problems = regress.compare(ref, ref, params, regress.read_tolerances())
    assert any("other parameters" in p for p in problems)
