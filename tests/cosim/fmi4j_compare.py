#!/usr/bin/env python3
"""Runs an FMU with fmpy exactly as tests/cosim/fmi4j/Fmi4jCheck.java does (fmi2SetupExperiment
with the stop time, the start values, initialization, fixed steps) and compares the outputs with
the ones FMI4j printed.

    fmi4j_compare.py FMI4J_OUTPUT FMU STOP_TIME STEP [name=value ...]

Exit status 1 when an output differs by more than 1e-9 relative (1e-12 absolute near zero)."""

import pathlib
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2]))
from hypoid.fmu.instance import Instance  # noqa: E402


def fmpy_outputs(fmu, stop, h, settings):
    inst = Instance(fmu, name="fmpy")
    inst.start(settings, stop_time=stop)
    for k in range(round(stop / h)):
        inst.do_step(k * h, h)
    out = {name: inst.get(name) for name, v in inst.vars.items()
           if v.causality == "output" and v.type in ("Real", "Integer")}
    inst.close()
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
