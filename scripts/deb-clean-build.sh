#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# scripts/deb-clean-build.sh [ROOT]   a fresh clone built on a clean Debian 12, as the README's
# install section tells a new user: debootstrap makes a minimal bookworm root (default
# /tmp/lutkit-build12, made anew) with only git added; in it, from a clone of this repository's
# HEAD:
#   1. scripts/package.sh makes the .deb (it installs what the build needs itself), lintian
#      reports no error on it, `apt install ./build/lutkit_*.deb` installs it, and both programs
#      run (lutkit --version, lutkit-editor --version, a neutral strip);
#   2. in a second fresh clone, ./run.sh builds the CLI and `cmake --install build --prefix DIR`
#      installs a CLI that runs (DIR/bin/lutkit convert).
# Needs root and the network (so not in CI: tests/install covers the package and the install from
# this machine's build tree). The host's ccache folder is mounted in the root when it exists
# (LUTKIT_CCACHE_DIR, default ~/.cache/ccache): the same Debian compiler reuses its objects, a
# cold build takes ~20 min on 2 cores. Prints each step's time; scripts/deb-clean-root.sh checks
# an already made .deb alone.
set -euo pipefail
root="${1:-/tmp/lutkit-build12}"
here="$(cd "$(dirname "$0")/.." && pwd)"
cache="${LUTKIT_CCACHE_DIR:-$HOME/.cache/ccache}"
[ "$(id -u)" -eq 0 ] || { echo "deb-clean-build: run as root (debootstrap, chroot)" >&2; exit 2; }
command -v debootstrap >/dev/null || apt-get install -y -qq debootstrap >/dev/null
step() { echo "== $* ($(date +%T))"; }
# shellcheck source=scripts/debian-root.sh
source "$(dirname "$0")/debian-root.sh"
mounted=()
cleanup() {
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do umount -l "${mounted[$i]}" 2>/dev/null || true; done
}
trap cleanup EXIT
bind() { mkdir -p "$2" && mount --bind "$1" "$2" && mounted+=("$2"); }

step "debootstrap --variant=minbase --include=git,ca-certificates bookworm $root"
make_bookworm_root "$root" git,ca-certificates
[ -d "$cache" ] && bind "$cache" "$root/root/.cache/ccache"
git clone -q "$here" "$root/root/lutkit"
git clone -q "$here" "$root/root/lutkit-run"

step "scripts/package.sh (a fresh clone; it installs what the build needs)"
chroot "$root" bash -c 'set -e; export DEBIAN_FRONTEND=noninteractive; apt-get update -qq
  cd /root/lutkit && scripts/package.sh >/root/package.log 2>&1 || { tail -40 /root/package.log; exit 1; }
  ls build/lutkit_*.deb'

step "lintian (no error) and apt install ./build/lutkit_*.deb"
chroot "$root" bash -c 'set -e; export DEBIAN_FRONTEND=noninteractive
  apt-get install -y -qq lintian >/dev/null
  cd /root/lutkit
  lintian build/lutkit_*.deb | tee /root/lintian.log
  if grep -q "^E:" /root/lintian.log; then echo "lintian reported errors"; exit 1; fi
  apt-get install -y -qq ./build/lutkit_*.deb >/root/apt.log 2>&1 || { cat /root/apt.log; exit 1; }
  cd /tmp && lutkit --version && QT_QPA_PLATFORM=offscreen lutkit-editor --version
  lutkit neutral neutral.png && lutkit convert neutral.png color_grading_lut.nutexb'

step "./run.sh in a second fresh clone, then cmake --install build --prefix /root/prefix"
chroot "$root" bash -c 'set -e; export DEBIAN_FRONTEND=noninteractive
  cd /root/lutkit-run && ./run.sh >/root/run.log 2>&1 || { tail -40 /root/run.log; exit 1; }
  cmake --install build --prefix /root/prefix >/root/install.log 2>&1 || { tail -40 /root/install.log; exit 1; }
  cd /tmp && /root/prefix/bin/lutkit --version
  /root/prefix/bin/lutkit convert /root/lutkit-run/samples/sample_grade.cube look.3dl'
step "passed: a fresh clone builds, packages, installs and runs on a clean Debian 12 ($root)"
