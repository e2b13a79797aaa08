"""Child process of test_extremes.py: runs extreme-condition cases against the FMU one after the
other and reports each, so that a crash or a hang kills only this process and is charged to the
case that caused it.

Usage: extremes_worker.py UNZIPPED_FMU_DIR CASES_JSON FIRST_INDEX
Protocol on stdout, one line each, flushed: "BEGIN <index>" then "RESULT <json>" per case.

A case is {"id", "values": {name: value} set before initialisation, "start" (default 0), "t_end"
(the span simulated), "h", "events": [[t, {input: value}], ...] (t from the start)}.
The result says how far it got ("init" failed in initialisation, "step" failed in fmi2DoStep,
"ok" finished), the FMU's log messages, which outputs are not finite, the gross energy
throughput (sums of |dE_in| and |dE_out| over the communication steps, which a torque reversal
does not cancel) and the energy audit at the end:
    residual = E_in - E_out - E_friction - E_damping + E_excitation - (E_stored - E_stored(0)).
"""

import json
import math
import pathlib
import sys
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2]))
from hypoid.fmu.instance import FmuError, Instance  # noqa: E402

ENERGY = ["E_in", "E_out", "E_friction", "E_damping", "E_excitation", "E_stored"]
FINAL_REALS = ["w_p", "DTE", "eta", "eta_cycle", "P_loss", "W_t"]
FINAL_INTS = ["contact", "n_impacts", "solver_steps", "rhs_evals"]


class Runner:
    def __init__(self, unzipped):
        self.dir = unzipped

    def run(self, case):
        inst = Instance(self.dir, name=case["id"][:60])
        inst._call(inst.slave.setDebugLogging, True, ["logStatusWarning", "logStatusError"])
        real_outputs = [v.name for v in inst.vars.values() if v.type == "Real"
                        and v.causality in ("output", "calculatedParameter")]
        out = dict(id=case["id"], stage="init", t=0.0)
        c0 = time.process_time()
        try:
            t0 = case.get("start", 0.0)
            inst.start(case["values"], start_time=t0)
            e_prev = inst.reals(ENERGY)
            out["E_stored0"] = e_prev[-1]
            gross = [0.0, 0.0]  # sum of |dE_in| and |dE_out| over the communication steps
            out["stage"] = "step"
            h = case["h"]
            n = int(round(case["t_end"] / h))
            events = {int(round(t / h)): v for t, v in case.get("events", [])}
            for k in range(n):
                if k in events:
                    inst.set_many(events[k])
                inst.do_step(t0 + k * h, h)
                out["t"] = t0 + (k + 1) * h
                e = inst.reals(ENERGY)
                gross[0] += abs(e[0] - e_prev[0])
                gross[1] += abs(e[1] - e_prev[1])
                e_prev = e
            out["stage"] = "ok"
            out["gross_in"], out["gross_out"] = gross
        except FmuError as e:
            out["exception"] = str(e)
        out["cpu"] = time.process_time() - c0
        try:
            out["nonfinite"] = [n for n, x in zip(real_outputs, inst.reals(real_outputs))
                                if not math.isfinite(x)]
            E = dict(zip(ENERGY, inst.reals(ENERGY)))
            out["E"] = E
            if "E_stored0" in out:
                out["residual"] = (E["E_in"] - E["E_out"] - E["E_friction"] - E["E_damping"]
                                   + E["E_excitation"] - (E["E_stored"] - out["E_stored0"]))
            out["final"] = dict(zip(FINAL_REALS, inst.reals(FINAL_REALS)))
            out["final"].update(zip(FINAL_INTS, inst.ints(FINAL_INTS)))
        except FmuError as e:
            out["get_exception"] = str(e)
        out["messages"] = [list(m) for m in inst.messages if m[0] >= 1][-8:]
        inst.used = out["stage"] != "init"  # fmi2Terminate only after initialisation
        inst.close()
        return out


def main():
    unzipped, cases_json, first = sys.argv[1], sys.argv[2], int(sys.argv[3])
    with open(cases_json) as f:
        cases = json.load(f)
    runner = Runner(unzipped)
    for i in range(first, len(cases)):
        print(f"BEGIN {i}", flush=True)
        print("RESULT " + json.dumps(runner.run(cases[i])), flush=True)


if __name__ == "__main__":
    main()
