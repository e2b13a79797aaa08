"""Instances are independent: the FMU binary has no mutable global or static data but the
process's store of read-only tables (fmu-src/model/table_store.c: its list and its lock), so
instances on different threads share nothing else (docs/integration.md, thread safety). The
threaded runs themselves are in tests/host/run_fmu.c (scripts/soak.sh; helgrind in
scripts/valgrind.sh)."""

import pathlib
import subprocess

# symbols the C runtime start files put in .data / .bss of every shared library
CRT = {"__dso_handle", "completed.0", "__TMC_END__"}
# the table store's state, guarded by its lock (model/table_store.h)
STORE = {"store", "store_lock", "store_built"}


def test_no_writable_data_but_the_c_runtime(unzipped):
    so = pathlib.Path(unzipped) / "binaries" / "linux64" / "HypoidGearPair.so"
    sections = subprocess.run(["readelf", "-SW", str(so)], check=True, capture_output=True,
                              text=True).stdout
    ranges = []
    for line in sections.splitlines():
        parts = line.replace("[ ", "[").split()
        if len(parts) > 5 and parts[1] in (".data", ".bss", ".tbss", ".tdata"):
            start, size = int(parts[3], 16), int(parts[5], 16)
            ranges.append((parts[1], start, start + size))
    symbols = subprocess.run(["nm", "--defined-only", str(so)], check=True, capture_output=True,
                             text=True).stdout
    writable = []
    for line in symbols.splitlines():
        fields = line.split()
        if len(fields) != 3:
            continue
        address, name = int(fields[0], 16), fields[2]
        for section, lo, hi in ranges:
            if lo <= address < hi and name not in CRT | STORE:
                writable.append((section, name))
    assert writable == [], f"mutable global/static data in the FMU: {writable}"
