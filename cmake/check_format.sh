#!/usr/bin/env bash
# Fails, naming the files, when a C++ source of the project is not formatted as .clang-format says.
#   cmake/check_format.sh SOURCE_DIR [CLANG_FORMAT]
# `make format` formats them. The test suite runs it (tests/layers/CMakeLists.txt), so CI fails on
# unformatted code.
set -euo pipefail
root="${1:?usage: check_format.sh SOURCE_DIR [CLANG_FORMAT]}"
tool="${2:-clang-format}"
cd "$root"
if ! command -v "$tool" >/dev/null 2>&1; then
  echo "check_format: $tool not found (scripts/install-deps.sh installs clang-format)" >&2
  exit 1
fi
mapfile -t files < <(find engine vehicles sensors scenes tools tests -name '*.h' -o -name '*.cc' | sort)
bad=()
for f in "${files[@]}"; do
  if ! "$tool" --dry-run --Werror "$f" >/dev/null 2>&1; then bad+=("$f"); fi
done
if [ ${#bad[@]} -gt 0 ]; then
  echo "check_format: ${#bad[@]} file(s) not clang-formatted (run 'make format'):" >&2
  printf '  %s\n' "${bad[@]}" >&2
  exit 1
fi
echo "check_format: ${#files[@]} files formatted"
