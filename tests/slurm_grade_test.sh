#!/bin/bash
# The Slurm recipe of docs/grading.md, run for real: starts a
# one-node Slurm cluster of its own on localhost (every file in a temporary
# folder, SLURM_CONF pointing there, auth/none; nothing in /etc touched), grades
# a class with scripts/slurm/submit in 3 shards, and checks that the merged
# grades.csv, grades.json and report.html (and every other file) equal one
# unsharded run's byte for byte. Stops the daemons it started, by PID, also on
# failure. Every wait is bounded by `timeout`.
#   tests/slurm_grade_test.sh M3055_BINARY
set -euo pipefail
m3055=$(realpath "$1")
repo=$(cd "$(dirname "$0")/.." && pwd)
for tool in slurmctld slurmd sbatch squeue scontrol sinfo; do
  if ! command -v "$tool" >/dev/null && ! [ -x "/usr/sbin/$tool" ]; then
    echo "FAIL: $tool is not installed (Debian: slurmctld slurmd slurm-client, installed by scripts/setup --for-tests)" >&2
    exit 1
  fi
done
PATH="$PATH:/usr/sbin"

work=$(mktemp -d "${TMPDIR:-/tmp}/m3055-slurm.XXXXXX")
pids=()
cleanup() {
  local status=$?
  for pid in "${pids[@]}"; do kill "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do timeout 10 tail --pid="$pid" -f /dev/null 2>/dev/null || kill -9 "$pid" 2>/dev/null || true; done
  if ((status != 0)); then
    for log in "$work"/slurmctld.log "$work"/slurmd.log "$work"/out.shards/slurm-*.out; do
      [ -f "$log" ] && { echo "---- $log"; tail -n 20 "$log"; }
    done
  fi
  rm -rf -- "$work"
  exit "$status"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

# Two free TCP ports for slurmctld and slurmd (the kernel picks them).
read -r ctld_port slurmd_port < <(python3 -c '
import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(("127.0.0.1", 0))
print(*(x.getsockname()[1] for x in s))')

mkdir -p "$work/state" "$work/spool"
user=$(id -un)
export SLURM_CONF="$work/slurm.conf"
cat >"$SLURM_CONF" <<CONF
ClusterName=m3055test
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
SlurmUser=$user
SlurmdUser=$user
AuthType=auth/none
CredType=cred/none
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
ProctrackType=proctrack/pgid
TaskPlugin=task/none
MpiDefault=none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
# A merge after a failed shard is cancelled, not left pending (22.05 reads this
# here, not under SchedulerParameters).
DependencyParameters=kill_invalid_depend
# Finished jobs stay known: an afterok on a purged job id would count as met.
MinJobAge=86400
JobCompType=jobcomp/none
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=test Nodes=localhost Default=YES MaxTime=INFINITE State=UP
CONF

slurmctld -D -i >"$work/slurmctld.stdout" 2>&1 &
pids+=($!)
# The node's name is "localhost", not the machine's hostname.
slurmd -D -N localhost >"$work/slurmd.stdout" 2>&1 &
pids+=($!)
if ! timeout 30 bash -c 'until [ "$(sinfo -h -n localhost -o %T 2>/dev/null)" = idle ]; do sleep 0.2; done'; then
  echo "FAIL: the one-node cluster did not reach idle in 30 s" >&2
  exit 1
fi

# The class: the three-point assignment's submissions, graded once unsharded...
assignment="$repo/assignments/three-point/assignment.json"
submissions="$repo/assignments/three-point/submissions"
cd "$work"
"$m3055" grade "$assignment" "$submissions" --out single >/dev/null 2>&1 || true  # exit 1: failing students
[ -f single/grades.json ] || { echo "FAIL: the unsharded run wrote no grades.json" >&2; exit 1; }

# ... and by the docs' recipe: 3 shards as a job array, then the merge job.
merge_job=$(M3055="$m3055" timeout 30 "$repo/scripts/slurm/submit" "$assignment" "$submissions" out 3)
state=""
if ! timeout 60 bash -c "until [ -z \"\$(squeue -h -j $merge_job -o %i 2>/dev/null)\" ] && \
     [ -n \"\$(scontrol show job $merge_job 2>/dev/null)\" ]; do sleep 0.5; done"; then
  echo "FAIL: the merge job $merge_job did not finish in 60 s" >&2
  squeue >&2 || true
  exit 1
fi
# sbatch --wait would exit 0 for a job cancelled before it ran: read the state.
state=$(scontrol show job "$merge_job" | grep -o 'JobState=[A-Z_]*' | head -n 1)
if [ "$state" != "JobState=COMPLETED" ]; then
  echo "FAIL: merge job $merge_job ended in $state" >&2
  exit 1
fi
shards=$(find out.shards -mindepth 1 -maxdepth 1 -type d | wc -l)
[ "$shards" -eq 3 ] || { echo "FAIL: expected 3 shard folders, got $shards" >&2; exit 1; }
# Every file but the shader cache, which grade keeps in its --out (docs/grading.md#outputs).
if ! diff -r -x .shader-cache single out >&2; then
  echo "FAIL: the merged output differs from the unsharded run" >&2
  exit 1
fi
echo "PASS: 3 shards under Slurm merged to the unsharded run's $(find single -path single/.shader-cache -prune -o -type f -print | wc -l) files, byte for byte"
