"""hypoid.drivecycle.interp.interp, the drive cycle's scalar lookup, gives numpy.interp's value
bit for bit: inside and at the nodes, at and beyond both ends, on repeated abscissae (a step), with
infinite values in the table, on one node, for NaN; and over every built-in cycle's trace."""

import math
import random

import numpy as np
import pytest

from hypoid.drivecycle import cycles
from hypoid.drivecycle.interp import interp

INF = math.inf


def same(a, b):
    return a == b or (math.isnan(a) and math.isnan(b))


@pytest.mark.parametrize("xp, fp", [
    ([0.0, 1.0, 3.0, 7.5], [2.0, -1.0, 0.3, 1e-300]),
    ([0.0, 1.0, 1.0, 2.0], [0.0, 5.0, -5.0, 1.0]),          # a step at x = 1
    ([0.0, 1.0, 2.0], [0.0, INF, 1.0]),                      # an infinite value
    ([0.0, 1.0, 2.0], [INF, INF, -INF]),
    ([0.0, 1e-300, 1.0], [1.0, 2.0, 3.0]),                   # a near-vertical slope
    ([4.0], [9.0]),                                          # one node
])
def test_as_numpy_interp(xp, fp):
    rng = random.Random(7)
    xs = xp + [x + d for x in xp for d in (-1e-12, 1e-12, 0.25)]
    xs += [rng.uniform(xp[0] - 1.0, xp[-1] + 1.0) for _ in range(2000)] + [-INF, INF, math.nan]
    for x in xs:
        assert same(interp(x, xp, fp), float(np.interp(x, xp, fp))), (x, xp, fp)


def test_every_built_in_cycle_as_numpy_interp():
    rng = random.Random(3)
    for name in cycles.BUILTIN:
        c = cycles.load_cycle(name)
        t_end = float(c.t[-1])
        for t in [rng.uniform(-2.0, t_end + 2.0) for _ in range(3000)] + [0.0, t_end]:
            assert c.speed(t) == float(np.interp(t, c.t, c.v)), (name, t)
