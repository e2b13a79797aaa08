"""The axle's loss map: the parts of P_axle (mesh, churning, bearings, seals) and eta_axle over
pinion speed x input torque at fixed oil temperatures, from steady runs of the FMU (speed
governor, rigid mesh, ehl_thermal, axle_losses = full). Writes docs/figures/axle_loss_map.png and
prints a markdown table (docs/axle.md).

  .venv/bin/python tools/axle_loss_map.py [--temps 40 80] [--speeds 500 1000 2000 3000 4000]
                                          [--torques 0 25 50 100 200]"""

import argparse
import pathlib
import sys

import numpy as np

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from hypoid.instance import Instance  # noqa: E402

PARTS = [("mesh", "P_loss"), ("churning", "P_churn"), ("bearings", "P_bearings"),
         ("seals", "P_seals")]


def point(inst, rpm, torque, T_oil):
    inst.start({"axle_losses": "full", "mesh_model": "rigid", "friction_model": "ehl_thermal",
                "speed_rpm": rpm, "T_s": torque, "T_bath": T_oil + 273.15, "rtol": 1e-6})
    names = [n for _, n in PARTS] + ["P_in_axle", "eta_axle"]
    rows = inst.record(0.6, 0.02, names)
    return dict(zip(names, rows[-10:].mean(axis=0)))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--temps", type=float, nargs="+", default=[40.0, 80.0])
    ap.add_argument("--speeds", type=float, nargs="+", default=[500, 1000, 2000, 3000, 4000])
    ap.add_argument("--torques", type=float, nargs="+", default=[0, 25, 50, 100, 200])
    ap.add_argument("--png", default=str(ROOT / "docs" / "figures" / "axle_loss_map.png"))
    args = ap.parse_args()
    res = {}
    with Instance(ROOT / "build" / "HypoidGearPair.fmu", name="lossmap") as inst:
        for T in args.temps:
            for n in args.speeds:
                for tq in args.torques:
                    res[T, n, tq] = point(inst, n, tq, T)
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(len(args.temps), len(args.torques), figsize=(3 * len(args.torques),
                             3.2 * len(args.temps)), sharex=True, squeeze=False)
    for i, T in enumerate(args.temps):
        for j, tq in enumerate(args.torques):
            ax = axes[i][j]
            bottom = np.zeros(len(args.speeds))
            for k, (label, name) in enumerate(PARTS):
                y = np.array([res[T, n, tq][name] for n in args.speeds])
                ax.bar(range(len(args.speeds)), y, bottom=bottom, color=f"C{k}", label=label)
                bottom += y
            ax.set_title(f"{T:.0f} °C, T_s = {tq:.0f} N·m", fontsize=9)
            ax.set_xticks(range(len(args.speeds)), [f"{n:.0f}" for n in args.speeds],
                          fontsize=8)
            if j == 0:
                ax.set_ylabel("loss power (W)")
            if i == len(args.temps) - 1:
                ax.set_xlabel("pinion speed (rpm)")
    axes[0][0].legend(fontsize=8)
    fig.suptitle("Axle losses by part (gear set 1, OS265962, rigid mesh, oil at fixed T)")
    fig.tight_layout()
    fig.savefig(args.png, dpi=100)
    print("| oil °C | rpm | T_s N·m | mesh W | churning W | bearings W | seals W | eta_axle % |")
    print("|---|---|---|---|---|---|---|---|")
    for (T, n, tq), r in res.items():
        print(f"| {T:.0f} | {n:.0f} | {tq:.0f} | " + " | ".join(f"{r[name]:.1f}" for _, name in
                                                              PARTS)
              + f" | {100 * r['eta_axle']:.2f} |")


if __name__ == "__main__":
    main()
