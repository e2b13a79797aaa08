"""The half-shaft coupling (load_mode = half_shaft with the vehicle's coupling 3) under a master
that holds its inputs: a few cells of bench/coupling_matrix.py's matrix (the tip-out / tip-in
scene with its backlash crossings at the longest steps), the one-step map's stability from 0.1 to
20 ms, the warning for a longer step and the range check of an input that jumps. The whole
matrix, with the torque coupling beside it, is the benchmark (docs/records/coupling-matrix.md)."""

import math
import pathlib
import sys

import pytest

from hypoid.cosim import ecos
from hypoid.fmu.instance import FmuError, Instance

from conftest import FMU_PATH

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "cosim"))
import coupling_master as cm  # noqa: E402
import coupling_stability as cs  # noqa: E402

VEHICLE = FMU_PATH.parent / "LongitudinalVehicle.fmu"
INTENUM = FMU_PATH.parent / "HypoidGearPair_intenum.fmu"


@pytest.fixture(scope="module")
def tip():
    """The tip-out / tip-in scene cut to its tip-out and backlash crossing (0.5-1.0 s)."""
    return cm.Scene("tip", 1.0, ((0.0, 150.0), (0.6, 150.0), (0.7, -50.0), (1.0, -50.0)),
                    100.0, 0.0)


@pytest.mark.parametrize("h", [1e-2, 5e-3])
def test_jacobi_holds_at_long_steps(tip, h):
    """Jacobi with held inputs at 5 and 10 ms (the torque coupling diverges there and runs onto a
    limit cycle at 1 ms): no limit cycle, the energy closes within 1e-3 of the input work, w_p
    ends within 1e-3 of the reference (a fine Gauss-Seidel run with the driver's torque held as
    the coarse run holds it)."""
    ref = cm.run(tip, "half_shaft", "gauss-seidel", 2e-4, FMU_PATH, VEHICLE, hold=h)
    r = cm.run(tip, "half_shaft", "jacobi", h, FMU_PATH, VEHICLE)
    assert not r.failed, r.failed
    m = cm.measures(r, ref, tip)
    assert m["std_ratio"] < 1.5
    assert abs(m["energy"]) < 1e-3
    k = int(round(h / ref.h))
    assert abs(r.gear["w_p"][-1] - ref.gear["w_p"][::k][len(r.t) - 1]) < 1e-3 * ref.gear["w_p"][0]


@pytest.mark.parametrize("h", [1e-2, 5e-3])
def test_the_wheel_speed_correction_holds_w_p_within_1e_3(h):
    """The whole tip-out / tip-in scene (its tip-in after the backlash crossing included) under
    Jacobi at 5 and 10 ms: with I_vehicle the vehicle's inertia (coupling_master's default) the
    largest w_p error stays within 1e-3 of max |w_p| against a Gauss-Seidel run at 0.1 ms
    (measured 6.8e-4 at 10 ms, 3.8e-4 at 5 ms); without the correction (I_vehicle = 0) the
    vehicle's speed trails the half-shaft's impulse by T_wheel's prediction error and w_p is off
    by more than twice as much (2.5e-3 and 1.0e-3). The energy still closes within 1e-3."""
    scene = cm.SCENES["tip"]
    ref = cm.run(scene, "half_shaft", "gauss-seidel", 1e-4, FMU_PATH, VEHICLE, hold=h)
    on = cm.measures(cm.run(scene, "half_shaft", "jacobi", h, FMU_PATH, VEHICLE), ref, scene)
    off_scene = cm.Scene(**{**scene.__dict__, "gear": {"I_vehicle": 0.0}})
    off = cm.measures(cm.run(off_scene, "half_shaft", "jacobi", h, FMU_PATH, VEHICLE), ref,
                      scene)
    assert on["w_p_err"] <= 1e-3
    assert on["w_p_err"] < 0.5 * off["w_p_err"]
    assert abs(on["energy"]) < 1e-3 and on["std_ratio"] < 1.5


def test_the_correction_takes_what_the_vehicle_was_given_ahead():
    """The gear with I_vehicle set, fed a wheel speed w as a Jacobi host would, steps as the gear
    without the correction fed w - (given - own) / I_vehicle: given the sum of its T_wheel (read
    before each step) times the step, own the half-shaft's impulse, here summed from T_wheel's
    step means (T_wheel = 2 M_k - M_k-1 for equal steps, M_1 the first step's output), so the
    bookkeeping is checked against the outputs rather than against itself."""
    I_v, h = 50.0, 1e-3
    start = {"load_mode": 3, "mesh_model": "rigid", "w_p0": 10.0, "T_s": 80.0}
    with Instance(FMU_PATH, name="corr") as a, Instance(FMU_PATH, name="plain") as b:
        a.start({**start, "I_vehicle": I_v})
        b.start(start)
        given = own = 0.0
        T, M = a.get("T_wheel"), None
        for k in range(60):  # the wheel speed swings at 15 Hz, the half-shaft's torque with it
            w = (10.0 + 0.5 * math.sin(2 * math.pi * 15.0 * k * h)) / cm.RATIO
            a.set("w_wheel", w)
            b.set("w_wheel", w - (given - own) / I_v)
            a.step(h)
            b.step(h)
            given += T * h
            T = a.get("T_wheel")
            M = T if M is None else 0.5 * (T + M)
            own += M * h
        assert abs(given - own) > 1e-3  # the correction acted
        for name in ("w_p", "W_t", "T_wheel"):
            assert abs(a.get(name) - b.get(name)) <= 1e-9 * max(abs(b.get(name)), 1.0), name


def test_one_step_map_is_stable_from_0_1_to_20_ms():
    """The linearised Jacobi map of the half-shaft coupling (both extrapolations, the loaded
    gear at 150 N.m, the shipped vehicle): every mode decays at every step, without the wheel
    speed's correction and with it for I_vehicle the vehicle's inertia, half and twice that, and
    for vehicles of 50 and 3000 kg; the torque coupling's map grows at 1 ms (its mode 2)."""
    p = cs.gear_values({"tooth_data": "loaded"}, 0.0, 150.0)
    J_v = cm.I_VEHICLE
    for h in (1e-4, 5e-4, 1e-3, 2e-3, 5e-3, 1e-2, 2e-2):
        for I_v in (0.0, J_v, 0.5 * J_v, 2.0 * J_v):
            rate, _ = cs.half_shaft_rate(p, h, I_vehicle=I_v)
            assert rate < -1.0, (h, I_v)
        for m in (50.0, 3000.0):
            vehicle = {**cs.VEHICLE, "m": m}
            I_v = m * vehicle["r_dyn"] ** 2 + vehicle["J_wheels"]
            assert cs.half_shaft_rate(p, h, vehicle, I_v)[0] < -1.0, (h, m)
    assert cs.least_damped(p, 1e-3, 100.0)[0] > 0.0


def test_a_step_beyond_the_limit_is_reported_once():
    with Instance(FMU_PATH, name="long", logging=True) as g:
        g.start({"load_mode": 3, "mesh_model": "rigid"})
        for _ in range(3):
            g.step(0.05)
        warnings = [m[2] for m in g.messages if "longer than" in m[2]]
        assert len(warnings) == 1
        assert "0.05 s" in warnings[0] and "0.0204" in warnings[0]


def test_an_input_jumping_by_orders_of_magnitude_is_refused_by_name():
    with Instance(FMU_PATH, name="jump") as g:
        g.start({"load_mode": 3, "mesh_model": "rigid"})
        g.step(1e-3)
        with pytest.raises(FmuError) as e:
            g.set("w_wheel", 7.2e4)
        assert "w_wheel" in str(e.value) and "range" in str(e.value)


def test_libcosim_runs_the_half_shaft_coupling_as_the_fmpy_master(tip):
    """libcosim's fixed-step algorithm (the integer-coded gear FMU, load_mode = 3) with the same
    links: the same run as the fmpy Jacobi master to round-off (measured 1.2e-11 of w_p at 10 ms,
    9.9e-12 at 1 ms in the full tip scene)."""
    h = 1e-2
    a = cm.run(tip, "half_shaft", "jacobi", h, FMU_PATH, VEHICLE)
    b = cm.run_libcosim(tip, "half_shaft", h, INTENUM, VEHICLE)
    for name in ("w_p", "W_t"):
        scale = max(abs(a.gear[name]))
        assert max(abs(a.gear[name][1:] - b.gear[name])) < 1e-9 * scale, name


def need_ecos():
    why = ecos.why_unavailable()
    if why:
        pytest.skip(f"Ecos (ecospy) is not usable here: {why}")


@pytest.mark.parametrize("h", [1e-2, 1e-3])
def test_ecos_runs_the_half_shaft_coupling_as_the_fmpy_master(tip, h):
    """Ecos' fixed-step algorithm (ecospy 0.7.2: the integer-coded gear FMU, load_mode = 3, the
    coupling's two connections, T_s set before each step) is the fmpy Jacobi master's run from
    the start on: measured bit-identical at 1 and 10 ms in the full tip scene (w_p, W_t, T_wheel,
    the vehicle's w_wheel, every energy). Both make the same FMI calls with the same values on
    the same binary; the bound (1e-12 of each signal's largest value, the energy residual to
    1e-12 of the input work) leaves room for round-off only, where a value passed a step late or a
    start value lost changes these signals in the third digit and more."""
    need_ecos()
    a = cm.run(tip, "half_shaft", "jacobi", h, FMU_PATH, VEHICLE)
    b = cm.run_ecos(tip, "half_shaft", h, INTENUM, VEHICLE)
    assert not a.failed and not b.failed, (a.failed, b.failed)
    assert list(b.t) == list(a.t)
    for side, name in (("gear", "w_p"), ("gear", "W_t"), ("gear", "T_wheel"),
                       ("vehicle", "w_wheel")):
        x, y = getattr(a, side)[name], getattr(b, side)[name]
        assert max(abs(x - y)) <= 1e-12 * max(abs(x)), name
    (res_a, scale), (res_b, _) = cm.energy(a), cm.energy(b)
    assert abs(res_a - res_b) <= 1e-12 * scale


def test_ecos_stops_where_an_fmu_refuses_its_input(tip):
    """Ecos goes on when an FMU refuses an input (it ignores fmi2SetReal's status); the driver
    checks every connection after each step. The torque coupling at 10 ms diverges: the fmpy
    master stops when the gear refuses T_w out of its range, and the Ecos run stops after the
    same step, naming the input, with the same rows up to it."""
    need_ecos()
    h = 1e-2
    a = cm.run(tip, "torque", "jacobi", h, FMU_PATH, VEHICLE)
    b = cm.run_ecos(tip, "torque", h, INTENUM, VEHICLE)
    assert "fmi2SetReal" in a.failed
    assert "gear::T_w" in b.failed and "refused" in b.failed
    assert len(b.t) == len(a.t) - 1  # the fmpy run keeps the step's end, whose transfer failed
    assert list(b.gear["w_p"]) == list(a.gear["w_p"][:-1])
