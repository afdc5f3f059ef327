#!/bin/sh
# Builds the CGAL timing program into tools/cgal-timing/build/cgal-timing.
# Installs CGAL (header-only; pulls in GMP and MPFR) with apt if missing.
#
#   tools/cgal-timing/build.sh           the program the README's figures use
#   tools/cgal-timing/build.sh --native  also build/cgal-timing-native, the
#                                        same with -march=native (see README.md)
set -eu
here=$(cd "$(dirname "$0")" && pwd)

"$here/../install-cgal.sh"

mkdir -p "$here/build"
# -O3 -DNDEBUG: what a CMake Release build of a CGAL program uses.
# -frounding-math: CGAL's interval filters switch the rounding mode, which
# the optimizer must not assume is round-to-nearest.
# No -march=native: for the reason, see README.md.
flags="-std=c++17 -O3 -DNDEBUG -frounding-math -Wall -Wextra"
g++ $flags -o "$here/build/cgal-timing" "$here/cgal_timing.cpp" -lmpfr -lgmp
if [ "${1:-}" = "--native" ]; then
    g++ $flags -march=native -o "$here/build/cgal-timing-native" "$here/cgal_timing.cpp" -lmpfr -lgmp
fi
