#!/bin/sh
# Builds the CGAL fixture generator into tools/cgal-fixtures/build/.
# Installs CGAL (header-only; pulls in GMP and MPFR) with apt if missing.
set -eu
here=$(cd "$(dirname "$0")" && pwd)

if [ ! -f /usr/include/CGAL/version.h ] || ! command -v g++ >/dev/null 2>&1; then
    sudo_cmd=""
    [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
    $sudo_cmd apt-get update
    $sudo_cmd apt-get install -y g++ libcgal-dev libgmp-dev libmpfr-dev
fi

mkdir -p "$here/build"
# -frounding-math: CGAL's interval filters switch the rounding mode, which
# the optimizer must not assume is round-to-nearest.
# -ffp-contract=off: no fused multiply-add, so the plain-f64 statistics the
# generator prints are the same on every machine (the fixtures never depend
# on them).
g++ -std=c++17 -O2 -frounding-math -ffp-contract=off -Wall -Wextra \
    -o "$here/build/generate" "$here/generate.cpp" -lmpfr -lgmpxx -lgmp
