"""`hypoid regress`: run a small fixed set of scenarios and compare their outputs with the
reference in tests/regression/reference.csv, within the tolerances of
tests/regression/tolerances.csv (documented in tests/regression/README.md).

    hypoid regress                 # compare; exit status 1 when anything moved beyond tolerance
    hypoid regress --update        # rewrite the reference deliberately (review the diff, commit)

Each scenario runs a fixed time (no steady-state detection, so only the FMU is under test):
SETTLE_CYCLES mesh cycles, then RECORD_CYCLES mesh cycles sampled 32 times per cycle.
"""

import argparse
import csv
import json
import math
import pathlib
import sys

from hypoid import metrics, steady
from hypoid.instance import RPM, SPEED_KEY, Instance

ROOT = pathlib.Path(__file__).resolve().parents[1]
REF_DIR = ROOT / "tests" / "regression"
SETTLE_CYCLES = 60
RECORD_CYCLES = 20
SCENARIOS = {
    "set1_os962_100Nm_2000rpm": {"T_s": 100.0, SPEED_KEY: 2000.0},
    "set1_os962_50Nm_1200rpm_contact_loss": {"T_s": 50.0, SPEED_KEY: 1200.0},
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
    row = metrics.window_metrics(window, steady.half_backlash(inst))
    return {q: row[q] for q in QUANTITIES}


def run_all(fmu_path):
    inst = Instance(fmu_path)
    try:
        return {name: run_scenario(inst, p) for name, p in SCENARIOS.items()}
    finally:
        inst.close()


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


def write_reference(values, path=REF_DIR / "reference.csv"):
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["scenario", "quantity", "value", "params"])
        for name, qs in values.items():
            p = json.dumps(SCENARIOS[name], sort_keys=True)
            for q, v in qs.items():
                w.writerow([name, q, repr(float(v)), p])


def compare(values, ref, ref_params, tol):
    """Rows (scenario, quantity, reference, value, allowed, ok) and a list of problems."""
    rows, problems = [], []
    for name in SCENARIOS:
        if name not in ref:
            problems.append(f"{name}: no reference (run `hypoid regress --update`)")
            continue
        if ref_params.get(name) != json.dumps(SCENARIOS[name], sort_keys=True):
            problems.append(f"{name}: the reference was made for other parameters "
                            f"({ref_params.get(name)})")
        for q in QUANTITIES:
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


def main(argv):
    ap = argparse.ArgumentParser(prog="hypoid regress", description=__doc__.splitlines()[0])
    ap.add_argument("--fmu", default=str(ROOT / "build" / "HypoidGearPair.fmu"))
    ap.add_argument("--update", action="store_true", help="rewrite the reference values")
    args = ap.parse_args(argv)
    values = run_all(args.fmu)
    if args.update:
        old = read_reference()[0] if (REF_DIR / "reference.csv").exists() else {}
        write_reference(values)
        moved = sum(1 for n, qs in values.items() for q, v in qs.items()
                    if n in old and not math.isclose(v, old[n].get(q, math.nan), rel_tol=1e-12))
        print(f"hypoid regress: wrote {REF_DIR / 'reference.csv'} ({len(values)} scenarios; "
              f"{moved} values changed)")
        return 0
    ref, ref_params = read_reference()
    _, problems = compare(values, ref, ref_params, read_tolerances())
    for p in problems:
        print("MOVED " + p)
    print(f"hypoid regress: {len(SCENARIOS)} scenarios, "
          f"{'all within tolerance' if not problems else f'{len(problems)} problems'}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
