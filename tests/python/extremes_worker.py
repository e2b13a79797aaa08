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
import sys
import time

from fmpy import calloc, free, read_model_description
from fmpy.fmi1 import FMICallException
from fmpy.fmi2 import (FMU2Slave, fmi2CallbackAllocateMemoryTYPE, fmi2CallbackFreeMemoryTYPE,
                       fmi2CallbackFunctions, fmi2CallbackLoggerTYPE)

ENERGY = ["E_in", "E_out", "E_friction", "E_damping", "E_excitation", "E_stored"]


class Runner:
    def __init__(self, unzipped):
        self.dir = unzipped
        self.md = read_model_description(unzipped)
        self.var = {v.name: v for v in self.md.modelVariables}
        self.real_outputs = [v.name for v in self.md.modelVariables if v.type == "Real"
                             and v.causality in ("output", "calculatedParameter")]

    def run(self, case):
        messages = []

        def logger(env, inst, status, category, message):
            messages.append([status, category.decode(), message.decode(errors="replace")
                             .replace("%%", "%")])

        cb = fmi2CallbackFunctions()
        cb.logger = fmi2CallbackLoggerTYPE(logger)
        cb.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
        cb.freeMemory = fmi2CallbackFreeMemoryTYPE(free)
        s = FMU2Slave(guid=self.md.guid, unzipDirectory=self.dir,
                      modelIdentifier=self.md.coSimulation.modelIdentifier,
                      instanceName=case["id"][:60])
        s.instantiate(loggingOn=False, callbacks=cb)
        s.setDebugLogging(True, ["logStatusWarning", "logStatusError"])
        vr = {n: v.valueReference for n, v in self.var.items()}
        out = dict(id=case["id"], stage="init", t=0.0)
        c0 = time.process_time()

        def set_values(values):
            for name, value in values.items():
                kind = self.var[name].type
                if kind == "Real":
                    s.setReal([vr[name]], [float(value)])
                elif kind == "String":
                    s.setString([vr[name]], [str(value)])
                else:
                    s.setInteger([vr[name]], [int(value)])

        try:
            t0 = case.get("start", 0.0)
            s.setupExperiment(startTime=t0)
            set_values(case["values"])
            s.enterInitializationMode()
            s.exitInitializationMode()
            vr_e = [vr[n] for n in ENERGY]
            e_prev = s.getReal(vr_e)
            out["E_stored0"] = e_prev[-1]
            gross = [0.0, 0.0]  # sum of |dE_in| and |dE_out| over the communication steps
            out["stage"] = "step"
            h = case["h"]
            n = int(round(case["t_end"] / h))
            events = {int(round(t / h)): v for t, v in case.get("events", [])}
            for k in range(n):
                if k in events:
                    set_values(events[k])
                s.doStep(t0 + k * h, h)
                out["t"] = t0 + (k + 1) * h
                e = s.getReal(vr_e)
                gross[0] += abs(e[0] - e_prev[0])
                gross[1] += abs(e[1] - e_prev[1])
                e_prev = e
            out["stage"] = "ok"
            out["gross_in"], out["gross_out"] = gross
        except FMICallException as e:
            out["exception"] = str(e)
        out["cpu"] = time.process_time() - c0
        try:
            values = s.getReal([vr[n] for n in self.real_outputs])
            out["nonfinite"] = [n for n, x in zip(self.real_outputs, values)
                                if not math.isfinite(x)]
            E = dict(zip(ENERGY, s.getReal([vr[n] for n in ENERGY])))
            out["E"] = E
            if "E_stored0" in out:
                out["residual"] = (E["E_in"] - E["E_out"] - E["E_friction"] - E["E_damping"]
                                   + E["E_excitation"] - (E["E_stored"] - out["E_stored0"]))
            named = ["w_p", "DTE", "eta", "eta_cycle", "P_loss", "W_t"]
            out["final"] = dict(zip(named, s.getReal([vr[n] for n in named])))
            ints = ["contact", "n_impacts", "solver_steps", "rhs_evals"]
            out["final"].update(zip(ints, s.getInteger([vr[n] for n in ints])))
        except FMICallException as e:
            out["get_exception"] = str(e)
        out["messages"] = [m for m in messages if m[0] >= 1][-8:]
        try:
            if out["stage"] != "init":
                s.terminate()
        except FMICallException:
            pass
        s.freeInstance()
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
