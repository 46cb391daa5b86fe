#!/usr/bin/env bash
# Builds the whole test suite with AddressSanitizer + UndefinedBehaviorSanitizer and runs it.
# Usage: scripts/sanitize.sh [BUILD_DIR]   (default build-asan)
# Optimised lightly (-O1) so the slow tests stay bearable while stack traces stay readable.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build-asan}"
case "$build" in /*) ;; *) build="$root/$build" ;; esac
jobs="$(nproc)"

start=$(date +%s)
cmake -S "$root" -B "$build" -DLUTKIT_SANITIZE=ON -DLUTKIT_BUILD_GUI=OFF -DLUTKIT_BUILD_BENCH=OFF \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" >/dev/null
cmake --build "$build" -j"$jobs"
built=$(date +%s)
echo "sanitize: build took $(( built - start )) s"

export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:${ASAN_OPTIONS:-}"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:${UBSAN_OPTIONS:-}"
if [ -f "$root/scripts/lsan.supp" ]; then
  export LSAN_OPTIONS="suppressions=$root/scripts/lsan.supp:${LSAN_OPTIONS:-}"
fi
(cd "$build" && QT_QPA_PLATFORM=offscreen ctest --output-on-failure -j"$jobs")
echo "sanitize: tests took $(( $(date +%s) - built )) s"
