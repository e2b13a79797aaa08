#!/usr/bin/env bash
# Fetches the FMI 2.0 and 3.0 C headers of the Modelica Association Project "FMI" (2-Clause BSD)
# from a package registry, once, into build/third_party/fmi-<version>/ (cached like the Debian
# sources of scripts/third_party.sh), so that the C build needs no Python package: the headers
# as the FMPy wheel on PyPI ships them (fmpy/c-code/; the version that pyproject.toml pins),
# downloaded with pip (the project's .venv when it exists, else python3 -m pip).
#   fmi2/  fmi2Functions.h, fmi2FunctionTypes.h, fmi2TypesPlatform.h   (CMake's FMI2_INCLUDE_DIR)
#   fmi3/  fmi3Functions.h, fmi3FunctionTypes.h, fmi3PlatformTypes.h   (CMake's FMI3_INCLUDE_DIR)
#   LICENSE.txt  the licence text the headers carry, cut out of fmi3Functions.h
#
#   scripts/fmi_headers.sh      prints the directory; exits 1 with a message when it cannot fetch
set -euo pipefail
cd "$(dirname "$0")/.."
version=$(sed -n 's/^ *"fmpy==\([0-9.]*\)",*$/\1/p' pyproject.toml)
[ -n "$version" ] || { echo "fmi_headers: no 'fmpy==X.Y.Z' pin in pyproject.toml" >&2; exit 1; }
dir=$PWD/build/third_party/fmi-$version
if [ ! -f "$dir/LICENSE.txt" ]; then
  pip=(python3 -m pip)
  [ -x .venv/bin/python ] && pip=(.venv/bin/python -m pip)
  "${pip[@]}" --version >/dev/null 2>&1 \
    || { echo "fmi_headers: pip is missing (run scripts/setup.sh, or set FMI2_INCLUDE_DIR)" >&2; exit 1; }
  mkdir -p build/third_party
  work=$(mktemp -d build/third_party/fmi-fetch.XXXXXX)
  trap 'rm -rf "$work"' EXIT
  echo "fmi_headers: fetching the FMI headers from PyPI (fmpy $version)" >&2
  "${pip[@]}" download -q --no-deps --only-binary=:all: --dest "$work" "fmpy==$version" >&2
  python3 - "$work" <<'PY'
import pathlib, re, sys, zipfile
work = pathlib.Path(sys.argv[1])
with zipfile.ZipFile(next(work.glob("fmpy-*.whl"))) as whl:
    for name in whl.namelist():
        m = re.fullmatch(r"fmpy/c-code/(fmi([23])\w*\.h)", name)
        if m:
            out = work / "out" / f"fmi{m[2]}" / m[1]
            out.parent.mkdir(parents=True, exist_ok=True)
            out.write_bytes(whl.read(name))
PY
  # the licence block of the header's comment: from its copyright line to its closing rule
  awk '/^Copyright \(C\) 2008-2011 MODELISAR consortium,/ { on = 1 }
       on { print } on && /^-+$/ && ++rules == 2 { exit }' "$work/out/fmi3/fmi3Functions.h" \
    > "$work/out/LICENSE.txt"
  grep -q "Redistribution and use in source and binary forms" "$work/out/LICENSE.txt" \
    || { echo "fmi_headers: no licence text found in fmi3Functions.h" >&2; exit 1; }
  rm -rf "$dir" && mv "$work/out" "$dir"
fi
echo "$dir"
