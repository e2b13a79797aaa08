"""Child process of test_robustness_inputs.py: runs scripted FMI call sequences ("cases") against
the FMU's shared library through fmi2_raw and reports a transcript of each, so that a crash or a
hang kills only this process and is reported against the case that caused it.

Usage: robust_runner.py SO_PATH GUID RESOURCE_URI CASES_JSON FIRST_INDEX
Protocol on stdout, one line each, flushed: "BEGIN <index>" then "RESULT <json>" per case.

A case is {"id": ..., "steps": [step, ...]}; a step is a dict with "op" and arguments:
  instantiate  name, type (1 = CS), guid ("<guid>" = the right one), uri ("<uri>" = the FMU's
               resources), callbacks ("full" | "no_logger" | "null"), logging, slot
  free         slot                      (every slot left open is freed at the end of the case)
  setup        start, stop (null = undefined)
  enter / exit / terminate / reset / cancel
  set          kind (Real | Integer | Boolean | String), vrs, values, n (default len(vrs)),
               null_vrs, null_values
  get          kind, vrs, n, null_vrs, null_values
  all_reals    GetReal of every Real variable (vrs given); checks they are finite
  step         t ("now" | number), h, n (repeat, default 1)
  log          on, cats (list or null), n
  der_in       vrs, orders, values ; der_out vrs ; dir_der
  state_get / state_set / state_free   slot name "state_slot"
  Model Exchange: event_mode, new_states, continuous, completed (null_args), time (t),
               states_set (values, n, null), states_get / nominals / derivatives / indicators
               (n, null; check that they are finite), me_run (n Euler steps of h with events)
  serialize    -> keeps the bytes ; deserialize  bytes ("last" | hex), mutate [[offset, xor]], cut
  status       kind (GetStatus | GetRealStatus | GetIntegerStatus | GetBooleanStatus |
               GetStringStatus), which, null_value
Any step may name comp "NULL" to pass a NULL instance.
"""

import json
import math
import sys
from ctypes import byref, c_char, c_char_p, c_double, c_int, c_size_t, c_void_p

import fmi2_raw as F

KINDS = ("Real", "Integer", "Boolean", "String")


class Case:
    def __init__(self, lib, guid, uri):
        self.lib, self.guid, self.uri = lib, guid, uri
        self.slots = {}
        self.callbacks = {}
        self.states = {}
        self.blob = None
        self.t = 0.0

    def comp(self, step):
        if step.get("comp") == "NULL":
            return None
        return self.slots.get(step.get("slot", "a"))

    # ------------------------------------------------------------------ life cycle
    def op_instantiate(self, s):
        kind = s.get("callbacks", "full")
        cb = None if kind == "null" else self.lib.callbacks(logger=kind != "no_logger")
        slot = s.get("slot", "a")
        self.callbacks[slot] = cb
        guid = s.get("guid", "<guid>")
        guid = self.guid if guid == "<guid>" else guid
        uri = s.get("uri", "<uri>")
        uri = self.uri if uri == "<uri>" else uri
        name = s.get("name", "instance")
        enc = (lambda v: None if v is None else v.encode("utf-8", "surrogateescape"))
        handle = self.lib.fmi2Instantiate(enc(name), s.get("type", F.CS), enc(guid), enc(uri),
                                          None if cb is None else byref(cb),
                                          0, int(s.get("logging", 0)))
        if handle:
            self.slots[slot] = handle
        self.t = 0.0
        return {"status": "instance" if handle else "NULL"}

    def op_free(self, s):
        c = self.comp(s)
        self.lib.fmi2FreeInstance(c)
        self.slots.pop(s.get("slot", "a"), None)
        return {"status": "void"}

    def op_setup(self, s):
        stop = s.get("stop")
        start = s.get("start", 0.0)
        r = self.lib.fmi2SetupExperiment(self.comp(s), int(s.get("tol_defined", 0)),
                                         s.get("tol", 0.0), start, stop is not None,
                                         0.0 if stop is None else stop)
        if r == F.OK:
            self.t = start
        return {"status": r}

    def op_enter(self, s):
        return {"status": self.lib.fmi2EnterInitializationMode(self.comp(s))}

    def op_exit(self, s):
        return {"status": self.lib.fmi2ExitInitializationMode(self.comp(s))}

    def op_terminate(self, s):
        return {"status": self.lib.fmi2Terminate(self.comp(s))}

    def op_reset(self, s):
        r = self.lib.fmi2Reset(self.comp(s))
        self.t = 0.0
        return {"status": r}

    def op_cancel(self, s):
        return {"status": self.lib.fmi2CancelStep(self.comp(s))}

    def op_log(self, s):
        cats = s.get("cats")
        arr = F.string_array(cats) if cats is not None else None
        n = s.get("n", len(cats) if cats is not None else 0)
        return {"status": self.lib.fmi2SetDebugLogging(self.comp(s), int(s.get("on", 1)), n, arr)}

    # ------------------------------------------------------------------ variables
    def _arrays(self, s, out):
        kind, vrs = s["kind"], s.get("vrs", [])
        n = s.get("n", len(vrs))
        vr = None if s.get("null_vrs") else F.vr_array(vrs)
        size = max(n, len(vrs), 1)
        if s.get("null_values"):
            val = None
        elif out:
            val = {"Real": c_double, "Integer": c_int, "Boolean": c_int, "String": c_char_p}[kind]
            val = (val * size)()
        else:
            values = s["values"]
            if kind == "Real":
                val = F.real_array([float(v) for v in values], size)
            elif kind == "String":
                val = F.string_array([None if v is None else
                                      v.encode("utf-8", "surrogateescape") for v in values], size)
            else:
                val = F.int_array([int(v) for v in values], size)
        return kind, n, vr, val

    def op_set(self, s):
        kind, n, vr, val = self._arrays(s, out=False)
        return {"status": getattr(self.lib, "fmi2Set" + kind)(self.comp(s), vr, n, val)}

    def op_get(self, s):
        kind, n, vr, val = self._arrays(s, out=True)
        r = getattr(self.lib, "fmi2Get" + kind)(self.comp(s), vr, n, val)
        res = {"status": r}
        if r in (F.OK, F.WARNING) and val is not None:
            if kind == "String":
                res["values"] = [None if val[i] is None else val[i].decode("utf-8", "replace")
                                 for i in range(n)]
            else:
                res["values"] = [val[i] for i in range(n)]
        return res

    def op_all_reals(self, s):
        vrs = s["vrs"]
        val = (c_double * len(vrs))()
        r = self.lib.fmi2GetReal(self.comp(s), F.vr_array(vrs), len(vrs), val)
        res = {"status": r}
        if r in (F.OK, F.WARNING):
            bad = [(vrs[i], repr(val[i])) for i in range(len(vrs)) if not math.isfinite(val[i])]
            res["nonfinite"] = bad
        return res

    # ------------------------------------------------------------------ stepping
    def op_step(self, s):
        res = {"status": F.OK, "steps": 0}
        for _ in range(s.get("n", 1)):
            t = self.t if s.get("t", "now") == "now" else s["t"]
            h = s.get("h", 1e-4)
            r = self.lib.fmi2DoStep(self.comp(s), t, h, 1)
            res["status"] = r
            if r != F.OK:
                break
            self.t = t + h
            res["steps"] += 1
        return res

    def op_der_in(self, s):
        vrs = s["vrs"]
        orders = None if s.get("null_orders") else F.int_array(s["orders"])
        values = None if s.get("null_values") else F.real_array(s["values"])
        n = s.get("n", len(vrs))
        return {"status": self.lib.fmi2SetRealInputDerivatives(
            self.comp(s), None if s.get("null_vrs") else F.vr_array(vrs), n, orders, values)}

    def op_der_out(self, s):
        vrs = s.get("vrs", [0])
        out = (c_double * max(len(vrs), 1))()
        return {"status": self.lib.fmi2GetRealOutputDerivatives(
            self.comp(s), F.vr_array(vrs), len(vrs), F.int_array([1] * len(vrs)), out)}

    def op_dir_der(self, s):
        dz = (c_double * 1)()
        return {"status": self.lib.fmi2GetDirectionalDerivative(
            self.comp(s), F.vr_array([9]), 1, F.vr_array([0]), 1, F.real_array([1.0]), dz)}

    def op_status(self, s):
        kind = s.get("kind", "GetStatus")
        ctype = {"GetStatus": c_int, "GetRealStatus": c_double, "GetIntegerStatus": c_int,
                 "GetBooleanStatus": c_int, "GetStringStatus": c_char_p}[kind]
        value = ctype()
        r = getattr(self.lib, "fmi2" + kind)(self.comp(s), s.get("which", 0),
                                             None if s.get("null_value") else byref(value))
        res = {"status": r}
        if r == F.OK and kind in ("GetRealStatus", "GetStatus", "GetBooleanStatus"):
            res["value"] = value.value
        return res

    # ------------------------------------------------------------------ Model Exchange
    def op_event_mode(self, s):
        return {"status": self.lib.fmi2EnterEventMode(self.comp(s))}

    def op_new_states(self, s):
        info = F.EventInfo()
        r = self.lib.fmi2NewDiscreteStates(self.comp(s), None if s.get("null") else byref(info))
        return {"status": r, "changed": info.valuesOfContinuousStatesChanged}

    def op_continuous(self, s):
        return {"status": self.lib.fmi2EnterContinuousTimeMode(self.comp(s))}

    def op_completed(self, s):
        event, stop = c_int(), c_int()
        null = s.get("null_args")
        r = self.lib.fmi2CompletedIntegratorStep(self.comp(s), 1, None if null else byref(event),
                                                 None if null else byref(stop))
        return {"status": r, "event": event.value}

    def op_time(self, s):
        r = self.lib.fmi2SetTime(self.comp(s), s.get("t", self.t))
        if r == F.OK:
            self.t = s.get("t", self.t)
        return {"status": r}

    def op_states_set(self, s):
        values = s.get("values", [0.0])
        n = s.get("n", len(values))
        arr = None if s.get("null") else F.real_array([float(v) for v in values], max(n, 1))
        return {"status": self.lib.fmi2SetContinuousStates(self.comp(s), arr, n)}

    def _me_array(self, s, fn):
        n = s.get("n", s.get("size", 1))
        arr = None if s.get("null") else (c_double * max(n, 1))()
        r = getattr(self.lib, fn)(self.comp(s), arr, n)
        res = {"status": r}
        if r == F.OK and arr is not None:
            res["values"] = [arr[i] for i in range(n)]
            res["nonfinite"] = [(i, repr(arr[i])) for i in range(n) if not math.isfinite(arr[i])]
        return res

    def op_states_get(self, s):
        return self._me_array(s, "fmi2GetContinuousStates")

    def op_nominals(self, s):
        return self._me_array(s, "fmi2GetNominalsOfContinuousStates")

    def op_derivatives(self, s):
        return self._me_array(s, "fmi2GetDerivatives")

    def op_indicators(self, s):
        return self._me_array(s, "fmi2GetEventIndicators")

    def op_me_run(self, s):
        """From continuous-time mode, n forward Euler steps of h, an event iteration wherever an
        indicator changes sign or a step asks for one (enough to run a model on at 1 us)."""
        nx, nz, h = s["nx"], s["nz"], s.get("h", 1e-6)
        x, dx, z0, z = (c_double * nx)(), (c_double * nx)(), (c_double * nz)(), (c_double * nz)()
        comp, lib, res = self.comp(s), self.lib, {"status": F.OK, "steps": 0, "events": 0}
        for fn, arr, n in (("fmi2GetContinuousStates", x, nx), ("fmi2GetEventIndicators", z0, nz)):
            res["status"] = getattr(lib, fn)(comp, arr, n)
            if res["status"] != F.OK:
                return res
        for _ in range(s.get("n", 10)):
            calls = [lambda: lib.fmi2GetDerivatives(comp, dx, nx)]
            calls.append(lambda: lib.fmi2SetTime(comp, self.t + h))
            calls.append(lambda: lib.fmi2SetContinuousStates(
                comp, (c_double * nx)(*[x[i] + h * dx[i] for i in range(nx)]), nx))
            calls.append(lambda: lib.fmi2GetContinuousStates(comp, x, nx))
            calls.append(lambda: lib.fmi2GetEventIndicators(comp, z, nz))
            for call in calls:
                res["status"] = call()
                if res["status"] != F.OK:
                    return res
            self.t += h
            event, stop = c_int(), c_int()
            res["status"] = lib.fmi2CompletedIntegratorStep(comp, 1, byref(event), byref(stop))
            crossed = any((z0[i] > 0) != (z[i] > 0) for i in range(nz))
            if res["status"] == F.OK and (crossed or event.value):
                res["events"] += 1
                info = F.EventInfo()
                for call in (lambda: lib.fmi2EnterEventMode(comp),
                             lambda: lib.fmi2NewDiscreteStates(comp, byref(info)),
                             lambda: lib.fmi2EnterContinuousTimeMode(comp),
                             lambda: lib.fmi2GetContinuousStates(comp, x, nx),
                             lambda: lib.fmi2GetEventIndicators(comp, z, nz)):
                    res["status"] = call()
                    if res["status"] != F.OK:
                        return res
            if res["status"] != F.OK:
                return res
            z0[:] = z[:]
            res["steps"] += 1
        return res

    # ------------------------------------------------------------------ FMU states
    def op_state_get(self, s):
        name = s.get("state", "s")
        if s.get("null_out"):
            return {"status": self.lib.fmi2GetFMUstate(self.comp(s), None)}
        st = self.states.setdefault(name, c_void_p())
        return {"status": self.lib.fmi2GetFMUstate(self.comp(s), byref(st))}

    def op_state_set(self, s):
        st = self.states.get(s.get("state", "s"))
        return {"status": self.lib.fmi2SetFMUstate(self.comp(s), None if st is None else st)}

    def op_state_free(self, s):
        if s.get("null_ptr"):
            return {"status": self.lib.fmi2FreeFMUstate(self.comp(s), None)}
        st = self.states.get(s.get("state", "s"), c_void_p())
        r = self.lib.fmi2FreeFMUstate(self.comp(s), byref(st))
        if r == F.OK and st.value is None:
            self.states.pop(s.get("state", "s"), None)
        return {"status": r}

    def op_serialize(self, s):
        st = self.states.get(s.get("state", "s"))
        size = c_size_t()
        r = self.lib.fmi2SerializedFMUstateSize(self.comp(s), st,
                                                None if s.get("null_size") else byref(size))
        if r != F.OK:
            return {"status": r, "stage": "size"}
        n = size.value + s.get("extra", 0)
        buf = None if s.get("null_buffer") else (c_char * max(n, 1))()
        r = self.lib.fmi2SerializeFMUstate(self.comp(s), st, buf, n)
        if r == F.OK:
            self.blob = bytes(buf[:size.value])
        return {"status": r, "size": size.value}

    def op_deserialize(self, s):
        data = self.blob if s.get("bytes", "last") == "last" else bytes.fromhex(s["bytes"])
        data = bytearray(data or b"")
        for offset, xor in s.get("mutate", []):
            if offset < len(data):
                data[offset] ^= xor
        if "cut" in s:
            data = data[:s["cut"]]
        if "append" in s:
            data += bytes.fromhex(s["append"])
        name = s.get("state", "d")
        st = self.states.setdefault(name, c_void_p())
        buf = None if s.get("null_bytes") else (c_char * max(len(data), 1)).from_buffer_copy(
            bytes(data) or b"\0")
        r = self.lib.fmi2DeSerializeFMUstate(self.comp(s), buf, len(data),
                                             None if s.get("null_out") else byref(st))
        return {"status": r}

    # ------------------------------------------------------------------ driver
    def run(self, steps):
        transcript = []
        for step in steps:
            before = len(self.lib.messages)
            result = getattr(self, "op_" + step["op"])(step)
            result["op"] = step["op"]
            result["msgs"] = self.lib.messages[before:]
            transcript.append(result)
        return transcript

    def close(self):
        """Frees FMU states, then every instance still open: must never crash."""
        for name, st in list(self.states.items()):
            if st.value:
                comp = next(iter(self.slots.values()), None)
                if comp:
                    self.lib.fmi2FreeFMUstate(comp, byref(st))
        for slot, handle in list(self.slots.items()):
            self.lib.fmi2FreeInstance(handle)
        self.slots.clear()


def main():
    so_path, guid, uri, cases_path, first = sys.argv[1:6]
    lib = F.Library(so_path)
    with open(cases_path, encoding="utf-8") as f:
        cases = json.load(f)
    out = sys.stdout
    for index in range(int(first), len(cases)):
        case = cases[index]
        out.write(f"BEGIN {index}\n")
        out.flush()
        lib.messages.clear()
        runner = Case(lib, guid, uri)
        try:
            transcript = runner.run(case["steps"])
            runner.close()
            result = {"index": index, "transcript": transcript, "exception": None}
        except Exception as exc:  # a Python-side problem in the case itself, not a crash
            runner.close()
            result = {"index": index, "transcript": [], "exception": repr(exc)}
        out.write("RESULT " + json.dumps(result) + "\n")
        out.flush()


if __name__ == "__main__":
    main()
