"""Communication steps and integrator restarts (docs/model.md, "Steps without restarts"): inputs
held for many steps (the integrator passes the step ends), a ramp given with derivatives (no
restarts), a ramp given as many small jumps and a torque step (restarts; the explicit method's
keep its step size). Each against the same input sequence at a tight tolerance, with the energy
audit closing and a state round trip bit-identical."""

import numpy as np
import pytest

from hypoid.fmu.levels import LEVELS

AUDIT = ["E_in", "E_out", "E_friction", "E_damping", "E_excitation", "E_stored"]
REALS = ["w_p", "w_s", "W_t", "P_loss", "eta"] + AUDIT
COUNTERS = ["solver_steps", "rhs_evals"]
OUT = REALS + COUNTERS
AUDIT_COLS = slice(len(REALS) - len(AUDIT), len(REALS))
# The tight solution: rtol and atol (m of DTE, the other states' scaled from it) both tight, for
# at the defaults the speeds' error follows atol rather than rtol
TIGHT = dict(rtol=1e-10, atol=1e-14)
# The friction energy against the tight solution: the integrator's error on it follows the
# friction power's ripple along the mesh cycle, which the loaded tooth data (the defaults) double
# (6.8 % peak to peak on the rigid mesh at 125 N.m, the paper's one series 3.1 %): measured on the
# rigid level 3.3e-5 for the held ramp and 1.1e-5 with derivatives (one series 8e-6), the same with
# the friction solved directly (so not the table). Speeds and E_in stay held to 2e-5.
FRICTION_REL = 1e-4
# The energy audit closes to the integrator's error: with the loaded force law 1.5e-6 of E_in on
# the full level at its rtol 1e-6 in the held ramp (1.1e-7 at rtol 1e-7; the one series 1.0e-7).
AUDIT_REL = 3e-6


def audit_residual(row):
    """E_in - E_out - E_friction - E_damping + E_excitation - (E_stored - E_stored(0))."""
    e_in, e_out, e_fric, e_damp, e_exc, e_stored = row
    return e_in - e_out - e_fric - e_damp + e_exc - e_stored


def start(harness, level, name="run", **extra):
    """An initialised instance of the level (enumeration items by name) with extra values."""
    x = harness(name=name)
    values = {**LEVELS[level], **extra}
    return x.start({k: x.enum_value(k, v) if isinstance(v, str) else v
                     for k, v in values.items()}, checked=False)


def run(harness, level, torque, n, h, derivative=None, name="run", **extra):
    """n steps of h with T_s = torque(t) at each step's start (and its derivative when given);
    returns the outputs after each step and the harness."""
    x = start(harness, level, name, **extra)
    e0 = x.get("E_stored")
    rows = []
    for _ in range(n):
        x.set_unchecked(dict(T_s=torque(x.t)))
        if derivative is not None:
            x.slave.setRealInputDerivatives([x.ref("T_s")], [1], [derivative(x.t)])
        rows.append(list(x.record(x.t + h, h, REALS)[0]) + list(x.ints(COUNTERS)))
    rows = np.array(rows)
    rows[:, OUT.index("E_stored")] -= e0
    return rows, x


def col(rows, name):
    return rows[:, OUT.index(name)]


def ramp(t):
    return 100.0 + 250.0 * t  # N.m: 100 -> 150 over 0.2 s


@pytest.mark.parametrize("level", ["rigid", "map", "full"])
def test_a_ramp_of_small_steps_matches_the_tight_solution(harness, level):
    """T_s held over each step (piecewise constant, 0.25 N.m a step): each jump restarts the
    integrator (continuing through them drifted by 5e-5 in E_in on the rigid level), and the
    run matches the tight one."""
    n = 200 if level != "full" else 40
    rows, _ = run(harness, level, ramp, n, 1e-3)
    tight, _ = run(harness, level, ramp, n, 1e-3, name="tight", **TIGHT)
    for name in ("w_p", "w_s", "E_in"):
        assert col(rows, name)[-1] == pytest.approx(col(tight, name)[-1], rel=2e-5), name
    assert col(rows, "E_friction")[-1] == pytest.approx(col(tight, "E_friction")[-1],
                                                        rel=FRICTION_REL)
    assert abs(audit_residual(rows[-1, AUDIT_COLS])) < AUDIT_REL * col(rows, "E_in")[-1]


def test_the_explicit_method_restarts_with_its_step_size(harness):
    """arkode_erk through a ramp held over each step: each jump restarts it, keeping its step
    size, so it costs little more than the same ramp given with derivatives (no restarts;
    measured 1.11x, 1.56x when the restarts estimated a first step anew) and keeps its accuracy."""
    cost = {}
    for label, slope in (("held", None), ("derivatives", lambda t: 250.0)):
        rows, _ = run(harness, "full", ramp, 60, 1e-3, derivative=slope, name=label,
                      solver="arkode_erk", rtol=1e-4)
        tight, _ = run(harness, "full", ramp, 60, 1e-3, derivative=slope, name="t" + label,
                       **TIGHT)
        assert col(rows, "w_s")[-1] == pytest.approx(col(tight, "w_s")[-1], rel=2e-5)
        assert col(rows, "E_in")[-1] == pytest.approx(col(tight, "E_in")[-1], rel=1e-6)
        cost[label] = col(rows, "rhs_evals")[-1] - col(rows, "rhs_evals")[19]
    assert cost["held"] < 1.25 * cost["derivatives"]


def test_a_ramp_with_derivatives_continues_and_matches_the_tight_solution(harness):
    """T_s given as value and slope at each step (fmi2SetRealInputDerivatives): the right-hand
    side stays continuous and the integrator never restarts for it."""
    n, h = 200, 1e-3
    rows, _ = run(harness, "rigid", ramp, n, h, derivative=lambda t: 250.0)
    tight, _ = run(harness, "rigid", ramp, n, h, derivative=lambda t: 250.0, name="tight",
                   **TIGHT)
    for name in ("w_p", "E_in"):
        assert col(rows, name)[-1] == pytest.approx(col(tight, name)[-1], rel=2e-5), name
    assert col(rows, "E_friction")[-1] == pytest.approx(col(tight, "E_friction")[-1],
                                                        rel=FRICTION_REL)
    assert abs(audit_residual(rows[-1, AUDIT_COLS])) < 1e-6 * col(rows, "E_in")[-1]


@pytest.mark.parametrize("level", ["rigid", "full"])
def test_a_torque_step_restarts_and_keeps_its_accuracy(harness, level):
    """A ramp given with derivatives (the integrator continues through it), then a step of
    +200 N.m at 20 ms, which restarts it: the transient after it against the tight solution, at
    the defaults and with a finer absolute tolerance, whose error must be markedly smaller."""
    def torque(t):
        return 100.0 + 250.0 * t + (200.0 if t > 0.02 - 1e-12 else 0.0)

    def w_s_error(name, **tol):
        rows, _ = run(harness, level, torque, n, h, derivative=lambda t: 250.0, name=name, **tol)
        return rows, np.abs(col(rows, "w_s") - col(tight, "w_s")) / np.ptp(col(tight, "w_s")[19:])

    n, h = 40, 1e-3
    tight, _ = run(harness, level, torque, n, h, derivative=lambda t: 250.0, name="tight",
                   **TIGHT)
    rows, error = w_s_error("defaults")
    _, finer = w_s_error("finer", atol=1e-12)
    # The speeds' error follows atol (their tolerance is atol scaled by the highest mode's
    # frequency over R_p), hardly rtol: measured against the tight solution, full 1.8e-3 of the
    # swing at the defaults (1.5e-3 at rtol 1e-7, 9e-5 at atol 1e-12); rigid 1.3e-2 (2.3e-3 at
    # atol 1e-12), BDF's restart at order 1 after the step (before it 1e-5).
    assert error.max() < (2.5e-3 if level == "full" else 2e-2)
    assert finer.max() < 0.3 * error.max()
    assert col(rows, "E_in")[-1] == pytest.approx(col(tight, "E_in")[-1], rel=2e-5)
    assert abs(audit_residual(rows[-1, AUDIT_COLS])) < 1e-6 * col(rows, "E_in")[-1]


def test_held_inputs_pass_the_step_ends_at_the_map_level(harness):
    """The map level with its inputs held: 1 ms steps take a fraction of a solver step each and
    give eta_cycle within 0.01 %-point of the tight solution."""
    names = ["eta_cycle", "eta", "w_p", "E_in", "E_friction"]
    x = start(harness, "map")
    x.record(0.1, 1e-3, names)
    steps_0 = x.ints(["solver_steps"])[0]
    rows = x.record(0.5, 1e-3, names)
    steps_held = x.ints(["solver_steps"])[0] - steps_0  # after the start-up: 400 steps of 1 ms
    tight = start(harness, "map", "tight", **TIGHT).record(0.5, 1e-3, names)
    assert rows[-1, 0] < 1.0  # windows completed
    assert abs(rows[-1, 0] - tight[-1, 0]) < 1e-4
    assert rows[-1, 3] == pytest.approx(tight[-1, 3], rel=1e-5)
    assert steps_held < 0.1 * 400


def test_the_explicit_method_passes_held_step_ends(harness):
    """arkode_erk with its inputs held steps past the communication points and interpolates there,
    so its steps do not depend on the communication step: with the loaded tooth data (whose steps
    the error test sets, shorter than the step limit) 0.5 ms and 1 ms steps take the same solver
    steps over 0.1-0.3 s (both tile the limit to 1/6 ms). Stopping at each point cut a step short
    there and took 1.3x the steps at 0.5 ms. The interpolated DTE stays within 0.05 um of the
    tight solution at 1 ms (measured 0.01 um)."""
    names = ["DTE"]
    counts, dte = {}, {}
    for h in (0.5e-3, 1e-3):
        x = start(harness, "full", f"h{h}", tooth_data="loaded")
        x.record(0.1, h, names)
        steps_0 = x.ints(["solver_steps"])[0]
        dte[h] = x.record(0.3, h, names)[:, 0]
        counts[h] = x.ints(["solver_steps"])[0] - steps_0
    tight = start(harness, "full", "tight", tooth_data="loaded", rtol=1e-10, atol=1e-14)
    tight.record(0.1, 1e-3, names)
    ref = tight.record(0.3, 1e-3, names)[:, 0]
    assert counts[0.5e-3] == pytest.approx(counts[1e-3], rel=0.02)
    assert counts[1e-3] > 1.1 * 0.2 * 6000  # the error test, not the 1/6 ms limit, sets them
    assert np.max(np.abs(dte[1e-3] - ref)) < 0.05e-6


@pytest.mark.parametrize("level,derivative", [("map", None), ("rigid", 250.0)])
def test_state_round_trip_while_continuing_is_bit_identical(harness, level, derivative):
    """A state taken while the integrator passes step ends (held inputs) or continues through a
    ramp restores to the same bits."""
    x = start(harness, level)
    names = ["w_p", "DTE", "W_t", "P_loss", "eta", "E_in", "E_friction"]

    def go(k0, k1):
        out = []
        for k in range(k0, k1):
            if derivative is not None:
                x.set_unchecked(dict(T_s=100.0 + derivative * x.t))
                x.slave.setRealInputDerivatives([x.ref("T_s")], [1], [derivative])
            out.append(x.record(x.t + 1e-3, 1e-3, names)[0])
        return np.array(out)

    go(0, 60)
    state, t_state = x.slave.getFMUstate(), x.t
    first = go(60, 100)
    x.slave.setFMUstate(state)
    x.t = t_state
    second = go(60, 100)
    x.slave.freeFMUstate(state)
    assert np.array_equal(first, second)


def test_the_rigid_level_steps_over_the_input_shafts_mode_at_low_speed(harness):
    """The rigid level at 500 rpm, 100 N.m with its inputs held: BDF limited to order 2 steps over
    the lightly damped 1.7 kHz input-shaft mode it does not resolve (37 solver steps per mesh
    cycle from 0.2 s to 0.5 s; at orders up to 5 the order and step controller chased the mode:
    139) and gives eta_cycle within 0.01 %-point of its own tight solution (measured 4e-7)."""
    w = 500.0 * np.pi / 30.0
    names = ["eta_cycle", "w_p"]
    x = start(harness, "rigid", w_set=w, w_p0=w)
    x.record(0.2, 1e-3, names)
    steps_0 = x.ints(["solver_steps"])[0]
    rows = x.record(0.5, 1e-3, names)
    cycles = 0.3 * w / (2.0 * np.pi) * x.pinion_teeth()
    per_cycle = (x.ints(["solver_steps"])[0] - steps_0) / cycles
    tight = start(harness, "rigid", "tight", w_set=w, w_p0=w, **TIGHT).record(0.5, 1e-3, names)
    assert rows[-1, 0] < 1.0  # windows completed
    assert abs(rows[-1, 0] - tight[-1, 0]) < 1e-4
    assert per_cycle < 45
