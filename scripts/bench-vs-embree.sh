#!/usr/bin/env bash
# Runs tress and the Embree baseline on the same reference scene, in one go, and prints
# one line per figure: NAME tress=X embree=Y ratio=Z (ratio = tress / embree).
#
# Usage: scripts/bench-vs-embree.sh DIR [REPS]
#   DIR   a scene directory written by scripts/gen_scenes.py (scene.json, torus.obj,
#         hairy_torus.hair), e.g. `python3 scripts/gen_scenes.py /tmp/ht720k` (needs numpy).
# Needs Embree 3 (Debian: apt-get install -y libembree-dev); builds bench/embree/bench.
# Throughput is reported by wall clock and by CPU time: on a shared machine the CPU-time
# figures (rays per CPU-second times threads) are the steadier ones.
set -euo pipefail
dir=${1:?usage: scripts/bench-vs-embree.sh DIR [REPS]}
reps=${2:-3}
root=$(cd "$(dirname "$0")/.." && pwd)
[ -x "$root/bench/embree/bench" ] || sh "$root/bench/embree/build.sh" >/dev/null
cargo build --release --quiet --manifest-path "$root/Cargo.toml"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$root/target/release/tress" bench "$dir" --thread-counts 1,2 --reps "$reps" | tee "$out/tress.txt" >&2
"$root/bench/embree/bench" --dir "$dir" --kind round_linear --reps "$reps" --spp 16 --threads 1,2 \
  | tee "$out/embree.txt" >&2

# field VALUE after a word in the RESULT line matching a pattern
pick() { grep -E "$2" "$1" | head -1 | sed -E "s#.*$3 +([0-9.]+).*#\1#"; }
line() { awk -v n="$1" -v t="$2" -v e="$3" 'BEGIN { if (t == "" || e == "" || e + 0 == 0) printf "%s tress=%s embree=%s ratio=n/a\n", n, t, e; else printf "%s tress=%s embree=%s ratio=%.2f\n", n, t, e, t / e }'; }
echo
line build_ms "$(pick "$out/tress.txt" 'RESULT build_ms' 'build_ms median')" "$(pick "$out/embree.txt" 'RESULT build_ms' 'build_ms median')"
line build_cpu_ms "$(pick "$out/tress.txt" 'RESULT build_ms' 'all threads\) median')" "$(pick "$out/embree.txt" 'RESULT build_ms' 'all threads\) median')"
line bytes_per_segment "$(pick "$out/tress.txt" 'RESULT mem' 'total/segment')" "$(pick "$out/embree.txt" 'RESULT mem' 'total/segment')"
line bvh_bytes_per_segment "$(pick "$out/tress.txt" 'RESULT mem' 'bvh/segment')" "$(pick "$out/embree.txt" 'RESULT mem' 'bvh/segment')"
# Single rays against rtcIntersect1 / rtcOccluded1; packets (a pixel's 16 samples) against
# Embree's packets of the same rays: rtcIntersect16 over a pixel's samples, rtcOccluded16
# over 16 consecutive shadow rays.
for t in 1 2; do
  for kind in primary shadow primary-packet shadow-packet; do
    case $kind in
      primary) e='rtcIntersect1 ' ;;
      shadow) e='rtcOccluded1 ' ;;
      primary-packet) e='rtcIntersect16 pixel' ;;
      shadow-packet) e='rtcOccluded16' ;;
    esac
    ek=${kind%-packet}
    line "${kind}_mrays_${t}t" "$(pick "$out/tress.txt" "RESULT threads $t $kind " 'Mrays/s median')" \
      "$(pick "$out/embree.txt" "RESULT threads $t $ek +$e" 'Mrays/s median')"
    line "${kind}_mrays_cpu_${t}t" "$(pick "$out/tress.txt" "RESULT threads $t $kind " 'cpu-time based')" \
      "$(pick "$out/embree.txt" "RESULT threads $t $ek +$e" 'cpu-time based')"
  done
done
