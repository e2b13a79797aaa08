"""Reference for the mesh force law of the loaded tooth data (docs/physics.md §10.8, "In the FMU").

The loaded contact of hypoid.tca.loaded gives, at every mesh angle θ, the normal load W that the
teeth carry at a mesh approach a = δ − e_u beyond first touch: W(a, θ), tabulated here finely in a
and θ. An elastic contact follows this law at once (its footprint settles with the elastic waves,
in microseconds, against mesh periods of milliseconds), so the reference integrates the paper's
4-DoF torsional model (docs/physics.md §8.1, frictionless, both ends torque-driven) with the
mesh force W(x − b, θ) itself. The same model runs with the force laws an FMU can hold:

    secant    W = k_s(θ; T_km) (x − b),  k_s = W_l/(δ_l − e_u): the FMU's former law
    tangent   W = k_t(θ; T_km) (x − b − Δ),  Δ = δ_l − e_u − W_l/k_t: linearised about each
              level's static state, contact where the tangent line crosses zero
    powerlaw  W instantaneous between the levels' static points (a_l, W_l) = (W_l/k_s, W_l),
              W = W_l (a/a_l)^p_l with p_l = ln(W_(l+1)/W_l)/ln(a_(l+1)/a_l) (the FMU's law,
              fmu-src/mesh/mesh_law.c)

T_km is the transmitted torque filtered over three mesh periods, as in the FMU. Everything else
(R_p(θ) and e_0(θ) of the gear-set file's level, the dampers, the inertias and shaft
stiffnesses of Table 3) is the same for all laws; the dampers are passed in (the FMU computes
them from its own k_m0, so they differ between data; compare like with like).

    python tools/mesh_law_reference.py point --speed 2000 --torque 100 [--law reference ...]
    python tools/mesh_law_reference.py sweep --torque 100 --speeds 1000 3400 45
    python tools/mesh_law_reference.py static --torque 100
    python tools/mesh_law_reference.py record [--fmu build/HypoidGearPair.fmu]

`record` runs the comparison of the record docs/records/mesh-law (the reference, the filtered
secant and the tangent law here, and the FMU itself through fmpy with the same file,
frictionless and torque-driven at both ends, with the dampers the FMU computes, at
1000-3400 rpm x 50 and 100 N·m), keeps it in its data, mesh-law.json, and writes its page.

Classical RK4 with a fixed step (--dt, 10 µs agrees with DOP853 at rtol 1e-8 within 0.2 %),
all speeds of a sweep at once; the last 0.1 s of --t-end are analysed. Needs scipy (PCHIP);
prints one line per run. Lengths in m, forces in N, angles in rad.
"""

import argparse
import datetime
import json
import math
import pathlib
import sys

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from hypoid.records import docblocks  # noqa: E402
from hypoid.records.registry import FOLDER, RECORDS  # noqa: E402
from hypoid.tca import gearsets as tca
from hypoid.tca import loaded as tl  # noqa: E402
from hypoid.tca import surrogate as sur  # noqa: E402
from hypoid.tca.gearset_file import read_gearset  # noqa: E402

TABLE3 = {"I_s": 0.014, "I_p": 0.014, "I_g": 0.29, "I_w": 0.29, "k_t1": 8e5, "k_t2": 8e5}
B_HALF = 70e-6  # half backlash [m]
N_THETA = 256  # mesh angles of a cycle in the tables
TORQUE_GRID = np.concatenate(([0.05], np.geomspace(0.2, 1200.0, 60)))  # [N·m] for W(a, θ)
FILTER_CYCLES = 3.0
RECORD = FOLDER / "mesh-law.json"
RECORD_TORQUES = (100.0, 50.0)  # [N·m] pinion torques of the comparison
RECORD_SPEEDS = (1000.0, 3400.0, 25)  # [rpm] first, last, count (100 rpm steps)
RECORD_LAWS = ("reference", "secant", "tangent")  # the Python models; "fmu" is the FMU itself


def periodic_table(values):
    """Samples at 2π k/n along the last axis, the first repeated at the end (for lookups)."""
    v = np.asarray(values, dtype=float)
    return np.concatenate((v, v[..., :1]), axis=-1)


def lookup(table, theta):
    """Linear interpolation of periodic_table rows at mesh angles θ (array)."""
    n = table.shape[-1] - 1
    s = np.mod(theta, 2.0 * math.pi) * (n / (2.0 * math.pi))
    i = np.minimum(s.astype(int), n - 1)
    t = s - i
    return table[..., i] + t * (table[..., i + 1] - table[..., i])


class ContactTable:
    """W(a, θ) of the loaded contact of one flank: a uniform grid of approaches a beyond first
    touch at N_THETA mesh angles; per θ a monotone cubic (PCHIP) through the solved points
    (δ(T) − e_u, T/R_p0) with W = 0 at a ≤ 0, continued beyond the last point with its slope."""

    def __init__(self, blank_no=1, flank="drive", n_a=3000):
        from scipy.interpolate import PchipInterpolator
        fl = tl.LoadedFlank(tl.flank_set(sur.TABLE_1[blank_no], flank))
        meshes = [tl.loaded_mesh(fl, T, N_THETA) for T in TORQUE_GRID]
        a = np.array([m.delta - m.e_u for m in meshes])  # (nT, nθ)
        W = np.array([m.W for m in meshes])
        self.a_max = a[-1].min()
        self.da = self.a_max / (n_a - 1)
        grid = np.arange(n_a) * self.da
        W_grid, slope = np.empty((N_THETA, n_a)), np.empty(N_THETA)
        for i in range(N_THETA):
            p = PchipInterpolator(np.concatenate(([0.0], a[:, i])), np.concatenate(([0.0], W)))
            W_grid[i], slope[i] = p(grid), p.derivative()(grid[-1])
        self.W = np.concatenate((W_grid, W_grid[:1]))  # (nθ + 1, n_a)
        self.slope_end = np.concatenate((slope, slope[:1]))
        self.n_a = n_a

    def force(self, a, theta):
        """W [N] at approaches a [m] and mesh angles θ (arrays; bilinear in the table)."""
        a, theta = np.broadcast_arrays(np.asarray(a, float), np.asarray(theta, float))
        s = np.mod(theta, 2.0 * math.pi) * (N_THETA / (2.0 * math.pi))
        i = np.minimum(s.astype(int), N_THETA - 1)
        t = s - i
        u = np.clip(a, 0.0, self.a_max) / self.da
        j = np.minimum(u.astype(int), self.n_a - 2)
        r = u - j
        W0 = self.W[i, j] + r * (self.W[i, j + 1] - self.W[i, j])
        W1 = self.W[i + 1, j] + r * (self.W[i + 1, j + 1] - self.W[i + 1, j])
        extra = np.maximum(a - self.a_max, 0.0)
        W0 = W0 + self.slope_end[i] * extra
        W1 = W1 + self.slope_end[i + 1] * extra
        return np.where(a > 0.0, W0 + t * (W1 - W0), 0.0)


class Levels:
    """Per-level series of one flank: from the gear-set file (k_s, R_p, e_0 as the FMU reads
    them) and from the loaded contact (k_t, the tangent's offset Δ) at N_THETA mesh angles."""

    def __init__(self, path, blank_no=1, flank="drive", e_0_scale=1.0):
        gs = read_gearset(path)
        theta = 2.0 * math.pi * np.arange(N_THETA) / N_THETA
        self.T = np.array(gs.torque_levels)
        lay = [gs.layers[(flank, l + 1)] for l in range(len(self.T))]
        self.k_s = periodic_table([s["k_m"](theta) for s in lay])
        self.R_p = periodic_table([s["R_p"](theta) for s in lay])
        e0 = gs.series["e_0"]
        i = np.arange(1, len(e0.sin) + 1)
        arg = np.multiply.outer(theta, i)
        self.de_0 = e_0_scale * periodic_table(np.cos(arg) @ (e0.sin * i) - np.sin(arg) @ (e0.cos * i))
        fl = tl.LoadedFlank(tl.flank_set(sur.TABLE_1[blank_no], flank))
        self.R_p0 = fl.gs.R_p0
        meshes = [tca.level_mesh(fl, T, N_THETA)[0] for T in self.T]  # the levels' loads
        self.k_t = periodic_table([m.k_t for m in meshes])
        self.offset = periodic_table([m.delta - m.e_u - m.W / m.k_t for m in meshes])
        self.W_l = np.array([m.W for m in meshes])

    def blend(self, table, T, theta):
        """Rows of a per-level table blended linearly on the pinion torques T at θ (arrays),
        held beyond the first and last level (the FMU's hg_gearset_level_at)."""
        n = len(self.T)
        hi = np.clip(np.searchsorted(self.T, T), 1, n - 1)
        lo = hi - 1
        w = np.clip((T - self.T[lo]) / (self.T[hi] - self.T[lo]), 0.0, 1.0)
        v = lookup(table, theta)  # (L, S)
        cols = np.arange(np.size(theta))
        return (1.0 - w) * v[lo, cols] + w * v[hi, cols]


# --- force laws: W(a = x − b, θ, T_km), arrays -------------------------------------------------

def law_reference(table):
    return lambda a, theta, T, lev: table.force(a, theta)


def law_secant(a, theta, T, lev):
    return np.where(a > 0.0, lev.blend(lev.k_s, T, theta) * a, 0.0)


def law_tangent(a, theta, T, lev):
    d = a - lev.blend(lev.offset, T, theta)
    return np.where(d > 0.0, lev.blend(lev.k_t, T, theta) * d, 0.0)


def law_powerlaw(a, theta, T, lev):
    """The levels' static points (a_l, W_l), a_l = W_l/k_s,l(θ), joined by power laws
    W = W_l (a/a_l)^p_l; the first segment's law continues down to a = 0, the last point's
    tangent beyond the last."""
    W_l = lev.W_l[:, None]
    a_l = W_l / lookup(lev.k_s, theta)  # (L, S)
    n = len(lev.W_l)
    l = np.clip(np.sum(a[None, :] >= a_l[1:-1], axis=0), 0, n - 2)
    cols = np.arange(np.size(a))
    a0, a1 = a_l[l, cols], a_l[l + 1, cols]
    W0, W1 = lev.W_l[l], lev.W_l[l + 1]
    p = np.log(W1 / W0) / np.log(a1 / a0)
    pos = np.maximum(a, 1e-30)
    W = W0 * (pos / a0) ** p
    beyond = W1 * (1.0 + p * (pos / a1 - 1.0))
    W = np.where(a > a_l[-1], beyond, W)
    return np.where(a > 0.0, W, 0.0)


LAWS = ("reference", "secant", "tangent", "powerlaw")


# --- the 4-DoF model (docs/physics.md §8.1, frictionless, torque at both ends) ----------------

def simulate(law, lev, speeds_rpm, torque, dampers, t_end=0.3, t_keep=0.1, dt=5e-6,
             N_p=13, N_g=36):
    """Integrates the model at several pinion speeds at once (classical RK4, step dt [s]);
    returns the DTE x [m] and the contact flags over the last t_keep, shape (steps, speeds)."""
    P = TABLE3
    ratio = N_g / N_p
    c_t1, c_m, c_t2 = dampers
    w_p0 = np.asarray(speeds_rpm, float) * math.pi / 30.0
    T_w = torque * ratio

    def rhs(y):
        theta = N_p * y[2]
        R_p = lev.blend(lev.R_p, y[8], theta)
        R_g = R_p * ratio
        xdot = R_p * y[5] - R_g * y[6] - lookup(lev.de_0, theta) * N_p * y[5]
        a = y[3] - B_HALF
        W = law(a, theta, y[8], lev) + np.where(a > 0.0, c_m * xdot, 0.0)
        T_1 = P["k_t1"] * y[0] + c_t1 * (y[4] - y[5])
        T_2 = P["k_t2"] * y[1] + c_t2 * (y[6] - y[7])
        tau = FILTER_CYCLES * 2.0 * math.pi / (N_p * np.maximum(np.abs(y[5]), 1.0))
        return np.array([y[4] - y[5], y[6] - y[7], y[5], xdot,
                         (torque - T_1) / P["I_s"], (T_1 - R_p * W) / P["I_p"],
                         (R_g * W - T_2) / P["I_g"], (T_2 - T_w) / P["I_w"],
                         (np.abs(W) * R_p - y[8]) / tau]), a > 0.0

    S = len(w_p0)
    T0 = np.full(S, float(torque))
    R_p = lev.blend(lev.R_p, T0, np.zeros(S))
    W0 = torque / R_p
    x0 = B_HALF + static_approach(law, lev, W0, T0)
    y = np.array([np.full(S, torque / P["k_t1"]), W0 * R_p * ratio / P["k_t2"], np.zeros(S), x0,
                  w_p0, w_p0, w_p0 / ratio, w_p0 / ratio, T0])
    n_steps, n_keep = int(round(t_end / dt)), int(round(t_keep / dt))
    xs, cs = [], []
    for k in range(n_steps):
        k1, c = rhs(y)
        k2, _ = rhs(y + 0.5 * dt * k1)
        k3, _ = rhs(y + 0.5 * dt * k2)
        k4, _ = rhs(y + dt * k3)
        y = y + dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4)
        if k >= n_steps - n_keep:
            xs.append(y[3].copy())
            cs.append(c)
    return np.array(xs), np.array(cs)


def static_approach(law, lev, W, T, theta=None):
    """The approaches a at which law carries the loads W at θ (default 0; bisection)."""
    theta = np.zeros(np.size(W)) if theta is None else theta
    lo, hi = np.zeros(np.size(W)), np.full(np.size(W), 1e-3)
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        low = law(mid, theta, T, lev) < W
        lo, hi = np.where(low, mid, lo), np.where(low, hi, mid)
    return 0.5 * (lo + hi)


def make_law(name, table):
    return {"reference": law_reference(table) if table else None, "secant": law_secant,
            "tangent": law_tangent, "powerlaw": law_powerlaw}[name]


# --- the recorded comparison of physics.md §10.8 ------------------------------------------------

def dte_stats(x, contact):
    """DTE peak to peak, its mean and minimum beyond the half backlash [µm] and the fraction of
    the time the teeth are apart, of one run's last part."""
    return {"pp_um": float(np.ptp(x)) * 1e6, "mean_minus_b_um": (float(np.mean(x)) - B_HALF) * 1e6,
            "min_minus_b_um": (float(np.min(x)) - B_HALF) * 1e6,
            "apart": 1.0 - float(np.mean(contact))}


def fmu_start(torque, rpm, path):
    """The FMU's start values of the comparison: the file, no friction, torque at both ends."""
    return {"gear_set_file": str(path), "friction_model": "none", "load_mode": "torque",
            "T_s": torque, "T_w": torque * 36.0 / 13.0, "speed_rpm": rpm}


def fmu_sweep(fmu, path, torque, speeds, t_end=0.3, t_keep=0.1, h=1e-5):
    """The FMU at each speed (steps of h, the last t_keep analysed), and what it computed at the
    start: its dampers and the modal k_m0 and f_3."""
    from hypoid.fmu.instance import Instance

    with Instance(fmu, name="mesh_law_reference") as gear:
        gear.start(fmu_start(torque, speeds[0], path))
        setup = {k: gear.get(k) for k in ("c_t1", "c_m", "c_t2", "k_m0", "f_3")}
        runs = []
        for n in speeds:
            gear.start(fmu_start(torque, n, path))
            r = gear.series(t_end, h, ["DTE", "contact"])
            late = r["time"] > t_end - t_keep + 1e-9
            runs.append(dte_stats(r["DTE"][late], r["contact"][late] == 1))
    return setup, runs


def record(fmu, path):
    """Runs the comparison at RECORD_TORQUES x RECORD_SPEEDS; returns the record."""
    speeds = [float(n) for n in np.linspace(*RECORD_SPEEDS[:2], int(RECORD_SPEEDS[2]))]
    lev, table = Levels(path), ContactTable()
    out = {"file": str(pathlib.Path(path).resolve().relative_to(ROOT)), "speeds": speeds,
           "recorded": datetime.date.today().isoformat(), "commit": docblocks.commit(ROOT),
           "torques": {}}
    for torque in RECORD_TORQUES:
        setup, fmu_runs = fmu_sweep(fmu, path, torque, speeds)
        level = list(lev.T).index(torque)
        rec = {"fmu_setup": setup, "runs": {"fmu": fmu_runs},
               "k_t_contact": float(lev.k_t[level, :-1].mean()),
               "k_m_secant": float(lev.k_s[level, :-1].mean())}
        dampers = (setup["c_t1"], setup["c_m"], setup["c_t2"])
        for name in RECORD_LAWS:
            x, contact = simulate(make_law(name, table), lev, speeds, torque, dampers)
            rec["runs"][name] = [dte_stats(x[:, i], contact[:, i]) for i in range(len(speeds))]
            print(f"mesh_law_reference: {name} at {torque:g} N.m done", flush=True)
        out["torques"][f"{torque:g}"] = rec
    return out



def main(argv=None):
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("command", choices=("point", "sweep", "static", "record"))
    p.add_argument("--file", default=str(ROOT / "resources/gearsets/loaded/gearset1.txt"))
    p.add_argument("--law", nargs="+", default=list(LAWS), choices=LAWS)
    p.add_argument("--speed", type=float, default=2000.0)
    p.add_argument("--torque", type=float, default=100.0)
    p.add_argument("--speeds", type=float, nargs=3, default=(1000.0, 3400.0, 25))
    p.add_argument("--dampers", type=float, nargs=3, default=(3.458, 8519.7, 12.666),
                   help="c_t1 [N m s/rad], c_m [N s/m], c_t2 [N m s/rad]")
    p.add_argument("--e-0-scale", type=float, default=1.0, help="as the FMU's e_0_scale")
    p.add_argument("--t-end", type=float, default=0.3)
    p.add_argument("--dt", type=float, default=5e-6, help="RK4 step [s]")
    p.add_argument("--fmu", default=str(ROOT / "build" / "HypoidGearPair.fmu"))
    a = p.parse_args(argv)
    if a.command == "record":
        RECORD.write_text(json.dumps(record(a.fmu, a.file), indent=1) + "\n")
        (FOLDER / "mesh-law.md").write_text(RECORDS["mesh-law"].write())
        return 0
    lev = Levels(a.file, e_0_scale=a.e_0_scale)
    table = ContactTable() if "reference" in a.law else None
    if a.command == "static":
        th = 2.0 * math.pi * np.arange(64) / 64
        W = np.full(64, a.torque / lev.R_p0)
        T = np.full(64, a.torque)
        for name in a.law:
            law = make_law(name, table)
            s = static_approach(law, lev, W, T, th)
            k = (law(s + 1e-9, th, T, lev) - law(s - 1e-9, th, T, lev)) / 2e-9
            print(f"{name:10s} {a.torque:g} N.m: static approach mean {s.mean() * 1e6:.3f} um, "
                  f"p-p {np.ptp(s) * 1e6:.3f} um; dW/da mean {k.mean():.4g} N/m")
        return
    speeds = [a.speed] if a.command == "point" else np.linspace(*a.speeds[:2], int(a.speeds[2]))
    for name in a.law:
        x, contact = simulate(make_law(name, table), lev, speeds, a.torque, a.dampers,
                              t_end=a.t_end, dt=a.dt)
        for i, n in enumerate(speeds):
            print(f"{name:10s} {n:7.1f} rpm {a.torque:6.1f} N.m: DTE p-p "
                  f"{np.ptp(x[:, i]) * 1e6:7.3f} um mean {x[:, i].mean() * 1e6:7.3f} um "
                  f"min(x)-b {(x[:, i].min() - B_HALF) * 1e6:7.3f} um "
                  f"apart {100 * (1 - contact[:, i].mean()):5.1f} %", flush=True)


if __name__ == "__main__":
    sys.exit(main())
