"""Every FMU the build makes carries, in documentation/licenses/, the project's licence and the
licence texts of what its binaries link (THIRD_PARTY.md), copied from those packages' own files:
SUNDIALS (the gear FMUs), musl's math (every FMU, when the build links it), the FMI headers'
(every FMU) and the mingw-w64 runtime's (FMUs with a win64 binary)."""
import re
import zipfile

import pytest

from conftest import ROOT

BUILD = ROOT / "build"
THIRD_PARTY = BUILD / "third_party"
GEAR_FMUS = ["HypoidGearPair.fmu", "HypoidGearPair_intenum.fmu"]
ALL_FMUS = GEAR_FMUS + ["LongitudinalVehicle.fmu"]


def cache_value(name):
    """A CMake cache entry of the build (empty when unset)."""
    match = re.search(rf"^{name}:\w+=(.*)$", (BUILD / "CMakeCache.txt").read_text(), re.M)
    return match[1] if match else ""


def licenses(fmu):
    path = BUILD / fmu
    if not path.exists():
        pytest.fail(f"{path} is missing: build it first (scripts/setup.sh)")
    with zipfile.ZipFile(path) as z:
        return {n.removeprefix("documentation/licenses/"): z.read(n).decode("utf-8")
                for n in z.namelist()
                if n.startswith("documentation/licenses/") and not n.endswith("/")}, z.namelist()


def expected(fmu, names):
    """{name in the FMU: (the file it is copied from, a phrase the text must hold)}."""
    fmi_dir = cache_value("FMI2_INCLUDE_DIR").removesuffix("/fmi2")
    out = {"license.txt": (ROOT / "LICENSE", "BSD 2-Clause License"),
           "FMI-headers-LICENSE.txt": (f"{fmi_dir}/LICENSE.txt",
                                       'Modelica Association Project "FMI"')}
    musl = cache_value("HG_MUSL_DIR")
    if musl:
        out["musl-COPYRIGHT.txt"] = (f"{musl}/COPYRIGHT", "standard MIT license")
    if fmu in GEAR_FMUS:
        sundials = cache_value("HG_SUNDIALS_SOURCE")
        out["SUNDIALS-LICENSE.txt"] = (f"{sundials}/LICENSE", "Lawrence Livermore National")
        out["SUNDIALS-NOTICE.txt"] = (f"{sundials}/NOTICE", "Lawrence Livermore National")
    if any(n.startswith("binaries/win64/") for n in names):
        out["mingw-w64-copyright.txt"] = (cache_value("HG_MINGW_LICENSE"), "ZPL-2.1")
    return out


@pytest.mark.parametrize("fmu", ALL_FMUS)
def test_licence_texts_in_the_fmu(fmu):
    texts, names = licenses(fmu)
    want = expected(fmu, names)
    assert sorted(texts) == sorted(want), f"{fmu}: documentation/licenses/ holds {sorted(texts)}"
    for name, (source, phrase) in want.items():
        assert phrase in texts[name], f"{fmu}: {name} lacks '{phrase}'"
        with open(source, encoding="utf-8") as f:
            assert texts[name] == f.read(), f"{fmu}: {name} is not a copy of {source}"


def test_the_product_build_links_musl_and_carries_its_licence():
    """The build of scripts/setup.sh links musl's math (Debian's source package): its text is
    then in every FMU; without the source package (a degraded build) this says so."""
    if not (THIRD_PARTY / "src").is_dir():
        pytest.skip("no third-party sources in build/third_party/src (scripts/third_party.sh)")
    assert cache_value("HG_MUSL_DIR"), "the build does not link musl's math (HG_MUSL_DIR unset)"
