"""The axle's loss map (hypoid.maps.lossmap): the parts of P_axle (mesh, churning, bearings, seals)
and eta_axle over pinion speed x input torque at fixed oil temperatures. Writes
docs/figures/axle_loss_map.png and prints a markdown table (docs/axle.md).

  .venv/bin/python tools/axle_loss_map.py [--temps 40 80] [--speeds 500 1000 2000 3000 4000]
                                          [--torques 0 25 50 100 200]"""

import argparse
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from hypoid.maps import lossmap  # noqa: E402
from hypoid.fmu import parallel
from hypoid.study import plots


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


if __name__ == "__main__":
    main()
