#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Builds the whole test suite with AddressSanitizer + UndefinedBehaviorSanitizer and runs it.
# Usage: scripts/sanitize.sh [BUILD_DIR]   (default build-asan)
# Optimised lightly (-O1) so the slow tests stay bearable; -g1 (line tables only) keeps stack
# traces at file:line and costs about a third less compile time than -g. The tests' sources
# compile in batches (LUTKIT_UNITY_TESTS, tests/CMakeLists.txt): about half their CPU with an
# empty ccache (CONTRIBUTING.md, "The CI time budget").
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build-asan}"
case "$build" in /*) ;; *) build="$root/$build" ;; esac
jobs="$(nproc)"

start=$(date +%s)
cmake -S "$root" -B "$build" -DLUTKIT_SANITIZE=ON -DLUTKIT_BUILD_GUI=OFF -DLUTKIT_BUILD_BENCH=OFF -DLUTKIT_UNITY_TESTS=ON \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O1 -g1" >/dev/null
cmake --build "$build" -j"$jobs"
built=$(date +%s)
echo "sanitize: build took $(( built - start )) s"

export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:${ASAN_OPTIONS:-}"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:${UBSAN_OPTIONS:-}"
if [ -f "$root/scripts/lsan.supp" ]; then
  export LSAN_OPTIONS="suppressions=$root/scripts/lsan.supp:${LSAN_OPTIONS:-}"
fi
# Each test executable runs whole, split in one shard per core (GTEST_TOTAL_SHARDS), instead of one
# process per case as ctest runs them: under ASan a process costs its start-up (the libraries,
# OpenColorIO's first use) and the leak check at exit, ~1-2 s a case and most of the stage when
# each of ~1,000 cases paid it (an OpenColorIO file's case: ~3.6 s alone, ~1.4 s in a running
# process). The Release stage still runs every case in its own process, so a case that leans on
# another's state fails there. ctest runs what is not a GoogleTest case (no '.' in its name: the
# API samples, the output record, the install and desktop checks).
# Left to the Release stage: the accuracy studies, which run the code of smaller tests that stay
# here on more data (which patch is the most accurate, every edit file and target's printed bound,
# every neutral size, the 256^3 LUT maths): ~330 s of CPU here, nothing ASan could add.
studies='Defaults.*:EveryEditFileAndTarget/*:SmashTarget.DefaultPatchIsTheMostAccurate'
studies+=':CheckDefects.NeutralOfEverySizeHasNoFinding:LargeLuts.Size256'
studies+=':MemoryBounds.*:CliMatchLooks.*:BakeDefaults.LatticeSizesAreOciobakelutsPerFormat'
studies+=':Fit.PrintedMaximaBoundEveryPixelOfTheFittedPicture:Fit.TheSamePicturesGiveTheSameLutWhateverTheThreads'
studies+=':AboveWhite.BothRoutesShowTheEditOfTheScreenshotOnAStage'
for w in apply_png apply_jpg apply_exr apply_bmp apply_tga apply_hdr apply_webp apply_dpx apply_gif \
  apply_ppm structure stdout preview embed; do
  studies+=":Groups/WriteMatrix.EveryOutputReadBackByOtherPrograms/$w"
done
(cd "$build" && QT_QPA_PLATFORM=offscreen ctest --output-on-failure -j"$jobs" -E '\.')
mkdir -p "$build/logs"
failed=0
for exe in "$build"/bin/*_tests; do
  name="$(basename "$exe")"
  t0=$(date +%s)
  pids=()
  for ((s = 0; s < jobs; s++)); do
    (cd "$build/bin" && GTEST_TOTAL_SHARDS="$jobs" GTEST_SHARD_INDEX="$s" QT_QPA_PLATFORM=offscreen \
      timeout 3600 "./$name" --gtest_filter="-$studies" >"$build/logs/$name-$s.log" 2>&1) &
    pids+=($!)
  done
  for ((s = 0; s < jobs; s++)); do
    log="$build/logs/$name-$s.log"
    if wait "${pids[$s]}"; then
      echo "sanitize: $name shard $s: $(grep -m1 -F '[  PASSED  ]' "$log") ($(( $(date +%s) - t0 )) s)"
    else
      echo "sanitize: $name shard $s FAILED; from $log:"
      grep -B2 -A40 -m1 "ERROR: AddressSanitizer\|ERROR: LeakSanitizer\|runtime error\|\[  FAILED  \]" \
        "$log" | head -60 || true
      grep -F '[  FAILED  ]' "$log" | sort -u | head -20 || true
      failed=1
    fi
  done
done
echo "sanitize: tests took $(( $(date +%s) - built )) s"
[ "$failed" = 0 ]
