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
# OpenColorIO's test files (Files/OcioAllFiles, one case per file, ~226) run in one process per
# half instead of one process per case: under ASan each case costs ~1.4 s in a running process and
# ~3.6 s as its own process (the libraries' start-up and OpenColorIO's first use), ~800 s of the
# stage's ~2,700 s CPU.
grouped='^Files/OcioAllFiles\.'
# Left to the Release stage: the accuracy studies, which run the code of smaller tests that stay
# here on more data (which patch is the most accurate, every edit file and target's printed bound,
# every neutral size, the 256^3 LUT maths): ~330 s of CPU here, nothing ASan could add.
studies='^Defaults\.|^EveryEditFileAndTarget/|^SmashTarget\.DefaultPatchIsTheMostAccurate$'
studies+='|^CheckDefects\.NeutralOfEverySizeHasNoFinding$|^LargeLuts\.Size256$'
# Peak memory (MemoryBounds: resident sizes under ASan's shadow and quarantine say nothing of the
# program's own), match against numpy on 1080p pictures (CliMatchLooks, a benchmark's script) and
# ociobakelut's sizes baked at 64^3 in ten formats (BakeDefaults.LatticeSizes...): the Release
# stage runs them; the code they reach runs here in smaller tests.
studies+='|^MemoryBounds\.|^CliMatchLooks\.|^BakeDefaults\.LatticeSizesAreOciobakelutsPerFormat$'
# Fit's maxima over every pixel of a full screenshot and its same-LUT-whatever-the-threads check
# (TSan runs Fit.*), and both authoring routes on a real stage (~140 s of CPU here): the code they
# reach runs here in Fit's and AboveWhite's smaller tests.
studies+='|^Fit\.(PrintedMaximaBoundEveryPixelOfTheFittedPicture|TheSamePicturesGiveTheSameLutWhateverTheThreads)$|^AboveWhite\.BothRoutesShowTheEditOfTheScreenshotOnAStage$'
# The write matrix (tests/robust/write_matrix.py: ~2,000 outside reads, 4 min of the Release
# stage's test time) runs whole in the Release stage; here two of its groups, the TIFF writer and
# every compression, which cover the writers' own code paths under ASan and UBSan.
studies+='|^Groups/WriteMatrix\.EveryOutputReadBackByOtherPrograms/(apply_(png|jpg|exr|bmp|tga|hdr|webp|dpx|gif|ppm)|structure|stdout|preview|embed)( |$)'
(cd "$build" && QT_QPA_PLATFORM=offscreen ctest --output-on-failure -j"$jobs" \
  -E "$grouped|$studies")
mkdir -p "$build/logs"
pids=()
for ((s = 0; s < jobs; s++)); do
  (cd "$build/bin" && GTEST_TOTAL_SHARDS="$jobs" GTEST_SHARD_INDEX="$s" \
    ./formats_tests --gtest_filter='Files/OcioAllFiles.*' >"$build/logs/ocio-all-files-$s.log" 2>&1) &
  pids+=($!)
done
failed=0
for ((s = 0; s < jobs; s++)); do
  if wait "${pids[$s]}"; then
    echo "sanitize: Files/OcioAllFiles shard $s: $(grep -m1 -F '[  PASSED  ]' "$build/logs/ocio-all-files-$s.log")"
  else
    echo "sanitize: Files/OcioAllFiles shard $s FAILED; from $build/logs/ocio-all-files-$s.log:"
    grep -B2 -A40 -m1 "ERROR: AddressSanitizer\|runtime error\|\[  FAILED  \]" \
      "$build/logs/ocio-all-files-$s.log" | head -60 || true
    failed=1
  fi
done
echo "sanitize: tests took $(( $(date +%s) - built )) s"
[ "$failed" = 0 ]
