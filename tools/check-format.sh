#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Checks that every C++ file follows .clang-format; with --fix, rewrites them instead.
# Exit 0 when clean (or fixed), 1 when a file differs.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"
command -v clang-format >/dev/null || { echo "clang-format is not installed" >&2; exit 1; }
mapfile -t files < <(find ecs rendergraph systems sandbox tests tools -name '*.cpp' -o -name '*.h' | sort)
if [[ "${1:-}" == --fix ]]; then
  clang-format -i "${files[@]}"
  echo "formatted ${#files[@]} files"
else
  clang-format --dry-run --Werror "${files[@]}"
  echo "${#files[@]} files follow .clang-format"
fi
