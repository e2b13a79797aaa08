#!/usr/bin/env python3
"""linux64 and win64 binaries of the FMU on the same calls: every Real variable after the same
run, compared bit for bit (docs/portability.md). Both binaries carry musl's math and the same
SUNDIALS sources built with the same flags, so they must agree exactly: a variable that differs
fails the check, and the relative differences are printed.

    compare.py --fmu-dir DIR --linux-host run_fmu --win-host run_fmu.exe --wine wine64

DIR is the unzipped FMU (binaries/linux64 and binaries/win64); the hosts are tests/host/run_fmu.c
built for each platform (scripts/win64.sh test). Exit status 1 when a case fails."""

import argparse
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

T_END = 0.1
CASES = {  # name -> NAME=VALUE settings (a last "me": Model Exchange, the host's Euler steps)
    "defaults (full model, rtol 1e-6)": [],
    "rtol 1e-10, atol 1e-14": ["rtol=1e-10", "atol=1e-14"],
    "load_mode = torque, isothermal EHL": ["load_mode=torque", "friction_model=ehl_isothermal"],
    "newmark, mean mesh": ["solver=newmark", "mesh_model=mean"],
    "axle losses and oil sump": ["axle_losses=full", "thermal_model=sump"],
    "Model Exchange, defaults": ["me"],
    "Model Exchange, axle losses and oil sump": ["axle_losses=full", "thermal_model=sump", "me"],
}
T_END_ME = 0.02  # Model Exchange: 20 000 Euler steps of 1 us


def run(cmd):
    out = subprocess.run(cmd, capture_output=True, text=True, env=dict(os.environ, WINEDEBUG="-all"))
    if out.returncode:
        sys.exit(f"compare: {' '.join(cmd)} failed ({out.returncode}): {out.stderr.strip()}")
    values = {}
    for line in out.stdout.splitlines():
        vr, hexa, _ = line.split()
        values[int(vr)] = float.fromhex(hexa)
    return values


def windows_path(path):
    return "Z:" + os.path.abspath(path).replace("/", "\\")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--fmu-dir", required=True)
    ap.add_argument("--linux-host", required=True)
    ap.add_argument("--win-host", required=True)
    ap.add_argument("--wine", required=True)
    args = ap.parse_args()
    root = ET.parse(os.path.join(args.fmu_dir, "modelDescription.xml")).getroot()
    names = {int(v.get("valueReference")): v.get("name") for v in root.iter("ScalarVariable")}
    failed = False
    for case, settings in CASES.items():
        t_end = T_END_ME if settings[-1:] == ["me"] else T_END
        lin = run([args.linux_host, args.fmu_dir, "outputs", str(t_end)] + settings)
        win = run([args.wine, args.win_host, windows_path(args.fmu_dir), "outputs", str(t_end)]
                  + settings)
        if lin.keys() != win.keys() or not lin:
            sys.exit("compare: the two runs report different variables")
        differ = {vr: abs(win[vr] - lin[vr]) / max(abs(lin[vr]), 1e-300)
                  for vr in lin if lin[vr].hex() != win[vr].hex()}
        print(f"compare: {case}: t = {t_end} s, {len(lin) - len(differ)} of {len(lin)} Real "
              f"variables bit-identical on linux64 and win64"
              + ("" if not differ else "; differing (relative): " + ", ".join(
                  f"{names[vr]} ({d:.1e})" for vr, d in sorted(differ.items(),
                                                              key=lambda x: -x[1])[:8])))
        failed = failed or bool(differ)
    if failed:
        print("compare: FAILED - linux64 and win64 results differ", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
