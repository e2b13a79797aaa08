"""Child process of test_fmi3_bad_input.py: the FMU's FMI 3.0 functions through ctypes, without
fmpy's checks, called with what a careless host might pass (calls in the wrong state, NULL
pointers, NaN and out-of-range values, wrong array sizes, unknown value references). Each case
prints one line "RESULT <json>": its name, the statuses returned and the messages logged, so that
a crash kills only this process and is reported against the case that caused it ("BEGIN <name>"
is printed before each).

Usage: fmi3_raw.py SO_PATH TOKEN RESOURCE_DIR VR_JSON"""

import ctypes
import json
import math
import sys
from ctypes import (POINTER, byref, c_bool, c_char_p, c_double, c_int, c_int32, c_int64,
                    c_size_t, c_uint32, c_uint8, c_void_p)

LOG = ctypes.CFUNCTYPE(None, c_void_p, c_int, c_char_p, c_char_p)
VRS = POINTER(c_uint32)


class Host:
    def __init__(self, so, token, resources, vr):
        self.lib = ctypes.CDLL(so)
        self.token, self.resources, self.vr = token, resources, vr
        self.messages = []
        self.log = LOG(lambda env, status, cat, msg: self.messages.append(msg.decode()))
        for name, restype in (("fmi3InstantiateCoSimulation", c_void_p),
                              ("fmi3InstantiateModelExchange", c_void_p),
                              ("fmi3FreeInstance", None)):
            getattr(self.lib, name).restype = restype
        self.lib.fmi3InstantiateCoSimulation.argtypes = [
            c_char_p, c_char_p, c_char_p, c_bool, c_bool, c_bool, c_bool, VRS, c_size_t,
            c_void_p, LOG, c_void_p]
        self.lib.fmi3InstantiateModelExchange.argtypes = [
            c_char_p, c_char_p, c_char_p, c_bool, c_bool, c_void_p, LOG]
        self.lib.fmi3EnterInitializationMode.argtypes = [c_void_p, c_bool, c_double, c_double,
                                                         c_bool, c_double]
        self.lib.fmi3DoStep.argtypes = [c_void_p, c_double, c_double, c_bool, c_void_p,
                                        c_void_p, c_void_p, c_void_p]

    def new(self, name=b"i", token=None, resources=None):
        return self.lib.fmi3InstantiateCoSimulation(
            name, token or self.token.encode(), resources or self.resources.encode(), False,
            True, False, False, None, 0, None, self.log, None)

    def new_me(self, continuous=True):
        """A Model Exchange instance, initialised, in continuous-time mode (or event mode)."""
        inst = self.lib.fmi3InstantiateModelExchange(b"me", self.token.encode(),
                                                     self.resources.encode(), False, True, None,
                                                     self.log)
        self.init(inst)
        if continuous:
            flags = [c_bool() for _ in range(5)]
            self.lib.fmi3UpdateDiscreteStates(c_void_p(inst), *[byref(f) for f in flags],
                                              byref(c_double()))
            self.lib.fmi3EnterContinuousTimeMode(c_void_p(inst))
        return inst

    def init(self, inst, stop=None):
        self.lib.fmi3EnterInitializationMode(c_void_p(inst), False, 0.0, 0.0, stop is not None,
                                             stop or 0.0)
        return self.lib.fmi3ExitInitializationMode(c_void_p(inst))

    def step(self, inst, t, h, null_out=False):
        flags = [c_bool(), c_bool(), c_bool()]
        last = c_double()
        ptrs = [None] * 4 if null_out else [byref(f) for f in flags] + [byref(last)]
        return self.lib.fmi3DoStep(c_void_p(inst), t, h, True, *ptrs)

    def call(self, fn, inst, *args):
        return getattr(self.lib, fn)(c_void_p(inst), *args)


def vrs(*refs):
    return (c_uint32 * len(refs))(*refs)


def values(ctype, *xs):
    return (ctype * max(len(xs), 1))(*xs)


def cases(h):
    """{name: function(host) -> list of statuses}; each makes and frees its own instances."""
    v = h.vr
    f64 = lambda *x: values(c_double, *x)  # noqa: E731

    def fresh(init=False, stop=None):
        inst = h.new()
        if init:
            h.init(inst, stop)
        return inst

    def run(fn):
        def case():
            inst = fresh(init=fn.__code__.co_varnames[:1] == ("ready",))
            try:
                return fn(inst)
            finally:
                h.lib.fmi3FreeInstance(c_void_p(inst))
        return case

    out = {}

    def case(fn):
        out[fn.__name__] = run(fn)
        return fn

    @case
    def dostep_before_initialization(inst):
        return [h.step(inst, 0.0, 1e-3)]

    @case
    def get_in_instantiated_state(inst):
        return [h.call("fmi3GetFloat64", inst, vrs(v["w_p"]), 1, f64(0.0), 1)]

    @case
    def get_null_value_references(ready):
        return [h.call("fmi3GetFloat64", ready, None, 1, f64(0.0), 1)]

    @case
    def get_null_values(ready):
        return [h.call("fmi3GetFloat64", ready, vrs(v["w_p"]), 1, None, 1)]

    @case
    def dostep_null_outputs(ready):
        return [h.step(ready, 0.0, 1e-3, null_out=True)]

    @case
    def set_nan_input(ready):
        return [h.call("fmi3SetFloat64", ready, vrs(v["T_s"]), 1, f64(math.nan), 1)]

    @case
    def set_out_of_range_input(inst):
        return [h.call("fmi3SetFloat64", inst, vrs(v["T_bath"]), 1, f64(1000.0), 1)]

    @case
    def set_enumeration_out_of_range(inst):
        return [h.call("fmi3SetInt64", inst, vrs(v["mesh_model"]), 1,
                       values(c_int64, 7), 1)]

    @case
    def set_enumeration_beyond_int(inst):
        return [h.call("fmi3SetInt64", inst, vrs(v["mesh_model"]), 1,
                       values(c_int64, 1 << 40), 1)]

    @case
    def get_array_wrong_n_values(ready):
        return [h.call("fmi3GetFloat64", ready, vrs(v["pair.W"]), 1, f64(0, 0, 0), 1)]

    @case
    def set_wrong_n_values(inst):
        return [h.call("fmi3SetFloat64", inst, vrs(v["T_s"]), 1, f64(1.0, 2.0), 2)]

    @case
    def get_unknown_value_reference(ready):
        return [h.call("fmi3GetFloat64", ready, vrs(99999), 1, f64(0.0), 1)]

    @case
    def get_array_element_value_reference(ready):
        return [h.call("fmi3GetFloat64", ready, vrs(v["pair.W"] + 1), 1, f64(0.0), 1)]

    @case
    def get_enumeration_as_int32(ready):
        return [h.call("fmi3GetInt32", ready, vrs(v["mesh_model"]), 1, values(c_int32, 0), 1)]

    @case
    def set_time(ready):
        return [h.call("fmi3SetFloat64", ready, vrs(v["time"]), 1, f64(1.0), 1)]

    @case
    def set_fixed_parameter_after_initialization(ready):
        return [h.call("fmi3SetFloat64", ready, vrs(v["w_p0"]), 1, f64(100.0), 1)]

    @case
    def set_string_null(inst):
        return [h.call("fmi3SetString", inst, vrs(v["gear_set_file"]), 1,
                       values(c_char_p, None), 1)]

    @case
    def dostep_nan(ready):
        return [h.step(ready, 0.0, math.nan)]

    @case
    def dostep_wrong_time(ready):
        return [h.step(ready, 5.0, 1e-3)]

    @case
    def get_float32(ready):
        return [h.call("fmi3GetFloat32", ready, vrs(v["w_p"]), 1,
                       values(ctypes.c_float, 0.0), 1)]

    @case
    def get_binary(ready):
        return [h.call("fmi3GetBinary", ready, vrs(v["w_p"]), 1, values(c_size_t, 0),
                       values(c_void_p, None), 1)]

    @case
    def enter_event_mode(ready):
        return [h.call("fmi3EnterEventMode", ready)]

    @case
    def output_derivative_second_order(ready):
        return [h.call("fmi3GetOutputDerivatives", ready, vrs(v["w_p"]), 1,
                       values(c_int32, 2), f64(0.0), 1)]

    @case
    def output_derivative_of_no_state(ready):
        return [h.call("fmi3GetOutputDerivatives", ready, vrs(v["eta"]), 1,
                       values(c_int32, 1), f64(0.0), 1)]

    @case
    def output_derivative_null_orders(ready):
        return [h.call("fmi3GetOutputDerivatives", ready, vrs(v["w_p"]), 1, None, f64(0.0), 1)]

    @case
    def model_exchange_function(ready):
        return [h.call("fmi3GetContinuousStates", ready, f64(0.0), 1)]

    @case
    def get_fmu_state_null(ready):
        return [h.call("fmi3GetFMUState", ready, None)]

    @case
    def serialized_size_null(ready):
        return [h.call("fmi3SerializedFMUStateSize", ready, None, byref(c_size_t()))]

    @case
    def deserialize_garbage(ready):
        junk = (c_uint8 * 64)(*range(64))
        state = c_void_p()
        return [h.call("fmi3DeserializeFMUState", ready, junk, 64, byref(state))]

    @case
    def debug_logging_unknown_category(inst):
        return [h.call("fmi3SetDebugLogging", inst, c_bool(True), 1,
                       values(c_char_p, b"logNothing"))]

    @case
    def terminate_twice(ready):
        return [h.call("fmi3Terminate", ready), h.call("fmi3Terminate", ready)]

    @case
    def reset_then_step(ready):
        return [h.call("fmi3Reset", ready), h.step(ready, 0.0, 1e-3)]

    def null_instance():
        return [h.lib.fmi3DoStep(None, 0.0, 1e-3, True, None, None, None, None),
                h.lib.fmi3GetFloat64(None, vrs(v["w_p"]), 1, f64(0.0), 1),
                h.lib.fmi3Terminate(None), h.lib.fmi3EnterEventMode(None)]

    def instantiate_wrong_token():
        return [0 if h.new(token=b"{not-the-token}") is None else 1]

    def instantiate_blank_name():
        return [0 if h.new(name=b"  ") is None else 1]

    def me(fn, continuous=True):
        def case():
            inst = h.new_me(continuous)
            try:
                return fn(inst)
            finally:
                h.lib.fmi3FreeInstance(c_void_p(inst))
        return case

    nx = 64  # more than the model's states: room for a wrong count
    me_cases = {
        "me_dostep": lambda i: [h.step(i, 0.0, 1e-3)],
        "me_wrong_number_of_derivatives": lambda i: [
            h.call("fmi3GetContinuousStateDerivatives", i, f64(*[0.0] * nx), 3)],
        "me_null_states": lambda i: [h.call("fmi3SetContinuousStates", i, None, 1)],
        "me_nan_state": lambda i: [h.call("fmi3SetContinuousStates", i,
                                          f64(*[math.nan] * nx), v["n_states"])],
        "me_set_time_nan": lambda i: [h.call("fmi3SetTime", i, c_double(math.nan))],
        "me_number_null": lambda i: [h.call("fmi3GetNumberOfContinuousStates", i, None)],
        "me_set_event_indicator": lambda i: [h.call("fmi3SetFloat64", i,
                                                    vrs(v["event_indicator[1]"]), 1,
                                                    f64(0.0), 1)],
    }
    for name, fn in me_cases.items():
        out[name] = me(fn)
    out["me_update_null"] = me(lambda i: [h.call("fmi3UpdateDiscreteStates", i, None, None,
                                                 None, None, None, None)], continuous=False)
    out["me_completed_step_in_event_mode"] = me(lambda i: [h.call(
        "fmi3CompletedIntegratorStep", i, c_bool(True), byref(c_bool()), byref(c_bool()))],
        continuous=False)

    def missing_resources():
        inst = h.new(resources=b"/nonexistent/resources/")
        try:
            return [h.init(inst)]
        finally:
            h.lib.fmi3FreeInstance(c_void_p(inst))

    out.update(null_instance=null_instance, instantiate_wrong_token=instantiate_wrong_token,
               instantiate_blank_name=instantiate_blank_name,
               missing_resources=missing_resources)
    return out


def main():
    so, token, resources, vr_json = sys.argv[1:5]
    h = Host(so, token, resources, json.loads(vr_json))
    for name, fn in cases(h).items():
        print("BEGIN " + name, flush=True)
        h.messages.clear()
        statuses = fn()
        print("RESULT " + json.dumps({"case": name, "statuses": statuses,
                                      "messages": list(h.messages)}), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
