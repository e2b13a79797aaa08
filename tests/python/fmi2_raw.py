"""A thin ctypes binding of the FMU's FMI 2.0 functions (co-simulation and Model Exchange), without fmpy's checks, so
that tests can pass exactly what a careless host might: NULL pointers, wrong types, unknown value
references, calls in the wrong order. Log messages are recorded as (status, category, text).

Used in-process by nothing that could crash: tests/python/robust_runner.py loads it in a child
process (see test_robustness_inputs.py)."""

import ctypes
from ctypes import (POINTER, byref, c_char, c_char_p, c_double, c_int, c_size_t, c_uint,
                    c_void_p)

OK, WARNING, DISCARD, ERROR, FATAL, PENDING = range(6)
STATUS_NAMES = ["OK", "Warning", "Discard", "Error", "Fatal", "Pending"]
ME, CS = 0, 1

LOGGER = ctypes.CFUNCTYPE(None, c_void_p, c_char_p, c_int, c_char_p, c_char_p)
ALLOCATE = ctypes.CFUNCTYPE(c_void_p, c_size_t, c_size_t)
FREE = ctypes.CFUNCTYPE(None, c_void_p)
STEP_FINISHED = ctypes.CFUNCTYPE(None, c_void_p, c_int)


class Callbacks(ctypes.Structure):
    _fields_ = [("logger", LOGGER), ("allocateMemory", ALLOCATE), ("freeMemory", FREE),
                ("stepFinished", STEP_FINISHED), ("componentEnvironment", c_void_p)]


_libc = ctypes.CDLL(None)
_libc.calloc.restype = c_void_p
_libc.calloc.argtypes = [c_size_t, c_size_t]
_libc.free.argtypes = [c_void_p]

VR_ARRAY = POINTER(c_uint)

# name: (restype, argtypes)
_SIGNATURES = {
    "fmi2GetTypesPlatform": (c_char_p, []),
    "fmi2GetVersion": (c_char_p, []),
    "fmi2SetDebugLogging": (c_int, [c_void_p, c_int, c_size_t, POINTER(c_char_p)]),
    "fmi2Instantiate": (c_void_p, [c_char_p, c_int, c_char_p, c_char_p, c_void_p, c_int, c_int]),
    "fmi2FreeInstance": (None, [c_void_p]),
    "fmi2SetupExperiment": (c_int, [c_void_p, c_int, c_double, c_double, c_int, c_double]),
    "fmi2EnterInitializationMode": (c_int, [c_void_p]),
    "fmi2ExitInitializationMode": (c_int, [c_void_p]),
    "fmi2Terminate": (c_int, [c_void_p]),
    "fmi2Reset": (c_int, [c_void_p]),
    "fmi2GetReal": (c_int, [c_void_p, VR_ARRAY, c_size_t, POINTER(c_double)]),
    "fmi2GetInteger": (c_int, [c_void_p, VR_ARRAY, c_size_t, POINTER(c_int)]),
    "fmi2GetBoolean": (c_int, [c_void_p, VR_ARRAY, c_size_t, POINTER(c_int)]),
    "fmi2GetString": (c_int, [c_void_p, VR_ARRAY, c_size_t, POINTER(c_char_p)]),
    "fmi2SetReal": (c_int, [c_void_p, VR_ARRAY, c_size_t, POINTER(c_double)]),
    "fmi2SetInteger": (c_int, [c_void_p, VR_ARRAY, c_size_t, POINTER(c_int)]),
    "fmi2SetBoolean": (c_int, [c_void_p, VR_ARRAY, c_size_t, POINTER(c_int)]),
    "fmi2SetString": (c_int, [c_void_p, VR_ARRAY, c_size_t, POINTER(c_char_p)]),
    "fmi2GetFMUstate": (c_int, [c_void_p, POINTER(c_void_p)]),
    "fmi2SetFMUstate": (c_int, [c_void_p, c_void_p]),
    "fmi2FreeFMUstate": (c_int, [c_void_p, POINTER(c_void_p)]),
    "fmi2SerializedFMUstateSize": (c_int, [c_void_p, c_void_p, POINTER(c_size_t)]),
    "fmi2SerializeFMUstate": (c_int, [c_void_p, c_void_p, POINTER(c_char), c_size_t]),
    "fmi2DeSerializeFMUstate": (c_int, [c_void_p, POINTER(c_char), c_size_t, POINTER(c_void_p)]),
    "fmi2GetDirectionalDerivative": (c_int, [c_void_p, VR_ARRAY, c_size_t, VR_ARRAY, c_size_t,
                                             POINTER(c_double), POINTER(c_double)]),
    "fmi2SetRealInputDerivatives": (c_int, [c_void_p, VR_ARRAY, c_size_t, POINTER(c_int),
                                            POINTER(c_double)]),
    "fmi2GetRealOutputDerivatives": (c_int, [c_void_p, VR_ARRAY, c_size_t, POINTER(c_int),
                                             POINTER(c_double)]),
    "fmi2DoStep": (c_int, [c_void_p, c_double, c_double, c_int]),
    "fmi2CancelStep": (c_int, [c_void_p]),
    "fmi2GetStatus": (c_int, [c_void_p, c_int, POINTER(c_int)]),
    "fmi2GetRealStatus": (c_int, [c_void_p, c_int, POINTER(c_double)]),
    "fmi2GetIntegerStatus": (c_int, [c_void_p, c_int, POINTER(c_int)]),
    "fmi2GetBooleanStatus": (c_int, [c_void_p, c_int, POINTER(c_int)]),
    "fmi2GetStringStatus": (c_int, [c_void_p, c_int, POINTER(c_char_p)]),
    # Model Exchange
    "fmi2EnterEventMode": (c_int, [c_void_p]),
    "fmi2NewDiscreteStates": (c_int, [c_void_p, c_void_p]),  # fmi2EventInfo *: 6 fields
    "fmi2EnterContinuousTimeMode": (c_int, [c_void_p]),
    "fmi2CompletedIntegratorStep": (c_int, [c_void_p, c_int, POINTER(c_int), POINTER(c_int)]),
    "fmi2SetTime": (c_int, [c_void_p, c_double]),
    "fmi2SetContinuousStates": (c_int, [c_void_p, POINTER(c_double), c_size_t]),
    "fmi2GetContinuousStates": (c_int, [c_void_p, POINTER(c_double), c_size_t]),
    "fmi2GetNominalsOfContinuousStates": (c_int, [c_void_p, POINTER(c_double), c_size_t]),
    "fmi2GetDerivatives": (c_int, [c_void_p, POINTER(c_double), c_size_t]),
    "fmi2GetEventIndicators": (c_int, [c_void_p, POINTER(c_double), c_size_t]),
}


class EventInfo(ctypes.Structure):
    """fmi2EventInfo."""
    _fields_ = [("newDiscreteStatesNeeded", c_int), ("terminateSimulation", c_int),
                ("nominalsOfContinuousStatesChanged", c_int),
                ("valuesOfContinuousStatesChanged", c_int), ("nextEventTimeDefined", c_int),
                ("nextEventTime", c_double)]


class Library:
    """The FMU's shared library with typed fmi2 functions and one shared message log."""

    def __init__(self, so_path):
        self.dll = ctypes.CDLL(str(so_path))
        for name, (restype, argtypes) in _SIGNATURES.items():
            fn = getattr(self.dll, name)
            fn.restype, fn.argtypes = restype, argtypes
        self.messages = []
        self._logger = LOGGER(self._log)
        self._allocate = ALLOCATE(lambda n, size: _libc.calloc(n, size))
        self._free = FREE(lambda p: _libc.free(p))
        self._step_finished = STEP_FINISHED(0)

    def _log(self, env, instance, status, category, message):
        text = (message or b"").decode("utf-8", "replace")
        self.messages.append((status, (category or b"").decode("utf-8", "replace"), text))

    def callbacks(self, logger=True):
        """A callbacks struct kept alive by the caller; logger=False gives a NULL logger."""
        cb = Callbacks()
        if logger:
            cb.logger = self._logger
        cb.allocateMemory = self._allocate
        cb.freeMemory = self._free
        cb.stepFinished = self._step_finished
        cb.componentEnvironment = None
        return cb

    def __getattr__(self, name):
        if name.startswith("fmi2"):
            return getattr(self.dll, name)
        raise AttributeError(name)


def vr_array(refs):
    return None if refs is None else (c_uint * max(len(refs), 1))(*refs)


def real_array(values, n=None):
    return None if values is None else (c_double * max(n or len(values), 1))(*values)


def int_array(values, n=None):
    return None if values is None else (c_int * max(n or len(values), 1))(*values)


def string_array(values, n=None):
    if values is None:
        return None
    encoded = [v if v is None or isinstance(v, bytes) else v.encode() for v in values]
    return (c_char_p * max(n or len(encoded), 1))(*encoded)


def pointer_out():
    return c_void_p()


__all__ = ["Library", "Callbacks", "vr_array", "real_array", "int_array", "string_array",
           "pointer_out", "byref", "EventInfo", "OK", "WARNING", "DISCARD", "ERROR", "FATAL",
           "ME", "CS", "STATUS_NAMES"]
