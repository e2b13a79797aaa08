#!/usr/bin/env python3
"""What each fidelity level costs and how accurate it is at the FMU's defaults, measured into the
record docs/records/level-table.json (hypoid.records.level_table writes its page).

    .venv/bin/python bench/level_table.py     # measure (about 5 min), write the data and the page

Costs: the C host (build/bench_fmu, no Python in the loop), 2000 rpm, 100 N.m, 40 degC, the six
usual outputs read after every step, medians of --runs batches of --cpu s CPU: every level at
1 ms steps with the defaults and with cvode_bdf in one run (batches interleaved), then at 0.1 s
steps. Errors: each level at its defaults against its own CVODE BDF rtol 1e-10 solution in the
five work-precision scenes (bench/wp_driver.py): the worst |d eta_E| and |d eta_cycle| [%-point],
|d DTE p-p| [um] (compliant meshes) and the worst energy-audit residual relative to the energy
through the gear.
"""

import argparse
import datetime
import json
import os
import pathlib
import re
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
from hypoid.records.level_table import TITLES  # noqa: E402
from hypoid.records.registry import FOLDER, RECORDS  # noqa: E402

DATA = FOLDER / "level-table.json"
SOURCES = ["fmu-src", "modelDescription", "resources", "CMakeLists.txt", "cmake", "scripts",
           "tests/host", "bench"]  # what the measured binaries and the benchmark are made of


# ------------------------------------------------------------------ measurement


def bench_rows(command):
    """The rows of bench_fmu's levels table: {(level, variant): real-time factor}."""
    out = subprocess.run(command, check=True, capture_output=True, text=True).stdout
    rows = {}
    for line in out.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) == 8 and cells[0] in TITLES:
            rows[(cells[0], cells[1])] = float(cells[2])
    return rows


def costs(bench, fmu_dir, runs, cpu):
    common = ["--runs", str(runs), "--cpu", str(cpu)]
    at_1ms = [bench, fmu_dir, "levels", *common, "--variant", "defaults:",
              "--variant", "cvode_bdf:solver=cvode_bdf"]
    at_100ms = [bench, fmu_dir, "levels", "--h", "0.1", *common]
    fast, slow = bench_rows(at_1ms), bench_rows(at_100ms)
    figures = {lv: dict(rtf_1ms=fast[(lv, "defaults")], rtf_1ms_bdf=fast[(lv, "cvode_bdf")],
                        rtf_100ms=slow[(lv, "this FMU")]) for lv in TITLES}
    rel = [os.path.relpath(c, ROOT) if os.path.isabs(c) else c for c in at_1ms + at_100ms]
    n = len(at_1ms)
    return figures, [" ".join(_quote(c) for c in rel[:n]), " ".join(_quote(c) for c in rel[n:])]


def _quote(word):
    return f"'{word}'" if re.search(r"[\s()]", word) else word


def errors(fmu_path):
    """Per level and scene: the defaults' metrics and those of the level's own tight solution."""
    sys.path.insert(0, str(ROOT / "bench"))
    import wp_driver as W

    fmu = W.Fmu(fmu_path)

    def metrics(scene, level, setting):
        _, recs, counters = W.timed_run(fmu, scene, level, setting)
        out = W.coarse_metrics(scene, recs, counters)
        if W.LEVELS[level].get("mesh_model") not in ("rigid", 3):
            out.update(W.fine_metrics(scene, *W.fine_run(fmu, scene, level, setting)))
        return out

    result = {}
    for level in TITLES:
        result[level] = {}
        for key, scene in W.scenes().items():
            print(f"  {level} / {key}", flush=True)
            result[level][key] = dict(defaults=metrics(scene, level, W.DEFAULT),
                                      tight=metrics(scene, level, W.REFERENCE))
    return result


def worst(per_scene):
    """The worst errors over the scenes, in the table's units."""
    def d(name, factor):
        vals = [abs(s["defaults"][name] - s["tight"][name]) * factor
                for s in per_scene.values() if name in s["defaults"]]
        return max(vals) if vals else None
    return dict(eta_E_pt=d("eta_E", 100.0), eta_cycle_pt=d("eta_cycle", 100.0),
                dte_pp_um=d("dte_pp", 1e6),
                energy_residual=max(s["defaults"]["energy_residual"] for s in per_scene.values()))


def git(*args):
    return subprocess.run(["git", "-C", str(ROOT), *args], capture_output=True,
                          text=True).stdout.strip()


def measure(args):
    fmu_dir = str(ROOT / "build" / "fmu")
    figures, commands = costs(args.bench, fmu_dir, args.runs, args.cpu)
    per_scene = errors(args.fmu)
    levels = {lv: dict(solver="cvode_bdf" if lv in ("rigid", "map") else "arkode_erk",
                       **figures[lv], **worst(per_scene[lv]), scenes=per_scene[lv])
              for lv in TITLES}
    return dict(meta=dict(commit=git("rev-parse", "--short", "HEAD"),
                          dirty=bool(git("status", "--porcelain", "--untracked-files=no",
                                         "--", *SOURCES)),
                          date=datetime.date.today().isoformat(),
                          load_average=round(os.getloadavg()[0], 1),
                          cost_commands=commands,
                          error_command="bench/level_table.py (bench/wp_driver.py scenes)"),
                levels=levels)


def bench_parser(doc):
    """The options of a benchmark that times the C host: the FMU, bench_fmu, the timed batches."""
    ap = argparse.ArgumentParser(description=doc.splitlines()[0])
    ap.add_argument("--fmu", default=str(ROOT / "build" / "HypoidGearPair.fmu"))
    ap.add_argument("--bench", default=str(ROOT / "build" / "bench_fmu"))
    ap.add_argument("--runs", type=int, default=3, help="timed batches per variant")
    ap.add_argument("--cpu", type=float, default=0.2, help="CPU seconds per batch")
    return ap


def main():
    args = bench_parser(__doc__).parse_args()
    for path in (args.fmu, args.bench):
        if not os.path.exists(path):
            print(f"level_table: {path} is missing (build first: scripts/setup.sh)")
            return 2
    DATA.write_text(json.dumps(measure(args), indent=1) + "\n")
    (FOLDER / "level-table.md").write_text(RECORDS["level-table"].write())
    return 0


if __name__ == "__main__":
    sys.exit(main())
