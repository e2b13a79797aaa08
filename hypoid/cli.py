"""The `hypoid` command: `hypoid <tool> [args...]` dispatches to a tool module's main(argv)."""

import importlib
import sys

TOOLS = {
    "tca": ("hypoid.tca", "tooth contact data: surrogate gear sets, import of a user's TCA table"),
    "lubricant": ("hypoid.lubricant", "lubricant data files from data-sheet values"),
    "run": ("hypoid.scenario", "simulate one scenario and write results and plots"),
    "effmap": ("hypoid.effmap", "efficiency maps of the full model for the FMU's map level"),
    "sweep": ("hypoid.sweep", "grid of steady-state points or continuation sweeps (dask, resume)"),
    "study": ("hypoid.study", "the paper's studies: tables, plots and a report (default, full)"),
    "regress": ("hypoid.regress", "compare FMU outputs with tests/regression (--update)"),
}


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if not argv or argv[0] in ("-h", "--help") or argv[0] not in TOOLS:
        print("usage: hypoid <tool> [args...]\n\ntools:")
        for name, (_, text) in TOOLS.items():
            print(f"  {name:<10} {text}")
        return 0 if argv and argv[0] in ("-h", "--help") else 2
    module = importlib.import_module(TOOLS[argv[0]][0])
    return module.main(argv[1:])


if __name__ == "__main__":
    sys.exit(main())
