#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Sourced by scripts/deb-clean-root.sh and scripts/deb-clean-build.sh: one clean Debian 12 root.
#   make_bookworm_root ROOT [PACKAGE,...]   debootstrap --variant=minbase bookworm into ROOT (made
#                                           anew; the packages named are added), with bookworm's
#                                           main, updates and security sources and this machine's
#                                           resolver. DEBIAN_MIRROR chooses the mirror.
make_bookworm_root() {
  local root="$1" include="${2:-}" mirror="${DEBIAN_MIRROR:-http://deb.debian.org/debian}"
  # Never rm -rf through a mount (a bind of /dev or a cache left by an interrupted run).
  if grep -q " $root/" /proc/mounts; then
    echo "$(basename "$0"): something is still mounted under $root; unmount it first" >&2
    return 2
  fi
  rm -rf "$root"
  debootstrap --variant=minbase ${include:+--include="$include"} bookworm "$root" "$mirror" >/dev/null
  cat >"$root/etc/apt/sources.list" <<SOURCES
deb $mirror bookworm main
deb $mirror bookworm-updates main
deb http://deb.debian.org/debian-security bookworm-security main
SOURCES
  cp /etc/resolv.conf "$root/etc/resolv.conf"
}
