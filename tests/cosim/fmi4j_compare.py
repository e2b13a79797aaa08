#!/usr/bin/env python3
"""Runs an FMU with fmpy exactly as tests/cosim/fmi4j/Fmi4jCheck.java does (fmi2SetupExperiment
with the stop time, the start values, initialization, fixed steps) and compares the outputs with
the ones FMI4j printed.

    fmi4j_compare.py FMI4J_OUTPUT FMU STOP_TIME STEP [name=value ...]

Exit status 1 when an output differs by more than 1e-9 relative (1e-12 absolute near zero)."""

import sys
import tempfile

from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Slave


def fmpy_outputs(fmu, stop, h, settings):
    md = read_model_description(fmu)
    var = {v.name: v for v in md.modelVariables}
    with tempfile.TemporaryDirectory() as tmp:
        slave = FMU2Slave(guid=md.guid, unzipDirectory=extract(fmu, tmp),
                          modelIdentifier=md.coSimulation.modelIdentifier, instanceName="fmpy")
        slave.instantiate()
        slave.setupExperiment(startTime=0.0, stopTime=stop)
        for name, value in settings.items():
            v = var[name]
            if v.type == "Real":
                slave.setReal([v.valueReference], [float(value)])
            else:
                slave.setInteger([v.valueReference], [int(value)])
        slave.enterInitializationMode()
        slave.exitInitializationMode()
        for k in range(round(stop / h)):
            slave.doStep(k * h, h)
        out = {}
        for v in md.modelVariables:
            if v.causality == "output" and v.type == "Real":
                out[v.name] = slave.getReal([v.valueReference])[0]
            elif v.causality == "output" and v.type == "Integer":
                out[v.name] = slave.getInteger([v.valueReference])[0]
        slave.terminate()
        slave.freeInstance()
    return out


def main():
    if len(sys.argv) < 5:
        sys.exit(__doc__)
    printed, fmu, stop, h = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
    settings = dict(a.split("=", 1) for a in sys.argv[5:])
    fmi4j = {}
    for line in open(printed):
        if line.strip() and not line.startswith("#"):
            name, value = line.split()
            fmi4j[name] = float(value)
    ref = fmpy_outputs(fmu, stop, h, settings)
    if set(ref) != set(fmi4j):
        sys.exit(f"outputs differ: only FMI4j {sorted(set(fmi4j) - set(ref))}, "
                 f"only fmpy {sorted(set(ref) - set(fmi4j))}")
    worst = max(ref, key=lambda n: abs(fmi4j[n] - ref[n]) / max(abs(ref[n]), 1e-3))
    rel = abs(fmi4j[worst] - ref[worst]) / max(abs(ref[worst]), 1e-3)
    print(f"{fmu}: {len(ref)} outputs after {stop} s, FMI4j vs fmpy: largest difference "
          f"{rel:.3g} (relative, {worst}: {fmi4j[worst]!r} vs {ref[worst]!r})")
    return 0 if rel <= 1e-9 else 1


if __name__ == "__main__":
    sys.exit(main())
