#!/usr/bin/env bash
# The FMU's win64 binary, cross-compiled on Linux with Debian's mingw-w64, and its tests under
# Wine (docs/portability.md):
#
#   scripts/win64.sh build   the toolchain (apt: mingw-w64, wine64), SUNDIALS 6.4.1 for Windows
#                            (static, from Debian's source package) and build/win64/: the DLLs
#                            (the gear's and the example vehicle's) and the C tests; prints the
#                            vehicle DLL's path and, on its last line, the gear DLL's (setup.sh
#                            puts them into the FMUs)
#   scripts/win64.sh test    rebuilds the DLLs and FMUs where sources changed, then the DLL's
#                            exports and imports (objdump), the C unit tests and the C
#                            host (tests/host) under Wine on build/HypoidGearPair.fmu, and the
#                            linux64/win64 agreement (tests/portability/compare.py), the FMI 3.0
#                            FMU's outputs on linux64 and win64 (tests/host/run_fmu3.c); the
#                            vehicle FMU's DLL: exports, imports and the same output bits as linux64
#
# Third-party pieces are cached under build/third_party/ (sources, SUNDIALS for Windows, the Wine
# prefix), so only the first run downloads and builds them. Where the cross toolchain cannot be
# installed (not Linux x86_64, no apt-get, no network) or HG_WIN64=0 is set, both steps say
# "win64: SKIPPED ..." and exit 0.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD
mode=${1:?usage: scripts/win64.sh build|test}
tp=$root/build/third_party
win=$root/build/win64
triple=x86_64-w64-mingw32
wine=/usr/lib/wine/wine64
export WINEPREFIX=$tp/wineprefix WINEDEBUG=-all

skip() {
  echo "win64: SKIPPED ($mode) - $*; the FMU carries no win64 binary" >&2
  exit 0
}
[ "${HG_WIN64:-1}" != 0 ] || skip "HG_WIN64=0"
[ "$(uname -sm)" = "Linux x86_64" ] || skip "the cross build runs on Linux x86_64 only"

toolchain() {
  if ! command -v $triple-gcc >/dev/null || [ ! -x $wine ]; then
    command -v apt-get >/dev/null || skip "mingw-w64 and wine64 are missing and there is no apt-get"
    scripts/ensure_apt.sh --no-install-recommends mingw-w64 wine64 \
      || skip "mingw-w64 and wine64 could not be installed with apt-get"
  fi
}

# SUNDIALS 6.4.1 as static Windows libraries, built once (scripts/sundials.sh)
sundials_win64() {
  scripts/sundials.sh "$1" "$tp/sundials-win64" \
    -DCMAKE_TOOLCHAIN_FILE="$root/cmake/mingw-w64-x86_64.cmake" | tail -1
}

fmi_include() { # fmi2 (default) or fmi3
  echo "$(scripts/fmi_headers.sh)/${1:-fmi2}"
}

build() {
  toolchain
  local musl="" sundials=""
  while IFS='=' read -r key value; do
    case $key in musl) musl=$value ;; sundials) sundials=$value ;; esac
  done < <(scripts/third_party.sh)
  [ -n "$sundials" ] || skip "Debian's sundials source package could not be fetched"
  [ -n "$musl" ] || skip "Debian's musl source package could not be fetched"
  local prefix
  prefix=$(sundials_win64 "$sundials")
  cmake -S . -B "$win" -DCMAKE_TOOLCHAIN_FILE="$root/cmake/mingw-w64-x86_64.cmake" \
    -DCMAKE_FIND_ROOT_PATH="$prefix" -DHG_PYTHON="$root/.venv/bin/python" \
    -DHG_MUSL_DIR="$musl" >/dev/null
  cmake --build "$win" -j"$(nproc)" >"$win/build.log" 2>&1 || { tail -40 "$win/build.log" >&2; exit 1; }
  # the project's C host, for Windows
  $triple-gcc -std=c99 -O2 -Wall -Wextra -Wpedantic -Werror -I"$(fmi_include)" \
    tests/host/run_fmu.c tests/host/fmu_host.c -o "$win/run_fmu.exe" -static -lpthread
  echo "$win/vehicle_fmu/binaries/win64/LongitudinalVehicle.dll"
  echo "$win/fmu/binaries/win64/HypoidGearPair.dll"
}

# Fails unless the DLL exports only FMI functions (prefix $2: fmi2, or fmi[23] for the gear's, which
# serves FMI 2.0 and 3.0) and imports only system DLLs.
check_dll() {
  local dll=$1 prefix=${2:-fmi2} dump exports imports bad
  dump=$($triple-objdump -p "$dll")
  exports=$(awk '/\[Ordinal\/Name Pointer\] Table/ { on = 1; next } on && /^[ \t]*\[/ { print $NF; next }
                 on { on = 0 }' <<<"$dump")
  imports=$(awk '/DLL Name:/ { print $3 }' <<<"$dump" | sort -u)
  echo "win64: $(basename "$dll") exports $(wc -w <<<"$exports") functions:" $exports
  echo "win64: $(basename "$dll") imports:" $imports
  bad=$(grep -v "^$prefix" <<<"$exports" || true)
  [ -z "$bad" ] || { echo "win64: FAILED - exports that are not $prefix*: $bad" >&2; exit 1; }
  [ "$(wc -w <<<"$exports")" -ge 30 ] || { echo "win64: FAILED - too few exports" >&2; exit 1; }
  for fn in ${3:-}; do # the entry points this DLL must export
    grep -qx "$fn" <<<"$exports" || { echo "win64: FAILED - $fn is not exported" >&2; exit 1; }
  done
  bad=$(grep -viE '^(KERNEL32|msvcrt)\.dll$' <<<"$imports" || true)
  [ -z "$bad" ] || { echo "win64: FAILED - imports other than KERNEL32/msvcrt: $bad" >&2; exit 1; }
}

# After a source change the DLLs are rebuilt (incrementally) and the FMUs repacked, so the tests
# never run stale win64 binaries against a fresh linux64 build.
refresh() {
  cmake --build "$win" -j"$(nproc)" >"$win/build.log" 2>&1 || { tail -40 "$win/build.log" >&2; exit 1; }
  cmake --build build -j"$(nproc)" >/dev/null
}

run_tests() {
  [ -f "$win/run_fmu.exe" ] || skip "build/win64 was not built (scripts/win64.sh build)"
  refresh
  local fmu=build/HypoidGearPair.fmu dir=$win/fmu-unzipped
  rm -rf "$dir" && python3 -m zipfile -e "$fmu" "$dir"
  [ -f "$dir/binaries/win64/HypoidGearPair.dll" ] \
    || { echo "win64: FAILED - $fmu has no binaries/win64/HypoidGearPair.dll" >&2; exit 1; }
  check_dll "$dir/binaries/win64/HypoidGearPair.dll" 'fmi[23]' "fmi2EnterEventMode
    fmi2NewDiscreteStates fmi2EnterContinuousTimeMode fmi2CompletedIntegratorStep fmi2SetTime
    fmi2SetContinuousStates fmi2GetContinuousStates fmi2GetNominalsOfContinuousStates
    fmi2GetDerivatives fmi2GetEventIndicators"
  [ -d "$WINEPREFIX" ] || { echo "win64: creating the Wine prefix $WINEPREFIX" >&2; $wine wineboot -i >/dev/null 2>&1; }
  ctest --test-dir "$win" --output-on-failure -j"$(nproc)" | tail -3
  # the C host: instantiate, initialise, a run with a state saved, serialized and restored
  # (resource URI file:///Z:/..., a drive letter)
  $wine "$win/run_fmu.exe" "Z:${dir//\//\\}" simulate 0.1
  $wine "$win/run_fmu.exe" "Z:${dir//\//\\}" simulate 0.01 me
  # a folder name that is not ASCII: the URI carries UTF-8, the FMU opens its files through UTF-16
  local odd="$win/fmu-Zürich"
  rm -rf "$odd" && cp -r "$dir" "$odd"
  LC_ALL=C.UTF-8 $wine "$win/run_fmu.exe" "Z:${odd//\//\\}" simulate 0.01
  # linux64 and win64 on the same calls
  cc -std=c99 -O2 -Wall -Wextra -Werror -I"$(fmi_include)" tests/host/run_fmu.c \
    tests/host/fmu_host.c -o "$win/run_fmu_linux" -ldl -lpthread
  .venv/bin/python tests/portability/compare.py --fmu-dir "$dir" --wine "$wine" \
    --win-host "$win/run_fmu.exe" --linux-host "$win/run_fmu_linux"
  fmi3
  vehicle
  /usr/lib/wine/wineserver -w # Wine's server ends a few seconds after its last client: wait
}

# The FMI 3.0 FMU: every Float64 output (arrays element by element) after each of 100
# co-simulation steps of 1 ms and after each of 1000 Model Exchange Euler steps of 1 us from the
# default start, bit for bit as on linux64 (tests/host/run_fmu3.c on both)
fmi3() {
  local fmu=build/HypoidGearPair_fmi3.fmu dir=$win/fmu3-unzipped flags=(-std=c99 -O2 -Wall
    -Wextra -Wpedantic -Werror -I"$(fmi_include fmi3)")
  rm -rf "$dir" && python3 -m zipfile -e "$fmu" "$dir"
  [ -f "$dir/binaries/x86_64-windows/HypoidGearPair.dll" ] \
    || { echo "win64: FAILED - $fmu has no binaries/x86_64-windows/HypoidGearPair.dll" >&2; exit 1; }
  $triple-gcc "${flags[@]}" tests/host/run_fmu3.c -o "$win/run_fmu3.exe" -static -lpthread
  cc "${flags[@]}" tests/host/run_fmu3.c -o "$win/run_fmu3_linux" -ldl -lpthread
  local run what
  for run in "0.1 0.001" "0.001 1e-6 me"; do
    what="co-simulation, 100 steps"
    [[ $run == *me ]] && what="Model Exchange, 1000 Euler steps"
    # shellcheck disable=SC2086 # the run's arguments, split
    diff <($wine "$win/run_fmu3.exe" "Z:${dir//\//\\}" $run | tr -d '\r') \
      <("$win/run_fmu3_linux" "$dir" $run) >/dev/null \
      || { echo "win64: FAILED - the FMI 3.0 FMU's outputs differ between win64 and linux64 ($what)" >&2; exit 1; }
    # shellcheck disable=SC2086
    echo "win64: the FMI 3.0 FMU's $("$win/run_fmu3_linux" "$dir" $run | wc -w) values ($what) agree bit for bit with linux64"
  done
}

# The example vehicle FMU (examples/vehicle): its DLL's exports and imports, and every Real
# output bit for bit as on linux64 after 1 s of road load and braking (the C host's `outputs`)
# (and in Model Exchange: 0.2 s of the half-shaft coupling by the C host's Euler steps)
vehicle() {
  local fmu=build/LongitudinalVehicle.fmu dir=$win/vehicle-unzipped run
  rm -rf "$dir" && python3 -m zipfile -e "$fmu" "$dir" && mkdir -p "$dir/resources"
  [ -f "$dir/binaries/win64/LongitudinalVehicle.dll" ] \
    || { echo "win64: FAILED - $fmu has no binaries/win64/LongitudinalVehicle.dll" >&2; exit 1; }
  check_dll "$dir/binaries/win64/LongitudinalVehicle.dll" fmi2 "fmi2GetDerivatives
    fmi2SetContinuousStates fmi2NewDiscreteStates"
  for run in "outputs 1.0 coupling=2 w_w=50 T_brake=120" "outputs 0.2 coupling=1 w_w=50 v0=10 me"; do
    # shellcheck disable=SC2086 # the words of the run
    diff <($wine "$win/run_fmu.exe" "Z:${dir//\//\\}" $run | tr -d '\r') \
      <("$win/run_fmu_linux" "$dir" $run) >/dev/null \
      || { echo "win64: FAILED - the vehicle FMU's outputs ($run) differ between win64 and linux64" >&2; exit 1; }
    # shellcheck disable=SC2086
    echo "win64: the vehicle FMU's $(grep -c '' <("$win/run_fmu_linux" "$dir" $run)) Real values ($run) agree bit for bit with linux64"
  done
}

case $mode in
  build) build ;;
  test) toolchain; run_tests ;;
  *) echo "usage: scripts/win64.sh build|test" >&2; exit 2 ;;
esac
