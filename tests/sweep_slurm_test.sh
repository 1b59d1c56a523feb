#!/usr/bin/env bash
# `plywood sweep --slurm` against a real single-node Slurm cluster that this test starts on
# localhost (munged, slurmctld, slurmd under pid files it owns) and stops again, whatever happens.
# Checks: the job array's results are byte-identical to a local sweep; scancel of the array and
# re-submitting resumes like a local kill. Skips (exit 77) where Slurm is not installed.
#   tests/sweep_slurm_test.sh PLYWOOD_BINARY SOURCE_ROOT
set -euo pipefail
plywood=$1
root=$2
for tool in munged slurmctld slurmd sbatch squeue scancel sinfo start-stop-daemon; do
  if ! command -v "$tool" >/dev/null 2>&1 && [ ! -x "/usr/sbin/$tool" ]; then
    echo "SKIPPED: $tool not installed (scripts/setup installs slurmctld slurmd slurm-client munge)"
    exit 77
  fi
done
if [ "$(id -u)" -ne 0 ]; then
  echo "SKIPPED: starting munged/slurmctld/slurmd here needs root"
  exit 77
fi
if [ ! -r /etc/munge/munge.key ]; then
  echo "SKIPPED: no /etc/munge/munge.key"
  exit 77
fi

work=$(mktemp -d /tmp/plywood-slurm.XXXXXX)
stop() {
  if [ -n "${watchdog:-}" ]; then
    kill "$watchdog" 2>/dev/null || true
    [ -f "$work/watchdog_sleep.pid" ] && kill "$(cat "$work/watchdog_sleep.pid")" 2>/dev/null || true
  fi
  for daemon in slurmd slurmctld munged; do
    if [ -f "$work/$daemon.pid" ]; then
      start-stop-daemon --stop --quiet --retry TERM/10/KILL/5 --pidfile "$work/$daemon.pid" \
        >/dev/null 2>&1 || true
    fi
  done
  rm -rf "$work"
}
trap stop EXIT
trap 'exit 1' INT TERM
# ctest kills the script with SIGKILL at its TIMEOUT (300 s), which no trap sees, and the daemons
# (detached by start-stop-daemon) would outlive it. So the script ends itself first: after
# $deadline_s seconds the watchdog sends it TERM, and the EXIT trap stops the daemons (up to 15 s
# each, 45 s for the three, and the command under way finishes first: 240 + 45 + a few < 300).
deadline_s=${PLYWOOD_SLURM_TEST_DEADLINE_S:-240}
# Its sleep holds no stream of the script's (ctest waits for those to close) and is stopped with
# it.
(
  sleep "$deadline_s" </dev/null >/dev/null 2>&1 &
  echo $! >"$work/watchdog_sleep.pid"
  wait $! && echo "FAIL: still running after $deadline_s s; stopping the cluster" && kill -TERM $$
) &
watchdog=$!

mkdir -p "$work/state" "$work/spool" /run/munge
chown munge:munge /run/munge
chmod 0755 /run/munge
cpus=$(nproc)
export SLURM_CONF=$work/slurm.conf
# Addresses as numbers: a machine whose /etc/hosts lacks localhost (a bare debootstrap root) left
# slurmd retrying "Unable to resolve localhost" until the wait ran out.
cat >"$SLURM_CONF" <<CONF
ClusterName=plywoodtest
SlurmctldHost=localhost(127.0.0.1)
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
MpiDefault=none
MailProg=/bin/true
ReturnToService=2
SchedulerParameters=batch_sched_delay=0,sched_min_interval=0
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldPidFile=$work/slurmctld.internal.pid
SlurmdPidFile=$work/slurmd.internal.pid
SlurmctldLogFile=$work/slurmctld.log
SlurmdLogFile=$work/slurmd.log
SlurmctldPort=26817
SlurmdPort=26818
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$cpus RealMemory=1000 State=UNKNOWN
PartitionName=debug Nodes=ALL Default=YES MaxTime=INFINITE State=UP
CONF

start-stop-daemon --start --background --make-pidfile --pidfile "$work/munged.pid" \
  --chuid munge --exec /usr/sbin/munged -- -F
for _ in $(seq 100); do [ -S /run/munge/munge.socket.2 ] && break; sleep 0.1; done
start-stop-daemon --start --background --make-pidfile --pidfile "$work/slurmctld.pid" \
  --exec "$(command -v slurmctld || echo /usr/sbin/slurmctld)" -- -D -i -f "$SLURM_CONF"
start-stop-daemon --start --background --make-pidfile --pidfile "$work/slurmd.pid" \
  --exec "$(command -v slurmd || echo /usr/sbin/slurmd)" -- -D -f "$SLURM_CONF"
# Up to 30 s for the node to be idle. A daemon that exits on start (slurmd without a cgroup file
# system, say) is seen at once, and every sinfo has its own time limit: before, a slurmd that died
# at start left sinfo waiting, and the script ran into ctest's timeout with no line printed.
alive() { [ -f "$work/$1.pid" ] && kill -0 "$(cat "$work/$1.pid")" 2>/dev/null; }
state=""
come_up_end=$((SECONDS + 30))
while ((SECONDS < come_up_end)); do
  state=$(timeout 5 sinfo -h -o %T 2>/dev/null || true)
  [ "$state" = idle ] && break
  for daemon in munged slurmctld slurmd; do
    alive "$daemon" || { state="$daemon exited at start"; break 2; }
  done
  sleep 0.2
done
if [ "$state" != idle ]; then
  echo "SKIPPED: the local Slurm cluster did not come up (sinfo: '$state')"
  tail -n 5 "$work/slurmctld.log" "$work/slurmd.log" 2>/dev/null || true
  exit 77
fi
echo "slurm: cluster up ($cpus CPUs)"

# Six short runs: the default experiment in the hall with the hall's own tour (the office's
# waypoints lie beyond its walls: refused since s52), two durations x three seeds.
cat >"$work/sweep.yaml" <<YAML
experiment: $root/experiments/default.yaml
seeds: [1, 2, 3]
worlds: [$root/worlds/hall.xml]
set:
  controller.waypoints: ["[[2, -2], [2, 2], [-2, 2], [-2, -2]]"]
  duration_s: [3, 4]
  output.snapshot: [false]
metrics: [truth.distance_m]
YAML

wait_for_job() {
  local job=$1
  for _ in $(seq 600); do
    [ -z "$(squeue -h -j "$job" 2>/dev/null)" ] && return 0
    sleep 0.2
  done
  echo "FAIL: job $job did not finish"
  return 1
}

"$plywood" sweep "$work/sweep.yaml" --out "$work/local" --quiet

# 1. The job array gives the same bytes as the local sweep. The folder's name holds what sbatch
# reads specially in an #SBATCH line (a space ends the value, '#' starts a comment, '%' starts a
# file name pattern): the task logs went to "$work/cluster" (a file), not into the folder (s42b).
cluster="$work/cluster #1 at 100%a"
out=$("$plywood" sweep "$work/sweep.yaml" --out "$cluster" --slurm --max-parallel 2)
echo "$out"
job=$(echo "$out" | awk '/submitted job/ {print $3}')
[ -n "$job" ] || { echo "FAIL: no job id"; exit 1; }
wait_for_job "$job"
"$plywood" sweep --collect "$cluster" --quiet
cmp "$work/local/results.csv" "$cluster/results.csv"
for task in 0 1 2 3 4 5; do
  [ -f "$cluster/slurm/task-$task.log" ] || {
    echo "FAIL: no task log $cluster/slurm/task-$task.log:"; ls -la "$work"; exit 1; }
done
echo "slurm: job array results byte-identical to the local sweep, task logs in the sweep folder"

# 2. scancel part-way, submit again: resumes, same bytes, finished runs not redone.
out=$("$plywood" sweep "$work/sweep.yaml" --out "$work/cancelled" --slurm --max-parallel 1)
job=$(echo "$out" | awk '/submitted job/ {print $3}')
# Up to 2 min for the first run: on a loaded 2-core machine slurmd may start the array late.
n=0
for _ in $(seq 1200); do
  n=$(find "$work/cancelled/runs" -mindepth 1 -maxdepth 1 -type d ! -name '.partial' 2>/dev/null | wc -l || true)
  [ "$n" -ge 1 ] && break
  sleep 0.1
done
[ "$n" -ge 1 ] || { echo "FAIL: no run of job $job finished within 120 s"; exit 1; }
scancel "$job"
wait_for_job "$job"
before=$(find "$work/cancelled/runs" -mindepth 1 -maxdepth 1 -type d ! -name '.partial' | sort)
n_before=$(echo "$before" | grep -c . || true)
[ "$n_before" -lt 6 ] || { echo "FAIL: cancel came too late to test resuming ($n_before of 6)"; exit 1; }
inodes_before=$(for d in $before; do stat -c '%i %n' "$d"; done)
out=$("$plywood" sweep "$work/sweep.yaml" --out "$work/cancelled" --slurm)
job=$(echo "$out" | awk '/submitted job/ {print $3}')
wait_for_job "$job"
"$plywood" sweep --collect "$work/cancelled" --quiet
cmp "$work/local/results.csv" "$work/cancelled/results.csv"
inodes_after=$(for d in $before; do stat -c '%i %n' "$d"; done)
[ "$inodes_before" = "$inodes_after" ] || { echo "FAIL: finished runs were redone"; exit 1; }
echo "slurm: scancel after $n_before of 6 runs, re-submitted: same bytes, no run redone"
echo "1 passed, 0 failed"
