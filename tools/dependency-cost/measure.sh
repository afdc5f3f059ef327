#!/usr/bin/env bash
# What a user pays to depend on exactray: a new binary crate depending on
# it (by path, as a user's crate would by version), built cold (a fresh
# target directory, registry sources already downloaded) in the release
# and dev profiles, beside the same crate depending on `robust` and on
# `parry3d-f64`. Prints a markdown table: crates compiled and wall seconds.
#
#   tools/dependency-cost/measure.sh            # from the repository root
#
# Timings move with the machine's load: run it alone (it runs one build at
# a time, niced). Needs network access to crates.io for the first fetch.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# name | dependency line
configs=(
  "exactray (default: std, rayon)|exactray = { path = \"$root\" }"
  "exactray, default-features = false|exactray = { path = \"$root\", default-features = false }"
  "exactray + ploc (obvhs)|exactray = { path = \"$root\", features = [\"ploc\"] }"
  "exactray + serde + mint|exactray = { path = \"$root\", features = [\"serde\", \"mint\"] }"
  "robust 1.2|robust = \"1.2\""
  "parry3d-f64 0.31|parry3d-f64 = \"0.31\""
)

echo "| dependency | release: crates | release: s | debug: crates | debug: s |"
echo "|---|---|---|---|---|"
for config in "${configs[@]}"; do
  name="${config%%|*}"
  dep="${config#*|}"
  crate="$work/user"
  rm -rf "$crate"
  mkdir -p "$crate/src"
  printf '[package]\nname = "user"\nversion = "0.0.0"\nedition = "2024"\n\n[dependencies]\n%s\n\n[workspace]\n' "$dep" >"$crate/Cargo.toml"
  echo 'fn main() {}' >"$crate/src/main.rs"
  (cd "$crate" && cargo fetch -q)
  cells=""
  for profile in release dev; do
    rm -rf "$crate/target"
    start=$(date +%s.%N)
    log=$(cd "$crate" && nice cargo build --profile "$profile" 2>&1)
    end=$(date +%s.%N)
    # Every crate compiled, the user's own crate included.
    crates=$(grep -c '^ *Compiling ' <<<"$log" || true)
    seconds=$(python3 -c "print(f'{$end - $start:.1f}')")
    cells="$cells | $crates | $seconds"
  done
  echo "| $name$cells |"
done
