"""The machine a record's figures were measured on, for its provenance: real-time factors
differ between processors by tens of per cent, so a record names the processor it ran on."""

import pathlib
import platform

CPUINFO = pathlib.Path("/proc/cpuinfo")


def processor(cpuinfo=CPUINFO):
    """The processor's model name (Linux's /proc/cpuinfo), else what `platform` knows of it."""
    try:
        for line in cpuinfo.read_text(errors="replace").splitlines():
            key, _, value = line.partition(":")
            if key.strip() == "model name" and value.strip():
                return value.strip()
    except OSError:
        pass
    return platform.processor() or platform.machine()
