#!/usr/bin/env bash
# Regenerates, in one command, the data that depend on the full model's default results, after a
# deliberate change of the defaults (friction, tooth data, contact, kinematics): the six built-in
# efficiency maps (resources/maps), the FMU that packs them, the regression reference (the values
# that moved are printed first: log the reason in tests/regression/README.md), the README's
# per-level table (docs/level-table.json) and the axle's loss-map figure (its table is printed for
# docs/axle.md). Niced; the maps take about 3 min each with two workers.
#
#   scripts/regenerate.sh                  # all of it
#   scripts/regenerate.sh maps regress     # only the named parts (maps, regress, levels, lossmap)
#
# The printed tables go to build/regenerate/; what the docs quote from them is updated by hand.
set -euo pipefail
cd "$(dirname "$0")/.."
parts=("$@")
[ ${#parts[@]} -gt 0 ] || parts=(maps regress levels lossmap)
out=build/regenerate
mkdir -p "$out"
py=.venv/bin/python
run() { echo "regenerate: $*" >&2; nice -n 10 "$@"; }

run cmake --build build -j2 >/dev/null
for part in "${parts[@]}"; do
  case $part in
    maps)
      run .venv/bin/hypoid effmap --all --out-dir resources/maps --workers 2
      run cmake --build build -j2 >/dev/null ;; # the FMU packs the new maps
    regress)
      run .venv/bin/hypoid regress >"$out/regress-before.txt" || true # exit 1: values moved
      run .venv/bin/hypoid regress --update >"$out/regress-update.txt" ;;
    levels)
      run "$py" bench/level_table.py >"$out/level-table.txt" ;;
    lossmap)
      run "$py" tools/axle_loss_map.py >"$out/axle-loss-map.md" ;;
    *)
      echo "regenerate: unknown part '$part' (maps, regress, levels, lossmap)" >&2
      exit 2 ;;
  esac
done
echo "regenerate: done; tables in $out/" >&2
