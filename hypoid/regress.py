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

import csv
import json
import math
import pathlib
import sys
import tomllib

from hypoid.cli import args as cliargs
from hypoid.study import metrics, steady
from hypoid.fmu.instance import RPM, SPEED_KEY, Instance
from hypoid.paths import user_path
from hypoid.fmu.values import TABLE

ROOT = pathlib.Path(__file__).resolve().parents[1]
REF_DIR = ROOT / "tests" / "regression"
SETTLE_CYCLES = 60
RECORD_CYCLES = 20
SCENARIOS = {
    "set1_os962_100Nm_2000rpm": {"T_s": 100.0, SPEED_KEY: 2000.0},
    "set1_os962_100Nm_2000rpm_paper": {"T_s": 100.0, SPEED_KEY: 2000.0, "preset": "paper"},
    # the paper's calibrated mode 2 (the loaded files' stiffer mesh keeps the teeth together)
    "set1_os962_50Nm_1200rpm_contact_loss": {"T_s": 50.0, SPEED_KEY: 1200.0,
                                             "tooth_data": "paper"},
    # the default (loaded) data's mode 3 at 50 N.m: the teeth apart a quarter of the time
    "set1_os962_50Nm_2300rpm_contact_loss": {"T_s": 50.0, SPEED_KEY: 2300.0},
    "set1_os963_300Nm_1000rpm": {"lubricant": 2, "T_s": 300.0, SPEED_KEY: 1000.0},
    "set2_os962_100Nm_3000rpm_bath80C": {"gear_set": 2, "T_s": 100.0, SPEED_KEY: 3000.0,
                                         "T_bath": 353.15},
    "set3_os962_200Nm_4000rpm_isothermal": {"gear_set": 3, "T_s": 200.0, SPEED_KEY: 4000.0,
                                            "friction_model": "ehl_isothermal"},
    "set1_mean_mesh_coulomb_torque_mode": {"mesh_model": "mean", "friction_model": "coulomb",
                                           "load_mode": "torque", "T_s": 100.0,
                                           SPEED_KEY: 1500.0},
}
QUANTITIES = ("eta_rms", "eta_energy", "P_loss_mean_W", "speed_mean_rpm", "DTE_mean_um",
              "DTE_pp_um", "DTE_min_minus_b_um", "contact_loss_fraction", "W_t_mean_N",
              "W_t_peak_N", "mu_mean", "h_c_mean_um", "lambda_mean", "T_c_max_C")
# and in a scenario with axle_losses = full, the axle's ledger (hypoid.study.metrics)
AXLE_QUANTITIES = metrics.AXLE_FIGURES


def run_scenario(inst, params):
    """The QUANTITIES of one scenario."""
    settings = steady.Settings()
    inst.start(params)
    sampler = steady.Sampler(inst, settings)
    w = params[SPEED_KEY] * RPM
    h = sampler.mesh_step(w)
    spc = settings.samples_per_cycle
    sampler.sample(SETTLE_CYCLES * spc, h)
    window = sampler.sample(RECORD_CYCLES * spc, h)
    axle = steady.whole_axle(inst)
    row = metrics.window_metrics(window, steady.half_backlash(inst), axle=axle)
    return {q: row[q] for q in QUANTITIES + (AXLE_QUANTITIES if axle else ())}


def run_all(fmu_path, scenarios=SCENARIOS):
    inst = Instance(fmu_path)
    try:
        return {name: run_scenario(inst, p) for name, p in scenarios.items()}
    finally:
        inst.close()


def read_scenarios(path):
    """A user's scenarios file (TOML, one table per scenario), checked against the variables."""
    try:
        with open(path, "rb") as fh:
            data = tomllib.load(fh)
    except tomllib.TOMLDecodeError as e:
        raise cliargs.UsageError(f"{path}: not a TOML scenarios file ({e})") from None
    scenarios = {}
    for name, params in data.items():
        if not isinstance(params, dict) or SPEED_KEY not in params:
            raise cliargs.UsageError(f"{path}: scenario [{name}] needs a table of start values "
                                     f"with {SPEED_KEY} (see hypoid regress --help)")
        try:
            scenarios[name] = {k: TABLE.parse(k, v) for k, v in params.items()}
        except ValueError as e:
            raise cliargs.UsageError(f"{path}: scenario [{name}]: {e}") from None
    if not scenarios:
        raise cliargs.UsageError(f"{path}: no scenarios")
    return scenarios


def read_tolerances(path=REF_DIR / "tolerances.csv"):
    with open(path, newline="") as fh:
        return {r["quantity"]: (float(r["rel"]), float(r["abs"])) for r in csv.DictReader(fh)}


def read_reference(path=REF_DIR / "reference.csv"):
    ref, params = {}, {}
    with open(path, newline="") as fh:
        for r in csv.DictReader(fh):
            ref.setdefault(r["scenario"], {})[r["quantity"]] = float(r["value"])
            params[r["scenario"]] = r["params"]
    return ref, params


def _params_text(params):
    return json.dumps(params, sort_keys=True)


def write_reference(values, path=REF_DIR / "reference.csv", scenarios=SCENARIOS):
    path = pathlib.Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["scenario", "quantity", "value", "params"])
        for name, qs in values.items():
            p = _params_text(scenarios[name])
            for q, v in qs.items():
                w.writerow([name, q, repr(float(v)), p])


def compare(values, ref, ref_params, tol, scenarios=SCENARIOS):
    """Rows (scenario, quantity, reference, value, allowed, ok) and a list of problems."""
    rows, problems = [], []
    for name in scenarios:
        if name not in ref:
            problems.append(f"{name}: no reference (run `hypoid regress --update`)")
            continue
        if ref_params.get(name) != _params_text(scenarios[name]):
            problems.append(f"{name}: the reference was made for other parameters "
                            f"({ref_params.get(name)})")
        for q in values[name]:  # QUANTITIES, and AXLE_QUANTITIES in an axle scenario
            r, v = ref[name].get(q, math.nan), values[name][q]
            rel, ab = tol[q]
            allowed = ab + rel * abs(r)
            same_nan = math.isnan(r) and math.isnan(v)
            ok = same_nan or abs(v - r) <= allowed
            rows.append((name, q, r, v, allowed, ok))
            if not ok:
                problems.append(f"{name}: {q} = {v:.6g}, reference {r:.6g} "
                                f"(|diff| {abs(v - r):.3g} > {allowed:.3g})")
    return rows, problems


def _parser():
    ap = cliargs.Parser("hypoid regress", __doc__)
    ap.add_fmu()
    ap.add_argument("--scenarios", type=user_path,
                    help="TOML file of your own scenarios (default: the built-in ones)")
    ap.add_argument("--reference", type=user_path,
                    help="reference CSV (default: tests/regression/reference.csv, or "
                         "<scenarios>.reference.csv with --scenarios)")
    ap.add_argument("--tolerances", type=user_path, default=str(REF_DIR / "tolerances.csv"),
                    help="tolerances CSV (default: tests/regression/tolerances.csv)")
    ap.add_argument("--update", action="store_true", help="rewrite the reference values")
    return ap


def main(argv):
    args = _parser().parse_args(argv)
    scenarios = read_scenarios(args.scenarios) if args.scenarios else SCENARIOS
    reference = pathlib.Path(args.reference or (
        pathlib.Path(args.scenarios).with_suffix(".reference.csv") if args.scenarios
        else REF_DIR / "reference.csv"))
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


if __name__ == "__main__":
    from hypoid import cli

    sys.exit(cli.main(["regress", *sys.argv[1:]]))
