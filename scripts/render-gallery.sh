#!/usr/bin/env bash
# Renders the gallery: every image of README.md's gallery into docs/images/, and
# docs/images/gallery.md, one caption line per image (scene file, integrator, samples per
# pixel, render time) for the README.
#
# Usage, from the repository root:
#   scripts/render-gallery.sh              # every image
#   scripts/render-gallery.sh groom_brown  # only the images whose name contains a word
# Environment: TRESS (the tress binary; default: built with cargo --release),
# THREADS (worker threads; default every core), SPP_SCALE (a factor on every image's
# samples per pixel, e.g. 0.25 for a quick look; default 1).
#
# The groom's assets and the sky map are made by scripts/make_groom.py and
# scripts/make_sky_hdri.py; both are committed, so this script only renders.
set -euo pipefail
cd "$(dirname "$0")/.."

if [[ -z "${TRESS:-}" ]]; then
    cargo build --release --quiet --bin tress
    TRESS=target/release/tress
fi
THREADS=${THREADS:-0}
SPP_SCALE=${SPP_SCALE:-1}
FILTER=${1:-}
OUT=docs/images
CAPTIONS=$OUT/gallery.md

# name | scene file | integrator | spp | resolution | extra options
GALLERY=(
    "groom_brown|scenes/groom_brown.toml|path|48|1280x720|"
    "groom_blonde|scenes/groom_blonde.toml|path|48|1280x720|"
    "groom_red|scenes/groom_red.toml|path|48|1280x720|"
    "rings_of_fur|scenes/rings_of_fur.toml|direct|16|1280x720|"
    "furry_pillow|scenes/furry_pillow.toml|direct|16|1280x720|"
    "hair_system_head|scenes/hair_system_head.toml|direct|16|640x480|"
    "hair_system_torus|scenes/hair_system_torus.toml|direct|16|640x480|"
    "gi_hair_mirror_fur|scenes/gi_hair_mirror_fur.toml|final-gather|16|640x480|"
    "lod_field_lod|scenes/lod_field.toml|direct|16|640x360|"
    "lod_field_nolod|scenes/lod_field.toml|direct|16|640x360|--no-lod"
    "demo||direct|16|640x480|"
)

[[ -f $CAPTIONS ]] || printf '# Gallery captions (written by scripts/render-gallery.sh)\n\n' >"$CAPTIONS"

for entry in "${GALLERY[@]}"; do
    IFS='|' read -r name scene integrator spp resolution extra <<<"$entry"
    if [[ -n $FILTER && $name != *"$FILTER"* ]]; then
        continue
    fi
    spp=$(awk -v s="$spp" -v f="$SPP_SCALE" 'BEGIN { n = int(s * f + 0.5); print (n < 1 ? 1 : n) }')
    log=$(mktemp)
    start=$(date +%s.%N)
    # shellcheck disable=SC2086 # `extra` holds separate options
    "$TRESS" render $scene --integrator "$integrator" --spp "$spp" --resolution "$resolution" \
        --threads "$THREADS" --force $extra -o "$OUT/$name.png" 2>"$log" || { cat "$log"; exit 1; }
    end=$(date +%s.%N)
    seconds=$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.0f", b - a }')
    time=$(awk -v s="$seconds" 'BEGIN { if (s >= 60) printf "%d min %d s", s / 60, s % 60; else printf "%d s", s }')
    threads=$(grep -o '[0-9]* threads' "$log" | head -1 || true)
    # The render's own summary: its render time and the scene build before it.
    render_s=$(awk '/^render / { printf "%.0f", $2 }' "$log")
    build_s=$(awk '/^scene build / { printf "%.0f", $3 }' "$log")
    rm -f "$log"
    caption="\`${scene:-built-in demo}\`${extra:+ ($extra)}, \`$integrator\`, $spp spp, $resolution, $time in all (${render_s:-?} s render after a ${build_s:-?} s scene build; ${threads:-all cores})"
    # One line per image: replace this image's line, keep the others.
    grep -v "^- $name: " "$CAPTIONS" >"$CAPTIONS.tmp" || true
    printf -- '- %s: %s\n' "$name" "$caption" >>"$CAPTIONS.tmp"
    mv "$CAPTIONS.tmp" "$CAPTIONS"
    echo "$name: $caption"
done
