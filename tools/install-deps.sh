#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs the Debian 12 (or 13) packages Shadowgraph needs to build, run and test, and any
# packages named as arguments (bootstrap.sh's `test --clang` adds clang). Idempotent: installs
# only what is missing, and runs `apt-get update` only when something is.
set -euo pipefail

packages=(
  cmake g++ make pkg-config clang-format     # toolchain, and the formatter CTest checks the code with
  libvulkan-dev glslang-tools                # Vulkan loader/headers, GLSL -> SPIR-V compiler
  mesa-vulkan-drivers vulkan-validationlayers  # lavapipe CPU device, Khronos validation
  libglfw3-dev libglm-dev libtinygltf-dev libimgui-dev libstb-dev
  nlohmann-json3-dev libcli11-dev
  libembree-dev                              # Intel Embree: ray-traced shadow reference (tools/reference)
  libgtest-dev libbenchmark-dev              # tests and benchmarks
  xvfb xauth                                 # a virtual display for the window tests
  "$@"
)

missing=()
for p in "${packages[@]}"; do
  if [[ "$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null)" != "install ok installed" ]]; then
    missing+=("$p")
  fi
done

if [[ ${#missing[@]} -eq 0 ]]; then
  echo "==> all ${#packages[@]} Debian packages are installed"
  exit 0
fi

sudo=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "error: run as root (or install sudo) to install: ${missing[*]}" >&2; exit 1; }
  sudo=(sudo)
fi
echo "==> installing ${#missing[@]} missing Debian packages: ${missing[*]}"
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -q
"${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "${missing[@]}"
