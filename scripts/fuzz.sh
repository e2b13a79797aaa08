#!/usr/bin/env bash
# Fuzzes the FMU's FMI 2.0 interface with libFuzzer (tests/fuzz/fuzz_fmi2.c): builds the target
# with clang, AddressSanitizer and UndefinedBehaviorSanitizer into build-fuzz/, writes a seed
# corpus, and fuzzes for SECONDS (default 60, the CI run). The corpus in build-fuzz/fuzz-corpus/
# is kept between runs, so longer runs build on earlier ones.
#
#   scripts/fuzz.sh              # 60 s (test.sh runs this)
#   scripts/fuzz.sh 3600         # an hour; FUZZ_JOBS=2 scripts/fuzz.sh 3600 for two processes
#   scripts/fuzz.sh FILE...      # replay inputs (e.g. a finding in build-fuzz/fuzz-artifacts/)
#
# Installs clang and its libFuzzer runtime with apt when missing. Exit status 1 on a finding:
# a crash, sanitizer report, leak, timeout (> 120 s for one input) or a broken interface property
# (fmi2Error without a log message, fmi2GetReal returning a non-finite value with fmi2OK).
set -euo pipefail
cd "$(dirname "$0")/.."

command -v clang >/dev/null || scripts/ensure_apt.sh clang
runtime="$(clang -print-runtime-dir)/libclang_rt.fuzzer-x86_64.a"
if [ ! -f "$runtime" ]; then
  major="$(clang -dumpversion | cut -d. -f1)"
  scripts/ensure_apt.sh "libclang-rt-${major}-dev" || scripts/ensure_apt.sh "libclang-common-${major}-dev"
fi
[ -x .venv/bin/python ] || scripts/setup.sh

cmake -S . -B build-fuzz -DCMAKE_C_COMPILER=clang -DHG_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DHG_PYTHON="$PWD/.venv/bin/python" >/dev/null
cmake --build build-fuzz --target fuzz_fmi2 -j2 >/dev/null
fuzzer=build-fuzz/tests/fuzz/fuzz_fmi2
export ASAN_OPTIONS="detect_leaks=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"

if [ $# -gt 0 ] && [ -f "$1" ]; then
  exec "$fuzzer" "$@" </dev/null
fi

seconds="${1:-60}"
seeds=build-fuzz/fuzz-seeds corpus=build-fuzz/fuzz-corpus artifacts=build-fuzz/fuzz-artifacts
export HG_FUZZ_TMPDIR="$PWD/build-fuzz/fuzz-tmp" # data files written from the inputs
rm -rf "$seeds" "$artifacts" "$HG_FUZZ_TMPDIR"
mkdir -p "$seeds" "$corpus" "$artifacts" "$HG_FUZZ_TMPDIR"
HG_FUZZ_WRITE_SEEDS="$seeds" "$fuzzer"
log=build-fuzz/fuzz.log
set +e
# -timeout is libFuzzer's per-input limit in wall time: a legal but costly input (max_step = 1e-9 s
# takes the 500 000 solver steps of one fmi2DoStep, ~5 s of CPU under ASan) must not count as a
# hang on a loaded machine; a real hang still shows.
"$fuzzer" -max_total_time="$seconds" -timeout=120 -rss_limit_mb=2048 -max_len=20000 \
  -print_final_stats=1 -artifact_prefix="$artifacts/" ${FUZZ_JOBS:+-jobs=$FUZZ_JOBS -workers=$FUZZ_JOBS} \
  "$corpus" "$seeds" </dev/null >"$log" 2>&1
rc=$?
set -e
rm -rf "$HG_FUZZ_TMPDIR"
if [ -n "${FUZZ_JOBS:-}" ]; then cat fuzz-*.log >>"$log" 2>/dev/null && rm -f fuzz-*.log; fi
runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | awk '{s += $2} END {print s + 0}')
findings=$(find "$artifacts" -type f | wc -l)
echo "fuzz: ${seconds} s, ${runs} executions, corpus $(find "$corpus" -type f | wc -l) inputs," \
     "${findings} finding(s) (log: $log)"
if [ "$rc" -ne 0 ] || [ "$findings" -ne 0 ]; then
  grep -E "ERROR|SUMMARY|fuzz_fmi2:|Test unit written" "$log" | head -20
  echo "fuzz: replay a finding with scripts/fuzz.sh $artifacts/<file>"
  exit 1
fi
