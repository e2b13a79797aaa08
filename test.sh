#!/usr/bin/env bash
# Builds everything on a fresh machine and runs all tests: C unit tests (ctest), then the FMU
# through fmpy (pytest).
set -euo pipefail
cd "$(dirname "$0")"
scripts/setup.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"
.venv/bin/python -m pytest -q "$@"
