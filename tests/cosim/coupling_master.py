"""Fixed-step masters for the gear FMU and the vehicle FMU in either coupling, the coupling
matrix's scenes and its measures (docs/integration.md; bench/coupling_matrix.py runs the whole
matrix, tests/python/test_coupling.py a few of its cells).

Couplings (the connection a host makes):
  torque      gear load_mode = torque, vehicle coupling 1: the vehicle's half-shaft torque T_hs
              -> gear T_w, gear w_w -> vehicle w_w (the stiff half-shaft split across the
              interface, the small wheel-end inertia I_w on the gear's side)
  half_shaft  gear load_mode = half_shaft, vehicle coupling 3: the gear integrates the half-shaft
              (k_hs, c_hs) and gives its torque T_w_out -> vehicle T_wheel; the vehicle's wheel
              speed w_wheel (a state of its large inertia) -> gear w_wheel; the gear's I_vehicle
              the shipped vehicle's inertia at its wheels (its default m, r_dyn and J_wheels)

Masters, every input held over the communication step:
  jacobi        both FMUs step with the outputs of the step's start (libcosim, Ecos, the FMU
                containers' parallel scheduling, Simulink's FMU block)
  gauss-seidel  the gear steps first, the vehicle then with the gear's new outputs
  iterative     both step, are rolled back (FMU states) and step again with the other's outputs
                at the step's end, ITERATIONS times in all
"""

import math
import time
from dataclasses import dataclass, field

import numpy as np

ITERATIONS = 3
RPM = math.pi / 30.0
RATIO = 36.0 / 13.0
R_DYN = 0.3
I_VEHICLE = 1500.0 * R_DYN ** 2 + 3.0  # kg.m2: the shipped vehicle's m r_dyn^2 + J_wheels

GEAR_OUT = ["w_p", "w_w", "W_t", "T_w_out", "E_in", "E_out", "E_friction", "E_damping",
            "E_excitation", "E_stored"]
VEHICLE_OUT = ["T_hs", "w_wheel", "v", "P_in", "E_in", "E_kin", "E_spring", "E_road", "E_grade",
               "E_damper", "E_brake"]

COUPLINGS = {
    "torque": {"gear": {"load_mode": 1}, "vehicle": {"coupling": 1},
               # (from FMU, output, to FMU, input)
               "links": [("vehicle", "T_hs", "gear", "T_w"), ("gear", "w_w", "vehicle", "w_w")]},
    "half_shaft": {"gear": {"load_mode": 3, "I_vehicle": I_VEHICLE}, "vehicle": {"coupling": 3},
                   "links": [("gear", "T_wheel", "vehicle", "T_wheel"),
                             ("vehicle", "w_wheel", "gear", "w_wheel")]},
}
MASTERS = ("jacobi", "gauss-seidel", "iterative")


@dataclass
class Scene:
    """T_s piecewise linear through `profile` (s, N.m), held at its mean over each step; the
    gear at pinion speed w_p0_rpm, the vehicle at the matching speed on `grade` (rad)."""
    name: str
    stop_time: float
    profile: tuple
    w_p0_rpm: float
    grade: float = 0.0
    title: str = ""
    gear: dict = field(default_factory=dict)
    vehicle: dict = field(default_factory=dict)

    def torque(self, t):
        ts, vs = zip(*self.profile)
        return float(np.interp(t, ts, vs))

    def mean_torque(self, t, h):
        """T_s's mean over [t, t + h]: what the master holds over that step, so that every step
        size drives the gear with the profile's exact impulse."""
        ts, vs = zip(*self.profile)
        x = np.unique(np.concatenate([[t, t + h], [u for u in ts if t < u < t + h]]))
        return float(np.trapezoid(np.interp(x, ts, vs), x) / h)

    def flat(self, t, settle=0.05):
        """True where T_s has been constant for `settle` seconds (the windows in which the mesh
        force's spread is measured: no driver input, only what the coupling and the mesh make)."""
        return abs(self.torque(t) - self.torque(max(t - settle, 0.0))) < 1e-9 and t >= settle


def _grade_for(T_s, w_p_rpm):
    """The grade (rad) on which T_s holds the default vehicle at the speed of w_p_rpm."""
    v = R_DYN * w_p_rpm * RPM / RATIO
    road = 0.012 * 1500 * 9.81 + 0.5 * 1.2 * 0.7 * v * v
    return math.asin((T_s * RATIO / R_DYN - road) / (1500 * 9.81))


SCENES = {
    "cruise": Scene("cruise", 1.0, ((0.0, 100.0), (1.0, 100.0)), 2000.0,
                    _grade_for(100.0, 2000.0), "steady cruise, 2000 rpm, 100 N.m"),
    "tip": Scene("tip", 1.5, ((0.0, 0.0), (0.2, 150.0), (0.6, 150.0), (0.7, -50.0), (1.0, -50.0),
                              (1.1, 150.0), (1.5, 150.0)), 100.0, 0.0,
                 "tip-out / tip-in with backlash crossings, 100 rpm start"),
    "launch": Scene("launch", 1.0, ((0.0, 0.0), (0.3, 150.0), (1.0, 150.0)), 0.0, 0.0,
                    "launch from standstill, 0 -> 150 N.m"),
    "downhill": Scene("downhill", 1.0, ((0.0, -40.0), (1.0, -40.0)), 1500.0, -0.08,
                      "engine braking downhill, 1500 rpm, -40 N.m, 8 % grade"),
}


@dataclass
class Run:
    coupling: str
    master: str
    h: float
    scene: str
    t: np.ndarray = None
    T_s: np.ndarray = None
    gear: dict = None
    vehicle: dict = None
    cpu: float = 0.0
    failed: str = ""     # the FMU's error when a step failed


def _start_values(scene, coupling):
    c = COUPLINGS[coupling]
    T0 = scene.torque(0.0)
    gear = {**c["gear"], "w_p0": scene.w_p0_rpm * RPM, "T_s": T0}
    vehicle = {**c["vehicle"], "v0": R_DYN * scene.w_p0_rpm * RPM / RATIO, "grade": scene.grade}
    if coupling == "torque":  # the half-shaft preloaded by the start torque, T_w consistent
        gear["T_w"] = T0 * RATIO
        vehicle.update({"T_hs0": T0 * RATIO, "w_w": scene.w_p0_rpm * RPM / RATIO})
    gear.update(scene.gear)
    vehicle.update(scene.vehicle)
    return gear, vehicle


class _Side:
    def __init__(self, path, name, start, outputs):
        from hypoid.fmu.instance import Instance
        self.inst = Instance(path, name=name)
        self.fmu = self.inst.slave
        self.inst.set_many(start)
        self.out_names = outputs
        self.out_vr = [self.inst.ref(n) for n in outputs]

    def outputs(self):
        return dict(zip(self.out_names, self.fmu.getReal(self.out_vr)))

    def set(self, values):
        if values:
            self.fmu.setReal([self.inst.ref(n) for n in values], list(values.values()))

    def close(self):
        self.inst.close()


def run(scene, coupling, master, h, gear_fmu, vehicle_fmu, extra_gear_out=(), hold=None):
    """One cell of the matrix: the scene with this coupling and master at step h (fmpy). T_s is
    held at the profile's mean over each interval of length `hold` (default h): a reference at a
    fine step gets the driver's torque as the coarse run does, so that their difference is the
    coupling's alone."""
    hold = hold or h
    links = COUPLINGS[coupling]["links"]
    gs, vs = _start_values(scene, coupling)
    sides = {"gear": _Side(gear_fmu, "gear", gs, GEAR_OUT + list(extra_gear_out)),
             "vehicle": _Side(vehicle_fmu, "vehicle", vs, VEHICLE_OUT + [
                 l[1] for l in links if l[0] == "vehicle" and l[1] not in VEHICLE_OUT])}
    for l in links:
        if l[0] == "gear" and l[1] not in sides["gear"].out_names:
            sides["gear"].out_names.append(l[1])
            sides["gear"].out_vr.append(sides["gear"].inst.ref(l[1]))
    n = int(round(scene.stop_time / h))
    r = Run(coupling, master, h, scene.name, t=np.arange(n + 1) * h, T_s=np.empty(n + 1))

    def inputs_of(to, outs):
        return {inp: outs[src][out] for src, out, dst, inp in links if dst == to}

    rows, cpu = [], time.process_time()
    try:
        for s in sides.values():
            s.fmu.setupExperiment(startTime=0.0)
            s.fmu.enterInitializationMode()
        sides["gear"].set({"T_s": scene.torque(0.0)})
        outs = {k: s.outputs() for k, s in sides.items()}
        for _ in range(2):  # set inputs, get outputs, transfer (libcosim's initialization)
            for k, s in sides.items():
                s.set(inputs_of(k, outs))
            outs = {k: s.outputs() for k, s in sides.items()}
        for s in sides.values():
            s.fmu.exitInitializationMode()
        outs = {k: s.outputs() for k, s in sides.items()}
        rows = [outs]
        cpu = time.process_time()
        for k in range(n):
            tk = k * h
            t_hold = math.floor(tk / hold + 1e-9) * hold
            r.T_s[k] = scene.mean_torque(t_hold, hold)
            sides["gear"].set({"T_s": r.T_s[k]})
            outs = _step(sides, outs, master, tk, h, inputs_of)
            rows.append(outs)
        r.cpu = time.process_time() - cpu
    except Exception as e:  # FmuError, or fmpy's when the FMU lacks a function (FMU states)
        why = str(e).strip().splitlines()
        r.failed = f"t = {(len(rows) - 1) * h:.3f} s: " + (why[-1][:160] if why else type(e).__name__)
        r.cpu = time.process_time() - cpu
    finally:
        for s in sides.values():
            s.close()
    r.T_s[-1] = r.T_s[-2] if n > 0 else 0.0
    m = len(rows)
    r.t, r.T_s = r.t[:m], r.T_s[:m]
    r.gear = {name: np.array([row["gear"][name] for row in rows]) for name in sides["gear"].out_names}
    r.vehicle = {name: np.array([row["vehicle"][name] for row in rows])
                 for name in sides["vehicle"].out_names}
    return r


def _step(sides, outs, master, tk, h, inputs_of):
    g, v = sides["gear"], sides["vehicle"]
    if master == "jacobi":
        g.set(inputs_of("gear", outs))
        v.set(inputs_of("vehicle", outs))
        g.fmu.doStep(tk, h)
        v.fmu.doStep(tk, h)
        return {"gear": g.outputs(), "vehicle": v.outputs()}
    if master == "gauss-seidel":
        g.set(inputs_of("gear", outs))
        g.fmu.doStep(tk, h)
        new = {"gear": g.outputs(), "vehicle": outs["vehicle"]}
        v.set(inputs_of("vehicle", new))
        v.fmu.doStep(tk, h)
        new["vehicle"] = v.outputs()
        return new
    if master == "iterative":
        states = {k: s.fmu.getFMUstate() for k, s in sides.items()}
        guess = outs
        for it in range(ITERATIONS):
            if it:
                for k, s in sides.items():
                    s.fmu.setFMUstate(states[k])
            g.set(inputs_of("gear", guess))
            v.set(inputs_of("vehicle", guess))
            g.fmu.doStep(tk, h)
            v.fmu.doStep(tk, h)
            guess = {"gear": g.outputs(), "vehicle": v.outputs()}
        for k, s in sides.items():
            s.fmu.freeFMUstate(states[k])
        return guess
    raise ValueError(master)


# ------------------------------------------------------------------ measures


def energy(r):
    """The coupled system's energy residual over the run's rows and its scale (J): the work of T_s
    on the gear against what both FMUs dissipated and stored (docs/cosimulation.md, "Energy"),
    each a change from the first row (the FMUs count from their start: a run whose rows start at
    t = h, libcosim's, is measured over its own span)."""
    g, v = ({k: x[-1] - x[0] for k, x in side.items()} for side in (r.gear, r.vehicle))
    w_ts = g["E_in"]
    gear = g["E_friction"] + g["E_damping"] - g["E_excitation"] + g["E_stored"]
    veh = v["E_kin"] + v["E_spring"] + v["E_road"] + v["E_grade"] + v["E_damper"] + v["E_brake"]
    # the input work: what T_s did plus what the grade gave back (engine braking downhill)
    scale = abs(w_ts) + max(-v["E_grade"], 0.0)
    return w_ts - gear - veh, scale


def _spread(x, mask):
    """The pooled standard deviation of x about its own mean in each run of True in mask (each
    flat window): the oscillation, not the windows' different levels."""
    edges = np.flatnonzero(np.diff(np.concatenate([[0], mask.astype(int), [0]])))
    parts = [x[a:b] - np.mean(x[a:b]) for a, b in zip(edges[::2], edges[1::2])]
    return float(np.sqrt(np.mean(np.concatenate(parts) ** 2))) if parts else 0.0


def measures(r, ref, scene):
    """Per run against the reference: mesh-force spread in the flat windows (W_t's standard
    deviation about each window's mean at the run's communication points, over the reference's
    at the same instants), largest w_p error over
    max |w_p| of the reference (and its RMS over the reference's), energy residual over the input work, CPU."""
    out = {"coupling": r.coupling, "master": r.master, "h": r.h, "scene": r.scene,
           "cpu": r.cpu, "failed": r.failed}
    if r.failed:
        out.update(stable=False, std_ratio=math.inf, w_p_err=math.inf, w_p_rms=math.inf,
                   energy=math.inf)
        return out
    at = np.rint(r.t / ref.h).astype(int)  # the reference's rows at the run's instants
    ref_W, ref_wp = ref.gear["W_t"][at], ref.gear["w_p"][at]
    mask = np.array([scene.flat(t) for t in r.t])
    s_run, s_ref = _spread(r.gear["W_t"], mask), _spread(ref_W, mask)
    # a floor for the reference's spread: 1 % of its mean force (a steady run's ripple)
    s_ref = max(s_ref, 0.01 * float(np.mean(np.abs(ref_W[mask]))), 1.0)
    res, scale = energy(r)
    out.update(std_ratio=s_run / s_ref, std_W=s_run, std_W_ref=s_ref,
               w_p_err=float(np.max(np.abs(r.gear["w_p"] - ref_wp))
                             / max(float(np.max(np.abs(ref_wp))), 1.0)),
               w_p_rms=float(np.sqrt(np.mean((r.gear["w_p"] - ref_wp) ** 2)
                                     / max(float(np.mean(ref_wp ** 2)), 1.0))),
               energy=res / scale if scale > 0 else 0.0)
    out["stable"] = out["std_ratio"] <= 1.5
    return out


def run_host(Execution, scene, coupling, h, gear_fmu, vehicle_fmu):
    """The scene in a host's fixed-step (Jacobi) algorithm: `Execution` is the driver's class
    (hypoid.cosim.libcosim.Execution or hypoid.cosim.ecos.Execution, which take the same calls),
    gear_fmu the integer-coded gear FMU (<name>_intenum.fmu: neither host sets Enumerations), the
    links of the coupling its connections, T_s set before each step at the profile's mean over
    it. Rows as run()'s from t = 0 where the host has outputs after its initialisation
    (Execution.outputs_at_start: Ecos); libcosim initialises inside the first step, so its Run
    starts at t = h. A step that the host or an FMU refused ends the run (Run.failed)."""
    ex = Execution(h)
    try:
        ex.add("gear", gear_fmu)
        ex.add("vehicle", vehicle_fmu)
        gs, vs = _start_values(scene, coupling)
        ex.initial("gear", gs)
        ex.initial("vehicle", vs)
        links = COUPLINGS[coupling]["links"]
        for src, out, dst, inp in links:
            ex.connect(src, out, dst, inp)
        names = {side: outs + [l[1] for l in links if l[0] == side and l[1] not in outs]
                 for side, outs in (("gear", GEAR_OUT), ("vehicle", VEHICLE_OUT))}
        refs = {side: [ex.ref(side, v) for v in names[side]] for side in names}
        n, first = int(round(scene.stop_time / h)), 0 if ex.outputs_at_start else 1
        r = Run(coupling, "jacobi", h, scene.name)
        rows, T_s = [], []

        def read():
            rows.append({side: list(ex.reals(side, refs[side])) for side in refs})

        if first == 0:
            read()
        cpu = time.process_time()
        try:
            for k in range(n):
                T_s.append(scene.mean_torque(k * h, h))
                ex.set_reals("gear", ["T_s"], [T_s[-1]])
                ex.step()
                read()
        except RuntimeError as e:
            r.failed = f"step {k * h:.3f}-{(k + 1) * h:.3f} s: {str(e)[:160]}"
        r.cpu = time.process_time() - cpu
    finally:
        ex.close()
    r.t = (np.arange(len(rows)) + first) * h
    r.T_s = np.array((T_s + T_s[-1:])[:len(rows)])  # T_s[k]: held over step k
    r.gear, r.vehicle = ({v: np.array([row[side][j] for row in rows])
                          for j, v in enumerate(names[side])} for side in ("gear", "vehicle"))
    return r


def run_libcosim(scene, coupling, h, gear_fmu, vehicle_fmu):
    """run_host in libcosim (libcosimpy)."""
    from hypoid.cosim.libcosim import Execution
    return run_host(Execution, scene, coupling, h, gear_fmu, vehicle_fmu)


def run_ecos(scene, coupling, h, gear_fmu, vehicle_fmu):
    """run_host in Ecos (ecospy)."""
    from hypoid.cosim.ecos import Execution
    return run_host(Execution, scene, coupling, h, gear_fmu, vehicle_fmu)
