"""ModelStructure against the model: the dependencies generate.py writes from variables.toml's
[start_dependencies] are what the FMU does when an input changes. After a step no output moves
until the next step (every output dependencies=""); in initialization mode each input moves the
initial unknowns listed for it and no other, in some load mode, axle and thermal model. Also the
DefaultExperiment's step and the start without inputs (docs/integration.md, "The start")."""

import re
import xml.etree.ElementTree as ET
import zipfile

import pytest

from hypoid.fmu.instance import Instance

from conftest import FMU_PATH as FMU

CONFIGS = [{"load_mode": 1}, {"load_mode": 2}, {"load_mode": 3, "axle_losses": 2},
           {"load_mode": 1, "axle_losses": 2, "thermal_model": 2}]
START = {"T_s": 100.0, "T_w": 277.0, "w_wheel": 70.0}


def description():
    with zipfile.ZipFile(FMU) as z:
        return ET.fromstring(z.read("modelDescription.xml"))


def variables(root):
    return [sv for sv in root.find("ModelVariables")]


def moved(a, b):
    return {n for n in a if not (a[n] == b[n] or (a[n] != a[n] and b[n] != b[n]))}


def bump(g, name):
    x = g.get(name)
    g.set(name, x * 1.1 + 1.0)


@pytest.fixture(scope="module")
def structure():
    root = description()
    svs = variables(root)
    names = [sv.get("name") for sv in svs]
    inputs = [sv.get("name") for sv in svs if sv.get("causality") == "input"]
    ms = root.find("ModelStructure")
    outputs = {names[int(u.get("index")) - 1]: u.get("dependencies")
               for u in ms.find("Outputs")}
    initial = {names[int(u.get("index")) - 1]:  # the states and derivatives of Model Exchange
               {names[int(k) - 1] for k in u.get("dependencies").split()}  # declare none: all
               for u in ms.find("InitialUnknowns") if u.get("dependencies") is not None}
    return names, inputs, outputs, initial


def test_no_output_moves_before_the_next_step(structure):
    """Co-simulation: no output moves when an input is set (sound for whatever is declared);
    the declaration names no parameter or other output, only inputs and the continuous states
    (the knowns of Model Exchange, which the same ModelStructure serves:
    test_model_exchange_outputs_move_with_the_listed_inputs_only)."""
    names, inputs, outputs, _ = structure
    svs = variables(description())
    states = {names[int(svs[int(u.get("index")) - 1].find("Real").get("derivative")) - 1]
              for u in description().find("ModelStructure").find("Derivatives")}
    for deps in outputs.values():
        known = {names[int(k) - 1] for k in deps.split()}
        assert known <= set(inputs) | states and states <= known
    for cfg in CONFIGS[:3]:
        with Instance(FMU, name="ms") as g:
            g.start({**cfg, **START})
            g.step(1e-3)
            before = {n: g.get(n) for n in outputs}
            for name in inputs:
                bump(g, name)
            assert moved(before, {n: g.get(n) for n in outputs}) == set(), cfg


def test_model_exchange_outputs_move_with_the_listed_inputs_only(structure):
    """Model Exchange, continuous-time mode: an input set moves only the outputs that declare
    it (the states held)."""
    from hypoid.fmu.exchange import ExchangeInstance

    names, inputs, outputs, _ = structure
    declared = {o: {names[int(k) - 1] for k in d.split()} for o, d in outputs.items()}
    for cfg in CONFIGS:
        for name in inputs:
            with ExchangeInstance(FMU, name="ms") as g:
                g.start({**cfg, **START})
                before = {n: g.get(n) for n in outputs}
                bump(g, name)
                for o in moved(before, {n: g.get(n) for n in outputs}):
                    assert name in declared[o], f"{name} moves {o} in Model Exchange ({cfg})"


def test_initial_unknowns_move_with_the_listed_inputs_only(structure):
    """Sound (nothing moves that is not declared) and exact (every declared input moves its
    unknown, or a pair's sibling, in one of the configurations)."""
    names, inputs, _, initial = structure
    unknowns = list(initial)
    seen = set()
    for cfg in CONFIGS:
        for name in inputs:
            with Instance(FMU, name="ms") as g:
                g.set_many({**cfg, **START})
                g.slave.setupExperiment(startTime=0.0)
                g.slave.enterInitializationMode()
                before = {u: g.get(u) for u in unknowns}
                bump(g, name)
                after = {u: g.get(u) for u in unknowns}
            for u in moved(before, after):
                assert name in initial[u], f"{name} moves {u} at the start ({cfg})"
                seen.add((name, re.sub(r"\[\d+\]", "[k]", u)))
    declared = {(i, re.sub(r"\[\d+\]", "[k]", u)) for u, deps in initial.items()
                for i in deps if i in inputs}
    assert declared - seen == set()


def test_default_experiment_proposes_the_documented_step():
    exp = description().find("DefaultExperiment")
    assert float(exp.get("stepSize")) == 1e-3


@pytest.mark.parametrize("inputs", [{}, {"T_s": 0.0, "T_w": 0.0, "w_wheel": 0.0}],
                         ids=["never-set", "zeros"])
def test_half_shaft_starts_without_a_kick(inputs):
    """Inputs never set (T_s at its start value) or all 0: the half-shaft carries what the gear
    passes on, the wheel turns at the gear's speed: 10 ms keep w_p within 1e-5 (measured 4.7e-6,
    the losses settling); under load_mode = torque a T_w left at 0 moves it by 9.7 rad/s."""
    with Instance(FMU, name="start") as g:
        g.start({"load_mode": 3, "mesh_model": "mean", "w_p0": 200.0, **inputs})
        w0 = g.get("w_p")
        for _ in range(10):
            g.step(1e-3)
        assert abs(g.get("w_p") - w0) < 1e-5 * w0
        T = g.get("T_s") * g.get("ratio")
        assert g.get("T_w_out") == pytest.approx(T, rel=0.02, abs=1e-9)
