#!/usr/bin/env bash
# Renders a thumbnail of every fur preset on the unit torus into docs/presets/NAME.png.
# Run from the repository root: bash docs/presets/render.sh [NAME...]
set -euo pipefail
cargo build --release --quiet
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
names=("$@")
if [ ${#names[@]} -eq 0 ]; then
    names=($(ls presets/*.toml | xargs -n1 basename | sed 's/\.toml$//'))
fi
for name in "${names[@]}"; do
    # The skin takes the fur's base colour, as Maya's documentation advises, so gaps
    # between clumps do not show a foreign colour.
    skin=$(sed -n 's/^base_color = //p' "presets/$name.toml")
    cat > "$tmp/$name.toml" <<SCENE
[camera]
eye = [0.0, 1.9, 3.6]
target = [0.0, 0.0, 0.0]
vfov = 36.0

[render]
resolution = [200, 150]
spp = 16

[[light]]
type = "distant"
direction = [0.4, 0.9, 0.6]
irradiance = [3.0, 3.0, 3.0]

[[light]]
type = "environment"
radiance = [0.45, 0.45, 0.5]

[[mesh]]
shape = { type = "torus", major = 1.0, minor = 0.35 }
material = { type = "diffuse", color = $skin }
transform = { rotate = [1.0, 0.0, 0.0, 50.0] }

[[fur]]
mesh = 1
preset = "$name"
seed = 1
SCENE
    ./target/release/tress render "$tmp/$name.toml" -o "docs/presets/$name.png" --force --quiet
    echo "docs/presets/$name.png"
done
