"""The axle's loss map: the parts of P_axle (mesh, churning, bearings, seals) and eta_axle over
pinion speed x input torque at fixed oil temperatures, from steady runs of the FMU (speed
governor, rigid mesh, ehl_thermal, axle_losses = full, oil held at T_bath). docs/axle.md
describes the models; tools/axle_loss_map.py and `hypoid study` (its report's loss-map section)
both run it from here."""

import time

import pandas as pd

from hypoid.fmu import parallel

PARTS = [("mesh", "P_loss"), ("churning", "P_churn"), ("bearings", "P_bearings"),
         ("seals", "P_seals")]
OUTPUTS = [n for _, n in PARTS] + ["P_axle", "P_in_axle", "eta_axle"]
COLUMNS = ["T_oil_C", "speed_rpm", "T_s"] + OUTPUTS + ["cpu_s"]
T_END_S, H_S, MEAN_STEPS = 0.6, 0.02, 10  # rigid mesh: settled well before 0.6 s

# Published whole-axle figures that the report compares with (docs/axle.md gives the sources).
PUBLISHED_ETA_RANGE = (0.95, 0.97)  # passenger-car / light-commercial axles, warm, loaded
PUBLISHED_MIN_LOSS_WARM = 0.06  # TRL RR10 (Ford Transit axles): >= 6 % lost at high power, warm


def point(inst, rpm, torque, T_oil_C):
    """The mean of the last MEAN_STEPS outputs of a steady run at one operating point."""
    t0 = time.process_time()
    inst.start({"axle_losses": "full", "mesh_model": "rigid", "friction_model": "ehl_thermal",
                "speed_rpm": rpm, "T_s": torque, "T_bath": T_oil_C + 273.15, "rtol": 1e-6})
    rows = inst.record(T_END_S, H_S, OUTPUTS)
    mean = rows[-MEAN_STEPS:].mean(axis=0)
    return {"status": "ok", "T_oil_C": T_oil_C, "speed_rpm": rpm, "T_s": torque,
            **{n: float(v) for n, v in zip(OUTPUTS, mean)}, "cpu_s": time.process_time() - t0}


class Plan:
    """The map's points as tasks of hypoid.study.sweep.execute / hypoid.fmu.parallel.run."""

    def __init__(self, temps, speeds, torques):
        self.tasks = [((float(T), float(n), float(tq)), point, (float(n), float(tq), float(T)))
                      for T in temps for n in speeds for tq in torques]
        self.rows = {}

    def on_result(self, key, res):
        if res.get("status") != "ok":
            raise RuntimeError(f"loss map point {key}: {res.get('message')}")
        self.rows[key] = {c: res[c] for c in COLUMNS}

    def finish(self):
        return pd.DataFrame([self.rows[k] for k, _, _ in self.tasks], columns=COLUMNS)


def run(fmu, temps, speeds, torques, client=None):
    """The map as a DataFrame (one row a point, COLUMNS); fmu is a parallel.FmuRef."""
    plan = Plan(temps, speeds, torques)
    parallel.run(plan.tasks, fmu, plan.on_result, client, desc="loss map")
    return plan.finish()


def spin_torque_Nm(df, T_oil_C, rpm):
    """The no-load drag at the pinion, P_axle / omega at T_s = 0 (NaN if not in the map)."""
    import math

    sel = df[(df["T_oil_C"] == T_oil_C) & (df["speed_rpm"] == rpm) & (df["T_s"] == 0)]
    if sel.empty:
        return float("nan")
    return float(sel["P_axle"].iloc[0]) / (rpm * math.pi / 30.0)


def markdown(df):
    """The map as a Markdown table (W and %)."""
    lines = ["| oil °C | rpm | T_s N·m | mesh W | churning W | bearings W | seals W | "
             "P_axle W | eta_axle % |", "|---|---|---|---|---|---|---|---|---|"]
    for r in df.itertuples(index=False):
        parts = " | ".join(f"{getattr(r, name):.1f}" for _, name in PARTS)
        lines.append(f"| {r.T_oil_C:.0f} | {r.speed_rpm:.0f} | {r.T_s:.0f} | {parts} | "
                     f"{r.P_axle:.1f} | {100 * r.eta_axle:.2f} |")
    return "\n".join(lines)
