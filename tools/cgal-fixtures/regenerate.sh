#!/bin/sh
# Rebuilds the generator and rewrites the fixtures it owns in tests/fixtures/
# (other files there are left alone). The output is deterministic: rerunning
# gives byte-identical files.
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
        if ! cmp -s "$f" "$dest/$(basename "$f")"; then
            echo "stale: tests/fixtures/$(basename "$f")" >&2
            status=1
        fi
    done
    exit $status
fi

mkdir -p "$dest"
for f in "$tmp"/*.txt; do
    cp "$f" "$dest/$(basename "$f")"
done
echo "wrote $(ls "$tmp" | wc -l) files to $dest" >&2
