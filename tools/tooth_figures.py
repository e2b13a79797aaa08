"""Figures and tables of the loaded tooth contact analysis (docs/physics.md §10.8):
docs/figures/km_torque.png (k_m and k_t per torque level, both flanks, each built-in set, with
ISO 10300's full-contact k_n and the calibrated k_m0) and docs/figures/km_effect.png (what the
loaded stiffness level does to efficiency and DTE at 2000 rpm x 50/300 N·m, through the FMU's
k_m_scale set to the loaded tangent level, and with the layered gear-set files of `hypoid tca
surrogate --loaded`, whose mesh force the FMU takes from the loaded contact law). The effect table is the record
docs/records/km-effect (its data km-effect.json; hypoid.records.tooth_data writes the page).

    python tools/tooth_figures.py [--fmu build/HypoidGearPair.fmu] [--out docs/figures]
"""

import argparse
import json
import pathlib
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from hypoid.records.registry import FOLDER, RECORDS  # noqa: E402
from hypoid.tca import gearsets as tca
from hypoid.tca import loaded as tl  # noqa: E402
from hypoid.tca.gearset_file import write_gearset  # noqa: E402
from hypoid.tca import surrogate as sur  # noqa: E402

ROOT = pathlib.Path(__file__).resolve().parents[1]
EFFECT = FOLDER / "km-effect.json"
SETS = (1, 2, 3)
POINT_RPM, POINT_TORQUES = 2000.0, (50.0, 300.0)


def stiffness_table():
    """{(set, flank): [LoadedMesh per torque of tl.TORQUES]}."""
    return {(n, f): meshes for n in SETS
            for f, meshes in tl.loaded_flanks(sur.TABLE_1[n]).items()}


def km_at(meshes, torque, which="k_m"):
    """Mean stiffness at a torque, interpolated in log-log between the levels [N/m]: the secant
    k_m or the tangent k_t."""
    T = np.log([m.torque for m in meshes])
    k = np.log([getattr(m, which).mean() for m in meshes])
    return float(np.exp(np.interp(np.log(torque), T, k)))


def plot_stiffness(table, out):
    fig, axes = plt.subplots(1, 3, figsize=(12, 3.8), sharey=True)
    for ax, n in zip(axes, SETS):
        gs = sur.GearSet(sur.TABLE_1[n])
        for f, style in (("drive", "-"), ("coast", "--")):
            meshes = table[(n, f)]
            T = [m.torque for m in meshes]
            ax.plot(T, [m.k_m.mean() / 1e8 for m in meshes], "o" + style, color="C0",
                    label=f"k_m secant, {f}")
            ax.fill_between(T, [m.k_m.min() / 1e8 for m in meshes],
                            [m.k_m.max() / 1e8 for m in meshes], color="C0",
                            alpha=0.12 if f == "drive" else 0.05)
            ax.plot(T, [m.k_t.mean() / 1e8 for m in meshes], "s" + style, color="C1",
                    label=f"k_t tangent, {f}")
        ax.axhline(gs.k_n / 1e8, color="k", lw=0.8, ls=":", label="ISO 10300 k_n (full contact)")
        ax.axhline(gs.k_m0 / 1e8, color="C3", lw=0.8, label="calibrated k_m0")
        ax.set_xscale("log")
        ax.set_xticks(tl.TORQUES, [f"{t:g}" for t in tl.TORQUES])
        ax.minorticks_off()
        ax.set_xlabel("pinion torque [N·m]")
        ax.set_title(f"set {n}: contact ratio {table[(n, 'drive')][0].contact_ratio:.2f}"
                     f" → {table[(n, 'drive')][-1].contact_ratio:.2f}")
    axes[0].set_ylabel("mesh stiffness [10⁸ N/m]")
    axes[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out / "km_torque.png", dpi=90)


def operating_point(gear, n, torque, data):
    """eta_cycle, P_loss_cycle and the DTE peak to peak over the last 4 mesh cycles [1, W, m];
    data: the tooth-data parameters (k_m_scale, or a gear_set_file)."""
    gear.start({"gear_set": n, "load_mode": "speed", "T_s": torque, "speed_rpm": POINT_RPM,
                "n_avg_cycles": 20, **data})
    while gear.t < 0.3 - 1e-9:
        gear.step(0.01)
    period = 60.0 / (POINT_RPM * sur.TABLE_1[n].N_p)
    dte = []
    for _ in range(200):
        gear.step(4 * period / 200)
        dte.append(gear.get("DTE"))
    return gear.get("eta_cycle"), gear.get("P_loss_cycle"), float(np.ptp(dte))


def one_series():
    """The start values that select the one-series tooth data of a built-in set (calibrated
    k_m0): `tooth_data = paper` where the FMU has that choice, else its built-in files."""
    from hypoid.fmu import variables
    return {"tooth_data": "paper"} if "tooth_data" in variables.VARIABLES else {}


def effect_table(table, fmu):
    """Per set and torque: the k_m_scale of the loaded level and the operating point with the
    one-series data, with that scale, and with the layered file of both flanks and five levels."""
    from hypoid.fmu.instance import Instance
    gear = Instance(fmu)
    base = one_series()
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        for n in SETS:
            k_m0 = sur.GearSet(sur.TABLE_1[n]).k_m0
            layered = pathlib.Path(tmp) / f"gearset{n}_loaded.txt"
            write_gearset(layered, tca.loaded_surrogate(n))
            for torque in POINT_TORQUES:
                scale = km_at(table[(n, "drive")], torque, "k_t") / k_m0
                rows.append((n, torque, scale, operating_point(gear, n, torque, base),
                             operating_point(gear, n, torque, {**base, "k_m_scale": scale}),
                             operating_point(gear, n, torque, {"gear_set_file": str(layered)})))
    return rows


def plot_effect(rows, out):
    fig, ax = plt.subplots(1, 2, figsize=(10, 3.6))
    labels = [f"set {n}\n{t:g} N·m" for n, t, *_ in rows]
    x = np.arange(len(rows))
    for i, (what, unit, scale) in enumerate((("P_loss_cycle", "W", 1.0),
                                             ("DTE peak to peak", "µm", 1e6))):
        j = 1 if i == 0 else 2
        for k, label in enumerate(("built-in (k_m0 calibrated)", "k_m_scale = k_t(T)/k_m0",
                                   "layered file (both flanks, 5 levels)")):
            ax[i].bar(x + 0.27 * (k - 1), [r[3 + k][j] * scale for r in rows], 0.27, label=label)
        ax[i].set_xticks(x, labels, fontsize=7)
        ax[i].set_ylabel(f"{what} [{unit}]")
    ax[0].legend(fontsize=7)
    fig.suptitle(f"{POINT_RPM:g} rpm: the mesh stiffness level of §10.8 against the calibrated one")
    fig.tight_layout()
    fig.savefig(out / "km_effect.png", dpi=90)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--fmu", default=str(ROOT / "build" / "HypoidGearPair.fmu"))
    ap.add_argument("--out", default=str(ROOT / "docs" / "figures"))
    args = ap.parse_args()
    out = pathlib.Path(args.out)
    table = stiffness_table()
    plot_stiffness(table, out)
    print("| set | flank | " + " | ".join(f"{t:g} N·m" for t in tl.TORQUES) + " |")
    for (n, f), meshes in table.items():
        print(f"| {n} | {f} k_m / k_t [10⁸ N/m], ε | " + " | ".join(
            f"{m.k_m.mean() / 1e8:.2f} / {m.k_t.mean() / 1e8:.2f}, {m.contact_ratio:.2f}"
            for m in meshes) + " |")
    rows = effect_table(table, args.fmu)
    plot_effect(rows, out)
    EFFECT.write_text(json.dumps({"rows": rows, "one_series": one_series()}, indent=1) + "\n")
    (FOLDER / "km-effect.md").write_text(RECORDS["km-effect"].write())
    return 0


if __name__ == "__main__":
    sys.exit(main())
