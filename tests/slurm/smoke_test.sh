#!/usr/bin/env bash
# End-to-end check of local_slurm.sh against the real Slurm daemons: the job-array + afterok pattern that
# `airis dataset --slurm N` submits, what Slurm does when one array task fails or is cancelled, and the
# start/stop guards (a second start is refused, a killed run's state is recovered, stop leaves nothing).
#
# Job state is read with `scontrol show job`: sacct needs slurmdbd, and without it (AccountingStorageType=
# accounting_storage/none) it only says "Slurm accounting storage is disabled" and exits 1. slurmctld keeps
# finished jobs for MinJobAge (300 s), far longer than any wait here.
#
# Run as root: tests/slurm/smoke_test.sh (CTest: SlurmSmoke; installs the Debian packages when missing,
# skips with exit 77 when not root). Ends with "N passed, N failed"; exits 0 only if all checks held.
# shellcheck disable=SC2016  # job scripts and eval'd checks are single-quoted on purpose: they expand later
set -euo pipefail

LOCAL_SLURM="$(cd "$(dirname "$0")" && pwd)/local_slurm.sh"
readonly LOCAL_SLURM
# Every wait is bounded; 30 s is ten times what the slowest step takes on a 2-core machine.
readonly WAIT_S=30

if [ "$(id -u)" -ne 0 ]; then
  echo "SKIP: needs root to start slurmd (it runs jobs as their owner); run as root (as CI does)"
  exit 77
fi
"$LOCAL_SLURM" install

work="$(mktemp -d /tmp/airis-slurm-smoke.XXXXXX)"
state="$work/cluster"
passed=0
failed=0

on_exit() {
  local rc=$?
  if [ "$rc" -ne 0 ] || [ "$failed" -ne 0 ]; then
    if [ -f "$state/log/slurmctld.log" ]; then
      echo "---- slurmctld.log (last 30 lines)"
      tail -n 30 "$state/log/slurmctld.log"
    fi
  fi
  "$LOCAL_SLURM" stop "$state" || true
  rm -rf -- "$work"
}
trap on_exit EXIT

# check DESCRIPTION CMD...: runs CMD and counts the outcome.
check() {
  local desc="$1"
  shift
  if "$@"; then
    echo "ok   $desc"
    passed=$((passed + 1))
  else
    echo "FAIL $desc"
    failed=$((failed + 1))
  fi
}

# wait_for CMD...: true as soon as CMD succeeds, false (with a note) after WAIT_S.
wait_for() {
  local n
  for ((n = 0; n < WAIT_S * 10; n++)); do
    if "$@"; then return 0; fi
    sleep 0.1
  done
  echo "     timed out after ${WAIT_S}s: $*"
  return 1
}

# job_field JOB FIELD: the value scontrol reports, JOB being a job id or ARRAYID_TASK.
job_field() {
  scontrol show job -o "$1" 2>/dev/null | tr ' ' '\n' | sed -n "s/^$2=//p" | head -n 1
}

field_is() {
  [ "$(job_field "$1" "$2")" = "$3" ]
}

# submit SBATCH_ARGS...: prints the job id (--parsable may append ";cluster").
submit() {
  local out
  out="$(sbatch --parsable --chdir="$work" --output="$work/joblogs/%A_%a.out" "$@")"
  echo "${out%%;*}"
}

file_is() {
  [ -f "$1" ] && [ "$(cat "$1")" = "$2" ]
}

# alive PID: running and not a zombie. A killed daemon's parent is PID 1, which in a container may reap it
# late, and kill -0 succeeds on a zombie.
alive() {
  local s
  s="$(ps -o stat= -p "$1" 2>/dev/null)" && [ "${s:0:1}" != Z ]
}

none_alive() {
  local pid
  for pid in "$@"; do
    if alive "$pid"; then return 1; fi
  done
}

pid_gone() {
  [ -s "$1" ] && none_alive "$(cat "$1")"
}

start_refused_with() {
  local out
  if out="$("$LOCAL_SLURM" start "$1" 2>&1)"; then return 1; fi
  grep -qF "$2" <<<"$out"
}

mkdir -p "$work/out" "$work/joblogs"
"$LOCAL_SLURM" start "$state"
eval "$("$LOCAL_SLURM" env "$state")"

echo "== array of 3 tasks, then a job that depends on it (afterok)"
t0=$(date +%s%N)
array="$(submit --array=0-2 --wrap 'echo "task $SLURM_ARRAY_TASK_ID" >out/$SLURM_ARRAY_TASK_ID')"
merge="$(submit --dependency=afterok:"$array" --wrap 'cat out/0 out/1 out/2 >out/all')"
check "dependent job $merge completes" wait_for field_is "$merge" JobState COMPLETED
echo "     submit to dependent job done: $((($(date +%s%N) - t0) / 1000000)) ms"
for t in 0 1 2; do
  check "task ${array}_$t COMPLETED with exit 0:0" \
    eval 'field_is "${array}_$t" JobState COMPLETED && field_is "${array}_$t" ExitCode 0:0'
done
check "dependent job concatenated the three task files in order" \
  file_is "$work/out/all" "$(printf 'task 0\ntask 1\ntask 2')"

echo "== array whose task 2 fails: the dependent job never runs"
array="$(submit --array=1-3 --wrap '[ "$SLURM_ARRAY_TASK_ID" -ne 2 ]')"
merge="$(submit --dependency=afterok:"$array" --wrap 'touch out/merge_ran')"
check "task ${array}_2 FAILED with exit 1:0" wait_for field_is "${array}_2" ExitCode 1:0
check "task ${array}_2 state is FAILED" field_is "${array}_2" JobState FAILED
check "tasks ${array}_1 and ${array}_3 COMPLETED" \
  eval 'wait_for field_is "${array}_1" JobState COMPLETED && wait_for field_is "${array}_3" JobState COMPLETED'
# Slurm 22.05 without SchedulerParameters=kill_invalid_depend leaves such a job pending for ever.
check "dependent job $merge pending with reason DependencyNeverSatisfied" \
  eval 'wait_for field_is "$merge" Reason DependencyNeverSatisfied && field_is "$merge" JobState PENDING'
check "dependent job's dependency names the failed array" field_is "$merge" Dependency "afterok:${array}_*(failed)"
check "dependent job did not run" test ! -e "$work/out/merge_ran"
scancel "$merge"
check "dependent job CANCELLED by scancel" wait_for field_is "$merge" JobState CANCELLED

echo "== scancel of one running array task"
array="$(submit --array=0-1 --wrap 'echo $$ >out/pid.$SLURM_ARRAY_TASK_ID; exec sleep 120')"
merge="$(submit --dependency=afterok:"$array" --wrap 'touch out/merge2_ran')"
check "task ${array}_1 RUNNING and has written its pid" \
  eval 'wait_for field_is "${array}_1" JobState RUNNING && wait_for test -s "$work/out/pid.1"'
scancel "${array}_1"
check "task ${array}_1 CANCELLED" wait_for field_is "${array}_1" JobState CANCELLED
check "task ${array}_1's process was killed" wait_for pid_gone "$work/out/pid.1"
check "task ${array}_0 still RUNNING" field_is "${array}_0" JobState RUNNING
# Slurm judges afterok on an array once every task has ended: until then the reason stays Dependency.
check "dependent job $merge still waits (reason Dependency) while ${array}_0 runs" \
  field_is "$merge" Reason Dependency
scancel "$array"
check "task ${array}_0 CANCELLED by scancel of the whole array" wait_for field_is "${array}_0" JobState CANCELLED
check "task ${array}_0's process was killed" wait_for pid_gone "$work/out/pid.0"
check "dependent job $merge pending with reason DependencyNeverSatisfied" \
  wait_for field_is "$merge" Reason DependencyNeverSatisfied
check "dependent job did not run" test ! -e "$work/out/merge2_ran"
scancel "$merge"

echo "== start and stop guards"
check "a second start in the same state dir is refused" start_refused_with "$state" "already running"
check "a second cluster on the same ports is refused" start_refused_with "$work/other" "is taken"
# Simulate a run killed with SIGKILL: the daemons die, the state dir stays.
kill -KILL "$(cat "$state/pids/slurmd")" "$(cat "$state/pids/slurmctld")" "$(cat "$state/pids/munged")"
# shellcheck disable=SC2046  # one pid per word
check "daemons of the killed run are gone" wait_for none_alive $(cat "$state"/pids/*)
check "start over a killed run's state dir succeeds" "$LOCAL_SLURM" start "$state"
check "sinfo answers after the restart" eval '[ "$(sinfo -h -o %T)" = idle ]'
pids="$(cat "$state"/pids/*)"
check "stop succeeds" "$LOCAL_SLURM" stop "$state"
check "stop removed the state dir" test ! -e "$state"
# shellcheck disable=SC2086  # one pid per word
check "stop left none of the daemons running" none_alive $pids

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
