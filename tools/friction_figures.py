"""mu and P_loss of the full model, the paper's EHL choices against the FMU's defaults, at
1000/2000/5000 rpm x 50/300 N.m for both built-in oils, beside the mean gear friction
coefficient of the FZG gear-test correlation (docs/friction-evidence.md):

    .venv/bin/python tools/friction_figures.py [--fmu build/HypoidGearPair.fmu]
        [--before friction_preset=paper]

--before names the settings of the "before" column (default: the paper's friction on the
default tooth data; preset=paper: the whole paper against the defaults), --after those of the
"after" column (default: none, the FMU's defaults); `--before tooth_data=paper --after
tooth_data=loaded` gives what the loaded tooth data change (docs/physics.md §10.8).
The last row is the worked example's operating point (docs/physics.md §12: OS265962, 2000 rpm,
100 N·m).

    .venv/bin/python tools/friction_figures.py --record friction-defaults
    .venv/bin/python tools/friction_figures.py --before tooth_data=paper --after tooth_data=loaded \
        --record friction-tooth-data

--record NAME keeps the table as the record docs/records/NAME (its data NAME.json;
hypoid.records.tooth_data writes the page).

Each point: the regression scenario protocol (hypoid/regress.py: 60 mesh cycles to settle, 20
recorded, 40 degC bath, gear set 1); mu is the load-weighted mean over the pairs, P_loss the mean
mesh friction loss; mu_mZ is Schlenk's correlation of FZG power-loss measurements as ISO/TR
14179-2 gives it, mu_mZ = 0.048 (w / (v_sum rho_red))^0.2 eta_oil^-0.05 Ra^0.25 X_L, evaluated
for set 1's virtual cylindrical gear (X_L = 1, mineral oil)."""

import argparse
import datetime
import json
import math
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from hypoid.records import docblocks  # noqa: E402
from hypoid.records.registry import FOLDER, RECORDS  # noqa: E402
from hypoid.fmu.instance import SPEED_KEY, Instance  # noqa: E402
from hypoid.regress import run_scenario  # noqa: E402

OILS = {1: "OS265962", 2: "OS265963"}
SPEEDS = (1000.0, 2000.0, 5000.0)
TORQUES = (50.0, 300.0)
WORKED = (1, 2000.0, 100.0)  # lubricant, rpm, N·m of the worked example (physics.md §12)

# Set 1 for the correlation (resources/gearsets/gearset1.txt header; docs/physics.md §10.2):
R_P0 = 21.009e-3      # [m] lever arm of the normal force, W_t = T_s / R_p0
BETA_VB = 34.26       # [deg] base helix angle of the virtual gear: F_bt = W_t cos(beta_vb)
B_V_EFF = 24.09       # [mm] effective face width of the virtual gear
RHO_RED = 17.65       # [mm] relative radius of curvature at the pitch point
U_E_PER_RPM = 3.34 / 2000.0  # [m/s per rpm] load-weighted entrainment relative to the moving
                             # contact point in the running model (set 1, 2000 rpm: 3.34 m/s)
ETA_OIL_40C = 85.6    # [mPa.s] both oils at the 40 degC bath: KV40 100 mm^2/s, rho 856 kg/m^3
RA = 0.2              # [um] arithmetic roughness of each flank (sigma_s = 0.25 um RMS, Gaussian)


def mu_mz(T_s, rpm, X_L=1.0):
    """ISO/TR 14179-2's mean coefficient of friction of the mesh (Schlenk 1994)."""
    w = T_s / R_P0 * math.cos(math.radians(BETA_VB)) / B_V_EFF  # [N/mm]
    v_sum = 2.0 * U_E_PER_RPM * rpm                               # [m/s]
    return 0.048 * (w / (v_sum * RHO_RED)) ** 0.2 * ETA_OIL_40C ** -0.05 * RA ** 0.25 * X_L


def points():
    """(lubricant, rpm, N·m) of the table: both oils at SPEEDS x TORQUES, then WORKED."""
    return [(lub, rpm, T) for lub in OILS for rpm in SPEEDS for T in TORQUES] + [WORKED]


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--fmu", default="build/HypoidGearPair.fmu")
    ap.add_argument("--before", nargs="+", default=["friction_preset=paper"],
                    metavar="NAME=VALUE", help="the settings of the 'before' column")
    ap.add_argument("--after", nargs="+", default=[], metavar="NAME=VALUE",
                    help="the settings of the 'after' column (default: the FMU's defaults)")
    ap.add_argument("--record", choices=[n for n in RECORDS if n.startswith("friction-")],
                    help="keep the table as this record (docs/records/NAME.json and .md)")
    args = ap.parse_args(argv)
    before, after = (dict(item.split("=", 1) for item in a) for a in (args.before, args.after))
    label = "paper" if before == {"friction_preset": "paper"} else " ".join(args.before)
    new = " ".join(args.after) or "default"
    inst = Instance(args.fmu)
    print(f"| oil | rpm | N·m | μ {label} | μ {new} | μ_mZ ISO/TR 14179-2 | P_loss {label} [W] "
          f"| P_loss {new} [W] | ΔP_loss / P_loss | η {label} | η {new} |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    rows = []
    for lub, rpm, T in points():
        point = {"lubricant": lub, "T_s": T, SPEED_KEY: rpm}
        a = run_scenario(inst, {**point, **before})
        b = run_scenario(inst, {**point, **after})
        rows.append({"lubricant": lub, "rpm": rpm, "T_s": T, "mu_mZ": mu_mz(T, rpm),
                     "before": a, "after": b})
        dP = b["P_loss_mean_W"] / a["P_loss_mean_W"] - 1.0
        print(f"| {OILS[lub]} | {rpm:.0f} | {T:.0f} | {a['mu_mean']:.4f} | {b['mu_mean']:.4f} "
              f"| {mu_mz(T, rpm):.4f} | {a['P_loss_mean_W']:.1f} "
              f"| {b['P_loss_mean_W']:.1f} | {100 * dP:+.1f} % "
              f"| {a['eta_rms']:.4f} | {b['eta_rms']:.4f} |", flush=True)
    inst.close()
    if args.record:
        rec = {"before": " ".join(args.before), "after": " ".join(args.after), "rows": rows,
               "commit": docblocks.commit(ROOT), "recorded": datetime.date.today().isoformat()}
        (FOLDER / f"{args.record}.json").write_text(json.dumps(rec, indent=1) + "\n")
        (FOLDER / f"{args.record}.md").write_text(RECORDS[args.record].write())
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
