"""Every record of the project in one table: its page and data in docs/records/, the command
that measures it, and the function that writes its page from its data."""

import dataclasses
import importlib
import pathlib

ROOT = pathlib.Path(__file__).resolve().parents[2]  # the checkout (records live in its docs/)
FOLDER = ROOT / "docs" / "records"


@dataclasses.dataclass(frozen=True)
class Record:
    name: str       # the page is docs/records/NAME.md
    title: str
    what: str       # one line for the index: what was measured
    data: tuple     # its data files, in docs/records/
    measure: str    # the command that measures it (from the checkout's root; minutes, niced)
    render: str     # "module:function", function(record, folder, page_text) -> page text
    mixed: bool = False  # the page has written text around generated blocks

    @property
    def page(self):
        return f"{self.name}.md"

    def write(self, folder=FOLDER):
        """The page as its data make it (the page's current text is kept around generated
        blocks of a mixed page)."""
        module, function = self.render.split(":")
        path = pathlib.Path(folder) / self.page
        old = path.read_text() if self.mixed else None
        return getattr(importlib.import_module(module), function)(self, pathlib.Path(folder), old)


R = "hypoid.records."
RECORDS = {r.name: r for r in [
    Record("level-table", "Cost and accuracy of each fidelity level at its defaults",
           "each level's real-time factor at 1 ms and 0.1 s steps, its error against its own "
           "tight solution and its energy-audit residual",
           ("level-table.json",), "python bench/level_table.py", R + "level_table:page"),
    Record("full-targets", "Speed targets of the full model, with their accuracy",
           "the full model at its defaults against arkode_erk at rtol 1e-4 and Newmark: cost "
           "per mesh cycle, steps, accuracy in the five work-precision scenes",
           ("full-targets.json",), "python bench/full_targets.py", R + "full_targets:page"),
    Record("work-precision", "Work-precision of the HypoidGearPair FMU",
           "cost and error of every level and solver setting in five scenes, real-time factor "
           "against the communication step, which level for which use",
           ("work-precision.csv", "work-precision.json"), "python bench/work_precision.py",
           R + "work_precision:page"),
    Record("tooth-data-cost", "What the loaded tooth data cost",
           "the full model with the one-series and the loaded tooth data at five operating "
           "points: real-time factor, steps, right-hand sides and CPU per mesh cycle",
           ("tooth-data-cost.json",), "python bench/tooth_data_cost.py", R + "pages:tables_page"),
    Record("rigid-speed", "The rigid level's speed sweep",
           "the rigid level against the full level from 500 to 6000 rpm in one run per speed: "
           "real-time factor, solver steps and CPU per mesh cycle",
           ("rigid-speed.json",), "python bench/rigid_speed.py", R + "pages:tables_page"),
    Record("startup", "The start of an instance",
           "the full level's first instance of a process and further instances: CPU from "
           "instantiation to 10 ms, memory each, with and without the shipped tables; the "
           "FMU's size", ("startup.json",), "python bench/startup.py", R + "pages:tables_page"),
    Record("fmpy-outputs", "A scene from t = 0 through fmpy, every output read",
           "the full level's 1 s scene from t = 0 at 1 ms steps through fmpy, every output or "
           "w_p only read after each step: real-time factor, CPU of the start, the steps and "
           "the reads", ("fmpy-outputs.json",), "python bench/fmpy_outputs.py",
           R + "pages:tables_page"),
    Record("paper-findings", "The paper's findings in this FMU",
           "the default and full studies' verdicts on the paper's findings, the resonances, the "
           "modal analysis, the what-if inertia, the loaded tooth data's sweep",
           ("paper-findings.json",), "rm -rf build/records/study && hypoid study default --out build/records/study && "
           "python tools/paper_findings.py --study build/records/study",
           R + "paper_findings:page", mixed=True),
    Record("km-effect", "What the loaded stiffness does at 2000 rpm",
           "efficiency, friction loss and DTE at 2000 rpm with the one-series, scaled and "
           "layered tooth data of gear sets 1-3",
           ("km-effect.json",), "python tools/tooth_figures.py", R + "tooth_data:km_effect"),
    Record("mesh-law", "The mesh force laws against the reference model",
           "DTE over 1000-3400 rpm of the FMU's contact law, the filtered secant and the tangent "
           "per level against a reference model with the loaded contact's own law",
           ("mesh-law.json",), "python tools/mesh_law_reference.py record", R + "tooth_data:mesh_law"),
    Record("friction-tooth-data", "Friction and DTE with the paper's and the loaded tooth data",
           "μ, P_loss and DTE on the regression protocol with tooth_data = paper and loaded",
           ("friction-tooth-data.json",),
           "python tools/friction_figures.py --before tooth_data=paper --after tooth_data=loaded "
           "--record friction-tooth-data", R + "tooth_data:friction"),
    Record("friction-defaults", "Friction with the paper's choices and the defaults",
           "μ, P_loss and DTE on the regression protocol with friction_preset = paper and the "
           "FMU's friction defaults, beside ISO/TR 14179-2's μ_mZ",
           ("friction-defaults.json",), "python tools/friction_figures.py --record friction-defaults",
           R + "tooth_data:friction"),
    Record("axle-loss-map", "The axle's loss map",
           "steady losses by part and eta_axle of gear set 1 at 40 and 80 °C over speed and "
           "torque", ("axle-loss-map.json",), "python tools/axle_loss_map.py", R + "pages:tables_page"),
    Record("validation", "The axle's losses against what is measured and published",
           "bearing loss against torque, spin loss at SAE J2985's temperatures, churning and "
           "mesh friction against the oil temperature (beside Xu et al. and ISO/TR 14179-2), "
           "the pinion bearings' share", ("validation.json",),
           "python tools/axle_trends.py --record", R + "pages:tables_page"),
    Record("drive-cycle", "The axle over a drive cycle",
           "WLTC class 3b: losses by part and phase cold and warm, cost and axle loss of the map, "
           "fast and full levels, the energy audit",
           ("drive-cycle-levels.json", "drive-cycle.json"),
           "rm -rf build/records/wltc3 && hypoid drive-cycle --level fast --out build/records "
           "--name wltc3 && python bench/drive_cycle.py --summary build/records/wltc3 && "
           "python bench/drive_cycle.py", R + "drive_cycle:page"),
    Record("drive-cycle-cost", "What a drive cycle costs at each level",
           "CPU, real-time factor and the axle's cycle loss against the full level of the map, "
           "fast and full levels over WLTC class 3b and US06 from -7 and 20 °C and warm",
           ("drive-cycle-cost.json",), "python bench/drive_cycle_cost.py",
           R + "drive_cycle:cost"),
    Record("study-time", "What the default study costs",
           "wall and CPU time of `hypoid study default` and of its kinds of task",
           ("study-time.json",), "python bench/study_time.py", R + "drive_cycle:study_time"),
    Record("coupling-matrix", "The coupling matrix: couplings, masters and steps in four scenes",
           "mesh-force spread, w_p error, energy residual and CPU of the gear and vehicle FMUs "
           "coupled through the half-shaft and the torque load mode, under Jacobi, Gauss-Seidel "
           "and iterative masters at 0.1-10 ms, against a fine reference",
           ("coupling-matrix.json",),
           "python bench/coupling_matrix.py --json build/records/cm.json && "
           "python bench/coupling_matrix.py --couplings half_shaft --masters jacobi "
           "--hosts fmpy --gear-values friction_table=false "
           "--label ' (friction_table off)' --json build/records/cm-direct.json && "
           "python bench/coupling_matrix.py --record build/records/cm.json "
           "build/records/cm-direct.json",
           R + "pages:tables_page"),
    Record("cosimulation", "The gear FMU in a co-simulation: energy, stability, hosts",
           "the coupling's energy residual per step, the Jacobi coupling's growth rates, the "
           "hosts' agreement and what tolerances the scene needs",
           ("cosimulation.json",), "python tests/cosim/cosim_driver.py --record && "
           "python tests/cosim/coupling_stability.py --record", R + "cosimulation:page"),
    Record("me-speed", "The gear and the vehicle as one Model Exchange system: speed",
           "real-time factor, steps, right-hand sides and events of the launch, tip-out and "
           "tip-in in a C host (full and map level, rtol 1e-6 and 1e-5, friction tables solved "
           "or already in the process) and in fmpy's CVode from Python",
           ("me-speed.json",), "python bench/me_speed.py", R + "pages:tables_page"),
]}
