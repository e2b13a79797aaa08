"""The FMI 3.0 FMU (build/HypoidGearPair_fmi3.fmu): fmpy validates and simulates it, its
co-simulation is bit-identical to the FMI 2.0 FMU's at equal settings (the default scene and two
fidelity levels), and so is its Model Exchange under the same integrator; its typed access
(arrays, Enumeration as Int64, time, event indicators) and its FMU states, serialization and
reset behave as in FMI 2.0."""

import pathlib
from ctypes import POINTER, c_double

import numpy as np
import pytest
from fmpy import extract, read_model_description, simulate_fmu
from fmpy.fmi3 import FMU3Model, FMU3Slave
from fmpy.validation import validate_fmu

from hypoid.fmu.levels import LEVELS
from hypoid.fmu.variables import ENUMERATIONS, VARIABLES

ROOT = pathlib.Path(__file__).resolve().parents[2]
FMU2 = ROOT / "build" / "HypoidGearPair.fmu"
FMU3 = ROOT / "build" / "HypoidGearPair_fmi3.fmu"
STOP, STEP = 0.02, 1e-3


@pytest.fixture(scope="module")
def fmu3():
    if not FMU3.exists():
        pytest.fail(f"{FMU3} is missing: build it first (scripts/setup.sh)")
    return FMU3


@pytest.fixture(scope="module")
def md3(fmu3):
    return read_model_description(str(fmu3))


def coded(values):
    """Enumeration items by name -> their codes (fmpy sets the codes)."""
    return {name: ENUMERATIONS[VARIABLES[name].enumeration][v] if isinstance(v, str) else v
            for name, v in values.items()}


def test_fmpy_validates_the_fmi3_fmu(fmu3, md3):
    assert validate_fmu(str(fmu3)) == []
    assert md3.fmiVersion == "3.0" and md3.coSimulation is not None
    assert md3.modelExchange is not None
    assert len(md3.derivatives) == len([v for v in VARIABLES if v.startswith("der(")]) > 0
    assert len(md3.eventIndicators) > 0
    names = {v.name: v for v in md3.modelVariables}
    assert names["time"].causality == "independent"
    assert int(names["pair.W"].dimensions[0].start) == 3
    assert names["solver"].type == "Enumeration"


def outputs2():
    return [v.name for v in VARIABLES.values() if v.causality == "output"]


@pytest.mark.parametrize("scene", [{}, dict(LEVELS["rigid"], T_s=150.0), LEVELS["map"]],
                         ids=["default", "rigid", "map"])
def test_fmi3_cosimulation_is_bit_identical_to_fmi2(fmu3, scene):
    start = coded(scene)
    kw = dict(stop_time=STOP, output_interval=STEP, start_values=start)
    r2 = simulate_fmu(str(FMU2), output=outputs2(), **kw)
    names3 = sorted({n.split("[")[0] + n.split("]")[1] if "[" in n else n for n in outputs2()})
    r3 = simulate_fmu(str(fmu3), output=names3, **kw)
    assert len(r2) == len(r3) == round(STOP / STEP) + 1
    assert np.array_equal(r2["time"], r3["time"])
    for name in outputs2():
        if "[" in name:  # pair[k].W -> column k - 1 of the array pair.W
            k = int(name.split("[")[1].split("]")[0])
            got = r3[name.split("[")[0] + name.split("]")[1]][:, k - 1]
        else:
            got = r3[name]
        want = r2[name]
        assert np.array_equal(np.asarray(got, float).view(np.uint64),
                              np.asarray(want, float).view(np.uint64)), name


def make(fmu3, md3, tmp_path, name="i"):
    unzipped = tmp_path / "fmu3"
    if not unzipped.exists():
        extract(str(fmu3), str(unzipped))
    slave = FMU3Slave(guid=md3.guid, unzipDirectory=str(unzipped),
                      modelIdentifier=md3.coSimulation.modelIdentifier, instanceName=name)
    slave.instantiate()
    return slave


def test_typed_access_arrays_and_time(fmu3, md3, tmp_path):
    vr = {v.name: v.valueReference for v in md3.modelVariables}
    s = make(fmu3, md3, tmp_path)
    s.setInt64([vr["mesh_model"]], [ENUMERATIONS["mesh_model"]["rigid"]])
    s.enterInitializationMode(startTime=0.5)
    s.exitInitializationMode()
    s.doStep(0.5, 0.01)
    assert s.getFloat64([vr["time"]]) == [pytest.approx(0.51, abs=1e-15)]
    assert s.getInt64([vr["mesh_model"]]) == [ENUMERATIONS["mesh_model"]["rigid"]]
    w = s.getFloat64([vr["pair.W"], vr["W_t"]], nValues=4)
    assert len(w) == 4 and all(np.isfinite(w))
    assert s.getString([vr["gear_set_file"]]) in ([""], [b""])
    assert s.getBoolean([vr[next(n for n, v in VARIABLES.items() if v.type == "Boolean")]])
    with pytest.raises(Exception):  # nValues must count the array's elements
        s.getFloat64([vr["pair.W"], vr["W_t"]])
    with pytest.raises(Exception):  # an enumeration is Int64, not Int32
        s.getInt32([vr["mesh_model"]])
    s.terminate()
    s.freeInstance()


def run(slave, t, n, vr):
    out = []
    for _ in range(n):
        slave.doStep(t, STEP)
        t += STEP
        out.append(slave.getFloat64([vr])[0])
    return t, out


def test_states_serialization_and_reset(fmu3, md3, tmp_path):
    vr = next(v.valueReference for v in md3.modelVariables if v.name == "w_p")
    s = make(fmu3, md3, tmp_path)
    s.enterInitializationMode()
    s.exitInitializationMode()
    t, before = run(s, 0.0, 5, vr)
    state = s.getFMUState()  # the next step restarts the integrator (restored runs match)
    blob = s.serializeFMUState(state)
    _, first = run(s, t, 5, vr)
    s.setFMUState(state)
    _, again = run(s, t, 5, vr)
    restored = s.deserializeFMUState(blob)
    s.setFMUState(restored)
    _, thrice = run(s, t, 5, vr)
    assert first == again == thrice
    s.freeFMUState(state)
    s.freeFMUState(restored)
    s.reset()
    s.enterInitializationMode()
    s.exitInitializationMode()
    _, fresh = run(s, 0.0, 5, vr)
    assert fresh == before
    s.terminate()
    s.freeInstance()


def test_fmu_reproduces_its_reference_results(fmu3, tmp_path):
    """extra/org.fmi-standard.fmi-ls-ref/ (tools/fmi_ls_ref.py): the experiment's start values,
    times and step, run by fmpy on the FMI 3.0 FMU as any importer would, reproduce the
    reference CSV (made with the FMI 2.0 FMU: the same to the last bit on one machine; a
    tolerance of 1e-6 of each output's range for other machines' libm-free builds)."""
    import csv
    import xml.etree.ElementTree as ET
    import zipfile

    with zipfile.ZipFile(fmu3) as z:
        z.extractall(tmp_path)
    exp = ET.parse(tmp_path / "extra/org.fmi-standard.fmi-ls-ref/fmi-ls-experiments.xml") \
        .getroot().find("Experiment")
    ssv = ET.parse(tmp_path / exp.find("Parameters").get("source")).getroot()
    starts = {p.get("name"): float(p[0].get("value")) for p in ssv.iter()
              if p.tag.endswith("}Parameter")}
    with open(tmp_path / exp.find("References").get("source"), newline="") as fh:
        rows = list(csv.reader(fh))
    names, ref = rows[0], np.array(rows[1:], dtype=float)
    step = float(exp.get("stepSize"))
    every = round((ref[1, 0] - ref[0, 0]) / step)
    res = simulate_fmu(str(fmu3), start_time=float(exp.get("startTime")),
                       stop_time=float(exp.get("stopTime")), output_interval=step,
                       start_values=starts, output=names[1:])
    got = res[::every]
    assert len(got) == len(ref)
    for j, name in enumerate(names[1:], 1):
        scale = np.ptp(ref[:, j]) + abs(ref[:, j]).max() * 1e-3
        assert np.allclose(got[name], ref[:, j], rtol=0, atol=1e-6 * scale), (
            f"{name}: the FMU no longer reproduces its reference results; after a deliberate "
            "change of the model run `scripts/regenerate.sh regress` (it rewrites them with the regression's reference)")


@pytest.mark.parametrize("scene", [{}, LEVELS["rigid"]], ids=["default", "rigid"])
def test_model_exchange_is_bit_identical_to_fmi2(fmu3, scene):
    """fmpy's CVode on the FMI 3.0 and the FMI 2.0 Model Exchange: the same bits; and near the
    co-simulation (the agreement at tolerance is test_model_exchange.py's)."""
    names = ["w_p", "w_g", "eta", "DTE", "P_loss", "T_fp"]
    kw = dict(stop_time=STOP, output_interval=STEP, start_values=coded(scene), output=names,
              fmi_type="ModelExchange", relative_tolerance=1e-6)
    r3 = simulate_fmu(str(fmu3), **kw)
    r2 = simulate_fmu(str(FMU2), **kw)
    cs = simulate_fmu(str(fmu3), stop_time=STOP, output_interval=STEP,
                      start_values=coded(scene), output=names)
    for name in names:
        assert np.array_equal(r3[name].view(np.uint64), r2[name].view(np.uint64)), name
    assert r3["w_p"][-1] == pytest.approx(cs["w_p"][-1], rel=1e-3)


def test_model_exchange_states_and_serialization(fmu3, md3, tmp_path):
    """Explicit Euler steps through fmi3 Model Exchange: a state taken, serialized, restored
    in the same and in a second instance continues bit-identically."""
    unzipped = tmp_path / "fmu3me"
    extract(str(fmu3), str(unzipped))
    nx, nz = len(md3.derivatives), len(md3.eventIndicators)

    def model(name):
        m = FMU3Model(guid=md3.guid, unzipDirectory=str(unzipped),
                      modelIdentifier=md3.modelExchange.modelIdentifier, instanceName=name)
        m.instantiate()
        m.enterInitializationMode()
        m.exitInitializationMode()
        m.updateDiscreteStates()
        m.enterContinuousTimeMode()
        return m

    def ptr(a):
        return a.ctypes.data_as(POINTER(c_double))

    def euler(m, t, n, h=1e-6):
        x, dx, z, y = (np.zeros(nx), np.zeros(nx), np.zeros(nz), np.zeros(nx))
        for _ in range(n):
            m.getContinuousStates(ptr(x), nx)
            m.getContinuousStateDerivatives(ptr(dx), nx)
            t += h
            m.setTime(t)
            y[:] = x + h * dx
            m.setContinuousStates(ptr(y), nx)
            m.getEventIndicators(ptr(z), nz)
            enter, _ = m.completedIntegratorStep()
            if enter:
                m.enterEventMode()
                m.updateDiscreteStates()
                m.enterContinuousTimeMode()
        m.getContinuousStates(ptr(x), nx)
        return t, x.copy()

    a = model("a")
    t, _ = euler(a, 0.0, 50)
    state = a.getFMUState()
    blob = a.serializeFMUState(state)
    _, first = euler(a, t, 50)
    a.setFMUState(state)
    _, again = euler(a, t, 50)
    b = model("b")
    restored = b.deserializeFMUState(blob)
    b.setFMUState(restored)
    _, other = euler(b, t, 50)
    assert np.array_equal(first, again) and np.array_equal(first, other)
    for m, s in ((a, state), (b, restored)):
        m.freeFMUState(s)
        m.terminate()
        m.freeInstance()


def test_output_derivatives_are_the_states_derivatives(fmu3, md3, tmp_path):
    """fmi3GetOutputDerivatives (order 1) of the shaft-end speeds a host extrapolates: der(w_s),
    der(w_w) of the model, close to the slope of the next small step."""
    vr = {v.name: v.valueReference for v in md3.modelVariables}
    assert md3.coSimulation.maxOutputDerivativeOrder == 1
    s = make(fmu3, md3, tmp_path)
    s.enterInitializationMode()
    s.exitInitializationMode()
    t, h = 0.0, 1e-4
    for _ in range(50):
        s.doStep(t, h)
        t += h
    names = ["w_s", "w_w", "w_p"]
    der = s.getOutputDerivatives([vr[n] for n in names], [1, 1, 1])
    state = {"w_s": "w_s_state"}  # the state whose value w_s gives (w_p at the map level)
    assert der == s.getFloat64([vr[f"der({state.get(n, n)})"] for n in names])
    ends = [vr["w_s"], vr["w_w"]]  # the shaft ends a driveline couples to
    before = s.getFloat64(ends)
    s.doStep(t, 1e-7)
    slope = (np.array(s.getFloat64(ends)) - before) / 1e-7
    assert np.allclose(der[:2], slope, rtol=1e-2, atol=1.0)
    s.terminate()
    s.freeInstance()
