"""The `hypoid` command: `hypoid <tool> [args...]` dispatches to a tool module's main(argv).

Every tool's errors take one path (hypoid.cli.args): one line `hypoid <tool>: what was wrong and
what is allowed` on stderr and exit status 2, never a traceback (set HYPOID_TRACEBACK=1 to see
one for an unexpected error)."""

import importlib
import os
import sys

TOOLS = {
    "tca": ("hypoid.cli.tca", "tooth contact data: surrogate gear sets, import of a user's TCA table"),
    "lubricant": ("hypoid.cli.lubricant", "lubricant data files from data-sheet values"),
    "run": ("hypoid.cli.run", "simulate one scenario and write results and plots"),
    "effmap": ("hypoid.cli.effmap", "efficiency maps of the full model for the FMU's map level"),
    "sweep": ("hypoid.cli.sweep", "grid of steady-state points or continuation sweeps (dask, resume)"),
    "study": ("hypoid.cli.study", "the paper's studies: tables, plots and a report (default, full)"),
    "regress": ("hypoid.cli.regress", "compare FMU outputs with regression references (--update)"),
    "records": ("hypoid.cli.records", "the measured records of docs/records/: pages from their "
                "data, checks, measurements"),
    "drive-cycle": ("hypoid.cli.drive_cycle", "the axle in a car over WLTC, NEDC or a CSV cycle: losses, oil "
                    "temperature"),
}


def usage():
    lines = ["usage: hypoid <tool> [args...]   (hypoid <tool> --help for each)", "", "tools:"]
    lines += [f"  {name:<10} {text}" for name, (_, text) in TOOLS.items()]
    return "\n".join(lines)


def expected_errors():
    """The exceptions that are the user's or the FMU's, printed as one line."""
    from hypoid.errors import UsageError
    from hypoid.fmu.instance import FmuError
    from hypoid.fmu.values import BadValue

    return (UsageError, BadValue, FmuError, OSError)


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    # numpy's OpenBLAS starts a thread per core that spins after its calls; the tools' matrices
    # have a few rows (modes, Fourier series), so those threads only take CPU from the workers
    # (set before a tool imports numpy; a value in the environment is kept)
    os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
    if not argv or argv[0] in ("-h", "--help"):
        print(usage())
        return 0 if argv else 2
    tool = argv[0]
    if tool not in TOOLS:
        print(f"hypoid: unknown tool {tool!r}; the tools are {', '.join(TOOLS)} "
              "(hypoid --help)", file=sys.stderr)
        return 2
    prog = f"hypoid {tool}"
    try:
        return importlib.import_module(TOOLS[tool][0]).main(argv[1:])
    except SystemExit as stop:  # --help (0) or a tool's own exit
        if stop.code is None or isinstance(stop.code, int):
            return stop.code or 0
        print(f"{prog}: {stop.code}", file=sys.stderr)
        return 2
    except KeyboardInterrupt as stop:  # Ctrl-C, or SIGTERM (hypoid.fmu.parallel.Terminated)
        print(f"{prog}: interrupted{' by SIGTERM' if str(stop) == 'SIGTERM' else ''}; "
              "the worker processes are ended", file=sys.stderr)
        return 2
    except Exception as e:  # noqa: BLE001 - the one error path of all tools
        if os.environ.get("HYPOID_TRACEBACK"):
            raise
        known = isinstance(e, expected_errors())
        text = " ".join(str(e).split()) or type(e).__name__
        if not known:
            text = f"unexpected {type(e).__name__}: {text} (HYPOID_TRACEBACK=1 shows where)"
        print(f"{prog}: {text}", file=sys.stderr)
        return 2
