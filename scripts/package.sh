#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# scripts/package.sh [BUILD_DIR]   build what the Debian package holds (Release: the CLI, the
# editor, the image module, the man page and completions) and make it with CPack
# (cmake/LutkitPackage.cmake): BUILD_DIR/lutkit_<version>_<arch>.deb, default build/ (the tree
# ./run.sh and ./test.sh use). Then: sudo apt install ./build/lutkit_0.1.0_amd64.deb
# `lintian --info build/lutkit_*.deb` reports no error (docs/packaging.md: what it checks, and the
# two warnings that stay).
# scripts/package.sh --windows [OUTDIR]   the Windows zip (docs/windows.md): lutkit.exe
# (scripts/build-windows.sh), README-windows.txt (the README's Windows section), LICENSE.txt and
# the neutral strips to grade, made by the Linux lutkit of build/:
# OUTDIR/lutkit-<version>-windows-x64.zip, default build/windows.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$root}" CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"
if [ "${1:-}" = "--windows" ]; then
  out="${2:-$root/build/windows}"
  case "$out" in /*) ;; *) out="$PWD/$out" ;; esac
  "$root/scripts/install-deps.sh" --cli mingw-w64 zip
  "$root/scripts/build-windows.sh" "$out"
  # The Linux lutkit makes the neutral strips (the same bytes lutkit.exe writes: tests/windows).
  cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$root/build" -j"$(nproc)" --target lutkit >/dev/null
  lutkit="$root/build/bin/lutkit"
  version="$("$lutkit" --version | awk '{print $2}')"
  name="lutkit-$version-windows-x64"
  stage="$out/$name"
  rm -rf "$stage" "$out/$name.zip"
  mkdir -p "$stage/neutral"
  cp "$out/lutkit.exe" "$stage/"
  "$lutkit" neutral "$stage/neutral/neutral.png" >/dev/null                         # 256x16, Smash
  "$lutkit" neutral --layout reshade "$stage/neutral/neutral-reshade.png" >/dev/null # 1024x32
  "$lutkit" neutral --layout unity "$stage/neutral/neutral-unity.png" >/dev/null     # 256x16
  "$lutkit" neutral --level 8 "$stage/neutral/neutral-hald8.png" >/dev/null          # 512x512
  "$lutkit" neutral --size 33 "$stage/neutral/neutral-33.cube" >/dev/null
  # Text files with Windows' line ends, for Notepad.
  sed -n '/<!-- windows -->/,/<!-- \/windows -->/p' "$root/README.md" | sed '1d;$d' |
    sed 's/$/\r/' >"$stage/README-windows.txt"
  printf '\r\nlutkit %s. In a command prompt, lutkit.exe help lists every command; the\r\n%s\r\n' \
    "$version" "sources' README.md and docs/windows.md say the rest." >>"$stage/README-windows.txt"
  sed 's/$/\r/' "$root/LICENSE" >"$stage/LICENSE.txt"
  (cd "$out" && zip -q -r -X "$name.zip" "$name")
  echo "package: $out/$name.zip ($(stat -c %s "$out/$name.zip") bytes)"
  exit 0
fi
build="${1:-$root/build}"
case "$build" in /*) ;; *) build="$root/$build" ;; esac
# The editor's build dependencies, and dpkg-dev for dpkg-shlibdeps (the runtime dependencies) with
# file, which CPack's shlibdeps step runs (a clean Debian 12 has no `file`: cpack failed there).
"$root/scripts/install-deps.sh" --editor dpkg-dev file
# No tests or benchmarks, as ./run.sh: GoogleTest is not among what --editor installs, and a fresh
# clone on a clean Debian 12 stopped here (scripts/deb-clean-build.sh found it).
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DLUTKIT_BUILD_TESTS=OFF \
  -DLUTKIT_BUILD_BENCH=OFF >/dev/null
cmake --build "$build" -j"$(nproc)" --target lutkit lutkit_docs
# The target list read whole first: `grep -q` stops reading at its first match, and under pipefail
# the writer's SIGPIPE made the test false (the editor was never built, cpack failed).
targets="$(cmake --build "$build" --target help)"
if grep -q 'lutkit-editor$' <<<"$targets"; then # Qt 6 was found
  cmake --build "$build" -j"$(nproc)" --target lutkit-editor
fi
(cd "$build" && cpack -G DEB)
ls -1 "$build"/lutkit_*.deb
