#!/usr/bin/env python3
"""Linear stability of the scene's Jacobi coupling (docs/cosimulation.md, "Stability"), and of
the half-shaft coupling (load_mode = half_shaft, half_shaft_map; docs/integration.md).

    python tests/cosim/coupling_stability.py [--steps 2e-3 1e-3 5e-4 1e-4] [--torques 25 150]
                                             [--start 0] [--set tooth_data=loaded ...]
                                             [--record]

prints, for each communication step h, the growth rate (1/s; > 0: unstable) and frequency of the
least damped oscillation of the coupled gear and vehicle, linearised about a loaded state.

The model is the two FMUs' equations, linear: the gear's four inertias on its two shafts and the
mesh spring (R_p phi_p - R_g phi_g; the stiffness a small vibration sees, the FMU's k_m0 at the
operating torque: the law's mean tangent with layered tooth data), with the FMU's own dampers
c_t1, c_m, c_t2 (computed at the start torque of the run); the vehicle's half-shaft spring k_hs
and damper c_hs to the vehicle's inertia reflected at the wheel, J_v = m r_dyn^2 + J_wheels.
Road load, friction and the mesh's variation with the angle are left out. Over a communication
step each side is integrated exactly with its input held (the gear's T_w, the vehicle's w_w),
then the outputs are transferred: T_hs = k_hs twist + c_hs (w_w - w_wheel) with the w_w the
vehicle held over the step (libcosim's fixed_step_algorithm, cd.run_fmpy's "jacobi"). The
eigenvalues mu of that one-step map give the rates ln|mu| / h."""

import argparse
import math
import pathlib
import sys

import numpy as np
from scipy.linalg import expm

import cosim_driver as cd

VEHICLE = {"m": 1500.0, "r_dyn": 0.3, "J_wheels": 3.0, "k_hs": 12000.0, "c_hs": 40.0}
GEAR = ("I_s", "I_p", "I_g", "I_w", "k_t1", "k_t2", "c_t1", "c_m", "c_t2", "k_m0", "R_p0", "ratio")


def gear_values(gear, T_start, T_op=None):
    """The gear's linear model from the FMU (build/HypoidGearPair.fmu) with parameters gear: its
    dampers as computed for a run starting at T_s = T_start, and k_m0 as computed at T_s = T_op
    (the mean stiffness a vibration sees at that torque)."""
    from hypoid.fmu.instance import Instance

    def read(T_s):
        with Instance(cd.GEAR_FMU, name="linear") as g:
            g.start({"load_mode": 1, **gear, "T_s": T_s, "T_w": T_s * cd.RATIO})
            return {n: g.get(n) for n in GEAR}

    values = read(T_start)
    if T_op is not None and T_op != T_start:
        values["k_m0"] = read(T_op)["k_m0"]
    return values


def gear_system(p):
    """x' = A x + B T_w, w_w = C x for x = (phi_s, phi_p, phi_g, phi_w, their speeds)."""
    R_p, R_g = p["R_p0"], p["R_p0"] * p["ratio"]
    K, D = np.zeros((4, 4)), np.zeros((4, 4))
    for i, j, a, b, k, c in ((0, 1, 1.0, -1.0, p["k_t1"], p["c_t1"]),
                             (1, 2, R_p, -R_g, p["k_m0"], p["c_m"]),
                             (2, 3, 1.0, -1.0, p["k_t2"], p["c_t2"])):
        v = np.zeros(4)
        v[i], v[j] = a, b
        K += k * np.outer(v, v)
        D += c * np.outer(v, v)
    M_inv = np.diag([1.0 / p[n] for n in ("I_s", "I_p", "I_g", "I_w")])
    A = np.block([[np.zeros((4, 4)), np.eye(4)], [-M_inv @ K, -M_inv @ D]])
    B = np.zeros((8, 1))
    B[7, 0] = -1.0 / p["I_w"]  # T_w resists at the wheel end
    C = np.zeros((1, 8))
    C[0, 7] = 1.0
    return A, B, C


def vehicle_system(v=VEHICLE):
    """z' = A z + B w_w, T_hs = C z + D w_w for z = (twist, w_wheel)."""
    J_v = v["m"] * v["r_dyn"] ** 2 + v["J_wheels"]
    A = np.array([[0.0, -1.0], [v["k_hs"] / J_v, -v["c_hs"] / J_v]])
    B = np.array([[1.0], [v["c_hs"] / J_v]])
    return A, B, np.array([[v["k_hs"], -v["c_hs"]]]), v["c_hs"]


def held(A, B, h):
    """The exact step of x' = A x + B u over h with u held: x+ = F x + G u."""
    n, m = A.shape[0], B.shape[1]
    E = expm(np.block([[A, B], [np.zeros((m, n + m))]]) * h)
    return E[:n, :n], E[:n, n:]


def jacobi_map(gear, vehicle, h):
    """The one-step map of (gear state, vehicle state, held T_w, held w_w)."""
    (Ag, Bg, Cg), (Av, Bv, Cv, Dv) = gear, vehicle
    (Fg, Gg), (Fv, Gv) = held(Ag, Bg, h), held(Av, Bv, h)
    ng, nv = Fg.shape[0], Fv.shape[0]
    iu, iw = ng + nv, ng + nv + 1
    P = np.zeros((ng + nv + 2, ng + nv + 2))
    P[:ng, :ng], P[:ng, iu] = Fg, Gg[:, 0]
    P[ng:iu, ng:iu], P[ng:iu, iw] = Fv, Gv[:, 0]
    P[iu] = Cv[0] @ P[ng:iu]  # the vehicle's T_hs at the step's end, its input still the held w_w
    P[iu, iw] += Dv
    P[iw] = Cg[0] @ P[:ng]    # the gear's w_w at the step's end
    return P


def least_damped(p, h, f_min=1.0, vehicle=VEHICLE):
    """(growth rate 1/s, frequency Hz) of the least damped eigenvalue oscillating faster than f_min
    of the Jacobi map at step h (frequencies folded into 0 .. 1/(2h)); h = None: of the continuous
    coupled system."""
    if h is None:
        (Ag, Bg, Cg), (Av, Bv, Cv, Dv) = gear_system(p), vehicle_system(vehicle)
        A = np.block([[Ag + Dv * Bg @ Cg, Bg @ Cv], [Bv @ Cg, Av]])
        lam = np.linalg.eigvals(A)
    else:
        mu = np.linalg.eigvals(jacobi_map(gear_system(p), vehicle_system(vehicle), h))
        lam = np.log(mu[np.abs(mu) > 0].astype(complex)) / h  # (the held inputs give mu = 0)
    lam = lam[np.abs(lam.imag) > 2 * math.pi * f_min]  # not the rigid rotation
    k = np.argmax(lam.real)
    return float(lam[k].real), float(abs(lam[k].imag) / (2 * math.pi))


def half_shaft_system(p, vehicle=VEHICLE):
    """The gear with load_mode = half_shaft: x' = A x + B w_wheel for x = (phi_s .. phi_w, their
    speeds, the half-shaft's twist, its torque's impulse), T_hs = C x + D w_wheel."""
    Ag, _, _ = gear_system(p)
    k, c = vehicle["k_hs"], vehicle["c_hs"]
    A = np.zeros((10, 10))
    A[:8, :8] = Ag
    A[8, 7] = 1.0                                   # twist' = w_w - w_wheel
    A[7, 8], A[7, 7] = A[7, 8] - k / p["I_w"], A[7, 7] - c / p["I_w"]
    A[9, 8], A[9, 7] = k, c                         # impulse' = T_hs
    B = np.zeros((10, 1))
    B[8, 0], B[7, 0], B[9, 0] = -1.0, c / p["I_w"], -c
    C = np.zeros((1, 10))
    C[0, 8], C[0, 7] = k, c
    return A, B, C, -c


def half_shaft_map(p, h, vehicle=VEHICLE, I_vehicle=0.0):
    """The one-step Jacobi map of the half-shaft coupling as the FMUs run it: the gear holds
    w_wheel extrapolated linearly from the last two values (1.5 w_k - 0.5 w_k-1 on average over
    the step), the vehicle holds T_wheel = 2 Tbar_k - Tbar_k-1 (the gear's mean half-shaft torque
    over the last step, extrapolated), and integrates J_v w_wheel' = T_wheel (road load left
    out). With I_vehicle > 0 the gear takes E / I_vehicle from each w_wheel it receives, E the
    impulse given through T_wheel less its own (E += h (T_wheel - Tbar) each step). State:
    (gear x with the impulse reset each step, w_wheel, the corrected w_wheel of the step before,
    Tbar_k, Tbar_k-1, E)."""
    A, B, _, _ = half_shaft_system(p, vehicle)
    F, G = held(A, B, h)
    J_v = vehicle["m"] * vehicle["r_dyn"] ** 2 + vehicle["J_wheels"]
    n = A.shape[0]
    iw, iwc, itb, itbp, ie = n, n + 1, n + 2, n + 3, n + 4
    P = np.zeros((n + 5, n + 5))
    w_c = np.zeros(n + 5)                            # the corrected wheel speed of this step
    w_c[iw], w_c[ie] = 1.0, -1.0 / I_vehicle if I_vehicle > 0.0 else 0.0
    w_in = 1.5 * w_c
    w_in[iwc] -= 0.5
    u = np.zeros(n + 5)
    u[itb], u[itbp] = 2.0, -1.0
    X = np.zeros((n, n + 5))
    X[:, :n] = F
    X[:, n - 1] = 0.0                                # the impulse starts from 0 each step
    X += np.outer(G[:, 0], w_in)
    P[:n - 1] = X[:n - 1]
    P[iw, iw] = 1.0
    P[iw] += u * h / J_v
    P[iwc] = w_c
    P[itb] = X[n - 1] / h
    P[itbp, itb] = 1.0
    P[ie, ie] = 1.0
    P[ie] += h * (u - P[itb])
    return P


def half_shaft_rate(p, h, vehicle=VEHICLE, I_vehicle=0.0):
    """(growth rate 1/s, frequency Hz) of the least damped mode of half_shaft_map, the rigid
    rotation and the uncorrected E (eigenvalues at 1) left out."""
    mu = np.linalg.eigvals(half_shaft_map(p, h, vehicle, I_vehicle))
    mu = mu[(np.abs(mu) > 1e-12) & (np.abs(mu - 1.0) > 1e-4)]
    lam = np.log(mu.astype(complex)) / h
    k = np.argmax(lam.real)
    return float(lam[k].real), float(abs(lam[k].imag) / (2 * math.pi))


STEPS = [2e-3, 1.2e-3, 1e-3, 8e-4, 5e-4, 1e-4]
TORQUES = [25.0, 50.0, 100.0, 150.0, 300.0]


def rows(gear, start, torques, steps, f_min):
    """Per operating torque: (T, k_m0, [(rate, f) continuous, then at each step])."""
    out = []
    for T in torques:
        p = gear_values(gear, start, T)
        out.append((T, p["k_m0"], [least_damped(p, h, f_min) for h in [None] + steps]))
    return out


def doc_table(steps=STEPS, torques=TORQUES):
    """The markdown table of the cosimulation record: both tooth data, dampers of the scene's
    start (0 N.m), the gear's modes (above 100 Hz)."""
    lines = ["| tooth data | T_s (N.m) | k_m0 (N/m) | f_2 (Hz) | continuous | "
             + " | ".join(f"{h * 1e3:g} ms" for h in steps) + " |",
             "|---|---|---|---|---|" + "---|" * len(steps)]
    for data, at in (("loaded", torques), ("paper", torques[:1])):  # paper: one k_m0 at all
        for T, k, cells in rows({"tooth_data": data}, 0.0, at, steps, 100.0):
            label = f"{T:g}" if data == "loaded" else "any"
            lines.append(f"| {data} | {label} | {k:.2e} | {cells[0][1]:.0f} | "
                         + " | ".join(("**%+.1f**" if r > 0 else "%+.1f") % r for r, _ in cells)
                         + " |")
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--steps", type=float, nargs="+", default=STEPS)
    ap.add_argument("--torques", type=float, nargs="+", default=TORQUES,
                    help="operating torques T_s (N.m) for k_m0")
    ap.add_argument("--start", type=float, default=0.0, help="start torque (the dampers')")
    ap.add_argument("--f-min", type=float, default=100.0,
                    help="only oscillations faster than this (Hz; default: the gear's own modes)")
    ap.add_argument("--set", nargs="*", default=[], help="gear parameters NAME=VALUE")
    ap.add_argument("--record", action="store_true", help="keep the table (both tooth data, "
                    "the defaults otherwise) in the record docs/records/cosimulation")
    args = ap.parse_args()
    if args.record:
        import time

        from hypoid.records import cosimulation
        from hypoid.records.registry import FOLDER

        cosimulation.save(FOLDER, "stability", doc_table().splitlines(),
                          f"{time.strftime('%Y-%m-%d')}, by `tests/cosim/coupling_stability.py`")
        return 0
    gear = dict(s.split("=", 1) for s in args.set)
    print(f"gear {gear or 'defaults'}, dampers at T_s = {args.start:g} N.m; growth rate 1/s "
          f"(frequency Hz) of the least damped oscillation above {args.f_min:g} Hz")
    print(f"{'T_s':>6} {'k_m0':>9} {'continuous':>15} "
          + " ".join(f"{h * 1e3:>9g} ms" for h in args.steps))
    for T, k, cells in rows(gear, args.start, args.torques, args.steps, args.f_min):
        print(f"{T:6g} {k:9.3e} " + " ".join(f"{r:+7.1f} ({f:4.0f})" for r, f in cells))
    return 0


if __name__ == "__main__":
    sys.exit(main())
