"""Bad input through every door of the FMI 2.0 interface, co-simulation and Model Exchange.

Every parameter and input (taken from the model description, not listed by hand) gets NaN, +-Inf,
negative, zero, tiny, huge and just-out-of-range values, before and during the run; every
variable is accessed with the wrong type and set when it may not be; unknown value references,
data files that are missing, empty, truncated, malformed, huge, directories or pipes; resource
URIs of many shapes through a raw fmi2Instantiate; calls in the wrong state and order; NULL
pointers where a host may pass them; bad step sizes and bad serialized states.

Each case runs as a scripted call sequence in a child process (robust_runner.py, one process for
many cases, restarted after a crash), so that a crash or a hang is reported against its case
instead of killing pytest. A case passes when the call under test returns fmi2Error with a log
message naming the variable and value (or the argument), or - for a legal value - the instance
runs on with finite outputs or stops with a clean, logged error; the instance must always be safe
to free. A summary of the counts is printed at the end of the session.
"""

import dataclasses
import json
import math
import os
import pathlib
import queue
import re
import shutil
import subprocess
import sys
import threading
import urllib.parse

import pytest
from fmpy import read_model_description

import fmi2_raw as F
from case_clock import CaseClock

RUNNER = pathlib.Path(__file__).with_name("robust_runner.py")
# [s] of the child's CPU time: a case that uses more, or that uses none for as long, is a hang
# (case_clock.py; wall time misjudged costly cases on a loaded machine: max_step = 1e-300 takes
# 500 000 solver steps, 4.8 s of CPU under ASan)
CASE_BUDGET = 20.0
OUTCOMES = ("rejected", "later_error", "refused", "accepted", "failure", "known_failure")
CLEAN_ERRORS = ("rejected", "later_error", "refused")
INT_MIN, INT_MAX = -2**31, 2**31 - 1
DBL_MAX = 1.7976931348623157e308
F_KINDS = ("Real", "Integer", "Boolean", "String")


class Problem(Exception):
    """The case did not behave as required."""


@dataclasses.dataclass
class Case:
    id: str
    steps: list
    judge: object  # callable(transcript) -> outcome in OUTCOMES; raises Problem
    target: int = -1  # index of the step under test (-1: judged as a whole)
    silent: bool = False  # no logger: errors cannot carry messages


# ---------------------------------------------------------------------------------------------
# the session-wide tally and the runner


class Tally:
    def __init__(self):
        self.counts = {k: 0 for k in OUTCOMES}
        self.by_group = {}

    def add(self, group, outcome):
        self.counts[outcome] += 1
        g = self.by_group.setdefault(group, {k: 0 for k in OUTCOMES})
        g[outcome] += 1

    def lines(self):
        total = sum(self.counts.values())
        clean = sum(self.counts[k] for k in CLEAN_ERRORS)
        out = [f"robustness: {total} bad-input cases tried; {clean} ended in a clean fmi2Error "
               f"(rejected at the call {self.counts['rejected']}, refused instantiation "
               f"{self.counts['refused']}, clean error later {self.counts['later_error']}); "
               f"{self.counts['accepted']} legal and ran with finite outputs; "
               f"{self.counts['failure']} failures; {self.counts['known_failure']} known "
               "failures (xfail)"]
        for group, g in sorted(self.by_group.items()):
            out.append(f"  {group:<22} " + ", ".join(f"{k} {v}" for k, v in g.items() if v))
        return out


@pytest.fixture(scope="session")
def tally(request):
    t = Tally()
    yield t
    if not sum(t.counts.values()):
        return
    lines = t.lines()
    summary = pathlib.Path(request.config.rootpath) / "build" / "robustness-summary.txt"
    try:
        summary.write_text("\n".join(lines) + "\n")
    except OSError:
        pass
    capture = request.config.pluginmanager.getplugin("capturemanager")
    reporter = request.config.pluginmanager.getplugin("terminalreporter")
    with capture.global_and_fixture_disabled():
        for line in lines:
            if reporter is not None:
                reporter.write_line(line)
            else:
                print(line)


@pytest.fixture(scope="session")
def fmu(request):
    """What a case needs: the library path, GUID, resource URI and the variable table. The
    unzipped FMU is build/'s, or HG_ROBUSTNESS_FMU_DIR (scripts/sanitize.sh: build-asan/fmu)."""
    other = os.environ.get("HG_ROBUSTNESS_FMU_DIR")
    if other:
        unzipped = pathlib.Path(other)
        model_description = read_model_description(str(unzipped / "modelDescription.xml"))
    else:
        unzipped = request.getfixturevalue("unzipped")
        model_description = request.getfixturevalue("model_description")
    so = pathlib.Path(unzipped) / "binaries" / "linux64" / "HypoidGearPair.so"
    enums = {t.name: [int(i.value) for i in t.items] for t in model_description.typeDefinitions}
    variables = []
    for v in model_description.modelVariables:
        kind = "Integer" if v.type == "Enumeration" else v.type
        lo = float(v.min) if v.min is not None else None
        hi = float(v.max) if v.max is not None else None
        if v.type == "Enumeration" and v.declaredType is not None:
            items = enums[v.declaredType.name]
            lo = lo if lo is not None else min(items)
            hi = hi if hi is not None else max(items)
        variables.append(dict(name=v.name, vr=v.valueReference, kind=kind, type=v.type,
                              causality=v.causality, variability=v.variability, min=lo, max=hi,
                              start=v.start))
    real_vrs = [v["vr"] for v in variables if v["kind"] == "Real"]
    states = [d.variable.derivative.name for d in model_description.derivatives]
    return dict(so=str(so), guid=model_description.guid, states=states,
                nz=model_description.numberOfEventIndicators,
                uri=(pathlib.Path(unzipped) / "resources").as_uri(), resources=pathlib.Path(
                    unzipped) / "resources", variables=variables, real_vrs=real_vrs,
                n_vars=max(v["vr"] for v in variables) + 1)


def run_cases(fmu, cases, tmp_path, budget=CASE_BUDGET):
    """Runs the cases in child processes; returns one result per case. A crash or a hang (more
    than `budget` s of CPU, or none for as long: CaseClock) ends the child, is recorded against
    the case it was running, and a new child goes on."""
    cases_file = tmp_path / "cases.json"
    cases_file.write_text(json.dumps([{"id": c.id, "steps": c.steps} for c in cases]))
    results = [None] * len(cases)
    env = dict(os.environ, PYTHONPATH=str(RUNNER.parent))
    first = 0
    while first < len(cases):
        with open(tmp_path / "runner-stderr.txt", "w+") as err:
            proc = subprocess.Popen(
                [sys.executable, str(RUNNER), fmu["so"], fmu["guid"], fmu["uri"],
                 str(cases_file), str(first)], stdout=subprocess.PIPE, stderr=err, text=True,
                env=env, cwd=str(tmp_path))
            lines = queue.Queue()
            reader = threading.Thread(target=lambda: [lines.put(x) for x in proc.stdout]
                                      + [lines.put(None)], daemon=True)
            reader.start()
            current, clock, dead = None, CaseClock(proc.pid, budget), None
            while True:
                try:
                    line = lines.get(timeout=0.05)
                except queue.Empty:
                    why = clock.expired() if current is not None else None
                    if why:
                        proc.kill()
                        dead = {"index": current, "hang": why}
                        break
                    continue
                if line is None:  # the child ended
                    break
                if line.startswith("BEGIN "):
                    current = int(line[6:])
                    clock.start()
                elif line.startswith("RESULT "):
                    r = json.loads(line[7:])
                    results[r["index"]] = r
                    current = None
            proc.wait()
            reader.join(timeout=5)
            proc.stdout.close()
            err.seek(0)
            stderr = err.read()[-3000:]
        if dead is None and current is not None:
            dead = {"index": current, "crash": proc.returncode, "stderr": stderr}
        if dead is not None:
            results[dead["index"]] = dead
            first = dead["index"] + 1
        elif proc.returncode != 0:
            raise RuntimeError(f"runner exited with {proc.returncode} between cases: {stderr}")
        else:
            first = len(cases)
    return results


# ---------------------------------------------------------------------------------------------
# judging


NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def text_of(step):
    """The messages of a step as the host shows them (the FMU escapes '%' as '%%')."""
    return " ".join(m[2].replace("%%", "%") for m in step["msgs"])


def names_value(text, value):
    """Does the message text show the value (as the FMU formats it: %g, %.10g, ...)?"""
    if isinstance(value, float) and math.isnan(value):
        return "nan" in text.lower()
    if isinstance(value, float) and math.isinf(value):
        return ("-inf" if value < 0 else "inf") in text.lower()
    if any(fmt % value in text for fmt in ("%g", "%.10g", "%.12g", "%.17g", "%d")):
        return True
    for token in NUMBER.findall(text):
        x = float(token)
        if x == value or (value != 0 and abs(x - value) <= 1e-6 * abs(value)):
            return True
    return False


def check_invariants(case, transcript):
    """What must hold for every step of every case."""
    for i, step in enumerate(transcript):
        status = step["status"]
        if status in (F.FATAL, F.PENDING):
            raise Problem(f"step {i} ({step['op']}) returned status {status}")
        if status == F.ERROR and not case.silent and case.steps[i].get("comp") != "NULL" \
                and not step["msgs"]:
            raise Problem(f"step {i} ({step['op']}) returned fmi2Error without a log message")
        for m in step["msgs"]:
            if not m[2].strip():
                raise Problem(f"step {i} ({step['op']}) logged an empty message")
            if "%" in m[2].replace("%%", ""):
                raise Problem(f"step {i}: unescaped '%' in a message the host formats: {m[2]!r}")
        if step.get("nonfinite"):
            raise Problem(f"step {i}: fmi2GetReal returned non-finite values {step['nonfinite']}")
        if step["op"] == "get" and status == F.OK and case.steps[i]["kind"] == "Real":
            bad = [x for x in step.get("values", []) if not math.isfinite(x)]
            if bad:
                raise Problem(f"step {i}: fmi2GetReal returned {bad}")


def later_outcome(case, transcript, start):
    """After the call under test: a clean error somewhere later, or a clean run."""
    for step in transcript[start:]:
        if step["status"] == F.ERROR:
            return "later_error"
    return "accepted"


def judge_error(*words, value=None, then=None):
    """The target call must fail with fmi2Error and a message containing the words (and the
    value); then='runs' also requires the rest of the case to succeed."""
    def judge(case, transcript):
        step = transcript[case.target]
        text = text_of(step)
        if step["status"] != F.ERROR:
            raise Problem(f"{step['op']} returned {step['status']}, want fmi2Error")
        missing = [w for w in words if w not in text]
        if missing:
            raise Problem(f"message {text!r} lacks {missing}")
        if value is not None and not names_value(text, value):
            raise Problem(f"message {text!r} does not show the value {value!r}")
        if then == "runs":
            later = [s for s in transcript[case.target + 1:] if s["status"] not in (F.OK, "void")]
            if later:
                raise Problem(f"after the rejected call the instance did not run on: {later[0]}")
        return "rejected"
    return judge


def judge_value(var, value):
    """A set of one value: rejected naming variable and value, or legal and then clean."""
    def judge(case, transcript):
        step = transcript[case.target]
        text = text_of(step)
        if step["status"] == F.ERROR:
            if var["name"] not in text:
                raise Problem(f"message {text!r} does not name {var['name']}")
            if var["kind"] != "String" and not names_value(text, value):
                raise Problem(f"message {text!r} does not show the value {value!r}")
            rest = [s for s in transcript[case.target + 1:] if s["status"] not in (F.OK, "void")]
            if rest:
                raise Problem(f"after the rejected set the instance did not run on: {rest[0]}")
            return "rejected"
        if step["status"] != F.OK:
            raise Problem(f"set returned {step['status']}")
        if var["kind"] in ("Real", "Integer") and not legal(var, value):
            raise Problem(f"{var['name']} = {value!r} is outside [{var['min']}, {var['max']}] "
                          "or not finite, but was accepted")
        return later_outcome(case, transcript, case.target + 1)
    return judge


def judge_ok(case, transcript):
    """The call under test is legal (e.g. NULL arrays with n = 0): it must return fmi2OK."""
    step = transcript[case.target]
    if step["status"] not in (F.OK, "void", "instance"):
        raise Problem(f"{step['op']} returned {step['status']} ({text_of(step)!r}), want fmi2OK")
    return later_outcome(case, transcript, case.target + 1)


def judge_run_or_clean_error(case, transcript):
    """The case as a whole must end in success or in clean, logged errors."""
    return later_outcome(case, transcript, 0)


def legal(var, value):
    if not math.isfinite(value):
        return False
    if var["min"] is not None and value < var["min"]:
        return False
    return var["max"] is None or value <= var["max"]


def settle(cases, results, tally, group, known_issue=None):
    """Judges the results and counts them; known_issue: the reason of an expected failure."""
    failures = []
    for case, result in zip(cases, results):
        if result is None:
            outcome, why = "failure", "no result (runner lost the case)"
        elif "crash" in result:
            outcome, why = "failure", f"CRASH (exit {result['crash']}): {result['stderr']}"
        elif "hang" in result:
            outcome, why = "failure", f"HANG ({result['hang']})"
        elif result["exception"]:
            outcome, why = "failure", f"runner exception {result['exception']}"
        else:
            try:
                check_invariants(case, result["transcript"])
                outcome, why = case.judge(case, result["transcript"]), None
            except Problem as p:
                outcome, why = "failure", str(p)
        if outcome == "failure" and known_issue:
            outcome = "known_failure"
        tally.add(group, outcome)
        if outcome in ("failure", "known_failure"):
            failures.append(f"{case.id}: {why}")
    if failures and known_issue:
        pytest.xfail(f"{known_issue}: " + "; ".join(failures))
    assert not failures, f"{len(failures)} of {len(cases)} cases failed:\n" + "\n".join(
        failures[:40])


# ---------------------------------------------------------------------------------------------
# building cases


def inst(**kw):
    return dict(op="instantiate", **kw)


def reach(stage, **inst_kw):
    """Steps that bring a fresh instance to a state of the FMI 2.0 co-simulation state machine."""
    steps = [inst(**inst_kw)]
    if stage == "instantiated":
        return steps + [dict(op="setup", start=0.0)]
    steps += [dict(op="setup", start=0.0), dict(op="enter")]
    if stage == "initialization":
        return steps
    steps += [dict(op="exit"), dict(op="step", h=1e-4, n=2)]
    if stage == "step_complete":
        return steps
    if stage == "terminated":
        return steps + [dict(op="terminate")]
    if stage == "error":  # a serialized state whose state field says 'error' (16)
        return steps + [dict(op="state_get"), dict(op="serialize"),
                        dict(op="deserialize", mutate=[[12, 4 ^ 16]]), dict(op="state_set",
                                                                              state="d")]
    raise ValueError(stage)


def finish(stage, fmu):
    """After the call under test: run on to a few steps and read every Real variable."""
    tail = []
    if stage in ("instantiated",):
        tail.append(dict(op="enter"))
    if stage in ("instantiated", "initialization"):
        tail.append(dict(op="exit"))
    tail += [dict(op="step", h=1e-4, n=3), dict(op="all_reals", vrs=fmu["real_vrs"]),
             dict(op="terminate")]
    return tail


def set_step(var, value, **kw):
    return dict(op="set", kind=var["kind"], vrs=[var["vr"]], values=[value], target=True, **kw)


def real_values(var):
    values = [math.nan, math.inf, -math.inf, -1.0, -1e300, 0.0, -0.0, 5e-324, 1e-300, 1e300,
              DBL_MAX, -DBL_MAX]
    if var["min"] is not None:
        values.append(math.nextafter(var["min"], -math.inf))
        values.append(var["min"] - max(1.0, abs(var["min"])))
    if var["max"] is not None:
        values.append(math.nextafter(var["max"], math.inf))
        values.append(var["max"] * 10 + 1)
    seen, out = set(), []
    for v in values:
        key = repr(v)
        if key not in seen:
            seen.add(key)
            out.append(v)
    return out


def int_values(var):
    values = [0, -1, INT_MIN, INT_MAX, 1000000]
    if var["min"] is not None:
        values.append(int(var["min"]) - 1)
    if var["max"] is not None:
        values.append(int(var["max"]) + 1)
    return [v for v in dict.fromkeys(values) if INT_MIN <= v <= INT_MAX]


def settable_vars(fmu):
    return [v for v in fmu["variables"] if v["causality"] in ("parameter", "input")
            and v["kind"] in ("Real", "Integer", "Boolean")]


# ---------------------------------------------------------------------------------------------
# 1. values: every parameter and input


def value_cases(fmu):
    cases = []
    for var in settable_vars(fmu):
        stages = ["instantiated", "initialization"]
        if var["causality"] == "input":
            stages.append("step_complete")
        values = real_values(var) if var["kind"] == "Real" else int_values(var)
        for stage in stages:
            for value in values:
                steps = reach(stage) + [set_step(var, value)] + finish(stage, fmu)
                cases.append(Case(f"{var['name']}={value!r}@{stage}", steps,
                                  judge_value(var, value), target=len(reach(stage))))
    return cases


def test_every_parameter_and_input_rejects_bad_values(fmu, tmp_path, tally):
    cases = value_cases(fmu)
    assert len(cases) > 300
    settle(cases, run_cases(fmu, cases, tmp_path), tally, "values")


def test_input_derivatives_reject_bad_values(fmu, tmp_path, tally):
    cases = []
    inputs = [v for v in fmu["variables"] if v["causality"] == "input" and v["kind"] == "Real"]
    others = [v for v in fmu["variables"] if v["causality"] != "input" and v["kind"] == "Real"]
    for var in inputs:
        for value in (math.nan, math.inf, -math.inf):
            steps = reach("step_complete") + [dict(op="der_in", vrs=[var["vr"]], orders=[1],
                                                   values=[value], target=True)]
            steps += finish("step_complete", fmu)
            cases.append(Case(f"der {var['name']}={value}", steps,
                              judge_error(var["name"], value=value, then="runs"),
                              target=len(reach("step_complete"))))
        for order in (0, 2, -1, INT_MAX):
            steps = reach("step_complete") + [dict(op="der_in", vrs=[var["vr"]], orders=[order],
                                                   values=[1.0], target=True)]
            cases.append(Case(f"der {var['name']} order {order}", steps,
                              judge_error(var["name"], f"order {order}"),
                              target=len(reach("step_complete"))))
        if var["min"] is None and var["max"] is None:
            continue
        span = 10.0 * (float(var["max"]) - float(var["min"])) / 1e-4  # leaves the range in a step
        for value in (1e300, -1e300, span, -span):  # the extrapolation leaves the range
            steps = reach("step_complete") + [dict(op="der_in", vrs=[var["vr"]], orders=[1],
                                                   values=[value]),
                                              dict(op="step", h=1e-4, target=True),
                                              dict(op="der_in", vrs=[var["vr"]], orders=[1],
                                                   values=[0.0])]
            steps += finish("step_complete", fmu)
            cases.append(Case(f"der {var['name']}={value}", steps,
                              judge_error(var["name"], "range", value=value, then="runs"),
                              target=len(reach("step_complete")) + 1))
    for var in others[:: max(1, len(others) // 12)]:
        steps = reach("step_complete") + [dict(op="der_in", vrs=[var["vr"]], orders=[1],
                                               values=[1.0], target=True)]
        cases.append(Case(f"der of non-input {var['name']}", steps, judge_error(var["name"]),
                          target=len(reach("step_complete"))))
    settle(cases, run_cases(fmu, cases, tmp_path), tally, "input derivatives")


def test_absurd_values_of_inputs_fail_fast(fmu, tmp_path, tally):
    """Huge finite values (or ramps) of the torque and speed inputs: the inputs carry declared
    ranges, so they are refused at once (they used to make CVODE grind for minutes)."""
    cases = []
    for var in fmu["variables"]:
        if var["causality"] != "input" or var["kind"] != "Real" or var["name"] == "T_bath":
            continue
        value = 1e10 if var["name"] != "T_w" else -1e10
        torque = [dict(op="set", kind="Integer", vrs=[load_mode_vr(fmu)], values=[1])] \
            if var["name"] == "T_w" else []
        steps = reach("instantiated") + [set_step(var, value)] + torque
        steps += finish("instantiated", fmu)
        cases.append(Case(f"{var['name']}={value}", steps, judge_value(var, value),
                          target=len(reach("instantiated"))))
        steps = reach("step_complete") + [dict(op="der_in", vrs=[var["vr"]], orders=[1],
                                               values=[1e20], target=True)]
        steps += finish("step_complete", fmu)
        cases.append(Case(f"d{var['name']}/dt=1e20", steps, judge_ok,
                          target=len(reach("step_complete"))))
    # the same through a serialized state whose input derivatives are garbage. The blob of
    # fmi/fmi2_state.c: magic (4 bytes), size (8), then the snapshot, whose input_der (T_s,
    # T_w, T_bath, w_set) starts at snapshot offset 32, i.e. blob offset 44: the high bytes of
    # T_s and w_set are at 51 and 75
    for offset in (51, 75):
        steps = reach("step_complete") + [
            dict(op="state_get"), dict(op="serialize"),
            dict(op="deserialize", mutate=[[offset, 0x7F]], target=True),
            dict(op="state_set", state="d"), dict(op="step", h=1e-4, n=2),
            dict(op="all_reals", vrs=fmu["real_vrs"])]
        cases.append(Case(f"serialized state, byte {offset} ^ 0x7F", steps,
                          judge_run_or_clean_error, target=len(reach("step_complete")) + 2))
    settle(cases, run_cases(fmu, cases, tmp_path, budget=2.0), tally, "absurd input values")


def load_mode_vr(fmu):
    return next(v["vr"] for v in fmu["variables"] if v["name"] == "load_mode")


# ---------------------------------------------------------------------------------------------
# 2. variables that may not be set now, wrong types, unknown value references


def test_fixed_parameters_and_outputs_cannot_be_set(fmu, tmp_path, tally):
    cases = []
    for var in fmu["variables"]:
        if var["kind"] == "String":
            value = "x"
        elif var["kind"] == "Real":
            value = float(var["start"]) if var["start"] is not None else 1.0
        elif var["kind"] == "Boolean":
            value = int(var["start"] == "true")
        else:
            value = int(float(var["start"])) if var["start"] is not None else 1
        if var["causality"] == "parameter":
            steps = reach("step_complete") + [set_step(var, value)] + finish("step_complete",
                                                                              fmu)
            cases.append(Case(f"set fixed {var['name']} after init", steps,
                              judge_error(var["name"], "fixed parameter", then="runs"),
                              target=len(reach("step_complete"))))
        elif var["causality"] in ("output", "calculatedParameter"):
            for stage in ("instantiated", "step_complete"):
                steps = reach(stage) + [set_step(var, value)] + finish(stage, fmu)
                cases.append(Case(f"set {var['causality']} {var['name']}@{stage}", steps,
                                  judge_error(var["name"], "computed by the FMU", then="runs"),
                                  target=len(reach(stage))))
        for stage in ("terminated", "error"):
            steps = reach(stage) + [set_step(var, value)]
            cases.append(Case(f"set {var['name']}@{stage}", steps,
                              judge_error("fmi2Set", "not allowed in state"),
                              target=len(reach(stage))))
    settle(cases, run_cases(fmu, cases, tmp_path), tally, "not settable")


def test_wrong_type_access_names_the_variable(fmu, tmp_path, tally):
    cases = []
    samples = {"Real": 1.0, "Integer": 1, "Boolean": 1, "String": "x"}
    for var in fmu["variables"]:
        for kind in F_KINDS:
            if kind == var["kind"]:
                continue
            get = dict(op="get", kind=kind, vrs=[var["vr"]], target=True)
            steps = reach("initialization") + [get] + finish("initialization", fmu)
            cases.append(Case(f"get{kind} {var['name']}", steps,
                              judge_error(var["name"], var["kind"], then="runs"),
                              target=len(reach("initialization"))))
            put = dict(op="set", kind=kind, vrs=[var["vr"]], values=[samples[kind]], target=True)
            steps = reach("instantiated") + [put] + finish("instantiated", fmu)
            cases.append(Case(f"set{kind} {var['name']}", steps,
                              judge_error(var["name"], var["kind"], then="runs"),
                              target=len(reach("instantiated"))))
    settle(cases, run_cases(fmu, cases, tmp_path), tally, "wrong type")


def test_unknown_value_references(fmu, tmp_path, tally):
    cases = []
    n = fmu["n_vars"]
    samples = {"Real": 1.0, "Integer": 1, "Boolean": 1, "String": "x"}
    for vr in (n, n + 1, 2**31, 2**32 - 1):
        for kind in F_KINDS:
            get = dict(op="get", kind=kind, vrs=[vr], target=True)
            cases.append(Case(f"get{kind} vr {vr}", reach("initialization") + [get]
                              + finish("initialization", fmu),
                              judge_error(str(vr), "unknown value reference", then="runs"),
                              target=len(reach("initialization"))))
            put = dict(op="set", kind=kind, vrs=[vr], values=[samples[kind]], target=True)
            cases.append(Case(f"set{kind} vr {vr}", reach("instantiated") + [put]
                              + finish("instantiated", fmu),
                              judge_error(str(vr), "unknown value reference", then="runs"),
                              target=len(reach("instantiated"))))
        mixed = dict(op="get", kind="Real", vrs=[fmu["real_vrs"][0], vr], target=True)
        cases.append(Case(f"getReal [good, {vr}]", reach("step_complete") + [mixed],
                          judge_error(str(vr)), target=len(reach("step_complete"))))
    settle(cases, run_cases(fmu, cases, tmp_path), tally, "unknown vr")


# ---------------------------------------------------------------------------------------------
# 2b. data that each lie in their declared ranges but cannot exist together: bearings whose
# outside diameter is not outside their bore, a preload beyond the pair's static rating, an oil
# colder or hotter than the lubricant's data describe (docs/axle.md)


def sets(fmu, values):
    """Set steps for {name: value} (enumerations by item code)."""
    by = {v["name"]: v for v in fmu["variables"]}
    return [dict(op="set", kind=by[n]["kind"], vrs=[by[n]["vr"]], values=[x])
            for n, x in values.items()]


IMPOSSIBLE_AT_INIT = [  # ({name: value}, the variable and value the message must name)
    ({"axle_losses": 2, "brg_gn_D": 0.045}, "brg_gn_D", 0.045),  # bore 50 mm
    ({"axle_losses": 2, "brg_ph_d": 0.09}, "brg_ph_D", 0.09),   # bore = outside diameter
    ({"axle_losses": 2, "F_pre_p": 90000.0}, "F_pre_p", 90000.0),  # 32306: C_0/Y_0 = 81 kN
    ({"axle_losses": 2, "F_pre_g": 50000.0, "brg_g_C0": 20000.0}, "F_pre_g", 50000.0),
    ({"T_bath": 228.15}, "T_bath", 228.15),    # -45 degC: OS265962 is a -41 degC oil
    ({"T_bath": 463.15}, "T_bath", 463.15),    # 190 degC
    ({"axle_losses": 2, "thermal_model": 2, "T_oil0": 220.0}, "T_oil0", 220.0),
]


def test_impossible_axle_and_oil_data_fail_naming_the_variable(fmu, tmp_path, tally):
    cases = []
    for values, name, value in IMPOSSIBLE_AT_INIT:
        steps = reach("instantiated") + sets(fmu, values) + [dict(op="enter"),
                                                             dict(op="exit", target=True)]
        cases.append(Case(f"{values}", steps, judge_error(name, value=value),
                          target=len(steps) - 1))
    # the bath cooled below the lubricant's range while running: the next step refuses it
    for T in (220.0, 470.0):
        steps = reach("step_complete") + sets(fmu, {"T_bath": T}) + [
            dict(op="step", h=1e-4, target=True)]
        cases.append(Case(f"T_bath={T} while running", steps, judge_error("T_bath", value=T),
                          target=len(steps) - 1))
    settle(cases, run_cases(fmu, cases, tmp_path), tally, "impossible axle and oil data")


# ---------------------------------------------------------------------------------------------
# 3. data files: gear_set_file and lubricant_file


def is_number(text):
    try:
        float(text)
        return True
    except ValueError:
        return False


def file_variants(tmp_path, resources, which):
    """(label, path string, expect-error) for the file parameter `which`."""
    src = resources / ("gearsets/gearset1.txt" if which == "gear_set_file"
                       else "lubricants/OS265962.txt")
    good = src.read_text()
    lines = good.splitlines(keepends=True)
    at = next(i for i, ln in enumerate(lines) if ln.strip() and not ln.lstrip().startswith("#"))
    header, comments, rest = lines[at], "".join(lines[:at]), "".join(lines[at + 1:])
    d = tmp_path / which
    d.mkdir()
    out = []

    def put(label, data, mode="w"):
        p = d / (label + ".txt")
        if isinstance(data, bytes):
            p.write_bytes(data)
        else:
            p.write_text(data)
        out.append((label, str(p)))

    put("empty", "")
    put("blank", "\n\n   \n")
    put("comments_only", "# nothing\n# here\n")
    for frac in (0.1, 0.5, 0.9):
        put(f"truncated_{int(frac * 100)}pct", "".join(lines[:max(1, int(len(lines) * frac))]))
    put("truncated_mid_line", good[: len(good) // 2 + 3])
    put("header_only", comments + header)
    put("wrong_header", comments + "hypoid-something 1\n" + rest)
    put("wrong_version", comments + header.split()[0] + " 99\n" + rest)
    put("version_text", comments + header.split()[0] + " one\n" + rest)
    put("no_header", comments + rest)
    body = [ln for ln in lines[at + 1:] if ln.strip() and not ln.lstrip().startswith("#")]
    numeric = next(ln for ln in body if len(ln.split()) == 2 and is_number(ln.split()[1]))
    key = numeric.split()[0]
    put("duplicate_key", good + body[0])
    put("unknown_key", good + "no_such_key 1\n")
    put("nan_value", good.replace(numeric, f"{key} nan\n", 1))
    put("inf_value", good.replace(numeric, f"{key} inf\n", 1))
    put("huge_value", good.replace(numeric, f"{key} 1e400\n", 1))
    put("negative_value", good.replace(numeric, f"{key} -1e30\n", 1))
    put("text_value", good.replace(numeric, f"{key} twelve\n", 1))
    put("missing_key", good.replace(numeric, "", 1))
    put("binary", bytes(range(256)) * 64)
    put("nul_byte", good.encode() + b"\0x 1\n")
    put("not_utf8", b"\xff\xfe" + good.encode("utf-16-le"))
    put("one_long_line", header + key + " " + "1 " * 500000 + "\n")
    put("many_keys", header + "".join(f"k{i} 1\n" for i in range(300000)))
    put("many_keys_repeat", header + "".join(f"k{i} 1\n" for i in range(300000)) + "k7 2\n")
    put("over_4MiB", header + ("# " + "x" * 1021 + "\n") * 4200)
    put("crlf", good.replace("\n", "\r\n"))
    put("percent_signs_%s%n%x", comments + header)  # broken, so the name shows in a message
    nested = d / "a directory"
    nested.mkdir()
    out.append(("directory", str(nested)))
    fifo = d / "fifo"
    os.mkfifo(fifo)
    out.append(("fifo", str(fifo)))
    link = d / "loop"
    os.symlink(link, link)
    out.append(("symlink_loop", str(link)))
    out.append(("missing", str(d / "does-not-exist.txt")))
    out.append(("dev_null", "/dev/null"))
    out.append(("dev_zero", "/dev/zero"))
    out.append(("dev_urandom", "/dev/urandom"))
    out.append(("proc_self_mem", "/proc/self/mem"))
    out.append(("relative_escape", "../../../../../../../../etc/passwd"))
    out.append(("relative_missing", "no/such/file.txt"))
    out.append(("root_dir", "/"))
    out.append(("dot", "."))
    out.append(("long_4095", "/" + "a" * 4094))
    out.append(("newline", str(d / "a\nb.txt")))
    out.append(("spaces_only", "   "))
    return out


@pytest.mark.parametrize("which", ["gear_set_file", "lubricant_file"])
def test_bad_data_files_fail_initialisation_naming_the_file(fmu, tmp_path, tally, which):
    var = next(v for v in fmu["variables"] if v["name"] == which)
    cases = []
    for label, path in file_variants(tmp_path, fmu["resources"], which):
        steps = reach("instantiated") + [dict(op="set", kind="String", vrs=[var["vr"]],
                                              values=[path]),
                                         dict(op="enter"), dict(op="exit", target=True)]
        steps += [dict(op="step", h=1e-4, n=2), dict(op="all_reals", vrs=fmu["real_vrs"])]
        shown = os.path.basename(path.rstrip("/")) or path
        if label in ("crlf",):
            judge = judge_run_or_clean_error  # may be accepted: then it must run
        elif label == "spaces_only":
            judge = judge_run_or_clean_error
        else:
            judge = judge_error(which, shown[:60].replace("%", "%"))
        cases.append(Case(f"{which} {label}", steps, judge, target=len(steps) - 3))
    # strings the FMU must refuse at fmi2SetString
    for label, value in (("4096 chars", "/" + "b" * 4095), ("1 MiB", "c" * 2**20),
                         ("NULL", None)):
        steps = reach("instantiated") + [dict(op="set", kind="String", vrs=[var["vr"]],
                                              values=[value], target=True)]
        steps += finish("instantiated", fmu)
        cases.append(Case(f"{which} {label}", steps, judge_error(which, then="runs"),
                          target=len(reach("instantiated"))))
    settle(cases, run_cases(fmu, cases, tmp_path), tally, "data files")


# ---------------------------------------------------------------------------------------------
# 4. resource URIs through fmi2Instantiate


def uri_variants(fmu, tmp_path):
    """(label, uri, expectation): 'runs' | 'refused' | 'init_error'."""
    res = fmu["resources"]
    path = str(res)
    odd = tmp_path / "dir with space %25 & ü"
    shutil.copytree(res, odd / "resources")
    odd_res = odd / "resources"
    spaced = tmp_path / "dir with space"
    shutil.copytree(res, spaced / "resources")
    quoted = urllib.parse.quote(str(odd_res))
    every = "/" + "".join(f"%{b:02X}" for b in str(res)[1:].encode())
    return [
        ("file:///abs", "file://" + path, "runs"),
        ("file:/abs", "file:" + path, "runs"),
        ("file://localhost/abs", "file://localhost" + path, "runs"),
        ("FILE://LOCALHOST/abs", "FILE://LOCALHOST" + path, "runs"),
        ("trailing slash", "file://" + path + "/", "runs"),
        ("trailing slashes", "file://" + path + "///", "runs"),
        ("percent %20 %25 utf-8", "file://" + quoted, "runs"),
        ("every byte escaped", "file://" + every, "runs"),
        ("lowercase hex", "file://" + every.lower(), "runs"),
        ("double slash in path", "file://" + path.replace("/", "//"), "runs"),
        ("unescaped space", "file://" + str(spaced / "resources"), "runs"),
        ("unescaped %25 dir name", "file://" + str(odd_res), "init_error"),
        ("invalid %zz", "file://" + path + "%zz", "refused"),
        ("truncated %2", "file://" + path + "%2", "refused"),
        ("lone %", "file://" + path + "%", "refused"),
        ("%00", "file://" + path + "%00x", "refused"),
        ("http:", "http://example.com/resources", "refused"),
        ("https:", "https://example.com/resources", "refused"),
        ("ftp:", "ftp://example.com/resources", "refused"),
        ("remote host", "file://otherhost" + path, "refused"),
        ("localhost without path", "file://localhost", "refused"),
        ("file:// only", "file://", "refused"),
        ("file: only", "file:", "refused"),
        ("relative file:", "file:resources", "refused"),
        ("relative path", "resources", "refused"),
        ("bare absolute path", path, "refused"),
        ("windows style", "file:///C:/fmu/resources", "init_error"),
        ("nonexistent dir", "file:///nonexistent/resources", "init_error"),
        ("a file, not a dir", "file:///dev/null", "init_error"),
        ("root", "file:///", "init_error"),
        ("query and fragment", "file://" + path + "?x=1#frag", "init_error"),
        ("very long", "file:///" + "d/" * 5000, "init_error"),
        ("escaped slash %2F", "file:///" + path[1:].replace("/", "%2F"), "runs"),
        ("control chars", "file://" + path + "%0A%09", "init_error"),
        ("empty", "", "init_error"),
        ("NULL", None, "init_error"),
        ("whitespace", "   ", "refused"),
        ("invalid utf-8", "file:///\udcff\udcfe", "init_error"),
    ]


def test_resource_uris(fmu, tmp_path, tally):
    cases = []
    for label, uri, expect in uri_variants(fmu, tmp_path):
        steps = [inst(uri=uri, target=True)]
        if expect != "refused":
            steps += [dict(op="setup", start=0.0), dict(op="enter"), dict(op="exit"),
                      dict(op="step", h=1e-4, n=2), dict(op="all_reals", vrs=fmu["real_vrs"])]

        def judge(case, tr, expect=expect, uri=uri):
            first = tr[0]
            if expect == "refused":
                if first["status"] != "NULL":
                    raise Problem("instantiated, want refused")
                text = text_of(first)
                if "fmuResourceLocation" not in text:
                    raise Problem(f"message {text!r} does not name fmuResourceLocation")
                return "refused"
            if first["status"] != "instance":
                raise Problem(f"refused ({text_of(first)!r}), want an instance")
            statuses = [s["status"] for s in tr[1:]]
            if expect == "runs":
                if any(s != F.OK for s in statuses):
                    raise Problem(f"did not run: {[text_of(s) for s in tr[1:]]}")
                return "accepted"
            exit_step = tr[3]
            if exit_step["status"] != F.ERROR:
                raise Problem(f"fmi2ExitInitializationMode returned {exit_step['status']}")
            return "later_error"

        cases.append(Case(f"uri {label}", steps, judge, target=0))
    settle(cases, run_cases(fmu, cases, tmp_path), tally, "resource URIs")


# ---------------------------------------------------------------------------------------------
# 5. fmi2Instantiate arguments and NULL pointers


def all_errors(case, tr):
    """Every call from the target on must fail (with a message unless there is no logger)."""
    bad = [s for s in tr[case.target:] if s["status"] != F.ERROR]
    if bad:
        raise Problem(f"want fmi2Error, got {bad[0]}")
    return "rejected"


def test_instantiate_arguments(fmu, tmp_path, tally):
    def refused(*words):
        def judge(case, tr):
            if tr[0]["status"] != "NULL":
                raise Problem("instantiated, want refused")
            text = text_of(tr[0])
            if not case.silent and not all(w in text for w in words):
                raise Problem(f"message {text!r} lacks {words}")
            return "refused"
        return judge

    def runs(case, tr):
        if tr[0]["status"] != "instance" or any(s["status"] not in (F.OK, "instance")
                                                  for s in tr[1:]):
            raise Problem(f"want a working instance: {tr}")
        return "accepted"

    run = [dict(op="setup", start=0.0), dict(op="enter"), dict(op="exit"),
           dict(op="step", h=1e-4, n=2), dict(op="all_reals", vrs=fmu["real_vrs"])]
    cases = [
        Case("NULL instanceName", [inst(name=None)], refused("instanceName"), target=0),
        Case("empty instanceName", [inst(name="")], refused("instanceName"), target=0),
        Case("blank instanceName", [inst(name=" \t\n")], refused("instanceName"), target=0),
        Case("NULL GUID", [inst(guid=None)], refused("GUID", "(null)"), target=0),
        Case("wrong GUID", [inst(guid="{0000}")], refused("GUID", "{0000}"), target=0),
        Case("empty GUID", [inst(guid="")], refused("GUID"), target=0),
        Case("type 7", [inst(type=7)], refused("fmi2ModelExchange"), target=0),
        Case("type -1", [inst(type=-1)], refused("fmi2ModelExchange"), target=0),
        Case("NULL callbacks", [inst(callbacks="null")], refused(), target=0, silent=True),
        Case("NULL callbacks, NULL name", [inst(callbacks="null", name=None)], refused(),
             target=0, silent=True),
        Case("NULL logger runs", [inst(callbacks="no_logger")] + run, runs, target=0,
             silent=True),
        Case("NULL logger, wrong GUID", [inst(callbacks="no_logger", guid="x")], refused(),
             target=0, silent=True),
        Case("NULL logger, errors everywhere", [inst(callbacks="no_logger"),
                                                dict(op="step", h=1e-4),
                                                dict(op="set", kind="Real", vrs=[2**31],
                                                     values=[1.0]),
                                                dict(op="get", kind="Real", vrs=[0]),
                                                dict(op="setup", start=math.nan),
                                                dict(op="log", cats=["nonsense"]),
                                                dict(op="deserialize", bytes="00")],
             all_errors, target=1, silent=True),
        Case("long instanceName", [inst(name="n" * 100000)] + run, runs, target=0),
        Case("instanceName with %s%n", [inst(name="%s%n%x")] + run
             + [dict(op="step", t=99.0, h=1e-4)], all_errors, target=len(run) + 1),
        Case("logging on", [inst(logging=1)] + run, runs, target=0),
        Case("two instances same name", [inst(slot="a"), inst(slot="b")]
             + [dict(s, slot="b") for s in run], runs, target=0),
    ]
    settle(cases, run_cases(fmu, cases, tmp_path), tally, "instantiate")


def test_null_pointers(fmu, tmp_path, tally):
    vr0 = fmu["real_vrs"][0]
    int_vr = next(v["vr"] for v in fmu["variables"] if v["kind"] == "Integer")
    str_var = next(v for v in fmu["variables"] if v["kind"] == "String")
    sc = reach("step_complete")
    cases = []
    # NULL arrays with n = 0: allowed, a no-op
    for op, stage in (("get", "step_complete"), ("set", "instantiated"), ("set", "step_complete")):
        for kind in F_KINDS:
            step = dict(op=op, kind=kind, vrs=[], values=[], n=0, null_vrs=True,
                        null_values=True, target=True)
            cases.append(Case(f"{op}{kind} n=0 NULL arrays @{stage}", reach(stage) + [step]
                              + finish(stage, fmu), judge_ok, target=len(reach(stage))))
    # NULL arrays with n > 0: an error, no crash
    for op, stage in (("get", "step_complete"), ("set", "instantiated")):
        for kind in F_KINDS:
            vr = {"Real": vr0, "Integer": int_vr, "Boolean": int_vr, "String": str_var["vr"]}[kind]
            value = {"Real": 1.0, "Integer": 1, "Boolean": 1, "String": "x"}[kind]
            for null in ("null_vrs", "null_values"):
                step = dict(op=op, kind=kind, vrs=[vr], values=[value], n=1, target=True,
                            **{null: True})
                cases.append(Case(f"{op}{kind} n=1 {null}", reach(stage) + [step]
                                  + finish(stage, fmu), judge_error("NULL", then="runs"),
                                  target=len(reach(stage))))
    cases.append(Case("setString NULL element", reach("instantiated")
                      + [dict(op="set", kind="String", vrs=[str_var["vr"]], values=[None],
                              target=True)] + finish("instantiated", fmu),
                      judge_error(str_var["name"], "NULL", then="runs"),
                      target=len(reach("instantiated"))))
    # NULL instance to every function
    null_calls = [dict(op="setup"), dict(op="enter"), dict(op="exit"), dict(op="terminate"),
                  dict(op="reset"), dict(op="cancel"), dict(op="log", cats=None, n=0),
                  dict(op="step", t=0.0, h=1e-4), dict(op="der_in", vrs=[0], orders=[1],
                                                       values=[1.0]),
                  dict(op="der_out"), dict(op="dir_der"), dict(op="state_get"),
                  dict(op="state_set"), dict(op="state_free"), dict(op="deserialize", bytes="00"),
                  ] + [dict(op="get", kind=k, vrs=[0]) for k in F_KINDS] \
        + [dict(op="set", kind="Real", vrs=[0], values=[1.0])] \
        + [dict(op="status", kind=k) for k in ("GetStatus", "GetRealStatus",
                                               "GetIntegerStatus", "GetBooleanStatus",
                                               "GetStringStatus")]
    for call in null_calls:
        steps = [inst(), dict(call, comp="NULL", target=True), dict(op="setup", start=0.0),
                 dict(op="enter"), dict(op="exit"), dict(op="step", h=1e-4)]
        cases.append(Case(f"NULL instance {call['op']} {call.get('kind', '')}", steps,
                          judge_error(then="runs"), target=1))
    cases.append(Case("fmi2FreeInstance(NULL)", [dict(op="free", comp="NULL", target=True)],
                      judge_ok, target=0))
    # logging
    cases += [
        Case("setDebugLogging n=0 NULL", reach("instantiated") + [dict(op="log", cats=None, n=0,
                                                                       target=True)],
             judge_ok, target=2),
        Case("setDebugLogging n=2 NULL", reach("instantiated") + [dict(op="log", cats=None, n=2,
                                                                       target=True)],
             judge_error("NULL"), target=2),
        Case("setDebugLogging NULL category", reach("instantiated")
             + [dict(op="log", cats=["logAll", None], target=True)], judge_error("(null)"),
             target=2),
        Case("setDebugLogging unknown category", reach("instantiated")
             + [dict(op="log", cats=["logNope"], target=True)], judge_error("logNope"),
             target=2),
        Case("setDebugLogging %s category", reach("instantiated")
             + [dict(op="log", cats=["%s%s%n"], target=True)], judge_error("unknown"),
             target=2),
    ]
    # FMU states
    cases += [
        Case("getFMUstate NULL out", sc + [dict(op="state_get", null_out=True, target=True)],
             judge_error("NULL"), target=len(sc)),
        Case("setFMUstate NULL", sc + [dict(op="state_set", state="none", target=True)],
             judge_error("NULL"), target=len(sc)),
        Case("freeFMUstate NULL pointer", sc + [dict(op="state_free", null_ptr=True,
                                                     target=True)], judge_ok, target=len(sc)),
        Case("freeFMUstate pointer to NULL", sc + [dict(op="state_free", state="none",
                                                        target=True)], judge_ok, target=len(sc)),
        Case("serializedSize NULL state", sc + [dict(op="serialize", state="none", target=True)],
             judge_error("NULL"), target=len(sc)),
        Case("serializedSize NULL size", sc + [dict(op="state_get"),
                                               dict(op="serialize", null_size=True, target=True)],
             judge_error("NULL"), target=len(sc) + 1),
        Case("serialize NULL buffer", sc + [dict(op="state_get"),
                                            dict(op="serialize", null_buffer=True, target=True)],
             judge_error("NULL"), target=len(sc) + 1),
        Case("serialize short buffer", sc + [dict(op="state_get"),
                                             dict(op="serialize", extra=-1, target=True)],
             judge_error("smaller"), target=len(sc) + 1),
        Case("deserialize NULL bytes", sc + [dict(op="deserialize", bytes="00" * 64,
                                                  null_bytes=True, target=True)],
             judge_error("bytes"), target=len(sc)),
        Case("deserialize NULL out", sc + [dict(op="state_get"), dict(op="serialize"),
                                           dict(op="deserialize", null_out=True, target=True)],
             judge_error("bytes"), target=len(sc) + 2),
        Case("deserialize 0 bytes", sc + [dict(op="deserialize", bytes="", target=True)],
             judge_error("0 bytes"), target=len(sc)),
    ]
    # status queries
    for kind in ("GetStatus", "GetRealStatus", "GetBooleanStatus"):
        cases.append(Case(f"{kind} NULL value", sc + [dict(op="status", kind=kind,
                                                           null_value=True, target=True)],
                          judge_error("NULL"), target=len(sc)))
    settle(cases, run_cases(fmu, cases, tmp_path), tally, "NULL pointers")


# ---------------------------------------------------------------------------------------------
# 6. calls in the wrong state and the wrong order

# the FMI 2.0 co-simulation state machine (standard, section 4.2.4): states a call is allowed in
STATES = ("instantiated", "initialization", "step_complete", "terminated", "error")
ALLOWED = {
    "setup": {"instantiated"},
    "enter": {"instantiated"},
    "exit": {"initialization"},
    "terminate": {"step_complete", "error"},  # 'error': tolerated, so a host can always end
    "reset": set(STATES),
    "step": {"step_complete"},
    "get": {"initialization", "step_complete", "terminated", "error"},
    "set": {"instantiated", "initialization", "step_complete"},
    "der_in": {"instantiated", "initialization", "step_complete"},
    "state_get": set(STATES),
    "log": set(STATES),
    "status": {"step_complete", "terminated", "error"},
    "cancel": set(),  # steps are synchronous: never 'step in progress'
}


def test_calls_in_the_wrong_state(fmu, tmp_path, tally):
    t_bath = next(v for v in fmu["variables"] if v["name"] == "T_bath")
    calls = {
        "setup": dict(op="setup", start=0.0),
        "enter": dict(op="enter"),
        "exit": dict(op="exit"),
        "terminate": dict(op="terminate"),
        "reset": dict(op="reset"),
        "step": dict(op="step", h=1e-4),
        "get": dict(op="get", kind="Real", vrs=[t_bath["vr"]]),
        "set": dict(op="set", kind="Real", vrs=[t_bath["vr"]], values=[320.0]),
        "der_in": dict(op="der_in", vrs=[t_bath["vr"]], orders=[1], values=[1.0]),
        "state_get": dict(op="state_get"),
        "log": dict(op="log", cats=["logEvents"]),
        "status": dict(op="status", kind="GetStatus"),
        "cancel": dict(op="cancel"),
    }
    cases = []
    for stage in STATES:
        for name, call in calls.items():
            steps = reach(stage) + [dict(call, target=True)]
            if stage != "error" and name != "reset":
                steps.append(dict(op="all_reals", vrs=fmu["real_vrs"])
                             if stage != "instantiated" else dict(op="reset"))
            allowed = stage in ALLOWED[name]
            if allowed:
                judge = judge_ok
            elif name == "cancel":
                judge = judge_error("fmi2CancelStep")
            else:
                judge = judge_error("not allowed in state")
            cases.append(Case(f"{name}@{stage}", steps, judge, target=len(reach(stage))))
    # orders that hosts get wrong
    wrong_orders = [
        ("exit before enter", [inst(), dict(op="setup"), dict(op="exit", target=True)]),
        ("enter twice", [inst(), dict(op="setup"), dict(op="enter"),
                         dict(op="enter", target=True)]),
        ("setup after enter", [inst(), dict(op="enter"), dict(op="setup", target=True)]),
        ("step before init", [inst(), dict(op="step", h=1e-4, target=True)]),
        ("step in init mode", [inst(), dict(op="setup"), dict(op="enter"),
                               dict(op="step", h=1e-4, target=True)]),
        ("step after terminate", reach("terminated") + [dict(op="step", h=1e-4, target=True)]),
        ("terminate twice", reach("terminated") + [dict(op="terminate", target=True)]),
        ("terminate before init", [inst(), dict(op="terminate", target=True)]),
        ("step after reset", reach("step_complete") + [dict(op="reset"),
                                                       dict(op="step", h=1e-4, target=True)]),
        ("exit twice", reach("step_complete") + [dict(op="exit", target=True)]),
        ("step in error", reach("error") + [dict(op="step", h=1e-4, target=True)]),
        ("set in error", reach("error") + [dict(op="set", kind="Real", vrs=[t_bath["vr"]],
                                                values=[300.0], target=True)]),
    ]
    for label, steps in wrong_orders:
        target = next(i for i, s in enumerate(steps) if s.get("target"))
        cases.append(Case(label, steps, judge_error("not allowed in state"), target=target))
    # the instance recovers: reset from every state gives a working instance
    for stage in STATES:
        steps = reach(stage) + [dict(op="reset", target=True), dict(op="setup", start=0.0),
                                dict(op="enter"), dict(op="exit"), dict(op="step", h=1e-4, n=2),
                                dict(op="all_reals", vrs=fmu["real_vrs"])]
        cases.append(Case(f"reset from {stage} runs", steps, judge_error_free,
                          target=len(reach(stage))))
    settle(cases, run_cases(fmu, cases, tmp_path), tally, "wrong state/order")


def judge_error_free(case, tr):
    bad = [s for s in tr if s["status"] not in (F.OK, "instance", "void")]
    if bad:
        raise Problem(f"want every call to succeed: {bad[0]}")
    return "accepted"


# ---------------------------------------------------------------------------------------------
# 7. time arguments: fmi2SetupExperiment and fmi2DoStep


def test_bad_time_arguments(fmu, tmp_path, tally):
    cases = []
    for start in (math.nan, math.inf, -math.inf):
        steps = [inst(), dict(op="setup", start=start, target=True)]
        steps += [dict(op="setup", start=0.0), dict(op="enter"), dict(op="exit"),
                  dict(op="step", h=1e-4)]
        cases.append(Case(f"start {start}", steps, judge_error("startTime", then="runs"),
                          target=1))
    for stop in (math.nan, -1.0, -math.inf):
        steps = [inst(), dict(op="setup", start=0.0, stop=stop, target=True),
                 dict(op="setup", start=0.0), dict(op="enter"), dict(op="exit"),
                 dict(op="step", h=1e-4)]
        cases.append(Case(f"stop {stop}", steps, judge_error("stopTime", then="runs"),
                          target=1))
    for start in (1e300, 1e12, DBL_MAX):  # legal start, but no step can resolve it
        steps = [inst(), dict(op="setup", start=start), dict(op="enter"), dict(op="exit"),
                 dict(op="step", h=1e-4, target=True), dict(op="all_reals", vrs=fmu["real_vrs"])]
        cases.append(Case(f"start {start}, h 1e-4", steps, judge_error("resolution", value=1e-4),
                          target=4))
    for start in (-1e3, -1.0, 1e5):  # legal, runs
        steps = [inst(), dict(op="setup", start=start), dict(op="enter"), dict(op="exit"),
                 dict(op="step", h=1e-4, n=3, target=True),
                 dict(op="all_reals", vrs=fmu["real_vrs"])]
        cases.append(Case(f"start {start}", steps, judge_ok, target=4))
    sc = reach("step_complete")
    for label, t, h, words in (
            ("h NaN", "now", math.nan, ["nan"]), ("h +Inf", "now", math.inf, ["inf"]),
            ("h -Inf", "now", -math.inf, ["-inf"]), ("h negative", "now", -1e-3, ["-0.001"]),
            ("h absurd", "now", 1e300, ["1e+300"]), ("h DBL_MAX", "now", DBL_MAX, ["limit"]),
            ("h 1e6", "now", 1e6, ["limit"]), ("h denormal", "now", 5e-324, ["resolution"]),
            ("t NaN", math.nan, 1e-4, ["nan"]), ("t Inf", math.inf, 1e-4, ["inf"]),
            ("t behind", 0.0, 1e-4, ["does not continue"]),
            ("t ahead", 1.0, 1e-4, ["does not continue"]),
            ("t -1e300", -1e300, 1e-4, ["does not continue"])):
        steps = sc + [dict(op="step", t=t, h=h, target=True), dict(op="step", h=1e-4),
                      dict(op="all_reals", vrs=fmu["real_vrs"])]
        cases.append(Case(f"doStep {label}", steps, judge_error("fmi2DoStep", *words,
                                                                then="runs"), target=len(sc)))
    steps = sc + [dict(op="step", h=0.0, n=3, target=True), dict(op="all_reals",
                                                                 vrs=fmu["real_vrs"])]
    cases.append(Case("doStep h = 0", steps, judge_ok, target=len(sc)))
    # stop time: stepping past it is an error (FMI 2.0, fmi2SetupExperiment)
    steps = [inst(), dict(op="setup", start=0.0, stop=3e-4), dict(op="enter"), dict(op="exit"),
             dict(op="step", h=1e-4, n=3), dict(op="step", h=1e-4, target=True),
             dict(op="all_reals", vrs=fmu["real_vrs"])]
    cases.append(Case("doStep past stopTime", steps, judge_error("stopTime"), target=5))
    steps = [inst(), dict(op="setup", start=0.0, stop=3e-4), dict(op="enter"), dict(op="exit"),
             dict(op="step", h=1e-4, n=3, target=True)]
    cases.append(Case("doStep up to stopTime", steps, judge_ok, target=4))
    settle(cases, run_cases(fmu, cases, tmp_path), tally, "time arguments")


# ---------------------------------------------------------------------------------------------
# 8. serialized FMU states from outside


def test_bad_serialized_states(fmu, tmp_path, tally):
    sc = reach("step_complete")
    base = sc + [dict(op="state_get"), dict(op="serialize")]
    cases = []

    def deser(label, tail, judge=None, **kw):
        steps = base + [dict(op="deserialize", target=True, **kw)] + tail
        cases.append(Case(label, steps, judge or judge_error("not a state"), target=len(base)))

    then_set_and_step = [dict(op="state_set", state="d"), dict(op="step", h=1e-4, n=2),
                         dict(op="all_reals", vrs=fmu["real_vrs"])]
    deser("garbage", [], bytes="ab" * 300)
    deser("one byte", [], bytes="00")
    deser("zeros", [], bytes="00" * 5000)
    for cut in (1, 4, 12, 13, 100, 500, -1, -8, -9):
        deser(f"cut {cut}", [], cut=cut)
    deser("extra byte", [], append="00")
    deser("magic flipped", [], mutate=[[0, 0xFF]])
    deser("size field", [], mutate=[[4, 1]])
    deser("state field 0", [], mutate=[[12, 4]])
    deser("state field 64", [], mutate=[[12, 4 ^ 64]])
    deser("set_up field 2", [], mutate=[[16, 3]])
    deser("step complete without set-up", [], mutate=[[16, 1]])
    # flip a byte in each 8-byte word of the blob: rejected, or accepted and then the
    # instance must run on or fail cleanly (some words hold legal values in any bit pattern)
    for offset in range(12, 1400, 8):
        if 44 <= offset + 7 < 76:  # input derivatives: in test_absurd_values_of_inputs_...
            continue
        steps = base + [dict(op="deserialize", mutate=[[offset + 7, 0x7F]], target=True)] \
            + then_set_and_step
        cases.append(Case(f"byte {offset + 7} ^ 0x7F", steps, judge_run_or_clean_error,
                          target=len(base)))
    deser("round trip ok", then_set_and_step, judge=judge_ok)
    settle(cases, run_cases(fmu, cases, tmp_path), tally, "serialized states")


# ---------------------------------------------------------------------------------------------
# 9. Model Exchange: its entry points in every state of its state machine, the co-simulation
# functions refused on a Model Exchange instance and the other way round, NULL pointers, arrays
# of the wrong size, bad numbers for the time and the states

ME_STATES = ("instantiated", "initialization", "event", "continuous", "terminated", "error")
ME_READ = {"initialization", "event", "continuous", "terminated", "error"}


def me_calls(fmu):
    nx, nz = len(fmu["states"]), fmu["nz"]
    return {  # name: (call, FMI function, states it is allowed in)
        "event_mode": (dict(op="event_mode"), "fmi2EnterEventMode", {"continuous"}),
        "new_states": (dict(op="new_states"), "fmi2NewDiscreteStates", {"event"}),
        "continuous": (dict(op="continuous"), "fmi2EnterContinuousTimeMode", {"event"}),
        "completed": (dict(op="completed"), "fmi2CompletedIntegratorStep", {"continuous"}),
        "time": (dict(op="time", t=1e-6), "fmi2SetTime", {"event", "continuous"}),
        "states_get": (dict(op="states_get", n=nx), "fmi2GetContinuousStates", ME_READ),
        "states_set": (dict(op="states_set", values=[0.0] * nx), "fmi2SetContinuousStates",
                       {"continuous"}),
        "nominals": (dict(op="nominals", n=nx), "fmi2GetNominalsOfContinuousStates",
                     ME_READ | {"instantiated"}),
        "derivatives": (dict(op="derivatives", n=nx), "fmi2GetDerivatives", ME_READ),
        "indicators": (dict(op="indicators", n=nz), "fmi2GetEventIndicators", ME_READ),
        "terminate": (dict(op="terminate"), "fmi2Terminate", {"event", "continuous", "error"}),
    }


def me_reach(stage, fmu):
    """Steps that bring a fresh Model Exchange instance to a state of its state machine."""
    steps = [inst(type=F.ME), dict(op="setup", start=0.0)]
    if stage == "instantiated":
        return steps
    steps.append(dict(op="enter"))
    if stage == "initialization":
        return steps
    steps += [dict(op="exit"), dict(op="new_states")]
    if stage == "event":
        return steps
    steps.append(dict(op="continuous"))
    if stage == "continuous":
        return steps
    if stage == "terminated":
        return steps + [dict(op="terminate")]
    if stage == "error":  # a state far beyond the model's reach: its derivatives overflow
        return steps + [dict(op="states_set", values=[1e300] * len(fmu["states"])),
                        dict(op="derivatives", n=len(fmu["states"]))]
    raise ValueError(stage)


def me_run(fmu, n=200):
    """On from continuous-time mode: Euler steps of 1 us with events, every Real read."""
    return [dict(op="me_run", nx=len(fmu["states"]), nz=fmu["nz"], n=n),
            dict(op="all_reals", vrs=fmu["real_vrs"])]


def judge_error_or_ok(case, transcript):
    """In the error state a call that is allowed may succeed or fail cleanly."""
    return "rejected" if transcript[case.target]["status"] == F.ERROR else judge_ok(
        case, transcript)


def me_state_cases(fmu):
    cases = []
    for stage in ME_STATES:
        for name, (call, fn, allowed) in me_calls(fmu).items():
            steps = me_reach(stage, fmu) + [dict(call, target=True)]
            if stage not in allowed:
                judge = judge_error(fn, "not allowed in state")
            else:
                judge = judge_error_or_ok if stage == "error" else judge_ok
            cases.append(Case(f"ME {name}@{stage}", steps, judge,
                              target=len(me_reach(stage, fmu))))
    # the co-simulation functions on a Model Exchange instance and the other way round
    cont = me_reach("continuous", fmu)
    for call, fn in ((dict(op="der_in", vrs=[0], orders=[1], values=[1.0]),
                      "fmi2SetRealInputDerivatives"),
                     (dict(op="der_out"), "fmi2GetRealOutputDerivatives")):
        cases.append(Case(f"ME instance {fn}", cont + [dict(call, target=True)] + me_run(fmu),
                          judge_error(fn, "co-simulation", then="runs"), target=len(cont)))
    cases.append(Case("ME instance fmi2DoStep", cont + [dict(op="step", h=1e-4, target=True)],
                      judge_error("fmi2DoStep", "not allowed"), target=len(cont)))
    cs = reach("initialization")
    for name, (call, fn, _) in me_calls(fmu).items():
        if name in ("terminate",):
            continue
        cases.append(Case(f"CS instance {fn}", cs + [dict(call, target=True)] + finish(
            "initialization", fmu), judge_error(fn), target=len(cs)))
    return cases


def me_argument_cases(fmu):
    nx, nz, cases = len(fmu["states"]), fmu["nz"], []
    cont = me_reach("continuous", fmu)
    at = len(cont)

    def case(label, call, judge, then=None):
        cases.append(Case(label, cont + [dict(call, target=True)] + (
            me_run(fmu) if then is None else then), judge, target=at))

    start = [1.0] * nx  # replaced by the real state below
    for op, fn, n_model in (("states_get", "fmi2GetContinuousStates", nx),
                            ("nominals", "fmi2GetNominalsOfContinuousStates", nx),
                            ("derivatives", "fmi2GetDerivatives", nx),
                            ("indicators", "fmi2GetEventIndicators", nz)):
        case(f"{fn} NULL", dict(op=op, n=n_model, null=True), judge_error(fn, "NULL", then="runs"))
        for n in (0, n_model - 1, n_model + 1):
            case(f"{fn} n={n}", dict(op=op, n=n), judge_error(fn, f"{n} ", str(n_model),
                                                              then="runs"))
    case("fmi2SetContinuousStates NULL", dict(op="states_set", values=start, null=True),
         judge_error("fmi2SetContinuousStates", "NULL", then="runs"))
    for n in (0, nx - 1, nx + 1):
        case(f"fmi2SetContinuousStates n={n}", dict(op="states_set", values=start[:max(n, 1)]
                                                    + [1.0] * max(n - nx, 0), n=n),
             judge_error("fmi2SetContinuousStates", str(nx), then="runs"))
    for k in sorted({0, 3, 5, nx - 1}):
        for bad in (math.nan, math.inf, -math.inf):
            values = [0.0] * nx
            values[k] = bad
            case(f"state {fmu['states'][k]}={bad!r}", dict(op="states_set", values=values),
                 judge_error("fmi2SetContinuousStates", fmu["states"][k], value=bad,
                             then="runs"))
    for bad in (math.nan, math.inf, -math.inf, -1.0):
        case(f"fmi2SetTime {bad!r}", dict(op="time", t=bad),
             judge_error("fmi2SetTime", value=bad, then="runs"))
    case("fmi2CompletedIntegratorStep NULL", dict(op="completed", null_args=True),
         judge_error("fmi2CompletedIntegratorStep", "NULL", then="runs"))
    ev = me_reach("event", fmu)
    cases.append(Case("fmi2NewDiscreteStates NULL", ev + [dict(op="new_states", null=True,
                                                               target=True)],
                      judge_error("fmi2NewDiscreteStates", "NULL"), target=len(ev)))
    # an absurd state: the derivatives overflow; a clean error naming one, the instance freed
    case("state 1e300 everywhere", dict(op="states_set", values=[1e300] * nx), judge_ok,
         then=[dict(op="derivatives", n=nx), dict(op="terminate")])
    cases[-1].judge = lambda c, tr: judge_error("fmi2GetDerivatives", "der(")(
        dataclasses.replace(c, target=c.target + 1), tr)
    # variables: unknown references, a state that is not settable, inputs good and bad
    real_in = next(v for v in fmu["variables"] if v["name"] == "T_s")
    state = next(v for v in fmu["variables"] if v["name"] == fmu["states"][0])
    case("unknown value reference in ME", dict(op="get", kind="Real", vrs=[fmu["n_vars"]]),
         judge_error("unknown value reference", str(fmu["n_vars"]), then="runs"))
    case("set a state by fmi2SetReal", dict(op="set", kind="Real", vrs=[state["vr"]],
                                            values=[0.0]),
         judge_error(state["name"], "cannot be set", then="runs"))
    for value in (math.nan, math.inf, 1e300, -1e300):
        case(f"input T_s={value!r} in continuous-time mode", set_step(real_in, value),
             judge_value(real_in, value))
    case("input T_s=150 in continuous-time mode", set_step(real_in, 150.0),
         judge_value(real_in, 150.0))
    # NULL instance to every Model Exchange function; then a fresh run goes on
    for name, (call, fn, _) in me_calls(fmu).items():
        steps = cont + [dict(call, comp="NULL", target=True)] + me_run(fmu, n=20)
        cases.append(Case(f"NULL instance {fn}", steps, judge_error(then="runs"), target=at))
    # an FMU state of one interface into an instance of the other
    cases.append(Case("ME state into a CS instance", cont + [
        dict(op="state_get"), inst(slot="b"), dict(op="setup", slot="b"),
        dict(op="state_set", slot="b", target=True)],
        judge_error("fmi2SetFMUstate", "Model Exchange"), target=at + 3))
    cases.append(Case("ME state restored runs", cont + me_run(fmu, n=50) + [
        dict(op="state_get"), dict(op="me_run", nx=nx, nz=nz, n=50), dict(op="state_set",
                                                                          target=True)]
        + me_run(fmu, n=50), judge_error_free, target=at + 4))
    return cases


def test_model_exchange_entry_points(fmu, tmp_path, tally):
    cases = me_state_cases(fmu) + me_argument_cases(fmu)
    assert len(cases) > 100
    settle(cases, run_cases(fmu, cases, tmp_path), tally, "Model Exchange")
