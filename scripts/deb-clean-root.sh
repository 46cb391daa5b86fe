#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# scripts/deb-clean-root.sh DEB [ROOT]   the package on a clean Debian 12, as a user installs it:
# debootstrap makes a minimal bookworm root (default /tmp/lutkit-deb12, made anew), `apt install
# ./lutkit_*.deb` runs in it (the runtime dependencies come from Debian's mirror), then
# `lutkit --version`, `lutkit-editor --version` and the README's quick starts, on made-up inputs,
# run in it. Needs root and the network (so not in CI, whose package test extracts the .deb
# instead: tests/install/PackageTest.cmake). About 3 minutes; prints each step's time.
set -euo pipefail
deb="$(readlink -f "${1:?usage: scripts/deb-clean-root.sh DEB [ROOT]}")"
root="${2:-/tmp/lutkit-deb12}"
[ "$(id -u)" -eq 0 ] || { echo "deb-clean-root: run as root (debootstrap, chroot)" >&2; exit 2; }
command -v debootstrap >/dev/null || apt-get install -y -qq debootstrap >/dev/null
command -v oiiotool >/dev/null || { echo "deb-clean-root: oiiotool makes the inputs (scripts/install-deps.sh)" >&2; exit 2; }
step() { echo "== $* ($(date +%T))"; }
# shellcheck source=scripts/debian-root.sh
source "$(dirname "$0")/debian-root.sh"

step "debootstrap --variant=minbase bookworm $root"
make_bookworm_root "$root"

step "apt install ./$(basename "$deb")"
mkdir -p "$root/root/qs"
cp "$deb" "$root/root/"
chroot "$root" bash -c "export DEBIAN_FRONTEND=noninteractive; cd /root && apt-get update -qq &&
  { apt-get install -y -qq ./$(basename "$deb") >/root/apt.log 2>&1 || { cat /root/apt.log; exit 1; }; }"

step "the programs and the README's quick starts"
here="$(cd "$(dirname "$0")/.." && pwd)"
cp "$here/samples/sample_grade.cube" "$root/root/qs/look.cube"
oiiotool --pattern "fill:topleft=0.1,0.2,0.3:topright=0.9,0.4,0.1:bottomleft=0,0.8,0.6:bottomright=0.8,0.7,0.6" \
  1280x720 3 -d uint8 -o "$root/root/qs/screenshot.png"
for i in 0001 0002; do
  oiiotool --pattern "fill:top=0.1,0.2,0.3:bottom=0.9,0.4,0.1" 640x360 3 -d half -o "$root/root/qs/plate.$i.exr"
done
chroot "$root" bash -c 'set -e; cd /root/qs
  lutkit --version
  QT_QPA_PLATFORM=offscreen lutkit-editor --version
  lutkit neutral neutral.png
  cp neutral.png graded.png # (the grade made in a paint program)
  lutkit convert graded.png color_grading_lut.nutexb
  lutkit preview screenshot.png -o in_game.png --lut color_grading_lut.nutexb
  lutkit convert look.cube look.3dl
  lutkit apply --lut look.cube plate.%04d.exr -o graded.%04d.exr'
step "passed: the package installs and runs on a clean Debian 12 ($root)"
