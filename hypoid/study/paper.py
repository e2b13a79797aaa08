"""The paper's studies (Paouris et al. 2016, Figs. 5-11) on the FMU: their specifications, the
steady-state grids and continuation sweeps they run, tables, plots and the report. The command is
`hypoid study` (hypoid/cli/study.py)."""

import json
import pathlib
import time
from dataclasses import dataclass, field

from hypoid.fmu import parallel
from hypoid.fmu.instance import SPEED_KEY
from hypoid.maps import lossmap
from hypoid.study import steady, sweep
from hypoid.study.modes import I_P_GEOMETRY
from hypoid.study.tables import PAPER_CHOICES

SWAPPED_NAME = "OS265963 with alpha* of OS265962"
SWAPPED_FILE = "OS265963-alpha-OS265962.txt"


def _rng(a, b, s):
    return list(range(a, b + 1, s))


@dataclass
class WhatIf:
    """A variant of gear set 1 (OS265962, the paper's EHL) on its own grid and continuation
    sweeps, reported beside the reference (docs/records/paper-findings.md, 'What-if')."""

    label: str
    params: dict  # what the variant changes
    torques: list
    speeds: list
    sweep_torques: list
    sweep_speeds: list
    trace_points: list  # (T_s, speed)


# the pinion's inertia from its geometry (hypoid.study.modes.I_P_GEOMETRY): mode 3 (2118 rpm) becomes
# the strongest DTE resonance; the grid brackets it and mode 2 (1413 rpm) by 200 rpm for the
# dips, the sweep crosses mode 3 at the paper's jump torque (100 N.m)
WHATIF_IP = WhatIf("I_p from the pinion's geometry", {"I_p": I_P_GEOMETRY},
                   torques=[50, 100, 200, 300],
                   speeds=[1200, 1400, 1600, 1800, 1900, 2000, 2050, 2100, 2150, 2200, 2400,
                           5000],
                   sweep_torques=[100], sweep_speeds=_rng(2000, 2250, 50),
                   trace_points=[(50, 2100), (50, 5000), (100, 2100), (100, 5000)])


@dataclass
class Spec:
    """What a study runs. Speeds in rpm (pinion), torques in N.m."""

    speeds: list  # gear set 1 grids (Figs. 6-8)
    torques: list  # Fig. 8
    set_speeds: list  # gear sets 2 and 3 (Fig. 11)
    sweep_torques: list  # continuation (Fig. 9)
    sweep_speeds: list
    trace_points: list  # (T_s, speed) of gear set 1, OS265962 whose signals are kept
    sweep_sets: list = field(default_factory=lambda: [1])
    extra: list = field(default_factory=list)  # (label, base params, {name: values}) grids
    whatif: list = field(default_factory=list)  # WhatIf variants of gear set 1
    settings: steady.Settings = field(default_factory=steady.Settings)
    ramp_time: float = 0.1
    # the axle's loss map (hypoid.maps.lossmap): oil temperatures in degC x speeds x torques
    loss_temps: list = field(default_factory=lambda: [40.0, 80.0])
    loss_speeds: list = field(default_factory=lambda: [1000, 2000, 4000])
    loss_torques: list = field(default_factory=lambda: [0, 50, 200])


SPECS = {
    "ci": Spec(speeds=[1000, 1200, 2000, 3000], torques=[50, 300], set_speeds=[1000, 3000],
               sweep_torques=[50], sweep_speeds=[1100, 1150, 1200, 1250],
               trace_points=[(50, 1000), (50, 1200)], loss_speeds=[1000, 2000],
               loss_torques=[0, 50],
               whatif=[WhatIf(WHATIF_IP.label, WHATIF_IP.params, [50], [1900, 2100, 2300], [],
                              [], [(50, 2100)])]),
    "default": Spec(
        speeds=[800, 1000, 1100, 1150, 1200, 1250, 1300, 1400, 1600, 1800, 1900, 2000, 2100,
                2200, 2500, 3000, 3500, 4000, 4500, 5000],
        torques=[50, 100, 200, 300],
        set_speeds=_rng(800, 2600, 50) + [3000, 3500, 4000, 4500, 5000],
        sweep_torques=[50, 100],
        sweep_speeds=_rng(1000, 1400, 25) + [1500, 1600, 1700] + _rng(1800, 2200, 50),
        trace_points=[(50, 1000), (300, 1000), (100, 1200), (100, 2000), (100, 5000)],
        whatif=[WHATIF_IP]),
    "full": Spec(
        speeds=_rng(500, 5000, 50),
        torques=[50, 100, 200, 300],
        set_speeds=_rng(500, 5000, 50),
        sweep_torques=[50, 100, 200, 300],
        sweep_speeds=_rng(900, 2400, 20),
        trace_points=[(50, 1000), (300, 1000), (100, 1200), (100, 2000), (100, 5000),
                      (50, 1200), (50, 2000)],
        whatif=[WhatIf(WHATIF_IP.label, WHATIF_IP.params, [50, 100, 200, 300],
                       _rng(1000, 3000, 50) + [3500, 4000, 5000], [50, 100, 200, 300],
                       _rng(1800, 2400, 20), WHATIF_IP.trace_points)],
        extra=[("bath 80 degC", {"T_bath": 353.15}, {SPEED_KEY: _rng(500, 5000, 250)}),
               ("isothermal EHL", {"friction_model": "ehl_isothermal"},
                {SPEED_KEY: _rng(500, 5000, 250)}),
               ("mean mesh (no backlash)", {"mesh_model": "mean"},
                {SPEED_KEY: _rng(500, 5000, 250)}),
               ("OS265963, k_f 0.80", {"lubricant": 2, "k_f": 0.80},
                {SPEED_KEY: _rng(500, 5000, 250)}),
               ("Roelands Z exact", {"roelands_z": "exact"}, {SPEED_KEY: _rng(500, 5000, 250)}),
               ("e_0 x3 (calibration probe)", {"e_0_scale": 3.0},
                {"T_s": [50, 100, 200, 300], SPEED_KEY: _rng(800, 2600, 50) + [3000, 4000, 5000]}),
               ]),
}


def swapped_lubricant(out_dir):
    """OS265963 with OS265962's alpha* data, written with the lubricant tool; absolute path."""
    from hypoid import lubricant

    path = (pathlib.Path(out_dir) / "lubricants" / SWAPPED_FILE).resolve()
    path.parent.mkdir(parents=True, exist_ok=True)
    data = dict(lubricant.BUILTIN["OS265963"])
    data["alpha_star"] = lubricant.BUILTIN["OS265962"]["alpha_star"]
    text = lubricant.render(lubricant.build(name=SWAPPED_NAME, **data), [
        "Study variant for paper Fig. 7: OS265963 with the pressure-viscosity (alpha*) data of",
        "OS265962; everything else is OS265963's."])
    if not path.exists() or path.read_text() != text:
        path.write_text(text)
    return str(path)


def points_of(spec, swapped_file):
    """All steady points of a study (duplicates across figures are fine: keys dedupe them)."""
    g1 = {"gear_set": 1, "lubricant": 1}
    pts = sweep.grid(g1, {"T_s": spec.torques, SPEED_KEY: spec.speeds})  # Fig. 8
    pts += sweep.grid({**g1, "lubricant": 2, "T_s": 100}, {SPEED_KEY: spec.speeds})  # Fig. 6a
    pts += sweep.grid({**g1, "lubricant_file": swapped_file, "T_s": 100},
                      {SPEED_KEY: spec.speeds})  # Fig. 7
    pts += sweep.grid({"lubricant": 1, "T_s": 100},
                      {"gear_set": [2, 3], SPEED_KEY: spec.set_speeds})  # Fig. 11
    for _, base, vary in spec.extra:
        pts += sweep.grid({**g1, "T_s": 100, **base}, vary)
    if 100 not in spec.torques:  # Figs. 6, 7 compare with OS265962 at 100 N.m
        pts += sweep.grid({**g1, "T_s": 100}, {SPEED_KEY: spec.speeds})
    for t, n in spec.trace_points:
        pts.append({**g1, "T_s": t, SPEED_KEY: n})
    for w in spec.whatif:
        pts += sweep.grid({**g1, **w.params}, {"T_s": w.torques, SPEED_KEY: w.speeds})
        pts += [{**g1, **w.params, "T_s": t, SPEED_KEY: n} for t, n in w.trace_points]
    return pts


def traces_of(spec):
    """The points whose signals are kept: the reference's and each what-if's."""
    g1 = {"gear_set": 1, "lubricant": 1}
    return ([{**g1, "T_s": t, SPEED_KEY: n} for t, n in spec.trace_points]
            + [{**g1, **w.params, "T_s": t, SPEED_KEY: n} for w in spec.whatif
               for t, n in w.trace_points])


def sweeps_of(spec):
    """The continuation sweeps (params without speed, speeds): the reference's, each what-if's."""
    base = [({"gear_set": s, "lubricant": 1, "T_s": t}, spec.sweep_speeds)
            for s in spec.sweep_sets for t in spec.sweep_torques]
    return base + [({"gear_set": 1, "lubricant": 1, **w.params, "T_s": t}, w.sweep_speeds)
                   for w in spec.whatif for t in w.sweep_torques]


def varied_columns(spec):
    """Parameters some rows of a study set besides the grid's own: every row carries them."""
    return sorted({k for _, base, _ in spec.extra for k in base}
                  | {k for w in spec.whatif for k in w.params})


# One point at the shipped FMU's own defaults (no paper choices), so that the report can give
# the defaults' figure beside the paper's at the paper's reference point
DEFAULTS_POINT = {"gear_set": 1, "lubricant": 1, "T_s": 100.0, SPEED_KEY: 2000.0}


def paper_ehl(points):
    """The points with the paper's EHL choices and calibrated tooth data wherever a point does
    not set its own: the study reproduces the paper, where the FMU's defaults follow the traction
    evidence (docs/friction-evidence.md) and the loaded tooth-contact analysis."""
    return [{**PAPER_CHOICES, **p} for p in points]


def unique(points):
    from hypoid.study import results

    seen = {}
    for p in points:
        seen.setdefault(results.canonical(p), p)
    return list(seen.values())


def run(name, out, fmu_path, scheduler=None, workers=2):
    """Runs a study; returns (points, continuation, info). The axle's loss map goes to
    out/lossmap.csv (info["lossmap"])."""
    spec = SPECS[name]
    out = pathlib.Path(out)
    out.mkdir(parents=True, exist_ok=True)
    fmu = parallel.FmuRef(fmu_path)
    swapped = swapped_lubricant(out)
    extra_cols = varied_columns(spec)
    points = unique(sweep.complete(paper_ehl(points_of(spec, swapped)) + [DEFAULTS_POINT],
                                   extra_cols))
    traced = sweep.complete(paper_ehl(traces_of(spec)), extra_cols)
    plan = sweeps_of(spec)
    sweeps = [({k: v for k, v in p.items() if k != SPEED_KEY}, speeds) for p, (_, speeds)
              in zip(sweep.complete(paper_ehl([p for p, _ in plan]), extra_cols), plan)]
    loss_plan = lossmap.Plan(spec.loss_temps, spec.loss_speeds, spec.loss_torques)
    t0 = time.time()
    with parallel.executor(scheduler, workers) as client:
        t1 = time.time()
        # the sweeps are long single tasks: submitted first, they overlap with the points;
        # the loss map's short rigid-mesh runs come last and fill the gaps
        cont, pts, lm = sweep.execute([sweep.SweepsPlan(sweeps, out, fmu, spec.settings,
                                                        spec.ramp_time),
                                       sweep.PointsPlan(points, out, fmu, spec.settings, traced),
                                       loss_plan], fmu, client, desc=f"study {name}")
    wall = time.time() - t0
    lm.to_csv(out / "lossmap.csv", index=False)
    info = {"study": name, "fmu": str(fmu_path), "fmu_sha256": fmu.sha,
            "scheduler": scheduler or f"local pool, {workers} processes"
            if workers else "in-process", "cluster_start_s": t1 - t0, "wall_s": wall,
            "n_points": len(pts), "n_sweeps": len(sweeps), "n_sweep_rows": len(cont),
            "settings": spec.settings.as_dict(), "ramp_time_s": spec.ramp_time,
            "swapped_lubricant_file": swapped,
            "extra": [(label, base) for label, base, _ in spec.extra],
            "whatif": [(w.label, w.params) for w in spec.whatif],
            "lossmap": "lossmap.csv", "lossmap_points": len(lm),
            "lossmap_cpu_s": float(lm["cpu_s"].sum()),
            "finished": time.strftime("%Y-%m-%d %H:%M:%S")}
    return pts, cont, info


def write_report(out, pts, cont, info, workers=2):
    """Results -> figures (drawn on `workers` local processes), findings and modal tables ->
    report.md (each by its own module)."""
    from hypoid.study import findings, plots, report, tables

    import pandas as pd

    ok_pts, ok_cont = tables.prepare(pts), tables.prepare(cont)
    lm_path = out / info.get("lossmap", "lossmap.csv")
    lm = pd.read_csv(lm_path) if lm_path.exists() else None
    figs = plots.all_figures(ok_pts, ok_cont, out / "figures", lm, workers)
    find = findings.all_findings(pts, cont, out / "traces")
    find.to_csv(out / "findings.csv", index=False)
    modal = tables.modal_table(ok_pts)
    modal.to_csv(out / "modal.csv", index=False)
    det = findings.details(pts, cont, out / "traces", info.get("extra", []))
    (out / "details.json").write_text(json.dumps(det, indent=1, default=_plain) + "\n")
    return report.write(out, pts, cont, info, figs, find, modal, lm, det)


def _plain(x):
    """numpy scalars for json.dumps."""
    return x.item() if hasattr(x, "item") else str(x)
