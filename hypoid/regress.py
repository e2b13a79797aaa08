"""Regression of FMU outputs: fixed scenarios run for a fixed time (no steady-state detection,
so only the FMU is under test) and their outputs compared with a reference within per-quantity
tolerances (tests/regression/README.md); with axle_losses = full the axle's ledger too. The
command is `hypoid regress` (hypoid/cli/regress.py)."""

import csv
import json
import math
import pathlib
import tomllib

from hypoid import data
from hypoid.errors import UsageError
from hypoid.fmu.instance import RPM, SPEED_KEY, Instance
from hypoid.fmu.values import TABLE
from hypoid.study import metrics, steady

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
    # the whole axle's ledger (churning, bearings, seals) in a 20 degC bath
    "set1_os962_150Nm_1500rpm_axle_full_bath20C": {"axle_losses": "full", "T_s": 150.0,
                                                   SPEED_KEY: 1500.0, "T_bath": 293.15},
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
        raise UsageError(f"{path}: not a TOML scenarios file ({e})") from None
    scenarios = {}
    for name, params in data.items():
        if not isinstance(params, dict) or SPEED_KEY not in params:
            raise UsageError(f"{path}: scenario [{name}] needs a table of start values "
                                     f"with {SPEED_KEY} (see hypoid regress --help)")
        try:
            scenarios[name] = {k: TABLE.parse(k, v) for k, v in params.items()}
        except ValueError as e:
            raise UsageError(f"{path}: scenario [{name}]: {e}") from None
    if not scenarios:
        raise UsageError(f"{path}: no scenarios")
    return scenarios


def read_tolerances(path=None):
    with open(path or data.regression("tolerances.csv"), newline="") as fh:
        return {r["quantity"]: (float(r["rel"]), float(r["abs"])) for r in csv.DictReader(fh)}


def read_reference(path=None):
    ref, params = {}, {}
    with open(path or data.regression("reference.csv"), newline="") as fh:
        for r in csv.DictReader(fh):
            ref.setdefault(r["scenario"], {})[r["quantity"]] = float(r["value"])
            params[r["scenario"]] = r["params"]
    return ref, params


def _params_text(params):
    return json.dumps(params, sort_keys=True)


def write_reference(values, path=None, scenarios=SCENARIOS):
    path = pathlib.Path(path or default_reference(update=True))
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


def default_reference(update):
    """The built-in scenarios' reference (the package's regression data); --update rewrites the
    checkout's tests/regression/reference.csv."""
    if update:
        return data.writable("tests/regression", "--reference") / "reference.csv"
    return data.regression("reference.csv")
