"""The FMU as a package: model description, exported symbols, run-time dependencies, and the
variable table that must not drift from the modelDescription."""

import pathlib
import re
import subprocess
import zipfile

from fmpy.validation import validate_fmu

from conftest import ROOT


def test_validate_finds_nothing(fmu_path):
    assert validate_fmu(str(fmu_path)) == []


def test_archive_layout(fmu_path):
    names = set(zipfile.ZipFile(fmu_path).namelist())
    assert "modelDescription.xml" in names
    assert "binaries/linux64/HypoidGearPair.so" in names
    for k in (1, 2, 3):
        assert f"resources/gearsets/gearset{k}.txt" in names


def test_only_fmi_symbols_exported(unzipped):
    """The binary serves FMI 2.0 and FMI 3.0 (the FMI 3.0 FMU packs it too): fmi2* and fmi3*."""
    so = pathlib.Path(unzipped) / "binaries" / "linux64" / "HypoidGearPair.so"
    out = subprocess.run(["nm", "-D", "--defined-only", str(so)], check=True,
                         capture_output=True, text=True).stdout
    symbols = [line.split()[-1] for line in out.splitlines() if line.strip()]
    assert symbols, "no exported symbols at all"
    assert [s for s in symbols if not s.startswith(("fmi2", "fmi3"))] == []
    for required in ("fmi2Instantiate", "fmi2DoStep", "fmi2GetFMUstate",
                     "fmi2SerializeFMUstate", "fmi2SetRealInputDerivatives", "fmi2Reset",
                     "fmi3InstantiateCoSimulation", "fmi3DoStep", "fmi3GetFloat64"):
        assert required in symbols


def test_depends_on_libc_and_libm_only(unzipped):
    so = pathlib.Path(unzipped) / "binaries" / "linux64" / "HypoidGearPair.so"
    out = subprocess.run(["ldd", str(so)], check=True, capture_output=True, text=True).stdout
    libs = [line.split()[0] for line in out.splitlines() if line.strip()]
    allowed = re.compile(r"^(linux-vdso\.so\.1|libc\.so\.6|libm\.so\.6|/lib64/ld-linux-x86-64\.so\.2)$")
    assert [lib for lib in libs if not allowed.match(lib)] == []
    undefined = subprocess.run(["nm", "-D", "--undefined-only", str(so)], check=True,
                               capture_output=True, text=True).stdout
    assert "sundials" not in undefined.lower() and "CVode" not in undefined


def test_capabilities(model_description):
    cs = model_description.coSimulation
    assert cs.canHandleVariableCommunicationStepSize
    assert cs.canGetAndSetFMUstate and cs.canSerializeFMUstate
    assert cs.canInterpolateInputs
    assert not cs.canBeInstantiatedOnlyOncePerProcess
    cats = {c for c, _ in model_description.logCategories} if model_description.logCategories \
        and isinstance(model_description.logCategories[0], tuple) else \
        {getattr(c, "name", c) for c in model_description.logCategories}
    assert {"logEvents", "logStatusWarning", "logStatusError", "logAll"} <= cats


def test_contract_variables_present(model_description):
    """The names, causalities and units of the interface contract (the variables hosts rely on)."""
    by_name = {v.name: v for v in model_description.modelVariables}
    for name in ("T_s", "T_w", "T_bath", "w_set"):
        assert by_name[name].causality == "input"
    outputs = ["w_s", "w_p", "w_g", "w_w", "DTE", "W_t", "T_fp", "T_fg", "P_loss", "eta",
               "eta_cycle", "T_w_out"]
    outputs += [f"pair[{k}].{q}" for k in (1, 2, 3) for q in
                ("W", "h_c", "lambda", "mu", "F_v", "F_b", "T_c", "u_e", "V_s", "R_e", "R_s", "p_h")]
    for name in outputs:
        assert by_name[name].causality == "output", name
    assert by_name["w_p"].unit == "rad/s" and by_name["w_p"].displayUnit == "rpm"
    assert by_name["T_bath"].unit == "K" and by_name["T_bath"].displayUnit == "degC"
    assert by_name["DTE"].unit == "m" and by_name["DTE"].displayUnit == "um"
    assert by_name["T_s"].start == "100.0"


def test_readme_variable_table_is_current():
    """README's table is generated from variables.toml, the source of the XML and the C table."""
    subprocess.run(["python3", str(ROOT / "modelDescription" / "generate.py"), "--readme",
                    str(ROOT / "README.md"), "--check"], check=True)


def test_python_variable_table_is_current():
    """hypoid/fmu/variables.py is generated from variables.toml like the README table."""
    subprocess.run(["python3", str(ROOT / "modelDescription" / "generate.py"), "--python",
                    str(ROOT / "hypoid" / "fmu" / "variables.py"), "--check"], check=True)


def test_python_variable_table_matches_the_model_description(model_description):
    """Names, value references, causalities, units and enumeration codes of hypoid.fmu.variables
    agree with the built FMU's modelDescription.xml, read by fmpy."""
    from hypoid.fmu.variables import ENUMERATIONS, GUID, VARIABLES

    assert model_description.guid == GUID
    assert [v.name for v in model_description.modelVariables] == list(VARIABLES)
    for v in model_description.modelVariables:
        mine = VARIABLES[v.name]
        assert (mine.vr, mine.causality, mine.type) == (v.valueReference, v.causality, v.type)
        assert (mine.unit or None) == (v.unit or None), v.name
        if v.type == "Enumeration":
            items = {i.name: int(i.value) for i in v.declaredType.items}
            assert ENUMERATIONS[mine.enumeration] == items
            assert int(v.start) == mine.start


def test_readme_shows_enumeration_codes():
    """Hosts such as fmpy set enumerations by their integer codes, so the
    README table gives each item's code (load_mode: 1 = torque, 2 = speed)."""
    text = (ROOT / "README.md").read_text()
    row = next(line for line in text.splitlines() if line.startswith("| `friction_model` |"))
    assert "1 = none" in row and "4 = ehl_thermal" in row and "5 = map" in row
    assert "`4` (ehl_thermal)" in row
