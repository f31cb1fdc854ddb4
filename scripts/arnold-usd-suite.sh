#!/usr/bin/env bash
# Renders every test of an Arnold-USD checkout's test suite that has a USD layer and a
# reference render, and prints one line per test: name, ok/fail (or unreadable-reference), mean absolute difference
# to Arnold's reference (0-255, scripts/compare_reference.py), the figures docs/interop.md
# quotes. Each test's `data/scene.usda` or `data/test.usda` (else its first .usda) is
# rendered at the reference's size with 16 samples per pixel.
#
# usage: scripts/arnold-usd-suite.sh ARNOLD_USD_CHECKOUT [TRESS [FILE]] > suite.tsv
#   ARNOLD_USD_CHECKOUT  a clone of github.com/Autodesk/arnold-usd (its testsuite/ is read)
#   TRESS                the tress binary (default: target/release/tress)
#   FILE                 render each test's data/FILE instead (e.g. test.ass, the Arnold
#                        scene Arnold rendered the reference from); tests without it are
#                        left out
# Needs python3 with numpy, pillow, tifffile and imagecodecs. Not run by CI.
set -uo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
suite="${1:?usage: $0 ARNOLD_USD_CHECKOUT [TRESS]}/testsuite"
tress="${2:-$here/../target/release/tress}"
file="${3:-}"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
for dir in "$suite"/test_*; do
    ref="$dir/ref/reference.tif"
    [ -f "$ref" ] || continue
    layer=""
    [ -n "$file" ] && { [ -f "$dir/data/$file" ] || continue; layer="$dir/data/$file"; }
    [ -n "$layer" ] || for name in scene.usda test.usda; do
        [ -f "$dir/data/$name" ] && { layer="$dir/data/$name"; break; }
    done
    [ -n "$layer" ] || layer="$(ls "$dir"/data/*.usda 2>/dev/null | head -n 1)"
    [ -n "$layer" ] || continue
    test="$(basename "$dir")"
    size="$(python3 -c 'import sys, tifffile; s = tifffile.imread(sys.argv[1]).shape; print(f"{s[1]}x{s[0]}")' "$ref" 2>/dev/null)"
    if [ -z "$size" ]; then
        printf '%s\tunreadable-reference\t\n' "$test"
    elif timeout 120 "$tress" render "$layer" -r "$size" -s 16 -f -o "$out/$test.png" >/dev/null 2>&1; then
        mae="$(python3 "$here/compare_reference.py" "$ref" "$out/$test.png" | sed 's/^mae=\([0-9.]*\).*/\1/')"
        printf '%s\tok\t%s\n' "$test" "$mae"
    else
        printf '%s\tfail\t\n' "$test"
    fi
done
