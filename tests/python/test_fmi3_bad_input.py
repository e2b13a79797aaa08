"""Bad input at every FMI 3.0 entry point of the FMU, co-simulation and Model Exchange: calls in
the wrong state or of the other interface, NULL pointers, NaN and out-of-range values, wrong array
sizes, unknown value references, unsupported functions.
Each returns fmi3Error (instantiation: NULL) with a message naming the function and, where there
is one, the variable and the value; none crashes (the calls run in a child process,
tests/python/fmi3_raw.py)."""

import json
import os
import pathlib
import subprocess
import sys
import zipfile

import pytest
from fmpy import read_model_description

ROOT = pathlib.Path(__file__).resolve().parents[2]
FMU3 = pathlib.Path(os.environ.get("HG_FMI3_FMU", ROOT / "build" / "HypoidGearPair_fmi3.fmu"))
ERROR = 3

# case: (statuses wanted, words the messages must hold; the function's name first)
EXPECTED = {
    "dostep_before_initialization": ([ERROR], ["fmi3DoStep", "not allowed"]),
    "get_in_instantiated_state": ([ERROR], ["fmi3GetFloat64", "not allowed"]),
    "get_null_value_references": ([ERROR], ["fmi3GetFloat64", "NULL"]),
    "get_null_values": ([ERROR], ["fmi3GetFloat64", "NULL"]),
    "dostep_null_outputs": ([ERROR], ["fmi3DoStep", "NULL", "lastSuccessfulTime"]),
    "set_nan_input": ([ERROR], ["fmi3SetFloat64", "T_s", "nan"]),
    "set_out_of_range_input": ([ERROR], ["fmi3SetFloat64", "T_bath", "1000", "range"]),
    "set_enumeration_out_of_range": ([ERROR], ["fmi3SetInt64", "mesh_model", "7", "range"]),
    "set_enumeration_beyond_int": ([ERROR], ["fmi3SetInt64", "mesh_model", "range"]),
    "get_array_wrong_n_values": ([ERROR], ["fmi3GetFloat64", "nValues = 1", "3 values"]),
    "set_wrong_n_values": ([ERROR], ["fmi3SetFloat64", "nValues = 2", "1 values"]),
    "get_unknown_value_reference": ([ERROR], ["fmi3GetFloat64", "unknown value reference 99999"]),
    "get_array_element_value_reference": ([ERROR], ["fmi3GetFloat64", "unknown value reference"]),
    "get_enumeration_as_int32": ([ERROR], ["fmi3GetInt32", "mesh_model", "Enumeration"]),
    "set_time": ([ERROR], ["fmi3SetFloat64", "'time'"]),
    "set_fixed_parameter_after_initialization": ([ERROR], ["fmi3SetFloat64", "w_p0",
                                                           "fixed parameter"]),
    "set_string_null": ([ERROR], ["fmi3SetString", "gear_set_file", "NULL"]),
    "dostep_nan": ([ERROR], ["fmi3DoStep", "not finite"]),
    "dostep_wrong_time": ([ERROR], ["fmi3DoStep", "does not continue"]),
    "get_float32": ([ERROR], ["fmi3GetFloat32", "no Float32 variables"]),
    "get_binary": ([ERROR], ["fmi3GetBinary", "no Binary variables"]),
    "enter_event_mode": ([ERROR], ["fmi3EnterEventMode", "not allowed"]),
    "output_derivative_second_order": ([ERROR], ["fmi3GetOutputDerivatives", "w_p", "order 2",
                                                 "maxOutputDerivativeOrder = 1"]),
    "output_derivative_of_no_state": ([ERROR], ["fmi3GetOutputDerivatives", "'eta'",
                                                "not an output with a derivative"]),
    "output_derivative_null_orders": ([ERROR], ["fmi3GetOutputDerivatives", "NULL"]),
    "model_exchange_function": ([ERROR], ["fmi3GetContinuousStates", "Model Exchange"]),
    "get_fmu_state_null": ([ERROR], ["fmi3GetFMUState", "NULL"]),
    "serialized_size_null": ([ERROR], ["fmi3SerializedFMUStateSize", "NULL"]),
    "deserialize_garbage": ([ERROR], ["fmi3DeserializeFMUState", "64 bytes"]),
    "debug_logging_unknown_category": ([ERROR], ["fmi3SetDebugLogging", "logNothing"]),
    "terminate_twice": ([0, ERROR], ["fmi3Terminate", "not allowed"]),
    "reset_then_step": ([0, ERROR], ["fmi3DoStep", "not allowed"]),
    "null_instance": ([ERROR] * 4, []),
    "instantiate_wrong_token": ([0], ["fmi3InstantiateCoSimulation", "{not-the-token}"]),
    "instantiate_blank_name": ([0], ["fmi3InstantiateCoSimulation", "instanceName"]),
    "me_dostep": ([ERROR], ["fmi3DoStep", "co-simulation function", "Model Exchange"]),
    "me_wrong_number_of_derivatives": ([ERROR], ["fmi3GetContinuousStateDerivatives",
                                                 "3 derivatives"]),
    "me_null_states": ([ERROR], ["fmi3SetContinuousStates", "NULL"]),
    "me_nan_state": ([ERROR], ["fmi3SetContinuousStates", "state 0", "not a finite"]),
    "me_set_time_nan": ([ERROR], ["fmi3SetTime", "not finite"]),
    "me_number_null": ([ERROR], ["fmi3GetNumberOfContinuousStates", "NULL"]),
    "me_set_event_indicator": ([ERROR], ["fmi3SetFloat64", "event_indicator"]),
    "me_update_null": ([ERROR], ["fmi3UpdateDiscreteStates", "NULL"]),
    "me_completed_step_in_event_mode": ([ERROR], ["fmi3CompletedIntegratorStep",
                                                  "not allowed", "event mode"]),
    "missing_resources": ([ERROR], ["fmi3ExitInitializationMode", "/nonexistent/resources"]),
}


@pytest.fixture(scope="module")
def transcript(tmp_path_factory):
    if not FMU3.exists():
        pytest.fail(f"{FMU3} is missing: build it first (scripts/setup.sh)")
    d = tmp_path_factory.mktemp("fmu3")
    with zipfile.ZipFile(FMU3) as z:
        z.extractall(d)
    md = read_model_description(str(FMU3))
    vr = {v.name: v.valueReference for v in md.modelVariables}
    vr["n_states"] = len(md.derivatives)
    so = d / "binaries" / "x86_64-linux" / "HypoidGearPair.so"
    proc = subprocess.run([sys.executable, str(ROOT / "tests/python/fmi3_raw.py"), str(so),
                           md.instantiationToken, str(d / "resources") + "/", json.dumps(vr)],
                          capture_output=True, text=True, timeout=300)
    results, last = {}, None
    for line in proc.stdout.splitlines():
        if line.startswith("BEGIN "):
            last = line[6:]
        elif line.startswith("RESULT "):
            r = json.loads(line[7:])
            results[r["case"]] = r
    assert proc.returncode == 0, (f"the FMU crashed (exit {proc.returncode}) in case {last}: "
                                  f"{proc.stderr[-2000:]}")
    return results


@pytest.mark.parametrize("case", sorted(EXPECTED))
def test_bad_input_is_an_error_naming_function_and_variable(transcript, case):
    statuses, words = EXPECTED[case]
    r = transcript[case]
    assert r["statuses"] == statuses, r
    text = " | ".join(r["messages"])
    for w in words:
        assert w in text, f"{case}: '{w}' not in the messages: {text}"


def test_every_case_is_judged(transcript):
    assert set(transcript) == set(EXPECTED)
