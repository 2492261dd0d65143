#!/usr/bin/env bash
# A real one-node Slurm cluster on localhost for tests: munged, slurmctld and slurmd run as root in the
# background with every file they write (config, munge key and socket, spool, state, logs, pid files) inside
# one state directory, so nothing in /etc is touched and two checkouts never share a cluster by accident.
#
#   local_slurm.sh install            apt-get the Debian packages (sudo when not root), skipped when present
#   local_slurm.sh start STATE_DIR    write STATE_DIR/slurm.conf, start the daemons, wait for the node to be idle
#   local_slurm.sh env STATE_DIR      print the export lines clients need: eval "$(local_slurm.sh env DIR)"
#   local_slurm.sh stop STATE_DIR     cancel all jobs, stop exactly the daemons start began, remove STATE_DIR
#
# Environment: AIRIS_SLURM_CTLD_PORT (default 16817) and AIRIS_SLURM_SLURMD_PORT (default 16818) move the
# ports off Slurm's own 6817/6818, so a site install on the same host does not clash;
# AIRIS_SLURM_READY_TIMEOUT_S (default 60) bounds the wait for the node to come up.
set -euo pipefail

readonly CTLD_PORT="${AIRIS_SLURM_CTLD_PORT:-16817}"
readonly SLURMD_PORT="${AIRIS_SLURM_SLURMD_PORT:-16818}"
readonly READY_TIMEOUT_S="${AIRIS_SLURM_READY_TIMEOUT_S:-60}"
readonly PACKAGES=(slurmctld slurmd slurm-client munge)
# Started in this order, stopped in the reverse one: slurmctld and slurmd authenticate through munged.
readonly DAEMONS=(munged slurmctld slurmd)
# A file only this script writes: stop deletes a directory only when it holds it.
readonly MARKER=".airis-local-slurm"
# Set in each daemon's environment, so a pid can be checked to be one of ours before it is signalled, even
# if the recorded pid has been reused. (slurmstepd cannot be told this way: it overwrites its environ to
# set its process title; see is_our_stepd.)
readonly TAG_VAR="AIRIS_LOCAL_SLURM_STATE"

die() {
  echo "local_slurm: $*" >&2
  exit 1
}

usage() {
  sed -n '5,9s/^# \{0,1\}//p' "$0" >&2
  exit 2
}

require_root() {
  # slurmd must run as root to start jobs as their submitting user; there is no unprivileged mode.
  [ "$(id -u)" -eq 0 ] || die "'$1' needs root (slurmd runs jobs as their owner): run it as root or with sudo"
}

# The absolute path, without requiring it to exist: slurm.conf needs absolute paths.
abs_dir() {
  [ -n "$1" ] || usage
  realpath -m -- "$1"
}

# True when pid $1 is alive and carries our tag for state dir $2.
is_ours() {
  local pid="$1" state="$2"
  [ -n "$pid" ] || return 1
  # -z: environ is NUL-separated. No pipe, so pipefail cannot turn a match into a failure.
  grep -qzxF "$TAG_VAR=$state" "/proc/$pid/environ" 2>/dev/null
}

# True when pid $1 is a slurmstepd of state dir $2: it keeps SlurmdLogFile open.
is_our_stepd() {
  local pid="$1" state="$2" fd
  [ "$(cat "/proc/$pid/comm" 2>/dev/null)" = slurmstepd ] || return 1
  for fd in "/proc/$pid/fd/"*; do
    if [ "$(readlink "$fd" 2>/dev/null)" = "$state/log/slurmd.log" ]; then return 0; fi
  done
  return 1
}

# True when pid $1 is a child of this shell that has not yet become its daemon: between the fork and
# the daemon's exec it runs as a subshell, then env and setsid, none with the tag in its environment
# (under load that can take a while). A child that exited (a zombie) is not starting.
starting() {
  local pid="$1" stat run_state ppid
  [ -n "$pid" ] || return 1
  stat="$(cat "/proc/$pid/stat" 2>/dev/null)" || return 1
  stat="${stat##*) }"  # the fields after "pid (comm) ": state, ppid, ...
  read -r run_state ppid _ <<<"$stat"
  [ "$run_state" != Z ] && [ "$ppid" = "$BASHPID" ]
}

recorded_pid() {
  cat "$1/pids/$2" 2>/dev/null || true
}

# Prints the names of the daemons of $1 that are still running.
running_daemons() {
  local state="$1" d
  for d in "${DAEMONS[@]}"; do
    if is_ours "$(recorded_pid "$state" "$d")" "$state"; then echo "$d"; fi
  done
}

port_in_use() {
  # A connect succeeds only when something listens; bash's /dev/tcp needs no extra tool.
  (exec 3<>"/dev/tcp/127.0.0.1/$1") 2>/dev/null
}

# Lines every start logs that mean nothing here: the MPI plugins all load even with MpiDefault=none and
# PMIx is not installed; a fresh StateSaveLocation has no state files to recover.
readonly LOG_NOISE='pmix|MPI: Cannot create context|(job|reservation) state file|Trying backup state save'

# Shows the end of each daemon's stderr, so a failed start explains itself without another command. In the
# foreground (-D, --foreground) the daemons log everything to stderr too, including errors from before they
# open their log file (a bad slurm.conf line).
show_logs() {
  local f
  for f in "$1"/log/*.stderr; do
    [ -s "$f" ] || continue
    echo "---- $f (last 15 lines, known noise left out)" >&2
    grep -vE "$LOG_NOISE" "$f" | tail -n 15 >&2 || true
  done
}

cmd_install() {
  local missing=() p sudo=""
  for p in "${PACKAGES[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
      missing+=("$p")
    fi
  done
  if [ ${#missing[@]} -eq 0 ]; then
    echo "local_slurm: all ${#PACKAGES[@]} packages present"
    return 0
  fi
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  echo "local_slurm: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  # The packages' postinst scripts try to start the system services; that fails harmlessly (no
  # /etc/slurm/slurm.conf) or is denied by policy-rc.d. This script never uses them.
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

# Writes the cluster's slurm.conf; each line says why it is there.
write_conf() {
  local state="$1" node="$2" hw="$3"
  cat >"$state/slurm.conf" <<EOF
# Written by tests/slurm/local_slurm.sh for a throw-away one-node test cluster.
ClusterName=airis-local
# The short hostname, as slurmctld checks that it runs on SlurmctldHost; the address avoids any DNS lookup.
SlurmctldHost=$node(127.0.0.1)
# Off Slurm's 6817/6818 so a site install on the same host does not answer our clients.
SlurmctldPort=$CTLD_PORT
SlurmdPort=$SLURMD_PORT
# Our own munged; auth/munge and cred/munge (the defaults) both read the socket from here.
AuthInfo=socket=$state/munge/munge.socket
# Everything the daemons write stays in the state dir.
StateSaveLocation=$state/ctld
SlurmdSpoolDir=$state/slurmd
SlurmctldPidFile=$state/run/slurmctld.pid
SlurmdPidFile=$state/run/slurmd.pid
SlurmctldLogFile=$state/log/slurmctld.log
SlurmdLogFile=$state/log/slurmd.log
# Defaults in 22.05, stated because the rest relies on them: no slurm user to create, no cgroups, no
# accounting daemon (so sacct answers "Slurm accounting storage is disabled"), no MPI.
SlurmUser=root
SlurmdUser=root
TaskPlugin=task/none
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
MpiDefault=none
# The default, proctrack/cgroup, fails in containers such as gVisor ("cgroup namespace 'freezer' not
# mounted. aborting" in slurmstepd, and the job never runs); following parent pids in /proc needs nothing.
ProctrackType=proctrack/linuxproc
# The default, select/linear, gives each job a whole node: array tasks would run one at a time.
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
# Up to 4 jobs per core, so a test's array tasks start in one scheduling pass on a 2-core machine.
PartitionName=debug Nodes=$node Default=YES MaxTime=INFINITE State=UP OverSubscribe=FORCE:4
# The default 3 s delay before batch jobs are scheduled is paid again at each step of an array + afterok
# chain; at 0 a job starts at the next of slurmctld's 1 s scheduler ticks.
SchedulerParameters=batch_sched_delay=0
# scancel sends SIGTERM, then SIGKILL after KillWait (default 30 s); stop waits for cancelled jobs to end.
KillWait=5
# A node that was DOWN comes back as soon as its slurmd registers (default 0: stays down until resumed).
ReturnToService=2
# A record of every finished job that outlives MinJobAge (300 s), for reading after a failed test.
JobCompType=jobcomp/filetxt
JobCompLoc=$state/jobcomp.txt
# The default /bin/mail is not installed; slurmctld logs an error at each start without this.
MailProg=/bin/true
# slurmd -C's view of this machine (CPUs, sockets, cores, threads, RealMemory).
NodeName=$hw NodeAddr=127.0.0.1 State=UNKNOWN
EOF
}

# Starts daemon $2 of state dir $1 in the background, detached from the caller's session and output (so
# `$(local_slurm.sh start ...)` or a test runner waiting on its pipes does not hang), and records its pid.
launch() {
  local state="$1" name="$2"
  shift 2
  env "$TAG_VAR=$state" SLURM_CONF="$state/slurm.conf" setsid "$@" \
    </dev/null >>"$state/log/$name.stderr" 2>&1 &
  echo $! >"$state/pids/$name"
}

cmd_start() {
  local state node hw d pid t0 waited=0 state_now=""
  state="$(abs_dir "${1:-}")"
  require_root start
  for d in munged mungekey slurmctld slurmd sinfo; do
    command -v "$d" >/dev/null || die "$d not found: run '$0 install' first"
  done

  if [ -e "$state" ]; then
    if [ -f "$state/$MARKER" ]; then
      local alive
      alive="$(running_daemons "$state" | tr '\n' ' ')"
      if [ -n "$alive" ]; then
        die "a cluster is already running in $state (${alive% }); stop it first: $0 stop $state"
      fi
      # Left by a run that was killed before it could stop: its daemons are gone, its state is stale.
      echo "local_slurm: removing stale state of a killed run in $state" >&2
      stop_daemons "$state"
      rm -rf -- "$state"
    elif [ -n "$(ls -A -- "$state")" ]; then
      die "$state is not empty and was not made by this script; refusing to use it"
    fi
  fi
  [[ "$CTLD_PORT" =~ ^[0-9]+$ && "$SLURMD_PORT" =~ ^[0-9]+$ && "$CTLD_PORT" != "$SLURMD_PORT" ]] ||
    die "AIRIS_SLURM_CTLD_PORT ($CTLD_PORT) and AIRIS_SLURM_SLURMD_PORT ($SLURMD_PORT) must be two different port numbers"
  for d in "$CTLD_PORT" "$SLURMD_PORT"; do
    if port_in_use "$d"; then
      die "port $d on 127.0.0.1 is taken (another cluster still running?); set AIRIS_SLURM_CTLD_PORT / AIRIS_SLURM_SLURMD_PORT"
    fi
  done

  t0=$(date +%s%N)
  mkdir -p "$state"/{ctld,slurmd,run,log,pids}
  # munged refuses a key or socket directory that group or others can write.
  mkdir -m 0755 "$state/munge"
  touch "$state/$MARKER"

  node="$(hostname -s)"
  # slurmd -C prints the node line as slurmd will report it at registration; configuring exactly that
  # keeps the node from being drained for "Low socket*core*thread count" or "Low RealMemory".
  hw="$(slurmd -C)"
  hw="${hw%%$'\n'*}"
  hw="${hw#NodeName=* }"
  [ -n "$hw" ] || die "slurmd -C printed no node line"
  write_conf "$state" "$node" "$node $hw"

  mungekey --create --keyfile="$state/munge/munge.key"
  # --force: munged refuses a socket whose parent directories are not all world-executable, and a state
  # dir made by mktemp -d sits in a 0700 one. With --force that is a warning; only root (and users who can
  # traverse the path) can then reach the socket, which is all this cluster serves.
  launch "$state" munged munged --foreground --force \
    --socket="$state/munge/munge.socket" --key-file="$state/munge/munge.key" \
    --pid-file="$state/run/munged.pid" --log-file="$state/log/munged.log" \
    --seed-file="$state/munge/munged.seed"
  launch "$state" slurmctld slurmctld -D -c -f "$state/slurm.conf"
  launch "$state" slurmd slurmd -D -N "$node" -f "$state/slurm.conf"

  export SLURM_CONF="$state/slurm.conf"
  while :; do
    for d in "${DAEMONS[@]}"; do
      pid="$(recorded_pid "$state" "$d")"
      if ! is_ours "$pid" "$state" && ! starting "$pid"; then
        show_logs "$state"
        stop_daemons "$state"
        die "$d exited during start (logs above; state kept in $state)"
      fi
    done
    state_now="$(sinfo -h -N -n "$node" -o %T 2>/dev/null || true)"
    if [ "$state_now" = "idle" ]; then break; fi
    if [ "$waited" -ge $((READY_TIMEOUT_S * 10)) ]; then
      show_logs "$state"
      stop_daemons "$state"
      die "node $node not idle after ${READY_TIMEOUT_S}s (last state: '${state_now:-no answer}'; logs above; state kept in $state)"
    fi
    sleep 0.1
    waited=$((waited + 1))
  done
  local ms=$((($(date +%s%N) - t0) / 1000000))
  printf 'local_slurm: node %s idle after %d.%03ds (state in %s)\n' "$node" $((ms / 1000)) $((ms % 1000)) "$state"
}

# Prints the pids of every descendant of pid $1.
descendants() {
  local -A children=()
  local pid ppid queue=("$1") out=()
  while read -r pid ppid; do children[$ppid]+="$pid "; done < <(ps -e -o pid=,ppid=)
  while [ ${#queue[@]} -gt 0 ]; do
    for pid in ${children[${queue[0]}]:-}; do
      out+=("$pid")
      queue+=("$pid")
    done
    queue=("${queue[@]:1}")
  done
  echo "${out[*]}"
}

# Sends TERM to our daemons (newest first), waits up to 15 s for each, then KILLs what is left. Afterwards
# kills any slurmstepd of ours with the job processes under it: slurmstepd outlives slurmd by design, and
# one is left over only when slurmctld was gone and stop could not cancel the jobs.
stop_daemons() {
  local state="$1" i d pid n
  for ((i = ${#DAEMONS[@]} - 1; i >= 0; i--)); do
    d="${DAEMONS[i]}"
    pid="$(recorded_pid "$state" "$d")"
    is_ours "$pid" "$state" || continue
    kill -TERM "$pid" 2>/dev/null || true
    for ((n = 0; n < 150; n++)); do
      is_ours "$pid" "$state" || break
      sleep 0.1
    done
    if is_ours "$pid" "$state"; then
      echo "local_slurm: $d (pid $pid) ignored TERM for 15s; killing it" >&2
      kill -KILL "$pid" 2>/dev/null || true
    fi
  done
  for pid in /proc/[0-9]*; do
    pid="${pid#/proc/}"
    if is_our_stepd "$pid" "$state"; then
      echo "local_slurm: killing leftover $(tr '\0' ' ' <"/proc/$pid/cmdline" 2>/dev/null) (pid $pid)" >&2
      # shellcheck disable=SC2046  # one pid per word
      kill -KILL "$pid" $(descendants "$pid") 2>/dev/null || true
    fi
  done
}

cmd_stop() {
  local state n
  state="$(abs_dir "${1:-}")"
  # Nothing there is not an error: a trap may call stop after a start that never got going.
  [ -e "$state" ] || return 0
  [ -f "$state/$MARKER" ] || die "$state was not made by this script; refusing to delete it"
  require_root stop
  if is_ours "$(recorded_pid "$state" slurmctld)" "$state"; then
    # Cancel the jobs first so slurmd reaps their processes; a job left running would outlive the cluster.
    export SLURM_CONF="$state/slurm.conf"
    scancel --partition=debug 2>/dev/null || true
    # Bounded by KillWait (5 s) plus slack: by then slurmd has SIGKILLed what ignored SIGTERM.
    for ((n = 0; n < 150; n++)); do
      [ -z "$(squeue -h -t running,completing -o %i 2>/dev/null)" ] && break
      sleep 0.1
    done
  fi
  stop_daemons "$state"
  rm -rf -- "$state"
}

cmd_env() {
  local state
  state="$(abs_dir "${1:-}")"
  [ -f "$state/slurm.conf" ] || die "no cluster in $state (run '$0 start $state' first)"
  # The munge socket is named in slurm.conf (AuthInfo), so SLURM_CONF is all a client needs.
  printf 'export SLURM_CONF=%q\n' "$state/slurm.conf"
}

case "${1:-}" in
  install) cmd_install ;;
  start) cmd_start "${2:-}" ;;
  stop) cmd_stop "${2:-}" ;;
  env) cmd_env "${2:-}" ;;
  *) usage ;;
esac
