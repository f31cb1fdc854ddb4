#!/usr/bin/env bash
# Renders scenes/hairy_torus_closeup.toml four times, tube shading and the physical hair
# BSDF, blonde and brown, and puts the images in a 2x2 grid:
# docs/images/hair_bsdf_comparison.png (columns: tube, physical; rows: blonde, brown).
# Needs ImageMagick's `montage`. Usage: docs/images/make_hair_bsdf_comparison.sh [ARGS]
# (ARGS go to `tress render`, e.g. --resolution 320x240 --spp 4 for a preview).
set -euo pipefail
cd "$(dirname "$0")/../.."
cargo build --release --quiet
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
variants=(
  "tube_blonde|{ type = \"tube\", diffuse = [0.8, 0.6, 0.35] }"
  "physical_blonde|{ type = \"physical\", eumelanin = 0.3 }"
  "tube_brown|{ type = \"tube\", diffuse = [0.35, 0.2, 0.1] }"
  "physical_brown|{ type = \"physical\", eumelanin = 1.3 }"
)
images=()
for v in "${variants[@]}"; do
  name=${v%%|*}
  # The scene's hair material is the last `material` line; its files are made absolute
  # so that the copy in the temporary directory still finds them.
  sed -e "s|^file = \"|file = \"$PWD/scenes/|" \
      -e "s|^material = { type = \"physical\".*|material = ${v#*|}|" \
      scenes/hairy_torus_closeup.toml > "$tmp/$name.toml"
  echo "$name" >&2
  ./target/release/tress render "$tmp/$name.toml" -o "$tmp/$name.png" --quiet "$@"
  images+=("$tmp/$name.png")
done
montage "${images[@]}" -tile 2x2 -geometry +2+2 -background white docs/images/hair_bsdf_comparison.png
echo "wrote docs/images/hair_bsdf_comparison.png" >&2
