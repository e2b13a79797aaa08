"""The axle's loss trends that measured axles show, from steady runs of the FMU (speed governor,
rigid mesh, ehl_thermal, axle_losses = full, oil held at T_bath, the mean of the last 10 of 30
samples over 0.6 s, as hypoid.lossmap): the bearing loss against the transmitted torque, the
spin loss at SAE J2985's two oil temperatures beside the oil's viscosity, the churning against
the oil temperature, the mesh friction against the oil temperature, and the pinion bearings'
share of the axle loss. Prints markdown tables (docs/axle.md).

  .venv/bin/python tools/axle_trends.py [--fmu build/HypoidGearPair.fmu] [--json out.json]"""

import argparse
import json
import math
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from hypoid.fmu.instance import Instance  # noqa: E402

T_END_S, H_S, MEAN_STEPS = 0.6, 0.02, 10
PAIRS = 3
BASE = ["P_loss", "P_in", "P_churn", "P_bearings", "P_seals", "P_axle", "P_in_axle", "eta",
        "eta_axle", "T_oil"]
SPLIT = ["P_bearings_p", "P_bearings_g"]  # per bearing pair, where the FMU has them
PAIR_OUT = [f"pair[{k}].{q}" for k in range(1, PAIRS + 1) for q in ("mu", "W")]


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
        mu = rows[:, [self.outputs.index(f"pair[{k}].mu") for k in range(1, PAIRS + 1)]]
        W = rows[:, [self.outputs.index(f"pair[{k}].W") for k in range(1, PAIRS + 1)]]
        out["mu_eff"] = float((mu * W).sum() / W.sum()) if W.sum() > 0 else 0.0
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
    for rpm, tq in ((2000, 100.0), (4500, 250.0), (1000, 300.0)):
        for T in (-10.0, 20.0, 40.0, 80.0, 100.0):
            p = r.point(rpm, tq, T)
            rows.append({"rpm": rpm, "T_s": tq, "T_C": T, "eta": p["eta"], "mu_eff": p["mu_eff"],
                         "P_loss": p["P_loss"]})
    return rows


def pinion_share(r):
    rows = []
    for tq in (50.0, 200.0):
        p = r.point(2000, tq, 40.0)
        rows.append({"T_s": tq, "P_axle": p["P_axle"], "P_bearings": p["P_bearings"],
                     "P_bearings_p": p.get("P_bearings_p", float("nan"))})
    return rows


def fmt(x, f):
    return "–" if x is None or (isinstance(x, float) and math.isnan(x)) else format(x, f)


def report(res):
    out = ["Bearing loss against the transmitted torque (2000 rpm, 80 °C oil):", "",
           "| T_s N·m | bearings W | pinion pair W | carrier pair W | mesh W |", "|---|---|---|---|---|"]
    for b in res["bearings_vs_torque"]:
        out.append(f"| {b['T_s']:.0f} | {fmt(b['P_bearings'], '.1f')} | "
                   f"{fmt(b.get('P_bearings_p'), '.1f')} | {fmt(b.get('P_bearings_g'), '.1f')} | "
                   f"{fmt(b['P_loss'], '.1f')} |")
    s = res["spin_vs_temperature"]
    out += ["", "Spin loss (2000 rpm, no torque) at SAE J2985's oil temperatures:", "",
            "| oil °C | P_axle W | bearings W | churning W | seals W |", "|---|---|---|---|---|"]
    for x in s:
        out.append(f"| {x['T_C']:.0f} | {x['P_axle']:.1f} | {x['P_bearings']:.1f} | "
                   f"{x['P_churn']:.1f} | {x['P_seals']:.1f} |")
    out.append(f"| 28/65 ratio | {s[0]['P_axle'] / s[1]['P_axle']:.2f} | "
               f"{s[0]['P_bearings'] / s[1]['P_bearings']:.2f} | "
               f"{s[0]['P_churn'] / s[1]['P_churn']:.2f} | |")
    out += ["", "Churning (4000 rpm, no torque):", "", "| oil °C | P_churn W |", "|---|---|"]
    out += [f"| {c['T_C']:.0f} | {c['P_churn']:.1f} |" for c in res["churning_vs_temperature"]]
    out += ["", "Mesh friction against the oil temperature (rigid mesh, ehl_thermal):", "",
            "| rpm | T_s N·m | oil °C | mesh eta % | mu (load-weighted) | P_loss W |",
            "|---|---|---|---|---|---|"]
    out += [f"| {m['rpm']} | {m['T_s']:.0f} | {m['T_C']:.0f} | {100 * m['eta']:.2f} | "
            f"{m['mu_eff']:.4f} | {m['P_loss']:.1f} |" for m in res["mesh_vs_temperature"]]
    out += ["", "Pinion bearings' share of the axle loss (2000 rpm, 40 °C):", "",
            "| T_s N·m | P_axle W | bearings W | pinion pair W | pinion share |", "|---|---|---|---|---|"]
    for p in res["pinion_share"]:
        out.append(f"| {p['T_s']:.0f} | {p['P_axle']:.1f} | {p['P_bearings']:.1f} | "
                   f"{fmt(p['P_bearings_p'], '.1f')} | "
                   f"{fmt(p['P_bearings_p'] / p['P_axle'], '.1%')} |")
    return "\n".join(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--fmu", default=str(ROOT / "build" / "HypoidGearPair.fmu"))
    ap.add_argument("--json", help="also write the figures to this file")
    args = ap.parse_args()
    r = Runner(args.fmu)
    res = {f.__name__: f(r) for f in (bearings_vs_torque, spin_vs_temperature,
                                      churning_vs_temperature, mesh_vs_temperature, pinion_share)}
    if args.json:
        pathlib.Path(args.json).write_text(json.dumps(res, indent=1) + "\n")
    print(report(res))


if __name__ == "__main__":
    main()
