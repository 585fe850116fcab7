#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# From a fresh clone to a picture or a green test suite:
#   bash tools/bootstrap.sh sandbox [sandbox options]   install, build, run the default scene
#   bash tools/bootstrap.sh test [--sanitize]           install, build, run every test
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$root"

mode="${1:-}"
shift || true
case "$mode" in
  sandbox|test) ;;
  *) echo "usage: bash tools/bootstrap.sh sandbox [sandbox options] | test [--sanitize]" >&2; exit 2 ;;
esac

bash tools/install-deps.sh

build_dir=build
cmake_args=(-DCMAKE_BUILD_TYPE=Release)
if [[ "$mode" == test ]]; then
  cmake_args+=(-DSHADOWGRAPH_WERROR=ON)
  if [[ "${1:-}" == --sanitize ]]; then
    build_dir=build-sanitize
    cmake_args+=(-DSHADOWGRAPH_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo)
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
