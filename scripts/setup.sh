#!/usr/bin/env bash
# Installs what the project needs on a fresh Debian/Ubuntu machine and builds the FMU:
#   apt: a C compiler, cmake, SUNDIALS (static archives), python3 with venv; libtbb12 (Ecos'
#        engine); for the win64 binary mingw-w64 and wine64 (scripts/win64.sh);
#   .venv: the hypoid package with its pinned dependencies;
#   build/third_party/: the Debian source packages of musl and SUNDIALS (scripts/third_party.sh),
#        and SUNDIALS built from it with optimisation for linux64 (scripts/sundials.sh); the FMI
#        2.0 and 3.0 headers from PyPI (scripts/fmi_headers.sh, which CMake runs).
# Idempotent: each part is skipped when already present.
set -euo pipefail
cd "$(dirname "$0")/.."

need_apt=()
command -v cc >/dev/null || need_apt+=(build-essential)
command -v cmake >/dev/null || need_apt+=(cmake)
[ -f /usr/lib/x86_64-linux-gnu/libsundials_cvode.a ] || need_apt+=(libsundials-dev)
python3 -c 'import venv, ensurepip' 2>/dev/null || need_apt+=(python3-venv)
python3 -c 'import sys; sys.exit(sys.version_info < (3, 11))' 2>/dev/null || need_apt+=(python3)
scripts/ensure_apt.sh "${need_apt[@]}"
# Ecos (ecospy, a test extra) ships its engine built against Debian's TBB: without libtbb12 its
# tests skip with the reason (hypoid.cosim.ecos.why_unavailable)
scripts/ensure_apt.sh libtbb12 || echo "setup: WARNING - libtbb12 could not be installed;" \
  "the tests that run Ecos skip" >&2

if [ ! -x .venv/bin/python ] || ! .venv/bin/python -c 'import hypoid, fmpy, pytest' 2>/dev/null \
   || [ pyproject.toml -nt .venv/.installed ]; then
  echo "setup: creating the Python environment in .venv"
  python3 -m venv .venv
  .venv/bin/pip install -q --upgrade pip
  .venv/bin/pip install -q -e ".[test]"
  touch .venv/.installed
fi
# hypoid drive-cycle's UDDS, HWFET, US06 and FTP-75 are the cycle files of NREL's FASTSim package;
# installed without its dependencies (it pins an older numpy): only its files are read.
.venv/bin/python -c 'import importlib.util as u, sys; sys.exit(u.find_spec("fastsim") is None)' \
  || .venv/bin/pip install -q --no-deps fastsim==2.1.5

# Third-party sources from Debian (cached in build/third_party/): musl's portable math for the
# FMU binaries, SUNDIALS for the win64 one; then the win64 DLL (skipped with a message where the
# cross toolchain cannot be installed; docs/portability.md).
musl="" sundials="" sundials_dir=""
third_party=$(scripts/third_party.sh) || echo "setup: WARNING - fetching the third-party sources" \
  "failed (see above); building without them" >&2
while IFS='=' read -r key value; do
  case $key in musl) musl=$value ;; sundials) sundials=$value ;; esac
done <<<"$third_party"
[ -n "$sundials" ] && [ -n "$musl" ] || echo "setup: WARNING - without Debian's musl and sundials" \
  "sources the FMU uses the system libm and Debian's SUNDIALS archives (built without" \
  "optimisation: about 2x slower) and carries no win64 binary; run scripts/setup.sh again" >&2
# SUNDIALS for linux64 built with optimisation from the same source (else Debian's archives)
[ -z "$sundials" ] ||
  sundials_dir=$(scripts/sundials.sh "$sundials" "$PWD/build/third_party/sundials-linux64" | tail -1)
win64=$(scripts/win64.sh build | tail -2) # the vehicle's DLL, then the gear's (or nothing)
win64_dll=$(tail -1 <<<"$win64") win64_vehicle_dll=$(sed -n '1{$!p}' <<<"$win64")
cmake -S . -B build -DHG_PYTHON="$PWD/.venv/bin/python" -DHG_MUSL_DIR="$musl" \
  -DHG_SUNDIALS_DIR="$sundials_dir" -DHG_WIN64_DLL="$win64_dll" \
  -DHG_WIN64_VEHICLE_DLL="$win64_vehicle_dll" >/dev/null
cmake --build build -j"$(nproc)"
echo "setup: built build/HypoidGearPair.fmu (binaries: $(python3 -c 'import sys, zipfile
print(" ".join(sorted({n.split("/")[1] for n in zipfile.ZipFile(sys.argv[1]).namelist()
                       if n.startswith("binaries/") and n.count("/") > 1})))' build/HypoidGearPair.fmu))"
