#!/usr/bin/env bash
# Runs the Modelica Association's FMU Compliance Checker (fmuCheck) on the FMUs the build makes:
# the XML check, co-simulation at h/stop = 1e-4/0.1 s, 1e-3/1 s, 1e-2/2 s, and a run driven by an
# input file; for an FMU with Model Exchange also that, integrated by the checker's forward Euler
# (steps below the stability bound of the gear's stiffest mode: 1 us and 2 us; the vehicle 1 ms),
# alone and driven by the input file. Every run must end with 0 warnings and 0 errors (from the
# checker and from the FMU).
#
#   scripts/fmucheck.sh [FMU ...]     default: build/HypoidGearPair.fmu build/LongitudinalVehicle.fmu
#                                     (and build/HypoidGearPair_intenum.fmu when it exists)
#
# fmuCheck is third-party test tooling, not part of the repository: it is built offline, once,
# into build/third_party/fmucheck/ by the team's tools/fmucheck/build.sh, looked for in
# $HG_SHARED, ../shared and ../../shared (beside this clone or its worktree folder). Where none is
# found (a user's own clone), the check is skipped with a message and exit status 0.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$PWD

builder=""
for dir in ${HG_SHARED:+"$HG_SHARED"} "$root/../shared" "$root/../../shared"; do
  if [ -x "$dir/tools/fmucheck/build.sh" ]; then builder="$dir/tools/fmucheck/build.sh"; break; fi
done
if [ -z "$builder" ]; then
  echo "fmucheck: SKIPPED - the team's tools/fmucheck/build.sh was not found (set HG_SHARED to" \
       "the folder holding tools/fmucheck/); the FMUs were not compliance-checked"
  exit 0
fi
cache=build/third_party/fmucheck
fmucheck=$("$builder" "$cache" | tail -1)

out=build/fmucheck
rm -rf "$out" && mkdir -p "$out/tmp"

# Input files: first column time, then inputs by name; values vary within the declared ranges.
# The gear runs at its default load_mode = speed, where T_w is not used (setting it is warned
# about), so the file drives the other inputs.
cat >"$out/HypoidGearPair.in.csv" <<'EOF'
"time","T_s","T_bath","w_set"
0.0,100.0,313.15,209.44
0.05,150.0,313.15,209.44
0.1,150.0,323.15,230.0
0.2,80.0,333.15,200.0
EOF
cat >"$out/LongitudinalVehicle.in.csv" <<'EOF'
"time","w_w"
0.0,0.0
0.1,20.0
0.2,30.0
EOF

failed=0
check() { # NAME FMU STOP|- fmuCheck-options...   (STOP: the time the results must reach)
  local name=$1 fmu=$2 stop=$3
  shift 3
  local log="$out/$name.log"
  "$fmucheck" "$@" -l 3 -t "$out/tmp" -e "$log" -o "$out/$name.csv" "$fmu" >/dev/null 2>&1 || true
  local warn err fmu_msgs
  warn=$(sed -n 's/^[[:space:]]*\([0-9]\+\) Warning(s)$/\1/p' "$log" | tail -1)
  err=$(sed -n 's/^[[:space:]]*\([0-9]\+\) Error(s)$/\1/p' "$log" | tail -1)
  fmu_msgs=$(sed -n 's/^[[:space:]]*\([0-9]\+\) warning(s) and error(s)$/\1/p' "$log" | head -1)
  printf 'fmucheck: %-34s %s warning(s), %s error(s), FMU: %s warning(s)/error(s)\n' \
    "$name" "${warn:-?}" "${err:-?}" "${fmu_msgs:-?}"
  if [ "${warn:-x}" != 0 ] || [ "${err:-x}" != 0 ] || [ "${fmu_msgs:-x}" != 0 ]; then
    grep -E 'WARNING|ERROR|FATAL' "$log" | head -20 >&2 || true
    failed=1
  fi
  if [ "$stop" != - ] && ! tail -1 "$out/$name.csv" 2>/dev/null | awk -F, -v s="$stop" \
       '{ d = $1 - s; exit !(d < 1e-9 && d > -1e-9) }'; then
    echo "fmucheck: $name: the results do not reach t = $stop s" >&2
    failed=1
  fi
}

fmus=("$@")
if [ ${#fmus[@]} -eq 0 ]; then
  fmus=(build/HypoidGearPair.fmu build/LongitudinalVehicle.fmu)
  [ -f build/HypoidGearPair_intenum.fmu ] && fmus+=(build/HypoidGearPair_intenum.fmu)
fi
for fmu in "${fmus[@]}"; do
  [ -f "$fmu" ] || { echo "fmucheck: $fmu is missing (build it first: scripts/setup.sh)" >&2; exit 1; }
  base=$(basename "$fmu" .fmu)
  input="$out/${base%_intenum}.in.csv"
  check "$base.xml" "$fmu" - -k xml
  check "$base.cs_1e-4_0.1s" "$fmu" 0.1 -k cs -h 1e-4 -s 0.1
  check "$base.cs_1e-3_1s" "$fmu" 1 -k cs -h 1e-3 -s 1
  check "$base.cs_1e-2_2s" "$fmu" 2 -k cs -h 1e-2 -s 2
  check "$base.cs_input_file" "$fmu" 0.2 -k cs -h 1e-3 -s 0.2 -i "$input"
  [[ $(unzip -p "$fmu" modelDescription.xml) == *'<ModelExchange'* ]] || continue
  if [ "${base%_intenum}" = HypoidGearPair ]; then h_me=(1e-6 2e-6); else h_me=(1e-3 1e-3); fi
  check "$base.me_${h_me[0]}_0.05s" "$fmu" 0.05 -k me -h "${h_me[0]}" -s 0.05
  check "$base.me_input_file" "$fmu" 0.2 -k me -h "${h_me[1]}" -s 0.2 -i "$input"
done
rm -rf "$out/tmp"
if [ $failed -ne 0 ]; then
  echo "fmucheck: FAILED - fmuCheck reported warnings or errors (logs in $out/)" >&2
  exit 1
fi
echo "fmucheck: all runs 0 warnings, 0 errors (logs and results in $out/)"
