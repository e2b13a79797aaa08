#!/usr/bin/env bash
# SUNDIALS 6.4.1 (CVODE, ARKODE and what they need) as static libraries built from Debian's
# source package (scripts/third_party.sh), once, with -O3 -ffp-contract=off (double, 64-bit
# index, position-independent; -O3 vectorises the vector operations' loops, element by element,
# so the results stay those of -O2 bit for bit, and the full model runs 10 % faster):
#
#   scripts/sundials.sh SRC PREFIX [CMAKE_ARGS...]   builds into PREFIX unless it is there,
#                                                     built with these flags (PREFIX/hg-cflags);
#                                                     prints PREFIX on its last line
#
# setup.sh builds the linux64 one (build/third_party/sundials-linux64: Debian's libsundials-dev
# archives are compiled without optimisation, which made SUNDIALS's share of a step 2-3 times
# dearer, docs/portability.md), win64.sh the Windows one with its toolchain file.
set -euo pipefail
src=${1:?usage: scripts/sundials.sh SRC PREFIX [CMAKE_ARGS...]}
prefix=${2:?usage: scripts/sundials.sh SRC PREFIX [CMAKE_ARGS...]}
shift 2
cflags="-O3 -ffp-contract=off"
built=$(cat "$prefix/hg-cflags" 2>/dev/null || true)
if [ ! -f "$prefix/lib/libsundials_arkode.a" ] || [ "$built" != "$cflags" ]; then
  work="$prefix-build" log="$prefix.log"
  echo "sundials: building SUNDIALS (static) into $prefix" >&2
  rm -rf "$work" "$prefix"
  cmake -S "$src" -B "$work" "$@" \
    -DCMAKE_INSTALL_PREFIX="$prefix" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_C_FLAGS_RELEASE="$cflags" -DCMAKE_POSITION_INDEPENDENT_CODE=ON \
    -DBUILD_SHARED_LIBS=OFF -DBUILD_STATIC_LIBS=ON -DBUILD_ARKODE=ON -DBUILD_CVODE=ON \
    -DBUILD_CVODES=OFF -DBUILD_IDA=OFF -DBUILD_IDAS=OFF -DBUILD_KINSOL=OFF \
    -DBUILD_FORTRAN_MODULE_INTERFACE=OFF -DBUILD_BENCHMARKS=OFF -DEXAMPLES_ENABLE_C=OFF \
    -DEXAMPLES_ENABLE_CXX=OFF -DEXAMPLES_INSTALL=OFF -DENABLE_MPI=OFF -DENABLE_OPENMP=OFF \
    -DENABLE_PTHREAD=OFF -DENABLE_LAPACK=OFF -DENABLE_KLU=OFF -DSUNDIALS_PRECISION=double \
    -DSUNDIALS_INDEX_SIZE=64 >"$log" 2>&1 \
    && cmake --build "$work" -j"$(nproc)" >>"$log" 2>&1 \
    && cmake --install "$work" >>"$log" 2>&1 \
    || { tail -30 "$log" >&2; exit 1; }
  echo "$cflags" >"$prefix/hg-cflags"
  rm -rf "$work"
fi
echo "$prefix"
