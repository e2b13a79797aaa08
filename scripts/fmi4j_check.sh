#!/usr/bin/env bash
# Loads the FMUs in FMI4j (Maven Central info.laht.fmi4j:fmi-import, a JVM host using JNI), runs
# them and checks FMI4j's outputs against fmpy's for the same calls (tests/cosim/fmi4j_compare.py).
#   - build/HypoidGearPair.fmu: 0.1 s with h = 1e-4 at the default scene, and torque-driven
#   - build/LongitudinalVehicle.fmu: 1 s with h = 1e-3
# Installs a JDK and Maven with apt-get when missing; Maven fetches FMI4j from Maven Central.
# Builds the FMUs (scripts/setup.sh) when missing. Not part of ./test.sh (it needs the JVM and
# downloads): run it by hand or in CI as a separate step.
set -euo pipefail
cd "$(dirname "$0")/.."

need_apt=()
command -v javac >/dev/null || need_apt+=(default-jdk-headless)
command -v mvn >/dev/null || need_apt+=(maven)
scripts/ensure_apt.sh "${need_apt[@]}"
if [ ! -f build/HypoidGearPair.fmu ] || [ ! -f build/LongitudinalVehicle.fmu ]; then
  scripts/setup.sh
fi

proj=tests/cosim/fmi4j
out=build/fmi4j # Maven builds into $out/target (see the pom)
mkdir -p "$out"
if ! mvn -B -f "$proj/pom.xml" compile dependency:copy-dependencies \
     -DoutputDirectory="$PWD/$out/target/dependency" >"$out/maven.log" 2>&1; then
  cat "$out/maven.log"
  exit 1
fi
cp="$out/target/classes:$out/target/dependency/*"

check() { # NAME FMU STOP STEP [name=value ...]
  local name=$1
  shift
  java -cp "$cp" Fmi4jCheck "$@" >"$out/$name.txt"
  .venv/bin/python tests/cosim/fmi4j_compare.py "$out/$name.txt" "$@"
}

check gear_default build/HypoidGearPair.fmu 0.1 1e-4
check gear_torque build/HypoidGearPair.fmu 0.1 1e-4 load_mode=1 T_s=150 T_w=300 w_p0=50
check vehicle build/LongitudinalVehicle.fmu 1.0 1e-3 v0=10 w_w=33.3 T_hs0=100
sed -n '1,8p' "$out/gear_default.txt"
echo "fmi4j_check: FMI4j and fmpy agree (outputs in $out/)"
