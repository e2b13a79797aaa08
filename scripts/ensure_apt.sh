#!/usr/bin/env bash
# Installs the Debian/Ubuntu packages named on the command line that are not installed yet
# (apt-get, with sudo when not root). Idempotent: does nothing when all are present.
#   ensure_apt.sh [--no-install-recommends] PACKAGE...
# Everything it prints goes to stderr: callers' stdout carries data (paths that scripts/setup.sh
# reads from scripts/win64.sh build), which a progress line must not take the place of.
set -euo pipefail
exec 1>&2
opts=()
if [ "${1:-}" = --no-install-recommends ]; then
  opts+=(--no-install-recommends)
  shift
fi
missing=()
for pkg in "$@"; do
  dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || missing+=("$pkg")
done
[ ${#missing[@]} -eq 0 ] && exit 0
sudo_cmd=""
[ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
echo "ensure_apt: installing ${missing[*]} with apt-get"
$sudo_cmd apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq ${opts[@]+"${opts[@]}"} "${missing[@]}" >/dev/null
