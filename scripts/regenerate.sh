#!/usr/bin/env bash
# Regenerates, in one command, the data that depend on the full model's default results, after a
# deliberate change of the defaults (friction, tooth data, contact, kinematics): the six built-in
# efficiency maps (resources/maps), the FMU that packs them, the regression reference (the values
# that moved are printed first: log the reason in docs/decisions.md) with the FMI 3.0 FMU's
# reference results (extra/org.fmi-standard.fmi-ls-ref/, tools/fmi_ls_ref.py), and the records
# that depend on them (docs/records/: the level table and the axle's loss map; `hypoid records
# --list` names the others, each remade by `hypoid records --measure NAME`). Niced; the maps
# take about 8 min each with two workers (their speeds banded through the mesh resonances).
#
#   scripts/regenerate.sh                  # all of it
#   scripts/regenerate.sh maps regress     # only the named parts (maps, regress, levels, lossmap)
#
# The regression's printed tables go to build/regenerate/.
set -euo pipefail
cd "$(dirname "$0")/.."
parts=("$@")
[ ${#parts[@]} -gt 0 ] || parts=(maps regress levels lossmap)
out=build/regenerate
mkdir -p "$out"
run() { echo "regenerate: $*" >&2; nice -n 10 "$@"; }

run cmake --build build -j2 >/dev/null
for part in "${parts[@]}"; do
  case $part in
    maps)
      run .venv/bin/hypoid effmap --all --out-dir resources/maps --workers 2
      run cmake --build build -j2 >/dev/null ;; # the FMU packs the new maps
    regress)
      run .venv/bin/hypoid regress >"$out/regress-before.txt" || true # exit 1: values moved
      run .venv/bin/hypoid regress --update >"$out/regress-update.txt"
      run .venv/bin/python tools/fmi_ls_ref.py
      run cmake --build build -j2 >/dev/null ;; # the FMI 3.0 FMU packs them
    levels)
      run .venv/bin/hypoid records --measure level-table ;;
    lossmap)
      run .venv/bin/hypoid records --measure axle-loss-map ;;
    *)
      echo "regenerate: unknown part '$part' (maps, regress, levels, lossmap)" >&2
      exit 2 ;;
  esac
done
echo "regenerate: done; the regression tables in $out/, the records in docs/records/" >&2
