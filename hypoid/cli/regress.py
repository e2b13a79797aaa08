"""`hypoid regress`: run a set of scenarios and compare their outputs with a reference, within
per-quantity tolerances. Exit status 1 when anything moved beyond its tolerance.

    hypoid regress                        # the built-in scenarios against tests/regression/
    hypoid regress --update               # rewrite the reference deliberately (review, commit)
    hypoid regress --scenarios mine.toml --update   # make a reference of your own scenarios
    hypoid regress --scenarios mine.toml            # ... and compare with it later

A scenarios file of your own is TOML, one table per scenario with the start values by name
(any parameter or input, enumeration items by name, speed_rpm required):

    [hot_oil_3000rpm]
    speed_rpm = 3000
    T_s = 150
    T_bath = 363.15
    lubricant_file = "my_oil.txt"

Its reference goes to <file>.reference.csv beside it unless --reference names another file; the
tolerances are tests/regression/tolerances.csv unless --tolerances names another file (columns
quantity, rel, abs; documented in tests/regression/README.md). Each scenario runs a fixed time
(no steady-state detection, so only the FMU is under test): 60 mesh cycles, then 20 mesh cycles
sampled 32 times per cycle. The quantities compared are those of the study tables, and in a
scenario with axle_losses = full the axle's ledger too (P_axle, eta_axle, every part, T_oil).
"""

import math
import pathlib

from hypoid.cli import args as cliargs
from hypoid.paths import user_path
from hypoid.regress import (SCENARIOS, compare, default_reference, read_reference,
                            read_scenarios, read_tolerances, run_all, write_reference)


def _parser():
    ap = cliargs.Parser("hypoid regress", __doc__)
    ap.add_fmu()
    ap.add_argument("--scenarios", type=user_path,
                    help="TOML file of your own scenarios (default: the built-in ones)")
    ap.add_argument("--reference", type=user_path,
                    help="reference CSV (default: tests/regression/reference.csv, in the "
                         "package's data, or <scenarios>.reference.csv with --scenarios)")
    ap.add_argument("--tolerances", type=user_path,
                    help="tolerances CSV (default: tests/regression/tolerances.csv, in the "
                         "package's data)")
    ap.add_argument("--update", action="store_true", help="rewrite the reference values")
    return ap


def main(argv):
    args = _parser().parse_args(argv)
    scenarios = read_scenarios(args.scenarios) if args.scenarios else SCENARIOS
    reference = pathlib.Path(args.reference or (
        pathlib.Path(args.scenarios).with_suffix(".reference.csv") if args.scenarios
        else default_reference(args.update)))
    tolerances = read_tolerances(args.tolerances)
    values = run_all(cliargs.fmu_path(args.fmu), scenarios)
    if args.update:
        old = read_reference(reference)[0] if reference.exists() else {}
        write_reference(values, reference, scenarios)
        moved = sum(1 for n, qs in values.items() for q, v in qs.items()
                    if n in old and not math.isclose(v, old[n].get(q, math.nan), rel_tol=1e-12))
        print(f"hypoid regress: wrote {reference} ({len(values)} scenarios; "
              f"{moved} values changed)")
        return 0
    if not reference.exists():
        raise cliargs.UsageError(f"{reference}: no reference yet; make it with --update")
    ref, ref_params = read_reference(reference)
    _, problems = compare(values, ref, ref_params, tolerances, scenarios)
    for p in problems:
        print("MOVED " + p)
    print(f"hypoid regress: {len(scenarios)} scenarios against {reference}, "
          f"{'all within tolerance' if not problems else f'{len(problems)} problems'}")
    return 1 if problems else 0
