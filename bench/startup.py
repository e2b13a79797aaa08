#!/usr/bin/env python3
"""The start of an instance of the full level: instantiate, initialise and the first 10 ms at 1 ms
steps, in the C host (build/bench_fmu startup, no Python in the loop), for the first instance of
a process and for ten further instances kept alive in it (CPU each, resident memory each), as
shipped and with the FMU's resources/tables/ removed (every table then solved), medians over
--processes processes run alternately; and the FMU's size and its tables'. Prints the table and
writes the record docs/records/startup (its data and page).

    .venv/bin/python bench/startup.py             # about 10 s
"""

import argparse
import datetime
import json
import pathlib
import re
import shlex
import shutil
import statistics
import subprocess
import sys
import tempfile
import zipfile

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from hypoid.fmu.instance import unzipped  # noqa: E402
from hypoid.records.docblocks import commit  # noqa: E402
from hypoid.records.registry import FOLDER, RECORDS  # noqa: E402

FURTHER = 10
LINE = re.compile(r"first instance of the process ([\d.]+) ms CPU; \d+ further instances: "
                  r"median ([\d.]+) ms CPU, ([\d.]+) MB resident each")
COLUMNS = ["FMU", "first instance [ms CPU]", "further instance [ms CPU]",
           "further instance [MB resident]"]


def one(bench, fmu_dir):
    out = subprocess.run([bench, str(fmu_dir), "startup", "--runs", str(FURTHER + 1)],
                         capture_output=True, text=True, check=True).stdout
    return tuple(float(x) for x in LINE.search(out).groups())


def sizes(fmu):
    with zipfile.ZipFile(fmu) as z:
        tables = [i for i in z.infolist() if "/tables/" in i.filename and not i.is_dir()]
    return (pathlib.Path(fmu).stat().st_size, len(tables), sum(i.file_size for i in tables),
            sum(i.compress_size for i in tables))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--fmu", default=str(ROOT / "build" / "HypoidGearPair.fmu"))
    ap.add_argument("--bench", default=str(ROOT / "build" / "bench_fmu"))
    ap.add_argument("--processes", type=int, default=9)
    args = ap.parse_args()
    shipped = unzipped(args.fmu)
    with tempfile.TemporaryDirectory() as tmp:
        bare = pathlib.Path(tmp) / "fmu"
        shutil.copytree(shipped, bare)
        shutil.rmtree(bare / "resources" / "tables")
        runs = {"as shipped": [], "without resources/tables/": []}
        for _ in range(args.processes):
            runs["as shipped"].append(one(args.bench, shipped))
            runs["without resources/tables/"].append(one(args.bench, bare))
    rows = []
    for name, figs in runs.items():
        first, further, mb = (statistics.median(f[k] for f in figs) for k in range(3))
        rows.append([name, f"{first:.1f}", f"{further:.2f}", f"{mb:.2f}"])
    size, n, raw, packed = sizes(args.fmu)
    command = shlex.join(["build/bench_fmu", "FMU_DIR", "startup", "--runs", str(FURTHER + 1)])
    text = (f"The full level at the FMU's start values, instantiate → initialise → 10 steps of "
            f"1 ms in the C host (`{command}`): the process's first instance and {FURTHER} "
            f"further ones kept alive, CPU of each and the resident memory each further one "
            f"adds; medians of {args.processes} processes per row, the rows' processes "
            "alternating. Without `resources/tables/` every table is solved as the first "
            "instance needs it.")
    size_text = (f"HypoidGearPair.fmu: {size / 1e6:.2f} MB, of it {n} table files in "
                 f"`resources/tables/`, {raw / 1e6:.2f} MB unpacked, {packed / 1e6:.2f} MB "
                 "zipped.")
    data = {"provenance": f"Measured on {commit(ROOT)}, {datetime.date.today().isoformat()}.",
            "sections": [{"text": text}, {"table": {"columns": COLUMNS, "rows": rows}},
                         {"text": size_text}]}
    print("| " + " | ".join(COLUMNS) + " |")
    for r in rows:
        print("| " + " | ".join(r) + " |")
    print(size_text)
    (FOLDER / "startup.json").write_text(json.dumps(data, indent=1, ensure_ascii=False) + "\n")
    (FOLDER / "startup.md").write_text(RECORDS["startup"].write())
    return 0


if __name__ == "__main__":
    sys.exit(main())
