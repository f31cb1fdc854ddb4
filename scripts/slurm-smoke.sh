#!/usr/bin/env bash
# Slurm smoke test: a real single-node Slurm cluster on localhost renders the tiles of one
# frame as a job array, merges them in a job that depends on the array, and the merged image
# must equal the single-process render byte for byte.
#
# Needs root (it installs Debian's slurm-wlm and munge with apt-get if they are missing).
# Everything it starts (munged, slurmctld, slurmd) lives in a temporary directory with its
# own key, socket, ports and state, and is stopped by process id at the end.
#
#   scripts/slurm-smoke.sh            # uses target/release/tress, building it if needed
#   TRESS=/path/to/tress TILES=6 scripts/slurm-smoke.sh
set -euo pipefail

ROOT=$(cd "$(dirname "$0")/.." && pwd)
TILES=${TILES:-4}
FRAME=${FRAME:-12}
SCENE="$ROOT/scenes/animated.toml"
RENDER_ARGS=(--frame "$FRAME" --resolution 160x120 --spp 4 --quiet)
WORK=$(mktemp -d /tmp/tress-slurm.XXXXXX)
chmod 755 "$WORK"
PIDS=()

log() { echo "[slurm-smoke] $*"; }

cleanup() {
    for pid in "${PIDS[@]}"; do
        kill "$pid" 2>/dev/null || true
    done
    for pid in "${PIDS[@]}"; do
        while kill -0 "$pid" 2>/dev/null; do sleep 0.1; done
    done
    if [ "${KEEP:-0}" != 1 ]; then rm -rf "$WORK"; fi
}
trap cleanup EXIT

if [ -z "${TRESS:-}" ]; then
    TRESS="$ROOT/target/release/tress"
    [ -x "$TRESS" ] || (cd "$ROOT" && cargo build --release)
fi

if ! command -v slurmctld >/dev/null || ! command -v slurmd >/dev/null || ! command -v munged >/dev/null; then
    log "installing slurm-wlm and munge"
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq
    apt-get install -y -qq slurm-wlm munge >/dev/null
fi
log "$(slurmctld -V), $(munged --version 2>&1 | head -1)"

# munge: its own key and socket, so a system munged (if any) is left alone.
mkdir -p "$WORK/munge"
chmod 700 "$WORK/munge"
dd if=/dev/urandom of="$WORK/munge/munge.key" bs=1024 count=1 status=none
chmod 400 "$WORK/munge/munge.key"
munged --force --key-file="$WORK/munge/munge.key" --socket="$WORK/munge/munge.sock" \
    --pid-file="$WORK/munge/munged.pid" --log-file="$WORK/munge/munged.log" --seed-file="$WORK/munge/seed"
for _ in $(seq 50); do [ -s "$WORK/munge/munged.pid" ] && break; sleep 0.1; done
PIDS+=("$(cat "$WORK/munge/munged.pid")")

# Slurm: one node (this machine) in one partition, no accounting, no cgroups.
HOST=$(hostname -s)
CPUS=$(nproc)
MEM=$(( $(awk '/MemTotal/ {print $2}' /proc/meminfo) / 1024 / 2 ))
mkdir -p "$WORK/state" "$WORK/spool" "$WORK/out"
cat > "$WORK/slurm.conf" <<CONF
ClusterName=tress-smoke
SlurmctldHost=$HOST
SlurmctldPort=16817
SlurmdPort=16818
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$WORK/munge/munge.sock
StateSaveLocation=$WORK/state
SlurmdSpoolDir=$WORK/spool
SlurmctldPidFile=$WORK/slurmctld.pid
SlurmdPidFile=$WORK/slurmd.pid
SlurmctldLogFile=$WORK/slurmctld.log
SlurmdLogFile=$WORK/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
SchedulerType=sched/backfill
MpiDefault=none
ReturnToService=2
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
MinJobAge=600
NodeName=$HOST CPUs=$CPUS RealMemory=$MEM State=UNKNOWN
PartitionName=smoke Nodes=$HOST Default=YES MaxTime=INFINITE State=UP
CONF
export SLURM_CONF="$WORK/slurm.conf"
slurmctld -f "$SLURM_CONF" -i
for _ in $(seq 100); do [ -s "$WORK/slurmctld.pid" ] && break; sleep 0.1; done
PIDS+=("$(cat "$WORK/slurmctld.pid")")
slurmd -f "$SLURM_CONF"
for _ in $(seq 100); do [ -s "$WORK/slurmd.pid" ] && break; sleep 0.1; done
PIDS+=("$(cat "$WORK/slurmd.pid")")

log "waiting for node $HOST"
for i in $(seq 120); do
    state=$(sinfo -h -n "$HOST" -o %t 2>/dev/null || true)
    case "$state" in idle*|mix*|alloc*) break ;; esac
    [ "$i" = 120 ] && { log "node never came up (state '$state')"; tail -20 "$WORK/slurmctld.log" "$WORK/slurmd.log"; exit 1; }
    sleep 0.5
done
sinfo

# The tiles of one frame as a job array, and the merge as a job that runs only once every
# array task has succeeded: the job scripts docs/render-farm.md shows.
OUT="$WORK/out"
cat > "$WORK/tiles.sbatch" <<JOB
#!/bin/bash
#SBATCH --job-name=tress-tiles
#SBATCH --array=0-$((TILES - 1))
#SBATCH --cpus-per-task=1
#SBATCH --output=$OUT/tile-%a.log
exec "$TRESS" render "$SCENE" ${RENDER_ARGS[*]} --threads \$SLURM_CPUS_PER_TASK \\
    --tile \$SLURM_ARRAY_TASK_ID/$TILES -o "$OUT/frame$FRAME.tile\$SLURM_ARRAY_TASK_ID.exr"
JOB
cat > "$WORK/merge.sbatch" <<JOB
#!/bin/bash
#SBATCH --job-name=tress-merge
#SBATCH --output=$OUT/merge.log
"$TRESS" merge "$OUT"/frame$FRAME.tile*.exr -o "$OUT/frame$FRAME.exr"
"$TRESS" merge "$OUT"/frame$FRAME.tile*.exr -o "$OUT/frame$FRAME.png"
JOB
log "tile job script:"
cat "$WORK/tiles.sbatch"
TILE_JOB=$(sbatch --parsable "$WORK/tiles.sbatch")
MERGE_JOB=$(sbatch --parsable --dependency=afterok:"$TILE_JOB" "$WORK/merge.sbatch")
log "submitted tile array $TILE_JOB (tasks 0-$((TILES - 1))) and merge job $MERGE_JOB (afterok:$TILE_JOB)"
squeue

job_state() { scontrol show job "$1" 2>/dev/null | grep -o 'JobState=[A-Z_]*' | head -1 | cut -d= -f2; }
for i in $(seq 600); do
    state=$(job_state "$MERGE_JOB")
    case "$state" in
        COMPLETED) break ;;
        FAILED|CANCELLED|TIMEOUT|NODE_FAIL|OUT_OF_MEMORY)
            log "merge job ended $state"; cat "$OUT"/*.log; exit 1 ;;
    esac
    [ "$i" = 600 ] && { log "merge job still $state after 5 minutes"; squeue; exit 1; }
    sleep 0.5
done
for t in $(seq 0 $((TILES - 1))); do
    log "tile task ${TILE_JOB}_$t: $(job_state "${TILE_JOB}_$t"): $(head -1 "$OUT/tile-$t.log")"
done
log "merge job $MERGE_JOB: $(job_state "$MERGE_JOB")"
cat "$OUT/merge.log"

log "single-process render for comparison"
"$TRESS" render "$SCENE" "${RENDER_ARGS[@]}" -o "$WORK/single.exr" 2>/dev/null
"$TRESS" render "$SCENE" "${RENDER_ARGS[@]}" -o "$WORK/single.png" 2>/dev/null
for ext in exr png; do
    if cmp "$WORK/single.$ext" "$OUT/frame$FRAME.$ext"; then
        log "merged frame$FRAME.$ext is byte for byte the single-process render ($(stat -c %s "$WORK/single.$ext") bytes, sha256 $(sha256sum "$WORK/single.$ext" | cut -c1-16))"
    else
        log "MISMATCH: merged frame$FRAME.$ext differs from the single-process render"
        exit 1
    fi
done
log "PASS"
