"""The studies' sampling loop in C (sample_loop.c beside this module, built into the checkout's
build/libhg_sample_loop.so): hypoid.fmu.instance.FastIo.run hands it the FMU's own fmi2DoStep,
fmi2GetReal, fmi2GetInteger and fmi2SetReal, and it makes the same calls with the same arguments
as FastIo's Python loop, so the results are the same, without ctypes and the interpreter around
every call. An installed package (no build/) or a build without it runs the Python loop."""

import ctypes
import functools

import numpy as np

from hypoid import data

NAME = "libhg_sample_loop.so"
CALLS = (None, "fmi2SetReal", "fmi2DoStep", "fmi2GetReal", "fmi2GetInteger")  # host's CALL_*
_P = ctypes.c_void_p
_N = ctypes.c_size_t


@functools.cache
def library():
    """hg_sample_loop of the checkout's build, or None."""
    root = data.checkout()
    path = root / "build" / NAME if root is not None else None
    if path is None or not path.is_file():
        return None
    try:
        fn = ctypes.CDLL(str(path)).hg_sample_loop
    except (OSError, AttributeError):  # another platform's build, or an older one
        return None
    fn.restype = ctypes.c_int
    fn.argtypes = [_P, _P, _P, _P, _P, ctypes.c_double, ctypes.c_double, _N,
                   _P, _N, _P, _N, _P, _N, _P, _N, _P, _N, _P, _P,
                   ctypes.POINTER(_N), ctypes.POINTER(ctypes.c_int),
                   ctypes.POINTER(ctypes.c_double)]
    return fn


def run(loop, fns, io, t, h, reals, ints, times, inputs):
    """FastIo.run's loop in C (`loop` = library(), `fns` the FMU's four functions' addresses);
    returns (status, calls done, failed call's name or None, time reached)."""
    done, call, t_end = _N(), ctypes.c_int(), ctypes.c_double()
    if inputs is not None:
        inputs = np.ascontiguousarray(inputs, dtype=np.float64)
    status = loop(*fns, io.component, t, h, len(times),
                  ctypes.addressof(io._vr_real), io.n_real, reals.ctypes.data,
                  reals.strides[0] // 8, ctypes.addressof(io._vr_int), io.n_int,
                  ints.ctypes.data, ints.strides[0] // 4, ctypes.addressof(io._vr_in),
                  len(io._vr_in) if inputs is None else inputs.shape[1],
                  None if inputs is None else inputs.ctypes.data, times.ctypes.data,
                  ctypes.byref(done), ctypes.byref(call), ctypes.byref(t_end))
    return status, done.value, CALLS[call.value], t_end.value
