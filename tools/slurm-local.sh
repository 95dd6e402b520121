#!/usr/bin/env bash
# A one-node Slurm cluster on localhost, for tests and for trying the cluster
# examples (examples/cluster/) on one machine.
#
#   tools/slurm-local.sh start DIR [--stop-with PID]   prints: export SLURM_CONF=DIR/slurm.conf
#   tools/slurm-local.sh stop DIR
#
# `start` writes DIR/slurm.conf (one node with this machine's cores and memory
# as `slurmd -C` reports them, select/cons_tres), a fresh munge key, and starts
# munged, slurmctld and slurmd with every state, log and pid file inside DIR;
# it returns once `sinfo` shows the node idle. Containers usually have neither
# systemd nor usable cgroups, so processes are tracked by /proc
# (proctrack/linuxproc, task/none), and there is no accounting daemon:
# `sacct` does not work, use `squeue`, `scontrol show job` or DIR/jobcomp.log.
# The daemons listen on 127.0.0.1 only, on free ports chosen at start, so
# several clusters can run side by side. `eval "$(tools/slurm-local.sh start
# DIR)"` points the client commands (sbatch, squeue, ...) at this cluster.
# With --stop-with PID a watcher stops the cluster when process PID ends (a
# test that is killed still leaves no daemon behind).
#
# `stop` cancels the cluster's jobs, then ends only the daemons that this
# DIR's pid files name (and whose command line names DIR), first with SIGTERM,
# then SIGKILL.
#
# Exit status: 0 done, 2 usage, 77 the daemons cannot run here (not installed,
# or one of them did not come up: its log is quoted), 1 anything else.
set -euo pipefail

NODE=aglocal
DAEMONS=(slurmd slurmctld munged)  # stop order: the reverse of start

die() {
  echo "slurm-local: $2" >&2
  exit "$1"
}

usage() { die 2 "usage: slurm-local.sh start DIR [--stop-with PID] | stop DIR"; }

# A TCP port on which nothing listens now.
free_port() {
  local used port
  used="$(ss -Hltn 2>/dev/null | awk '{print $4}' | sed 's/.*://')"
  for _ in $(seq 200); do
    port=$((20000 + RANDOM % 30000))
    if ! grep -qx "$port" <<<"$used" && [ "$port" != "${1:-}" ]; then
      echo "$port"
      return
    fi
  done
  die 1 "no free TCP port found"
}

# The pid in DIR's pid file for a daemon, if that process runs and is ours.
our_pid() {
  local dir="$1" name="$2" pid
  [ -s "$dir/pids/$name.pid" ] || return 1
  pid="$(tr -dc 0-9 <"$dir/pids/$name.pid")"
  [ -n "$pid" ] && [ -r "/proc/$pid/cmdline" ] || return 1
  tr '\0' ' ' <"/proc/$pid/cmdline" | grep -qF -- "$dir/" || return 1
  echo "$pid"
}

# True while process $1 runs (a zombie has ended: only its parent has not
# collected it yet).
alive() {
  local stat
  stat="$(cat "/proc/$1/stat" 2>/dev/null)" || return 1
  [ "$(sed 's/.*) //' <<<"$stat" | cut -d' ' -f1)" != "Z" ]
}

# Last lines of a daemon's log, for the message when it does not come up.
log_tail() {
  tail -n 3 "$1" 2>/dev/null | tr '\n' ' ' || true
}

# Waits up to $2 seconds (in 0.1 s steps) for command $3... to succeed.
wait_for() {
  local what="$1" tenths=$(($2 * 10))
  shift 2
  for _ in $(seq "$tenths"); do
    if "$@" >/dev/null 2>&1; then return 0; fi
    sleep 0.1
  done
  return 1
}

write_config() {
  local dir="$1" ctld_port slurmd_port hardware
  ctld_port="$(free_port)"
  slurmd_port="$(free_port "$ctld_port")"
  # "CPUs=2 Boards=1 SocketsPerBoard=1 CoresPerSocket=2 ThreadsPerCore=1 RealMemory=24105"
  hardware="$(slurmd -C | head -n 1 | sed 's/^NodeName=[^ ]* //')"
  cat >"$dir/slurm.conf" <<EOF
# Written by tools/slurm-local.sh: a one-node cluster on localhost.
ClusterName=areagraph-local
SlurmctldHost=$(hostname -s)(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
CommunicationParameters=NoInAddrAny,NoCtldInAddrAny
SlurmUser=$(id -un)
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$dir/munge/munge.socket
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$dir/pids/slurmctld.pid
SlurmdPidFile=$dir/pids/slurmd.pid
SlurmctldLogFile=$dir/logs/slurmctld.log
SlurmdLogFile=$dir/logs/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/filetxt
JobCompLoc=$dir/jobcomp.log
MpiDefault=none
SwitchType=switch/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
SchedulerType=sched/backfill
ReturnToService=2
KillWait=5
DefMemPerCPU=512
MinJobAge=600
PlugStackConfig=$dir/plugstack.conf
NodeName=$NODE NodeAddr=127.0.0.1 NodeHostname=$(hostname -s) $hardware State=UNKNOWN
PartitionName=local Nodes=$NODE Default=YES MaxTime=INFINITE State=UP
EOF
  : >"$dir/plugstack.conf"
}

start_munge() {
  local dir="$1"
  mkdir -p "$dir/munge"
  chmod 755 "$dir/munge"  # clients need to reach the socket; the key itself is 0400
  if [ -s "$dir/munge/munge.key" ]; then
    :  # DIR's earlier run made it
  elif command -v mungekey >/dev/null; then
    mungekey --create --keyfile="$dir/munge/munge.key" >/dev/null
  else
    head -c 1024 /dev/urandom >"$dir/munge/munge.key"
  fi
  chmod 400 "$dir/munge/munge.key"
  setsid munged --force --socket="$dir/munge/munge.socket" --key-file="$dir/munge/munge.key" \
    --log-file="$dir/logs/munged.log" --pid-file="$dir/pids/munged.pid" \
    --seed-file="$dir/munge/munged.seed" </dev/null >>"$dir/logs/munged.log" 2>&1 ||
    die 77 "munged did not start: $(log_tail "$dir/logs/munged.log")"
  wait_for munged 10 test -S "$dir/munge/munge.socket" ||
    die 77 "munged did not open its socket: $(log_tail "$dir/logs/munged.log")"
}

start() {
  local dir="$1" owner="$2"
  for program in munged slurmctld slurmd sinfo sbatch; do
    command -v "$program" >/dev/null ||
      die 77 "$program is not installed (tools/install-deps.sh installs slurm-wlm and munge)"
  done
  mkdir -p "$dir"
  dir="$(cd "$dir" && pwd)"
  if our_pid "$dir" slurmctld >/dev/null; then die 1 "a cluster already runs in $dir"; fi
  mkdir -p "$dir/state" "$dir/spool" "$dir/pids" "$dir/logs"
  write_config "$dir"
  export SLURM_CONF="$dir/slurm.conf"
  start_munge "$dir"
  # -c: start clean even if DIR holds an earlier run's state; -N: the node is
  # "aglocal" whatever this machine's host name is.
  setsid slurmctld -c -f "$SLURM_CONF" </dev/null >>"$dir/logs/slurmctld.log" 2>&1 ||
    { stop "$dir"; die 77 "slurmctld did not start: $(log_tail "$dir/logs/slurmctld.log")"; }
  setsid slurmd -N "$NODE" -f "$SLURM_CONF" </dev/null >>"$dir/logs/slurmd.log" 2>&1 ||
    { stop "$dir"; die 77 "slurmd did not start: $(log_tail "$dir/logs/slurmd.log")"; }
  if [ -n "$owner" ]; then
    setsid bash -c 'while kill -0 "$1" 2>/dev/null; do sleep 1; done; exec "$2" stop "$3"' \
      watcher "$owner" "$(realpath "$0")" "$dir" </dev/null >/dev/null 2>&1 &
    echo $! >"$dir/pids/watcher.pid"
  fi
  if ! wait_for "node" 30 node_idle; then
    local state
    state="$(sinfo -h -n "$NODE" -o '%t %E' 2>&1 || true)"
    stop "$dir"
    die 77 "the node did not become idle within 30 s (sinfo: $state); slurmd: $(log_tail \
      "$dir/logs/slurmd.log") slurmctld: $(log_tail "$dir/logs/slurmctld.log")"
  fi
  echo "export SLURM_CONF=$SLURM_CONF"
}

node_idle() { [ "$(sinfo -h -n "$NODE" -o %t)" = "idle" ]; }

stop() {
  local dir pid
  dir="$(cd "$1" 2>/dev/null && pwd)" || return 0
  # Jobs first: their processes (slurmstepd and the job's own) would outlive
  # slurmd. Up to 10 s for them to end (KillWait is 5 s).
  if our_pid "$dir" slurmctld >/dev/null; then
    SLURM_CONF="$dir/slurm.conf" scancel --user="$(id -un)" >/dev/null 2>&1 || true
    for _ in $(seq 100); do
      [ -z "$(SLURM_CONF="$dir/slurm.conf" squeue -h -t R,CG 2>/dev/null)" ] && break
      sleep 0.1
    done
  fi
  for name in "${DAEMONS[@]}"; do
    pid="$(our_pid "$dir" "$name")" || continue
    kill -TERM "$pid" 2>/dev/null || true
    for _ in $(seq 100); do
      alive "$pid" || break
      sleep 0.1
    done
    if alive "$pid"; then kill -KILL "$pid" 2>/dev/null || true; fi
  done
  # The watcher, unless it is the one stopping the cluster.
  if [ -s "$dir/pids/watcher.pid" ]; then
    pid="$(tr -dc 0-9 <"$dir/pids/watcher.pid")"
    if [ -n "$pid" ] && [ "$pid" != "$PPID" ] && [ "$pid" != "$$" ] &&
      tr '\0' ' ' <"/proc/$pid/cmdline" 2>/dev/null | grep -qF -- "$dir"; then
      kill -TERM "$pid" 2>/dev/null || true
    fi
    rm -f "$dir/pids/watcher.pid"
  fi
}

[ $# -ge 2 ] || usage
command="$1"
dir="$2"
shift 2
case "$command" in
  start)
    owner=""
    if [ $# -eq 2 ] && [ "$1" = "--stop-with" ] && [[ "$2" =~ ^[0-9]+$ ]]; then
      owner="$2"
    elif [ $# -ne 0 ]; then
      usage
    fi
    start "$dir" "$owner"
    ;;
  stop)
    [ $# -eq 0 ] || usage
    stop "$dir"
    ;;
  *) usage ;;
esac
