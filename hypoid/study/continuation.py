"""Continuation sweeps for the jump phenomenon: one FMU run goes up through a list of pinion
speeds and back down, ramping w_set slowly between them and carrying the state over, so the
response stays on whichever branch it is on; at each speed it settles and records a window."""

import time

from hypoid.study import steady
from hypoid.fmu.instance import RPM, SPEED_KEY


def speed_path(speeds):
    """[(speed, branch), ...]: up through the sorted speeds, then down again (the top speed is
    recorded once on each branch, the second time after a further settling)."""
    up = sorted(speeds)
    return [(s, "up") for s in up] + [(s, "down") for s in reversed(up)]


def ramp(sampler, w_from, w_to, ramp_time):
    """Moves w_set linearly from w_from to w_to over about ramp_time seconds."""
    if w_from == w_to or ramp_time <= 0:
        sampler.inst.set("w_set", w_to)
        return
    h = sampler.mesh_step(min(w_from, w_to))  # the finer of the two sampling steps
    n = max(1, int(round(ramp_time / h)))
    sampler.sample(n, h, w_ramp=(w_from, w_to), brief=True)


def run_sweep(inst, params, speeds, settings=steady.Settings(), ramp_time=0.1):
    """Up-then-down continuation from a fresh start at the lowest speed; returns one row per
    (speed, branch) with the steady-state figures and `branch`, `order` columns."""
    path = speed_path(speeds)
    cpu0 = time.process_time()
    start = {k: v for k, v in params.items() if k != SPEED_KEY}
    start[SPEED_KEY] = path[0][0]
    inst.start(start)
    sampler = steady.Sampler(inst, settings, cpu0)
    constants = steady.model_constants(inst)
    rows, w_prev = [], path[0][0] * RPM
    for order, (speed, branch) in enumerate(path):
        cpu_point = time.process_time()
        w = speed * RPM
        ramp(sampler, w_prev, w, ramp_time)
        info = steady.settle(sampler, w)
        window = steady.record(sampler, w)
        row = {SPEED_KEY: speed, "branch": branch, "order": order, **info,
               **steady.window_row(inst, sampler, window, w), **constants,
               "cpu_s": time.process_time() - cpu_point}
        rows.append(row)
        w_prev = w
    return rows
