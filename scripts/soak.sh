#!/usr/bin/env bash
# Batch and thread checks with the C host tests/host/run_fmu.c against the normal FMU build:
#   soak: CYCLES instantiate / simulate 2 ms / serialize-deserialize / free cycles (default 2000,
#         the CI run; scripts/soak.sh 10000 for the full one), then CYCLES/10 with dlopen/dlclose
#         each; RSS may grow by at most 2 MiB after the warm-up and open file descriptors not at all;
#   threads: 4 instances with different parameters on 4 threads (0.1 s each, twice) bit-identical
#         to each run alone, fmi2Reset on each thread reproducing its run;
#   simulate: state save / serialize / restore in another instance / reset / fresh instance,
#         all bit-identical;
#   both again in Model Exchange (the host's Euler steps of 1 us, events, FMU states).
set -euo pipefail
cd "$(dirname "$0")/.."

cycles="${1:-2000}"
[ -f build/fmu/modelDescription.xml ] || scripts/setup.sh
fmi_include=$(sed -n 's/^FMI2_INCLUDE_DIR:PATH=//p' build/CMakeCache.txt)
cc -std=c99 -O2 -g -Wall -Wextra -Werror -I"$fmi_include" tests/host/run_fmu.c tests/host/fmu_host.c -o build/run_fmu \
   -ldl -lpthread
build/run_fmu build/fmu soak "$cycles"
build/run_fmu build/fmu soak $((cycles / 10)) reload
build/run_fmu build/fmu threads 4 0.1
build/run_fmu build/fmu simulate 0.1
build/run_fmu build/fmu threads 4 0.02 me
build/run_fmu build/fmu simulate 0.05 me
