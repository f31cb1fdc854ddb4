#!/usr/bin/env bash
# Renders the same reference scene with tress, Mitsuba 3 and Blender Cycles (640x480,
# 16 spp, direct lighting, every core), one after the other, REPS rounds, and prints one
# line per figure: NAME tress=X other=Y ratio=Z (ratio = tress / other; the target
# is a ratio of at most 0.5 against the faster peer).
#
# Usage: scripts/compare-end-to-end.sh DIR [REPS]
#   DIR   a scene directory written by scripts/gen_scenes.py (scene.json, torus.obj,
#         hairy_torus.hair, hairy_torus.txt), e.g. `python3 scripts/gen_scenes.py /tmp/ht720k`.
# Needs: pip install mitsuba bpy numpy; a libLLVM that Dr.Jit's LLVM backend can use
# (LLVM 15 fails to select `fminimum`: apt-get install -y libllvm19; the newest
# /usr/lib/*/libLLVM* is passed as DRJIT_LIBLLVM_PATH unless it is set).
#
# Figures, per renderer the median over the rounds (the lower middle one for an even count):
#   process_wall_s  the whole process: start-up, reading the files, BVH build, render,
#                   writing the image (Mitsuba's includes a 1-spp warm-up render that
#                   JIT-compiles its kernels)
#   process_cpu_s   user + system CPU time of the whole process: steadier than wall time
#                   on a shared machine
#   render_s        each renderer's own render time: tress without loading and BVH build;
#                   Mitsuba without loading and JIT warm-up; Cycles with its scene sync
#                   and BVH build (Blender does not report them apart)
set -euo pipefail
dir=${1:?usage: scripts/compare-end-to-end.sh DIR [REPS]}
reps=${2:-1}
root=$(cd "$(dirname "$0")/.." && pwd)
py=${PYTHON:-python3}
if [ -z "${DRJIT_LIBLLVM_PATH:-}" ]; then
  llvm=$(ls /usr/lib/*/libLLVM*.so* 2>/dev/null | sort -V | tail -1 || true)
  [ -n "$llvm" ] && export DRJIT_LIBLLVM_PATH=$llvm
fi
cargo build --release --quiet --manifest-path "$root/Cargo.toml"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

# run NAME REP CMD...: runs CMD under /usr/bin/time, keeping its output for the figures.
run() {
  local name=$1 rep=$2
  shift 2
  /usr/bin/time -f "TIME wall %e cpu %U %S" -o "$out/$name.$rep.time" "$@" >"$out/$name.$rep.log" 2>&1 || {
    echo "$name failed:" >&2
    tail -20 "$out/$name.$rep.log" >&2
    return 1
  }
  echo "$name round $rep: $(awk '{printf "wall %s s, cpu %.2f s", $3, $5 + $6}' "$out/$name.$rep.time")" >&2
}
for rep in $(seq 1 "$reps"); do
  run tress "$rep" "$root/target/release/tress" render "$dir" -o "$out/tress.exr" --force
  run mitsuba "$rep" "$py" "$root/scripts/mitsuba_reference.py" "$dir" "$out/mitsuba.exr"
  run cycles "$rep" "$py" "$root/scripts/cycles_reference.py" "$dir" "$out/cycles.exr"
done

# median NAME FIELD: the median over the rounds of a figure of one renderer.
median() {
  local name=$1 field=$2
  for rep in $(seq 1 "$reps"); do
    case $field in
      wall) awk '{print $3}' "$out/$name.$rep.time" ;;
      cpu) awk '{print $5 + $6}' "$out/$name.$rep.time" ;;
      render)
        case $name in
          tress) sed -nE 's/^render +([0-9.]+) s.*/\1/p' "$out/$name.$rep.log" ;;
          *) sed -nE "s/^$name render ([0-9.]+) s.*/\1/p" "$out/$name.$rep.log" ;;
        esac ;;
    esac
  done | sort -g | awk '{v[NR] = $1} END {print v[int((NR + 1) / 2)]}'
}
line() { awk -v n="$1" -v o="$2" -v t="$3" -v e="$4" 'BEGIN { printf "%s tress=%s %s=%s ratio=%.2f\n", n, t, o, e, t / e }'; }
declare -A label=([wall]=process_wall_s [cpu]=process_cpu_s [render]=render_s)
echo
for field in wall cpu render; do
  t=$(median tress $field)
  m=$(median mitsuba $field)
  c=$(median cycles $field)
  line "${label[$field]}" mitsuba "$t" "$m"
  line "${label[$field]}" cycles "$t" "$c"
  line "${label[$field]}_vs_faster" faster "$t" "$(awk -v a="$m" -v b="$c" 'BEGIN { print (a < b ? a : b) }')"
done
