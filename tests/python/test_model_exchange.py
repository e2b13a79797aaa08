"""The gear FMU in Model Exchange: one binary and one modelDescription.xml with both interfaces,
the host integrating the model's states. Against co-simulation in two of the work-precision scenes
(bench/me_vs_cs.py runs all five), through fmpy's simulate_fmu (CVode) and through
hypoid.fmu.exchange; FMU states, serialization and reset in Model Exchange. The bad-input suite
(test_robustness_inputs.py, section 9) covers the entry points' arguments and states.

About 10 s."""

import math

import numpy as np
import pytest
from fmpy import simulate_fmu

from hypoid.fmu.exchange import ExchangeInstance
from hypoid.fmu.instance import FmuError, Instance
from hypoid.fmu.levels import LEVELS
from hypoid.fmu.values import RPM

# The model's state vector (fmu-src/model/dynamics.h), the order of fmi2GetContinuousStates.
STATES = ["twist_1", "twist_2", "phi_p", "DTE", "w_s_state", "w_p", "w_g", "w_w", "governor_integral",
          "E_in", "E_out", "E_friction", "E_damping", "E_excitation", "eta2_integral", "T_sump",
          "Q_housing", "E_churn", "E_bearings", "E_seals", "eta_axle2_integral", "T_km", "twist_hs",
          "impulse_w"]
NAMES = ["w_p", "DTE", "eta", "eta_cycle", "P_loss"]


def test_one_model_description_declares_both_interfaces(model_description):
    md = model_description
    assert md.modelExchange.modelIdentifier == md.coSimulation.modelIdentifier == "HypoidGearPair"
    me = md.modelExchange
    assert me.canGetAndSetFMUstate and me.canSerializeFMUstate
    assert not me.completedIntegratorStepNotNeeded  # the friction tables' key asks for events
    assert md.numberOfContinuousStates == len(STATES)
    assert md.numberOfEventIndicators == 4  # the two contact edges, the window's two ends
    assert [d.variable.derivative.name for d in md.derivatives] == STATES
    for d in md.derivatives:
        state = d.variable.derivative
        assert d.variable.name == f"der({state.name})" and d.variable.causality == "local"
        assert state.causality in ("output", "local") and state.variability == "continuous"


def run_both(fmu, values, stop_time, interval, names=NAMES):
    """The scene in Model Exchange (fmpy's CVode at the FMU's rtol, 1e-6) and co-simulation."""
    kw = dict(start_values=values, output=names, stop_time=stop_time, output_interval=interval)
    me = simulate_fmu(str(fmu), fmi_type="ModelExchange", relative_tolerance=1e-6,
                      record_events=False, **kw)
    return me, simulate_fmu(str(fmu), fmi_type="CoSimulation", **kw)


def test_design_point_agrees_with_co_simulation(fmu_path):
    """2000 rpm, 100 N.m, 40 degC to the end of the first averaging window: eta_cycle within
    1e-4 (it agrees to 1e-9), w_p within 1e-4 of itself at every output point; both are within
    their tolerance of a BDF rtol 1e-10 run (bench/me_vs_cs.py)."""
    me, cs = run_both(fmu_path, {}, 0.3, 1e-3)
    assert me["eta_cycle"][-1] < 1.0, "the averaging window must have closed"
    assert abs(me["eta_cycle"][-1] - cs["eta_cycle"][-1]) < 1e-4
    assert np.max(np.abs(me["w_p"] - cs["w_p"]) / cs["w_p"]) < 1e-4
    assert np.max(np.abs(me["DTE"] - cs["DTE"])) < 1e-7  # 0.1 um of a DTE of ~80 um


def test_tooth_separation_events_agree_with_co_simulation(fmu_path):
    """The resonance scene of the work-precision benchmark (2300 rpm, 50 N.m, frictionless: the
    teeth come apart each mesh cycle): the host finds every contact change on the backlash's
    event indicators, and the motion matches co-simulation's."""
    w = 2300 * RPM
    values = dict(T_s=50.0, w_set=w, w_p0=w, friction_model=1)
    me, cs = run_both(fmu_path, values, 0.12, 2e-5, NAMES + ["n_impacts", "contact"])
    late = me["time"] > 0.06
    assert cs["n_impacts"][-1] > 100
    assert abs(me["n_impacts"][-1] - cs["n_impacts"][-1]) <= 0.02 * cs["n_impacts"][-1]
    assert np.mean(me["contact"][late] == 0) > 0.1  # apart a good part of the time
    dte = [r["DTE"][late] for r in (me, cs)]
    assert abs(np.ptp(dte[0]) - np.ptp(dte[1])) < 0.02 * np.ptp(dte[1])
    assert abs(np.mean(me["w_p"][late]) - np.mean(cs["w_p"][late])) < 1e-4 * w


def test_states_serialization_and_reset(fmu_path):
    """A restored FMU state, one deserialized into another instance and a reset instance all
    continue bit-identically: the snapshot holds the model's contact mode, window, friction-table
    key and warm starts besides the host's states."""
    a = ExchangeInstance(fmu_path, name="a").start()
    first = a.integrate(0.02, 1e-3, NAMES)
    x_saved = a.states()
    state = a.slave.getFMUstate()
    blob = a.slave.serializeFMUstate(state)
    on = a.integrate(0.04, 1e-3, NAMES)
    a.slave.setFMUstate(state)
    a.t = 0.02
    assert np.array_equal(a.states(), x_saved)
    again = a.integrate(0.04, 1e-3, NAMES)
    assert np.array_equal(on.view(np.float64), again.view(np.float64))
    b = ExchangeInstance(fmu_path, name="b").start()
    b.slave.setFMUstate(b.slave.deSerializeFMUstate(blob))
    b.t = 0.02
    assert np.array_equal(on.view(np.float64), b.integrate(0.04, 1e-3, NAMES).view(np.float64))
    a.start()  # fmi2Reset and a new start
    assert np.array_equal(first.view(np.float64), a.integrate(0.02, 1e-3, NAMES).view(np.float64))
    a.slave.freeFMUstate(state)
    for inst in (a, b):
        inst.close()


@pytest.mark.parametrize("level", ["full", "map"])
def test_states_and_derivatives_are_readable_variables(fmu_path, level):
    """The state vector and its derivatives as variables (fmi2GetReal), in either interface, read
    before or after the other outputs (an output that is a state is the state itself)."""
    values = {k: v for k, v in LEVELS[level].items()}
    me = ExchangeInstance(fmu_path).start(values)
    me.reals(NAMES)
    x, dx = me.states(), me.derivatives()
    assert np.array_equal(me.reals(STATES), x)
    assert np.array_equal(me.reals([f"der({s})" for s in STATES]), dx)
    assert dx[STATES.index("phi_p")] == x[STATES.index("w_p")]
    assert np.all(me.nominals() > 0)
    cs = Instance(fmu_path).start(values)
    assert np.array_equal(cs.reals(STATES), x)  # the same start in co-simulation
    cs.step(1e-3)
    cs.reals(NAMES)
    first = cs.reals(STATES)
    assert np.array_equal(cs.reals(NAMES + STATES)[len(NAMES):], first)
    for inst in (me, cs):
        inst.close()


def test_gear_and_vehicle_as_one_ode_against_co_simulation(fmu_path):
    """The gear (load_mode = torque) and the vehicle FMU (half-shaft coupling), both in Model
    Exchange, integrated as one ODE by hypoid.cosim.exchange (CVODE, rtol 1e-6) through a launch,
    a tip-out into coast and a tip-in (tests/cosim's scene, compressed to 0.6 s). The coupled
    system's energy closes to 1e-6 with no coupling error at all (the gear's E_out is the
    vehicle's E_in); co-simulation (Jacobi, fmpy) at 0.1 and 0.05 ms converges to it at first
    order in the step, and Richardson's extrapolation of the two lands four times closer still
    (measured: w_p 0.22 / 0.115 / 0.012 rad/s, E_in 0.21 / 0.105 / 0.003 J)."""
    import sys

    from conftest import ROOT
    from hypoid.cosim.exchange import GearVehicleExchange

    sys.path.insert(0, str(ROOT / "tests" / "cosim"))
    import cosim_driver as cd

    scene = cd.Scene(stop_time=0.6, profile=((0.0, 0.0), (0.1, 150.0), (0.25, 150.0),
                                             (0.3, -50.0), (0.45, -50.0), (0.5, 150.0),
                                             (0.6, 150.0)))
    dt = 0.005
    with GearVehicleExchange(fmu_path, cd.VEHICLE_FMU, scene.gear_start(),
                             scene.vehicle_start(), scene.torque) as m:
        g, v = m.run(scene.stop_time, dt, cd.GEAR_OUT, cd.VEHICLE_OUT)
    me = cd.Result("me", dt, g["time"], None, {n: g[n] for n in cd.GEAR_OUT},
                   {n: v[n] for n in cd.VEHICLE_OUT}, 0.0)
    balance = cd.energy_balance(me)
    # the same work, integrated as two states of one ODE: equal to the last bits of their sums
    assert abs(balance["coupling"]) < 1e-14 * balance["interface_throughput"]
    assert abs(balance["relative_residual"]) < 1e-6
    assert min(g["T_w_out"]) < -50.0 < 150.0 < max(g["T_w_out"])  # coast and drive both ran

    def co_simulation(h):
        r = cd.run_fmpy(scene, h)
        k = int(round(dt / h))
        return {n: r.gear[n][::k][:len(g)] for n in ("w_p", "E_in")}

    coarse, fine = co_simulation(1e-4), co_simulation(5e-5)
    for n in ("w_p", "E_in"):
        err_coarse, err_fine = (np.max(np.abs(g[n] - cs[n])) for cs in (coarse, fine))
        richardson = np.max(np.abs(g[n] - (2.0 * fine[n] - coarse[n])))
        assert 1.5 < err_coarse / err_fine < 2.5, n  # first order in the step
        assert richardson < 0.25 * err_fine, n


def test_prepared_real_calls_match_the_checked_ones(fmu_path):
    """ExchangeInstance.real_setter and real_getter (a master's connections at every right-hand
    side, as bare FMI calls): the values set_reals and get_reals give, and a refused value
    raises FmuError with the FMU's message as set_reals does."""
    me = ExchangeInstance(fmu_path).start()
    refs = me.refs(["T_s", "T_w"])
    me.real_setter(refs)([12.5, -3.0])
    assert me.get_reals(refs) == [12.5, -3.0]
    assert me.real_getter(refs)() == [12.5, -3.0]
    with pytest.raises(FmuError, match="T_s"):
        me.real_setter(refs)([float("nan"), 0.0])
    me.close()


def test_friction_tables_keyed_on_the_load_lattice(fmu_path):
    """In Model Exchange, as in co-simulation, the friction tables' load range is one of
    1000 N x 4^k (hg_ft_load_range_on_lattice): the launch of tests/cosim's scene, whose pair
    load grows from nothing to 5.5 kN, keys its tables on three ranges (at twice the load itself
    it took five: 1.0 / 2.6 / 4.5 / 7.6 / 11.0 kN), each solving its own node tables."""
    import re
    import sys

    from conftest import ROOT
    from hypoid.cosim.exchange import GearVehicleExchange

    sys.path.insert(0, str(ROOT / "tests" / "cosim"))
    import cosim_driver as cd

    scene = cd.Scene(stop_time=0.3)
    with GearVehicleExchange(fmu_path, cd.VEHICLE_FMU, scene.gear_start(),
                             scene.vehicle_start(), scene.torque) as m:
        m.gear.slave.setDebugLogging(True, [])
        m.run(scene.stop_time, 0.01, ["w_p"], ["v"])
        text = [msg for _, _, msg in m.gear.messages]
    ranges = {float(r) for t in text for r in re.findall(r"pair loads up to (\d+) N", t)}
    assert ranges, "no friction table was keyed"
    assert all(math.log(r / 1000.0, 4.0) == round(math.log(r / 1000.0, 4.0)) for r in ranges)
    assert len(ranges) <= 3 and max(ranges) >= 16000.0, sorted(ranges)


def test_vehicle_model_exchange_entry_points_refuse_bad_input():
    """The vehicle FMU's Model Exchange: each entry point in a wrong state, with NULL or
    wrong-sized arrays, a state that is not finite, on a co-simulation instance; road load
    (coupling 2) refused at initialization; every refusal logged with the function's name."""
    import ctypes

    import fmi2_raw as F
    from conftest import ROOT
    from hypoid.fmu.instance import unzipped

    d = unzipped(ROOT / "build" / "LongitudinalVehicle.fmu")
    lib = F.Library(d / "binaries" / "linux64" / "LongitudinalVehicle.so")
    guid = b"{6b1f3c52-2d8e-4f0a-9c57-1e0b7a4d9e21}"
    cb = lib.callbacks()

    def instance(kind, **params):
        c = lib.fmi2Instantiate(b"v", kind, guid, b"", ctypes.byref(cb), 0, 1)
        assert c and lib.fmi2SetupExperiment(c, 0, 0.0, 0.0, 0, 0.0) == F.OK
        for vr, value in params.items():
            assert lib.fmi2SetReal(c, F.vr_array([int(vr)]), 1, F.real_array([value])) == F.OK
        assert lib.fmi2EnterInitializationMode(c) == F.OK
        return c

    def refused(status, *words):
        text = " ".join(m[2] for m in lib.messages)
        lib.messages.clear()
        assert status == F.ERROR and all(w in text for w in words), (status, text)

    x, info = (ctypes.c_double * 8)(), F.EventInfo()
    c = instance(F.ME)
    refused(lib.fmi2SetTime(c, 0.1), "fmi2SetTime", "not allowed")
    assert lib.fmi2ExitInitializationMode(c) == F.OK
    refused(lib.fmi2SetContinuousStates(c, x, 7), "fmi2SetContinuousStates", "not allowed")
    assert lib.fmi2NewDiscreteStates(c, ctypes.byref(info)) == F.OK
    assert lib.fmi2EnterContinuousTimeMode(c) == F.OK
    refused(lib.fmi2GetDerivatives(c, x, 6), "fmi2GetDerivatives", "6 values given", "has 7")
    refused(lib.fmi2GetContinuousStates(c, None, 7), "fmi2GetContinuousStates", "NULL")
    refused(lib.fmi2GetEventIndicators(c, x, 1), "fmi2GetEventIndicators", "none")
    refused(lib.fmi2SetTime(c, math.nan), "fmi2SetTime", "nan")
    x[3] = math.inf
    refused(lib.fmi2SetContinuousStates(c, x, 7), "fmi2SetContinuousStates", "state 3", "inf")
    refused(lib.fmi2DoStep(c, 0.0, 1e-3, 1), "fmi2DoStep", "not allowed")
    assert lib.fmi2GetDerivatives(c, x, 7) == F.OK and lib.fmi2Terminate(c) == F.OK
    lib.fmi2FreeInstance(c)
    cs = instance(F.CS)
    refused(lib.fmi2GetDerivatives(cs, x, 7), "fmi2GetDerivatives", "co-simulation")
    lib.fmi2FreeInstance(cs)
    road = instance(F.ME, **{"16": 2.0})  # coupling = 2
    refused(lib.fmi2ExitInitializationMode(road), "fmi2ExitInitializationMode", "coupling = 2")
    lib.fmi2FreeInstance(road)
