#!/usr/bin/env bash
# Time against noise: renders a reference scene with tress and Mitsuba 3 at several sample
# counts and prints, per image, its render time and its RMS error against a converged
# reference, so the two can be compared at equal noise rather than at equal spp (the
# end-to-end figure of scripts/compare-end-to-end.sh). One line per image:
#   NAME spp=N render_s=T rmse=R
#
# Usage: scripts/compare-noise.sh DIR [REF_SPP] [MITSUBA_SPP...]
#   DIR          a scene directory of scripts/gen_scenes.py (see compare-end-to-end.sh)
#   REF_SPP      samples of the reference (default 256), rendered by tress with seed 7, so
#                its noise is independent of the seed-0 images measured against it
#   MITSUBA_SPP  sample counts of Mitsuba's images (default: the scene's, 3 and 4 times it)
# tress renders at the scene's spp, half and a quarter of it. Mitsuba renders with its
# `independent` sampler (compare-end-to-end.sh's) and its `multijitter` sampler (the least
# noisy of its samplers on the hairy torus). A Mitsuba reference at REF_SPP is rendered too,
# and its distance to tress's printed (`reference_gap`): the two renderers converge to the
# same image when that is about the Mitsuba reference's own noise.
# Needs what compare-end-to-end.sh needs (mitsuba, numpy, a libLLVM for Dr.Jit).
set -euo pipefail
dir=${1:?usage: scripts/compare-noise.sh DIR [REF_SPP] [MITSUBA_SPP...]}
ref_spp=${2:-256}
shift $(($# < 2 ? $# : 2))
root=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-python3}
if [ -z "${DRJIT_LIBLLVM_PATH:-}" ]; then
  llvm=$(ls /usr/lib/*/libLLVM*.so* 2>/dev/null | sort -V | tail -1 || true)
  [ -n "$llvm" ] && export DRJIT_LIBLLVM_PATH=$llvm
fi
spp=$("$py" -c 'import json, sys; print(json.load(open(sys.argv[1]))["film"]["spp"])' "$dir/scene.json")
mitsuba_spp=("$@")
[ ${#mitsuba_spp[@]} -gt 0 ] || mitsuba_spp=("$spp" $((3 * spp)) $((4 * spp)))
cargo build --release --quiet --manifest-path "$root/Cargo.toml"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

tress() { "$root/target/release/tress" render "$dir" --force "$@"; }
mitsuba() { "$py" "$root/scripts/mitsuba_reference.py" "$dir" "$@"; }
seconds() { sed -nE 's/^(mitsuba )?render +([0-9.]+) s.*/\2/p' "$1"; }
# logged NAME CMD...: runs CMD with its output in $out/NAME.log, shown if it fails.
logged() {
  local name=$1
  shift
  "$@" >"$out/$name.log" 2>&1 || { echo "$name failed:" >&2; tail -20 "$out/$name.log" >&2; return 1; }
}

logged reference tress --spp "$ref_spp" --seed 7 -o "$out/reference.exr"
logged mitsuba-reference mitsuba "$out/mitsuba-reference.exr" --spp "$ref_spp" --seed 7
names=()
for n in "$spp" $((spp / 2)) $((spp / 4)); do
  [ "$n" -ge 1 ] || continue
  logged "tress-$n" tress --spp "$n" -o "$out/tress-$n.exr"
  names+=("tress-$n")
done
for sampler in independent multijitter; do
  for n in "${mitsuba_spp[@]}"; do
    logged "mitsuba-$sampler-$n" mitsuba "$out/mitsuba-$sampler-$n.exr" --spp "$n" --sampler "$sampler"
    names+=("mitsuba-$sampler-$n")
  done
done

# One RMSE per line, in the order of the images given: the Mitsuba reference, then `names`.
images=("$out/mitsuba-reference.exr")
for name in "${names[@]}"; do images+=("$out/$name.exr"); done
mapfile -t rmse < <("$py" "$root/scripts/rmse.py" "$out/reference.exr" "${images[@]}" | sed -E 's/.* rmse=//')
echo
echo "reference_gap spp=$ref_spp rmse=${rmse[0]}"
for i in "${!names[@]}"; do
  name=${names[$i]}
  echo "${name%-*} spp=${name##*-} render_s=$(seconds "$out/$name.log") rmse=${rmse[$((i + 1))]}"
done
