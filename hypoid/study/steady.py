"""Steady-state operating points: run the FMU in load_mode = speed from w_p0 = w_set, step it
with a fixed number of samples per mesh cycle, wait until the transient has decayed (block-to-
block change of the mean efficiency, the DTE peak-to-peak and the mean speed below tolerances
for consecutive blocks of mesh cycles, or a time limit), then record a window of mesh cycles."""

import math
import time
from dataclasses import asdict, dataclass

import numpy as np

from hypoid.fmu.instance import RPM, SPEED_KEY
from hypoid.fmu.parallel import PointTimeout
from hypoid.study import metrics


@dataclass(frozen=True)
class Settings:
    samples_per_cycle: int = 32  # communication steps per mesh cycle (docs/physics.md §9.2: >= 32)
    window_cycles: int = 50  # mesh cycles recorded after the transient (the paper's window)
    block_cycles: int = 10  # mesh cycles per settling block
    min_settle_cycles: int = 30  # settle at least this long
    max_settle_time: float = 1.0  # s of simulated settling before giving up (converged = False)
    tol_eta: float = 1e-5  # block-to-block change of the mean efficiency
    tol_dte_rel: float = 0.01  # ... of the DTE peak-to-peak, relative
    tol_dte_abs: float = 0.1e-6  # ... plus this absolute allowance [m]
    tol_speed_rel: float = 1e-3  # block mean pinion speed vs w_set
    stable_blocks: int = 2  # consecutive blocks that must pass
    max_cpu: float = 300.0  # CPU seconds per point before it is abandoned (status = timeout)

    def as_dict(self):
        return asdict(self)


class Sampler:
    """Steps an initialised instance and samples metrics.REALS and metrics.INTEGERS, or only
    metrics.BRIEF (brief=True: the settling test's and the mesh angle's; the FMU computes an
    output only when it is read, and the tooth pairs' outputs each solve their contacts)."""

    def __init__(self, inst, settings, cpu_start=None):
        self.inst = inst
        self.settings = settings
        self.t = 0.0
        self.io = inst.fast_io(metrics.REALS, metrics.INTEGERS, inputs=("w_set",))
        self.io_brief = inst.fast_io(metrics.BRIEF, inputs=("w_set",))
        self.cpu_start = time.process_time() if cpu_start is None else cpu_start
        self.theta = 0.0  # mesh angle N_p * integral of w_p dt since t = 0 (phi_p(0) = 0)
        self.n_p = inst.pinion_teeth()

    def mesh_step(self, w_set):
        """Communication step for the pinion speed w_set [rad/s]."""
        return 2.0 * math.pi / (self.n_p * w_set) / self.settings.samples_per_cycle

    def sample(self, n, h, w_ramp=None, brief=False):
        """n steps of size h; w_ramp = (w_from, w_to) ramps w_set linearly over the n steps."""
        io = self.io_brief if brief else self.io
        names = metrics.BRIEF if brief else metrics.REALS
        reals = np.empty((n, io.n_real))
        ints = np.empty((n, io.n_int), dtype=np.int32)
        times = np.empty(n)
        inputs = None if w_ramp is None else [
            [w_ramp[0] + (w_ramp[1] - w_ramp[0]) * (i + 1) / n] for i in range(n)]
        self.t = io.run(self.t, h, reals, ints, times, inputs)
        # the mesh angle by the rectangle rule (drift << one mesh cycle), summed in step order
        j_w = names.index("w_p")
        theta = np.add.accumulate(np.concatenate(([self.theta], self.n_p * reals[:, j_w] * h)))
        self.theta = float(theta[-1])
        if time.process_time() - self.cpu_start > self.settings.max_cpu:
            raise PointTimeout(f"more than {self.settings.max_cpu:g} s CPU at t = {self.t:.4f} s")
        out = {name: reals[:, j] for j, name in enumerate(names)}
        if not brief:
            out.update({name: ints[:, j].astype(np.int64)
                        for j, name in enumerate(metrics.INTEGERS)})
        out["time"] = times
        out["theta"] = theta[1:]
        return out


def settle(sampler, w_set):
    """Runs blocks of mesh cycles until steady; returns the settling diagnostics."""
    st = sampler.settings
    h = sampler.mesh_step(w_set)
    n_block = st.block_cycles * st.samples_per_cycle
    t0, prev, passed, blocks = sampler.t, None, 0, 0
    d_eta = d_dte = float("nan")
    while True:
        b = metrics.block_stats(sampler.sample(n_block, h, brief=True))
        blocks += 1
        if prev is not None:
            d_eta = abs(b["eta"] - prev["eta"])
            d_dte = abs(b["dte_pp"] - prev["dte_pp"])
            ok = (d_eta <= st.tol_eta
                  and d_dte <= st.tol_dte_rel * b["dte_pp"] + st.tol_dte_abs
                  and abs(b["w"] - w_set) <= st.tol_speed_rel * w_set)
            passed = passed + 1 if ok else 0
        prev = b
        enough = blocks * st.block_cycles >= st.min_settle_cycles
        if enough and passed >= st.stable_blocks:
            converged = True
            break
        if sampler.t - t0 >= st.max_settle_time:
            converged = False
            break
    return {"converged": converged, "settle_time_s": sampler.t - t0, "settle_blocks": blocks,
            "settle_d_eta": d_eta, "settle_d_dte_um": d_dte * 1e6}


def record(sampler, w_set):
    """Samples the steady-state window; returns the window's signals."""
    st = sampler.settings
    return sampler.sample(st.window_cycles * st.samples_per_cycle, sampler.mesh_step(w_set))


def half_backlash(inst):
    """The backlash the dynamics uses: b, or 0 with mesh_model = mean (no backlash there)."""
    varying = inst.get("mesh_model") == inst.enum_value("mesh_model", "varying")
    return inst.get("b") if varying else 0.0


def model_constants(inst):
    """Per-point constants worth keeping with every row (modal frequencies, tooth count...)."""
    n_p = inst.pinion_teeth()
    row = {name: inst.get(name) for name in ("f_2", "f_3", "f_4", "ratio", "k_m0", "R_p0",
                                             "c_t1", "c_m", "c_t2")}
    row["N_p"] = n_p
    row["b_um"] = half_backlash(inst) * 1e6
    for k in (2, 3):
        row[f"n_f{k}_rpm"] = 60.0 * row[f"f_{k}"] / n_p
    return row


def whole_axle(inst):
    """True when the instance runs the axle's whole ledger (axle_losses = full)."""
    return inst.get("axle_losses") == inst.enum_value("axle_losses", "full")


def window_row(inst, sampler, window, w_set):
    """The metrics of a window plus counters and constants."""
    row = metrics.window_metrics(window, half_backlash(inst), axle=whole_axle(inst))
    row["speed_set_rpm"] = w_set / RPM
    row["sim_time_s"] = sampler.t
    row["solver_steps"] = inst.get("solver_steps")
    row["rhs_evals"] = inst.get("rhs_evals")
    return row


def run_point(inst, params, settings=Settings(), trace=False):
    """One operating point from a fresh start; returns (row, trace or None)."""
    cpu0 = time.process_time()
    inst.start(params)
    w_set = params[SPEED_KEY] * RPM if SPEED_KEY in params else inst.get("w_set")
    sampler = Sampler(inst, settings, cpu0)
    info = settle(sampler, w_set)
    window = record(sampler, w_set)
    row = {**info, **window_row(inst, sampler, window, w_set), **model_constants(inst)}
    row["cpu_s"] = time.process_time() - cpu0
    return row, (window if trace else None)
