"""The pinion's and the carrier's tapered roller bearing pairs by the SKF model, worked out here
in Python from the catalogue's formulas at the FMU's default bearings and preloads (an
independent check of fmu-src/axle/bearings.c): the rotating torque at hand speed that the
workshop manuals specify, the torque at driving speeds and oil temperatures, its rolling and
sliding parts, and the preloads' change with the carrier's temperature. Prints the markdown
tables of docs/axle.md ("Bearings").

  .venv/bin/python tools/bearing_models.py

SKF model (SKF rolling bearings catalogue, "The SKF model for calculating the frictional
moment"; tapered roller bearings): M = phi_ish phi_rs G_rr (nu n)^0.6 + G_sl mu_sl,
  G_rr = R1 d_m^2.38 (F_r + R2 Y F_a)^0.31,  G_sl = S1 d_m^0.82 (F_r + S2 Y F_a),
  phi_ish = 1 / (1 + 1.84e-9 (n d_m)^1.28 nu^0.64),
  phi_rs = exp(-K_rs nu n (d + D) sqrt(K_z / (2 (D - d)))),  K_z = 6, K_rs = 0 for the
  flooded bearings of the FMU's default (brg_feed = flooded), 3e-8 for a low-level bath or jet,
  mu_sl = phi_bl mu_bl + (1 - phi_bl) mu_EHL,  phi_bl = exp(-2.6e-8 (n nu)^1.4 d_m),
  mu_bl = 0.15, mu_EHL = 0.002; R2 = 10.9, S2 = 2 [N mm, mm, mm^2/s, r/min]. No seal term
  (open bearings), no drag term (the bath stays below the bearings)."""

import math
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from hypoid.fmu.variables import VARIABLES  # noqa: E402

# the pairs: their bearings (FMU name prefixes), series constants, preload and stiffness
# parameters, their spread [m] and the shaft's speed per pinion speed (gear set 1, 13:36)
PAIRS = {"pinion": (("ph", "pt"), "p", "F_pre_p", "k_ax_p", ("brg_pt_x", "-brg_ph_x"), 1.0),
         "carrier": (("gn", "gf"), "g", "F_pre_g", "k_ax_g", ("brg_gn_x", "brg_gf_x"),
                     13.0 / 36.0)}
HAND_RPM, HAND_C = 30.0, 20.0  # at the pinion nut
ALPHA_STEEL, ALPHA_ALUMINIUM = 11.5e-6, 23e-6  # 1/K (docs/axle.md)


def start(name):
    return float(VARIABLES[name].start)


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


K_RS = {"flooded": 0.0, "low_level": 3e-8}  # brg_feed


def skf(d, D, Y, R1, S1, F_a, n, nu, F_r=0.0, feed="flooded"):
    """(rolling, sliding) moments [N m] of one bearing; d, D [mm]."""
    d_m = 0.5 * (d + D)
    G_rr = R1 * d_m ** 2.38 * (F_r + 10.9 * Y * F_a) ** 0.31
    G_sl = S1 * d_m ** 0.82 * (F_r + 2.0 * Y * F_a)
    phi_ish = 1.0 / (1.0 + 1.84e-9 * (n * d_m) ** 1.28 * nu ** 0.64)
    phi_rs = math.exp(-K_RS[feed] * nu * n * (d + D) * math.sqrt(6.0 / (2.0 * (D - d))))
    phi_bl = math.exp(-2.6e-8 * (n * nu) ** 1.4 * d_m)
    mu_sl = phi_bl * 0.15 + (1.0 - phi_bl) * 0.002
    return 1e-3 * phi_ish * phi_rs * G_rr * (nu * n) ** 0.6, 1e-3 * G_sl * mu_sl


def spread(which):
    a, b = PAIRS[which][4]
    return start(a) + (-start(b[1:]) if b.startswith("-") else start(b))


def preload(which, T_C, alpha_c=None):
    """The pair's preload [N] at T_C, set at 20 degC (fmu-src/axle/bearings.c)."""
    _, _, F_name, k_name, _, _ = PAIRS[which]
    alpha_c = start("alpha_carrier") if alpha_c is None else alpha_c
    return max(0.0, start(F_name) - start(k_name) * (alpha_c - ALPHA_STEEL) * spread(which)
               * (T_C - 20.0))


def pair(which, n_pinion, T_C, F_a=None):
    """(rolling, sliding) moments [N m] of the pair, no external load, on its own shaft at the
    pinion speed n_pinion [r/min]."""
    bearings, s, _, _, _, ratio = PAIRS[which]
    F_a = preload(which, T_C) if F_a is None else F_a
    n, nu = n_pinion * ratio, nu_mm2s(T_C)
    parts = [skf(1e3 * start(f"brg_{b}_d"), 1e3 * start(f"brg_{b}_D"), start(f"brg_{b}_Y"),
                 start(f"brg_{s}_R1"), start(f"brg_{s}_S1"), F_a, n, nu) for b in bearings]
    return sum(p[0] for p in parts), sum(p[1] for p in parts)


def table(which):
    hand = sum(pair(which, HAND_RPM, HAND_C))
    ratio = PAIRS[which][5]
    print(f"{which} pair, preload {start(PAIRS[which][2]) / 1e3:.2f} kN at 20 °C: "
          f"{hand:.3f} N·m on its shaft at {HAND_RPM:.0f} r/min of the pinion in {HAND_C:.0f} °C "
          f"oil ({hand * ratio:.3f} N·m at the pinion)\n")
    print("| oil °C | ν mm²/s | preload kN | pinion r/min | rolling N·m | sliding N·m | total N·m |")
    print("|---|---|---|---|---|---|---|")
    for T_C in (20.0, 28.0, 40.0, 65.0, 80.0):
        for n in (1000.0, 2000.0, 4000.0):
            rr, sl = pair(which, n, T_C)
            print(f"| {T_C:.0f} | {nu_mm2s(T_C):.1f} | {preload(which, T_C) / 1e3:.2f} | {n:.0f} | "
                  f"{rr:.3f} | {sl:.3f} | {rr + sl:.3f} |")
    k = start(PAIRS[which][3]) * spread(which)
    print(f"\npreload change: {-k * (start('alpha_carrier') - ALPHA_STEEL):+.1f} N/K with the "
          f"default carrier, {-k * (ALPHA_ALUMINIUM - ALPHA_STEEL):+.1f} N/K with an aluminium "
          f"one (spread {1e3 * spread(which):.0f} mm)\n")


def main():
    for which in PAIRS:
        table(which)


if __name__ == "__main__":
    main()
