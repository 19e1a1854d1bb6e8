#!/bin/bash
# Every C++ file git tracks is formatted as .clang-format says (clang-format --dry-run --Werror
# lists the first differences of each file that is not). Exit 77, a skip, where clang-format is
# not installed (./setup.sh test installs it).
set -euo pipefail
root=${1:?usage: format_check.sh SOURCE_DIR}
cd "$root"
if ! command -v clang-format >/dev/null; then
  echo "format_check: skipped, clang-format is not installed (./setup.sh test installs it)"
  exit 77
fi
mapfile -t files < <(git ls-files '*.cpp' '*.h')
if [ "${#files[@]}" -eq 0 ]; then
  echo "format_check: no C++ files found by git in $root" >&2
  exit 1
fi
if ! clang-format --dry-run --Werror "${files[@]}"; then
  echo "format_check: run 'clang-format -i' on the files above (git ls-files '*.cpp' '*.h' | xargs clang-format -i)" >&2
  exit 1
fi
echo "format_check: ${#files[@]} files formatted as .clang-format says"
