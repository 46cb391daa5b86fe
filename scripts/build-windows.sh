#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# scripts/build-windows.sh [OUTDIR]   lutkit for Windows (docs/windows.md): the portable CLI
# cross-compiled with Debian's MinGW-w64 into one self-contained lutkit.exe in OUTDIR (default
# build/windows). The build tree is build-windows/ (ccache works with MinGW).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="${1:-$root/build/windows}"
case "$out" in /*) ;; *) out="$PWD/$out" ;; esac
tree="${LUTKIT_WINDOWS_BUILD_DIR:-$root/build-windows}"
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$root}" CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"
if ! command -v x86_64-w64-mingw32-g++-posix >/dev/null; then
  echo "build-windows: mingw-w64 is not installed (scripts/install-deps.sh installs it)" >&2
  exit 1
fi
cmake -S "$root" -B "$tree" -DCMAKE_BUILD_TYPE=Release -DLUTKIT_PORTABLE=ON \
  -DCMAKE_TOOLCHAIN_FILE="$root/cmake/toolchains/mingw-w64.cmake" -DLUTKIT_WARNINGS_AS_ERRORS=ON >/dev/null
cmake --build "$tree" -j"$(nproc)" --target lutkit
mkdir -p "$out"
cp "$tree/bin/lutkit.exe" "$out/"
x86_64-w64-mingw32-strip "$out/lutkit.exe"
echo "build-windows: $out/lutkit.exe ($(stat -c %s "$out/lutkit.exe") bytes)"
