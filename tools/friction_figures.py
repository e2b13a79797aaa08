"""mu and P_loss of the full model, the paper's EHL choices against the recommended ones
(RECOMMENDED: Z exact, the stress over the Hertzian field, limiting shear 0.075), at
1000/2000/5000 rpm x 50/300 N.m for both built-in oils (docs/friction-evidence.md):

    .venv/bin/python tools/friction_figures.py [--fmu build/HypoidGearPair.fmu]

Each point: the regression scenario protocol (hypoid/regress.py: 60 mesh cycles to settle, 20
recorded); mu is the load-weighted mean over the pairs, P_loss the mean mesh friction loss."""

import argparse
import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1]))

from hypoid.instance import SPEED_KEY, Instance  # noqa: E402
from hypoid.regress import run_scenario  # noqa: E402

OILS = {1: "OS265962", 2: "OS265963"}
RECOMMENDED = {"roelands_z": "exact", "shear_pressure": "hertz", "Lambda_cap": 0.075}
SPEEDS = (1000.0, 2000.0, 5000.0)
TORQUES = (50.0, 300.0)


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--fmu", default="build/HypoidGearPair.fmu")
    args = ap.parse_args(argv)
    inst = Instance(args.fmu)
    print("| oil | rpm | N·m | μ paper | μ recommended | P_loss paper [W] | P_loss recommended [W] "
          "| ΔP_loss / P_loss | η paper | η recommended |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for lub, oil in OILS.items():
        for rpm in SPEEDS:
            for T in TORQUES:
                point = {"lubricant": lub, "T_s": T, SPEED_KEY: rpm}
                a = run_scenario(inst, {**point, "friction_preset": "paper"})
                b = run_scenario(inst, {**point, **RECOMMENDED})
                dP = b["P_loss_mean_W"] / a["P_loss_mean_W"] - 1.0
                print(f"| {oil} | {rpm:.0f} | {T:.0f} | {a['mu_mean']:.4f} | {b['mu_mean']:.4f} "
                      f"| {a['P_loss_mean_W']:.1f} | {b['P_loss_mean_W']:.1f} | {100 * dP:+.0f} % "
                      f"| {a['eta_rms']:.4f} | {b['eta_rms']:.4f} |", flush=True)


if __name__ == "__main__":
    main(sys.argv[1:])
