#!/usr/bin/env bash
# Fails, naming each file and line, when a C++ source is not as clang-format (Debian's 14, with the
# repository's .clang-format) writes it. `scripts/check-format.sh --fix` rewrites them instead.
set -euo pipefail
cd "$(dirname "$0")/.."
command -v clang-format >/dev/null || { echo "clang-format not found: scripts/install-deps.sh installs it" >&2; exit 2; }
mapfile -t files < <(find benchmarks cmake include src tests -name '*.cpp' -o -name '*.h' | sort)
if [ "${1:-}" = "--fix" ]; then
  clang-format -i "${files[@]}"
else
  clang-format --dry-run --Werror "${files[@]}"
  echo "format: ${#files[@]} files as clang-format writes them"
fi
