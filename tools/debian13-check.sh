#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs the README's test command (bootstrap.sh test) on Debian 13 in a chroot, from a copy of this
# working tree (tracked and untracked files, not ignored ones):
#   sudo bash tools/debian13-check.sh [CHROOT]   CHROOT: default /var/tmp/shadowgraph-debian13
# Needs root (debootstrap, chroot, mounts) and Debian's mirror. The chroot is kept between runs,
# so its packages are installed once; the tree is copied afresh each run and built from scratch.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
target="${1:-/var/tmp/shadowgraph-debian13}"
[[ $(id -u) -eq 0 ]] || { echo "error: run as root: debootstrap, chroot and mounts need it" >&2; exit 1; }

if ! command -v debootstrap >/dev/null; then
  echo "==> installing debootstrap"
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q debootstrap
fi
if [[ ! -x "$target/usr/bin/apt-get" ]]; then
  echo "==> creating a Debian 13 (trixie) chroot in $target"
  debootstrap --variant=minbase trixie "$target" http://deb.debian.org/debian
fi

unmount() {
  umount -R "$target/dev" 2>/dev/null || true
  umount -R "$target/sys" 2>/dev/null || true
  umount "$target/proc" 2>/dev/null || true
}
trap unmount EXIT
mount -t proc proc "$target/proc"
mount --rbind /dev "$target/dev"
mount --rbind /sys "$target/sys"
cp /etc/resolv.conf "$target/etc/resolv.conf"

echo "==> copying the working tree to $target/src"
rm -rf "$target/src"
mkdir -p "$target/src"
git -C "$root" ls-files -z --cached --others --exclude-standard |
  tar -C "$root" --null -T - -cf - | tar -C "$target/src" -xf -

chroot "$target" bash -c "cd /src && bash tools/bootstrap.sh test"
