#!/usr/bin/env python3
"""A 1 s scene from t = 0 at 1 ms steps through fmpy, reading every output after each step, as
Simulink ports, libcosim observers and result files do: the full level at the FMU's start values
(2000 rpm, 100 N·m, 40 °C, the speed governor). Each run is a fresh process (its first instance
pays for its start: loading the binary, the shipped tables, the tables it must solve) followed
by a second instance in the same process; CPU split into the start (instantiate → initialised),
fmi2DoStep and the reads (fmi2GetReal, fmi2GetInteger), all through fmpy's FMU2Slave. Medians
over --processes processes, the two read sets alternating. Prints the table and writes the record docs/records/fmpy-outputs.

    .venv/bin/python bench/fmpy_outputs.py                  # about 15 s
    .venv/bin/python bench/fmpy_outputs.py --processes 3 --no-record
"""

import argparse
import datetime
import json
import os
import pathlib
import statistics
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from hypoid.fmu.instance import unzipped  # noqa: E402
from hypoid.records.docblocks import commit  # noqa: E402
from hypoid.records.registry import FOLDER, RECORDS  # noqa: E402

H = 1e-3           # s, the communication step
STOP = 1.0         # s, the scene's length
READS = {"every output": None, "w_p only": ["w_p"]}  # None: every Real and Integer output
COLUMNS = ["outputs read after each step", "instance", "real-time factor", "CPU [ms]",
           "start [ms]", "fmi2DoStep [ms]", "reads [ms]"]


def scene(fmpy_slave, md, directory, reals, ints):
    """One instance through the scene: CPU seconds of the start, the steps and the reads (the
    Real outputs `reals`, then the Integer ones `ints` if any)."""
    clock = time.process_time
    t0 = clock()
    s = fmpy_slave(guid=md.guid, unzipDirectory=directory,
                   modelIdentifier=md.coSimulation.modelIdentifier, instanceName="gear")
    s.instantiate()
    s.setupExperiment(startTime=0.0)
    s.enterInitializationMode()
    s.exitInitializationMode()
    start = clock() - t0
    stepping = reading = 0.0
    for k in range(int(round(STOP / H))):
        a = clock()
        s.doStep(k * H, H)
        b = clock()
        s.getReal(reals)
        if ints:
            s.getInteger(ints)
        reading += clock() - b
        stepping += b - a
    s.terminate()
    s.freeInstance()
    return {"start": start, "step": stepping, "read": reading, "total": clock() - t0}


def child(directory, read):
    """The body of one process: the first instance, then a second one."""
    from fmpy import read_model_description
    from fmpy.fmi2 import FMU2Slave
    md = read_model_description(directory)
    outputs = [v for v in md.modelVariables if v.causality == "output"
               and (READS[read] is None or v.name in READS[read])]
    reals = [v.valueReference for v in outputs if v.type == "Real"]
    ints = [v.valueReference for v in outputs if v.type == "Integer"]
    runs = [scene(FMU2Slave, md, directory, reals, ints) for _ in range(2)]
    print(json.dumps({"n": len(reals) + len(ints), "runs": runs}))


def measure(directory, read):
    out = subprocess.run([sys.executable, __file__, "--child", str(directory), read],
                         capture_output=True, text=True, check=True).stdout
    return json.loads(out)


def rows_of(results):
    rows = []
    for read, runs in results.items():
        for i, label in enumerate(["first of the process", "second in the process"]):
            med = {k: statistics.median(r["runs"][i][k] for r in runs)
                   for k in ("total", "start", "step", "read")}
            rows.append([f"{read} ({runs[0]['n']})", label, f"{STOP / med['total']:.1f}",
                         f"{1e3 * med['total']:.1f}", f"{1e3 * med['start']:.1f}",
                         f"{1e3 * med['step']:.1f}", f"{1e3 * med['read']:.1f}"])
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--fmu", default=str(ROOT / "build" / "HypoidGearPair.fmu"))
    ap.add_argument("--processes", type=int, default=7)
    ap.add_argument("--no-record", action="store_true", help="print the table only")
    ap.add_argument("--child", nargs=2, metavar=("DIR", "READ"), help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.child:
        return child(*args.child)
    directory = unzipped(args.fmu)
    load_before = os.getloadavg()[0]
    results = {read: [] for read in READS}
    for _ in range(args.processes):
        for read in READS:
            results[read].append(measure(directory, read))
    rows = rows_of(results)
    load = (f"load average (1 min) {load_before:.1f} → {os.getloadavg()[0]:.1f} on "
            f"{os.cpu_count()} CPUs")
    text = (f"The full level at the FMU's start values from t = 0 to {STOP:g} s at "
            f"{1e3 * H:g} ms steps through fmpy's FMU2Slave (`python bench/fmpy_outputs.py`), "
            "each process's first instance and a second one after it; CPU of the whole run "
            "(instantiation included), of the start (instantiate → initialised), of the "
            "fmi2DoStep calls and of the reads (fmi2GetReal, and fmi2GetInteger for the Integer "
            "outputs; fmpy's own Python included); medians of "
            f"{args.processes} processes per row, the read sets' processes alternating; {load}.")
    print("| " + " | ".join(COLUMNS) + " |")
    for r in rows:
        print("| " + " | ".join(r) + " |")
    if args.no_record:
        return 0
    data = {"provenance": f"Measured on {commit(ROOT)}, {datetime.date.today().isoformat()}.",
            "sections": [{"text": text}, {"table": {"columns": COLUMNS, "rows": rows}}]}
    (FOLDER / "fmpy-outputs.json").write_text(json.dumps(data, indent=1, ensure_ascii=False)
                                              + "\n")
    (FOLDER / "fmpy-outputs.md").write_text(RECORDS["fmpy-outputs"].write())
    return 0


if __name__ == "__main__":
    sys.exit(main())
