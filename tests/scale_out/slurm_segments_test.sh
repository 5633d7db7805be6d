#!/usr/bin/env bash
# A single-node Slurm cluster started by hand under a temporary directory
# (munged, slurmctld and slurmd in the foreground, no systemd, loopback only,
# no accounting): a 3-task job array renders the segments with --segment auto,
# a job that depends on it (afterok) joins them with vibra concat, and the
# result decodes to exactly the one-pass render's frames. Every daemon started
# here is stopped on every way out.
# First one task fails: the concat job must wait for ever
# (DependencyNeverSatisfied); it is cancelled, the array resubmitted, the
# finished segments skip themselves (--skip-existing), and a new concat job
# joins them: the recovery docs/scale-out.md describes.
#   tests/scale_out/slurm_segments_test.sh path/to/vibra
set -euo pipefail
VIBRA=$(realpath "$1")
source "$(dirname "$0")/common.sh"
for tool in munged slurmctld slurmd sbatch scontrol sinfo; do
  command -v "$tool" >/dev/null ||
    missing "$tool is not installed: install the Debian packages slurm-wlm and munge (scripts/setup does)"
done
[ "$(id -u)" -eq 0 ] || missing "starting slurmd needs root: run the suite as root (CI does)"
WORK=$(mktemp -d /tmp/vibra_slurm.XXXXXX)  # /tmp: munged's socket path must stay short
chmod 711 "$WORK"  # munged wants its socket's directories searchable by all
DAEMONS=()
stop_daemons() {
  local pid
  for pid in "${DAEMONS[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${DAEMONS[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
  done
  if [ -n "${KEEP_LOGS:-}" ]; then echo "logs kept in $WORK"; else rm -rf "$WORK"; fi
}
trap stop_daemons EXIT
trap 'exit 1' INT TERM
show_logs() { tail -n 20 "$WORK"/log/* >&2 || true; }

# MUNGE: its own key, socket, pid, log and seed files.
mkdir -m 711 "$WORK/munge"
mkdir "$WORK/log" "$WORK/state" "$WORK/spool" "$WORK/parts"
head -c 1024 /dev/urandom >"$WORK/munge/munge.key"
chmod 400 "$WORK/munge/munge.key"
munged --foreground --key-file="$WORK/munge/munge.key" --socket="$WORK/munge/socket" \
  --pid-file="$WORK/munge/munged.pid" --log-file="$WORK/log/munged.log" --seed-file="$WORK/munge/seed" \
  >"$WORK/log/munged.out" 2>&1 &
DAEMONS+=($!)

# Two free TCP ports on loopback for slurmctld and slurmd.
free_port() {
  local port
  while :; do
    port=$((20000 + RANDOM % 40000))
    ss -Hltn "sport = :$port" 2>/dev/null | grep -q . || { echo "$port"; return; }
  done
}
CTLD_PORT=$(free_port)
SLURMD_PORT=$(free_port)
[ "$CTLD_PORT" != "$SLURMD_PORT" ] || SLURMD_PORT=$((CTLD_PORT + 1))
NODE=$(hostname -s)
export SLURM_CONF="$WORK/slurm.conf"
cat >"$SLURM_CONF" <<CONF
ClusterName=vibratest
SlurmctldHost=$NODE(127.0.0.1)
SlurmctldPort=$CTLD_PORT
SlurmdPort=$SLURMD_PORT
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$WORK/munge/socket
StateSaveLocation=$WORK/state
SlurmdSpoolDir=$WORK/spool
SlurmctldPidFile=$WORK/slurmctld.pid
SlurmdPidFile=$WORK/slurmd.pid
SlurmctldLogFile=$WORK/log/slurmctld.log
SlurmdLogFile=$WORK/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MpiDefault=none
MailProg=/bin/true
ReturnToService=2
NodeName=$NODE NodeAddr=127.0.0.1 CPUs=2 State=UNKNOWN
PartitionName=test Nodes=$NODE Default=YES MaxTime=INFINITE State=UP
CONF
# slurmd reads cgroup.conf beside slurm.conf even when no plugin uses cgroups.
printf 'CgroupPlugin=cgroup/v1\nCgroupAutomount=no\n' >"$WORK/cgroup.conf"

# Wait until the munge socket answers, then start Slurm.
for _ in $(seq 100); do [ -S "$WORK/munge/socket" ] && break; sleep 0.1; done
[ -S "$WORK/munge/socket" ] || { show_logs; fail "munged did not start"; }
slurmctld -D -f "$SLURM_CONF" >"$WORK/log/slurmctld.out" 2>&1 &
DAEMONS+=($!)
slurmd -D -f "$SLURM_CONF" >"$WORK/log/slurmd.out" 2>&1 &
DAEMONS+=($!)
for _ in $(seq 120); do
  [ "$(sinfo -h -n "$NODE" -o %t 2>/dev/null)" = idle ] && break
  sleep 0.5
done
[ "$(sinfo -h -n "$NODE" -o %t 2>/dev/null)" = idle ] || { show_logs; fail "the node did not become idle"; }
echo "ok: a one-node Slurm cluster is up ($NODE, ports $CTLD_PORT and $SLURMD_PORT)"

# The reference: the whole render in one process.
"$VIBRA" render "${RENDER_ARGS[@]}" -q -o "$WORK/whole.mp4"

# Three array tasks render their segments; the concat job waits for all of
# them. While the file "broken" exists, task 1 fails.
cat >"$WORK/render.sbatch" <<JOB
#!/bin/sh
if [ "\$SLURM_ARRAY_TASK_ID" = 1 ] && [ -e "$WORK/broken" ]; then echo "task 1 breaks"; exit 1; fi
exec "$VIBRA" render ${RENDER_ARGS[*]} --segment auto --skip-existing -o "$WORK/parts/lecture.mp4"
JOB
submit() {  # ROUND: the array, then the concat job that depends on it
  ARRAY=$(sbatch --parsable --array=0-2 --chdir="$WORK" --output="$WORK/log/render_$1_%a.out" "$WORK/render.sbatch")
  CONCAT=$(sbatch --parsable --dependency=afterok:"$ARRAY" --chdir="$WORK" --output="$WORK/log/concat_$1.out" \
    --wrap "exec \"$VIBRA\" concat \"$WORK\"/parts/lecture.seg-*-of-3.mp4 -o \"$WORK/lecture.mp4\"")
  echo "ok: round $1: submitted array job $ARRAY and concat job $CONCAT"
}
job() { scontrol show job "$1" 2>/dev/null; }
state() { job "$1" | sed -n 's/.*JobState=\([A-Z_]*\).*/\1/p' | sort -u | tr '\n' ' '; }
# wait_for JOB PATTERN: until the job's record (all array tasks) matches; 120 s at most.
wait_for() {
  for _ in $(seq 240); do
    job "$1" | grep -Eq "$2" && return 0
    sleep 0.5
  done
  show_logs
  fail "job $1 did not reach '$2' in 120 s: $(state "$1")"
}

touch "$WORK/broken"
submit 1
wait_for "$CONCAT" "Reason=DependencyNeverSatisfied"
[ "$(state "$ARRAY")" = "COMPLETED FAILED " ] || fail "round 1: the array ended as $(state "$ARRAY")"
[ "$(ls "$WORK/parts")" = "$(printf 'lecture.seg-0-of-3.mp4\nlecture.seg-2-of-3.mp4')" ] ||
  fail "round 1: expected segments 0 and 2 alone, got: $(ls -a "$WORK/parts")"
scancel "$CONCAT"
echo "ok: task 1 failed, the concat job waits for ever (DependencyNeverSatisfied), segments 0 and 2 are complete"

rm "$WORK/broken"
submit 2
wait_for "$CONCAT" "JobState=(COMPLETED|FAILED|CANCELLED|TIMEOUT)"
[ "$(state "$CONCAT")" = "COMPLETED " ] || { show_logs; fail "the concat job ended as $(state "$CONCAT")"; }
[ "$(state "$ARRAY")" = "COMPLETED " ] || fail "round 2: the array tasks ended as $(state "$ARRAY")"
for k in 0 2; do
  grep -q "lecture.seg-$k-of-3.mp4 is already complete: skipped" "$WORK/log/render_2_$k.out" ||
    fail "round 2: task $k did not skip its segment: $(cat "$WORK/log/render_2_$k.out")"
done
grep -q "wrote .*lecture.seg-1-of-3.mp4" "$WORK/log/render_2_1.out" ||
  fail "round 2: task 1 did not render segment 1: $(cat "$WORK/log/render_2_1.out")"
grep -q "from 3 segments" "$WORK/log/concat_2.out" || fail "concat said: $(cat "$WORK/log/concat_2.out")"
echo "ok: resubmitted, tasks 0 and 2 skipped their segments, task 1 rendered its own, concat joined them"
check_same_frames "$WORK/lecture.mp4" "$WORK/whole.mp4"
