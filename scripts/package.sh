#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# scripts/package.sh [BUILD_DIR]   build what the Debian package holds (Release: the CLI, the
# editor, the image module, the man page and completions) and make it with CPack
# (cmake/LutkitPackage.cmake): BUILD_DIR/lutkit_<version>_<arch>.deb, default build/ (the tree
# ./run.sh and ./test.sh use). Then: sudo apt install ./build/lutkit_0.1.0_amd64.deb
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build}"
case "$build" in /*) ;; *) build="$root/$build" ;; esac
# The editor's build dependencies, and dpkg-dev for dpkg-shlibdeps (the runtime dependencies).
"$root/scripts/install-deps.sh" --editor dpkg-dev
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$root}" CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build" -j"$(nproc)" --target lutkit lutkit_docs
# The target list read whole first: `grep -q` stops reading at its first match, and under pipefail
# the writer's SIGPIPE made the test false (the editor was never built, cpack failed).
targets="$(cmake --build "$build" --target help)"
if grep -q 'lutkit-editor$' <<<"$targets"; then # Qt 6 was found
  cmake --build "$build" -j"$(nproc)" --target lutkit-editor
fi
(cd "$build" && cpack -G DEB)
ls -1 "$build"/lutkit_*.deb
