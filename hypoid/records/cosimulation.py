"""The cosimulation record: the tables of docs/cosimulation.md's scene (the gear FMU and the
vehicle FMU coupled): the energy residual per communication step and the hosts' agreement and
tolerances (tests/cosim/cosim_driver.py --record), the Jacobi coupling's growth rates
(tests/cosim/coupling_stability.py --record). The data hold each table's cells as the measuring
script formats them, with where and when it was measured."""

import json

from hypoid.records.pages import head, load, table

TABLES = {  # name: (heading, what the table holds)
    "energy": ("Energy: closure within the coupling error",
               "The residual of the energy balance over the scene, the coupling's term "
               "`E_out(gear) − E_in(vehicle)` and each FMU's own closure, per communication "
               "step h (libcosim, the gear at its defaults)."),
    "stability": ("Stability of the Jacobi coupling",
                  "Growth rates in 1/s of the least damped gear mode (above 100 Hz; positive, in "
                  "bold: unstable) of the exact one-step Jacobi map of both FMUs linearised, "
                  "dampers of the scene's start at 0 N.m."),
    "hosts": ("Agreement of the hosts",
              "Largest difference of the gear's outputs over the run, over the output's largest "
              "magnitude (for `eta`, whose mesh-frequency ripple shifts in phase, RMS over RMS)."),
    "tolerances": ("Tolerances: what \"tight\" takes in this scene",
                   "Each gear setting at 0.5 ms in the fmpy master against the converged run "
                   "(CVODE BDF, rtol 1e-12, atol 1e-16 m), and the hosts against the master under "
                   "it: w_p's largest difference over max |w_p|."),
}


def cells(lines):
    """Columns and rows of Markdown table lines."""
    split = [[c.strip() for c in line.strip().strip("|").split("|")] for line in lines
             if line.startswith("|")]
    return {"columns": split[0], "rows": split[2:]}


def save(folder, name, lines, measured):
    """Keeps one table (Markdown lines as the measuring script makes them) in the record's data
    and writes the page."""
    from hypoid.records.registry import RECORDS

    record = RECORDS["cosimulation"]
    path = folder / record.data[0]
    data = json.loads(path.read_text()) if path.exists() else {"tables": {}}
    data["tables"][name] = {**cells(lines), "measured": measured}
    path.write_text(json.dumps(data, indent=1, ensure_ascii=False) + "\n")
    (folder / record.page).write_text(record.write(folder))


def page(record, folder, _old=None):
    data = load(folder, record.data[0])["tables"]
    out = [head(record), "The scene, the masters and what the figures mean: "
           "[docs/cosimulation.md](../cosimulation.md)."]
    for name, (heading, text) in TABLES.items():
        if name in data:
            t = data[name]
            out += ["", f"## {heading}", "", text, "", table(t["columns"], t["rows"]), "",
                    f"*Measured {t['measured']}.*"]
    return "\n".join(out) + "\n"
