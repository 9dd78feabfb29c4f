#!/usr/bin/env bash
# A one-node Slurm cluster on 127.0.0.1 owned by the calling user, for `simcap collect --slurm
# --submit` on a workstation and for tests/collect/test_slurm_cluster.cpp.
#
# usage: scripts/slurm_local.sh start|stop|status DIR
#   start DIR   writes DIR/slurm.conf, a munge key, state/spool folders; starts munged,
#               slurmctld and slurmd; waits until the node is idle; prints the line to eval:
#                 eval "$(scripts/slurm_local.sh start /tmp/simcap-slurm)"
#   stop DIR    stops the daemons started in DIR by their pid files (nothing running: no-op)
#   status DIR  says which daemons run and what sinfo sees; exit 0 only when all three run
# Exit status: 0 done, 1 failed, 2 bad usage, 3 Slurm or munge is not installed.
# SLURM_LOCAL_TIMEOUT (seconds, default 60) bounds the wait for the node.
#
# Why a script and not systemd units: setup.sh installs the packages but a workstation (or CI
# container) has no cluster, and starting the distribution's units needs root and touches
# /etc. Everything here lives under DIR, runs as the user, and listens on free loopback ports,
# so several clusters (a user's and a test's) can run side by side.
set -euo pipefail

usage() {
  echo "usage: $0 start|stop|status DIR" >&2
  exit 2
}

fail() {
  echo "slurm_local.sh: $*" >&2
  exit 1
}

# The daemons live in sbin, which a user's PATH often lacks.
PATH="$PATH:/usr/sbin:/usr/local/sbin:/sbin"

[[ $# -eq 2 ]] || usage
command=$1
[[ -n $2 ]] || usage
# Absolute, because slurm.conf and the printed export line must work from any folder.
dir=$(realpath -m -- "$2")

# Daemon name, pid file and log, in the order they are started (stopped in reverse).
daemons=(munged slurmctld slurmd)
pid_file() {
  case $1 in
    munged) echo "$dir/munge/munged.pid" ;;
    *) echo "$dir/$1.pid" ;;
  esac
}
log_file() {
  case $1 in
    munged) echo "$dir/munge/munged.log" ;;
    *) echo "$dir/$1.log" ;;
  esac
}

# The pid of `name` started in DIR if it still runs. The process name is checked so a stale
# pid file whose number was reused by another process never gets that process killed.
running_pid() {
  local file pid
  file=$(pid_file "$1")
  [[ -r $file ]] || return 1
  pid=$(tr -dc 0-9 <"$file")
  [[ -n $pid ]] || return 1
  [[ $(cat "/proc/$pid/comm" 2>/dev/null) == "$1" ]] || return 1
  echo "$pid"
}

# A TCP port on 127.0.0.1 that nothing listens on now (bash's /dev/tcp connect fails).
free_port() {
  local port
  for _ in $(seq 100); do
    port=$(shuf -i 20000-60999 -n 1)
    if ! (exec 3<>"/dev/tcp/127.0.0.1/$port") 2>/dev/null; then
      echo "$port"
      return
    fi
  done
  fail "no free TCP port found on 127.0.0.1"
}

# Prints the daemon's log (last lines) under a heading, for error messages.
show_log() {
  local log
  log=$(log_file "$1")
  echo "--- $log (last 20 lines) ---" >&2
  tail -n 20 "$log" >&2 2>/dev/null || echo "(no log written)" >&2
}

stop() {
  local i name pid
  for ((i = ${#daemons[@]} - 1; i >= 0; i--)); do
    name=${daemons[i]}
    if pid=$(running_pid "$name"); then
      kill -TERM "$pid" 2>/dev/null || true
      # slurmctld saves its state on SIGTERM; give it time before the next daemon goes.
      for _ in $(seq 100); do
        kill -0 "$pid" 2>/dev/null || break
        sleep 0.1
      done
      if kill -0 "$pid" 2>/dev/null; then
        kill -KILL "$pid" 2>/dev/null || true
        echo "slurm_local.sh: $name ($pid) ignored SIGTERM for 10 s; killed" >&2
      fi
      echo "stopped $name ($pid)" >&2
    fi
    rm -f "$(pid_file "$name")"
  done
}

status() {
  local name pid all=0
  for name in "${daemons[@]}"; do
    if pid=$(running_pid "$name"); then
      echo "$name: running (pid $pid)"
    else
      echo "$name: stopped"
      all=1
    fi
  done
  if [[ $all -eq 0 ]]; then
    SLURM_CONF="$dir/slurm.conf" sinfo -N -o '%N %T %c' || all=1
    printf 'export SLURM_CONF=%q\n' "$dir/slurm.conf"
  fi
  return $all
}

start() {
  local p name port_ctld port_d host timeout state
  for p in munged slurmctld slurmd sbatch squeue sinfo; do
    if ! command -v "$p" >/dev/null; then
      echo "slurm_local.sh: $p is not installed (scripts/setup.sh installs slurmctld, slurmd," \
        "slurm-client and munge)" >&2
      exit 3
    fi
  done
  for name in "${daemons[@]}"; do
    if running_pid "$name" >/dev/null; then
      fail "a cluster already runs in $dir ($name, pid $(running_pid "$name")); use it" \
        "(export SLURM_CONF=$dir/slurm.conf) or stop it first: $0 stop $dir"
    fi
  done

  # munged refuses a key or socket folder that others can read.
  mkdir -p "$dir/munge" "$dir/state" "$dir/spool"
  chmod 700 "$dir/munge"
  if [[ ! -s $dir/munge/munge.key ]]; then
    (umask 077 && head -c 1024 /dev/urandom >"$dir/munge/munge.key")
  fi
  chmod 400 "$dir/munge/munge.key"

  host=$(hostname)
  port_ctld=$(free_port)
  port_d=$(free_port)
  [[ $port_d != "$port_ctld" ]] || port_d=$(free_port)
  # Written fresh on each start: the ports are chosen anew. Accounting needs slurmdbd and a
  # database, too much for a workstation, so sacct answers "accounting storage is disabled";
  # each finished job's state (COMPLETED, FAILED, TIMEOUT) goes to DIR/jobcomp.log instead.
  cat >"$dir/slurm.conf" <<EOF
ClusterName=simcap
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$port_ctld
SlurmdPort=$port_d
SlurmUser=$(id -un)
SlurmdUser=$(id -un)
AuthType=auth/munge
CryptoType=crypto/munge
AuthInfo=socket=$dir/munge/munge.socket
StateSaveLocation=$dir/state
SlurmdSpoolDir=$dir/spool
SlurmctldPidFile=$(pid_file slurmctld)
SlurmdPidFile=$(pid_file slurmd)
SlurmctldLogFile=$(log_file slurmctld)
SlurmdLogFile=$(log_file slurmd)
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
MpiDefault=none
SchedulerType=sched/builtin
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
ReturnToService=2
JobCompType=jobcomp/filetxt
JobCompLoc=$dir/jobcomp.log
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) RealMemory=$(awk '/MemTotal/ {print int($2 * 0.9 / 1024)}' /proc/meminfo)
PartitionName=debug Nodes=ALL Default=YES MaxTime=INFINITE State=UP
EOF

  # A daemon that fails leaves the ones started before it stopped, not orphaned.
  munged --force --key-file="$dir/munge/munge.key" --socket="$dir/munge/munge.socket" \
    --pid-file="$(pid_file munged)" --log-file="$(log_file munged)" \
    --seed-file="$dir/munge/munged.seed" >&2 || {
    show_log munged
    fail "munged did not start"
  }
  export SLURM_CONF="$dir/slurm.conf"
  for name in slurmctld slurmd; do
    "$name" -f "$SLURM_CONF" >&2 || {
      show_log "$name"
      stop 2>/dev/null
      fail "$name did not start"
    }
  done

  timeout=${SLURM_LOCAL_TIMEOUT:-60}
  state=
  for ((i = 0; i < timeout * 5; i++)); do
    state=$(sinfo -h -N -o %T 2>/dev/null || true)
    [[ $state == idle* ]] && break
    sleep 0.2
  done
  if [[ $state != idle* ]]; then
    echo "slurm_local.sh: the node is not idle after ${timeout} s (sinfo: ${state:-no answer})" >&2
    for name in slurmctld slurmd; do
      running_pid "$name" >/dev/null || echo "slurm_local.sh: $name is no longer running" >&2
      show_log "$name"
    done
    stop 2>/dev/null
    fail "cluster in $dir did not come up; see $(log_file slurmctld) and $(log_file slurmd)"
  fi
  echo "slurm_local.sh: one-node cluster up in $dir ($host, $(nproc) CPUs)" >&2
  printf 'export SLURM_CONF=%q\n' "$SLURM_CONF"
}

case $command in
  start) start ;;
  stop) stop ;;
  status) status ;;
  *) usage ;;
esac
