#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# ./test.sh   install what is missing, build, and run the whole test suite with ctest.
# Exits non-zero on any failure. Set LUTKIT_QUICK=1 to skip the sanitizer builds and fuzzing.
# Stages: Release build + ctest (build/), then (unless LUTKIT_QUICK=1): the Windows edition
# cross-built and run under Wine against it (build-windows/, build/windows/, tests/windows/run.sh;
# when mingw-w64 and wine are installed), lutkit for the browser built (build-web/, build/web/),
# each command against the native CLI and its page driven in headless Chromium (tests/web/run.sh),
# ASan+UBSan build + ctest (build-asan/, scripts/sanitize.sh), ThreadSanitizer build + the
# threaded code's tests (build-tsan/, scripts/tsan.sh), each libFuzzer harness for
# LUTKIT_FUZZ_SECONDS (default 30) s (build-fuzz/, scripts/fuzz.sh; findings land in
# build-fuzz/findings/). The last line says ALL PASSED or the stage that failed.
set -euo pipefail
root="$(cd "$(dirname "$0")" && pwd)"
# A final summary line in every case, naming the stage that failed.
stage="install"
t0=$(date +%s)
ts=$t0
# One line per stage with its time, so a slow stage shows in CI's log.
took() { echo "test.sh: $stage took $(( $(date +%s) - ts )) s"; ts=$(date +%s); }
trap 'rc=$?; if [ $rc -ne 0 ]; then echo "test.sh: FAILED in stage: $stage (exit $rc) after $(( $(date +%s) - t0 )) s"; fi' EXIT
"$root/scripts/install-deps.sh"
jobs="$(nproc)"
# ccache (CMakeLists.txt uses it when installed): paths inside the clone are hashed relative to
# it and the build folder is not hashed, so another clone of the same sources reuses the objects.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$root}" CCACHE_NOHASHDIR="${CCACHE_NOHASHDIR:-1}"

took
stage="release"
echo "== Release build and tests"
# Tests and benchmarks on (./run.sh builds the same tree without them). The tests' sources compile
# in batches (LUTKIT_UNITY_TESTS, tests/CMakeLists.txt): ~470 s less CPU with an empty ccache;
# LUTKIT_UNITY_TESTS=OFF ./test.sh keeps one file per translation unit (quicker to rebuild one).
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release -DLUTKIT_WARNINGS_AS_ERRORS=ON \
  -DLUTKIT_BUILD_TESTS=ON -DLUTKIT_BUILD_BENCH=ON -DLUTKIT_UNITY_TESTS="${LUTKIT_UNITY_TESTS:-ON}" >/dev/null
cmake --build "$root/build" -j"$jobs"
(cd "$root/build" && QT_QPA_PLATFORM=offscreen ctest --output-on-failure -j"$jobs")

took

if [ "${LUTKIT_QUICK:-0}" != "1" ]; then
  # The Windows edition (docs/windows.md): lutkit.exe cross-built with MinGW-w64 and run under Wine
  # against the Linux build just made, outputs compared byte for byte (tests/windows/run.sh).
  if command -v x86_64-w64-mingw32-g++-posix >/dev/null && command -v wine >/dev/null; then
    stage="windows"
    echo "== Windows edition: cross-built, run under Wine against the Linux build (tests/windows)"
    "$root/scripts/build-windows.sh" "$root/build/windows"
    "$root/tests/windows/run.sh" "$root/build/bin/lutkit" "$root/build/windows/lutkit.exe" \
      "$root/build/windows-tests"
    took
  fi
  stage="web"
  echo "== lutkit for the browser: the build, each command against the native CLI and the page, in headless Chromium (tests/web/run.sh)"
  "$root/tests/web/run.sh"
  took
  stage="sanitizers"
  echo "== AddressSanitizer + UBSan build and tests (scripts/sanitize.sh)"
  "$root/scripts/sanitize.sh" "$root/build-asan"
  took
  stage="tsan"
  echo "== ThreadSanitizer build and the threaded code's tests (scripts/tsan.sh)"
  "$root/scripts/tsan.sh" "$root/build-tsan"
  took
  stage="fuzzing"
  echo "== Fuzzing each reader for ${LUTKIT_FUZZ_SECONDS:-30} s (scripts/fuzz.sh)"
  "$root/scripts/fuzz.sh" "$root/build-fuzz" "${LUTKIT_FUZZ_SECONDS:-30}"
  took
fi
stage="done"
echo "test.sh: ALL PASSED in $(( $(date +%s) - t0 )) s$([ "${LUTKIT_QUICK:-0}" = "1" ] && echo " (quick: no browser edition, sanitizers or fuzzing)")"
