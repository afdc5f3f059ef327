#!/bin/sh
# Rebuilds the generator and rewrites the fixtures it owns in tests/fixtures/:
# orient2d.txt, orient3d.txt, plane_side.txt, incircle.txt, insphere.txt,
# orient3d_lpi.txt, orient3d_tpi.txt, orient2d_ssi.txt, less_on_axis_lpi.txt,
# one nearest-<set>.txt per point set, and ray_sphere.txt, ray_cylinder.txt,
# ray_cone.txt, ray_quadric.txt, ray_triangle.txt, one ray_mesh-<mesh>.txt
# per mesh, and one mesh_side-<mesh>.txt and mesh_closest-<mesh>.txt per
# closed mesh (other files there are left alone). The output is deterministic:
# rerunning gives byte-identical files.
#
#   tools/cgal-fixtures/regenerate.sh          rewrite tests/fixtures/
#   tools/cgal-fixtures/regenerate.sh --check  fail if tests/fixtures/ is stale
set -eu
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
dest="$root/tests/fixtures"

"$here/build.sh"

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$here/build/generate" "$tmp"

if [ "${1:-}" = "--check" ]; then
    status=0
    for f in "$tmp"/*.txt; do
        name=$(basename "$f")
        if [ ! -f "$dest/$name" ]; then
            echo "missing: tests/fixtures/$name" >&2
            status=1
        elif ! cmp -s "$f" "$dest/$name"; then
            echo "stale: tests/fixtures/$name" >&2
            status=1
        fi
    done
    # A nearest set or ray file the generator no longer writes (renamed or
    # removed).
    for f in "$dest"/nearest-*.txt "$dest"/ray_*.txt "$dest"/mesh_*.txt; do
        [ -f "$f" ] || continue
        if [ ! -f "$tmp/$(basename "$f")" ]; then
            echo "not generated (remove it?): tests/fixtures/$(basename "$f")" >&2
            status=1
        fi
    done
    [ $status -eq 0 ] && echo "up to date: $(ls "$tmp" | wc -l) files in tests/fixtures/" >&2
    exit $status
fi

mkdir -p "$dest"
for f in "$tmp"/*.txt; do
    cp "$f" "$dest/$(basename "$f")"
done
echo "wrote $(ls "$tmp" | wc -l) files to $dest" >&2
for f in "$dest"/nearest-*.txt "$dest"/ray_*.txt; do
    [ -f "$f" ] || continue
    [ -f "$tmp/$(basename "$f")" ] || echo "warning: tests/fixtures/$(basename "$f") is not generated any more" >&2
done
