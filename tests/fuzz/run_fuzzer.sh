#!/usr/bin/env bash
# Runs one libFuzzer target for a bounded budget and fails on any finding (a crash, a sanitizer
# report, an uncaught exception, a leak, an input slower than 25 s or one that needs more than 2 GB):
#
#   tests/fuzz/run_fuzzer.sh FUZZER WORK_DIR BUDGET CORPUS [MORE_CORPORA...] [-- LIBFUZZER_FLAGS...]
#
# BUDGET is either SECONDS (a run by hand that explores; WORK_DIR/corpus carries over to the next
# run) or runs=N: N executions from the seeds alone (WORK_DIR/corpus emptied first), which with a
# fixed -seed repeat the same inputs on any machine, at any speed, from any folder: what CTest runs
# (tests/fuzz/CMakeLists.txt), so a CI result is the same wherever it runs. For that, a runs=N budget
# turns off what makes libFuzzer's choices depend on the clock or on addresses: re-reading the
# output folder every second (-reload=0), the operands of comparisons as mutation material
# (-use_cmp=0: pointers compared in the target differ from run to run with address randomization
# and the size of the environment), and address randomization itself (setarch -R, where the
# system allows it): containers ordered by pointer (and hash tables of them) visit their entries in
# another order in each run, which reaches other code, which libFuzzer counts as coverage and keeps
# other inputs for. Measured on the scene target: its seeds alone gave coverage 15,403 to 15,413 in
# five runs with randomization, 15,408 in all three without. Longer runs by SECONDS keep all three.
#
# The seeds (every file under the CORPUS folders) reach libFuzzer as one list in byte order of their
# paths, not by reading the folders, whose order differs between file systems. New inputs that reach
# new code go to WORK_DIR/corpus (never into the repository's corpora, which are read only); a
# finding is written to WORK_DIR/findings/ and its path printed. docs/fuzzing.md shows a longer run.
set -euo pipefail
fuzzer=$1 work=$2 budget=$3
shift 3
corpora=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do corpora+=("$1"); shift; done
[ $# -gt 0 ] && shift  # the --
fixed=()
case $budget in
  runs=*)
    limit=(-runs="${budget#runs=}" -reload=0 -use_cmp=0)
    rm -rf "$work/corpus"
    if setarch "$(uname -m)" -R true 2>/dev/null; then
      fixed=(setarch "$(uname -m)" -R)
    else
      echo "run_fuzzer.sh: setarch -R is refused here: addresses are randomized, runs may differ" >&2
    fi
    ;;
  *) limit=(-max_total_time="$budget") ;;
esac
mkdir -p "$work/corpus" "$work/findings"
# Files a target writes (the mesh target's input files) go under WORK_DIR/tmp, emptied here, not
# into the system's temporary folder.
rm -rf "$work/tmp"
mkdir -p "$work/tmp"
export TMPDIR="$work/tmp"
find "${corpora[@]}" -type f | LC_ALL=C sort | paste -sd, > "$work/seeds"
export ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
exec "${fixed[@]}" "$fuzzer" "${limit[@]}" -seed_inputs=@"$work/seeds" -timeout=25 -rss_limit_mb=2048 \
  -max_len=65536 -print_final_stats=1 -artifact_prefix="$work/findings/" "$@" "$work/corpus"
