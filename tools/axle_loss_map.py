"""The axle's loss map (hypoid.maps.lossmap): the parts of P_axle (mesh, churning, bearings, seals)
and eta_axle over pinion speed x input torque at fixed oil temperatures. Writes
docs/figures/axle_loss_map.png and the record docs/records/axle-loss-map (its data and page: the
table at 1000, 2000, 4000 rpm x 0, 50, 200 N·m).

  .venv/bin/python tools/axle_loss_map.py [--temps 40 80] [--speeds 500 1000 2000 3000 4000]
                                          [--torques 0 25 50 100 200]"""

import argparse
import datetime
import json
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from hypoid.fmu import parallel  # noqa: E402
from hypoid.maps import lossmap  # noqa: E402
from hypoid.records.docblocks import commit  # noqa: E402
from hypoid.records.registry import FOLDER, RECORDS  # noqa: E402
from hypoid.study import plots  # noqa: E402

TABLE_SPEEDS, TABLE_TORQUES = (1000.0, 2000.0, 4000.0), (0.0, 50.0, 200.0)  # the record's table


def record(lm):
    """The record's data: the map's table at TABLE_SPEEDS x TABLE_TORQUES."""
    rows = lm[lm["speed_rpm"].isin(TABLE_SPEEDS) & lm["T_s"].isin(TABLE_TORQUES)]
    lines = lossmap.markdown(rows).splitlines()
    cells = [[c.strip() for c in line.strip("|").split("|")] for line in lines]
    text = ("Gear set 1, OS265962, the FMU's defaults with `axle_losses = full`: steady states "
            "of `hypoid.maps.lossmap` (speed governor, rigid mesh, `ehl_thermal`, the oil held at "
            "40 and 80 °C). At `T_s = 0` no power enters, so `eta_axle` is 0 by definition (the "
            "governor supplies the spin loss from the wheel side). The figure over the whole "
            "grid is [axle_loss_map.png](../figures/axle_loss_map.png).")
    return {"provenance": f"Recorded on {commit(ROOT)}, {datetime.date.today().isoformat()}.",
            "sections": [{"text": text},
                         {"table": {"columns": cells[0], "rows": cells[2:]}}]}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--temps", type=float, nargs="+", default=[40.0, 80.0])
    ap.add_argument("--speeds", type=float, nargs="+", default=[500, 1000, 2000, 3000, 4000])
    ap.add_argument("--torques", type=float, nargs="+", default=[0, 25, 50, 100, 200])
    ap.add_argument("--png", default=str(ROOT / "docs" / "figures" / "axle_loss_map.png"))
    args = ap.parse_args()
    fmu = parallel.FmuRef(ROOT / "build" / "HypoidGearPair.fmu")
    lm = lossmap.run(fmu, args.temps, args.speeds, args.torques)
    png = pathlib.Path(args.png)
    plots.axle_loss_map(lm, png.parent, png.stem)
    print(lossmap.markdown(lm))
    (FOLDER / "axle-loss-map.json").write_text(json.dumps(record(lm), indent=1,
                                                          ensure_ascii=False) + "\n")
    (FOLDER / "axle-loss-map.md").write_text(RECORDS["axle-loss-map"].write())


if __name__ == "__main__":
    main()
