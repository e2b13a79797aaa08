#!/usr/bin/env bash
# Builds everything on a fresh machine and runs all tests: C unit tests (ctest), then the FMU
# through fmpy (pytest), the FMU Compliance Checker, then the robustness runs below (about 2.5
# minutes on 2 cores). This is what CI runs.
#
#   ./test.sh --quick [pytest args]   the inner loop: the build, the C unit tests and the pytest
#                                     subset marked quick (tests/python/conftest.py: every layer,
#                                     about two minutes); no compliance, win64 or robustness runs
set -euo pipefail
cd "$(dirname "$0")"
quick=0
if [ "${1:-}" = "--quick" ]; then
  quick=1
  shift
fi
scripts/setup.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"
if [ "$quick" = 1 ]; then
  exec .venv/bin/python -m pytest -q -m quick "$@"
fi
.venv/bin/python -m pytest -q "$@"
# The FMU Compliance Checker on the built FMUs (0 warnings, 0 errors; skipped with a message where
# the team's fmuCheck sources are absent).
scripts/fmucheck.sh
# The win64 binary: its exports and imports, the C tests and the C host under Wine, and the same
# bits as linux64 (docs/portability.md; skipped with a message without the cross toolchain).
scripts/win64.sh test
# Robustness (docs/integration.md): fuzzing the C API for 60 s, the sanitizer build (ctest, C host,
# fmpy, bad-input cases), valgrind memcheck and helgrind, soak and threads with the C host.
scripts/fuzz.sh 60
scripts/sanitize.sh
scripts/valgrind.sh
scripts/soak.sh 2000
