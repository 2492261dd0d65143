#!/usr/bin/env bash
# `airis dataset --slurm 3` on a real one-node Slurm (local_slurm.sh): the merged dataset is byte for
# byte the unsharded run's; a shard task cancelled mid-run shows as failed in `airis dataset status`,
# its merge is cancelled, and `--only-shards` runs it again (resuming its folder) and merges the same
# bytes; a campaign of two seeds makes two one-task datasets with their seeds. Prints the wall times
# (unsharded run, submit to merged) for docs/performance.md.
#
#   tests/slurm/dataset_slurm_test.sh AIRIS_BINARY      (from the repository root; CTest: SlurmDataset)
#
# Needs root (slurmd starts jobs as their owner): as any other user it skips (exit 77) and says so.
# As root it installs slurmctld, slurmd, slurm-client and munge from Debian when missing, and a
# daemon that cannot start fails the test with the daemon's own log lines. Every daemon it started is
# stopped by pid and its state directory removed, also when a check fails.
# shellcheck disable=SC2016  # eval'd checks are single-quoted on purpose: they expand later
set -euo pipefail

AIRIS="$(realpath "${1:?usage: $0 AIRIS_BINARY}")"
readonly AIRIS
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
readonly ROOT
readonly LOCAL_SLURM="$ROOT/tests/slurm/local_slurm.sh"
# The README demo: 118 frames of the city survey.
readonly SCENE="$ROOT/scenes/city.yaml"
readonly MISSION="$ROOT/scenes/missions/city_survey.yaml"
# Every wait is bounded: ten times what the slowest step takes on a 2-core machine.
readonly WAIT_S=300

if [ "$(id -u)" -ne 0 ]; then
  echo "SKIP: needs root to start slurmd (it runs jobs as their owner); run as root (as CI does)"
  exit 77
fi
if ! command -v apt-get >/dev/null && ! command -v slurmctld >/dev/null; then
  echo "SKIP: Slurm is not installed and there is no apt-get to install it (Debian's slurm-wlm)"
  exit 77
fi
"$LOCAL_SLURM" install

work="$(mktemp -d /tmp/airis-slurm-dataset.XXXXXX)"
state="$work/cluster"
passed=0
failed=0

on_exit() {
  local rc=$?
  if [ "$rc" -ne 0 ] || [ "$failed" -ne 0 ]; then
    for f in "$state/log/slurmctld.log" "$work"/*/slurm/logs/*.out; do
      [ -f "$f" ] || continue
      echo "---- $f (last 20 lines)"
      tail -n 20 "$f"
    done
  fi
  "$LOCAL_SLURM" stop "$state" || true
  rm -rf -- "$work"
}
trap on_exit EXIT

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

now_ms() { echo $(($(date +%s%N) / 1000000)); }
seconds_since() { local ms=$(($(now_ms) - $1)); printf '%d.%03d' $((ms / 1000)) $((ms % 1000)); }

# json_get FILE_OR_- EXPR: a value from JSON, EXPR in Python over `j`.
json_get() {
  python3 -c 'import json, sys
j = json.load(open(sys.argv[1]) if sys.argv[1] != "-" else sys.stdin)
print(eval(sys.argv[2]))' "$@"
}

status_json() { "$AIRIS" dataset status "$1" --json; }

# shard_states DIR: "done done failed" (ShardState names, shard 1 first).
shard_states() { status_json "$1" | json_get - '" ".join(s["state"] for s in j["shards"])'; }

# merge_state DIR: done, waiting, running, failed, ...
merge_state() { status_json "$1" | json_get - 'j["merge"]["state"]'; }

# merged DIR: DIR's manifest says complete, which is what `airis dataset status` calls a merge done
# (a merge in progress writes complete: false first and the final manifest last).
merged() { grep -qs '"complete": true' "$1/manifest.json"; }

# wait_merge_ended DIR: until the merge is done or failed; prints it. The manifest is looked at every
# 0.05 s and Slurm's view (`airis dataset status`, which asks squeue) once a second: the wait is timed,
# and a status poll costs about a tenth of a CPU-second, which on two cores is taken from the shards.
wait_merge_ended() {
  local n s=""
  for ((n = 1; n <= WAIT_S * 20; n++)); do
    if merged "$1"; then echo done; return 0; fi
    if ((n % 20 == 0)); then
      s="$(merge_state "$1")"
      case "$s" in done | failed) echo "$s"; return 0 ;; esac
    fi
    sleep 0.05
  done
  echo "timed out after ${WAIT_S}s (merge: $s)"
  return 1
}

# same_dataset A B: the files of A and B are the same bytes, leaving out B's shards/ and slurm/.
same_dataset() {
  diff -r -q --exclude=shards --exclude=slurm "$1" "$2"
}

"$LOCAL_SLURM" start "$state"
eval "$("$LOCAL_SLURM" env "$state")"

echo "== the unsharded run"
t0=$(now_ms)
"$AIRIS" dataset "$SCENE" --mission "$MISSION" --out "$work/plain" >/dev/null
echo "     unsharded run: $(seconds_since "$t0") s"
frames="$(json_get "$work/plain/manifest.json" 'j["counts"]["frames"]')"

echo "== --slurm 3: three shard tasks and a merge job"
out="$work/three"
t0=$(now_ms)
"$AIRIS" dataset "$SCENE" --mission "$MISSION" --out "$out" --slurm 3 | tee "$work/submit.txt"
check "submission printed the array and merge job ids" \
  grep -qE "^submitted $out: shards 1-3 as array job [0-9]+, merge as job [0-9]+" "$work/submit.txt"
check "the merge ended done" eval '[ "$(wait_merge_ended "$out")" = done ]'
echo "     submit to merged: $(seconds_since "$t0") s"
check "the merged dataset is byte for byte the unsharded run's" same_dataset "$work/plain" "$out"
check "status: shards 1-3 done" eval '[ "$(shard_states "$out")" = "done done done" ]'
check "status: the shards' frames sum to the dataset's ($frames)" \
  eval '[ "$(status_json "$out" | json_get - "j[\"shard_frames\"]")" = "$frames" ]'
"$AIRIS" dataset status "$out" | tee "$work/status.txt"
check "status table shows the merge done with $frames frames" \
  grep -qE "^  merge +done +$frames " "$work/status.txt"

echo "== shard 2 cancelled mid-run, then run again with --only-shards 2"
out="$work/retry"
"$AIRIS" dataset "$SCENE" --mission "$MISSION" --out "$out" --slurm 3 >/dev/null
array="$(json_get "$out/slurm/submission.json" 'j["submissions"][0]["array_job"]')"
first_frame() { [ -s "$out/shards/2/checksums.journal" ]; }
for ((n = 0; n < WAIT_S * 10; n++)); do
  if first_frame; then break; fi
  sleep 0.1
done
check "shard 2 wrote its first frame" first_frame
scancel "${array}_2"
check "the merge ended failed (Slurm cancels it: its dependency can never be met)" \
  eval '[ "$(wait_merge_ended "$out")" = failed ]'
check "shard 2's manifest says incomplete: it was stopped mid-run" \
  eval '[ "$(json_get "$out/shards/2/manifest.json" "j[\"complete\"]")" = False ]'
status_json "$out" >"$work/status.json"
check "status: shards done, failed, done" eval '[ "$(shard_states "$out")" = "done failed done" ]'
check "status: shard 2 kept the frames it wrote before it was stopped" \
  eval '[ "$(json_get "$work/status.json" "j[\"shards\"][1][\"frames\"] > 0")" = True ]'
check "status: shard 2 is to be resubmitted, with --only-shards 2" \
  eval '[ "$(json_get "$work/status.json" "j[\"to_resubmit\"] == [2] and j[\"resubmit\"].endswith(\" --only-shards 2\")")" = True ]'
"$AIRIS" dataset status "$out"
resubmit="$(json_get "$work/status.json" 'j["resubmit"]')"
echo "     $resubmit"
t0=$(now_ms)
eval "$resubmit" >/dev/null
check "the new merge ended done" eval '[ "$(wait_merge_ended "$out")" = done ]'
echo "     resubmit to merged: $(seconds_since "$t0") s"
array2="$(json_get "$out/slurm/submission.json" 'j["submissions"][1]["array_job"]')"
check "the resubmitted task continued shard 2's folder (--resume)" \
  grep -q "continuing the earlier attempt" "$out/slurm/logs/shard-${array2}_2.out"
check "the merged dataset is byte for byte the unsharded run's" same_dataset "$work/plain" "$out"
check "status: every shard done, merge done" \
  eval '[ "$(shard_states "$out") $(merge_state "$out")" = "done done done done" ]'

echo "== a campaign: two seeds of the city, one dataset each"
cat >"$work/train.yaml" <<EOF
name: train
datasets:
  - name: city
    scene: $SCENE
    mission: $MISSION
    seeds: [5, 6]
EOF
"$AIRIS" campaign submit "$work/train.yaml" --out "$work/train" --slurm --shards 1
campaign_merged() {
  "$AIRIS" campaign status "$work/train" --json | json_get - 'j["merged"]'
}
for ((n = 0; n < WAIT_S * 5; n++)); do
  if [ "$(campaign_merged)" = 2 ]; then break; fi
  sleep 0.2
done
check "campaign status: both datasets merged" eval '[ "$(campaign_merged)" = 2 ]'
check "each dataset was made with its own seed" \
  eval '[ "$(json_get "$work/train/city/seed-5/manifest.json" "j[\"scene\"][\"seed\"]") $(json_get "$work/train/city/seed-6/manifest.json" "j[\"scene\"][\"seed\"]")" = "5 6" ]'
"$AIRIS" campaign status "$work/train"

echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
