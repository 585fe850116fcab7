#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# From a fresh clone to a picture or a green test suite:
#   bash tools/bootstrap.sh sandbox [sandbox options]   install, build, run the default scene
#   bash tools/bootstrap.sh test [--sanitize|--clang]   install, build, run every test
#     --sanitize: in build-sanitize/ with AddressSanitizer and UndefinedBehaviorSanitizer
#     --clang:    in build-clang/ with Debian's clang (14) instead of GCC
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"

mode="${1:-}"
shift || true
case "$mode" in
  sandbox|test) ;;
  *) echo "usage: bash tools/bootstrap.sh sandbox [sandbox options] | test [--sanitize|--clang]" >&2; exit 2 ;;
esac
variant=""
if [[ "$mode" == test ]]; then
  variant="${1:-}"
  case "$variant" in
    ""|--sanitize|--clang) ;;
    *) echo "unknown test option '$variant' (--sanitize or --clang)" >&2; exit 2 ;;
  esac
fi

if [[ "$variant" == --clang ]]; then bash tools/install-deps.sh clang; else bash tools/install-deps.sh; fi

build_dir=build
cmake_args=(-DCMAKE_BUILD_TYPE=Release)
if [[ "$mode" == test ]]; then
  cmake_args+=(-DSHADOWGRAPH_WERROR=ON)
  if [[ "$variant" == --sanitize ]]; then
    build_dir=build-sanitize
    cmake_args+=(-DSHADOWGRAPH_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo)
  elif [[ "$variant" == --clang ]]; then
    build_dir=build-clang
    cmake_args+=(-DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++)
  fi
fi

jobs=$(nproc)
echo "==> configuring $build_dir"
cmake -S . -B "$build_dir" "${cmake_args[@]}" >/dev/null
echo "==> building with $jobs jobs"
cmake --build "$build_dir" -j "$jobs"

has_display() { [[ -n "${DISPLAY:-}" || -n "${WAYLAND_DISPLAY:-}" ]]; }

if [[ "$mode" == sandbox ]]; then
  echo "==> running the sandbox"
  exec "$build_dir/sandbox/shadowgraph-sandbox" "$@"
fi

export SHADOWGRAPH_VALIDATION=1
if [[ "$build_dir" == build-sanitize ]]; then
  # The Vulkan driver and layers are not built with the sanitizer; their one-time allocations
  # would read as leaks.
  export LSAN_OPTIONS="suppressions=$root/tests/lsan.supp:print_suppressions=0"
fi
ctest_cmd=(ctest --test-dir "$build_dir" --output-on-failure -j "$jobs")
if has_display; then
  echo "==> running the tests"
  "${ctest_cmd[@]}"
else
  echo "==> running the tests on a virtual display (Xvfb)"
  xvfb-run -a -s "-screen 0 1280x1024x24" "${ctest_cmd[@]}"
fi
