#!/usr/bin/env bash
# Runs one libFuzzer target for a bounded time and fails on any finding (a crash, a sanitizer report,
# an uncaught exception, a leak, an input slower than 25 s or one that needs more than 2 GB):
#
#   tests/fuzz/run_fuzzer.sh FUZZER WORK_DIR SECONDS CORPUS [MORE_CORPORA...] [-- LIBFUZZER_FLAGS...]
#
# New inputs that reach new code go to WORK_DIR/corpus (never into the repository's corpora, which
# are read only); a finding is written to WORK_DIR/findings/ and its path printed. CTest runs it as
# Fuzz.NAME (tests/fuzz/CMakeLists.txt); docs/fuzzing.md shows a longer run.
set -euo pipefail
fuzzer=$1 work=$2 seconds=$3
shift 3
corpora=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do corpora+=("$1"); shift; done
[ $# -gt 0 ] && shift  # the --
mkdir -p "$work/corpus" "$work/findings"
export ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
exec "$fuzzer" -max_total_time="$seconds" -timeout=25 -rss_limit_mb=2048 -max_len=65536 \
  -print_final_stats=1 -artifact_prefix="$work/findings/" "$@" "$work/corpus" "${corpora[@]}"
