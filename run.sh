#!/usr/bin/env bash
# Builds everything on a fresh machine and runs the main job; results go to results/.
set -euo pipefail
cd "$(dirname "$0")"
scripts/setup.sh
.venv/bin/hypoid study default --fmu build/HypoidGearPair.fmu --out results "$@"
