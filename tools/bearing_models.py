"""The pinion's and the carrier's tapered roller bearing pairs in the FMU's Palmgren form beside
the SKF catalogue's rolling + sliding model, at the FMU's default geometry and preloads: the
rotating torque at hand speed (what workshop manuals specify; the SKF preload is the one that
gives the same hand torque) and the drag at driving speeds. Prints the markdown tables of
docs/axle.md ("Bearings: Palmgren beside SKF").

  .venv/bin/python tools/bearing_models.py

SKF model (SKF rolling bearings catalogue, "The SKF model for calculating the frictional
moment"; tapered roller bearings, Table 2a/2b): M = phi_ish phi_rs G_rr (nu n)^0.6 + G_sl mu_sl,
  G_rr = R1 d_m^2.38 (F_r + R2 Y F_a)^0.31,  G_sl = S1 d_m^0.82 (F_r + S2 Y F_a),
  phi_ish = 1 / (1 + 1.84e-9 (n d_m)^1.28 nu^0.64),
  phi_rs = exp(-K_rs nu n (d + D) sqrt(K_z / (2 (D - d)))),  K_rs = 3e-8, K_z = 6,
  mu_sl = phi_bl mu_bl + (1 - phi_bl) mu_EHL,  phi_bl = exp(-2.6e-8 (n nu)^1.4 d_m),
  mu_bl = 0.15, mu_EHL = 0.002 (tapered roller bearings); series 323 (pinion): R1 = 2.38e-6,
  R2 = 10.9, S1 = 0.019, S2 = 2; series 320 X (carrier): R1 = 2.38e-6, R2 = 10.9, S1 = 0.014,
  S2 = 2 [N mm, mm, mm^2/s, r/min]. No seal term (open bearings), no drag term (splash-fed
  bearings; the drag formula needs the oil level at the bearing)."""

import math
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from hypoid.fmu.variables import VARIABLES  # noqa: E402

# The pairs: bearings (FMU name: d, D [mm] of the catalogue size), SKF series constants, the
# preload parameter and the shaft's speed per pinion speed (gear set 1, 13:36). Pinion: 32308
# (head) and 32306 (tail); carrier: two 32010 X (the FMU's defaults are their catalogue d_m and Y).
SKF_323 = dict(R1=2.38e-6, R2=10.9, S1=0.019, S2=2.0)
SKF_320X = dict(R1=2.38e-6, R2=10.9, S1=0.014, S2=2.0)
PAIRS = {"pinion": ({"ph": (40.0, 90.0), "pt": (30.0, 72.0)}, SKF_323, "F_pre_p", 1.0),
         "carrier": ({"gn": (50.0, 80.0), "gf": (50.0, 80.0)}, SKF_320X, "F_pre_g", 13.0 / 36.0)}
HAND_RPM, HAND_C = 30.0, 20.0  # at the pinion nut


def lubricant():
    keys = {}
    for line in (ROOT / "resources" / "lubricants" / "OS265962.txt").read_text().splitlines():
        words = line.split("#")[0].split()
        if len(words) == 2 and words[0] != "name":
            keys[words[0]] = float(words[1])
    return keys


def nu_mm2s(T_C, lub=lubricant()):
    T = T_C + 273.15
    rho = lub["rho_15"] * (1.0 - 7e-4 * (T - 288.15))
    return lub["vogel_a"] * math.exp(lub["vogel_b"] / (T - lub["vogel_c"])) / rho * 1e6


def start(name):
    return float(VARIABLES[name].start)


def palmgren(d_m, Y, F_a, n, nu):
    """The FMU's moment [N m] (fmu-src/axle/bearings.c), d_m [mm]."""
    M0 = 1e-7 * start("brg_f0") * max((nu * n) ** (2 / 3), 160.0) * d_m ** 3
    return 1e-3 * (M0 + start("brg_f1") * 2 * Y * F_a * d_m)


def skf(d, D, Y, F_a, n, nu, F_r=0.0, c=SKF_323):
    d_m = 0.5 * (d + D)
    G_rr = c["R1"] * d_m ** 2.38 * (F_r + c["R2"] * Y * F_a) ** 0.31
    G_sl = c["S1"] * d_m ** 0.82 * (F_r + c["S2"] * Y * F_a)
    phi_ish = 1.0 / (1.0 + 1.84e-9 * (n * d_m) ** 1.28 * nu ** 0.64)
    phi_rs = math.exp(-3e-8 * nu * n * (d + D) * math.sqrt(6.0 / (2.0 * (D - d))))
    phi_bl = math.exp(-2.6e-8 * (n * nu) ** 1.4 * d_m)
    mu_sl = phi_bl * 0.15 + (1.0 - phi_bl) * 0.002
    return 1e-3 * (phi_ish * phi_rs * G_rr * (nu * n) ** 0.6 + G_sl * mu_sl)


def pair(which, model, F_a, n_pinion, T_C):
    """The pair's moment [N m] on its own shaft at the pinion speed n_pinion [r/min]."""
    bearings, series, _, ratio = PAIRS[which]
    n, nu = n_pinion * ratio, nu_mm2s(T_C)
    if model == "palmgren":
        return sum(palmgren(start(f"brg_{b}_dm") * 1e3, start(f"brg_{b}_Y"), F_a, n, nu)
                   for b in bearings)
    return sum(skf(*bearings[b], start(f"brg_{b}_Y"), F_a, n, nu, c=series) for b in bearings)


def matching_preload(which, target):
    """The SKF preload [N] whose hand-speed torque is `target` [N m] (bisection)."""
    lo, hi = 0.0, 100000.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if pair(which, "skf", mid, HAND_RPM, HAND_C) < target else (lo, mid)
    return 0.5 * (lo + hi)


def table(which):
    F_pre = start(PAIRS[which][2])
    target = pair(which, "palmgren", F_pre, HAND_RPM, HAND_C)
    F_skf = matching_preload(which, target)
    print(f"{which} pair at {HAND_RPM:.0f} r/min of the pinion, {HAND_C:.0f} degC: Palmgren "
          f"{target:.3f} N m at {F_pre / 1e3:.1f} kN; SKF gives that torque at "
          f"{F_skf / 1e3:.2f} kN\n")
    print(f"| oil °C | pinion r/min | Palmgren, {F_pre / 1e3:.1f} kN N·m | SKF, "
          f"{F_skf / 1e3:.2f} kN N·m | SKF / Palmgren |")
    print("|---|---|---|---|---|")
    for T_C in (20.0, 40.0, 80.0):
        for n in (HAND_RPM, 1000.0, 2000.0, 4000.0):
            p, s = pair(which, "palmgren", F_pre, n, T_C), pair(which, "skf", F_skf, n, T_C)
            print(f"| {T_C:.0f} | {n:.0f} | {p:.3f} | {s:.3f} | {s / p:.2f} |")
    print()


def main():
    for which in PAIRS:
        table(which)


if __name__ == "__main__":
    main()
