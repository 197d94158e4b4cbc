#!/usr/bin/env bash
# Checks that every C++ source of the project is formatted with .clang-format (clang-format 14,
# Debian 12's `clang-format`). Prints the files that are not and exits 1; --fix formats them
# in place instead. packaging/test.sh runs it as the "format" stage.
set -uo pipefail
cd "$(dirname "$0")/.."

fix=0
[ "${1:-}" = "--fix" ] && fix=1
if ! command -v clang-format > /dev/null; then
  echo "check-format: clang-format is not installed (packaging/install-deps.sh installs it)" >&2
  exit 1
fi
mapfile -t files < <(git ls-files -- '*.cpp' '*.h' '*.c' | grep -E '^(core|sim|cli|ui|app|tests)/')
if [ "${#files[@]}" -eq 0 ]; then
  echo "check-format: no sources found (run it inside the git checkout)" >&2
  exit 1
fi
if [ "$fix" -eq 1 ]; then
  clang-format -i --style=file "${files[@]}"
  echo "check-format: formatted ${#files[@]} files"
  exit 0
fi
bad=()
for f in "${files[@]}"; do
  if ! clang-format --style=file --dry-run -Werror "$f" > /dev/null 2>&1; then
    bad+=("$f")
  fi
done
if [ "${#bad[@]}" -gt 0 ]; then
  echo "check-format: ${#bad[@]} of ${#files[@]} files are not formatted with .clang-format:"
  printf '  %s\n' "${bad[@]}"
  echo "  fix: packaging/check-format.sh --fix"
  exit 1
fi
echo "check-format: all ${#files[@]} files formatted"
