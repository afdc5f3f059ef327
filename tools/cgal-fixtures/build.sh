#!/bin/sh
# Builds the CGAL fixture generator into tools/cgal-fixtures/build/.
# Installs CGAL (header-only; pulls in GMP and MPFR) with apt if missing.
# Each family is its own translation unit (see generate.cpp); a unit is
# recompiled when it or one of the headers is newer than its object.
set -eu
here=$(cd "$(dirname "$0")" && pwd)

"$here/../install-cgal.sh"

mkdir -p "$here/build"
# -frounding-math: CGAL's interval filters switch the rounding mode, which
# the optimizer must not assume is round-to-nearest.
# -ffp-contract=off: no fused multiply-add, so the plain-f64 statistics the
# generator prints are the same on every machine (the fixtures never depend
# on them).
flags="-std=c++17 -O2 -frounding-math -ffp-contract=off -Wall -Wextra"
objects=""
for unit in generate predicates implicit nearest ray_quadrics ray_triangle ray_mesh mesh_points; do
    src="$here/$unit.cpp"
    obj="$here/build/$unit.o"
    stale=0
    [ -f "$obj" ] || stale=1
    for dep in "$src" "$here"/*.h "$here/build.sh"; do
        [ "$dep" -nt "$obj" ] && stale=1
    done
    if [ $stale -eq 1 ]; then
        g++ $flags -c -o "$obj" "$src"
    fi
    objects="$objects $obj"
done
g++ -o "$here/build/generate" $objects -lmpfr -lgmpxx -lgmp
