"""The FMI 3.0 FMU's reference results after the FMI layered standard for references (FMI-LS-REF,
alpha): extra/org.fmi-standard.fmi-ls-ref/ with its manifest, one experiment (start, stop, step),
its start values as an SSP parameter set and the reference CSV. The experiment is the regression's
first scenario (hypoid/regress.py SCENARIOS: the README's default point) run as the regression
runs it (SETTLE_CYCLES + RECORD_CYCLES mesh cycles, 32 communication steps per cycle), so the
same table and run make both; scripts/regenerate.sh regress rewrites both. The reference is the
FMI 2.0 FMU's (the same binary; tests/python/test_fmi3.py checks that the FMI 3.0 FMU
reproduces it).

  .venv/bin/python tools/fmi_ls_ref.py [--fmu build/HypoidGearPair.fmu] [--out extra]"""

import argparse
import csv
import math
import pathlib
import sys
from xml.sax.saxutils import quoteattr

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from hypoid import regress  # noqa: E402
from hypoid.fmu.instance import RPM, SPEED_KEY, Instance  # noqa: E402
from hypoid.fmu.values import TABLE  # noqa: E402

LS_DIR = "extra/org.fmi-standard.fmi-ls-ref"
OUTPUTS = ("w_p", "w_g", "eta", "P_loss", "DTE", "W_t", "T_fp")
SAMPLES_PER_CYCLE = 32
RECORD_EVERY = 8  # a reference row every 8 communication steps (4 per mesh cycle)


def experiment():
    """(name, its start values {variable: value}, step, number of steps)."""
    name, params = next(iter(regress.SCENARIOS.items()))
    inst = Instance(ROOT / "build" / "HypoidGearPair.fmu")
    try:
        n_p = inst.start(params).pinion_teeth()
    finally:
        inst.close()
    starts = {var.name: value for var, value in TABLE.fmu_values(params)}
    step = 2.0 * math.pi / (n_p * params[SPEED_KEY] * RPM) / SAMPLES_PER_CYCLE
    return name, params, starts, step, (regress.SETTLE_CYCLES + regress.RECORD_CYCLES) * SAMPLES_PER_CYCLE


def run(fmu, params, step, n):
    """Rows [t, outputs...] every RECORD_EVERY steps, t = 0 included."""
    inst = Instance(fmu)
    try:
        inst.start(params)
        rows, t = [[0.0] + inst.reals(OUTPUTS)], 0.0
        for i in range(1, n + 1):
            inst.do_step(t, step)
            t = i * step
            if i % RECORD_EVERY == 0:
                rows.append([t] + inst.reals(OUTPUTS))
        return rows
    finally:
        inst.close()


def ssv(name, starts):
    lines = ['<?xml version="1.0" encoding="UTF-8"?>',
             '<ssv:ParameterSet xmlns:ssv="http://ssp-standard.org/SSP1/SystemStructureParameterValues"'
             f' version="1.0" name={quoteattr(name)}>', "  <ssv:Parameters>"]
    for var, value in starts.items():
        v = TABLE.variable(var)
        kind = {"Real": "Real", "Integer": "Integer", "Boolean": "Boolean", "String": "String",
                "Enumeration": "Enumeration"}[v.type]
        if v.type == "Enumeration":
            value = next(k for k, code in TABLE.enumerations[v.enumeration].items() if code == value)
        text = repr(float(value)) if kind == "Real" else str(value).lower() if kind == "Boolean" \
            else str(value)
        lines.append(f"    <ssv:Parameter name={quoteattr(var)}><ssv:{kind} "
                     f"value={quoteattr(text)}/></ssv:Parameter>")
    return "\n".join(lines + ["  </ssv:Parameters>", "</ssv:ParameterSet>", ""])


def write(out, name, params, starts, step, n, rows):
    d = pathlib.Path(out) / "org.fmi-standard.fmi-ls-ref"
    (d / name).mkdir(parents=True, exist_ok=True)
    (d / name / "parameters.ssv").write_text(ssv(name, starts))
    with open(d / name / "references.csv", "w", newline="") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(("time",) + OUTPUTS)
        w.writerows([repr(float(x)) for x in row] for row in rows)
    what = ", ".join(f"{k} = {v}" for k, v in params.items())
    description = quoteattr(f"the default point ({what}): static equilibrium at speed, {n} "
                            f"co-simulation steps, {SAMPLES_PER_CYCLE} per mesh cycle, outputs "
                            f"every {RECORD_EVERY} steps")
    (d / "fmi-ls-experiments.xml").write_text("\n".join([
        '<?xml version="1.0" encoding="UTF-8"?>',
        '<Experiments name="HypoidGearPair reference results">',
        f'  <Experiment name={quoteattr(name)} description={description}'
        f' startTime="0.0" stopTime="{n * step!r}" stepSize="{step!r}">',
        f'    <Parameters source="{LS_DIR}/{name}/parameters.ssv" '
        'type="application/x-ssp-parameter-set"/>',
        f'    <References source="{LS_DIR}/{name}/references.csv" type="text/csv"/>',
        "  </Experiment>", "</Experiments>", ""]))
    (d / "fmi-ls-manifest.xml").write_text("\n".join([
        '<?xml version="1.0" encoding="UTF-8"?>',
        '<fmiReferences xmlns:fmi-ls="http://fmi-standard.org/fmi-ls-manifest" '
        'fmi-ls:fmi-ls-name="org.fmi-standard.fmi-ls-ref" fmi-ls:fmi-ls-version="1.0.0-alpha.1" '
        'fmi-ls:fmi-ls-description="Layered Standard providing information on related files '
        'included in an FMU.">',
        f'  <Related source="{LS_DIR}/fmi-ls-experiments.xml" role="experiments" '
        'type="application/xml" description="the reference experiment and its results"/>',
        "</fmiReferences>", ""]))
    return d


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--fmu", default=str(ROOT / "build" / "HypoidGearPair.fmu"))
    ap.add_argument("--out", default=str(ROOT / "extra"))
    args = ap.parse_args(argv)
    name, params, starts, step, n = experiment()
    d = write(args.out, name, params, starts, step, n, run(args.fmu, params, step, n))
    print(f"fmi_ls_ref: wrote {d} ({name}, {n} steps of {step:.6g} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
