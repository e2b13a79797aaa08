#!/usr/bin/env bash
# Builds everything with AddressSanitizer + UndefinedBehaviorSanitizer (CMake option HG_SANITIZE)
# into build-asan/ and runs, each of which must be clean:
#   1. the C unit tests (ctest), leak detection on;
#   2. the C host tests/host/run_fmu.c, built with the sanitizers, against the sanitized FMU:
#      simulate 0.1 s with state save / serialize / restore / reset, 4 instances on 4 threads,
#      200 instantiate-simulate-free cycles and 20 with dlopen/dlclose, and the first two again in
#      Model Exchange (the host's Euler steps, events, states) - leak detection on, so a leak in
#      the FMU fails the run; the FMI 3.0 C host tests/host/run_fmu3.c likewise on the FMI 3.0
#      FMU;
#   3. fmpy simulating the sanitized FMU in Python (libasan preloaded; leak detection off there,
#      because the Python interpreter's own allocations would count - the C host covers leaks),
#      and every bad-input case of tests/python/test_robustness_inputs.py and of the FMI 3.0
#      entry points (test_fmi3_bad_input.py) against it (SANITIZE_ROBUSTNESS=0 skips them).
# Installs the GCC sanitizer runtimes with apt when missing.
set -euo pipefail
cd "$(dirname "$0")/.."

if ! echo 'int main(void){return 0;}' | cc -fsanitize=address,undefined -x c - -o /tmp/hg-asan-probe 2>/dev/null; then
  scripts/ensure_apt.sh libasan8 libubsan1 || scripts/ensure_apt.sh gcc
fi
rm -f /tmp/hg-asan-probe
[ -x .venv/bin/python ] || scripts/setup.sh

cmake -S . -B build-asan -DHG_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DHG_PYTHON="$PWD/.venv/bin/python" >/dev/null
cmake --build build-asan -j2 >/dev/null
fmi_include=$(sed -n 's/^FMI2_INCLUDE_DIR:PATH=//p' build-asan/CMakeCache.txt)

common="detect_stack_use_after_return=1:check_initialization_order=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"

echo "sanitize: ctest (ASan + UBSan, leaks checked)"
ASAN_OPTIONS="detect_leaks=1:$common" ctest --test-dir build-asan --output-on-failure -j2

echo "sanitize: C host (ASan + UBSan, leaks checked)"
cc -std=c99 -O1 -g -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all \
   -Wall -Wextra -Werror -I"$fmi_include" tests/host/run_fmu.c tests/host/fmu_host.c \
   -o build-asan/run_fmu -ldl -lpthread
export ASAN_OPTIONS="detect_leaks=1:$common"
build-asan/run_fmu build-asan/fmu simulate 0.1
build-asan/run_fmu build-asan/fmu threads 4 0.02
build-asan/run_fmu build-asan/fmu soak 200 norss
build-asan/run_fmu build-asan/fmu soak 20 reload norss
build-asan/run_fmu build-asan/fmu simulate 0.01 me
build-asan/run_fmu build-asan/fmu threads 3 0.005 me
cc -std=c99 -O1 -g -fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all \
   -Wall -Wextra -Werror -I"$(sed -n 's/^FMI3_INCLUDE_DIR:PATH=//p' build-asan/CMakeCache.txt)" \
   tests/host/run_fmu3.c -o build-asan/run_fmu3 -ldl -lpthread
build-asan/run_fmu3 build-asan/fmu_fmi3 0.05 0.001 >/dev/null
build-asan/run_fmu3 build-asan/fmu_fmi3 0.0002 1e-6 me >/dev/null
build-asan/run_fmu3 build-asan/fmu_fmi3 0.01 0.001 threads 3
build-asan/run_fmu3 build-asan/fmu_fmi3 0.0001 1e-6 me threads 3

echo "sanitize: fmpy in Python with libasan preloaded (leaks not checked in Python)"
libasan=$(cc -print-file-name=libasan.so)
export ASAN_OPTIONS="detect_leaks=0:$common"
LD_PRELOAD="$libasan" .venv/bin/python - <<'PY'
import numpy as np
from fmpy import simulate_fmu
r = simulate_fmu("build-asan/HypoidGearPair.fmu", stop_time=0.05, output_interval=1e-4,
                 start_values={"T_s": 120.0}, output=["w_p", "DTE", "eta"])
assert np.all(np.isfinite(r["w_p"])) and len(r) > 400, r
print(f"sanitize: fmpy simulated {len(r)} points, w_p(end) = {r['w_p'][-1]:.3f} rad/s")
r = simulate_fmu("build-asan/HypoidGearPair.fmu", fmi_type="ModelExchange", stop_time=0.02,
                 output_interval=1e-4, relative_tolerance=1e-6, output=["w_p", "DTE", "eta"])
assert np.all(np.isfinite(r["w_p"])) and len(r) > 150, r
print(f"sanitize: fmpy's CVode on Model Exchange, {len(r)} points, w_p(end) = "
      f"{r['w_p'][-1]:.3f} rad/s")
PY
if [ "${SANITIZE_ROBUSTNESS:-1}" != 0 ]; then
  HG_ROBUSTNESS_FMU_DIR="$PWD/build-asan/fmu" LD_PRELOAD="$libasan" \
    .venv/bin/python -m pytest -q -p no:cacheprovider tests/python/test_robustness_inputs.py
  HG_FMI3_FMU="$PWD/build-asan/HypoidGearPair_fmi3.fmu" LD_PRELOAD="$libasan" \
    .venv/bin/python -m pytest -q -p no:cacheprovider tests/python/test_fmi3_bad_input.py
fi
echo "sanitize: all clean"
