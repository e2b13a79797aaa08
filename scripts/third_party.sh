#!/usr/bin/env bash
# Fetches the third-party sources that the build compiles but the repository never holds, from
# Debian's source packages, into build/third_party/src/ (cached: nothing is fetched twice):
#   musl     1.2.3   (MIT)  - its portable C math (src/math) goes into the linux64 and win64
#                             binaries, so that both compute the same bits (docs/portability.md)
#   sundials 6.4.1   (BSD)  - CVODE, cross-compiled for the win64 binary (scripts/win64.sh)
# apt-get source needs a deb-src entry: this script adds one (the same mirrors as the machine's
# own Debian entries), fetches, and removes it again, also when interrupted.
#
#   scripts/third_party.sh      prints "musl=DIR" and "sundials=DIR" for what is available
# Where apt-get or Debian's sources are not available it says so and prints nothing; the build
# then uses the system libm and builds no win64 binary.
set -euo pipefail
cd "$(dirname "$0")/.."
src=build/third_party/src
mkdir -p "$src"
packages=(musl sundials)
declare -A version=([musl]=1.2.3 [sundials]=6.4.1)

have() { compgen -G "$src/$1-${version[$1]}*/" >/dev/null; }
missing=()
for p in "${packages[@]}"; do have "$p" || missing+=("$p"); done

if [ ${#missing[@]} -gt 0 ]; then
  if ! command -v apt-get >/dev/null || ! command -v dpkg-source >/dev/null \
     || [ ! -f /etc/apt/sources.list.d/debian.sources ]; then
    echo "third_party: SKIPPED fetching ${missing[*]}: needs apt-get, dpkg-source and Debian's" \
         "/etc/apt/sources.list.d/debian.sources" >&2
  else
    sudo_cmd=""
    [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
    # one fetch at a time on this machine: the deb-src entry is shared, and a second checkout's
    # cleanup would remove it under the first one's download
    exec 9>"${TMPDIR:-/tmp}/hypoid-third-party.lock"
    flock 9
    entry=/etc/apt/sources.list.d/zz-hypoid-deb-src.sources
    apt_quiet() { $sudo_cmd apt-get -o DPkg::Lock::Timeout=300 -qq "$@" >/dev/null; }
    cleanup() { $sudo_cmd rm -f "$entry"; apt_quiet update || true; }
    trap cleanup EXIT
    echo "third_party: fetching the Debian source packages of ${missing[*]} (deb-src entry added" \
         "for the download, removed afterwards)" >&2
    # the deb entries of the main archive (not -security), turned into deb-src
    awk 'BEGIN { RS = ""; ORS = "\n\n" } /URIs:[^\n]*\/debian\/?\n/ {
           sub(/Types: deb/, "Types: deb-src"); print }' /etc/apt/sources.list.d/debian.sources \
      | $sudo_cmd tee "$entry" >/dev/null
    apt_quiet update
    work=$(mktemp -d "$src/fetch.XXXXXX")
    (cd "$work" && apt-get -qq -o APT::Sandbox::User=root source --download-only "${missing[@]}" \
       >/dev/null)
    for p in "${missing[@]}"; do
      dsc=$(ls "$work/${p}_${version[$p]}"*.dsc)
      dpkg-source --no-check -x "$dsc" "$src/$p-${version[$p]}" >/dev/null  # Debian's patches applied
    done
    rm -rf "$work" "$src"/*.orig.tar.*
    cleanup
    trap - EXIT
  fi
fi
for p in "${packages[@]}"; do
  if have "$p"; then echo "$p=$(cd "$src/$p-${version[$p]}" && pwd)"; fi
done
