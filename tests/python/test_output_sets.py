"""Outputs computed in sets, each when one of its outputs is read (variables.toml's
[output_sets], docs/architecture.md "How a value travels"): the pair outputs, every pair's
friction model solved directly, only when a pair output is read; the others as the right-hand
side computes them (through the friction table). Whatever a host reads when, each output it
reads has the bits it has when everything is read after every step; a restored state gives back
the outputs it had even after the friction table was built for other inputs. (A failed step
that built a table: tests/c/test_model.c, test_output_sets.)"""

import numpy as np
import pytest

from hypoid.fmu.levels import LEVELS
from hypoid.fmu.variables import VARIABLES

REALS = [n for n, v in VARIABLES.items() if v.causality == "output" and v.type == "Real"]
INTS = [n for n, v in VARIABLES.items() if v.causality == "output" and v.type != "Real"]
STATE_INTS = [n for n in INTS if n not in ("solver_steps", "rhs_evals")]  # the integrator's
# counters go on counting through a restored state
FEW = ["w_p", "DTE", "W_t", "P_loss", "eta", "eta_cycle"]  # what bench/bench_fmu.c reads
H = 1e-3


def start(harness, name, level="full", logging=False):
    x = harness(name=name, logging=logging)
    return x.start({k: x.enum_value(k, v) if isinstance(v, str) else v
                     for k, v in LEVELS[level].items()}, checked=False)


def read_all(x, ints=INTS):
    return np.array(list(x.reals(REALS)) + list(x.ints(ints)), dtype=float)


def tables_built(x):
    return sum("friction table built" in m[2] for m in x.messages)


@pytest.mark.parametrize("level", ["full", "rigid", "map"])
def test_outputs_read_now_and_then_are_those_read_every_step(harness, level):
    """One instance reads every output after every step; another the six usual ones after every
    step and everything after every seventh step only, or after a run of steps read not at all;
    a third reads the pairs alone now and then. Same bits at every step either read."""
    n = 40
    every = start(harness, "every", level)
    rows = []
    for _ in range(n):
        every.step(H)
        rows.append(read_all(every))
    some, pairs = start(harness, "some", level), start(harness, "pairs", level)
    pair_names = [r for r in REALS if r.startswith("pair[")]
    for k in range(n):
        some.step(H)
        pairs.step(H)
        if k < 20 or k % 3 == 0:
            assert np.array_equal(some.reals(FEW), rows[k][[REALS.index(r) for r in FEW]]), k
        if k % 7 == 6 or k == n - 1:
            assert np.array_equal(read_all(some), rows[k]), k
        if k % 5 == 4:
            assert np.array_equal(pairs.reals(pair_names),
                                  rows[k][[REALS.index(r) for r in pair_names]]), k
    assert np.array_equal(read_all(pairs), rows[-1])


def test_pair_outputs_are_the_direct_solve_and_the_main_ones_the_table(harness):
    """The two sets at one state agree within the friction table's error (its test bounds it at
    1.5e-3 of a pair's friction): P_loss (the table, as integrated into E_friction) against the
    pairs' mu W V_s (each pair's friction model solved); the split of P_loss adds up to it."""
    x = start(harness, "x")
    x.record(0.02, H, ["w_p"])
    for _ in range(8):
        x.step(H / 4)
        mu, W, V_s = (np.array(x.reals([f"pair[{k}].{q}" for k in (1, 2, 3)]))
                      for q in ("mu", "W", "V_s"))
        P_loss, visc, bound = x.reals(["P_loss", "P_loss_viscous", "P_loss_boundary"])
        assert np.sum(mu * W * V_s) == pytest.approx(P_loss, rel=1.5e-3)
        assert visc > 0.0 and bound > 0.0 and visc + bound == pytest.approx(P_loss, rel=1e-14)


def test_a_restored_state_gives_its_outputs_after_a_new_friction_table(harness):
    """A state taken at 20 ms, its outputs and the ten steps after it; then a warmer bath builds
    another friction table; the restored state reads the outputs it had (on the table it ran on,
    built again) and continues bit for bit as it did the first time."""
    x = start(harness, "x", logging=True)
    x.record(0.02, H, ["w_p"])
    state, t_state = x.slave.getFMUstate(), x.t

    def outputs_and_ten_steps():
        out = [read_all(x, STATE_INTS)]
        for _ in range(10):
            x.step(H)
            out.append(read_all(x, STATE_INTS))
        return np.array(out)

    first = outputs_and_ten_steps()
    built = tables_built(x)
    x.set_unchecked(dict(T_bath=x.get("T_bath") + 5.0))
    x.record(x.t + 5 * H, H, ["w_p"])
    assert tables_built(x) == built + 1  # the warmer bath's
    x.slave.setFMUstate(state)
    x.t = t_state
    x.slave.freeFMUstate(state)
    assert np.array_equal(read_all(x, STATE_INTS), first[0])
    assert tables_built(x) == built + 2  # the state's own again
    assert np.array_equal(outputs_and_ten_steps(), first)
