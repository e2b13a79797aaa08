"""The axle's loss trends that measured axles show, from steady runs of the FMU (speed governor,
rigid mesh, ehl_thermal, axle_losses = full, oil held at T_bath, the mean of the last 10 of 30
samples over 0.6 s, as hypoid.lossmap): the bearing loss against the transmitted torque, the
spin loss at SAE J2985's two oil temperatures beside the oil's viscosity, the churning against
the oil temperature, the mesh friction against the oil temperature, and the pinion bearings'
share of the axle loss, each beside the published figures it is held to in docs/validation.md
(Xu et al.'s and ISO/TR 14179-2's mesh friction are evaluated here). Prints the record's page;
--record writes the record docs/records/validation.

  .venv/bin/python tools/axle_trends.py [--fmu build/HypoidGearPair.fmu] [--json out.json]
                                        [--record]"""

import argparse
import datetime
import json
import math
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from hypoid.fmu.instance import Instance  # noqa: E402
from hypoid.records import pages  # noqa: E402
from hypoid.records.docblocks import commit  # noqa: E402
from hypoid.records.registry import FOLDER, RECORDS  # noqa: E402

sys.path.insert(0, str(ROOT / "tools"))
import bearing_models  # noqa: E402  (the oil's viscosity from the lubricant file)
import friction_figures as ff  # noqa: E402  (gear set 1's virtual cylindrical gear)

T_END_S, H_S, MEAN_STEPS = 0.6, 0.02, 10
PAIRS = 3
BASE = ["P_loss", "P_in", "P_churn", "P_bearings", "P_seals", "P_axle", "P_in_axle", "eta",
        "eta_axle", "T_oil", "w_p", "w_g"]
SPLIT = ["P_bearings_p", "P_bearings_g"]  # per bearing pair, where the FMU has them
PAIR_Q = ("mu", "W", "p_h", "V_s", "u_e", "R_e")
PAIR_OUT = [f"pair[{k}].{q}" for k in range(1, PAIRS + 1) for q in PAIR_Q]
SIGMA_S_UM = 0.25  # RMS roughness of each flank [um] (the FMU's sigma_s)
# Xu, Kahraman, Anderson, Maddock, ASME J. Mech. Des. 129 (2007) 58-68: regression of their
# EHL friction model over gear-like conditions (P_h GPa, V_e m/s, nu_o cP, R m, S um; R in metres
# as public implementations take it, which gives gear-like levels of 0.02-0.05; in millimetres
# every level would fall 15-fold)
XU_B = (-8.916465, 1.03303, 1.036077, -0.354068, 2.812084, -0.100601, 0.752755, -0.390958,
        0.620305)


def eta_oil_mPas(T_C):
    """The oil's dynamic viscosity at T_C [mPa s] (Vogel, the lubricant file)."""
    lub = bearing_models.lubricant()
    return 1e3 * lub["vogel_a"] * math.exp(lub["vogel_b"] / (T_C + 273.15 - lub["vogel_c"]))


def mu_xu(p_h, V_s, u_e, R_e, T_C):
    """Xu et al.'s friction coefficient of one contact: mu = exp(f) P_h^b2 |SR|^b3 V_e^b6
    nu_o^b7 R^b8, f = b1 + b4 |SR| P_h log10(nu_o) + b5 exp(-|SR| P_h log10(nu_o)) + b9 exp(S),
    with SR = V_s/u_e, V_e = u_e, nu_o the oil's viscosity at the bath temperature."""
    b = XU_B
    P, SR, nu = p_h * 1e-9, abs(V_s) / u_e, eta_oil_mPas(T_C)
    x = SR * P * math.log10(nu)
    f = b[0] + b[3] * x + b[4] * math.exp(-x) + b[8] * math.exp(SIGMA_S_UM)
    return math.exp(f) * P ** b[1] * SR ** b[2] * u_e ** b[5] * nu ** b[6] * R_e ** b[7]


def mu_iso(T_s, rpm, T_C, X_L=1.0):
    """ISO/TR 14179-2's mu_mZ (Schlenk) on gear set 1's virtual gear at the oil's viscosity at T_C
    (tools/friction_figures.py evaluates it at 40 degC)."""
    w = T_s / ff.R_P0 * math.cos(math.radians(ff.BETA_VB)) / ff.B_V_EFF
    v_sum = 2.0 * ff.U_E_PER_RPM * rpm
    return (0.048 * (w / (v_sum * ff.RHO_RED)) ** 0.2 * eta_oil_mPas(T_C) ** -0.05 * ff.RA ** 0.25
            * X_L)


def nu_cSt(inst_outputs):
    return inst_outputs.get("nu_oil", float("nan")) * 1e6


class Runner:
    def __init__(self, fmu):
        self.inst = Instance(fmu)
        names = set(self.inst.vars)
        self.outputs = BASE + [n for n in SPLIT + ["nu_oil"] if n in names] + PAIR_OUT

    def point(self, rpm, torque, T_C, mesh_model="rigid", **extra):
        """The mean outputs of a steady run; mu_eff = sum(mu_k W_k) / sum(W_k) over the pairs."""
        self.inst.start({"axle_losses": "full", "mesh_model": mesh_model,
                         "friction_model": "ehl_thermal", "speed_rpm": rpm, "T_s": torque,
                         "T_bath": T_C + 273.15, "rtol": 1e-6, **extra})
        rows = self.inst.record(T_END_S, H_S, self.outputs)[-MEAN_STEPS:]
        out = {n: float(v) for n, v in zip(self.outputs, rows.mean(axis=0))}
        col = {q: rows[:, [self.outputs.index(f"pair[{k}].{q}") for k in range(1, PAIRS + 1)]]
               for q in PAIR_Q}
        W = col["W"]
        out["mu_eff"] = float((col["mu"] * W).sum() / W.sum()) if W.sum() > 0 else 0.0
        xu = [[mu_xu(*(col[q][i, k] for q in ("p_h", "V_s", "u_e", "R_e")), T_C)
               if min(W[i, k], col["p_h"][i, k], col["u_e"][i, k], col["R_e"][i, k]) > 0
               else 0.0
               for k in range(PAIRS)] for i in range(len(rows))]
        out["mu_xu"] = float((xu * W).sum() / W.sum()) if W.sum() > 0 else 0.0
        out["nu_cSt"] = nu_cSt(out)
        return out


def bearings_vs_torque(r):
    rows = []
    for tq in (0.0, 50.0, 100.0, 200.0):
        p = r.point(2000, tq, 80.0)
        rows.append({"T_s": tq, **{k: p.get(k) for k in ["P_bearings"] + SPLIT + ["P_loss"]}})
    return rows


def spin_vs_temperature(r):
    return [{"T_C": T, **{k: p.get(k) for k in ["P_axle", "P_bearings", "P_churn", "P_seals",
                                                  "nu_cSt"] + SPLIT}}
            for T in (28.0, 65.0) for p in [r.point(2000, 0.0, T)]]


def churning_vs_temperature(r):
    return [{"T_C": T, "P_churn": r.point(4000, 0.0, T)["P_churn"]} for T in (40.0, 60.0, 80.0)]


def mesh_vs_temperature(r):
    rows = []
    for rpm, tq in ((2000, 100.0), (4500, 250.0), (1000, 300.0), (1000, 50.0), (4500, 50.0)):
        for T in (-10.0, 20.0, 40.0, 80.0, 100.0):
            p = r.point(rpm, tq, T)
            rows.append({"rpm": rpm, "T_s": tq, "T_C": T, "eta": p["eta"], "mu_eff": p["mu_eff"],
                         "P_loss": p["P_loss"], "mu_xu": p["mu_xu"],
                         "mu_iso": mu_iso(tq, rpm, T)})
    return rows


D_SEAL_P_MM, D_SEAL_W_MM = 45.0, 40.0  # the default seal shafts (d_seal_p, d_seal_w)


def linke_factor(T_C):
    """Linke's bracket 145 - 1.6 theta + 350 lg lg(nu_40 + 0.8), nu_40 [mm^2/s] the oil's at
    40 degC (Vogel, the ledger's density), not below 0 (docs/axle.md)."""
    rho_40 = bearing_models.lubricant()["rho_15"] * (1.0 - 7e-4 * 25.0)
    nu_40 = eta_oil_mPas(40.0) / (rho_40 * 1e-3)
    return max(0.0, 145.0 - 1.6 * T_C + 350.0 * math.log10(math.log10(nu_40 + 0.8)))


def seals_vs_temperature(r):
    """The three seals at 2000 rpm of the pinion, no torque: the FMU with seal_model = linke (the
    default) and iso14179, and Linke's law worked here at the FMU's shaft speeds."""
    rows = []
    for T in (-30.0, -7.0, 20.0, 40.0, 80.0, 100.0):
        p = r.point(2000, 0.0, T)
        n_p, n_g = (p[k] * 30.0 / math.pi for k in ("w_p", "w_g"))
        f = linke_factor(T)
        rows.append({"T_C": T, "P_seals": p["P_seals"],
                     "P_seals_iso": r.point(2000, 0.0, T, seal_model="iso14179")["P_seals"],
                     "linke_pinion": f * 1e-7 * D_SEAL_P_MM ** 2 * n_p,
                     "linke_shafts": 2.0 * f * 1e-7 * D_SEAL_W_MM ** 2 * n_g})
    return rows


def pinion_share(r):
    rows = []
    for tq in (50.0, 200.0):
        p = r.point(2000, tq, 40.0)
        rows.append({"T_s": tq, "P_axle": p["P_axle"], "P_bearings": p["P_bearings"],
                     "P_bearings_p": p.get("P_bearings_p", float("nan"))})
    return rows


def spin_with_aluminium(r):
    """The spin loss at SAE J2985's temperatures with an aluminium carrier (alpha 23e-6 1/K)."""
    return [{"T_C": T, **{k: p.get(k) for k in ["P_axle", "P_bearings"] + SPLIT}}
            for T in (28.0, 65.0) for p in [r.point(2000, 0.0, T, alpha_carrier=23e-6)]]


def axle_efficiency(r):
    """eta_axle at loaded points, cold and warm oil (TRL RR10's trend, the quoted 95-97 %)."""
    return [{"rpm": rpm, "T_s": tq, "T_C": T, "eta_axle": r.point(rpm, tq, T)["eta_axle"]}
            for rpm, tq in ((1000, 50.0), (2000, 50.0), (2000, 200.0), (4000, 200.0))
            for T in (40.0, 80.0)]


def hand_torques(r):
    """Turned by hand at 30 r/min of the pinion in 20 degC oil, no mesh friction (the workshop's
    reading, docs/axle.md): the pinion pair's torque and the carrier's share at the pinion."""
    w = 30.0 * math.pi / 30.0
    p = r.point(30, 0.0, 20.0, friction_model="coulomb", mu_const=0.0)
    if "P_bearings_p" not in p:
        return {}
    return {"pinion_Nm": p["P_bearings_p"] / w,
            "carrier_share_Nm": (p["P_bearings_g"] + p["P_churn"] + p["P_loss"]) / w}


MEASURES = (bearings_vs_torque, spin_vs_temperature, spin_with_aluminium,
            churning_vs_temperature, seals_vs_temperature, mesh_vs_temperature, pinion_share,
            axle_efficiency, hand_torques)


def fmt(x, f):
    return "–" if x is None or (isinstance(x, float) and math.isnan(x)) else format(x, f)


def section(heading, text, columns, rows):
    return [{"heading": heading, "level": 2}, {"text": text},
            {"table": {"columns": columns, "rows": rows}}]


def sections(res):
    """The record's sections (hypoid.records.pages.sections) from the measured figures."""
    out = section(
        "Bearing loss against the transmitted torque",
        "2000 rpm, oil at 80 °C: the four bearings, each pair, and the mesh.",
        ["T_s N·m", "bearings W", "pinion pair W", "carrier pair W", "mesh W"],
        [[f"{b['T_s']:.0f}", fmt(b["P_bearings"], ".1f"), fmt(b.get("P_bearings_p"), ".1f"),
          fmt(b.get("P_bearings_g"), ".1f"), fmt(b["P_loss"], ".1f")]
         for b in res["bearings_vs_torque"]])
    for key, what in (("spin_vs_temperature", "the default cast iron carrier"),
                      ("spin_with_aluminium", "an aluminium carrier (`alpha_carrier` = 23·10⁻⁶ 1/K)")):
        s = res[key]
        rows = [[f"{x['T_C']:.0f}", f"{x['P_axle']:.1f}", f"{x['P_bearings']:.1f}",
                 fmt(x.get("P_bearings_p"), ".1f"), fmt(x.get("P_bearings_g"), ".1f")] for x in s]
        rows.append(["28/65", f"{s[0]['P_axle'] / s[1]['P_axle']:.2f}",
                     f"{s[0]['P_bearings'] / s[1]['P_bearings']:.2f}", "", ""])
        out += section(f"Spin loss at SAE J2985's temperatures, {what}",
                       "2000 rpm, no torque: what the governor supplies.",
                       ["oil °C", "P_axle W", "bearings W", "pinion pair W", "carrier pair W"],
                       rows)
    out += section("Churning against the oil temperature", "4000 rpm, no torque.",
                   ["oil °C", "P_churn W"],
                   [[f"{c['T_C']:.0f}", f"{c['P_churn']:.1f}"]
                    for c in res["churning_vs_temperature"]])
    out += section(
        "Seals against the oil temperature",
        "2000 rpm of the pinion, no torque: the pinion seal (45 mm) and the two axle-shaft seals "
        "(40 mm). The FMU with `seal_model` = linke (the default) and iso14179; Linke's law "
        "worked here at the FMU's shaft speeds, with the oil's viscosity at 40 °C.",
        ["oil °C", "P_seals W", "Linke: pinion W", "Linke: shafts W", "Linke W",
         "P_seals iso14179 W", "linke / iso14179"],
        [[f"{s['T_C']:.0f}", f"{s['P_seals']:.2f}", f"{s['linke_pinion']:.2f}",
          f"{s['linke_shafts']:.2f}", f"{s['linke_pinion'] + s['linke_shafts']:.2f}",
          f"{s['P_seals_iso']:.2f}", f"{s['P_seals'] / s['P_seals_iso']:.2f}"]
         for s in res["seals_vs_temperature"]])
    out += section(
        "Mesh friction against the oil temperature",
        "Rigid mesh, `ehl_thermal`, the defaults; μ load-weighted over the pairs. Xu et al.'s "
        "regression (ASME J. Mech. Des. 129 (2007) 58–68) on the same contacts (each pair's "
        "`p_h`, `V_s`, `u_e`, `R_e`, R in metres, the oil's viscosity at the bath, σ 0.25 µm); "
        "ISO/TR 14179-2's μ_mZ (Schlenk, `X_L` = 1) on gear set 1's virtual gear at the bath's "
        "viscosity (`tools/friction_figures.py`).",
        ["rpm", "T_s N·m", "oil °C", "mesh η %", "μ", "P_loss W", "μ Xu", "μ ISO", "μ / Xu",
         "μ / ISO"],
        [[f"{m['rpm']}", f"{m['T_s']:.0f}", f"{m['T_C']:.0f}", f"{100 * m['eta']:.2f}",
          f"{m['mu_eff']:.4f}", f"{m['P_loss']:.1f}", f"{m['mu_xu']:.4f}", f"{m['mu_iso']:.4f}",
          f"{m['mu_eff'] / m['mu_xu']:.2f}", f"{m['mu_eff'] / m['mu_iso']:.2f}"]
         for m in res["mesh_vs_temperature"]])
    out += section(
        "The pinion bearings' share of the axle loss", "2000 rpm, oil at 40 °C.",
        ["T_s N·m", "P_axle W", "bearings W", "pinion pair W", "pinion share"],
        [[f"{p['T_s']:.0f}", f"{p['P_axle']:.1f}", f"{p['P_bearings']:.1f}",
          fmt(p["P_bearings_p"], ".1f"), fmt(100 * p["P_bearings_p"] / p["P_axle"], ".1f") + " %"]
         for p in res["pinion_share"]])
    out += published(res)
    return out


def published(res):
    """The published figures beside the model's (docs/validation.md cites them)."""
    share = {p["T_s"]: p["P_bearings_p"] / p["P_axle"] for p in res["pinion_share"]}
    s = res["spin_vs_temperature"]
    eta = {(e["rpm"], e["T_s"], e["T_C"]): e["eta_axle"] for e in res["axle_efficiency"]}
    nu_ratio = eta_oil_mPas(28.0) / eta_oil_mPas(65.0)
    hand = res["hand_torques"]
    rows = [["pinion bearings' share of a rear axle's loss", "JTEKT, FISITA 2006 F2006P299",
             "about 50 %", f"{100 * share[50.0]:.0f} % at 50 N·m, {100 * share[200.0]:.0f} % at "
             "200 N·m (2000 rpm, 40 °C)"],
            ["spin loss 28 °C / 65 °C (SAE J2985's temperatures)", "the oil's viscosity ratio",
             f"{nu_ratio:.2f}", f"{s[0]['P_axle'] / s[1]['P_axle']:.2f} (2000 rpm)"],
            ["whole-axle torque efficiency, warm and loaded", "FEUP/INEGI axle-oil literature "
             "(quoted)", "95–97 %", f"{100 * eta[(2000, 200.0, 80.0)]:.1f} % (2000 rpm, 200 N·m, "
             f"80 °C), {100 * eta[(4000, 200.0, 80.0)]:.1f} % (4000 rpm)"],
            ["efficiency rises with oil temperature", "TRL RR10 (Ford Transit axles)",
             "yes, at every power", ", ".join(
                 f"{100 * eta[(n, t, 40.0)]:.1f} → {100 * eta[(n, t, 80.0)]:.1f} % "
                 f"({n} rpm, {t:.0f} N·m)" for n, t in ((1000, 50.0), (2000, 50.0), (2000, 200.0)))]]
    if hand:
        rows += [["pinion pair turned by hand, run-in bearings", "four workshop manuals "
                  "(docs/axle.md)", "0.6–1.7 N·m, common part 0.9–1.0", f"{hand['pinion_Nm']:.2f} N·m"],
                 ["the carrier's share of the hand torque at the pinion", "five workshop "
                  "manuals (docs/axle.md)", "0.32–1.80 N·m, mean of midpoints 1.02",
                  f"{hand['carrier_share_Nm']:.2f} N·m"]]
    return section("Published figures beside the model", "What docs/validation.md cites, and "
                   "the model's figure at the same conditions.",
                   ["figure", "source", "published", "model"], rows)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--fmu", default=str(ROOT / "build" / "HypoidGearPair.fmu"))
    ap.add_argument("--json", help="also write the figures to this file")
    ap.add_argument("--record", action="store_true",
                    help="write the record docs/records/validation (its data and page)")
    args = ap.parse_args()
    r = Runner(args.fmu)
    res = {f.__name__: f(r) for f in MEASURES}
    if args.json:
        pathlib.Path(args.json).write_text(json.dumps(res, indent=1) + "\n")
    data = {"provenance": f"Recorded on {commit(ROOT)}, {datetime.date.today().isoformat()} "
                          "(`tools/axle_trends.py --record`): steady runs of gear set 1, "
                          "OS265962, `axle_losses = full`, the oil held at the bath's "
                          "temperature.", "sections": sections(res)}
    print(pages.sections(data["sections"]))
    if args.record:
        (FOLDER / "validation.json").write_text(json.dumps(data, indent=1, ensure_ascii=False)
                                                + "\n")
        (FOLDER / "validation.md").write_text(RECORDS["validation"].write())


if __name__ == "__main__":
    main()
